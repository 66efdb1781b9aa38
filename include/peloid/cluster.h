/* Clusters of touching colloids by union-find over linked cells (DESIGN.md
 * "Observables"; Hecht Sec. IX.C and Fig. 9: the clustering regime of the
 * (kappa, Psi0) phase diagram, and the cluster sizes its outlook asks for).
 *
 * Particles i and j are bonded when their surface gap
 *     r_ij - a_i - a_j < gap
 * (r_ij the minimum-image distance on periodic axes).  Clusters are the
 * connected components of that bond graph.  Candidates come from linked
 * cells of edge >= 2 a_max + gap (kernels/colloid_cells.c), so the search is
 * O(n); components by union-find with path halving, the root of a tree
 * always the smaller index, so each particle's cluster id is the smallest
 * particle index in its cluster (canonical: independent of visiting order).
 *
 * A bond rule may refine the bond (pl_cluster_params_t.bond): a pair within
 * the gap above is then bonded only when bond(ctx, i, j, r) returns a kind
 * 1..PL_CLUSTER_KINDS (0: no bond); the bonds of each kind are counted (with
 * no rule every bond is of kind 1).  The observer bonds by pair energy this
 * way, kind 1 in the primary minimum and 2 in the secondary.
 *
 * The search is serial: for the colloid numbers of a scene (<= 10^5) it costs
 * milliseconds per call, and it makes the result trivially independent of the
 * thread count.
 */
#ifndef PELOID_CLUSTER_H
#define PELOID_CLUSTER_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/error.h"

enum { PL_CLUSTER_KINDS = 2 };

/* i < j, r their minimum-image centre distance; returns the bond kind. */
typedef int (*pl_cluster_bond_fn)(const void *ctx, int32_t i, int32_t j, double r);

typedef struct {
    double box[3];
    int periodic[3];
    double gap;     /* bond: surface gap below this (may be negative: overlap) */
    double rad_max; /* largest radius that pl_cluster_find will be given */
    size_t nmax;    /* most particles */
    pl_cluster_bond_fn bond; /* NULL: every pair within gap is a bond of kind 1 */
    const void *bond_ctx;
} pl_cluster_params_t;

typedef struct pl_cluster pl_cluster_t;

int pl_cluster_create(const pl_cluster_params_t *par, pl_cluster_t **out, pl_err_t *err);
void pl_cluster_free(pl_cluster_t *c);

/* Partitions n <= nmax particles (radius rad[i] <= rad_max). */
int pl_cluster_find(pl_cluster_t *c, size_t n, const double *x, const double *y, const double *z,
                    const double *rad, pl_err_t *err);

/* Results of the last pl_cluster_find. */
const int32_t *pl_cluster_ids(const pl_cluster_t *c);  /* n: smallest member index */
size_t pl_cluster_count(const pl_cluster_t *c);
size_t pl_cluster_largest(const pl_cluster_t *c);
/* Number-average size n / count, and weight-average sum s^2 N_s / sum s N_s
 * (the size of the cluster a randomly picked particle belongs to). */
double pl_cluster_mean_size(const pl_cluster_t *c);
double pl_cluster_weight_mean_size(const pl_cluster_t *c);
/* Bonds of kind k (1..PL_CLUSTER_KINDS; 0 for any other k). */
size_t pl_cluster_bonds(const pl_cluster_t *c, int kind);
/* hist[s] = number of clusters of s particles, s = 0..n (hist[0] = 0). */
const uint64_t *pl_cluster_size_hist(const pl_cluster_t *c, size_t *len);

#endif
