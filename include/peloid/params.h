/* The derived parameters of a scene (src/app/params.c): `peloid
 * params` and `peloid check`, and summary.json "derived". */
#ifndef PELOID_PARAMS_H
#define PELOID_PARAMS_H

#include <stdio.h>

#include "peloid/error.h"
#include "peloid/scene.h"

/* `peloid params`: derived SRD parameters (PL Eqs. 4, 6, 9-15) as text. */
void pl_params_print(const pl_scene_t *scene, FILE *out);

/* The same as a jansson object (summary.json "derived"); a non-finite value
 * is PL_ERR_INPUT naming the key. */
struct json_t;
int pl_params_json(const pl_scene_t *scene, struct json_t **out, pl_err_t *err);

/* `peloid check`: what `run` validates short of running: the thread count
 * of a run without --threads (OMP_NUM_THREADS), the derived values (finite),
 * the mapping report, the colloid placement (init file, overlaps). */
int pl_run_check(const pl_scene_t *scene, pl_err_t *err);

/* `peloid params --json`: the object above, or {"srd": ..., "mapping": ...}
 * for a scene with physical{} (strict: audit warnings are errors). */
int pl_params_write_json(const pl_scene_t *scene, FILE *out, int strict, pl_err_t *err);

#endif
