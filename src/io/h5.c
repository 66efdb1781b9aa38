/* HDF5 helpers without time stamps, and the H5MD header (H5MD 1.1). */
#include "peloid/h5.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include "peloid_build.h" /* PL_GIT_REV, PL_CFLAGS (generated) */

hid_t pl_h5_group(hid_t parent, const char *name)
{
    hid_t gcpl = H5Pcreate(H5P_GROUP_CREATE);
    H5Pset_obj_track_times(gcpl, 0);
    hid_t g = H5Gcreate2(parent, name, H5P_DEFAULT, gcpl, H5P_DEFAULT);
    H5Pclose(gcpl);
    return g;
}

int pl_h5_attr_str(hid_t obj, const char *name, const char *value)
{
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, strlen(value) + 1);
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
    herr_t st = a >= 0 ? H5Awrite(a, t, value) : -1;
    if (a >= 0 && H5Aclose(a) < 0) st = -1;
    H5Sclose(sp);
    H5Tclose(t);
    return st < 0 ? -1 : 0;
}

int pl_h5_attr_vlstr(hid_t obj, const char *name, const char *value)
{
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    H5Tset_cset(t, H5T_CSET_UTF8);
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
    herr_t st = a >= 0 ? H5Awrite(a, t, &value) : -1;
    if (a >= 0 && H5Aclose(a) < 0) st = -1;
    H5Sclose(sp);
    H5Tclose(t);
    return st < 0 ? -1 : 0;
}

int pl_h5_attr_doubles(hid_t obj, const char *name, const double *v, hsize_t n)
{
    hid_t sp = n > 1 ? H5Screate_simple(1, &n, NULL) : H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(obj, name, H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT, H5P_DEFAULT);
    herr_t st = a >= 0 ? H5Awrite(a, H5T_NATIVE_DOUBLE, v) : -1;
    if (a >= 0 && H5Aclose(a) < 0) st = -1;
    H5Sclose(sp);
    return st < 0 ? -1 : 0;
}

int pl_h5_write(hid_t parent, const char *name, hid_t type, int rank, const hsize_t *dims, const void *data)
{
    hid_t sp = rank > 0 ? H5Screate_simple(rank, dims, NULL) : H5Screate(H5S_SCALAR);
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_obj_track_times(dcpl, 0);
    hid_t ds = H5Dcreate2(parent, name, type, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    H5Pclose(dcpl);
    herr_t st = ds >= 0 ? H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : -1;
    if (ds >= 0 && H5Dclose(ds) < 0) st = -1;
    H5Sclose(sp);
    return st < 0 ? -1 : 0;
}

int pl_h5_h5md_header(hid_t file)
{
    hid_t h5md = pl_h5_group(file, "h5md");
    if (h5md < 0) return -1;
    int version[2] = {1, 1};
    hsize_t two = 2;
    hid_t sp = H5Screate_simple(1, &two, NULL);
    hid_t a = H5Acreate2(h5md, "version", H5T_NATIVE_INT, sp, H5P_DEFAULT, H5P_DEFAULT);
    int bad = a < 0 || H5Awrite(a, H5T_NATIVE_INT, version) < 0;
    if (a >= 0 && H5Aclose(a) < 0) bad = 1;
    H5Sclose(sp);
    hid_t g = pl_h5_group(h5md, "author");
    bad |= g < 0 || pl_h5_attr_str(g, "name", "peloid");
    if (g >= 0) H5Gclose(g);
    g = pl_h5_group(h5md, "creator");
    bad |= g < 0 || pl_h5_attr_str(g, "name", "peloid") || pl_h5_attr_str(g, "version", PL_GIT_REV);
    if (g >= 0) H5Gclose(g);
    if (H5Gclose(h5md) < 0) bad = 1;
    return bad ? -1 : 0;
}

int pl_h5_h5md_units(hid_t file, const char *system)
{
    /* H5MD units module 1.0: /h5md/modules/units {version, system} */
    hid_t mods = H5Lexists(file, "h5md/modules", H5P_DEFAULT) > 0 ? H5Gopen2(file, "h5md/modules", H5P_DEFAULT)
                                                                    : pl_h5_group(file, "h5md/modules");
    hid_t g = mods >= 0 ? pl_h5_group(mods, "units") : -1;
    int uv[2] = {1, 0}, bad = g < 0;
    hsize_t two = 2;
    hid_t sp = H5Screate_simple(1, &two, NULL);
    hid_t a = g >= 0 ? H5Acreate2(g, "version", H5T_NATIVE_INT, sp, H5P_DEFAULT, H5P_DEFAULT) : -1;
    bad |= a < 0 || H5Awrite(a, H5T_NATIVE_INT, uv) < 0;
    if (a >= 0 && H5Aclose(a) < 0) bad = 1;
    H5Sclose(sp);
    bad |= g < 0 || pl_h5_attr_str(g, "system", system);
    if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    if (mods >= 0 && H5Gclose(mods) < 0) bad = 1;
    return bad ? -1 : 0;
}

void pl_h5_quiet(void) { H5Eset_auto2(H5E_DEFAULT, NULL, NULL); }

void pl_h5_init_process(void)
{
    /* HDF5 1.10's exit handler crashes on a file whose H5Fclose failed (a
     * full disk: H5F__close_cb on the half-closed file); every file peloid
     * opens is closed before exit or abandoned with its .tmp unlinked, so
     * the handler has nothing to do. */
    H5dont_atexit();
    pl_h5_quiet();
}

typedef struct {
    char *buf;
    size_t n;
    int found;
} err_walk_t;

/* The system error text of a low-level I/O failure ("errno = 28, error
 * message = 'No space left on device'" in the sec2 driver's description),
 * else the innermost description. */
static herr_t err_walk(unsigned k, const H5E_error2_t *e, void *data)
{
    err_walk_t *w = data;
    const char *m = e->desc ? strstr(e->desc, "error message = '") : NULL;
    if (m && !w->found) {
        m += strlen("error message = '");
        const char *q = strchr(m, '\'');
        snprintf(w->buf, w->n, "%.*s", q ? (int)(q - m) : (int)strlen(m), m);
        w->found = 1;
    } else if (k == 0 && !w->found && e->desc) {
        snprintf(w->buf, w->n, "HDF5: %s (in %s)", e->desc, e->func_name ? e->func_name : "?");
    }
    return 0;
}

void pl_h5_error_text(char *buf, size_t n)
{
    int e = errno;
    err_walk_t w = {buf, n, 0};
    buf[0] = '\0';
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, err_walk, &w);
    if (!w.found && e) snprintf(buf, n, "%s", strerror(e));
    else if (!buf[0]) snprintf(buf, n, "HDF5 error");
}
