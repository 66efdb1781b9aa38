/* S(q) by the direct sum (src/observe/sq.c).
 *
 * Lattice: a simple cubic lattice of 64 points 4 apart in a box of 16 has
 * S = N = 64 on its reciprocal lattice (n a multiple of 4 on each axis) and 0
 * at every other wave vector of the box, exactly up to round-off (1e-9 N).
 * The bins (width 0.01 / a0) are narrower than the gap between neighbouring
 * shells |n|^2 = k, k + 1 near |n| = 4 (0.048 / a0), so a bin holds one shell.
 * Ideal gas: 1000 independent samples of 200 uniform points give S = 1
 * within 4 SE in every bin with vectors (4 SE fails by chance 6e-5 per bin:
 * at most ~3e-3 over the 38 bins with vectors; the seed is fixed), and chi^2 per bin
 * below 1.5.  Thread count: bitwise the same result at 1 and 3 threads. */
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/sq.h"
#include "support.h"

Test(sq, simple_cubic_lattice)
{
    enum { N = 64, NB = 200 };
    double x[N], y[N], z[N];
    for (int i = 0; i < N; ++i) {
        x[i] = 4.0 * (i % 4) + 1.0;
        y[i] = 4.0 * ((i / 4) % 4) + 1.0;
        z[i] = 4.0 * (i / 16) + 1.0;
    }
    pl_sq_params_t par = {.box = {16, 16, 16}, .qmax = 2.0, .nbins = NB, .nmax = N};
    pl_sq_t *s = NULL;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_sq_create(&par, 1, &s, &err), 0, "%s", err.msg);
    pl_sq_sample(s, N, x, y, z);
    double q[NB], qm[NB], S[NB];
    uint64_t nv[NB];
    pl_sq_result(s, q, qm, S, NULL, nv);
    const double dq = 2.0 * PL_PI / 16.0;
    int lattice_bins = 0, other_bins = 0;
    for (int b = 0; b < NB; ++b) {
        if (!nv[b]) continue;
        const double n2 = qm[b] * qm[b] / (dq * dq); /* the shell |n|^2 of this bin */
        cr_assert(fabs(n2 - rint(n2)) < 1e-9, "bin %d holds more than one shell (%g)", b, n2);
        /* |n|^2 = 16 is the one shell below qmax (|n| < 5.09) on the reciprocal
         * lattice: (4, 0, 0) and its permutations */
        if ((long)rint(n2) == 16) {
            cr_expect(nv[b] == 3 && fabs(S[b] - N) < 1e-9 * N, "S(2 pi / 4) = %.12g (%llu vectors)", S[b],
                      (unsigned long long)nv[b]);
            lattice_bins++;
        } else {
            cr_expect(fabs(S[b]) < 1e-9 * N, "S at |n|^2 = %g: %.3g, want 0", n2, S[b]);
            other_bins++;
        }
    }
    cr_expect_eq(lattice_bins, 1);
    cr_expect(other_bins > 20);
    pl_sq_free(s);
}

static void gas(int nthreads, double *S, double *se, size_t nb)
{
    enum { N = 200 };
    const int nsamp = pl_test_quick() ? 100 : 1000;
    double x[N], y[N], z[N];
    pl_sq_params_t par = {.box = {10, 10, 10}, .qmax = 5.0, .nbins = nb, .nmax = N};
    pl_sq_t *s = NULL;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_sq_create(&par, nthreads, &s, &err), 0, "%s", err.msg);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 17);
    for (int k = 0; k < nsamp; ++k) {
        for (int i = 0; i < N; ++i) {
            x[i] = 10.0 * gsl_rng_uniform(rng);
            y[i] = 10.0 * gsl_rng_uniform(rng);
            z[i] = 10.0 * gsl_rng_uniform(rng);
        }
        pl_sq_sample(s, N, x, y, z);
    }
    cr_assert_eq(pl_sq_samples(s), (uint64_t)nsamp);
    pl_sq_result(s, NULL, NULL, S, se, NULL);
    gsl_rng_free(rng);
    pl_sq_free(s);
}

Test(sq, ideal_gas_and_threads)
{
    enum { NB = 50 };
    double S[NB], se[NB], S3[NB], se3[NB];
    gas(1, S, se, NB);
    gas(3, S3, se3, NB);
    double chi2 = 0.0;
    int used = 0;
    for (int b = 0; b < NB; ++b) {
        cr_expect(memcmp(&S[b], &S3[b], sizeof S[b]) == 0 && memcmp(&se[b], &se3[b], sizeof se[b]) == 0,
                  "bin %d differs between 1 and 3 threads", b);
        if (isnan(S[b])) continue; /* no wave vector in the bin (|q| < 2 pi / L) */
        double zz = (S[b] - 1.0) / se[b];
        cr_expect(fabs(zz) < 4.0, "bin %d: S = %.4f +- %.4f", b, S[b], se[b]);
        chi2 += zz * zz;
        used++;
    }
    cr_expect(used > 30, "%d bins with vectors", used); /* 38: the low-q bins between shells are empty */
    cr_expect(chi2 / used < 1.5, "chi^2 per bin %.3f over %d bins", chi2 / used, used);
    cr_log_info("ideal gas: chi^2 per bin %.3f over %d bins", chi2 / used, used);
}
