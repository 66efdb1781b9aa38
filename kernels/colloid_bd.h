/* Brownian dynamics reference integrator: overdamped Langevin with Stokes
 * friction zeta_t = 6 pi eta R (translation) and zeta_r = 8 pi eta R^3
 * (rotation), Euler-Maruyama:
 *   x(t+dt) = x + F dt / zeta_t + sqrt(2 kT dt / zeta_t) xi
 * (PL Sec. III compares SRD against such BD in Fig. 4).  The noise is
 * counter-based (Philox keyed by the seed and PL_RNG_BD_NOISE, counter =
 * step, particle, draw), so each particle's kick is independent of the thread
 * count; each loop iteration writes only particle i.  An overdamped particle
 * has no velocity of its own: v and w are set to the drift F/zeta, T/zeta_r
 * (the noise displacement / dt diverges as dt -> 0).  Private to kernels/:
 * the BD region of kernels/colloid_md_region.c runs it per colloid. */
#ifndef PELOID_COLLOID_BD_H
#define PELOID_COLLOID_BD_H

#include <math.h>

#include "peloid/real.h" /* PL_PI */
#include "colloid_integrate.h" /* pl_colloid_wrap, pl_colloid_quat_rotate_at */
#include "peloid/rng.h"

/* The Brownian step of colloid i. */
static inline void pl_colloid_bd_one(const pl_colloid_bd_params_t *p, size_t i, const double box[3],
                                     const int periodic[3], const double *restrict rad, double *restrict x,
                                     double *restrict y, double *restrict z, int32_t *restrict ix,
                                     int32_t *restrict iy, int32_t *restrict iz, const double *restrict fx,
                                     const double *restrict fy, const double *restrict fz,
                                     const double *restrict tx, const double *restrict ty,
                                     const double *restrict tz, double *restrict vx, double *restrict vy,
                                     double *restrict vz, double *restrict wx, double *restrict wy,
                                     double *restrict wz, double *restrict q0, double *restrict q1,
                                     double *restrict q2, double *restrict q3)
{
    const double dt = p->dt;
    double R = rad[i];
    double zt = 6.0 * PL_PI * p->eta * R, zr = 8.0 * PL_PI * p->eta * R * R * R;
    double st = sqrt(2.0 * p->kT * dt / zt), sr = sqrt(2.0 * p->kT * dt / zr);
    pl_rand4_t a = pl_rng_uniform4(p->seed, PL_RNG_BD_NOISE, p->step, i, 0);
    pl_rand4_t b = pl_rng_uniform4(p->seed, PL_RNG_BD_NOISE, p->step, i, 1);
    double g[6];
    pl_rng_gauss2(a.u[0], a.u[1], &g[0], &g[1]);
    pl_rng_gauss2(a.u[2], a.u[3], &g[2], &g[3]);
    pl_rng_gauss2(b.u[0], b.u[1], &g[4], &g[5]);
    double dx = fx[i] * dt / zt + st * g[0];
    double dy = fy[i] * dt / zt + st * g[1];
    double dz = fz[i] * dt / zt + st * g[2];
    double px = tx[i] * dt / zr + sr * g[3];
    double py = ty[i] * dt / zr + sr * g[4];
    double pz = tz[i] * dt / zr + sr * g[5];
    x[i] += dx;
    y[i] += dy;
    z[i] += dz;
    if (periodic[0]) pl_colloid_wrap(&x[i], &ix[i], box[0]);
    if (periodic[1]) pl_colloid_wrap(&y[i], &iy[i], box[1]);
    if (periodic[2]) pl_colloid_wrap(&z[i], &iz[i], box[2]);
    vx[i] = fx[i] / zt;
    vy[i] = fy[i] / zt;
    vz[i] = fz[i] / zt;
    wx[i] = tx[i] / zr;
    wy[i] = ty[i] / zr;
    wz[i] = tz[i] / zr;
    pl_colloid_quat_rotate_at(i, px, py, pz, q0, q1, q2, q3);
}

#endif
