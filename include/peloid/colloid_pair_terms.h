/* The per-row functions of the pair-term table (PL_PAIR_TERMS,
 * colloid_kernels.h): each term's cut-off, and for a RADIAL term its value
 * U, F = -dU/dr, d2U/dr2 inside the cut-off; the cut-off of a set of terms,
 * computed once here for the neighbour lists, the force kernel and the
 * scene checks.  Inline, for the kernels (kernels/colloid_forces.c,
 * kernels/colloid_neighbors.c) and src/colloid/colloid_params.c.
 * Formulas: colloid_pair.h (Hecht Eqs. 1-3, PL Eq. 16), depletion.h
 * (PL Sec. III.C.1). */
#ifndef PELOID_COLLOID_PAIR_TERMS_H
#define PELOID_COLLOID_PAIR_TERMS_H

#include "peloid/colloid_kernels.h"
#include "peloid/colloid_pair.h"
#include "peloid/depletion.h"

/* cut-offs in centre distance for contact distance d = R_i + R_j */
static inline double pl_pair_rc_DLVO(const pl_colloid_pair_params_t *p, double d) { return d + p->dlvo_hcut; }
static inline double pl_pair_rc_HERTZ(const pl_colloid_pair_params_t *p, double d) { (void)p; return d; }
static inline double pl_pair_rc_LUB(const pl_colloid_pair_params_t *p, double d) { return d + p->lub_hcut; }
/* PL Eq. 16: 2^{1/n} sigma, sigma = wca.sigma or R_i + R_j */
static inline double pl_pair_rc_WCA(const pl_colloid_pair_params_t *p, double d)
{
    return (p->wca_sigma > 0.0 ? p->wca_sigma : d) * p->wca_rfac;
}
static inline double pl_pair_rc_DEPL(const pl_colloid_pair_params_t *p, double d) { (void)d; return p->dep_rc; }
static inline double pl_pair_rc_TAB(const pl_colloid_pair_params_t *p, double d) { (void)d; return p->tab_rc; }

/* RADIAL terms, r below the term's cut-off */
static inline __attribute__((always_inline)) pl_pair_val_t pl_pair_term_WCA(const pl_colloid_pair_params_t *p,
                                                                           double r, double d)
{
    return pl_pair_wca(r, p->wca_sigma > 0.0 ? p->wca_sigma : d, p->wca_eps, p->wca_n);
}
static inline __attribute__((always_inline)) pl_pair_val_t pl_pair_term_DEPL(const pl_colloid_pair_params_t *p,
                                                                            double r, double d)
{
    (void)d;
    pl_pair_val_t v;
    pl_depletion_table_eval(p->dep_u, p->dep_du, p->dep_inv_h, r, &v.u, &v.f, &v.k2);
    return v;
}

/* table: U and F each interpolated linearly between the internal nodes
 * (as LAMMPS pair_style table linear), d2U/dr2 = -dF/dr of the interval;
 * below the first node U continues with the first node's force. */
static inline __attribute__((always_inline)) pl_pair_val_t pl_pair_term_TAB(const pl_colloid_pair_params_t *p,
                                                                           double r, double d)
{
    (void)d;
    const double t = (r - p->tab_r0) * p->tab_inv_h;
    pl_pair_val_t v;
    if (t < 0.0) {
        v.f = p->tab_uf[1];
        v.u = p->tab_uf[0] - v.f * (r - p->tab_r0);
        v.k2 = 0.0;
        return v;
    }
    const int k = (int)t;
    const double s = t - k, *q = p->tab_uf + 2 * k;
    v.u = q[0] + s * (q[2] - q[0]);
    v.f = q[1] + s * (q[3] - q[1]);
    v.k2 = -(q[3] - q[1]) * p->tab_inv_h;
    return v;
}

/* The cut-off of the terms in mask for contact distance d: the largest of
 * start and their cut-offs (with a mask known at compile time only its
 * terms are looked at). */
static inline __attribute__((always_inline)) double pl_colloid_pair_rc_from(const pl_colloid_pair_params_t *p,
                                                                           unsigned mask, double d, double start)
{
    double rc = start;
#define PL_RC_(ID, id, name, slot, kind)              \
    if (mask & PL_CT_##ID) {                          \
        const double c_ = pl_pair_rc_##ID(p, d);      \
        rc = c_ > rc ? c_ : rc;                       \
    }
    PL_PAIR_TERMS(PL_RC_)
#undef PL_RC_
    return rc;
}

/* The pair cut-off of the terms in mask: never below contact d, so that
 * every overlapping pair reaches the overlap guard. */
static inline __attribute__((always_inline)) double pl_colloid_pair_rc(const pl_colloid_pair_params_t *p,
                                                                      unsigned mask, double d)
{
    return pl_colloid_pair_rc_from(p, mask, d, d);
}

#endif
