/* Shared writers of the observers' outputs (the observer modules in src/observe):
 * H5MD datasets with unit attributes and time-series groups in
 * observables.h5, and the error-against-run-time part of a summary.json
 * entry.  Private to the library. */
#ifndef PELOID_OBSERVABLES_OUT_H
#define PELOID_OBSERVABLES_OUT_H

#include <hdf5.h>
#include <stddef.h>

#include "json_build.h"
#include "peloid/error.h"

enum { PL_OBS_NFRAC = 4 };
/* The run fractions the error-against-time points are taken at. */
extern const double pl_obs_fractions[PL_OBS_NFRAC];

/* An estimate taken at a run fraction. */
typedef struct pl_obs_point {
    long long step;
    double wall_s, value, se;
    int valid, plateau;
} pl_obs_point_t;

/* Dataset `name` in g with a unit attribute (NULL: none); 0 or -1. */
int pl_obs_put(hid_t g, const char *name, hid_t type, int rank, const hsize_t *dims, const void *data,
               const char *unit);
/* H5MD time series group /observables/<name>/{step, time, value}; 0 or -1. */
int pl_obs_series(hid_t obs, const char *name, size_t n, const long long *step, double dt, const double *value,
                  const char *unit);
/* Adds to entry e: se_vs_time (the valid points) and, when the last point is
 * valid and value, se > 0, target_rel_error, wall_s_for_target (SE ~ 1/sqrt(t))
 * and extrapolation_reliable (= plateau). */
void pl_obs_error_time(pl_json_t *b, json_t *e, const pl_obs_point_t pts[PL_OBS_NFRAC], double value, double se,
                       int plateau, double target);

struct pl_sim;
/* summary.json's "observables" section: the one already in doc (an observer
 * that finished before wrote it this run), or a new one with the run's head
 * (first_step, last_step; for a restarted run whether the observers resumed
 * and, when not, why) set into doc.  NULL (and b failed) when out of
 * memory. */
json_t *pl_obs_summary_section(pl_json_t *b, json_t *doc, const struct pl_sim *sim, long long first);

/* Closes observables file f written at tmp and commits it to path
 * (pl_atomic_commit); bad: a write failed before, then `what` names the
 * writer in the error (PL_ERR_IO, with HDF5's reason) and tmp is removed. */
int pl_obs_h5_commit(hid_t f, int bad, const char *tmp, const char *path, const char *what, pl_err_t *err);

#endif
