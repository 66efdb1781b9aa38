/* Potential coupling (PL Sec. III.A, Eq. 17): the fluid particles that can
 * reach the cut-off rc = 2^{1/6} sigma_cf of a colloid within a collision
 * step are selected at its start; streaming moves every particle as usual,
 * then the selected ones are put back and integrated together with the
 * colloids by velocity Verlet at the MD step (PL Eqs. 18-19), feeling PL
 * Eq. 17 (and the fluid body force); the rest of the fluid never sees the
 * MD step.  "Can reach": within rc + the particle's own flight over the
 * step (dt |v|, and the body force's and moving walls' share) + a budget
 * for the colloids' moves (0.1 a0 and twice the fastest colloid's flight),
 * capped at rc + margin (8 thermal speeds x dt + 0.1: the pairs' radius).
 * A particle not selected then cannot reach the cut-off unless a colloid
 * outruns its budget (counted; not seen in ordinary runs).  The selection
 * by each particle's own flight holds a third of the particles the margin
 * alone held, for the same physics: the others streamed instead of moved
 * by the MD step's free kicks and drifts, the same motion to rounding.
 *
 * This file keeps the bookkeeping (its state pl_coupling_potential_state_t:
 * buffers, built only for a scene with this coupling; the order of the
 * steps); the loops over the particles are the kernels of
 * kernels/coupling_select.c (the selection), coupling_wca.c (the forces) and
 * coupling_potential.c (the MD step).
 * Determinism: selection is parallel over the streaming's static chunks (in
 * the streaming itself while the fluid is sorted: the same lists) and
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

int pl_coupling_potential_create(const pl_coupling_t *cp, const pl_sim_t *sim,
                                 pl_coupling_potential_state_t **out, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const pl_colloid_t *c = sim->colloids;
    *out = NULL;
    pl_coupling_potential_state_t *ps = calloc(1, sizeof *ps);
    if (!ps) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the potential coupling");
    ps->wca.sigma = sc->coupling.sigma_cf > 0.0 ? sc->coupling.sigma_cf : sc->colloids.radius;
    ps->wca.eps = sc->coupling.epsilon_cf;
    for (int d = 0; d < 3; ++d) ps->wca.L[d] = sim->grid.L[d];
    for (int d = 0; d < 3; ++d) ps->wca.walls[d] = sim->grid.walls[d];
    double kT = pl_scene_kT_max(sc);
    ps->margin = 8.0 * sqrt(kT) * sc->srd.dt + 0.1;
    ps->rad_big = malloc((c->n + 1) * sizeof(double));
    ps->cf = malloc(3 * (c->n + 1) * sizeof(double));
    ps->found = pl_alloc((sim->fluid.n + 1) * sizeof(uint32_t), cp->nthreads);
    ps->found_cell = pl_alloc((sim->fluid.n + 1) * sizeof(uint32_t), cp->nthreads);
    ps->c0 = malloc(3 * (c->n + 1) * sizeof(double));
    ps->counts = pl_alloc((size_t)cp->nthreads * 8 * sizeof(uint64_t), cp->nthreads);
    /* reserved, not touched: each thread writes only what it selects, from
     * its chunk's start (malloc maps a large block lazily) */
    const int width = sim->fluid.tracked ? 9 : 6;
    ps->stage = calloc((size_t)cp->nthreads, sizeof *ps->stage);
    ps->stage_buf = malloc((sim->fluid.n + 1) * (size_t)width * sizeof(double));
    ps->armed_step = -1;
    for (int t = 0; ps->stage && t < cp->nthreads; ++t) {
        size_t lo, hi;
        pl_chunk(sim->fluid.n, t, cp->nthreads, &lo, &hi);
        ps->stage[t] = (pl_coupling_stage_t){.buf = ps->stage_buf + lo * (size_t)width, .cap = hi - lo, .width = width};
    }
    int rc = pl_coupling_lookup_init(&ps->lk, sim->grid.L, cp->nthreads, err);
    ps->cstart = pl_alloc((sim->grid.ncells + 2) * sizeof(uint32_t), cp->nthreads);
    ps->axis_buf = malloc((size_t)cp->nthreads * (size_t)(sim->grid.n[0] + sim->grid.n[1] + sim->grid.n[2]) * sizeof(int));
    ps->gap_buf = malloc((size_t)cp->nthreads * (size_t)(sim->grid.n[0] + sim->grid.n[1] + sim->grid.n[2]) * sizeof(double));
    if (!rc && (!ps->rad_big || !ps->cf || !ps->found || !ps->found_cell || !ps->c0 || !ps->counts ||
                !ps->stage || !ps->stage_buf ||
                !ps->cstart || !ps->axis_buf || !ps->gap_buf))
        rc = pl_err_set(err, PL_ERR_NOMEM, "out of memory for the potential coupling");
    if (rc) {
        pl_coupling_potential_free(ps);
        return rc;
    }
    *out = ps;
    return 0;
}

void pl_coupling_potential_free(pl_coupling_potential_state_t *ps)
{
    if (!ps) return;
    free(ps->rad_big);
    pl_coupling_lookup_free(&ps->lk);
    pl_free(ps->found);
    pl_free(ps->found_cell);
    pl_free(ps->counts);
    free(ps->stage);
    free(ps->stage_buf);
    pl_free(ps->cstart);
    free(ps->clist);
    free(ps->axis_buf);
    free(ps->gap_buf);
    free(ps->c0);
    free(ps->near_idx);
    free(ps->near_owner);
    free(ps->near_buf);
    free(ps->pair_start);
    free(ps->near_k0);
    free(ps->pair_j);
    free(ps->pair_k);
    free(ps->pair_buf);
    free(ps->cf);
    free(ps->cf_mean);
    free(ps->wca_partial);
    free(ps);
}

static pl_coupling_colloids_t big_view(const pl_coupling_potential_state_t *ps, const pl_colloid_t *c)
{
    pl_coupling_colloids_t v = pl_coupling_view(c);
    v.rad = ps->rad_big;
    return v;
}

/* The colloids at the selection (positions c0) with the selection radii. */
static pl_coupling_colloids_t sel_view(const pl_coupling_potential_state_t *ps, const pl_colloid_t *c)
{
    pl_coupling_colloids_t v = big_view(ps, c);
    v.x = ps->c0;
    v.y = ps->c0 + c->n;
    v.z = ps->c0 + 2 * c->n;
    return v;
}

/* Lookup with the selection radii around the colloids at the selection
 * (built when used: the full scan, the forces' fall-back). */
static int lookup_big(pl_coupling_potential_state_t *ps, const pl_sim_t *sim, pl_err_t *err)
{
    if (ps->lk_valid) return 0;
    pl_coupling_colloids_t v = sel_view(ps, sim->colloids);
    int rc = pl_coupling_lookup_fill(&ps->lk, sim, &v, err);
    ps->lk_valid = !rc;
    return rc;
}

#define NB(ps, a) ((ps)->near_buf + (size_t)(a) * (ps)->near_cap)

/* The selected particles as the kernels see them (rows of near_buf); the
 * displacements only for a fluid that tracks them. */
static pl_coupling_near_t near_view(const pl_coupling_potential_state_t *ps, const pl_fluid_t *f)
{
    pl_coupling_near_t nb = {
        .n = ps->nnear,
        .idx = ps->near_idx,
        .owner = ps->near_owner,
        .r = {NB(ps, 0), NB(ps, 1), NB(ps, 2)},
        .v = {NB(ps, 3), NB(ps, 4), NB(ps, 5)},
        .f = {NB(ps, 6), NB(ps, 7), NB(ps, 8)},
        .disp = {NB(ps, 9), NB(ps, 10), NB(ps, 11)},
        .r0 = {NB(ps, 12), NB(ps, 13), NB(ps, 14)},
        .k0 = ps->near_k0,
        .pstart = ps->pair_start,
        .pj = ps->pair_j,
        .pk = ps->pair_k,
    };
    if (!f->tracked)
        for (int d = 0; d < 3; ++d) nb.disp[d] = NULL;
    return nb;
}

/* Grows *buf to hold n elements of size sz (contents dropped). */
static int grow(void **buf, size_t *cap, size_t n, size_t sz)
{
    if (n <= *cap) return 0;
    free(*buf);
    *cap = n + n / 2 + 256;
    *buf = malloc(*cap * sz);
    return *buf ? 0 : -1;
}

/* How far a fluid particle can get within the collision step
 * (pl_coupling_reach_t): the streaming's kick by the fluid acceleration and
 * the moving walls' bounce-back in the tail; the colloids' budget 0.1 a0
 * (the margin's share for them) plus twice the flight of the fastest
 * colloid at its present speed.  A function of the state: the same
 * selection after a restart. */
static pl_coupling_reach_t particle_reach(const pl_sim_t *sim, const pl_coupling_t *cp, double rc)
{
    const pl_scene_t *sc = &sim->scene;
    const pl_colloid_t *c = sim->colloids;
    const double T = sc->srd.dt;
    double g2 = 0.0, u = 0.0, cv2 = 0.0;
    for (int d = 0; d < 3; ++d) {
        const double a = sc->fluid.body_force[d] + cp->fluid_accel[d]; /* the streaming's */
        g2 += a * a;
    }
    for (int w = 0; w < 2; ++w)
        u = fmax(u, sqrt(sim->wall_u[w][0] * sim->wall_u[w][0] + sim->wall_u[w][1] * sim->wall_u[w][1] +
                         sim->wall_u[w][2] * sim->wall_u[w][2]));
    for (size_t k = 0; k < c->n; ++k) cv2 = fmax(cv2, c->vx[k] * c->vx[k] + c->vy[k] * c->vy[k] + c->vz[k] * c->vz[k]);
    pl_coupling_reach_t r = {
        .rc = rc,
        .budget = 0.1 + 2.0 * T * sqrt(cv2),
        .tail = T * T * sqrt(g2) + 2.0 * T * u,
        .T = T,
    };
    return r;
}

/* The selected particles (the lists the selection left in found,
 * found_cell and counts, tested against the candidates cs, cl) gathered
 * with their pairs into the buffers of the MD step, grown as needed; their
 * state from stage when the selection ran inside the streaming, else from
 * the fluid. */
static int gather_selection(pl_sim_t *sim, const pl_coupling_t *cp, const uint32_t *cs, const int32_t *cl,
                            const pl_coupling_stage_t *stage, pl_err_t *err)
{
    pl_coupling_potential_state_t *ps = cp->pot;
    const pl_colloid_t *c = sim->colloids;
    const pl_coupling_colloids_t v = sel_view(ps, c);
    size_t nn = 0, np = 0;
    for (int t = 0; t < cp->nthreads; ++t) {
        nn += ps->counts[(size_t)t * 8 + 2];
        np += ps->counts[(size_t)t * 8 + 3];
    }
    if (np > UINT32_MAX) return pl_err_set(err, PL_ERR_NOMEM, "%zu near-colloid pairs: more than 2^32", np);
    /* allocated at the first selection even when it finds no particle: the
     * gather and the force kernels write pstart[0] */
    if (nn > ps->near_cap || !ps->pair_start) {
        free(ps->near_idx);
        free(ps->near_owner);
        free(ps->near_buf);
        free(ps->pair_start);
        free(ps->near_k0);
        ps->near_cap = nn + nn / 2 + 256;
        ps->near_idx = malloc(ps->near_cap * sizeof *ps->near_idx);
        ps->near_owner = malloc(ps->near_cap * sizeof *ps->near_owner);
        ps->near_buf = malloc(15 * ps->near_cap * sizeof *ps->near_buf);
        ps->pair_start = malloc((ps->near_cap + 1) * sizeof *ps->pair_start);
        ps->near_k0 = malloc(ps->near_cap * sizeof *ps->near_k0);
        if (!ps->near_idx || !ps->near_owner || !ps->near_buf || !ps->pair_start || !ps->near_k0)
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for %zu near-colloid particles", nn);
    }
    if (np > ps->pair_cap || !ps->pair_buf) {
        size_t cap = ps->pair_cap, need = np ? np : 1;
        free(ps->pair_buf);
        ps->pair_buf = NULL;
        if (grow((void **)&ps->pair_j, &cap, need, sizeof *ps->pair_j) ||
            (cap = ps->pair_cap, grow((void **)&ps->pair_k, &cap, need, sizeof *ps->pair_k)) ||
            !(ps->pair_buf = malloc(4 * cap * sizeof *ps->pair_buf)))
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for %zu near-colloid pairs", np);
        ps->pair_cap = cap;
    }
    pl_coupling_near_t nb = near_view(ps, &sim->fluid);
    nb.n = nn;
    nb.pstart[0] = 0;
    pl_coupling_potential_gather(&sim->fluid, &sim->grid, &v, ps->found, ps->found_cell, ps->counts, cs, cl, stage,
                                 cp->nthreads, &nb);
    const size_t partial = pl_coupling_wca_blocks(nn, c->n) * (3 * c->n + 1);
    if (partial > ps->wca_partial_cap) {
        free(ps->wca_partial);
        ps->wca_partial_cap = partial;
        ps->wca_partial = malloc(partial * sizeof *ps->wca_partial);
        if (!ps->wca_partial)
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the forces of %zu near-colloid particles", nn);
    }
    ps->nnear = nn;
    ps->npair = np;
    ps->near_total += nn;
    return 0;
}

/* While the fluid is as the last sort left it, the selection runs inside
 * the streaming that follows (pl_coupling_select_block, on each block the
 * streaming has read and not yet stored: no pass of its own over the
 * particles near colloids, ~70 % of the selection's time before), the same
 * lists as pl_coupling_find_sorted; the MD step gathers them.  Otherwise
 * (the first step, after a restart) the full scan here. */
int pl_coupling_stage_select(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    const pl_coupling_t *cp = ctx;
    pl_coupling_potential_state_t *ps = cp->pot;
    pl_fluid_t *f = &sim->fluid;
    const pl_colloid_t *c = sim->colloids;
    const double rc = ps->wca.sigma * pow(2.0, 1.0 / 6.0);
    for (size_t k = 0; k < c->n; ++k) {
        ps->rad_big[k] = rc + ps->margin;
        ps->c0[k] = c->x[k];
        ps->c0[c->n + k] = c->y[k];
        ps->c0[2 * c->n + k] = c->z[k];
    }
    ps->lk_valid = 0;
    ps->far2 = 0.0;
    ps->armed_step = -1;
    const pl_coupling_reach_t reach = particle_reach(sim, cp, rc);
    ps->budget = reach.budget;
    pl_coupling_colloids_t v = sel_view(ps, c);
    const uint32_t *cells = pl_srd_cells(sim->srd);
    if (cells) { /* the same list, from the cells near colloids */
        for (;;) {
            size_t need = pl_coupling_cell_candidates(&sim->grid, &v, ps->axis_buf, ps->gap_buf, ps->cstart, ps->clist,
                                                      ps->clist_cap, cp->nthreads);
            if (need <= ps->clist_cap) break;
            if (grow((void **)&ps->clist, &ps->clist_cap, need, sizeof *ps->clist))
                return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the colloids near each cell");
        }
        memset(ps->counts, 0, (size_t)cp->nthreads * 8 * sizeof *ps->counts);
        ps->sel_ctx = (pl_coupling_select_ctx_t){.f = f, .g = &sim->grid, .c = v, .reach = reach,
                                                 .cstart = ps->cstart, .clist = ps->clist,
                                                 .cell_start = cells, .nthreads = cp->nthreads,
                                                 .found = ps->found, .found_cell = ps->found_cell,
                                                 .counts = ps->counts, .stage = ps->stage};
        sim->stream_pre_hook = pl_coupling_select_block;
        sim->stream_pre_hook_ctx = &ps->sel_ctx;
        sim->stream_pre_hook_step = sim->step;
        ps->armed_step = sim->step;
        return 0;
    }
    int rc2 = lookup_big(ps, sim, err);
    if (rc2) return rc2;
    pl_coupling_find(f, &sim->grid, &v, &reach, ps->lk.start, ps->lk.list, cp->nthreads, ps->found, ps->found_cell,
                     ps->counts);
    return gather_selection(sim, cp, (const uint32_t *)ps->lk.start /* offsets >= 0 */, ps->lk.list, NULL, err);
}

/* The MD step's start: the selection the streaming ran, gathered. */
static int gather_armed(pl_sim_t *sim, const pl_coupling_t *cp, pl_err_t *err)
{
    pl_coupling_potential_state_t *ps = cp->pot;
    const int nthreads = cp->nthreads;
    if (ps->armed_step != sim->step || sim->stream_pre_hook)
        return pl_err_set(err, PL_ERR_INTERNAL, "the potential coupling's selection did not run in the streaming of step %lld",
                          sim->step);
    ps->armed_step = -1;
    uint64_t missed = 0;
    for (int t = 0; t < nthreads; ++t) missed += ps->counts[(size_t)t * 8 + 5];
    if (missed)
        return pl_err_set(err, PL_ERR_INTERNAL, "the potential coupling's selection had no room for %llu particles",
                          (unsigned long long)missed);
    return gather_selection(sim, cp, ps->cstart, ps->clist, ps->stage, err);
}

/* Fluid forces on the selected particles and the colloids (the colloids'
 * own forces recomputed first). */
static double min_image(double d, double L, int periodic)
{
    return periodic ? d - L * nearbyint(d / L) : d;
}

/* Whether every pair within the cut-off is a pair of the selection: a
 * particle within rc of a colloid now was within rc + |its move| + |the
 * colloid's move| of it at the selection, so a pair if the largest moves
 * add up to less than the margin (1e-9 a0 against rounding); then the
 * pairs' sums are the lookup's, bit for bit.  Otherwise (never seen: 8
 * thermal speeds) the forces go over the lookup. */
static int pairs_hold(const pl_coupling_potential_state_t *ps, double moved)
{
    return sqrt(ps->far2) + moved < ps->margin - 1e-9;
}

/* The largest move of a colloid since the selection. */
static double colloids_moved(const pl_coupling_potential_state_t *ps, const pl_colloid_t *c)
{
    double moved = 0.0;
    for (size_t k = 0; k < c->n; ++k) {
        const double dx = min_image(c->x[k] - ps->c0[k], c->box[0], c->periodic[0]);
        const double dy = min_image(c->y[k] - ps->c0[c->n + k], c->box[1], c->periodic[1]);
        const double dz = min_image(c->z[k] - ps->c0[2 * c->n + k], c->box[2], c->periodic[2]);
        const double d = sqrt(dx * dx + dy * dy + dz * dz);
        moved = d > moved ? d : moved;
    }
    return moved;
}

/* Fluid forces on the selected particles and the colloids (the colloids'
 * own forces recomputed first), fused with the particles' moves after
 * them (pl_coupling_potential_force_step: `kicks` half kicks, the drift
 * when dt > 0). */
static int forces(pl_coupling_t *cp, const pl_sim_t *sim, pl_colloid_t *c, const double g[3], double h,
                  int kicks, double dt, int64_t wacc[PL_WALL_ACC_N], pl_err_t *err)
{
    pl_coupling_potential_state_t *ps = cp->pot;
    if (!cp->pinned && pl_colloid_forces(c, err)) return err->code;
    memset(ps->cf, 0, 3 * c->n * sizeof(double));
    pl_coupling_colloids_t v = big_view(ps, c);
    const pl_coupling_near_t nb = near_view(ps, &sim->fluid);
    double *cf[3] = {ps->cf, ps->cf + c->n, ps->cf + 2 * c->n};
    ps->force_calls++;
    const double moved = colloids_moved(ps, c);
    const int hold = pairs_hold(ps, moved);
    /* a colloid beyond its budget: an unselected particle may have come
     * within the cut-off unseen (counted; the margin's breach the same) */
    if (!hold || !(moved < ps->budget)) ps->margin_exceeded++;
    if (hold) {
        ps->epot_cf = pl_coupling_potential_force_step(&ps->wca, &nb, &v, &sim->grid, sim->wall_u, h, g, kicks, dt,
                                                       cf[0], cf[1], cf[2], cp->nthreads, ps->wca_partial,
                                                       ps->pair_buf, ps->pair_cap, wacc, &ps->far2);
    } else {
        int rc = lookup_big(ps, sim, err);
        if (rc) return rc;
        ps->epot_cf = pl_coupling_wca_forces(&ps->wca, nb.n, nb.r[0], nb.r[1], nb.r[2], nb.f[0], nb.f[1], nb.f[2],
                                             &v, ps->lk.start, ps->lk.list, cf[0], cf[1], cf[2], cp->nthreads,
                                             ps->wca_partial);
        for (int q = 0; q < kicks; ++q) pl_coupling_potential_kick(&nb, h, g, cp->nthreads);
        ps->far2 = dt > 0.0 ? pl_coupling_potential_drift(&nb, &sim->grid, sim->wall_u, dt, cp->nthreads, wacc) : 0.0;
    }
    if (cp->pinned) return 0;
    for (size_t k = 0; k < c->n; ++k) {
        c->fx[k] += ps->cf[k];
        c->fy[k] += ps->cf[c->n + k];
        c->fz[k] += ps->cf[2 * c->n + k];
    }
    return 0;
}

int pl_coupling_mean_force_on(pl_coupling_t *cp, size_t ncolloids, pl_err_t *err)
{
    pl_coupling_potential_state_t *ps = cp->pot;
    if (!ps) return 0;
    if (!ps->cf_mean && !(ps->cf_mean = calloc(3 * (ncolloids + 1), sizeof(double))))
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the mean fluid force");
    return 0;
}

const double *pl_coupling_mean_force(const pl_coupling_t *cp)
{
    return cp && cp->pot ? cp->pot->cf_mean : NULL;
}

/* The mean fluid force over the step: trapezoid over the MD steps, h the
 * half MD step (as the pinned impulse). */
static void mean_force_add(pl_coupling_potential_state_t *ps, size_t n, double h)
{
    if (!ps->cf_mean) return;
    for (size_t k = 0; k < 3 * n; ++k) ps->cf_mean[k] += h * ps->cf[k];
}

int pl_coupling_stage_potential_md(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    pl_coupling_t *cp = ctx;
    pl_coupling_potential_state_t *ps = cp->pot;
    pl_colloid_t *c = sim->colloids;
    pl_fluid_t *f = &sim->fluid;
    const pl_scene_t *sc = &sim->scene;
    if (ps->armed_step >= 0 && gather_armed(sim, cp, err)) return err->code;
    double g[3];
    for (int d = 0; d < 3; ++d) g[d] = sc->fluid.body_force[d] + cp->fluid_accel[d];
    /* undo the free streaming of the selected particles, and the wall
     * impulses it counted for them (recomputed bitwise, in fixed point):
     * their displacements and wall impulses, so nothing to undo for an
     * untracked fluid without walls (the scatter overwrites the rest) */
    int64_t wacc[PL_WALL_ACC_N] = {0}, sacc[PL_WALL_ACC_N] = {0};
    pl_stream_params_t sp;
    pl_sim_stream_params(sim, &sp);
    const pl_coupling_near_t nb = near_view(ps, &sim->fluid);
    const int walls = pl_srd_walls_measured(sim->srd);
    if (f->tracked || walls) pl_coupling_potential_unstream(&nb, f, &sim->grid, walls ? &sp : NULL, cp->nthreads, sacc);
    const double dtm = c->dt, h = 0.5 * dtm;
    /* PL Eqs. 18-19, velocity Verlet; the particles' kick - drift - forces -
     * kick of each MD step regrouped as forces - kick (- kick - drift of the
     * next MD step) in one pass: each particle's operations and each
     * colloid's in the same order as in separate passes */
    const int S = c->substeps;
    if (forces(cp, sim, c, g, h, S > 0, S > 0 ? dtm : 0.0, wacc, err)) return err->code;
    if (ps->cf_mean) memset(ps->cf_mean, 0, 3 * c->n * sizeof(double));
    for (int s = 0; s < S; ++s) {
        if (!cp->pinned) {
            pl_colloid_kick(c->n, h, c->mass, c->inertia, c->fx, c->fy, c->fz, c->tx, c->ty, c->tz,
                            c->vx, c->vy, c->vz, c->wx, c->wy, c->wz, c->nthreads);
            pl_colloid_drift(c->n, dtm, c->box, c->periodic, c->x, c->y, c->z, c->ix, c->iy, c->iz,
                             c->vx, c->vy, c->vz, c->wx, c->wy, c->wz, c->q0, c->q1, c->q2, c->q3, c->nthreads);
        }
        if (cp->pinned) /* impulse of the fluid force over this MD step (trapezoid) */
            for (size_t k = 0; k < c->n; ++k)
                for (int d = 0; d < 3; ++d) cp->impulse[d] += h * ps->cf[(size_t)d * c->n + k];
        mean_force_add(ps, c->n, h);
        const int more = s + 1 < S;
        /* the MD step is done once these forces are in: counted first, so
         * they are those of its end (keys the lubrication noise,
         * pl_colloid_forces; the start of the next collision step recomputes
         * them with the same numbers) */
        if (!cp->pinned) c->md_step++;
        if (forces(cp, sim, c, g, h, more ? 2 : 1, more ? dtm : 0.0, wacc, err)) return err->code;
        mean_force_add(ps, c->n, h);
        if (cp->pinned)
            for (size_t k = 0; k < c->n; ++k)
                for (int d = 0; d < 3; ++d) cp->impulse[d] += h * ps->cf[(size_t)d * c->n + k];
        if (!cp->pinned) {
            pl_colloid_kick(c->n, h, c->mass, c->inertia, c->fx, c->fy, c->fz, c->tx, c->ty, c->tz,
                            c->vx, c->vy, c->vz, c->wx, c->wy, c->wz, c->nthreads);
            int rc = pl_colloid_guard(c, 0, err);
            if (rc) return rc;
        }
    }
    if (cp->pinned) cp->pinned_time += sc->srd.dt;
    if (ps->cf_mean)
        for (size_t k = 0; k < 3 * c->n; ++k) ps->cf_mean[k] /= (double)c->substeps * dtm;
    if (walls) {
        for (int k = 0; k < PL_WALL_ACC_N; ++k) wacc[k] -= sacc[k];
        pl_sim_wall_add(sim, wacc);
    }
    /* the selected particles back, wrapped, into their new cells */
    pl_coupling_potential_scatter(&nb, f, &sim->grid, pl_srd_scratch_counts(sim->srd), cp->nthreads);
    return 0;
}
