/* The largest pair energy of adaptive MD substeps (peloid/colloid_reach.h
 * has the rule): per owner its listed pairs within d + gap_cut, U(h) of the
 * conservative terms plus the kinetic energy of the approach,
 * m_red (v_ij . e_ij)^2 / 2 when the pair closes, plus the margin, and never
 * below ereq at the pair's own gap.
 *
 * OpenMP: a static loop over owners with exact max reductions (serial below
 * PL_COLLOID_OMP_MIN colloids), so the result is the same for any thread
 * count. */
#include <math.h>

#include "peloid/colloid_reach.h"

void pl_colloid_reach_energy(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                             const pl_colloid_reach_t *t, double margin, const double *x,
                             const double *y, const double *z, const double *vx, const double *vy,
                             const double *vz, const double *mass, double *emax, double *v2max,
                             int nthreads)
{
    const size_t n = nl->n;
    const double d = t->d, rc = d + p->gap_cut;
    double em = -INFINITY, vm = 0.0;
#pragma omp parallel for schedule(static) num_threads(nthreads) reduction(max : em, vm) if (n >= PL_COLLOID_OMP_MIN)
    for (size_t i = 0; i < n; ++i) {
        double v2 = vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i];
        /* a non-finite speed makes the caller fall back to the most steps */
        if (!(v2 <= vm)) vm = isnan(v2) ? INFINITY : v2;
        for (int32_t s = nl->start[i]; s < nl->start[i + 1]; ++s) {
            size_t j = (size_t)nl->nbr[s];
            double dx = pl_min_image(x[i] - x[j], p->box[0], p->periodic[0]);
            double dy = pl_min_image(y[i] - y[j], p->box[1], p->periodic[1]);
            double dz = pl_min_image(z[i] - z[j], p->box[2], p->periodic[2]);
            double r2 = dx * dx + dy * dy + dz * dz;
            if (!(r2 < rc * rc)) continue;
            double r = sqrt(r2), h = r - d;
            double vn = ((vx[i] - vx[j]) * dx + (vy[i] - vy[j]) * dy + (vz[i] - vz[j]) * dz) / r;
            double mred = mass[i] * mass[j] / (mass[i] + mass[j]);
            double kin = vn < 0.0 ? 0.5 * mred * vn * vn : 0.0;
            double e = pl_colloid_reach_u(t, h) + kin + margin;
            double eh = pl_colloid_reach_ereq(t, h);
            if (eh > e) e = eh;
            if (!(e <= em)) em = isnan(e) ? INFINITY : e;
        }
    }
    *emax = em;
    *v2max = vm;
}
