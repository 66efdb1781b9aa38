/* WCA forces of the potential coupling (PL Sec. III.A, PL Eq. 17):
 *   phi_cf(r) = 4 eps [(sigma/r)^12 - (sigma/r)^6 + 1/4],  r <= 2^{1/6} sigma,
 * a radial force: slip surfaces (PL Sec. III.B).  Between the selected fluid
 * particles and the colloids, from the lookup (pl_coupling_wca_forces) or
 * over the pairs the selection formed (pl_coupling_wca_pair_forces:
 * vectorised, no lookup per evaluation; its block is also the force pass of
 * the fused MD step, kernels/coupling_potential.c).  In parallel over fixed
 * blocks of particles: each block sums its reactions on the colloids in
 * particle order into its own row, and the rows are added in block order, so
 * the result depends on the number of selected particles and colloids but
 * not on the thread count. */
#include <math.h>

#include "coupling_geometry.h"
#include "coupling_wca.h"
#include "peloid/coupling_kernels.h"

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
    const pl_coupling_box_t q = pl_coupling_box(w->L, w->walls);
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
            for (int a = 0; a < 3; ++a) dv[a] = pl_coupling_min_image(dv[a], q.h[a], L[a]);
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

/* PL Eq. 17 for one pair at separation (dx, dy, dz) (minimum image taken
 * here): the force on the particle and the energy, 0 beyond the cut-off
 * (selected, not multiplied: the same bits as wca_block's skip once
 * summed). */
static inline void wca_pair(double dx, double dy, double dz, double s2, double rc2, double e24, double e4,
                            const double h[3], const double L[3], double *gx, double *gy, double *gz, double *ge)
{
    dx = dx > h[0] ? dx - L[0] : (dx < -h[0] ? dx + L[0] : dx);
    dy = dy > h[1] ? dy - L[1] : (dy < -h[1] ? dy + L[1] : dy);
    dz = dz > h[2] ? dz - L[2] : (dz < -h[2] ? dz + L[2] : dz);
    const double d2 = dx * dx + dy * dy + dz * dz;
    double sr6 = s2 / d2;
    sr6 = sr6 * sr6 * sr6;
    /* PL Eq. 17: F = 24 eps (2 (s/r)^12 - (s/r)^6) / r^2 * dv */
    const double ff = e24 * (2.0 * sr6 * sr6 - sr6) / d2, e = e4 * (sr6 * sr6 - sr6 + 0.25);
    const int in = d2 < rc2;
    const double fin = in ? ff : 0.0;
    *gx = fin * dx;
    *gy = fin * dy;
    *gz = fin * dz;
    *ge = in ? e : 0.0;
}

void pl_coupling_wca_pair_block(const pl_coupling_wca_t *w, const pl_coupling_near_t *nb,
                                const pl_coupling_colloids_t *c, size_t lo, size_t hi, double *rb,
                                double *restrict gx, double *restrict gy, double *restrict gz, double *restrict ge)
{
    const size_t nc = c->n, row = 3 * nc + 1, nn = nb->n;
    for (size_t q = 0; q < row; ++q) rb[q] = 0.0;
    const double s2 = w->sigma * w->sigma, rc2 = s2 * cbrt(2.0); /* (2^{1/6} sigma)^2 */
    const double e24 = 24.0 * w->eps, e4 = 4.0 * w->eps;
    const pl_coupling_box_t q = pl_coupling_box(w->L, w->walls);
    const double h[3] = {q.h[0], q.h[1], q.h[2]}, L[3] = {q.L[0], q.L[1], q.L[2]};
    const double *restrict x = nb->r[0], *restrict y = nb->r[1], *restrict z = nb->r[2];
    const double *restrict cx = c->x, *restrict cy = c->y, *restrict cz = c->z;
    const int32_t *restrict k0 = nb->k0, *restrict pk = nb->pk;
    const uint32_t *restrict pj = nb->pj, *restrict ps = nb->pstart;
    double *restrict fx = nb->f[0], *restrict fy = nb->f[1], *restrict fz = nb->f[2];
#pragma omp simd
    for (size_t j = lo; j < hi; ++j) {
        const int32_t k = k0[j];
        double a, b, d;
        wca_pair(x[j] - cx[k], y[j] - cy[k], z[j] - cz[k], s2, rc2, e24, e4, h, L, &a, &b, &d, ge + j);
        fx[j] = 0.0 + a;
        fy[j] = 0.0 + b;
        fz[j] = 0.0 + d;
    }
    for (uint32_t p = ps[lo]; p < ps[hi]; ++p) {
        const uint32_t j = pj[p];
        const int32_t k = pk[p];
        wca_pair(x[j] - cx[k], y[j] - cy[k], z[j] - cz[k], s2, rc2, e24, e4, h, L, gx + nn + p, gy + nn + p,
                 gz + nn + p, ge + nn + p);
    }
    /* the reaction on the colloid of the last first pair (kc) is held in
     * registers (a run of particles near one colloid: no round trip through
     * memory per particle); the same subtractions in the same order */
    double epot = 0.0;
    double *rx = rb, *ry = rb + nc, *rz = rb + 2 * nc;
    int32_t kc = lo < hi ? k0[lo] : 0;
    double ax = 0.0, ay = 0.0, az = 0.0; /* = row of kc, all 0 at the start */
    for (size_t j = lo; j < hi; ++j) {
        const int32_t k = k0[j];
        if (k != kc) {
            rx[kc] = ax;
            ry[kc] = ay;
            rz[kc] = az;
            kc = k;
            ax = rx[k];
            ay = ry[k];
            az = rz[k];
        }
        epot += ge[j];
        if (ps[j] == ps[j + 1]) { /* one pair: f = 0 + g */
            ax -= fx[j];
            ay -= fy[j];
            az -= fz[j];
            continue;
        }
        double g0, g1, g2, e0;
        wca_pair(x[j] - cx[k], y[j] - cy[k], z[j] - cz[k], s2, rc2, e24, e4, h, L, &g0, &g1, &g2, &e0);
        double F0 = 0.0 + g0, F1 = 0.0 + g1, F2 = 0.0 + g2;
        ax -= g0;
        ay -= g1;
        az -= g2;
        for (uint32_t p = ps[j]; p < ps[j + 1]; ++p) {
            const int32_t kp = pk[p];
            const size_t e = nn + p;
            epot += ge[e];
            F0 += gx[e];
            F1 += gy[e];
            F2 += gz[e];
            rx[kp] -= gx[e]; /* kp > k0[j] = kc: not held */
            ry[kp] -= gy[e];
            rz[kp] -= gz[e];
        }
        fx[j] = F0;
        fy[j] = F1;
        fz[j] = F2;
    }
    if (lo < hi) {
        rx[kc] = ax;
        ry[kc] = ay;
        rz[kc] = az;
    }
    rb[3 * nc] = epot;
}

double pl_coupling_wca_rows_sum(size_t nc, size_t nblk, const double *partial, double *cfx, double *cfy, double *cfz)
{
    const size_t row = 3 * nc + 1;
    double *cf[3] = {cfx, cfy, cfz};
    for (size_t q = 0; q < 3 * nc; ++q) /* in block order */
        for (size_t b = 0; b < nblk; ++b) cf[q / nc][q % nc] += partial[b * row + q];
    double epot = 0.0;
    for (size_t b = 0; b < nblk; ++b) epot += partial[b * row + 3 * nc];
    return epot;
}

double pl_coupling_wca_pair_forces(const pl_coupling_wca_t *w, const pl_coupling_near_t *nb,
                                   const pl_coupling_colloids_t *c, double *cfx, double *cfy, double *cfz,
                                   int nthreads, double *partial, double *pair_buf, size_t pair_cap)
{
    const size_t nn = nb->n, nc = c->n, row = 3 * nc + 1, nblk = pl_coupling_wca_blocks(nn, nc);
    double *gx = pair_buf, *gy = pair_buf + pair_cap, *gz = pair_buf + 2 * pair_cap, *ge = pair_buf + 3 * pair_cap;
#pragma omp parallel for schedule(dynamic, 1) num_threads(nthreads)
    for (size_t b = 0; b < nblk; ++b)
        pl_coupling_wca_pair_block(w, nb, c, nn * b / nblk, nn * (b + 1) / nblk, partial + b * row, gx, gy, gz, ge);
    return pl_coupling_wca_rows_sum(nc, nblk, partial, cfx, cfy, cfz);
}
