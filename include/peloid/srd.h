/* The SRD fluid as a component (issue 46): what the fluid module
 * (src/fluid/) creates and its stages take as their context.  The particle
 * arrays (pl_sim_t.fluid) and the grid (pl_sim_t.grid) are the view that the
 * other components read and move; the fluid's own state is opaque here (its
 * fields: src/fluid/srd_state.h, private to src/fluid/ and to the fluid's
 * own unit test and kernel bench).  Through the ports below the couplings use
 * the sort's order and borrow scratch of the fluid's shape, the
 * whole-simulation checkpoint (src/core/checkpoint.c) writes and reads what
 * the fluid keeps between steps, and the fields writer reads the
 * accumulators. */
#ifndef PELOID_SRD_H
#define PELOID_SRD_H

#include <stdint.h>

#include "peloid/srd_kernels.h"

struct pl_collision_rule;

/* The fluid's state: its fields are the fluid's own (src/fluid/srd_state.h);
 * other components use the ports below. */
typedef struct pl_srd pl_srd_t;

/* The fluid's ports (issue 46): what another component may use of this
 * state, by these functions and not by its fields (src/fluid/fluid_state.c).
 *
 * The collision cells of the present order, cell c being the particles
 * cell_start[c] .. cell_start[c + 1] - 1: valid from this step's sort
 * (PL_SLOT_SORT) until the particles move again; NULL when no particle
 * order is valid (the particles moved since the last sort, or a restart). */
const uint32_t *pl_srd_cells(const pl_srd_t *srd);
/* Scratch of the fluid's shape another component may borrow between the
 * fluid's own stages (their contents are not kept): nthreads x ncells
 * counts, and pl_srd_observe_scratch(n) doubles. */
uint32_t *pl_srd_scratch_counts(pl_srd_t *srd);
double *pl_srd_scratch_observe(pl_srd_t *srd);
/* Whether the walls' impulse is measured (no-slip walls): a component that
 * moves fluid particles off a wall adds what they gave it through
 * pl_sim_wall_add (the wall-impulse sink, peloid/sim.h). */
int pl_srd_walls_measured(const pl_srd_t *srd);
/* What the fluid keeps between steps beside its particles, which the
 * checkpoint (src/core/checkpoint.c) writes and reads back: the
 * time-averaged fields' fixed-point accumulator (4 x cells; NULL without
 * output.fields_interval) and its sample count, and kT_cell of the last
 * collision (PL Eq. A1), which the thermo row of a restart step prints. */
typedef struct {
    int64_t *field_acc;
    long long *field_samples;
    double *kT_cell;
} pl_srd_kept_t;
pl_srd_kept_t pl_srd_kept(pl_srd_t *srd);
/* The time-averaged fields for a writer: the accumulator (NULL: none) and
 * its sample count in *samples. */
const int64_t *pl_srd_fields(const pl_srd_t *srd, long long *samples);
/* The fluid guard's largest particle speed allowed (a restart checks the
 * particles read against it). */
double pl_srd_speed_bound(const pl_srd_t *srd);
/* The particles were replaced (a restart): no cell order is valid until the
 * next sort. */
void pl_srd_order_lost(pl_srd_t *srd);

#endif
