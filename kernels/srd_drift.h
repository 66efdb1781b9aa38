/* The drift of one fluid particle (private to kernels/): shared by the fused
 * stream+bin pass (srd_stream.c) and the stream-in-scatter sort (srd_sort.c),
 * so that both produce bitwise the same position, velocity and cell.
 *
 * Hecht Eq. 11 / PL Eqs. 1-2: r += v dt, after a velocity kick v += g dt for a
 * constant body force.  Periodic wrap, or reflection at the planar walls of
 * every closed axis (z = 0, Lz; x = 0, Lx and y = 0, Ly for a capillary, Hecht
 * Sec. VIII.A): bounce-back (no-slip, v -> 2U - v in the frame of a wall
 * moving with U; the x/y walls are at rest) or specular (slip, the normal
 * component reversed).  The collision cell under the current grid shift
 * (Hecht Sec. III) is computed from the stored (rounded) position. */
#ifndef PELOID_SRD_DRIFT_H
#define PELOID_SRD_DRIFT_H

#include <math.h>
#include <string.h>

#include "peloid/srd_kernels.h"

typedef struct {
    double dt, a[3];
    double L[3], iL[3], s[3];
    int n[3];
    int walls;    /* some axis is closed */
    int wall[3];  /* PL_WALLS_* of each axis */
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
        c->wall[d] = g->walls[d];
    }
    c->walls = g->any_walls;
    memcpy(c->wall_u, p->wall_u, sizeof c->wall_u);
}

static inline double pl_drift_wrap(double x, double L, double invL)
{
    x -= L * floor(x * invL);
    return x >= L ? 0.0 : x; /* x slightly below 0 can round up to L */
}


/* 1 when r lies beyond a wall of a closed axis. */
static inline int pl_drift_outside(const pl_drift_t *c, const double r[3])
{
    for (int d = 0; d < 3; ++d)
        if (c->wall[d] && (r[d] < 0.0 || r[d] > c->L[d])) return 1;
    return 0;
}

/* Reflects one particle at the walls after a drift of dt from (r0, v).  The
 * walls of axis d are at x_d = 0 (top = 0) and x_d = L_d (top = 1); the z
 * walls move with wall_u[top], the x/y walls are at rest.  The particle
 * bounces first off the wall it would have crossed earliest, then moves on
 * for the rest of the step; near an edge or corner this repeats for the next
 * wall (at most 8 bounces).  acc (NULL: not wanted) receives the impulse of
 * every bounce (pl_wall_acc_add, the x/y walls in one slot).  Out of line: few
 * particles reach a wall in a step, and inlined it kept pl_drift_one from
 * being inlined. */
__attribute__((noinline)) static void pl_drift_reflect(const pl_drift_t *c, double r[3], double v[3],
                                                       const double r0[3], int64_t *acc)
{
    static const double at_rest[3] = {0.0, 0.0, 0.0};
    double t_left = c->dt;
    double p[3] = {r0[0], r0[1], r0[2]};
    for (int bounce = 0; bounce < 8 && pl_drift_outside(c, r); ++bounce) {
        int ax = -1, top = 0;
        double tc = 0.0;
        for (int d = 0; d < 3; ++d) {
            if (!c->wall[d] || (r[d] >= 0.0 && r[d] <= c->L[d])) continue;
            const int t = r[d] > c->L[d];
            double td = ((t ? c->L[d] : 0.0) - p[d]) / v[d]; /* time to reach the wall */
            if (!(td >= 0.0)) td = 0.0;
            if (ax < 0 || td < tc) {
                ax = d;
                top = t;
                tc = td;
            }
        }
        if (tc > t_left) tc = t_left;
        for (int d = 0; d < 3; ++d) p[d] += v[d] * tc;
        p[ax] = top ? c->L[ax] : 0.0;
        t_left -= tc;
        const double vin[3] = {v[0], v[1], v[2]};
        if (c->wall[ax] == PL_WALLS_NOSLIP) {
            const double *U = ax == 2 ? c->wall_u[top] : at_rest;
            for (int d = 0; d < 3; ++d) v[d] = 2.0 * U[d] - v[d];
        } else {
            v[ax] = -v[ax];
        }
        if (acc) {
            const double dp[3] = {v[0] - vin[0], v[1] - vin[1], v[2] - vin[2]};
            pl_wall_acc_add(acc, pl_wall_slot(ax, top), dp);
        }
        for (int d = 0; d < 3; ++d) r[d] = p[d] + v[d] * t_left;
    }
    for (int d = 0; d < 3; ++d) { /* pathological velocities only */
        if (!c->wall[d]) continue;
        if (r[d] < 0.0) r[d] = 0.0;
        if (r[d] > c->L[d]) r[d] = c->L[d];
    }
}

/* Drifts the particle (r, v) in place: on return r and v hold the values to
 * store (exactly representable in pl_real), dr the unwrapped displacement
 * and the function value is the collision cell.  closed[d] != 0 exactly
 * when axis d has walls (c->wall[d] != PL_WALLS_NONE).  wall_acc: NULL, or
 * the fixed-point wall impulses (PL_WALL_ACC_N slots) to add the bounces
 * to. */
static inline __attribute__((always_inline)) uint32_t
pl_drift_one_closed(const pl_drift_t *c, const int closed[3], double r[3], double v[3], double dr[3],
                    int64_t *wall_acc)
{
    for (int d = 0; d < 3; ++d) v[d] += c->a[d];
    const double r0[3] = {r[0], r[1], r[2]};
    for (int d = 0; d < 3; ++d) r[d] = r0[d] + v[d] * c->dt;
    if (c->walls && ((closed[0] && (r[0] < 0.0 || r[0] > c->L[0])) ||
                     (closed[1] && (r[1] < 0.0 || r[1] > c->L[1])) ||
                     (closed[2] && (r[2] < 0.0 || r[2] > c->L[2])))) {
        /* copies, so that r, v, r0 do not escape and stay in registers */
        double rr[3] = {r[0], r[1], r[2]}, vv[3] = {v[0], v[1], v[2]};
        const double rs[3] = {r0[0], r0[1], r0[2]};
        pl_drift_reflect(c, rr, vv, rs, wall_acc);
        for (int d = 0; d < 3; ++d) {
            r[d] = rr[d];
            v[d] = vv[d];
        }
    }
    for (int d = 0; d < 3; ++d) dr[d] = r[d] - r0[d];
    int ic[3];
    for (int d = 0; d < 3; ++d) {
        if (closed[d]) { /* closed axis: cells 0 .. L+1, no wrap */
#ifdef PL_SINGLE
            ic[d] = pl_grid_cell_closed((double)(pl_real)r[d], c->s[d]); /* the stored position */
#else
            ic[d] = pl_grid_cell_closed(r[d], c->s[d]);
#endif
            continue;
        }
        r[d] = pl_drift_wrap(r[d], c->L[d], c->iL[d]);
#ifdef PL_SINGLE
        /* the stored (rounded) position is the one binned */
        r[d] = (pl_real)r[d] >= (pl_real)c->L[d] ? 0.0 : (double)(pl_real)r[d];
#endif
        ic[d] = pl_grid_cell_periodic(r[d], c->s[d], c->n[d]);
    }
#ifdef PL_SINGLE
    for (int d = 0; d < 3; ++d) v[d] = (double)(pl_real)v[d];
#endif
    return (uint32_t)((ic[2] * c->n[1] + ic[1]) * c->n[0] + ic[0]);
}

/* pl_drift_one_closed with the closed axes read from c; a caller may pass
 * them as constants instead (srd_stream.c), which removes their branches. */
static inline __attribute__((always_inline)) uint32_t pl_drift_one(const pl_drift_t *c, double r[3],
                                                                   double v[3], double dr[3],
                                                                   int64_t *wall_acc)
{
    return pl_drift_one_closed(c, c->wall, r, v, dr, wall_acc);
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
        /* pl_grid_cell_periodic written with the vectorisable floor */
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
