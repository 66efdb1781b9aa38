/* Colloid trajectory in H5MD 1.1 (de Buyl et al., Comput. Phys. Commun. 185,
 * 1546 (2014)), as MDAnalysis' H5MD reader, h5py and pyh5md read it:
 *   /h5md                 version = [1, 1]; author, creator; modules/units (SI)
 *   /particles/colloids/box       dimension = 3, boundary = periodic | none,
 *        edges/{step, time, value (T x 3 x 3)}: time-dependent and as the box
 *        matrix (rows = edge vectors, diagonal here), the form MDAnalysis reads
 *   /particles/colloids/{position, velocity, orientation, angular_velocity, image}
 *        /step (T), /time (T), /value (T x N x 3; orientation T x N x 4)
 *   /particles/colloids/{radius, mass, species, id}  (time independent, N);
 *        a physical scene's mass is the kinetic mass (below)
 *   /observables/dt/{step, time, value (T)}  the nominal time between frames
 *        (colloids.trajectory_interval SRD steps), read by MDAnalysis as the
 *        frame step (its H5MD reader takes ts.dt from an observable "dt"
 *        and has no other source; without it every frame is "1 ps" apart);
 *        a last frame off the interval is closer to its predecessor: the
 *        exact times are in position/time
 *   /particles/colloids/cluster_id/{step, time, value (T x N, int32)}  with the
 *        cluster observer (pl_colloid_traj_cluster_ids): the smallest member
 *        index of each colloid's cluster, -1 where the frame has none
 *   /parameters           attributes a0, t0, m_f in the file's units (model: 1, 1, 1)
 * Units: a scene with physical{} is written in nm, ps, nm ps-1, ps-1 and kg,
 * stated in `unit` on every dimensionful value and time dataset (H5MD units
 * module, system SI; unit strings MDAnalysis converts).  A model scene has
 * no physical scale: its values are in a0, t0, a0 t0-1, t0-1, m_f, stated in
 * `model_unit` attributes instead, because MDAnalysis refuses a file whose
 * `unit` it does not know even with convert_units=False (open model files
 * with convert_units=False).  Kinetic mass: the model realises the
 * suspension at a model temperature kT_model = m_f a0^2 / t0^2 (Hecht Sec.
 * VII.B), energy_scale = kT / kT_model times below the real one; velocities
 * are the model's (d position / d time in the mapped time), so with the
 * real colloid mass 1/2 m v^2 would give a temperature energy_scale times
 * too low.  The mass written is the colloid's model mass times the energy
 * scale, so that every combination of these datasets (kinetic temperature,
 * momentum balance over time) gives the scene's values; the real particle
 * mass is stated in the dataset's attribute `real_mass_kg` and in
 * /parameters.  The unit attributes are variable-length
 * strings: MDAnalysis 2.4 looks them up as str, which h5py gives only for
 * those.  With PATH.xyz beside (colloids.xyz, src/io/colloid_xyz.c) every frame
 * goes to both.  Written to PATH.tmp and renamed to PATH on close (DESIGN.md:
 * outputs are written atomically); an existing PATH is refused unless
 * overwrite.  A run resumed in place continues the file it finds (the
 * PATH.tmp a killed run left, else a copy of PATH) after dropping the frames
 * of steps from the restart step on (src/io/colloid_h5md_resume.c). */
#include <errno.h>
#include <hdf5.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "colloid_h5md_priv.h"
#include "peloid/h5.h"
#include "peloid/io.h"

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

/* Time-independent dataset of n values (scaled by `scale` for doubles) with
 * its unit (NULL: dimensionless); 0 or -1. */
static int fixed_1d(hid_t g, const char *name, hid_t type, const void *v, hsize_t n, double scale,
                    const char *attr, const char *unit, double *tmp)
{
    if (type == H5T_NATIVE_DOUBLE) {
        for (hsize_t i = 0; i < n; ++i) tmp[i] = ((const double *)v)[i] * scale;
        v = tmp;
    }
    hid_t sp = H5Screate_simple(1, &n, NULL);
    hid_t d = H5Dcreate2(g, name, type, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    int bad = d < 0 || H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0;
    if (!bad && unit) bad = pl_h5_attr_vlstr(d, attr, unit);
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
    if (t->dt_val > 0 && H5Dclose(t->dt_val) < 0) bad = 1;
    if (t->dt_step > 0 && H5Dclose(t->dt_step) < 0) bad = 1;
    if (t->dt_time > 0 && H5Dclose(t->dt_time) < 0) bad = 1;
    if (t->cid_val > 0 && H5Dclose(t->cid_val) < 0) bad = 1;
    if (t->cid_step > 0 && H5Dclose(t->cid_step) < 0) bad = 1;
    if (t->cid_time > 0 && H5Dclose(t->cid_time) < 0) bad = 1;
    free(t->cid_buf);
    if (t->file > 0 && H5Fclose(t->file) < 0) bad = 1;
    free(t->buf);
    free(t->ibuf);
    free(t->hold);
    free(t->ihold);
    free(t);
    return bad ? -1 : 0;
}

/* box: dimension, boundary (H5MD 1.1: "periodic" or "none" per axis) */
static int box_attrs(hid_t box, const int periodic[3])
{
    int three = 3, bad = 0;
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(box, "dimension", H5T_NATIVE_INT, sp, H5P_DEFAULT, H5P_DEFAULT);
    bad |= a < 0 || H5Awrite(a, H5T_NATIVE_INT, &three) < 0;
    if (a >= 0 && H5Aclose(a) < 0) bad = 1;
    H5Sclose(sp);
    hid_t st = H5Tcopy(H5T_C_S1);
    H5Tset_size(st, 9);
    char bnd[3][9] = {"periodic", "periodic", "periodic"};
    for (int k = 0; k < 3; ++k)
        if (!periodic[k]) snprintf(bnd[k], 9, "none");
    hsize_t n3 = 3;
    sp = H5Screate_simple(1, &n3, NULL);
    a = H5Acreate2(box, "boundary", st, sp, H5P_DEFAULT, H5P_DEFAULT);
    bad |= a < 0 || H5Awrite(a, st, bnd) < 0;
    if (a >= 0 && H5Aclose(a) < 0) bad = 1;
    H5Tclose(st);
    H5Sclose(sp);
    return bad ? -1 : 0;
}

/* One time-dependent element: group `name` under g with value/step/time. */
static int element(pl_colloid_traj_t *t, hid_t g, int k, const char *unit)
{
    hid_t tg = H5Gcreate2(g, TS_NAMES[k], H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (tg < 0) return -1;
    hsize_t w = k == 2 ? 4 : 3;
    if (k == TS_EDGES) t->val[k] = ext_dataset(tg, "value", H5T_NATIVE_DOUBLE, 3, 3, 3);
    else t->val[k] = ext_dataset(tg, "value", k == 4 ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE, 3, t->n, w);
    t->step[k] = ext_dataset(tg, "step", H5T_NATIVE_LLONG, 1, 0, 0);
    t->time[k] = ext_dataset(tg, "time", H5T_NATIVE_DOUBLE, 1, 0, 0);
    int bad = t->val[k] < 0 || t->step[k] < 0 || t->time[k] < 0;
    if (!bad && unit) bad = pl_h5_attr_vlstr(t->val[k], t->unit_attr, unit);
    if (!bad) bad = pl_h5_attr_vlstr(t->time[k], t->unit_attr, t->time_unit);
    if (H5Gclose(tg) < 0) bad = 1;
    return bad ? -1 : 0;
}

/* The real mass of each colloid (the kinetic mass over the energy scale) as
 * an attribute of /particles/colloids/mass, with what the dataset means. */
static int mass_attrs(hid_t col, const pl_colloid_t *c, const pl_colloid_traj_t *t)
{
    hid_t d = H5Dopen2(col, "mass", H5P_DEFAULT);
    if (d < 0) return -1;
    double *real = malloc((t->n ? t->n : 1) * sizeof *real);
    int bad = !real;
    for (size_t i = 0; real && i < t->n; ++i) real[i] = c->mass[i] * t->mass;
    if (!bad && t->n) bad = pl_h5_attr_doubles(d, "real_mass_kg", real, t->n);
    if (!bad) bad = pl_h5_attr_vlstr(d, "meaning",
                                     "kinetic mass: the model colloid mass times the mapping's energy scale "
                                     "kT/kT_model (/parameters/energy_scale), so that 1/2 m v^2 of velocity/value "
                                     "gives the scene's temperature; the real particle mass is real_mass_kg");
    free(real);
    if (H5Dclose(d) < 0) bad = 1;
    return bad ? -1 : 0;
}

/* /observables/dt: the nominal time between frames, one value per frame. */
static int dt_observable(pl_colloid_traj_t *t)
{
    hid_t obs = pl_h5_group(t->file, "observables");
    hid_t g = obs >= 0 ? H5Gcreate2(obs, "dt", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : -1;
    int bad = g < 0;
    if (!bad) {
        t->dt_val = ext_dataset(g, "value", H5T_NATIVE_DOUBLE, 1, 0, 0);
        t->dt_step = ext_dataset(g, "step", H5T_NATIVE_LLONG, 1, 0, 0);
        t->dt_time = ext_dataset(g, "time", H5T_NATIVE_DOUBLE, 1, 0, 0);
        bad = t->dt_val < 0 || t->dt_step < 0 || t->dt_time < 0 ||
              pl_h5_attr_vlstr(t->dt_val, t->unit_attr, t->time_unit) ||
              pl_h5_attr_vlstr(t->dt_time, t->unit_attr, t->time_unit);
    }
    if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    if (obs >= 0 && H5Gclose(obs) < 0) bad = 1;
    return bad ? -1 : 0;
}

static int write_header(pl_colloid_traj_t *t, const pl_colloid_t *c)
{
    char vunit[24], wunit[16];
    snprintf(vunit, sizeof vunit, "%s %s-1", t->len_unit, t->time_unit);
    snprintf(wunit, sizeof wunit, "%s-1", t->time_unit);
    const int phys = strcmp(t->len_unit, "a0") != 0;
    int bad = pl_h5_h5md_header(t->file) || (phys && pl_h5_h5md_units(t->file, "SI"));
    hid_t parts = pl_h5_group(t->file, "particles");
    hid_t col = parts >= 0 ? pl_h5_group(parts, "colloids") : -1;
    hid_t box = col >= 0 ? pl_h5_group(col, "box") : -1;
    bad |= box < 0 || box_attrs(box, t->periodic) || element(t, box, TS_EDGES, t->len_unit);
    double *tmp = malloc((t->n ? t->n : 1) * sizeof *tmp);
    int32_t *ids = malloc((t->n ? t->n : 1) * sizeof *ids), *species = calloc(t->n ? t->n : 1, sizeof *species);
    bad |= !tmp || !ids || !species;
    for (size_t i = 0; ids && i < t->n; ++i) ids[i] = (int32_t)i;
    if (!bad && col >= 0) {
        bad |= fixed_1d(col, "radius", H5T_NATIVE_DOUBLE, c->rad, t->n, t->len, t->unit_attr, t->len_unit, tmp);
        bad |= fixed_1d(col, "mass", H5T_NATIVE_DOUBLE, c->mass, t->n, t->kin_mass, t->unit_attr, phys ? "kg" : "m_f", tmp);
        if (!bad && phys) bad |= mass_attrs(col, c, t);
        bad |= fixed_1d(col, "species", H5T_NATIVE_INT32, species, t->n, 1.0, NULL, NULL, tmp);
        bad |= fixed_1d(col, "id", H5T_NATIVE_INT32, ids, t->n, 1.0, NULL, NULL, tmp);
        const char *units[5] = {t->len_unit, vunit, NULL, wunit, NULL};
        for (int k = 0; k < 5; ++k) bad |= element(t, col, k, units[k]);
    }
    free(tmp);
    free(ids);
    free(species);
    bad |= dt_observable(t);
    hid_t par = pl_h5_group(t->file, "parameters");
    bad |= par < 0 || pl_h5_attr_doubles(par, "a0", &t->len, 1) || pl_h5_attr_vlstr(par, "a0_unit", t->len_unit) ||
           pl_h5_attr_doubles(par, "t0", &t->tim, 1) || pl_h5_attr_vlstr(par, "t0_unit", t->time_unit) ||
           pl_h5_attr_doubles(par, "m_f", &t->mass, 1) || pl_h5_attr_vlstr(par, "m_f_unit", phys ? "kg" : "m_f");
    if (phys) {
        double es = t->kin_mass / t->mass;
        bad |= par < 0 || pl_h5_attr_doubles(par, "energy_scale", &es, 1) ||
               pl_h5_attr_vlstr(par, "energy_scale_meaning",
                                "kT / kT_model: the written colloid masses are the model masses times this "
                                "(kinetic masses, 1/2 m v^2 = the scene's kT)");
    }
    if (par >= 0 && H5Gclose(par) < 0) bad = 1;
    if (box >= 0) H5Gclose(box);
    if (col >= 0) H5Gclose(col);
    if (parts >= 0) H5Gclose(parts);
    return bad ? -1 : 0;
}

int pl_colloid_traj_open(const char *path, const pl_colloid_t *c, const pl_colloid_traj_params_t *p,
                         pl_colloid_traj_t **out, pl_err_t *err)
{
    if (!p->overwrite && !p->resume && access(path, F_OK) == 0)
        return pl_err_set(err, PL_ERR_IO, "%s exists; not overwritten without --force", path);
    char tmp[PATH_MAX + 8];
    pl_atomic_tmp(path, tmp, sizeof tmp);
    pl_colloid_traj_t *t = calloc(1, sizeof *t);
    if (!t) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    snprintf(t->path, sizeof t->path, "%s", path);
    snprintf(t->tmp, sizeof t->tmp, "%s", tmp);
    t->n = c->n;
    t->last_step = t->hold_step = -1;
    memcpy(t->box, c->box, sizeof t->box);
    memcpy(t->periodic, c->periodic, sizeof t->periodic);
    const int phys = p->a0_m > 0.0 && p->t0_s > 0.0 && p->m_f_kg > 0.0;
    t->len = phys ? p->a0_m * 1e9 : 1.0;
    t->tim = phys ? p->t0_s * 1e12 : 1.0;
    t->mass = phys ? p->m_f_kg : 1.0;
    t->kin_mass = phys && p->mass_kg > 0.0 ? p->mass_kg : t->mass;
    t->frame_dt = p->frame_dt;
    snprintf(t->len_unit, sizeof t->len_unit, "%s", phys ? "nm" : "a0");
    snprintf(t->time_unit, sizeof t->time_unit, "%s", phys ? "ps" : "t0");
    t->unit_attr = phys ? "unit" : "model_unit";
    size_t n1 = c->n ? c->n : 1;
    t->buf = malloc(n1 * 4 * sizeof(double));
    t->ibuf = malloc(n1 * 3 * sizeof(int));
    t->hold = malloc(n1 * NHOLD * sizeof(double));
    t->ihold = malloc(n1 * 3 * sizeof(int32_t));
    pl_h5_quiet();
    errno = 0;
    int oom = !t->buf || !t->ibuf || !t->hold || !t->ihold;
    t->file = -1;
    if (!oom && p->resume) {
        int rc = pl_colloid_traj_resume_open(t, p->keep_before, err);
        if (rc == 0 && p->xyz_path && pl_xyz_open_keep(p->xyz_path, p->keep_before, &t->xyz, err))
            rc = err ? err->code : PL_ERR_IO;
        if (rc == 0) {
            *out = t;
            return 0;
        }
        if (rc != 1) {
            traj_release(t);
            return rc;
        }
    }
    if (!oom) t->file = H5Fcreate(t->tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (t->file < 0) {
        char why[256];
        pl_h5_error_text(why, sizeof why);
        traj_release(t);
        return oom ? pl_err_set(err, PL_ERR_NOMEM, "out of memory") :
                     pl_err_set(err, PL_ERR_IO, "%s: cannot create HDF5 file: %s", tmp, why);
    }
    if (write_header(t, c) || H5Fflush(t->file, H5F_SCOPE_GLOBAL) < 0) {
        char why[256];
        pl_h5_error_text(why, sizeof why);
        traj_release(t);
        unlink(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot write the trajectory header: %s", path, why);
    }
    if (p->xyz_path && pl_xyz_open(p->xyz_path, &t->xyz, err)) {
        traj_release(t);
        unlink(tmp);
        return err ? err->code : PL_ERR_IO;
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

static int write_frame(pl_colloid_traj_t *t, const pl_traj_frame_t *f, pl_err_t *err)
{
    if (f->step == t->last_step) return 0; /* that frame is there already */
    const double *src[4][4] = {{f->x, f->y, f->z, NULL}, {f->vx, f->vy, f->vz, NULL},
                               {f->q0, f->q1, f->q2, f->q3}, {f->wx, f->wy, f->wz, NULL}};
    const double scale[4] = {t->len, t->len / t->tim, 1.0, 1.0 / t->tim};
    const double time = f->time * t->tim;
    int bad = 0;
    for (int k = 0; k < NTS; ++k) {
        hsize_t w = k == 2 ? 4 : 3;
        if (k == TS_EDGES) {
            double e[9] = {t->box[0] * t->len, 0, 0, 0, t->box[1] * t->len, 0, 0, 0, t->box[2] * t->len};
            bad |= append(t->val[k], H5T_NATIVE_DOUBLE, 3, t->nframes, 3, 3, e);
        } else if (k == 4) {
            for (size_t i = 0; i < t->n; ++i) {
                t->ibuf[3 * i] = f->ix[i], t->ibuf[3 * i + 1] = f->iy[i], t->ibuf[3 * i + 2] = f->iz[i];
            }
            bad |= append(t->val[k], H5T_NATIVE_INT, 3, t->nframes, t->n, w, t->ibuf);
        } else {
            for (size_t i = 0; i < t->n; ++i)
                for (hsize_t a = 0; a < w; ++a) t->buf[w * i + a] = src[k][a][i] * scale[k];
            bad |= append(t->val[k], H5T_NATIVE_DOUBLE, 3, t->nframes, t->n, w, t->buf);
        }
        bad |= append(t->step[k], H5T_NATIVE_LLONG, 1, t->nframes, 1, 1, &f->step);
        bad |= append(t->time[k], H5T_NATIVE_DOUBLE, 1, t->nframes, 1, 1, &time);
    }
    const double frame_dt = t->frame_dt * t->tim;
    bad |= append(t->dt_val, H5T_NATIVE_DOUBLE, 1, t->nframes, 1, 1, &frame_dt);
    bad |= append(t->dt_step, H5T_NATIVE_LLONG, 1, t->nframes, 1, 1, &f->step);
    bad |= append(t->dt_time, H5T_NATIVE_DOUBLE, 1, t->nframes, 1, 1, &time);
    if (t->cid_val > 0) {
        for (size_t i = 0; i < t->n; ++i) t->cid_buf[i] = f->cluster_id ? f->cluster_id[i] : -1;
        bad |= append(t->cid_val, H5T_NATIVE_INT32, 2, t->cid_frames, t->n, 1, t->cid_buf);
        bad |= append(t->cid_step, H5T_NATIVE_LLONG, 1, t->cid_frames, 1, 1, &f->step);
        bad |= append(t->cid_time, H5T_NATIVE_DOUBLE, 1, t->cid_frames, 1, 1, &time);
        t->cid_frames++;
    }
    t->nframes++;
    if (!bad) {
        errno = 0;
        bad = H5Fflush(t->file, H5F_SCOPE_GLOBAL) < 0;
    }
    if (bad) {
        char why[256];
        pl_h5_error_text(why, sizeof why);
        return pl_err_set(err, PL_ERR_IO, "%s: writing the frame of step %lld failed: %s", t->tmp, f->step, why);
    }
    t->last_step = f->step;
    return t->xyz ? pl_xyz_frame(t->xyz, f, err) : 0;
}

static void frame_of(const pl_colloid_traj_t *t, const pl_colloid_t *c, long long step, double time,
                     pl_traj_frame_t *f)
{
    *f = (pl_traj_frame_t){.n = t->n, .x = c->x, .y = c->y, .z = c->z, .vx = c->vx, .vy = c->vy, .vz = c->vz,
                           .q0 = c->q0, .q1 = c->q1, .q2 = c->q2, .q3 = c->q3, .wx = c->wx, .wy = c->wy,
                           .wz = c->wz, .rad = c->rad, .ix = c->ix, .iy = c->iy, .iz = c->iz, .box = t->box,
                           .periodic = t->periodic, .step = step, .time = time, .len = t->len, .tim = t->tim,
                           .len_unit = t->len_unit, .time_unit = t->time_unit, .has_cluster_id = t->ids != NULL};
}

int pl_colloid_traj_write(pl_colloid_traj_t *t, const pl_colloid_t *c, long long step, double time,
                          pl_err_t *err)
{
    pl_traj_frame_t f;
    frame_of(t, c, step, time, &f);
    if (t->ids && step != t->last_step) f.cluster_id = t->ids(t->ids_ctx, step, 1);
    return write_frame(t, &f, err);
}

int pl_colloid_traj_cluster_ids(pl_colloid_traj_t *t, pl_traj_ids_fn ids, void *ctx, pl_err_t *err)
{
    if (t->cid_val > 0) { /* already there: a new source */
        t->ids = ids;
        t->ids_ctx = ctx;
        return 0;
    }
    hid_t g = H5Gopen2(t->file, "particles/colloids", H5P_DEFAULT);
    hid_t tg = g >= 0 ? H5Gcreate2(g, "cluster_id", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : -1;
    int bad = tg < 0 || !(t->cid_buf = malloc((t->n ? t->n : 1) * sizeof(int32_t)));
    if (!bad) {
        t->cid_val = ext_dataset(tg, "value", H5T_NATIVE_INT32, 2, t->n, 1);
        t->cid_step = ext_dataset(tg, "step", H5T_NATIVE_LLONG, 1, 0, 0);
        t->cid_time = ext_dataset(tg, "time", H5T_NATIVE_DOUBLE, 1, 0, 0);
        bad = t->cid_val < 0 || t->cid_step < 0 || t->cid_time < 0 ||
              pl_h5_attr_vlstr(t->cid_time, t->unit_attr, t->time_unit) ||
              pl_h5_attr_vlstr(tg, "meaning", "the smallest colloid index of each colloid's cluster "
                                              "(observe.clusters_*), -1 where the frame has no partition");
    }
    if (tg >= 0 && H5Gclose(tg) < 0) bad = 1;
    if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    if (bad) {
        char why[256];
        pl_h5_error_text(why, sizeof why);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot add the cluster ids: %s", t->tmp, why);
    }
    t->ids = ids;
    t->ids_ctx = ctx;
    return 0;
}

void pl_colloid_traj_hold(pl_colloid_traj_t *t, const pl_colloid_t *c, long long step, double time)
{
    const double *s[NHOLD] = {c->x, c->y, c->z, c->vx, c->vy, c->vz, c->q0, c->q1, c->q2, c->q3, c->wx, c->wy, c->wz};
    for (int k = 0; k < NHOLD; ++k) memcpy(t->hold + (size_t)k * t->n, s[k], t->n * sizeof(double));
    memcpy(t->ihold, c->ix, t->n * sizeof(int32_t));
    memcpy(t->ihold + t->n, c->iy, t->n * sizeof(int32_t));
    memcpy(t->ihold + 2 * t->n, c->iz, t->n * sizeof(int32_t));
    t->hold_step = step;
    t->hold_time = time;
}

int pl_colloid_traj_write_held(pl_colloid_traj_t *t, const pl_colloid_t *c, pl_err_t *err)
{
    if (t->hold_step < 0) return 0;
    pl_traj_frame_t f;
    frame_of(t, c, t->hold_step, t->hold_time, &f);
    const double *h = t->hold;
    const size_t n = t->n;
    f.x = h, f.y = h + n, f.z = h + 2 * n, f.vx = h + 3 * n, f.vy = h + 4 * n, f.vz = h + 5 * n;
    f.q0 = h + 6 * n, f.q1 = h + 7 * n, f.q2 = h + 8 * n, f.q3 = h + 9 * n;
    f.wx = h + 10 * n, f.wy = h + 11 * n, f.wz = h + 12 * n;
    f.ix = t->ihold, f.iy = t->ihold + n, f.iz = t->ihold + 2 * n;
    if (t->ids && t->hold_step != t->last_step) f.cluster_id = t->ids(t->ids_ctx, t->hold_step, 0);
    return write_frame(t, &f, err);
}

int pl_colloid_traj_close(pl_colloid_traj_t *t, pl_err_t *err)
{
    if (!t) return 0;
    char tmp[PATH_MAX + 8], path[PATH_MAX], why[256] = "";
    snprintf(tmp, sizeof tmp, "%s", t->tmp);
    snprintf(path, sizeof path, "%s", t->path);
    pl_xyz_t *xyz = t->xyz;
    errno = 0;
    if (traj_release(t)) { /* the frames written so far stay in PATH.tmp */
        pl_h5_error_text(why, sizeof why);
        pl_xyz_close(xyz, NULL);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot finish the trajectory: %s", path, why);
    }
    if (pl_atomic_commit(tmp, path, err)) {
        pl_xyz_close(xyz, NULL);
        return PL_ERR_IO;
    }
    return pl_xyz_close(xyz, err);
}
