/* The stress observer (section observe{}, keys stress_*; DESIGN.md
 * "Observables and their errors"): the SRD fluid's momentum-flux tensor and
 * its shear viscosity by Green-Kubo, each with its standard error.
 *
 * Momentum flux, Helfand form.  With G_ab = sum_i m v_ia r_ib (r unwrapped),
 * one SRD step changes G by
 *
 *   g_ab = dt sum_i m v_ia v_ib                 streaming (kinetic part)
 *        + sum_i m dv_ia rho_ib                 collision (collisional part)
 *
 * where dv is the velocity change of the collision (and of a thermostat or a
 * constraint acting at fixed positions) and rho the position relative to the
 * centre of the particle's collision cell: cells conserve momentum, so any
 * origin inside a cell gives the same sum and the cell centre keeps it
 * independent of periodic images.  These are the kinetic and collisional
 * stresses of PL Eqs. 13-15 (Kikuchi et al., J. Chem. Phys. 119, 6388
 * (2003); Ihle, Tuezel & Kroll, Phys. Rev. E 72, 046707 (2005)).  The
 * velocities are relative to the box's mean (a Galilean invariant).  The
 * pressure tensor of a step is P_ab = g_ab / (V dt).
 *
 * Viscosity.  The Einstein-Helfand relation eta = lim <(G(t) - G(0))^2> /
 * (2 V kT t) for the sequence of steps is the discrete Green-Kubo sum
 *
 *   eta = (V dt / kT) [ C(0) / 2 + sum_{k>=1} C(k) ],   C(k) = <P_ab(n) P_ab(n+k)>
 *       = 1 / (2 V kT dt) < g(n) [ g(n) + 2 sum_{k=1..K} g(n-k) ] >
 *
 * (the trapezoidal end term is exact here, it is what makes the kinetic part
 * come out as PL Eq. 9's "- 1/2").  The per-step estimator in brackets,
 * averaged over the six off-diagonal (a, b), is a stationary time series
 * whose mean is eta truncated at K = observe.stress_gk_steps lags (default:
 * ten kinetic relaxation times, gk_lags); its SE
 * comes from blocking (peloid/blocking.h).  The running sum against the
 * truncation lag is written too (observables.h5 fluid_viscosity_gk), so that
 * its plateau can be checked.  Ideal-gas SRD has P = n kT exactly; the mean
 * pressure is reported with its SE as a check.
 *
 * Scope of Green-Kubo: the pure fluid in a periodic box.  A suspension's
 * stress needs the colloid virial and the coupling's momentum exchange,
 * which this observer does not build: refused at scene check.
 *
 * Couette (walls_z = noslip with different wall velocities, walls_xy none):
 * the viscosity from the wall stress instead (PL Eq. 13; the walls' impulse
 * on fluid and colloids, sim->wall_impulse), sigma = (dp_top - dp_bottom) /
 * (2 A dt) per step along the walls' relative velocity e, over the shear
 * rate measured from the fluid's velocity profile: the least-squares slope
 * of the layer means of v . e over the layers not touching a wall, sampled
 * every stress_interval steps.  eta = <sigma> / <slope>, SE propagated from
 * the two blocking SEs (their covariance neglected; the stress and the
 * profile's slope fluctuate nearly independently); the apparent viscosity
 * over the nominal rate |du| / Lz is reported too (what a rheometer
 * reports: it includes the walls' slip).  The layer profiles of velocity
 * and density are written at every sample.  With colloids this is the
 * suspension's viscosity.  Other walls are refused.
 *
 * Off (interval 0) it adds no stage and costs nothing; on, Green-Kubo adds
 * two passes over the fluid per step (before and after the collision),
 * Couette one pass per sample. */
#include <hdf5.h>
#include <jansson.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "json_build.h"
#include "stress_priv.h"
#include "observables_out.h"
#include "observables_si.h"
#include "peloid/blocking.h"
#include "checkpoint_h5.h"
#include "peloid/checkpoint.h"
#include "peloid/h5.h"
#include "peloid/io.h"
#include "peloid/module.h"
#include "peloid/real.h"
#include "peloid/srd_kernels.h"
#include "peloid/srd_theory.h"

/* the off-diagonal (a, b): a-momentum carried along b */
static const int off_a[NOFF] = {0, 0, 1, 1, 2, 2}, off_b[NOFF] = {1, 2, 0, 2, 0, 1};
static const int kin_index[3][3] = {{3, 6, 7}, {6, 4, 8}, {7, 8, 5}}; /* into the kernel's sums */

static void stress_begin(pl_stress_t *o, const pl_sim_t *sim, double t0);


/* ---- scene checks ------------------------------------------------------ */

#define OFFO(m) offsetof(pl_scene_t, observe.m)

/* No-slip z walls moving relative to each other, periodic in x and y. */
static int is_couette(const pl_scene_t *sc)
{
    const double *b = sc->box.wall_velocity[0], *t = sc->box.wall_velocity[1];
    return sc->box.walls_z == PL_WALLS_NOSLIP && sc->box.walls_xy == PL_WALLS_NONE &&
           (t[0] != b[0] || t[1] != b[1]);
}

static int gk_lags(const pl_scene_t *sc);

int pl_stress_validate_scene(const pl_scene_t *sc, pl_err_t *err)
{
    const long long s = sc->observe.stress_interval;
    if (s <= 0) return 0;
    if (is_couette(sc)) {
        if (sc->box.cells[2] < 4)
            return pl_scene_fail(sc, err, OFFO(stress_interval), "observe.stress_interval",
                                 "%lld with %d layers between the walls: the shear rate's fit needs >= 2 "
                                 "layers not touching a wall; allowed: box.cells[2] >= 4", s, sc->box.cells[2]);
    } else if (sc->box.walls_z != PL_WALLS_NONE || sc->box.walls_xy != PL_WALLS_NONE) {
        return pl_scene_fail(sc, err, OFFO(stress_interval), "observe.stress_interval",
                             "%lld with walls that shear nothing: Green-Kubo needs a periodic box, the wall "
                             "stress a Couette cell; allowed: 0, or walls_z = \"noslip\" with different "
                             "wall velocities and no x/y walls", s);
    } else if (sc->colloids.count > 0) {
        return pl_scene_fail(sc, err, OFFO(stress_interval), "observe.stress_interval",
                             "%lld with colloids in a periodic box: Green-Kubo here sums the SRD fluid's "
                             "stress only; a suspension's needs the colloid virial and the coupling's "
                             "momentum exchange, which it does not include; allowed: 0 with colloids, or a "
                             "Couette cell (walls_z = \"noslip\", different wall velocities)", s);
    }
    if (sc->fluid.density <= 0)
        return pl_scene_fail(sc, err, OFFO(stress_interval), "observe.stress_interval",
                             "%lld without fluid; allowed: 0 without fluid", s);
    const long long start = sc->observe.stress_start, last = sc->run.steps;
    if (start > last)
        return pl_scene_fail(sc, err, OFFO(stress_start), "observe.stress_start",
                             "%lld is after the run's last step %lld: the stress observer would accumulate "
                             "nothing; allowed: a start <= %lld", start, last, last);
    if (!is_couette(sc)) {
        /* Green-Kubo: the sum over K lags needs a window several times K long
         * to average the lag products; with fewer steps than lags it is absent */
        const long long lags = gk_lags(sc);
        if (last - start <= lags)
            return pl_scene_fail(sc, err, sc->observe.stress_gk_steps > 0 ? OFFO(stress_gk_steps) : OFFO(stress_start),
                                 sc->observe.stress_gk_steps > 0 ? "observe.stress_gk_steps" : "observe.stress_start",
                                 "the Green-Kubo sum over %lld lags needs more than %lld steps after "
                                 "observe.stress_start = %lld; the run ends at step %lld; allowed: fewer lags "
                                 "(observe.stress_gk_steps), an earlier start, or a longer run (steps)",
                                 lags, lags, start, last);
    }
    return 0;
}

/* ---- lifetime ---------------------------------------------------------- */

/* observe.stress_gk_steps, or ten kinetic relaxation times: the kinetic
 * stress of SRD decays by a factor f per step, and PL Eq. 9 reads
 * nu_kin = (kT dt / 2m) (2 / (1 - f) - 1). */
static int gk_lags(const pl_scene_t *sc)
{
    if (sc->observe.stress_gk_steps > 0) return (int)sc->observe.stress_gk_steps;
    pl_srd_theory_t th;
    const double kT = pl_scene_kT(sc);
    pl_srd_theory_of(sc, &th);
    const double tau = 0.5 * (2.0 * th.nu_kin / (kT * sc->srd.dt) + 1.0);
    const double k = ceil(10.0 * tau);
    return k < 10 ? 10 : k > 1e5 ? 100000 : (int)k;
}

static int stress_create(pl_sim_t *sim, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    if (sc->observe.stress_interval <= 0) return 0;
    pl_stress_t *o = calloc(1, sizeof *o);
    if (!o) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the stress observer");
    o->K = gk_lags(sc);
    o->V = (double)sim->grid.L[0] * sim->grid.L[1] * sim->grid.L[2];
    o->kT = pl_scene_kT(sc);
    o->dt = sc->srd.dt;
    o->N = (double)sim->fluid.n;
    o->couette = is_couette(sc);
    o->nlayers = o->couette ? sim->grid.L[2] : 0; /* Couette layers (0: Green-Kubo; checkpointed) */
    o->scratch = malloc((o->couette ? pl_srd_layer_scratch(sim->fluid.n, o->nlayers)
                                    : pl_srd_stress_scratch(sim->fluid.n)) * sizeof(double));
    o->ring = calloc((size_t)o->K * NOFF, sizeof(double));
    o->cacc = calloc((size_t)o->K + 1, sizeof(double));
    if (!o->scratch || !o->ring || !o->cacc) {
        free(o->scratch);
        free(o->ring);
        free(o->cacc);
        free(o);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the stress observer");
    }
    o->resume_step = -1;
    pl_blocking_init(&o->eta);
    pl_blocking_init(&o->pressure);
    pl_blocking_init(&o->sigma);
    pl_blocking_init(&o->rate);
    pl_module_set_state(sim, &pl_stress_module, o);
    if (!o->couette) return 0;
    const double *ub = sc->box.wall_velocity[0], *ut = sc->box.wall_velocity[1];
    o->du = hypot(ut[0] - ub[0], ut[1] - ub[1]);
    o->e[0] = (ut[0] - ub[0]) / o->du;
    o->e[1] = (ut[1] - ub[1]) / o->du;
    o->A = (double)sim->grid.L[0] * sim->grid.L[1];
    o->lay_sum = malloc(2 * (size_t)o->nlayers * sizeof(double));
    o->lay_cnt = o->lay_sum ? o->lay_sum + o->nlayers : NULL;
    if (!o->lay_sum) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the stress observer");
    return 0;
}

static void stress_destroy(pl_sim_t *sim)
{
    pl_stress_t *o = pl_stress_of(sim);
    if (!o) return;
    free(o->scratch);
    free(o->ring);
    free(o->cacc);
    free(o->ts_step);
    free(o->ts_val);
    free(o->lay_sum);
    free(o->ts_sigma);
    free(o->ts_rate);
    free(o->ts_prof);
    free(o);
    pl_module_set_state(sim, &pl_stress_module, NULL);
}


/* ---- stages ------------------------------------------------------------ */

/* Before the collision: the velocities the fluid streamed with, and the
 * collisional sums' "before". */
static int stage_pre(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    pl_stress_t *o = ctx;
    const double t0 = omp_get_wtime();
    if (sim->step + 1 >= sim->scene.observe.stress_start) { /* the step being done is sim->step + 1 */
        pl_srd_stress_sums(&sim->fluid, sim->grid.shift, o->scratch, o->pre, sim->nthreads);
        o->have_pre = 1;
    }
    o->wall += omp_get_wtime() - t0;
    return 0;
}

/* After the step (collision, thermostat, constraints done): g of the step. */
static int stage_post(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    pl_stress_t *o = ctx;
    if (!o->have_pre) return 0;
    const double t0 = omp_get_wtime();
    if (!o->begun) stress_begin(o, sim, t0);
    double post[PL_STRESS_NSUMS];
    pl_srd_stress_sums(&sim->fluid, sim->grid.shift, o->scratch, post, sim->nthreads);
    o->have_pre = 0;
    double g[3][3];
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
            const double kin = o->pre[kin_index[a][b]] - o->pre[a] * o->pre[b] / o->N;
            g[a][b] = o->dt * kin + (post[9 + 3 * a + b] - o->pre[9 + 3 * a + b]);
            if (!isfinite(g[a][b]))
                return pl_err_set(err, PL_ERR_GUARD, "step %lld: the fluid stress is not finite", sim->step);
        }
    /* Green-Kubo: per-step estimator and the correlation per lag */
    double gk = 0.0;
    const int full = o->ring_n >= o->K;
    for (int c = 0; c < NOFF; ++c) {
        const double x = g[off_a[c]][off_b[c]];
        double past = 0.0;
        o->cacc[0] += full ? x * x : 0.0;
        for (int k = 1; k <= o->K; ++k) {
            const int slot = (o->ring_head - (k - 1) + o->K) % o->K;
            const double y = o->ring[(size_t)slot * NOFF + (size_t)c];
            past += y;
            if (full) o->cacc[k] += x * y;
        }
        gk += x * (x + 2.0 * past);
    }
    if (full) {
        o->ncorr++;
        pl_blocking_add(&o->eta, gk / (NOFF * 2.0 * o->V * o->kT * o->dt));
    }
    o->ring_head = (o->ring_head + 1) % o->K;
    for (int c = 0; c < NOFF; ++c) o->ring[(size_t)o->ring_head * NOFF + (size_t)c] = g[off_a[c]][off_b[c]];
    o->ring_n++;
    /* pressure and the tensor's time series */
    const double scale = 1.0 / (o->V * o->dt);
    pl_blocking_add(&o->pressure, (g[0][0] + g[1][1] + g[2][2]) * scale / 3.0);
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) o->win[3 * a + b] += g[a][b] * scale;
    o->win_n++;
    if (sim->step % sim->scene.observe.stress_interval == 0) {
        if (o->ts_n == o->ts_cap) {
            size_t cap = o->ts_cap ? 2 * o->ts_cap : 64;
            long long *s = realloc(o->ts_step, cap * sizeof *s);
            if (s) o->ts_step = s;
            double *v = realloc(o->ts_val, cap * 9 * sizeof *v);
            if (v) o->ts_val = v;
            if (!s || !v) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the stress time series");
            o->ts_cap = cap;
        }
        o->ts_step[o->ts_n] = sim->step;
        for (int k = 0; k < 9; ++k) o->ts_val[9 * o->ts_n + (size_t)k] = o->win[k] / (double)o->win_n;
        o->ts_n++;
        memset(o->win, 0, sizeof o->win);
        o->win_n = 0;
    }
    /* error against run time */
    while (o->next_frac < NFRAC) {
        const long long at = o->first + (long long)ceil(pl_obs_fractions[o->next_frac] * (double)(o->last - o->first));
        if (sim->step < at) break;
        pl_obs_point_t *e = &o->ept[o->next_frac++];
        e->step = sim->step;
        e->wall_s = omp_get_wtime() - o->t_start;
        e->valid = pl_stress_eta_estimate(o, &e->value, &e->se, NULL);
    }
    o->wall += omp_get_wtime() - t0;
    return 0;
}

/* The impulse the walls gave along e since step 0: bottom, top. */
static void wall_impulse_along(const pl_sim_t *sim, const double e[3], double out[2])
{
    for (int w = 0; w < 2; ++w) out[w] = e[0] * sim->wall_impulse[w][0] + e[1] * sim->wall_impulse[w][1];
}

/* Least-squares slope of the layer means over layers 1 .. n-2 (centres k + 1/2). */
static double profile_slope(const double *sum_v, const double *count, int n)
{
    double m = 0, sz = 0, sv = 0, szz = 0, szv = 0;
    for (int k = 1; k < n - 1; ++k) {
        if (count[k] <= 0) continue;
        const double z = k + 0.5, v = sum_v[k] / count[k];
        m += 1; sz += z; sv += v; szz += z * z; szv += z * v;
    }
    return m >= 2 ? (m * szv - sz * sv) / (m * szz - sz * sz) : NAN;
}

/* Couette: the wall stress of each step, the shear rate at samples. */
static int stage_couette(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    pl_stress_t *o = ctx;
    const double t0 = omp_get_wtime();
    double imp[2];
    wall_impulse_along(sim, o->e, imp);
    if (sim->step == o->resume_step && o->t_start != 0.0) { /* sampled before the checkpoint */
        stress_begin(o, sim, t0);
        return 0;
    }
    if (sim->step < sim->scene.observe.stress_start || o->t_start == 0.0) { /* the reference of the first step */
        if (sim->step >= sim->scene.observe.stress_start) stress_begin(o, sim, t0);
        o->imp_prev[0] = imp[0];
        o->imp_prev[1] = imp[1];
        return 0;
    }
    const double sig = ((imp[1] - o->imp_prev[1]) - (imp[0] - o->imp_prev[0])) / (2.0 * o->A * o->dt);
    o->imp_prev[0] = imp[0];
    o->imp_prev[1] = imp[1];
    if (!isfinite(sig))
        return pl_err_set(err, PL_ERR_GUARD, "step %lld: the wall shear stress is not finite", sim->step);
    pl_blocking_add(&o->sigma, sig);
    o->win[0] += sig;
    o->win_n++;
    if (sim->step % sim->scene.observe.stress_interval == 0) {
        pl_srd_layer_velocity(&sim->fluid, o->nlayers, o->e, o->scratch, o->lay_sum, o->lay_cnt, sim->nthreads);
        const double slope = profile_slope(o->lay_sum, o->lay_cnt, o->nlayers);
        if (!isfinite(slope))
            return pl_err_set(err, PL_ERR_GUARD, "step %lld: the shear rate of the velocity profile is not finite "
                              "(empty layers)", sim->step);
        pl_blocking_add(&o->rate, slope);
        if (o->ts_n == o->ts_cap) {
            size_t cap = o->ts_cap ? 2 * o->ts_cap : 64;
            long long *st = realloc(o->ts_step, cap * sizeof *st);
            if (st) o->ts_step = st;
            double *a = realloc(o->ts_sigma, cap * sizeof *a);
            if (a) o->ts_sigma = a;
            double *b = realloc(o->ts_rate, cap * sizeof *b);
            if (b) o->ts_rate = b;
            double *c = realloc(o->ts_prof, cap * 2 * (size_t)o->nlayers * sizeof *c);
            if (c) o->ts_prof = c;
            if (!st || !a || !b || !c) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the stress time series");
            o->ts_cap = cap;
        }
        o->ts_step[o->ts_n] = sim->step;
        o->ts_sigma[o->ts_n] = o->win[0] / (double)o->win_n;
        o->ts_rate[o->ts_n] = slope;
        double *pr = o->ts_prof + 2 * (size_t)o->nlayers * o->ts_n;
        for (int k = 0; k < o->nlayers; ++k) {
            pr[k] = o->lay_cnt[k] > 0 ? o->lay_sum[k] / o->lay_cnt[k] : 0.0;
            pr[o->nlayers + k] = o->lay_cnt[k] / o->A; /* particles per a0^3: layers are 1 a0 thick */
        }
        o->ts_n++;
        o->win[0] = 0.0;
        o->win_n = 0;
    }
    while (o->next_frac < NFRAC) {
        const long long at = o->first + (long long)ceil(pl_obs_fractions[o->next_frac] * (double)(o->last - o->first));
        if (sim->step < at) break;
        pl_obs_point_t *q = &o->ept[o->next_frac++];
        q->step = sim->step;
        q->wall_s = omp_get_wtime() - o->t_start;
        q->valid = pl_stress_couette_estimate(o, &q->value, &q->se, NULL, NULL);
    }
    o->wall += omp_get_wtime() - t0;
    return 0;
}

static int stress_stages(pl_sim_t *sim, pl_err_t *err)
{
    int rc;
    pl_stress_t *o = pl_stress_of(sim);
    if (!o) return 0;
    if (o->couette) {
        pl_stage_t c = {.name = "stress-couette", .fn = stage_couette, .ctx = o, .interval = 1,
                        .phase = PL_PHASE_AFTER, .slot = PL_SLOT_OBSERVE, .at_start = 1};
        if ((rc = pl_sim_add_stage(sim, &c, err))) return rc;
        return 0;
    }
    pl_stage_t pre = {.name = "stress-before-collision", .fn = stage_pre, .ctx = o, .interval = 1,
                      .phase = PL_PHASE_STEP, .slot = PL_SLOT_PRE_COLLIDE};
    if ((rc = pl_sim_add_stage(sim, &pre, err))) return rc;
    pl_stage_t post = {.name = "stress", .fn = stage_post, .ctx = o, .interval = 1, .phase = PL_PHASE_AFTER,
                       .slot = PL_SLOT_OBSERVE};
    if ((rc = pl_sim_add_stage(sim, &post, err))) return rc;
    return 0;
}

/* ---- checkpoint -------------------------------------------------------- */

/* The first sample of a run: the run's bounds and, after a restart, the
 * error-against-time points of the combined run o->first..o->last (the rule
 * of the observer module: a point the first run recorded at that step is
 * taken over, one it did not is left out). */
static void stress_begin(pl_stress_t *o, const pl_sim_t *sim, double t0)
{
    o->begun = 1;
    if (!o->have_first) {
        o->first = sim->first_step;
        o->have_first = 1;
    }
    o->last = sim->last_step;
    if (o->t_start == 0.0) o->t_start = t0;
    if (o->resume_step < 0) return;
    memset(o->ept, 0, sizeof o->ept);
    o->next_frac = NFRAC;
    for (int k = NFRAC - 1; k >= 0; --k) {
        const long long at = o->first + (long long)ceil(pl_obs_fractions[k] * (double)(o->last - o->first));
        if (at > o->resume_step) {
            o->next_frac = k;
            continue;
        }
        for (int j = 0; j < o->nept_saved; ++j)
            if (o->ept_saved[j].step == at) {
                o->ept[k] = o->ept_saved[j];
                break;
            }
    }
}

/* Group /stress (src/observe/checkpoint_observe.c gives it the observer
 * fingerprint): meta (int64, SCK_* below), reals (the output window, the
 * last wall impulse; no clock reading, as in /observe), the Green-Kubo ring and correlation sums,
 * the blocking accumulators, the error-against-time points, the time series. */
enum { SCK_FIRST, SCK_STARTED, SCK_NEXT_FRAC, SCK_RING_HEAD, SCK_RING_N, SCK_NCORR, SCK_WIN_N, SCK_TS_N, SCK_K,
       SCK_NLAYERS, SCK_COUETTE, SCK_STEP, SCK_N };

static int stress_ckpt_write(int64_t file, const pl_sim_t *sim)
{
    const pl_stress_t *o = pl_stress_of(sim);
    if (!o) return 0;
    hid_t g = pl_ckpt_observe_group_write((hid_t)file, "stress", &sim->scene);
    if (g < 0) return -1;
    const int started = o->t_start != 0.0;
    long long meta[SCK_N] = {o->have_first ? o->first : sim->first_step, started, o->next_frac, o->ring_head,
                             o->ring_n, (long long)o->ncorr, o->win_n, (long long)o->ts_n, o->K, o->nlayers,
                             o->couette, sim->step};
    double re[11];
    memcpy(re, o->win, sizeof o->win);
    re[9] = o->imp_prev[0];
    re[10] = o->imp_prev[1];
    pl_blocking_t bl[4] = {o->eta, o->pressure, o->sigma, o->rate};
    long long est[2 * NFRAC];
    double eval[2 * NFRAC];
    for (int k = 0; k < NFRAC; ++k) {
        est[2 * k] = o->ept[k].step;
        est[2 * k + 1] = o->ept[k].valid;
        eval[2 * k] = o->ept[k].value;
        eval[2 * k + 1] = o->ept[k].se;
    }
    int bad = pl_ckpt_write_1d(g, "meta", H5T_NATIVE_LLONG, meta, SCK_N);
    bad |= pl_ckpt_write_1d(g, "reals", H5T_NATIVE_DOUBLE, re, 11);
    bad |= pl_ckpt_write_1d(g, "ring", H5T_NATIVE_DOUBLE, o->ring, (size_t)o->K * NOFF);
    bad |= pl_ckpt_write_1d(g, "correlation", H5T_NATIVE_DOUBLE, o->cacc, (size_t)o->K + 1);
    bad |= pl_ckpt_write_1d(g, "blocking", H5T_NATIVE_UCHAR, bl, sizeof bl);
    bad |= pl_ckpt_write_1d(g, "ept_step", H5T_NATIVE_LLONG, est, 2 * NFRAC);
    bad |= pl_ckpt_write_1d(g, "ept_values", H5T_NATIVE_DOUBLE, eval, 2 * NFRAC);
    bad |= pl_ckpt_write_1d(g, "series_step", H5T_NATIVE_LLONG, o->ts_step, o->ts_n);
    if (!o->couette) {
        bad |= pl_ckpt_write_1d(g, "series_pressure", H5T_NATIVE_DOUBLE, o->ts_val, 9 * o->ts_n);
    } else {
        bad |= pl_ckpt_write_1d(g, "series_sigma", H5T_NATIVE_DOUBLE, o->ts_sigma, o->ts_n);
        bad |= pl_ckpt_write_1d(g, "series_rate", H5T_NATIVE_DOUBLE, o->ts_rate, o->ts_n);
        bad |= pl_ckpt_write_1d(g, "series_profiles", H5T_NATIVE_DOUBLE, o->ts_prof,
                                2 * (size_t)o->nlayers * o->ts_n);
    }
    if (H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
}

static int stress_ckpt_read_group(hid_t g, pl_sim_t *sim, pl_stress_t *o, const char *path, pl_err_t *err)
{
    long long m[SCK_N], est[2 * NFRAC];
    double re[11], eval[2 * NFRAC];
    pl_blocking_t bl[4];
    int rc = pl_ckpt_read_1d(g, "meta", H5T_NATIVE_LLONG, m, SCK_N, path, err);
    if (rc) return rc;
    const char *why = m[SCK_STEP] != sim->step ? "step differs from the checkpoint's"
                      : m[SCK_K] != o->K ? "Green-Kubo lags differ"
                      : m[SCK_COUETTE] != o->couette || m[SCK_NLAYERS] != o->nlayers ? "another geometry"
                      : m[SCK_FIRST] < 0 || m[SCK_FIRST] > sim->step ? "first step out of range"
                      : m[SCK_NEXT_FRAC] < 0 || m[SCK_NEXT_FRAC] > NFRAC ? "next_frac out of range"
                      : m[SCK_RING_HEAD] < 0 || m[SCK_RING_HEAD] >= o->K ? "ring head out of range"
                      : m[SCK_RING_N] < 0 || m[SCK_NCORR] < 0 || m[SCK_WIN_N] < 0 ? "negative count"
                      : m[SCK_TS_N] < 0 || m[SCK_TS_N] > sim->step + 1 ? "series length out of range"
                          : NULL;
    if (why) return pl_err_set(err, PL_ERR_INPUT, "%s: /stress/meta: %s (corrupt checkpoint)", path, why);
    const size_t n = (size_t)m[SCK_TS_N], cap = n > 64 ? n : 64;
    if ((rc = pl_ckpt_read_1d(g, "reals", H5T_NATIVE_DOUBLE, re, 11, path, err)) ||
        (rc = pl_ckpt_read_1d(g, "ring", H5T_NATIVE_DOUBLE, o->ring, (size_t)o->K * NOFF, path, err)) ||
        (rc = pl_ckpt_read_1d(g, "correlation", H5T_NATIVE_DOUBLE, o->cacc, (size_t)o->K + 1, path, err)) ||
        (rc = pl_ckpt_read_1d(g, "blocking", H5T_NATIVE_UCHAR, bl, sizeof bl, path, err)) ||
        (rc = pl_ckpt_read_1d(g, "ept_step", H5T_NATIVE_LLONG, est, 2 * NFRAC, path, err)) ||
        (rc = pl_ckpt_read_1d(g, "ept_values", H5T_NATIVE_DOUBLE, eval, 2 * NFRAC, path, err)))
        return rc;
    for (int k = 0; k < 4; ++k)
        if (bl[k].nlev < 0 || bl[k].nlev > PL_BLOCKING_LEVELS)
            return pl_err_set(err, PL_ERR_INPUT, "%s: /stress/blocking: a level count is out of range (corrupt "
                                                 "checkpoint)", path);
    o->ts_step = malloc(cap * sizeof *o->ts_step);
    if (!o->ts_step) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the stress time series");
    if ((rc = pl_ckpt_read_1d(g, "series_step", H5T_NATIVE_LLONG, o->ts_step, n, path, err))) return rc;
    if (!o->couette) {
        if (!(o->ts_val = malloc(cap * 9 * sizeof(double))))
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the stress time series");
        if ((rc = pl_ckpt_read_1d(g, "series_pressure", H5T_NATIVE_DOUBLE, o->ts_val, 9 * n, path, err))) return rc;
    } else {
        o->ts_sigma = malloc(cap * sizeof(double));
        o->ts_rate = malloc(cap * sizeof(double));
        o->ts_prof = malloc(cap * 2 * (size_t)o->nlayers * sizeof(double));
        if (!o->ts_sigma || !o->ts_rate || !o->ts_prof)
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the stress time series");
        if ((rc = pl_ckpt_read_1d(g, "series_sigma", H5T_NATIVE_DOUBLE, o->ts_sigma, n, path, err)) ||
            (rc = pl_ckpt_read_1d(g, "series_rate", H5T_NATIVE_DOUBLE, o->ts_rate, n, path, err)) ||
            (rc = pl_ckpt_read_1d(g, "series_profiles", H5T_NATIVE_DOUBLE, o->ts_prof, 2 * (size_t)o->nlayers * n,
                                  path, err)))
            return rc;
    }
    o->ts_n = n;
    o->ts_cap = cap;
    o->eta = bl[0], o->pressure = bl[1], o->sigma = bl[2], o->rate = bl[3];
    memcpy(o->win, re, sizeof o->win);
    o->imp_prev[0] = re[9];
    o->imp_prev[1] = re[10];
    if (m[SCK_STARTED]) o->t_start = omp_get_wtime(); /* no clock reading is checkpointed: wall_s counts from here */
    o->first = m[SCK_FIRST];
    o->have_first = 1;
    o->next_frac = (int)m[SCK_NEXT_FRAC];
    o->nept_saved = (int)m[SCK_NEXT_FRAC];
    for (int k = 0; k < NFRAC; ++k) {
        o->ept_saved[k] = (pl_obs_point_t){.step = est[2 * k], .valid = (int)est[2 * k + 1], .wall_s = 0.0,
                                         .value = eval[2 * k], .se = eval[2 * k + 1]};
        o->ept[k] = o->ept_saved[k];
    }
    o->ring_head = (int)m[SCK_RING_HEAD];
    o->ring_n = m[SCK_RING_N];
    o->ncorr = (uint64_t)m[SCK_NCORR];
    o->win_n = m[SCK_WIN_N];
    o->resume_step = sim->step;
    return 0;
}

static int stress_ckpt_read(int64_t file, pl_sim_t *sim, const char *path, pl_err_t *err)
{
    pl_stress_t *o = pl_stress_of(sim);
    if (!o) return 0;
    hid_t g = pl_ckpt_observe_group_open((hid_t)file, "stress", sim);
    if (g < 0) return 0;
    int rc = stress_ckpt_read_group(g, sim, o, path, err);
    H5Gclose(g);
    return rc;
}

const pl_module_t pl_stress_module = {
    .name = "stress",
    .validate_scene = pl_stress_validate_scene,
    .create = stress_create,
    .destroy = stress_destroy,
    .add_stages = stress_stages,
    .finish = pl_stress_finish,
    .checkpoint_write = stress_ckpt_write,
    .checkpoint_read = stress_ckpt_read,
};
