/* MPC-AT+a, the Andersen-thermostat collision that keeps each cell's
 * angular momentum (kernels/mpc_at_a.c; peloid/mpc_at.h, peloid/cell_angular.h). */
#ifndef PELOID_MPC_AT_A_H
#define PELOID_MPC_AT_A_H

#include "peloid/srd_kernels.h"

/* The contract of pl_mpc_at_collide; reads the positions (sorted with the
 * velocities) and the grid's shift and walls. */
void pl_mpc_at_a_collide(pl_fluid_t *fluid, const pl_grid_t *grid, const uint32_t *cell_start,
                         const pl_collide_params_t *p, double *block_sum, int nthreads);

#endif
