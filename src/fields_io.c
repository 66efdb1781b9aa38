/* Time-averaged fluid fields on the (unshifted) cell grid, written in H5MD
 * layout where it applies: /h5md metadata (version, author, creator), and
 * /observables/fluid_density/value [Lz][Ly][Lx] (particles per cell) and
 * /observables/fluid_velocity/value [Lz][Ly][Lx][3] (mass-weighted mean
 * velocity; 0 where a cell was always empty), each with step and time.
 * Attributes boundary_x/y/z name each axis' boundary (periodic, or noslip /
 * slip walls at 0 and L: Hecht Sec. VIII.A, a capillary with walls_xy). */
#include <errno.h>
#include <hdf5.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "peloid/h5.h"
#include "peloid/io.h"

static int observable(hid_t obs, const char *name, int rank, const hsize_t *dims, const double *d,
                      long long step, double time)
{
    hid_t g = pl_h5_group(obs, name);
    if (g < 0) return -1;
    int bad = pl_h5_write(g, "value", H5T_NATIVE_DOUBLE, rank, dims, d);
    bad |= pl_h5_write(g, "step", H5T_NATIVE_LLONG, 0, NULL, &step);
    bad |= pl_h5_write(g, "time", H5T_NATIVE_DOUBLE, 0, NULL, &time);
    if (H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
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
    char tmp[PATH_MAX + 8], why[256];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    pl_h5_quiet();
    errno = 0;
    hid_t f = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (f < 0) {
        pl_h5_error_text(why, sizeof why);
        free(rho);
        free(vel);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot create HDF5 file: %s", tmp, why);
    }
    int bad = pl_h5_h5md_header(f);
    hid_t obs = pl_h5_group(f, "observables");
    if (obs >= 0) {
        bad |= pl_h5_attr_str(obs, "layout", "value[z][y][x] on the unshifted cell grid, cell size a0 = 1");
        int walls[3];
        pl_scene_box_walls(&sc->box, walls);
        static const char *const bname[3] = {"boundary_x", "boundary_y", "boundary_z"};
        for (int d = 0; d < 3; ++d) bad |= pl_h5_attr_str(obs, bname[d], pl_scene_boundary_name(walls[d]));
        hsize_t dims[4] = {(hsize_t)L[2], (hsize_t)L[1], (hsize_t)L[0], 3};
        double time = (double)sim->step * sc->srd.dt;
        bad |= observable(obs, "fluid_density", 3, dims, rho, sim->step, time);
        bad |= observable(obs, "fluid_velocity", 4, dims, vel, sim->step, time);
        long long samples = sim->field_samples;
        bad |= pl_h5_write(obs, "samples", H5T_NATIVE_LLONG, 0, NULL, &samples);
        if (H5Gclose(obs) < 0) bad = 1;
    } else {
        bad = 1;
    }
    free(rho);
    free(vel);
    if (bad) pl_h5_error_text(why, sizeof why); /* before H5Fclose clears the stack */
    if (H5Fclose(f) < 0 && !bad) {
        pl_h5_error_text(why, sizeof why);
        bad = 1;
    }
    if (bad) {
        unlink(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: writing fields failed: %s", tmp, why);
    }
    if (pl_fsync_path(tmp, 0) || rename(tmp, path) || pl_fsync_path(path, 1)) {
        int e = errno;
        unlink(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot commit to %s: %s", tmp, path, strerror(e));
    }
    return 0;
}
