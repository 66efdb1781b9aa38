/* SRD transport coefficients: PL Eqs. 4, 6, 9-15 (random-axis rule), Hecht
 * Eq. 28 (+-90 deg about the coordinate axes); friction of a slip sphere: PL
 * Eqs. 40-43 and the Hasimoto finite-size correction. */
#include "peloid/real.h" /* PL_PI */
#include "peloid/collision_rule.h"
#include "peloid/scene.h"
#include "peloid/srd_theory.h"

#include <math.h>

double pl_srd_f_kin(double g, double a)
{
    /* PL Eq. 11 */
    return 15.0 * g / ((g - 1.0 + exp(-g)) * (4.0 - 2.0 * cos(a) - 2.0 * cos(2.0 * a))) - 1.5;
}

double pl_srd_f_col(double g, double a)
{
    /* PL Eq. 12 */
    return (1.0 - cos(a)) * (1.0 - 1.0 / g + exp(-g) / g);
}

/* PL Eq. 6, the fluid self-diffusion of a rotation by a: a collision keeps
 * on average 1/3 of a relative velocity under both SRD rules at 90 deg (the
 * axis component whole, the two others rotated by 90 deg), so the velocity
 * memory is the same for the axes rule */
static double srd_d_fluid(double g, double a, double nu0, double lambda)
{
    return nu0 * lambda * (3.0 / (2.0 * (1.0 - cos(a))) * (g / (g - 1.0)) - 0.5);
}

void pl_srd_theory_random_axis(double g, double a, double nu0, pl_srd_theory_t *o)
{
    o->f_kin = pl_srd_f_kin(g, a);
    o->f_col = pl_srd_f_col(g, a);
    o->nu_kin = nu0 * o->lambda / 3.0 * o->f_kin;        /* PL Eq. 9 */
    o->nu_col = nu0 / (18.0 * o->lambda) * o->f_col;     /* PL Eq. 10 */
    o->D_f = srd_d_fluid(g, a, nu0, o->lambda);
}

void pl_srd_theory_hecht(double g, double a, double nu0, pl_srd_theory_t *o)
{
    /* Hecht Eq. 28, exact for +-90 deg about the coordinate axes:
     *   nu = a^2/(18 dt) (1 - (1 - e^-M)/M) + kT dt/(4 m_f) (M + 2)/(M - 1).
     * (The paper typesets the kinetic term garbled; this reading gives
     * its Eq. 29, 0.3052 a^2/dt for M = 2.5, lambda = 0.6.)  The
     * collisional part is PL Eq. 10 at 90 deg; the kinetic part is not
     * PL Eq. 9's: a fixed axis keeps the stress component about it. */
    (void)a;
    o->nu_kin = nu0 * (o->lambda / 4.0 * (g + 2.0) / (g - 1.0));
    o->nu_col = nu0 * ((1.0 - (1.0 - exp(-g)) / g) / (18.0 * o->lambda));
    o->f_kin = 3.0 * o->nu_kin / (nu0 * o->lambda); /* as PL Eq. 9 would need */
    o->f_col = 18.0 * o->lambda * o->nu_col / nu0;
    o->D_f = srd_d_fluid(g, 0.5 * PL_PI, nu0, o->lambda);
}

void pl_srd_theory(double g, int rule, double a, double dt, double kT, pl_srd_theory_t *o)
{
    /* units: t0 = a0 sqrt(m/kT) with m = a0 = 1 */
    double t0 = 1.0 / sqrt(kT), nu0 = sqrt(kT);
    o->lambda = dt / t0;                                     /* PL Eq. 4 */
    pl_collision_rule(rule)->theory(g, a, nu0, o);          /* the rule's row */
    o->nu = o->nu_kin + o->nu_col;
    o->eta = g * o->nu;                                      /* PL Eqs. 14-15 */
    o->Sc = o->nu / o->D_f;                                  /* PL Eq. 26 */
    o->tau_f = 1.0 / o->nu;
    o->c_s = sqrt(5.0 * kT / 3.0);
}

static const double HASIMOTO = 2.837297; /* periodic simple-cubic lattice sum */

double pl_srd_xi_enskog(double gamma, double kT, double sigma, double M)
{
    double mu = 1.0 / (1.0 + 1.0 / M); /* M m_f / (M + m_f), m_f = 1 */
    return 8.0 / 3.0 * sqrt(2.0 * PL_PI * kT * mu) * gamma * sigma * sigma; /* PL Eq. 40 */
}

double pl_srd_xi_parallel(double xi_S, double xi_E) { return 1.0 / (1.0 / xi_S + 1.0 / xi_E); }

double pl_srd_xi_stokes_pl(double eta, double sigma, double L)
{
    /* PL Eqs. 42-43 as PL evaluate them: f^-1 = 1 / (1 - 2.837 sigma / L)
     * reproduces their a_eff (Eq. 44) of 1.55, 3.78, 6.11 a0 */
    return 4.0 * PL_PI * eta * sigma / (1.0 - 2.837 * sigma / L);
}

double pl_srd_hasimoto_mobility(double eta, double L) { return HASIMOTO / (6.0 * PL_PI * eta * L); }

double pl_srd_xi_hasimoto(double xi_inf, double eta, double L)
{
    return 1.0 / (1.0 / xi_inf - pl_srd_hasimoto_mobility(eta, L));
}

double pl_srd_tail_missed(double kT, double rho, double a, double L, double t1, double t2)
{
    if (!(t2 > t1 && t1 > 0 && a > 0 && L > 0 && rho > 0 && isfinite(L))) return 0.0;
    /* the terms fall as e^{-a k^2 t1}: |n| up to where that is below e^-40 */
    const double k1 = 2.0 * PL_PI / L;
    const int nmax = (int)ceil(sqrt(40.0 / (a * t1)) / k1);
    double sum = 0.0;
    for (int i = -nmax; i <= nmax; ++i)
        for (int j = -nmax; j <= nmax; ++j)
            for (int l = -nmax; l <= nmax; ++l) {
                const int n2 = i * i + j * j + l * l;
                if (n2 == 0) continue;
                const double x = a * k1 * k1 * n2; /* a k^2 */
                sum += (exp(-x * t1) - exp(-x * t2)) / (x * x);
            }
    return 2.0 / 3.0 * kT / (rho * L * L * L) * sum / (t2 - t1);
}

void pl_srd_theory_of(const struct pl_scene *sc, pl_srd_theory_t *out)
{
    pl_srd_theory(sc->fluid.density, sc->srd.rule, sc->srd.alpha_deg * PL_PI / 180.0, sc->srd.dt, pl_scene_kT(sc),
                  out);
}
