/* Radial distribution function g(r) of the colloid centres (Hecht Sec. IX.C,
 * Figs. 5-7 and 10-13; PL Sec. IV.B, Fig. 4).
 *
 * Pairs are counted at their minimum-image distance (exact for r < L/2 on
 * every periodic axis, which create enforces) into nbins bins of width
 * rmax / nbins.  A sample of n particles is normalised by what an ideal gas
 * of the same n in the same region would give:
 *
 *   g_b = H_b / ( n (n-1)/2  P_b ),   P_b = probability that two independent
 *                                      uniform points lie r in [r_b, r_b+1) apart
 *
 * so that g = 1 exactly in expectation for uncorrelated points.
 *   periodic box V = Lx Ly Lz:  P_b = (4 pi / 3) (r_{b+1}^3 - r_b^3) / V.
 *   walls in z (x, y periodic, centres confined to the slab [zlo, zhi] of
 *   thickness h): a centre at height z sees the fraction
 *   f(r, z) = |[z - r, z + r] ∩ [zlo, zhi]| / (2 r) of its shell inside the
 *   slab (Archimedes: a sphere's area is uniform in its axial coordinate);
 *   averaged over z uniform in the slab, F(r) = 1 - r/(2h) for r <= h and
 *   h/(2r) for r >= h.  Then P_b = [G(r_{b+1}) - G(r_b)] / (Lx Ly h) with
 *   G' = 4 pi r^2 F:  G(r) = 4 pi (r^3/3 - r^4/(8h))            (r <= h),
 *                    G(r) = 5 pi h^3 / 6 + pi h (r^2 - h^2)      (r >= h).
 *   For colloids of radius a between walls at z = 0 and Lz the slab is the
 *   region the centres can reach, [a, Lz - a].
 *
 * Partial g_ab (size classes): with class_a, class_b >= 0 only pairs of one
 * particle of class a and one of class b count, normalised by the number of
 * such pairs, n_a n_b (a != b) or n_a (n_a - 1) / 2 (a = b), in place of
 * n (n-1)/2; P_b is the same for any two independent uniform points.
 *
 * Each sample's g_b goes into a blocking accumulator (peloid/blocking.h), so
 * the result is mean ± SE over samples with the correlation between
 * successive samples accounted for.
 */
#ifndef PELOID_RDF_H
#define PELOID_RDF_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/blocking.h"
#include "peloid/error.h"

typedef struct {
    double box[3];   /* Lx, Ly, Lz; x and y are periodic */
    int z_walls;     /* 0: z periodic; 1: walls, centres in [zlo, zhi] */
    double zlo, zhi;
    double rmax;     /* <= L/2 on every periodic axis */
    size_t nbins;
    int class_a, class_b; /* both -1: all pairs; else g_ab, classes from cls */
} pl_rdf_params_t;

typedef struct pl_rdf pl_rdf_t;

int pl_rdf_create(const pl_rdf_params_t *par, int nthreads, pl_rdf_t **out, pl_err_t *err);
void pl_rdf_free(pl_rdf_t *r);

/* One configuration of n particles, cls[i] the class of particle i (NULL
 * when all pairs count); counted on the nthreads given at create, bitwise
 * the same for any.  A sample with no pair of the wanted classes is skipped. */
void pl_rdf_sample(pl_rdf_t *r, size_t n, const double *x, const double *y, const double *z,
                   const int32_t *cls);

/* Bin centres, mean g and its SE (blocking over samples); plateau[b] = 1
 * when the blocking rule found a plateau (any pointer may be NULL). */
void pl_rdf_result(const pl_rdf_t *r, double *rmid, double *g, double *se, int *plateau);
/* Pair counts summed over all samples (nbins values). */
const uint64_t *pl_rdf_counts(const pl_rdf_t *r);
uint64_t pl_rdf_samples(const pl_rdf_t *r);

/* Everything a checkpoint must hold to continue bitwise (STYLE.md 15),
 * owned by r: counts[nbins] summed over samples and counts[nbins] = the
 * samples; one plain blocking accumulator per bin. */
typedef struct {
    uint64_t *counts;
    size_t ncounts;
    pl_blocking_t *blocking;
    size_t nblocking;
} pl_rdf_state_t;
pl_rdf_state_t pl_rdf_state(pl_rdf_t *r);
/* P_b of the header: the ideal-gas probability of bin [r1, r2). */
double pl_rdf_ideal_fraction(const pl_rdf_params_t *par, double r1, double r2);

/* The pair-count kernel (kernels/rdf_count.c): adds to hist[nbins] the
 * unordered pairs with minimum-image distance r < rmax, bin floor(r / dr).
 * scratch holds nthreads x nbins counters. */
typedef struct {
    double box[3];
    int periodic_z;
    double rmax;
    size_t nbins;
    const int32_t *cls; /* NULL: all pairs; else only pairs of classes (ca, cb) */
    int ca, cb;
} pl_rdf_geom_t;

void pl_rdf_count(const pl_rdf_geom_t *g, size_t n, const double *x, const double *y,
                  const double *z, uint64_t *hist, uint64_t *scratch, int nthreads);

#endif
