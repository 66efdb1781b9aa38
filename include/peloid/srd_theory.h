/* Transport coefficients of an SRD fluid (PL Sec. II.B, Eqs. 4-15), in the
 * simulation units a0 = 1, m_f = 1 (kT as given). */
#ifndef PELOID_SRD_THEORY_H
#define PELOID_SRD_THEORY_H

#include "peloid/kernel_enums.h" /* PL_RULE_* */

typedef struct {
    double lambda;   /* mean free path / a0 (PL Eq. 4) */
    double f_kin, f_col; /* PL Eqs. 11-12 */
    double nu_kin, nu_col, nu; /* kinematic viscosity (PL Eqs. 9-10) */
    double eta;      /* shear viscosity rho nu (PL Eqs. 14-15) */
    double D_f;      /* fluid self-diffusion (PL Eq. 6) */
    double Sc;       /* Schmidt number nu / D_f (PL Eq. 26) */
    double tau_f;    /* fluid momentum-diffusion time over a cell, a0^2 / nu */
    double c_s;      /* ideal-gas speed of sound sqrt(5 kT / 3 m) */
} pl_srd_theory_t;

/* gamma: particles per cell, rule: the collision rule's row (srd.rule,
 * peloid/collision_rule.h; PL_RULE_* for the SRD rows), alpha in radians
 * (the random-axis rule's angle; rules without an angle ignore it), dt:
 * collision step, kT.  The row's theory gives nu_kin, nu_col and D_f. */
void pl_srd_theory(double gamma, int rule, double alpha, double dt, double kT, pl_srd_theory_t *out);

double pl_srd_f_kin(double gamma, double alpha);
/* The SRD rows' theories (peloid/collision_rule.h): PL Eqs. 6, 9-12 for a
 * rotation by alpha about a random axis; Hecht Eq. 28 (and PL Eq. 6 at 90
 * deg) for +-90 deg about the coordinate axes, whatever alpha is. */
void pl_srd_theory_random_axis(double gamma, double alpha, double nu0, pl_srd_theory_t *out);
void pl_srd_theory_hecht(double gamma, double alpha, double nu0, pl_srd_theory_t *out);
double pl_srd_f_col(double gamma, double alpha);

/* Friction of a slip sphere of radius sigma_cf in an SRD fluid of gamma
 * particles (m_f = 1) per cell (PL Sec. V.A), simulation units. */

/* Enskog friction, PL Eq. 40, with the reduced mass M m_f / (M + m_f); a
 * pinned colloid is M = INFINITY. */
double pl_srd_xi_enskog(double gamma, double kT, double sigma_cf, double M);
/* PL Eq. 41: 1 / xi = 1 / xi_S + 1 / xi_E. */
double pl_srd_xi_parallel(double xi_S, double xi_E);
/* Stokes friction of a slip sphere in a periodic box of side L, PL Eqs.
 * 42-43 as PL evaluate them: 4 pi eta sigma_cf / (1 - 2.837 sigma_cf / L).
 * PL write f ~ 1 + 2.837 sigma_cf / L (lowest order) and xi_S = 4 pi eta
 * sigma_cf f^-1; their effective radii a_eff = 1.55, 3.78, 6.11 a0 (PL Eq.
 * 44, sigma_cf = 2, 4, 6, L = 16 sigma_cf) follow from f^-1 = 1 / (1 -
 * 2.837 sigma_cf / L), Hasimoto's drag factor of a fixed stick-sphere
 * array, and from neither 1 + 2.837 sigma_cf / L (1.52, 3.69, 5.97) nor
 * 1 / (1 + 2.837 sigma_cf / L) (1.21, 2.83, 4.50).  L = INFINITY: no
 * correction. */
double pl_srd_xi_stokes_pl(double eta, double sigma_cf, double L);
/* Friction of a sphere free to move in a periodic box of side L with zero
 * total momentum (Hasimoto 1959; Duenweg & Kremer 1993): the periodic images
 * add -2.837 / (6 pi eta L) to the mobility, whatever the surface, so
 * 1 / xi_L = 1 / xi_inf - 2.837 / (6 pi eta L); xi_inf is the unbounded
 * friction (e.g. PL Eq. 41 with xi_S = 4 pi eta sigma_cf). */
double pl_srd_xi_hasimoto(double xi_inf, double eta, double L);
/* The periodic images' share of that: 2.837 / (6 pi eta L), the mobility a
 * colloid loses in a periodic cube of side L (times kT: the lost D). */
double pl_srd_hasimoto_mobility(double eta, double L);

/* The hydrodynamic long-time tail a colloid's mean-squared displacement
 * misses at finite lags in a periodic cube of side L (Alder & Wainwright
 * 1970; Hansen & McDonald Sec. 8.6): each axis of the velocity
 * autocorrelation decays through the fluid's transverse modes k = 2 pi n / L
 * (n != 0, zero total momentum) as
 *   C(s) = (2/3) kT / (rho L^3) sum_k exp(-a k^2 s),   a = nu + D,
 * which is (2/3) (kT / rho) [4 pi a s]^-3/2 for L -> infinity.  The slope of
 * the MSD between lags t1 < t2 is the mean of D(t) = int_0^t C over [t1, t2];
 * it lies below the box's long-time D by the mean of int_t^inf C ds:
 *   (2/3) kT / (rho L^3) sum_k (e^{-a k^2 t1} - e^{-a k^2 t2}) / (a^2 k^4 (t2 - t1)).
 * This is that amount (the box's long-time D minus the slope; Hasimoto's
 * correction then takes the box's long-time D to the unbounded one).  rho:
 * the fluid's mass density (gamma m_f / a0^3). */
double pl_srd_tail_missed(double kT, double rho, double a, double L, double t1, double t2);

/* pl_srd_theory of a scene's fluid: its fluid.density, srd.rule, srd.alpha,
 * srd.dt and kT (pl_scene_kT). */
struct pl_scene;
void pl_srd_theory_of(const struct pl_scene *scene, pl_srd_theory_t *out);

#endif
