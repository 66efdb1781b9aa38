/* Observer Steinhardt Q4/Q6 (peloid/observer.h row "Steinhardt"; the
 * order parameters of peloid/steinhardt.h): every
 * observe.steinhardt_interval steps the local q4, q6 of each colloid
 * (neighbours closer than observe.steinhardt_rmax) and the global Q4, Q6
 * of the system-averaged q_lm; the time averages of Q4, Q6 and of the mean
 * local q4, q6 with their blocking SE (peloid/blocking.h), the estimates
 * steinhardt_Q4, steinhardt_Q6, steinhardt_q4_mean, steinhardt_q6_mean
 * (summary.json, stop.observable); observables.h5 /observables/
 * colloid_steinhardt also holds each colloid's q4, q6 at the last step. */
#include <gsl/gsl_sf_legendre.h>
#include <hdf5.h>
#include <jansson.h>
#include <math.h>
#include <stdlib.h>

#include "checkpoint_h5.h"
#include "json_build.h"
#include "observables_out.h"
#include "peloid/colloid.h"
#include "peloid/h5.h"
#include "peloid/observer.h"
#include "peloid/real.h" /* PL_PI */
#include "peloid/steinhardt.h"

static const int ells[PL_STEINHARDT_NL] = {4, 6};
enum { LMAX = 6, NLM = 5 + 7 }; /* m = 0..l of l = 4, 6 */

int pl_steinhardt(const pl_steinhardt_params_t *p, size_t n, const double *x, const double *y, const double *z,
                  double *q, pl_steinhardt_result_t *out, pl_err_t *err)
{
    double *acc = calloc(2 * NLM * (n ? n : 1), sizeof *acc); /* re, im of q_lm (m >= 0) per centre */
    size_t *nb = calloc(n ? n : 1, sizeof *nb);
    double *P = malloc(gsl_sf_legendre_array_n(LMAX) * sizeof *P);
    if (!acc || !nb || !P) {
        free(acc);
        free(nb);
        free(P);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the Steinhardt order");
    }
    *out = (pl_steinhardt_result_t){{0.0, 0.0}, {0.0, 0.0}, 0, 0};
    const double r2max = p->rmax * p->rmax;
    for (size_t i = 0; i < n; ++i) /* fixed order */
        for (size_t j = i + 1; j < n; ++j) {
            double d[3] = {x[j] - x[i], y[j] - y[i], z[j] - z[i]};
            for (int a = 0; a < 3; ++a)
                if (p->periodic[a]) d[a] -= p->box[a] * round(d[a] / p->box[a]);
            const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            if (!(r2 < r2max) || r2 == 0.0) continue;
            const double r = sqrt(r2), phi = atan2(d[1], d[0]);
            gsl_sf_legendre_array_e(GSL_SF_LEGENDRE_SPHARM, LMAX, d[2] / r, -1.0, P);
            /* Y_lm(-r) = (-1)^l Y_lm(r): the same for both ends at even l */
            for (int k = 0, o = 0; k < PL_STEINHARDT_NL; ++k)
                for (int m = 0; m <= ells[k]; ++m, ++o) {
                    const double plm = P[gsl_sf_legendre_array_index((size_t)ells[k], (size_t)m)];
                    const double re = plm * cos(m * phi), im = plm * sin(m * phi);
                    acc[2 * (NLM * i + (size_t)o)] += re, acc[2 * (NLM * i + (size_t)o) + 1] += im;
                    acc[2 * (NLM * j + (size_t)o)] += re, acc[2 * (NLM * j + (size_t)o) + 1] += im;
                }
            nb[i]++, nb[j]++;
            out->bonds++;
        }
    double Qlm[2 * NLM] = {0};
    for (size_t i = 0; i < n; ++i) {
        if (nb[i]) out->centres++;
        for (int k = 0, o = 0; k < PL_STEINHARDT_NL; ++k) {
            double s = 0.0;
            for (int m = 0; m <= ells[k]; ++m, ++o) {
                const double re = nb[i] ? acc[2 * (NLM * i + (size_t)o)] / (double)nb[i] : 0.0;
                const double im = nb[i] ? acc[2 * (NLM * i + (size_t)o) + 1] / (double)nb[i] : 0.0;
                s += (m ? 2.0 : 1.0) * (re * re + im * im); /* q_l,-m = (-1)^m conj(q_lm) */
                Qlm[2 * o] += re, Qlm[2 * o + 1] += im;
            }
            const double ql = sqrt(4.0 * PL_PI / (2.0 * ells[k] + 1.0) * s);
            if (q) q[2 * i + (size_t)k] = nb[i] ? ql : NAN;
            if (nb[i]) out->q_mean[k] += ql;
        }
    }
    for (int k = 0, o = 0; k < PL_STEINHARDT_NL; ++k) {
        double s = 0.0;
        const double c = out->centres ? (double)out->centres : 1.0;
        for (int m = 0; m <= ells[k]; ++m, ++o)
            s += (m ? 2.0 : 1.0) * (Qlm[2 * o] * Qlm[2 * o] + Qlm[2 * o + 1] * Qlm[2 * o + 1]) / (c * c);
        out->Q[k] = out->centres ? sqrt(4.0 * PL_PI / (2.0 * ells[k] + 1.0) * s) : NAN;
        out->q_mean[k] = out->centres ? out->q_mean[k] / c : NAN;
    }
    free(acc);
    free(nb);
    free(P);
    return 0;
}

/* ---- the observer ------------------------------------------------------ */

enum { NV = 4 }; /* Q4, Q6, mean q4, mean q6 */
static const char *const v_names[NV] = {"steinhardt_Q4", "steinhardt_Q6", "steinhardt_q4_mean",
                                        "steinhardt_q6_mean"};

typedef struct {
    pl_obs_run_t *run;
    pl_blocking_t b[NV];
} st_obs_t;

#define OFFO(m) offsetof(pl_scene_t, observe.m)

static int check(const pl_scene_t *sc, pl_err_t *err)
{
    const pl_scene_observe_t *o = &sc->observe;
    if (o->steinhardt_interval <= 0) return 0;
    double half = INFINITY; /* minimum image along the periodic axes */
    if (sc->box.walls_xy == PL_WALLS_NONE) half = 0.5 * fmin(sc->box.cells[0], sc->box.cells[1]);
    if (sc->box.walls_z == PL_WALLS_NONE) half = fmin(half, 0.5 * sc->box.cells[2]);
    if (!(o->steinhardt_rmax > 0))
        return pl_scene_fail(sc, err, OFFO(steinhardt_interval), "observe.steinhardt_interval",
                             "%lld needs its neighbour cut-off, observe.steinhardt_rmax (%g a0); allowed: 0, or "
                             "observe.steinhardt_rmax > 0 (e.g. the first minimum of g(r)) and <= %g a0",
                             o->steinhardt_interval, o->steinhardt_rmax, half);
    if (o->steinhardt_rmax > half)
        return pl_scene_fail(sc, err, OFFO(steinhardt_rmax), "observe.steinhardt_rmax",
                             "%g a0 is beyond half the periodic box edge; allowed: <= %g a0 (minimum image)",
                             o->steinhardt_rmax, half);
    const double contact = 2.0 * pl_colloid_radius_min(sc); /* the closest two colloids can be without overlap */
    if (o->steinhardt_rmax <= contact)
        return pl_scene_fail(sc, err, OFFO(steinhardt_rmax), "observe.steinhardt_rmax",
                             "%g a0 is at or below contact (2 x the smallest radius, %g a0): no two colloids are "
                             "neighbours, so Q4 and Q6 would have no bond; allowed: > %g a0 (e.g. the first "
                             "minimum of g(r)) and <= %g a0",
                             o->steinhardt_rmax, contact, contact, half);
    return 0;
}

static int create(pl_obs_run_t *run, void **state, pl_err_t *err)
{
    st_obs_t *o = calloc(1, sizeof *o);
    if (!o) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the Steinhardt observer");
    o->run = run;
    for (int k = 0; k < NV; ++k) pl_blocking_init(&o->b[k]);
    *state = o;
    return 0;
}

static void obs_free(void *state) { free(state); }

static pl_steinhardt_params_t params(const pl_sim_t *sim)
{
    const pl_colloid_t *c = sim->colloids;
    pl_steinhardt_params_t p = {.rmax = sim->scene.observe.steinhardt_rmax};
    for (int d = 0; d < 3; ++d) p.box[d] = c->box[d], p.periodic[d] = c->periodic[d];
    return p;
}

static int sample(pl_obs_run_t *run, void *state, pl_err_t *err)
{
    st_obs_t *o = state;
    const pl_colloid_t *c = run->sim->colloids;
    const pl_steinhardt_params_t p = params(run->sim);
    pl_steinhardt_result_t r;
    int rc = pl_steinhardt(&p, c->n, c->x, c->y, c->z, NULL, &r, err);
    if (rc || !r.centres) return rc; /* no bond: no sample */
    const double v[NV] = {r.Q[0], r.Q[1], r.q_mean[0], r.q_mean[1]};
    for (int k = 0; k < NV; ++k) pl_blocking_add(&o->b[k], v[k]);
    return 0;
}

/* /observables/colloid_steinhardt/{l, Q, Q_se, q_mean, q_mean_se, samples,
 * r_max, q_last (n x 2: each colloid's q4, q6 at the last step, NAN without
 * a neighbour)}. */
static int obs_write(int64_t obs, const pl_sim_t *sim, void *state)
{
    const st_obs_t *o = state;
    if (o->b[0].n == 0) return 0;
    const pl_colloid_t *c = sim->colloids;
    double Q[2], Qse[2], qm[2], qse[2];
    for (int k = 0; k < 2; ++k) {
        pl_blocking_result_t a = pl_blocking_result(&o->b[k]), b = pl_blocking_result(&o->b[2 + k]);
        Q[k] = a.mean, Qse[k] = isfinite(a.se) ? a.se : 0.0;
        qm[k] = b.mean, qse[k] = isfinite(b.se) ? b.se : 0.0;
    }
    double *ql = malloc(2 * (c->n ? c->n : 1) * sizeof *ql);
    pl_steinhardt_result_t r;
    pl_err_t ignore = {0, ""};
    const pl_steinhardt_params_t p = params(sim);
    hid_t g = pl_h5_group((hid_t)obs, "colloid_steinhardt");
    int bad = !ql || g < 0 || pl_steinhardt(&p, c->n, c->x, c->y, c->z, ql, &r, &ignore);
    if (!bad) {
        const long long l[2] = {4, 6};
        const unsigned long long ns = o->b[0].n;
        hsize_t d2[1] = {2}, dq[2] = {c->n, 2};
        bad |= pl_obs_put(g, "l", H5T_NATIVE_LLONG, 1, d2, l, NULL) != 0;
        bad |= pl_obs_put(g, "Q", H5T_NATIVE_DOUBLE, 1, d2, Q, "1") != 0;
        bad |= pl_obs_put(g, "Q_se", H5T_NATIVE_DOUBLE, 1, d2, Qse, "1") != 0;
        bad |= pl_obs_put(g, "q_mean", H5T_NATIVE_DOUBLE, 1, d2, qm, "1") != 0;
        bad |= pl_obs_put(g, "q_mean_se", H5T_NATIVE_DOUBLE, 1, d2, qse, "1") != 0;
        bad |= pl_obs_put(g, "samples", H5T_NATIVE_ULLONG, 0, NULL, &ns, NULL) != 0;
        bad |= pl_obs_put(g, "r_max", H5T_NATIVE_DOUBLE, 0, NULL, &p.rmax, "a0") != 0;
        bad |= pl_obs_put(g, "q_last", H5T_NATIVE_DOUBLE, 2, dq, ql, "1") != 0;
        bad |= pl_h5_attr_str(g, "meaning", "Steinhardt bond order, l = 4, 6, neighbours closer than r_max: Q the "
                                            "global Q_l of the colloid-averaged q_lm, q_mean the mean local q_l, "
                                            "time averages with the blocking SE; q_last: each colloid's q_l at "
                                            "the last step (NaN without a neighbour)") != 0;
    }
    if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    free(ql);
    return bad ? -1 : 0;
}

static int summary(pl_obs_sum_t *s, const pl_sim_t *sim, void *state)
{
    const st_obs_t *o = state;
    for (int k = 0; k < NV; ++k) {
        if (o->b[k].n < 2) continue;
        pl_blocking_result_t res = pl_blocking_result(&o->b[k]);
        if (!isfinite(res.mean) || !isfinite(res.se)) continue;
        json_t *e = pl_obs_entry(s, k, res.mean, res.se, res.n_indep, res.inefficiency, res.plateau, "1");
        pl_json_int(s->b, e, "samples", (long long)o->b[k].n);
        pl_json_int(s->b, e, "l", k % 2 ? 6 : 4);
        pl_json_real(s->b, e, "r_max", sim->scene.observe.steinhardt_rmax);
        pl_json_set(s->b, s->all, v_names[k], e);
    }
    return 0;
}

static void est(const void *state, int k, pl_obs_point_t *p)
{
    const st_obs_t *o = state;
    if (!o) return;
    pl_blocking_result_t r = pl_blocking_result(&o->b[k]);
    p->valid = o->b[k].n >= 2 && isfinite(r.mean) && isfinite(r.se);
    p->value = r.mean;
    p->se = r.se;
    p->plateau = r.plateau;
}
static void est0(const void *s, pl_obs_point_t *p) { est(s, 0, p); }
static void est1(const void *s, pl_obs_point_t *p) { est(s, 1, p); }
static void est2(const void *s, pl_obs_point_t *p) { est(s, 2, p); }
static void est3(const void *s, pl_obs_point_t *p) { est(s, 3, p); }

/* ---- checkpoint: steinhardt_blocking */

static int ckpt_write(int64_t g, const void *state)
{
    const st_obs_t *o = state;
    return pl_ckpt_write_1d((hid_t)g, "steinhardt_blocking", H5T_NATIVE_UCHAR, o->b, sizeof o->b);
}

static int ckpt_read(int64_t g, pl_obs_run_t *run, void *state, const long long *m, const char *path, pl_err_t *err)
{
    (void)run, (void)m;
    st_obs_t *o = state;
    return pl_obs_blocking_read(g, "steinhardt_blocking", o->b, NV, path, err);
}

static const pl_obs_estimate_t estimates[NV] = {
    {"steinhardt_Q4", -1, est0, NULL},
    {"steinhardt_Q6", -1, est1, NULL},
    {"steinhardt_q4_mean", -1, est2, NULL},
    {"steinhardt_q6_mean", -1, est3, NULL},
};

const pl_observer_t pl_observer_steinhardt = {
    .name = "Steinhardt", .stage = "observe-steinhardt",
    .interval = offsetof(pl_scene_observe_t, steinhardt_interval),
    .start = offsetof(pl_scene_observe_t, steinhardt_start), .interval_key = "observe.steinhardt_interval",
    .start_key = "observe.steinhardt_start", .at_start = 1, .need = 2, .pairs = 1,
    .none_why = "fewer than 2 samples with two colloids closer than observe.steinhardt_rmax",
    .check = check, .create = create, .sample = sample, .write = obs_write, .summary = summary,
    .meta_slot = -1, .ckpt_write = ckpt_write, .ckpt_read = ckpt_read, .free = obs_free,
    .estimates = estimates, .nestimates = NV,
};
