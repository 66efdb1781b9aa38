/* Parameter sweeps (`peloid sweep STUDY.cfg`): a study names a base scene
 * and a grid (cartesian product) or an explicit list of values over scene
 * keys; each point is the base scene with those keys set, run as its own
 * `peloid run` process (src/app/sweep.c), or as one task of a Slurm job
 * array.  The study file is libconfig, read like a scene (src/app/study.c). */
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
/* The study of `replicas` runs of one scene (`peloid run SCENE --replicas
 * N`): no swept key, seeds the scene's seed + 0 .. N - 1, its out out_dir
 * (NULL: out/<the scene's name>), named as the scene's run; replicas out of
 * 2..PL_STUDY_MAX_POINTS is refused ("replicas"). */
int pl_study_of_scene(const char *scene, int replicas, const char *out_dir, pl_study_t **out, pl_err_t *err);
/* The scene at path `scene` with n keys set (keys "section.key", values as
 * scene text, e.g. "\"II\""), as libconfig text (malloc'd, the caller
 * frees): what a study's point with those values runs (`peloid plan`). */
int pl_study_scene_with(const char *scene, int n, const char *const *keys, const char *const *values, char **text,
                        pl_err_t *err);

/* The runs of the study: its points times its replicas (study key
 * `replicas`, default 1).  Every k below is a run: replica k % replicas of
 * point k / replicas. */
int pl_study_npoints(const pl_study_t *study);
int pl_study_replicas(const pl_study_t *study);
/* The seed run k is given: the base scene's seed (its default when unset)
 * + its replica number (meaningful with replicas > 1; else the base's). */
long long pl_study_seed(const pl_study_t *study, int k);
/* Directory name of run k: p000, p001, ... (wider from 1000 points); with
 * replicas > 1 the replica follows: p000r0, p000r1, ... */
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
/* Copies the files the point last set by pl_study_point_scene reads
 * (colloids.init_file, colloids.table_file: relative to the base scene's
 * folder) into scenes_dir, beside its scene. */
int pl_study_point_files(const pl_study_t *study, const char *scenes_dir, pl_err_t *err);

/* Value of axis `axis` at run k as scene text (e.g. "1.4e+08", "\"II\""). */
int pl_study_point_value(const pl_study_t *study, int k, int axis, char *buf, size_t n);

/* The study's plot{} section as JSON text ("{}" when absent), for the collect
 * step (tools/sweep_collect.py). */
void pl_study_plot_json(const pl_study_t *study, char *buf, size_t n);

/* Checks every point's scene with the scene loader and the run's checks
 * (pl_run_check) before anything is written; a bad point is refused naming
 * the study line, the point and its values, then the loader's message.
 * cost (NULL: not wanted): each point's cost for the plan (pl_sweep_point_cost). */
struct pl_sweep_cost;
int pl_study_check_points(pl_study_t *study, const char *out_dir, struct pl_sweep_cost *cost, pl_err_t *err);

typedef struct {
    const char *out_dir;  /* NULL: the study's */
    const char *self;     /* the peloid executable the points run */
    const char *tools;    /* directory of sweep_collect.py */
    int jobs, threads;    /* 0: the rule of pl_sweep_plan */
    long long point;      /* >= 0: run only this point (a Slurm array task) */
    int slurm;            /* write the job-array scripts, run nothing */
    int collect_only;     /* only collect the table and plot */
    int progress_tty;     /* redraw one progress line (stderr is a terminal) */
    const char *calibrate; /* NULL, or a --calibrate mode every point's run is given */
    FILE *log;
    /* The driver's signal flag (NULL: none): 0 none, S > 0 a first signal S
     * (forwarded to the running points, which stop after their step and
     * write a checkpoint; no new point starts), -S a second one (the points
     * are killed, the sweep returns at once).  Polled between waits. */
    volatile sig_atomic_t *interrupt;
} pl_sweep_opts_t;

/* The throughput plan of a sweep (src/app/sweep_plan.c).  What a point
 * costs, from its scene (pl_sweep_point_cost): its run's memory estimate
 * (pl_scene_memory_bytes) and the most threads it gains from, by the rule
 * of thumb of README "Parameter sweeps": max(1, fluid particles / 131072,
 * colloids / 64), at most 8 with colloids (bench/RESULTS.md, issue 38). */
typedef struct pl_sweep_cost {
    double mem_bytes;      /* estimated bytes of its run at 1 thread */
    double mem_per_thread; /* + this per further thread (the sort's histograms) */
    int max_threads;       /* threads beyond this do not speed it up */
} pl_sweep_cost_t;

enum { PL_SWEEP_MAX_CORES = 4096, PL_SWEEP_MAX_DOMAINS = 256 };
/* A point's jobs get this much memory on top of the estimate (the process,
 * its libraries, HDF5 and observer buffers). */
#define PL_SWEEP_JOB_OVERHEAD_BYTES 64.0e6
/* Of the memory available at the start, the jobs together may use this share. */
#define PL_SWEEP_MEMORY_SHARE 0.8

/* The machine as the sweep sees it (pl_sweep_machine: hwloc, restricted to
 * the sweep's own CPU binding, e.g. taskset or a Slurm allocation). */
typedef struct {
    int cores;    /* cores with a PU in the binding */
    int pus;      /* hardware threads (PUs) on them */
    int ndomains; /* L3 caches holding them (else NUMA nodes, else 1) */
    int domain_cores[PL_SWEEP_MAX_DOMAINS]; /* cores per domain; hwloc's logical core order, domain by domain */
    char domain_kind[8]; /* "L3", "NUMA" or "machine" */
    double mem_bytes;    /* memory available now (MemAvailable; 0: unknown) */
} pl_sweep_machine_t;

/* What the plan is asked: points to run, --jobs and --threads (0: choose),
 * and the largest memory and max_threads of those points. */
typedef struct {
    int todo, jobs_given, threads_given;
    pl_sweep_cost_t cost;
} pl_sweep_request_t;

typedef struct {
    int jobs, threads;
    int bound;    /* each job bound to cores of its own: core[] */
    int split;    /* jobs whose cores span two domains */
    int idle;     /* cores no job uses (bound plans) */
    int mem_jobs; /* the most jobs the memory holds at `threads` (0: not known) */
    int core[PL_SWEEP_MAX_CORES]; /* job j: cores core[j * threads .. + threads - 1], logical indices */
    char why[768]; /* the choice and its reasons, one line */
} pl_sweep_plan_t;

/* Processes x threads for the highest throughput: with P points to run and
 * C cores, jobs = min(P, C) single-thread jobs when P >= C; when P < C,
 * jobs = P with threads = floor(C / P), at most cost.max_threads.  A given
 * --jobs or --threads wins (only --threads: jobs = C / threads; only --jobs:
 * threads = C / jobs bounded as above); jobs never exceed P.  Without --jobs,
 * jobs shrink until jobs x (the largest point's estimate + the overhead)
 * fits PL_SWEEP_MEMORY_SHARE of the memory; a given --jobs is kept and the
 * reason says it does not fit.  When jobs x threads <= C each job gets
 * cores of its own, inside one domain where one has room (the domain with
 * the most free cores first, so jobs spread over domains). */
void pl_sweep_plan(const pl_sweep_machine_t *m, const pl_sweep_request_t *r, pl_sweep_plan_t *p);
/* The machine (hwloc and /proc/meminfo). */
void pl_sweep_machine(pl_sweep_machine_t *m);
struct pl_scene;
void pl_sweep_point_cost(const struct pl_scene *scene, pl_sweep_cost_t *cost);

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
