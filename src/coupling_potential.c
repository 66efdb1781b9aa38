/* Potential coupling (PL Sec. III.A, Eq. 17): the fluid particles within the
 * cut-off 2^{1/6} sigma_cf + margin of a colloid at the start of a collision
 * step are selected; streaming moves every particle as usual, then the
 * selected ones are put back and integrated together with the colloids by
 * velocity Verlet at the MD step (PL Eqs. 18-19), feeling PL Eq. 17 (and the
 * fluid body force); the rest of the fluid never sees the MD step.  The
 * margin (8 thermal speeds x dt + 0.1) makes it very unlikely that an
 * unselected particle reaches the cut-off within the step.
 *
 * Determinism: selection is parallel over the streaming's static chunks and
 * gathered in particle order; the forces are summed over fixed blocks
 * (kernels/coupling_potential.c), the kicks and drifts are per particle and
 * the wall impulses are integers: no result depends on the thread count.
 * Momentum: equal and opposite forces in the same Verlet kicks. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/sim.h"

int pl_coupling_potential_setup(pl_coupling_t *cp, pl_sim_t *sim, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const pl_colloid_t *c = sim->colloids;
    cp->wca.sigma = sc->coupling.sigma_cf > 0.0 ? sc->coupling.sigma_cf : sc->colloids.radius;
    cp->wca.eps = sc->coupling.epsilon_cf;
    for (int d = 0; d < 3; ++d) cp->wca.L[d] = sim->grid.L[d];
    for (int d = 0; d < 3; ++d) cp->wca.walls[d] = sim->grid.walls[d];
    double kT = pl_scene_kT_max(sc);
    cp->margin = 8.0 * sqrt(kT) * sc->srd.dt + 0.1;
    cp->rad_big = malloc((c->n + 1) * sizeof(double));
    cp->cf = malloc(3 * (c->n + 1) * sizeof(double));
    cp->found = pl_alloc((sim->fluid.n + 1) * sizeof(uint32_t));
    cp->counts = pl_alloc((size_t)cp->nthreads * 8 * sizeof(uint64_t));
    size_t L3 = (size_t)sim->grid.L[0] * (size_t)sim->grid.L[1] * (size_t)sim->grid.L[2];
    cp->lk_start = pl_alloc((L3 + 1) * sizeof(int32_t));
    cp->marks = pl_alloc(sim->grid.ncells);
    cp->axis_buf = malloc((size_t)(sim->grid.n[0] + sim->grid.n[1] + sim->grid.n[2]) * sizeof(int));
    if (!cp->rad_big || !cp->cf || !cp->found || !cp->counts || !cp->lk_start || !cp->marks || !cp->axis_buf)
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the potential coupling");
    return 0;
}

static pl_coupling_colloids_t big_view(const pl_coupling_t *cp, const pl_colloid_t *c)
{
    pl_coupling_colloids_t v = pl_coupling_view(c);
    v.rad = cp->rad_big;
    return v;
}

/* Lookup with the selection radii around the current colloid positions. */
static int lookup_big(pl_coupling_t *cp, const pl_sim_t *sim, pl_err_t *err)
{
    const pl_colloid_t *c = sim->colloids;
    double rc = cp->wca.sigma * pow(2.0, 1.0 / 6.0);
    for (size_t k = 0; k < c->n; ++k) cp->rad_big[k] = rc + cp->margin;
    pl_coupling_colloids_t v = big_view(cp, c);
    return pl_coupling_lookup_fill(cp, sim, &v, err);
}

#define NB(cp, a) ((cp)->near_buf + (size_t)(a) * (cp)->near_cap)

int pl_coupling_stage_select(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    pl_coupling_t *cp = sim->coupling;
    pl_fluid_t *f = &sim->fluid;
    int rc = lookup_big(cp, sim, err);
    if (rc) return rc;
    pl_coupling_colloids_t v = big_view(cp, sim->colloids);
    if (sim->fluid_sorted) /* the same list, from the cells near colloids */
        pl_coupling_find_sorted(f, &sim->grid, &v, cp->lk_start, cp->lk_list, sim->cell_start, cp->marks,
                                cp->axis_buf, cp->nthreads, cp->found, cp->counts);
    else
        pl_coupling_find(f, &sim->grid, &v, cp->lk_start, cp->lk_list, cp->nthreads, cp->found, cp->counts);
    size_t nn = 0;
    for (int t = 0; t < cp->nthreads; ++t) nn += cp->counts[(size_t)t * 8 + 2];
    if (nn > cp->near_cap) {
        free(cp->near_idx);
        free(cp->near_owner);
        free(cp->near_buf);
        cp->near_cap = nn + nn / 2 + 256;
        cp->near_idx = malloc(cp->near_cap * sizeof *cp->near_idx);
        cp->near_owner = malloc(cp->near_cap * sizeof *cp->near_owner);
        cp->near_buf = malloc(12 * cp->near_cap * sizeof *cp->near_buf);
        if (!cp->near_idx || !cp->near_owner || !cp->near_buf)
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for %zu near-colloid particles", nn);
    }
    /* gathered in particle order: thread t's chunk goes after those of 0..t-1 */
#pragma omp parallel for schedule(static) num_threads(cp->nthreads)
    for (int t = 0; t < cp->nthreads; ++t) {
        size_t lo, hi, j = 0;
        pl_chunk(f->n, t, cp->nthreads, &lo, &hi);
        for (int u = 0; u < t; ++u) j += cp->counts[(size_t)u * 8 + 2];
        for (size_t q = 0; q < cp->counts[(size_t)t * 8 + 2]; ++q, ++j) {
            size_t i = cp->found[lo + q];
            cp->near_idx[j] = (uint32_t)i;
            cp->near_owner[j] = t;
            for (int d = 0; d < 3; ++d) {
                NB(cp, d)[j] = f->r[d][i];
                NB(cp, 3 + d)[j] = f->v[d][i];
                NB(cp, 9 + d)[j] = f->tracked ? f->disp[d][i] : 0.0;
            }
        }
    }
    const size_t nc = sim->colloids->n, partial = pl_coupling_wca_blocks(nn, nc) * (3 * nc + 1);
    if (partial > cp->wca_partial_cap) {
        free(cp->wca_partial);
        cp->wca_partial_cap = partial;
        cp->wca_partial = malloc(partial * sizeof *cp->wca_partial);
        if (!cp->wca_partial)
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the forces of %zu near-colloid particles", nn);
    }
    cp->nnear = nn;
    cp->near_total += nn;
    return 0;
}

/* Fluid forces on the selected particles and the colloids (the colloids'
 * own forces recomputed first). */
static int forces(pl_coupling_t *cp, pl_colloid_t *c, pl_err_t *err)
{
    if (!cp->pinned && pl_colloid_forces(c, err)) return err->code;
    memset(cp->cf, 0, 3 * c->n * sizeof(double));
    pl_coupling_colloids_t v = big_view(cp, c);
    size_t nn = cp->nnear;
    cp->epot_cf = pl_coupling_wca_forces(&cp->wca, nn, NB(cp, 0), NB(cp, 1), NB(cp, 2), NB(cp, 6),
                                         NB(cp, 7), NB(cp, 8), &v, cp->lk_start, cp->lk_list,
                                         cp->cf, cp->cf + c->n, cp->cf + 2 * c->n, cp->nthreads,
                                         cp->wca_partial);
    if (cp->pinned) return 0;
    for (size_t k = 0; k < c->n; ++k) {
        c->fx[k] += cp->cf[k];
        c->fy[k] += cp->cf[c->n + k];
        c->fz[k] += cp->cf[2 * c->n + k];
    }
    return 0;
}

/* v += h (F + g) for the selected particles (m_f = 1). */
static void kick_fluid(pl_coupling_t *cp, double h, const double g[3])
{
    const size_t nn = cp->nnear;
    double *v[3] = {NB(cp, 3), NB(cp, 4), NB(cp, 5)};
    const double *F[3] = {NB(cp, 6), NB(cp, 7), NB(cp, 8)};
#pragma omp parallel for schedule(static) num_threads(cp->nthreads)
    for (size_t j = 0; j < nn; ++j)
        for (int d = 0; d < 3; ++d) v[d][j] += h * (F[d][j] + g[d]);
}

/* r += v dt, with reflection at the walls of every closed axis (bounce-back
 * for no-slip in the frame of the wall, the z walls moving and the x/y walls
 * at rest; specular for slip; as the streaming does); the displacement is
 * accumulated, the walls' impulses added to acc (PL_WALL_ACC_N slots). */
static void drift_fluid(pl_coupling_t *cp, const pl_sim_t *sim, double dt, int64_t acc[PL_WALL_ACC_N])
{
    static const double at_rest[3] = {0.0, 0.0, 0.0};
    const pl_grid_t *g = &sim->grid;
    const size_t nn = cp->nnear;
    /* integer impulses: the sum is exact in any order */
#pragma omp parallel for schedule(static) num_threads(cp->nthreads) reduction(+ : acc[:PL_WALL_ACC_N])
    for (size_t j = 0; j < nn; ++j) {
        const double r0[3] = {NB(cp, 0)[j], NB(cp, 1)[j], NB(cp, 2)[j]};
        for (int d = 0; d < 3; ++d) {
            NB(cp, d)[j] += NB(cp, 3 + d)[j] * dt;
            NB(cp, 9 + d)[j] += NB(cp, 3 + d)[j] * dt;
        }
        for (int a = 0; a < 3; ++a) {
            double *x = &NB(cp, a)[j];
            const double La = g->L[a];
            if (g->walls[a] == PL_WALLS_NONE || !(*x < 0.0 || *x > La)) continue;
            int top = *x > La;
            double xw = top ? La : 0.0;
            NB(cp, 9 + a)[j] -= *x - r0[a];
            *x = 2.0 * xw - *x;
            NB(cp, 9 + a)[j] += *x - r0[a];
            double dp[3] = {0.0, 0.0, 0.0};
            dp[a] = -2.0 * NB(cp, 3 + a)[j];
            if (g->walls[a] == PL_WALLS_NOSLIP) {
                const double *U = a == 2 ? sim->wall_u[top] : at_rest;
                for (int d = 0; d < 3; ++d) dp[d] = 2.0 * (U[d] - NB(cp, 3 + d)[j]);
            }
            for (int d = 0; d < 3; ++d) NB(cp, 3 + d)[j] += dp[d];
            pl_wall_acc_add(acc, pl_wall_slot(a, top), dp);
        }
    }
}

/* First index of the selected list whose owner is >= t (owners ascend). */
static size_t owner_start(const pl_coupling_t *cp, int t)
{
    size_t lo = 0, hi = cp->nnear;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (cp->near_owner[mid] < t) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

int pl_coupling_stage_potential_md(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    pl_coupling_t *cp = sim->coupling;
    pl_colloid_t *c = sim->colloids;
    pl_fluid_t *f = &sim->fluid;
    const pl_scene_t *sc = &sim->scene;
    double g[3];
    for (int d = 0; d < 3; ++d) g[d] = sc->fluid.body_force[d] + cp->fluid_accel[d];
    /* undo the free streaming of the selected particles, and the wall
     * impulses it counted for them (recomputed bitwise, in fixed point) */
    int64_t wacc[PL_WALL_ACC_N] = {0}, sacc[PL_WALL_ACC_N] = {0};
    pl_stream_params_t sp;
    pl_sim_stream_params(sim, &sp);
    const size_t nnear = cp->nnear;
#pragma omp parallel for schedule(static) num_threads(cp->nthreads) reduction(+ : sacc[:PL_WALL_ACC_N])
    for (size_t j = 0; j < nnear; ++j) {
        size_t i = cp->near_idx[j];
        if (f->tracked)
            for (int d = 0; d < 3; ++d) f->disp[d][i] = NB(cp, 9 + d)[j];
        if (sim->wall_acc) {
            const double r0[3] = {NB(cp, 0)[j], NB(cp, 1)[j], NB(cp, 2)[j]};
            const double v0[3] = {NB(cp, 3)[j], NB(cp, 4)[j], NB(cp, 5)[j]};
            pl_srd_stream_wall_impulse(&sim->grid, &sp, r0, v0, sacc);
        }
    }
    const double dtm = c->dt, h = 0.5 * dtm;
    if (forces(cp, c, err)) return err->code;
    for (int s = 0; s < c->substeps; ++s) { /* PL Eqs. 18-19 */
        if (!cp->pinned) {
            pl_colloid_kick(c->n, h, c->mass, c->inertia, c->fx, c->fy, c->fz, c->tx, c->ty, c->tz,
                            c->vx, c->vy, c->vz, c->wx, c->wy, c->wz);
            pl_colloid_drift(c->n, dtm, c->box, c->periodic, c->x, c->y, c->z, c->ix, c->iy, c->iz,
                             c->vx, c->vy, c->vz, c->wx, c->wy, c->wz, c->q0, c->q1, c->q2, c->q3);
        }
        kick_fluid(cp, h, g);
        drift_fluid(cp, sim, dtm, wacc);
        if (cp->pinned) /* impulse of the fluid force over this MD step (trapezoid) */
            for (size_t k = 0; k < c->n; ++k)
                for (int d = 0; d < 3; ++d) cp->impulse[d] += h * cp->cf[(size_t)d * c->n + k];
        if (forces(cp, c, err)) return err->code;
        if (cp->pinned)
            for (size_t k = 0; k < c->n; ++k)
                for (int d = 0; d < 3; ++d) cp->impulse[d] += h * cp->cf[(size_t)d * c->n + k];
        kick_fluid(cp, h, g);
        if (!cp->pinned) {
            pl_colloid_kick(c->n, h, c->mass, c->inertia, c->fx, c->fy, c->fz, c->tx, c->ty, c->tz,
                            c->vx, c->vy, c->vz, c->wx, c->wy, c->wz);
            c->md_step++;
            int rc = pl_colloid_guard(c, 0, err);
            if (rc) return rc;
        }
    }
    if (cp->pinned) cp->pinned_time += sc->srd.dt;
    if (sim->wall_acc) {
        for (int k = 0; k < PL_WALL_ACC_N; ++k) wacc[k] -= sacc[k];
        pl_sim_wall_add(sim, wacc);
    }
    /* write the selected particles back, wrapped, into their new cells; the
     * particles of one owner (a contiguous run of the list) and its
     * histogram row are handled by one thread */
    const double L[3] = {sim->grid.L[0], sim->grid.L[1], sim->grid.L[2]};
#pragma omp parallel for schedule(static) num_threads(cp->nthreads)
    for (int t = 0; t < cp->nthreads; ++t) {
        size_t j = owner_start(cp, t), end = owner_start(cp, t + 1);
        uint32_t *hrow = sim->hist + (size_t)t * sim->grid.ncells;
        for (; j < end; ++j) {
            size_t i = cp->near_idx[j];
            for (int d = 0; d < 3; ++d) {
                double x = NB(cp, d)[j];
                if (sim->grid.walls[d] == PL_WALLS_NONE) {
                    x -= L[d] * floor(x / L[d]);
                    if (x >= L[d]) x = 0.0;
                }
                f->r[d][i] = (pl_real)x;
                f->v[d][i] = (pl_real)NB(cp, 3 + d)[j];
                if (f->tracked) f->disp[d][i] = NB(cp, 9 + d)[j];
            }
            uint32_t cell = pl_coupling_cell_of(&sim->grid, f->r[0][i], f->r[1][i], f->r[2][i]);
            hrow[f->cell[i]]--;
            hrow[cell]++;
            f->cell[i] = cell;
        }
    }
    return 0;
}
