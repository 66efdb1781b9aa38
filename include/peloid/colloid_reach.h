/* The reach table of adaptive MD substeps (colloids.adaptive_substeps): the fewest MD steps per
 * collision step that resolve, by colloids.min_contact_steps, the stiffest
 * contact the pairs present can reach with the energy they have.
 *
 * The reach table (src/colloid/colloid_adaptive.c) runs over the gaps
 * h_k = gap_cut - k dh, k = 0 .. nk, inward from the pair cut-off to the
 * largest overlap the overlap guard allows (as the mapping's contact
 * criterion does, src/mapping/mapping_colloids.c):
 *   ereq[k] = max U over [h_k, gap_cut]   (non-decreasing in k)
 *   k2[k]   = max U'' over [h_k, gap_cut] (non-decreasing in k)
 * A pair with total energy E cannot pass a gap where U > E coming from
 * outside, so it stays outward of the first h_k with ereq[k] > E, where the
 * curvature it meets is at most k2[k].  A pair found inward of a hump (the
 * primary minimum behind the barrier) is given at least the hump's energy,
 * ereq at its own gap, so it is treated as able to reach every gap inward. */
#ifndef PELOID_COLLOID_REACH_H
#define PELOID_COLLOID_REACH_H

#include "peloid/colloid_kernels.h"
#include "peloid/colloid_pair.h"

/* U and U'' at gap h (diameter d) of the conservative terms the force kernel
 * hands the contact guard: DLVO with the primary minimum, Hertz, WCA, summed
 * in that order. */
static inline pl_pair_val_t pl_colloid_contact_val(const pl_colloid_pair_params_t *p, double d, double h)
{
    pl_pair_val_t s = {0.0, 0.0, 0.0};
    double r = d + h;
    if ((p->terms & PL_CT_DLVO) && h < p->dlvo_hcut) {
        pl_pair_val_t v = pl_pair_dlvo(r, d, p->coul_C, p->kappa, p->hamaker, p->prim_hm, p->prim_h0,
                                       p->dlvo_shift);
        s.k2 += v.k2;
        s.u += v.u;
    }
    if ((p->terms & PL_CT_HERTZ) && h < 0.0) {
        pl_pair_val_t v = pl_pair_hertz(-h, p->hertz_K);
        s.k2 += v.k2;
        s.u += v.u;
    }
    if (p->terms & PL_CT_WCA) {
        double sg = p->wca_sigma > 0.0 ? p->wca_sigma : d;
        if (r < sg * p->wca_rfac) {
            pl_pair_val_t v = pl_pair_wca(r, sg, p->wca_eps, p->wca_n);
            s.k2 += v.k2;
            s.u += v.u;
        }
    }
    return s;
}

typedef struct pl_colloid_reach {
    double d;          /* the pair diameter of the table (monodisperse) */
    double hcut, dh;   /* h_k = hcut - k dh */
    int nk;            /* k = 0 .. nk */
    double *ereq, *k2; /* nk + 1 each */
    double *u;         /* nk + 2: U at the nodes (u[nk + 1] = u[nk]) */
} pl_colloid_reach_t;

/* U at gap h in [h_nk, hcut): the larger of the two nodes around it (above
 * U itself by at most |U''| dh^2 / 8, ~1e-5 kT at the stiffest contact of
 * the scenes here; no exponential, no logarithm in the per-step scan). */
static inline double pl_colloid_reach_u(const pl_colloid_reach_t *t, double h)
{
    if (h >= t->hcut) return t->u[0];
    double q = (t->hcut - h) / t->dh;
    if (!(q < (double)t->nk)) return INFINITY;
    const int k = (int)q;
    return t->u[k] > t->u[k + 1] ? t->u[k] : t->u[k + 1];
}

/* ereq at gap h, rounded inward to the next node (conservative); +inf
 * inward of the table. */
static inline double pl_colloid_reach_ereq(const pl_colloid_reach_t *t, double h)
{
    if (h >= t->hcut) return t->ereq[0];
    double q = (t->hcut - h) / t->dh;
    if (!(q < (double)t->nk)) return INFINITY;
    return t->ereq[(int)q + 1];
}

/* The largest pair energy of the colloids (kernels/colloid_reach.c): over
 * the pairs of the list closer than d + gap_cut (every valid list holds
 * them, so the result does not depend on when the list was built),
 * max(U(h) (tabulated) + approach kinetic energy + margin, ereq at h); also the largest
 * squared colloid speed.  Exact maxima: the same for any thread count. */
void pl_colloid_reach_energy(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                             const pl_colloid_reach_t *t, double margin, const double *x,
                             const double *y, const double *z, const double *vx, const double *vy,
                             const double *vz, const double *mass, double *emax, double *v2max,
                             int nthreads);

/* Owner i's share of pl_colloid_reach_energy, raised into *em and *vm (the
 * MD region of kernels/colloid_md_region.c runs it in its team). */
static inline void pl_colloid_reach_owner(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                                          const pl_colloid_reach_t *t, double margin, const double *x,
                                          const double *y, const double *z, const double *vx,
                                          const double *vy, const double *vz, const double *mass,
                                          size_t i, double *em, double *vm)
{
    const double d = t->d, rc = d + p->gap_cut;
    double v2 = vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i];
    /* a non-finite speed makes the caller fall back to the most steps */
    if (!(v2 <= *vm)) *vm = isnan(v2) ? INFINITY : v2;
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
        if (!(e <= *em)) *em = isnan(e) ? INFINITY : e;
    }
}

#endif
