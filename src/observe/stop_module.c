/* The stopping rule (section stop{}; DESIGN.md "a run may stop when a
 * requested relative error is reached"): an after-step stage, after the
 * observers, that ends the run once the chosen observable's standard error
 * is at most stop.rel_error of its value, checked every stop.check_interval
 * steps from the state alone, so a run stops at the same step for any
 * thread count; or after stop.max_wall_s of wall time (the one rule that
 * depends on the machine, reported as such).  The run then ends as at its
 * last step: last thermo row and trajectory frame, final checkpoint,
 * outputs; summary.json "stop" says why and when. */
#include <jansson.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <string.h>

#include "json_build.h"
#include "peloid/module.h"

/* ctx: the rule's settings (stop{}), both stages */
static int stage_stop(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    const pl_scene_stop_t *st = ctx;
    double v, se;
    if (sim->step % st->check_interval == 0 && pl_observe_estimate(sim, st->observable, &v, &se) && v != 0.0 &&
        se <= st->rel_error * fabs(v)) {
        sim->stop_requested = 1;
        snprintf(sim->stop_reason, sizeof sim->stop_reason, "%.60s reached SE %.3g = %.3g of %.6g (stop.rel_error %g)",
                 st->observable, se, se / fabs(v), v, st->rel_error);
    }
    return 0;
}

/* The wall-time limit, checked every step (a clock read). */
static int stage_wall(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    const pl_scene_stop_t *st = ctx;
    if (!sim->stop_requested && omp_get_wtime() - sim->run_wall_start >= st->max_wall_s) {
        sim->stop_requested = 1;
        snprintf(sim->stop_reason, sizeof sim->stop_reason, "stop.max_wall_s = %g s of wall time reached",
                 st->max_wall_s);
    }
    return 0;
}

static int stop_stages(pl_sim_t *sim, pl_err_t *err)
{
    int rc;
    const pl_scene_stop_t *st = &sim->scene.stop;
    if (strcmp(st->observable, "none") && pl_observe_running(sim)) {
        pl_stage_t s = {.name = "stop-rule", .fn = stage_stop, .ctx = &sim->scene.stop,
                        .interval = st->check_interval, .phase = PL_PHASE_AFTER, .slot = PL_SLOT_OBSERVE};
        if ((rc = pl_sim_add_stage(sim, &s, err))) return rc;
    }
    if (st->max_wall_s > 0) {
        pl_stage_t s = {.name = "stop-wall", .fn = stage_wall, .ctx = &sim->scene.stop, .interval = 1,
                        .phase = PL_PHASE_AFTER, .slot = PL_SLOT_OBSERVE};
        if ((rc = pl_sim_add_stage(sim, &s, err))) return rc;
    }
    return 0;
}

/* summary.json "stop": why the run ended. */
static int stop_finish(pl_sim_t *sim, const char *dir, json_t *doc, pl_err_t *err)
{
    (void)dir;
    if (!strcmp(sim->scene.stop.observable, "none") && !(sim->scene.stop.max_wall_s > 0)) return 0;
    pl_json_t b = {err, sim->scene.path, "stop", 0};
    json_t *o = json_object();
    pl_json_str(&b, o, "reason", sim->stop_requested ? sim->stop_reason : "the run's steps were done");
    pl_json_int(&b, o, "step", sim->step);
    pl_json_int(&b, o, "planned_last_step", sim->last_step);
    pl_json_set(&b, doc, "stop", o);
    return b.failed ? err->code : 0;
}

const pl_module_t pl_stop_module = {
    .name = "stop",
    .add_stages = stop_stages,
    .finish = stop_finish,
};
