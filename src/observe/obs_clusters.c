/* Observer clusters (peloid/observer.h row "cluster"): bond = surface gap
 * below observe.clusters_gap, or pair energy below -observe.clusters_energy
 * (primary / secondary minimum by the DLVO barrier gap), union-find over
 * linked cells (peloid/cluster.h; Hecht Figs. 9, 14): number of clusters,
 * largest, mean size, bonds per sample; their time averages with the
 * blocking SE (peloid/blocking.h) over the analysis window
 * (peloid/window.h, observe.average_from); the size distribution summed over
 * samples; the cluster id of each colloid with every trajectory frame
 * (pl_colloid_traj_cluster_ids). */
#include <hdf5.h>
#include <jansson.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint_h5.h"
#include "json_build.h"
#include "obs_window.h"
#include "observables_out.h"
#include "peloid/cluster.h"
#include "peloid/colloid.h"
#include "peloid/h5.h"
#include "peloid/io.h"
#include "peloid/observe_check.h"
#include "peloid/observer.h"

/* Per-sample quantities: number, largest, mean size, bonds, primary- and
 * secondary-minimum bonds (energy bonds), primary fraction of the bonds
 * (samples with a bond). */
enum { NCV = 7 };
static const char *const cv_names[NCV] = {"cluster_number", "largest_cluster", "mean_cluster_size", "cluster_bonds",
                                          "cluster_bonds_primary", "cluster_bonds_secondary",
                                          "cluster_primary_fraction"};

/* The energy-bond rule's context (energy_bond). */
typedef struct {
    const pl_colloid_t *c;
    double ec, barrier;
} ebond_t;

typedef struct {
    pl_obs_run_t *run;
    pl_cluster_t *cl;
    pl_blocking_t cb[NCV]; /* cv_names */
    long long *c_step;
    double *c_val[NCV];
    double c_barrier; /* energy bonds: the DLVO barrier gap (NAN: none, all primary) */
    ebond_t eb;
    long long ids_step; /* the step of the last partition (pl_cluster_ids), -1: none */
    size_t c_n, c_cap;
    uint64_t *c_hist; /* size distribution summed over samples */
    size_t c_hist_len;
} cl_obs_t;

#define OFFO(m) offsetof(pl_scene_t, observe.m)

/* Energy bonds need a pair minimum deeper than -clusters_energy: the
 * primary (gap primary_gap) or the secondary minimum of the DLVO potential
 * of the reference pair (radius colloids.radius), by the pair energy the run
 * uses (pl_colloid_pair_energy; the depletion_comp table, built later, left
 * out: it only makes the minima shallower). */
static int check(const pl_scene_t *sc, pl_err_t *err)
{
    if (sc->observe.clusters_interval <= 0 || sc->observe.clusters_bond != PL_BOND_ENERGY) return 0;
    const double Ec = sc->observe.clusters_energy, R = sc->colloids.radius;
    unsigned mask = 0;
    char bad[128];
    if (pl_colloid_parse_pairs(sc->colloids.pairs, &mask, bad, sizeof bad)) return 0; /* the colloid checks say */
    if (!(mask & PL_CT_DLVO))
        return pl_scene_fail(sc, err, OFFO(clusters_bond), "observe.clusters_bond",
                             "\"energy\" needs an attractive pair minimum: colloids.pairs = \"%s\" has no dlvo "
                             "term; allowed: \"gap\"", sc->colloids.pairs);
    pl_colloid_pair_params_t p;
    pl_colloid_dlvo_info_t info;
    pl_err_t ignore = {0, ""};
    if (pl_colloid_pair_params(sc, &p, &info, &ignore)) return 0; /* reported by the colloid checks */
    p.terms &= ~(unsigned)PL_CT_DEPL;
    double u1 = pl_colloid_pair_energy(&p, 2.0 * R + info.h0, R, R), u2 = INFINITY;
    if (isfinite(info.secmin_h)) u2 = pl_colloid_pair_energy(&p, 2.0 * R + info.secmin_h, R, R);
    if (!(fmin(u1, u2) < -Ec))
        return pl_scene_fail(sc, err, OFFO(clusters_energy), "observe.clusters_energy",
                             "%g kT_ref: no pair is that deeply bound (primary minimum %.4g kT_ref, secondary %.4g "
                             "kT_ref); allowed: < %.4g", Ec, u1, u2, -fmin(u1, u2));
    return 0;
}

static const int32_t *traj_ids(void *ctx, long long step, int compute);

static int create(pl_obs_run_t *run, void **state, pl_err_t *err)
{
    cl_obs_t *o = calloc(1, sizeof *o);
    if (!o) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the cluster observer");
    o->run = run;
    for (int k = 0; k < NCV; ++k) pl_blocking_init(&o->cb[k]);
    o->ids_step = -1;
    *state = o;
    /* the trajectory's frames carry the cluster ids (src/app/writer_colloids.c) */
    run->sim->frame_ids = traj_ids;
    run->sim->frame_ids_ctx = o;
    return 0;
}

static void obs_free(void *state)
{
    cl_obs_t *o = state;
    pl_cluster_free(o->cl);
    for (int k = 0; k < NCV; ++k) free(o->c_val[k]);
    free(o->c_step);
    free(o->c_hist);
    free(o);
}

/* Energy bond (observe.clusters_bond = "energy"): kind 1 (primary minimum)
 * when the pair energy is below -E_c at a surface gap inside the DLVO
 * barrier of the reference pair, kind 2 (secondary minimum) beyond it. */
static int energy_bond(const void *ctx, int32_t i, int32_t j, double r)
{
    const ebond_t *e = ctx;
    const double ri = e->c->rad[i], rj = e->c->rad[j];
    if (!(pl_colloid_pair_energy(&e->c->pair, r, ri, rj) < -e->ec)) return 0;
    return isnan(e->barrier) || r - ri - rj < e->barrier ? 1 : 2;
}

/* The cluster search, created at its first use. */
static int clusters_ready(const pl_sim_t *sim, cl_obs_t *o, pl_err_t *err)
{
    if (o->cl) return 0;
    const pl_scene_t *sc = &sim->scene;
    const pl_colloid_t *c = sim->colloids;
    pl_cluster_params_t p = pl_observe_cluster_params(sc, c);
    o->c_barrier = NAN;
    if (sc->observe.clusters_bond == PL_BOND_ENERGY) {
        o->c_barrier = c->dlvo.barrier_h;
        o->eb = (ebond_t){c, sc->observe.clusters_energy, o->c_barrier};
        p.bond = energy_bond;
        p.bond_ctx = &o->eb;
    }
    return pl_cluster_create(&p, &o->cl, err);
}

/* The partition of the present positions (computed once per step). */
static int clusters_now(const pl_sim_t *sim, cl_obs_t *o, pl_err_t *err)
{
    if (o->ids_step == sim->step) return 0;
    int rc = clusters_ready(sim, o, err);
    const pl_colloid_t *c = sim->colloids;
    if (!rc) rc = pl_cluster_find(o->cl, c->n, c->x, c->y, c->z, c->rad, err);
    o->ids_step = rc ? -1 : sim->step;
    return rc;
}

/* The series with room for cap samples and the size distribution of n
 * colloids (at the first sample or a restart). */
static int clusters_alloc(cl_obs_t *o, size_t cap, size_t n, pl_err_t *err)
{
    o->c_cap = cap;
    o->c_step = malloc(cap * sizeof *o->c_step);
    int oom = !o->c_step;
    for (int k = 0; k < NCV; ++k) oom |= !(o->c_val[k] = malloc(cap * sizeof(double)));
    o->c_hist_len = n + 1;
    o->c_hist = calloc(o->c_hist_len, sizeof *o->c_hist);
    if (oom || !o->c_hist) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the cluster observer");
    return 0;
}

static int sample(pl_obs_run_t *run, void *state, pl_err_t *err)
{
    cl_obs_t *o = state;
    const pl_sim_t *sim = run->sim;
    const pl_scene_t *sc = &sim->scene;
    if (!o->c_step) {
        const size_t cap = pl_obs_expected(run, sc->observe.clusters_start, sc->observe.clusters_interval);
        int rc = clusters_alloc(o, cap, sim->colloids->n, err);
        if (rc) return rc;
    }
    int rc = clusters_now(sim, o, err);
    if (rc) return rc;
    const double b1 = (double)pl_cluster_bonds(o->cl, 1), b2 = (double)pl_cluster_bonds(o->cl, 2);
    const double v[NCV] = {(double)pl_cluster_count(o->cl), (double)pl_cluster_largest(o->cl),
                           pl_cluster_mean_size(o->cl), b1 + b2, b1, b2, b1 + b2 > 0 ? b1 / (b1 + b2) : NAN};
    for (int k = 0; k < NCV; ++k)
        if (isfinite(v[k])) pl_blocking_add(&o->cb[k], v[k]);
    if (o->c_n < o->c_cap) {
        o->c_step[o->c_n] = sim->step;
        for (int k = 0; k < NCV; ++k) o->c_val[k][o->c_n] = v[k];
        o->c_n++;
    }
    size_t len;
    const uint64_t *h = pl_cluster_size_hist(o->cl, &len);
    for (size_t s = 0; s < len && s < o->c_hist_len; ++s) o->c_hist[s] += h[s];
    return 0;
}

/* The cluster ids of a trajectory frame (pl_colloid_traj_cluster_ids): the
 * partition of that step's positions, from clusters_start on; the observer's
 * own samples are not touched (a trajectory step between them costs one
 * more search). */
static const int32_t *traj_ids(void *ctx, long long step, int compute)
{
    cl_obs_t *o = ctx;
    const pl_sim_t *sim = o->run->sim;
    if (step < sim->scene.observe.clusters_start) return NULL;
    if (o->ids_step != step) {
        pl_err_t ignore = {0, ""};
        if (!compute || step != sim->step || clusters_now(sim, o, &ignore)) return NULL;
    }
    return pl_cluster_ids(o->cl);
}

static int obs_write(int64_t obs_, const pl_sim_t *sim, void *state)
{
    const cl_obs_t *o = state;
    const hid_t obs = (hid_t)obs_;
    if (!o->cl || o->c_n == 0) return 0;
    /* the bond kinds with energy bonds; the primary fraction (undefined in
     * samples without a bond) only in the summary */
    const int ncv = sim->scene.observe.clusters_bond == PL_BOND_ENERGY ? NCV - 1 : 4;
    int bad = 0;
    for (int k = 0; k < ncv && !bad; ++k) {
        bad |= pl_obs_series(obs, cv_names[k], o->c_n, o->c_step, sim->scene.srd.dt, o->c_val[k], "1") != 0;
        const pl_window_t w = pl_obs_window(o->run, o->c_step, o->c_val[k], o->c_n);
        if (!bad) bad |= pl_obs_window_h5(obs, cv_names[k], sim, &w) != 0;
    }
    size_t len = o->c_hist_len; /* trailing empty sizes left out */
    while (len > 1 && o->c_hist[len - 1] == 0) --len;
    hsize_t d1[1] = {len};
    hid_t g = pl_h5_group(obs, "cluster_size_distribution");
    bad |= g < 0 || pl_obs_put(g, "value", H5T_NATIVE_UINT64, 1, d1, o->c_hist, "1") != 0;
    if (g >= 0) bad |= pl_h5_attr_str(g, "meaning", "value[s]: clusters of s colloids, summed over samples") != 0;
    if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
}

static int summary(pl_obs_sum_t *s, const pl_sim_t *sim, void *state)
{
    const cl_obs_t *o = state;
    const int energy_bonds = sim->scene.observe.clusters_bond == PL_BOND_ENERGY;
    for (int k = 0; o->cl && k < NCV; ++k) {
        if (k > 3 && !energy_bonds) continue;
        /* the average over the window of the stored series (the accumulator
         * cb[k] holds the whole run's, for se_vs_time and stop.observable) */
        const pl_window_t w = pl_obs_window(o->run, o->c_step, o->c_val[k], o->c_n);
        uint64_t nw;
        pl_blocking_result_t res = pl_window_blocking(o->c_val[k], o->c_n, w.first, &nw);
        if (nw < 2 || !isfinite(res.mean) || !isfinite(res.se)) continue;
        json_t *e = pl_obs_entry(s, k, res.mean, res.se, res.n_indep, res.inefficiency, res.plateau, "1");
        pl_json_int(s->b, e, "samples", (long long)nw);
        pl_obs_window_json(s->b, e, sim, &w);
        if (k == 6) pl_json_str(s->b, e, "over", "samples with at least one bond");
        if (k >= 3 && energy_bonds) {
            pl_json_real(s->b, e, "bond_energy_kT", -sim->scene.observe.clusters_energy);
            if (isfinite(o->c_barrier)) pl_json_real(s->b, e, "barrier_gap_a0", o->c_barrier);
        }
        pl_json_set(s->b, s->all, cv_names[k], e);
    }
    return 0;
}

/* The time average of quantity k, once the cluster search exists. */
static void est_blocking(const void *state, int k, pl_obs_point_t *p)
{
    const cl_obs_t *o = state;
    if (!o || !o->cl) return;
    pl_blocking_result_t r = pl_blocking_result(&o->cb[k]);
    p->valid = o->cb[k].n >= 2 && isfinite(r.mean) && isfinite(r.se);
    p->value = r.mean;
    p->se = r.se;
    p->plateau = r.plateau;
}
#define EST(k)                                                                                                    \
    static void est##k(const void *state, pl_obs_point_t *p) { est_blocking(state, k, p); }
EST(0)
EST(1)
EST(2)
EST(3)
EST(4)
EST(5)
EST(6)

static const char *energy_only(const pl_scene_t *sc)
{
    return sc->observe.clusters_bond == PL_BOND_ENERGY ? NULL
                                                        : "counts energy bonds: needs observe.clusters_bond = \"energy\"";
}

/* ---- checkpoint: meta {samples (-1: none yet), size-distribution length};
 * cluster_blocking (head), clusters_step, the series, cluster_size_hist */

static void ckpt_meta(const void *state, long long *m)
{
    const cl_obs_t *o = state;
    m[0] = o && o->c_step ? (long long)o->c_n : -1;
    m[1] = o ? (long long)o->c_hist_len : 0;
}

/* (also when off, state NULL: the initial accumulators, as the first
 * checkpoints stored them) */
static int ckpt_head(int64_t g, const void *state)
{
    const cl_obs_t *o = state;
    pl_blocking_t none[NCV];
    for (int k = 0; !o && k < NCV; ++k) pl_blocking_init(&none[k]);
    return pl_ckpt_write_1d((hid_t)g, "cluster_blocking", H5T_NATIVE_UCHAR, o ? o->cb : none, sizeof none);
}

static int ckpt_write(int64_t g_, const void *state)
{
    const cl_obs_t *o = state;
    const hid_t g = (hid_t)g_;
    if (!o->c_step) return 0;
    int bad = pl_ckpt_write_1d(g, "clusters_step", H5T_NATIVE_LLONG, o->c_step, o->c_n);
    for (int k = 0; k < NCV; ++k) bad |= pl_ckpt_write_1d(g, cv_names[k], H5T_NATIVE_DOUBLE, o->c_val[k], o->c_n);
    bad |= pl_ckpt_write_1d(g, "cluster_size_hist", H5T_NATIVE_UINT64, o->c_hist, o->c_hist_len);
    return bad;
}

static int ckpt_read(int64_t g_, pl_obs_run_t *run, void *state, const long long *m, const char *path, pl_err_t *err)
{
    cl_obs_t *o = state;
    const hid_t g = (hid_t)g_;
    const pl_sim_t *sim = run->sim;
    if (m[0] >= 0 && (m[0] > sim->step + 1 || m[1] != (long long)sim->colloids->n + 1))
        return pl_obs_ckpt_corrupt(err, path, "cluster series or size distribution of the wrong length");
    int rc = pl_obs_blocking_read(g_, "cluster_blocking", o->cb, NCV, path, err);
    if (rc || m[0] < 0) return rc;
    o->c_n = (size_t)m[0];
    if ((rc = clusters_alloc(o, o->c_n ? o->c_n : 1, sim->colloids->n, err))) return rc;
    if ((rc = pl_ckpt_read_1d(g, "clusters_step", H5T_NATIVE_LLONG, o->c_step, o->c_n, path, err))) return rc;
    for (int k = 0; k < NCV; ++k)
        if ((rc = pl_ckpt_read_1d(g, cv_names[k], H5T_NATIVE_DOUBLE, o->c_val[k], o->c_n, path, err))) return rc;
    if ((rc = pl_ckpt_read_1d(g, "cluster_size_hist", H5T_NATIVE_UINT64, o->c_hist, o->c_hist_len, path, err)))
        return rc;
    return clusters_ready(sim, o, err);
}

static int resume(pl_obs_run_t *run, void *state, pl_err_t *err)
{
    cl_obs_t *o = state;
    const pl_scene_observe_t *so = &run->sim->scene.observe;
    if (!o->c_step) return 0;
    const size_t cap = pl_obs_expected(run, so->clusters_start, so->clusters_interval);
    if (cap <= o->c_cap) return 0;
    int bad = pl_obs_grow((void **)&o->c_step, o->c_n, cap, sizeof *o->c_step);
    for (int k = 0; k < NCV; ++k) bad |= pl_obs_grow((void **)&o->c_val[k], o->c_n, cap, sizeof(double));
    if (bad) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the cluster observer");
    o->c_cap = cap;
    return 0;
}

static const pl_obs_estimate_t estimates[NCV] = {
    {"cluster_number", 2, est0, NULL},          {"largest_cluster", 3, est1, NULL},
    {"mean_cluster_size", 4, est2, NULL},       {"cluster_bonds", 6, est3, NULL},
    {"cluster_bonds_primary", 7, est4, energy_only}, {"cluster_bonds_secondary", 8, est5, energy_only},
    {"cluster_primary_fraction", 9, est6, energy_only},
};

const pl_observer_t pl_observer_clusters = {
    .name = "cluster", .stage = "observe-clusters",
    .interval = offsetof(pl_scene_observe_t, clusters_interval),
    .start = offsetof(pl_scene_observe_t, clusters_start), .interval_key = "observe.clusters_interval",
    .start_key = "observe.clusters_start", .at_start = 1, .need = 1,
    .check = check, .create = create, .sample = sample, .write = obs_write, .summary = summary,
    .meta_slot = 8, .nmeta = 2, .ckpt_meta = ckpt_meta, .ckpt_head = ckpt_head, .ckpt_write = ckpt_write,
    .ckpt_read = ckpt_read, .resume = resume, .free = obs_free, .estimates = estimates, .nestimates = NCV,
};
