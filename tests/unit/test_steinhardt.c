/* Steinhardt bond order (peloid/steinhardt.h, src/observe/obs_steinhardt.c)
 * against analytic values.
 *
 * Perfect lattices in a periodic box, the cut-off between the first and the
 * second neighbour shell: every centre and the global order take the
 * lattice's values, fcc (12 neighbours) q4 = 0.19094, q6 = 0.57452; bcc (8)
 * q6 = 0.62854; sc (6) q4 = 0.76376, q6 = 0.35355 (five decimals: checked
 * to 1e-5).
 *
 * Ideal gas: the bond directions are independent and uniform, so E[Q_l^2]
 * = (1/C^2) sum_bonds (1/n_i + 1/n_j)^2 for the configuration's neighbour
 * counts n (C centres with a neighbour; ~1/bonds).  Q_l^2 / E[Q_l^2] of one
 * configuration is a chi^2 of ~2l+1 degrees of freedom over 2l+1 (relative
 * sd sqrt(2/13) = 0.39 for l = 6); the mean over 60 configurations is 1 +-
 * 0.05, checked within 4 sigma, [0.8, 1.2]. */
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

#include "peloid/steinhardt.h"
#include "support.h"

/* Lattice: k^3 cubic cells of edge 1, nb basis points each. */
static size_t lattice(int k, const double (*basis)[3], int nb, double *x, double *y, double *z)
{
    size_t n = 0;
    for (int a = 0; a < k; ++a)
        for (int b = 0; b < k; ++b)
            for (int c = 0; c < k; ++c)
                for (int s = 0; s < nb; ++s, ++n) {
                    x[n] = a + basis[s][0];
                    y[n] = b + basis[s][1];
                    z[n] = c + basis[s][2];
                }
    return n;
}

static void check_lattice(const double (*basis)[3], int nb, double rmax, size_t neighbours, double q4, double q6)
{
    const int k = 4;
    double *x = malloc(4 * 64 * 3 * sizeof(double)), *y = x + 256, *z = y + 256, q[2 * 256];
    const size_t n = lattice(k, basis, nb, x, y, z);
    pl_steinhardt_params_t p = {.box = {k, k, k}, .periodic = {1, 1, 1}, .rmax = rmax};
    pl_steinhardt_result_t r;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_steinhardt(&p, n, x, y, z, q, &r, &err), 0, "%s", err.msg);
    cr_assert_eq(r.bonds, n * neighbours / 2, "bonds %zu, expected %zu", r.bonds, n * neighbours / 2);
    cr_assert_eq(r.centres, n);
    const double want[2] = {q4, q6};
    for (int l = 0; l < 2; ++l) {
        if (!(want[l] >= 0)) continue;
        cr_assert(fabs(r.Q[l] - want[l]) < 1e-5, "global Q%d %.6f, expected %.5f", 4 + 2 * l, r.Q[l], want[l]);
        cr_assert(fabs(r.q_mean[l] - want[l]) < 1e-5, "mean q%d %.6f", 4 + 2 * l, r.q_mean[l]);
        for (size_t i = 0; i < n; ++i)
            cr_assert(fabs(q[2 * i + (size_t)l] - want[l]) < 1e-5, "q%d of centre %zu: %.6f", 4 + 2 * l, i,
                      q[2 * i + (size_t)l]);
    }
    free(x);
}

Test(steinhardt, fcc)
{
    static const double b[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    check_lattice(b, 4, 0.85, 12, 0.19094, 0.57452); /* shells at 0.707, 1 */
}

Test(steinhardt, bcc)
{
    static const double b[2][3] = {{0, 0, 0}, {0.5, 0.5, 0.5}};
    check_lattice(b, 2, 0.93, 8, NAN, 0.62854); /* shells at 0.866, 1 */
}

Test(steinhardt, sc)
{
    static const double b[1][3] = {{0.25, 0.25, 0.25}};
    check_lattice(b, 1, 1.2, 6, 0.76376, 0.35355); /* shells at 1, 1.414 */
}

Test(steinhardt, ideal_gas_global_order_is_noise)
{
    enum { N = 400, REPS = 60 };
    const double L = 10.0, rmax = 1.6;
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, 7);
    double x[N], y[N], z[N], ratio = 0.0, qb = 0.0;
    for (int rep = 0; rep < REPS; ++rep) {
        for (int i = 0; i < N; ++i) x[i] = L * gsl_rng_uniform(g), y[i] = L * gsl_rng_uniform(g), z[i] = L * gsl_rng_uniform(g);
        pl_steinhardt_params_t p = {.box = {L, L, L}, .periodic = {1, 1, 1}, .rmax = rmax};
        pl_steinhardt_result_t r;
        pl_err_t err = {0, ""};
        cr_assert_eq(pl_steinhardt(&p, N, x, y, z, NULL, &r, &err), 0, "%s", err.msg);
        /* the neighbour counts, then E[Q^2] = (1/C^2) sum_bonds (1/n_i + 1/n_j)^2 */
        int nb[N] = {0};
        size_t bonds = 0;
        for (int pass = 0; pass < 2; ++pass) {
            double e = 0.0;
            for (int i = 0; i < N; ++i)
                for (int j = i + 1; j < N; ++j) {
                    double d[3] = {x[j] - x[i], y[j] - y[i], z[j] - z[i]}, r2 = 0.0;
                    for (int a = 0; a < 3; ++a) d[a] -= L * round(d[a] / L), r2 += d[a] * d[a];
                    if (r2 >= rmax * rmax) continue;
                    if (pass == 0) nb[i]++, nb[j]++, bonds++;
                    else e += pow(1.0 / nb[i] + 1.0 / nb[j], 2);
                }
            if (pass == 1) {
                cr_assert_eq(r.bonds, bonds);
                ratio += r.Q[1] * r.Q[1] / (e / ((double)r.centres * (double)r.centres));
                qb += r.Q[1] * sqrt((double)bonds);
            }
        }
    }
    gsl_rng_free(g);
    ratio /= REPS;
    cr_assert(ratio > 0.8 && ratio < 1.2, "ideal gas: <Q6^2 / E[Q6^2]> = %.3f, expected 1 +- 0.05 (4 sigma)", ratio);
    cr_assert(qb / REPS < 2.0, "ideal gas: <Q6 sqrt(bonds)> = %.3f, expected ~1", qb / REPS);
}
