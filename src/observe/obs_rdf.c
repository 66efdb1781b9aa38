/* Observer g(r) (peloid/observer.h row "g(r)"): the colloid centres' radial
 * distribution function (Hecht Sec. IX.C, Figs. 5-7, 10-13; PL Fig. 4),
 * peloid/rdf.h: ideal-gas normalisation of the accessible region, mean and SE
 * per bin by blocking over samples; optionally per size class (radius rank,
 * equal counts: partial g_ab).  Estimate rdf_peak: the highest bin. */
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
#include "peloid/rdf.h"

typedef struct {
    pl_obs_run_t *run;
    pl_rdf_t *rdf;
    pl_rdf_params_t par;
    /* per size class: ncls classes, npair = ncls (ncls + 1) / 2 partials */
    size_t ncls, npair;
    pl_rdf_t **rdfc; /* npair, pair (a, b), a <= b, in row order */
    int32_t *cls;    /* n: class of each colloid */
    double *cls_rad; /* ncls x 2: smallest and largest radius of each class */
    size_t *cls_n;   /* ncls: colloids per class */
} rdf_obs_t;

#define OFFO(m) offsetof(pl_scene_t, observe.m)

static int check(const pl_scene_t *sc, pl_err_t *err)
{
    const pl_scene_observe_t *o = &sc->observe;
    if (o->rdf_size_classes > 0) {
        const char *why = o->rdf_interval <= 0 ? "needs observe.rdf_interval > 0"
                          : o->rdf_size_classes < 2 ? "one class is the total g(r)"
                          : o->rdf_size_classes > sc->colloids.count ? "more classes than colloids"
                          : !(sc->colloids.polydispersity > 0) && sc->colloids.init != PL_CINIT_FILE
                              ? "all radii are equal (colloids.polydispersity = 0, no init_file)"
                              : NULL;
        if (why)
            return pl_scene_fail(sc, err, OFFO(rdf_size_classes), "observe.rdf_size_classes",
                                 "%lld: %s; allowed: 0, or 2..min(16, colloids.count) with polydisperse radii",
                                 o->rdf_size_classes, why);
    }
    if (o->rdf_interval > 0) {
        if (sc->box.walls_xy != PL_WALLS_NONE)
            return pl_scene_fail(sc, err, OFFO(rdf_interval), "observe.rdf_interval",
                                 "%lld with box.walls_xy: g(r) is normalised for x and y periodic; allowed: 0 "
                                 "with x/y walls", o->rdf_interval);
        double half = 0.5 * fmin(sc->box.cells[0], sc->box.cells[1]);
        if (sc->box.walls_z == PL_WALLS_NONE) half = fmin(half, 0.5 * sc->box.cells[2]);
        if (o->rdf_rmax > half)
            return pl_scene_fail(sc, err, OFFO(rdf_rmax), "observe.rdf_rmax",
                                 "%g a0 is beyond half the periodic box edge; allowed: <= %g a0 (minimum image)",
                                 o->rdf_rmax, half);
    }
    return 0;
}

static int create(pl_obs_run_t *run, void **state, pl_err_t *err)
{
    rdf_obs_t *r = calloc(1, sizeof *r);
    if (!r) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the g(r) observer");
    r->run = run;
    *state = r;
    return 0;
}

static void obs_free(void *state)
{
    rdf_obs_t *r = state;
    pl_rdf_free(r->rdf);
    for (size_t k = 0; r->rdfc && k < r->npair; ++k) pl_rdf_free(r->rdfc[k]);
    free(r->rdfc);
    free(r->cls);
    free(r->cls_rad);
    free(r->cls_n);
    free(r);
}

/* Radius order, ties by index (a total order: the classes do not depend on
 * the sort's stability). */
typedef struct {
    double rad;
    size_t idx;
} rank_t;

static int by_radius(const void *a, const void *b)
{
    const rank_t *p = a, *q = b;
    if (p->rad != q->rad) return p->rad < q->rad ? -1 : 1;
    return (p->idx > q->idx) - (p->idx < q->idx);
}

/* The size classes of g(r) (observe.rdf_size_classes): rank by radius, k
 * classes of equal count, class floor(rank k / n); one partial g_ab per class
 * pair a <= b with the parameters of the total g(r). */
static int size_classes(rdf_obs_t *o, const pl_colloid_t *c, size_t k, int nthreads, pl_err_t *err)
{
    const size_t n = c->n;
    rank_t *ord = malloc(n * sizeof *ord);
    o->cls = malloc(n * sizeof *o->cls);
    o->cls_rad = malloc(2 * k * sizeof *o->cls_rad);
    o->cls_n = calloc(k, sizeof *o->cls_n);
    o->npair = k * (k + 1) / 2;
    o->rdfc = calloc(o->npair, sizeof *o->rdfc);
    if (!ord || !o->cls || !o->cls_rad || !o->cls_n || !o->rdfc) {
        free(ord);
        o->npair = 0;
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the g(r) size classes");
    }
    o->ncls = k;
    for (size_t i = 0; i < n; ++i) ord[i] = (rank_t){c->rad[i], i};
    qsort(ord, n, sizeof *ord, by_radius);
    for (size_t a = 0; a < k; ++a) o->cls_rad[2 * a] = INFINITY, o->cls_rad[2 * a + 1] = -INFINITY;
    for (size_t q = 0; q < n; ++q) {
        const size_t a = q * k / n, i = ord[q].idx;
        o->cls[i] = (int32_t)a;
        o->cls_n[a]++;
        o->cls_rad[2 * a] = fmin(o->cls_rad[2 * a], c->rad[i]);
        o->cls_rad[2 * a + 1] = fmax(o->cls_rad[2 * a + 1], c->rad[i]);
    }
    free(ord);
    size_t q = 0;
    for (size_t a = 0; a < k; ++a)
        for (size_t b = a; b < k; ++b, ++q) {
            pl_rdf_params_t p = o->par;
            p.class_a = (int)a;
            p.class_b = (int)b;
            int rc = pl_rdf_create(&p, nthreads, &o->rdfc[q], err);
            if (rc) return rc;
        }
    return 0;
}

/* The g(r) accumulator, created at its first use (or a restart). */
static int rdf_ready(const pl_sim_t *sim, rdf_obs_t *o, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const pl_colloid_t *c = sim->colloids;
    pl_rdf_params_t *p = &o->par;
    memset(p, 0, sizeof *p);
    for (int d = 0; d < 3; ++d) p->box[d] = c->box[d];
    p->z_walls = !c->periodic[2];
    double rmax_r = 0.0; /* the centres' slab between z walls: [R, Lz - R] */
    for (size_t i = 0; i < c->n; ++i) rmax_r = fmax(rmax_r, c->rad[i]);
    p->zlo = rmax_r;
    p->zhi = c->box[2] - rmax_r;
    double half = 0.5 * fmin(c->box[0], c->box[1]);
    if (!p->z_walls) half = fmin(half, 0.5 * c->box[2]);
    p->rmax = sc->observe.rdf_rmax > 0 ? sc->observe.rdf_rmax : half;
    p->nbins = (size_t)sc->observe.rdf_bins;
    p->class_a = p->class_b = -1;
    return pl_rdf_create(p, sim->nthreads, &o->rdf, err);
}

static int sample(pl_obs_run_t *run, void *state, pl_err_t *err)
{
    rdf_obs_t *o = state;
    const pl_sim_t *sim = run->sim;
    const pl_colloid_t *c = sim->colloids;
    if (!o->rdf) {
        int rc = rdf_ready(sim, o, err);
        if (rc) return rc;
    }
    pl_rdf_sample(o->rdf, c->n, c->x, c->y, c->z, NULL);
    if (sim->scene.observe.rdf_size_classes >= 2 && !o->rdfc) {
        int rc = size_classes(o, c, (size_t)sim->scene.observe.rdf_size_classes, sim->nthreads, err);
        if (rc) return rc;
    }
    for (size_t k = 0; k < o->npair; ++k) pl_rdf_sample(o->rdfc[k], c->n, c->x, c->y, c->z, o->cls);
    return 0;
}

/* The bin of the highest g(r) (the first coordination shell) and its SE;
 * none before 2 samples or when no pair fell within range (g = 0). */
static int rdf_peak_of(const pl_rdf_t *rdf, size_t nb, double *r, double *g, double *se)
{
    if (!rdf || pl_rdf_samples(rdf) < 2) return 0;
    double *rm = malloc(3 * nb * sizeof(double));
    if (!rm) return 0;
    double *gg = rm + nb, *ss = gg + nb;
    pl_rdf_result(rdf, rm, gg, ss, NULL);
    size_t best = 0;
    for (size_t b = 1; b < nb; ++b)
        if (gg[b] > gg[best]) best = b;
    *r = rm[best];
    *g = gg[best];
    *se = ss[best];
    free(rm);
    return isfinite(*g) && isfinite(*se) && *g > 0.0;
}

static void est_peak(const void *state, pl_obs_point_t *p)
{
    const rdf_obs_t *o = state;
    double r;
    p->valid = o && rdf_peak_of(o->rdf, o->par.nbins, &r, &p->value, &p->se);
    p->plateau = 1;
}

/* /observables/<name>/{r, r_over_R, [r_um], value (1 x np x nbins; 1 x nbins
 * for one), value_se, step, time, samples}: the run's average of np g(r)
 * sharing their bins; r also in units of colloids.radius and, for a physical
 * scene, in micrometres (the mapping's a0). */
static int write_rdf(hid_t obs, const char *name, const pl_sim_t *sim, const rdf_obs_t *o, pl_rdf_t *const *r,
                     size_t np)
{
    const size_t nb = o->par.nbins;
    double *buf = malloc((3 + 2 * np) * nb * sizeof(double));
    hid_t g = pl_h5_group(obs, name);
    int bad = !buf || g < 0;
    if (!bad) {
        double *rr = buf, *rR = buf + nb, *rum = buf + 2 * nb, *val = buf + 3 * nb, *se = val + np * nb;
        for (size_t k = 0; k < np; ++k) pl_rdf_result(r[k], rr, val + k * nb, se + k * nb, NULL);
        for (size_t k = 0; k < 2 * np * nb; ++k) /* empty bins (no ideal pair) carry no estimate */
            if (!isfinite(val[k])) val[k] = 0.0;
        const pl_scene_t *sc = &sim->scene;
        for (size_t b = 0; b < nb; ++b) {
            rR[b] = rr[b] / sc->colloids.radius;
            rum[b] = sc->mapping.enabled ? rr[b] * sc->mapping.map.a0 * 1e6 : 0.0;
        }
        hsize_t d1[1] = {nb}, d2[2] = {1, nb}, d3[3] = {1, np, nb}, one[1] = {1};
        long long st = sim->step;
        double t = (double)st * sc->srd.dt;
        bad |= pl_obs_put(g, "r", H5T_NATIVE_DOUBLE, 1, d1, rr, "a0") != 0;
        bad |= pl_obs_put(g, "r_over_R", H5T_NATIVE_DOUBLE, 1, d1, rR, "R") != 0;
        if (sc->mapping.enabled) bad |= pl_obs_put(g, "r_um", H5T_NATIVE_DOUBLE, 1, d1, rum, "um") != 0;
        bad |= pl_obs_put(g, "value", H5T_NATIVE_DOUBLE, np > 1 ? 3 : 2, np > 1 ? d3 : d2, val, "1") != 0;
        bad |= pl_obs_put(g, "value_se", H5T_NATIVE_DOUBLE, np > 1 ? 3 : 2, np > 1 ? d3 : d2, se, "1") != 0;
        bad |= pl_obs_put(g, "step", H5T_NATIVE_LLONG, 1, one, &st, NULL) != 0;
        bad |= pl_obs_put(g, "time", H5T_NATIVE_DOUBLE, 1, one, &t, "t0") != 0;
        unsigned long long ns = pl_rdf_samples(r[0]);
        bad |= pl_obs_put(g, "samples", H5T_NATIVE_ULLONG, 0, NULL, &ns, NULL) != 0;
    }
    if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    free(buf);
    return bad ? -1 : 0;
}

static int obs_write(int64_t obs_, const pl_sim_t *sim, void *state)
{
    const rdf_obs_t *o = state;
    const hid_t obs = (hid_t)obs_;
    int bad = 0;
    if (o->rdf && pl_rdf_samples(o->rdf) > 0) bad |= write_rdf(obs, "colloid_rdf", sim, o, &o->rdf, 1) != 0;
    if (!bad && o->npair && pl_rdf_samples(o->rdfc[0]) > 0) {
        hid_t g = -1;
        bad |= write_rdf(obs, "colloid_rdf_classes", sim, o, o->rdfc, o->npair) != 0;
        if (!bad) g = H5Gopen2(obs, "colloid_rdf_classes", H5P_DEFAULT);
        int32_t *pairs = malloc(2 * o->npair * sizeof *pairs);
        unsigned long long *cnt = malloc(o->ncls * sizeof *cnt);
        bad |= g < 0 || !pairs || !cnt;
        if (!bad) {
            size_t q = 0;
            for (size_t a = 0; a < o->ncls; ++a)
                for (size_t b2 = a; b2 < o->ncls; ++b2, ++q) pairs[2 * q] = (int32_t)a, pairs[2 * q + 1] = (int32_t)b2;
            for (size_t a = 0; a < o->ncls; ++a) cnt[a] = o->cls_n[a];
            hsize_t dp[2] = {o->npair, 2}, dc[2] = {o->ncls, 2}, dn[1] = {o->ncls};
            bad |= pl_obs_put(g, "pairs", H5T_NATIVE_INT32, 2, dp, pairs, NULL) != 0;
            bad |= pl_obs_put(g, "class_radius", H5T_NATIVE_DOUBLE, 2, dc, o->cls_rad, "a0") != 0;
            bad |= pl_obs_put(g, "class_count", H5T_NATIVE_ULLONG, 1, dn, cnt, NULL) != 0;
            bad |= pl_h5_attr_str(g, "meaning", "value[0][p]: g_ab(r) of class pair p = pairs[p] (a <= b); classes: "
                                                "colloids ranked by radius (ties by index), equal counts; "
                                                "class_radius: smallest and largest radius of each") != 0;
        }
        free(pairs);
        free(cnt);
        if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    }
    return bad ? -1 : 0;
}

/* r of g(r) in units of colloids.radius and, for a physical scene, in um. */
static void rdf_r_units(pl_json_t *b, json_t *e, const pl_scene_t *sc, double r)
{
    pl_json_real(b, e, "r_over_R", r / sc->colloids.radius);
    if (sc->mapping.enabled) pl_json_real(b, e, "r_um", r * sc->mapping.map.a0 * 1e6);
}

static int summary(pl_obs_sum_t *s, const pl_sim_t *sim, void *state)
{
    const rdf_obs_t *o = state;
    pl_json_t *b = s->b;
    double r, g, gse;
    if (o->rdf && rdf_peak_of(o->rdf, o->par.nbins, &r, &g, &gse)) {
        json_t *e = pl_obs_entry(s, 0, g, gse, (double)pl_rdf_samples(o->rdf), 0.0, 1, "1");
        pl_json_real(b, e, "r", r);
        rdf_r_units(b, e, &sim->scene, r);
        pl_json_int(b, e, "samples", (long long)pl_rdf_samples(o->rdf));
        pl_json_set(b, s->all, "rdf_peak", e);
    }
    if (o->npair) { /* the peak of each partial g_ab */
        json_t *arr = json_array();
        size_t q = 0;
        for (size_t a = 0; a < o->ncls; ++a)
            for (size_t c2 = a; c2 < o->ncls; ++c2, ++q) {
                if (!rdf_peak_of(o->rdfc[q], o->par.nbins, &r, &g, &gse)) continue;
                json_t *e = json_object();
                const long long ab[2] = {(long long)a, (long long)c2};
                json_t *cl = json_array();
                for (int k = 0; k < 2; ++k) json_array_append_new(cl, json_integer(ab[k]));
                pl_json_set(b, e, "classes", cl);
                const double ra[2] = {o->cls_rad[2 * a], o->cls_rad[2 * a + 1]};
                const double rb[2] = {o->cls_rad[2 * c2], o->cls_rad[2 * c2 + 1]};
                pl_json_reals(b, e, "radius_range_a", ra, 2);
                pl_json_reals(b, e, "radius_range_b", rb, 2);
                pl_json_real(b, e, "value", g);
                pl_json_real(b, e, "stderr", gse);
                pl_json_real(b, e, "n_independent", (double)pl_rdf_samples(o->rdfc[q]));
                pl_json_real(b, e, "wall_s", s->wall);
                pl_json_str(b, e, "unit", "1");
                pl_json_real(b, e, "r", r);
                rdf_r_units(b, e, &sim->scene, r);
                json_array_append_new(arr, e);
            }
        pl_json_set(b, s->all, "rdf_peak_classes", arr);
    }
    return 0;
}

/* ---- checkpoint: meta {created, size classes}; rdf_[classK_]{counts,blocking} */

static void ckpt_meta(const void *state, long long *m)
{
    const rdf_obs_t *o = state;
    m[0] = o && o->rdf != NULL;
    m[1] = o ? (long long)o->ncls : 0;
}

static int ckpt_write(int64_t g_, const void *state)
{
    const rdf_obs_t *o = state;
    const hid_t g = (hid_t)g_;
    int bad = 0;
    for (size_t q = 0; q < (o->rdf ? 1 + o->npair : 0); ++q) {
        pl_rdf_t *r = q ? o->rdfc[q - 1] : o->rdf;
        char a[64], b[64];
        snprintf(a, sizeof a, q ? "rdf_class%zu_counts" : "rdf_counts", q - 1);
        snprintf(b, sizeof b, q ? "rdf_class%zu_blocking" : "rdf_blocking", q - 1);
        pl_rdf_state_t st = pl_rdf_state(r);
        bad |= pl_ckpt_write_1d(g, a, H5T_NATIVE_UINT64, st.counts, st.ncounts);
        bad |= pl_ckpt_write_1d(g, b, H5T_NATIVE_UCHAR, st.blocking, st.nblocking * sizeof(pl_blocking_t));
    }
    return bad;
}

static int ckpt_read(int64_t g_, pl_obs_run_t *run, void *state, const long long *m, const char *path, pl_err_t *err)
{
    rdf_obs_t *o = state;
    const hid_t g = (hid_t)g_;
    const pl_sim_t *sim = run->sim;
    if (m[1] != 0 && (!m[0] || m[1] != sim->scene.observe.rdf_size_classes))
        return pl_obs_ckpt_corrupt(err, path, "size classes differ from observe.rdf_size_classes");
    if (!m[0]) return 0;
    int rc = rdf_ready(sim, o, err);
    if (!rc && m[1]) rc = size_classes(o, sim->colloids, (size_t)m[1], sim->nthreads, err);
    for (size_t q = 0; !rc && q < 1 + o->npair; ++q) {
        pl_rdf_state_t st = pl_rdf_state(q ? o->rdfc[q - 1] : o->rdf);
        char a[64], b[64];
        snprintf(a, sizeof a, q ? "rdf_class%zu_counts" : "rdf_counts", q - 1);
        snprintf(b, sizeof b, q ? "rdf_class%zu_blocking" : "rdf_blocking", q - 1);
        rc = pl_ckpt_read_1d(g, a, H5T_NATIVE_UINT64, st.counts, st.ncounts, path, err);
        if (!rc) rc = pl_obs_blocking_read(g, b, st.blocking, st.nblocking, path, err);
    }
    return rc;
}

static const pl_obs_estimate_t estimates[] = {{"rdf_peak", 1, est_peak, NULL}};

const pl_observer_t pl_observer_rdf = {
    .name = "g(r)", .stage = "observe-rdf",
    .interval = offsetof(pl_scene_observe_t, rdf_interval), .start = offsetof(pl_scene_observe_t, rdf_start),
    .interval_key = "observe.rdf_interval", .start_key = "observe.rdf_start", .at_start = 1, .need = 1, .pairs = 1,
    .none_why = "fewer than 2 samples, or no pair of colloids within observe.rdf_rmax at any",
    .check = check, .create = create, .sample = sample, .write = obs_write, .summary = summary,
    .meta_slot = 5, .nmeta = 2, .ckpt_meta = ckpt_meta, .ckpt_write = ckpt_write, .ckpt_read = ckpt_read,
    .free = obs_free, .estimates = estimates, .nestimates = 1,
};
