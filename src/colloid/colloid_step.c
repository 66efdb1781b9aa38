/* Colloid time stepping: one MD step (velocity Verlet for translation, Hecht
 * Eqs. 7-8 / PL Eqs. 18-19, rotation Hecht Eqs. 9-10; or one Brownian step)
 * followed by the guards, and the plan stage that runs the MD substeps of one
 * collision step (dt_MD = srd.dt / colloids.substeps, or with adaptive
 * substeps srd.dt / the count chosen at the step's start,
 * src/colloid/colloid_adaptive.c).  The velocity-Verlet (or Brownian) steps
 * of a collision step run in one parallel region (src/colloid/colloid_md.c). */
#include "peloid/colloid.h"
#include "peloid/colloid_integrator.h"

int pl_colloid_md_step(pl_colloid_t *c, pl_err_t *err)
{
    return pl_colloid_integrator(c->integrator)->run(c, 1, err);
}

int pl_colloid_advance(pl_colloid_t *c, long long collision_step, pl_err_t *err)
{
    (void)collision_step;
    c->slow_phase = 0; /* an outer step of multiple time stepping starts here */
    /* adaptive substeps (velocity Verlet only): the count chosen from the
     * state at the step's start, dt = srd.dt / count; should a contact come
     * within PL_ADAPT_REFINE x min_contact_steps MD steps of the guard's
     * bound anyway (energy from a third colloid or a wall beyond the
     * margin), the rest of the collision step runs at the finest MD step,
     * colloids.substeps per collision step: a function of the state, like the
     * choice (under multiple time stepping the outer steps keep their length
     * instead); both inside the MD region (src/colloid/colloid_md.c) */
    return pl_colloid_integrator(c->integrator)->run(c, c->adaptive ? 0 : c->substeps, err);
}
