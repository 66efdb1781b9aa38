/* The observer module (peloid/module.h; DESIGN.md "Observables and their
 * errors"): after-step stages that sample the colloids and, at the end of
 * the run, observables.h5 (H5MD /observables) and summary.json
 * "observables", every average with its standard error.
 *
 *   g(r)      colloid centres (Hecht Sec. IX.C, Figs. 5-7, 10-13; PL Fig. 4),
 *             peloid/rdf.h: ideal-gas normalisation of the accessible region,
 *             mean and SE per bin by blocking over samples; optionally per
 *             size class (radius rank, equal counts: partial g_ab).
 *   S(q)      colloid centres, direct sum over the box's wave vectors
 *             (peloid/sq.h), mean and SE per |q| bin.
 *   MSD, D    the multiple-tau correlator observers (mtau_observers.c):
 *   VACF      MSD and D (Hecht Eq. 36), VACF and the Green-Kubo D (Hecht
 *   C_FF      Eq. 35), C_FF of the fluid force and the Green-Kubo friction
 *             (PL Eq. B2).
 *   velocity  fluid and colloid velocity components, scaled by sqrt(M / kT)
 *   distr.    about their mean, histogrammed (peloid/vdist.h): chi^2 against
 *             the unit Gaussian of Maxwell-Boltzmann (Hecht Figs. 2, 8).
 *   sediment  the colloid volume fraction phi(z) (exact sphere slices), the
 *             mean (unwrapped) height h, <v_z> of the colloids; the settling
 *             velocity between samples, (h_k - h_{k-1}) / dt minus the fluid's
 *             mean velocity, whose blocking average is the (hindered)
 *             settling velocity of Hecht Eq. 37 (Richardson-Zaki) in a
 *             homogeneous suspension.
 *   clusters  bond = surface gap below observe.clusters_gap, or pair energy
 *             below -observe.clusters_energy (primary / secondary minimum by
 *             the DLVO barrier gap), union-find over linked cells
 *             (peloid/cluster.h; Hecht Figs. 9, 14): number of clusters,
 *             largest, mean size, bonds per sample; their time averages with
 *             the blocking SE (peloid/blocking.h); the size distribution
 *             summed over samples; the cluster id of each colloid with every
 *             trajectory frame (pl_colloid_traj_cluster_ids).
 *
 * Error against run time: at 1/8, 1/4, 1/2 and all of the run the current
 * estimate and SE of each observable are recorded with the wall time spent;
 * the summary extrapolates (SE ~ 1/sqrt(t)) the wall time that
 * observe.target_rel_error would need, flagged when the blocking found no
 * plateau.
 *
 * Restart: the accumulated state is the checkpoint group /observe (section
 * "checkpoint" below); with the same observe section the observers resume
 * and cover the whole history since they started (first_step the original
 * start, fractions of the combined run), with another one, or from a
 * checkpoint without the group, they start afresh and say so (README
 * "Observables", restart). */
#include <hdf5.h>
#include <jansson.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/real.h" /* PL_PI */
#include "json_build.h"
#include "observables_out.h"
#include "observables_si.h"
#include "peloid/blocking.h"
#include "peloid/cluster.h"
#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/h5.h"
#include "peloid/io.h"
#include "peloid/mapping.h"
#include "peloid/observe_check.h"
#include "peloid/module.h"
#include "peloid/rdf.h"
#include "peloid/sq.h"
#include "peloid/vdist.h"
#include "checkpoint_h5.h"
#include "mtau_observers.h"
#include "sediment_fit.h"

enum { NFRAC = PL_OBS_NFRAC, VD_BINS = 60 };
#define fractions pl_obs_fractions

/* Observables of the error-against-time report. */
enum { OB_D, OB_RDF_PEAK, OB_NCLUSTERS, OB_LARGEST, OB_MEANSIZE, OB_SETTLING, OB_BONDS, OB_BONDS_PRIMARY,
       OB_BONDS_SECONDARY, OB_PRIMARY_FRACTION, OB_N };
static const char *const ob_names[OB_N] = {"colloid_D", "rdf_peak", "cluster_number", "largest_cluster",
                                           "mean_cluster_size", "settling_velocity", "cluster_bonds",
                                           "cluster_bonds_primary", "cluster_bonds_secondary",
                                           "cluster_primary_fraction"};
/* Per-sample cluster quantities: number, largest, mean size, bonds, primary-
 * and secondary-minimum bonds (energy bonds), primary fraction of the bonds
 * (samples with a bond); the observables OB_NCLUSTERS.. and OB_BONDS.. */
enum { NCV = 7 };
static const char *const cv_names[NCV] = {"cluster_number", "largest_cluster", "mean_cluster_size", "cluster_bonds",
                                          "cluster_bonds_primary", "cluster_bonds_secondary",
                                          "cluster_primary_fraction"};

/* The energy-bond rule's context (energy_bond). */
typedef struct {
    const pl_colloid_t *c;
    double ec, barrier;
} ebond_t;

typedef pl_obs_point_t ept_t; /* an estimate at a run fraction (observables_out.h) */

/* The sampling observers besides the correlators, in plan order (the
 * correlators' stages come between S(q) and the clusters): table
 * `samplers`, before observe_stages. */
enum { SMP_RDF, SMP_SQ, SMP_CLUSTERS, SMP_VDIST, SMP_SEDIMENT, NSMP };

/* A sampling stage's context: the observers and the stage's row. */
typedef struct {
    struct pl_observe *o;
    int k;
} obs_stage_t;

typedef struct pl_observe {
    long long first, last; /* the run's steps */
    double t_start;        /* wall clock at the run's start */
    /* g(r) */
    pl_rdf_t *rdf;
    pl_rdf_params_t rdf_par;
    /* g(r) per size class: ncls classes, npair = ncls (ncls + 1) / 2 partials */
    size_t ncls, npair;
    pl_rdf_t **rdfc;   /* npair, pair (a, b), a <= b, in row order */
    int32_t *cls;      /* n: class of each colloid */
    double *cls_rad;   /* ncls x 2: smallest and largest radius of each class */
    size_t *cls_n;     /* ncls: colloids per class */
    /* S(q) */
    pl_sq_t *sq;
    /* MSD, VACF, C_FF (mtau_observers.h) */
    pl_mtobs_t mt[PL_MTOBS_N];
    /* clusters */
    pl_cluster_t *cl;
    pl_blocking_t cb[NCV]; /* cv_names */
    long long *c_step;
    double *c_val[NCV];
    double c_barrier; /* energy bonds: the DLVO barrier gap (NAN: none, all primary) */
    ebond_t eb;
    pl_sim_t *sim; /* for the trajectory's cluster ids (traj_ids) */
    long long ids_step; /* the step of the last partition (pl_cluster_ids), -1: none */
    size_t c_n, c_cap;
    uint64_t *c_hist; /* size distribution summed over samples */
    size_t c_hist_len;
    /* velocity distributions: 0 fluid, 1 colloids */
    pl_vdist_t *vd[2];
    double *vs[3]; /* scaled components, fluid count (>= colloid count) */
    size_t vs_n;
    /* sedimentation: phi(z) per sample, mean height, settling velocity */
    size_t s_bins, s_n, s_cap;
    long long *s_step;
    double *s_phi, *s_height, *s_vz, *s_vel; /* s_vel[k]: from heights k-1, k (k >= 1) */
    pl_blocking_t s_vb; /* settling velocity */
    /* the samplers' wall seconds and the stages' contexts */
    double wall[NSMP];
    obs_stage_t smp_ctx[NSMP], mt_ctx[PL_MTOBS_N];
    /* error against run time */
    ept_t ept[OB_N][NFRAC];
    int next_frac;
    /* restart (observe_ckpt_read): the checkpoint's step (-1: none), its
     * error-against-time points */
    long long resume_step;
    int begun;
    ept_t ept_saved[OB_N][NFRAC];
    int nept_saved;
} pl_observe_t;

static int any_observer(const pl_scene_observe_t *o)
{
    return o->rdf_interval > 0 || o->sq_interval > 0 || o->msd_interval > 0 || o->vacf_interval > 0 ||
           o->cff_interval > 0 || o->clusters_interval > 0 ||
           o->vdist_interval > 0 || o->sediment_interval > 0;
}

/* ---- scene checks ------------------------------------------------------ */

#define OFFO(m) offsetof(pl_scene_t, observe.m)

/* Energy bonds need a pair minimum deeper than -clusters_energy: the
 * primary (gap primary_gap) or the secondary minimum of the DLVO potential
 * of the reference pair (radius colloids.radius), by the pair energy the run
 * uses (pl_colloid_pair_energy; the depletion_comp table, built later, left
 * out: it only makes the minima shallower). */
static int energy_bond_check(const pl_scene_t *sc, pl_err_t *err)
{
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

int pl_observe_validate_scene(const pl_scene_t *sc, pl_err_t *err)
{
    const pl_scene_observe_t *o = &sc->observe;
    const struct { long long v; size_t off; const char *key; } need[] = {
        {o->rdf_interval, OFFO(rdf_interval), "observe.rdf_interval"},
        {o->sq_interval, OFFO(sq_interval), "observe.sq_interval"},
        {o->msd_interval, OFFO(msd_interval), "observe.msd_interval"},
        {o->vacf_interval, OFFO(vacf_interval), "observe.vacf_interval"},
        {o->cff_interval, OFFO(cff_interval), "observe.cff_interval"},
        {o->clusters_interval, OFFO(clusters_interval), "observe.clusters_interval"},
        {o->vdist_interval, OFFO(vdist_interval), "observe.vdist_interval"},
        {o->sediment_interval, OFFO(sediment_interval), "observe.sediment_interval"},
    };
    for (size_t k = 0; k < sizeof need / sizeof need[0]; ++k)
        if (need[k].v > 0 && sc->colloids.count == 0)
            return pl_scene_fail(sc, err, need[k].off, need[k].key,
                                 "%lld: the observer needs colloids (colloids.count = 0); allowed: 0 without colloids",
                                 need[k].v);
    /* the stopping rule's observable needs its observer */
    static const size_t stop_needs[OB_N] = {
        OFFO(msd_interval),      OFFO(rdf_interval),      OFFO(clusters_interval), OFFO(clusters_interval),
        OFFO(clusters_interval), OFFO(sediment_interval), OFFO(clusters_interval), OFFO(clusters_interval),
        OFFO(clusters_interval), OFFO(clusters_interval)};
    static const char *const stop_keys[OB_N] = {
        "observe.msd_interval",      "observe.rdf_interval",      "observe.clusters_interval",
        "observe.clusters_interval", "observe.clusters_interval", "observe.sediment_interval",
        "observe.clusters_interval", "observe.clusters_interval", "observe.clusters_interval",
        "observe.clusters_interval"};
    const int ob = sc->stop.observable - 1;
    if (ob >= OB_BONDS_PRIMARY && ob < OB_N && o->clusters_bond != PL_BOND_ENERGY)
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, stop.observable), "stop.observable",
                             "\"%s\" counts energy bonds: needs observe.clusters_bond = \"energy\"", ob_names[ob]);
    if (ob >= 0 && ob < OB_N && *(const long long *)((const char *)sc + stop_needs[ob]) <= 0)
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, stop.observable), "stop.observable",
                             "\"%s\" needs its observer: %s > 0", ob_names[ob], stop_keys[ob]);
    if (ob >= 0 && !(sc->stop.rel_error > 0))
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, stop.rel_error), "stop.rel_error",
                             "%g with stop.observable; allowed: > 0", sc->stop.rel_error);
    if (o->clusters_interval > 0 && o->clusters_bond == PL_BOND_ENERGY) {
        int rc = energy_bond_check(sc, err);
        if (rc) return rc;
    }
    if (o->sq_interval > 0 && (sc->box.walls_xy != PL_WALLS_NONE || sc->box.walls_z != PL_WALLS_NONE))
        return pl_scene_fail(sc, err, OFFO(sq_interval), "observe.sq_interval",
                             "%lld with walls: S(q) sums over the wave vectors of a periodic box; allowed: 0 "
                             "with walls", o->sq_interval);
    if (o->sq_interval > 0) {
        int rc = pl_observe_sq_cost_check(sc, err);
        if (rc) return rc;
    }
    if (o->cff_interval > 0 && sc->coupling.method != PL_COUPLE_POTENTIAL)
        return pl_scene_fail(sc, err, OFFO(cff_interval), "observe.cff_interval",
                             "%lld: the fluid force on the colloids is a force only with coupling.method = "
                             "\"potential\" (the collision couplings exchange impulses); allowed: 0",
                             o->cff_interval);
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
    return pl_observe_validate_measurable(sc, err);
}

/* ---- lifetime ---------------------------------------------------------- */

static int observe_create(pl_sim_t *sim, pl_err_t *err)
{
    (void)err;
    if (!sim->colloids || !any_observer(&sim->scene.observe)) return 0;
    pl_observe_t *o = calloc(1, sizeof *o);
    if (!o) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the observers");
    for (int k = 0; k < NCV; ++k) pl_blocking_init(&o->cb[k]);
    o->ids_step = -1;
    o->resume_step = -1;
    pl_blocking_init(&o->s_vb);
    for (int k = 0; k < NSMP; ++k) o->smp_ctx[k] = (obs_stage_t){o, k};
    for (int k = 0; k < PL_MTOBS_N; ++k) {
        o->mt[k].which = k;
        o->mt_ctx[k] = (obs_stage_t){o, k};
    }
    sim->observe = o;
    int rc = pl_observe_check_colloids(&sim->scene, sim->colloids, err); /* before any output */
    if (rc) return rc;
    if (sim->scene.observe.cff_interval > 0 && sim->coupling)
        return pl_coupling_mean_force_on(sim->coupling, sim->colloids->n, err);
    return 0;
}

static void observe_destroy(pl_sim_t *sim)
{
    pl_observe_t *o = sim->observe;
    if (!o) return;
    pl_rdf_free(o->rdf);
    for (size_t k = 0; o->rdfc && k < o->npair; ++k) pl_rdf_free(o->rdfc[k]);
    free(o->rdfc);
    free(o->cls);
    free(o->cls_rad);
    free(o->cls_n);
    pl_sq_free(o->sq);
    for (int k = 0; k < PL_MTOBS_N; ++k) pl_mtobs_free(&o->mt[k]);
    pl_cluster_free(o->cl);
    pl_vdist_free(o->vd[0]);
    pl_vdist_free(o->vd[1]);
    for (int d = 0; d < 3; ++d) free(o->vs[d]);
    for (int k = 0; k < NCV; ++k) free(o->c_val[k]);
    free(o->c_step);
    free(o->c_hist);
    free(o->s_step);
    free(o->s_phi);
    free(o->s_height);
    free(o->s_vel);
    free(o->s_vz);
    free(o);
    sim->observe = NULL;
}

/* Samples from `start` to the run's last step, every `interval`. */
static uint64_t expected_samples(const pl_observe_t *o, long long start, long long interval)
{
    long long a = o->first > start ? o->first : start;
    if (a % interval) a += interval - a % interval;
    return a > o->last ? 1 : (uint64_t)((o->last - a) / interval + 1);
}

/* ---- stages ------------------------------------------------------------ */

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
static int size_classes(pl_observe_t *o, const pl_colloid_t *c, size_t k, int nthreads, pl_err_t *err)
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
            pl_rdf_params_t p = o->rdf_par;
            p.class_a = (int)a;
            p.class_b = (int)b;
            int rc = pl_rdf_create(&p, nthreads, &o->rdfc[q], err);
            if (rc) return rc;
        }
    return 0;
}

/* The g(r) accumulator, created at its first use (or a restart). */
static int rdf_ready(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const pl_colloid_t *c = sim->colloids;
    pl_rdf_params_t *p = &o->rdf_par;
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

static int sample_rdf(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const pl_colloid_t *c = sim->colloids;
    if (!o->rdf) {
        int rc = rdf_ready(sim, o, err);
        if (rc) return rc;
    }
    pl_rdf_sample(o->rdf, c->n, c->x, c->y, c->z, NULL);
    if (sc->observe.rdf_size_classes >= 2 && !o->rdfc) {
        int rc = size_classes(o, c, (size_t)sc->observe.rdf_size_classes, sim->nthreads, err);
        if (rc) return rc;
    }
    for (size_t k = 0; k < o->npair; ++k) pl_rdf_sample(o->rdfc[k], c->n, c->x, c->y, c->z, o->cls);
    return 0;
}

static int sq_ready(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const pl_colloid_t *c = sim->colloids;
    pl_sq_params_t p = {.qmax = sc->observe.sq_qmax > 0 ? sc->observe.sq_qmax : 4.0 * PL_PI / sc->colloids.radius,
                        .nbins = (size_t)sc->observe.sq_bins, .nmax = c->n};
    for (int d = 0; d < 3; ++d) p.box[d] = c->box[d];
    int rc = pl_sq_create(&p, sim->nthreads, &o->sq, err);
    return rc;
}

static int sample_sq(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err)
{
    const pl_colloid_t *c = sim->colloids;
    if (!o->sq) {
        int rc = sq_ready(sim, o, err);
        if (rc) return rc;
    }
    pl_sq_sample(o->sq, c->n, c->x, c->y, c->z);
    return 0;
}

/* A multiple-tau observer's stage (ctx: its o->mt_ctx). */
static int stage_mtau(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    const obs_stage_t *s = ctx;
    pl_observe_t *o = s->o;
    if (sim->step == o->resume_step) return 0; /* sampled before the checkpoint */
    const pl_scene_observe_t *so = &sim->scene.observe;
    const uint64_t ns = expected_samples(o, pl_mtobs_start(so, s->k), pl_mtobs_interval(so, s->k));
    return pl_mtobs_sample(&o->mt[s->k], sim, o->first, ns, err);
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

/* The cluster search of the observer, created at its first use. */
static int clusters_ready(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err)
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
static int clusters_now(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err)
{
    if (o->ids_step == sim->step) return 0;
    int rc = clusters_ready(sim, o, err);
    const pl_colloid_t *c = sim->colloids;
    if (!rc) rc = pl_cluster_find(o->cl, c->n, c->x, c->y, c->z, c->rad, err);
    o->ids_step = rc ? -1 : sim->step;
    return rc;
}

/* The cluster series with room for cap samples and the size distribution
 * of n colloids (at the first sample or a restart). */
static int clusters_alloc(pl_observe_t *o, size_t cap, size_t n, pl_err_t *err)
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

static int sample_clusters(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const pl_colloid_t *c = sim->colloids;
    if (!o->c_step) {
        const size_t cap = expected_samples(o, sc->observe.clusters_start, sc->observe.clusters_interval);
        int rc = clusters_alloc(o, cap, c->n, err);
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
static int vdist_alloc(pl_observe_t *o, const pl_sim_t *sim, pl_err_t *err)
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

static int sample_vdist(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err)
{
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
    if (c->n > 1 && c->integrator != PL_CINT_BROWNIAN) {
        const double *const v[3] = {c->vx, c->vy, c->vz};
        scale_components(o->vs, c->n, v, c->mass, kT);
        pl_vdist_sample(o->vd[1], c->n, o->vs[0], o->vs[1], o->vs[2]);
    }
    return 0;
}

/* Volume of the part of a sphere (centre zc, radius R) between z = a and b. */
static double slice_volume(double zc, double R, double a, double b)
{
    double lo = fmax(a, zc - R) - zc, hi = fmin(b, zc + R) - zc;
    if (hi <= lo) return 0.0;
    return PL_PI * (R * R * (hi - lo) - (hi * hi * hi - lo * lo * lo) / 3.0);
}

/* The sedimentation series with room for cap samples of `bins` bins (at
 * the first sample or a restart); s_vel zeroed: no velocity at the first
 * sample (a defined checkpoint byte). */
static int sediment_alloc(pl_observe_t *o, size_t cap, size_t bins, pl_err_t *err)
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

static int sample_sediment(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const pl_colloid_t *c = sim->colloids;
    const double Lz = c->box[2];
    if (!o->s_step) {
        const size_t cap = expected_samples(o, sc->observe.sediment_start, sc->observe.sediment_interval);
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

/* The bin of the highest g(r) (the first coordination shell) and its SE. */
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
    return isfinite(*g) && isfinite(*se);
}

static int rdf_peak(const pl_observe_t *o, double *r, double *g, double *se)
{
    return rdf_peak_of(o->rdf, o->rdf_par.nbins, r, g, se);
}

/* r of g(r) in units of colloids.radius and, for a physical scene, in um. */
static void rdf_r_units(pl_json_t *b, json_t *e, const pl_scene_t *sc, double r)
{
    pl_json_real(b, e, "r_over_R", r / sc->colloids.radius);
    if (sc->mapping.enabled) pl_json_real(b, e, "r_um", r * sc->mapping.map.a0 * 1e6);
}

/* The blocking accumulator of a time-averaged observable (NULL: none). */
static const pl_blocking_t *ob_blocking(const pl_observe_t *o, int ob)
{
    if (ob == OB_SETTLING) return &o->s_vb;
    if (!o->cl) return NULL;
    if (ob >= OB_NCLUSTERS && ob <= OB_MEANSIZE) return &o->cb[ob - OB_NCLUSTERS];
    if (ob >= OB_BONDS && ob < OB_N) return &o->cb[3 + ob - OB_BONDS];
    return NULL;
}

int pl_observe_estimate(const pl_sim_t *sim, int ob, double *value, double *se)
{
    const pl_observe_t *o = sim->observe;
    double a, b;
    if (!o || ob < 0 || ob >= OB_N) return 0;
    if (ob == OB_D) return pl_mtobs_diffusion(&o->mt[PL_MTOBS_MSD], value, se, &a, &b);
    if (ob == OB_RDF_PEAK) return rdf_peak(o, &a, value, se);
    const pl_blocking_t *bl = ob_blocking(o, ob);
    if (!bl || bl->n < 2) return 0;
    pl_blocking_result_t r = pl_blocking_result(bl);
    *value = r.mean;
    *se = r.se;
    return isfinite(r.mean) && isfinite(r.se);
}

const char *pl_observe_name(int ob) { return ob >= 0 && ob < OB_N ? ob_names[ob] : "?"; }

/* Records the estimates of every active observable at the fractions of the
 * run (1/8, 1/4, 1/2, 1). */
static int stage_error_time(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    pl_observe_t *o = ctx;
    if (sim->step == o->resume_step) return 0; /* recorded before the checkpoint */
    while (o->next_frac < NFRAC) {
        const long long at = o->first + (long long)ceil(fractions[o->next_frac] * (double)(o->last - o->first));
        if (sim->step < at) break;
        const double wall = omp_get_wtime() - o->t_start;
        ept_t *e[OB_N];
        for (int k = 0; k < OB_N; ++k) {
            e[k] = &o->ept[k][o->next_frac];
            e[k]->step = sim->step;
            e[k]->wall_s = wall;
        }
        double a, b, c;
        e[OB_D]->valid = pl_mtobs_diffusion(&o->mt[PL_MTOBS_MSD], &e[OB_D]->value, &e[OB_D]->se, &a, &b);
        e[OB_D]->plateau = 1;
        e[OB_RDF_PEAK]->valid = rdf_peak(o, &a, &e[OB_RDF_PEAK]->value, &e[OB_RDF_PEAK]->se);
        e[OB_RDF_PEAK]->plateau = 1;
        (void)c;
        for (int k = OB_NCLUSTERS; k < OB_N; ++k) {
            const pl_blocking_t *bl = ob_blocking(o, k);
            if (!bl) continue;
            pl_blocking_result_t r = pl_blocking_result(bl);
            ept_t *q = e[k];
            q->valid = bl->n >= 2 && isfinite(r.mean) && isfinite(r.se);
            q->value = r.mean;
            q->se = r.se;
            q->plateau = r.plateau;
        }
        o->next_frac++;
    }
    return 0;
}

/* The cluster ids of a trajectory frame (pl_colloid_traj_cluster_ids): the
 * partition of that step's positions, from clusters_start on; the observer's
 * own samples are not touched (a trajectory step between them costs one
 * more search). */
static const int32_t *traj_ids(void *ctx, long long step, int compute)
{
    pl_observe_t *o = ctx;
    if (step < o->sim->scene.observe.clusters_start) return NULL;
    if (o->ids_step != step) {
        pl_err_t ignore = {0, ""};
        if (!compute || step != o->sim->step || clusters_now(o->sim, o, &ignore)) return NULL;
    }
    return pl_cluster_ids(o->cl);
}

static int observe_resume(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err);

/* The run's first state is known when the after-step stages first run; the
 * trajectory (opened after the plan) gets the cluster ids then, before its
 * first frame (the writers' slot follows the observers'). */
static int stage_begin(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    pl_observe_t *o = ctx;
    if (!o->begun) {
        o->begun = 1;
        o->last = sim->last_step;
        o->sim = sim;
        if (o->resume_step < 0) {
            o->first = sim->first_step;
            o->t_start = omp_get_wtime();
        } else {
            o->t_start = omp_get_wtime(); /* no clock reading is checkpointed */
            int rc = observe_resume(sim, o, err);
            if (rc) return rc;
        }
        if (sim->colloid_traj && sim->scene.observe.clusters_interval > 0) {
            int rc = pl_colloid_traj_cluster_ids(sim->colloid_traj, traj_ids, o, err);
            if (rc) return rc;
        }
    }
    return 0;
}

#define OFFS(m) offsetof(pl_scene_observe_t, m)
static const struct {
    const char *stage;
    int (*sample)(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err);
    size_t interval, start; /* in pl_scene_observe_t */
} samplers[NSMP] = {
    [SMP_RDF] = {"observe-rdf", sample_rdf, OFFS(rdf_interval), OFFS(rdf_start)},
    [SMP_SQ] = {"observe-sq", sample_sq, OFFS(sq_interval), OFFS(sq_start)},
    [SMP_CLUSTERS] = {"observe-clusters", sample_clusters, OFFS(clusters_interval), OFFS(clusters_start)},
    [SMP_VDIST] = {"observe-vdist", sample_vdist, OFFS(vdist_interval), OFFS(vdist_start)},
    [SMP_SEDIMENT] = {"observe-sediment", sample_sediment, OFFS(sediment_interval), OFFS(sediment_start)},
};

/* A sampler's stage (ctx: its o->smp_ctx): not at the checkpoint's step
 * (sampled before it) nor before the sampler's start step; its wall time
 * to o->wall. */
static int stage_sample(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    const obs_stage_t *s = ctx;
    pl_observe_t *o = s->o;
    if (sim->step == o->resume_step || sim->step < pl_scene_observe_ll(&sim->scene.observe, samplers[s->k].start))
        return 0;
    const double t0 = omp_get_wtime();
    const int rc = samplers[s->k].sample(sim, o, err);
    o->wall[s->k] += omp_get_wtime() - t0;
    return rc;
}

static int observe_stages(pl_sim_t *sim, pl_err_t *err)
{
    int rc;
    pl_observe_t *o = sim->observe;
    if (!o) return 0;
    const pl_scene_observe_t *so = &sim->scene.observe;
    pl_stage_t b = {.name = "observe-begin", .fn = stage_begin, .ctx = o, .interval = 1,
                    .phase = PL_PHASE_AFTER, .slot = PL_SLOT_OBSERVE, .at_start = 1};
    if ((rc = pl_sim_add_stage(sim, &b, err))) return rc;
    for (int k = 0; k < NSMP; ++k) {
        if (k == SMP_CLUSTERS) /* the correlators between S(q) and the clusters */
            for (int q = 0; q < PL_MTOBS_N; ++q) {
                if (pl_mtobs_interval(so, q) <= 0) continue;
                pl_stage_t s = pl_mtobs_stage(so, q);
                s.fn = stage_mtau;
                s.ctx = &o->mt_ctx[q];
                if ((rc = pl_sim_add_stage(sim, &s, err))) return rc;
            }
        if (pl_scene_observe_ll(so, samplers[k].interval) <= 0) continue;
        pl_stage_t s = {.name = samplers[k].stage, .fn = stage_sample, .ctx = &o->smp_ctx[k],
                        .interval = pl_scene_observe_ll(so, samplers[k].interval), .phase = PL_PHASE_AFTER,
                        .slot = PL_SLOT_OBSERVE, .at_start = 1};
        if ((rc = pl_sim_add_stage(sim, &s, err))) return rc;
    }
    pl_stage_t e = {.name = "observe-error-time", .fn = stage_error_time, .ctx = o, .interval = 1,
                    .phase = PL_PHASE_AFTER, .slot = PL_SLOT_OBSERVE, .at_start = 1};
    if ((rc = pl_sim_add_stage(sim, &e, err))) return rc;
    return 0;
}

/* ---- outputs ----------------------------------------------------------- */



/* /observables/<name>/{r, r_over_R, [r_um], value (1 x np x nbins; 1 x nbins
 * for one), value_se, step, time, samples}: the run's average of np g(r)
 * sharing their bins; r also in units of colloids.radius and, for a physical
 * scene, in micrometres (the mapping's a0). */
static int write_rdf(hid_t obs, const char *name, const pl_sim_t *sim, const pl_observe_t *o, pl_rdf_t *const *r,
                     size_t np)
{
    const size_t nb = o->rdf_par.nbins;
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

/* /observables/colloid_sq/{q, q_mean, q_R, value (1 x nbins), value_se,
 * vectors, step, time, samples}: bins without a wave vector hold 0. */
static int write_sq(hid_t obs, const pl_sim_t *sim, const pl_observe_t *o)
{
    size_t nb = (size_t)sim->scene.observe.sq_bins;
    double *buf = malloc(5 * nb * sizeof(double));
    uint64_t *nv = malloc(nb * sizeof *nv);
    hid_t g = pl_h5_group(obs, "colloid_sq");
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

/* Components sampled into velocity histogram k (0: none, e.g. Brownian
 * colloids have no velocity). */
static uint64_t vdist_total(const pl_observe_t *o, int k)
{
    uint64_t tot = 0;
    for (size_t b = 0; o->vd[k] && b < VD_BINS + 2; ++b) tot += pl_vdist_counts(o->vd[k], 3)[b];
    return tot;
}

static int write_h5(const pl_sim_t *sim, const pl_observe_t *o, const char *path, pl_err_t *err)
{
    char tmp[4200];
    pl_atomic_tmp(path, tmp, sizeof tmp);
    pl_h5_quiet();
    hid_t f = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (f < 0) return pl_err_set(err, PL_ERR_IO, "%s: cannot create the observables file", tmp);
    int bad = pl_h5_h5md_header(f) != 0;
    hid_t obs = pl_h5_group(f, "observables");
    bad |= obs < 0;
    const double dt = sim->scene.srd.dt;
    if (!bad && o->rdf && pl_rdf_samples(o->rdf) > 0) bad |= write_rdf(obs, "colloid_rdf", sim, o, &o->rdf, 1) != 0;
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
    if (!bad && o->sq && pl_sq_samples(o->sq) > 0) bad |= write_sq(obs, sim, o) != 0;
    for (int k = 0; !bad && k < PL_MTOBS_N; ++k) bad |= pl_mtobs_write(obs, &o->mt[k]) != 0;
    if (!bad && o->cl && o->c_n > 0) {
        /* the bond kinds with energy bonds; the primary fraction (undefined
         * in samples without a bond) only in the summary */
        const int ncv = sim->scene.observe.clusters_bond == PL_BOND_ENERGY ? NCV - 1 : 4;
        for (int k = 0; k < ncv && !bad; ++k)
            bad |= pl_obs_series(obs, cv_names[k], o->c_n, o->c_step, dt, o->c_val[k], "1") != 0;
        size_t len = o->c_hist_len; /* trailing empty sizes left out */
        while (len > 1 && o->c_hist[len - 1] == 0) --len;
        hsize_t d1[1] = {len};
        hid_t g = pl_h5_group(obs, "cluster_size_distribution");
        bad |= g < 0 || pl_obs_put(g, "value", H5T_NATIVE_UINT64, 1, d1, o->c_hist, "1") != 0;
        if (g >= 0) bad |= pl_h5_attr_str(g, "meaning", "value[s]: clusters of s colloids, summed over samples") != 0;
        if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    }
    if (!bad && o->s_n > 0) {
        bad |= pl_obs_series(obs, "colloid_height", o->s_n, o->s_step, dt, o->s_height, "a0") != 0;
        if (o->s_n > 1)
            bad |= pl_obs_series(obs, "settling_velocity", o->s_n - 1, o->s_step + 1, dt, o->s_vel + 1, "a0/t0") != 0;
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
    }
    static const char *const vname[2] = {"fluid_velocity_distribution", "colloid_velocity_distribution"};
    for (int k = 0; !bad && k < 2; ++k) {
        if (!vdist_total(o, k)) continue; /* no sample: no group */
        hid_t g = pl_h5_group(obs, vname[k]);
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
    if (obs >= 0 && H5Gclose(obs) < 0) bad = 1;
    if (!bad && sim->scene.mapping.enabled) bad = pl_obs_si_h5(f, &sim->scene.mapping.map) != 0;
    return pl_obs_h5_commit(f, bad, tmp, path, "observables", err);
}

/* {value, stderr, ..., se_vs_time, wall_s_for_target} of one observable. */
static json_t *entry(pl_json_t *b, const pl_observe_t *o, int ob, double value, double se, double n_indep,
                     double ineff, int plateau, double wall, double target, const char *unit)
{
    json_t *e = json_object();
    pl_json_real(b, e, "value", value);
    pl_json_real(b, e, "stderr", se);
    pl_json_real(b, e, "n_independent", n_indep);
    if (ineff > 0) pl_json_real(b, e, "statistical_inefficiency", ineff);
    pl_json_set(b, e, "plateau", json_boolean(plateau));
    pl_json_real(b, e, "wall_s", wall);
    pl_json_str(b, e, "unit", unit);
    pl_obs_error_time(b, e, o->ept[ob], value, se, plateau, target);
    return e;
}

static int observe_finish(pl_sim_t *sim, const char *dir, json_t *doc, pl_err_t *err)
{
    pl_observe_t *o = sim->observe;
    if (!o) return 0;
    char path[4096];
    pl_path_join(path, sizeof path, dir, "observables.h5");
    int rc = write_h5(sim, o, path, err);
    if (rc) return rc;
    const double target = sim->scene.observe.target_rel_error;
    pl_json_t b = {err, path, "observables", 0};
    json_t *all = pl_obs_summary_section(&b, doc, sim, o->first);
    if (!all) return err->code;
    double D, se, tmin, tmax;
    const pl_mtobs_t *msd = &o->mt[PL_MTOBS_MSD];
    if (pl_mtobs_diffusion(msd, &D, &se, &tmin, &tmax)) {
        json_t *e = entry(&b, o, OB_D, D, se, (double)sim->colloids->n, 0.0, 1, msd->wall, target, "a0^2/t0");
        const double fit[2] = {tmin, tmax};
        pl_json_reals(&b, e, "fit_window_t0", fit, 2);
        if (sim->scene.mapping.enabled) { /* a0^2 / t0 -> m^2/s */
            const pl_mapping_t *m = &sim->scene.mapping.map;
            pl_json_real(&b, e, "value_m2_per_s", D * m->a0 * m->a0 / m->t0);
            pl_json_real(&b, e, "stderr_m2_per_s", se * m->a0 * m->a0 / m->t0);
        }
        pl_json_set(&b, all, "colloid_D", e);
    }
    pl_mtobs_summary(&b, all, &o->mt[PL_MTOBS_VACF], sim);
    if (o->sq && pl_sq_samples(o->sq) >= 2) { /* the highest bin of S(q) */
        size_t nb = (size_t)sim->scene.observe.sq_bins, best = nb;
        double *buf = malloc(3 * nb * sizeof(double));
        if (buf) {
            double *qm = buf, *S = qm + nb, *sse = S + nb;
            pl_sq_result(o->sq, NULL, qm, S, sse, NULL);
            for (size_t k = 0; k < nb; ++k)
                if (isfinite(S[k]) && isfinite(sse[k]) && (best == nb || S[k] > S[best])) best = k;
            if (best < nb) {
                json_t *e = json_object();
                pl_json_real(&b, e, "value", S[best]);
                pl_json_real(&b, e, "stderr", sse[best]);
                pl_json_real(&b, e, "n_independent", (double)pl_sq_samples(o->sq));
                pl_json_real(&b, e, "q", qm[best]);
                pl_json_real(&b, e, "q_R", qm[best] * sim->scene.colloids.radius);
                pl_json_int(&b, e, "wave_vectors", (long long)pl_sq_vectors(o->sq));
                pl_json_real(&b, e, "wall_s", o->wall[SMP_SQ]);
                pl_json_str(&b, e, "unit", "1");
                pl_json_set(&b, all, "sq_peak", e);
            }
            free(buf);
        }
    }
    pl_mtobs_summary(&b, all, &o->mt[PL_MTOBS_CFF], sim);
    double r, g, gse;
    if (o->rdf && rdf_peak(o, &r, &g, &gse)) {
        json_t *e = entry(&b, o, OB_RDF_PEAK, g, gse, (double)pl_rdf_samples(o->rdf), 0.0, 1, o->wall[SMP_RDF],
                          target, "1");
        pl_json_real(&b, e, "r", r);
        rdf_r_units(&b, e, &sim->scene, r);
        pl_json_int(&b, e, "samples", (long long)pl_rdf_samples(o->rdf));
        pl_json_set(&b, all, "rdf_peak", e);
    }
    if (o->npair) { /* the peak of each partial g_ab */
        json_t *arr = json_array();
        size_t q = 0;
        for (size_t a = 0; a < o->ncls; ++a)
            for (size_t c2 = a; c2 < o->ncls; ++c2, ++q) {
                if (!rdf_peak_of(o->rdfc[q], o->rdf_par.nbins, &r, &g, &gse)) continue;
                json_t *e = json_object();
                const long long ab[2] = {(long long)a, (long long)c2};
                json_t *cl = json_array();
                for (int k = 0; k < 2; ++k) json_array_append_new(cl, json_integer(ab[k]));
                pl_json_set(&b, e, "classes", cl);
                const double ra[2] = {o->cls_rad[2 * a], o->cls_rad[2 * a + 1]};
                const double rb[2] = {o->cls_rad[2 * c2], o->cls_rad[2 * c2 + 1]};
                pl_json_reals(&b, e, "radius_range_a", ra, 2);
                pl_json_reals(&b, e, "radius_range_b", rb, 2);
                pl_json_real(&b, e, "value", g);
                pl_json_real(&b, e, "stderr", gse);
                pl_json_real(&b, e, "n_independent", (double)pl_rdf_samples(o->rdfc[q]));
                pl_json_real(&b, e, "wall_s", o->wall[SMP_RDF]);
                pl_json_str(&b, e, "unit", "1");
                pl_json_real(&b, e, "r", r);
                rdf_r_units(&b, e, &sim->scene, r);
                json_array_append_new(arr, e);
            }
        pl_json_set(&b, all, "rdf_peak_classes", arr);
    }
    const int energy_bonds = sim->scene.observe.clusters_bond == PL_BOND_ENERGY;
    for (int ob = OB_NCLUSTERS; o->cl && ob < OB_N; ++ob) {
        const pl_blocking_t *bl = ob_blocking(o, ob);
        if (ob == OB_SETTLING || !bl || bl->n < 2 || (ob > OB_BONDS && !energy_bonds)) continue;
        pl_blocking_result_t res = pl_blocking_result(bl);
        if (!isfinite(res.mean) || !isfinite(res.se)) continue;
        json_t *e = entry(&b, o, ob, res.mean, res.se, res.n_indep, res.inefficiency, res.plateau,
                          o->wall[SMP_CLUSTERS], target, "1");
        pl_json_int(&b, e, "samples", (long long)bl->n);
        if (ob == OB_PRIMARY_FRACTION) pl_json_str(&b, e, "over", "samples with at least one bond");
        if (ob >= OB_BONDS && energy_bonds) {
            pl_json_real(&b, e, "bond_energy_kT", -sim->scene.observe.clusters_energy);
            if (isfinite(o->c_barrier)) pl_json_real(&b, e, "barrier_gap_a0", o->c_barrier);
        }
        pl_json_set(&b, all, ob_names[ob], e);
    }
    if (o->s_vb.n >= 2) {
        pl_blocking_result_t res = pl_blocking_result(&o->s_vb);
        if (isfinite(res.mean) && isfinite(res.se)) {
            json_t *e = entry(&b, o, OB_SETTLING, res.mean, res.se, res.n_indep, res.inefficiency, res.plateau,
                              o->wall[SMP_SEDIMENT], target, "a0/t0");
            pl_json_int(&b, e, "samples", (long long)o->s_vb.n);
            if (sim->scene.mapping.enabled) { /* a0/t0 -> m/s */
                const pl_mapping_t *m = &sim->scene.mapping.map;
                pl_json_real(&b, e, "value_m_per_s", res.mean * m->a0 / m->t0);
                pl_json_real(&b, e, "stderr_m_per_s", res.se * m->a0 / m->t0);
            }
            pl_json_set(&b, all, "settling_velocity", e);
        }
    }
    if (o->s_n >= 2) pl_sediment_summary(&b, all, &sim->scene, o->s_vel + 1, o->s_step + 1, o->s_n - 1);
    static const char *const vkey[2] = {"fluid_velocity_chi2", "colloid_velocity_chi2"};
    for (int k = 0; k < 2; ++k) {
        double chi2, p;
        int dof;
        pl_err_t ignore = {0, ""};
        if (!vdist_total(o, k) || pl_vdist_chi2(o->vd[k], 3, 1.0, &chi2, &dof, &p, &ignore)) continue;
        json_t *e = json_object();
        pl_json_real(&b, e, "chi2", chi2);
        pl_json_int(&b, e, "dof", dof);
        pl_json_real(&b, e, "p_value", p);
        pl_json_real(&b, e, "wall_s", o->wall[SMP_VDIST]);
        pl_json_str(&b, e, "against", "unit Gaussian of (v - <v>) sqrt(M/kT), all axes (Maxwell-Boltzmann)");
        pl_json_set(&b, all, vkey[k], e);
    }
    return b.failed ? err->code : 0;
}


/* ---- checkpoint -------------------------------------------------------- */

/* Group /observe of the checkpoint (src/io/checkpoint_observe.c gives it the
 * observer fingerprint): everything the observers accumulated, so that a
 * restarted run's observables equal those of the uninterrupted run bitwise.
 * The objects are read back as they were (correlators with the levels the
 * first run planned for); observe_resume, at the restart's first step, sizes
 * them for the combined run.  Datasets: meta (int64, OCK_* below), the
 * error-against-time points, then one set per observer present.  No clock
 * reading is stored (the same state gives the same bytes): after a restart
 * the wall times (wall_s) count the restarted run's, and the points of
 * se_vs_time taken over from the first run carry wall_s = 0. */
enum { OCK_FIRST, OCK_NEXT_FRAC, OCK_MSD, OCK_VACF, OCK_CFF, OCK_RDF, OCK_NCLS, OCK_SQ, OCK_CN, OCK_CHIST,
       OCK_VD, OCK_SN, OCK_SBINS, OCK_STEP, OCK_N };
enum { NEPT = OB_N * NFRAC };

static int observe_ckpt_write(int64_t file, const pl_sim_t *sim)
{
    pl_observe_t *o = sim->observe;
    if (!o) return 0;
    hid_t g = pl_ckpt_observe_group_write((hid_t)file, "observe", &sim->scene);
    if (g < 0) return -1;
    long long meta[OCK_N] = {o->begun ? o->first : sim->step, o->next_frac,
                             pl_mtobs_levels(&o->mt[PL_MTOBS_MSD]), pl_mtobs_levels(&o->mt[PL_MTOBS_VACF]),
                             pl_mtobs_levels(&o->mt[PL_MTOBS_CFF]), o->rdf != NULL, (long long)o->ncls, o->sq != NULL,
                             o->c_step ? (long long)o->c_n : -1, (long long)o->c_hist_len, o->vd[1] != NULL,
                             o->s_step ? (long long)o->s_n : -1, (long long)o->s_bins, sim->step};
    long long est[NEPT], eflag[2 * NEPT];
    double eval[2 * NEPT];
    for (int k = 0; k < NEPT; ++k) {
        const ept_t *e = &o->ept[k / NFRAC][k % NFRAC];
        est[k] = e->step;
        eflag[2 * k] = e->valid;
        eflag[2 * k + 1] = e->plateau;
        eval[2 * k] = e->value;
        eval[2 * k + 1] = e->se;
    }
    int bad = pl_ckpt_write_1d(g, "meta", H5T_NATIVE_LLONG, meta, OCK_N);
    bad |= pl_ckpt_write_1d(g, "ept_step", H5T_NATIVE_LLONG, est, NEPT);
    bad |= pl_ckpt_write_1d(g, "ept_flags", H5T_NATIVE_LLONG, eflag, 2 * NEPT);
    bad |= pl_ckpt_write_1d(g, "ept_values", H5T_NATIVE_DOUBLE, eval, 2 * NEPT);
    bad |= pl_ckpt_write_1d(g, "cluster_blocking", H5T_NATIVE_UCHAR, o->cb, sizeof o->cb);
    bad |= pl_ckpt_write_1d(g, "settling_blocking", H5T_NATIVE_UCHAR, &o->s_vb, sizeof o->s_vb);
    pl_rdf_t *const one[1] = {o->rdf};
    for (size_t q = 0; q < (o->rdf ? 1 + o->npair : 0); ++q) {
        pl_rdf_t *r = q ? o->rdfc[q - 1] : one[0];
        char a[64], b[64];
        snprintf(a, sizeof a, q ? "rdf_class%zu_counts" : "rdf_counts", q - 1);
        snprintf(b, sizeof b, q ? "rdf_class%zu_blocking" : "rdf_blocking", q - 1);
        pl_rdf_state_t st = pl_rdf_state(r);
        bad |= pl_ckpt_write_1d(g, a, H5T_NATIVE_UINT64, st.counts, st.ncounts);
        bad |= pl_ckpt_write_1d(g, b, H5T_NATIVE_UCHAR, st.blocking, st.nblocking * sizeof(pl_blocking_t));
    }
    if (o->sq) {
        pl_sq_state_t st = pl_sq_state(o->sq);
        bad |= pl_ckpt_write_1d(g, "sq_blocking", H5T_NATIVE_UCHAR, st.blocking, st.nblocking * sizeof(pl_blocking_t));
        bad |= pl_ckpt_write_1d(g, "sq_samples", H5T_NATIVE_UINT64, st.samples, 1);
    }
    for (int k = 0; k < PL_MTOBS_N; ++k)
        if (o->mt[k].c) bad |= pl_mtobs_ckpt_write(g, &o->mt[k]);
    if (o->c_step) {
        bad |= pl_ckpt_write_1d(g, "clusters_step", H5T_NATIVE_LLONG, o->c_step, o->c_n);
        for (int k = 0; k < NCV; ++k) bad |= pl_ckpt_write_1d(g, cv_names[k], H5T_NATIVE_DOUBLE, o->c_val[k], o->c_n);
        bad |= pl_ckpt_write_1d(g, "cluster_size_hist", H5T_NATIVE_UINT64, o->c_hist, o->c_hist_len);
    }
    if (o->vd[1]) {
        static const char *const vn[2] = {"vdist_fluid", "vdist_colloid"};
        for (int k = 0; k < 2; ++k) {
            pl_vdist_state_t st = pl_vdist_state(o->vd[k]);
            bad |= pl_ckpt_write_1d(g, vn[k], H5T_NATIVE_UINT64, st.counts, st.ncounts);
        }
    }
    if (o->s_step) {
        bad |= pl_ckpt_write_1d(g, "sediment_step", H5T_NATIVE_LLONG, o->s_step, o->s_n);
        bad |= pl_ckpt_write_1d(g, "sediment_phi", H5T_NATIVE_DOUBLE, o->s_phi, o->s_n * o->s_bins);
        bad |= pl_ckpt_write_1d(g, "sediment_height", H5T_NATIVE_DOUBLE, o->s_height, o->s_n);
        bad |= pl_ckpt_write_1d(g, "sediment_vz", H5T_NATIVE_DOUBLE, o->s_vz, o->s_n);
        bad |= pl_ckpt_write_1d(g, "sediment_velocity", H5T_NATIVE_DOUBLE, o->s_vel, o->s_n);
    }
    if (H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
}

/* A blocking accumulator read from a file: its level count in range (the
 * result walks nlev levels). */
static int ck_blocking_ok(const pl_blocking_t *b, size_t n)
{
    for (size_t k = 0; k < n; ++k)
        if (b[k].nlev < 0 || b[k].nlev > PL_BLOCKING_LEVELS) return 0;
    return 1;
}

static int ck_blocking_read(hid_t g, const char *name, pl_blocking_t *b, size_t n, const char *path, pl_err_t *err)
{
    int rc = pl_ckpt_read_1d(g, name, H5T_NATIVE_UCHAR, b, n * sizeof *b, path, err);
    if (!rc && !ck_blocking_ok(b, n))
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: /observe/%s: a blocking level count is out of range (corrupt "
                                           "checkpoint)", path, name);
    return rc;
}

static int observe_ckpt_read_group(hid_t g, pl_sim_t *sim, pl_observe_t *o, const char *path, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const pl_scene_observe_t *so = &sc->observe;
    const pl_colloid_t *c = sim->colloids;
    long long m[OCK_N], est[NEPT], eflag[2 * NEPT];
    double eval[2 * NEPT];
    int rc = pl_ckpt_read_1d(g, "meta", H5T_NATIVE_LLONG, m, OCK_N, path, err);
    if (!rc) rc = pl_ckpt_read_1d(g, "ept_step", H5T_NATIVE_LLONG, est, NEPT, path, err);
    if (!rc) rc = pl_ckpt_read_1d(g, "ept_flags", H5T_NATIVE_LLONG, eflag, 2 * NEPT, path, err);
    if (!rc) rc = pl_ckpt_read_1d(g, "ept_values", H5T_NATIVE_DOUBLE, eval, 2 * NEPT, path, err);
    if (rc) return rc;
    int mt_off = 0; /* a correlator whose observer is off */
    for (int k = 0; k < PL_MTOBS_N; ++k) mt_off |= m[OCK_MSD + k] && pl_mtobs_interval(so, k) <= 0;
    /* what the observe section allows (the fingerprint matched, so only a
     * corrupt file has more) */
    const char *why = m[OCK_STEP] != sim->step ? "step differs from the checkpoint's"
                      : m[OCK_FIRST] < 0 || m[OCK_FIRST] > sim->step ? "first step out of range"
                      : m[OCK_NEXT_FRAC] < 0 || m[OCK_NEXT_FRAC] > NFRAC ? "next_frac out of range"
                      : mt_off || (m[OCK_RDF] && so->rdf_interval <= 0) ||
                                (m[OCK_SQ] && so->sq_interval <= 0) || (m[OCK_VD] && so->vdist_interval <= 0) ||
                                (m[OCK_CN] >= 0 && so->clusters_interval <= 0) ||
                                (m[OCK_SN] >= 0 && so->sediment_interval <= 0)
                          ? "an observer the scene does not switch on"
                      : m[OCK_NCLS] != 0 && (!m[OCK_RDF] || m[OCK_NCLS] != so->rdf_size_classes)
                          ? "size classes differ from observe.rdf_size_classes"
                      : m[OCK_CN] >= 0 && (m[OCK_CN] > sim->step + 1 || m[OCK_CHIST] != (long long)c->n + 1)
                          ? "cluster series or size distribution of the wrong length"
                      : m[OCK_SN] >= 0 && (m[OCK_SN] > sim->step + 1 ||
                                           m[OCK_SBINS] != (so->sediment_bins > 0 ? so->sediment_bins
                                                                                  : (long long)c->box[2]))
                          ? "sedimentation series or bins of the wrong length"
                          : NULL;
    if (why) return pl_err_set(err, PL_ERR_INPUT, "%s: /observe/meta: %s (corrupt checkpoint)", path, why);
    for (int k = 0; k < NEPT; ++k) {
        ept_t *e = &o->ept_saved[k / NFRAC][k % NFRAC];
        e->step = est[k];
        e->valid = (int)eflag[2 * k];
        e->plateau = (int)eflag[2 * k + 1];
        e->wall_s = 0.0; /* no clock reading is checkpointed */
        e->value = eval[2 * k];
        e->se = eval[2 * k + 1];
    }
    o->nept_saved = (int)m[OCK_NEXT_FRAC];
    if ((rc = ck_blocking_read(g, "cluster_blocking", o->cb, NCV, path, err))) return rc;
    if ((rc = ck_blocking_read(g, "settling_blocking", &o->s_vb, 1, path, err))) return rc;
    if (m[OCK_RDF]) {
        if ((rc = rdf_ready(sim, o, err))) return rc;
        if (m[OCK_NCLS] && (rc = size_classes(o, c, (size_t)m[OCK_NCLS], sim->nthreads, err))) return rc;
        for (size_t q = 0; q < 1 + o->npair; ++q) {
            pl_rdf_state_t st = pl_rdf_state(q ? o->rdfc[q - 1] : o->rdf);
            char a[64], b[64];
            snprintf(a, sizeof a, q ? "rdf_class%zu_counts" : "rdf_counts", q - 1);
            snprintf(b, sizeof b, q ? "rdf_class%zu_blocking" : "rdf_blocking", q - 1);
            if ((rc = pl_ckpt_read_1d(g, a, H5T_NATIVE_UINT64, st.counts, st.ncounts, path, err))) return rc;
            if ((rc = ck_blocking_read(g, b, st.blocking, st.nblocking, path, err))) return rc;
        }
    }
    if (m[OCK_SQ]) {
        if ((rc = sq_ready(sim, o, err))) return rc;
        pl_sq_state_t st = pl_sq_state(o->sq);
        if ((rc = ck_blocking_read(g, "sq_blocking", st.blocking, st.nblocking, path, err))) return rc;
        if ((rc = pl_ckpt_read_1d(g, "sq_samples", H5T_NATIVE_UINT64, st.samples, 1, path, err))) return rc;
    }
    for (int k = 0; k < PL_MTOBS_N; ++k)
        if (m[OCK_MSD + k] && (rc = pl_mtobs_ckpt_read(g, &o->mt[k], m[OCK_MSD + k], sim, path, err))) return rc;
    if (m[OCK_CN] >= 0) {
        o->c_n = (size_t)m[OCK_CN];
        if ((rc = clusters_alloc(o, o->c_n ? o->c_n : 1, c->n, err))) return rc;
        if ((rc = pl_ckpt_read_1d(g, "clusters_step", H5T_NATIVE_LLONG, o->c_step, o->c_n, path, err))) return rc;
        for (int k = 0; k < NCV; ++k)
            if ((rc = pl_ckpt_read_1d(g, cv_names[k], H5T_NATIVE_DOUBLE, o->c_val[k], o->c_n, path, err))) return rc;
        if ((rc = pl_ckpt_read_1d(g, "cluster_size_hist", H5T_NATIVE_UINT64, o->c_hist, o->c_hist_len, path, err)))
            return rc;
        if ((rc = clusters_ready(sim, o, err))) return rc;
    }
    if (m[OCK_VD]) {
        static const char *const vn[2] = {"vdist_fluid", "vdist_colloid"};
        if ((rc = vdist_alloc(o, sim, err))) return rc;
        for (int k = 0; k < 2; ++k) {
            pl_vdist_state_t st = pl_vdist_state(o->vd[k]);
            if ((rc = pl_ckpt_read_1d(g, vn[k], H5T_NATIVE_UINT64, st.counts, st.ncounts, path, err))) return rc;
        }
    }
    if (m[OCK_SN] >= 0) {
        o->s_n = (size_t)m[OCK_SN];
        if ((rc = sediment_alloc(o, o->s_n ? o->s_n : 1, (size_t)m[OCK_SBINS], err))) return rc;
        if ((rc = pl_ckpt_read_1d(g, "sediment_step", H5T_NATIVE_LLONG, o->s_step, o->s_n, path, err)) ||
            (rc = pl_ckpt_read_1d(g, "sediment_phi", H5T_NATIVE_DOUBLE, o->s_phi, o->s_n * o->s_bins, path, err)) ||
            (rc = pl_ckpt_read_1d(g, "sediment_height", H5T_NATIVE_DOUBLE, o->s_height, o->s_n, path, err)) ||
            (rc = pl_ckpt_read_1d(g, "sediment_vz", H5T_NATIVE_DOUBLE, o->s_vz, o->s_n, path, err)) ||
            (rc = pl_ckpt_read_1d(g, "sediment_velocity", H5T_NATIVE_DOUBLE, o->s_vel, o->s_n, path, err)))
            return rc;
    }
    o->first = m[OCK_FIRST];
    o->resume_step = sim->step;
    return 0;
}

/* The observers' state from group /observe; without the group, or with
 * another observe section, they start afresh (sim->observe_note). */
static int observe_ckpt_read(int64_t file, pl_sim_t *sim, const char *path, pl_err_t *err)
{
    pl_observe_t *o = sim->observe;
    if (!o) return 0;
    hid_t g = pl_ckpt_observe_group_open((hid_t)file, "observe", sim);
    if (g < 0) return 0;
    int rc = observe_ckpt_read_group(g, sim, o, path, err);
    H5Gclose(g);
    return rc;
}

/* Grows a series buffer from n to cap elements of size sz (new part zero). */
static int grow_buf(void **p, size_t n, size_t cap, size_t sz)
{
    void *q = realloc(*p, cap * sz);
    if (!q) return -1;
    memset((char *)q + n * sz, 0, (cap - n) * sz);
    *p = q;
    return 0;
}

/* At the restarted run's first step (its last step now known): the
 * correlators get the levels and the series the room the combined run needs
 * (what an uninterrupted run would have created: pl_mtau_grow), and the
 * error-against-time points are those of the combined run from o->first to
 * o->last: a point the first run recorded at that step is taken over, one it
 * did not record (its step fell between the first run's fractions) is left
 * out of se_vs_time. */
static int observe_resume(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err)
{
    const pl_scene_observe_t *so = &sim->scene.observe;
    for (int k = 0; k < PL_MTOBS_N; ++k) {
        if (!o->mt[k].c) continue; /* not sampled yet (its interval may be 0) */
        int rc = pl_mtobs_grow(&o->mt[k], expected_samples(o, pl_mtobs_start(so, k), pl_mtobs_interval(so, k)), err);
        if (rc) return rc;
    }
    if (o->c_step) {
        const size_t cap = expected_samples(o, so->clusters_start, so->clusters_interval);
        if (cap > o->c_cap) {
            int bad = grow_buf((void **)&o->c_step, o->c_n, cap, sizeof *o->c_step);
            for (int k = 0; k < NCV; ++k) bad |= grow_buf((void **)&o->c_val[k], o->c_n, cap, sizeof(double));
            if (bad) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the cluster observer");
            o->c_cap = cap;
        }
    }
    if (o->s_step) {
        const size_t cap = expected_samples(o, so->sediment_start, so->sediment_interval);
        if (cap > o->s_cap) {
            int bad = grow_buf((void **)&o->s_step, o->s_n, cap, sizeof *o->s_step);
            bad |= grow_buf((void **)&o->s_phi, o->s_n * o->s_bins, cap * o->s_bins, sizeof(double));
            bad |= grow_buf((void **)&o->s_height, o->s_n, cap, sizeof(double));
            bad |= grow_buf((void **)&o->s_vel, o->s_n, cap, sizeof(double));
            bad |= grow_buf((void **)&o->s_vz, o->s_n, cap, sizeof(double));
            if (bad) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the sedimentation observer");
            o->s_cap = cap;
        }
    }
    memset(o->ept, 0, sizeof o->ept);
    o->next_frac = NFRAC;
    for (int k = NFRAC - 1; k >= 0; --k) {
        const long long at = o->first + (long long)ceil(fractions[k] * (double)(o->last - o->first));
        if (at > o->resume_step) {
            o->next_frac = k;
            continue;
        }
        for (int j = 0; j < o->nept_saved; ++j)
            if (o->ept_saved[0][j].step == at) {
                for (int ob = 0; ob < OB_N; ++ob) o->ept[ob][k] = o->ept_saved[ob][j];
                break;
            }
    }
    return 0;
}

const pl_module_t pl_observe_module = {
    .name = "observe",
    .validate_scene = pl_observe_validate_scene,
    .create = observe_create,
    .destroy = observe_destroy,
    .add_stages = observe_stages,
    .finish = observe_finish,
    .checkpoint_write = observe_ckpt_write,
    .checkpoint_read = observe_ckpt_read,
};
