/* Static structure factor S(q) of the colloid centres in a periodic box, by
 * the direct sum over the wave vectors the box allows (optional part of the
 * g(r) observer of issue 14; Hecht Sec. IX.C, PL Fig. 4 in reciprocal space):
 *
 *   S(q) = |sum_j exp(i q . r_j)|^2 / N,   q = 2 pi (n_x / L_x, n_y / L_y, n_z / L_z),
 *
 * n integer, 0 < |q| < qmax; q and -q give the same value, so one of each
 * pair is kept (the first non-zero n positive).  Vectors are binned by |q|
 * (nbins bins of width qmax / nbins); a sample's value of a bin is the mean
 * over its vectors, and each bin's samples go into a blocking accumulator
 * (peloid/blocking.h): mean +- SE over samples.  An ideal gas gives S = 1 at
 * every q; a perfect lattice gives N on its reciprocal lattice, 0 elsewhere.
 *
 * The phase factors come from per-axis tables exp(i 2 pi n x_j / L) built by
 * recurrence-free cos/sin per particle and n, so one vector costs three
 * complex products per particle; the vectors are split over threads and each
 * vector's sum runs over particles in index order, so the result is bitwise
 * the same for any thread count.  Cost N x (number of vectors) per sample,
 * ~ (2 pi / 3) (qmax L / 2 pi)^3 N. */
#ifndef PELOID_SQ_H
#define PELOID_SQ_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/blocking.h"
#include "peloid/error.h"

typedef struct {
    double box[3]; /* all axes periodic */
    double qmax;   /* 1/a0 */
    size_t nbins;
    size_t nmax;   /* most particles */
} pl_sq_params_t;

typedef struct pl_sq pl_sq_t;

int pl_sq_create(const pl_sq_params_t *par, int nthreads, pl_sq_t **out, pl_err_t *err);
void pl_sq_free(pl_sq_t *s);
/* One configuration of n <= nmax particles. */
void pl_sq_sample(pl_sq_t *s, size_t n, const double *x, const double *y, const double *z);
/* Bin centres |q|, the mean |q| of each bin's vectors, mean S and its SE, the
 * vectors per bin (bins without a vector: NAN values; any pointer may be NULL). */
void pl_sq_result(const pl_sq_t *s, double *qmid, double *qmean, double *S, double *se, uint64_t *nvec);
uint64_t pl_sq_samples(const pl_sq_t *s);
size_t pl_sq_vectors(const pl_sq_t *s);
/* Everything a checkpoint must hold to continue bitwise (STYLE.md 15), owned
 * by s: one plain blocking accumulator per bin and the sample count (the wave
 * vectors and tables follow from the parameters). */
typedef struct {
    pl_blocking_t *blocking;
    size_t nblocking;
    uint64_t *samples;
} pl_sq_state_t;
pl_sq_state_t pl_sq_state(pl_sq_t *s);

/* The sum of one sample (kernels/sq_modes.c): for the nvec kept vectors
 * q = 2 pi (vec[3k] / box[0], vec[3k+1] / box[1], vec[3k+2] / box[2]),
 * |vec[3k+d]| <= nm[d], sv[k] = |sum_j exp(i q . r_j)|^2 / n over the n
 * particles at (x, y, z).  tab: scratch of 2 n sum_d (2 nm[d] + 1) doubles
 * (the phase tables). */
typedef struct {
    double box[3];
    int nm[3];
    size_t nvec;
    const int32_t *vec; /* 3 x nvec */
} pl_sq_modes_params_t;
void pl_sq_modes(const pl_sq_modes_params_t *p, size_t n, const double *x, const double *y, const double *z,
                 double *tab, double *sv, int nthreads);

#endif
