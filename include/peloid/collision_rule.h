/* A collision rule of the fluid as a component row (DESIGN.md "Core,
 * components, app"): its name (the scene's srd.rule), the keys it reads,
 * its check of the scene, the transport theory the physical mapping and the
 * observers use, and the kernels that run it.  The rows are listed once, in
 * src/fluid/collision_rules.c; a rule's own files hold its kernel, its
 * theory and its row.  The scene stores the row's index (srd.rule). */
#ifndef PELOID_COLLISION_RULE_H
#define PELOID_COLLISION_RULE_H

#include "peloid/error.h"
#include "peloid/srd_kernels.h" /* pl_collide_params_t, pl_fluid_t, pl_grid_t */
#include "peloid/srd_theory.h"

struct pl_scene;

/* One collision of every cell (the contract of pl_srd_collide: block_sum
 * receives per block of PL_CELL_BLOCK cells sum m (v-u)^2 after the
 * collision and the degrees of freedom 3(M-1); p->guard_bad, when set, one
 * flag per block). */
typedef void (*pl_collide_fn)(pl_fluid_t *fluid, const pl_grid_t *grid, const uint32_t *cell_start,
                              const pl_collide_params_t *p, double *block_sum, int nthreads);

typedef struct pl_collision_rule {
    const char *name;       /* the value of srd.rule */
    const char *doc;        /* what it does and its equations (README key reference) */
    const char *keys;       /* scene keys it reads besides srd.dt and fluid.density */
    const char *theory_ref; /* where its viscosity comes from (reports, summary.json) */
    /* transport coefficients: nu_kin, nu_col, f_kin, f_col and D_f of
     * *out from gamma, the angle alpha (radians; rules without one ignore
     * it), out->lambda (set) and nu0 = sqrt(kT / m) a0 */
    void (*theory)(double gamma, double alpha, double nu0, pl_srd_theory_t *out);
    /* NULL, or the rule's own check of the scene (what it needs besides the
     * checks every rule gets from its flags below); an error names the key */
    int (*validate)(const struct pl_scene *scene, pl_err_t *err);
    pl_collide_fn collide;       /* the collision */
    pl_collide_fn collide_heyes; /* with the Heyes thermostat; NULL: the rule refuses it */
    int srd_rotation;  /* PL_RULE_* of the rotation pl_srd_rotation draws (the SRD kernel and
                        * coupling II's colloid cells); -1: not a rotation rule */
    int thermostat;    /* the rule sets the temperature itself (no thermostat.type besides none) */
    int positions;     /* the kernel reads the particle positions */
    int angular;       /* the collision keeps each cell's angular momentum about its centre of mass */
    int wall_ghosts;   /* the kernel fills cells cut by a no-slip wall with virtual particles (Lamura et
                        * al. 2001); 0: the rule refuses no-slip walls (src/fluid/fluid_stages.c) */
} pl_collision_rule_t;

/* Row `rule` (the scene's srd.rule, an index into the rows); NULL outside. */
const pl_collision_rule_t *pl_collision_rule(int rule);
/* The rows' names in row order, NULL-terminated: the choices of srd.rule. */
extern const char *const pl_collision_rule_names[];

#endif
