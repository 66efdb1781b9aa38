/* MPC-AT, multi-particle collision with the Andersen thermostat, as a
 * collision-rule row (peloid/collision_rule.h): kernel kernels/mpc_at.c,
 * the cell step in peloid/mpc_at.h.  v_i' = u + xi_i - <xi> with xi_i drawn
 * at the bath's kT (Noguchi, Kikuchi & Gompper, EPL 78, 10005 (2007)).
 *
 * It is a thermostat: each collision draws the cell's relative kinetic
 * energy anew at kT = fluid.temperature (the fluid's kT, which a scene
 * without thermostat takes as its kT), so a second thermostat is refused
 * (fluid_validate); the run's kT_cell column shows the temperature it sets.
 *
 * Transport coefficients in 3D, a0 = m = 1, M = gamma particles per cell,
 * the MPC-AT expressions of Noguchi & Gompper, PRE 78, 016706 (2008) and
 * the review of Gompper, Ihle, Kroll & Winkler, Adv. Polym. Sci. 221, 1
 * (2009) (its MPC-AT section; the equation numbers are not cited: the
 * texts could not be read where this was written, the expressions are
 * re-derived below and tested against measured viscosities,
 * tests/physics/test_mpc_viscosity.c):
 *   nu_kin = (kT dt / m) [M / (M - 1 + e^-M) - 1/2]
 *   nu_col = a^2 / (12 dt) (M - 1 + e^-M) / M          (eta_col = m (M-1+e^-M) / (12 a dt))
 *   D      = (kT dt / m) [M / (M - 1 + e^-M) - 1/2]
 * The factors M - 1 + e^-M are the particle-number fluctuations of a
 * Poisson cell: a collision keeps the fraction (1 - e^-M)/M of a particle's
 * velocity (its share of u), and sum (Delta r_y)^2 of a cell's particles
 * about their centre of mass averages (M - 1 + e^-M) a^2 / 12. */
#include <math.h>

#include "peloid/collision_rule.h"
#include "peloid/mpc_at.h"

#include "srd_state.h"

/* nu0 = sqrt(kT/m) a0; nu0 * lambda = kT dt / m, nu0 / lambda = a0^2 / dt */
static void theory(double g, double alpha, double nu0, pl_srd_theory_t *o)
{
    (void)alpha;
    const double fluct = g - 1.0 + exp(-g); /* M - 1 + e^-M */
    o->nu_kin = nu0 * o->lambda * (g / fluct - 0.5);
    o->nu_col = nu0 / o->lambda * fluct / (12.0 * g);
    o->f_kin = 3.0 * o->nu_kin / (nu0 * o->lambda); /* as PL Eqs. 9-10 would need them */
    o->f_col = 18.0 * o->lambda * o->nu_col / nu0;
    o->D_f = nu0 * o->lambda * (g / fluct - 0.5);
}

const pl_collision_rule_t pl_rule_mpc_at = {
    .name = "mpc_at",
    .doc = "MPC with the Andersen thermostat: v_i' = u + xi_i - <xi>, xi_i Maxwell-Boltzmann at fluid.temperature "
           "(Noguchi, Kikuchi & Gompper 2007); itself a thermostat (thermostat.type must be none); periodic or "
           "slip walls",
    .keys = "fluid.temperature",
    .theory_ref = "MPC-AT: Noguchi & Gompper 2008",
    .theory = theory,
    .collide = pl_mpc_at_collide,
    .srd_rotation = -1,
    .thermostat = 1,
};
