/* Simulation object: the modules' state, the plan and the step loop.  The
 * plan is the ordered list of stages the modules (src/core/modules.c) add, each
 * with its interval and slot; a stage the scene does not need is not in the
 * plan (DESIGN.md "Scene -> plan").  pl_sim_step walks it: the step stages,
 * step + 1, the after-step stages (observers, writers). */
#include <math.h>
#include <omp.h> /* omp_get_wtime: the stages' profile */
#include <stdarg.h>
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

/* ---- lifetime ---------------------------------------------------------- */

int pl_sim_create(const pl_scene_t *scene, int nthreads, pl_sim_t **out, pl_err_t *err)
{
    /* the memory at this thread count, before any allocation (bad input, not exit 5 minutes later) */
    int rc = pl_scene_memory_check(scene, nthreads > 0 ? nthreads : omp_get_max_threads(), err);
    if (rc) return rc;
    pl_sim_t *sim = calloc(1, sizeof *sim);
    if (sim) sim->restart.observers = -1;
    if (!sim) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    sim->scene = *scene;
    sim->nthreads = nthreads > 0 ? nthreads : pl_threads_default();
    /* before any allocation: first touch (pl_alloc) runs on the bound
     * threads.  No process-wide thread count is set: every kernel and
     * pl_alloc are given sim->nthreads (num_threads clauses). */
    pl_threads_bind(sim->nthreads);
    for (int m = 0; pl_modules[m]; ++m) /* the fluid, the colloids, then the coupling between them */
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
    int nm = 0;
    while (pl_modules[nm]) ++nm;
    for (int m = nm - 1; m >= 0; --m) /* the coupling before the colloids it refers to */
        if (pl_modules[m]->destroy) pl_modules[m]->destroy(sim);
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

/* ---- the restart's outcome for the observers ----------------------------- */

void pl_sim_observers_resume(pl_sim_t *sim)
{
    if (sim->restart.observers != 0) sim->restart.observers = 1;
}

void pl_sim_observers_afresh(pl_sim_t *sim, const char *fmt, ...)
{
    if (sim->restart.observers == 0) return; /* the first reason stands */
    sim->restart.observers = 0;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(sim->restart.note, sizeof sim->restart.note, fmt, ap);
    va_end(ap);
}

int pl_sim_observers_resumed(const pl_sim_t *sim, const char **why)
{
    if (why) *why = sim->restart.observers == 0 ? sim->restart.note : NULL;
    return sim->restart.observers;
}
