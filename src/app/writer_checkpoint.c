/* The checkpoint as a writer row (peloid/writer.h): checkpoint.h5 every
 * output.checkpoint_interval steps (0: none on the way) and on the run's
 * last state; the format is the whole-simulation checkpoint's
 * (src/core/checkpoint.c), written atomically (a failed write leaves the
 * last good one). */
#include <limits.h>
#include <stdlib.h>

#include "peloid/checkpoint.h"
#include "peloid/io.h"
#include "peloid/writer.h"

static int wanted(const pl_sim_t *sim)
{
    (void)sim;
    return 1;
}

/* ctx: its path */
static int open_path(pl_sim_t *sim, const pl_writer_out_t *out, void **ctx, pl_err_t *err)
{
    (void)sim;
    char *path = malloc(PATH_MAX);
    if (!path) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    pl_path_join(path, PATH_MAX, out->dir, pl_outputs[PL_OUT_CHECKPOINT].name);
    *ctx = path;
    return 0;
}

static int stage_checkpoint(pl_sim_t *sim, void *ctx, pl_err_t *err) { return pl_checkpoint_write(sim, ctx, err); }

static int add_stages(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    const long long interval = sim->scene.output.checkpoint_interval;
    if (interval <= 0) return 0;
    pl_stage_t ck = {.name = "checkpoint", .fn = stage_checkpoint, .ctx = ctx, .interval = interval,
                     .phase = PL_PHASE_AFTER, .slot = PL_SLOT_WRITE, .writes = 1};
    return pl_sim_add_stage(sim, &ck, err);
}

static int finish(pl_sim_t *sim, void *ctx, const pl_writer_out_t *out, pl_err_t *err)
{
    (void)out;
    return pl_checkpoint_write(sim, ctx, err);
}

const pl_writer_t pl_writer_checkpoint = {
    .file = PL_OUT_CHECKPOINT,
    .wanted = wanted,
    .open = open_path,
    .add_stages = add_stages,
    .finish = finish,
    .close = free,
};
