/* SRD+a, the SRD rotation that keeps each cell's angular momentum
 * (kernels/srd_a.c; peloid/srd_rules.h, peloid/cell_angular.h). */
#ifndef PELOID_SRD_A_H
#define PELOID_SRD_A_H

#include "peloid/srd_kernels.h"

/* The contract of pl_srd_collide (p->rule: PL_RULE_RANDOM_AXIS, p->cos_a,
 * p->sin_a); reads the positions (sorted with the velocities) and the
 * grid's shift and walls. */
void pl_srd_a_collide(pl_fluid_t *fluid, const pl_grid_t *grid, const uint32_t *cell_start,
                      const pl_collide_params_t *p, double *block_sum, int nthreads);

#endif
