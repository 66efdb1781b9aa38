/* Spurious depletion forces of the potential coupling (PL Sec. III.C.1).
 *
 * The ideal SRD fluid, kept out of the colloids by the colloid-fluid WCA
 * repulsion of PL Eq. 17, pushes two colloids together with the equilibrium
 * depletion potential (PL Eqs. 22-23)
 *   Phi_depl(d) = n_f kT [V_excl(d) - V_excl(inf)]
 *               = -n_f kT  Int f(|r|) f(|r - d|) d^3r,   f = exp(-phi_cf/kT) - 1,
 * which vanishes beyond twice the colloid-fluid cut-off 2^{1/6} sigma_cf; for
 * hard colloid-fluid spheres it is PL Eq. 24.  This module computes it
 * (GSL adaptive quadrature in bipolar coordinates), tabulates the
 * compensating pair term Phi_comp = -Phi_depl for the colloid force kernel,
 * and gives PL's rule for the colloid-colloid diameter sigma_cc.
 * Energies in kT_ref, lengths in a0. */
#ifndef PELOID_DEPLETION_H
#define PELOID_DEPLETION_H

#include "peloid/error.h"

typedef struct {
    double sigma_cf;   /* colloid-fluid diameter of PL Eq. 17 */
    double epsilon_cf; /* its energy scale (kT_ref) */
    double n;          /* exponent: 4 eps [(s/r)^{2n} - (s/r)^n + 1/4]; PL Eq. 17: 6 */
    int hard_sphere;   /* 1: f = -1 for r < sigma_cf, else 0 (PL Eq. 24's model) */
    double density;    /* n_f = gamma / a0^3 */
    double kT;         /* fluid temperature (kT_ref) */
} pl_depletion_params_t;

/* Energy of PL's sigma_cc rule: phi_cc at twice the colloid-fluid cut-off. */
#define PL_DEPLETION_RULE_ENERGY 2.5

/* Range of phi_cf: 2^{1/n} sigma_cf (sigma_cf for hard spheres); the
 * depletion potential is zero from twice this distance on. */
double pl_depletion_cf_cutoff(const pl_depletion_params_t *p);

/* Phi_depl(d) (PL Eqs. 22-23) and dPhi/dd; 0 with the GSL status message
 * in err otherwise.  Relative accuracy ~1e-10. */
int pl_depletion_potential(const pl_depletion_params_t *p, double d, double *phi, double *dphi,
                           pl_err_t *err);

/* PL Eq. 24: hard colloid-fluid spheres of diameter sigma_cf, d < 2 sigma_cf. */
double pl_depletion_hs(double sigma_cf, double density, double kT, double d);

/* PL Sec. III.C.1 rule: the sigma_cc for which the colloid-colloid potential
 * of PL Eq. 16 (epsilon eps_cc, exponent n) equals `energy` at the distance
 * d_match (twice the colloid-fluid cut-off):
 *   4 eps [x^2 - x + 1/4] = energy,  x = (sigma/d)^n  =>
 *   sigma = d_match (1/2 + sqrt(energy / (4 eps)))^{1/n}. */
double pl_depletion_sigma_cc(double d_match, double eps_cc, double n, double energy);

/* Tabulated Phi_comp = -Phi_depl on m + 1 equidistant nodes r_k = k h,
 * h = 2 r_c / m (r_c = pl_depletion_cf_cutoff): u[k] = Phi_comp(r_k),
 * du[k] = dPhi_comp/dr; u[m] = du[m] = 0.  Interpolated by cubic Hermite
 * (pl_depletion_table_eval). */
int pl_depletion_table(const pl_depletion_params_t *p, int m, double *u, double *du,
                       pl_err_t *err);

/* Cubic Hermite interpolation of such a table at r (0 <= r < m h):
 * value, -d/dr (the repulsive force) and d^2/dr^2. */
static inline void pl_depletion_table_eval(const double *u, const double *du, double inv_h,
                                           double r, double *val, double *force, double *k2)
{
    double t = r * inv_h;
    int k = (int)t;
    double s = t - k, h = 1.0 / inv_h;
    double s2 = s * s, s3 = s2 * s;
    double u0 = u[k], u1 = u[k + 1], m0 = h * du[k], m1 = h * du[k + 1];
    *val = (2 * s3 - 3 * s2 + 1) * u0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * u1 +
           (s3 - s2) * m1;
    double d1 = (6 * s2 - 6 * s) * u0 + (3 * s2 - 4 * s + 1) * m0 + (-6 * s2 + 6 * s) * u1 +
                (3 * s2 - 2 * s) * m1;
    double d2 = (12 * s - 6) * u0 + (6 * s - 4) * m0 + (-12 * s + 6) * u1 + (6 * s - 2) * m1;
    *force = -d1 * inv_h;
    *k2 = d2 * inv_h * inv_h;
}

#endif
