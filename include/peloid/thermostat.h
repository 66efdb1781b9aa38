/* A thermostat of the fluid as a component row (issue 46, like
 * peloid/collision_rule.h): its name (the scene's thermostat.type), what it
 * does, the keys it reads, its check of the scene and what it adds to the
 * plan.  The rows are listed once, in src/fluid/thermostats.c; a
 * thermostat's own file holds its row and its stages.  The scene stores the
 * row's index (thermostat.type); row 0 is "none" (PL_THERMO_NONE,
 * peloid/scene.h): every other row sets thermostat.temperature. */
#ifndef PELOID_THERMOSTAT_H
#define PELOID_THERMOSTAT_H

#include "peloid/error.h"

struct pl_scene;
struct pl_sim;
struct pl_srd;

typedef struct pl_thermostat {
    const char *name; /* the value of thermostat.type */
    const char *doc;  /* what it does and its equations */
    const char *keys; /* thermostat.* keys it reads */
    /* it runs inside the collision: the collision rule's and coupling II's
     * Heyes kernels on multiples of thermostat.interval instead of the plain
     * ones (pl_sim_add_collide_stage) */
    int in_collision;
    /* NULL, or its own check of the scene (the collision rule it needs); an
     * error names the key */
    int (*validate)(const struct pl_scene *scene, pl_err_t *err);
    /* NULL, or adds its stages (pl_sim_add_stage), whose context is the
     * fluid's state fs */
    int (*add_stages)(struct pl_sim *sim, struct pl_srd *fs, pl_err_t *err);
} pl_thermostat_t;

/* Row `type` (the scene's thermostat.type); NULL outside. */
const pl_thermostat_t *pl_thermostat(int type);
/* The rows' names in row order, NULL-terminated: the choices of thermostat.type. */
extern const char *const pl_thermostat_names[];

#endif
