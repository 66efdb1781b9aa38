/* Potential coupling (PL Sec. III.A, Eq. 17): the fluid particles within the
 * cut-off 2^{1/6} sigma_cf + margin of a colloid at the start of a collision
 * step are selected; streaming moves every particle as usual, then the
 * selected ones are put back and integrated together with the colloids by
 * velocity Verlet at the MD step (PL Eqs. 18-19), feeling PL Eq. 17 (and the
 * fluid body force); the rest of the fluid never sees the MD step.  The
 * margin (8 thermal speeds x dt + 0.1) makes it very unlikely that an
 * unselected particle reaches the cut-off within the step.
 *
 * This file keeps the bookkeeping (buffers, the order of the steps); the
 * loops over the particles are the kernels of kernels/coupling_potential.c.
 * Determinism: selection is parallel over the streaming's static chunks and
 * gathered in particle order; the forces are summed over fixed blocks, the
 * kicks and drifts are per particle and the wall impulses are integers: no
 * result depends on the thread count.
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
    cp->found = pl_alloc((sim->fluid.n + 1) * sizeof(uint32_t), cp->nthreads);
    cp->counts = pl_alloc((size_t)cp->nthreads * 8 * sizeof(uint64_t), cp->nthreads);
    size_t L3 = (size_t)sim->grid.L[0] * (size_t)sim->grid.L[1] * (size_t)sim->grid.L[2];
    cp->lk_start = pl_alloc((L3 + 1) * sizeof(int32_t), cp->nthreads);
    cp->marks = pl_alloc(sim->grid.ncells, cp->nthreads);
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

/* The selected particles as the kernels see them (rows of near_buf). */
static pl_coupling_near_t near_view(const pl_coupling_t *cp)
{
    return (pl_coupling_near_t){
        .n = cp->nnear,
        .idx = cp->near_idx,
        .owner = cp->near_owner,
        .r = {NB(cp, 0), NB(cp, 1), NB(cp, 2)},
        .v = {NB(cp, 3), NB(cp, 4), NB(cp, 5)},
        .f = {NB(cp, 6), NB(cp, 7), NB(cp, 8)},
        .disp = {NB(cp, 9), NB(cp, 10), NB(cp, 11)},
    };
}

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
    pl_coupling_near_t nb = near_view(cp);
    nb.n = nn;
    pl_coupling_potential_gather(f, cp->found, cp->counts, cp->nthreads, &nb);
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

int pl_coupling_mean_force_on(pl_coupling_t *cp, size_t ncolloids, pl_err_t *err)
{
    if (!cp->cf_mean && !(cp->cf_mean = calloc(3 * (ncolloids + 1), sizeof(double))))
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the mean fluid force");
    return 0;
}

/* The mean fluid force over the step: trapezoid over the MD steps, h the
 * half MD step (as the pinned impulse). */
static void mean_force_add(pl_coupling_t *cp, size_t n, double h)
{
    if (!cp->cf_mean) return;
    for (size_t k = 0; k < 3 * n; ++k) cp->cf_mean[k] += h * cp->cf[k];
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
    const pl_coupling_near_t nb = near_view(cp);
    pl_coupling_potential_unstream(&nb, f, &sim->grid, sim->wall_acc ? &sp : NULL, cp->nthreads, sacc);
    const double dtm = c->dt, h = 0.5 * dtm;
    if (forces(cp, c, err)) return err->code;
    if (cp->cf_mean) memset(cp->cf_mean, 0, 3 * c->n * sizeof(double));
    for (int s = 0; s < c->substeps; ++s) { /* PL Eqs. 18-19 */
        if (!cp->pinned) {
            pl_colloid_kick(c->n, h, c->mass, c->inertia, c->fx, c->fy, c->fz, c->tx, c->ty, c->tz,
                            c->vx, c->vy, c->vz, c->wx, c->wy, c->wz, c->nthreads);
            pl_colloid_drift(c->n, dtm, c->box, c->periodic, c->x, c->y, c->z, c->ix, c->iy, c->iz,
                             c->vx, c->vy, c->vz, c->wx, c->wy, c->wz, c->q0, c->q1, c->q2, c->q3, c->nthreads);
        }
        pl_coupling_potential_kick(&nb, h, g, cp->nthreads);
        pl_coupling_potential_drift(&nb, &sim->grid, sim->wall_u, dtm, cp->nthreads, wacc);
        if (cp->pinned) /* impulse of the fluid force over this MD step (trapezoid) */
            for (size_t k = 0; k < c->n; ++k)
                for (int d = 0; d < 3; ++d) cp->impulse[d] += h * cp->cf[(size_t)d * c->n + k];
        mean_force_add(cp, c->n, h);
        if (forces(cp, c, err)) return err->code;
        mean_force_add(cp, c->n, h);
        if (cp->pinned)
            for (size_t k = 0; k < c->n; ++k)
                for (int d = 0; d < 3; ++d) cp->impulse[d] += h * cp->cf[(size_t)d * c->n + k];
        pl_coupling_potential_kick(&nb, h, g, cp->nthreads);
        if (!cp->pinned) {
            pl_colloid_kick(c->n, h, c->mass, c->inertia, c->fx, c->fy, c->fz, c->tx, c->ty, c->tz,
                            c->vx, c->vy, c->vz, c->wx, c->wy, c->wz, c->nthreads);
            c->md_step++;
            int rc = pl_colloid_guard(c, 0, err);
            if (rc) return rc;
        }
    }
    if (cp->pinned) cp->pinned_time += sc->srd.dt;
    if (cp->cf_mean)
        for (size_t k = 0; k < 3 * c->n; ++k) cp->cf_mean[k] /= (double)c->substeps * dtm;
    if (sim->wall_acc) {
        for (int k = 0; k < PL_WALL_ACC_N; ++k) wacc[k] -= sacc[k];
        pl_sim_wall_add(sim, wacc);
    }
    /* the selected particles back, wrapped, into their new cells */
    pl_coupling_potential_scatter(&nb, f, &sim->grid, sim->hist, cp->nthreads);
    return 0;
}
