/* MPC-AT+a, the Andersen-thermostat collision that keeps each cell's
 * angular momentum, as a collision-rule row (peloid/collision_rule.h):
 * kernel kernels/mpc_at_a.c (peloid/mpc_at.h, then peloid/cell_angular.h):
 *   v_i' = u + xi_i - <xi> + Pi^-1 [sum_j m r_j x (v_j - xi_j)] x r_i
 * (Noguchi, Kikuchi & Gompper, EPL 78, 10005 (2007); positions
 * about the cell's centre of mass in the shifted grid).  A thermostat like
 * MPC-AT (the 3M - 6 non-rigid relative degrees of freedom are drawn at
 * fluid.temperature, the rigid rotation keeps its old energy).
 *
 * Transport coefficients, 3D, a0 = m = 1, M = gamma.  The published
 * expressions (Noguchi & Gompper, PRE 78, 016706 (2008); Gompper et al.,
 * Adv. Polym. Sci. 221, 1 (2009)) could not be read where this was
 * written; these are derived here the way MPC-AT's are (rule_mpc_at.c) and
 * compared with measured viscosities (tests/physics/test_mpc_viscosity.c):
 *  - kinetic: a collision keeps of a cell's xy stress fluctuation the
 *    translational share (1 - e^-M)/M, as MPC-AT, and the rigid rotation's,
 *    tr(B^2) / (M/2) with B the xy stress form on the rotations in the Pi
 *    metric: 1/(4M) for a continuum, 0.43/M, 0.35/M, 0.30/M for M = 5, 10,
 *    20 uniform points (Monte Carlo); taken as 2/5 (within 0.7 % of 1 - f
 *    for M >= 5):
 *      nu_kin = (kT dt / m) [M / (M - 7/5 + e^-M) - 1/2];
 *    measured at M = 10, lambda = 1 (95 % kinetic): +1.4 +- 0.6 % (MPC-AT
 *    there: +3.2 +- 0.5 % against its published form); a velocity memory
 *    (2/M, as for D below) would be 11 % too high;
 *  - collisional: the momentum a collision moves across a cell in a linear
 *    shear flow v_x = s y: MPC-AT's is s sum (y - y_c)^2 (the
 *    (M - 1 + e^-M)/12 of nu_col); the rigid rotation +a keeps gives back
 *    s sum y^2 - (Pi^-1 L) x r, L = s (0, sum yz, -sum y^2): for a continuum
 *    half (the vorticity), for M uniform points X(M)/24 with X(M) = M - 2 +
 *    0.43, 0.19, 0.12, 0.09, 0.075, 0.069 for M = 2, 3, 4, 5, 10, 20 points
 *    (Monte Carlo, 2e5 cells each), over a Poisson cell (M >= 5, within
 *    1.5 % of the Monte Carlo)
 *      X(M) = M - 1.92 + (2 + M) e^-M,   nu_col = a^2 / (24 dt) X(M) / M;
 *    measured at M = 10, lambda = 0.05 (95 % collisional): -1.6 +- 1.0 %
 *    in an 8 x 8 x 24 box, but +9 +- 2.5 % in 4 x 4 x 16: the viscosity
 *    of the +a rule depends on the wavelength (k a = 0.26, 0.39) more than
 *    MPC-AT's.  At M = 5, lambda = 0.1 (12 x 12 x 24) the measured nu is
 *    8.7 +- 1.1 % above the sum (0.3807 +- 0.0042 against 0.350): not
 *    understood, not a test;
 *  - self-diffusion: a particle keeps its share of u (1/M) and of the rigid
 *    rotation (3 of the 3M degrees of freedom: 1/M): D = (kT dt / m)
 *    [M / (M - 2) - 1/2] (an estimate, not tested). */
#include <math.h>

#include "peloid/collision_rule.h"
#include "peloid/mpc_at_a.h"

#include "srd_state.h"

static void theory(double g, double alpha, double nu0, pl_srd_theory_t *o)
{
    (void)alpha;
    o->nu_kin = nu0 * o->lambda * (g / (g - 1.4 + exp(-g)) - 0.5);
    o->nu_col = nu0 / o->lambda * (g - 1.92 + (2.0 + g) * exp(-g)) / (24.0 * g);
    o->f_kin = 3.0 * o->nu_kin / (nu0 * o->lambda); /* as PL Eqs. 9-10 would need them */
    o->f_col = 18.0 * o->lambda * o->nu_col / nu0;
    o->D_f = nu0 * o->lambda * (g / (g - 2.0) - 0.5);
}

const pl_collision_rule_t pl_rule_mpc_at_a = {
    .name = "mpc_at_a",
    .doc = "MPC-AT+a: mpc_at followed by the rigid rotation that keeps each cell's angular momentum about its "
           "centre of mass (Noguchi, Kikuchi & Gompper 2007); itself a thermostat; periodic or slip walls",
    .keys = "fluid.temperature",
    .theory_ref = "MPC-AT+a: derived in src/fluid/rule_mpc_at_a.c",
    .theory = theory,
    .collide = pl_mpc_at_a_collide,
    .srd_rotation = -1,
    .thermostat = 1,
    .positions = 1,
    .angular = 1,
};
