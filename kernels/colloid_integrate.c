/* Colloid integrators: velocity Verlet for translation (Hecht Eqs. 7-8,
 * PL Eqs. 18-19, written as kick-drift-kick), the same split for rotation
 * (Hecht Eq. 9 with the torque over the moment of inertia) and the quaternion
 * update of the orientation (Hecht Eq. 10), normalised every step; external
 * forces (gravity, the walls of closed axes).
 *
 * Every loop is per particle and writes only particle i: no races, and the
 * result does not depend on the thread count. */
#include <math.h>

#include "colloid_integrate.h"

void pl_colloid_kick(size_t n, double h, const double *restrict mass,
                     const double *restrict inertia, const double *restrict fx,
                     const double *restrict fy, const double *restrict fz,
                     const double *restrict tx, const double *restrict ty,
                     const double *restrict tz, double *restrict vx, double *restrict vy,
                     double *restrict vz, double *restrict wx, double *restrict wy,
                     double *restrict wz, int nthreads)
{
#pragma omp parallel for schedule(static) num_threads(nthreads) if (n >= PL_COLLOID_OMP_MIN)
    for (size_t i = 0; i < n; ++i) pl_colloid_kick_one(i, h, mass, inertia, fx, fy, fz, tx, ty, tz, vx, vy, vz, wx, wy, wz);
}

void pl_colloid_quat_rotate(double px, double py, double pz, double q[4])
{
    /* Hecht Eq. 10: q <- exp(phi/2) q, phi = omega dt in the space frame */
    double th2 = px * px + py * py + pz * pz;
    double c, s;
    if (th2 < 1e-4) {
        /* |phi| < 0.01 (the usual MD step): Taylor series of cos(th/2) and
         * sin(th/2)/th to x^4, x = th^2/4; the next terms are below 1e-22 */
        double x = 0.25 * th2;
        c = 1.0 - x * (1.0 / 2 - x * (1.0 / 24 - x * (1.0 / 720 - x * (1.0 / 40320))));
        s = 0.5 * (1.0 - x * (1.0 / 6 - x * (1.0 / 120 - x * (1.0 / 5040 - x * (1.0 / 362880)))));
    } else {
        double th = sqrt(th2);
        c = cos(0.5 * th);
        s = sin(0.5 * th) / th;
    }
    double a0 = c, a1 = s * px, a2 = s * py, a3 = s * pz;
    double r0 = a0 * q[0] - a1 * q[1] - a2 * q[2] - a3 * q[3];
    double r1 = a0 * q[1] + a1 * q[0] + a2 * q[3] - a3 * q[2];
    double r2 = a0 * q[2] - a1 * q[3] + a2 * q[0] + a3 * q[1];
    double r3 = a0 * q[3] + a1 * q[2] - a2 * q[1] + a3 * q[0];
    double nrm = 1.0 / sqrt(r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3);
    q[0] = r0 * nrm;
    q[1] = r1 * nrm;
    q[2] = r2 * nrm;
    q[3] = r3 * nrm;
}

void pl_colloid_drift(size_t n, double dt, const double box[3], const int periodic[3],
                      double *restrict x, double *restrict y, double *restrict z,
                      int32_t *restrict ix, int32_t *restrict iy, int32_t *restrict iz,
                      const double *restrict vx, const double *restrict vy,
                      const double *restrict vz, const double *restrict wx,
                      const double *restrict wy, const double *restrict wz, double *restrict q0,
                      double *restrict q1, double *restrict q2, double *restrict q3, int nthreads)
{
    const size_t nblk = (n + PL_COLLOID_ROT_BLOCK - 1) / PL_COLLOID_ROT_BLOCK;
#pragma omp parallel for schedule(static) num_threads(nthreads) if (n >= PL_COLLOID_OMP_MIN)
    for (size_t bk = 0; bk < nblk; ++bk) {
        const size_t b = bk * PL_COLLOID_ROT_BLOCK, e = b + PL_COLLOID_ROT_BLOCK < n ? b + PL_COLLOID_ROT_BLOCK : n;
        for (size_t i = b; i < e; ++i) pl_colloid_move_one(i, dt, box, periodic, x, y, z, ix, iy, iz, vx, vy, vz);
        pl_colloid_rotate_block(b, e, dt, wx, wy, wz, q0, q1, q2, q3);
    }
}

void pl_colloid_ext_forces(const pl_colloid_ext_params_t *p, size_t n, const double *restrict x,
                           const double *restrict y, const double *restrict z,
                           const double *restrict zu, const double *restrict rad,
                           const double *restrict mass, double *restrict fx,
                           double *restrict fy, double *restrict fz, double *restrict epot, int nthreads)
{
    const double rf = pow(2.0, 1.0 / p->wall_n);
#pragma omp parallel for schedule(static) num_threads(nthreads) if (n >= PL_COLLOID_OMP_MIN)
    for (size_t i = 0; i < n; ++i) pl_colloid_ext_one(p, rf, n, i, x, y, z, zu, rad, mass, fx, fy, fz, epot);
}
