/* Coupling I's events within a step (private to kernels/): the events'
 * view of the colloids, shared by the reflections (coupling_reflect.c) and
 * the order in which they run (coupling_order.c). */
#ifndef PELOID_COUPLING_EVENTS_H
#define PELOID_COUPLING_EVENTS_H

#include "peloid/coupling_kernels.h"

/* The events' view of the colloids: c (true radii, the corrected end
 * positions x, y, z = pos, the live velocities), cb (the positions the MD
 * left and the enlarged radii the detection and cstart, clist used), disp
 * (3 x n: pos - cb's position) and the largest |disp| of each colloid
 * (cb->rad - c->rad). */
typedef struct {
    pl_coupling_colloids_t c;
    const pl_coupling_colloids_t *cb;
    double *pos[3], *disp;
    const uint32_t *cstart;
    const int32_t *clist;
    int move; /* 0: pinned colloids, no displacement */
} pl_c1_events_t;

/* The step's events in order (the file header of coupling_order.c): sc->idx
 * the particles, sc->owner the threads whose histogram rows hold their
 * cells, for j < total. */
void pl_coupling1_order(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *prm,
                        const pl_c1_events_t *e, int nthreads, const uint32_t *found, const uint64_t *counts,
                        size_t total, pl_coupling1_scratch_t *sc);

/* Each event's candidate colloid sc->k and the colloids' chains of events
 * (sc->next), none taken or done yet. */
void pl_coupling1_chains(const pl_fluid_t *f, const pl_grid_t *g, const pl_c1_events_t *e, int nthreads,
                         size_t total, pl_coupling1_scratch_t *sc);

/* Colloid sc->k[j]'s chain from its head j gathered for
 * pl_coupling1_chain_next; its number of untaken events. */
size_t pl_coupling1_chain_gather(const pl_fluid_t *f, pl_coupling1_scratch_t *sc, size_t j);

/* The next event of colloid k's gathered chain (*m left, one fewer after),
 * or -1 when the chain is done. */
int64_t pl_coupling1_chain_next(const pl_c1_events_t *e, const pl_grid_t *g, const pl_coupling1_params_t *prm,
                                pl_coupling1_scratch_t *sc, int32_t k, size_t *m);

#endif
