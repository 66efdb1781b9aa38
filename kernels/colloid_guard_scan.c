/* The colloid guard's parallel pass (src/colloid/colloid_guard.c; the
 * criteria are Hecht Sec. II's, listed there): per colloid the state tests
 * (finite, image counters in range) and the maxima of the pair kernel's guard
 * quantities, the same as the close of the fused MD step computes
 * (kernels/colloid_verlet.h) when the forces came from the separate passes.
 *
 * OpenMP: a static loop over colloids with the exact max reduction
 * pl_guard_max (serial below PL_COLLOID_OMP_MIN colloids), so the result is
 * the same for any thread count. */
#include "peloid/colloid_kernels.h"

void pl_colloid_guard_scan(const pl_colloid_guard_view_t *v, pl_colloid_guard_max_t *g, int nthreads)
{
    const size_t n = v->n;
    pl_colloid_guard_max_t gm = {0.0, 0.0, 0.0, 0};
#pragma omp parallel for schedule(static) num_threads(nthreads) reduction(pl_guard_max : gm) \
    if (n >= PL_COLLOID_OMP_MIN)
    for (size_t i = 0; i < n; ++i) {
        const int ok = pl_colloid_state_finite(v->x[i], v->y[i], v->z[i], v->vx[i], v->vy[i], v->vz[i],
                                               v->fx[i], v->fy[i], v->fz[i], v->wx[i], v->wy[i], v->wz[i]) &&
                       pl_colloid_image_axis_out(v->ix[i], v->iy[i], v->iz[i]) < 0;
        pl_colloid_guard_add(&gm, ok, v->g_overlap[i], v->g_omega2[i], v->g_damp[i]);
    }
    *g = gm;
}
