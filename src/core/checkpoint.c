/* HDF5 checkpoint: the complete dynamic state, so that N steps + restart +
 * N steps equals 2N steps bitwise.  Random numbers are counter based (keyed
 * by step), so the state is positions, velocities (in their sorted order:
 * the stable sort depends on it), tracking arrays, step, field accumulators,
 * with colloids the group /colloids (src/colloid/checkpoint_colloid.c), the wall
 * and coupling run counters (src/coupling/checkpoint_coupling.c), and with
 * observers their accumulated state, /observe and /stress (written by their
 * modules; fingerprint of the observe section: src/observe/checkpoint_observe.c;
 * absent in older files, which still load: the observers start afresh).
 * The fluid's own items (field accumulator, field_samples, kT_cell) are its
 * module's (src/fluid/checkpoint_fluid.c), in the places the core once wrote
 * them (peloid/module.h: checkpoint_attrs, checkpoint_write_last).
 * Written atomically (pl_atomic_commit); the HDF5 helpers (checksummed 1-d
 * datasets, attributes) are in src/io/checkpoint_h5.c.
 * No object carries a time stamp, so the same state gives the same bytes.
 *
 * Nothing read is trusted (format 2): the root attribute format_version must
 * be PL_CKPT_FORMAT, every dataset carries its FNV-1a checksum
 * ("fnv1a64"), the scene fingerprint must match (src/core/checkpoint_scene.c),
 * and every array is range-checked before the first kernel sees it
 * (finite; positions inside the box; velocities within the fluid guard's
 * one-cell-per-step bound; ids a permutation; counts >= 0). */
#include <errno.h>
#include <hdf5.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "checkpoint_h5.h"
#include "peloid/checkpoint.h"
#include "peloid/colloid.h"
#include "peloid/h5.h"
#include "peloid/io.h"
#include "peloid/module.h"

#define H5_REAL (sizeof(pl_real) == sizeof(double) ? H5T_NATIVE_DOUBLE : H5T_NATIVE_FLOAT)

static const char *const rnames[3] = {"x", "y", "z"};
static const char *const vnames[3] = {"vx", "vy", "vz"}; /* fluid/ velocities */
static const char *const dnames[3] = {"disp_x", "disp_y", "disp_z"};

static int write_failed(pl_err_t *err, const char *tmp, const char *what)
{
    char why[256];
    pl_h5_error_text(why, sizeof why);
    unlink(tmp); /* a partial file must not take the space the next try needs */
    return pl_err_set(err, PL_ERR_IO, "%s: %s: %s", tmp, what, why);
}

int pl_checkpoint_write(const pl_sim_t *sim, const char *path, pl_err_t *err)
{
    char tmp[PATH_MAX + 8];
    pl_atomic_tmp(path, tmp, sizeof tmp);
    pl_h5_quiet();
    errno = 0;
    hid_t f = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (f < 0) return write_failed(err, tmp, "cannot create the checkpoint");
    const pl_fluid_t *fl = &sim->fluid;
    const pl_scene_t *sc = &sim->scene;
    long long meta[8] = {sim->step, sc->run.seed, (long long)fl->n, sc->box.cells[0], sc->box.cells[1],
                         sc->box.cells[2], fl->tracked, (long long)sizeof(pl_real)};
    long long ncol = sim->colloids ? (long long)sim->colloids->n : 0;
    long long version = PL_CKPT_FORMAT;
    int bad = pl_ckpt_attr_i64(f, "format_version", &version, 1, 1);
    bad |= pl_ckpt_attr_i64(f, "peloid_checkpoint", meta, 8, 1);
    for (int m = 0; pl_modules[m]; ++m) /* the modules' root attributes (the fluid's field_samples) */
        if (pl_modules[m]->checkpoint_attrs) bad |= pl_modules[m]->checkpoint_attrs(f, sim) != 0;
    bad |= pl_ckpt_attr_i64(f, "colloid_count", &ncol, 1, 1);
    /* only with x/y walls, so that other checkpoints stay as they were */
    long long walls_xy = sc->box.walls_xy;
    if (walls_xy != PL_WALLS_NONE) bad |= pl_ckpt_attr_i64(f, "walls_xy", &walls_xy, 1, 1);
    bad |= pl_ckpt_scene_write(f, sc);
    hid_t g = pl_ckpt_group_create(f, "fluid");
    for (int d = 0; d < 3 && g >= 0; ++d) {
        bad |= pl_ckpt_write_1d(g, rnames[d], H5_REAL, fl->r[d], fl->n);
        bad |= pl_ckpt_write_1d(g, vnames[d], H5_REAL, fl->v[d], fl->n);
        if (fl->tracked) bad |= pl_ckpt_write_1d(g, dnames[d], H5T_NATIVE_DOUBLE, fl->disp[d], fl->n);
    }
    if (fl->tracked && g >= 0) bad |= pl_ckpt_write_1d(g, "id", H5T_NATIVE_UINT32, fl->id, fl->n);
    if (g >= 0) H5Gclose(g);
    else bad = 1;
    for (int m = 0; pl_modules[m]; ++m) /* each module's items (the fluid's accumulators, colloids, coupling) */
        if (pl_modules[m]->checkpoint_write) bad |= pl_modules[m]->checkpoint_write(f, sim) != 0;
    for (int m = 0; pl_modules[m]; ++m) /* and the last ones (the fluid's kT_cell) */
        if (pl_modules[m]->checkpoint_write_last) bad |= pl_modules[m]->checkpoint_write_last(f, sim) != 0;
    if (bad) {
        char why[256];
        pl_h5_error_text(why, sizeof why); /* before H5Fclose clears the stack */
        H5Fclose(f);
        unlink(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: writing the checkpoint failed: %s", tmp, why);
    }
    if (H5Fclose(f) < 0) return write_failed(err, tmp, "writing the checkpoint failed");
    return pl_atomic_commit(tmp, path, err);
}

/* Range checks of the particles just read (serial, once per restart); the
 * fluid module checks their speeds and its own items (src/fluid/checkpoint_fluid.c). */
static int check_fluid(const pl_sim_t *sim, const char *path, pl_err_t *err)
{
    const pl_fluid_t *fl = &sim->fluid;
    const pl_scene_t *sc = &sim->scene;
    for (size_t i = 0; i < fl->n; ++i) {
        for (int d = 0; d < 3; ++d) {
            const double x = fl->r[d][i], L = sc->box.cells[d];
            if (!(x >= 0.0 && x <= L))
                return pl_err_set(err, PL_ERR_INPUT,
                                  "%s: fluid/%s[%zu] = %.17g is outside the box [0, %g] (corrupt checkpoint)",
                                  path, rnames[d], i, x, L);
            if (fl->tracked && !isfinite(fl->disp[d][i]))
                return pl_err_set(err, PL_ERR_INPUT, "%s: fluid/%s[%zu] = %g is not finite", path, dnames[d], i,
                                  fl->disp[d][i]);
        }
    }
    if (fl->tracked) { /* ids: a permutation of 0 .. n-1 */
        unsigned char *seen = calloc(fl->n ? fl->n : 1, 1);
        if (!seen) return pl_err_set(err, PL_ERR_NOMEM, "out of memory checking fluid/id");
        for (size_t i = 0; i < fl->n; ++i) {
            uint32_t id = fl->id[i];
            if (id >= fl->n || seen[id]) {
                free(seen);
                return pl_err_set(err, PL_ERR_INPUT, "%s: fluid/id[%zu] = %u is %s (corrupt checkpoint)", path, i,
                                  id, id >= fl->n ? "out of range" : "a duplicate");
            }
            seen[id] = 1;
        }
        free(seen);
    }
    return 0;
}

int pl_checkpoint_read(pl_sim_t *sim, const char *path, pl_err_t *err)
{
    return pl_checkpoint_restart(sim, path, NULL, err);
}

int pl_checkpoint_restart(pl_sim_t *sim, const char *path, const char *changed, pl_err_t *err)
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
    long long meta[8];
    pl_fluid_t *fl = &sim->fluid;
    const pl_scene_t *sc = &sim->scene;
    if (pl_ckpt_attr_i64(f, "peloid_checkpoint", meta, 8, 0)) {
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: not a peloid checkpoint", path);
        goto close;
    }
    long long version = 1; /* files without the attribute: format 1 */
    if (H5Aexists(f, "format_version") > 0 && pl_ckpt_attr_i64(f, "format_version", &version, 1, 0))
        version = -1;
    if (version != PL_CKPT_FORMAT) {
        rc = pl_err_set(err, PL_ERR_INPUT,
                        "%s: checkpoint format version %lld; this peloid reads version %d only (format 1 had "
                        "no checksums and no scene fingerprint)", path, version, PL_CKPT_FORMAT);
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
    if (meta[0] < 0) {
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: checkpoint step %lld; allowed >= 0 (corrupt checkpoint)", path,
                        meta[0]);
        goto close;
    }
    /* format 2 always writes the count */
    long long ncol = 0, nscene = sim->colloids ? (long long)sim->colloids->n : 0;
    if (pl_ckpt_attr_i64(f, "colloid_count", &ncol, 1, 0)) {
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: checkpoint has no readable attribute colloid_count", path);
        goto close;
    }
    if (ncol != nscene) {
        rc = pl_err_set(err, PL_ERR_INPUT,
                        "%s: checkpoint does not match the scene: it holds %lld colloids, the scene "
                        "has %lld (colloids.count)", path, ncol, nscene);
        goto close;
    }
    /* format 2 writes walls_xy only for scenes with x/y walls (so that the
     * other checkpoints stayed byte-identical when x/y walls came) */
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
    if ((rc = pl_ckpt_scene_check(f, sc, changed, path, err))) goto close;
    if (changed && *changed) { /* observers do not average over two physics: they start afresh */
        pl_sim_observers_afresh(sim, "--restart-changed %.200s: the physics changed, the observers start afresh at "
                                     "the restart step", changed);
    }
    sim->step = meta[0];
    hid_t g = H5Lexists(f, "fluid", H5P_DEFAULT) > 0 ? H5Gopen2(f, "fluid", H5P_DEFAULT) : -1;
    if (g < 0) {
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: checkpoint has no /fluid group", path);
        goto close;
    }
    for (int d = 0; d < 3 && !rc; ++d) {
        rc = pl_ckpt_read_1d(g, rnames[d], H5_REAL, fl->r[d], fl->n, path, err);
        if (!rc) rc = pl_ckpt_read_1d(g, vnames[d], H5_REAL, fl->v[d], fl->n, path, err);
        if (!rc && fl->tracked) rc = pl_ckpt_read_1d(g, dnames[d], H5T_NATIVE_DOUBLE, fl->disp[d], fl->n, path, err);
    }
    if (!rc && fl->tracked) rc = pl_ckpt_read_1d(g, "id", H5T_NATIVE_UINT32, fl->id, fl->n, path, err);
    H5Gclose(g);
    if (!rc) rc = check_fluid(sim, path, err);
    for (int m = 0; !rc && pl_modules[m]; ++m) /* the fluid's items and checks first */
        if (pl_modules[m]->checkpoint_read) rc = pl_modules[m]->checkpoint_read(f, sim, path, err);
close:
    H5Fclose(f);
out:
    H5Eset_auto2(H5E_DEFAULT, old_fn, old_data);
    return rc;
}
