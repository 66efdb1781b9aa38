/* A coupling as a component row (DESIGN.md "Components"): what one
 * colloid-solvent coupling adds to a run.  The coupling module
 * (src/coupling/coupling_module.c) and the common part (coupling.c) ask the
 * row of the scene's coupling.method and hold no if-chain over the methods;
 * a new coupling is its own files plus one row of pl_coupling_rows
 * (src/coupling/coupling_rows.c) and one value of PL_COUPLE_*
 * (coupling_scene.h, with its two names). */
#ifndef PELOID_COUPLING_ROW_H
#define PELOID_COUPLING_ROW_H

#include "peloid/coupling.h"
#include "peloid/thermo.h"

struct pl_sim;
struct json_t;

typedef struct pl_coupling_row {
    int method; /* PL_COUPLE_* */
    /* Its cross-key checks of the scene (NULL: none), after the common
     * ones of pl_coupling_validate_scene; PL_ERR_INPUT naming file:line:key. */
    int (*validate)(const pl_scene_t *scene, pl_err_t *err);
    /* Its own stage moves the colloids (the colloid module then adds no MD). */
    int moves_colloids;
    /* Builds the method's state in cp (after the common part: fluid
     * acceleration, pinning) and prepares the fluid for it (e.g. clears the
     * colloid interiors); 0 or an error. */
    int (*create)(pl_coupling_t *cp, struct pl_sim *sim, pl_err_t *err);
    /* Frees what create made (cp's state may be partly built). */
    void (*free)(pl_coupling_t *cp);
    /* Adds the method's stages at their slots (pl_sim_add_stage). */
    int (*add_stages)(struct pl_sim *sim, pl_err_t *err);
    /* Its thermo.tsv columns (NULL, 0: none). */
    const pl_thermo_column_t *columns;
    int ncolumns;
    /* Its summary.json entries at the end of a run (NULL: none). */
    int (*finish)(const pl_coupling_t *cp, const struct pl_sim *sim, struct json_t *doc, pl_err_t *err);
} pl_coupling_row_t;

/* The row of coupling.method m; NULL for PL_COUPLE_NONE. */
const pl_coupling_row_t *pl_coupling_row(int m);

extern const pl_coupling_row_t pl_coupling1_row;          /* src/coupling/coupling1_row.c */
extern const pl_coupling_row_t pl_coupling2_row;          /* src/coupling/coupling2_row.c */
extern const pl_coupling_row_t pl_coupling_potential_row; /* src/coupling/coupling_potential_row.c */

/* Couplings I and potential start without fluid inside colloids (the
 * colloids' radii, or rad when given): such particles get a new uniform
 * position (src/coupling/coupling.c). */
void pl_coupling_clear_interiors_of(const pl_coupling_t *cp, struct pl_sim *sim, const pl_coupling_lookup_t *lk,
                                    const double *rad);

#endif
