/* The two halves of one velocity-Verlet MD step of the colloids (Hecht Eqs.
 * 7-10, PL Eqs. 18-19) per block or per colloid (private to kernels/), run
 * by the MD region of kernels/colloid_md_region.c inside its worksharing
 * loops instead of the seven separate passes (half kick, drift,
 * displacement check, pair forces, external forces, half kick, guard):
 *
 *   open:  per block of PL_COLLOID_ROT_BLOCK colloids, half kick + drift of
 *          each, the block's rotations in vector lanes, and each one's
 *          displacement since the list build (max);
 *   (the region rebuilds the neighbour list when the displacement asks)
 *   close: pair pass 1 (owners' pairs, pl_colloid_pair_owner_pass), barrier,
 *          then per colloid: pass 2 (reverse entries), unwrapped z, external
 *          forces, half kick and the guard's per-colloid tests and maxima.
 *
 * Multiple time stepping (r-RESPA, colloids.slow_interval = k > 1): the pair
 * pass covers the near list with the fast share of the forces; the slow
 * share's half kick of k dt / 2 comes first in the open of an outer step's
 * first MD step and last in the close of its last one, whose close also
 * evaluates the slow forces (kernels/colloid_slow.c; owner pass after the
 * fast one, reverse entries per colloid after the barrier).  A non-finite
 * slow force makes the velocity non-finite before the guard's test.
 *
 * Each colloid's operations are the ones of the separate passes
 * (kernels/colloid_integrate.h, pl_colloid_pair_reverse_one), in the same
 * order on the same operands, so the state is bitwise the same; nothing
 * relies on which thread runs a colloid (pass 2 starts after the barrier).
 * Maxima are exact: their reductions are independent of the thread count. */
#ifndef PELOID_COLLOID_VERLET_H
#define PELOID_COLLOID_VERLET_H

#include <math.h>

#include "colloid_integrate.h"

/* The open of block bk: slow kick (slow_h != 0), half kick, drift,
 * rotations; the block's largest squared displacement since the list build
 * raised into *m (+inf for a non-finite position, which forces a rebuild;
 * the NaN guard reports it). */
static inline void pl_colloid_verlet_open_block(const pl_colloid_dyn_t *s, size_t bk, double dt,
                                                double slow_h, const pl_colloid_nlist_t *nl, double *m)
{
    const size_t n = s->n;
    const double h = 0.5 * dt;
    const size_t b = bk * PL_COLLOID_ROT_BLOCK;
    const size_t e = b + PL_COLLOID_ROT_BLOCK < n ? b + PL_COLLOID_ROT_BLOCK : n;
    for (size_t i = b; i < e; ++i) {
        if (slow_h != 0.0)
            pl_colloid_slow_kick_one(i, slow_h, s->mass, s->fsx, s->fsy, s->fsz, s->vx, s->vy, s->vz);
        pl_colloid_kick_one(i, h, s->mass, s->inertia, s->fx, s->fy, s->fz, s->tx, s->ty, s->tz,
                            s->vx, s->vy, s->vz, s->wx, s->wy, s->wz);
        pl_colloid_move_one(i, dt, s->box, s->periodic, s->x, s->y, s->z, s->ix, s->iy, s->iz, s->vx,
                            s->vy, s->vz);
    }
    pl_colloid_rotate_block(b, e, dt, s->wx, s->wy, s->wz, s->q0, s->q1, s->q2, s->q3);
    double mm = *m;
    for (size_t i = b; i < e; ++i) {
        double d2 = pl_colloid_nlist_disp2(nl, s->box, s->periodic, s->x, s->y, s->z, i);
        if (!(d2 <= mm)) mm = isnan(d2) ? INFINITY : d2;
    }
    *m = mm;
}

/* The guard's tests of colloid i (finite state, image counters in range)
 * and its pair maxima, into gm. */
static inline void pl_colloid_guard_one(const pl_colloid_dyn_t *s, size_t i, const pl_colloid_view_t *v,
                                        pl_colloid_guard_max_t *gm)
{
    const int ok = pl_colloid_state_finite(s->x[i], s->y[i], s->z[i], s->vx[i], s->vy[i], s->vz[i],
                                           s->fx[i], s->fy[i], s->fz[i], s->wx[i], s->wy[i], s->wz[i]) &&
                   pl_colloid_image_axis_out(s->ix[i], s->iy[i], s->iz[i]) < 0;
    pl_colloid_guard_add(gm, ok, v->g_overlap[i], v->g_omega2[i], v->g_damp[i]);
}

/* Pass 2 of colloid i (its reverse entries), its unwrapped z and external
 * forces: the forces' end, after pair pass 1. */
static inline void pl_colloid_forces_close_one(const pl_colloid_dyn_t *s, size_t i, const pl_colloid_nlist_t *nl,
                                               const pl_colloid_view_t *v, int torques,
                                               const pl_colloid_ext_params_t *ext, double rf, double *epot)
{
    pl_colloid_pair_reverse_one(nl, v, i, torques);
    s->zu[i] = s->z[i] + (double)s->iz[i] * s->box[2];
    pl_colloid_ext_one(ext, rf, s->n, i, s->x, s->y, s->z, s->zu, s->rad, s->mass, s->fx, s->fy, s->fz,
                       epot);
}

/* The close of colloid i after pair pass 1 (nl: the pair pass's list; full:
 * the slow pass's, used when slow_h != 0; vs: pl_colloid_slow_view; rf =
 * 2^{1/wall_n}): reverse entries, unwrapped z, external forces, half kick,
 * the slow reverse entries and kick, and the guard's tests and maxima into
 * gm. */
static inline void pl_colloid_verlet_close_one(const pl_colloid_dyn_t *s, size_t i, double dt, double slow_h,
                                               const pl_colloid_nlist_t *nl, const pl_colloid_nlist_t *full,
                                               const pl_colloid_view_t *v, const pl_colloid_view_t *vs,
                                               int torques, const pl_colloid_ext_params_t *ext, double rf,
                                               double *epot, pl_colloid_guard_max_t *gm)
{
    const double h = 0.5 * dt;
    pl_colloid_forces_close_one(s, i, nl, v, torques, ext, rf, epot);
    pl_colloid_kick_one(i, h, s->mass, s->inertia, s->fx, s->fy, s->fz, s->tx, s->ty, s->tz, s->vx,
                        s->vy, s->vz, s->wx, s->wy, s->wz);
    if (slow_h != 0.0) {
        pl_colloid_pair_reverse_one(full, vs, i, 0);
        pl_colloid_slow_kick_one(i, slow_h, s->mass, s->fsx, s->fsy, s->fsz, s->vx, s->vy, s->vz);
    }
    pl_colloid_guard_one(s, i, v, gm);
}

#endif
