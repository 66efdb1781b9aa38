/* `peloid plan SCENE --target REL`: a guide to choosing the model for the
 * suspension of a physical scene, from what the mapping and the project's
 * measurements already know.
 *
 *  1. Coupling and resolution: each coupling at its default resolution (the
 *     scene with coarse_graining.coupling set, loaded with the theory's D)
 *     with its hydrodynamic radius R_h/R of a stick sphere (mapping_hydro.c:
 *     R_h = kT / (6 pi eta D)).  The theory's D is off by a factor the
 *     shipped calibrations measured (D_meas / D_theory, calibrate_mode.c);
 *     R_h is proportional to 1 / D, so the measured R_h/R is the theory's
 *     divided by that factor.  The scene's own coupling is shown as its
 *     mapping has it (calibrated when the scene was loaded so).  The
 *     recommendation is the coupling whose measured R_h/R is nearest 1:
 *     every many-body hydrodynamic effect (box correction, hindered
 *     settling, D(phi), lubrication) then has the stated sphere's strength.
 *     A resolution without a calibration costs one calibration run; the
 *     shipped ones' durations are their files' wall_s.  The matched
 *     resolution (R_h/R = 0.95) of coupling I follows from the law a
 *     resolution study measured for the scene's fluid (advise_match.c), its
 *     cost from that scene loaded at that cell size.
 *  2. Box: a periodic box slows D by 2.837 R_h / L (Hasimoto 1959, PL Eq.
 *     43); the edge that keeps that below the target is L >= 2.837 R_h /
 *     target.  Walls slow it further (not corrected).
 *  3. MD: the substeps the contact guard derives from the stiffness
 *     (hertz.K, coarse_graining.reach_energy, md_resolution).
 *  4. Run length: colloid_D is the MSD's slope fitted over lags [T/40, T/4]
 *     of the run T (src/observe/mtau_observers.c): the window grows with the
 *     run, so its relative SE does not fall with T but is ~C_D / sqrt(N) for
 *     N colloids once T/40 is past the velocity relaxation (T >= 400 tau_v,
 *     tau_v = M D / kT) and the colloids have moved their radius (T >= R^2 /
 *     D); a smaller SE takes replicas (`peloid run SCENE --replicas K`, SE /
 *     sqrt(K)) or more colloids.  C_D = 0.35 +- 0.06 (bench/RESULTS.md, "Plan
 *     cost model": the scatter of 16 replicas of 64 Brownian colloids).  The settling velocity's
 *     time average has SE sqrt(2 D / (N T)) (the integral of the velocity
 *     autocorrelation is D, Green-Kubo), so a relative SE e of the Stokes
 *     velocity v_s needs T = 2 D / (N v_s^2 e^2).  g(r) has no error model
 *     here: stop.observable = "rdf_peak" ends a run at its measured SE.
 *  5. CPU: per collision step n_fluid c_f + N substeps c_md with the
 *     per-coupling constants measured on one thread (bench/RESULTS.md, "Plan
 *     cost model"); another machine scales them.
 * Units: the mapping's (a0, t0, m_f, kT_model = 1) and SI for the user. */
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "advise_match.h"
#include "peloid/run.h"
#include "peloid/scene.h"
#include "peloid/sweep.h"

#define PL_PLAN_C_D 0.35
#define PL_PLAN_HASIMOTO 2.837

/* One thread, ns per fluid particle and collision step, and per colloid and
 * MD step (bench/RESULTS.md, "Plan cost model"). */
static const struct {
    int method;
    const char *name;
    double ns_fluid, ns_md;
} COST[] = {
    {PL_COUPLE_HECHT1, "I", 29.0, 177.0},
    {PL_COUPLE_HECHT2, "II", 21.5, 282.0},
    {PL_COUPLE_POTENTIAL, "potential", 24.1, 2410.0},
};
enum { NC = sizeof COST / sizeof COST[0] };

typedef struct {
    int ok;
    char why[400];             /* when not ok: the loader's refusal */
    double a0_over_R, rh;      /* R_h/R of a stick sphere, theory or calibrated */
    double rh_lo, rh_hi;       /* measured estimate (shipped calibrations) */
    int nshipped;
    double cal_s_lo, cal_s_hi; /* the shipped calibrations' wall seconds */
    double step_s, n_fluid;    /* CPU seconds per collision step */
    double real_s;             /* CPU seconds per second of real time (t0 of the measured D) */
    double step_real_s;        /* real seconds per collision step, t0 of the theory's D */
    long long substeps, n;
} option_t;

static double fluid_particles(const pl_scene_t *s)
{
    return s->fluid.density * (double)s->box.cells[0] * (double)s->box.cells[1] * (double)s->box.cells[2];
}

static double step_cost(const pl_scene_t *s, int k)
{
    return 1e-9 * (fluid_particles(s) * COST[k].ns_fluid +
                   (double)s->colloids.count * (double)s->mapping.map.md_substeps * COST[k].ns_md);
}

/* wall_s of the shipped calibration file `key` (NAN: unreadable). */
static double shipped_wall(const char *dir, const char *key)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/calibration-%s.json", dir, key);
    json_t *doc = json_load_file(path, 0, NULL);
    double w = doc ? json_number_value(json_object_get(doc, "wall_s")) : NAN;
    json_decref(doc);
    return w > 0 ? w : NAN;
}

/* CPU seconds per second of real time of an option whose measured D is `fix`
 * times its theory's (t0 matches the model D to the real one: a larger
 * measured D lengthens t0 by that factor). */
static double cpu_per_real_s(const option_t *o, double fix)
{
    return o->step_s / (o->step_real_s * fix);
}

/* The measured factor range of coupling k's theory and its calibrations' durations. */
static void shipped(int method, const char *dir, option_t *o)
{
    double lo = INFINITY, hi = -INFINITY;
    o->cal_s_lo = INFINITY;
    o->cal_s_hi = -INFINITY;
    int m;
    const char *key, *scene;
    double ratio;
    for (int r = 0; !pl_calibrate_shipped(r, &m, &key, &scene, &ratio); ++r) {
        if (m != method) continue;
        lo = fmin(lo, ratio);
        hi = fmax(hi, ratio);
        double w = dir ? shipped_wall(dir, key) : NAN;
        if (isfinite(w)) {
            o->cal_s_lo = fmin(o->cal_s_lo, w);
            o->cal_s_hi = fmax(o->cal_s_hi, w);
        }
        o->nshipped++;
    }
    /* R_h ~ 1 / D: the theory's R_h divided by D_meas / D_theory */
    o->rh_lo = o->nshipped ? o->rh / hi : NAN;
    o->rh_hi = o->nshipped ? o->rh / lo : NAN;
}

static void option_of(const pl_scene_t *s, int k, const char *dir, option_t *o)
{
    const pl_mapping_t *m = &s->mapping.map;
    o->ok = 1;
    o->a0_over_R = 1.0 / m->sigma;
    /* the theory's stick-sphere R_h: the mapping's own when it is on the theory's D */
    o->rh = m->rh_stick_over_R * (m->cg.d_col_calibrated > 0 ? m->d_col_sim / m->d_col_theory : 1.0);
    shipped(COST[k].method, dir, o);
    o->substeps = m->md_substeps;
    o->n = s->colloids.count;
    o->n_fluid = fluid_particles(s);
    o->step_s = step_cost(s, k);
    /* t0 matches the model D to the real one: a measured D larger by D_meas / D_theory lengthens t0 by it */
    const double fix = m->cg.d_col_calibrated > 0 ? 1.0 : o->nshipped ? 2.0 * o->rh / (o->rh_lo + o->rh_hi) : 1.0;
    o->step_real_s = s->srd.dt * m->t0;
    o->real_s = cpu_per_real_s(o, fix);
}

/* Coupling k at the scene's resolution, or at a0/R = cell_size where that is > 0. */
static void option_alt(const char *path, int k, double cell_size, const char *dir, option_t *o)
{
    char value[32], cell[32], *text = NULL;
    pl_err_t e = {0, ""};
    snprintf(value, sizeof value, "\"%s\"", COST[k].name);
    snprintf(cell, sizeof cell, "%.17g", cell_size);
    const char *const keys[] = {"coarse_graining.coupling", "coarse_graining.cell_size"};
    const char *const values[] = {value, cell};
    pl_scene_t *s = malloc(sizeof *s);
    int rc = s ? pl_study_scene_with(path, cell_size > 0 ? 2 : 1, keys, values, &text, &e) : PL_ERR_NOMEM;
    if (!rc) rc = pl_scene_load_string(text, path, s, &e);
    free(text);
    if (rc) {
        o->ok = 0;
        snprintf(o->why, sizeof o->why, "%.399s", s ? e.msg : "out of memory");
    } else {
        option_of(s, k, dir, o);
    }
    free(s);
}

static int coupling_index(int method)
{
    for (int k = 0; k < NC; ++k)
        if (COST[k].method == method) return k;
    return -1;
}

/* "a..b", or "a" when they agree to 2 digits */
static void range(double lo, double hi, const char *fmt_unit, char *buf, size_t n)
{
    char a[16], b[16];
    snprintf(a, sizeof a, "%.2g", lo);
    snprintf(b, sizeof b, "%.2g", hi);
    if (!strcmp(a, b)) snprintf(buf, n, "%.15s%.23s", a, fmt_unit);
    else snprintf(buf, n, "%.15s..%.15s%.23s", a, b, fmt_unit);
}

static void hms(double s, char *buf, size_t n)
{
    if (!isfinite(s)) snprintf(buf, n, "-");
    else if (s < 120) snprintf(buf, n, "%.3g s", s);
    else if (s < 7200) snprintf(buf, n, "%.3g min", s / 60);
    else snprintf(buf, n, "%.3g h", s / 3600);
}

/* The resolution at which coupling I's colloid is hydrodynamically the stated
 * sphere (R_h/R = 0.95), from the law measured for the scene's fluid
 * (advise_match.c), with its CPU per second of real time (t0 of the law's
 * D: the theory's R_h is 1, the law's 0.95). */
static void matched(const pl_scene_t *s, const char *path, const char *dir, FILE *f)
{
    pl_advise_match_t mt;
    pl_advise_match(s, dir, &mt);
    if (s->coupling.method != PL_COUPLE_HECHT1) {
        fprintf(f, "   matched R_h = R: measured for coupling I only (its colloid is a stick sphere whose deficit falls "
                   "with the resolution); coupling II's colloids are points in the collision and the potential "
                   "coupling's surface is slip: neither reaches R_h = R by the cell size (validation/REPORT.md)\n");
        return;
    }
    if (!mt.found) {
        fprintf(f, "   matched R_h = R: no resolution law measured for this scene's fluid (srd.rule, alpha, grid_shift, "
                   "particles per cell, mean free path, coupling.boundary); the measured fluids: %s/rh_resolution-*.json "
                   "(validation/REPORT.md)\n", dir);
        return;
    }
    char pts[200] = "";
    for (int i = 0; i < mt.npoints; ++i) {
        size_t l = strlen(pts);
        snprintf(pts + l, sizeof pts - l, "%s%.3g at %g", i ? ", " : "", mt.rh[i], mt.R[i]);
    }
    const double rho = s->mapping.enabled && s->fluid.density > 0 ? s->colloids.mass_density / s->fluid.density : NAN;
    char mass[160] = "";
    if (isfinite(rho) && fabs(rho / mt.rho_ratio - 1.0) > 0.01)
        snprintf(mass, sizeof mass, "; measured at colloid/fluid density %.3g, this scene's is %.3g (the friction "
                                    "moves by a few %% with the colloid mass)", mt.rho_ratio, rho);
    fprintf(f, "   matched R_h = R (coupling I in this fluid, study %s: R_h/R = %s a0 measured%s):\n", mt.study, pts,
            mass);
    if (!mt.have_match) {
        fprintf(f, "     no matched resolution: %s\n", mt.reason);
        return;
    }
    option_t o;
    memset(&o, 0, sizeof o);
    option_alt(path, coupling_index(PL_COUPLE_HECHT1), 1.0 / mt.R_match, dir, &o);
    if (!o.ok) {
        fprintf(f, "     R_h/R = 0.95 at R = %.3g +- %.2g a0; that scene does not load: %s\n", mt.R_match, mt.R_match_se,
                o.why);
        return;
    }
    char cpu[32];
    hms(cpu_per_real_s(&o, o.rh / 0.95), cpu, sizeof cpu); /* D_law / D_theory = R_h,theory / 0.95 R */
    fprintf(f, "     R_h/R = 0.95 at R = %.3g +- %.2g a0: coarse_graining.cell_size = %.3g (%.3g x the fluid per colloid "
               "of a0/R = 0.5); CPU per s of real time %s (t0 of the law's D)\n",
            mt.R_match, mt.R_match_se, 1.0 / mt.R_match, pow(0.5 * mt.R_match, 3.0), cpu);
    if (mt.checked)
        fprintf(f, "     run at R = %g a0: R_h/R = %.3f +- %.3f, %s (validation/REPORT.md, rule R8)\n", mt.check_R,
                mt.check_rh, mt.check_rh_se, mt.check_verdict);
}

int pl_plan_advise(const pl_scene_t *s, const char *path, double target, const char *shipped_dir, FILE *f,
                   pl_err_t *err)
{
    const pl_mapping_t *m = &s->mapping.map;
    if (!s->mapping.enabled || s->colloids.count <= 0)
        return pl_err_set(err, PL_ERR_INPUT, "plan: %s has no physical{} suspension of colloids (physical.radius "
                          "and physical.volume_fraction); allowed: a physical scene", path);
    const int own = coupling_index(s->coupling.method);
    if (own < 0) return pl_err_set(err, PL_ERR_INPUT, "plan: %s: its coupling has no plan; allowed: coupling I, II "
                                   "or potential (coarse_graining.coupling)", path);
    option_t opt[NC];
    memset(opt, 0, sizeof opt);
    for (int k = 0; k < NC; ++k) {
        if (k == own) option_of(s, k, shipped_dir, &opt[k]);
        else option_alt(path, k, 0.0, shipped_dir, &opt[k]);
    }
    const double R = m->real.radius, a0 = m->a0, t0 = m->t0, D = m->d_col_sim, N = (double)s->colloids.count;
    fprintf(f, "Plan for %s: target relative SE %.3g %% (colloid D%s)\n", path, 100 * target,
            m->real.g > 0 ? "; the settling velocity" : "");
    fprintf(f, "Suspension: R = %.4g um, phi = %.4g (%lld colloids), box %d x %d x %d a0 = %.4g x %.4g x %.4g um, "
               "coupling %s (a0 = %.4g um, t0 = %.4g s)\n",
            1e6 * R, s->mapping.colloid.phi_realised, s->colloids.count, s->box.cells[0], s->box.cells[1],
            s->box.cells[2], 1e6 * a0 * s->box.cells[0], 1e6 * a0 * s->box.cells[1], 1e6 * a0 * s->box.cells[2],
            COST[own].name, 1e6 * a0, t0);
    fprintf(f, "1. Coupling and resolution (R_h/R: the model colloid's hydrodynamic radius as a stick sphere, "
               "1 = the stated sphere)\n");
    fprintf(f, "   %-10s %6s %8s %-30s %-26s %s\n", "coupling", "a0/R", "R_h/R", "R_h/R measured",
            "calibration run", "CPU per s of real time");
    fprintf(f, "   %-10s %6s %8s\n", "", "", "(theory)");
    int best = -1;
    double best_d = INFINITY;
    for (int k = 0; k < NC; ++k) {
        const option_t *o = &opt[k];
        if (!o->ok) {
            fprintf(f, "   %-10s not for this scene: %s\n", COST[k].name, o->why);
            continue;
        }
        char meas[64], cal[64], cpu[32], a[24], b[24];
        if (k == own && m->cg.d_col_calibrated > 0) {
            snprintf(meas, sizeof meas, "%.3g +- %.2g (this scene)", m->rh_stick_over_R,
                     m->rh_stick_over_R * m->cg.d_col_calibrated_se / m->cg.d_col_calibrated);
        } else if (o->nshipped) {
            char r[64], u[24];
            snprintf(u, sizeof u, " (%d shipped)", o->nshipped);
            range(o->rh_lo, o->rh_hi, u, r, sizeof r);
            snprintf(meas, sizeof meas, "%s", r);
        } else snprintf(meas, sizeof meas, "not measured");
        hms(o->cal_s_lo, a, sizeof a);
        hms(o->cal_s_hi, b, sizeof b);
        if (k == own && m->cg.d_col_calibrated > 0) snprintf(cal, sizeof cal, "done (%s)", m->calib.source == PL_CALSRC_SHIPPED ? "shipped"
                                                                     : m->calib.source == PL_CALSRC_CACHE ? "cache"
                                                                     : m->calib.source == PL_CALSRC_TABLE ? "table" : "run");
        else if (isfinite(o->cal_s_lo) && strcmp(a, b)) snprintf(cal, sizeof cal, "%s..%s (shipped)", a, b);
        else if (isfinite(o->cal_s_lo)) snprintf(cal, sizeof cal, "%s (shipped)", a);
        else snprintf(cal, sizeof cal, "unknown");
        hms(o->real_s, cpu, sizeof cpu);
        fprintf(f, "   %-10s %6.3g %8.3g %-30s %-26s %s%s\n", COST[k].name, o->a0_over_R, o->rh, meas, cal, cpu,
                k == own ? "   <- this scene" : "");
        const double mid = k == own && m->cg.d_col_calibrated > 0 ? m->rh_stick_over_R
                           : o->nshipped ? 0.5 * (o->rh_lo + o->rh_hi) : NAN;
        if (isfinite(mid) && fabs(mid - 1.0) < best_d) {
            best_d = fabs(mid - 1.0);
            best = k;
        }
    }
    if (best >= 0)
        fprintf(f, "   recommended: coupling %s (coarse_graining.coupling = \"%s\"): its measured R_h/R is nearest 1 "
                   "(off by %.0f %%), so box corrections, hindered settling, D(phi) and lubrication have the stated "
                   "sphere's strength\n",
                COST[best].name, COST[best].name, 100 * best_d);
    int cheap = -1;
    for (int k = 0; k < NC; ++k)
        if (opt[k].ok && (cheap < 0 || opt[k].real_s < opt[cheap].real_s)) cheap = k;
    if (best >= 0 && cheap >= 0 && cheap != best)
        fprintf(f, "   cheapest: coupling %s (%.3g x less CPU per second of real time than %s): its D is matched by "
                   "the calibration, its many-body hydrodynamics are those of a sphere of R_h\n",
                COST[cheap].name, opt[best].real_s / opt[cheap].real_s, COST[best].name);
    matched(s, path, shipped_dir, f);
    /* 2. box */
    /* R_h as measured: this scene's calibration, else the shipped calibrations' (their mid-range), else theory */
    const option_t *mine = &opt[own];
    const int cal = m->cg.d_col_calibrated > 0, ship = !cal && mine->nshipped > 0;
    const double rh = R * (cal ? m->rh_stick_over_R : ship ? 0.5 * (mine->rh_lo + mine->rh_hi) : mine->rh);
    const double L = m->box_L * a0, corr = PL_PLAN_HASIMOTO * rh / L;
    fprintf(f, "2. Box: the periodic images slow D by 2.837 R_h / L (Hasimoto, PL Eq. 43) = %.3g %% at L = %.4g um "
               "(R_h = %.4g um, %s)%s; below the target (%.3g %%) from L >= %.4g um (%.0f a0)\n",
            100 * corr, 1e6 * L, 1e6 * rh, cal ? "this scene's calibration" : ship ? "the shipped calibrations" : "theory",
            m->box_periodic ? "" : "; walls slow it further (not corrected)",
            100 * target, 1e6 * PL_PLAN_HASIMOTO * rh / target, ceil(PL_PLAN_HASIMOTO * rh / target / a0));
    /* 3. MD */
    fprintf(f, "3. MD: %lld MD steps per collision step (dt_MD = %.4g s), derived from the stiffest contact "
               "(hertz.K = %.4g kT/a0^2.5, reached with coarse_graining.reach_energy = %g kT; the MD step is at "
               "most the shortest colloid time / coarse_graining.md_resolution = %g)\n",
            m->md_substeps, m->md_dt, s->colloids.hertz.K, s->mapping.cg.reach_energy, s->mapping.cg.md_resolution);
    /* 4. run length */
    const double tau_v = m->mass_sim * D, tmin = fmax(400.0 * tau_v, m->sigma * m->sigma / D);
    const double se1 = PL_PLAN_C_D / sqrt(N), reps = ceil(se1 * se1 / (target * target));
    const double steps = ceil(tmin / s->srd.dt), cpu = steps * opt[own].step_s;
    char c1[32], c2[32];
    hms(cpu, c1, sizeof c1);
    hms(cpu * fmax(reps, 1.0), c2, sizeof c2);
    fprintf(f, "4. Run length: colloid D (MSD slope over lags [T/40, T/4]) needs T >= %.4g s of real time (%.0f "
               "steps: 400 tau_v and R^2/D); its SE does not fall with T, it is ~%.2g/sqrt(N) = %.3g %% a run for "
               "N = %lld, %s\n",
            tmin * t0, steps, PL_PLAN_C_D, 100 * se1, s->colloids.count,
            reps <= 1 ? "one run meets the target" : "above the target");
    if (reps > 1)
        fprintf(f, "   the target takes %.0f replicas: peloid run %s --replicas %.0f (or %.0f colloids in a larger "
                   "box)\n",
                reps, path, reps, ceil(N * reps));
    fprintf(f, "   CPU: %s a run (%.4g s per step on one thread: %.4g fluid particles, %lld colloids x %lld MD "
               "steps), %s for the target\n",
            c1, opt[own].step_s, opt[own].n_fluid, s->colloids.count, m->md_substeps, c2);
    if (m->real.g > 0 && m->g_sim > 0) {
        const double vs = m->g_sim * m->mass_sim * D, ts = 2.0 * D / (N * vs * vs * target * target);
        char c3[32];
        hms(ceil(ts / s->srd.dt) * opt[own].step_s, c3, sizeof c3);
        fprintf(f, "   settling velocity (v_s = %.4g um/s, Pe = v_s R / D = %.3g): SE sqrt(2 D / (N T)) reaches %.3g "
                   "%% after T = %.4g s (%.0f steps, CPU %s)\n",
                1e6 * vs * a0 / t0, vs * m->sigma / D, 100 * target, ts * t0, ceil(ts / s->srd.dt), c3);
    }
    fprintf(f, "   g(r): no error model; stop: { observable = \"rdf_peak\"; rel_error = %.3g; } ends a run when its "
               "peak's SE meets the target\n", target);
    fprintf(f, "   (CPU figures: bench/RESULTS.md \"Plan cost model\", one thread of the 2-core machine it was "
               "measured on; the accuracy each choice reaches: validation/REPORT.md)\n");
    return 0;
}
