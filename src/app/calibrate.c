/* Coupling-true time (DESIGN.md "Units and mapping"): the colloid diffusion
 * coefficient that coupling I or II realises at the scene's resolution is
 * measured by a short deterministic model run, and the unit mapping matches
 * that, not the Stokes-Einstein value of the model viscosity, to the real
 * colloid's D (Hecht Eq. 30).  Coupling II's friction is the cell
 * collision's plus the hydrodynamic part, not 6 pi eta R (the colloids of a
 * theory-mapped scene diffused ~1.9x faster than Stokes-Einstein); coupling
 * I's stochastic surface is not exactly PL Eq. 39's either.
 *
 * The run: the scene's model fluid (gamma, lambda, rule, thermostat) and
 * colloid (radius, mass, coupling keys) in a periodic cube, without walls,
 * gravity or pair forces; coupling II: 32 colloids in one box (points in
 * their cells; 0.8 % of the cells); coupling I and the potential coupling:
 * 8 colloids on a lattice in a box with phi <= 0.02, with PL's colloid-colloid
 * WCA (PL Eq. 16, sigma_cc by PL's rule: no overlaps); the potential
 * coupling at the MD step the mapping derives from the fluid-colloid WCA
 * alone, coupling I at the contact guard's MD steps for the stiffest
 * colloid-colloid contact a pair reaches with 20 kT; their slowing of each other is divided
 * out: D (1 - 1.1795 phi) for slip spheres (PL Sec. VI.C, ref. 90; the
 * potential coupling and coupling I's slip rule), D (1 - 1.8315 phi) for
 * stick spheres (Batchelor 1976; coupling I's stick rules).  (Coupling I
 * used one colloid per box in replicas; 8 per box give 2.4 times the
 * colloid-time per fluid particle-step, and the blocks of one long run are
 * many times the longest lag.)  D from the slope of the
 * mean-squared displacement between the lags t1 = 4 tau_v and t2 = 12 tau_v,
 * tau_v = 2 M D_theory, a bound of the velocity relaxation time M D (coupling
 * II colloids move ~2x faster than the theory's D): for an exponential
 * relaxation the slope is then at most (e^-4 - e^-12) / 8 = 0.23 % below the
 * long-time one; averaged over colloids, origins and replicas; its standard
 * error from 8 blocks of time origins per replica.  The fluid's long-time
 * tail is slower: the slope misses its part beyond the lags (2-3 % of D for
 * coupling II in a 16^3 box, measured: the slope over [4, 12] tau_v rises
 * by that at lags of 20-150 t0, then stays), which the box's transverse
 * modes give (pl_srd_tail_missed) and which is added.  The periodic images
 * slow a colloid by 2.837 kT / (6 pi eta L) (Hasimoto 1959, PL Eq. 43; eta
 * of the rule: PL Eqs. 9-15 or Hecht Eq. 28), which is added back for the
 * unbounded D.
 *
 * The result depends only on the model parameters it hashes (not on t0, the
 * salt, the colloid count or the seed of the scene), so it is cached: in
 * PELOID_CACHE, else $XDG_CACHE_HOME/peloid, else ~/.cache/peloid, one JSON
 * file per parameter set (written atomically, under a lock so that
 * concurrent sweep points run it once), and read-only in the project's
 * calibration/ directory for the shipped scenes (`make calibrations`; not
 * read with PELOID_NO_SHIPPED_CALIBRATION set).  Entries are checked on
 * reading (src/app/calibration_cache.c): a bad shipped one is refused (a
 * bug), a bad cached one recalibrated and overwritten; a cache that cannot
 * store the result or a lock not released in time costs this run a
 * calibration and a warning, never the run.  The
 * run is bitwise deterministic, so a cached and a fresh calibration agree
 * to the last bit (tests/cli/calibration.sh).  --calibrate always skips the
 * shipped set and the cache on reading and replaces the entry; never is
 * src/app/calibrate_mode.c.  A run that has to measure says so before it
 * starts (its size), times its first steps (CAL_PROBE_FRACTION of them, or
 * CAL_PROBE_S of wall time, whichever comes first) and extrapolates them to
 * an estimated duration, then reports progress (src/app/progress.c). */
#include <errno.h>
#include <fcntl.h>
#include <jansson.h>
#include <math.h>
#include <stddef.h>
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/colloid.h"
#include "peloid/depletion.h"
#include "peloid/io.h"
#include "peloid/progress.h"
#include "peloid/real.h" /* PL_PI */
#include "peloid/run.h"
#include "peloid/sim.h"
#include "peloid/srd_theory.h"

#include "calibration_cache.h"

enum { CAL_BLOCKS = 8, CAL_N2 = 32, CAL_NP = 8 };
/* coupling I since 2026-12-05 (8 colloids per box; the events of a step see the colloid velocities the
 * step found, src/coupling/coupling_stages.c), hashed into its keys only: the coupling II and potential
 * calibrations keep their keys, a cached coupling-I calibration of the drifting coupling is not read */
static const int CAL_VERSION_I = 2;
static const long long CAL_SEED = 20261204;
static const double CAL_BUDGET = 6e8;       /* fluid particle-steps of one calibration */
static const double CAL_TARGET = 15000.0;   /* colloid-time in units of tau_v: ~3 % SE */
/* the potential coupling: finite colloids at phi <= CAL_PHI_P in their box,
 * its own budget (the fluid per colloid is phi-bound: ~8 x the particles per
 * colloid-time of coupling II's points) */
static const double CAL_PHI_P = 0.02, CAL_BUDGET_P = 4e9;
/* coupling I's colloid-colloid contact: the gap a pair reaches with this energy (a thermal pair,
 * e^-20), resolved as the contact guard asks (colloids.min_contact_steps per collision time) */
static const double CAL_CONTACT_KT = 20.0;
/* the estimate: the first 1 % of the steps (at least 10) or 2 s of wall time, whichever comes first; progress lines
 * off a terminal every output.progress_s seconds, at most CAL_PROGRESS_S */
static const double CAL_PROBE_FRACTION = 0.01, CAL_PROBE_MIN = 10.0, CAL_PROBE_S = 2.0, CAL_PROGRESS_S = 5.0;

/* ---- the model run ------------------------------------------------------ */

typedef struct {
    int n, L, replicas;
    long long steps, stride, lag1, lag2; /* collision steps; lags in strides */
} cal_plan_t;

/* Coupling I's MD steps per collision step: the colloid-colloid WCA (PL Eq.
 * 16, U = 4 eps (x^2 - x) + eps, x = (sigma_cc / r)^n) at the gap where a
 * pair has CAL_CONTACT_KT of energy, U'' there, and min_contact_steps MD
 * steps per collision time pi sqrt(m_red / U''), m_red = M / 2 (the contact
 * guard's bound, colloid_guard.c). */
static long long cal_contact_substeps(const pl_scene_t *c)
{
    const pl_scene_colloids_t *k = &c->colloids;
    pl_depletion_params_t dp;
    pl_colloid_depletion_params(c, &dp);
    const double eps = k->wca.epsilon, n = k->wca.n, kT = pl_scene_kT(c);
    const double sigma = pl_depletion_sigma_cc(2.0 * pl_depletion_cf_cutoff(&dp), eps, n, PL_DEPLETION_RULE_ENERGY * dp.kT);
    const double E = CAL_CONTACT_KT * kT, x = 0.5 * (1.0 + sqrt(1.0 + (E - eps) / eps));
    const double r = sigma / pow(x, 1.0 / n);
    const double u2 = 4.0 * eps * n * (2.0 * (2.0 * n + 1.0) * x * x - (n + 1.0) * x) / (r * r);
    const double M = k->mass_density * 4.0 / 3.0 * PL_PI * pow(k->radius, 3.0);
    const double collision = PL_PI * sqrt(0.5 * M / u2);
    const double steps = ceil(k->min_contact_steps * c->srd.dt / collision - 1e-9);
    return steps < 1.0 ? 1 : (long long)steps;
}

/* The calibration scene: the scene's model with the box, colloids and
 * everything that does not set the friction replaced. */
static void cal_scene(const pl_scene_t *sc, const cal_plan_t *p, int replica, pl_scene_t *c)
{
    *c = *sc;
    c->mapping.enabled = 0;
    c->run.seed = CAL_SEED + replica;
    for (int d = 0; d < 3; ++d) c->box.cells[d] = p->L;
    c->box.walls_z = c->box.walls_xy = PL_WALLS_NONE;
    memset(c->box.wall_velocity, 0, sizeof c->box.wall_velocity);
    memset(c->fluid.body_force, 0, sizeof c->fluid.body_force);
    pl_scene_colloids_t *k = &c->colloids;
    const int pot = sc->coupling.method == PL_COUPLE_POTENTIAL, one = sc->coupling.method == PL_COUPLE_HECHT1;
    k->count = p->n;
    k->init = pot || one ? PL_CINIT_LATTICE : PL_CINIT_RANDOM;
    k->polydispersity = 0.0;
    k->pairs[0] = '\0';
    k->integrator = PL_CINT_VERLET;
    k->substeps = 1; /* no force: free flight between the coupling's impulses */
    if (pot) /* the fluid-colloid WCA at the MD step the mapping derives from it alone */
        k->substeps = pl_mapping_cf_substeps(sc->coupling.sigma_cf > 0 ? sc->coupling.sigma_cf : k->radius,
                                             sc->coupling.epsilon_cf,
                                             k->mass_density * 4.0 / 3.0 * PL_PI * pow(k->radius, 3.0), sc->srd.dt,
                                             sc->mapping.cg.md_resolution > 0 ? sc->mapping.cg.md_resolution : 20.0);
    k->max_overlap = 1.0; /* ideal colloids: overlaps are not contacts here */
    k->slow_interval = 1;
    k->adaptive_substeps = 0; /* one MD step per collision step, as written */
    k->min_substeps = 1;
    memset(k->gravity, 0, sizeof k->gravity);
    k->trajectory_interval = 0;
    memset(&k->dlvo, 0, sizeof k->dlvo);
    memset(&k->hertz, 0, sizeof k->hertz);
    memset(&k->lub, 0, sizeof k->lub);
    memset(&k->wca, 0, sizeof k->wca);
    if (pot || one) { /* finite colloids keep PL's repulsion (PL Eq. 16, Sec. III.C.1): no overlaps */
        snprintf(k->pairs, sizeof k->pairs, "wca");
        k->wca = (pl_scene_wca_t){.epsilon = 2.5, .sigma = 0.0, .n = 24.0, .sigma_rule = PL_SIGMA_PL};
    }
    if (one) k->substeps = cal_contact_substeps(c);
    c->coupling.pinned = 0;
    c->coupling.compensate_gravity = 0;
    memset(c->coupling.flow_velocity, 0, sizeof c->coupling.flow_velocity);
    memset(c->coupling.pinned_spin, 0, sizeof c->coupling.pinned_spin);
    pl_scene_observe_t *o = &c->observe; /* no observer: the run only steps */
    o->rdf_interval = o->sq_interval = o->msd_interval = o->vacf_interval = o->cff_interval = 0;
    o->clusters_interval = o->vdist_interval = o->sediment_interval = o->stress_interval = 0;
    snprintf(c->stop.observable, sizeof c->stop.observable, "none");
}

/* FNV-1a over the parts of the calibration scene that set its bits. */
static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

static uint64_t cal_key(const pl_scene_t *c, const cal_plan_t *p)
{
    uint64_t h = 1469598103934665603ull;
    const int v = PL_CALCACHE_VERSION;
    h = fnv(h, &v, sizeof v);
    h = fnv(h, p, sizeof *p);
    h = fnv(h, &c->fluid, sizeof c->fluid);
    /* srd.sort_interval (the last member) left out: a calibration runs a
     * coupling, which refuses any value but 1, and the keys of the shipped
     * calibrations stay those written before the key existed */
    h = fnv(h, &c->srd, offsetof(pl_scene_srd_t, sort_interval));
    h = fnv(h, &c->thermostat, sizeof c->thermostat);
    /* coupling.pinned_spin (the last member) left out: a calibration holds
     * nothing (it is zeroed above), and the shipped keys stay as written */
    h = fnv(h, &c->coupling, offsetof(pl_scene_coupling_t, pinned_spin));
    const pl_scene_colloids_t *k = &c->colloids;
    const double cd[] = {k->radius, k->mass_density, k->temperature, k->max_overlap, k->neighbor_skin};
    h = fnv(h, cd, sizeof cd);
    if (c->coupling.method == PL_COUPLE_HECHT1) h = fnv(h, &CAL_VERSION_I, sizeof CAL_VERSION_I);
    if (c->coupling.method == PL_COUPLE_POTENTIAL || c->coupling.method == PL_COUPLE_HECHT1) {
        /* what coupling II leaves at its defaults */
        const double pd[] = {(double)k->substeps, k->wca.epsilon, k->wca.sigma, k->wca.n, (double)k->wca.sigma_rule,
                             (double)k->init, k->min_contact_steps};
        h = fnv(h, pd, sizeof pd);
        h = fnv(h, k->pairs, strlen(k->pairs));
    }
    return h;
}

static int cal_plan(const pl_scene_t *sc, cal_plan_t *p)
{
    const pl_mapping_t *m = &sc->mapping.map;
    const double sigma = sc->colloids.radius, M = m->mass_sim, dt = sc->srd.dt;
    /* the theory's D sizes the run; coupling II colloids move ~2x faster */
    const double tau_v = M * 2.0 * m->d_col_theory;
    const int two = sc->coupling.method == PL_COUPLE_HECHT2;
    const int finite = sc->coupling.method == PL_COUPLE_POTENTIAL || sc->coupling.method == PL_COUPLE_HECHT1;
    p->L = (int)fmax(16.0, ceil(8.0 * sigma));
    p->n = two ? CAL_N2 : CAL_NP;
    if (finite) /* phi <= CAL_PHI_P: the concentration correction stays small */
        p->L = (int)fmax(p->L, ceil(cbrt(CAL_NP * 4.0 / 3.0 * PL_PI * sigma * sigma * sigma / CAL_PHI_P)));
    p->stride = (long long)fmax(1.0, floor(tau_v / dt / 2.0));
    const double sdt = (double)p->stride * dt;
    p->lag1 = (long long)ceil(4.0 * tau_v / sdt);
    p->lag2 = (long long)ceil(12.0 * tau_v / sdt);
    if (p->lag2 < p->lag1 + 2) p->lag2 = p->lag1 + 2;
    /* each block holds 5 times the longest lag; the colloid-time the target asks */
    const double per_box = (double)p->L * p->L * p->L * sc->fluid.density;
    double strides = fmax(5.0 * CAL_BLOCKS * (double)p->lag2, CAL_TARGET * tau_v / (p->n * sdt));
    const double replicas = 1.0; /* one box (the field is hashed: the keys keep it) */
    double cost = per_box * strides * (double)p->stride;
    const double budget = finite ? CAL_BUDGET_P : CAL_BUDGET;
    if (cost > budget) /* within the budget; the SE says what it bought */
        strides = fmax(5.0 * CAL_BLOCKS * (double)p->lag2, strides * budget / cost);
    p->replicas = (int)replicas;
    p->steps = (long long)ceil(strides) * p->stride;
    return M > 0 && tau_v > 0 ? 0 : -1;
}

/* What the person waiting is told (NULL pg: nothing): the estimated
 * duration once the first `probe` steps (or CAL_PROBE_S) are timed, then
 * progress over all `total` steps of the replicas.  The first step (memory
 * first touched, threads started) is left out of the rate: the estimate is
 * the time so far plus the remaining steps at the rate of steps 2..probe. */
typedef struct {
    pl_progress_t *pg;
    double t_start, t_first;
    long long total, probe;
    int estimated;
} cal_watch_t;

static void cal_tick(cal_watch_t *w, long long step)
{
    if (!w->pg) return;
    if (w->estimated) {
        pl_progress_update(w->pg, step);
        return;
    }
    const double now = omp_get_wtime(), el = now - w->t_start;
    if (step == 1) w->t_first = now;
    if ((step < w->probe && el < CAL_PROBE_S) || step < 2) return;
    const double est = el + (now - w->t_first) / (double)(step - 1) * (double)(w->total - step);
    char min[32] = "";
    if (est >= 90.0) snprintf(min, sizeof min, " (%.1f min)", est / 60.0);
    w->estimated = 1;
    pl_progress_note(w->pg, "calibration: the first %lld of %lld steps took %.3g s: estimated duration %.3g s%s "
                     "(their rate extrapolated)", step, w->total, el, est, min);
}

/* Per replica: block means of the slope estimate, over colloids and origins. */
static int cal_replica(const pl_scene_t *sc, const cal_plan_t *p, int replica, int nthreads, cal_watch_t *w,
                       double *blocks, pl_err_t *err)
{
    pl_scene_t *c = malloc(sizeof *c);
    if (!c) return pl_err_set(err, PL_ERR_NOMEM, "out of memory (calibration scene)");
    cal_scene(sc, p, replica, c);
    pl_sim_t *sim = NULL;
    int rc = pl_sim_create(c, nthreads, &sim, err);
    free(c);
    if (rc) return rc;
    const long long nrec = p->steps / p->stride + 1;
    const size_t n = (size_t)p->n;
    double *r = malloc((size_t)nrec * n * 3 * sizeof *r);
    if (!r) {
        pl_sim_free(sim);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory (calibration positions)");
    }
    for (long long k = 0; k < nrec && !rc; ++k) {
        if (k > 0)
            for (long long s = 0; s < p->stride && !rc; ++s) {
                rc = pl_sim_step(sim, err);
                cal_tick(w, replica * p->steps + (k - 1) * p->stride + s + 1);
            }
        const pl_colloid_t *col = sim->colloids;
        for (size_t i = 0; i < n; ++i) {
            double *q = r + ((size_t)k * n + i) * 3;
            q[0] = col->x[i] + col->ix[i] * col->box[0];
            q[1] = col->y[i] + col->iy[i] * col->box[1];
            q[2] = col->z[i] + col->iz[i] * col->box[2];
        }
    }
    pl_sim_free(sim);
    if (rc) {
        free(r);
        return rc;
    }
    /* origins k in block b: [b, b + 1) * nrec / blocks, with k + lag2 < nrec */
    const long long last = nrec - 1 - p->lag2;
    const double dl = (double)(p->lag2 - p->lag1) * (double)p->stride * sc->srd.dt;
    for (int b = 0; b < CAL_BLOCKS; ++b) {
        long long k0 = (last + 1) * b / CAL_BLOCKS, k1 = (last + 1) * (b + 1) / CAL_BLOCKS;
        double sum = 0.0;
        for (long long k = k0; k < k1; ++k)
            for (size_t i = 0; i < n; ++i) {
                const double *a = r + ((size_t)k * n + i) * 3, *b1 = r + ((size_t)(k + p->lag1) * n + i) * 3,
                             *b2 = r + ((size_t)(k + p->lag2) * n + i) * 3;
                double s1 = 0.0, s2 = 0.0;
                for (int d = 0; d < 3; ++d) {
                    s1 += (b1[d] - a[d]) * (b1[d] - a[d]);
                    s2 += (b2[d] - a[d]) * (b2[d] - a[d]);
                }
                sum += (s2 - s1) / (6.0 * dl);
            }
        blocks[b] = sum / (double)((k1 - k0) * (long long)n);
    }
    free(r);
    return 0;
}

/* What an entry of this parameter set must hold: cal_run's plan and derived numbers. */
static void cal_expect(const pl_scene_t *sc, const cal_plan_t *p, pl_calcache_expect_t *e)
{
    const double L = p->L, sdt = (double)p->stride * sc->srd.dt;
    pl_srd_theory_t th;
    pl_srd_theory_of(sc, &th);
    e->kT = pl_scene_kT(sc);
    e->d_theory = sc->mapping.map.d_col_theory;
    e->hasimoto = e->kT * pl_srd_hasimoto_mobility(th.eta, L);
    e->nu = th.nu;
    e->rho = sc->fluid.density; /* m_f = 1 */
    e->t1 = (double)p->lag1 * sdt;
    e->t2 = (double)p->lag2 * sdt;
    e->phi = p->n * 4.0 / 3.0 * PL_PI * pow(sc->colloids.radius, 3) / (L * L * L);
    e->concentration = 1.0 - pl_mapping_concentration_c(sc) * e->phi;
    e->box = p->L;
    e->n_colloids = p->n * p->replicas;
    e->steps = p->steps;
}

static int cal_run(const pl_scene_t *sc, const cal_plan_t *p, int nthreads, const pl_progress_params_t *pp,
                   pl_mapping_calibration_t *cal, pl_err_t *err)
{
    const int nb = p->replicas * CAL_BLOCKS;
    double *blk = malloc((size_t)nb * sizeof *blk);
    if (!blk) return pl_err_set(err, PL_ERR_NOMEM, "out of memory (calibration)");
    const double t0 = omp_get_wtime();
    const double probe = fmax(CAL_PROBE_MIN, ceil(CAL_PROBE_FRACTION * (double)pp->last));
    cal_watch_t w = {.pg = pp->out ? pl_progress_create(pp) : NULL, .t_start = t0, .t_first = t0,
                     .total = pp->last, .probe = (long long)fmin((double)pp->last, probe), .estimated = 0};
    int rc = 0;
    for (int q = 0; q < p->replicas && !rc; ++q) rc = cal_replica(sc, p, q, nthreads, &w, blk + q * CAL_BLOCKS, err);
    if (!rc) pl_progress_finish(w.pg, pp->last);
    pl_progress_free(w.pg);
    if (rc) {
        free(blk);
        return rc;
    }
    double mean = 0.0, var = 0.0;
    for (int b = 0; b < nb; ++b) mean += blk[b];
    mean /= nb;
    for (int b = 0; b < nb; ++b) var += (blk[b] - mean) * (blk[b] - mean);
    free(blk);
    pl_calcache_expect_t e;
    cal_expect(sc, p, &e);
    const double kT = e.kT;
    cal->d_box = mean;
    cal->d_box_se = sqrt(var / (nb - 1.0) / nb);
    cal->hasimoto = e.hasimoto;
    cal->tail = pl_calcache_tail(&e, mean);
    cal->phi = e.phi;
    /* finite colloids slow each other: D_box + H = D (1 - c phi) (PL Sec. VI.C); coupling II's points: 1 */
    cal->concentration = e.concentration;
    /* a0^2/t0 at kT = 1, as the mapping uses it */
    cal->d_inf = (mean + cal->tail + cal->hasimoto) / cal->concentration / kT;
    cal->d_inf_se = cal->d_box_se / cal->concentration / kT;
    cal->n_colloids = p->n * p->replicas;
    cal->box = p->L;
    cal->steps = p->steps;
    cal->wall_s = omp_get_wtime() - t0;
    if (!(isfinite(cal->d_inf) && cal->d_inf > 0))
        return pl_err_set(err, PL_ERR_GUARD, "calibration: the measured colloid D is %g a0^2/t0 (not positive)",
                          cal->d_inf);
    return 0;
}

/* ---- the cache (src/app/calibration_cache.c) ---------------------------- */

/* The entry at path into *cal when it passes the checks (cal->cache names
 * it, this run paid nothing); else the reader's result, with why. */
static int from_cache(const char *path, const pl_calcache_expect_t *e, int source, pl_mapping_calibration_t *cal,
                      char *why, size_t nwhy)
{
    const int st = pl_calcache_read(path, e, cal, why, nwhy);
    if (st != PL_CALCACHE_OK) return st;
    snprintf(cal->cache, sizeof cal->cache, "%s", path);
    cal->wall_s = 0.0;
    cal->d_theory = e->d_theory;
    cal->source = source;
    return st;
}

/* ---- the entry point -------------------------------------------------------- */

static const char *cname(const pl_scene_t *sc) { return pl_couple_physical_name(sc->coupling.method); }

int pl_calibration_needed(const pl_scene_t *sc)
{
    const int m = sc->coupling.method;
    return sc->mapping.enabled && (m == PL_COUPLE_HECHT1 || m == PL_COUPLE_HECHT2 || m == PL_COUPLE_POTENTIAL) &&
           sc->colloids.count > 0 &&
           sc->fluid.density > 0;
}

/* The calibration run of plan p (c: its scene), with the line that opens it
 * and the progress that follows on o->log; stored at path when store. */
static int measure(const pl_scene_t *sc, const pl_scene_t *c, const cal_plan_t *p, int nthreads,
                   const pl_calibrate_opts_t *o, const char *where, pl_mapping_calibration_t *cal, pl_err_t *err)
{
    const double fluid_n = (double)p->L * p->L * p->L * sc->fluid.density;
    const double md = (double)c->colloids.substeps;
    if (o->log)
        fprintf(o->log, "peloid: calibrating the colloid diffusion of coupling %s at this resolution (%s; cached "
                        "in %s): %d x %d colloid(s) in %d^3 cells, %.4g fluid particles, %d MD step(s) per step, "
                        "%lld steps; timing the first steps for an estimate of the duration\n",
                cname(sc), o->mode == PL_CALIBRATE_ALWAYS ? "--calibrate always" : "once", where, p->replicas, p->n,
                p->L, fluid_n, (int)md, (long long)p->replicas * p->steps);
    const double every = sc->output.progress_s > 0 ? fmin(sc->output.progress_s, CAL_PROGRESS_S) : CAL_PROGRESS_S;
    const pl_progress_params_t pp = {.out = o->log, .terminal = o->terminal,
                                     .interval_s = o->progress_s > 0 ? o->progress_s : every, .first = 0,
                                     .last = (long long)p->replicas * p->steps, .dt = sc->srd.dt, .t0_s = 0.0,
                                     .fluid_n = fluid_n, .md_per_step = md, .label = "calibration"};
    return cal_run(sc, p, nthreads, &pp, cal, err);
}

int pl_calibrate(const pl_scene_t *sc, const char *shipped_dir, int nthreads, const pl_calibrate_opts_t *o,
                 pl_mapping_calibration_t *cal, pl_err_t *err)
{
    memset(cal, 0, sizeof *cal);
    FILE *log = o->log;
    const int fresh = o->mode == PL_CALIBRATE_ALWAYS; /* nothing stored is read */
    double timeout;
    int rc = pl_calcache_lock_timeout(&timeout, err);
    if (rc) return rc;
    cal_plan_t p;
    memset(&p, 0, sizeof p); /* hashed: no padding left undefined */
    if (cal_plan(sc, &p)) return pl_err_set(err, PL_ERR_INPUT, "calibration: the colloid has no mass or friction");
    pl_scene_t *c = malloc(sizeof *c);
    if (!c) return pl_err_set(err, PL_ERR_NOMEM, "out of memory (calibration)");
    cal_scene(sc, &p, 0, c);
    const uint64_t key = cal_key(c, &p);
    pl_calcache_expect_t e;
    cal_expect(sc, &p, &e);
    cal->d_theory = e.d_theory;
    char name[64], path[600], why[600];
    snprintf(name, sizeof name, "calibration-%016llx.json", (unsigned long long)key);
    const char *no_shipped = getenv("PELOID_NO_SHIPPED_CALIBRATION"); /* make calibrations, tests */
    if (shipped_dir && !fresh && !(no_shipped && *no_shipped)) { /* the project's read-only set: a bad entry is a bug */
        pl_path_join(path, sizeof path, shipped_dir, name);
        const int st = from_cache(path, &e, PL_CALSRC_SHIPPED, cal, why, sizeof why);
        if (st == PL_CALCACHE_BAD)
            rc = pl_err_set(err, PL_ERR_INTERNAL, "%s: %s: a corrupt shipped calibration (a bug: `make calibrations` "
                            "remeasures it; PELOID_NO_SHIPPED_CALIBRATION=1 skips the shipped set)", path, why);
        if (st == PL_CALCACHE_OK || rc) {
            free(c);
            cal->mode = o->mode;
            return rc;
        }
    }
    /* The user's cache: a folder that cannot take the result, a bad entry or a
     * lock that is not released cost this run a calibration, never the run. */
    char dir[512];
    pl_calcache_dir(dir, sizeof dir);
    pl_path_join(path, sizeof path, dir, name);
    /* stored and auto: the user's measurement first, then the shipped
     * resolution table (not with PELOID_NO_SHIPPED_CALIBRATION, which asks
     * for measurements), then stored gives up (theory) and auto measures */
    if (o->mode == PL_CALIBRATE_STORED || o->mode == PL_CALIBRATE_AUTO) {
        int found = from_cache(path, &e, PL_CALSRC_CACHE, cal, why, sizeof why) == PL_CALCACHE_OK;
        if (!found && !(no_shipped && *no_shipped) && pl_calibration_table(sc, shipped_dir, cal)) {
            cal->d_theory = e.d_theory; /* as from_cache sets it */
            found = 1;
        }
        if (found || o->mode == PL_CALIBRATE_STORED) {
            if (!found) memset(cal, 0, sizeof *cal); /* source NONE: the caller takes the theory */
            free(c);
            cal->mode = o->mode;
            return 0;
        }
    }
    int lock = -1, store = 0, st = PL_CALCACHE_ABSENT, done = 0;
    if (pl_calcache_dir_prepare(dir, why, sizeof why)) {
        if (log)
            fprintf(log, "peloid: warning: calibration cache %s: %s: this run calibrates without storing the result "
                         "(set PELOID_CACHE to a writable folder to keep it)\n", dir, why);
    } else if (!fresh && (st = from_cache(path, &e, PL_CALSRC_CACHE, cal, why, sizeof why)) == PL_CALCACHE_OK) {
        done = 1; /* entries appear whole */
    } else {
        char lwhy[800];
        const int lr = pl_calcache_lock(path, timeout, log, &lock, lwhy, sizeof lwhy);
        if (lr == PL_CALCACHE_LOCKED) { /* another process may have measured it meanwhile */
            if (!fresh && (st = from_cache(path, &e, PL_CALSRC_CACHE, cal, why, sizeof why)) == PL_CALCACHE_OK)
                done = 1;
            store = !done;
        } else if (log) {
            fprintf(log, "peloid: warning: calibration cache lock %s.lock: %s: this run calibrates without storing the "
                         "result\n", path, lwhy);
        }
    }
    if (!done && st == PL_CALCACHE_BAD && log)
        fprintf(log, "peloid: warning: calibration cache entry %s: %s: recalibrating%s\n", path, why,
                store ? " and overwriting it" : "");
    if (!done) {
        rc = measure(sc, c, &p, nthreads, o, store ? dir : "nowhere: see the warning above", cal, err);
        cal->d_theory = e.d_theory;
        cal->source = PL_CALSRC_RUN;
    }
    free(c);
    if (!done && !rc && store) {
        char about[400];
        snprintf(about, sizeof about,
                 "peloid coupling-%s calibration: gamma %g, lambda %g, rule %d, alpha %g, radius %.17g a0, mass "
                 "density %.17g m_f/a0^3; D in a0^2/t0 at kT = 1 (src/app/calibrate.c)",
                 cname(sc), sc->fluid.density, sc->srd.dt, sc->srd.rule,
                 sc->srd.alpha_deg, sc->colloids.radius, sc->colloids.mass_density);
        if (pl_calcache_write(path, cal, about, why, sizeof why) == 0)
            snprintf(cal->cache, sizeof cal->cache, "%s", path);
        else if (log)
            fprintf(log, "peloid: warning: calibration cache %s: cannot store the calibration: %s: used for this run "
                         "only (set PELOID_CACHE to a writable folder to keep it)\n", dir, why);
    }
    pl_calcache_unlock(lock);
    cal->mode = o->mode;
    return rc;
}
