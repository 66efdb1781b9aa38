/* Coupling II (Hecht Sec. V): colloids join the SRD collision of the cell
 * they are in.  For a cell with fluid particles (mass m_f = 1) and colloids
 * (mass M_k) the mean velocity is mass weighted, Hecht Eq. 15:
 *   u = sum_k m_k v_k / sum_k m_k,
 * and every velocity is rotated about it, v_k -> u + zeta R (v_k - u)
 * (Hecht Eq. 12), which conserves the cell's momentum for any matrix.
 * zeta != 1 only with the Heyes thermostat, here mass weighted (Hecht Sec.
 * VIII.B: "the mass is used as weight factor"): K = sum m_k (v_k - u)^2 / 2,
 * 3 (N - 1) degrees of freedom for N bodies, acceptance Hecht Eq. 33.
 *
 * The fluid kernel (kernels/srd_collide.c) has already collided these cells
 * without the colloids; their fluid velocities are recomputed here from the
 * copy saved before it ran, so the fluid kernel stays untouched.  An
 * occupied cell cut by a no-slip wall (Hecht's R = 0.62 a0 colloids resting
 * on a wall) gets the virtual particles the fluid kernel gave it: the same
 * number (from the fluid count) and the same draw, now in the mass-weighted
 * mean, without the Heyes factor, as there; the walls' push the fluid kernel
 * counted for the cell is replaced by the change of the cell's fluid +
 * colloid momentum (p->wall_fix, summed in cell order by the caller).
 *
 * Random numbers: Philox (seed, PL_RNG_COUPLE2_ROTATE / PL_RNG_COUPLE2_THERMOSTAT), counter (step,
 * cell).  Cells are independent and each owns its fluid and colloids: the
 * result does not depend on the thread count. */
#include <math.h>

#include "peloid/coupling_kernels.h"
#include "peloid/rng.h"
#include "peloid/srd_kernels.h"
#include "peloid/srd_rules.h"

/* Same two rules as the fluid collision (include/peloid/srd_rules.h). */
static void rotation(const pl_coupling2_params_t *p, uint64_t cell, double R[3][3])
{
    pl_srd_rotation(p->rule, p->cos_a, p->sin_a, p->seed, PL_RNG_COUPLE2_ROTATE, p->step, cell, R);
}

/* Mass-weighted Heyes factor (Hecht Eq. 33 with K = sum m (v-u)^2 / 2). */
static double heyes_zeta(const pl_coupling2_params_t *p, uint64_t cell, size_t nbody, double K)
{
    pl_rand4_t r = pl_rng_uniform4(p->seed, PL_RNG_COUPLE2_THERMOSTAT, p->step, cell, 0);
    return pl_heyes_zeta(p->heyes_eps, p->kT_target, (double)nbody, K, r.u[0], r.u[1], r.u[2]);
}

void pl_coupling2_save(const pl_fluid_t *f, const uint32_t *cell_start,
                       const pl_coupling2_cells_t *oc, double *vsave, int nthreads)
{
    const pl_real *restrict vx = f->v[0], *restrict vy = f->v[1], *restrict vz = f->v[2];
    /* Occupied cells are independent: static split over cells (serial when
     * they are few: a parallel region would cost more than the work). */
#pragma omp parallel for schedule(static) num_threads(nthreads) if (oc->nocc >= 256)
    for (size_t j = 0; j < oc->nocc; ++j) {
        const uint32_t c = oc->occ_cell[j];
        double *w = vsave + 3 * oc->occ_save[j];
        for (uint32_t i = cell_start[c]; i < cell_start[c + 1]; ++i, w += 3) {
            w[0] = vx[i];
            w[1] = vy[i];
            w[2] = vz[i];
        }
    }
}

/* One occupied cell j.  HEYES is a constant at each call site: each entry
 * point compiles its own loop. */
static inline __attribute__((always_inline)) void collide_cell(const pl_coupling2_params_t *p,
                                                               const pl_coupling2_cells_t *oc, const pl_grid_t *g,
                                                               const uint32_t *cell_start, const double *vsave,
                                                               pl_fluid_t *f, const double *cmass, double *cvx,
                                                               double *cvy, double *cvz, size_t j, const int HEYES)
{
    pl_real *restrict vx = f->v[0], *restrict vy = f->v[1], *restrict vz = f->v[2];
    static const double at_rest[3] = {0.0, 0.0, 0.0};
    const uint32_t c = oc->occ_cell[j];
    const uint32_t s = cell_start[c], e = cell_start[c + 1];
    const double *w = vsave + 3 * oc->occ_save[j];
    const int32_t k0 = oc->occ_col[j], k1 = oc->occ_col[j + 1];
    const size_t nbody = (size_t)(e - s) + (size_t)(k1 - k0);
    if (p->wall_fix)
        for (int q = 0; q < PL_WALL_ACC_N; ++q) p->wall_fix[PL_WALL_ACC_N * j + (size_t)q] = 0.0;
    int wall = -1, ng = 0; /* virtual particles, as in kernels/srd_collide.c */
    if (p->wall_ghosts && e - s >= 1) ng = pl_srd_ghost_count(g, p->ghost_density, c, e - s, &wall);
    if (nbody < 2) return;
    double P[3] = {0.0, 0.0, 0.0}, mtot = (double)(e - s);
    for (size_t i = 0; i < 3 * (size_t)(e - s); i += 3) {
        P[0] += w[i];
        P[1] += w[i + 1];
        P[2] += w[i + 2];
    }
    const double Pf[3] = {P[0], P[1], P[2]}; /* the fluid's, before */
    for (int32_t q = k0; q < k1; ++q) {
        int32_t k = oc->col_idx[q];
        P[0] += cmass[k] * cvx[k];
        P[1] += cmass[k] * cvy[k];
        P[2] += cmass[k] * cvz[k];
        mtot += cmass[k];
    }
    double u[3] = {P[0] / mtot, P[1] / mtot, P[2] / mtot}; /* Hecht Eq. 15 */
    if (ng > 0) {
        double N[3];
        pl_srd_ghost_noise(p->seed, p->step, c, ng, p->kT_wall, N);
        const double *U = wall >= 0 ? p->wall_u[wall] : at_rest;
        for (int d = 0; d < 3; ++d) u[d] = (P[d] + (double)ng * U[d] + N[d]) / (mtot + (double)ng);
    }
    double R[3][3];
    rotation(p, c, R);
    if (HEYES && ng == 0) {
        double K2 = 0.0;
        for (size_t i = 0; i < 3 * (size_t)(e - s); i += 3) {
            double a = w[i] - u[0], b = w[i + 1] - u[1], cc = w[i + 2] - u[2];
            K2 += a * a + b * b + cc * cc;
        }
        for (int32_t q = k0; q < k1; ++q) {
            int32_t k = oc->col_idx[q];
            double a = cvx[k] - u[0], b = cvy[k] - u[1], cc = cvz[k] - u[2];
            K2 += cmass[k] * (a * a + b * b + cc * cc);
        }
        double zeta = heyes_zeta(p, c, nbody, 0.5 * K2);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) R[a][b] *= zeta;
    }
    /* the fluid kernel's count for this cell: its result minus Pf */
    const int fix = p->wall_fix && ng > 0, slot = wall >= 0 ? wall : 2;
    double Qfk[3] = {0.0, 0.0, 0.0};
    for (uint32_t i = s; fix && i < e; ++i) {
        Qfk[0] += vx[i];
        Qfk[1] += vy[i];
        Qfk[2] += vz[i];
    }
    for (uint32_t i = 0; i < e - s; ++i) { /* Hecht Eq. 12 */
        double a = w[3 * i] - u[0], b = w[3 * i + 1] - u[1], cc = w[3 * i + 2] - u[2];
        vx[s + i] = (pl_real)(u[0] + R[0][0] * a + R[0][1] * b + R[0][2] * cc);
        vy[s + i] = (pl_real)(u[1] + R[1][0] * a + R[1][1] * b + R[1][2] * cc);
        vz[s + i] = (pl_real)(u[2] + R[2][0] * a + R[2][1] * b + R[2][2] * cc);
    }
    double Pn[3] = {0.0, 0.0, 0.0}; /* fluid + colloids, after */
    for (uint32_t i = s; fix && i < e; ++i) {
        Pn[0] += vx[i];
        Pn[1] += vy[i];
        Pn[2] += vz[i];
    }
    for (int32_t q = k0; q < k1; ++q) {
        int32_t k = oc->col_idx[q];
        double a = cvx[k] - u[0], b = cvy[k] - u[1], cc = cvz[k] - u[2];
        cvx[k] = u[0] + R[0][0] * a + R[0][1] * b + R[0][2] * cc;
        cvy[k] = u[1] + R[1][0] * a + R[1][1] * b + R[1][2] * cc;
        cvz[k] = u[2] + R[2][0] * a + R[2][1] * b + R[2][2] * cc;
        Pn[0] += cmass[k] * cvx[k];
        Pn[1] += cmass[k] * cvy[k];
        Pn[2] += cmass[k] * cvz[k];
    }
    /* the wall gave the cell Pn - P; the fluid kernel counted Qfk - Pf */
    if (fix)
        for (int d = 0; d < 3; ++d)
            p->wall_fix[PL_WALL_ACC_N * j + 3 * (size_t)slot + (size_t)d] = (Pn[d] - P[d]) - (Qfk[d] - Pf[d]);
}

void pl_coupling2_collide(const pl_coupling2_params_t *p, const pl_coupling2_cells_t *oc, const pl_grid_t *g,
                          const uint32_t *cell_start, const double *vsave, pl_fluid_t *f,
                          const double *cmass, double *cvx, double *cvy, double *cvz, int nthreads)
{
#pragma omp parallel for schedule(static) num_threads(nthreads) if (oc->nocc >= 256)
    for (size_t j = 0; j < oc->nocc; ++j)
        collide_cell(p, oc, g, cell_start, vsave, f, cmass, cvx, cvy, cvz, j, 0);
}

void pl_coupling2_collide_heyes(const pl_coupling2_params_t *p, const pl_coupling2_cells_t *oc, const pl_grid_t *g,
                                const uint32_t *cell_start, const double *vsave, pl_fluid_t *f,
                                const double *cmass, double *cvx, double *cvy, double *cvz, int nthreads)
{
#pragma omp parallel for schedule(static) num_threads(nthreads) if (oc->nocc >= 256)
    for (size_t j = 0; j < oc->nocc; ++j)
        collide_cell(p, oc, g, cell_start, vsave, f, cmass, cvx, cvy, cvz, j, 1);
}
