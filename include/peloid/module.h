/* Modules of a simulation (DESIGN.md "Scene -> plan"): the fluid, the
 * colloids, the colloid-solvent couplings, the observers.  Each registers
 * here, in one table row, what it adds to a run; its own file holds its
 * stages, its thermo columns and its summary entries.  Adding a module (a
 * coupling) is its file plus one row of pl_modules (src/core/modules.c);
 * adding an observable is its file plus one row of the observer table
 * (peloid/observer.h, src/observe/observers.c).  Where a module's stages run in a step is their slot
 * (pl_stage_slot_t, peloid/sim.h). */
#ifndef PELOID_MODULE_H
#define PELOID_MODULE_H

#include <stdint.h>
#include <stdio.h>

#include "peloid/error.h"
#include "peloid/sim.h"
#include "peloid/thermo.h"

struct json_t;

typedef struct pl_module {
    const char *name;
    /* Cross-key checks of its own scene sections, run by pl_scene_validate
     * in module order after the scene's generic checks (NULL: none);
     * PL_ERR_INPUT with file:line:key (pl_scene_fail). */
    int (*validate_scene)(const pl_scene_t *scene, pl_err_t *err);
    /* Creates the module's state in sim from sim->scene (NULL: nothing to
     * create; a module the scene does not ask for creates nothing). */
    int (*create)(pl_sim_t *sim, pl_err_t *err);
    /* Frees what create made (NULL: nothing). */
    void (*destroy)(pl_sim_t *sim);
    /* Adds the stages the scene needs (pl_sim_add_stage, with their slots);
     * 0 or the error of the stage it could not add. */
    int (*add_stages)(pl_sim_t *sim, pl_err_t *err);
    /* Adds the thermo.tsv columns the scene needs, in order (pl_thermo_add). */
    void (*thermo_columns)(const pl_sim_t *sim, pl_thermo_table_t *t);
    /* Writes what the user should know of its set-up at the start of a run
     * to log, "peloid: " lines (NULL: nothing). */
    void (*describe)(const pl_sim_t *sim, FILE *log);
    /* Adds its entries to the head of summary.json (NULL: none); a
     * non-finite value is PL_ERR_INPUT naming the key. */
    int (*summary)(const pl_sim_t *sim, struct json_t *doc, pl_err_t *err);
    /* At the end of a run: writes its output files into dir and adds what it
     * measured to summary.json (NULL: nothing). */
    int (*finish)(pl_sim_t *sim, const char *dir, struct json_t *doc, pl_err_t *err);
    /* Its checkpoint items, written into and read from the open HDF5 file
     * `file` (an hid_t) after the fluid's, in module order (NULL: none);
     * write: 0 or -1; read: 0 or PL_ERR_INPUT naming path and item. */
    int (*checkpoint_write)(int64_t file, const pl_sim_t *sim);
    int (*checkpoint_read)(int64_t file, pl_sim_t *sim, const char *path, pl_err_t *err);
    /* Items in two more places of the file (NULL: none), so that the
     * fluid's, which the core once wrote there, keep every checkpoint's
     * bytes: root attributes after the format's own (before colloid_count),
     * and items after every module's checkpoint_write; read by checkpoint_read. */
    int (*checkpoint_attrs)(int64_t file, const pl_sim_t *sim);
    int (*checkpoint_write_last)(int64_t file, const pl_sim_t *sim);
} pl_module_t;

/* The modules, NULL-terminated, in the order they are created, their stages
 * registered (within a slot), their columns and entries written. */
extern const pl_module_t *const pl_modules[];

extern const pl_module_t pl_fluid_module;    /* src/fluid/fluid_stages.c */
extern const pl_module_t pl_colloid_module;  /* src/colloid/colloid_module.c */
extern const pl_module_t pl_coupling_module; /* src/coupling/coupling_module.c */
extern const pl_module_t pl_observe_module;  /* src/observe/observe_module.c */
extern const pl_module_t pl_stop_module;     /* src/observe/stop_module.c */
extern const pl_module_t pl_stress_module;  /* src/observe/stress_module.c */

/* The state module m's create made (NULL: none), and setting it (create,
 * destroy); m must be a row of pl_modules.  Only the module itself (and its
 * own files) reads it: others use the functions it offers (src/core/modules.c). */
void *pl_module_state(const pl_sim_t *sim, const pl_module_t *m);
void pl_module_set_state(pl_sim_t *sim, const pl_module_t *m, void *state);

/* Whether the observers run in this simulation (the stop rule and the stress
 * observer's output ask; src/observe/observe_module.c). */
int pl_observe_running(const pl_sim_t *sim);

/* The present value and SE of the observers' estimate `name`
 * (stop.observable); 0 when it has none yet (src/observe/observe_module.c). */
int pl_observe_estimate(const pl_sim_t *sim, const char *name, double *value, double *se);

/* The k-th observer of the run (k = 0, 1, ...) that ended with none of its
 * estimates valid: 1 and why (n bytes: the observer, its interval key, the
 * estimates missing from summary.json and what keeps them from a value), or
 * 0 when there are fewer than k + 1 (src/observe/observe_module.c).  The
 * observe module lists them in summary.json "observables" "not_measured";
 * the run warns of each at its end. */
int pl_observe_unmeasured(const pl_sim_t *sim, int k, char *why, size_t n);

#endif
