/* The checkpoint of a whole simulation (src/core/checkpoint.c, format and
 * checks there) and the items it is made of: the scene fingerprint
 * (src/core/checkpoint_scene.c) and the components' own groups, each in its
 * component's folder and written by its module (pl_module_t.checkpoint_write).
 * The HDF5 helpers they share: src/io/checkpoint_h5.h. */
#ifndef PELOID_CHECKPOINT_H
#define PELOID_CHECKPOINT_H

#include <hdf5.h>

#include "peloid/colloid.h"
#include "peloid/error.h"
#include "peloid/scene.h"
#include "peloid/sim.h"

struct pl_coupling; /* peloid/coupling.h */

/* HDF5 checkpoint of the complete dynamic state: the fluid's
 * arrays (src/core/checkpoint.c), then each module's items in module order. */
int pl_checkpoint_write(const pl_sim_t *sim, const char *path, pl_err_t *err);
/* Loads a checkpoint into a sim created from the same scene: the format
 * version, every dataset's checksum, the scene's seed, box, particle and
 * colloid counts and every physics key of the scene fingerprint must match,
 * and every value must be in range (else PL_ERR_INPUT, nothing changed that
 * the caller keeps).  `changed`: comma-separated scene keys allowed to
 * differ (--restart-changed), or NULL. */
int pl_checkpoint_restart(pl_sim_t *sim, const char *path, const char *changed, pl_err_t *err);
/* pl_checkpoint_restart with no key allowed to change. */
int pl_checkpoint_read(pl_sim_t *sim, const char *path, pl_err_t *err);
/* The step checkpoint `path` holds (*step); -1 when it cannot be read. */
int pl_checkpoint_step(const char *path, long long *step);
/* PL_ERR_INPUT unless every comma-separated name in `list` is a scene key
 * ("srd.dt", top-level keys without a section: "seed"). */
int pl_checkpoint_changed_keys_valid(const char *list, pl_err_t *err);

/* Scene fingerprint (src/core/checkpoint_scene.c): writes the root attributes
 * scene_keys and scene_fingerprint; 0 or -1. */
int pl_ckpt_scene_write(hid_t f, const pl_scene_t *scene);
/* The observer fingerprint text (malloc'ed, NULL when out of memory): every
 * observe.* key but observe.target_rel_error (which shapes no observer
 * state), one "key = value" line each, as in scene_keys. */
char *pl_ckpt_observe_text(const pl_scene_t *scene);
/* PL_ERR_INPUT listing every physics key whose value differs between the
 * checkpoint and `scene` and is not named in `changed` (comma separated,
 * NULL: none). */
int pl_ckpt_scene_check(hid_t f, const pl_scene_t *scene, const char *changed, const char *path,
                        pl_err_t *err);

/* Writes group /colloids (the complete colloid state: see the .c). */
int pl_ckpt_colloid_write(hid_t f, const pl_colloid_t *c);
/* Reads group /colloids into c, created from `scene` with the same count
 * (the caller checked it).  PL_ERR_INPUT if the group is incomplete, a
 * checksum fails or a value is out of range (non-finite, outside the box,
 * non-positive radius or mass, image counter beyond PL_COLLOID_IMAGE_MAX). */
int pl_ckpt_colloid_read(hid_t f, pl_colloid_t *c, const pl_scene_t *scene, const char *path,
                         pl_err_t *err);

/* Writes /wall_impulse (walls) and group /coupling (with a coupling cp, the
 * coupling module's state; NULL without): the run counters
 * (src/coupling/checkpoint_coupling.c). */
int pl_ckpt_coupling_write(hid_t f, const struct pl_sim *sim, const struct pl_coupling *cp);
/* Reads them back; PL_ERR_INPUT naming what is missing. */
int pl_ckpt_coupling_read(hid_t f, struct pl_sim *sim, struct pl_coupling *cp, const char *path, pl_err_t *err);

/* Observer groups (src/observe/checkpoint_observe.c): creates group `name` with
 * the observer fingerprint (< 0 on failure). */
hid_t pl_ckpt_observe_group_write(hid_t f, const char *name, const pl_scene_t *sc);
/* Opens group `name` when its fingerprint matches the scene's observe
 * section (pl_sim_observers_resume); otherwise returns -1, the observers
 * afresh with the reason (pl_sim_observers_afresh: absent group, changed
 * observe section; or afresh already: --restart-changed). */
hid_t pl_ckpt_observe_group_open(hid_t f, const char *name, struct pl_sim *sim);

#endif
