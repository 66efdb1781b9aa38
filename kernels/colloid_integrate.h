/* One colloid's share of the velocity-Verlet MD step (private to kernels/):
 * the half kick, the drift with the quaternion update, and the external
 * forces.  Shared by the separate passes of kernels/colloid_integrate.c and
 * the fused step of kernels/colloid_verlet.c, so both give bitwise the same
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

/* x += dt v (PL Eq. 18 / Hecht Eq. 7, v already half-kicked), wrapped, and
 * the orientation rotated by dt w (Hecht Eq. 10). */
static inline void pl_colloid_drift_one(size_t i, double dt, const double box[3],
                                        const int periodic[3], double *restrict x,
                                        double *restrict y, double *restrict z,
                                        int32_t *restrict ix, int32_t *restrict iy,
                                        int32_t *restrict iz, const double *restrict vx,
                                        const double *restrict vy, const double *restrict vz,
                                        const double *restrict wx, const double *restrict wy,
                                        const double *restrict wz, double *restrict q0,
                                        double *restrict q1, double *restrict q2,
                                        double *restrict q3)
{
    x[i] += dt * vx[i];
    y[i] += dt * vy[i];
    z[i] += dt * vz[i];
    if (periodic[0]) pl_colloid_wrap(&x[i], &ix[i], box[0]);
    if (periodic[1]) pl_colloid_wrap(&y[i], &iy[i], box[1]);
    if (periodic[2]) pl_colloid_wrap(&z[i], &iz[i], box[2]);
    double q[4] = {q0[i], q1[i], q2[i], q3[i]};
    pl_colloid_quat_rotate(dt * wx[i], dt * wy[i], dt * wz[i], q);
    q0[i] = q[0];
    q1[i] = q[1];
    q2[i] = q[2];
    q3[i] = q[3];
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
