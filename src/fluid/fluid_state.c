/* The SRD fluid component's state (peloid/srd.h): made from the scene by
 * the fluid module's create, the first of the table (src/core/modules.c):
 * the grid, the particles and their initial state (src/fluid/fluid_init.c),
 * the cell arrays of the sort and the collision, the wall accumulators, the
 * time-averaged fields and the fluid guard's bounds.  Also the fluid's
 * observables (pl_sim_observe). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/collision_rule.h"
#include "peloid/sim.h"

#include "srd_state.h"

static void srd_free(pl_srd_t *s)
{
    if (!s) return;
    pl_free(s->hist);
    pl_free(s->cell_start);
    pl_free(s->block_sum);
    pl_free(s->guard_bad);
    pl_free(s->obs_scratch);
    pl_free(s->field_acc);
    pl_free(s->wall_acc);
    pl_free(s->wall_dp);
    free(s);
}

void pl_fluid_state_free(pl_sim_t *sim)
{
    pl_fluid_free(&sim->fluid);
    srd_free(sim->srd);
    sim->srd = NULL;
}

int pl_fluid_state_create(pl_sim_t *sim, pl_err_t *err)
{
    const pl_scene_t *scene = &sim->scene;
    int walls[3];
    pl_scene_box_walls(&scene->box, walls);
    pl_grid_init(&sim->grid, scene->box.cells, walls);
    double volume = (double)scene->box.cells[0] * scene->box.cells[1] * scene->box.cells[2];
    size_t n = (size_t)llround(scene->fluid.density * volume);
    pl_srd_t *s = calloc(1, sizeof *s);
    if (!s) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    int rc = pl_fluid_create(n, scene->output.track_fluid, sim->nthreads, &sim->fluid, err);
    if (rc) {
        free(s);
        return rc;
    }
    sim->srd = s;
    s->rule = pl_collision_rule(scene->srd.rule);
    size_t nc = sim->grid.ncells, L3 = (size_t)scene->box.cells[0] * (size_t)scene->box.cells[1] *
                                          (size_t)scene->box.cells[2];
    size_t nb = (nc + PL_CELL_BLOCK - 1) / PL_CELL_BLOCK;
    s->hist = pl_alloc((size_t)sim->nthreads * nc * sizeof(uint32_t), sim->nthreads);
    s->cell_start = pl_alloc((nc + 1) * sizeof(uint32_t), sim->nthreads);
    s->block_sum = pl_alloc(2 * nb * sizeof(double), sim->nthreads);
    s->guard_bad = pl_alloc(nb, sim->nthreads);
    s->guard_bad_step = -1;
    s->obs_scratch = pl_alloc(pl_srd_observe_scratch(n) * sizeof(double), sim->nthreads);
    if (scene->srd.sort_interval > 1) sim->fluid.order = pl_alloc(n * sizeof(uint32_t), sim->nthreads);
    if (scene->output.fields_interval > 0) s->field_acc = pl_alloc(4 * L3 * sizeof(int64_t), sim->nthreads);
    /* the momentum each wall exchanges (wall stress) */
    const int any_walls = sim->grid.any_walls;
    if (any_walls) {
        s->wall_acc = pl_alloc((size_t)sim->nthreads * PL_WALL_ACC_STRIDE * sizeof(int64_t), sim->nthreads);
        s->wall_dp = pl_alloc(PL_WALL_ACC_N * nb * sizeof(double), sim->nthreads);
    }
    memcpy(sim->wall_u, scene->box.wall_velocity, sizeof sim->wall_u); /* shear, Hecht Sec. VIII.C */
    if (!s->hist || !s->cell_start || !s->block_sum || !s->guard_bad || !s->obs_scratch ||
        (scene->srd.sort_interval > 1 && !sim->fluid.order) ||
        (scene->output.fields_interval > 0 && !s->field_acc) || (any_walls && (!s->wall_acc || !s->wall_dp)))
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the cell arrays (%zu cells)", nc);
    pl_fluid_init(&sim->fluid, scene, sim->nthreads);
    pl_fluid_guard_setup(sim);
    return 0;
}

void pl_sim_observe(const pl_sim_t *sim, pl_fluid_obs_t *obs, double *kT)
{
    pl_srd_observe(&sim->fluid, sim->srd->obs_scratch, obs, sim->nthreads);
    /* kT = sum m (v - V)^2 / (3 (N - 1)), V the centre-of-mass velocity */
    size_t n = sim->fluid.n;
    if (n < 2) {
        *kT = 0.0;
        return;
    }
    double p2 = 0.0;
    for (int d = 0; d < 3; ++d) p2 += obs->momentum[d] * obs->momentum[d];
    *kT = (2.0 * obs->kinetic - p2 / (double)n) / (3.0 * (double)(n - 1));
}

/* ---- the fluid's ports (peloid/srd.h) ---------------------------------------- */

const uint32_t *pl_srd_cells(const pl_srd_t *srd) { return srd->sorted ? srd->cell_start : NULL; }

uint32_t *pl_srd_scratch_counts(pl_srd_t *srd) { return srd->hist; }

double *pl_srd_scratch_observe(pl_srd_t *srd) { return srd->obs_scratch; }

int pl_srd_walls_measured(const pl_srd_t *srd) { return srd->wall_acc != NULL; }

pl_srd_kept_t pl_srd_kept(pl_srd_t *srd)
{
    return (pl_srd_kept_t){.field_acc = srd->field_acc, .field_samples = &srd->field_samples,
                           .kT_cell = &srd->last_kT_meas};
}

const int64_t *pl_srd_fields(const pl_srd_t *srd, long long *samples)
{
    *samples = srd->field_samples;
    return srd->field_acc;
}

double pl_srd_speed_bound(const pl_srd_t *srd) { return srd->guard_vmax; }

void pl_srd_order_lost(pl_srd_t *srd) { srd->sorted = 0; }
