/* SRD+a, the SRD rotation that keeps each cell's angular momentum, as a
 * collision-rule row (peloid/collision_rule.h): kernel kernels/srd_a.c
 * (peloid/srd_rules.h, then peloid/cell_angular.h):
 *   v_i' = u + R (v_i - u) + Pi^-1 [sum_j m r_j x (v_j - v_j^R)] x r_i,
 * R the random-axis rotation by alpha of PL Eq. 3 (the cell's draw of the
 * random_axis rule), v^R the rotated velocities, r about the cell's centre
 * of mass in the shifted grid (Noguchi & Gompper, PRE 78, 016706 (2008);
 * Goetze, Noguchi & Gompper, PRE 76, 046705 (2007): with it the stress
 * tensor is symmetric and a rotating colloid feels the right torque).
 *
 * Transport coefficients, 3D, a0 = m = 1, M = gamma.  The published
 * expressions could not be read where this was written; derived here:
 *  - collisional: the collision's momentum change in a linear shear flow is
 *    linear in v - v', and its mean over the random axis, (1 - <R>) (v - u)
 *    = 2/3 (1 - cos alpha) (v - u), is that of MPC-AT (whose mean change is
 *    v - u) times c = 2/3 (1 - cos alpha); the +a rotation is linear in the
 *    same change, so SRD+a's collisional viscosity is c times MPC-AT+a's
 *    (src/fluid/rule_mpc_at_a.c, X(M) = M - 1.92 + (2 + M) e^-M):
 *      nu_col = (1 - cos alpha) a^2 X(M) / (36 dt M)
 *    (the same c turns MPC-AT's (M - 1 + e^-M) / (12 M) into PL Eq. 10);
 *    tested against a Kolmogorov flow in the collisional regime
 *    (tests/physics/test_mpc_viscosity.c, validate-physics);
 *  - kinetic and the fluid's self-diffusion: SRD's (PL Eqs. 9, 6), not
 *    derived for +a (whose kept rigid rotation retains a little more of the
 *    stress and of the velocity); at lambda = 0.05, gamma = 10 the kinetic
 *    part is 3 % of nu.
 * Each cell's kinetic energy kept (kernels/srd_a.c): the two rotations
 * change the energy of the part of the relative velocities that is not the
 * cell's rigid rotation (that part keeps its energy, its angular momentum
 * being kept), so that part is scaled back to its energy before the
 * collision; momentum and angular momentum are untouched by the scaling.
 * Like SRD, then, the rule keeps mass, momentum and energy and needs no
 * thermostat; it also keeps angular momentum.  Its stationary state (a
 * pure fluid's checkpoint read with h5py): the cells' relative and mean
 * velocities at kT, the velocity distribution's fourth moment measurably
 * above Maxwell's (the scaled projection is not an orthogonal map of the
 * non-rigid velocities, so the cell's microcanonical measure is kept only
 * nearly).  Before the scaling, the rigid rotation heated the fluid, and a
 * rescaling thermostat could not bring it to equilibrium (the cells' mean
 * velocities ran hot).  The figures: validation/REPORT.md, "A pure fluid
 * at equilibrium" (tests/validation/fluid_equilibrium.sh) and the SRD+a
 * section of the resolution study. */
#include <math.h>

#include "peloid/collision_rule.h"
#include "peloid/srd_a.h"

#include "srd_state.h"

static void theory(double g, double alpha, double nu0, pl_srd_theory_t *o)
{
    pl_srd_theory_random_axis(g, alpha, nu0, o); /* kinetic part and D_f: SRD's (see above) */
    o->nu_col = nu0 / o->lambda * (1.0 - cos(alpha)) * (g - 1.92 + (2.0 + g) * exp(-g)) / (36.0 * g);
    o->f_col = 18.0 * o->lambda * o->nu_col / nu0; /* as PL Eq. 10 would need it */
}

const pl_collision_rule_t pl_rule_srd_a = {
    .name = "srd_a",
    .doc = "SRD+a: random_axis followed by the rigid rotation that keeps each cell's angular momentum about its "
           "centre of mass (Noguchi & Gompper 2008), each cell's energy kept by scaling the rest of its relative "
           "velocities back (no thermostat needed); periodic or slip walls; not with coupling II.  Its velocity "
           "distribution departs slightly from Maxwell's (validation/REPORT.md, a pure fluid at equilibrium); mpc_at_a "
           "keeps angular momentum with an exact Andersen thermostat",
    .keys = "srd.alpha",
    .theory_ref = "SRD+a: derived in src/fluid/rule_srd_a.c",
    .theory = theory,
    .collide = pl_srd_a_collide,
    .srd_rotation = PL_RULE_RANDOM_AXIS,
    .positions = 1,
    .angular = 1,
};
