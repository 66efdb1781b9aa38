/* The potential coupling's MD step on the fluid particles near colloids
 * (PL Sec. III.A; the order of the step: src/coupling/coupling_potential.c;
 * the selection: kernels/coupling_select.c): gathers them with their
 * (particle, colloid) pairs, takes back their free streaming, kicks and
 * drifts them (PL Eqs. 18-19, per particle) and writes them back.  The
 * forces over the pairs (kernels/coupling_wca.c) are fused with the kicks
 * and the drift around them (pl_coupling_potential_force_step): one pass
 * over the selected particles per MD step instead of four, the same bits
 * (each particle's and each colloid's operations in the same order). */
#include <math.h>

#include "coupling_geometry.h"
#include "coupling_wca.h"
#include "peloid/coupling_kernels.h"
#include "peloid/srd_kernels.h"

/* Drift of particle j (PL Eq. 18) with the streaming's wall bounce; returns
 * |r - r0|^2. */
static inline double drift_one(const pl_coupling_near_t *nb, const pl_grid_t *g, const double wall_u[2][3],
                               double dt, size_t j, int64_t acc[PL_WALL_ACC_N])
{
    double *const *r = nb->r, *const *v = nb->v, *const *disp = nb->disp, *const *rs = nb->r0;
    const double r0[3] = {r[0][j], r[1][j], r[2][j]};
    for (int d = 0; d < 3; ++d) {
        r[d][j] += v[d][j] * dt;
        if (disp[0]) disp[d][j] += v[d][j] * dt;
    }
    if (g->any_walls) {
        /* the streaming's wall bounce (earliest wall first) */
        double rr[3] = {r[0][j], r[1][j], r[2][j]}, vv[3] = {v[0][j], v[1][j], v[2][j]};
        if (pl_srd_wall_bounce(g, wall_u, dt, r0, rr, vv, acc))
            for (int d = 0; d < 3; ++d) {
                if (disp[0]) disp[d][j] += rr[d] - r[d][j];
                r[d][j] = rr[d];
                v[d][j] = vv[d];
            }
    }
    const double a = r[0][j] - rs[0][j], b = r[1][j] - rs[1][j], e = r[2][j] - rs[2][j];
    return a * a + b * b + e * e;
}

double pl_coupling_potential_force_step(const pl_coupling_wca_t *w, const pl_coupling_near_t *nb,
                                        const pl_coupling_colloids_t *c, const pl_grid_t *g,
                                        const double wall_u[2][3], double h, const double ga[3], int kicks,
                                        double dt, double *cfx, double *cfy, double *cfz, int nthreads,
                                        double *partial, double *pair_buf, size_t pair_cap,
                                        int64_t acc[PL_WALL_ACC_N], double *far2)
{
    const size_t nn = nb->n, nc = c->n, row = 3 * nc + 1, nblk = pl_coupling_wca_blocks(nn, nc);
    double *gx = pair_buf, *gy = pair_buf + pair_cap, *gz = pair_buf + 2 * pair_cap, *ge = pair_buf + 3 * pair_cap;
    double *const *v = nb->v, *const *F = nb->f;
    const double g0 = ga[0], g1 = ga[1], g2 = ga[2];
    double far = 0.0;
    /* integer impulses: the sum is exact in any order; max is exact.
     * Static blocks: a thread keeps its blocks, and their particles in its
     * L2, over the MD steps of a collision step (the gather filled them in
     * the same halves); the bits do not depend on which thread runs a block */
#pragma omp parallel for schedule(static) num_threads(nthreads) reduction(+ : acc[:PL_WALL_ACC_N]) \
    reduction(max : far)
    for (size_t b = 0; b < nblk; ++b) {
        const size_t lo = nn * b / nblk, hi = nn * (b + 1) / nblk;
        pl_coupling_wca_pair_block(w, nb, c, lo, hi, partial + b * row, gx, gy, gz, ge);
        /* per particle, as pl_coupling_potential_kick (kicks times), then
         * pl_coupling_potential_drift */
        double *restrict vx = v[0], *restrict vy = v[1], *restrict vz = v[2];
        const double *restrict fx = F[0], *restrict fy = F[1], *restrict fz = F[2];
        if (dt > 0.0 && !g->any_walls && !nb->disp[0] && (kicks == 1 || kicks == 2)) {
            /* the kicks and drift_one in one vectorised pass, the velocity
             * kept in registers between them: the same operations on each
             * particle in the same order */
            double *restrict x = nb->r[0], *restrict y = nb->r[1], *restrict z = nb->r[2];
            const double *restrict x0 = nb->r0[0], *restrict y0 = nb->r0[1], *restrict z0 = nb->r0[2];
            const int twice = kicks == 2;
            /* the squared displacements of a chunk go to a buffer and their
             * maximum is taken after the vectorised loop (clang does not
             * vectorise the max inside it) */
            enum { CH = 256 };
            double d2b[CH];
            for (size_t j0 = lo; j0 < hi; j0 += CH) {
                const size_t j1 = hi - j0 < CH ? hi : j0 + CH;
#pragma omp simd
                for (size_t j = j0; j < j1; ++j) {
                    const double kx = h * (fx[j] + g0), ky = h * (fy[j] + g1), kz = h * (fz[j] + g2);
                    double ux = vx[j] + kx, uy = vy[j] + ky, uz = vz[j] + kz;
                    if (twice) {
                        ux += kx;
                        uy += ky;
                        uz += kz;
                    }
                    vx[j] = ux;
                    vy[j] = uy;
                    vz[j] = uz;
                    const double px = x[j] + ux * dt, py = y[j] + uy * dt, pz = z[j] + uz * dt;
                    x[j] = px;
                    y[j] = py;
                    z[j] = pz;
                    const double a = px - x0[j], bb = py - y0[j], e = pz - z0[j];
                    d2b[j - j0] = a * a + bb * bb + e * e;
                }
                for (size_t k = 0; k < j1 - j0; ++k) far = d2b[k] > far ? d2b[k] : far;
            }
            continue;
        }
        for (int q = 0; q < kicks; ++q) {
#pragma omp simd
            for (size_t j = lo; j < hi; ++j) {
                vx[j] += h * (fx[j] + g0);
                vy[j] += h * (fy[j] + g1);
                vz[j] += h * (fz[j] + g2);
            }
        }
        if (dt > 0.0 && !g->any_walls && !nb->disp[0]) { /* drift_one, vectorised */
            double *restrict x = nb->r[0], *restrict y = nb->r[1], *restrict z = nb->r[2];
            const double *restrict x0 = nb->r0[0], *restrict y0 = nb->r0[1], *restrict z0 = nb->r0[2];
#pragma omp simd reduction(max : far)
            for (size_t j = lo; j < hi; ++j) {
                x[j] += vx[j] * dt;
                y[j] += vy[j] * dt;
                z[j] += vz[j] * dt;
                const double a = x[j] - x0[j], bb = y[j] - y0[j], e = z[j] - z0[j];
                const double d2 = a * a + bb * bb + e * e;
                far = d2 > far ? d2 : far;
            }
        } else if (dt > 0.0) {
            for (size_t j = lo; j < hi; ++j) {
                const double d2 = drift_one(nb, g, wall_u, dt, j, acc);
                far = d2 > far ? d2 : far;
            }
        }
    }
    *far2 = far;
    return pl_coupling_wca_rows_sum(nc, nblk, partial, cfx, cfy, cfz);
}

/* ---- the selected particles at the MD step ----------------------------- */
/* Each particle is handled by one iteration and writes only its own slots
 * (and, in the scatter, the histogram row of its owner thread); the wall
 * impulses are integers: the results are the same for any thread count. */

void pl_coupling_potential_gather(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling_colloids_t *c,
                                  const uint32_t *found, const uint32_t *found_cell, const uint64_t *counts,
                                  const uint32_t *cstart, const int32_t *clist,
                                  const pl_coupling_stage_t *stage, int nthreads, const pl_coupling_near_t *nb)
{
    const pl_coupling_box_t q = pl_coupling_box(g->L, g->walls);
    /* thread t's chunk goes after those of 0..t-1: particle order */
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (int t = 0; t < nthreads; ++t) {
        size_t lo, hi, j = 0, p = 0;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        for (int u = 0; u < t; ++u) {
            j += counts[(size_t)u * 8 + 2];
            p += counts[(size_t)u * 8 + 3] - counts[(size_t)u * 8 + 2]; /* pairs beyond the first */
        }
        for (size_t s = 0; s < counts[(size_t)t * 8 + 2]; ++s, ++j) {
            size_t i = found[lo + s];
            nb->idx[j] = (uint32_t)i;
            nb->owner[j] = t;
            if (stage) { /* the state the selection saw, before the streaming */
                const double *w = stage[t].buf + s * (size_t)stage[t].width;
                for (int d = 0; d < 3; ++d) {
                    nb->r[d][j] = nb->r0[d][j] = w[d];
                    nb->v[d][j] = w[3 + d];
                    if (nb->disp[0]) nb->disp[d][j] = stage[t].width > 6 ? w[6 + d] : 0.0;
                }
            } else
                for (int d = 0; d < 3; ++d) {
                    nb->r[d][j] = nb->r0[d][j] = f->r[d][i];
                    nb->v[d][j] = f->v[d][i];
                    if (nb->disp[0]) nb->disp[d][j] = f->tracked ? f->disp[d][i] : 0.0;
                }
            /* its pairs: the colloids of the selection's test, in order:
             * the first, then the further ones */
            nb->pstart[j] = (uint32_t)p;
            const uint32_t cl = found_cell[lo + s];
            if (cstart[cl + 1] - cstart[cl] == 1) { /* a listed particle with one candidate: its only pair */
                nb->k0[j] = clist[cstart[cl]];
                continue;
            }
            int first = 1;
            for (uint32_t e = cstart[cl]; e < cstart[cl + 1]; ++e) {
                const int32_t k = clist[e];
                if (!pl_coupling_hit(&q, c, k, nb->r[0][j], nb->r[1][j], nb->r[2][j])) continue;
                if (first) {
                    nb->k0[j] = k;
                    first = 0;
                    continue;
                }
                nb->pk[p] = k;
                nb->pj[p] = (uint32_t)j;
                p++;
            }
        }
        if (t == nthreads - 1) nb->pstart[j] = (uint32_t)p;
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
 * (tests/validation/test_coupling_wall.c: the exact Boltzmann force). */
double pl_coupling_potential_drift(const pl_coupling_near_t *nb, const pl_grid_t *g, const double wall_u[2][3],
                                   double dt, int nthreads, int64_t acc[PL_WALL_ACC_N])
{
    const size_t nn = nb->n;
    double far = 0.0;
    /* integer impulses: the sum is exact in any order; max is exact */
#pragma omp parallel for schedule(static) num_threads(nthreads) reduction(+ : acc[:PL_WALL_ACC_N]) \
    reduction(max : far)
    for (size_t j = 0; j < nn; ++j) {
        const double d2 = drift_one(nb, g, wall_u, dt, j, acc);
        far = d2 > far ? d2 : far;
    }
    return far;
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
    const double inner[3] = {L[0] * (1.0 - 0x1p-50), L[1] * (1.0 - 0x1p-50), L[2] * (1.0 - 0x1p-50)};
    /* the particles of one owner (a contiguous run of the list) and its
     * histogram row are handled by one thread */
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (int t = 0; t < nthreads; ++t) {
        size_t j = owner_start(nb, t), end = owner_start(nb, t + 1);
        uint32_t *hrow = hist + (size_t)t * g->ncells, blo, blen;
        pl_fluid_band(f, t, nthreads, (uint32_t)g->ncells, &blo, &blen);
        for (; j < end; ++j) {
            size_t i = nb->idx[j];
            for (int d = 0; d < 3; ++d) {
                double x = nb->r[d][j];
                /* x - L floor(x / L) is x where floor(x / L) = 0 for sure:
                 * 0 < x < L (1 - 2^-50) (x = -0 becomes +0) */
                if (g->walls[d] == PL_WALLS_NONE && !(x > 0.0 && x < inner[d])) {
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
            /* outside this thread's band of the counting sort: whole rows next sort */
            if (pl_fluid_band_out(cell, blo, blen, (uint32_t)g->ncells)) pl_fluid_band_overflow(f);
        }
    }
}
