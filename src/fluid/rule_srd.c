/* The two SRD rotation rules as collision-rule rows (peloid/collision_rule.h):
 * v_i -> u + R (v_i - u) with R a rotation by alpha about a random axis (PL
 * Eq. 3) or by +-90 deg about a coordinate axis (Hecht Sec. III); the kernel
 * is kernels/srd_collide.c (with or without the Heyes thermostat), the
 * theory src/fluid/srd_theory.c (PL Eqs. 6, 9-12; Hecht Eq. 28).  Both
 * conserve each cell's momentum and kinetic energy, not its angular
 * momentum. */
#include "peloid/collision_rule.h"

#include "srd_state.h"

const pl_collision_rule_t pl_rule_random_axis = {
    .name = "random_axis",
    .doc = "rotate the velocities relative to the cell's mean by alpha about a random axis (PL Eq. 3)",
    .keys = "srd.alpha",
    .theory_ref = "PL Eqs. 9-12",
    .theory = pl_srd_theory_random_axis,
    .collide = pl_srd_collide,
    .collide_heyes = pl_srd_collide_heyes,
    .srd_rotation = PL_RULE_RANDOM_AXIS,
    .wall_ghosts = 1,
};

const pl_collision_rule_t pl_rule_hecht_axes = {
    .name = "hecht_axes",
    .doc = "+-90 deg about one of the 3 coordinate axes (Hecht Sec. III)",
    .keys = "",
    .theory_ref = "Hecht Eq. 28",
    .theory = pl_srd_theory_hecht,
    .collide = pl_srd_collide,
    .collide_heyes = pl_srd_collide_heyes,
    .srd_rotation = PL_RULE_HECHT_AXES,
    .wall_ghosts = 1,
};
