/* An O(N log N) screen of the initial positions for gross overlaps, before
 * the neighbour list is built: the box is cut into cubes of edge
 * h = 2 (1 - max_overlap) R_min / sqrt(3), so two colloids in one cube are
 * closer than (1 - max_overlap)(R_i + R_j) and overlap beyond
 * colloids.max_overlap.  A configuration that passes holds at most one
 * colloid per cube, so every colloid has a bounded number of neighbours
 * and the neighbour list's cost is O(N); without the screen a crowded box
 * (10^6 colloids far beyond close packing) made the pair count O(N^2). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "peloid/colloid.h"

#define OFF(m) offsetof(pl_scene_t, m)

typedef struct {
    int64_t k[3];
    size_t i;
} cube_t;

static int cube_cmp(const void *a, const void *b)
{
    const cube_t *p = a, *q = b;
    for (int d = 0; d < 3; ++d)
        if (p->k[d] != q->k[d]) return p->k[d] < q->k[d] ? -1 : 1;
    return p->i < q->i ? -1 : p->i > q->i;
}

int pl_colloid_overlap_screen(const pl_colloid_t *c, const pl_scene_t *scene, pl_err_t *err)
{
    if (c->n < 2) return 0;
    double rmin = c->rad[0];
    for (size_t i = 1; i < c->n; ++i) rmin = fmin(rmin, c->rad[i]);
    const double h = 2.0 * (1.0 - scene->colloids.max_overlap) * rmin / sqrt(3.0);
    if (!(h > 0.0)) return 0;
    cube_t *cu = malloc(c->n * sizeof *cu);
    if (!cu) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the overlap screen (%zu colloids)", c->n);
    const double *const x[3] = {c->x, c->y, c->z};
    for (size_t i = 0; i < c->n; ++i) {
        for (int d = 0; d < 3; ++d) cu[i].k[d] = (int64_t)floor(x[d][i] / h);
        cu[i].i = i;
    }
    qsort(cu, c->n, sizeof *cu, cube_cmp);
    int rc = 0;
    for (size_t m = 1; m < c->n && !rc; ++m) {
        const cube_t *p = &cu[m - 1], *q = &cu[m];
        if (p->k[0] != q->k[0] || p->k[1] != q->k[1] || p->k[2] != q->k[2]) continue;
        size_t i = p->i, j = q->i;
        double dx = c->x[i] - c->x[j], dy = c->y[i] - c->y[j], dz = c->z[i] - c->z[j];
        double s = c->rad[i] + c->rad[j];
        char what[160];
        snprintf(what, sizeof what, "initial colloids %zu and %zu overlap by %.4g", i, j,
                 (s - sqrt(dx * dx + dy * dy + dz * dz)) / s);
        rc = pl_colloid_overlap_fail(scene, err, what);
    }
    free(cu);
    return rc;
}

int pl_colloid_overlap_fail(const pl_scene_t *scene, pl_err_t *err, const char *what)
{
    const pl_scene_colloids_t *cs = &scene->colloids;
    const pl_scene_physical_t *ph = &scene->mapping.physical;
    char from[160] = "";
    size_t off = OFF(colloids.count);
    const char *key = "colloids.count";
    if (scene->mapping.enabled && cs->init != PL_CINIT_FILE) {
        off = OFF(mapping.physical.volume_fraction);
        key = "physical.volume_fraction";
        snprintf(from, sizeof from, "%g gives %lld colloids (init = \"%s\"): ", ph->volume_fraction, cs->count,
                 cs->init == PL_CINIT_LATTICE ? "lattice" : "random");
    } else if (pl_scene_line_of(scene, OFF(colloids.init)) > 0) {
        off = OFF(colloids.init);
        key = "colloids.init";
    }
    return pl_scene_fail(scene, err, off, key,
                         "%s%s of R_i+R_j > colloids.max_overlap = %g; allowed: fewer colloids, a smaller radius "
                         "or another configuration", from, what, cs->max_overlap);
}
