/* The largest pair energy of adaptive MD substeps (peloid/colloid_reach.h
 * has the rule): per owner its listed pairs within d + gap_cut, U(h) of the
 * conservative terms plus the kinetic energy of the approach,
 * m_red (v_ij . e_ij)^2 / 2 when the pair closes, plus the margin, and never
 * below ereq at the pair's own gap.
 *
 * OpenMP: a static loop over owners (each pl_colloid_reach_owner, which the
 * MD region of kernels/colloid_md_region.c also runs) with exact max
 * reductions (serial below PL_COLLOID_OMP_MIN colloids), so the result is
 * the same for any thread count. */
#include <math.h>

#include "peloid/colloid_reach.h"

void pl_colloid_reach_energy(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                             const pl_colloid_reach_t *t, double margin, const double *x,
                             const double *y, const double *z, const double *vx, const double *vy,
                             const double *vz, const double *mass, double *emax, double *v2max,
                             int nthreads)
{
    const size_t n = nl->n;
    double em = -INFINITY, vm = 0.0;
#pragma omp parallel for schedule(static) num_threads(nthreads) reduction(max : em, vm) \
    if (n >= PL_COLLOID_OMP_MIN)
    for (size_t i = 0; i < n; ++i)
        pl_colloid_reach_owner(p, nl, t, margin, x, y, z, vx, vy, vz, mass, i, &em, &vm);
    *emax = em;
    *v2max = vm;
}
