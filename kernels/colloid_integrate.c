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
#include "peloid/real.h" /* PL_ROUND_AS_WRITTEN */

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

/* Rounds as written (PL_ROUND_AS_WRITTEN, peloid/real.h: gcc had fused the
 * quaternion product into vfmaddsub), as the vector lanes of
 * pl_colloid_rotate_block do (tests/unit/test_colloid_md.c). */
PL_ROUND_AS_WRITTEN void pl_colloid_quat_rotate(double px, double py, double pz, double q[4])
{
    /* Hecht Eq. 10 (kernels/colloid_integrate.h) */
    double th2 = px * px + py * py + pz * pz;
    double c, s;
    if (th2 < 1e-4) {
        pl_colloid_half_angle_small(th2, &c, &s);
    } else {
        double th = sqrt(th2);
        c = cos(0.5 * th);
        s = sin(0.5 * th) / th;
    }
    const pl_colloid_quat_t r = pl_colloid_quat_apply(c, s, px, py, pz, q[0], q[1], q[2], q[3]);
    for (int k = 0; k < 4; ++k) q[k] = r.q[k];
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

void pl_colloid_displace(size_t n, const double box[3], const int periodic[3], double *restrict x,
                         double *restrict y, double *restrict z, int32_t *restrict ix, int32_t *restrict iy,
                         int32_t *restrict iz, const double *restrict dx, const double *restrict dy,
                         const double *restrict dz)
{
    for (size_t i = 0; i < n; ++i) pl_colloid_move_one(i, 1.0, box, periodic, x, y, z, ix, iy, iz, dx, dy, dz);
}
