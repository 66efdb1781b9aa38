/* Geometry of the potential coupling's kernels (private to kernels/): the
 * minimum-image box and the distance of a fluid particle from a colloid
 * centre, shared by the selection of the particles near colloids
 * (coupling_select.c), the WCA forces of PL Eq. 17 (coupling_wca.c) and the
 * MD step on the selected particles (coupling_potential.c), so that the
 * pairs the MD step forms are the ones the selection tested, bit for bit. */
#ifndef PELOID_COUPLING_GEOMETRY_H
#define PELOID_COUPLING_GEOMETRY_H

#include <math.h>

#include "peloid/coupling_kernels.h"

/* The box for the minimum image: sides, and half sides on periodic axes
 * (INFINITY on closed ones: never exceeded). */
typedef struct {
    int L[3];
    double h[3];
} pl_coupling_box_t;

static inline pl_coupling_box_t pl_coupling_box(const int L[3], const int walls[3])
{
    pl_coupling_box_t q;
    for (int d = 0; d < 3; ++d) {
        q.L[d] = L[d];
        q.h[d] = walls[d] == PL_WALLS_NONE ? 0.5 * L[d] : INFINITY;
    }
    return q;
}

/* Minimum image of a separation d along an axis: one conditional shift
 * (separations here stay within one box side). */
static inline double pl_coupling_min_image(double d, double h, int L)
{
    return d > h ? d - L : (d < -h ? d + L : d);
}

/* pl_coupling_inside's test, written out for the selection: the cell is a
 * truncation clamped to [0, L) (= floor + clip), the minimum image one
 * conditional shift on periodic axes (positions there are wrapped into
 * [0, L)), and no early exit, so the outcome is appended without a branch.
 * The same selections as pl_coupling_inside (checkpoints of periodic, z-wall
 * and capillary scenes bitwise equal); select stage 14 -> 10 ns/particle at
 * 1 thread, 7.5 -> 5.5 at 2 (bench_coupling's potential case). */
static inline __attribute__((always_inline)) double pl_coupling_dist2_to(const pl_coupling_box_t *q, double cx,
                                                                        double cy, double cz, double x, double y,
                                                                        double z)
{
    const double dx = pl_coupling_min_image(x - cx, q->h[0], q->L[0]);
    const double dy = pl_coupling_min_image(y - cy, q->h[1], q->L[1]);
    const double dz = pl_coupling_min_image(z - cz, q->h[2], q->L[2]);
    return dx * dx + dy * dy + dz * dz;
}

static inline double pl_coupling_dist2(const pl_coupling_box_t *q, const pl_coupling_colloids_t *c, int32_t k,
                                       double x, double y, double z)
{
    return pl_coupling_dist2_to(q, c->x[k], c->y[k], c->z[k], x, y, z);
}

static inline int pl_coupling_hit(const pl_coupling_box_t *q, const pl_coupling_colloids_t *c, int32_t k,
                                  double x, double y, double z)
{
    return pl_coupling_dist2(q, c, k, x, y, z) < c->rad[k] * c->rad[k];
}

#endif
