/* Colloid-solvent coupling (src/coupling/coupling*.c): the state the plan
 * stages of the coupling need, built from the scene: a common part and the
 * state of the one method in use.  Kernels: coupling_kernels.h.
 *
 * Plan (src/core/sim.c): colloid-md (not with the potential coupling, whose
 * MD stage moves the colloids), [potential-select], stream+bin,
 * [potential-md | coupling1-reflect], sort, [coupling2-save], collide,
 * [coupling2-collide], thermostat, [flow-hold], [drift-removal].
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

/* The coupling object is split by method, so that a run holds only the
 * buffers its scene's coupling uses: pl_coupling_t keeps what every method
 * (and drift removal alone, method "none") needs, and points to the state of
 * the one method in use; the other method pointers are NULL.  Each method's
 * state is allocated, used and freed by that method's file (coupling.c only
 * clears the colloid interiors through it at the start); the structs are
 * public because the checkpoint (src/coupling/checkpoint_coupling.c: the run
 * counters only, the rest is rebuilt from the scene or before each use) and
 * the tests read them.  Kernels see none of them, only their arrays and
 * parameter structs. */

/* ---- colloid lookup (src/coupling/coupling_view.c) ---------------------- */
/* CSR lists of the colloids near each unit cell (pl_coupling_lookup_build):
 * couplings I and potential each own one, with their own radii. */
typedef struct {
    int32_t *start; /* L0 L1 L2 + 1 */
    int32_t *list;
    size_t cap;     /* entries list holds */
} pl_coupling_lookup_t;

/* ---- coupling I, reflection (src/coupling/coupling_stages.c) ------------- */
typedef struct pl_coupling1_state {
    pl_coupling1_params_t p;
    pl_coupling_lookup_t lk; /* the colloids with their own radii (the initial clearing) */
    uint32_t *cstart;    /* grid ncells + 2: the colloids near each collision cell */
    int32_t *clist;      /* (pl_coupling_cell_candidates, their own radii) */
    size_t clist_cap;
    int *axis_buf;       /* grid n[0] + n[1] + n[2] (scratch) */
    double *gap_buf;     /* as many (scratch) */
    uint32_t *found;     /* fluid n: particles found inside (scratch) */
    uint64_t *counts;    /* nthreads x 8 */
    pl_coupling1_scratch_t events_scratch; /* the events in parallel (grown as needed) */
    pl_coupling_find_ctx_t find_ctx; /* the detection inside the streaming */
    uint64_t *cell_mask; /* (grid ncells + 63) / 64: the cells with candidates */
    long long armed_step; /* the step whose streaming detects (-1: none) */
    double *rad_big;     /* colloids: radius + the margin of the end positions' move */
    size_t rad_cap;      /* colloids rad_big holds */
    unsigned long long events, truncations; /* since the start of this run */
} pl_coupling1_state_t;

/* ---- coupling II, colloids in the collision (src/coupling/coupling_stages.c) */
typedef struct pl_coupling2_state {
    pl_coupling2_params_t p;
    uint64_t *keys;      /* ncolloids: cell << 32 | index */
    uint32_t *occ_cell;
    size_t *occ_save;
    int32_t *occ_col, *col_idx;
    size_t nocc;
    double *vsave;
    size_t save_cap;     /* doubles */
} pl_coupling2_state_t;

/* ---- potential coupling (src/coupling/coupling_potential.c) -------------- */
typedef struct pl_coupling_potential_state {
    pl_coupling_wca_t wca;
    double margin;       /* selection shell beyond the cut-off (the pairs' radius; a
                          * particle's own reach may be less) */
    double budget;       /* this step's: how far the colloids may move (pl_coupling_reach_t) */
    double *rad_big;     /* ncolloids: cut-off + margin (lookup radii) */
    pl_coupling_lookup_t lk; /* the colloids with the radii rad_big */
    int lk_valid;        /* lk built for the colloids at this step's selection */
    uint32_t *found;     /* fluid n: particles selected (scratch) */
    uint32_t *found_cell; /* fluid n: the cell whose candidates each was tested against */
    /* the selection inside the streaming (pl_coupling_select_block) while
     * the fluid is sorted: its context, the state it saved (fluid n x
     * width doubles, reserved; each thread writes from its chunk's start
     * only what it lists), and the step it was armed for (-1: none, the
     * selection's stage gathered itself) */
    pl_coupling_select_ctx_t sel_ctx;
    pl_coupling_stage_t *stage; /* nthreads */
    double *stage_buf;
    long long armed_step;
    uint64_t *counts;    /* nthreads x 8 */
    uint32_t *cstart;    /* grid ncells + 2: candidates of each collision cell */
    int32_t *clist;      /* (pl_coupling_cell_candidates) */
    size_t clist_cap;
    int *axis_buf;       /* grid n[0] + n[1] + n[2] (scratch) */
    double *gap_buf;     /* as many (scratch) */
    double *c0;          /* 3 x ncolloids: colloid positions at the selection */
    double far2;         /* largest squared displacement of a selected particle since */
    size_t nnear, near_cap;
    uint32_t *near_idx;  /* selected particles, ascending */
    int32_t *near_owner; /* thread whose chunk (and histogram row) holds it */
    double *near_buf;    /* 15 x near_cap: r, v, f, saved displacement, r0 */
    size_t npair, pair_cap;
    int32_t *near_k0;    /* near_cap: the first pair's colloid */
    uint32_t *pair_start; /* near_cap + 1: the further pairs */
    uint32_t *pair_j;    /* pair_cap each: particle, colloid of each pair */
    int32_t *pair_k;
    double *pair_buf;    /* 4 x pair_cap (scratch of the forces) */
    double *cf;          /* 3 x ncolloids: fluid force on the colloids */
    double *cf_mean;     /* 3 x ncolloids: its mean over the last collision step (trapezoid over
                          * the MD steps), NULL unless asked for (pl_coupling_mean_force_on) */
    double *wca_partial; /* per-block partial reactions (pl_coupling_wca_forces) */
    size_t wca_partial_cap; /* doubles */
    double epot_cf;      /* PL Eq. 17 energy after the last MD step */
    unsigned long long near_total; /* selected particle-steps (cost counter) */
    /* force evaluations in this run, and those at which the selection margin
     * was used up (a selected particle's move plus the largest colloid move
     * since the selection reached it) or a colloid moved beyond the budget:
     * a fluid particle that was not selected may then have entered the
     * cut-off unseen until the next selection (summary.json "coupling") */
    unsigned long long force_calls, margin_exceeded;
} pl_coupling_potential_state_t;

/* ---- common part (src/coupling/coupling.c) ------------------------------- */
typedef struct pl_coupling {
    int method;          /* PL_COUPLE_* */
    int nthreads;
    uint64_t seed;
    double fluid_accel[3]; /* compensating fluid acceleration (0 without) */
    /* pinned colloids (coupling I, II or potential): impulse received
     * (momentum 0..2, angular 3..5) over pinned_time since the start of
     * this run */
    int pinned;
    double impulse[6], pinned_time;
    double spin[3]; /* the pinned colloids' held angular velocity (coupling.pinned_spin) */
    /* the state of the method in use; NULL for the others */
    pl_coupling1_state_t *c1;
    pl_coupling2_state_t *c2;
    pl_coupling_potential_state_t *pot;
} pl_coupling_t;

struct pl_sim;

/* From a validated scene, after fluid and colloids exist: the common part
 * and the state of the scene's method only.  With coupling I (potential
 * coupling) the fluid particles initially inside colloids (within sigma_cf)
 * are placed elsewhere. */
int pl_coupling_create(struct pl_sim *sim, pl_coupling_t **out, pl_err_t *err);
void pl_coupling_free(pl_coupling_t *cp);

/* Colloid lookup: start allocated for the box of sides L (list grows on
 * demand); 0 or PL_ERR_NOMEM. */
int pl_coupling_lookup_init(pl_coupling_lookup_t *lk, const int L[3], int nthreads, pl_err_t *err);
void pl_coupling_lookup_free(pl_coupling_lookup_t *lk);
/* Rebuilds it for the colloids with their own radii (grows it when needed). */
int pl_coupling_lookup_update(pl_coupling_lookup_t *lk, const struct pl_sim *sim, pl_err_t *err);
/* Same for the colloids seen through `v` (e.g. with enlarged radii). */
int pl_coupling_lookup_fill(pl_coupling_lookup_t *lk, const struct pl_sim *sim,
                            const pl_coupling_colloids_t *v, pl_err_t *err);

/* Method states (src/coupling/coupling_stages.c, coupling_potential.c), from
 * the common part cp and the sim pl_coupling_create is given; *out is NULL
 * on error.  The free functions take NULL. */
int pl_coupling1_create(const pl_coupling_t *cp, const struct pl_sim *sim, pl_coupling1_state_t **out,
                        pl_err_t *err);
void pl_coupling1_free(pl_coupling1_state_t *s);
int pl_coupling2_create(const pl_coupling_t *cp, const struct pl_sim *sim, pl_coupling2_state_t **out,
                        pl_err_t *err);
void pl_coupling2_free(pl_coupling2_state_t *s);
int pl_coupling_potential_create(const pl_coupling_t *cp, const struct pl_sim *sim,
                                 pl_coupling_potential_state_t **out, pl_err_t *err);
void pl_coupling_potential_free(pl_coupling_potential_state_t *s);

/* Plan stages (src/coupling/coupling_stages.c). */
int pl_coupling_stage_reflect_cells(struct pl_sim *sim, void *ctx, pl_err_t *err);
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
int pl_coupling_stage_select(struct pl_sim *sim, void *ctx, pl_err_t *err);
int pl_coupling_stage_potential_md(struct pl_sim *sim, void *ctx, pl_err_t *err);

/* Potential coupling: keep the mean fluid force on each colloid over every
 * collision step in cp->pot->cf_mean from now on (the C_FF observer);
 * changes no trajectory; nothing to keep with another method.  0 or
 * PL_ERR_NOMEM. */
int pl_coupling_mean_force_on(pl_coupling_t *cp, size_t ncolloids, pl_err_t *err);
/* That mean (3 x ncolloids, x block first), or NULL when not kept. */
const double *pl_coupling_mean_force(const pl_coupling_t *cp);

/* The run's coupling (NULL without one): the coupling module's state
 * (src/coupling/coupling_module.c). */
pl_coupling_t *pl_coupling_of(const struct pl_sim *sim);

/* Pinned colloids: their velocities (changed by a coupling stage) are taken
 * back to zero, their angular velocities to the held spin (cp->spin), and
 * the momentum and angular momentum they had gained are added to
 * cp->impulse. */
void pl_coupling_absorb_pinned(pl_coupling_t *cp, struct pl_colloid *c, double dt);

/* Total momentum of fluid + colloids (fixed-order sums) and total mass. */
void pl_coupling_total_momentum(const struct pl_sim *sim, double p[3], double *mass);

/* The kernels' view of the colloid arrays. */
pl_coupling_colloids_t pl_coupling_view(const struct pl_colloid *c);

#endif
