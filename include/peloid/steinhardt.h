/* Steinhardt bond-orientational order (Steinhardt, Nelson, Ronchetti, PRB
 * 28, 784 (1983); as freud's Steinhardt): for each centre i with N_b(i)
 * neighbours closer than r_max,
 *   q_lm(i) = (1/N_b(i)) sum_j Y_lm(r_ij),
 *   q_l(i)  = sqrt(4 pi / (2l + 1) sum_m |q_lm(i)|^2),
 * and the global Q_l of the system-averaged Q_lm = <q_lm(i)>_i over the
 * centres with a neighbour.  Y_lm from GSL (gsl_sf_legendre_array_e,
 * spherical-harmonic normalisation).  Perfect lattices: fcc (12 neighbours)
 * q4 = 0.19094, q6 = 0.57452; bcc (8) q6 = 0.62854; sc (6) q4 = 0.76376,
 * q6 = 0.35355; an ideal gas's global Q_l ~ 1/sqrt(bonds). */
#ifndef PELOID_STEINHARDT_H
#define PELOID_STEINHARDT_H

#include <stddef.h>

#include "peloid/error.h"

enum { PL_STEINHARDT_NL = 2 }; /* l = 4, 6 */

typedef struct {
    double box[3];
    int periodic[3]; /* minimum image along periodic axes */
    double rmax;     /* neighbour cut-off (<= half a periodic edge) */
} pl_steinhardt_params_t;

typedef struct {
    double Q[PL_STEINHARDT_NL];      /* global Q4, Q6 */
    double q_mean[PL_STEINHARDT_NL]; /* mean local q4, q6 over centres with a neighbour */
    size_t bonds;                    /* neighbour pairs */
    size_t centres;                  /* centres with at least one neighbour */
} pl_steinhardt_result_t;

/* The order of n centres (a fixed-order pair loop, O(n^2): the same bits for
 * any thread count); q (n x 2, q4 and q6 of each centre, NAN without a
 * neighbour) may be NULL.  0 or PL_ERR_NOMEM. */
int pl_steinhardt(const pl_steinhardt_params_t *p, size_t n, const double *x, const double *y, const double *z,
                  double *q, pl_steinhardt_result_t *out, pl_err_t *err);

#endif
