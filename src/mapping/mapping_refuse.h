/* The mapping's refusals, shared by its files (src/mapping/mapping_refuse.c). */
#ifndef PELOID_MAPPING_REFUSE_H
#define PELOID_MAPPING_REFUSE_H

#include <stddef.h>

#include "peloid/error.h"
#include "peloid/mapping.h"
#include "peloid/scene.h"

/* Whether the scene file gives the key at offset off. */
int pl_mapping_given(const pl_scene_t *s, size_t off);

/* A derived key in the file (its value given_v; the mapping's `derived`, or
 * the word `shown` for a choice): refused unless it carries the derived value
 * (an echoed scene reloads); in a provisional pass (PL_SCENE_PROVISIONAL) the
 * keys of the time unit a calibration replaces (MD step counts, model gravity
 * g t0^2 / a0) are recorded in s->mapping.held and wait for the calibrated pass. */
int pl_mapping_refuse_derived(pl_scene_t *s, pl_err_t *err, size_t off, const char *key, const char *from,
                              double given_v, double derived, const char *shown);

/* The pair term `term` without its material constants: refused at key (the
 * constants it needs, those missing); 0 when `missing` is empty. */
int pl_mapping_refuse_missing(const pl_scene_t *s, pl_err_t *err, size_t off, const char *key, const char *term,
                              const char *needs, const char *missing);

#endif
