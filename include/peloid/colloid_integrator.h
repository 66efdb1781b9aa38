/* A colloid integrator as a component row (DESIGN.md "Components"): the
 * colloid module and every check that depends on how colloids are moved ask
 * the row of colloids.integrator (its properties), never its value.  A new
 * integrator is its own files plus one row of pl_colloid_integrators
 * (src/colloid/colloid_integrators.c), one PL_CINT_* value and its name in
 * colloids.integrator's choices (src/scene/scene_keys_colloid.c). */
#ifndef PELOID_COLLOID_INTEGRATOR_H
#define PELOID_COLLOID_INTEGRATOR_H

#include "peloid/error.h"

struct pl_colloid;

typedef struct pl_colloid_integrator {
    int id;           /* PL_CINT_* */
    const char *name; /* its colloids.integrator value */
    /* Newton's equations: velocities and angular velocities are integrated
     * and carry the colloids' inertia, so a coupling to the fluid, the
     * thermal lubrication partner, the NVE energy guard, velocity observers
     * (VACF, velocity distribution), multiple time stepping and adaptive
     * substeps (the contact guard's MD) apply.  0: overdamped (a new
     * velocity each step; the solvent is the integrator's Stokes friction). */
    int inertial;
    /* n MD steps in one parallel region, each the move, the forces and the
     * guards (n = 0: adaptive substeps, inertial integrators only). */
    int (*run)(struct pl_colloid *c, int n, pl_err_t *err);
} pl_colloid_integrator_t;

/* The row of colloids.integrator id (every PL_CINT_* has one). */
const pl_colloid_integrator_t *pl_colloid_integrator(int id);

#endif
