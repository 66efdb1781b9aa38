/* Potential coupling (PL Sec. III.A): fluid particles near colloids feel the
 * WCA repulsion of PL Eq. 17,
 *   phi_cf(r) = 4 eps [(sigma/r)^12 - (sigma/r)^6 + 1/4],  r <= 2^{1/6} sigma,
 * a radial force: slip surfaces (PL Sec. III.B).  Only the particles near a
 * colloid are integrated at the MD step (the order of the step:
 * src/coupling/coupling_potential.c).  This file finds them (parallel over the
 * streaming's static chunks), gathers them, takes back their free
 * streaming, kicks and drifts them (PL Eqs. 18-19, per particle) and writes
 * them back, and evaluates the forces in parallel over fixed blocks of
 * particles: each block sums its reactions on the colloids in particle order
 * into its own row, and the rows are added in block order, so the result
 * depends on the number of selected particles and colloids but not on the
 * thread count. */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "peloid/coupling_kernels.h"
#include "peloid/srd_kernels.h"

/* The box for the minimum image: sides, and half sides on periodic axes
 * (INFINITY on closed ones: never exceeded). */
typedef struct {
    int L[3];
    double h[3];
} image_box_t;

static image_box_t image_box(const int L[3], const int walls[3])
{
    image_box_t q;
    for (int d = 0; d < 3; ++d) {
        q.L[d] = L[d];
        q.h[d] = walls[d] == PL_WALLS_NONE ? 0.5 * L[d] : INFINITY;
    }
    return q;
}

/* Minimum image of a separation d along an axis: one conditional shift
 * (separations here stay within one box side). */
static inline double min_image(double d, double h, int L) { return d > h ? d - L : (d < -h ? d + L : d); }

/* pl_coupling_inside's test, written out for the selection: the cell is a
 * truncation clamped to [0, L) (= floor + clip), the minimum image one
 * conditional shift on periodic axes (positions there are wrapped into
 * [0, L)), and no early exit, so the outcome is appended without a branch.
 * The same selections as pl_coupling_inside (checkpoints of periodic, z-wall
 * and capillary scenes bitwise equal); select stage 14 -> 10 ns/particle at
 * 1 thread, 7.5 -> 5.5 at 2 (bench_coupling's potential case). */
static inline int near_any(const image_box_t *q, const pl_coupling_colloids_t *c, const int32_t *lk_start,
                           const int32_t *lk_list, double x, double y, double z)
{
    int ix = (int)x, iy = (int)y, iz = (int)z;
    ix = ix < 0 ? 0 : ix < q->L[0] ? ix : q->L[0] - 1;
    iy = iy < 0 ? 0 : iy < q->L[1] ? iy : q->L[1] - 1;
    iz = iz < 0 ? 0 : iz < q->L[2] ? iz : q->L[2] - 1;
    const size_t cell = ((size_t)iz * (size_t)q->L[1] + (size_t)iy) * (size_t)q->L[0] + (size_t)ix;
    int in = 0;
    for (int32_t p = lk_start[cell], e = lk_start[cell + 1]; p < e; ++p) {
        const int32_t k = lk_list[p];
        const double dx = min_image(x - c->x[k], q->h[0], q->L[0]);
        const double dy = min_image(y - c->y[k], q->h[1], q->L[1]);
        const double dz = min_image(z - c->z[k], q->h[2], q->L[2]);
        in |= dx * dx + dy * dy + dz * dz < c->rad[k] * c->rad[k];
    }
    return in;
}

void pl_coupling_find(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling_colloids_t *c,
                      const int32_t *lk_start, const int32_t *lk_list, int nthreads,
                      uint32_t *found, uint64_t *counts)
{
    const image_box_t q = image_box(g->L, g->walls);
#pragma omp parallel num_threads(nthreads)
    {
        int t = omp_get_thread_num();
        size_t lo, hi, m = 0;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        for (size_t i = lo; i < hi; ++i) {
            found[lo + m] = (uint32_t)i;
            m += (size_t)near_any(&q, c, lk_start, lk_list, f->r[0][i], f->r[1][i], f->r[2][i]);
        }
        counts[(size_t)t * 8 + 2] = m;
    }
}

/* Collision cells along one axis, under shift s, that can hold a point
 * within R of x: those of [x - R, x + R] widened by 1e-6 a0 against
 * rounding (the cells are floor(x - s) of the stored positions, the test
 * near_any's, both in double: errors ~1e-12 a0); periodic axes wrap (every
 * cell once the span covers the axis), closed axes (cells 0 .. L + 1,
 * kernels/coupling_lookup.c) are clipped. */
static int axis_cells(double x, double R, double s, int n, int periodic, int *idx)
{
    const double eps = 1e-6;
    int lo = (int)floor(x - R - eps - s), hi = (int)floor(x + R + eps - s);
    if (!periodic) {
        lo = lo + 1 < 0 ? 0 : lo + 1;
        hi = hi + 1 > n - 1 ? n - 1 : hi + 1;
    } else if (hi - lo + 1 >= n) {
        lo = 0;
        hi = n - 1;
    }
    int m = 0;
    for (int i = lo; i <= hi; ++i) idx[m++] = periodic ? ((i % n) + n) % n : i;
    return m;
}

void pl_coupling_find_sorted(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling_colloids_t *c,
                             const int32_t *lk_start, const int32_t *lk_list, const uint32_t *cell_start,
                             uint8_t *marks, int *axis_buf, int nthreads, uint32_t *found, uint64_t *counts)
{
    const image_box_t q = image_box(g->L, g->walls);
    const size_t ncells = g->ncells;
    /* mark the cells a selection sphere reaches (serial: colloids are few) */
    memset(marks, 0, ncells);
    int *ax[3] = {axis_buf, axis_buf + g->n[0], axis_buf + g->n[0] + g->n[1]};
    for (size_t k = 0; k < c->n; ++k) {
        const double r[3] = {c->x[k], c->y[k], c->z[k]};
        int m[3];
        for (int d = 0; d < 3; ++d)
            m[d] = axis_cells(r[d], c->rad[k], g->shift[d], g->n[d], g->walls[d] == PL_WALLS_NONE, ax[d]);
        for (int a = 0; a < m[2]; ++a)
            for (int b = 0; b < m[1]; ++b) {
                uint8_t *row = marks + ((size_t)ax[2][a] * (size_t)g->n[1] + (size_t)ax[1][b]) * (size_t)g->n[0];
                for (int e = 0; e < m[0]; ++e) row[ax[0][e]] = 1;
            }
    }
#pragma omp parallel num_threads(nthreads)
    {
        int t = omp_get_thread_num();
        size_t lo, hi, m = 0;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        /* first cell ending after lo */
        size_t a = 0, b = ncells;
        while (a < b) {
            size_t mid = a + (b - a) / 2;
            if (cell_start[mid + 1] <= lo) a = mid + 1;
            else b = mid;
        }
        for (size_t cl = a; cl < ncells && cell_start[cl] < hi; ++cl) {
            if (!marks[cl]) continue;
            size_t i0 = cell_start[cl] > lo ? cell_start[cl] : lo;
            size_t i1 = cell_start[cl + 1] < hi ? cell_start[cl + 1] : hi;
            for (size_t i = i0; i < i1; ++i) {
                found[lo + m] = (uint32_t)i;
                m += (size_t)near_any(&q, c, lk_start, lk_list, f->r[0][i], f->r[1][i], f->r[2][i]);
            }
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
    const image_box_t q = image_box(w->L, w->walls);
    double epot = 0.0;
    for (size_t j = lo; j < hi; ++j) {
        double r[3] = {x[j], y[j], z[j]}, F[3] = {0.0, 0.0, 0.0};
        int ic[3];
        for (int d = 0; d < 3; ++d) {
            /* the lookup cell (positions here are unwrapped by at most one
             * step's drift; closed axes clipped): any cell next to the
             * particle lists every colloid within the cut-off (lookup radii:
             * cut-off + margin) */
            const double u = q.h[d] == INFINITY ? r[d] : r[d] < 0.0 ? r[d] + L[d] : r[d] >= L[d] ? r[d] - L[d] : r[d];
            ic[d] = (int)u;
            ic[d] = ic[d] < 0 ? 0 : ic[d] < L[d] ? ic[d] : L[d] - 1;
        }
        size_t cell = ((size_t)ic[2] * (size_t)L[1] + (size_t)ic[1]) * (size_t)L[0] + (size_t)ic[0];
        for (int32_t p = lk_start[cell]; p < lk_start[cell + 1]; ++p) {
            int32_t k = lk_list[p];
            double dv[3] = {r[0] - c->x[k], r[1] - c->y[k], r[2] - c->z[k]};
            /* equal to dv - L nearbyint(dv / L) wherever the pair can be
             * within the cut-off (|dv| < L / 2 + rc, L > 2 rc) */
            for (int a = 0; a < 3; ++a) dv[a] = min_image(dv[a], q.h[a], L[a]);
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

/* ---- the selected particles at the MD step ----------------------------- */
/* Each particle is handled by one iteration and writes only its own slots
 * (and, in the scatter, the histogram row of its owner thread); the wall
 * impulses are integers: the results are the same for any thread count. */

void pl_coupling_potential_gather(const pl_fluid_t *f, const uint32_t *found, const uint64_t *counts,
                                  int nthreads, const pl_coupling_near_t *nb)
{
    /* thread t's chunk goes after those of 0..t-1: particle order */
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (int t = 0; t < nthreads; ++t) {
        size_t lo, hi, j = 0;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        for (int u = 0; u < t; ++u) j += counts[(size_t)u * 8 + 2];
        for (size_t q = 0; q < counts[(size_t)t * 8 + 2]; ++q, ++j) {
            size_t i = found[lo + q];
            nb->idx[j] = (uint32_t)i;
            nb->owner[j] = t;
            for (int d = 0; d < 3; ++d) {
                nb->r[d][j] = f->r[d][i];
                nb->v[d][j] = f->v[d][i];
                nb->disp[d][j] = f->tracked ? f->disp[d][i] : 0.0;
            }
        }
    }
}

void pl_coupling_potential_unstream(const pl_coupling_near_t *nb, pl_fluid_t *f, const pl_grid_t *g,
                                    const pl_stream_params_t *sp, int nthreads, int64_t acc[PL_WALL_ACC_N])
{
    const size_t nn = nb->n;
    /* integer impulses: the sum is exact in any order */
#pragma omp parallel for schedule(static) num_threads(nthreads) reduction(+ : acc[:PL_WALL_ACC_N])
    for (size_t j = 0; j < nn; ++j) {
        size_t i = nb->idx[j];
        if (f->tracked)
            for (int d = 0; d < 3; ++d) f->disp[d][i] = nb->disp[d][j];
        if (sp) {
            const double r0[3] = {nb->r[0][j], nb->r[1][j], nb->r[2][j]};
            const double v0[3] = {nb->v[0][j], nb->v[1][j], nb->v[2][j]};
            pl_srd_stream_wall_impulse(g, sp, r0, v0, acc);
        }
    }
}

void pl_coupling_potential_kick(const pl_coupling_near_t *nb, double h, const double g[3], int nthreads)
{
    const size_t nn = nb->n;
    double *const *v = nb->v;
    double *const *F = nb->f;
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t j = 0; j < nn; ++j)
        for (int d = 0; d < 3; ++d) v[d][j] += h * (F[d][j] + g[d]);
}

/* Walls: the streaming's bounce (pl_srd_wall_bounce: to the wall at the
 * crossing time, bounce-back or specular, the rest of the step; earliest wall
 * first), so a particle near a colloid meets the same wall as any other.  A
 * per-axis mirror of the end point with a bounce-back velocity made the
 * equilibrium force of a pinned colloid near a no-slip wall 7 % too strong
 * (tests/test_coupling_wall.c: the exact Boltzmann force). */
void pl_coupling_potential_drift(const pl_coupling_near_t *nb, const pl_grid_t *g, const double wall_u[2][3],
                                 double dt, int nthreads, int64_t acc[PL_WALL_ACC_N])
{
    const size_t nn = nb->n;
    double *const *r = nb->r, *const *v = nb->v, *const *disp = nb->disp;
    /* integer impulses: the sum is exact in any order */
#pragma omp parallel for schedule(static) num_threads(nthreads) reduction(+ : acc[:PL_WALL_ACC_N])
    for (size_t j = 0; j < nn; ++j) {
        const double r0[3] = {r[0][j], r[1][j], r[2][j]};
        for (int d = 0; d < 3; ++d) {
            r[d][j] += v[d][j] * dt;
            disp[d][j] += v[d][j] * dt;
        }
        if (!g->any_walls) continue;
        /* the streaming's wall bounce (earliest wall first) */
        double rr[3] = {r[0][j], r[1][j], r[2][j]}, vv[3] = {v[0][j], v[1][j], v[2][j]};
        if (!pl_srd_wall_bounce(g, wall_u, dt, r0, rr, vv, acc)) continue;
        for (int d = 0; d < 3; ++d) {
            disp[d][j] += rr[d] - r[d][j];
            r[d][j] = rr[d];
            v[d][j] = vv[d];
        }
    }
}

/* First index of the selected list whose owner is >= t (owners ascend). */
static size_t owner_start(const pl_coupling_near_t *nb, int t)
{
    size_t lo = 0, hi = nb->n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (nb->owner[mid] < t) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

void pl_coupling_potential_scatter(const pl_coupling_near_t *nb, pl_fluid_t *f, const pl_grid_t *g,
                                   uint32_t *hist, int nthreads)
{
    const double L[3] = {g->L[0], g->L[1], g->L[2]};
    /* the particles of one owner (a contiguous run of the list) and its
     * histogram row are handled by one thread */
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (int t = 0; t < nthreads; ++t) {
        size_t j = owner_start(nb, t), end = owner_start(nb, t + 1);
        uint32_t *hrow = hist + (size_t)t * g->ncells;
        for (; j < end; ++j) {
            size_t i = nb->idx[j];
            for (int d = 0; d < 3; ++d) {
                double x = nb->r[d][j];
                if (g->walls[d] == PL_WALLS_NONE) {
                    x -= L[d] * floor(x / L[d]);
                    if (x >= L[d]) x = 0.0;
                }
                f->r[d][i] = (pl_real)x;
                f->v[d][i] = (pl_real)nb->v[d][j];
                if (f->tracked) f->disp[d][i] = nb->disp[d][j];
            }
            uint32_t cell = pl_coupling_cell_of(g, f->r[0][i], f->r[1][i], f->r[2][i]);
            hrow[f->cell[i]]--;
            hrow[cell]++;
            f->cell[i] = cell;
        }
    }
}
