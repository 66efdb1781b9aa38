/* Analysis windows of the observers' time averages (src/observe/window.c):
 * which samples of a scalar series a summary value averages.  The user
 * chooses the start (observe.average_from: a time or a percentage of the
 * run), or it is detected per series by Chodera's automated equilibration
 * detection (J. D. Chodera, J. Chem. Theory Comput. 12, 1799 (2016)): the
 * start t0 that maximises the effective number of uncorrelated samples
 * N_eff(t0) = (T - t0) / g(t0), g the statistical inefficiency of the
 * samples from t0 on.  Every output states the start (step, time) and
 * where it came from (window_source: "user", "detected", "whole run"). */
#ifndef PELOID_WINDOW_H
#define PELOID_WINDOW_H

#include <stddef.h>

#include "peloid/blocking.h"

/* observe.average_from parsed: "auto" (detect), "start" (whole run), "<t>"
 * (a time in the scene's unit: s with physical{}, t0 otherwise), "<p>%"
 * (that percentage of the run). */
typedef enum { PL_WINDOW_AUTO, PL_WINDOW_START, PL_WINDOW_TIME, PL_WINDOW_PERCENT } pl_window_kind_t;

typedef struct {
    pl_window_kind_t kind;
    double value; /* the time or the percentage */
} pl_window_spec_t;

/* Parses text into *spec; 0, or -1 when it is none of the forms above or
 * a number is negative, not finite, or a percentage is 100 or more. */
int pl_window_parse(const char *text, pl_window_spec_t *spec);

/* The statistical inefficiency g = 1 + 2 sum_t (1 - t/n) C(t) / C(0) of
 * x[0..n), the sum up to the first lag with C(t) <= 0 (Chodera 2016 Eq. 5;
 * lags taken with a growing stride 1, 2, 3, ... as pymbar's fast estimate),
 * at least 1; 1 for n < 2 or a constant series. */
double pl_window_inefficiency(const double *x, size_t n);

/* Chodera's detection on x[0..n): the t0 in [0, n/2] (every candidate, or
 * at most 200 evenly spaced ones) with the largest N_eff = (n - t0) / g(t0),
 * the earliest on ties; *g and *neff (when not NULL) at that t0.  The
 * search stops at half the series so that the average keeps at least half
 * of it (a series drifting throughout is not declared equilibrated at its
 * tail).  0 for n < 8. */
size_t pl_window_detect(const double *x, size_t n, double *g, double *neff);

/* Where a series' average starts. */
typedef enum { PL_WSRC_WHOLE, PL_WSRC_USER, PL_WSRC_DETECTED } pl_window_source_t;

typedef struct {
    size_t first;         /* index of the first sample averaged */
    long long step;       /* its step */
    pl_window_source_t source;
    double g, neff;       /* detected: inefficiency and N_eff at the start (NAN otherwise) */
} pl_window_t;

/* The window of a series of n samples (steps step[], values x[]; the
 * non-finite values are left out of the detection) for spec, the run from
 * step run_first to run_last: a user start is the first sample at or after
 * step `from_step` (computed by the caller from the spec, see
 * pl_window_from_step); PL_WINDOW_AUTO detects (a start at sample 0 is
 * "whole run").  scratch has room for n doubles. */
pl_window_t pl_window_choose(const pl_window_spec_t *spec, long long from_step, const long long *step,
                             const double *x, size_t n, double *scratch);

/* The first step of a user window: time t (in model time units t0; the
 * caller converts seconds) as ceil(t / dt), a percentage p as run_first +
 * ceil(p/100 (run_last - run_first)); run_first for auto and start. */
long long pl_window_from_step(const pl_window_spec_t *spec, double t_model, double dt, long long run_first,
                              long long run_last);

/* The blocking result of the finite values x[first..n) (as the observers'
 * on-the-fly accumulators form it, so that a window from sample 0 gives the
 * same bits); *count the samples added. */
pl_blocking_result_t pl_window_blocking(const double *x, size_t n, size_t first, uint64_t *count);

/* "user", "detected" or "whole run". */
const char *pl_window_source_name(pl_window_source_t s);

#endif
