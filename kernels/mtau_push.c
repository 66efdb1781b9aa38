/* Multiple-tau correlator: the per-particle update of one sample
 * (Ramirez et al. 2010, Sec. II; the object and its rules are in
 * include/peloid/mtau.h and src/observe/mtau.c).
 *
 * Per-particle state, stride = levels (6 p + 3) doubles: per level, p slots
 * of (value[3], accumulated correlation[3]) and the running sum[3] of the
 * values for the level above; a sample touches level 0's 6 p + 3 contiguous
 * doubles and, 1/m^l as often, level l's.  A sample enters level 0 and, when
 * the owner says so, the levels above it (nrecv of them); each new value of a
 * level is correlated with the p - 1 values before it.
 *
 * OpenMP: particles are independent and each owns its slice of state, so a
 * static loop over particles is race-free and gives the same bits for any
 * thread count. */
#include "peloid/mtau.h"

static void push_one(const pl_mtau_push_t *pp, int levels, double v0, double v1, double v2,
                     double *restrict s)
{
    const int p = pp->p;
    const size_t lstride = 6 * (size_t)p + 3;
    double v[3] = {v0, v1, v2};
    const double inv_m = 1.0 / (double)pp->m;
    for (int l = 0; l < pp->nrecv; ++l) {
        double *b = s + (size_t)l * lstride; /* slot k: b[6k..6k+2] value, b[6k+3..6k+5] acc */
        if (l > 0 && pp->average) {
            double *below = b - lstride + 6 * (size_t)p;
            for (int d = 0; d < 3; ++d) {
                v[d] = below[d] * inv_m;
                below[d] = 0.0;
            }
        }
        const int h = pp->head[l];
        for (int d = 0; d < 3; ++d) b[6 * h + d] = v[d];
        if (pp->kind == PL_MTAU_MSD) {
            for (int j = pp->jmin[l]; j <= pp->jmax[l]; ++j) {
                int k = h - j < 0 ? h - j + p : h - j;
                for (int d = 0; d < 3; ++d) {
                    double u = v[d] - b[6 * k + d];
                    b[6 * j + 3 + d] += u * u;
                }
            }
        } else {
            for (int j = pp->jmin[l]; j <= pp->jmax[l]; ++j) {
                int k = h - j < 0 ? h - j + p : h - j;
                for (int d = 0; d < 3; ++d) b[6 * j + 3 + d] += v[d] * b[6 * k + d];
            }
        }
        if (pp->average && l + 1 < levels)
            for (int d = 0; d < 3; ++d) b[6 * (size_t)p + (size_t)d] += v[d];
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
