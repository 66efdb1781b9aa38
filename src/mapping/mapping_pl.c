/* Padding-Louis quantities of a colloid in an SRD fluid (simulation units,
 * PL Table VI) and of a colloid in a real solvent (SI, PL Table V): friction,
 * diffusion, the time scales of PL Table III and the dimensionless numbers
 * of PL Table II.
 *
 * PL Eqs. 26 (Sc), 28 (Ma), 29 (Re), 30 (t_S), 31 (tau_nu), 34 (Kn), 35 (Pe),
 * 36 (tau_D), 39-41 (Stokes and Enskog friction in parallel), 46 (t_cs),
 * 47 (tau_B), 53 (tau_E), 54 (Stokes-Einstein).  Length scale a = R = sigma_cf
 * (PL Table VI caption: a ~ sigma_cf).  The MD step of the colloid-fluid
 * contact of PL Eq. 17. */
#include <math.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/mapping.h"

void pl_mapping_pl_colloid(double sigma, double rho_ratio, double v_sim, const pl_mapping_cg_t *cg,
                           pl_mapping_t *m)
{
    const double gamma = cg->gamma, lambda = cg->lambda;
    m->sigma = sigma;
    m->nu_sim = pl_mapping_nu(cg->viscosity, lambda, gamma, cg->alpha);
    m->d_fluid_sim = pl_mapping_d_fluid_rule(cg->viscosity, lambda, gamma, cg->alpha); /* the rule's own */
    m->mass_sim = rho_ratio * gamma * 4.0 / 3.0 * PL_PI * sigma * sigma * sigma; /* PL Table VI */
    double eta = gamma * m->nu_sim;                                   /* PL Eq. 13: eta = rho_f nu */
    double k = cg->boundary == PL_BOUNDARY_STICK ? 6.0 : 4.0;         /* PL Eq. 39 and below */
    m->xi_stokes_sim = k * PL_PI * eta * sigma;
    m->xi_enskog_sim = pl_mapping_xi_enskog(sigma, m->mass_sim, gamma, cg->boundary);
    m->xi_sim = cg->enskog ? 1.0 / (1.0 / m->xi_stokes_sim + 1.0 / m->xi_enskog_sim) /* PL Eq. 41 */
                           : m->xi_stokes_sim;
    m->d_col_theory = 1.0 / m->xi_sim; /* PL Eq. 54, kT = 1 */
    /* what the coupling realises, where a calibration measured it */
    m->d_col_sim = cg->d_col_calibrated > 0 ? cg->d_col_calibrated : m->d_col_theory;

    const double cs = sqrt(5.0 / 3.0); /* PL Sec. IV.B: c_s = sqrt(5 kT / 3 m_f) */
    pl_mapping_pl_times_t *t = &m->pl_model;
    t->t_cs = sigma / cs;                    /* PL Eq. 46 */
    t->tau_nu = sigma * sigma / m->nu_sim;   /* PL Eq. 31 */
    t->tau_B = m->mass_sim / m->xi_stokes_sim; /* PL Eq. 47 */
    t->tau_E = m->mass_sim / m->xi_enskog_sim; /* PL Eq. 53 */
    t->tau_D = sigma * sigma / m->d_col_sim; /* PL Eq. 36 */
    t->t_S = v_sim > 0 ? sigma / v_sim : NAN; /* PL Eq. 30 */

    pl_mapping_numbers_t *n = &m->num_model;
    n->Sc = m->nu_sim / m->d_fluid_sim;      /* PL Eq. 26 */
    n->Ma = v_sim / cs;                      /* PL Eq. 28 */
    n->Re = v_sim * sigma / m->nu_sim;       /* PL Eq. 29 */
    n->Kn = lambda / sigma;                  /* PL Eq. 34, lambda_free = lambda a0 */
    n->Pe = v_sim * sigma / m->d_col_sim;    /* PL Eq. 35 */
}

void pl_mapping_pl_real(const pl_mapping_system_t *r, const pl_mapping_solvent_t *sv, double v,
                        int boundary, pl_mapping_pl_times_t *t, pl_mapping_numbers_t *n)
{
    const double a = r->radius;
    double eta = r->rho_f * r->nu;
    double mass = 4.0 / 3.0 * PL_PI * a * a * a * r->rho_p;
    double xi_s = (boundary == PL_BOUNDARY_STICK ? 6.0 : 4.0) * PL_PI * eta * a;
    double D = r->kT / xi_s; /* PL Table V neglects the Enskog term */
    t->t_cs = sv->sound_speed > 0 ? a / sv->sound_speed : NAN;
    t->tau_nu = a * a / r->nu;
    t->tau_B = mass / xi_s;
    t->tau_E = NAN; /* needs the molecular Enskog friction; not modelled */
    t->tau_D = a * a / D;
    t->t_S = v > 0 ? a / v : NAN;
    n->Sc = sv->self_diffusion > 0 ? r->nu / sv->self_diffusion : NAN;
    n->Ma = sv->sound_speed > 0 ? v / sv->sound_speed : NAN;
    n->Re = v * a / r->nu;
    n->Kn = sv->mean_free_path / a;
    n->Pe = v * a / D;
}

double pl_mapping_cf_contact_time(double sigma_cf, double eps_cf, double M)
{
    /* PL Eq. 17 = kT at r_1 (bisection on s = (sigma/r)^6 in [1/2, big]:
     * 4 eps (s^2 - s + 1/4) = 1 has the root s = 1/2 + sqrt(1 / (4 eps))) */
    const double s6 = 0.5 + sqrt(1.0 / (4.0 * eps_cf));
    const double r = sigma_cf / pow(s6, 1.0 / 6.0);
    const double u2 = 4.0 * eps_cf * (156.0 * s6 * s6 - 42.0 * s6) / (r * r); /* U''(r_1) */
    const double m_red = M / (M + 1.0);
    return PL_PI * sqrt(m_red / u2);
}

long long pl_mapping_cf_substeps(double sigma_cf, double eps_cf, double M, double dt, double resolution)
{
    const double n = ceil(resolution * dt / pl_mapping_cf_contact_time(sigma_cf, eps_cf, M) - 1e-9);
    return n < 1.0 ? 1 : (long long)n;
}
