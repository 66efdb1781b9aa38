/* SRD collision step with the optional Heyes Monte Carlo cell thermostat.
 *
 * For every cell c (particles contiguous after the counting sort):
 *   u = mean velocity of the cell, v_i -> u + zeta R (v_i - u)
 * PL Eq. 3 / Hecht Eq. 12.  R: rotation by alpha about a random axis (PL
 * Eq. 3, axis uniform on the sphere, Rodrigues' formula) or +-90 degrees
 * about one of the three coordinate axes, each of the 6 with probability 1/6
 * (Hecht Sec. III).  Cells with one particle are left as they are.
 *
 * Heyes thermostat (Hecht Sec. VIII.B, Eq. 33): eps uniform in [0, eps_max],
 * zeta = 1+eps or 1/(1+eps) with probability 1/2 each (a proposal symmetric
 * in ln zeta), accepted with probability
 *   min(1, zeta^{3(M-1)} exp(-(zeta^2 - 1) K / kT*)),  K = sum m (v-u)^2 / 2.
 * With Hecht's local temperature T = m sum (v-u)^2 / (2 (M-1) k_B) this is
 * exactly Eq. 33: (M-1)(zeta^2-1) T/T* = (zeta^2-1) K/kT*.  Only v - u is
 * scaled, so the cell momentum is unchanged.
 *
 * No-slip walls: cells cut by a wall get virtual particles up to the mean
 * density (Lamura et al. 2001): their summed momentum is drawn from the
 * Maxwell-Boltzmann distribution of n_ghost particles moving with the wall.
 * Any no-slip wall counts (z walls; x/y walls of a capillary, at rest).  A
 * cell cut by a z wall and an x/y wall (an edge of a closed box) takes the
 * z wall's velocity: a moving z wall is what drives the flow, and where it
 * meets a wall at rest the velocity is singular anyway (lid-driven cavity).
 * The momentum they give the real particles of the cell is the wall's share
 * of the stress there (summed per block when p->wall_dp is set): counted to
 * the z wall whose velocity the virtual particles carry for a cell a z wall
 * cuts (an edge cell too), to the x/y walls' slot for a cell cut by x/y
 * walls only.
 *
 * Random numbers: Philox keyed (seed, purpose), counter (step, cell): the
 * result does not depend on which thread handles a cell. */
#include <math.h>

#include "peloid/rng.h"
#include "peloid/srd_kernels.h"
#include "peloid/srd_rules.h"

/* q, opaque to the vectoriser: the index loops below stay scalar (the
 * AVX-512 gathers and scatters GCC would emit for 10 elements are slower
 * than scalar loads and stores on the development machine's Zen 4). */
static inline size_t scalar_index(size_t q)
{
    __asm__("" : "+r"(q));
    return q;
}

/* Heyes's factor of a cell from its draw (seed, PL_RNG_THERMOSTAT, step,
 * cell, 0), lane `lane` of u. */
static double heyes_zeta(const pl_collide_params_t *p, size_t M, double K, double u[4][PL_RNG_LANES], size_t lane)
{
    return pl_heyes_zeta(p->heyes_eps, p->kT_target, (double)M, K, u[0][lane], u[1][lane], u[2][lane]);
}

/* One block of PL_CELL_BLOCK cells.  HEYES is a constant at each call
 * site, so each entry point below compiles its own loop (the thermostat
 * costs nothing in the steps that do not apply it). */
/* IDX (a constant too): slot i of the cells is particle p->order[i] (the
 * arrays keep the order of the last full sort, srd.sort_interval) rather
 * than particle i. */
static inline __attribute__((always_inline)) void collide_block(pl_real *restrict vx, pl_real *restrict vy,
                                                                pl_real *restrict vz, const pl_grid_t *g,
                                                                const uint32_t *cell_start,
                                                                const pl_collide_params_t *p, double *block_sum,
                                                                size_t b, const int HEYES, const int IDX)
{
    const uint32_t *restrict ord = p->order;
    const size_t n = IDX ? cell_start[g->ncells] : 0;
    enum { PF = 64 }; /* IDX: prefetch distance in slots */
    /* IDX: slot i's particle, in scalar loops (not the AVX-512 gathers and
     * scatters GCC would emit for ~10 elements; nor a local copy of the
     * cell, whose vector loads stall on store forwarding) */
#define AT(i) (IDX ? scalar_index(ord[i]) : (i))
    static const double at_rest[3] = {0.0, 0.0, 0.0};
    const size_t ncells = g->ncells;
    double sum2 = 0.0, dof = 0.0, wdp[PL_WALL_ACC_N] = {0.0};
    const int GUARD = p->guard_bad != NULL; /* a run-time test: a third constant
                                              * doubled the loops and GCC stopped inlining
                                              * the rotation (collide 4.7 -> 6.3 ns) */
    const double vmax2 = p->guard_vmax2;
    int bad = 0; /* GUARD: some particle of the block may fail the speed test of srd_guard.c */
    size_t c_hi = (b + 1) * PL_CELL_BLOCK < ncells ? (b + 1) * PL_CELL_BLOCK : ncells;
    /* The rotations of PL_RNG_LANES cells are drawn first, in vector lanes
     * (pl_srd_rotations: the Philox rounds of 32 cells side by side, not
     * one dependency chain after another); they depend on (seed, step,
     * cell) only and have the bits of pl_srd_rotation, so the result is
     * unchanged; so are the Heyes thermostat's draws.  (Lanes past the
     * block's last cell are drawn and unused.) */
    double Rb[9][PL_RNG_LANES], Hu[4][PL_RNG_LANES]; /* Hu: the thermostat's draws (HEYES) */
    size_t c_base = b * PL_CELL_BLOCK, c_rot = c_base;
    for (size_t c = b * PL_CELL_BLOCK; c < c_hi; ++c) {
        if (c == c_rot) {
            pl_srd_rotations(p->rule, p->cos_a, p->sin_a, p->seed, PL_RNG_COLLIDE, p->step, c, Rb);
            if (HEYES) pl_rng_uniform4_lanes(p->seed, PL_RNG_THERMOSTAT, p->step, c, 0, Hu);
            c_base = c;
            c_rot = c + PL_RNG_LANES;
        }
        const size_t lane = c - c_base;
        const size_t s = cell_start[c], e = cell_start[c + 1], M = e - s;
        int wall = 0, ng = 0;
        if (p->wall_ghosts && M >= 1) ng = pl_srd_ghost_count(g, p->ghost_density, c, M, &wall);
        if (M + (size_t)ng < 2) {
            if (GUARD)
                for (size_t i = s; i < e; ++i) {
                    const size_t q = AT(i);
                    const double x = vx[q], y = vy[q], z = vz[q];
                    bad |= !(x * x + y * y + z * z <= vmax2);
                }
            continue;
        }
        double P[3] = {0.0, 0.0, 0.0}, S = 0.0; /* one pass: momentum and sum v^2 */
        for (size_t i = s; i < e; ++i) {
            if (IDX && i + PF < n) { /* the slots' particles lie in a few runs: their lines ahead */
                const size_t qp = ord[i + PF];
                __builtin_prefetch(vx + qp, 1, 3);
                __builtin_prefetch(vy + qp, 1, 3);
                __builtin_prefetch(vz + qp, 1, 3);
            }
            const size_t q = AT(i);
            P[0] += vx[q];
            P[1] += vy[q];
            P[2] += vz[q];
            S += (double)vx[q] * vx[q] + (double)vy[q] * vy[q] + (double)vz[q] * vz[q];
        }
        double u[3], ur[3];
        for (int d = 0; d < 3; ++d) ur[d] = P[d] / (double)M;
        if (ng > 0) {
            double N[3];
            pl_srd_ghost_noise(p->seed, p->step, c, ng, p->kT_wall, N);
            const double *U = wall >= 0 ? p->wall_u[wall] : at_rest;
            for (int d = 0; d < 3; ++d) u[d] = (P[d] + (double)ng * U[d] + N[d]) / (double)(M + (size_t)ng);
        } else {
            for (int d = 0; d < 3; ++d) u[d] = ur[d];
        }
        /* K2 = sum (v - u)^2 = S - 2 u.P + M u^2, invariant under the
         * rotation (a second pass over the cell saved; the cancellation
         * costs ~1e-16 S, far below the thermal K2 ~ S) */
        const double K2 = S - 2.0 * (u[0] * P[0] + u[1] * P[1] + u[2] * P[2]) +
                          (double)M * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        double zeta = 1.0;
        if (HEYES && ng == 0 && M >= 2) zeta = heyes_zeta(p, M, 0.5 * K2, Hu, lane);
        double R[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) R[i][j] = Rb[3 * i + j][lane] * zeta;
        for (size_t i = s; i < e; ++i) {
            const size_t q = AT(i);
            double a = vx[q] - u[0], bb = vy[q] - u[1], cc = vz[q] - u[2];
            vx[q] = (pl_real)(u[0] + R[0][0] * a + R[0][1] * bb + R[0][2] * cc);
            vy[q] = (pl_real)(u[1] + R[1][0] * a + R[1][1] * bb + R[1][2] * cc);
            vz[q] = (pl_real)(u[2] + R[2][0] * a + R[2][1] * bb + R[2][2] * cc);
        }
        /* GUARD, cells without virtual particles: sum v'^2 = M u^2 +
         * zeta^2 K2 (P = M u), which bounds every particle's v'^2; a
         * particle beyond vmax2 (or a NaN, Inf) makes it exceed 0.99 vmax2
         * (rounding is ~1e-16 of it), so the block is flagged and the guard
         * rescans it particle by particle.  Cells with virtual particles:
         * S1 below, the sum itself. */
        if (GUARD && ng == 0)
            bad |= !((double)M * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) + zeta * zeta * K2 <= 0.99 * vmax2);
        if (ng == 0) {
            if (M < 2) continue;
            sum2 += zeta * zeta * K2;
        } else { /* the real particles' own mean moved: measure again */
            double Q[3] = {0.0, 0.0, 0.0}, S1 = 0.0;
            for (size_t i = s; i < e; ++i) {
                const size_t q = AT(i);
                Q[0] += vx[q]; Q[1] += vy[q]; Q[2] += vz[q];
                S1 += (double)vx[q] * vx[q] + (double)vy[q] * vy[q] + (double)vz[q] * vz[q];
            }
            if (GUARD) bad |= !(S1 <= 0.99 * vmax2);
            const int slot = wall >= 0 ? wall : 2; /* the z wall's push, or the x/y walls' */
            for (int d = 0; d < 3; ++d) wdp[3 * slot + d] += Q[d] - P[d];
            if (M < 2) continue;
            sum2 += S1 - (Q[0] * Q[0] + Q[1] * Q[1] + Q[2] * Q[2]) / (double)M;
        }
        dof += 3.0 * (double)(M - 1);
    }
    if (GUARD) p->guard_bad[b] = (unsigned char)bad;
    block_sum[2 * b] = sum2;
    block_sum[2 * b + 1] = dof;
    if (p->wall_dp)
        for (size_t k = 0; k < PL_WALL_ACC_N; ++k) p->wall_dp[PL_WALL_ACC_N * b + k] = wdp[k];
#undef AT
}

/* Cells are independent; blocks of cells give fixed-order partial sums. */
void pl_srd_collide(pl_fluid_t *f, const pl_grid_t *g, const uint32_t *cell_start,
                    const pl_collide_params_t *p, double *block_sum, int nthreads)
{
    const size_t nblocks = (g->ncells + PL_CELL_BLOCK - 1) / PL_CELL_BLOCK;
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t b = 0; b < nblocks; ++b) {
        if (p->order) collide_block(f->v[0], f->v[1], f->v[2], g, cell_start, p, block_sum, b, 0, 1);
        else collide_block(f->v[0], f->v[1], f->v[2], g, cell_start, p, block_sum, b, 0, 0);
    }
}

void pl_srd_collide_heyes(pl_fluid_t *f, const pl_grid_t *g, const uint32_t *cell_start,
                          const pl_collide_params_t *p, double *block_sum, int nthreads)
{
    const size_t nblocks = (g->ncells + PL_CELL_BLOCK - 1) / PL_CELL_BLOCK;
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t b = 0; b < nblocks; ++b) {
        if (p->order) collide_block(f->v[0], f->v[1], f->v[2], g, cell_start, p, block_sum, b, 1, 1);
        else collide_block(f->v[0], f->v[1], f->v[2], g, cell_start, p, block_sum, b, 1, 0);
    }
}

void pl_srd_rescale(pl_fluid_t *f, const uint32_t *cell_start, size_t ncells, double factor, int nthreads)
{
    pl_real *restrict vx = f->v[0], *restrict vy = f->v[1], *restrict vz = f->v[2];
    /* PL Appendix A: v - v_cm scaled by sqrt(T / T_meas) in cells with N > 1. */
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t c = 0; c < ncells; ++c) {
        const size_t s = cell_start[c], e = cell_start[c + 1];
        if (e - s < 2) continue;
        double P[3] = {0.0, 0.0, 0.0};
        for (size_t i = s; i < e; ++i) {
            P[0] += vx[i]; P[1] += vy[i]; P[2] += vz[i];
        }
        const double inv = 1.0 / (double)(e - s);
        const double u0 = P[0] * inv, u1 = P[1] * inv, u2 = P[2] * inv;
        for (size_t i = s; i < e; ++i) {
            vx[i] = (pl_real)(u0 + factor * (vx[i] - u0));
            vy[i] = (pl_real)(u1 + factor * (vy[i] - u1));
            vz[i] = (pl_real)(u2 + factor * (vz[i] - u2));
        }
    }
}
