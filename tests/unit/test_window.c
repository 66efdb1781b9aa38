/* Analysis windows (src/observe/window.c): Chodera's equilibration
 * detection on synthetic series with a known transient, the parser of
 * observe.average_from, and the windowed blocking average.
 *
 * Series: x_t = A exp(-t / tau) + e_t, e_t an AR(1) process of unit
 * variance and correlation phi (statistical inefficiency (1+phi)/(1-phi)).
 * With n = 2000, A = 10, tau = 50, phi = 0.8 the whole-run mean is biased
 * by A tau / n = 0.25, 3.5 times its SE (~0.07); the detected start must
 * lie after 1.5 tau (the transient then at A e^-1.5 = 2.2 noise SDs) and at
 * most n/2 (the search bound), and the mean from it must be within 3 of its
 * SEs (sqrt(g / (n - t0))) of the true 0.  Chodera's rule trades bias for
 * variance, so its start scatters (this seed: 84..486 over 50 series).
 * Stationary series: N_eff grows with every kept sample, so only noise in
 * g moves the start off 0: at most 5 of 50 series start after n/10 (this
 * seed: 1, at 204; 32 at 0). */
#include <criterion/criterion.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "peloid/window.h"

static void relax_ar1(gsl_rng *r, double A, double tau, double phi, size_t n, double *x)
{
    const double c = sqrt(1.0 - phi * phi);
    double e = gsl_ran_gaussian_ziggurat(r, 1.0);
    for (size_t t = 0; t < n; ++t) {
        if (t) e = phi * e + c * gsl_ran_gaussian_ziggurat(r, 1.0);
        x[t] = A * exp(-(double)t / tau) + e;
    }
}

Test(window, detects_after_relaxation)
{
    enum { NSER = 50, N = 2000 };
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 49);
    double *x = malloc(N * sizeof *x);
    size_t lo = N, hi = 0;
    for (int s = 0; s < NSER; ++s) {
        relax_ar1(r, 10.0, 50.0, 0.8, N, x);
        double g, neff;
        const size_t t0 = pl_window_detect(x, N, &g, &neff);
        if (t0 < lo) lo = t0;
        if (t0 > hi) hi = t0;
        double m = 0.0;
        for (size_t t = t0; t < N; ++t) m += x[t];
        m /= (double)(N - t0);
        cr_assert_geq(t0, 75, "series %d: start %zu not after 1.5 tau", s, t0);
        cr_assert_lt(fabs(m), 3.0 * sqrt(g / (double)(N - t0)), "series %d: windowed mean %g biased", s, m);
        cr_assert_leq(t0, N / 2, "series %d: start %zu beyond n/2", s, t0);
        cr_assert_gt(g, 1.0);
        cr_assert_float_eq(neff, (double)(N - t0) / g, 1e-9);
    }
    fprintf(stderr, "window: relaxation tau = 50 + AR(1) 0.8, n = %d: starts %zu..%zu over %d series\n", N, lo, hi,
            NSER);
    free(x);
    gsl_rng_free(r);
}

Test(window, stationary_starts_near_zero)
{
    enum { NSER = 50, N = 2000 };
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 50);
    double *x = malloc(N * sizeof *x);
    size_t hi = 0;
    int late = 0, zero = 0;
    for (int s = 0; s < NSER; ++s) {
        relax_ar1(r, 0.0, 1.0, 0.8, N, x);
        const size_t t0 = pl_window_detect(x, N, NULL, NULL);
        if (t0 > hi) hi = t0;
        late += t0 > N / 10;
        zero += t0 == 0;
    }
    fprintf(stderr, "window: stationary AR(1) 0.8, n = %d: %d of %d series start at 0, %d after n/10, largest %zu\n",
            N, zero, NSER, late, hi);
    cr_assert_leq(late, 5, "%d of %d stationary series start after n/10", late, NSER);
    free(x);
    gsl_rng_free(r);
}

/* Inefficiency of white noise ~1 (within 0.2: the truncated sum's noise
 * at n = 4000), of AR(1) 0.8 ~ 9 (within 25 %). */
Test(window, inefficiency_of_ar1)
{
    enum { N = 4000 };
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 51);
    double *x = malloc(N * sizeof *x);
    relax_ar1(r, 0.0, 1.0, 0.0, N, x);
    cr_assert_lt(fabs(pl_window_inefficiency(x, N) - 1.0), 0.2);
    double gm = 0.0;
    for (int s = 0; s < 20; ++s) {
        relax_ar1(r, 0.0, 1.0, 0.8, N, x);
        gm += pl_window_inefficiency(x, N) / 20.0;
    }
    cr_assert_lt(fabs(gm / 9.0 - 1.0), 0.25, "mean g = %g", gm);
    const double c[4] = {2.0, 2.0, 2.0, 2.0};
    cr_assert_eq(pl_window_inefficiency(c, 4), 1.0);
    free(x);
    gsl_rng_free(r);
}

Test(window, parse)
{
    pl_window_spec_t s;
    cr_assert_eq(pl_window_parse("auto", &s), 0);
    cr_assert_eq(s.kind, PL_WINDOW_AUTO);
    cr_assert_eq(pl_window_parse("start", &s), 0);
    cr_assert_eq(s.kind, PL_WINDOW_START);
    cr_assert_eq(pl_window_parse("12.5", &s), 0);
    cr_assert(s.kind == PL_WINDOW_TIME && s.value == 12.5);
    cr_assert_eq(pl_window_parse("75%", &s), 0);
    cr_assert(s.kind == PL_WINDOW_PERCENT && s.value == 75.0);
    cr_assert_eq(pl_window_parse("-1", &s), -1);
    cr_assert_eq(pl_window_parse("100%", &s), -1);
    cr_assert_eq(pl_window_parse("half", &s), -1);
    cr_assert_eq(pl_window_parse("3 s", &s), -1);
}

/* A user window keeps the samples from the first step at or after its
 * start; a window from sample 0 gives the on-the-fly accumulator's bits. */
Test(window, user_window_and_blocking)
{
    const long long step[6] = {0, 10, 20, 30, 40, 50};
    const double x[6] = {5.0, 4.0, 1.0, 2.0, NAN, 3.0};
    double scratch[6];
    pl_window_spec_t s = {PL_WINDOW_TIME, 2.5};
    const long long from = pl_window_from_step(&s, 2.5, 0.25, 0, 50);
    cr_assert_eq(from, 10);
    pl_window_t w = pl_window_choose(&s, 15, step, x, 6, scratch);
    cr_assert(w.first == 2 && w.step == 20 && w.source == PL_WSRC_USER);
    uint64_t n;
    pl_blocking_result_t b = pl_window_blocking(x, 6, w.first, &n);
    cr_assert_eq(n, 3);
    cr_assert_float_eq(b.mean, 2.0, 1e-15);
    pl_blocking_t on;
    pl_blocking_init(&on);
    for (int i = 0; i < 6; ++i)
        if (isfinite(x[i])) pl_blocking_add(&on, x[i]);
    pl_blocking_result_t a = pl_blocking_result(&on), c = pl_window_blocking(x, 6, 0, NULL);
    cr_assert(a.mean == c.mean && a.se == c.se);
    pl_window_spec_t p = {PL_WINDOW_PERCENT, 50.0};
    cr_assert_eq(pl_window_from_step(&p, 0.0, 0.25, 100, 301), 201);
}
