/* Internal to the colloid trajectory writers (src/io/colloid_h5md.c, the H5MD
 * file, and src/io/colloid_xyz.c, its extended-XYZ twin): one frame as the
 * writers see it. */
#ifndef PELOID_COLLOID_TRAJ_H
#define PELOID_COLLOID_TRAJ_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/error.h"

typedef struct {
    size_t n;
    const double *x, *y, *z, *vx, *vy, *vz, *q0, *q1, *q2, *q3, *wx, *wy, *wz, *rad;
    const int32_t *ix, *iy, *iz;
    int has_cluster_id;         /* the cluster observer's ids are written */
    const int32_t *cluster_id;  /* n ids of this frame, NULL: none (written -1) */
    const double *box;  /* 3 edges, a0 */
    const int *periodic;
    long long step;
    double time;        /* t0 */
    double len, tim;    /* file units per a0 and per t0 (1, 1 in model units) */
    const char *len_unit, *time_unit;
} pl_traj_frame_t;

typedef struct pl_xyz pl_xyz_t;
/* Opens "<path>.tmp" for writing; PL_ERR_IO naming it. */
int pl_xyz_open(const char *path, pl_xyz_t **out, pl_err_t *err);
/* Resume in place: continues the frames of steps < keep of PATH.tmp (a
 * killed run's, the newest) or else of PATH in PATH.tmp; none there: as
 * pl_xyz_open. */
int pl_xyz_open_keep(const char *path, long long keep, pl_xyz_t **out, pl_err_t *err);
/* Appends one frame and flushes it; PL_ERR_IO naming the file. */
int pl_xyz_frame(pl_xyz_t *x, const pl_traj_frame_t *f, pl_err_t *err);
/* Flushes, fsyncs and renames PATH.tmp to PATH (the frames written so far,
 * also after a guard stop); frees x.  PL_ERR_IO naming the file. */
int pl_xyz_close(pl_xyz_t *x, pl_err_t *err);

#endif
