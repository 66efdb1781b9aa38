/* g(r) (src/observe/rdf.c, kernels/rdf_count.c).
 *
 * Ideal gas: uniform independent points give g = 1 at every r, in a periodic
 * box and in a slab with walls in z (where the accessible-volume
 * normalisation of peloid/rdf.h is what makes it 1: the periodic one would be
 * off by the factor F(r): 1 - r/(2h) up to r = h, h/(2r) = 1/3 at r = 6 in the
 * slab used).
 * Each bin's SE comes from blocking over 1000 independent samples; 4 SE on
 * each of 40 bins fails by chance with probability 40 x 6e-5 = 2.5e-3 (the
 * seeds are fixed, so a pass is reproducible).
 * Lattices: the pair counts land exactly on the known shells with the known
 * coordination numbers. */
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "peloid/rdf.h"
#include "support.h"

static void ideal_gas(int z_walls)
{
    const size_t n = 300, nb = 40;
    const int nsamp = 1000;
    pl_rdf_params_t par = {.box = {12.0, 12.0, z_walls ? 7.0 : 12.0}, .z_walls = z_walls,
                           .zlo = 1.0, .zhi = 5.0, .rmax = 6.0, .nbins = nb, .class_a = -1,
                           .class_b = -1};
    pl_rdf_t *r = NULL;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_rdf_create(&par, 1, &r, &err), 0, "%s", err.msg);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 5u + (unsigned)z_walls);
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *z = malloc(n * sizeof *z);
    for (int s = 0; s < nsamp; ++s) {
        for (size_t i = 0; i < n; ++i) {
            x[i] = par.box[0] * gsl_rng_uniform(rng);
            y[i] = par.box[1] * gsl_rng_uniform(rng);
            z[i] = z_walls ? par.zlo + (par.zhi - par.zlo) * gsl_rng_uniform(rng)
                           : par.box[2] * gsl_rng_uniform(rng);
        }
        pl_rdf_sample(r, n, x, y, z, NULL);
    }
    double rm[40], g[40], se[40];
    int pl[40];
    pl_rdf_result(r, rm, g, se, pl);
    double chi2 = 0.0;
    int plateaus = 0;
    for (size_t b = 0; b < nb; ++b) {
        plateaus += pl[b];
        cr_assert_lt(fabs(g[b] - 1.0), 4.0 * se[b], "walls %d r = %.3f: g = %.4f +- %.4f", z_walls, rm[b],
                     g[b], se[b]);
        chi2 += (g[b] - 1.0) * (g[b] - 1.0) / (se[b] * se[b]);
    }
    fprintf(stderr, "rdf ideal gas (walls %d): chi2 of g = 1 over %zu bins = %.1f; g(%.2f) = %.4f +- %.4f\n",
            z_walls, nb, chi2, rm[nb - 1], g[nb - 1], se[nb - 1]);
    cr_assert_eq(pl_rdf_samples(r), (uint64_t)nsamp);
    /* independent samples: the blocking rule should find its plateau */
    cr_assert_geq(plateaus, 36, "plateau in %d of 40 bins", plateaus);
    free(x), free(y), free(z);
    gsl_rng_free(rng);
    pl_rdf_free(r);
}

Test(rdf, ideal_gas_periodic)
{
    ideal_gas(0);
}

Test(rdf, ideal_gas_slab)
{
    ideal_gas(1);
}

/* The slab normalisation integrates to the exact pair-distance distribution:
 * summed over all r it is 1 (r up to the box diagonal is not reachable with
 * the minimum image, so check G(r) against a direct quadrature of
 * 4 pi r^2 F(r) instead, on both sides of r = h). */
Test(rdf, slab_fraction_formula)
{
    pl_rdf_params_t par = {.box = {20.0, 20.0, 5.0}, .z_walls = 1, .zlo = 0.5, .zhi = 3.5, .rmax = 9.0,
                           .nbins = 1};
    double h = 3.0, V = 20.0 * 20.0 * h;
    const double pi = 3.14159265358979323846;
    for (double r2 = 0.5; r2 <= 9.0; r2 += 0.5) {
        double q = 0.0;
        const int K = 20000;
        for (int k = 0; k < K; ++k) { /* midpoint rule */
            double r = r2 * ((double)k + 0.5) / K;
            double F = r <= h ? 1.0 - r / (2.0 * h) : h / (2.0 * r);
            q += 4.0 * pi * r * r * F * (r2 / K);
        }
        cr_assert_float_eq(pl_rdf_ideal_fraction(&par, 0.0, r2), q / V, 1e-7 * q / V, "r = %g", r2);
    }
}

static void lattice_counts(const double *x, const double *y, const double *z, size_t n, double L, double rmax,
                           size_t nb, const double *shell, const int *coord, int nshell)
{
    for (int th = 1; th <= 2; ++th) {
        pl_rdf_params_t par = {.box = {L, L, L}, .rmax = rmax, .nbins = nb, .class_a = -1, .class_b = -1};
        pl_rdf_t *r = NULL;
        pl_err_t err = {0, ""};
        cr_assert_eq(pl_rdf_create(&par, th, &r, &err), 0, "%s", err.msg);
        pl_rdf_sample(r, n, x, y, z, NULL);
        const uint64_t *h = pl_rdf_counts(r);
        uint64_t *want = calloc(nb, sizeof *want);
        double dr = rmax / (double)nb;
        for (int s = 0; s < nshell; ++s) {
            double f = shell[s] / dr;
            cr_assert_gt(fabs(f - nearbyint(f)), 0.2, "shell %g on a bin edge", shell[s]);
            want[(size_t)f] += (uint64_t)n * (uint64_t)coord[s] / 2;
        }
        for (size_t b = 0; b < nb; ++b)
            cr_assert_eq(h[b], want[b], "%d threads, bin %zu (r = %.4f): %llu pairs, want %llu", th, b,
                         dr * ((double)b + 0.5), (unsigned long long)h[b], (unsigned long long)want[b]);
        free(want);
        pl_rdf_free(r);
    }
}

Test(rdf, simple_cubic_shells)
{
    const int c = 6;
    const size_t n = (size_t)(c * c * c);
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *z = malloc(n * sizeof *z);
    size_t q = 0;
    for (int i = 0; i < c; ++i)
        for (int j = 0; j < c; ++j)
            for (int k = 0; k < c; ++k, ++q) {
                x[q] = i + 0.25;
                y[q] = j + 0.25;
                z[q] = k + 0.25;
            }
    const double shell[] = {1.0, sqrt(2.0), sqrt(3.0), 2.0, sqrt(5.0), sqrt(6.0), sqrt(8.0)};
    const int coord[] = {6, 12, 8, 6, 24, 24, 12};
    lattice_counts(x, y, z, n, (double)c, 2.99, 291, shell, coord, 7);
    free(x), free(y), free(z);
}

Test(rdf, fcc_shells)
{
    const int c = 4;
    const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    const size_t n = 4 * (size_t)(c * c * c);
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *z = malloc(n * sizeof *z);
    size_t q = 0;
    for (int i = 0; i < c; ++i)
        for (int j = 0; j < c; ++j)
            for (int k = 0; k < c; ++k)
                for (int b = 0; b < 4; ++b, ++q) {
                    x[q] = i + basis[b][0] + 0.1;
                    y[q] = j + basis[b][1] + 0.1;
                    z[q] = k + basis[b][2] + 0.1;
                }
    /* fcc, cube edge 1: r^2 = s/2 for s = 1..7 with 12, 6, 24, 12, 24, 8, 48 */
    const double shell[] = {sqrt(0.5), 1.0, sqrt(1.5), sqrt(2.0), sqrt(2.5), sqrt(3.0), sqrt(3.5)};
    const int coord[] = {12, 6, 24, 12, 24, 8, 48};
    lattice_counts(x, y, z, n, (double)c, 1.99, 212, shell, coord, 7);
    free(x), free(y), free(z);
}

Test(rdf, bad_params)
{
    pl_rdf_params_t par = {.box = {10, 10, 10}, .rmax = 6.0, .nbins = 10, .class_a = -1, .class_b = -1};
    pl_rdf_t *r = NULL;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_rdf_create(&par, 1, &r, &err), PL_ERR_INPUT);
    cr_assert(strstr(err.msg, "half the periodic box"), "%s", err.msg);
    par.rmax = 4.0;
    par.z_walls = 1;
    par.zlo = par.zhi = 2.0;
    cr_assert_eq(pl_rdf_create(&par, 1, &r, &err), PL_ERR_INPUT);
    cr_assert_null(r);
    par.z_walls = 0;
    par.class_a = 1;
    cr_assert_eq(pl_rdf_create(&par, 1, &r, &err), PL_ERR_INPUT);
    cr_assert(strstr(err.msg, "classes"), "%s", err.msg);
}

/* Partial g_ab on the rock-salt colouring of a simple cubic lattice (class
 * (i + j + k) mod 2): unlike neighbours at 1, sqrt 3, sqrt 5 (6, 8, 24 of
 * them), like ones at sqrt 2, 2, sqrt 6, sqrt 8 (12, 6, 24, 12); 1 and 2
 * threads. */
Test(rdf, partial_rock_salt)
{
    const int c = 6;
    const size_t n = (size_t)(c * c * c), nb = 291;
    const double rmax = 2.99, dr = rmax / (double)nb;
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *z = malloc(n * sizeof *z);
    int32_t *cls = malloc(n * sizeof *cls);
    size_t q = 0;
    for (int i = 0; i < c; ++i)
        for (int j = 0; j < c; ++j)
            for (int k = 0; k < c; ++k, ++q) {
                x[q] = i + 0.5, y[q] = j + 0.5, z[q] = k + 0.5;
                cls[q] = (i + j + k) % 2;
            }
    const double sh_ab[] = {1.0, sqrt(3.0), sqrt(5.0)}, sh_aa[] = {sqrt(2.0), 2.0, sqrt(6.0), sqrt(8.0)};
    const int co_ab[] = {6, 8, 24}, co_aa[] = {12, 6, 24, 12};
    for (int th = 1; th <= 2; ++th)
        for (int kind = 0; kind < 3; ++kind) { /* (0,1), (1,0), (0,0) */
            pl_rdf_params_t par = {.box = {c, c, c}, .rmax = rmax, .nbins = nb,
                                   .class_a = kind == 1 ? 1 : 0, .class_b = kind == 0 ? 1 : 0};
            pl_rdf_t *r = NULL;
            pl_err_t err = {0, ""};
            cr_assert_eq(pl_rdf_create(&par, th, &r, &err), 0, "%s", err.msg);
            pl_rdf_sample(r, n, x, y, z, cls);
            const uint64_t *h = pl_rdf_counts(r);
            uint64_t *want = calloc(nb, sizeof *want);
            const double *sh = kind < 2 ? sh_ab : sh_aa;
            const int *co = kind < 2 ? co_ab : co_aa, ns = kind < 2 ? 3 : 4;
            /* n/2 particles of a class; unlike pairs n/2 * co, like n/2 * co / 2 */
            for (int s = 0; s < ns; ++s)
                want[(size_t)(sh[s] / dr)] += (uint64_t)(n / 2) * (uint64_t)co[s] / (kind < 2 ? 1 : 2);
            for (size_t b = 0; b < nb; ++b)
                cr_assert_eq(h[b], want[b], "kind %d, %d threads, r = %.3f: %llu, want %llu", kind, th,
                             dr * ((double)b + 0.5), (unsigned long long)h[b], (unsigned long long)want[b]);
            double g[291];
            pl_rdf_result(r, NULL, g, NULL, NULL);
            size_t b1 = (size_t)(sh[0] / dr);
            double P = pl_rdf_ideal_fraction(&par, dr * (double)b1, dr * (double)(b1 + 1));
            double npair = kind < 2 ? (double)(n / 2) * (double)(n / 2) : 0.5 * (double)(n / 2) * (double)(n / 2 - 1);
            cr_assert_float_eq(g[b1], (double)want[b1] / (npair * P), 1e-12 * g[b1]);
            free(want);
            pl_rdf_free(r);
        }
    free(x), free(y), free(z), free(cls);
}

/* The state view continues bitwise: 20 samples = 9 + copy into a fresh
 * object + 11, counts and per-bin blocking alike. */
Test(rdf, restart_continues_bitwise)
{
    const size_t n = 50;
    pl_rdf_params_t par = {.box = {8, 8, 8}, .rmax = 4.0, .nbins = 16, .class_a = -1, .class_b = -1};
    pl_rdf_t *a = NULL, *b = NULL, *b2 = NULL;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_rdf_create(&par, 1, &a, &err), 0, "%s", err.msg);
    cr_assert_eq(pl_rdf_create(&par, 2, &b, &err), 0, "%s", err.msg);
    cr_assert_eq(pl_rdf_create(&par, 1, &b2, &err), 0, "%s", err.msg);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 6);
    double x[50], y[50], z[50];
    for (int s = 0; s < 20; ++s) {
        for (size_t i = 0; i < n; ++i)
            x[i] = 8.0 * gsl_rng_uniform(rng), y[i] = 8.0 * gsl_rng_uniform(rng), z[i] = 8.0 * gsl_rng_uniform(rng);
        if (s == 9) {
            pl_rdf_state_t from = pl_rdf_state(b), to = pl_rdf_state(b2);
            memcpy(to.counts, from.counts, from.ncounts * sizeof *from.counts);
            memcpy(to.blocking, from.blocking, from.nblocking * sizeof *from.blocking);
            pl_rdf_free(b);
            b = b2;
        }
        pl_rdf_sample(a, n, x, y, z, NULL);
        pl_rdf_sample(b, n, x, y, z, NULL);
    }
    pl_rdf_state_t sa = pl_rdf_state(a), sb = pl_rdf_state(b);
    cr_assert_eq(memcmp(sa.counts, sb.counts, sa.ncounts * sizeof *sa.counts), 0);
    cr_assert_eq(memcmp(sa.blocking, sb.blocking, sa.nblocking * sizeof *sa.blocking), 0);
    cr_assert_eq(pl_rdf_samples(b), 20);
    pl_rdf_free(a);
    pl_rdf_free(b);
    gsl_rng_free(rng);
}
