/* Internal to src/io/colloid_h5md.c and src/io/colloid_h5md_resume.c: the
 * H5MD colloid trajectory writer's state. */
#ifndef PELOID_COLLOID_H5MD_PRIV_H
#define PELOID_COLLOID_H5MD_PRIV_H

#include <hdf5.h>
#include <limits.h>
#include <stdint.h>

#include "colloid_traj.h"
#include "peloid/colloid.h"

enum { NTS = 6, TS_EDGES = 5 };
static const char *const TS_NAMES[NTS] = {"position", "velocity", "orientation", "angular_velocity", "image",
                                          "edges"};
/* the time-independent per-colloid arrays and the held frame: 13 doubles
 * (x, y, z, vx, vy, vz, q0..q3, wx, wy, wz) and 3 images per colloid */
enum { NHOLD = 13 };

struct pl_colloid_traj {
    hid_t file;
    hid_t val[NTS], step[NTS], time[NTS];
    hsize_t nframes;
    long long last_step; /* step of the last frame written (-1: none) */
    size_t n;
    double box[3];
    int periodic[3];
    double len, tim, mass, kin_mass, frame_dt;
    char len_unit[8], time_unit[8];
    const char *unit_attr; /* "unit" (physical scene) or "model_unit" */
    char path[PATH_MAX], tmp[PATH_MAX + 8];
    double *buf;
    int *ibuf;
    pl_xyz_t *xyz;
    hid_t dt_val, dt_step, dt_time; /* /observables/dt */
    /* cluster ids (pl_colloid_traj_cluster_ids); val 0: none */
    hid_t cid_val, cid_step, cid_time;
    hsize_t cid_frames;
    pl_traj_ids_fn ids;
    void *ids_ctx;
    int32_t *cid_buf;
    /* the state at the start of the current step (pl_colloid_traj_hold) */
    double *hold;
    int32_t *ihold;
    long long hold_step;
    double hold_time;
};

/* Resume in place: opens the trajectory to continue in t->tmp, the one a
 * killed run left there (the newest) or else a copy of PATH, keeping the
 * frames of steps < keep; 1 when there is none (a new file is made), 0, or
 * an error code (src/io/colloid_h5md_resume.c). */
int pl_colloid_traj_resume_open(pl_colloid_traj_t *t, long long keep, pl_err_t *err);

#endif
