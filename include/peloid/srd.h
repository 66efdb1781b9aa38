/* The SRD fluid as a component (issue 46): what the fluid module
 * (src/fluid/) creates and its stages take as their context.  The particle
 * arrays (pl_sim_t.fluid) and the grid (pl_sim_t.grid) are the view that the
 * other components read and move; of this state the couplings use the
 * sort's order and borrow scratch of the fluid's shape through the ports
 * below; the whole-simulation checkpoint
 * (src/core/checkpoint.c) writes the field accumulators and kT_cell, the
 * fields writer reads the accumulators.  The rest only the fluid touches. */
#ifndef PELOID_SRD_H
#define PELOID_SRD_H

#include <stdint.h>

#include "peloid/srd_kernels.h"

struct pl_collision_rule;

typedef struct pl_srd {
    const struct pl_collision_rule *rule; /* srd.rule's row (peloid/collision_rule.h) */
    uint32_t *hist;       /* nthreads x ncells */
    uint32_t *cell_start; /* ncells + 1 */
    /* no particle moved since the last sort: the fluid is in collision-cell
     * order under grid.shift, with cell_start (0 after creation or restart) */
    int sorted;
    /* this step's sort was the index sort (srd.sort_interval): cell c is the
     * particles fluid.order[cell_start[c] .. cell_start[c+1]) */
    int indexed;
    double *block_sum;    /* 2 x ceil(ncells / PL_CELL_BLOCK) */
    double *obs_scratch;  /* pl_srd_observe_scratch(n) */
    double last_kT_meas;  /* PL Eq. A1 temperature of the last collision */
    pl_collide_params_t collide; /* fixed when the plan is built; the stage sets the step */
    int64_t *wall_acc;    /* nthreads x PL_WALL_ACC_STRIDE (streaming bounces; NULL without walls) */
    double *wall_dp;      /* PL_WALL_ACC_N x blocks (virtual particles of the collision) */
    /* fluid guard bounds (pl_fluid_guard_setup, src/fluid/fluid_guard.c) */
    double guard_vmax;             /* largest speed allowed */
    /* the collision's per-block speed flags (pl_collide_params_t.guard_bad)
     * and the step whose collision wrote them (-1: none) */
    unsigned char *guard_bad;
    long long guard_bad_step;
    double guard_kT_lo, guard_kT_hi; /* kT_cell band with a thermostat (else 0, inf) */
    /* time-averaged fields (NULL without output.fields_interval) */
    int64_t *field_acc;   /* 4 x L0 L1 L2, fixed point */
    long long field_samples;
} pl_srd_t;

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

#endif
