/* Observer S(q) (peloid/observer.h row "S(q)"): the colloid centres' static
 * structure factor, direct sum over the box's wave vectors (peloid/sq.h),
 * mean and SE per |q| bin; summary sq_peak: the highest bin. */
#include <hdf5.h>
#include <jansson.h>
#include <math.h>
#include <stdlib.h>

#include "checkpoint_h5.h"
#include "json_build.h"
#include "observables_out.h"
#include "peloid/h5.h"
#include "peloid/observe_check.h"
#include "peloid/observer.h"
#include "peloid/real.h" /* PL_PI */
#include "peloid/sq.h"

typedef struct {
    pl_obs_run_t *run;
    pl_sq_t *sq;
} sq_obs_t;

static int check(const pl_scene_t *sc, pl_err_t *err)
{
    const pl_scene_observe_t *o = &sc->observe;
    if (o->sq_interval > 0 && (sc->box.walls_xy != PL_WALLS_NONE || sc->box.walls_z != PL_WALLS_NONE))
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, observe.sq_interval), "observe.sq_interval",
                             "%lld with walls: S(q) sums over the wave vectors of a periodic box; allowed: 0 "
                             "with walls", o->sq_interval);
    return o->sq_interval > 0 ? pl_observe_sq_cost_check(sc, err) : 0;
}

static int create(pl_obs_run_t *run, void **state, pl_err_t *err)
{
    sq_obs_t *s = calloc(1, sizeof *s);
    if (!s) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the S(q) observer");
    s->run = run;
    *state = s;
    return 0;
}

static void obs_free(void *state)
{
    sq_obs_t *s = state;
    pl_sq_free(s->sq);
    free(s);
}

static int sq_ready(const pl_sim_t *sim, sq_obs_t *o, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const pl_colloid_t *c = sim->colloids;
    pl_sq_params_t p = {.qmax = sc->observe.sq_qmax > 0 ? sc->observe.sq_qmax : 4.0 * PL_PI / sc->colloids.radius,
                        .nbins = (size_t)sc->observe.sq_bins, .nmax = c->n};
    for (int d = 0; d < 3; ++d) p.box[d] = c->box[d];
    return pl_sq_create(&p, sim->nthreads, &o->sq, err);
}

static int sample(pl_obs_run_t *run, void *state, pl_err_t *err)
{
    sq_obs_t *o = state;
    const pl_colloid_t *c = run->sim->colloids;
    if (!o->sq) {
        int rc = sq_ready(run->sim, o, err);
        if (rc) return rc;
    }
    pl_sq_sample(o->sq, c->n, c->x, c->y, c->z);
    return 0;
}

/* /observables/colloid_sq/{q, q_mean, q_R, value (1 x nbins), value_se,
 * vectors, step, time, samples}: bins without a wave vector hold 0. */
static int obs_write(int64_t obs, const pl_sim_t *sim, void *state)
{
    const sq_obs_t *o = state;
    if (!o->sq || pl_sq_samples(o->sq) == 0) return 0;
    size_t nb = (size_t)sim->scene.observe.sq_bins;
    double *buf = malloc(5 * nb * sizeof(double));
    uint64_t *nv = malloc(nb * sizeof *nv);
    hid_t g = pl_h5_group((hid_t)obs, "colloid_sq");
    int bad = !buf || !nv || g < 0;
    if (!bad) {
        double *q = buf, *qm = q + nb, *qR = qm + nb, *S = qR + nb, *se = S + nb;
        pl_sq_result(o->sq, q, qm, S, se, nv);
        for (size_t b = 0; b < nb; ++b) {
            qR[b] = q[b] * sim->scene.colloids.radius;
            if (!isfinite(qm[b])) qm[b] = 0.0;
            if (!isfinite(S[b])) S[b] = 0.0;
            if (!isfinite(se[b])) se[b] = 0.0;
        }
        hsize_t d1[1] = {nb}, d2[2] = {1, nb}, one[1] = {1};
        long long st = sim->step;
        double t = (double)st * sim->scene.srd.dt;
        unsigned long long ns = pl_sq_samples(o->sq);
        bad |= pl_obs_put(g, "q", H5T_NATIVE_DOUBLE, 1, d1, q, "1/a0") != 0;
        bad |= pl_obs_put(g, "q_mean", H5T_NATIVE_DOUBLE, 1, d1, qm, "1/a0") != 0;
        bad |= pl_obs_put(g, "q_R", H5T_NATIVE_DOUBLE, 1, d1, qR, "1/R") != 0;
        bad |= pl_obs_put(g, "value", H5T_NATIVE_DOUBLE, 2, d2, S, "1") != 0;
        bad |= pl_obs_put(g, "value_se", H5T_NATIVE_DOUBLE, 2, d2, se, "1") != 0;
        bad |= pl_obs_put(g, "vectors", H5T_NATIVE_UINT64, 1, d1, nv, NULL) != 0;
        bad |= pl_obs_put(g, "step", H5T_NATIVE_LLONG, 1, one, &st, NULL) != 0;
        bad |= pl_obs_put(g, "time", H5T_NATIVE_DOUBLE, 1, one, &t, "t0") != 0;
        bad |= pl_obs_put(g, "samples", H5T_NATIVE_ULLONG, 0, NULL, &ns, NULL) != 0;
    }
    if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    free(buf);
    free(nv);
    return bad ? -1 : 0;
}

static const char *const entries[] = {"sq_peak", NULL}; /* the row's entries */

/* sq_peak: the highest bin of S(q). */
static int summary(pl_obs_sum_t *s, const pl_sim_t *sim, void *state)
{
    const sq_obs_t *o = state;
    pl_json_t *b = s->b;
    if (!o->sq || pl_sq_samples(o->sq) < 2) return 0;
    size_t nb = (size_t)sim->scene.observe.sq_bins, best = nb;
    double *buf = malloc(3 * nb * sizeof(double));
    if (!buf) return 0;
    double *qm = buf, *S = qm + nb, *sse = S + nb;
    pl_sq_result(o->sq, NULL, qm, S, sse, NULL);
    for (size_t k = 0; k < nb; ++k)
        if (isfinite(S[k]) && isfinite(sse[k]) && (best == nb || S[k] > S[best])) best = k;
    if (best < nb) {
        json_t *e = json_object();
        pl_json_real(b, e, "value", S[best]);
        pl_json_real(b, e, "stderr", sse[best]);
        pl_json_real(b, e, "n_independent", (double)pl_sq_samples(o->sq));
        pl_json_real(b, e, "q", qm[best]);
        pl_json_real(b, e, "q_R", qm[best] * sim->scene.colloids.radius);
        pl_json_int(b, e, "wave_vectors", (long long)pl_sq_vectors(o->sq));
        pl_json_real(b, e, "wall_s", s->wall);
        pl_json_str(b, e, "unit", "1");
        pl_json_set(b, s->all, entries[0], e);
    }
    free(buf);
    return 0;
}

/* ---- checkpoint: meta {created}; sq_blocking, sq_samples */

static void ckpt_meta(const void *state, long long *m)
{
    const sq_obs_t *o = state;
    m[0] = o && o->sq != NULL;
}

static int ckpt_write(int64_t g, const void *state)
{
    const sq_obs_t *o = state;
    if (!o->sq) return 0;
    pl_sq_state_t st = pl_sq_state(o->sq);
    int bad = pl_ckpt_write_1d((hid_t)g, "sq_blocking", H5T_NATIVE_UCHAR, st.blocking,
                               st.nblocking * sizeof(pl_blocking_t));
    bad |= pl_ckpt_write_1d((hid_t)g, "sq_samples", H5T_NATIVE_UINT64, st.samples, 1);
    return bad;
}

static int ckpt_read(int64_t g, pl_obs_run_t *run, void *state, const long long *m, const char *path, pl_err_t *err)
{
    sq_obs_t *o = state;
    if (!m[0]) return 0;
    int rc = sq_ready(run->sim, o, err);
    if (rc) return rc;
    pl_sq_state_t st = pl_sq_state(o->sq);
    if ((rc = pl_obs_blocking_read(g, "sq_blocking", st.blocking, st.nblocking, path, err))) return rc;
    return pl_ckpt_read_1d((hid_t)g, "sq_samples", H5T_NATIVE_UINT64, st.samples, 1, path, err);
}

const pl_observer_t pl_observer_sq = {
    .name = "S(q)", .stage = "observe-sq",
    .interval = offsetof(pl_scene_observe_t, sq_interval), .start = offsetof(pl_scene_observe_t, sq_start),
    .interval_key = "observe.sq_interval", .start_key = "observe.sq_start", .at_start = 1, .need = 1,
    .check = check, .create = create, .sample = sample, .write = obs_write, .summary = summary,
    .meta_slot = 7, .nmeta = 1, .ckpt_meta = ckpt_meta, .ckpt_write = ckpt_write, .ckpt_read = ckpt_read,
    .free = obs_free,
    .entries = entries,
};
