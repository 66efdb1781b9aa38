/* Multiple-tau correlator (src/observe/mtau.c, kernels/mtau_push.c).
 *
 * 1. Against a brute-force O(T^2) correlator of the series each level sees
 *    (the samples themselves at level 0, block means or every m-th sample
 *    above): equal to the last bit at every lag, both kinds, both rules, 1
 *    and 2 threads.  Level 0 is thereby the full brute force (all origins).
 * 2. MSD of an exact random walk (Gaussian steps, variance 2 D dt per axis):
 *    6 D t within 4 SE at one lag per decade; with averaging, the smoothing
 *    bias of the coarse levels is the predicted one; D from the slope.
 * 3. VACF of AR(1) velocities, C(t) = phi^t, with and without averaging. */
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/mtau.h"
#include "support.h"

static pl_mtau_t *make(size_t n, int p, int m, int levels, pl_mtau_kind_t kind, int average)
{
    pl_mtau_params_t par = {.n = n, .p = p, .m = m, .levels = levels, .kind = kind,
                            .average = average, .dt = 0.5};
    pl_mtau_t *c = NULL;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_mtau_create(&par, &c, &err), 0, "%s", err.msg);
    return c;
}

/* The values level l sees: V_l[k] for k < *nv (series of particle i, axis d
 * at s[(t * n + i) * 3 + d]). */
static double *level_series(const double *s, size_t T, size_t n, size_t i, int d, int l, int m,
                            int average, size_t *nv)
{
    double *v = malloc(T * sizeof *v);
    size_t len = T;
    for (size_t t = 0; t < T; ++t) v[t] = s[(t * n + i) * 3 + (size_t)d];
    for (int q = 0; q < l; ++q) {
        size_t nlen = average ? len / (size_t)m : (len + (size_t)m - 1) / (size_t)m;
        for (size_t k = 0; k < nlen; ++k) {
            if (average) {
                double acc = 0.0;
                for (int r = 0; r < m; ++r) acc += v[k * (size_t)m + (size_t)r];
                v[k] = acc * (1.0 / (double)m);
            } else {
                v[k] = v[k * (size_t)m];
            }
        }
        len = nlen;
    }
    *nv = len;
    return v;
}

static void brute(const double *s, size_t T, size_t n, int p, int m, int levels, pl_mtau_kind_t kind,
                  int average, double *value, uint64_t *origins)
{
    size_t k = 0;
    for (int l = 0; l < levels; ++l)
        for (int j = l ? p / m : 0; j < p; ++j, ++k) {
            double acc[PL_MTAU_COLS] = {0};
            size_t cnt = 0;
            double *a = calloc(n * 3, sizeof *a);
            for (size_t i = 0; i < n; ++i)
                for (int d = 0; d < 3; ++d) {
                    size_t nv;
                    double *v = level_series(s, T, n, i, d, l, m, average, &nv);
                    cnt = nv > (size_t)j ? nv - (size_t)j : 0;
                    for (size_t q = (size_t)j; q < nv; ++q) {
                        double u = kind == PL_MTAU_MSD ? (v[q] - v[q - (size_t)j]) * (v[q] - v[q - (size_t)j])
                                                       : v[q] * v[q - (size_t)j];
                        a[3 * i + (size_t)d] += u;
                    }
                    free(v);
                }
            origins[k] = cnt;
            for (int col = 0; col < PL_MTAU_COLS; ++col) {
                if (!cnt) {
                    value[PL_MTAU_COLS * k + (size_t)col] = NAN;
                    continue;
                }
                for (size_t i = 0; i < n; ++i) {
                    const double *ai = a + 3 * i;
                    acc[col] += (col < 3 ? ai[col] : ai[0] + ai[1] + ai[2]) / (double)cnt;
                }
                value[PL_MTAU_COLS * k + (size_t)col] = acc[col] / (double)n;
            }
            free(a);
        }
}

Test(mtau, equals_brute_force_bitwise)
{
    const size_t n = 5, T = 300;
    const int p = 8, m = 2, levels = pl_mtau_levels_for(T, p, m);
    cr_assert_eq(levels, 7); /* 7 * 2^5 = 224 < 299 <= 7 * 2^6 */
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 3);
    double *s = malloc(T * n * 3 * sizeof *s);
    for (size_t q = 0; q < T * n * 3; ++q) s[q] = (q >= n * 3 ? s[q - n * 3] : 0.0) + gsl_ran_gaussian(r, 1.0);
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *z = malloc(n * sizeof *z);
    for (int kind = 0; kind < 2; ++kind)
        for (int average = 0; average < 2; ++average) {
            pl_mtau_t *c1 = make(n, p, m, levels, (pl_mtau_kind_t)kind, average);
            pl_mtau_t *c2 = make(n, p, m, levels, (pl_mtau_kind_t)kind, average);
            for (size_t t = 0; t < T; ++t) {
                for (size_t i = 0; i < n; ++i) {
                    x[i] = s[(t * n + i) * 3 + 0];
                    y[i] = s[(t * n + i) * 3 + 1];
                    z[i] = s[(t * n + i) * 3 + 2];
                }
                pl_mtau_add(c1, x, y, z, 1);
                pl_mtau_add(c2, x, y, z, 2);
            }
            size_t nl = pl_mtau_nlags(c1);
            cr_assert_eq(nl, (size_t)(p + (levels - 1) * (p - p / m)));
            double *v1 = malloc(nl * PL_MTAU_COLS * sizeof *v1), *v2 = malloc(nl * PL_MTAU_COLS * sizeof *v2);
            double *vb = malloc(nl * PL_MTAU_COLS * sizeof *vb), *lag = malloc(nl * sizeof *lag);
            uint64_t *o1 = malloc(nl * sizeof *o1), *ob = malloc(nl * sizeof *ob);
            pl_mtau_result(c1, lag, o1, v1, NULL);
            pl_mtau_result(c2, NULL, NULL, v2, NULL);
            brute(s, T, n, p, m, levels, (pl_mtau_kind_t)kind, average, vb, ob);
            int with_data = 0;
            for (size_t k = 0; k < nl; ++k) {
                if (k) cr_assert_gt(lag[k], lag[k - 1], "lags increase");
                cr_assert_eq(o1[k], ob[k], "kind %d avg %d lag %g: origins %llu, brute %llu", kind,
                             average, lag[k], (unsigned long long)o1[k], (unsigned long long)ob[k]);
                with_data += o1[k] > 0;
                for (int col = 0; col < PL_MTAU_COLS; ++col) {
                    size_t q = PL_MTAU_COLS * k + (size_t)col;
                    int same = (isnan(v1[q]) && isnan(vb[q])) || v1[q] == vb[q];
                    cr_assert(same, "kind %d avg %d lag %g col %d: %.17g vs brute %.17g", kind, average,
                              lag[k], col, v1[q], vb[q]);
                    cr_assert(memcmp(&v1[q], &v2[q], sizeof(double)) == 0, "1 vs 2 threads");
                }
            }
            cr_assert_geq(with_data, 28); /* all but the top level: 4 or 5 values, lags j >= 4 */
            free(v1), free(v2), free(vb), free(lag), free(o1), free(ob);
            pl_mtau_free(c1);
            pl_mtau_free(c2);
        }
    free(s), free(x), free(y), free(z);
    gsl_rng_free(r);
}

Test(mtau, bad_params)
{
    pl_mtau_params_t par = {.n = 4, .p = 10, .m = 3, .levels = 4, .kind = PL_MTAU_MSD, .dt = 1.0};
    pl_mtau_t *c = NULL;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_mtau_create(&par, &c, &err), PL_ERR_INPUT);
    cr_assert(strstr(err.msg, "multiple of m"), "%s", err.msg);
    cr_assert_null(c);
    par.m = 2;
    par.levels = 0;
    cr_assert_eq(pl_mtau_create(&par, &c, &err), PL_ERR_INPUT);
}

/* Random walk, n = 400 particles, T = 2^14 samples (PL_QUICK: 100, 2^12),
 * D = 0.5, dt = 1 per sample (steps of variance 2 D dt = 1 per axis).  The SE is the spread over
 * the independent particles, so |MSD - expected| < 4 SE at each of the 5
 * checked lags fails by chance with probability ~3e-4. */
static void random_walk(int average)
{
    const int quick = pl_test_quick();
    const size_t n = quick ? 100 : 400, T = (size_t)1 << (quick ? 12 : 14);
    const double D = 0.5;
    const int p = 16, m = 2, levels = pl_mtau_levels_for(T, p, m);
    pl_mtau_params_t par = {.n = n, .p = p, .m = m, .levels = levels, .kind = PL_MTAU_MSD,
                            .average = average, .dt = 1.0};
    pl_mtau_t *c = NULL;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_mtau_create(&par, &c, &err), 0, "%s", err.msg);
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 2024u + (unsigned)average);
    double *x = calloc(n, sizeof *x), *y = calloc(n, sizeof *y), *z = calloc(n, sizeof *z);
    double sig = sqrt(2.0 * D);
    for (size_t t = 0; t < T; ++t) {
        pl_mtau_add(c, x, y, z, 1);
        for (size_t i = 0; i < n; ++i) {
            x[i] += gsl_ran_gaussian_ziggurat(r, sig);
            y[i] += gsl_ran_gaussian_ziggurat(r, sig);
            z[i] += gsl_ran_gaussian_ziggurat(r, sig);
        }
    }
    size_t nl = pl_mtau_nlags(c);
    double *lag = malloc(nl * sizeof *lag), *v = malloc(nl * PL_MTAU_COLS * sizeof *v);
    double *se = malloc(nl * PL_MTAU_COLS * sizeof *se);
    pl_mtau_result(c, lag, NULL, v, se);
    const double decades[] = {1, 10, 100, 1000, quick ? 2000 : 5000};
    int biased = 0;
    for (size_t q = 0; q < sizeof decades / sizeof *decades; ++q) {
        size_t k = 0;
        for (size_t kk = 0; kk < nl; ++kk)
            if (fabs(log(lag[kk] / decades[q])) < fabs(log(lag[k] / decades[q])) || lag[k] == 0.0) k = kk;
        /* Window of the level the lag belongs to: w = m^l, lag = j w. */
        double w = 1.0;
        for (size_t kk = (size_t)p; kk <= k; kk += (size_t)(p - p / m)) w *= m;
        double L = lag[k], expect = average ? L - (w * w - 1.0) / (3.0 * w) : L;
        expect *= 2.0 * D;
        for (int col = 0; col < PL_MTAU_COLS; ++col) {
            double e = col < 3 ? expect : 3.0 * expect, val = v[PL_MTAU_COLS * k + (size_t)col];
            double s = se[PL_MTAU_COLS * k + (size_t)col];
            cr_assert_lt(fabs(val - e), 4.0 * s, "avg %d lag %g col %d: MSD %g, expected %g, SE %g",
                         average, L, col, val, e, s);
            if (col == 3 && w > 1.0 && fabs(val - 6.0 * D * L) > 4.0 * s) biased = 1;
        }
        fprintf(stderr, "mtau MSD avg=%d lag %6.0f: %.5g +- %.2g (6Dt = %.5g, expected %.5g)\n", average,
                L, v[PL_MTAU_COLS * k + 3], se[PL_MTAU_COLS * k + 3], 6.0 * D * L, 3.0 * expect);
    }
    if (average && !quick) cr_assert(biased, "the averaging bias should be visible at some level >= 1 lag");
    if (!average) {
        /* D from the slope of the long-time MSD, per particle, then the SE
         * over particles: 4 SE again. */
        double slope[PL_MTAU_COLS], sse[PL_MTAU_COLS];
        cr_assert_eq(pl_mtau_slope(c, 50.0, (double)T / 5.0, slope, sse, &err), 0, "%s", err.msg);
        double Dfit = slope[3] / 6.0, Dse = sse[3] / 6.0;
        fprintf(stderr, "mtau random walk: D = %.4f +- %.4f (exact %.4f)\n", Dfit, Dse, D);
        cr_assert_lt(fabs(Dfit - D), 4.0 * Dse);
        cr_assert_lt(Dse, (quick ? 0.1 : 0.05) * D);
        cr_assert_neq(pl_mtau_slope(c, 1e9, 2e9, slope, sse, &err), 0);
    }
    free(lag), free(v), free(se), free(x), free(y), free(z);
    gsl_rng_free(r);
    pl_mtau_free(c);
}

Test(mtau, random_walk_msd_every_mth)
{
    random_walk(0);
}

Test(mtau, random_walk_msd_averaged)
{
    random_walk(1);
}

/* AR(1) velocities v_t = phi v_{t-1} + sqrt(1 - phi^2) g (unit variance):
 * C(L) = phi^L; block means of w samples L >= w apart correlate as
 * phi^L (sum_i phi^i)(sum_k phi^-k) / w^2.  4 SE at every lag. */
Test(mtau, ar1_vacf)
{
    const size_t n = 200, T = pl_test_quick() ? 5000 : 20000;
    const double phi = 0.9, cphi = sqrt(1.0 - phi * phi);
    const int p = 8, m = 2, levels = 10;
    for (int average = 0; average < 2; ++average) {
        pl_mtau_params_t par = {.n = n, .p = p, .m = m, .levels = levels, .kind = PL_MTAU_AUTO,
                                .average = average, .dt = 1.0};
        pl_mtau_t *c = NULL;
        pl_err_t err = {0, ""};
        cr_assert_eq(pl_mtau_create(&par, &c, &err), 0, "%s", err.msg);
        gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
        gsl_rng_set(r, 99u + (unsigned)average);
        double *v[3];
        for (int d = 0; d < 3; ++d) {
            v[d] = malloc(n * sizeof(double));
            for (size_t i = 0; i < n; ++i) v[d][i] = gsl_ran_gaussian_ziggurat(r, 1.0);
        }
        for (size_t t = 0; t < T; ++t) {
            pl_mtau_add(c, v[0], v[1], v[2], 1);
            for (int d = 0; d < 3; ++d)
                for (size_t i = 0; i < n; ++i) v[d][i] = phi * v[d][i] + cphi * gsl_ran_gaussian_ziggurat(r, 1.0);
        }
        size_t nl = pl_mtau_nlags(c);
        double *lag = malloc(nl * sizeof *lag), *val = malloc(nl * PL_MTAU_COLS * sizeof *val);
        double *se = malloc(nl * PL_MTAU_COLS * sizeof *se);
        pl_mtau_result(c, lag, NULL, val, se);
        double w = 1.0;
        for (size_t k = 0; k < nl; ++k) {
            if (k >= (size_t)p && (k - (size_t)p) % (size_t)(p - p / m) == 0) w *= m;
            double L = lag[k], expect = pow(phi, L);
            if (average && w > 1.0) {
                double s1 = 0.0, s2 = 0.0;
                for (int i = 0; i < (int)w; ++i) {
                    s1 += pow(phi, i);
                    s2 += pow(phi, -i);
                }
                expect *= s1 * s2 / (w * w);
            }
            double x = val[PL_MTAU_COLS * k + 3] / 3.0, s = se[PL_MTAU_COLS * k + 3] / 3.0;
            cr_assert_lt(fabs(x - expect), 4.0 * s + 1e-12, "avg %d lag %g: C = %g, expected %g, SE %g",
                         average, L, x, expect, s);
        }
        if (!average) {
            /* Green-Kubo (Hecht Eq. 35 with dt = 1): D = 1/2 + sum_j phi^j =
             * (1 + phi) / (2 (1 - phi)) = 9.5 per axis; truncated at t = 100
             * (tail phi^100 / (1 - phi) = 3e-4; the noise of the integral
             * grows with its length) and the trapezoid on the coarse grid (spacing
             * h = 2^l, relative error ~ (h ln phi)^2 / 12 on the tail it
             * covers: ~0.01 in all) against 4 SE. */
            double I[PL_MTAU_COLS], Ise[PL_MTAU_COLS];
            cr_assert_eq(pl_mtau_integral(c, 100.0, I, Ise, &err), 0, "%s", err.msg);
            double Dgk = I[3] / 3.0, Dse = Ise[3] / 3.0, Dexact = (1.0 + phi) / (2.0 * (1.0 - phi));
            cr_log_info("mtau AR(1) Green-Kubo: D = %.4f +- %.4f (exact %.4f)", Dgk, Dse, Dexact);
            cr_assert_lt(fabs(Dgk - Dexact), 4.0 * Dse + 0.01);
            cr_assert_neq(pl_mtau_integral(c, -1.0, I, Ise, &err), 0);
        }
        free(lag), free(val), free(se);
        for (int d = 0; d < 3; ++d) free(v[d]);
        gsl_rng_free(r);
        pl_mtau_free(c);
    }
}

/* A checkpoint of the state (both arrays copied into a fresh object with the
 * same parameters) continues bitwise: 2N samples = N + restart + N. */
Test(mtau, restart_continues_bitwise)
{
    const size_t n = 7, T = 500;
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 8);
    double *s = malloc(T * n * 3 * sizeof *s);
    for (size_t q = 0; q < T * n * 3; ++q) s[q] = gsl_ran_gaussian(r, 1.0);
    for (int average = 0; average < 2; ++average) {
        pl_mtau_t *a = make(n, 8, 2, 7, PL_MTAU_AUTO, average);
        pl_mtau_t *b = make(n, 8, 2, 7, PL_MTAU_AUTO, average);
        pl_mtau_t *b2 = make(n, 8, 2, 7, PL_MTAU_AUTO, average);
        for (size_t t = 0; t < T; ++t) {
            const double *x = s + t * n * 3;
            double xs[7], ys[7], zs[7];
            for (size_t i = 0; i < n; ++i) xs[i] = x[3 * i], ys[i] = x[3 * i + 1], zs[i] = x[3 * i + 2];
            pl_mtau_add(a, xs, ys, zs, 1);
            if (t == 333) { /* restart b into b2 at an odd sample */
                pl_mtau_state_t from = pl_mtau_state(b), to = pl_mtau_state(b2);
                cr_assert_eq(from.nvalues, to.nvalues);
                cr_assert_eq(from.ncounters, to.ncounters);
                memcpy(to.values, from.values, from.nvalues * sizeof(double));
                memcpy(to.counters, from.counters, from.ncounters * sizeof(uint64_t));
                pl_mtau_free(b);
                b = b2;
                b2 = NULL;
            }
            pl_mtau_add(b, xs, ys, zs, 1);
        }
        pl_mtau_state_t sa = pl_mtau_state(a), sb = pl_mtau_state(b);
        cr_assert_eq(memcmp(sa.values, sb.values, sa.nvalues * sizeof(double)), 0);
        cr_assert_eq(memcmp(sa.counters, sb.counters, sa.ncounters * sizeof(uint64_t)), 0);
        cr_assert_eq(pl_mtau_samples(b), (uint64_t)T);
        pl_mtau_free(a);
        pl_mtau_free(b);
    }
    free(s);
    gsl_rng_free(r);
}

/* A restart that runs longer than the first run planned for: the first run's
 * correlator (levels for T1 samples) grown to the levels for T samples
 * (pl_mtau_grow) and fed the rest equals, state and counters bitwise, the
 * correlator created with those levels and fed all T samples; for both kinds
 * (every-m-th rule). */
Test(mtau, grow_equals_planned_bitwise)
{
    const size_t n = 4, T1 = 60, T = 400;
    const int p = 8, m = 2, l1 = pl_mtau_levels_for(T1, p, m), l = pl_mtau_levels_for(T, p, m);
    cr_assert_lt(l1, l);
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 5);
    double x[4], y[4], z[4];
    for (int kind = 0; kind < 2; ++kind) {
        pl_mtau_t *full = make(n, p, m, l, (pl_mtau_kind_t)kind, 0), *part = make(n, p, m, l1, (pl_mtau_kind_t)kind, 0);
        pl_mtau_t *grown = NULL;
        for (size_t t = 0; t < T; ++t) {
            for (size_t i = 0; i < n; ++i) {
                x[i] = gsl_ran_gaussian(r, 1.0);
                y[i] = gsl_ran_gaussian(r, 1.0);
                z[i] = gsl_ran_gaussian(r, 1.0);
            }
            pl_mtau_add(full, x, y, z, 1);
            if (t < T1) {
                pl_mtau_add(part, x, y, z, 1);
            } else {
                if (!grown) {
                    pl_err_t err = {0, ""};
                    cr_assert_eq(pl_mtau_grow(part, l, &grown, &err), 0, "%s", err.msg);
                }
                pl_mtau_add(grown, x, y, z, 2);
            }
        }
        pl_mtau_state_t a = pl_mtau_state(full), b = pl_mtau_state(grown);
        cr_assert_eq(a.nvalues, b.nvalues);
        cr_assert_eq(a.ncounters, b.ncounters);
        cr_assert(!memcmp(a.values, b.values, a.nvalues * sizeof(double)), "kind %d: values differ", kind);
        cr_assert(!memcmp(a.counters, b.counters, a.ncounters * sizeof(uint64_t)), "kind %d: counters differ", kind);
        pl_mtau_free(full);
        pl_mtau_free(part);
        pl_mtau_free(grown);
    }
    gsl_rng_free(r);
}
