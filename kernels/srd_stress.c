/* Momentum-flux sums of the SRD fluid for the stress observer
 * (peloid/srd_kernels.h; src/observe/stress.c).  Blocks of STRESS_BLOCK
 * particles are summed in parallel and the block partials added in block
 * order, so the sums are bitwise independent of the thread count. */
#include <math.h>

#include "peloid/srd_kernels.h"

enum { STRESS_BLOCK = 8192 };

static void block_partial(const pl_fluid_t *f, const double s[3], size_t lo, size_t hi, double out[PL_STRESS_NSUMS])
{
    double acc[PL_STRESS_NSUMS] = {0};
    for (size_t i = lo; i < hi; ++i) {
        const double v[3] = {f->v[0][i], f->v[1][i], f->v[2][i]};
        double rho[3];
        for (int b = 0; b < 3; ++b) {
            const double x = (double)f->r[b][i] - s[b];
            rho[b] = x - floor(x) - 0.5;
        }
        acc[0] += v[0];
        acc[1] += v[1];
        acc[2] += v[2];
        acc[3] += v[0] * v[0];
        acc[4] += v[1] * v[1];
        acc[5] += v[2] * v[2];
        acc[6] += v[0] * v[1];
        acc[7] += v[0] * v[2];
        acc[8] += v[1] * v[2];
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) acc[9 + 3 * a + b] += v[a] * rho[b];
    }
    for (int k = 0; k < PL_STRESS_NSUMS; ++k) out[k] = acc[k];
}

size_t pl_srd_stress_scratch(size_t n) { return PL_STRESS_NSUMS * ((n + STRESS_BLOCK - 1) / STRESS_BLOCK + 1); }

void pl_srd_stress_sums(const pl_fluid_t *f, const double shift[3], double *scratch, double out[PL_STRESS_NSUMS],
                        int nthreads)
{
    const size_t nb = (f->n + STRESS_BLOCK - 1) / STRESS_BLOCK;
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t b = 0; b < nb; ++b) {
        const size_t lo = b * STRESS_BLOCK, hi = lo + STRESS_BLOCK < f->n ? lo + STRESS_BLOCK : f->n;
        block_partial(f, shift, lo, hi, scratch + PL_STRESS_NSUMS * b);
    }
    for (int k = 0; k < PL_STRESS_NSUMS; ++k) out[k] = 0.0;
    for (size_t b = 0; b < nb; ++b)
        for (int k = 0; k < PL_STRESS_NSUMS; ++k) out[k] += scratch[PL_STRESS_NSUMS * b + (size_t)k];
}

enum { LAYER_BLOCK = 65536 };

size_t pl_srd_layer_scratch(size_t n, int nlayers)
{
    return 2 * (size_t)nlayers * ((n + LAYER_BLOCK - 1) / LAYER_BLOCK + 1);
}

void pl_srd_layer_velocity(const pl_fluid_t *f, int nlayers, const double e[3], double *scratch, double *sum_v,
                           double *count, int nthreads)
{
    const size_t nb = (f->n + LAYER_BLOCK - 1) / LAYER_BLOCK, w = 2 * (size_t)nlayers;
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t b = 0; b < nb; ++b) {
        double *acc = scratch + w * b;
        for (size_t k = 0; k < w; ++k) acc[k] = 0.0;
        const size_t lo = b * LAYER_BLOCK, hi = lo + LAYER_BLOCK < f->n ? lo + LAYER_BLOCK : f->n;
        for (size_t i = lo; i < hi; ++i) {
            int k = (int)floor((double)f->r[2][i]);
            k = k < 0 ? 0 : k >= nlayers ? nlayers - 1 : k;
            acc[2 * k] += e[0] * f->v[0][i] + e[1] * f->v[1][i] + e[2] * f->v[2][i];
            acc[2 * k + 1] += 1.0;
        }
    }
    for (int k = 0; k < nlayers; ++k) sum_v[k] = count[k] = 0.0;
    for (size_t b = 0; b < nb; ++b)
        for (int k = 0; k < nlayers; ++k) {
            sum_v[k] += scratch[w * b + 2 * (size_t)k];
            count[k] += scratch[w * b + 2 * (size_t)k + 1];
        }
}
