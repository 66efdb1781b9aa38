/* Parameter sweeps (`peloid sweep STUDY.cfg`): a study names a base scene
 * and a grid (cartesian product) or an explicit list of values over scene
 * keys; each point is the base scene with those keys set, run as its own
 * `peloid run` process (src/sweep/sweep.c), or as one task of a Slurm job
 * array.  The study file is libconfig, read like a scene (src/sweep/study.c). */
#ifndef PELOID_SWEEP_H
#define PELOID_SWEEP_H

#include <signal.h>
#include <stdio.h>

#include "peloid/error.h"

enum { PL_STUDY_MAX_AXES = 16, PL_STUDY_MAX_POINTS = 100000 };

typedef struct pl_study pl_study_t;

/* Reads and checks a study file: every key known, every swept key a scene
 * key (section.key as `peloid keys` lists it), at least one value per key,
 * the base scene readable, `name` not swept, no point twice (a value given
 * twice on a grid axis, two equal rows of points{}).  Errors: PL_ERR_INPUT, "FILE:LINE: key '...': what;
 * allowed: ...". */
int pl_study_load(const char *path, pl_study_t **out, pl_err_t *err);
void pl_study_free(pl_study_t *study);

int pl_study_npoints(const pl_study_t *study);
/* Directory name of point k: p000, p001, ... (wider from 1000 points). */
void pl_study_point_id(const pl_study_t *study, int k, char *buf, size_t n);
int pl_study_naxes(const pl_study_t *study);
const char *pl_study_name(const pl_study_t *study);
const char *pl_study_out(const pl_study_t *study);  /* out = "..." or out/<name> */
const char *pl_study_path(const pl_study_t *study);
const char *pl_study_axis_key(const pl_study_t *study, int axis);

/* The scene of point k (0-based): the base scene's settings with the point's
 * keys set, as libconfig text (malloc'd, the caller frees); `name` becomes
 * the scene's name (a study cannot sweep `name`). */
int pl_study_point_scene(pl_study_t *study, int k, const char *name, char **text, pl_err_t *err);

/* Value of axis `axis` at point k as scene text (e.g. "1.4e+08", "\"II\""). */
int pl_study_point_value(const pl_study_t *study, int k, int axis, char *buf, size_t n);

/* The study's plot{} section as JSON text ("{}" when absent), for the collect
 * step (tools/sweep_collect.py). */
void pl_study_plot_json(const pl_study_t *study, char *buf, size_t n);

/* Checks every point's scene with the scene loader and the run's checks
 * (pl_run_check) before anything is written; a bad point is refused naming
 * the study line, the point and its values, then the loader's message. */
int pl_study_check_points(pl_study_t *study, const char *out_dir, pl_err_t *err);

typedef struct {
    const char *out_dir;  /* NULL: the study's */
    const char *self;     /* the peloid executable the points run */
    const char *tools;    /* directory of sweep_collect.py */
    int jobs, threads;    /* 0: the rule of pl_sweep_plan */
    long long point;      /* >= 0: run only this point (a Slurm array task) */
    int slurm;            /* write the job-array scripts, run nothing */
    int collect_only;     /* only collect the table and plot */
    int progress_tty;     /* redraw one progress line (stderr is a terminal) */
    FILE *log;
    /* The driver's signal flag (NULL: none): 0 none, S > 0 a first signal S
     * (forwarded to the running points, which stop after their step and
     * write a checkpoint; no new point starts), -S a second one (the points
     * are killed, the sweep returns at once).  Polled between waits. */
    volatile sig_atomic_t *interrupt;
} pl_sweep_opts_t;

/* Processes and threads for `todo` points on `cpus` CPUs: jobs = min(todo,
 * cpus), threads = max(1, cpus / jobs); a given --jobs or --threads wins
 * (only --threads: jobs = max(1, cpus / threads), at most todo). */
void pl_sweep_plan(int todo, int cpus, int jobs_given, int threads_given, int *jobs, int *threads);

/* The sweep: checks every point, writes OUT/points.json and each point's
 * scene, runs the points not yet finished (a point a signal interrupted
 * resumes from its own checkpoint), records each failure (OUT/status/), and
 * collects OUT/sweep.{tsv,json,png}.  Each point runs in its own process
 * group.  Returns 0 when every point ran, 1 when some failed or a signal to
 * it alone stopped it (recorded; the others ran), PL_ERR_INTERRUPTED when o->interrupt was raised (the running
 * points were interrupted and recorded, the table written unless a second
 * signal came), PL_ERR_* when the sweep itself could not run. */
int pl_sweep(pl_study_t *study, const pl_sweep_opts_t *o, pl_err_t *err);

#endif
