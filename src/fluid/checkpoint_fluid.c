/* The fluid's own items of the checkpoint (src/core/checkpoint.c writes the
 * particles, the core's typed view): the field accumulator and its sample
 * count, and kT_cell of the last collision (the thermo row at the restart
 * step).  Their places in the file are the ones they had when the core wrote
 * them, so that every checkpoint keeps its bytes: field_samples among the
 * root's attributes (checkpoint_attrs), field_accumulator right after the
 * /fluid group (the fluid is the first module), kT_cell after every module's
 * items (checkpoint_write_last).  On reading, the fluid forgets its cell
 * order (the restart replaced its particles) and range-checks what it read
 * and the velocities the core read (the fluid guard's speed bound). */
#include <hdf5.h>
#include <math.h>

#include "checkpoint_h5.h"
#include "peloid/checkpoint.h"
#include "srd_state.h"

static const char *const vnames[3] = {"vx", "vy", "vz"};

static size_t cells(const pl_scene_t *sc)
{
    return (size_t)sc->box.cells[0] * (size_t)sc->box.cells[1] * (size_t)sc->box.cells[2];
}

int pl_fluid_ckpt_attrs(int64_t f, const pl_sim_t *sim)
{
    long long samples = *pl_srd_kept(sim->srd).field_samples;
    return pl_ckpt_attr_i64((hid_t)f, "field_samples", &samples, 1, 1);
}

int pl_fluid_ckpt_write(int64_t f, const pl_sim_t *sim)
{
    const pl_srd_kept_t kept = pl_srd_kept(sim->srd);
    if (!kept.field_acc) return 0;
    return pl_ckpt_write_1d((hid_t)f, "field_accumulator", H5T_NATIVE_INT64, kept.field_acc, 4 * cells(&sim->scene));
}

int pl_fluid_ckpt_write_last(int64_t f, const pl_sim_t *sim)
{
    return pl_ckpt_write_1d((hid_t)f, "kT_cell", H5T_NATIVE_DOUBLE, pl_srd_kept(sim->srd).kT_cell, 1);
}

/* The velocities the core read, against the fluid guard's speed bound. */
static int check_speeds(const pl_sim_t *sim, const char *path, pl_err_t *err)
{
    const pl_fluid_t *fl = &sim->fluid;
    const double vmax = pl_srd_speed_bound(sim->srd);
    for (size_t i = 0; i < fl->n; ++i) {
        double v2 = 0.0;
        for (int d = 0; d < 3; ++d) {
            const double v = fl->v[d][i];
            if (!isfinite(v))
                return pl_err_set(err, PL_ERR_INPUT, "%s: fluid/%s[%zu] = %g is not finite (corrupt checkpoint)",
                                  path, vnames[d], i, v);
            v2 += v * v;
        }
        if (!(v2 <= vmax * vmax))
            return pl_err_set(err, PL_ERR_INPUT,
                              "%s: fluid particle %zu has speed %.4g; bound %.4g (the fluid guard's, src/"
                              "fluid_guard.c; corrupt checkpoint)", path, i, sqrt(v2), vmax);
    }
    return 0;
}

int pl_fluid_ckpt_read(int64_t file, pl_sim_t *sim, const char *path, pl_err_t *err)
{
    const hid_t f = (hid_t)file;
    pl_srd_order_lost(sim->srd); /* the cell order is not stored */
    const pl_srd_kept_t kept = pl_srd_kept(sim->srd);
    if (pl_ckpt_attr_i64(f, "field_samples", kept.field_samples, 1, 0))
        return pl_err_set(err, PL_ERR_INPUT, "%s: unreadable attribute field_samples", path);
    int rc = 0;
    if (kept.field_acc) {
        if (H5Lexists(f, "field_accumulator", H5P_DEFAULT) > 0)
            rc = pl_ckpt_read_1d(f, "field_accumulator", H5T_NATIVE_INT64, kept.field_acc, 4 * cells(&sim->scene),
                                 path, err);
        else
            *kept.field_samples = 0;
    }
    if (!rc && H5Lexists(f, "kT_cell", H5P_DEFAULT) > 0)
        rc = pl_ckpt_read_1d(f, "kT_cell", H5T_NATIVE_DOUBLE, kept.kT_cell, 1, path, err);
    if (rc || (rc = check_speeds(sim, path, err))) return rc;
    if (kept.field_acc) {
        const size_t L3 = cells(&sim->scene);
        for (size_t c = 0; c < L3; ++c)
            if (kept.field_acc[c] < 0)
                return pl_err_set(err, PL_ERR_INPUT, "%s: field_accumulator count of cell %zu is negative (%lld)",
                                  path, c, (long long)kept.field_acc[c]);
    }
    if (*kept.field_samples < 0 || *kept.field_samples > sim->step)
        return pl_err_set(err, PL_ERR_INPUT, "%s: field_samples = %lld; allowed 0 .. step %lld", path,
                          *kept.field_samples, sim->step);
    if (!(*kept.kT_cell >= 0.0 && isfinite(*kept.kT_cell)))
        return pl_err_set(err, PL_ERR_INPUT, "%s: kT_cell = %g; allowed finite >= 0", path, *kept.kT_cell);
    return 0;
}
