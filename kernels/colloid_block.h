/* A block of a colloid's neighbour-list partners copied into contiguous
 * arrays (private to kernels/): the SIMD loops of the pair kernels
 * (kernels/colloid_forces.c, kernels/colloid_slow.c) then read them with
 * plain vector loads.  gcc turns this copy into gathers with AVX-512; kept
 * scalar it was slower on a Zen 4 machine (bench/RESULTS_colloid.md). */
#ifndef PELOID_COLLOID_BLOCK_H
#define PELOID_COLLOID_BLOCK_H

#include "peloid/colloid_kernels.h"

/* Positions and radii of the partners in slots s0 .. s0 + m - 1 of nl. */
static inline void pl_colloid_gather_block(const pl_colloid_nlist_t *nl, int32_t s0, int m,
                                           const double *restrict x, const double *restrict y,
                                           const double *restrict z, const double *restrict rad,
                                           double *restrict gx, double *restrict gy,
                                           double *restrict gz, double *restrict gr)
{
    for (int k = 0; k < m; ++k) {
        size_t j = (size_t)nl->nbr[s0 + k];
        gx[k] = x[j];
        gy[k] = y[j];
        gz[k] = z[j];
        gr[k] = rad[j];
    }
}

#endif
