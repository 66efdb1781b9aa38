/* Clusters by union-find (src/observe/cluster.c) on constructed configurations whose
 * partition is known exactly, and on random ones against a brute-force O(n^2)
 * search; the result must not depend on the OpenMP thread count. */
#include <gsl/gsl_rng.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>

#include "peloid/cluster.h"
#include "support.h"

static pl_cluster_t *make(double L, int walls_z, double gap, double rmax, size_t nmax)
{
    pl_cluster_params_t par = {.box = {L, L, L}, .periodic = {1, 1, !walls_z}, .gap = gap,
                               .rad_max = rmax, .nmax = nmax};
    pl_cluster_t *c = NULL;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_cluster_create(&par, &c, &err), 0, "%s", err.msg);
    return c;
}

static void find(pl_cluster_t *c, size_t n, const double *x, const double *y, const double *z,
                 const double *r)
{
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_cluster_find(c, n, x, y, z, r, &err), 0, "%s", err.msg);
}

/* A chain of 10 spheres (radius 1) 2.5 apart: surface gaps 0.5.  Bonded for
 * gap 0.6 (one cluster), not for 0.4 (ten).  The chain runs across the
 * periodic boundary in x (x from 25 to 47.5 in a box of 30). */
Test(cluster, chain_across_boundary)
{
    enum { N = 10 };
    double x[N], y[N], z[N], r[N];
    for (int i = 0; i < N; ++i) {
        x[i] = fmod(25.0 + 2.5 * i, 30.0);
        y[i] = 5.0;
        z[i] = 5.0;
        r[i] = 1.0;
    }
    pl_cluster_t *c = make(30.0, 0, 0.6, 1.0, N);
    find(c, N, x, y, z, r);
    cr_assert_eq(pl_cluster_count(c), 1);
    cr_assert_eq(pl_cluster_largest(c), N);
    for (int i = 0; i < N; ++i) cr_assert_eq(pl_cluster_ids(c)[i], 0);
    pl_cluster_free(c);
    c = make(30.0, 0, 0.4, 1.0, N);
    find(c, N, x, y, z, r);
    cr_assert_eq(pl_cluster_count(c), N);
    cr_assert_eq(pl_cluster_largest(c), 1);
    for (int i = 0; i < N; ++i) cr_assert_eq(pl_cluster_ids(c)[i], i);
    pl_cluster_free(c);
}

/* Two interleaved rings of 12 (particle 2k in ring A, 2k+1 in ring B), ring A
 * centred on the box corner so that it crosses three periodic faces, ring B
 * in the middle; one free particle, index 24, touching nothing.  Ring
 * neighbours are 2 R sin(pi/12) = 2.07 apart for R = 4 (gap 0.07 for radius
 * 1), next-nearest 4.0 (gap 2.0). */
Test(cluster, interleaved_rings_and_canonical_ids)
{
    enum { N = 25 };
    const double L = 20.0, R = 4.0, pi = 3.14159265358979323846;
    double x[N], y[N], z[N], r[N];
    for (int k = 0; k < 12; ++k) {
        double a = 2.0 * pi * k / 12.0;
        x[2 * k] = fmod(L + R * cos(a), L); /* ring A about (0, 0, 0) */
        y[2 * k] = fmod(L + R * sin(a), L);
        z[2 * k] = fmod(L + 0.3 * R * sin(a), L);
        x[2 * k + 1] = 10.0 + R * cos(a);
        y[2 * k + 1] = 10.0;
        z[2 * k + 1] = 10.0 + R * sin(a);
    }
    x[24] = 14.0, y[24] = 3.0, z[24] = 17.0;
    for (int i = 0; i < N; ++i) r[i] = 1.0;
    pl_cluster_t *c = make(L, 0, 0.5, 1.0, N);
    find(c, N, x, y, z, r);
    const int32_t *id = pl_cluster_ids(c);
    for (int k = 0; k < 12; ++k) {
        cr_assert_eq(id[2 * k], 0, "ring A member %d has id %d", 2 * k, id[2 * k]);
        cr_assert_eq(id[2 * k + 1], 1, "ring B member %d has id %d", 2 * k + 1, id[2 * k + 1]);
    }
    cr_assert_eq(id[24], 24);
    size_t len;
    const uint64_t *h = pl_cluster_size_hist(c, &len);
    cr_assert_eq(len, (size_t)N + 1);
    cr_assert_eq(h[1], 1);
    cr_assert_eq(h[12], 2);
    cr_assert_eq(pl_cluster_count(c), 3);
    cr_assert_eq(pl_cluster_largest(c), 12);
    cr_assert_float_eq(pl_cluster_mean_size(c), 25.0 / 3.0, 1e-12);
    cr_assert_float_eq(pl_cluster_weight_mean_size(c), (1.0 + 2.0 * 144.0) / 25.0, 1e-12);
    pl_cluster_free(c);
}

/* Reference: every pair, union-find with the same canonical labels. */
static int32_t root(int32_t *p, int32_t i)
{
    while (p[i] != i) i = p[i];
    return i;
}

static void brute(size_t n, const double *x, const double *y, const double *z, const double *r, double L,
                  int walls_z, double gap, int32_t *id)
{
    for (size_t i = 0; i < n; ++i) id[i] = (int32_t)i;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            double d[3] = {x[j] - x[i], y[j] - y[i], z[j] - z[i]}, r2 = 0.0;
            for (int k = 0; k < 3; ++k) {
                if (k < 2 || !walls_z) d[k] -= L * nearbyint(d[k] / L);
                r2 += d[k] * d[k];
            }
            if (sqrt(r2) - r[i] - r[j] < gap) {
                int32_t a = root(id, (int32_t)i), b = root(id, (int32_t)j);
                if (a < b) id[b] = a;
                else if (b < a) id[a] = b;
            }
        }
    for (size_t i = 0; i < n; ++i) id[i] = root(id, (int32_t)i);
}

/* 3000 random spheres, radii in [0.3, 0.6], in a box of 16: near the
 * percolation of the bond graph for gap 0 (2.2 bonds a particle), so clusters of every size;
 * periodic and with walls in z (positions given unwrapped by up to one box
 * on the periodic axes), 1 and 2 threads. */
Test(cluster, random_matches_brute_force)
{
    const size_t n = 3000;
    const double L = 16.0, gap = 0.0;
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *z = malloc(n * sizeof *z);
    double *r = malloc(n * sizeof *r);
    int32_t *ref = malloc(n * sizeof *ref), *first = malloc(n * sizeof *first);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 12);
    for (int walls = 0; walls < 2; ++walls) {
        for (size_t i = 0; i < n; ++i) {
            x[i] = L * (3.0 * gsl_rng_uniform(rng) - 1.0);
            y[i] = L * gsl_rng_uniform(rng);
            z[i] = walls ? 0.6 + (L - 1.2) * gsl_rng_uniform(rng) : L * (3.0 * gsl_rng_uniform(rng) - 1.0);
            r[i] = 0.3 + 0.3 * gsl_rng_uniform(rng);
        }
        brute(n, x, y, z, r, L, walls, gap, ref);
        for (int th = 1; th <= 2; ++th) {
            omp_set_num_threads(th);
            pl_cluster_t *c = make(L, walls, gap, 0.6, n);
            find(c, n, x, y, z, r);
            const int32_t *id = pl_cluster_ids(c);
            for (size_t i = 0; i < n; ++i)
                cr_assert_eq(id[i], ref[i], "walls %d: particle %zu in cluster %d, brute force %d", walls, i,
                             id[i], ref[i]);
            if (th == 1) memcpy(first, id, n * sizeof *first);
            else cr_assert_eq(memcmp(first, id, n * sizeof *first), 0);
            size_t count = 0;
            for (size_t i = 0; i < n; ++i) count += ref[i] == (int32_t)i;
            cr_assert_eq(pl_cluster_count(c), count);
            if (th == 1)
                cr_log_info("walls %d: %zu clusters, largest %zu, weight-mean size %.1f", walls, count,
                            pl_cluster_largest(c), pl_cluster_weight_mean_size(c));
            cr_assert_gt(pl_cluster_largest(c), 20);
            cr_assert_gt(count, 100);
            pl_cluster_free(c);
        }
    }
    free(x), free(y), free(z), free(r), free(ref), free(first);
    gsl_rng_free(rng);
}

Test(cluster, bad_input)
{
    pl_cluster_params_t par = {.box = {4, 4, 4}, .periodic = {1, 1, 1}, .gap = 0.5, .rad_max = 1.0, .nmax = 3};
    pl_cluster_t *c = NULL;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_cluster_create(&par, &c, &err), PL_ERR_INPUT);
    cr_assert(strstr(err.msg, "half the periodic box"), "%s", err.msg);
    par.box[0] = par.box[1] = par.box[2] = 10.0;
    cr_assert_eq(pl_cluster_create(&par, &c, &err), 0, "%s", err.msg);
    double x[4] = {0}, r[4] = {1, 1, 2, 1};
    cr_assert_eq(pl_cluster_find(c, 4, x, x, x, r, &err), PL_ERR_INPUT);
    cr_assert_eq(pl_cluster_find(c, 3, x, x, x, r, &err), PL_ERR_INPUT);
    cr_assert(strstr(err.msg, "exceeds rad_max"), "%s", err.msg);
    pl_cluster_free(c);
}

/* A bond rule (pl_cluster_params_t.bond): a chain of 8 spheres 2.5 apart
 * (gaps 0.5, all within the candidate gap 0.6) where the rule bonds the pairs
 * (i, i+1) with i even as kind 1, i = 3 as kind 2 and refuses the others:
 * clusters {0,1}, {2,3,4,5}, {6,7}; 4 bonds of kind 1, 1 of kind 2.  Pairs
 * beyond the candidate gap never reach the rule (next-nearest: gap 3). */
static int alternate(const void *ctx, int32_t i, int32_t j, double r)
{
    int *calls = (int *)(uintptr_t)ctx;
    ++*calls;
    cr_expect(j == i + 1 && fabs(r - 2.5) < 1e-12, "pair (%d, %d) at %g", i, j, r);
    return i % 2 == 0 ? 1 : i == 3 ? 2 : 0;
}

Test(cluster, bond_rule_and_kinds)
{
    enum { N = 8 };
    double x[N], y[N], z[N], r[N];
    for (int i = 0; i < N; ++i) {
        x[i] = 3.0 + 2.5 * i;
        y[i] = z[i] = 5.0;
        r[i] = 1.0;
    }
    int calls = 0;
    pl_cluster_params_t par = {.box = {30, 30, 30}, .periodic = {1, 1, 1}, .gap = 0.6, .rad_max = 1.0,
                               .nmax = N, .bond = alternate, .bond_ctx = &calls};
    pl_cluster_t *c = NULL;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_cluster_create(&par, &c, &err), 0, "%s", err.msg);
    find(c, N, x, y, z, r);
    cr_expect_eq(calls, N - 1);
    cr_expect_eq(pl_cluster_count(c), 3);
    cr_expect_eq(pl_cluster_largest(c), 4);
    cr_expect_eq(pl_cluster_bonds(c, 1), 4);
    cr_expect_eq(pl_cluster_bonds(c, 2), 1);
    cr_expect_eq(pl_cluster_bonds(c, 0), 0);
    const int32_t want[N] = {0, 0, 2, 2, 2, 2, 6, 6};
    for (int i = 0; i < N; ++i) cr_expect_eq(pl_cluster_ids(c)[i], want[i], "id[%d] = %d", i, pl_cluster_ids(c)[i]);
    /* without the rule every candidate is a bond of kind 1 */
    pl_cluster_free(c);
    par.bond = NULL;
    cr_assert_eq(pl_cluster_create(&par, &c, &err), 0, "%s", err.msg);
    find(c, N, x, y, z, r);
    cr_expect(pl_cluster_count(c) == 1 && pl_cluster_bonds(c, 1) == N - 1 && pl_cluster_bonds(c, 2) == 0);
    pl_cluster_free(c);
}
