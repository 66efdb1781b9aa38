/* `peloid run`: opens the outputs, registers the writers (thermo log,
 * checkpoints) as after-step stages of the plan, walks it, and writes the
 * final checkpoint, fields and summary.  Reports go through the driver's
 * callbacks: the library prints nothing itself. */
#ifndef PELOID_RUN_H
#define PELOID_RUN_H

#include <stdio.h>

#include "peloid/error.h"
#include "peloid/scene.h"

/* Where a run stands, for the driver's progress display. */
typedef struct {
    long long step, first, last; /* collision steps */
    double elapsed_s;            /* wall time since the first step */
    double time;                 /* simulated time, t0 */
    double time_s;               /* simulated time in s (physical scenes; else 0) */
    double fluid_updates;        /* fluid particle updates since the first step */
    double md_steps;             /* colloid MD steps since the first step */
    int done;                    /* the last call of this run */
} pl_run_progress_t;

typedef struct {
    const char *out_dir;     /* NULL: out/<scene name> */
    long long steps;         /* < 0: the scene's run.steps */
    int threads;             /* <= 0: OpenMP default */
    const char *restart;     /* checkpoint to continue from, or NULL */
    int force;               /* write into an existing output directory */
    /* progress: called about every progress_interval_s seconds of wall time
     * and once at the end (done = 1); NULL: none */
    void (*progress)(const pl_run_progress_t *p, void *user);
    double progress_interval_s;
    /* one line of information (the run's start, its set-up, its end); NULL: none */
    void (*log)(const char *line, void *user);
    void *user;
    const char *restart_changed; /* --restart-changed: comma-separated scene keys
                                  * allowed to differ from the checkpoint's, or NULL */
} pl_run_opts_t;

/* Largest step a run may reach (steps and checkpoint steps above it are
 * refused): 2^62, far from signed overflow in step arithmetic. */
#define PL_RUN_MAX_STEP (1LL << 62)

int pl_run(const pl_scene_t *scene, const pl_run_opts_t *opts, pl_err_t *err);

/* `peloid params`: derived SRD parameters (PL Eqs. 4, 6, 9-15) as text. */
void pl_params_print(const pl_scene_t *scene, FILE *out);

/* The same as a jansson object (summary.json "derived"); a non-finite value
 * is PL_ERR_INPUT naming the key. */
struct json_t;
int pl_params_json(const pl_scene_t *scene, struct json_t **out, pl_err_t *err);

/* `peloid check`: what `run` validates short of running: the derived values
 * (finite), the mapping report, the colloid placement (init file, overlaps). */
int pl_run_check(const pl_scene_t *scene, pl_err_t *err);

/* `peloid params --json`: the object above, or {"srd": ..., "mapping": ...}
 * for a scene with physical{} (strict: audit warnings are errors). */
int pl_params_write_json(const pl_scene_t *scene, FILE *out, int strict, pl_err_t *err);

#endif
