/* HDF5 helpers of the checkpoint writer and reader (checkpoint_h5.h):
 * groups without time stamps, 1-d datasets carrying their FNV-1a checksum,
 * integer and string attributes.  The bottom of the checkpoint modules:
 * checkpoint.c, checkpoint_colloid.c, checkpoint_coupling.c and
 * checkpoint_scene.c use these and nothing uses them back. */
#include <hdf5.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint_h5.h"
#include "peloid/h5.h"

hid_t pl_ckpt_group_create(hid_t f, const char *name) { return pl_h5_group(f, name); }

/* FNV-1a, 64 bit (Fowler, Noll, Vo): offset basis and prime */
uint64_t pl_ckpt_fnv1a_more(uint64_t h, const void *data, size_t n)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 1099511628211ULL;
    }
    return h;
}

uint64_t pl_ckpt_fnv1a(const void *data, size_t n) { return pl_ckpt_fnv1a_more(14695981039346656037ULL, data, n); }

int pl_ckpt_write_1d(hid_t g, const char *name, hid_t type, const void *data, size_t n)
{
    hsize_t dims[1] = {n};
    hid_t sp = H5Screate_simple(1, dims, NULL);
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_obj_track_times(dcpl, 0); /* no time stamps: same state => same bytes */
    hid_t ds = H5Dcreate2(g, name, type, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    H5Pclose(dcpl);
    herr_t st = ds < 0 ? -1 : n ? H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : 0;
    long long sum = (long long)pl_ckpt_fnv1a(data, n * H5Tget_size(type));
    if (st >= 0 && pl_ckpt_attr_i64(ds, "fnv1a64", &sum, 1, 1)) st = -1;
    if (ds >= 0 && H5Dclose(ds) < 0) st = -1;
    H5Sclose(sp);
    return st < 0 ? -1 : 0;
}

int pl_ckpt_read_1d(hid_t g, const char *name, hid_t type, void *data, size_t n, const char *path,
                    pl_err_t *err)
{
    char where[256];
    if (H5Iget_name(g, where, sizeof where) < 0) where[0] = '\0';
    const char *sep = strcmp(where, "/") ? "/" : "";
    if (H5Lexists(g, name, H5P_DEFAULT) <= 0)
        return pl_err_set(err, PL_ERR_INPUT, "%s: checkpoint has no dataset %s%s%s", path, where, sep, name);
    hid_t ds = H5Dopen2(g, name, H5P_DEFAULT);
    if (ds < 0) return pl_err_set(err, PL_ERR_INPUT, "%s: cannot open dataset %s%s%s", path, where, sep, name);
    hid_t sp = H5Dget_space(ds);
    hsize_t dims[1] = {0};
    int ok = H5Sget_simple_extent_ndims(sp) == 1 && H5Sget_simple_extent_dims(sp, dims, NULL) == 1 &&
             dims[0] == n;
    herr_t st = !ok ? -1 : n ? H5Dread(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : 0;
    long long sum = 0;
    int has_sum = st >= 0 && pl_ckpt_attr_i64(ds, "fnv1a64", &sum, 1, 0) == 0;
    H5Sclose(sp);
    H5Dclose(ds);
    if (!ok)
        return pl_err_set(err, PL_ERR_INPUT, "%s: dataset %s%s%s has %llu elements, the scene needs %zu", path,
                          where, sep, name, (unsigned long long)dims[0], n);
    if (st < 0) return pl_err_set(err, PL_ERR_INPUT, "%s: dataset %s%s%s is unreadable", path, where, sep, name);
    if (!has_sum)
        return pl_err_set(err, PL_ERR_INPUT, "%s: dataset %s%s%s has no checksum (attribute fnv1a64)", path,
                          where, sep, name);
    uint64_t got = pl_ckpt_fnv1a(data, n * H5Tget_size(type));
    if (got != (uint64_t)sum)
        return pl_err_set(err, PL_ERR_INPUT,
                          "%s: dataset %s%s%s fails its checksum (stored fnv1a64 %016llx, data %016llx): "
                          "the checkpoint is corrupt", path, where, sep, name, (unsigned long long)sum,
                          (unsigned long long)got);
    return 0;
}

char *pl_ckpt_attr_str_read(hid_t obj, const char *name)
{
    if (H5Aexists(obj, name) <= 0) return NULL;
    hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
    if (a < 0) return NULL;
    hid_t t = H5Aget_type(a);
    char *s = NULL;
    size_t n = t >= 0 && H5Tget_class(t) == H5T_STRING && !H5Tis_variable_str(t) ? H5Tget_size(t) : 0;
    if (n > 0 && n < ((size_t)1 << 24) && (s = malloc(n + 1))) {
        if (H5Aread(a, t, s) < 0) {
            free(s);
            s = NULL;
        } else {
            s[n] = '\0';
        }
    }
    if (t >= 0) H5Tclose(t);
    H5Aclose(a);
    return s;
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
