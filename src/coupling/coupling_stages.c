/* Couplings I and II (Hecht Secs. IV-V): their state (pl_coupling1_state_t,
 * pl_coupling2_state_t), built here from the scene, and their plan stages,
 * which unpack the sim and call the kernels of kernels/coupling_*.c, then
 * apply what the kernels collected to the colloids.  The state lives with
 * the stages that use it; a run builds only its method's.  Also the stages
 * every method may have: pinned colloids' impulse, flow hold, centre-of-mass
 * drift removal (Hecht Sec. VIII.A). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/collision_rule.h"
#include "peloid/colloid.h"
#include "peloid/colloid_kernels.h"
#include "peloid/coupling.h"
#include "peloid/sim.h"

/* ---- coupling I ---------------------------------------------------------- */
int pl_coupling1_create(const pl_coupling_t *cp, const pl_sim_t *sim, pl_coupling1_state_t **out, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    *out = NULL;
    pl_coupling1_state_t *s = calloc(1, sizeof *s);
    if (!s) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the coupling");
    s->armed_step = -1;
    pl_coupling1_params_t *p = &s->p;
    p->dt = sc->srd.dt;
    p->kT = sc->coupling.wall_temperature > 0.0 ? sc->coupling.wall_temperature : pl_scene_kT(sc);
    p->boundary = sc->coupling.boundary;
    p->placement = sc->coupling.placement;
    p->max_refl = (int)sc->coupling.max_reflections;
    p->seed = cp->seed;
    memcpy(p->wall_u, sim->wall_u, sizeof p->wall_u);
    int rc = pl_coupling_lookup_init(&s->lk, sim->grid.L, cp->nthreads, err);
    s->found = pl_alloc((sim->fluid.n + 1) * sizeof(uint32_t), cp->nthreads);
    s->counts = pl_alloc((size_t)cp->nthreads * 8 * sizeof(uint64_t), cp->nthreads);
    s->cstart = pl_alloc((sim->grid.ncells + 2) * sizeof(uint32_t), cp->nthreads);
    s->axis_buf = malloc((size_t)cp->nthreads * (size_t)(sim->grid.n[0] + sim->grid.n[1] + sim->grid.n[2]) * sizeof(int));
    s->gap_buf = malloc((size_t)cp->nthreads * (size_t)(sim->grid.n[0] + sim->grid.n[1] + sim->grid.n[2]) * sizeof(double));
    s->cell_mask = malloc((sim->grid.ncells + 63) / 64 * sizeof(uint64_t) + 8);
    if (!rc && (!s->found || !s->counts || !s->cstart || !s->axis_buf || !s->gap_buf || !s->cell_mask))
        rc = pl_err_set(err, PL_ERR_NOMEM, "out of memory for the coupling");
    if (rc) {
        pl_coupling1_free(s);
        return rc;
    }
    *out = s;
    return 0;
}

static void scratch_free(pl_coupling1_scratch_t *sc)
{
    free(sc->key);
    free(sc->idx);
    free(sc->owner);
    free(sc->k);
    free(sc->next);
    free(sc->taken);
    free(sc->head);
    free(sc->cbeg);
    free(sc->chain);
    free(sc->cq);
    free(sc->done);
    free(sc->state);
    free(sc->vsave);
    free(sc->pos);
    free(sc->disp);
    const unsigned long long par = sc->parallel, gave = sc->gave_up;
    memset(sc, 0, sizeof *sc);
    sc->parallel = par;
    sc->gave_up = gave;
}

/* Room for n events and nc colloids; 0 when out of memory. */
static int scratch_grow(pl_coupling1_scratch_t *sc, size_t n, size_t nc)
{
    if (n <= sc->cap && 6 * nc <= sc->vcap) return 1;
    scratch_free(sc);
    const size_t cap = n + n / 2 + 256;
    sc->key = malloc(2 * cap * sizeof *sc->key);
    sc->idx = malloc(cap * sizeof *sc->idx);
    sc->owner = malloc(cap * sizeof *sc->owner);
    sc->k = malloc(cap * sizeof *sc->k);
    sc->next = malloc(cap * sizeof *sc->next);
    sc->taken = malloc(cap * sizeof *sc->taken);
    sc->head = malloc((nc + 1) * sizeof *sc->head);
    sc->cbeg = malloc((nc + 1) * sizeof *sc->cbeg);
    sc->chain = malloc(7 * cap * sizeof *sc->chain);
    sc->cq = malloc(cap * sizeof *sc->cq);
    sc->done = malloc(cap * sizeof *sc->done);
    sc->state = malloc(7 * cap * sizeof *sc->state);
    sc->vsave = malloc((6 * nc + 1) * sizeof *sc->vsave);
    sc->pos = malloc((3 * nc + 1) * sizeof *sc->pos);
    sc->disp = malloc((3 * nc + 1) * sizeof *sc->disp);
    if (!sc->key || !sc->idx || !sc->owner || !sc->k || !sc->next || !sc->taken || !sc->head || !sc->cbeg ||
        !sc->chain || !sc->cq || !sc->done || !sc->state || !sc->vsave || !sc->pos || !sc->disp) {
        scratch_free(sc);
        return 0;
    }
    sc->cap = cap;
    sc->vcap = 6 * nc;
    return 1;
}

void pl_coupling1_free(pl_coupling1_state_t *s)
{
    if (!s) return;
    pl_coupling_lookup_free(&s->lk);
    free(s->rad_big);
    pl_free(s->found);
    pl_free(s->counts);
    pl_free(s->cstart);
    scratch_free(&s->events_scratch);
    free(s->clist);
    free(s->axis_buf);
    free(s->gap_buf);
    free(s->cell_mask);
    free(s);
}

/* The colloids near each collision cell under the shift of g (cstart,
 * clist). */
static int cell_candidates(pl_coupling1_state_t *s, const pl_grid_t *g, const pl_coupling_colloids_t *v,
                           int nthreads, pl_err_t *err)
{
    for (;;) {
        size_t need = pl_coupling_cell_candidates(g, v, s->axis_buf, s->gap_buf, s->cstart, s->clist, s->clist_cap,
                                                  nthreads);
        if (need <= s->clist_cap) return 0;
        free(s->clist);
        s->clist_cap = need + need / 2 + 256;
        if (!(s->clist = malloc(s->clist_cap * sizeof *s->clist)))
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the colloids near each cell");
    }
}

/* How far the events may move a colloid's end position, in thermal
 * displacements dt sqrt(kT/M): the step's kicks add up to about
 * sqrt(3 kT/M), moving the end position by about half of that times dt, so
 * 4 leaves ~5 of those typical moves (beyond it the move is cut,
 * kernels/coupling_reflect.c). */
#define PL_C1_MARGIN 4.0

/* The colloids as the detection sees them: radii enlarged by the margin
 * the events may move their end positions (none for pinned colloids). */
static int enlarged_view(pl_coupling1_state_t *s, const pl_colloid_t *c, int pinned, pl_coupling_colloids_t *v,
                         pl_err_t *err)
{
    if (s->rad_cap < c->n) {
        free(s->rad_big);
        s->rad_cap = 0;
        if (!(s->rad_big = malloc((c->n + 1) * sizeof *s->rad_big)))
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the coupling I radii");
        s->rad_cap = c->n;
    }
    for (size_t k = 0; k < c->n; ++k)
        s->rad_big[k] = c->rad[k] + (pinned ? 0.0 : PL_C1_MARGIN * s->p.dt * sqrt(s->p.kT / c->mass[k]));
    *v = pl_coupling_view(c);
    v->rad = s->rad_big;
    return 0;
}

/* Coupling I before stream+bin (after the colloid MD): the colloids near
 * each collision cell under the shift this step's streaming draws (the same
 * draw: a function of seed and step), and the detection armed to run inside
 * the streaming (pl_coupling_find_block on each block just streamed, while
 * it is in L1: no pass of its own over the cells and positions, ~a tenth of
 * the fluid step).  The colloids do not move until the reflections. */
int pl_coupling_stage_reflect_cells(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    pl_coupling_t *cp = ctx;
    pl_coupling1_state_t *s = cp->c1;
    const pl_scene_t *sc = &sim->scene;
    pl_grid_t g = sim->grid;
    pl_grid_draw_shift(&g, (uint64_t)sc->run.seed, (uint64_t)sim->step, sc->srd.grid_shift);
    pl_coupling_colloids_t v;
    int rc = enlarged_view(s, sim->colloids, cp->pinned, &v, err);
    if (!rc) rc = cell_candidates(s, &g, &v, sim->nthreads, err);
    if (rc) return rc;
    pl_coupling_cell_mask(s->cstart, g.ncells, s->cell_mask);
    memset(s->counts, 0, (size_t)sim->nthreads * 8 * sizeof *s->counts);
    s->find_ctx = (pl_coupling_find_ctx_t){.f = &sim->fluid, .g = &sim->grid, .c = v, .cstart = s->cstart,
                                           .clist = s->clist, .mask = s->cell_mask, .nthreads = sim->nthreads,
                                           .found = s->found, .counts = s->counts};
    sim->stream_hook = pl_coupling_find_block;
    sim->stream_hook_ctx = &s->find_ctx;
    sim->stream_hook_step = sim->step;
    s->armed_step = sim->step;
    return 0;
}

/* Coupling I after stream+bin: reflections with their impulses on the
 * colloids, event counters, and the colloids' end positions moved as their
 * velocities changed during the step.  Each event sees the colloid
 * velocity and end position the events before it left, the events of a
 * step in the order the particles met the colloids, ties in a random order
 * that is a function of (seed, step, particle) (kernels/coupling_reflect.c). */
int pl_coupling_stage_reflect(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    pl_coupling_t *cp = ctx;
    pl_coupling1_state_t *s = cp->c1;
    pl_colloid_t *c = sim->colloids;
    s->p.step = (uint64_t)sim->step;
    s->p.move = !cp->pinned;
    const pl_coupling_colloids_t v = pl_coupling_view(c);
    pl_coupling_colloids_t vb;
    int rc = enlarged_view(s, c, cp->pinned, &vb, err);
    if (rc) return rc;
    /* the streaming ran the detection armed for it (it clears the hook),
     * else the colloids near each collision cell of the binning now */
    const int detected = s->armed_step == sim->step && !sim->stream_hook;
    s->armed_step = -1;
    if (!detected) {
        if ((rc = cell_candidates(s, &sim->grid, &vb, cp->nthreads, err))) return rc;
        pl_coupling_find_binned(&sim->fluid, &sim->grid, &vb, s->cstart, s->clist, cp->nthreads, s->found,
                                s->counts);
    }
    pl_coupling1_scratch_t *sc = &s->events_scratch;
    if (!scratch_grow(sc, pl_coupling1_found(s->counts, cp->nthreads), c->n))
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the coupling I events");
    double *const vel[6] = {c->vx, c->vy, c->vz, c->wx, c->wy, c->wz};
    int64_t wall[PL_WALL_ACC_N] = {0};
    s->p.wall_acc = pl_srd_walls_measured(sim->srd) ? wall : NULL;
    pl_coupling1_reflect(&sim->fluid, &sim->grid, &s->p, &v, &vb, vel, s->cstart, s->clist,
                         pl_srd_scratch_counts(sim->srd),
                         cp->nthreads, s->found, s->counts, sc);
    s->p.wall_acc = NULL;
    if (s->p.move) /* the colloids where the events left them */
        pl_colloid_displace(c->n, c->box, c->periodic, c->x, c->y, c->z, c->ix, c->iy, c->iz, sc->disp,
                            sc->disp + c->n, sc->disp + 2 * c->n);
    if (pl_srd_walls_measured(sim->srd)) pl_sim_wall_add(sim, wall);
    s->events += s->counts[0];
    s->truncations += s->counts[1];
    if (cp->pinned) pl_coupling_absorb_pinned(cp, c, sim->scene.srd.dt);
    return 0;
}

void pl_coupling_absorb_pinned(pl_coupling_t *cp, pl_colloid_t *c, double dt)
{
    for (size_t k = 0; k < c->n; ++k) { /* fixed order */
        double *v[6] = {c->vx, c->vy, c->vz, c->wx, c->wy, c->wz};
        for (int j = 0; j < 6; ++j) {
            const double held = j < 3 ? 0.0 : cp->spin[j - 3];
            cp->impulse[j] += (j < 3 ? c->mass[k] : c->inertia[k]) * (v[j][k] - held);
            v[j][k] = held;
        }
    }
    cp->pinned_time += dt;
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* ---- coupling II --------------------------------------------------------- */
int pl_coupling2_create(const pl_coupling_t *cp, const pl_sim_t *sim, pl_coupling2_state_t **out, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const size_t nc = sim->colloids ? sim->colloids->n : 0;
    *out = NULL;
    pl_coupling2_state_t *s = calloc(1, sizeof *s);
    if (!s) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the coupling");
    pl_coupling2_params_t *p = &s->p;
    p->rule = pl_collision_rule(sc->srd.rule)->srd_rotation; /* a rotation rule (fluid_validate) */
    p->cos_a = cos(sc->srd.alpha_deg * PL_PI / 180.0);
    p->sin_a = sin(sc->srd.alpha_deg * PL_PI / 180.0);
    p->seed = cp->seed;
    p->kT_target = sc->thermostat.temperature;
    p->heyes_eps = sc->thermostat.heyes_epsilon;
    /* virtual wall particles: those of the fluid collision */
    p->wall_ghosts = pl_sim_wall_ghosts(sim, &p->ghost_density, &p->kT_wall);
    memcpy(p->wall_u, sim->wall_u, sizeof p->wall_u);
    int bad = p->wall_ghosts && !(p->wall_fix = malloc(PL_WALL_ACC_N * (nc + 1) * sizeof *p->wall_fix));
    s->keys = malloc((nc + 1) * sizeof *s->keys);
    s->occ_cell = malloc((nc + 1) * sizeof *s->occ_cell);
    s->occ_save = malloc((nc + 1) * sizeof *s->occ_save);
    s->occ_col = malloc((nc + 1) * sizeof *s->occ_col);
    s->col_idx = malloc((nc + 1) * sizeof *s->col_idx);
    s->save_cap = 3 * (nc * (size_t)(4.0 * sc->fluid.density + 16.0) + 64);
    s->vsave = pl_alloc(s->save_cap * sizeof(double), cp->nthreads);
    if (bad || !s->keys || !s->occ_cell || !s->occ_save || !s->occ_col || !s->col_idx || !s->vsave) {
        pl_coupling2_free(s);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the coupling");
    }
    *out = s;
    return 0;
}

void pl_coupling2_free(pl_coupling2_state_t *s)
{
    if (!s) return;
    free(s->p.wall_fix);
    free(s->keys);
    free(s->occ_cell);
    free(s->occ_save);
    free(s->occ_col);
    free(s->col_idx);
    pl_free(s->vsave);
    free(s);
}

/* Coupling II before the fluid collision: colloids binned into the shifted
 * collision cells (sorted by cell, then index), the fluid velocities of the
 * occupied cells saved. */
int pl_coupling_stage_save(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    const pl_coupling_t *cp = ctx;
    pl_coupling2_state_t *s = cp->c2;
    const pl_colloid_t *c = sim->colloids;
    const uint32_t *cells = pl_srd_cells(sim->srd); /* after the sort (PL_SLOT_PRE_COLLIDE) */
    for (size_t k = 0; k < c->n; ++k)
        s->keys[k] = (uint64_t)pl_coupling_cell_of(&sim->grid, c->x[k], c->y[k], c->z[k]) << 32 | k;
    qsort(s->keys, c->n, sizeof *s->keys, cmp_u64);
    size_t nocc = 0, nsave = 0;
    for (size_t q = 0; q < c->n; ++q) {
        uint32_t cell = (uint32_t)(s->keys[q] >> 32);
        if (q == 0 || cell != s->occ_cell[nocc - 1]) {
            s->occ_cell[nocc] = cell;
            s->occ_col[nocc] = (int32_t)q;
            s->occ_save[nocc] = nsave;
            nsave += cells[cell + 1] - cells[cell];
            nocc++;
        }
        s->col_idx[q] = (int32_t)(s->keys[q] & 0xffffffffu);
    }
    s->occ_col[nocc] = (int32_t)c->n;
    s->occ_save[nocc] = nsave;
    s->nocc = nocc;
    if (3 * nsave > s->save_cap) {
        pl_free(s->vsave);
        s->save_cap = 3 * (nsave + nsave / 2 + 64);
        if (!(s->vsave = pl_alloc(s->save_cap * sizeof(double), cp->nthreads)))
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the coupling II buffer");
    }
    pl_coupling2_cells_t oc = {s->nocc, s->occ_cell, s->occ_save, s->occ_col, s->col_idx};
    pl_coupling2_save(&sim->fluid, cells, &oc, s->vsave, cp->nthreads);
    return 0;
}

/* Coupling II after the fluid collision: the occupied cells again, with the
 * colloids (Hecht Eq. 15). */
static int collide(pl_sim_t *sim, pl_coupling_t *cp, int heyes)
{
    pl_coupling2_state_t *s = cp->c2;
    pl_colloid_t *c = sim->colloids;
    s->p.step = (uint64_t)sim->step;
    pl_coupling2_cells_t oc = {s->nocc, s->occ_cell, s->occ_save, s->occ_col, s->col_idx};
    const uint32_t *cells = pl_srd_cells(sim->srd); /* after the sort and the collision */
    if (heyes)
        pl_coupling2_collide_heyes(&s->p, &oc, &sim->grid, cells, s->vsave, &sim->fluid, c->mass,
                                   c->vx, c->vy, c->vz, cp->nthreads);
    else
        pl_coupling2_collide(&s->p, &oc, &sim->grid, cells, s->vsave, &sim->fluid, c->mass, c->vx,
                             c->vy, c->vz, cp->nthreads);
    /* the walls' push in the occupied cells, replacing the fluid kernel's
     * count there; summed in cell order (deterministic) */
    for (size_t j = 0; s->p.wall_fix && j < s->nocc; ++j)
        pl_sim_wall_add_momentum(sim, s->p.wall_fix + PL_WALL_ACC_N * j);
    if (cp->pinned) pl_coupling_absorb_pinned(cp, c, sim->scene.srd.dt);
    return 0;
}

int pl_coupling_stage_collide(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    return collide(sim, ctx, 0);
}

int pl_coupling_stage_collide_heyes(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    return collide(sim, ctx, 1);
}

void pl_coupling_total_momentum(const pl_sim_t *sim, double p[3], double *mass)
{
    pl_fluid_obs_t o;
    pl_srd_observe(&sim->fluid, pl_srd_scratch_observe(sim->srd), &o, sim->nthreads);
    double M = (double)sim->fluid.n;
    for (int d = 0; d < 3; ++d) p[d] = o.momentum[d];
    const pl_colloid_t *c = sim->colloids;
    for (size_t k = 0; c && k < c->n; ++k) { /* fixed order */
        p[0] += c->mass[k] * c->vx[k];
        p[1] += c->mass[k] * c->vy[k];
        p[2] += c->mass[k] * c->vz[k];
        M += c->mass[k];
    }
    *mass = M;
}

/* Hecht Sec. VIII.A: the centre-of-mass velocity of fluid + colloids is
 * subtracted from every velocity. */
int pl_coupling_stage_drift(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    const pl_coupling_t *cp = ctx;
    double P[3], M;
    pl_coupling_total_momentum(sim, P, &M);
    const double u[3] = {P[0] / M, P[1] / M, P[2] / M};
    /* v + (-u) rounds as v - u does (IEEE 754 subtraction is the addition
     * of the negated operand): the same bits */
    const double du[3] = {-u[0], -u[1], -u[2]};
    pl_srd_velocity_add(&sim->fluid, du, cp->nthreads);
    pl_colloid_t *c = sim->colloids;
    for (size_t k = 0; c && k < c->n; ++k) {
        c->vx[k] -= u[0];
        c->vy[k] -= u[1];
        c->vz[k] -= u[2];
    }
    return 0;
}

int pl_coupling_stage_flow(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    const pl_coupling_t *cp = ctx;
    pl_fluid_obs_t o;
    pl_fluid_t *f = &sim->fluid;
    pl_srd_observe(f, pl_srd_scratch_observe(sim->srd), &o, cp->nthreads);
    double u[3];
    for (int d = 0; d < 3; ++d)
        u[d] = sim->scene.coupling.flow_velocity[d] - o.momentum[d] / (double)f->n;
    pl_srd_velocity_add(f, u, cp->nthreads);
    return 0;
}
