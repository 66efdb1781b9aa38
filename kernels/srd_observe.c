/* Fluid observables with fixed-order reductions, and the fixed-point field
 * accumulator.
 *
 * pl_srd_observe sums over blocks of OBS_BLOCK particles in parallel, then
 * adds the block partials in block order: the result is bitwise independent
 * of the thread count (a reduction(+) clause would not be).
 * pl_srd_fields_accumulate adds integers (fixed point, 2^-24 resolution), so
 * the atomics' order does not matter either. */
#include <math.h>
#include <string.h>

#include "peloid/srd_kernels.h"

enum { OBS_BLOCK = 8192 };

static void block_partial(const pl_fluid_t *f, size_t lo, size_t hi, double out[5])
{
    double p0 = 0, p1 = 0, p2 = 0, k = 0, m = 0;
    for (size_t i = lo; i < hi; ++i) {
        double a = f->v[0][i], b = f->v[1][i], c = f->v[2][i];
        p0 += a; p1 += b; p2 += c;
        k += a * a + b * b + c * c;
    }
    if (f->tracked)
        for (size_t i = lo; i < hi; ++i)
            m += f->disp[0][i] * f->disp[0][i] + f->disp[1][i] * f->disp[1][i] +
                 f->disp[2][i] * f->disp[2][i];
    out[0] = p0; out[1] = p1; out[2] = p2; out[3] = k; out[4] = m;
}

size_t pl_srd_observe_scratch(size_t n) { return 5 * ((n + OBS_BLOCK - 1) / OBS_BLOCK + 1); }

void pl_srd_observe(const pl_fluid_t *f, double *scratch, pl_fluid_obs_t *obs, int nthreads)
{
    size_t nb = (f->n + OBS_BLOCK - 1) / OBS_BLOCK;
    double acc[5] = {0, 0, 0, 0, 0};
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t b = 0; b < nb; ++b) {
        size_t lo = b * OBS_BLOCK, hi = lo + OBS_BLOCK < f->n ? lo + OBS_BLOCK : f->n;
        block_partial(f, lo, hi, scratch + 5 * b);
    }
    for (size_t b = 0; b < nb; ++b)
        for (int k = 0; k < 5; ++k) acc[k] += scratch[5 * b + (size_t)k];
    for (int d = 0; d < 3; ++d) obs->momentum[d] = acc[d];
    obs->kinetic = 0.5 * acc[3];
    obs->msd = f->tracked && f->n ? acc[4] / (double)f->n : 0.0;
}

void pl_srd_fields_accumulate(const pl_fluid_t *f, const int L[3], int64_t *acc, int nthreads)
{
    const size_t ncell = (size_t)L[0] * (size_t)L[1] * (size_t)L[2];
    const double scale = (double)(1LL << PL_FIELD_FIXED_SHIFT);
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t i = 0; i < f->n; ++i) {
        int ix = (int)f->r[0][i], iy = (int)f->r[1][i], iz = (int)f->r[2][i];
        /* x = L exactly: on a wall (z walls, or x/y walls of a capillary) */
        if (ix >= L[0]) ix = L[0] - 1;
        if (iy >= L[1]) iy = L[1] - 1;
        if (iz >= L[2]) iz = L[2] - 1;
        size_t c = ((size_t)iz * (size_t)L[1] + (size_t)iy) * (size_t)L[0] + (size_t)ix;
#pragma omp atomic
        acc[c] += 1;
        for (int d = 0; d < 3; ++d) {
            int64_t q = (int64_t)llround(f->v[d][i] * scale);
#pragma omp atomic
            acc[(size_t)(d + 1) * ncell + c] += q;
        }
    }
}
