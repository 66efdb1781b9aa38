/* The SRD fluid component's state (private to src/fluid/; other components
 * use the ports of peloid/srd.h, issue 46): made by pl_fluid_state_create
 * (fluid_state.c) and the context of the fluid's stages, thermostats and
 * collision rules. */
#ifndef PELOID_FLUID_SRD_STATE_H
#define PELOID_FLUID_SRD_STATE_H

#include "peloid/sim.h"
#include "peloid/srd.h"

struct pl_srd {
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
};

/* The fluid's checkpoint items (checkpoint_fluid.c): the hooks of its row of
 * the module table (peloid/module.h). */
int pl_fluid_ckpt_attrs(int64_t file, const pl_sim_t *sim);
int pl_fluid_ckpt_write(int64_t file, const pl_sim_t *sim);
int pl_fluid_ckpt_write_last(int64_t file, const pl_sim_t *sim);
int pl_fluid_ckpt_read(int64_t file, pl_sim_t *sim, const char *path, pl_err_t *err);

#endif
