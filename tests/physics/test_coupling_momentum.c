/* Coupling invariants in a periodic box without external forces: total
 * momentum of fluid + colloids is conserved to round-off by coupling I
 * (every surface rule and placement), coupling II (with and without the
 * mass-weighted Heyes thermostat) and the potential coupling (PL Eq. 17). */
#include <math.h>
#include <stdio.h>

#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "support.h"

static const char *BASE =
    "seed = 7;\n"
    "box: { cells = [12, 12, 12]; };\n"
    "fluid: { density = 5.0; temperature = 1.0; };\n"
    "srd: { dt = 0.1; };\n"
    "colloids: { count = 8; radius = 2.0; mass_density = 5.0; temperature = 1.0;\n"
    "  init = \"random\"; pairs = \"hertz\"; substeps = 4; };\n";

/* Runs `steps` steps and returns the largest |P(t) - P(0)| per component,
 * relative to the thermal momentum scale sqrt(M_total kT). */
static double momentum_drift(const char *coupling, long long steps, int threads)
{
    char text[2048];
    snprintf(text, sizeof text, "%scoupling: { %s };\n", BASE, coupling);
    pl_sim_t *sim = pl_test_sim(text, threads);
    double P0[3], P[3], M;
    pl_coupling_total_momentum(sim, P0, &M);
    double worst = 0.0;
    for (long long s = 0; s < steps; ++s) {
        pl_test_steps(sim, 1);
        pl_coupling_total_momentum(sim, P, &M);
        for (int d = 0; d < 3; ++d) worst = fmax(worst, fabs(P[d] - P0[d]));
    }
    if (pl_coupling_of(sim) && pl_coupling_of(sim)->method == PL_COUPLE_HECHT1)
        cr_assert_gt(pl_coupling_of(sim)->c1->events, 100, "coupling I: too few reflections (%llu) to test",
                     pl_coupling_of(sim)->c1->events);
    pl_sim_free(sim);
    return worst / sqrt(M);
}

/* Bound: round-off of ~1e4 particle updates per step over 200 steps is
 * ~1e-13 of sqrt(M kT); 1e-10 leaves room and still catches any real leak
 * (a single missed reflection moves ~1e-2 of that scale). */
static const double TOL = 1e-10;

Test(coupling_momentum, hecht1_surface_rules, .timeout = 120)
{
    const char *cases[] = {
        "method = \"hecht1\"; boundary = \"slip\"; placement = \"entry\";",
        "method = \"hecht1\"; boundary = \"stick_stochastic\"; placement = \"entry\";",
        "method = \"hecht1\"; boundary = \"stick_bounce\"; placement = \"entry\";",
        "method = \"hecht1\"; boundary = \"stick_stochastic\"; placement = \"nearest\";",
    };
    long long steps = pl_test_quick() ? 20 : 200;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        double e = momentum_drift(cases[k], steps, 2);
        cr_log_info("momentum drift %s: %.3g", cases[k], e);
        cr_expect_lt(e, TOL, "%s: |dP| / sqrt(M kT) = %.3g", cases[k], e);
    }
}

Test(coupling_momentum, hecht2, .timeout = 120)
{
    long long steps = pl_test_quick() ? 20 : 200;
    double e = momentum_drift("method = \"hecht2\";", steps, 2);
    cr_log_info("momentum drift hecht2: %.3g", e);
    cr_expect_lt(e, TOL, "hecht2: |dP| / sqrt(M kT) = %.3g", e);
}

Test(coupling_momentum, potential, .timeout = 120)
{
    long long steps = pl_test_quick() ? 20 : 200;
    double e = momentum_drift("method = \"potential\"; sigma_cf = 2.0;", steps, 2);
    cr_log_info("momentum drift potential: %.3g", e);
    cr_expect_lt(e, TOL, "potential: |dP| / sqrt(M kT) = %.3g", e);
}

Test(coupling_momentum, hecht2_heyes, .timeout = 120)
{
    long long steps = pl_test_quick() ? 20 : 200;
    char text[2048];
    snprintf(text, sizeof text, "%sthermostat: { type = \"heyes\"; temperature = 1.2; };\n"
             "coupling: { method = \"hecht2\"; };\n", BASE);
    pl_sim_t *sim = pl_test_sim(text, 2);
    double P0[3], P[3], M;
    pl_coupling_total_momentum(sim, P0, &M);
    pl_test_steps(sim, steps);
    pl_coupling_total_momentum(sim, P, &M);
    for (int d = 0; d < 3; ++d)
        cr_expect_lt(fabs(P[d] - P0[d]) / sqrt(M), TOL, "axis %d: %.3g", d, fabs(P[d] - P0[d]));
    pl_sim_free(sim);
}

/* Coupling I detects the right number of wall collisions: for a heavy colloid
 * the rate is the kinetic-theory flux n sqrt(kT / 2 pi m_f) 4 pi R^2 per
 * unit time (n the fluid density outside the colloids).  Tolerance 3%: the
 * count is ~1.6e4 events (Poisson error 0.8%); a sphere test that misses
 * grazing particles or counts a particle twice misses by more. */
Test(coupling_momentum, hecht1_collision_rate, .timeout = 60)
{
    const char *text =
        "seed = 17;\n"
        "box: { cells = [16, 16, 16]; };\n"
        "fluid: { density = 5.0; temperature = 1.0; };\n"
        "srd: { dt = 0.1; };\n"
        "colloids: { count = 8; radius = 2.0; mass_density = 1000.0; temperature = 1.0;\n"
        "  init = \"lattice\"; pairs = \"\"; substeps = 1; };\n"
        "coupling: { method = \"hecht1\"; boundary = \"slip\"; };\n";
    long long steps = pl_test_quick() ? 20 : 200;
    pl_sim_t *sim = pl_test_sim(text, 2);
    pl_test_steps(sim, steps);
    const double PI = 3.14159265358979323846, R = 2.0, L3 = 16.0 * 16.0 * 16.0;
    double n_out = (double)sim->fluid.n / (L3 - 8.0 * 4.0 / 3.0 * PI * R * R * R);
    double expect = n_out * sqrt(1.0 / (2.0 * PI)) * 4.0 * PI * R * R * 0.1 * 8.0 * (double)steps;
    double got = (double)pl_coupling_of(sim)->c1->events;
    cr_log_info("coupling I events: %.0f, kinetic theory %.0f (%+.2f%%)", got, expect,
                100.0 * (got / expect - 1.0));
    if (!pl_test_quick())
        cr_expect_lt(fabs(got / expect - 1.0), 0.03, "events %.0f vs flux %.0f", got, expect);
    cr_expect_eq(pl_coupling_of(sim)->c1->truncations, 0);
    pl_sim_free(sim);
}

/* Coupling I has no preferred direction: a colloid pinned in a periodic box
 * (Hecht Table I's resolution: gamma = 2.5, lambda = 0.6, hecht_axes, a =
 * R / 2, stick_stochastic, entry) leaves the fluid at rest on average.
 * When each event saw the colloid velocity the events before it left
 * (particle order = the counting sort's z-major order), the lower events
 * pushed the colloid up before the upper ones met it and the fluid settled
 * into a stream of P_z ~ +300 = 3 sqrt(M_f kT) (a free colloid drifted
 * towards -z at a fifth of its thermal speed).  The fluid momentum relaxes
 * through the colloid's drag in M_f D / kT ~ 430 steps, so its mean over
 * steps 600-3000 has SE ~ sqrt(2 M_f kT 430 / 2400) ~ 60 per component;
 * bound 2 sqrt(M_f kT) = 202 (3.4 SE; the old stream is 5 SE). */
Test(coupling_momentum, hecht1_pinned_no_stream, .timeout = 120)
{
    const char *text =
        "seed = 11;\n"
        "box: { cells = [16, 16, 16]; };\n"
        "fluid: { density = 2.5; temperature = 1.0; };\n"
        "srd: { dt = 0.6; rule = \"hecht_axes\"; grid_shift = false; };\n"
        "thermostat: { type = \"heyes\"; temperature = 1.0; };\n"
        "colloids: { count = 1; radius = 2.0; mass_density = 9.75; temperature = 1.0;\n"
        "  init = \"lattice\"; pairs = \"\"; substeps = 1; };\n"
        "coupling: { method = \"hecht1\"; boundary = \"stick_stochastic\"; placement = \"entry\"; pinned = true; };\n";
    const long long steps = pl_test_quick() ? 100 : 3000, from = pl_test_quick() ? 50 : 600;
    pl_sim_t *sim = pl_test_sim(text, 2);
    double sum[3] = {0.0, 0.0, 0.0}, P[3], M = 0.0;
    double n = 0.0;
    for (long long s = 0; s < steps; ++s) {
        pl_test_steps(sim, 1);
        if (s < from || s % 10) continue;
        pl_coupling_total_momentum(sim, P, &M);
        for (int d = 0; d < 3; ++d) sum[d] += P[d];
        n += 1.0;
    }
    const double Mf = (double)sim->fluid.n, bound = 2.0 * sqrt(Mf);
    for (int d = 0; d < 3; ++d) {
        cr_log_info("pinned colloid, coupling I: mean fluid momentum[%d] = %.1f (bound %.0f)", d, sum[d] / n, bound);
        if (!pl_test_quick()) cr_expect_lt(fabs(sum[d] / n), bound, "axis %d: <P> = %.1f", d, sum[d] / n);
    }
    pl_sim_free(sim);
}
