/* Velocity distribution against Maxwell-Boltzmann (Hecht Sec. IX.A, Fig. 2:
 * fluid velocities relax to a Gaussian; the colloids' velocity distribution
 * of Hecht's abstract).
 *
 * Each Cartesian component of a particle of mass M in equilibrium at
 * temperature kT is Gaussian with variance kT/M.  Two tests of that:
 *   chi^2  over a fixed histogram of the components accumulated over samples:
 *          bins of width 2 vmax / nbins plus the two tails |v| > vmax,
 *          grouped left to right until a group expects >= 5 counts (a short
 *          remainder joins the last group); dof = groups - 1,
 *          p = Q(chi^2 | dof) (GSL);
 *   KS     Kolmogorov-Smirnov of one sample of components (exact empirical
 *          CDF, sorted in place), D = sup |F_n - Phi|, p from the Kolmogorov
 *          distribution with Stephens' correction
 *          lambda = (sqrt n + 0.12 + 0.11/sqrt n) D.
 * Both p-values assume independent draws: components of one particle, and
 * successive samples closer than the velocity correlation time, are not; take
 * samples further apart than that, or read p as a comparison between runs.
 */
#ifndef PELOID_VDIST_H
#define PELOID_VDIST_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/error.h"

typedef struct {
    size_t nbins;  /* bins on [-vmax, vmax] */
    double vmax;
} pl_vdist_params_t;

typedef struct pl_vdist pl_vdist_t;

int pl_vdist_create(const pl_vdist_params_t *par, pl_vdist_t **out, pl_err_t *err);
void pl_vdist_free(pl_vdist_t *h);
/* Adds the components v[d][i] of n particles, axes d = 0..2. */
void pl_vdist_sample(pl_vdist_t *h, size_t n, const double *vx, const double *vy, const double *vz);
/* Counts of axis d (0..2; 3 = all axes): nbins + 2 values, [0] below -vmax,
 * [nbins + 1] above vmax. */
const uint64_t *pl_vdist_counts(const pl_vdist_t *h, int axis);
/* The checkpoint state (STYLE.md 15): the counts of all four histograms. */
typedef struct {
    uint64_t *counts;
    size_t ncounts;
} pl_vdist_state_t;
pl_vdist_state_t pl_vdist_state(pl_vdist_t *h);

/* chi^2 of the histogram of axis (0..3) against N(0, sigma^2), sigma =
 * sqrt(kT / M).  Fails when fewer than two bins are left after merging. */
int pl_vdist_chi2(const pl_vdist_t *h, int axis, double sigma, double *chi2, int *dof, double *p,
                  pl_err_t *err);
/* KS of the n values v (sorted in place) against N(0, sigma^2). */
void pl_vdist_ks(double *v, size_t n, double sigma, double *D, double *p);

#endif
