/* Resume in place of the H5MD colloid trajectory (src/io/colloid_h5md.c):
 * the file a killed run left (PATH.tmp) or a copy of PATH is opened, every
 * time series (the particles', the box edges', the cluster ids', the frame
 * interval's) is cut to the frames of steps before the restart step, and
 * writing continues after them. */
#include <errno.h>
#include <hdf5.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "colloid_h5md_priv.h"
#include "peloid/h5.h"
#include "peloid/io.h"

/* Opens the time series of element k (group g) of a file being continued. */
static int open_element(pl_colloid_traj_t *t, hid_t g, int k)
{
    hid_t tg = H5Gopen2(g, TS_NAMES[k], H5P_DEFAULT);
    if (tg < 0) return -1;
    t->val[k] = H5Dopen2(tg, "value", H5P_DEFAULT);
    t->step[k] = H5Dopen2(tg, "step", H5P_DEFAULT);
    t->time[k] = H5Dopen2(tg, "time", H5P_DEFAULT);
    int bad = t->val[k] < 0 || t->step[k] < 0 || t->time[k] < 0;
    if (H5Gclose(tg) < 0) bad = 1;
    return bad ? -1 : 0;
}

/* Frames of steps < keep (their steps increase) of the time series whose
 * step dataset is d; -1 when it cannot be read. */
static long long frames_before(hid_t d, long long keep)
{
    hid_t sp = H5Dget_space(d);
    hssize_t nf = sp >= 0 ? H5Sget_simple_extent_npoints(sp) : -1;
    if (sp >= 0) H5Sclose(sp);
    if (nf < 0) return -1;
    long long *st = malloc((size_t)(nf ? nf : 1) * sizeof *st), n = 0;
    if (!st || (nf > 0 && H5Dread(d, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, st) < 0)) n = -1;
    while (n >= 0 && n < nf && st[n] < keep) ++n;
    free(st);
    return n;
}

/* Cuts value, step and time of one time series to nf frames. */
static int cut_series(hid_t val, hid_t step, hid_t time, hsize_t nf)
{
    hsize_t dims[3];
    hid_t sp = H5Dget_space(val);
    int rank = sp >= 0 ? H5Sget_simple_extent_dims(sp, dims, NULL) : -1;
    if (sp >= 0) H5Sclose(sp);
    if (rank < 1) return -1;
    dims[0] = nf;
    return H5Dset_extent(val, dims) < 0 || H5Dset_extent(step, &nf) < 0 || H5Dset_extent(time, &nf) < 0 ? -1 : 0;
}

/* /observables/dt of a continued trajectory, cut to its nf kept frames;
 * -1 when the file has none (written before it existed: another layout). */
static int dt_resume(pl_colloid_traj_t *t, hsize_t nf)
{
    if (H5Lexists(t->file, "observables", H5P_DEFAULT) <= 0 ||
        H5Lexists(t->file, "observables/dt", H5P_DEFAULT) <= 0)
        return -1;
    hid_t g = H5Gopen2(t->file, "observables/dt", H5P_DEFAULT);
    t->dt_val = g >= 0 ? H5Dopen2(g, "value", H5P_DEFAULT) : -1;
    t->dt_step = g >= 0 ? H5Dopen2(g, "step", H5P_DEFAULT) : -1;
    t->dt_time = g >= 0 ? H5Dopen2(g, "time", H5P_DEFAULT) : -1;
    int bad = t->dt_val < 0 || t->dt_step < 0 || t->dt_time < 0 || cut_series(t->dt_val, t->dt_step, t->dt_time, nf);
    if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
}

/* Continues the trajectory in t->tmp (opened in t->file): keeps the frames
 * of steps < keep, opens the datasets to append to; -1 when the file is not
 * one of this run's colloids. */
static int traj_resume(pl_colloid_traj_t *t, long long keep)
{
    hid_t col = H5Gopen2(t->file, "particles/colloids", H5P_DEFAULT);
    hid_t box = col >= 0 ? H5Gopen2(col, "box", H5P_DEFAULT) : -1;
    int bad = box < 0;
    for (int k = 0; k < NTS && !bad; ++k) bad = open_element(t, k == TS_EDGES ? box : col, k);
    hsize_t dims[3] = {0, 0, 0};
    hid_t sp = bad ? -1 : H5Dget_space(t->val[0]);
    bad |= sp < 0 || H5Sget_simple_extent_ndims(sp) != 3 || H5Sget_simple_extent_dims(sp, dims, NULL) < 0 ||
           dims[1] != t->n;
    if (sp >= 0) H5Sclose(sp);
    long long nf = bad ? -1 : frames_before(t->step[0], keep);
    bad |= nf < 0;
    for (int k = 0; k < NTS && !bad; ++k) bad = cut_series(t->val[k], t->step[k], t->time[k], (hsize_t)nf);
    if (!bad && nf > 0) { /* the last kept frame's step */
        hsize_t at = (hsize_t)nf - 1, one = 1;
        hid_t fs = H5Dget_space(t->step[0]), ms = H5Screate_simple(1, &one, NULL);
        H5Sselect_hyperslab(fs, H5S_SELECT_SET, &at, NULL, &one, NULL);
        bad = H5Dread(t->step[0], H5T_NATIVE_LLONG, ms, fs, H5P_DEFAULT, &t->last_step) < 0;
        H5Sclose(ms);
        H5Sclose(fs);
    }
    t->nframes = bad ? 0 : (hsize_t)nf;
    if (!bad && col >= 0 && H5Lexists(col, "cluster_id", H5P_DEFAULT) > 0) {
        hid_t cg = H5Gopen2(col, "cluster_id", H5P_DEFAULT);
        t->cid_val = cg >= 0 ? H5Dopen2(cg, "value", H5P_DEFAULT) : -1;
        t->cid_step = cg >= 0 ? H5Dopen2(cg, "step", H5P_DEFAULT) : -1;
        t->cid_time = cg >= 0 ? H5Dopen2(cg, "time", H5P_DEFAULT) : -1;
        long long nc = t->cid_step >= 0 ? frames_before(t->cid_step, keep) : -1;
        bad = t->cid_val < 0 || t->cid_time < 0 || nc < 0 ||
              cut_series(t->cid_val, t->cid_step, t->cid_time, (hsize_t)nc) ||
              !(t->cid_buf = malloc((t->n ? t->n : 1) * sizeof(int32_t)));
        t->cid_frames = bad ? 0 : (hsize_t)nc;
        if (cg >= 0 && H5Gclose(cg) < 0) bad = 1;
    }
    if (!bad) bad = dt_resume(t, (hsize_t)nf);
    if (box >= 0 && H5Gclose(box) < 0) bad = 1;
    if (col >= 0 && H5Gclose(col) < 0) bad = 1;
    return bad || H5Fflush(t->file, H5F_SCOPE_GLOBAL) < 0 ? -1 : 0;
}

int pl_colloid_traj_resume_open(pl_colloid_traj_t *t, long long keep, pl_err_t *err)
{
    if (access(t->tmp, F_OK) == 0) {
        t->file = H5Fopen(t->tmp, H5F_ACC_RDWR, H5P_DEFAULT);
        if (t->file < 0 && access(t->path, F_OK) != 0) {
            char why[256];
            pl_h5_error_text(why, sizeof why);
            return pl_err_set(err, PL_ERR_IO, "%s: cannot open the trajectory to continue: %s", t->tmp, why);
        }
    }
    if (t->file < 0) {
        if (access(t->path, F_OK) != 0) return 1;
        if (pl_file_copy(t->path, t->tmp, err)) return PL_ERR_IO;
        t->file = H5Fopen(t->tmp, H5F_ACC_RDWR, H5P_DEFAULT);
    }
    if (t->file < 0 || traj_resume(t, keep)) {
        char why[256];
        pl_h5_error_text(why, sizeof why);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot continue the trajectory (frames before step %lld of %zu "
                          "colloids): %s", t->path, keep, t->n, why[0] ? why : "another layout");
    }
    return 0;
}
