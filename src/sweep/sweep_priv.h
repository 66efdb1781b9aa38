/* What the files of `peloid sweep` share (sweep.c runs the points,
 * sweep_slurm.c writes the Slurm job array); nothing outside src/sweep/
 * sees it. */
#ifndef PELOID_SWEEP_PRIV_H
#define PELOID_SWEEP_PRIV_H

#include "peloid/error.h"
#include "peloid/sweep.h"

typedef struct {
    pl_study_t *st;
    const pl_sweep_opts_t *o;
    char out[3072];
    int n;     /* the study's points */
    int total; /* the points of this run (n, or 1 with --point) */
} sweep_t;

/* Atomic write of `text` to `path` through "<path>.tmp.<pid>". */
int pl_sweep_write_text(const char *path, const char *text, pl_err_t *err);

/* OUT/sweep.sbatch, collect.sbatch, submit.sh: task K runs point K. */
int pl_sweep_write_slurm(const sweep_t *s, pl_err_t *err);

#endif
