/* One velocity-Verlet MD step of the colloids (Hecht Eqs. 7-10, PL Eqs.
 * 18-19) in two parallel regions instead of the seven of its separate passes
 * (half kick, drift, displacement check, pair forces, external forces, half
 * kick, guard): on a dense suspension the MD step is short (~0.2 ms for 1155
 * colloids on 2 cores), so each fork/join (several us on a VM) and each pass
 * over the arrays counts.
 *
 *   open:  per block of PL_COLLOID_ROT_BLOCK colloids, half kick + drift of
 *          each, the block's rotations in vector lanes, and each one's
 *          displacement since the list build (max-reduced);
 *   (the caller rebuilds the neighbour list when the displacement asks)
 *   close: pair pass 1 (owners' pairs), barrier, then per colloid: pass 2
 *          (reverse entries), unwrapped z, external forces, half kick and the
 *          guard's per-colloid tests and maxima (reduced).
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
 * order on the same operands, so the state is bitwise the same; the static
 * schedule of every loop gives colloid i to the same thread in pass 1 and in
 * the close loop, but nothing relies on it (pass 2 starts after the
 * barrier).  Maxima are exact: the reductions are independent of the thread
 * count. */
#include <math.h>

#include "colloid_integrate.h"

double pl_colloid_verlet_open(const pl_colloid_dyn_t *s, double dt, double slow_h,
                              const pl_colloid_nlist_t *nl, int nthreads)
{
    const size_t n = s->n;
    const double h = 0.5 * dt;
    double m = 0.0;
    const size_t nblk = (n + PL_COLLOID_ROT_BLOCK - 1) / PL_COLLOID_ROT_BLOCK;
#pragma omp parallel for schedule(static) num_threads(nthreads) reduction(max : m) if (n >= PL_COLLOID_OMP_MIN)
    for (size_t bk = 0; bk < nblk; ++bk) {
        const size_t b = bk * PL_COLLOID_ROT_BLOCK, e = b + PL_COLLOID_ROT_BLOCK < n ? b + PL_COLLOID_ROT_BLOCK : n;
        for (size_t i = b; i < e; ++i) {
            if (slow_h != 0.0)
                pl_colloid_slow_kick_one(i, slow_h, s->mass, s->fsx, s->fsy, s->fsz, s->vx, s->vy, s->vz);
            pl_colloid_kick_one(i, h, s->mass, s->inertia, s->fx, s->fy, s->fz, s->tx, s->ty, s->tz,
                                s->vx, s->vy, s->vz, s->wx, s->wy, s->wz);
            pl_colloid_move_one(i, dt, s->box, s->periodic, s->x, s->y, s->z, s->ix, s->iy, s->iz, s->vx,
                                s->vy, s->vz);
        }
        pl_colloid_rotate_block(b, e, dt, s->wx, s->wy, s->wz, s->q0, s->q1, s->q2, s->q3);
        for (size_t i = b; i < e; ++i) {
            double d2 = pl_colloid_nlist_disp2(nl, s->box, s->periodic, s->x, s->y, s->z, i);
            /* a non-finite position forces a rebuild; the NaN guard reports it */
            if (!(d2 <= m)) m = isnan(d2) ? INFINITY : d2;
        }
    }
    return m;
}

void pl_colloid_verlet_close(const pl_colloid_dyn_t *s, double dt, double slow_h,
                             const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                             const pl_colloid_nlist_t *full, const pl_colloid_view_t *v,
                             const pl_colloid_ext_params_t *ext, double *epot,
                             pl_colloid_guard_max_t *g, int nthreads)
{
    const size_t n = s->n;
    const double h = 0.5 * dt, rf = pow(2.0, 1.0 / ext->wall_n), Lz = s->box[2];
    const int torques = pl_colloid_pair_torques(p);
    const pl_colloid_view_t vs = pl_colloid_slow_view(n, s->fsx, s->fsy, s->fsz);
    pl_colloid_guard_max_t gm = {0.0, 0.0, 0.0, 0};
#pragma omp parallel num_threads(nthreads) if (n >= PL_COLLOID_OMP_MIN)
    {
        pl_colloid_pair_owner_pass(p, nl, v);
        if (slow_h != 0.0)
            pl_colloid_slow_owner_pass(p, full, s->x, s->y, s->z, s->rad, s->fsx, s->fsy, s->fsz);
#pragma omp for schedule(static) reduction(pl_guard_max : gm)
        for (size_t i = 0; i < n; ++i) {
            pl_colloid_pair_reverse_one(nl, v, i, torques);
            s->zu[i] = s->z[i] + (double)s->iz[i] * Lz;
            pl_colloid_ext_one(ext, rf, n, i, s->x, s->y, s->z, s->zu, s->rad, s->mass, s->fx,
                               s->fy, s->fz, epot);
            pl_colloid_kick_one(i, h, s->mass, s->inertia, s->fx, s->fy, s->fz, s->tx, s->ty,
                                s->tz, s->vx, s->vy, s->vz, s->wx, s->wy, s->wz);
            if (slow_h != 0.0) {
                pl_colloid_pair_reverse_one(full, &vs, i, 0);
                pl_colloid_slow_kick_one(i, slow_h, s->mass, s->fsx, s->fsy, s->fsz, s->vx, s->vy,
                                         s->vz);
            }
            const int ok = pl_colloid_state_finite(s->x[i], s->y[i], s->z[i], s->vx[i], s->vy[i],
                                                   s->vz[i], s->fx[i], s->fy[i], s->fz[i],
                                                   s->wx[i], s->wy[i], s->wz[i]) &&
                           pl_colloid_image_axis_out(s->ix[i], s->iy[i], s->iz[i]) < 0;
            pl_colloid_guard_add(&gm, ok, v->g_overlap[i], v->g_omega2[i], v->g_damp[i]);
        }
    }
    *g = gm;
}
