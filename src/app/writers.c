/* The output writers of a run, one row each (peloid/writer.h).  The list
 * below is the only place that names them all: a new writer is its own file
 * (src/app/writer_<name>.c: row and stages; its format under src/io/), its
 * file in the list of outputs (src/io/outputs.c) and one line here.  Row
 * order is the order they open, add their stages and finish. */
#include <stddef.h>

#include "peloid/writer.h"

extern const pl_writer_t pl_writer_colloids;   /* src/app/writer_colloids.c */
extern const pl_writer_t pl_writer_checkpoint; /* src/app/writer_checkpoint.c */
extern const pl_writer_t pl_writer_fields;     /* src/app/writer_fields.c */

static const pl_writer_t *const rows[] = {
    &pl_writer_colloids,
    &pl_writer_checkpoint,
    &pl_writer_fields,
};
enum { NROWS = (int)(sizeof rows / sizeof rows[0]) };
_Static_assert((int)NROWS <= (int)PL_WRITERS_MAX, "pl_writers_t holds every row");

int pl_writers_open(pl_sim_t *sim, const pl_writer_out_t *out, pl_writers_t *w, pl_err_t *err)
{
    int rc = 0;
    for (int k = 0; !rc && k < NROWS; ++k) {
        if (!rows[k]->wanted(sim)) continue;
        w->on[k] = 1;
        if (rows[k]->open) rc = rows[k]->open(sim, out, &w->ctx[k], err);
        if (!rc && rows[k]->add_stages) rc = rows[k]->add_stages(sim, w->ctx[k], err);
    }
    return rc;
}

void pl_writers_hold(const pl_sim_t *sim, const pl_writers_t *w)
{
    for (int k = 0; k < NROWS; ++k)
        if (w->on[k] && rows[k]->hold) rows[k]->hold(sim, w->ctx[k]);
}

void pl_writers_guard_stop(const pl_sim_t *sim, const pl_writers_t *w)
{
    for (int k = 0; k < NROWS; ++k)
        if (w->on[k] && rows[k]->guard_stop) rows[k]->guard_stop(sim, w->ctx[k]);
}

int pl_writers_finish(pl_sim_t *sim, const pl_writers_t *w, const pl_writer_out_t *out, pl_err_t *err)
{
    int rc = 0;
    for (int k = 0; !rc && k < NROWS; ++k)
        if (w->on[k] && rows[k]->finish) rc = rows[k]->finish(sim, w->ctx[k], out, err);
    return rc;
}

void pl_writers_close(pl_writers_t *w)
{
    for (int k = 0; k < NROWS; ++k) {
        if (w->on[k] && rows[k]->close) rows[k]->close(w->ctx[k]);
        w->on[k] = 0;
        w->ctx[k] = NULL;
    }
}
