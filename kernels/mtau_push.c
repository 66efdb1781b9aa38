/* Multiple-tau correlator: the per-particle update of one sample
 * (Ramirez et al. 2010, Sec. II; the object and its rules are in
 * include/peloid/mtau.h and src/mtau.c).
 *
 * Per-particle state, stride doubles: buf[levels][p][3], acc[levels][p][3],
 * csum[levels][3].  A sample enters level 0 and, when the owner says so, the
 * levels above it (nrecv of them); each new value of a level is correlated
 * with the p - 1 values before it.
 *
 * OpenMP: particles are independent and each owns its slice of state, so a
 * static loop over particles is race-free and gives the same bits for any
 * thread count. */
#include "peloid/mtau.h"

static void push_one(const pl_mtau_push_t *pp, int levels, double v0, double v1, double v2,
                     double *restrict s)
{
    const int p = pp->p;
    double *buf = s;
    double *acc = s + (size_t)levels * (size_t)p * 3;
    double *csum = acc + (size_t)levels * (size_t)p * 3;
    double v[3] = {v0, v1, v2};
    const double inv_m = 1.0 / (double)pp->m;
    for (int l = 0; l < pp->nrecv; ++l) {
        if (l > 0 && pp->average) {
            for (int d = 0; d < 3; ++d) {
                v[d] = csum[3 * (l - 1) + d] * inv_m;
                csum[3 * (l - 1) + d] = 0.0;
            }
        }
        double *b = buf + (size_t)l * (size_t)p * 3, *a = acc + (size_t)l * (size_t)p * 3;
        const int h = pp->head[l];
        for (int d = 0; d < 3; ++d) b[3 * h + d] = v[d];
        if (pp->kind == PL_MTAU_MSD) {
            for (int j = pp->jmin[l]; j <= pp->jmax[l]; ++j) {
                int k = h - j < 0 ? h - j + p : h - j;
                for (int d = 0; d < 3; ++d) {
                    double u = v[d] - b[3 * k + d];
                    a[3 * j + d] += u * u;
                }
            }
        } else {
            for (int j = pp->jmin[l]; j <= pp->jmax[l]; ++j) {
                int k = h - j < 0 ? h - j + p : h - j;
                for (int d = 0; d < 3; ++d) a[3 * j + d] += v[d] * b[3 * k + d];
            }
        }
        if (pp->average && l + 1 < levels)
            for (int d = 0; d < 3; ++d) csum[3 * l + d] += v[d];
    }
}

void pl_mtau_push(const pl_mtau_push_t *pp, size_t n, const double *x, const double *y,
                  const double *z, double *state, int nthreads)
{
    const size_t stride = (size_t)pp->stride;
    const int levels = pp->levels;
    if (nthreads < 1) nthreads = 1;
#pragma omp parallel for schedule(static) num_threads(nthreads) if (nthreads > 1)
    for (size_t i = 0; i < n; ++i) push_one(pp, levels, x[i], y[i], z[i], state + i * stride);
}
