/* Fluid guard scan (src/fluid/fluid_guard.c reports what it finds): the lowest
 * index of a particle whose position is outside [0, L] on some axis (which
 * catches NaN and Inf too) or whose speed^2 exceeds a bound (or is not
 * finite); positions = 0: the speeds only.  One read-only pass over r and v
 * (48 B per particle in double; 24 B for the speeds).
 *
 * Each thread scans its static chunk in blocks: a branch-free, vectorised
 * "any bad?" test per block, and only a flagged block is rescanned for the
 * index.  The result is combined with reduction(min), which is exact, so it
 * is the same for any thread count. */
#include <omp.h>
#include <stdint.h>

#include "omp_parts.h"
#include "peloid/srd_kernels.h"

enum { GUARD_BLOCK = 512 };

static inline int bad_v(const pl_real *restrict vx, const pl_real *restrict vy, const pl_real *restrict vz,
                        size_t i, double vmax2)
{
    const double u = vx[i], v = vy[i], w = vz[i];
    return !(u * u + v * v + w * w <= vmax2);
}

static inline int bad_one(const pl_real *restrict x, const pl_real *restrict y, const pl_real *restrict z,
                          const pl_real *restrict vx, const pl_real *restrict vy,
                          const pl_real *restrict vz, size_t i, const double L[3], double vmax2)
{
    const double a = x[i], b = y[i], c = z[i], u = vx[i], v = vy[i], w = vz[i];
    const int ok = (a >= 0.0) & (a <= L[0]) & (b >= 0.0) & (b <= L[1]) & (c >= 0.0) & (c <= L[2]) &
                   (u * u + v * v + w * w <= vmax2);
    return !ok;
}

size_t pl_srd_guard_scan(const pl_fluid_t *f, const int Lc[3], double vmax2, int positions, int nthreads)
{
    const double L[3] = {Lc[0], Lc[1], Lc[2]};
    const pl_real *restrict x = f->r[0], *restrict y = f->r[1], *restrict z = f->r[2];
    const pl_real *restrict vx = f->v[0], *restrict vy = f->v[1], *restrict vz = f->v[2];
    const size_t n = f->n;
    size_t first = n;
    /* the same static chunks as the other fluid kernels: each thread reads
     * the pages it first touched (parts: omp_parts.h) */
#pragma omp parallel num_threads(nthreads) reduction(min : first)
    PL_FOR_PART(t, nthreads) {
        size_t lo, hi, mine = n; /* (the private `first` starts at SIZE_MAX) */
        pl_chunk(n, t, nthreads, &lo, &hi);
        for (size_t i0 = lo; i0 < hi && mine == n; i0 += GUARD_BLOCK) {
            const size_t i1 = hi - i0 < GUARD_BLOCK ? hi : i0 + GUARD_BLOCK;
            int bad = 0;
            if (positions) {
#pragma omp simd reduction(| : bad)
                for (size_t i = i0; i < i1; ++i) bad |= bad_one(x, y, z, vx, vy, vz, i, L, vmax2);
            } else {
#pragma omp simd reduction(| : bad)
                for (size_t i = i0; i < i1; ++i) bad |= bad_v(vx, vy, vz, i, vmax2);
            }
            if (!bad) continue;
            for (size_t i = i0; i < i1; ++i)
                if (positions ? bad_one(x, y, z, vx, vy, vz, i, L, vmax2) : bad_v(vx, vy, vz, i, vmax2)) {
                    mine = i;
                    break;
                }
        }
        if (mine < first) first = mine;
    }
    return first;
}

size_t pl_srd_guard_scan_speeds(const pl_fluid_t *f, size_t lo, size_t hi, double vmax2)
{
    const pl_real *restrict vx = f->v[0], *restrict vy = f->v[1], *restrict vz = f->v[2];
    for (size_t i = lo; i < hi; ++i)
        if (bad_v(vx, vy, vz, i, vmax2)) return i;
    return hi;
}
