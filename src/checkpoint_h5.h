/* Private to src/checkpoint*.c: HDF5 helpers of the checkpoint writer and
 * reader, and the colloid part of the checkpoint (src/checkpoint_colloid.c).
 * Every object is created without time stamps, so the same state gives the
 * same bytes. */
#ifndef PELOID_CHECKPOINT_H5_H
#define PELOID_CHECKPOINT_H5_H

#include <hdf5.h>

#include "peloid/colloid.h"
#include "peloid/error.h"
#include "peloid/scene.h"

/* 1-d dataset `name` of n elements under g; 0 or -1. */
int pl_ckpt_write_1d(hid_t g, const char *name, hid_t type, const void *data, size_t n);
/* Reads dataset `name`; -1 if it is missing, not 1-d or not of length n. */
int pl_ckpt_read_1d(hid_t g, const char *name, hid_t type, void *data, size_t n);
/* Writes (write != 0) or reads an n-element int64 attribute; a read of an
 * attribute with another element count fails (-1). */
int pl_ckpt_attr_i64(hid_t obj, const char *name, long long *v, int n, int write);
/* Group without time stamps; < 0 on failure. */
hid_t pl_ckpt_group_create(hid_t f, const char *name);

/* Writes group /colloids (the complete colloid state: see the .c). */
int pl_ckpt_colloid_write(hid_t f, const pl_colloid_t *c);
/* Reads group /colloids into c, created from `scene` with the same count
 * (the caller checked it).  PL_ERR_INPUT if the group is incomplete. */
int pl_ckpt_colloid_read(hid_t f, pl_colloid_t *c, const pl_scene_t *scene, const char *path,
                         pl_err_t *err);

struct pl_sim;
/* Writes /wall_impulse (walls) and group /coupling (with a coupling): the run
 * counters (src/checkpoint_coupling.c). */
int pl_ckpt_coupling_write(hid_t f, const struct pl_sim *sim);
/* Reads them back; PL_ERR_INPUT naming what is missing. */
int pl_ckpt_coupling_read(hid_t f, struct pl_sim *sim, const char *path, pl_err_t *err);

#endif
