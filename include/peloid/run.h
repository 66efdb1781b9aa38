/* `peloid run`: opens the outputs, registers the writers (thermo log,
 * checkpoints) as after-step stages of the plan, walks it, and writes the
 * final checkpoint, fields and summary.  Reports go through the driver's
 * callbacks: the library prints nothing itself. */
#ifndef PELOID_RUN_H
#define PELOID_RUN_H

#include <limits.h>
#include <signal.h>
#include <stdio.h>

#include "peloid/error.h"
#include "peloid/params.h"
#include "peloid/scene.h"
#include "peloid/threads.h"

/* Where a run ended (pl_run_opts_t.end): for the driver's resume hint. */
typedef struct {
    long long step, last;  /* the step reached, the step the run was to end at */
    char dir[PATH_MAX];    /* the resolved output directory ("" before it is known) */
} pl_run_end_t;

typedef struct {
    const char *out_dir;     /* NULL: out/<scene name> */
    long long steps;         /* < 0: the scene's run.steps */
    int threads;             /* <= 0: OpenMP default */
    const char *restart;     /* checkpoint to continue from, or NULL */
    int force;               /* write into an existing output directory */
    int progress;            /* log is a terminal: one updating progress line */
    FILE *log;               /* progress, notes and the mapping audit's warnings (the driver's stderr), or NULL */
    const char *restart_changed; /* --restart-changed: comma-separated scene keys
                                  * allowed to differ from the checkpoint's, or NULL */
    /* The driver's signal flag (the signal number, 0: none), or NULL: polled
     * between steps; when set the run ends at the step reached as at its
     * normal end (last thermo row and trajectory frame, checkpoint, fields,
     * observables, summary.json with "interrupted": true) and returns
     * PL_ERR_INTERRUPTED. */
    const volatile sig_atomic_t *interrupt;
    pl_run_end_t *end;           /* filled when not NULL */
} pl_run_opts_t;

/* Largest step a run may reach (steps and checkpoint steps above it are
 * refused): 2^62, far from signed overflow in step arithmetic. */
#define PL_RUN_MAX_STEP (1LL << 62)

int pl_run(const pl_scene_t *scene, const pl_run_opts_t *opts, pl_err_t *err);

/* Coupling-true time (src/app/calibrate.c).  Whether a scene's mapping
 * needs the measured colloid D: a physical scene with coupling I or II. */
int pl_calibration_needed(const pl_scene_t *scene);
/* How a run, check or params gets the colloid D (--calibrate) and where a
 * calibration run reports: before it starts, its size and an estimate of its
 * duration (extrapolated from its first steps), then progress lines (percent,
 * elapsed, ETA) every progress_s seconds, or one line rewritten in place on a
 * terminal (src/app/progress.c). */
typedef struct {
    int mode;          /* PL_CALIBRATE_* (mapping.h) */
    FILE *log;         /* NULL: silent */
    int terminal;      /* log is a terminal */
    double progress_s; /* > 0: seconds between progress lines off a terminal */
} pl_calibrate_opts_t;
/* "never", "auto", "always", "stored" -> PL_CALIBRATE_*; -1 for anything else. */
int pl_calibrate_mode_parse(const char *s, int *mode); /* names: pl_calibrate_mode_name (mapping.h) */
/* The colloid D of the scene's model fluid and colloid, from
 * shipped_dir/calibration-<key>.json, else the user's cache, else the
 * shipped resolution table (pl_calibration_table), else a calibration run
 * (nthreads), cached; with PL_CALIBRATE_ALWAYS a calibration run whatever is
 * stored (the cache entry replaced); with PL_CALIBRATE_STORED what is stored
 * or tabled, else the coupling's theory (PL_CALSRC_THEORY), never a run. */
int pl_calibrate(const pl_scene_t *scene, const char *shipped_dir, int nthreads, const pl_calibrate_opts_t *o,
                 pl_mapping_calibration_t *cal, pl_err_t *err);
/* Coupling I in a fluid whose resolution table is shipped in dir
 * (rh_resolution-*.json) at an R/a0 inside its measured range: *cal from the
 * table's law (PL_CALSRC_TABLE, d_inf and its SE; d_theory left 0 for the
 * caller), 1; else 0 and *cal unchanged (src/app/calibration_table.c). */
int pl_calibration_table(const pl_scene_t *scene, const char *dir, pl_mapping_calibration_t *cal);
/* The coupling theory's relative error (PL_CALSRC_THEORY fields of cal) for
 * the scene's coupling (src/app/calibrate_mode.c). */
void pl_calibrate_theory(const pl_scene_t *scene, pl_mapping_calibration_t *cal);
/* pl_scene_load_flags, then, where needed, pl_calibrate (or, with
 * PL_CALIBRATE_NEVER, the theory) and the scene loaded again with that D
 * (pl_scene_load_calibrated); the provenance lands in scene->mapping.calib. */
int pl_scene_load_coupling_true(const char *path, unsigned flags, const char *shipped_dir, int nthreads,
                                const pl_calibrate_opts_t *o, pl_scene_t *scene, pl_err_t *err);

/* Row k of the shipped calibrations (src/app/calibrate_mode.c): the
 * coupling (PL_COUPLE_*), the file key (calibration-<key>.json), the scene
 * that reads it and D_measured / D_theory; -1 past the last row. */
int pl_calibrate_shipped(int k, int *method, const char **key, const char **scene, double *ratio);

/* `peloid plan SCENE --target REL` (src/app/advise.c): for the physical
 * scene (loaded, calibrated as the caller chose) the couplings at their
 * default resolution with their hydrodynamic radius R_h/R (this scene's
 * mapping; the others from their theory scaled by the shipped calibrations'
 * D_measured / D_theory) and calibration cost, the box against Hasimoto's
 * correction, the MD settings, and the run length and CPU time for a
 * relative SE `target` of the colloid D (and of the settling velocity under
 * gravity), with the recommendation.  path: the scene's file (the other
 * couplings are loaded from it with coarse_graining.coupling set). */
int pl_plan_advise(const pl_scene_t *scene, const char *path, double target, const char *shipped_dir, FILE *out,
                   pl_err_t *err);

#endif
