/* Shared helpers of the coupling tests (header-only, like support.h). */
#ifndef PELOID_TEST_COUPLING_UTIL_H
#define PELOID_TEST_COUPLING_UTIL_H

#include <math.h>

#include "peloid/coupling.h"
#include "support.h"

/* The mean force along `axis` that the fluid exerts on the pinned colloids
 * (coupling.pinned): nblocks (<= 64) consecutive blocks of `block` steps,
 * each block's mean force from the pinned impulse over the pinned time; the
 * mean of the block means, *se their standard error. */
static inline double pl_test_pinned_force(pl_sim_t *sim, int axis, int nblocks, long long block, double *se)
{
    double F[64], mean = 0.0, var = 0.0;
    cr_assert(nblocks >= 2 && nblocks <= 64, "pl_test_pinned_force: 2..64 blocks");
    for (int b = 0; b < nblocks; ++b) {
        double p0 = pl_coupling_of(sim)->impulse[axis], t0 = pl_coupling_of(sim)->pinned_time;
        pl_test_steps(sim, block);
        F[b] = (pl_coupling_of(sim)->impulse[axis] - p0) / (pl_coupling_of(sim)->pinned_time - t0);
        mean += F[b] / nblocks;
    }
    for (int b = 0; b < nblocks; ++b) var += (F[b] - mean) * (F[b] - mean) / (nblocks - 1);
    *se = sqrt(var / nblocks);
    return mean;
}

#endif
