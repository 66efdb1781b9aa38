/* Run progress for a person watching (src/app/progress.c).  The library does not
 * print: the driver hands in the stream (its stderr) and whether it is a
 * terminal.  On a terminal one line is rewritten in place; otherwise a plain
 * line goes out every interval_s seconds of wall time (batch logs). */
#ifndef PELOID_PROGRESS_H
#define PELOID_PROGRESS_H

#include <stdio.h>

typedef struct pl_progress pl_progress_t;

typedef struct {
    FILE *out;          /* NULL: silent */
    int terminal;       /* 1: one updating line; 0: a log line every interval_s */
    double interval_s;  /* > 0 */
    long long first, last; /* collision steps of the run */
    double dt;          /* collision step, t0 */
    double t0_s;        /* > 0: physical scene, t0 in seconds (time shown in s too) */
    double fluid_n;     /* fluid particles (updates per step) */
    double md_per_step; /* colloid MD steps per collision step (0: none) */
    const char *label;  /* NULL: a run (simulated time shown); else e.g. "calibration": the
                           lines are named by it and show the elapsed wall time instead */
} pl_progress_params_t;

/* NULL when out of memory (progress is then silent). */
pl_progress_t *pl_progress_create(const pl_progress_params_t *p);
/* Called after every step (cheap: a clock read unless a line is due). */
void pl_progress_update(pl_progress_t *p, long long step);
/* One line outside the progress line (finishes the terminal line first). */
void pl_progress_note(pl_progress_t *p, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Remembers a file the run wrote (listed with its size by finish). */
void pl_progress_file(pl_progress_t *p, const char *dir, const char *name);
/* The end: wall time, rates, and the files written with their sizes. */
void pl_progress_finish(pl_progress_t *p, long long step);
void pl_progress_free(pl_progress_t *p);

#endif
