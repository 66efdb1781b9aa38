/* The WCA pair pass of the potential coupling (private to kernels/: defined
 * in coupling_wca.c), shared by pl_coupling_wca_pair_forces and the fused
 * MD step pl_coupling_potential_force_step (coupling_potential.c), so both
 * give the same bits. */
#ifndef PELOID_COUPLING_WCA_H
#define PELOID_COUPLING_WCA_H

#include <stddef.h>

#include "peloid/coupling_kernels.h"

/* Block of particles [lo, hi): forces into nb->f, reactions and energy into
 * its row rb (3 nc + 1).  The first pair of each particle (its first
 * candidate) vectorised over the particles, its force written straight into
 * f as the sum's first term (0 + g) and its energy into ge[j]; the further
 * ones (scratch g*[nb->n + p]) over their list; then the sums of wca_block,
 * in particle order, each particle's pairs in colloid order.  A particle
 * with one pair (nearly all) takes its reaction from f: -(0 + g) subtracts
 * the same as -g (they differ only for g = -0, and no row holds -0: it
 * starts at +0 and a sum is -0 only when both terms are); one with further
 * pairs has its first pair evaluated again (the same bits) for the sum. */
void pl_coupling_wca_pair_block(const pl_coupling_wca_t *w, const pl_coupling_near_t *nb,
                                const pl_coupling_colloids_t *c, size_t lo, size_t hi, double *rb,
                                double *restrict gx, double *restrict gy, double *restrict gz, double *restrict ge);

/* The reactions of the blocks' rows added in block order into cf, and their
 * energy (returned). */
double pl_coupling_wca_rows_sum(size_t nc, size_t nblk, const double *partial, double *cfx, double *cfy, double *cfz);

#endif
