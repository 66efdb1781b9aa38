/* Potential coupling (PL Sec. III.A): fluid particles near colloids feel the
 * WCA repulsion of PL Eq. 17,
 *   phi_cf(r) = 4 eps [(sigma/r)^12 - (sigma/r)^6 + 1/4],  r <= 2^{1/6} sigma,
 * a radial force: slip surfaces (PL Sec. III.B).  Only the particles near a
 * colloid are integrated at the MD step (src/coupling_potential.c); this
 * file finds them (parallel over the streaming's static chunks) and
 * evaluates the forces, in parallel over fixed blocks of particles: each
 * block sums its reactions on the colloids in particle order into its own
 * row, and the rows are added in block order, so the result depends on the
 * number of selected particles and colloids but not on the thread count. */
#include <math.h>
#include <omp.h>

#include "peloid/coupling_kernels.h"
#include "peloid/scene.h"
#include "peloid/srd_kernels.h"

void pl_coupling_find(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling_colloids_t *c,
                      const int32_t *lk_start, const int32_t *lk_list, int nthreads,
                      uint32_t *found, uint64_t *counts)
{
    /* pl_coupling_inside's test, written out for the selection: the cell is
     * a truncation clamped to [0, L) (= floor + clip), the minimum image one
     * conditional shift on periodic axes (positions there are wrapped into
     * [0, L)), and no early exit, so the outcome is appended without a
     * branch.  The same selections as pl_coupling_inside (checkpoints of
     * periodic, z-wall and capillary scenes bitwise equal); select stage
     * 14 -> 10 ns/particle at 1 thread, 7.5 -> 5.5 at 2 (bench_coupling's
     * potential case). */
    const int L0 = g->L[0], L1 = g->L[1], L2 = g->L[2];
    const int p0 = g->walls[0] == PL_WALLS_NONE, p1 = g->walls[1] == PL_WALLS_NONE, p2 = g->walls[2] == PL_WALLS_NONE;
    /* half box on periodic axes; never exceeded on closed ones */
    const double h0 = p0 ? 0.5 * L0 : INFINITY, h1 = p1 ? 0.5 * L1 : INFINITY, h2 = p2 ? 0.5 * L2 : INFINITY;
#pragma omp parallel num_threads(nthreads)
    {
        int t = omp_get_thread_num();
        size_t lo, hi, m = 0;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        for (size_t i = lo; i < hi; ++i) {
            const double x = f->r[0][i], y = f->r[1][i], z = f->r[2][i];
            int ix = (int)x, iy = (int)y, iz = (int)z;
            ix = ix < 0 ? 0 : ix < L0 ? ix : L0 - 1;
            iy = iy < 0 ? 0 : iy < L1 ? iy : L1 - 1;
            iz = iz < 0 ? 0 : iz < L2 ? iz : L2 - 1;
            const size_t cell = ((size_t)iz * (size_t)L1 + (size_t)iy) * (size_t)L0 + (size_t)ix;
            int in = 0;
            for (int32_t q = lk_start[cell], e = lk_start[cell + 1]; q < e; ++q) {
                const int32_t k = lk_list[q];
                double dx = x - c->x[k], dy = y - c->y[k], dz = z - c->z[k];
                dx = dx > h0 ? dx - L0 : (dx < -h0 ? dx + L0 : dx);
                dy = dy > h1 ? dy - L1 : (dy < -h1 ? dy + L1 : dy);
                dz = dz > h2 ? dz - L2 : (dz < -h2 ? dz + L2 : dz);
                in |= dx * dx + dy * dy + dz * dz < c->rad[k] * c->rad[k];
            }
            found[lo + m] = (uint32_t)i;
            m += (size_t)in;
        }
        counts[(size_t)t * 8 + 2] = m;
    }
}

size_t pl_coupling_wca_blocks(size_t nn, size_t ncolloids)
{
    enum { BLOCK = 2048 };
    const size_t row = 3 * ncolloids + 1, cap = (size_t)1 << 20; /* doubles of partial sums */
    size_t nblk = (nn + BLOCK - 1) / BLOCK, most = cap / row;
    if (nblk > most) nblk = most;
    return nblk ? nblk : 1;
}

/* Forces on particles [lo, hi); reactions summed into row (3 nc + 1: x, y,
 * z per colloid, then the energy). */
static void wca_block(const pl_coupling_wca_t *w, size_t lo, size_t hi, const double *x, const double *y,
                      const double *z, double *fx, double *fy, double *fz, const pl_coupling_colloids_t *c,
                      const int32_t *lk_start, const int32_t *lk_list, double *row)
{
    const double s2 = w->sigma * w->sigma, rc2 = s2 * cbrt(2.0); /* (2^{1/6} sigma)^2 */
    const int *L = w->L;
    const size_t nc = c->n;
    double epot = 0.0;
    for (size_t j = lo; j < hi; ++j) {
        double r[3] = {x[j], y[j], z[j]}, F[3] = {0.0, 0.0, 0.0};
        int ic[3];
        for (int d = 0; d < 3; ++d) {
            double u = r[d] - L[d] * floor(r[d] / L[d]);
            ic[d] = (int)floor(u);
            if (ic[d] < 0) ic[d] = 0;
            if (ic[d] >= L[d]) ic[d] = L[d] - 1;
        }
        size_t cell = ((size_t)ic[2] * (size_t)L[1] + (size_t)ic[1]) * (size_t)L[0] + (size_t)ic[0];
        for (int32_t q = lk_start[cell]; q < lk_start[cell + 1]; ++q) {
            int32_t k = lk_list[q];
            double dv[3] = {r[0] - c->x[k], r[1] - c->y[k], r[2] - c->z[k]};
            for (int a = 0; a < 3; ++a)
                if (w->walls[a] == PL_WALLS_NONE) dv[a] -= L[a] * nearbyint(dv[a] / L[a]);
            double d2 = dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2];
            if (d2 >= rc2) continue;
            double sr6 = s2 / d2;
            sr6 = sr6 * sr6 * sr6;
            /* PL Eq. 17: F = 24 eps (2 (s/r)^12 - (s/r)^6) / r^2 * dv */
            double ff = 24.0 * w->eps * (2.0 * sr6 * sr6 - sr6) / d2;
            epot += 4.0 * w->eps * (sr6 * sr6 - sr6 + 0.25);
            for (int a = 0; a < 3; ++a) {
                F[a] += ff * dv[a];
                row[(size_t)a * nc + (size_t)k] -= ff * dv[a];
            }
        }
        fx[j] = F[0];
        fy[j] = F[1];
        fz[j] = F[2];
    }
    row[3 * nc] = epot;
}

double pl_coupling_wca_forces(const pl_coupling_wca_t *w, size_t nn, const double *x, const double *y,
                              const double *z, double *fx, double *fy, double *fz,
                              const pl_coupling_colloids_t *c, const int32_t *lk_start,
                              const int32_t *lk_list, double *cfx, double *cfy, double *cfz,
                              int nthreads, double *partial)
{
    const size_t nc = c->n, row = 3 * nc + 1, nblk = pl_coupling_wca_blocks(nn, nc);
#pragma omp parallel num_threads(nthreads)
    {
#pragma omp for schedule(dynamic, 1)
        for (size_t b = 0; b < nblk; ++b) {
            double *rb = partial + b * row;
            for (size_t q = 0; q < row; ++q) rb[q] = 0.0;
            wca_block(w, nn * b / nblk, nn * (b + 1) / nblk, x, y, z, fx, fy, fz, c, lk_start, lk_list, rb);
        }
        double *cf[3] = {cfx, cfy, cfz};
#pragma omp for schedule(static)
        for (size_t q = 0; q < 3 * nc; ++q) /* in block order */
            for (size_t b = 0; b < nblk; ++b) cf[q / nc][q % nc] += partial[b * row + q];
    }
    double epot = 0.0;
    for (size_t b = 0; b < nblk; ++b) epot += partial[b * row + 3 * nc];
    return epot;
}
