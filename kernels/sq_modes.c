/* The per-sample sum of the static structure factor S(q) (include/peloid/sq.h;
 * Hecht Sec. IX.C, PL Fig. 4 in reciprocal space): per-axis phase tables
 * exp(i 2 pi m x_j / L), then for each kept wave vector
 * S(q) = |sum_j exp(i q . r_j)|^2 / N from three complex products per
 * particle.
 *
 * OpenMP: the tables are split over particles and the sums over wave
 * vectors, both static loops in which each iteration writes only its own
 * entries, and each vector's sum runs over the particles in index order: the
 * result is bitwise the same for any thread count. */
#include <math.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/sq.h"

void pl_sq_modes(const pl_sq_modes_params_t *p, size_t n, const double *x, const double *y, const double *z,
                 double *tab, double *sv, int nthreads)
{
    const double *in[3] = {x, y, z};
    double *tb[3];
    size_t w[3];
    tb[0] = tab;
    for (int d = 0; d < 3; ++d) {
        w[d] = (size_t)(2 * p->nm[d] + 1);
        if (d < 2) tb[d + 1] = tb[d] + 2 * w[d] * n;
    }
    /* tables: tb[d][2 (j w + (m + nm))] = cos, sin of 2 pi m x_j / L */
    for (int d = 0; d < 3; ++d) {
        const double k0 = 2.0 * PL_PI / p->box[d];
        const int nm = p->nm[d];
#pragma omp parallel for num_threads(nthreads) schedule(static)
        for (size_t j = 0; j < n; ++j)
            for (int m = -nm; m <= nm; ++m) {
                double ph = k0 * (double)m * in[d][j];
                tb[d][2 * (j * w[d] + (size_t)(m + nm))] = cos(ph);
                tb[d][2 * (j * w[d] + (size_t)(m + nm)) + 1] = sin(ph);
            }
    }
#pragma omp parallel for num_threads(nthreads) schedule(static)
    for (size_t k = 0; k < p->nvec; ++k) {
        const size_t oa = 2 * (size_t)(p->vec[3 * k] + p->nm[0]), ob = 2 * (size_t)(p->vec[3 * k + 1] + p->nm[1]),
                     oc = 2 * (size_t)(p->vec[3 * k + 2] + p->nm[2]);
        double re = 0.0, im = 0.0;
        for (size_t j = 0; j < n; ++j) {
            const double *ta = tb[0] + 2 * j * w[0] + oa, *tbb = tb[1] + 2 * j * w[1] + ob,
                         *tc = tb[2] + 2 * j * w[2] + oc;
            double pr = ta[0] * tbb[0] - ta[1] * tbb[1], pi = ta[0] * tbb[1] + ta[1] * tbb[0];
            re += pr * tc[0] - pi * tc[1];
            im += pr * tc[1] + pi * tc[0];
        }
        sv[k] = (re * re + im * im) / (double)n;
    }
}
