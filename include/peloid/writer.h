/* An output writer as a component row (issue 46): a file the run writes
 * besides its own thermo.tsv, scene.cfg and summary.json.  Its file (an
 * entry of peloid/outputs.h), whether the simulation wants it, how it opens,
 * the stages that write it (their context is what it opened), what it keeps
 * before each step for a guard stop, and what it writes at the end.  The
 * rows are listed once, in src/app/writers.c, in the order they open, add
 * their stages and finish; each writer's own file (src/app/writer_*.c)
 * holds its row, the formats are src/io/'s. */
#ifndef PELOID_WRITER_H
#define PELOID_WRITER_H

#include "peloid/error.h"
#include "peloid/outputs.h"
#include "peloid/sim.h"

struct pl_progress;

/* Time-averaged fields in H5MD layout, fields.h5 and fields.xdmf beside it
 * (src/app/fields_io.c; the fields writer's row, src/app/writer_fields.c). */
int pl_fields_write(const pl_sim_t *sim, const char *path, pl_err_t *err);

/* What every writer is given: the run's output directory and how the run
 * starts there. */
typedef struct {
    const char *dir;        /* the output directory */
    int in_place;           /* resuming in place: its file continues after step `first` */
    long long first;        /* the run's first step */
    struct pl_progress *pg; /* the run's notes (pl_progress_note) */
} pl_writer_out_t;

typedef struct pl_writer {
    pl_output_id_t file; /* the file it writes (and what it writes beside it: the list's next entries) */
    int (*wanted)(const pl_sim_t *sim);
    /* Before the run's first step: opens its file (a resumed one after
     * out->first), *ctx its state (NULL: nothing to open). */
    int (*open)(pl_sim_t *sim, const pl_writer_out_t *out, void **ctx, pl_err_t *err);
    /* Adds its stages (NULL: none), ctx their context. */
    int (*add_stages)(pl_sim_t *sim, void *ctx, pl_err_t *err);
    /* Before every step (NULL: nothing): what a guard stop in the step
     * writes (the last good state). */
    void (*hold)(const pl_sim_t *sim, void *ctx);
    /* After the guard stopped a step (NULL: nothing). */
    void (*guard_stop)(const pl_sim_t *sim, void *ctx);
    /* After the run's last step, the run complete: its last write, its file
     * closed (NULL: nothing). */
    int (*finish)(pl_sim_t *sim, void *ctx, const pl_writer_out_t *out, pl_err_t *err);
    /* On every path, last: releases what open made (NULL: nothing). */
    void (*close)(void *ctx);
} pl_writer_t;

/* The writers of a run: each row's state while it is wanted. */
enum { PL_WRITERS_MAX = 8 };
typedef struct {
    int on[PL_WRITERS_MAX];
    void *ctx[PL_WRITERS_MAX];
} pl_writers_t;

/* Opens the wanted writers in row order and adds their stages; on error
 * the ones opened stay for pl_writers_close. */
int pl_writers_open(pl_sim_t *sim, const pl_writer_out_t *out, pl_writers_t *w, pl_err_t *err);
void pl_writers_hold(const pl_sim_t *sim, const pl_writers_t *w);
void pl_writers_guard_stop(const pl_sim_t *sim, const pl_writers_t *w);
int pl_writers_finish(pl_sim_t *sim, const pl_writers_t *w, const pl_writer_out_t *out, pl_err_t *err);
void pl_writers_close(pl_writers_t *w);

#endif
