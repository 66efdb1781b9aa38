/* Simulation object: state allocation, the plan and the step loop.  The
 * plan is the ordered list of stages the modules (src/plan/modules.c) add, each
 * with its interval and slot; a stage the scene does not need is not in the
 * plan (DESIGN.md "Scene -> plan").  pl_sim_step walks it: the step stages,
 * step + 1, the after-step stages (observers, writers). */
#include <math.h>
#include <omp.h> /* omp_get_wtime: the stages' profile */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/module.h"
#include "peloid/sim.h"
#include "peloid/threads.h"

int pl_sim_add_stage(pl_sim_t *sim, const pl_stage_t *stage, pl_err_t *err)
{
    if (sim->nstages >= PL_MAX_STAGES)
        return err ? pl_err_set(err, PL_ERR_INTERNAL, "plan full: %d stages, stage %s left out", PL_MAX_STAGES,
                                stage->name)
                   : PL_ERR_INTERNAL;
    int at = sim->nstages; /* after every stage of an earlier or the same (phase, slot) */
    while (at > 0 && (sim->stages[at - 1].phase > stage->phase ||
                      (sim->stages[at - 1].phase == stage->phase && sim->stages[at - 1].slot > stage->slot)))
        --at;
    memmove(&sim->stages[at + 1], &sim->stages[at], (size_t)(sim->nstages - at) * sizeof sim->stages[0]);
    sim->nstages++;
    pl_stage_t *s = &sim->stages[at];
    *s = *stage;
    if (s->interval <= 0) s->interval = 1;
    s->seconds = 0.0;
    return 0;
}

int pl_sim_add_collide_stage(pl_sim_t *sim, const pl_stage_t *plain, const pl_stage_t *heyes, pl_err_t *err)
{
    if (sim->scene.thermostat.type != PL_THERMO_HEYES) return pl_sim_add_stage(sim, plain, err);
    const long long k = sim->scene.thermostat.interval;
    pl_stage_t p = *plain, h = *heyes;
    p.interval = 1;
    p.except = k;
    h.interval = k;
    int rc = k > 1 ? pl_sim_add_stage(sim, &p, err) : 0;
    return rc ? rc : pl_sim_add_stage(sim, &h, err);
}

/* ---- lifetime ---------------------------------------------------------- */

int pl_sim_create(const pl_scene_t *scene, int nthreads, pl_sim_t **out, pl_err_t *err)
{
    /* the memory at this thread count, before any allocation (bad input, not exit 5 minutes later) */
    int rc = pl_scene_memory_check(scene, nthreads > 0 ? nthreads : omp_get_max_threads(), err);
    if (rc) return rc;
    pl_sim_t *sim = calloc(1, sizeof *sim);
    if (sim) sim->observe_resumed = -1;
    if (!sim) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    sim->scene = *scene;
    sim->nthreads = nthreads > 0 ? nthreads : pl_threads_default();
    /* before any allocation: first touch (pl_alloc) runs on the bound
     * threads.  No process-wide thread count is set: every kernel and
     * pl_alloc are given sim->nthreads (num_threads clauses). */
    pl_threads_bind(sim->nthreads);
    int walls[3];
    pl_scene_box_walls(&scene->box, walls);
    pl_grid_init(&sim->grid, scene->box.cells, walls);
    double volume = (double)scene->box.cells[0] * scene->box.cells[1] * scene->box.cells[2];
    size_t n = (size_t)llround(scene->fluid.density * volume);
    rc = pl_fluid_create(n, scene->output.track_fluid, sim->nthreads, &sim->fluid, err);
    if (rc) {
        free(sim);
        return rc;
    }
    size_t nc = sim->grid.ncells, L3 = (size_t)scene->box.cells[0] * (size_t)scene->box.cells[1] *
                                          (size_t)scene->box.cells[2];
    size_t nb = (nc + PL_CELL_BLOCK - 1) / PL_CELL_BLOCK;
    sim->hist = pl_alloc((size_t)sim->nthreads * nc * sizeof(uint32_t), sim->nthreads);
    sim->cell_start = pl_alloc((nc + 1) * sizeof(uint32_t), sim->nthreads);
    sim->block_sum = pl_alloc(2 * nb * sizeof(double), sim->nthreads);
    sim->guard_bad = pl_alloc(nb, sim->nthreads);
    sim->guard_bad_step = -1;
    sim->obs_scratch = pl_alloc(pl_srd_observe_scratch(n) * sizeof(double), sim->nthreads);
    if (scene->srd.sort_interval > 1) sim->fluid.order = pl_alloc(n * sizeof(uint32_t), sim->nthreads);
    if (scene->output.fields_interval > 0) sim->field_acc = pl_alloc(4 * L3 * sizeof(int64_t), sim->nthreads);
    /* the momentum each wall exchanges (wall stress) */
    const int any_walls = sim->grid.any_walls;
    if (any_walls) {
        sim->wall_acc = pl_alloc((size_t)sim->nthreads * PL_WALL_ACC_STRIDE * sizeof(int64_t), sim->nthreads);
        sim->wall_dp = pl_alloc(PL_WALL_ACC_N * nb * sizeof(double), sim->nthreads);
    }
    memcpy(sim->wall_u, scene->box.wall_velocity, sizeof sim->wall_u); /* shear, Hecht Sec. VIII.C */
    if (!sim->hist || !sim->cell_start || !sim->block_sum || !sim->guard_bad || !sim->obs_scratch ||
        (scene->srd.sort_interval > 1 && !sim->fluid.order) ||
        (scene->output.fields_interval > 0 && !sim->field_acc) || (any_walls && (!sim->wall_acc || !sim->wall_dp))) {
        pl_sim_free(sim);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the cell arrays (%zu cells)", nc);
    }
    pl_fluid_init(&sim->fluid, scene, sim->nthreads);
    for (int m = 0; pl_modules[m]; ++m) /* colloids, then the coupling between them and the fluid */
        if (pl_modules[m]->create && (rc = pl_modules[m]->create(sim, err))) {
            pl_sim_free(sim);
            return rc;
        }
    /* the plan: every module's stages at their slots */
    sim->nstages = 0;
    for (int m = 0; pl_modules[m]; ++m)
        if (pl_modules[m]->add_stages && (rc = pl_modules[m]->add_stages(sim, err))) {
            pl_sim_free(sim);
            return rc;
        }
    *out = sim;
    return 0;
}

void pl_sim_free(pl_sim_t *sim)
{
    if (!sim) return;
    pl_fluid_free(&sim->fluid);
    int nm = 0;
    while (pl_modules[nm]) ++nm;
    for (int m = nm - 1; m >= 0; --m) /* the coupling before the colloids it refers to */
        if (pl_modules[m]->destroy) pl_modules[m]->destroy(sim);
    pl_free(sim->hist);
    pl_free(sim->cell_start);
    pl_free(sim->block_sum);
    pl_free(sim->guard_bad);
    pl_free(sim->obs_scratch);
    pl_free(sim->field_acc);
    pl_free(sim->wall_acc);
    pl_free(sim->wall_dp);
    free(sim);
}

int pl_sim_stage_due(const pl_sim_t *sim, const pl_stage_t *s, long long step)
{
    if (s->except > 0 && step % s->except == 0) return 0;
    return step % s->interval == 0 ||
           (s->phase == PL_PHASE_AFTER && s->at_end && (step == sim->last_step || sim->stop_requested));
}

static int run_stage(pl_sim_t *sim, pl_stage_t *s, pl_err_t *err)
{
    double t0 = omp_get_wtime();
    int rc = s->fn(sim, s->ctx, err);
    s->seconds += omp_get_wtime() - t0;
    return rc;
}

int pl_sim_begin(pl_sim_t *sim, long long last, pl_err_t *err)
{
    sim->first_step = sim->step;
    sim->last_step = last;
    sim->run_wall_start = omp_get_wtime();
    for (int k = 0; k < sim->nstages; ++k) {
        pl_stage_t *s = &sim->stages[k];
        int rc;
        if (s->phase == PL_PHASE_AFTER && s->at_start && sim->step % s->interval == 0 &&
            (rc = run_stage(sim, s, err)))
            return rc;
    }
    return 0;
}

int pl_sim_end_here(pl_sim_t *sim, const char *reason, pl_err_t *err)
{
    sim->stop_requested = 1;
    snprintf(sim->stop_reason, sizeof sim->stop_reason, "%s", reason);
    for (int k = 0; k < sim->nstages; ++k) {
        pl_stage_t *s = &sim->stages[k];
        if (s->phase != PL_PHASE_AFTER) continue;
        int ran = sim->step % s->interval == 0 && !(s->except > 0 && sim->step % s->except == 0);
        int rc;
        if (((s->at_end && !ran) || s->slot == PL_SLOT_OUTPUT_GUARD) && (rc = run_stage(sim, s, err))) return rc;
    }
    return 0;
}

int pl_sim_step(pl_sim_t *sim, pl_err_t *err)
{
    int rc;
    for (int k = 0; k < sim->nstages; ++k) {
        pl_stage_t *s = &sim->stages[k];
        if (s->phase == PL_PHASE_STEP && pl_sim_stage_due(sim, s, sim->step) && (rc = run_stage(sim, s, err)))
            return rc;
    }
    sim->step++;
    for (int k = 0; k < sim->nstages; ++k) {
        pl_stage_t *s = &sim->stages[k];
        if (s->phase == PL_PHASE_AFTER && pl_sim_stage_due(sim, s, sim->step) && (rc = run_stage(sim, s, err)))
            return rc;
    }
    return 0;
}

void pl_sim_observe(const pl_sim_t *sim, pl_fluid_obs_t *obs, double *kT)
{
    pl_srd_observe(&sim->fluid, sim->obs_scratch, obs, sim->nthreads);
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
