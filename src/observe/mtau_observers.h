/* The multiple-tau correlator observers of the observer module (MSD, VACF,
 * C_FF; src/observe/mtau_observers.c): one struct and one set of functions
 * serve all three, so that their sampling, checkpoint items and outputs
 * cannot drift apart.  Private to src/observe. */
#ifndef PELOID_MTAU_OBSERVERS_H
#define PELOID_MTAU_OBSERVERS_H

#include <hdf5.h>
#include <stdint.h>

#include "json_build.h"
#include "peloid/error.h"
#include "peloid/mtau.h"
#include "peloid/sim.h"

/* The observers, in the order of their plan stages, checkpoint items and
 * observables.h5 groups. */
enum { PL_MTOBS_MSD, PL_MTOBS_VACF, PL_MTOBS_CFF, PL_MTOBS_N };

typedef struct {
    int which;         /* PL_MTOBS_* */
    pl_mtau_t *c;      /* NULL until the first sample (or a restart) */
    double dt;         /* lag unit: the observer's interval x srd.dt */
    double wall;       /* wall seconds spent sampling */
    double *u[3];      /* MSD: the unwrapped positions (per-sample scratch) */
} pl_mtobs_t;

/* The scene's interval and start step of observer `which`. */
long long pl_mtobs_interval(const pl_scene_observe_t *so, int which);
long long pl_mtobs_start(const pl_scene_observe_t *so, int which);
/* Its plan stage, fn and ctx left to the caller (name, interval, phase,
 * slot; at_start: C_FF has no sample at the start state, which has no step). */
pl_stage_t pl_mtobs_stage(const pl_scene_observe_t *so, int which);

/* Frees the correlator and scratch of m (not m itself). */
void pl_mtobs_free(pl_mtobs_t *m);

/* One sample at sim->step, from observer `which`'s start on (C_FF from the
 * end of the run's first step, `first`, on, when the coupling has a mean
 * force).  At the first sample the correlator is created with the levels
 * `expected` samples need (pl_mtau_levels_for). */
int pl_mtobs_sample(pl_mtobs_t *m, pl_sim_t *sim, long long first, uint64_t expected, pl_err_t *err);

/* A restart: the created correlator (m->c) gets the levels `expected`
 * samples of the combined run need (pl_mtau_grow; nothing when it has them). */
int pl_mtobs_grow(pl_mtobs_t *m, uint64_t expected, pl_err_t *err);

/* The correlator's levels for the checkpoint's meta (0: not created). */
long long pl_mtobs_levels(const pl_mtobs_t *m);
/* Checkpoint datasets <name>_values and <name>_counters in g; 0 or nonzero. */
int pl_mtobs_ckpt_write(hid_t g, const pl_mtobs_t *m);
/* The correlator read back with `levels` levels (meta), as it was written;
 * errors name path. */
int pl_mtobs_ckpt_read(hid_t g, pl_mtobs_t *m, long long levels, const pl_sim_t *sim, const char *path,
                       pl_err_t *err);

/* /observables/colloid_<name>/{lag, origins, value, value_se} when the
 * correlator has more than one sample; 0 or -1. */
int pl_mtobs_write(hid_t obs, const pl_mtobs_t *m);

/* D = slope / 6 of the summed MSD over [T/40, T/4] (mtau_observers.c
 * header); 0 when too few lags. */
int pl_mtobs_diffusion(const pl_mtobs_t *msd, double *D, double *se, double *tmin, double *tmax);
/* summary.json's colloid_D_green_kubo (VACF) or colloid_friction_green_kubo
 * (C_FF) in `all`, when the correlator has enough samples. */
void pl_mtobs_summary(pl_json_t *b, json_t *all, const pl_mtobs_t *m, const pl_sim_t *sim);
/* their names (the VACF's and C_FF's rows' entries, NULL-terminated) */
extern const char *const pl_mtobs_vacf_entries[], *const pl_mtobs_cff_entries[];

#endif
