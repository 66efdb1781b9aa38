/* The slow share of the colloid pair forces under multiple time stepping
 * (colloids.slow_interval > 1, r-RESPA: Tuckerman, Berne and Martyna, J.
 * Chem. Phys. 97, 1990 (1992)).  Each pair's DLVO force (Hecht Eqs. 1-2)
 * is split as F = (1 - w) F + w F with w = pl_pair_slow_share(r^2, d, hin,
 * hout): the fast share, with every other term, is evaluated every MD step
 * over the near list (kernels/colloid_forces.c with p->mts); the slow share,
 * w F, here, once per outer step, over the full Verlet list, and applied as
 * a kick of slow_interval MD steps at each end of the outer step
 * (kernels/colloid_verlet.h).  w = 0 below the gap hin, which lies beyond
 * the primary minimum's match gap, so the slow share is Eqs. 1-2 alone; it
 * holds no dissipative term, so it is a function of the positions only.
 *
 * Accumulation as in the force kernel: the owner sums its pairs in slot
 * order and writes each pair's force into the pair's slot;
 * the force kernel's pass 2 (pl_colloid_pair_reverse_one over
 * pl_colloid_slow_view) adds those after the barrier, in owner order.
 * A listed pair outside (hin, dlvo_hcut) adds exactly +-0, so any valid list
 * gives the same bits (a restart recomputes the slow forces bitwise). */
#include <math.h>

#include "colloid_block.h"
#include "peloid/colloid_kernels.h"
#include "peloid/colloid_pair.h"

void pl_colloid_slow_owner_pass(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                                const double *x, const double *y, const double *z,
                                const double *rad, double *fsx, double *fsy, double *fsz)
{
    enum { BLK = 32 };
    const double L[3] = {p->box[0], p->box[1], p->box[2]};
    const double iL[3] = {1.0 / L[0], 1.0 / L[1], 1.0 / L[2]};
    const int per[3] = {p->periodic[0], p->periodic[1], p->periodic[2]};
    const double pL[3] = {per[0] ? L[0] : 0.0, per[1] ? L[1] : 0.0, per[2] ? L[2] : 0.0};
    const double A6 = p->hamaker / 6.0, hin = p->mts_hin, hout = p->mts_hout;
#pragma omp for schedule(static)
    for (size_t i = 0; i < nl->n; ++i) {
        const double xi = x[i], yi = y[i], zi = z[i], ri = rad[i];
        double sx = 0.0, sy = 0.0, sz = 0.0;
        for (int32_t s0 = nl->start[i]; s0 < nl->start[i + 1]; s0 += BLK) {
            const int m = nl->start[i + 1] - s0 < BLK ? nl->start[i + 1] - s0 : BLK;
            double gx[BLK], gy[BLK], gz[BLK], gr[BLK];
            double bfx[BLK], bfy[BLK], bfz[BLK], bw[BLK], br2[BLK];
            double bcl[BLK]; /* 1: the screened Coulomb term of Eq. 1 is not negligible */
            pl_colloid_gather_block(nl, s0, m, x, y, z, rad, gx, gy, gz, gr);
#pragma omp simd
            for (int k = 0; k < m; ++k) {
                double dx = xi - gx[k], dy = yi - gy[k], dz = zi - gz[k];
                dx -= pL[0] * rint(dx * iL[0]);
                dy -= pL[1] * rint(dy * iL[1]);
                dz -= pL[2] * rint(dz * iL[2]);
                double r2 = dx * dx + dy * dy + dz * dz;
                double d = ri + gr[k], rd = d + p->dlvo_hcut, rq = d + p->coul_hcut;
                double w = pl_pair_slow_share(r2, d, hin, hout);
                /* on: w > 0 inside the DLVO cut-off (as selects of values) */
                double fm = r2 < rd * rd ? w : 0.0;
                /* Eq. 2's force over r, F/r = -A d^6 / (6 r^4 (r^2 - d^2)^2);
                 * lanes that are off compute on harmless operands */
                double d2 = d * d, r2f = fm > 0.0 ? r2 : 2.0, sf = fm > 0.0 ? r2 - d2 : 1.0;
                double ir2 = 1.0 / r2f, is = 1.0 / sf;
                double fc = -(A6 * d2 * d2 * d2) * (ir2 * ir2) * (is * is);
                bfx[k] = fm * (fc * dx);
                bfy[k] = fm * (fc * dy);
                bfz[k] = fm * (fc * dz);
                bw[k] = fm;
                br2[k] = r2;
                bcl[k] = fm > 0.0 && r2 < rq * rq ? 1.0 : 0.0;
            }
            for (int k = 0; k < m; ++k) {
                const int32_t s = s0 + k;
                if (bcl[k] != 0.0) { /* Eqs. 1 + 2 with the exponential (scalar) */
                    size_t j = (size_t)nl->nbr[s];
                    double dx = xi - x[j], dy = yi - y[j], dz = zi - z[j];
                    pl_colloid_min_image(per, L, iL, &dx, &dy, &dz);
                    double r = sqrt(br2[k]), d = ri + rad[j];
                    pl_pair_val_t v = pl_pair_dlvo_raw(r, d, p->coul_C, p->kappa, p->hamaker);
                    double fr = bw[k] * v.f / r;
                    bfx[k] = fr * dx;
                    bfy[k] = fr * dy;
                    bfz[k] = fr * dz;
                }
                sx += bfx[k];
                sy += bfy[k];
                sz += bfz[k];
                pl_colloid_pair_store(nl, nl->pf, s, bfx[k], bfy[k], bfz[k]);
            }
        }
        fsx[i] = sx;
        fsy[i] = sy;
        fsz[i] = sz;
    }
}

void pl_colloid_slow_forces(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                            const double *x, const double *y, const double *z, const double *rad,
                            double *fsx, double *fsy, double *fsz, int nthreads)
{
#pragma omp parallel num_threads(nthreads) if (nl->n >= PL_COLLOID_OMP_MIN)
    {
        const pl_colloid_view_t vs = pl_colloid_slow_view(nl->n, fsx, fsy, fsz);
        pl_colloid_slow_owner_pass(p, nl, x, y, z, rad, fsx, fsy, fsz);
#pragma omp for schedule(static)
        for (size_t i = 0; i < nl->n; ++i) pl_colloid_pair_reverse_one(nl, &vs, i, 0);
    }
}
