/* Geometry shared by the couplings: the collision cell of a point under the
 * current grid shift (as in kernels/srd_stream.c), and a colloid lookup on
 * unshifted unit cells so that "is this fluid particle inside a colloid?"
 * costs one cell visit for the many particles far from any colloid.  The
 * lookup is built serially (colloids are few) in colloid index order, so a
 * cell lists its colloids in index order whatever the thread count.
 * Also the initial replacement of the fluid found inside colloids (parallel
 * per particle, its draws keyed by the particle index). */
#include <math.h>
#include <string.h>

#include "peloid/coupling_kernels.h"
#include "peloid/rng.h"

/* Cell range [lo, hi] along one axis touched by [x - R, x + R]; periodic
 * axes wrap later, closed axes are clipped. */
static void span(double x, double R, int L, int periodic, int *lo, int *hi)
{
    *lo = (int)floor(x - R);
    *hi = (int)floor(x + R);
    if (periodic && *hi - *lo + 1 > L) {
        *lo = 0;
        *hi = L - 1;
    }
    if (!periodic) {
        if (*lo < 0) *lo = 0;
        if (*hi > L - 1) *hi = L - 1;
    }
}

static inline int wrapi(int i, int L)
{
    i %= L;
    return i < 0 ? i + L : i;
}

size_t pl_coupling_lookup_build(const pl_coupling_colloids_t *c, const int L[3], const int walls[3],
                                int32_t *start, int32_t *list, size_t cap)
{
    const size_t ncells = (size_t)L[0] * (size_t)L[1] * (size_t)L[2];
    int per[3];
    for (int d = 0; d < 3; ++d) per[d] = walls[d] == PL_WALLS_NONE;
    memset(start, 0, (ncells + 1) * sizeof *start);
    for (int pass = 0; pass < 2; ++pass) {
        for (size_t k = 0; k < c->n; ++k) {
            double r[3] = {c->x[k], c->y[k], c->z[k]};
            int lo[3], hi[3];
            for (int d = 0; d < 3; ++d) span(r[d], c->rad[k], L[d], per[d], &lo[d], &hi[d]);
            for (int iz = lo[2]; iz <= hi[2]; ++iz)
                for (int iy = lo[1]; iy <= hi[1]; ++iy)
                    for (int ix = lo[0]; ix <= hi[0]; ++ix) {
                        size_t cell = ((size_t)wrapi(iz, L[2]) * (size_t)L[1] +
                                       (size_t)wrapi(iy, L[1])) * (size_t)L[0] +
                                      (size_t)wrapi(ix, L[0]);
                        if (pass == 0) start[cell + 1]++;
                        else list[start[cell]++] = (int32_t)k;
                    }
        }
        if (pass == 0) {
            for (size_t i = 0; i < ncells; ++i) start[i + 1] += start[i];
            if ((size_t)start[ncells] > cap) return (size_t)start[ncells];
        } else { /* start[i] now points at the end of cell i: shift back */
            for (size_t i = ncells; i > 0; --i) start[i] = start[i - 1];
            start[0] = 0;
        }
    }
    return (size_t)start[ncells];
}

/* The first colloid of list[b .. e) that contains r (p: r - centre). */
static int32_t inside_of(const pl_coupling_colloids_t *c, const int L[3], const int walls[3], const int32_t *list,
                         int32_t b, int32_t e, const double r[3], double p[3])
{
    for (int32_t q = b; q < e; ++q) {
        int32_t k = list[q];
        double d[3] = {r[0] - c->x[k], r[1] - c->y[k], r[2] - c->z[k]};
        for (int a = 0; a < 3; ++a)
            if (walls[a] == PL_WALLS_NONE) d[a] -= L[a] * nearbyint(d[a] / L[a]);
        double R = c->rad[k];
        if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < R * R) {
            p[0] = d[0];
            p[1] = d[1];
            p[2] = d[2];
            return k;
        }
    }
    return -1;
}

int32_t pl_coupling_inside(const pl_coupling_colloids_t *c, const int L[3], const int walls[3],
                           const int32_t *start, const int32_t *list, const double r[3],
                           double p[3])
{
    int ic[3];
    for (int d = 0; d < 3; ++d) {
        ic[d] = (int)floor(r[d]);
        if (ic[d] < 0) ic[d] = 0;
        if (ic[d] >= L[d]) ic[d] = L[d] - 1;
    }
    size_t cell = ((size_t)ic[2] * (size_t)L[1] + (size_t)ic[1]) * (size_t)L[0] + (size_t)ic[0];
    return inside_of(c, L, walls, list, start[cell], start[cell + 1], r, p);
}

int32_t pl_coupling_inside_cells(const pl_coupling_colloids_t *c, const pl_grid_t *g, const uint32_t *cstart,
                                 const int32_t *clist, const double r[3], double p[3])
{
    const uint32_t cell = pl_coupling_cell_of(g, r[0], r[1], r[2]);
    return inside_of(c, g->L, g->walls, clist, (int32_t)cstart[cell], (int32_t)cstart[cell + 1], r, p);
}

void pl_coupling_clear_interiors(pl_fluid_t *f, const pl_coupling_colloids_t *c, const int L[3],
                                 const int walls[3], const int32_t *lk_start, const int32_t *lk_list,
                                 uint64_t seed, int nthreads)
{
    /* per particle, draws keyed by its index: any static split gives the same */
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t i = 0; i < f->n; ++i) {
        double r[3] = {f->r[0][i], f->r[1][i], f->r[2][i]}, p[3];
        for (uint64_t draw = 0; draw < 1000; ++draw) {
            if (pl_coupling_inside(c, L, walls, lk_start, lk_list, r, p) < 0) break;
            pl_rand4_t u = pl_rng_uniform4(seed, PL_RNG_FLUID_REPLACE, 0, i, draw);
            for (int d = 0; d < 3; ++d) {
                r[d] = u.u[d] * L[d];
                if (r[d] >= L[d]) r[d] = 0.0;
            }
        }
        for (int d = 0; d < 3; ++d) f->r[d][i] = (pl_real)r[d];
    }
}
