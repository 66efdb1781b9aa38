/* SRD transport coefficients and colloid friction in simulation units
 * (a0 = m_f = kT = 1, t0 = a0 sqrt(m_f/kT)).
 *
 * PL Eqs. 6, 9-12 (fluid self-diffusion, kinetic and collisional kinematic
 * viscosity for rotation by alpha about a random axis), Hecht Eq. 28 (the
 * viscosity for +-90 deg rotations about the coordinate axes), PL Eq. 40
 * (Enskog friction, slip).
 */
#include <math.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/mapping.h"
#include "peloid/srd_theory.h"

/* PL Eqs. 6 and 9-12 live in src/fluid/srd_theory.c; these evaluate them in the
 * mapping's units (kT = 1, dt = lambda). */
static pl_srd_theory_t srd(double lambda, double gamma, int rule, double alpha)
{
    pl_srd_theory_t t;
    pl_srd_theory(gamma, rule, alpha, lambda, 1.0, &t);
    return t;
}

double pl_mapping_nu_kin(double lambda, double gamma, double alpha) { return srd(lambda, gamma, PL_RULE_RANDOM_AXIS, alpha).nu_kin; }
double pl_mapping_nu_col(double lambda, double gamma, double alpha) { return srd(lambda, gamma, PL_RULE_RANDOM_AXIS, alpha).nu_col; }
double pl_mapping_d_fluid(double lambda, double gamma, double alpha) { return srd(lambda, gamma, PL_RULE_RANDOM_AXIS, alpha).D_f; }

double pl_mapping_nu_hecht(double lambda, double gamma)
{
    pl_srd_theory_t t = srd(lambda, gamma, PL_RULE_HECHT_AXES, 0.5 * PL_PI); /* Hecht Eq. 28 */
    return t.nu_col + t.nu_kin;
}

double pl_mapping_nu(int rule, double lambda, double gamma, double alpha)
{
    pl_srd_theory_t t = srd(lambda, gamma, rule, alpha); /* the rule's row */
    return t.nu_kin + t.nu_col;
}

double pl_mapping_d_fluid_rule(int rule, double lambda, double gamma, double alpha)
{
    return srd(lambda, gamma, rule, alpha).D_f;
}

double pl_mapping_xi_enskog(double sigma, double mc, double gamma, int boundary)
{
    /* PL Eq. 40, slip: xi_E = 8/3 sqrt(2 pi kT mu) n_f sigma^2 with the
     * reduced mass mu = M m_f/(M + m_f) (the paper prints M + m_f in the
     * numerator's place; the reduced mass is meant). */
    double mu = mc / (mc + 1.0);
    double xi = 8.0 / 3.0 * sqrt(2.0 * PL_PI * mu) * gamma * sigma * sigma;
    if (boundary == PL_BOUNDARY_STICK) {
        /* Stick (stochastic, rough-sphere) boundaries: PL Table VI uses the
         * stick form of ref. [58], not printed in PL.  The kinetic-theory
         * rough-sphere result multiplies the smooth-sphere friction by
         * (1 + 2k)/(1 + k), k = 4 I/(M sigma_d^2) = 2/5 for a uniform sphere;
         * it reproduces Table VI's tau_E = 0.98 t0 and 4.9 t0. */
        const double k = 0.4;
        xi *= (1.0 + 2.0 * k) / (1.0 + k);
    }
    return xi;
}

double pl_mapping_debye_kappa(double ionic_strength_molar, double eps_r, double kT)
{
    /* Debye-Hueckel: kappa^2 = 2 N_A e^2 I / (eps_r eps0 kT), I = 1/2 sum c_i z_i^2
     * converted from mol/L to mol/m^3. */
    double I = ionic_strength_molar * 1.0e3;
    return sqrt(2.0 * PL_NA * PL_E_CHARGE * PL_E_CHARGE * I / (eps_r * PL_EPS0 * kT));
}
