/* Colloid-solvent coupling (src/coupling*.c): the state the plan stages of
 * the coupling need, built from the scene.  Kernels: coupling_kernels.h.
 *
 * Plan (src/plan/sim.c): colloid-md, stream+bin, [coupling1-reflect], sort,
 * [coupling2-save], collide, [coupling2-collide], thermostat, [drift-removal].
 * Gravity compensation (Hecht Sec. VIII.A iii) enters the streaming as the
 * extra fluid acceleration fluid_accel. */
#ifndef PELOID_COUPLING_H
#define PELOID_COUPLING_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/coupling_kernels.h"
#include "peloid/error.h"
#include "peloid/scene.h"

struct pl_colloid;

typedef struct pl_coupling {
    int method;          /* PL_COUPLE_* */
    int nthreads;
    uint64_t seed;
    double fluid_accel[3]; /* compensating fluid acceleration (0 without) */
    /* coupling I */
    pl_coupling1_params_t p1;
    int32_t *lk_start, *lk_list;
    size_t lk_cap;
    uint32_t *found;     /* fluid n: particles found inside (scratch) */
    uint64_t *counts;    /* nthreads x 8 */
    unsigned long long events, truncations; /* since the start of this run */
    /* pinned colloids: impulse received (momentum 0..2, angular 3..5) over
     * pinned_time since the start of this run */
    int pinned;
    double impulse[6], pinned_time;
    /* coupling II */
    pl_coupling2_params_t p2;
    uint64_t *keys;      /* ncolloids: cell << 32 | index */
    uint32_t *occ_cell;
    size_t *occ_save;
    int32_t *occ_col, *col_idx;
    size_t nocc;
    double *vsave;
    size_t save_cap;     /* doubles */
    /* potential coupling (src/coupling/coupling_potential.c) */
    pl_coupling_wca_t wca;
    double margin;       /* selection shell beyond the cut-off */
    double *rad_big;     /* ncolloids: cut-off + margin (lookup radii) */
    uint8_t *marks;      /* grid ncells: cells a selection sphere reaches */
    int *axis_buf;       /* grid n[0] + n[1] + n[2] (scratch) */
    size_t nnear, near_cap;
    uint32_t *near_idx;  /* selected particles, ascending */
    int32_t *near_owner; /* thread whose chunk (and histogram row) holds it */
    double *near_buf;    /* 12 x near_cap: r, v, f, saved displacement */
    double *cf;          /* 3 x ncolloids: fluid force on the colloids */
    double *cf_mean;     /* 3 x ncolloids: its mean over the last collision step (trapezoid over
                          * the MD steps), NULL unless asked for (pl_coupling_mean_force_on) */
    double *wca_partial; /* per-block partial reactions (pl_coupling_wca_forces) */
    size_t wca_partial_cap; /* doubles */
    double epot_cf;      /* PL Eq. 17 energy after the last MD step */
    unsigned long long near_total; /* selected particle-steps (cost counter) */
} pl_coupling_t;

struct pl_sim;

/* From a validated scene, after fluid and colloids exist.  With coupling I
 * the fluid particles initially inside colloids are placed elsewhere. */
int pl_coupling_create(struct pl_sim *sim, pl_coupling_t **out, pl_err_t *err);
void pl_coupling_free(pl_coupling_t *cp);

/* Rebuilds the colloid lookup of coupling I (grows it when needed). */
int pl_coupling_lookup_update(pl_coupling_t *cp, const struct pl_sim *sim, pl_err_t *err);
/* Same for the colloids seen through `v` (e.g. with enlarged radii). */
int pl_coupling_lookup_fill(pl_coupling_t *cp, const struct pl_sim *sim,
                            const pl_coupling_colloids_t *v, pl_err_t *err);

/* Plan stages (src/coupling/coupling_stages.c). */
int pl_coupling_stage_reflect(struct pl_sim *sim, void *ctx, pl_err_t *err);
int pl_coupling_stage_save(struct pl_sim *sim, void *ctx, pl_err_t *err);
int pl_coupling_stage_collide(struct pl_sim *sim, void *ctx, pl_err_t *err);
/* The same with the Heyes thermostat (the plan's variant on multiples of
 * thermostat.interval). */
int pl_coupling_stage_collide_heyes(struct pl_sim *sim, void *ctx, pl_err_t *err);
int pl_coupling_stage_drift(struct pl_sim *sim, void *ctx, pl_err_t *err);
/* Pinned colloids in a flow: the fluid mean velocity is set to
 * coupling.flow_velocity (a uniform shift, i.e. an adaptive body force). */
int pl_coupling_stage_flow(struct pl_sim *sim, void *ctx, pl_err_t *err);
/* Potential coupling: select the fluid near colloids (before stream+bin),
 * then integrate them with the colloids at the MD step (after it). */
int pl_coupling_potential_setup(pl_coupling_t *cp, struct pl_sim *sim, pl_err_t *err);
int pl_coupling_stage_select(struct pl_sim *sim, void *ctx, pl_err_t *err);
int pl_coupling_stage_potential_md(struct pl_sim *sim, void *ctx, pl_err_t *err);

/* Potential coupling: keep the mean fluid force on each colloid over every
 * collision step in cp->cf_mean from now on (the C_FF observer); changes no
 * trajectory.  0 or PL_ERR_NOMEM. */
int pl_coupling_mean_force_on(pl_coupling_t *cp, size_t ncolloids, pl_err_t *err);

/* Pinned colloids: their velocities (changed by a coupling stage) are taken
 * back to zero and the momentum they had gained is added to cp->impulse. */
void pl_coupling_absorb_pinned(pl_coupling_t *cp, struct pl_colloid *c, double dt);

/* Total momentum of fluid + colloids (fixed-order sums) and total mass. */
void pl_coupling_total_momentum(const struct pl_sim *sim, double p[3], double *mass);

/* The kernels' view of the colloid arrays. */
pl_coupling_colloids_t pl_coupling_view(const struct pl_colloid *c);

#endif
