/* HDF5 checkpoint: the complete dynamic state, so that N steps + restart +
 * N steps equals 2N steps bitwise.  Random numbers are counter based (keyed
 * by step), so the state is positions, velocities (in their sorted order:
 * the stable sort depends on it), tracking arrays, step, field accumulators,
 * with colloids the group /colloids (src/checkpoint_colloid.c), and the wall
 * and coupling run counters (src/checkpoint_coupling.c).
 * Written to "<path>.tmp" and renamed.  No object carries a time stamp, so
 * the same state gives the same bytes. */
#include <hdf5.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "checkpoint_h5.h"
#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/h5.h"
#include "peloid/io.h"

#define H5_REAL (sizeof(pl_real) == sizeof(double) ? H5T_NATIVE_DOUBLE : H5T_NATIVE_FLOAT)

static const char *const rnames[3] = {"x", "y", "z"};
static const char *const vnames[3] = {"vx", "vy", "vz"};
static const char *const dnames[3] = {"disp_x", "disp_y", "disp_z"};

int pl_ckpt_write_1d(hid_t g, const char *name, hid_t type, const void *data, size_t n)
{
    hsize_t dims[1] = {n};
    hid_t sp = H5Screate_simple(1, dims, NULL);
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_obj_track_times(dcpl, 0); /* no time stamps: same state => same bytes */
    hid_t ds = H5Dcreate2(g, name, type, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    H5Pclose(dcpl);
    herr_t st = ds < 0 ? -1 : n ? H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : 0;
    if (ds >= 0) H5Dclose(ds);
    H5Sclose(sp);
    return st < 0 ? -1 : 0;
}

int pl_ckpt_read_1d(hid_t g, const char *name, hid_t type, void *data, size_t n)
{
    hid_t ds = H5Dopen2(g, name, H5P_DEFAULT);
    if (ds < 0) return -1;
    hid_t sp = H5Dget_space(ds);
    hsize_t dims[1] = {0};
    int ok = H5Sget_simple_extent_ndims(sp) == 1 && H5Sget_simple_extent_dims(sp, dims, NULL) == 1 &&
             dims[0] == n;
    herr_t st = !ok ? -1 : n ? H5Dread(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : 0;
    H5Sclose(sp);
    H5Dclose(ds);
    return st < 0 ? -1 : 0;
}

int pl_ckpt_attr_i64(hid_t obj, const char *name, long long *v, int n, int write)
{
    hsize_t dims[1] = {(hsize_t)n};
    if (!write) {
        hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
        if (a < 0) return -1;
        hid_t sp = H5Aget_space(a);
        herr_t st = H5Sget_simple_extent_npoints(sp) == n ? H5Aread(a, H5T_NATIVE_LLONG, v) : -1;
        H5Sclose(sp);
        H5Aclose(a);
        return st < 0 ? -1 : 0;
    }
    hid_t sp = H5Screate_simple(1, dims, NULL);
    hid_t a = H5Acreate2(obj, name, H5T_NATIVE_LLONG, sp, H5P_DEFAULT, H5P_DEFAULT);
    herr_t st = a >= 0 ? H5Awrite(a, H5T_NATIVE_LLONG, v) : -1;
    if (a >= 0) H5Aclose(a);
    H5Sclose(sp);
    return st < 0 ? -1 : 0;
}

hid_t pl_ckpt_group_create(hid_t f, const char *name) { return pl_h5_group(f, name); }

int pl_checkpoint_write(const pl_sim_t *sim, const char *path, pl_err_t *err)
{
    char tmp[PATH_MAX + 8];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    hid_t f = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (f < 0) return pl_err_set(err, PL_ERR_IO, "%s: cannot create HDF5 file", tmp);
    const pl_fluid_t *fl = &sim->fluid;
    const pl_scene_t *sc = &sim->scene;
    long long meta[8] = {sim->step, sc->run.seed, (long long)fl->n, sc->box.cells[0], sc->box.cells[1],
                         sc->box.cells[2], fl->tracked, (long long)sizeof(pl_real)};
    long long ncol = sim->colloids ? (long long)sim->colloids->n : 0;
    long long samples = sim->field_samples;
    int bad = pl_ckpt_attr_i64(f, "peloid_checkpoint", meta, 8, 1);
    bad |= pl_ckpt_attr_i64(f, "field_samples", &samples, 1, 1);
    bad |= pl_ckpt_attr_i64(f, "colloid_count", &ncol, 1, 1);
    /* only with x/y walls, so that other checkpoints stay as they were */
    long long walls_xy = sc->box.walls_xy;
    if (walls_xy != PL_WALLS_NONE) bad |= pl_ckpt_attr_i64(f, "walls_xy", &walls_xy, 1, 1);
    hid_t g = pl_ckpt_group_create(f, "fluid");
    for (int d = 0; d < 3 && g >= 0; ++d) {
        bad |= pl_ckpt_write_1d(g, rnames[d], H5_REAL, fl->r[d], fl->n);
        bad |= pl_ckpt_write_1d(g, vnames[d], H5_REAL, fl->v[d], fl->n);
        if (fl->tracked) bad |= pl_ckpt_write_1d(g, dnames[d], H5T_NATIVE_DOUBLE, fl->disp[d], fl->n);
    }
    if (fl->tracked && g >= 0) bad |= pl_ckpt_write_1d(g, "id", H5T_NATIVE_UINT32, fl->id, fl->n);
    if (sim->field_acc) {
        size_t L3 = (size_t)sc->box.cells[0] * (size_t)sc->box.cells[1] * (size_t)sc->box.cells[2];
        bad |= pl_ckpt_write_1d(f, "field_accumulator", H5T_NATIVE_INT64, sim->field_acc, 4 * L3);
    }
    if (g >= 0) H5Gclose(g);
    else bad = 1;
    if (sim->colloids) bad |= pl_ckpt_colloid_write(f, sim->colloids);
    bad |= pl_ckpt_coupling_write(f, sim);
    /* kT_cell of the last collision: the thermo row at the restart step */
    bad |= pl_ckpt_write_1d(f, "kT_cell", H5T_NATIVE_DOUBLE, &sim->last_kT_meas, 1);
    if (H5Fclose(f) < 0) bad = 1;
    if (bad) return pl_err_set(err, PL_ERR_IO, "%s: writing the checkpoint failed", tmp);
    if (rename(tmp, path)) return pl_err_set(err, PL_ERR_IO, "%s: cannot rename to %s", tmp, path);
    return 0;
}

int pl_checkpoint_read(pl_sim_t *sim, const char *path, pl_err_t *err)
{
    H5E_auto2_t old_fn;
    void *old_data;
    H5Eget_auto2(H5E_DEFAULT, &old_fn, &old_data);
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL); /* our own messages only */
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    int rc = 0;
    if (f < 0) {
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: cannot open checkpoint (missing or not HDF5)", path);
        goto out;
    }
    sim->fluid_sorted = 0; /* cell_start is not stored */
    long long meta[8];
    pl_fluid_t *fl = &sim->fluid;
    const pl_scene_t *sc = &sim->scene;
    if (pl_ckpt_attr_i64(f, "peloid_checkpoint", meta, 8, 0)) {
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: not a peloid checkpoint", path);
        goto close;
    }
    if (meta[1] != sc->run.seed || meta[2] != (long long)fl->n || meta[3] != sc->box.cells[0] ||
        meta[4] != sc->box.cells[1] || meta[5] != sc->box.cells[2] || meta[6] != fl->tracked ||
        meta[7] != (long long)sizeof(pl_real)) {
        rc = pl_err_set(err, PL_ERR_INPUT,
                        "%s: checkpoint does not match the scene (seed %lld/%lld, particles %lld/%zu, "
                        "box %lldx%lldx%lld, tracked %lld/%d, real size %lld/%zu)",
                        path, meta[1], sc->run.seed, meta[2], fl->n, meta[3], meta[4], meta[5], meta[6],
                        fl->tracked, meta[7], sizeof(pl_real));
        goto close;
    }
    /* fluid-only checkpoints written before colloids existed have no count */
    long long ncol = 0, nscene = sim->colloids ? (long long)sim->colloids->n : 0;
    if (H5Aexists(f, "colloid_count") > 0 && pl_ckpt_attr_i64(f, "colloid_count", &ncol, 1, 0)) {
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: unreadable attribute colloid_count", path);
        goto close;
    }
    if (ncol != nscene) {
        rc = pl_err_set(err, PL_ERR_INPUT,
                        "%s: checkpoint does not match the scene: it holds %lld colloids, the scene "
                        "has %lld (colloids.count)", path, ncol, nscene);
        goto close;
    }
    /* checkpoints without the attribute come from scenes without x/y walls */
    long long walls_xy = PL_WALLS_NONE;
    if (H5Aexists(f, "walls_xy") > 0 && pl_ckpt_attr_i64(f, "walls_xy", &walls_xy, 1, 0)) {
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: unreadable attribute walls_xy", path);
        goto close;
    }
    if (walls_xy != sc->box.walls_xy) {
        static const char *const wn[3] = {"none", "noslip", "slip"};
        rc = pl_err_set(err, PL_ERR_INPUT,
                        "%s: checkpoint does not match the scene: box.walls_xy \"%s\" there, \"%s\" "
                        "in the scene", path, walls_xy >= 0 && walls_xy < 3 ? wn[walls_xy] : "?",
                        wn[sc->box.walls_xy]);
        goto close;
    }
    sim->step = meta[0];
    int bad = pl_ckpt_attr_i64(f, "field_samples", &sim->field_samples, 1, 0);
    hid_t g = H5Gopen2(f, "fluid", H5P_DEFAULT);
    for (int d = 0; d < 3 && g >= 0; ++d) {
        bad |= pl_ckpt_read_1d(g, rnames[d], H5_REAL, fl->r[d], fl->n);
        bad |= pl_ckpt_read_1d(g, vnames[d], H5_REAL, fl->v[d], fl->n);
        if (fl->tracked) bad |= pl_ckpt_read_1d(g, dnames[d], H5T_NATIVE_DOUBLE, fl->disp[d], fl->n);
    }
    if (fl->tracked && g >= 0) bad |= pl_ckpt_read_1d(g, "id", H5T_NATIVE_UINT32, fl->id, fl->n);
    if (g >= 0) H5Gclose(g);
    else bad = 1;
    if (sim->field_acc) {
        size_t L3 = (size_t)sc->box.cells[0] * (size_t)sc->box.cells[1] * (size_t)sc->box.cells[2];
        if (H5Lexists(f, "field_accumulator", H5P_DEFAULT) > 0)
            bad |= pl_ckpt_read_1d(f, "field_accumulator", H5T_NATIVE_INT64, sim->field_acc, 4 * L3);
        else
            sim->field_samples = 0;
    }
    if (bad) {
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: checkpoint is incomplete or corrupt", path);
        goto close;
    }
    if (sim->colloids) rc = pl_ckpt_colloid_read(f, sim->colloids, sc, path, err);
    /* the colloid set-up the reader redoes knows nothing of the coupling:
     * coupled colloids exchange energy with the fluid, no NVE drift guard
     * (as pl_coupling_create decided) */
    if (!rc && sim->colloids && sim->coupling && sim->coupling->method != PL_COUPLE_NONE)
        sim->colloids->nve = 0;
    if (!rc) rc = pl_ckpt_coupling_read(f, sim, path, err);
    if (!rc && H5Lexists(f, "kT_cell", H5P_DEFAULT) > 0 &&
        pl_ckpt_read_1d(f, "kT_cell", H5T_NATIVE_DOUBLE, &sim->last_kT_meas, 1))
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: unreadable kT_cell", path);
close:
    H5Fclose(f);
out:
    H5Eset_auto2(H5E_DEFAULT, old_fn, old_data);
    return rc;
}
