/* Colloid trajectory in H5MD layout (de Buyl et al., H5MD 1.1), readable with
 * h5py:
 *   /h5md (version = [1, 1]; author, creator groups)
 *   /particles/colloids/box        dimension = 3, boundary, edges
 *   /particles/colloids/{position,velocity,orientation,angular_velocity,image}
 *        /step (T), /time (T), /value (T x N x 3, orientation T x N x 4)
 *   /particles/colloids/radius, mass  (time independent, N)
 * Written to PATH.tmp and renamed to PATH on close (DESIGN.md: outputs are
 * written atomically); an existing PATH is refused unless overwrite. */
#include <errno.h>
#include <hdf5.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "peloid/colloid.h"
#include "peloid/h5.h"
#include "peloid/io.h"

enum { NTS = 5 };
static const char *const TS_NAMES[NTS] = {"position", "velocity", "orientation", "angular_velocity", "image"};

struct pl_colloid_traj {
    hid_t file;
    hid_t val[NTS], step[NTS], time[NTS];
    hsize_t nframes;
    size_t n;
    char path[PATH_MAX], tmp[PATH_MAX + 8];
    double *buf;
    int *ibuf;
};

static hid_t ext_dataset(hid_t g, const char *name, hid_t type, int rank, hsize_t n, hsize_t w)
{
    hsize_t dims[3] = {0, n, w}, maxd[3] = {H5S_UNLIMITED, n, w}, chunk[3] = {1, n ? n : 1, w};
    hid_t sp = H5Screate_simple(rank, dims, maxd);
    hid_t pl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(pl, rank, chunk);
    hid_t d = H5Dcreate2(g, name, type, sp, H5P_DEFAULT, pl, H5P_DEFAULT);
    H5Pclose(pl);
    H5Sclose(sp);
    return d;
}

static int fixed_1d(hid_t g, const char *name, const double *v, hsize_t n)
{
    hid_t sp = H5Screate_simple(1, &n, NULL);
    hid_t d = H5Dcreate2(g, name, H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    int bad = d < 0 || H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0;
    if (d >= 0 && H5Dclose(d) < 0) bad = 1;
    H5Sclose(sp);
    return bad ? -1 : 0;
}

/* Closes every handle of t (none stays open for HDF5's exit handler) and
 * frees it; 0 or -1. */
static int traj_release(pl_colloid_traj_t *t)
{
    int bad = 0;
    for (int k = 0; k < NTS; ++k) {
        if (t->val[k] > 0 && H5Dclose(t->val[k]) < 0) bad = 1;
        if (t->step[k] > 0 && H5Dclose(t->step[k]) < 0) bad = 1;
        if (t->time[k] > 0 && H5Dclose(t->time[k]) < 0) bad = 1;
    }
    if (t->file > 0 && H5Fclose(t->file) < 0) bad = 1;
    free(t->buf);
    free(t->ibuf);
    free(t);
    return bad ? -1 : 0;
}

int pl_colloid_traj_open(const char *path, const pl_colloid_t *c, int overwrite,
                         pl_colloid_traj_t **out, pl_err_t *err)
{
    if (!overwrite && access(path, F_OK) == 0)
        return pl_err_set(err, PL_ERR_IO, "%s exists; not overwritten without --force", path);
    pl_colloid_traj_t *t = calloc(1, sizeof *t);
    if (!t) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    snprintf(t->path, sizeof t->path, "%s", path);
    snprintf(t->tmp, sizeof t->tmp, "%s.tmp", path);
    t->n = c->n;
    t->buf = malloc((c->n ? c->n : 1) * 4 * sizeof(double));
    t->ibuf = malloc((c->n ? c->n : 1) * 3 * sizeof(int));
    pl_h5_quiet();
    errno = 0;
    t->file = H5Fcreate(t->tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (t->file < 0 || !t->buf || !t->ibuf) {
        char why[256];
        pl_h5_error_text(why, sizeof why);
        int oom = !t->buf || !t->ibuf;
        traj_release(t);
        return oom ? pl_err_set(err, PL_ERR_NOMEM, "out of memory") :
                     pl_err_set(err, PL_ERR_IO, "%s: cannot create HDF5 file: %s", t->tmp, why);
    }
    int bad = pl_h5_h5md_header(t->file);
    hid_t sp, a;
    hid_t parts = H5Gcreate2(t->file, "particles", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    hid_t col = H5Gcreate2(parts, "colloids", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    hid_t box = H5Gcreate2(col, "box", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    int three = 3;
    sp = H5Screate(H5S_SCALAR);
    a = H5Acreate2(box, "dimension", H5T_NATIVE_INT, sp, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_INT, &three);
    H5Aclose(a);
    H5Sclose(sp);
    /* boundary: fixed-length strings, 3 entries */
    hid_t st = H5Tcopy(H5T_C_S1);
    H5Tset_size(st, 9);
    char bnd[3][9] = {"periodic", "periodic", "periodic"};
    for (int k = 0; k < 3; ++k)
        if (!c->periodic[k]) snprintf(bnd[k], 9, "none");
    hsize_t n3 = 3;
    sp = H5Screate_simple(1, &n3, NULL);
    a = H5Acreate2(box, "boundary", st, sp, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, st, bnd);
    H5Aclose(a);
    H5Tclose(st);
    H5Sclose(sp);
    bad |= fixed_1d(box, "edges", c->box, 3);
    H5Gclose(box);
    bad |= fixed_1d(col, "radius", c->rad, c->n);
    bad |= fixed_1d(col, "mass", c->mass, c->n);
    for (int k = 0; k < NTS; ++k) {
        hid_t tg = H5Gcreate2(col, TS_NAMES[k], H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        hsize_t w = k == 2 ? 4 : 3;
        t->val[k] = ext_dataset(tg, "value", k == 4 ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE, 3, c->n, w);
        t->step[k] = ext_dataset(tg, "step", H5T_NATIVE_LLONG, 1, 0, 0);
        t->time[k] = ext_dataset(tg, "time", H5T_NATIVE_DOUBLE, 1, 0, 0);
        bad |= tg < 0 || t->val[k] < 0 || t->step[k] < 0 || t->time[k] < 0;
        if (tg >= 0) H5Gclose(tg);
    }
    if (col >= 0) H5Gclose(col);
    if (parts >= 0) H5Gclose(parts);
    if (bad || H5Fflush(t->file, H5F_SCOPE_GLOBAL) < 0) {
        char why[256], tmp[PATH_MAX + 8];
        pl_h5_error_text(why, sizeof why);
        snprintf(tmp, sizeof tmp, "%s", t->tmp);
        traj_release(t);
        unlink(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot write the trajectory header: %s", path, why);
    }
    *out = t;
    return 0;
}

static int append(hid_t d, hid_t type, int rank, hsize_t frame, hsize_t n, hsize_t w, const void *v)
{
    hsize_t dims[3] = {frame + 1, n, w}, start[3] = {frame, 0, 0}, cnt[3] = {1, n, w};
    if (H5Dset_extent(d, dims) < 0) return -1;
    hid_t fs = H5Dget_space(d);
    H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, cnt, NULL);
    hid_t ms = H5Screate_simple(rank, cnt, NULL);
    herr_t r = H5Dwrite(d, type, ms, fs, H5P_DEFAULT, v);
    H5Sclose(ms);
    H5Sclose(fs);
    return r < 0 ? -1 : 0;
}

int pl_colloid_traj_write(pl_colloid_traj_t *t, const pl_colloid_t *c, long long step, double time,
                          pl_err_t *err)
{
    const double *src[5][4] = {{c->x, c->y, c->z, NULL}, {c->vx, c->vy, c->vz, NULL},
                               {c->q0, c->q1, c->q2, c->q3}, {c->wx, c->wy, c->wz, NULL}};
    int bad = 0;
    for (int k = 0; k < NTS; ++k) {
        hsize_t w = k == 2 ? 4 : 3;
        if (k == 4) {
            for (size_t i = 0; i < t->n; ++i) {
                t->ibuf[3 * i] = c->ix[i], t->ibuf[3 * i + 1] = c->iy[i], t->ibuf[3 * i + 2] = c->iz[i];
            }
            bad |= append(t->val[k], H5T_NATIVE_INT, 3, t->nframes, t->n, w, t->ibuf);
        } else {
            for (size_t i = 0; i < t->n; ++i)
                for (hsize_t a = 0; a < w; ++a) t->buf[w * i + a] = src[k][a][i];
            bad |= append(t->val[k], H5T_NATIVE_DOUBLE, 3, t->nframes, t->n, w, t->buf);
        }
        bad |= append(t->step[k], H5T_NATIVE_LLONG, 1, t->nframes, 1, 1, &step);
        bad |= append(t->time[k], H5T_NATIVE_DOUBLE, 1, t->nframes, 1, 1, &time);
    }
    t->nframes++;
    if (!bad) {
        errno = 0;
        bad = H5Fflush(t->file, H5F_SCOPE_GLOBAL) < 0;
    }
    if (bad) {
        char why[256];
        pl_h5_error_text(why, sizeof why);
        return pl_err_set(err, PL_ERR_IO, "%s: writing the frame of step %lld failed: %s", t->tmp, step, why);
    }
    return 0;
}

int pl_colloid_traj_close(pl_colloid_traj_t *t, pl_err_t *err)
{
    if (!t) return 0;
    char tmp[PATH_MAX + 8], path[PATH_MAX], why[256] = "";
    snprintf(tmp, sizeof tmp, "%s", t->tmp);
    snprintf(path, sizeof path, "%s", t->path);
    errno = 0;
    int rc = traj_release(t);
    if (rc) pl_h5_error_text(why, sizeof why);
    else if (pl_fsync_path(tmp, 0) || rename(tmp, path) || pl_fsync_path(path, 1)) {
        rc = -1;
        snprintf(why, sizeof why, "%s", strerror(errno));
    }
    if (rc) pl_err_set(err, PL_ERR_IO, "%s: cannot finish the trajectory: %s", path, why);
    return rc ? PL_ERR_IO : 0;
}
