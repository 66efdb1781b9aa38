/* The analysis window (peloid/window.h) in a run: observe.average_from
 * checked against the run, each series' window, and how the outputs state
 * it.  Private to the library. */
#ifndef PELOID_OBS_WINDOW_H
#define PELOID_OBS_WINDOW_H

#include <hdf5.h>

#include "json_build.h"
#include "peloid/observer.h"
#include "peloid/window.h"

/* Whether observe.average_from is malformed or starts after step `last`:
 * 1 and why (n bytes, "...; allowed: ..."), else 0. */
int pl_obs_window_problem(const pl_scene_t *sc, long long last, char *why, size_t n);

/* The window of the series (step[], x[], n samples) of this run. */
pl_window_t pl_obs_window(const pl_obs_run_t *run, const long long *step, const double *x, size_t n);

/* Adds average_from_step, average_from_time, average_from_time_unit ("s"
 * with physical{}, else "t0"), window_source and, when detected,
 * window_inefficiency and window_n_eff to summary entry e. */
void pl_obs_window_json(pl_json_t *b, json_t *e, const pl_sim_t *sim, const pl_window_t *w);

/* The same as attributes of group obs/<name> (a series of
 * pl_obs_series); 0 or -1. */
int pl_obs_window_h5(hid_t obs, const char *name, const pl_sim_t *sim, const pl_window_t *w);

#endif
