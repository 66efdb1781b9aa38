/* On-the-fly blocking (src/observe/blocking.c) against series whose SE of the mean is
 * known exactly.
 *
 * AR(1): x_t = phi x_{t-1} + sqrt(1 - phi^2) g_t, x_0 ~ N(0, 1), has unit
 * variance, correlation phi^|i-j| and hence
 *   Var(mean) = (1/N) [(1+phi)/(1-phi) - 2 phi (1 - phi^N) / (N (1-phi)^2)].
 * Tolerances are stated next to each check. */
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "peloid/blocking.h"
#include "support.h"

static double ar1_exact_se(double phi, size_t n)
{
    double dn = (double)n;
    double v = ((1.0 + phi) / (1.0 - phi) -
                2.0 * phi * (1.0 - pow(phi, dn)) / (dn * (1.0 - phi) * (1.0 - phi))) /
               dn;
    return sqrt(v);
}

static void ar1_fill(gsl_rng *r, double phi, size_t n, double *x)
{
    double c = sqrt(1.0 - phi * phi);
    x[0] = gsl_ran_gaussian_ziggurat(r, 1.0);
    for (size_t t = 1; t < n; ++t) x[t] = phi * x[t - 1] + c * gsl_ran_gaussian_ziggurat(r, 1.0);
}

/* 200 series of 2^16 samples, tau_int = 4.5 (phi = 0.8, inefficiency 9).
 * Each blocking SE is uncertain by ~1/sqrt(2 n_k) <= 5 % (n_k >= 256 blocks at
 * the chosen level), so the mean ratio over 200 series has a statistical
 * error ~0.4 %; the residual bias of the rule (~tau/B) is a few %.  The brief
 * asks 10 %. */
Test(blocking, ar1_se_matches_exact)
{
    enum { NSER = 200 };
    const size_t n = (size_t)1 << 16;
    const double phi = 0.8;
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 14);
    double *x = malloc(n * sizeof *x);
    double ratio[NSER], means[NSER];
    int plateaus = 0;
    double se_exact = ar1_exact_se(phi, n);
    for (int s = 0; s < NSER; ++s) {
        ar1_fill(r, phi, n, x);
        pl_blocking_t b;
        pl_blocking_init(&b);
        for (size_t t = 0; t < n; ++t) pl_blocking_add(&b, x[t]);
        pl_blocking_result_t res = pl_blocking_result(&b);
        ratio[s] = res.se / se_exact;
        means[s] = res.mean;
        plateaus += res.plateau;
        cr_assert_eq(b.n, n);
        cr_assert_float_eq(res.mean, gsl_stats_mean(x, 1, n), 1e-12);
    }
    double rm = gsl_stats_mean(ratio, 1, NSER), rsd = gsl_stats_sd(ratio, 1, NSER);
    double sd_means = gsl_stats_sd(means, 1, NSER);
    fprintf(stderr, "blocking AR(1) phi=%.1f N=%zu: SE/exact = %.4f +- %.4f (sd over %d), "
                    "plateau in %d, sd of means / exact SE = %.3f\n",
            phi, n, rm, rsd, NSER, plateaus, sd_means / se_exact);
    cr_assert_lt(fabs(rm - 1.0), 0.10, "blocking SE / exact = %g", rm);
    /* The generator itself: the spread of 200 means is the exact SE within
     * 1/sqrt(2*199) = 5 %; 4 sigma = 20 %. */
    cr_assert_lt(fabs(sd_means / se_exact - 1.0), 0.2);
    cr_assert_geq(plateaus, NSER * 95 / 100, "plateau found in %d of %d", plateaus, NSER);
    free(x);
    gsl_rng_free(r);
}

/* Uncorrelated Gaussian data: level 0 is exactly the textbook s/sqrt(N)
 * (to rounding), the plateau SE is sigma/sqrt(N) within its own error
 * (mean ratio over 100 series: error ~1/sqrt(2 n_k * 100) < 1 %; 5 % allowed)
 * and the inefficiency is 1. */
Test(blocking, uncorrelated_is_sigma_over_sqrt_n)
{
    enum { NSER = 100 };
    const size_t n = 50000;
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 141);
    double *x = malloc(n * sizeof *x);
    double ratio[NSER], ineff[NSER];
    for (int s = 0; s < NSER; ++s) {
        pl_blocking_t b;
        pl_blocking_init(&b);
        for (size_t t = 0; t < n; ++t) {
            x[t] = 3.0 + 2.0 * gsl_ran_gaussian_ziggurat(r, 1.0);
            pl_blocking_add(&b, x[t]);
        }
        double se0 = gsl_stats_sd(x, 1, n) / sqrt((double)n);
        cr_assert_float_eq(pl_blocking_level_se(&b, 0), se0, 1e-12 * se0);
        pl_blocking_result_t res = pl_blocking_result(&b);
        cr_assert(res.plateau);
        ratio[s] = res.se / (2.0 / sqrt((double)n));
        ineff[s] = res.inefficiency;
    }
    double rm = gsl_stats_mean(ratio, 1, NSER), im = gsl_stats_mean(ineff, 1, NSER);
    fprintf(stderr, "blocking uncorrelated N=%zu: SE/(sigma/sqrt N) = %.4f +- %.4f, inefficiency %.3f\n",
            n, rm, gsl_stats_sd(ratio, 1, NSER), im);
    cr_assert_lt(fabs(rm - 1.0), 0.05);
    cr_assert_lt(fabs(im - 1.0), 0.10);
    free(x);
    gsl_rng_free(r);
}

static void assert_same_state(const pl_blocking_t *a, const pl_blocking_t *b, double tol)
{
    cr_assert_eq(a->n, b->n);
    cr_assert_eq(a->nlev, b->nlev);
    for (int k = 0; k < a->nlev; ++k) {
        cr_assert_eq(a->lev[k].n, b->lev[k].n, "level %d", k);
        cr_assert_eq(a->lev[k].has_pending, b->lev[k].has_pending, "level %d", k);
        cr_assert_float_eq(a->lev[k].mean, b->lev[k].mean, tol, "level %d", k);
        cr_assert_float_eq(a->lev[k].m2, b->lev[k].m2, tol * (1.0 + fabs(b->lev[k].m2)), "level %d", k);
        if (a->lev[k].has_pending)
            cr_assert_float_eq(a->lev[k].pending, b->lev[k].pending, tol, "level %d", k);
    }
}

/* Merging two stretches equals adding them in sequence (to rounding, 1e-12)
 * when the first ends on a block boundary of every level the second reaches
 * (2048 = 2^11 > 952); any split keeps N, the mean and level 0 exact; and a
 * merge is a fixed sequence of operations (bitwise repeatable). */
Test(blocking, merge_equals_sequential)
{
    const size_t n = 3000;
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 1414);
    double *x = malloc(n * sizeof *x);
    ar1_fill(r, 0.5, n, x);
    pl_blocking_t seq;
    pl_blocking_init(&seq);
    for (size_t t = 0; t < n; ++t) pl_blocking_add(&seq, x[t]);

    size_t splits[] = {2048, 1000, 1, 2999};
    for (size_t si = 0; si < sizeof splits / sizeof *splits; ++si) {
        size_t m = splits[si];
        pl_blocking_t a, b, a2;
        pl_blocking_init(&a);
        pl_blocking_init(&b);
        for (size_t t = 0; t < m; ++t) pl_blocking_add(&a, x[t]);
        for (size_t t = m; t < n; ++t) pl_blocking_add(&b, x[t]);
        a2 = a;
        pl_blocking_merge(&a, &b);
        pl_blocking_merge(&a2, &b);
        cr_assert_eq(memcmp(&a, &a2, sizeof a), 0, "merge is not repeatable");
        cr_assert_eq(a.n, n);
        cr_assert_float_eq(pl_blocking_mean(&a), pl_blocking_mean(&seq), 1e-12);
        cr_assert_float_eq(pl_blocking_level_se(&a, 0), pl_blocking_level_se(&seq, 0), 1e-12);
        if (m == 2048) assert_same_state(&a, &seq, 1e-12);
    }
    /* Merging into an empty accumulator is a copy. */
    pl_blocking_t e;
    pl_blocking_init(&e);
    pl_blocking_merge(&e, &seq);
    assert_same_state(&e, &seq, 0.0);
    free(x);
    gsl_rng_free(r);
}

/* A run shorter than its correlation time (tau ~ 1000 steps, N = 2048) has no
 * plateau and says so; its SE is then a lower bound of the exact one. */
Test(blocking, no_plateau_is_flagged)
{
    const size_t n = 2048;
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 7);
    double *x = malloc(n * sizeof *x);
    int flagged = 0;
    for (int s = 0; s < 20; ++s) {
        ar1_fill(r, 0.999, n, x);
        pl_blocking_t b;
        pl_blocking_init(&b);
        for (size_t t = 0; t < n; ++t) pl_blocking_add(&b, x[t]);
        pl_blocking_result_t res = pl_blocking_result(&b);
        flagged += !res.plateau;
    }
    cr_assert_geq(flagged, 19, "no plateau flagged in only %d of 20", flagged);
    free(x);
    gsl_rng_free(r);
}

/* SE ~ 1/sqrt(t): the SE after N/4 samples predicts that N samples reach the
 * SE measured at N.  Both SEs are uncertain by ~2 % (n_k ~ 1000 blocks), so
 * the predicted N is within 4 * 2 * 2 % = 16 % of the actual; 20 % allowed. */
Test(blocking, time_for_se)
{
    cr_assert_float_eq(pl_blocking_time_for_se(0.1, 10.0, 0.05), 40.0, 1e-12);
    cr_assert(isinf(pl_blocking_time_for_se(0.1, 10.0, 0.0)));
    const size_t n = (size_t)1 << 18;
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 77);
    double *x = malloc(n * sizeof *x);
    ar1_fill(r, 0.6, n, x);
    pl_blocking_t b;
    pl_blocking_init(&b);
    double se_quarter = 0.0;
    for (size_t t = 0; t < n; ++t) {
        pl_blocking_add(&b, x[t]);
        if (t + 1 == n / 4) se_quarter = pl_blocking_result(&b).se;
    }
    double se_full = pl_blocking_result(&b).se;
    double pred = pl_blocking_time_for_se(se_quarter, (double)(n / 4), se_full);
    fprintf(stderr, "blocking time_for_se: predicted %.0f samples, actual %zu\n", pred, n);
    cr_assert_lt(fabs(pred / (double)n - 1.0), 0.2);
    free(x);
    gsl_rng_free(r);
}
