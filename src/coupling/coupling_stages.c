/* Plan stages of the coupling: they unpack the sim and call the kernels of
 * kernels/coupling_*.c, then apply what the kernels collected to the
 * colloids.  Centre-of-mass drift removal (Hecht Sec. VIII.A). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/sim.h"

/* Coupling I after stream+bin: reflections with their impulses on the
 * colloids, event counters. */
int pl_coupling_stage_reflect(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    pl_coupling_t *cp = sim->coupling;
    pl_colloid_t *c = sim->colloids;
    int rc = pl_coupling_lookup_update(cp, sim, err);
    if (rc) return rc;
    cp->p1.step = (uint64_t)sim->step;
    pl_coupling_colloids_t v = pl_coupling_view(c);
    double *const vel[6] = {c->vx, c->vy, c->vz, c->wx, c->wy, c->wz};
    int64_t wall[PL_WALL_ACC_N] = {0};
    cp->p1.wall_acc = sim->wall_acc ? wall : NULL;
    pl_coupling1_reflect(&sim->fluid, &sim->grid, &cp->p1, &v, vel, cp->lk_start, cp->lk_list,
                         sim->hist, cp->nthreads, cp->found, cp->counts);
    cp->p1.wall_acc = NULL;
    if (sim->wall_acc) pl_sim_wall_add(sim, wall);
    cp->events += cp->counts[0];
    cp->truncations += cp->counts[1];
    if (cp->pinned) pl_coupling_absorb_pinned(cp, c, sim->scene.srd.dt);
    return 0;
}

void pl_coupling_absorb_pinned(pl_coupling_t *cp, pl_colloid_t *c, double dt)
{
    for (size_t k = 0; k < c->n; ++k) { /* fixed order */
        double *v[6] = {c->vx, c->vy, c->vz, c->wx, c->wy, c->wz};
        for (int j = 0; j < 6; ++j) {
            cp->impulse[j] += (j < 3 ? c->mass[k] : c->inertia[k]) * v[j][k];
            v[j][k] = 0.0;
        }
    }
    cp->pinned_time += dt;
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* Coupling II before the fluid collision: colloids binned into the shifted
 * collision cells (sorted by cell, then index), the fluid velocities of the
 * occupied cells saved. */
int pl_coupling_stage_save(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    pl_coupling_t *cp = sim->coupling;
    const pl_colloid_t *c = sim->colloids;
    for (size_t k = 0; k < c->n; ++k)
        cp->keys[k] = (uint64_t)pl_coupling_cell_of(&sim->grid, c->x[k], c->y[k], c->z[k]) << 32 | k;
    qsort(cp->keys, c->n, sizeof *cp->keys, cmp_u64);
    size_t nocc = 0, nsave = 0;
    for (size_t q = 0; q < c->n; ++q) {
        uint32_t cell = (uint32_t)(cp->keys[q] >> 32);
        if (q == 0 || cell != cp->occ_cell[nocc - 1]) {
            cp->occ_cell[nocc] = cell;
            cp->occ_col[nocc] = (int32_t)q;
            cp->occ_save[nocc] = nsave;
            nsave += sim->cell_start[cell + 1] - sim->cell_start[cell];
            nocc++;
        }
        cp->col_idx[q] = (int32_t)(cp->keys[q] & 0xffffffffu);
    }
    cp->occ_col[nocc] = (int32_t)c->n;
    cp->occ_save[nocc] = nsave;
    cp->nocc = nocc;
    if (3 * nsave > cp->save_cap) {
        pl_free(cp->vsave);
        cp->save_cap = 3 * (nsave + nsave / 2 + 64);
        if (!(cp->vsave = pl_alloc(cp->save_cap * sizeof(double), cp->nthreads)))
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the coupling II buffer");
    }
    pl_coupling2_cells_t oc = {cp->nocc, cp->occ_cell, cp->occ_save, cp->occ_col, cp->col_idx};
    pl_coupling2_save(&sim->fluid, sim->cell_start, &oc, cp->vsave, cp->nthreads);
    return 0;
}

/* Coupling II after the fluid collision: the occupied cells again, with the
 * colloids (Hecht Eq. 15). */
static int collide(pl_sim_t *sim, int heyes)
{
    pl_coupling_t *cp = sim->coupling;
    pl_colloid_t *c = sim->colloids;
    cp->p2.step = (uint64_t)sim->step;
    pl_coupling2_cells_t oc = {cp->nocc, cp->occ_cell, cp->occ_save, cp->occ_col, cp->col_idx};
    if (heyes)
        pl_coupling2_collide_heyes(&cp->p2, &oc, &sim->grid, sim->cell_start, cp->vsave, &sim->fluid, c->mass,
                                   c->vx, c->vy, c->vz, cp->nthreads);
    else
        pl_coupling2_collide(&cp->p2, &oc, &sim->grid, sim->cell_start, cp->vsave, &sim->fluid, c->mass, c->vx,
                             c->vy, c->vz, cp->nthreads);
    /* the walls' push in the occupied cells, replacing the fluid kernel's
     * count there; summed in cell order (deterministic) */
    for (size_t j = 0; cp->p2.wall_fix && j < cp->nocc; ++j)
        pl_sim_wall_add_momentum(sim, cp->p2.wall_fix + PL_WALL_ACC_N * j);
    if (cp->pinned) pl_coupling_absorb_pinned(cp, c, sim->scene.srd.dt);
    return 0;
}

int pl_coupling_stage_collide(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    (void)err;
    return collide(sim, 0);
}

int pl_coupling_stage_collide_heyes(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    (void)err;
    return collide(sim, 1);
}

void pl_coupling_total_momentum(const pl_sim_t *sim, double p[3], double *mass)
{
    pl_fluid_obs_t o;
    pl_srd_observe(&sim->fluid, sim->obs_scratch, &o, sim->nthreads);
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
    (void)ctx;
    (void)err;
    double P[3], M;
    pl_coupling_total_momentum(sim, P, &M);
    const double u[3] = {P[0] / M, P[1] / M, P[2] / M};
    /* v + (-u) rounds as v - u does (IEEE 754 subtraction is the addition
     * of the negated operand): the same bits */
    const double du[3] = {-u[0], -u[1], -u[2]};
    pl_srd_velocity_add(&sim->fluid, du, sim->nthreads);
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
    (void)ctx;
    (void)err;
    pl_fluid_obs_t o;
    pl_fluid_t *f = &sim->fluid;
    pl_srd_observe(f, sim->obs_scratch, &o, sim->nthreads);
    double u[3];
    for (int d = 0; d < 3; ++d)
        u[d] = sim->scene.coupling.flow_velocity[d] - o.momentum[d] / (double)f->n;
    pl_srd_velocity_add(f, u, sim->nthreads);
    return 0;
}
