/* One colloid's share of the velocity-Verlet MD step (private to kernels/):
 * the half kick, the drift, the quaternion update (in blocks), and the external
 * forces.  Shared by the separate passes of kernels/colloid_integrate.c and
 * the fused step of kernels/colloid_verlet.h, so both give bitwise the same
 * state.  Formulas: see kernels/colloid_integrate.c. */
#ifndef PELOID_COLLOID_INTEGRATE_H
#define PELOID_COLLOID_INTEGRATE_H

#include <math.h>

#include "peloid/colloid_kernels.h"

/* v += h F/m, w += h T/I (PL Eq. 19 / Hecht Eq. 8, rotation Hecht Eq. 9:
 * one half of the symmetric split). */
static inline void pl_colloid_kick_one(size_t i, double h, const double *restrict mass,
                                       const double *restrict inertia, const double *restrict fx,
                                       const double *restrict fy, const double *restrict fz,
                                       const double *restrict tx, const double *restrict ty,
                                       const double *restrict tz, double *restrict vx,
                                       double *restrict vy, double *restrict vz,
                                       double *restrict wx, double *restrict wy, double *restrict wz)
{
    double a = h / mass[i], b = h / inertia[i];
    vx[i] += a * fx[i];
    vy[i] += a * fy[i];
    vz[i] += a * fz[i];
    wx[i] += b * tx[i];
    wy[i] += b * ty[i];
    wz[i] += b * tz[i];
}

/* v += H Fs/m: the slow forces' kick of multiple time stepping (H = k dt / 2
 * at each end of an outer step of k MD steps; no torque). */
static inline void pl_colloid_slow_kick_one(size_t i, double H, const double *restrict mass,
                                            const double *restrict fsx, const double *restrict fsy,
                                            const double *restrict fsz, double *restrict vx,
                                            double *restrict vy, double *restrict vz)
{
    double a = H / mass[i];
    vx[i] += a * fsx[i];
    vy[i] += a * fsy[i];
    vz[i] += a * fsz[i];
}

/* Wraps x into [0, L) and counts the crossing in img. */
static inline void pl_colloid_wrap(double *x, int32_t *img, double L)
{
    double k = floor(*x / L);
    if (k != 0.0) {
        if (!isfinite(k)) return; /* NaN/Inf position: the NaN guard reports it */
        *x -= k * L;
        if (*x >= L) *x -= L; /* rounding of -tiny + L */
        /* saturated beyond PL_COLLOID_IMAGE_MAX (the colloid guard stops
         * the run): no int32 overflow */
        const double im = (double)*img + k;
        *img = im > PL_COLLOID_IMAGE_MAX ? PL_COLLOID_IMAGE_MAX + 1
               : im < -PL_COLLOID_IMAGE_MAX ? -PL_COLLOID_IMAGE_MAX - 1 : (int32_t)im;
    }
}

/* x += dt v (PL Eq. 18 / Hecht Eq. 7, v already half-kicked), wrapped. */
static inline void pl_colloid_move_one(size_t i, double dt, const double box[3], const int periodic[3],
                                       double *restrict x, double *restrict y, double *restrict z,
                                       int32_t *restrict ix, int32_t *restrict iy, int32_t *restrict iz,
                                       const double *restrict vx, const double *restrict vy,
                                       const double *restrict vz)
{
    x[i] += dt * vx[i];
    y[i] += dt * vy[i];
    z[i] += dt * vz[i];
    if (periodic[0]) pl_colloid_wrap(&x[i], &ix[i], box[0]);
    if (periodic[1]) pl_colloid_wrap(&y[i], &iy[i], box[1]);
    if (periodic[2]) pl_colloid_wrap(&z[i], &iz[i], box[2]);
}

/* Hecht Eq. 10, q <- exp(phi/2) q with phi = omega dt in the space frame,
 * in two parts shared by pl_colloid_quat_rotate (kernels/colloid_integrate.c)
 * and the vector lanes of pl_colloid_rotate_block, so both round the same.
 * The factors of exp(phi/2) = (c, s phi) for a small angle, th2 = |phi|^2
 * < 1e-4 (|phi| < 0.01, the usual MD step): cos(th/2) and sin(th/2)/th by
 * their Taylor series to x^4, x = th2/4 (the next terms are below 1e-22). */
static inline __attribute__((always_inline)) void pl_colloid_half_angle_small(double th2, double *c, double *s)
{
    const double x = 0.25 * th2;
    *c = 1.0 - x * (1.0 / 2 - x * (1.0 / 24 - x * (1.0 / 720 - x * (1.0 / 40320))));
    *s = 0.5 * (1.0 - x * (1.0 / 6 - x * (1.0 / 120 - x * (1.0 / 5040 - x * (1.0 / 362880)))));
}

typedef struct {
    double q[4];
} pl_colloid_quat_t;

/* (c, s phi) q, normalised. */
static inline __attribute__((always_inline)) pl_colloid_quat_t pl_colloid_quat_apply(
    double c, double s, double px, double py, double pz, double Q0, double Q1, double Q2, double Q3)
{
    const double a0 = c, a1 = s * px, a2 = s * py, a3 = s * pz;
    const double r0 = a0 * Q0 - a1 * Q1 - a2 * Q2 - a3 * Q3;
    const double r1 = a0 * Q1 + a1 * Q0 + a2 * Q3 - a3 * Q2;
    const double r2 = a0 * Q2 - a1 * Q3 + a2 * Q0 + a3 * Q1;
    const double r3 = a0 * Q3 + a1 * Q2 - a2 * Q1 + a3 * Q0;
    const double nrm = 1.0 / sqrt(r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3);
    const pl_colloid_quat_t r = {{r0 * nrm, r1 * nrm, r2 * nrm, r3 * nrm}};
    return r;
}

/* Colloid i's orientation (q0..q3)[i] rotated by phi (pl_colloid_quat_rotate). */
static inline void pl_colloid_quat_rotate_at(size_t i, double px, double py, double pz, double *restrict q0,
                                             double *restrict q1, double *restrict q2, double *restrict q3)
{
    double q[4] = {q0[i], q1[i], q2[i], q3[i]};
    pl_colloid_quat_rotate(px, py, pz, q);
    q0[i] = q[0];
    q1[i] = q[1];
    q2[i] = q[2];
    q3[i] = q[3];
}

/* Colloids go through the orientation update in blocks of this many,
 * counted from colloid 0, on every path (the lanes of a block's vector loop
 * and its remainder are the same for any thread count). */
enum { PL_COLLOID_ROT_BLOCK = 64 };

/* The orientations of colloids [b, e) (a block: b a multiple of
 * PL_COLLOID_ROT_BLOCK) rotated by dt w (Hecht Eq. 10, q <- exp(phi/2) q,
 * phi = omega dt in the space frame): for the usual small angle (|phi| <
 * 0.01) pl_colloid_quat_rotate's Taylor branch, in vector lanes; a larger
 * (or non-finite) angle by pl_colloid_quat_rotate itself. */
static inline void pl_colloid_rotate_block(size_t b, size_t e, double dt, const double *restrict wx,
                                           const double *restrict wy, const double *restrict wz,
                                           double *restrict q0, double *restrict q1, double *restrict q2,
                                           double *restrict q3)
{
    int big = 0;
#pragma omp simd reduction(+ : big)
    for (size_t i = b; i < e; ++i) {
        const double px = dt * wx[i], py = dt * wy[i], pz = dt * wz[i];
        const double th2 = px * px + py * py + pz * pz;
        const int small = th2 < 1e-4;
        double c, sn;
        pl_colloid_half_angle_small(th2, &c, &sn);
        const double Q0 = q0[i], Q1 = q1[i], Q2 = q2[i], Q3 = q3[i];
        const pl_colloid_quat_t r = pl_colloid_quat_apply(c, sn, px, py, pz, Q0, Q1, Q2, Q3);
        q0[i] = small ? r.q[0] : Q0;
        q1[i] = small ? r.q[1] : Q1;
        q2[i] = small ? r.q[2] : Q2;
        q3[i] = small ? r.q[3] : Q3;
        big += !small;
    }
    if (big)
        for (size_t i = b; i < e; ++i) {
            const double px = dt * wx[i], py = dt * wy[i], pz = dt * wz[i];
            if (px * px + py * py + pz * pz < 1e-4) continue;
            pl_colloid_quat_rotate_at(i, px, py, pz, q0, q1, q2, q3);
        }
}

/* Gravity and the walls of closed axes on colloid i (PL Eq. 16 form with
 * sigma = R_i at the wall distance), added to f; with epot, its wall and
 * gravity energies (zu: unwrapped z).  rf = 2^{1/wall_n}. */
static inline void pl_colloid_ext_one(const pl_colloid_ext_params_t *p, double rf, size_t n,
                                      size_t i, const double *restrict x,
                                      const double *restrict y, const double *restrict z,
                                      const double *restrict zu, const double *restrict rad,
                                      const double *restrict mass, double *restrict fx,
                                      double *restrict fy, double *restrict fz,
                                      double *restrict epot)
{
    const double nn = p->wall_n, eps = p->wall_eps;
    double m = mass[i];
    fx[i] += m * p->g[0];
    fy[i] += m * p->g[1];
    fz[i] += m * p->g[2];
    double ew = 0.0;
    const double pos[3] = {x[i], y[i], z[i]};
    double *const f[3] = {&fx[i], &fy[i], &fz[i]};
    for (int d = 0; d < 3; ++d) {
        if (!p->walls[d]) continue;
        double s = rad[i], hs[2] = {pos[d], p->L[d] - pos[d]}, sg[2] = {1.0, -1.0};
        for (int w = 0; w < 2; ++w) {
            double hw = hs[w] > 1e-3 * s ? hs[w] : 1e-3 * s;
            if (hw < rf * s) {
                double sn = pow(s / hw, nn), s2n = sn * sn;
                ew += 4.0 * eps * (s2n - sn + 0.25);
                *f[d] += sg[w] * 4.0 * eps * nn * (2.0 * s2n - sn) / hw;
            }
        }
    }
    if (epot) {
        epot[(size_t)PL_CE_WALL * n + i] = ew;
        /* -m g . x with the unwrapped height (gravity acts along z) */
        epot[(size_t)PL_CE_GRAVITY * n + i] = -m * p->g[2] * zu[i];
    }
}

#endif
