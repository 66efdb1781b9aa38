/* What the files of `peloid sweep` share (sweep.c runs the points,
 * sweep_slurm.c writes the Slurm job array); nothing outside src/app/
 * sees it. */
#ifndef PELOID_SWEEP_PRIV_H
#define PELOID_SWEEP_PRIV_H

#include <sched.h>

#include "peloid/error.h"
#include "peloid/sweep.h"

typedef struct {
    pl_study_t *st;
    const pl_sweep_opts_t *o;
    char out[3072];
    int n;     /* the study's points */
    int total; /* the points of this run (n, or 1 with --point) */
    pl_sweep_cost_t *cost; /* each point's, from its scene (the plan's input) */
} sweep_t;

/* Atomic write of `text` to `path` through "<path>.tmp.<pid>". */
int pl_sweep_write_text(const char *path, const char *text, pl_err_t *err);
/* The file's bytes, NUL-terminated (malloc'd; NULL when it cannot be opened). */
char *pl_sweep_read_text(const char *path);
/* pl_sweep_write_text unless the file already holds `text`. */
int pl_sweep_write_changed(const char *path, const char *text, pl_err_t *err);
/* OUT/points.json (sweep_text.c). */
int pl_sweep_write_points(const sweep_t *s, pl_err_t *err);

/* The plan of one run of the pool (sweep_plan.c): the machine, the plan,
 * each job's CPU set (NULL: the jobs are not bound). */
typedef struct {
    pl_sweep_machine_t machine;
    pl_sweep_plan_t *plan;
    cpu_set_t *sets;
} sweep_plan_t;

/* Plans points [first, first + n) whose state is 0 (to run; `todo` of them)
 * from their costs (s->cost), binds the jobs unless PL_NO_BIND is set, and
 * writes OUT/plan.json (not for --point). */
int pl_sweep_plan_points(const sweep_t *s, int first, int n, const int *state, int todo, sweep_plan_t *pl,
                         pl_err_t *err);
void pl_sweep_plan_free(sweep_plan_t *pl);

/* Each job's CPU set (the PUs of its cores, sweep_plan.c) and its hwloc
 * list text; -1 when the plan binds nothing or hwloc fails. */
int pl_sweep_cpusets(const pl_sweep_plan_t *p, cpu_set_t *sets, char (*text)[64]);

/* OUT/sweep.sbatch, collect.sbatch, submit.sh: task K runs point K. */
int pl_sweep_write_slurm(const sweep_t *s, pl_err_t *err);

#endif
