/* The drift of one fluid particle (private to kernels/): shared by the fused
 * stream+bin pass (srd_stream.c) and the stream-in-scatter sort (srd_sort.c),
 * so that both produce bitwise the same position, velocity and cell.
 *
 * Hecht Eq. 11 / PL Eqs. 1-2: r += v dt, after a velocity kick v += g dt for a
 * constant body force.  Periodic wrap, or reflection at planar walls z = 0
 * and z = Lz: bounce-back (no-slip, v -> 2U - v in the frame of a wall moving
 * with U) or specular (slip, v_z -> -v_z).  The collision cell under the
 * current grid shift (Hecht Sec. III) is computed from the stored (rounded)
 * position. */
#ifndef PELOID_SRD_DRIFT_H
#define PELOID_SRD_DRIFT_H

#include <math.h>
#include <string.h>

#include "peloid/scene.h"
#include "peloid/srd_kernels.h"

typedef struct {
    double dt, a[3];
    double L[3], iL[3], s[3];
    int n[3];
    int walls, noslip;
    double wall_u[2][3];
} pl_drift_t;

/* move = 0: no kick, no drift (binning only). */
static inline void pl_drift_init(pl_drift_t *c, const pl_grid_t *g, const pl_stream_params_t *p,
                                 int move)
{
    c->dt = move ? p->dt : 0.0;
    for (int d = 0; d < 3; ++d) {
        c->a[d] = move ? p->accel[d] * p->dt : 0.0;
        c->L[d] = g->L[d];
        c->iL[d] = 1.0 / c->L[d];
        c->s[d] = g->shift[d];
        c->n[d] = g->n[d];
    }
    c->walls = g->walls_z != PL_WALLS_NONE;
    c->noslip = g->walls_z == PL_WALLS_NOSLIP;
    memcpy(c->wall_u, p->wall_u, sizeof c->wall_u);
}

static inline double pl_drift_wrap(double x, double L, double invL)
{
    x -= L * floor(x * invL);
    return x >= L ? 0.0 : x; /* x slightly below 0 can round up to L */
}

static inline int pl_drift_cell_1d(double x, double s, int n)
{
    int i = (int)floor(x - s);
    if (i < 0) i += n;
    else if (i >= n) i -= n;
    return i;
}

/* Impulse dp (m_f = 1) given by wall `top` to a particle, added in fixed
 * point (PL_FIELD_FIXED_SHIFT) to acc[3 top + d]: integer sums do not depend
 * on the order, hence not on the thread count. */
static inline void pl_drift_wall_acc(int64_t *acc, int top, const double dp[3])
{
    for (int d = 0; d < 3; ++d) acc[3 * top + d] += llround(ldexp(dp[d], PL_FIELD_FIXED_SHIFT));
}

/* Reflects one particle at the walls after a drift of dt from (r0, v).  Walls
 * are at z = 0 (index 0) and z = Lz (index 1).  acc (NULL: not wanted)
 * receives the impulse of every bounce (pl_drift_wall_acc). */
static inline void pl_drift_reflect_z(double r[3], double v[3], const double r0[3], double dt,
                                      double Lz, int noslip, const double wall_u[2][3], int64_t *acc)
{
    double t_left = dt;
    double p[3] = {r0[0], r0[1], r0[2]};
    for (int bounce = 0; bounce < 8 && (r[2] < 0.0 || r[2] > Lz); ++bounce) {
        int top = r[2] > Lz;
        double zw = top ? Lz : 0.0;
        double tc = (zw - p[2]) / v[2]; /* time to reach the wall */
        if (!(tc >= 0.0)) tc = 0.0;
        if (tc > t_left) tc = t_left;
        for (int d = 0; d < 3; ++d) p[d] += v[d] * tc;
        p[2] = zw;
        t_left -= tc;
        const double vin[3] = {v[0], v[1], v[2]};
        if (noslip) {
            for (int d = 0; d < 3; ++d) v[d] = 2.0 * wall_u[top][d] - v[d];
        } else {
            v[2] = -v[2];
        }
        if (acc) {
            const double dp[3] = {v[0] - vin[0], v[1] - vin[1], v[2] - vin[2]};
            pl_drift_wall_acc(acc, top, dp);
        }
        for (int d = 0; d < 3; ++d) r[d] = p[d] + v[d] * t_left;
    }
    if (r[2] < 0.0) r[2] = 0.0;     /* pathological velocities only */
    if (r[2] > Lz) r[2] = Lz;
}

/* Drifts the particle (r, v) in place: on return r and v hold the values to
 * store (exactly representable in pl_real), dr the unwrapped displacement
 * and the function value is the collision cell.  wall_acc: NULL, or the
 * fixed-point wall impulses (bottom xyz, top xyz) to add the bounces to. */
static inline uint32_t pl_drift_one(const pl_drift_t *c, double r[3], double v[3], double dr[3],
                                    int64_t *wall_acc)
{
    for (int d = 0; d < 3; ++d) v[d] += c->a[d];
    const double r0[3] = {r[0], r[1], r[2]};
    for (int d = 0; d < 3; ++d) r[d] = r0[d] + v[d] * c->dt;
    if (c->walls && (r[2] < 0.0 || r[2] > c->L[2]))
        pl_drift_reflect_z(r, v, r0, c->dt, c->L[2], c->noslip, c->wall_u, wall_acc);
    for (int d = 0; d < 3; ++d) dr[d] = r[d] - r0[d];
    r[0] = pl_drift_wrap(r[0], c->L[0], c->iL[0]);
    r[1] = pl_drift_wrap(r[1], c->L[1], c->iL[1]);
    if (!c->walls) r[2] = pl_drift_wrap(r[2], c->L[2], c->iL[2]);
#ifdef PL_SINGLE
    /* the stored (rounded) position is the one binned */
    r[0] = (pl_real)r[0] >= (pl_real)c->L[0] ? 0.0 : (double)(pl_real)r[0];
    r[1] = (pl_real)r[1] >= (pl_real)c->L[1] ? 0.0 : (double)(pl_real)r[1];
    if (!c->walls) r[2] = (pl_real)r[2] >= (pl_real)c->L[2] ? 0.0 : (double)(pl_real)r[2];
    for (int d = 0; d < 3; ++d) v[d] = (double)(pl_real)v[d];
    const double zb = (double)(pl_real)r[2];
#else
    const double zb = r[2];
#endif
    const int iz = c->walls ? (int)floor(zb - c->s[2]) + 1 /* layers 0 .. Lz+1 */
                            : pl_drift_cell_1d(zb, c->s[2], c->n[2]);
    return (uint32_t)((iz * c->n[1] + pl_drift_cell_1d(r[1], c->s[1], c->n[1])) * c->n[0] +
                      pl_drift_cell_1d(r[0], c->s[0], c->n[0]));
}

/* Block version for periodic boxes (no walls): the same operations in the
 * same order as pl_drift_one, written branch-free so that the compiler
 * vectorises it; bitwise the same results (no FMA contraction in ISO C
 * mode).  Reads particles [i0, i0 + m), writes the drifted values and cells
 * into the block buffers. */
enum { PL_DRIFT_BLOCK = 256 };

/* floor() written with truncating conversions, which GCC vectorises in ISO C
 * mode (floor() calls block it).  Equal to floor(y) for |y| < 2^63 except
 * that -0.0 becomes +0.0 (a drifted position is never -0.0: x >= +0). */
static inline double pl_drift_floor(double y)
{
    const double t = (double)(int64_t)y;
    return t > y ? t - 1.0 : t;
}

/* (int)floor(y) for |y| < 2^31. */
static inline int pl_drift_ifloor(double y)
{
    const int t = (int)y;
    return (double)t > y ? t - 1 : t;
}

static inline double pl_drift_wrap_sel(double x, double L, double invL)
{
    x -= L * pl_drift_floor(x * invL);
    return x >= L ? 0.0 : x;
}

__attribute__((noinline)) static void pl_drift_block_periodic(const pl_drift_t *c, const pl_real *restrict x,
                                           const pl_real *restrict y, const pl_real *restrict z,
                                           const pl_real *restrict vx, const pl_real *restrict vy,
                                           const pl_real *restrict vz, size_t m,
                                           double (*restrict rb)[PL_DRIFT_BLOCK],
                                           double (*restrict vb)[PL_DRIFT_BLOCK],
                                           uint32_t *restrict cb)
{
    const double dt = c->dt, a0 = c->a[0], a1 = c->a[1], a2 = c->a[2];
    const double L0 = c->L[0], L1 = c->L[1], L2 = c->L[2];
    const double i0 = c->iL[0], i1 = c->iL[1], i2 = c->iL[2];
    const double s0 = c->s[0], s1 = c->s[1], s2 = c->s[2];
    const int n0 = c->n[0], n1 = c->n[1], n2 = c->n[2];
#pragma omp simd
    for (size_t k = 0; k < m; ++k) {
        double v0 = (double)vx[k] + a0, v1 = (double)vy[k] + a1, v2 = (double)vz[k] + a2;
#ifndef PL_SINGLE
        double r0 = pl_drift_wrap_sel((double)x[k] + v0 * dt, L0, i0);
        double r1 = pl_drift_wrap_sel((double)y[k] + v1 * dt, L1, i1);
        double r2 = pl_drift_wrap_sel((double)z[k] + v2 * dt, L2, i2);
#else
        /* pl_drift_one's wrap then rounding, reordered so that no float
         * conversion sits in a select arm (which blocks if-conversion):
         * x >= L implies (float)x >= L (L is an integer), so
         * "wrap to 0 if x >= L, round, wrap to 0 if >= L" equals
         * "round, wrap to 0 if >= L" on the unselected x - L floor(x / L). */
        double w0 = (double)x[k] + v0 * dt, w1 = (double)y[k] + v1 * dt, w2 = (double)z[k] + v2 * dt;
        w0 -= L0 * pl_drift_floor(w0 * i0);
        w1 -= L1 * pl_drift_floor(w1 * i1);
        w2 -= L2 * pl_drift_floor(w2 * i2);
        const pl_real f0 = (pl_real)w0, f1 = (pl_real)w1, f2 = (pl_real)w2;
        /* (double)f * (f < L) is (double)f or +0.0 (f >= 0): the select,
         * with the conversion kept out of its arm */
        double r0 = (double)f0 * (double)(f0 < (pl_real)L0);
        double r1 = (double)f1 * (double)(f1 < (pl_real)L1);
        double r2 = (double)f2 * (double)(f2 < (pl_real)L2);
        v0 = (double)(pl_real)v0; v1 = (double)(pl_real)v1; v2 = (double)(pl_real)v2;
#endif
        int ix = pl_drift_ifloor(r0 - s0), iy = pl_drift_ifloor(r1 - s1), iz = pl_drift_ifloor(r2 - s2);
        ix += ix < 0 ? n0 : 0; ix -= ix >= n0 ? n0 : 0;
        iy += iy < 0 ? n1 : 0; iy -= iy >= n1 ? n1 : 0;
        iz += iz < 0 ? n2 : 0; iz -= iz >= n2 ? n2 : 0;
        rb[0][k] = r0; rb[1][k] = r1; rb[2][k] = r2;
        vb[0][k] = v0; vb[1][k] = v1; vb[2][k] = v2;
        cb[k] = (uint32_t)((iz * n1 + iy) * n0 + ix);
    }
}

#endif
