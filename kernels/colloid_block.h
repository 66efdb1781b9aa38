/* A block of a colloid's neighbour-list partners copied into contiguous
 * arrays (private to kernels/): the SIMD loops of the pair kernels
 * (kernels/colloid_forces.c, kernels/colloid_slow.c) then read them with
 * plain vector loads.  gcc turns this copy into gathers with AVX-512; kept
 * scalar it was slower on a Zen 4 machine (bench/RESULTS_colloid.md). */
#ifndef PELOID_COLLOID_BLOCK_H
#define PELOID_COLLOID_BLOCK_H

#include <math.h>

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

/* The minimum image of a separation on the periodic axes (per[d] != 0). */
static inline void pl_colloid_min_image(const int per[3], const double L[3], const double iL[3], double *dx,
                                        double *dy, double *dz)
{
    if (per[0]) *dx -= L[0] * rint(*dx * iL[0]);
    if (per[1]) *dy -= L[1] * rint(*dy * iL[1]);
    if (per[2]) *dz -= L[2] * rint(*dz * iL[2]);
}

/* Slot s's three components into a per-pair array (nl->pf, nl->pt), at
 * the place of nl's layout (pl_colloid_pair_at). */
static inline void pl_colloid_pair_store(const pl_colloid_nlist_t *nl, double *a, int32_t s, double x,
                                         double y, double z)
{
    const size_t q = pl_colloid_pair_at(nl, s);
    a[q] = x;
    a[q + 1] = y;
    a[q + 2] = z;
}

#endif
