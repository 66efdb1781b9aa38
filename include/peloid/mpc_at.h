/* Multi-particle collision with the Andersen thermostat, MPC-AT (Noguchi,
 * Kikuchi & Gompper, EPL 78, 10005 (2007); Gompper, Ihle, Kroll & Winkler,
 * Adv. Polym. Sci. 221, 1 (2009), Sec. 2.3): the velocities relative to the
 * cell's mean are replaced by fresh Maxwell-Boltzmann ones,
 *   v_i' = u + xi_i - <xi>,   xi_i Gaussian with variance kT/m per component,
 * <xi> their cell mean.  Each cell keeps its momentum; its kinetic energy
 * relative to u is drawn anew at the bath's kT (the rule is a thermostat,
 * not energy conserving), and its angular momentum is not kept (MPC-AT+a,
 * peloid/cell_angular.h, restores it).  m = 1. */
#ifndef PELOID_MPC_AT_H
#define PELOID_MPC_AT_H

#include <string.h>

#include "peloid/rng.h"
#include "peloid/srd_kernels.h"

/* The Gaussian xi_i / sqrt(kT) of particle k of cell `cell` (k = 0, 1, ...
 * in the cell's sorted order): draw k of the stream (seed,
 * PL_RNG_ANDERSEN, step, cell), so the result depends on neither the thread
 * nor the block that handles the cell. */
static inline void pl_mpc_at_gauss(uint64_t seed, uint64_t step, uint64_t cell, uint64_t k, double g[3])
{
    const pl_rand4_t r = pl_rng_uniform4(seed, PL_RNG_ANDERSEN, step, cell, k);
    double unused;
    pl_rng_gauss2(r.u[0], r.u[1], &g[0], &g[1]);
    pl_rng_gauss2(r.u[2], r.u[3], &g[2], &unused);
}

/* Cells up to this many particles keep their draws on the stack; larger
 * ones (rare at any usual density) draw them a second time. */
enum { PL_MPC_AT_CELL_BUF = 64 };

/* The Andersen collision of cell `cell`, particles [s, e) (e - s >= 2):
 * v_i <- u + sd (g_i - <g>), sd = sqrt(kT/m).  Returns sum (v_i' - u)^2
 * (what the cell's temperature is measured from). */
static inline double pl_mpc_at_cell(pl_real *restrict vx, pl_real *restrict vy, pl_real *restrict vz, size_t s,
                                    size_t e, double sd, uint64_t seed, uint64_t step, uint64_t cell)
{
    const double M = (double)(e - s);
    const int keep = e - s <= PL_MPC_AT_CELL_BUF;
    double P[3] = {0.0, 0.0, 0.0}, G[3] = {0.0, 0.0, 0.0}, buf[PL_MPC_AT_CELL_BUF][3];
    for (size_t i = s; i < e; ++i) {
        double g[3];
        pl_mpc_at_gauss(seed, step, cell, i - s, g);
        if (keep) memcpy(buf[i - s], g, sizeof g);
        P[0] += vx[i]; P[1] += vy[i]; P[2] += vz[i];
        G[0] += g[0]; G[1] += g[1]; G[2] += g[2];
    }
    double u[3], gm[3], sum2 = 0.0;
    for (int d = 0; d < 3; ++d) {
        u[d] = P[d] / M;
        gm[d] = G[d] / M;
    }
    for (size_t i = s; i < e; ++i) {
        double g[3];
        if (keep) memcpy(g, buf[i - s], sizeof g);
        else pl_mpc_at_gauss(seed, step, cell, i - s, g);
        const double a = sd * (g[0] - gm[0]), b = sd * (g[1] - gm[1]), c = sd * (g[2] - gm[2]);
        vx[i] = (pl_real)(u[0] + a);
        vy[i] = (pl_real)(u[1] + b);
        vz[i] = (pl_real)(u[2] + c);
        sum2 += a * a + b * b + c * c;
    }
    return sum2;
}

/* MPC-AT in every cell with >= 2 particles (cells of one particle keep it:
 * u + xi - xi = u).  The contract of pl_srd_collide (block sums, guard
 * flags); p->kT_target is the bath's kT.  No virtual wall particles: the
 * rule's row refuses no-slip walls. */
void pl_mpc_at_collide(pl_fluid_t *fluid, const pl_grid_t *grid, const uint32_t *cell_start,
                       const pl_collide_params_t *p, double *block_sum, int nthreads);

#endif
