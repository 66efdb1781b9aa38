/* Multiple-tau correlator for per-particle vector time series (DESIGN.md
 * "Observables": MSD, VACF, Green-Kubo).
 *
 * Ramirez, Sukumaran, Vorselaars & Likhtman, J. Chem. Phys. 133, 154103
 * (2010): level 0 holds the last p samples and gives lags 0..p-1; level l >= 1
 * holds p values, each standing for m^l samples, and gives lags j m^l for
 * j = p/m..p-1 (smaller j repeat level l-1).  Memory is O(n p levels), i.e.
 * O(N log T); a sample costs O(n p m/(m-1)).
 *
 * Two kinds, per axis d of particle i, averaged over time origins t0:
 *   PL_MTAU_AUTO  <a_d(t0) a_d(t0 + tau)>      VACF (Hecht Eq. 34, PL Eq. 52
 *                                              before normalising), force-force
 *                                              C_FF (PL Eq. 50)
 *   PL_MTAU_MSD   <(a_d(t0 + tau) - a_d(t0))^2> of unwrapped positions
 *                                              (Hecht Eq. 36 at every lag)
 * Two coarse-graining rules for the values of level l >= 1:
 *   average = 1  the mean of m values of level l-1 (Ramirez et al.): every
 *                sample contributes, at the price of a smoothing bias; for an
 *                MSD of a random walk with window w = m^l the MSD at lag L
 *                samples is 2 D dt (L - (w^2 - 1)/(3 w)) instead of 2 D dt L.
 *   average = 0  every m-th value (the one at times k m^l): unbiased at every
 *                lag, fewer origins at large lags.  The right choice for MSD.
 *
 * Results: per lag, the per-particle time averages c_i(tau) are averaged over
 * the n particles; their spread gives the SE, sd_i(c_i)/sqrt(n), which is the
 * SE of the result when particles move independently (dilute colloids); with
 * strong interparticle correlations it is a lower bound.  Columns: x, y, z
 * and the sum over axes (PL_MTAU_COLS = 4).
 *
 * Determinism: a particle's accumulators are touched only by the thread that
 * owns that particle in the update, and the sums over particles run in index
 * order, so results are bitwise identical for any thread count.
 */
#ifndef PELOID_MTAU_H
#define PELOID_MTAU_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/error.h"

#define PL_MTAU_COLS 4
#define PL_MTAU_MAX_LEVELS 48

typedef enum { PL_MTAU_AUTO = 0, PL_MTAU_MSD = 1 } pl_mtau_kind_t;

typedef struct {
    size_t n;            /* particles */
    int p;               /* points per level, >= 2, a multiple of m */
    int m;               /* coarse-graining factor, >= 2 */
    int levels;          /* 1..PL_MTAU_MAX_LEVELS; see pl_mtau_levels_for */
    pl_mtau_kind_t kind;
    int average;         /* 1: mean of m values (Ramirez); 0: every m-th value */
    double dt;           /* time between two samples */
} pl_mtau_params_t;

typedef struct pl_mtau pl_mtau_t;

/* Fewest levels whose largest lag (p - 1) m^(levels-1) reaches nsamples - 1. */
int pl_mtau_levels_for(uint64_t nsamples, int p, int m);

int pl_mtau_create(const pl_mtau_params_t *par, pl_mtau_t **out, pl_err_t *err);
void pl_mtau_free(pl_mtau_t *c);

/* One sample: component d of particle i is (x, y, z)[d][i].  Runs the
 * particle loop on nthreads threads (1: serial). */
void pl_mtau_add(pl_mtau_t *c, const double *x, const double *y, const double *z, int nthreads);

uint64_t pl_mtau_samples(const pl_mtau_t *c);

/* Everything a checkpoint must hold to continue bitwise (STYLE.md 15): two
 * arrays owned by c.  Write them out; to restart, create an object with the
 * same parameters and read them back into the arrays of its state. */
typedef struct {
    double *values;     /* per-particle buffers and accumulators */
    size_t nvalues;
    uint64_t *counters; /* origins per lag, values per level, samples */
    size_t ncounters;
} pl_mtau_state_t;
pl_mtau_state_t pl_mtau_state(pl_mtau_t *c);
int pl_mtau_levels(const pl_mtau_t *c);
/* A correlator with `levels` (>= c's) levels in the state it would have had,
 * had it been created with them and fed c's samples (a restarted run that
 * goes on longer than the first run planned for).  Exact for the every-m-th
 * rule (average = 0): level l >= c's levels holds the samples at multiples of
 * m^l, all of them still in c's top level while that level has not wrapped
 * (it has not while c's samples fit its lags, pl_mtau_levels_for).  Fails
 * (PL_ERR_INPUT) for average = 1 or a wrapped top level. */
int pl_mtau_grow(const pl_mtau_t *c, int levels, pl_mtau_t **out, pl_err_t *err);
/* Lag slots, in increasing lag: p + (levels - 1) (p - p/m). */
size_t pl_mtau_nlags(const pl_mtau_t *c);
/* lag[k] (time), origins[k], value[PL_MTAU_COLS k + col], se[...]; a lag with
 * no origin yet gives NAN (any output pointer may be NULL). */
void pl_mtau_result(const pl_mtau_t *c, double *lag, uint64_t *origins, double *value, double *se);
/* Least-squares slope in time of each column over the lags in [tmin, tmax]
 * with at least one origin, fitted per particle, then averaged over particles
 * with the SE of that mean (D = slope / 2 per axis, / 6 for the sum).
 * Fails when fewer than two lags lie in the window. */
int pl_mtau_slope(const pl_mtau_t *c, double tmin, double tmax, double slope[PL_MTAU_COLS],
                  double se[PL_MTAU_COLS], pl_err_t *err);

/* Trapezoid integral in time of each column over the lags 0..tmax (those
 * with an origin), per particle, then mean and SE over particles.  On the
 * uniform lags of level 0 this is Hecht Eq. 35, D_x = dt (g(0)/2 + sum_j
 * g(j)), truncated at tmax (Green-Kubo, PL Eq. 58 D(t)); the coarse levels
 * continue it on their wider grid.  Fails when fewer than two lags qualify. */
int pl_mtau_integral(const pl_mtau_t *c, double tmax, double integral[PL_MTAU_COLS],
                     double se[PL_MTAU_COLS], pl_err_t *err);

/* The per-particle update (kernels/mtau_push.c), for the owning object. */
typedef struct {
    int nrecv;          /* levels 0..nrecv-1 receive this sample */
    int p, m, levels, average, kind;
    int stride;         /* doubles per particle: levels (6 p + 3) */
    int head[PL_MTAU_MAX_LEVELS];  /* slot the new value goes to */
    int jmin[PL_MTAU_MAX_LEVELS];  /* smallest lag index of the level */
    int jmax[PL_MTAU_MAX_LEVELS];  /* largest lag index with an origin */
} pl_mtau_push_t;

void pl_mtau_push(const pl_mtau_push_t *pp, size_t n, const double *x, const double *y,
                  const double *z, double *state, int nthreads);

#endif
