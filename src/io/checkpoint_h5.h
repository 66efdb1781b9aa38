/* Private to src/checkpoint*.c: HDF5 helpers of the checkpoint writer and
 * reader, and the colloid part of the checkpoint (src/io/checkpoint_colloid.c).
 * Every object is created without time stamps, so the same state gives the
 * same bytes. */
#ifndef PELOID_CHECKPOINT_H5_H
#define PELOID_CHECKPOINT_H5_H

#include <hdf5.h>
#include <stdint.h>

#include "peloid/colloid.h"
#include "peloid/error.h"
#include "peloid/scene.h"

/* Format of the files pl_checkpoint_write writes (root attribute
 * "format_version"); the reader refuses any other.  2: per-dataset
 * checksums and the scene fingerprint. */
enum { PL_CKPT_FORMAT = 2 };

/* 64-bit FNV-1a hash of n bytes (the per-dataset checksum). */
uint64_t pl_ckpt_fnv1a(const void *data, size_t n);
/* The same continued over more bytes: pl_ckpt_fnv1a(a b) =
 * pl_ckpt_fnv1a_more(pl_ckpt_fnv1a(a), b). */
uint64_t pl_ckpt_fnv1a_more(uint64_t h, const void *data, size_t n);

/* 1-d dataset `name` of n elements under g, with the attribute "fnv1a64":
 * the FNV-1a hash of its n elements' bytes in memory; 0 or -1.  type must be
 * a native type (file and memory bytes are then the same). */
int pl_ckpt_write_1d(hid_t g, const char *name, hid_t type, const void *data, size_t n);
/* Reads dataset `name` and verifies its checksum; on failure sets err
 * (PL_ERR_INPUT, naming path and dataset: missing, not 1-d, not of length n,
 * unreadable, or checksum mismatch) and returns its code. */
int pl_ckpt_read_1d(hid_t g, const char *name, hid_t type, void *data, size_t n, const char *path,
                    pl_err_t *err);
/* String attribute (write: 0 or -1; read: malloc'ed text or NULL). */
char *pl_ckpt_attr_str_read(hid_t obj, const char *name);

/* Scene fingerprint (src/io/checkpoint_scene.c): writes the root attributes
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
/* Writes (write != 0) or reads an n-element int64 attribute; a read of an
 * attribute with another element count fails (-1). */
int pl_ckpt_attr_i64(hid_t obj, const char *name, long long *v, int n, int write);
/* Group without time stamps; < 0 on failure. */
hid_t pl_ckpt_group_create(hid_t f, const char *name);

/* Writes group /colloids (the complete colloid state: see the .c). */
int pl_ckpt_colloid_write(hid_t f, const pl_colloid_t *c);
/* Reads group /colloids into c, created from `scene` with the same count
 * (the caller checked it).  PL_ERR_INPUT if the group is incomplete, a
 * checksum fails or a value is out of range (non-finite, outside the box,
 * non-positive radius or mass, image counter beyond PL_COLLOID_IMAGE_MAX). */
int pl_ckpt_colloid_read(hid_t f, pl_colloid_t *c, const pl_scene_t *scene, const char *path,
                         pl_err_t *err);

struct pl_sim;
/* Writes /wall_impulse (walls) and group /coupling (with a coupling): the run
 * counters (src/io/checkpoint_coupling.c). */
int pl_ckpt_coupling_write(hid_t f, const struct pl_sim *sim);
/* Reads them back; PL_ERR_INPUT naming what is missing. */
int pl_ckpt_coupling_read(hid_t f, struct pl_sim *sim, const char *path, pl_err_t *err);

struct pl_sim;
/* Observer groups (src/io/checkpoint_observe.c): creates group `name` with
 * the observer fingerprint (< 0 on failure). */
hid_t pl_ckpt_observe_group_write(hid_t f, const char *name, const pl_scene_t *sc);
/* Opens group `name` when its fingerprint matches the scene's observe
 * section (sim->observe_resumed = 1); otherwise returns -1 with
 * sim->observe_resumed = 0 and sim->observe_note saying why (absent group,
 * changed observe section; or already 0: --restart-changed). */
hid_t pl_ckpt_observe_group_open(hid_t f, const char *name, struct pl_sim *sim);

#endif
