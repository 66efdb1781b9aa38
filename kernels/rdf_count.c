/* Pair-distance histogram for g(r) (include/peloid/rdf.h), O(n^2).
 *
 * OpenMP: rows i are dealt out dynamically (row i has n - 1 - i pairs); each
 * thread counts into its own row of scratch, and the rows are summed after
 * the loop.  The counts are integers, so the sum is exact and the histogram
 * is the same for any thread count and any schedule. */
#include <math.h>
#include <omp.h>

#include "peloid/rdf.h"

static inline __attribute__((always_inline)) void count_rows(const pl_rdf_geom_t *g, size_t n,
                                                             const double *restrict x,
                                                             const double *restrict y,
                                                             const double *restrict z,
                                                             uint64_t *restrict scratch,
                                                             const int periodic_z, const int classes)
{
    const double Lx = g->box[0], Ly = g->box[1], Lz = g->box[2];
    const double ix = 1.0 / Lx, iy = 1.0 / Ly, iz = 1.0 / Lz;
    const double rmax2 = g->rmax * g->rmax, inv_dr = (double)g->nbins / g->rmax;
    const size_t nb = g->nbins;
    const int32_t *cls = g->cls;
    const int ca = g->ca, cb = g->cb;
#pragma omp for schedule(dynamic, 8)
    for (size_t i = 0; i < n; ++i) {
        uint64_t *h = scratch + (size_t)omp_get_thread_num() * nb;
        const int ci = classes ? cls[i] : 0;
        if (classes && ci != ca && ci != cb) continue;
        for (size_t j = i + 1; j < n; ++j) {
            if (classes && !((ci == ca && cls[j] == cb) || (ci == cb && cls[j] == ca))) continue;
            double dx = x[j] - x[i], dy = y[j] - y[i], dz = z[j] - z[i];
            dx -= Lx * nearbyint(dx * ix);
            dy -= Ly * nearbyint(dy * iy);
            if (periodic_z) dz -= Lz * nearbyint(dz * iz);
            double r2 = dx * dx + dy * dy + dz * dz;
            if (r2 >= rmax2) continue;
            size_t b = (size_t)(sqrt(r2) * inv_dr);
            h[b < nb ? b : nb - 1]++;
        }
    }
}

void pl_rdf_count(const pl_rdf_geom_t *g, size_t n, const double *x, const double *y,
                  const double *z, uint64_t *hist, uint64_t *scratch, int nthreads)
{
    if (nthreads < 1) nthreads = 1;
    const size_t nb = g->nbins;
    /* zeroed here, not in the region: the team may be smaller than asked */
    for (size_t b = 0; b < (size_t)nthreads * nb; ++b) scratch[b] = 0;
#pragma omp parallel num_threads(nthreads)
    {
        if (g->cls) {
            if (g->periodic_z) count_rows(g, n, x, y, z, scratch, 1, 1);
            else count_rows(g, n, x, y, z, scratch, 0, 1);
        } else {
            if (g->periodic_z) count_rows(g, n, x, y, z, scratch, 1, 0);
            else count_rows(g, n, x, y, z, scratch, 0, 0);
        }
    }
    for (int t = 0; t < nthreads; ++t)
        for (size_t b = 0; b < nb; ++b) hist[b] += scratch[(size_t)t * nb + b];
}
