/* Observer velocity distributions (peloid/observer.h row
 * "velocity-distribution"): fluid and colloid velocity components, scaled by
 * sqrt(M / kT) about their mean, histogrammed (peloid/vdist.h): chi^2
 * against the unit Gaussian of Maxwell-Boltzmann (Hecht Figs. 2, 8). */
#include <hdf5.h>
#include <jansson.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint_h5.h"
#include "json_build.h"
#include "observables_out.h"
#include "peloid/colloid.h"
#include "peloid/h5.h"
#include "peloid/observer.h"
#include "peloid/vdist.h"
#include "peloid/colloid_integrator.h"

enum { VD_BINS = 60 };

typedef struct {
    pl_obs_run_t *run;
    pl_vdist_t *vd[2]; /* 0 fluid, 1 colloids */
    double *vs[3];     /* scaled components, fluid count (>= colloid count) */
    size_t vs_n;
} vd_obs_t;

static int create(pl_obs_run_t *run, void **state, pl_err_t *err)
{
    vd_obs_t *o = calloc(1, sizeof *o);
    if (!o) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the velocity-distribution observer");
    o->run = run;
    *state = o;
    return 0;
}

static void obs_free(void *state)
{
    vd_obs_t *o = state;
    pl_vdist_free(o->vd[0]);
    pl_vdist_free(o->vd[1]);
    for (int d = 0; d < 3; ++d) free(o->vs[d]);
    free(o);
}

/* Velocity components scaled to the unit Gaussian: (v - <v>) sqrt(M / kT). */
static void scale_components(double *const out[3], size_t n, const double *const v[3], const double *mass,
                             double kT)
{
    for (int d = 0; d < 3; ++d) {
        double m = 0.0;
        for (size_t i = 0; i < n; ++i) m += v[d][i]; /* fixed order */
        m /= (double)n;
        for (size_t i = 0; i < n; ++i) out[d][i] = (v[d][i] - m) * sqrt((mass ? mass[i] : 1.0) / kT);
    }
}

/* The two histograms and the scaled components' buffers (at the first
 * sample or a restart). */
static int vdist_alloc(vd_obs_t *o, const pl_sim_t *sim, pl_err_t *err)
{
    pl_vdist_params_t p = {.nbins = VD_BINS, .vmax = 4.0}; /* unit Gaussian: 4 sigma, the tails apart */
    for (int k = 0; k < 2; ++k) {
        int rc = pl_vdist_create(&p, &o->vd[k], err);
        if (rc) return rc;
    }
    o->vs_n = sim->fluid.n > sim->colloids->n ? sim->fluid.n : sim->colloids->n;
    for (int d = 0; d < 3; ++d)
        if (!(o->vs[d] = malloc(o->vs_n * sizeof(double))))
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the velocity-distribution observer");
    return 0;
}

static int sample(pl_obs_run_t *run, void *state, pl_err_t *err)
{
    vd_obs_t *o = state;
    const pl_sim_t *sim = run->sim;
    const pl_colloid_t *c = sim->colloids;
    const size_t nf = sim->fluid.n;
    if (!o->vd[1]) {
        int rc = vdist_alloc(o, sim, err);
        if (rc) return rc;
    }
    const double kT = pl_scene_kT(&sim->scene);
    if (nf > 1) {
        for (int d = 0; d < 3; ++d)
            for (size_t i = 0; i < nf; ++i) o->vs[d][i] = (double)sim->fluid.v[d][i];
        const double *const v[3] = {o->vs[0], o->vs[1], o->vs[2]};
        scale_components(o->vs, nf, v, NULL, kT);
        pl_vdist_sample(o->vd[0], nf, o->vs[0], o->vs[1], o->vs[2]);
    }
    if (c->n > 1 && pl_colloid_integrator(c->integrator)->inertial) {
        const double *const v[3] = {c->vx, c->vy, c->vz};
        scale_components(o->vs, c->n, v, c->mass, kT);
        pl_vdist_sample(o->vd[1], c->n, o->vs[0], o->vs[1], o->vs[2]);
    }
    return 0;
}

/* Components sampled into histogram k (0: none, e.g. Brownian colloids
 * have no velocity). */
static uint64_t vdist_total(const vd_obs_t *o, int k)
{
    uint64_t tot = 0;
    for (size_t b = 0; o->vd[k] && b < VD_BINS + 2; ++b) tot += pl_vdist_counts(o->vd[k], 3)[b];
    return tot;
}

static int obs_write(int64_t obs, const pl_sim_t *sim, void *state)
{
    (void)sim;
    const vd_obs_t *o = state;
    static const char *const vname[2] = {"fluid_velocity_distribution", "colloid_velocity_distribution"};
    int bad = 0;
    for (int k = 0; !bad && k < 2; ++k) {
        if (!vdist_total(o, k)) continue; /* no sample: no group */
        hid_t g = pl_h5_group((hid_t)obs, vname[k]);
        bad |= g < 0;
        uint64_t buf[4 * (VD_BINS + 2)];
        for (int a = 0; a < 4; ++a)
            memcpy(buf + (VD_BINS + 2) * a, pl_vdist_counts(o->vd[k], a), (VD_BINS + 2) * sizeof(uint64_t));
        hsize_t d2[2] = {4, VD_BINS + 2};
        if (!bad) bad |= pl_obs_put(g, "value", H5T_NATIVE_UINT64, 2, d2, buf, "1") != 0;
        if (!bad)
            bad |= pl_h5_attr_str(g, "meaning", "counts of (v - <v>) sqrt(M/kT) per axis x, y, z, all: bin 0 below "
                                                "-4, bins 1..60 of width 2/15 over [-4, 4], bin 61 above 4") != 0;
        if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    }
    return bad ? -1 : 0;
}

static int summary(pl_obs_sum_t *s, const pl_sim_t *sim, void *state)
{
    (void)sim;
    const vd_obs_t *o = state;
    static const char *const vkey[2] = {"fluid_velocity_chi2", "colloid_velocity_chi2"};
    for (int k = 0; k < 2; ++k) {
        double chi2, p;
        int dof;
        pl_err_t ignore = {0, ""};
        if (!vdist_total(o, k) || pl_vdist_chi2(o->vd[k], 3, 1.0, &chi2, &dof, &p, &ignore)) continue;
        json_t *e = json_object();
        pl_json_real(s->b, e, "chi2", chi2);
        pl_json_int(s->b, e, "dof", dof);
        pl_json_real(s->b, e, "p_value", p);
        pl_json_real(s->b, e, "wall_s", s->wall);
        pl_json_str(s->b, e, "against", "unit Gaussian of (v - <v>) sqrt(M/kT), all axes (Maxwell-Boltzmann)");
        pl_json_set(s->b, s->all, vkey[k], e);
    }
    return 0;
}

/* ---- checkpoint: meta {created}; vdist_fluid, vdist_colloid */

static const char *const vn[2] = {"vdist_fluid", "vdist_colloid"};

static void ckpt_meta(const void *state, long long *m)
{
    const vd_obs_t *o = state;
    m[0] = o && o->vd[1] != NULL;
}

static int ckpt_write(int64_t g, const void *state)
{
    const vd_obs_t *o = state;
    int bad = 0;
    for (int k = 0; o->vd[1] && k < 2; ++k) {
        pl_vdist_state_t st = pl_vdist_state(o->vd[k]);
        bad |= pl_ckpt_write_1d((hid_t)g, vn[k], H5T_NATIVE_UINT64, st.counts, st.ncounts);
    }
    return bad;
}

static int ckpt_read(int64_t g, pl_obs_run_t *run, void *state, const long long *m, const char *path, pl_err_t *err)
{
    vd_obs_t *o = state;
    if (!m[0]) return 0;
    int rc = vdist_alloc(o, run->sim, err);
    for (int k = 0; !rc && k < 2; ++k) {
        pl_vdist_state_t st = pl_vdist_state(o->vd[k]);
        rc = pl_ckpt_read_1d((hid_t)g, vn[k], H5T_NATIVE_UINT64, st.counts, st.ncounts, path, err);
    }
    return rc;
}

const pl_observer_t pl_observer_vdist = {
    .name = "velocity-distribution", .stage = "observe-vdist",
    .interval = offsetof(pl_scene_observe_t, vdist_interval), .start = offsetof(pl_scene_observe_t, vdist_start),
    .interval_key = "observe.vdist_interval", .start_key = "observe.vdist_start", .at_start = 1, .need = 1,
    .create = create, .sample = sample, .write = obs_write, .summary = summary,
    .meta_slot = 10, .nmeta = 1, .ckpt_meta = ckpt_meta, .ckpt_write = ckpt_write, .ckpt_read = ckpt_read,
    .free = obs_free,
};
