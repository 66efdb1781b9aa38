/* Velocity distribution tests (src/observe/vdist.c) on exact Gaussian samples.
 *
 * A correct p-value is uniform on (0, 1) under the null: over 300 samples the
 * fraction with p < 0.05 is 0.05 +- 0.0126 (binomial), checked within 4
 * sigma, [0, 0.10].  A 5 % error in sigma (10 % in kT) and a uniform
 * distribution of the same variance must be rejected at p < 1e-6 with 3 x
 * 10^5 components: both are many sigma away at that size. */
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

#include "peloid/vdist.h"
#include "support.h"

static pl_vdist_t *make(double vmax)
{
    pl_vdist_params_t par = {.nbins = 40, .vmax = vmax};
    pl_vdist_t *h = NULL;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_vdist_create(&par, &h, &err), 0, "%s", err.msg);
    return h;
}

static void fill(gsl_rng *r, double *v, size_t n, double sigma, int uniform)
{
    for (size_t i = 0; i < n; ++i)
        v[i] = uniform ? sigma * sqrt(3.0) * (2.0 * gsl_rng_uniform(r) - 1.0) : gsl_ran_gaussian(r, sigma);
}

Test(vdist, pvalues_uniform_under_null)
{
    const double kT = 1.3, M = 2.0, sigma = sqrt(kT / M);
    const size_t n = 1000;
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 31);
    double *v[3], *all = malloc(3 * n * sizeof *all);
    for (int d = 0; d < 3; ++d) v[d] = malloc(n * sizeof(double));
    int low_chi = 0, low_ks = 0;
    const int reps = 300;
    for (int k = 0; k < reps; ++k) {
        pl_vdist_t *h = make(4.0 * sigma);
        for (int d = 0; d < 3; ++d) fill(r, v[d], n, sigma, 0);
        pl_vdist_sample(h, n, v[0], v[1], v[2]);
        double chi2, p;
        int dof;
        pl_err_t err = {0, ""};
        cr_assert_eq(pl_vdist_chi2(h, 3, sigma, &chi2, &dof, &p, &err), 0, "%s", err.msg);
        cr_assert_gt(dof, 20);
        low_chi += p < 0.05;
        for (int d = 0; d < 3; ++d) memcpy(all + (size_t)d * n, v[d], n * sizeof(double));
        double D;
        pl_vdist_ks(all, 3 * n, sigma, &D, &p);
        low_ks += p < 0.05;
        pl_vdist_free(h);
    }
    cr_log_info("vdist null: p < 0.05 in %d (chi2) and %d (KS) of %d", low_chi, low_ks, reps);
    cr_assert_leq(low_chi, reps / 10, "chi2: p < 0.05 in %d of %d", low_chi, reps);
    cr_assert_leq(low_ks, reps / 10, "KS: p < 0.05 in %d of %d", low_ks, reps);
    cr_assert_geq(low_chi, 1);
    cr_assert_geq(low_ks, 1);
    for (int d = 0; d < 3; ++d) free(v[d]);
    free(all);
    gsl_rng_free(r);
}

Test(vdist, rejects_wrong_temperature_and_shape)
{
    const double sigma = 1.0;
    const size_t n = 100000;
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 32);
    double *v[3], *all = malloc(3 * n * sizeof *all);
    for (int d = 0; d < 3; ++d) v[d] = malloc(n * sizeof(double));
    for (int kase = 0; kase < 3; ++kase) { /* right, 5 % too wide, uniform */
        pl_vdist_t *h = make(4.0);
        for (int d = 0; d < 3; ++d) fill(r, v[d], n, kase == 1 ? 1.05 * sigma : sigma, kase == 2);
        pl_vdist_sample(h, n, v[0], v[1], v[2]);
        const uint64_t *c = pl_vdist_counts(h, 3);
        uint64_t tot = 0;
        for (size_t b = 0; b < 42; ++b) tot += c[b];
        cr_assert_eq(tot, 3 * n);
        double chi2, p, D, pk;
        int dof;
        pl_err_t err = {0, ""};
        cr_assert_eq(pl_vdist_chi2(h, 3, sigma, &chi2, &dof, &p, &err), 0, "%s", err.msg);
        for (int d = 0; d < 3; ++d) memcpy(all + (size_t)d * n, v[d], n * sizeof(double));
        pl_vdist_ks(all, 3 * n, sigma, &D, &pk);
        cr_log_info("vdist case %d: chi2 = %.1f (dof %d, p = %.3g), KS D = %.4f (p = %.3g)", kase, chi2, dof, p,
                    D, pk);
        if (kase == 0) {
            cr_assert_gt(p, 1e-3);
            cr_assert_gt(pk, 1e-3);
        } else {
            cr_assert_lt(p, 1e-6, "case %d: chi2 p = %g", kase, p);
            cr_assert_lt(pk, 1e-6, "case %d: KS p = %g", kase, pk);
        }
        pl_vdist_free(h);
    }
    for (int d = 0; d < 3; ++d) free(v[d]);
    free(all);
    gsl_rng_free(r);
}
