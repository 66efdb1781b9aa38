/* The colloid integrator rows (peloid/colloid_integrator.h), indexed by
 * PL_CINT_*: velocity Verlet with quaternion rotation (Hecht Eqs. 7-10, PL
 * Eqs. 18-19) and overdamped Brownian dynamics with Stokes friction; both
 * run their steps in src/colloid/colloid_md.c. */
#include "peloid/colloid.h"
#include "peloid/colloid_integrator.h"

static const pl_colloid_integrator_t rows[] = {
    [PL_CINT_VERLET] = {.id = PL_CINT_VERLET, .name = "verlet", .inertial = 1, .run = pl_colloid_verlet_run},
    [PL_CINT_BROWNIAN] = {.id = PL_CINT_BROWNIAN, .name = "brownian", .inertial = 0, .run = pl_colloid_bd_run},
};

const pl_colloid_integrator_t *pl_colloid_integrator(int id) { return &rows[id]; }
