/* The time-averaged fields as a writer row (peloid/writer.h): fields.h5
 * (H5MD) and fields.xdmf beside it (src/app/fields_io.c) at the end of a run
 * with output.fields_interval, from the fluid's accumulators (its sampling
 * stage, src/fluid/fluid_stages.c); none when no sample was taken. */
#include <limits.h>
#include <stdlib.h>

#include "peloid/io.h"
#include "peloid/progress.h"
#include "peloid/writer.h"

static int wanted(const pl_sim_t *sim)
{
    long long samples;
    return pl_srd_fields(sim->srd, &samples) != NULL;
}

/* ctx: the path of fields.h5 */
static int open_path(pl_sim_t *sim, const pl_writer_out_t *out, void **ctx, pl_err_t *err)
{
    (void)sim;
    char *path = malloc(PATH_MAX);
    if (!path) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    pl_path_join(path, PATH_MAX, out->dir, pl_outputs[PL_OUT_FIELDS].name);
    *ctx = path;
    return 0;
}

static int finish(pl_sim_t *sim, void *ctx, const pl_writer_out_t *out, pl_err_t *err)
{
    long long samples;
    pl_srd_fields(sim->srd, &samples);
    if (samples == 0) {
        pl_progress_note(out->pg, "no field sample was taken (output.fields_start = %lld, last step %lld): "
                                  "fields.h5 not written", sim->scene.output.fields_start, sim->step);
        return 0;
    }
    return pl_fields_write(sim, ctx, err);
}

const pl_writer_t pl_writer_fields = {
    .file = PL_OUT_FIELDS,
    .wanted = wanted,
    .open = open_path,
    .finish = finish,
    .close = free,
};
