/* Time-averaged fluid fields on the (unshifted) cell grid, written in H5MD
 * layout where it applies: /h5md metadata (version, author, creator), and
 * /observables/fluid_density/value [Lz][Ly][Lx] (particles per cell) and
 * /observables/fluid_velocity/value [Lz][Ly][Lx][3] (mass-weighted mean
 * velocity; 0 where a cell was always empty), each with step and time. */
#include <hdf5.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/io.h"

static void attr_str(hid_t obj, const char *name, const char *value)
{
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, strlen(value) + 1);
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, t, value);
    H5Aclose(a);
    H5Sclose(sp);
    H5Tclose(t);
}

static void write_nd(hid_t g, const char *name, int rank, const hsize_t *dims, hid_t type, const void *d)
{
    hid_t sp = H5Screate_simple(rank, dims, NULL);
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_obj_track_times(dcpl, 0); /* same fields => same bytes */
    hid_t ds = H5Dcreate2(g, name, type, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    H5Pclose(dcpl);
    H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, d);
    H5Dclose(ds);
    H5Sclose(sp);
}

static hid_t group(hid_t parent, const char *name)
{
    hid_t gcpl = H5Pcreate(H5P_GROUP_CREATE);
    H5Pset_obj_track_times(gcpl, 0);
    hid_t g = H5Gcreate2(parent, name, H5P_DEFAULT, gcpl, H5P_DEFAULT);
    H5Pclose(gcpl);
    return g;
}

static void observable(hid_t obs, const char *name, int rank, const hsize_t *dims, const double *d,
                       long long step, double time)
{
    hid_t g = group(obs, name);
    write_nd(g, "value", rank, dims, H5T_NATIVE_DOUBLE, d);
    hsize_t one = 1;
    write_nd(g, "step", 0, &one, H5T_NATIVE_LLONG, &step);
    write_nd(g, "time", 0, &one, H5T_NATIVE_DOUBLE, &time);
    H5Gclose(g);
}

int pl_fields_write(const pl_sim_t *sim, const char *path, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const int *L = sc->box.cells;
    size_t L3 = (size_t)L[0] * (size_t)L[1] * (size_t)L[2];
    double *rho = malloc(L3 * sizeof *rho), *vel = malloc(3 * L3 * sizeof *vel);
    if (!rho || !vel) {
        free(rho);
        free(vel);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory writing fields");
    }
    const double inv_fixed = 1.0 / (double)(1LL << PL_FIELD_FIXED_SHIFT);
    double ns = sim->field_samples > 0 ? (double)sim->field_samples : 1.0;
    for (size_t c = 0; c < L3; ++c) {
        int64_t cnt = sim->field_acc[c];
        rho[c] = (double)cnt / ns;
        for (int d = 0; d < 3; ++d)
            vel[3 * c + (size_t)d] =
                cnt > 0 ? (double)sim->field_acc[(size_t)(d + 1) * L3 + c] * inv_fixed / (double)cnt : 0.0;
    }
    char tmp[1100];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    hid_t f = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (f < 0) {
        free(rho);
        free(vel);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot create HDF5 file", tmp);
    }
    hid_t h5md = group(f, "h5md");
    int version[2] = {1, 1};
    hsize_t two = 2;
    hid_t sp = H5Screate_simple(1, &two, NULL);
    hid_t a = H5Acreate2(h5md, "version", H5T_NATIVE_INT, sp, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_INT, version);
    H5Aclose(a);
    H5Sclose(sp);
    hid_t au = group(h5md, "author");
    attr_str(au, "name", "peloid user");
    H5Gclose(au);
    hid_t cr = group(h5md, "creator");
    attr_str(cr, "name", "peloid");
    attr_str(cr, "version", PL_GIT_REV);
    H5Gclose(cr);
    H5Gclose(h5md);
    hid_t obs = group(f, "observables");
    attr_str(obs, "layout", "value[z][y][x] on the unshifted cell grid, cell size a0 = 1");
    hsize_t dims[4] = {(hsize_t)L[2], (hsize_t)L[1], (hsize_t)L[0], 3};
    double time = (double)sim->step * sc->srd.dt;
    observable(obs, "fluid_density", 3, dims, rho, sim->step, time);
    observable(obs, "fluid_velocity", 4, dims, vel, sim->step, time);
    long long samples = sim->field_samples;
    write_nd(obs, "samples", 0, dims, H5T_NATIVE_LLONG, &samples);
    H5Gclose(obs);
    free(rho);
    free(vel);
    if (H5Fclose(f) < 0) return pl_err_set(err, PL_ERR_IO, "%s: writing fields failed", tmp);
    if (rename(tmp, path)) return pl_err_set(err, PL_ERR_IO, "%s: cannot rename to %s", tmp, path);
    return 0;
}
