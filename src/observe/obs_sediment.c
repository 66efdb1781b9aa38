/* Observer sedimentation (peloid/observer.h row "sedimentation"): the
 * colloid volume fraction phi(z) (exact sphere slices), the mean (unwrapped)
 * height h, <v_z> of the colloids; the settling velocity between samples,
 * -((h_k - h_{k-1}) / dt - the fluid's mean v_z), whose blocking average
 * over the analysis window (peloid/window.h) is the (hindered) settling
 * velocity of Hecht Eq. 37 (Richardson-Zaki) in a homogeneous suspension.
 *
 * Sign: gravity points along -z, and every settling velocity the observer
 * writes (the series, its summary entry and estimates, the initial settling
 * velocity of sediment_fit.c) is positive down, the series marked so by its
 * attribute `positive` = "down" and the entries by "positive": "down".  The
 * state keeps dz/dt (s_vel, s_vb: the checkpoint's bytes); the outputs negate
 * it.  colloid_vz stays the z component (up positive). */
#include <hdf5.h>
#include <jansson.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint_h5.h"
#include "json_build.h"
#include "obs_window.h"
#include "observables_out.h"
#include "peloid/colloid.h"
#include "peloid/h5.h"
#include "peloid/observer.h"
#include "peloid/real.h" /* PL_PI */
#include "sediment_fit.h"

typedef struct {
    pl_obs_run_t *run;
    size_t s_bins, s_n, s_cap;
    long long *s_step;
    double *s_phi, *s_height, *s_vz, *s_vel; /* s_vel[k]: dz/dt from heights k-1, k (k >= 1) */
    pl_blocking_t s_vb;                      /* of s_vel (dz/dt) */
} sed_obs_t;

static int create(pl_obs_run_t *run, void **state, pl_err_t *err)
{
    sed_obs_t *o = calloc(1, sizeof *o);
    if (!o) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the sedimentation observer");
    o->run = run;
    pl_blocking_init(&o->s_vb);
    *state = o;
    return 0;
}

static void obs_free(void *state)
{
    sed_obs_t *o = state;
    free(o->s_step);
    free(o->s_phi);
    free(o->s_height);
    free(o->s_vel);
    free(o->s_vz);
    free(o);
}

/* Volume of the part of a sphere (centre zc, radius R) between z = a and b. */
static double slice_volume(double zc, double R, double a, double b)
{
    double lo = fmax(a, zc - R) - zc, hi = fmin(b, zc + R) - zc;
    if (hi <= lo) return 0.0;
    return PL_PI * (R * R * (hi - lo) - (hi * hi * hi - lo * lo * lo) / 3.0);
}

/* The series with room for cap samples of `bins` bins (at the first sample
 * or a restart); s_vel zeroed: no velocity at the first sample (a defined
 * checkpoint byte). */
static int sediment_alloc(sed_obs_t *o, size_t cap, size_t bins, pl_err_t *err)
{
    o->s_cap = cap;
    o->s_bins = bins;
    o->s_step = malloc(cap * sizeof *o->s_step);
    o->s_phi = calloc(cap * bins, sizeof(double));
    o->s_height = malloc(cap * sizeof(double));
    o->s_vel = calloc(cap, sizeof(double));
    o->s_vz = malloc(cap * sizeof(double));
    if (!o->s_step || !o->s_phi || !o->s_height || !o->s_vel || !o->s_vz)
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the sedimentation observer");
    return 0;
}

static int sample(pl_obs_run_t *run, void *state, pl_err_t *err)
{
    sed_obs_t *o = state;
    pl_sim_t *sim = run->sim;
    const pl_scene_t *sc = &sim->scene;
    const pl_colloid_t *c = sim->colloids;
    const double Lz = c->box[2];
    if (!o->s_step) {
        const size_t cap = pl_obs_expected(run, sc->observe.sediment_start, sc->observe.sediment_interval);
        int rc = sediment_alloc(o, cap, sc->observe.sediment_bins > 0 ? (size_t)sc->observe.sediment_bins : (size_t)Lz,
                                err);
        if (rc) return rc;
    }
    if (o->s_n >= o->s_cap) return 0;
    double *phi = o->s_phi + o->s_n * o->s_bins;
    const double dz = Lz / (double)o->s_bins, slab = c->box[0] * c->box[1] * dz;
    double h = 0.0, v = 0.0;
    for (size_t i = 0; i < c->n; ++i) { /* fixed order */
        h += c->z[i] + (double)c->iz[i] * Lz;
        v += c->vz[i];
        const double R = c->rad[i];
        /* the slabs the sphere cuts; periodic images in z wrap */
        const long long b0 = (long long)floor((c->z[i] - R) / dz), b1 = (long long)floor((c->z[i] + R) / dz);
        for (long long b = b0; b <= b1; ++b) {
            long long bw = ((b % (long long)o->s_bins) + (long long)o->s_bins) % (long long)o->s_bins;
            if (!c->periodic[2] && bw != b) continue;
            phi[bw] += slice_volume(c->z[i], R, (double)b * dz, (double)(b + 1) * dz) / slab;
        }
    }
    h /= (double)c->n;
    v /= (double)c->n;
    double uf = 0.0; /* the fluid's mean velocity (the back flow of a periodic box) */
    if (sim->fluid.n > 0) {
        pl_fluid_obs_t fo;
        double kT;
        pl_sim_observe(sim, &fo, &kT);
        uf = fo.momentum[2] / (double)sim->fluid.n;
    }
    const size_t k = o->s_n;
    o->s_step[k] = sim->step;
    o->s_height[k] = h;
    o->s_vz[k] = v - uf;
    if (k > 0) { /* from the mean height (Brownian colloids have no velocity) */
        o->s_vel[k] = (h - o->s_height[k - 1]) / ((double)(sim->step - o->s_step[k - 1]) * sc->srd.dt) - uf;
        pl_blocking_add(&o->s_vb, o->s_vel[k]);
    }
    o->s_n++;
    return 0;
}

/* The n settling samples from dz/dt, positive down (NULL: out of memory). */
static double *down_positive(const double *dzdt, size_t n)
{
    double *v = malloc((n ? n : 1) * sizeof *v);
    for (size_t k = 0; v && k < n; ++k) v[k] = -dzdt[k];
    return v;
}

static int obs_write(int64_t obs_, const pl_sim_t *sim, void *state)
{
    const sed_obs_t *o = state;
    const hid_t obs = (hid_t)obs_;
    const double dt = sim->scene.srd.dt;
    if (o->s_n == 0) return 0;
    int bad = pl_obs_series(obs, "colloid_height", o->s_n, o->s_step, dt, o->s_height, "a0") != 0;
    if (o->s_n > 1) {
        double *v = down_positive(o->s_vel + 1, o->s_n - 1);
        bad |= !v || pl_obs_series(obs, "settling_velocity", o->s_n - 1, o->s_step + 1, dt, v, "a0/t0") != 0;
        if (!bad) {
            const pl_window_t w = pl_obs_window(o->run, o->s_step + 1, v, o->s_n - 1);
            bad |= pl_obs_window_h5(obs, "settling_velocity", sim, &w) != 0;
            hid_t g = H5Gopen2(obs, "settling_velocity", H5P_DEFAULT);
            bad |= g < 0 || pl_h5_attr_str(g, "positive", "down") != 0;
            if (g >= 0 && H5Gclose(g) < 0) bad = 1;
        }
        free(v);
    }
    bad |= pl_obs_series(obs, "colloid_vz", o->s_n, o->s_step, dt, o->s_vz, "a0/t0") != 0;
    hid_t g = pl_h5_group(obs, "colloid_phi_z");
    bad |= g < 0;
    if (!bad) {
        double *t = malloc(o->s_n * sizeof(double)), *z = malloc(o->s_bins * sizeof(double));
        bad |= !t || !z;
        for (size_t k = 0; t && k < o->s_n; ++k) t[k] = (double)o->s_step[k] * dt;
        const double dzb = sim->colloids->box[2] / (double)o->s_bins;
        for (size_t k = 0; z && k < o->s_bins; ++k) z[k] = ((double)k + 0.5) * dzb;
        hsize_t d1[1] = {o->s_n}, d2[2] = {o->s_n, o->s_bins}, dz1[1] = {o->s_bins};
        if (!bad) {
            bad |= pl_obs_put(g, "step", H5T_NATIVE_LLONG, 1, d1, o->s_step, NULL) != 0;
            bad |= pl_obs_put(g, "time", H5T_NATIVE_DOUBLE, 1, d1, t, "t0") != 0;
            bad |= pl_obs_put(g, "value", H5T_NATIVE_DOUBLE, 2, d2, o->s_phi, "1") != 0;
            bad |= pl_obs_put(g, "z", H5T_NATIVE_DOUBLE, 1, dz1, z, "a0") != 0;
        }
        free(t);
        free(z);
    }
    if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
}

static int summary(pl_obs_sum_t *s, const pl_sim_t *sim, void *state)
{
    const sed_obs_t *o = state;
    if (o->s_n < 2) return 0;
    double *v = down_positive(o->s_vel + 1, o->s_n - 1);
    if (!v) return pl_err_set(s->b->err, PL_ERR_NOMEM, "out of memory for the sedimentation summary");
    if (o->s_n >= 3) {
        /* the average over the window of the stored velocities (s_vb holds
         * the whole run's, for se_vs_time and stop.observable) */
        const pl_window_t w = pl_obs_window(o->run, o->s_step + 1, v, o->s_n - 1);
        uint64_t nw;
        pl_blocking_result_t res = pl_window_blocking(v, o->s_n - 1, w.first, &nw);
        if (nw >= 2 && isfinite(res.mean) && isfinite(res.se)) {
            pl_obs_point_t pts[PL_OBS_NFRAC]; /* se_vs_time: the estimate's points (dz/dt) positive down */
            for (int f = 0; f < PL_OBS_NFRAC; ++f) {
                pts[f] = s->ept[f];
                pts[f].value = -pts[f].value;
            }
            pl_obs_sum_t down = *s;
            down.ept = pts;
            json_t *e = pl_obs_entry(&down, 0, res.mean, res.se, res.n_indep, res.inefficiency, res.plateau, "a0/t0");
            pl_json_str(s->b, e, "positive", "down");
            pl_json_int(s->b, e, "samples", (long long)nw);
            pl_obs_window_json(s->b, e, sim, &w);
            if (sim->scene.mapping.enabled) { /* a0/t0 -> m/s */
                const pl_mapping_t *m = &sim->scene.mapping.map;
                pl_json_real(s->b, e, "value_m_per_s", res.mean * m->a0 / m->t0);
                pl_json_real(s->b, e, "stderr_m_per_s", res.se * m->a0 / m->t0);
            }
            pl_json_set(s->b, s->all, "settling_velocity", e);
        }
    }
    pl_sediment_summary(s->b, s->all, &sim->scene, v, o->s_step + 1, o->s_n - 1);
    free(v);
    return 0;
}

/* settling_velocity (off: the estimate of no sample, as the first
 * checkpoints stored it) */
static void est_settling(const void *state, pl_obs_point_t *p)
{
    const sed_obs_t *o = state;
    pl_blocking_t none;
    if (!o) pl_blocking_init(&none);
    const pl_blocking_t *bl = o ? &o->s_vb : &none;
    pl_blocking_result_t r = pl_blocking_result(bl);
    p->valid = bl->n >= 2 && isfinite(r.mean) && isfinite(r.se);
    p->value = r.mean; /* dz/dt, as the state (summary() negates it) */
    p->se = r.se;
    p->plateau = r.plateau;
}

/* ---- checkpoint: meta {samples (-1: none yet), bins}; settling_blocking
 * (head), sediment_{step, phi, height, vz, velocity} */

static void ckpt_meta(const void *state, long long *m)
{
    const sed_obs_t *o = state;
    m[0] = o && o->s_step ? (long long)o->s_n : -1;
    m[1] = o ? (long long)o->s_bins : 0;
}

/* (also when off, state NULL: the initial accumulator, as the first
 * checkpoints stored it) */
static int ckpt_head(int64_t g, const void *state)
{
    const sed_obs_t *o = state;
    pl_blocking_t none;
    if (!o) pl_blocking_init(&none);
    return pl_ckpt_write_1d((hid_t)g, "settling_blocking", H5T_NATIVE_UCHAR, o ? &o->s_vb : &none, sizeof none);
}

static int ckpt_write(int64_t g_, const void *state)
{
    const sed_obs_t *o = state;
    const hid_t g = (hid_t)g_;
    if (!o->s_step) return 0;
    int bad = pl_ckpt_write_1d(g, "sediment_step", H5T_NATIVE_LLONG, o->s_step, o->s_n);
    bad |= pl_ckpt_write_1d(g, "sediment_phi", H5T_NATIVE_DOUBLE, o->s_phi, o->s_n * o->s_bins);
    bad |= pl_ckpt_write_1d(g, "sediment_height", H5T_NATIVE_DOUBLE, o->s_height, o->s_n);
    bad |= pl_ckpt_write_1d(g, "sediment_vz", H5T_NATIVE_DOUBLE, o->s_vz, o->s_n);
    bad |= pl_ckpt_write_1d(g, "sediment_velocity", H5T_NATIVE_DOUBLE, o->s_vel, o->s_n);
    return bad;
}

static int ckpt_read(int64_t g_, pl_obs_run_t *run, void *state, const long long *m, const char *path, pl_err_t *err)
{
    sed_obs_t *o = state;
    const hid_t g = (hid_t)g_;
    const pl_sim_t *sim = run->sim;
    const pl_scene_observe_t *so = &sim->scene.observe;
    if (m[0] >= 0 &&
        (m[0] > sim->step + 1 || m[1] != (so->sediment_bins > 0 ? so->sediment_bins : (long long)sim->colloids->box[2])))
        return pl_obs_ckpt_corrupt(err, path, "sedimentation series or bins of the wrong length");
    int rc = pl_obs_blocking_read(g_, "settling_blocking", &o->s_vb, 1, path, err);
    if (rc || m[0] < 0) return rc;
    o->s_n = (size_t)m[0];
    if ((rc = sediment_alloc(o, o->s_n ? o->s_n : 1, (size_t)m[1], err))) return rc;
    if ((rc = pl_ckpt_read_1d(g, "sediment_step", H5T_NATIVE_LLONG, o->s_step, o->s_n, path, err)) ||
        (rc = pl_ckpt_read_1d(g, "sediment_phi", H5T_NATIVE_DOUBLE, o->s_phi, o->s_n * o->s_bins, path, err)) ||
        (rc = pl_ckpt_read_1d(g, "sediment_height", H5T_NATIVE_DOUBLE, o->s_height, o->s_n, path, err)) ||
        (rc = pl_ckpt_read_1d(g, "sediment_vz", H5T_NATIVE_DOUBLE, o->s_vz, o->s_n, path, err)) ||
        (rc = pl_ckpt_read_1d(g, "sediment_velocity", H5T_NATIVE_DOUBLE, o->s_vel, o->s_n, path, err)))
        return rc;
    return 0;
}

static int resume(pl_obs_run_t *run, void *state, pl_err_t *err)
{
    sed_obs_t *o = state;
    const pl_scene_observe_t *so = &run->sim->scene.observe;
    if (!o->s_step) return 0;
    const size_t cap = pl_obs_expected(run, so->sediment_start, so->sediment_interval);
    if (cap <= o->s_cap) return 0;
    int bad = pl_obs_grow((void **)&o->s_step, o->s_n, cap, sizeof *o->s_step);
    bad |= pl_obs_grow((void **)&o->s_phi, o->s_n * o->s_bins, cap * o->s_bins, sizeof(double));
    bad |= pl_obs_grow((void **)&o->s_height, o->s_n, cap, sizeof(double));
    bad |= pl_obs_grow((void **)&o->s_vel, o->s_n, cap, sizeof(double));
    bad |= pl_obs_grow((void **)&o->s_vz, o->s_n, cap, sizeof(double));
    if (bad) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the sedimentation observer");
    o->s_cap = cap;
    return 0;
}

static const pl_obs_estimate_t estimates[] = {{"settling_velocity", 5, est_settling, NULL}};

const pl_observer_t pl_observer_sediment = {
    .name = "sedimentation", .stage = "observe-sediment",
    .interval = offsetof(pl_scene_observe_t, sediment_interval),
    .start = offsetof(pl_scene_observe_t, sediment_start), .interval_key = "observe.sediment_interval",
    .start_key = "observe.sediment_start", .at_start = 1, .need = 2,
    .create = create, .sample = sample, .write = obs_write, .summary = summary,
    .meta_slot = 11, .nmeta = 2, .ckpt_meta = ckpt_meta, .ckpt_head = ckpt_head, .ckpt_write = ckpt_write,
    .ckpt_read = ckpt_read, .resume = resume, .free = obs_free, .estimates = estimates, .nestimates = 1,
    .entries = pl_sediment_entries,
};
