/* Colloid pair terms as pure inline functions of the centre distance r
 * (and of the radii), each returning the energy U, the radial force
 * F = -dU/dr (positive = repulsive) and the curvature K2 = d^2U/dr^2, which the
 * stability guard turns into a collision time.  Used by the force kernel
 * (kernels/colloid_forces.c), by the parameter set-up (src/colloid/colloid_params.c)
 * and directly by the tests.  Energies in kT_ref, lengths in a0.
 *
 *   Hecht Eq. 1  screened Coulomb     U = C d^2/r exp(-kappa (r - d))
 *   Hecht Eq. 2  van der Waals        U = -A/12 [d^2/(r^2-d^2) + d^2/r^2 + 2 ln((r^2-d^2)/r^2)]
 *   Hecht Sec. II parabolic primary minimum (C^1 match, see pl_colloid_dlvo)
 *   Hecht Eq. 3  Hertz                U = K (d - r)^{5/2}, r < d
 *   PL Eq. 16    WCA, exponent n      U = 4 eps [(s/r)^{2n} - (s/r)^n + 1/4], r < 2^{1/n} s
 *
 * d = R_i + R_j (Eqs. 1-2 are written for equal spheres; with polydisperse
 * radii the sum of the radii stands in for the diameter). */
#ifndef PELOID_COLLOID_PAIR_H
#define PELOID_COLLOID_PAIR_H

#include <math.h>

#include "peloid/real.h" /* PL_PI */

typedef struct {
    double u, f, k2;
} pl_pair_val_t;

/* Hecht Eq. 1: C is the prefactor pi eps_r eps_0 [4kT/(ze) tanh(ze Psi0/4kT)]^2
 * in kT / a0 (src/colloid/colloid_params.c converts it). */
static inline __attribute__((always_inline)) pl_pair_val_t pl_pair_coulomb(double r, double d, double C, double kappa)
{
    double ir = 1.0 / r;
    double u = C * d * d * ir * exp(-kappa * (r - d));
    double g = ir + kappa;
    pl_pair_val_t v = {u, u * g, u * (g * g + ir * ir)};
    return v;
}

/* Hecht Eq. 2 (r > d); F = -A d^6 / (6 r^3 (r^2-d^2)^2).  Two reciprocals
 * (1/r, shared with the caller's, and 1/(r^2-d^2)) instead of five divisions. */
static inline __attribute__((always_inline)) pl_pair_val_t pl_pair_vdw(double r, double d, double A)
{
    double d2 = d * d, r2 = r * r, s = r2 - d2;
    double ir = 1.0 / r, ir2 = ir * ir, is = 1.0 / s;
    double u = -A / 12.0 * (d2 * is + d2 * ir2 + 2.0 * log(s * ir2));
    double c = A * d2 * d2 * d2 / 6.0;
    double q = c * ir2 * is * is;
    pl_pair_val_t v = {u, -(q * ir), -q * (3.0 * ir2 + 4.0 * is)};
    return v;
}

/* Hecht Eqs. 1 + 2, no primary-minimum model (diverges at contact). */
static inline __attribute__((always_inline)) pl_pair_val_t pl_pair_dlvo_raw(double r, double d, double C, double kappa, double A)
{
    pl_pair_val_t a = pl_pair_coulomb(r, d, C, kappa), b = pl_pair_vdw(r, d, A);
    pl_pair_val_t v = {a.u + b.u, a.f + b.f, a.k2 + b.k2};
    return v;
}

/* The parabola's curvature c (pl_pair_dlvo). */
static inline double pl_pair_parabola_curvature(double vp, double hm, double h0)
{
    return vp / (2.0 * (hm - h0));
}

/* The parabola of the primary minimum at gap h < hm, from the value mu and
 * the slope vp = dU/dr of Eqs. 1-2 at the match gap hm and its curvature c
 * (pl_pair_parabola_curvature); the force kernel keeps mu, vp and c of the
 * reference diameter (pl_colloid_pair_params_t prim_*), the same numbers. */
static inline pl_pair_val_t pl_pair_parabola(double h, double hm, double mu, double vp, double c,
                                             double shift)
{
    double x = h - hm;
    pl_pair_val_t v = {mu - shift + vp * x + c * x * x, -(vp + 2.0 * c * x), 2.0 * c};
    return v;
}

/* DLVO with the parabolic primary minimum (Hecht Sec. II): for a surface gap
 * h = r - d below the match gap hm the potential is the parabola
 *   U = V(hm) + V'(hm) (h - hm) + c (h - hm)^2,  c = V'(hm) / (2 (hm - h0)),
 * which joins Eqs. 1-2 with continuous value and slope and has its minimum at
 * the gap h0; for the reference diameter hm is chosen so that the minimum is
 * exactly `depth` deep (src/colloid/colloid_params.c).  `shift` is subtracted so that
 * U is continuous at the cut-off. */
static inline __attribute__((always_inline)) pl_pair_val_t pl_pair_dlvo(double r, double d, double C, double kappa, double A,
                                         double hm, double h0, double shift)
{
    double h = r - d;
    if (h >= hm) {
        pl_pair_val_t v = pl_pair_dlvo_raw(r, d, C, kappa, A);
        v.u -= shift;
        return v;
    }
    pl_pair_val_t m = pl_pair_dlvo_raw(d + hm, d, C, kappa, A);
    double vp = -m.f; /* dU/dr at the match point, > 0 (attractive) */
    return pl_pair_parabola(h, hm, m.u, vp, pl_pair_parabola_curvature(vp, hm, h0), shift);
}

/* The gap hout at which the slow share reaches 1, for colloids.slow_gap = hin. */
static inline double pl_pair_slow_hout(double hin) { return 2.0 * hin; }

/* Multiple time stepping: the share w of a pair's DLVO force carried by the
 * outer (slow) steps, for contact distance d and squared centre distance r2:
 * 0 up to the gap hin, 1 from the gap hout on, and between them the cubic
 * smoothstep x^2 (3 - 2x) of x = (r2 - (d+hin)^2) / ((d+hout)^2 - (d+hin)^2)
 * (continuous slope: the slow force has no kink for the outer step to jump).
 * The force split F = (1 - w) F + w F is the r-RESPA force splitting of
 * Tuckerman, Berne and Martyna (J. Chem. Phys. 97, 1990 (1992)). */
static inline double pl_pair_slow_share(double r2, double d, double hin, double hout)
{
    double a = d + hin, b = d + hout;
    double x = (r2 - a * a) / (b * b - a * a);
    x = x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x);
    return x * x * (3.0 - 2.0 * x);
}

/* Hecht Eq. 3, delta = d - r > 0 the overlap. */
static inline pl_pair_val_t pl_pair_hertz(double delta, double K)
{
    double sq = sqrt(delta);
    pl_pair_val_t v = {K * delta * delta * sq, 2.5 * K * delta * sq, 3.75 * K * sq};
    return v;
}

/* PL Eq. 16 with a general exponent n (n = 24 in the paper), r < 2^{1/n} sigma. */
static inline pl_pair_val_t pl_pair_wca(double r, double sigma, double eps, double n)
{
    double sn = pow(sigma / r, n), s2n = sn * sn;
    pl_pair_val_t v = {4.0 * eps * (s2n - sn + 0.25), 4.0 * eps * n * (2.0 * s2n - sn) / r,
                       4.0 * eps * n * (2.0 * (2.0 * n + 1.0) * s2n - (n + 1.0) * sn) / (r * r)};
    return v;
}

/* Hecht Eqs. 4-5: squeeze-mode friction coefficient zeta (F = -zeta (v_rel.r) r)
 * for the surface gap h, limited at the minimum gap hmin as Hecht describes (the
 * 1/h law shifted by hmin so the largest force is reached at contact) and
 * shifted to zero at the cut-off gap hcut. */
static inline double pl_pair_lub_zeta(double h, double ri, double rj, double eta, double hmin,
                                      double hcut)
{
    double rred = ri * rj / (ri + rj);
    double he = (h > 0.0 ? h : 0.0) + hmin;
    return 6.0 * PL_PI * eta * rred * rred * (1.0 / he - 1.0 / (hcut + hmin));
}

#endif
