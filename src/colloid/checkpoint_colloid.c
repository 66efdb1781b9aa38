/* Colloid part of the checkpoint: group /colloids holds every array the next
 * MD step reads.  Besides positions, velocities, spins, quaternions, images,
 * radii, masses and moments of inertia, that is:
 *   - forces and torques: velocity Verlet's first half kick and the Brownian
 *     step use the forces of the previous step, and the dissipative terms
 *     (Hertz damping, tangential friction, lubrication) were evaluated at the
 *     half-step velocities, so recomputing them at restart would differ;
 *   - md_step (keys the Brownian noise and the drift-guard interval);
 *   - e0, the reference energy of the energy-drift guard.
 * Not stored: the per-particle potential energies (functions of positions and
 * images only, recomputed bitwise by the set-up on reading) and scratch
 * (guard maxima, linked cells, unwrapped heights) that the next force
 * evaluation rebuilds. */
#include <math.h>
#include <stdio.h>

#include "checkpoint_h5.h"
#include "peloid/checkpoint.h"
#include "peloid/colloid_kernels.h"

enum { NPOS = 16, NFORCE = 6, NIMG = 3 };

typedef struct {
    const char *name;
    double *a;
} darr_t;

/* Restored before the set-up (which sizes the cells from the radii). */
static void pos_arrays(const pl_colloid_t *c, darr_t t[NPOS])
{
    const darr_t a[NPOS] = {{"x", c->x},   {"y", c->y},   {"z", c->z},       {"vx", c->vx},
                            {"vy", c->vy}, {"vz", c->vz}, {"wx", c->wx},     {"wy", c->wy},
                            {"wz", c->wz}, {"q0", c->q0}, {"q1", c->q1},     {"q2", c->q2},
                            {"q3", c->q3}, {"rad", c->rad}, {"mass", c->mass}, {"inertia", c->inertia}};
    for (int k = 0; k < NPOS; ++k) t[k] = a[k];
}

/* Restored after the set-up (which recomputes them from the state). */
static void force_arrays(const pl_colloid_t *c, darr_t t[NFORCE])
{
    const darr_t a[NFORCE] = {{"fx", c->fx}, {"fy", c->fy}, {"fz", c->fz},
                              {"tx", c->tx}, {"ty", c->ty}, {"tz", c->tz}};
    for (int k = 0; k < NFORCE; ++k) t[k] = a[k];
}

static void image_arrays(const pl_colloid_t *c, int32_t *t[NIMG])
{
    t[0] = c->ix;
    t[1] = c->iy;
    t[2] = c->iz;
}

static const char *const img_names[NIMG] = {"ix", "iy", "iz"};

int pl_ckpt_colloid_write(hid_t f, const pl_colloid_t *c)
{
    hid_t g = pl_ckpt_group_create(f, "colloids");
    if (g < 0) return -1;
    size_t n = c->n;
    darr_t p[NPOS], fo[NFORCE];
    int32_t *img[NIMG];
    pos_arrays(c, p);
    force_arrays(c, fo);
    image_arrays(c, img);
    int bad = 0;
    for (int k = 0; k < NPOS; ++k) bad |= pl_ckpt_write_1d(g, p[k].name, H5T_NATIVE_DOUBLE, p[k].a, n);
    for (int k = 0; k < NFORCE; ++k) bad |= pl_ckpt_write_1d(g, fo[k].name, H5T_NATIVE_DOUBLE, fo[k].a, n);
    for (int k = 0; k < NIMG; ++k) bad |= pl_ckpt_write_1d(g, img_names[k], H5T_NATIVE_INT32, img[k], n);
    bad |= pl_ckpt_write_1d(g, "md_step", H5T_NATIVE_LLONG, &c->md_step, 1);
    bad |= pl_ckpt_write_1d(g, "e0", H5T_NATIVE_DOUBLE, &c->e0, 1);
    if (H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
}

/* Range checks of the arrays read before the set-up: finite, inside the
 * box (periodic or walled), radius, mass and inertia positive, quaternion
 * of unit norm, image counters within PL_COLLOID_IMAGE_MAX. */
static int check_state(const pl_colloid_t *c, const darr_t p[NPOS], int32_t *const img[NIMG], const char *path,
                       pl_err_t *err)
{
    for (size_t i = 0; i < c->n; ++i) {
        for (int k = 0; k < NPOS; ++k)
            if (!isfinite(p[k].a[i]))
                return pl_err_set(err, PL_ERR_INPUT, "%s: colloids/%s[%zu] = %g is not finite (corrupt checkpoint)",
                                  path, p[k].name, i, p[k].a[i]);
        for (int d = 0; d < 3; ++d)
            if (!(p[d].a[i] >= 0.0 && p[d].a[i] <= c->box[d]))
                return pl_err_set(err, PL_ERR_INPUT,
                                  "%s: colloids/%s[%zu] = %.17g is outside the box [0, %g] (corrupt checkpoint)",
                                  path, p[d].name, i, p[d].a[i], c->box[d]);
        for (int k = 13; k < NPOS; ++k) /* rad, mass, inertia */
            if (!(p[k].a[i] > 0.0))
                return pl_err_set(err, PL_ERR_INPUT, "%s: colloids/%s[%zu] = %g; allowed > 0 (corrupt checkpoint)",
                                  path, p[k].name, i, p[k].a[i]);
        const double qn = c->q0[i] * c->q0[i] + c->q1[i] * c->q1[i] + c->q2[i] * c->q2[i] + c->q3[i] * c->q3[i];
        if (!(fabs(qn - 1.0) < 1e-6))
            return pl_err_set(err, PL_ERR_INPUT,
                              "%s: colloids/q0..q3[%zu] has |q|^2 = %.17g; allowed 1 +- 1e-6 (corrupt checkpoint)",
                              path, i, qn);
        for (int k = 0; k < NIMG; ++k)
            if (img[k][i] > PL_COLLOID_IMAGE_MAX || img[k][i] < -PL_COLLOID_IMAGE_MAX)
                return pl_err_set(err, PL_ERR_INPUT, "%s: colloids/%s[%zu] = %d; allowed |%s| <= %d (corrupt "
                                  "checkpoint)", path, img_names[k], i, img[k][i], img_names[k],
                                  PL_COLLOID_IMAGE_MAX);
    }
    if (c->md_step < 0)
        return pl_err_set(err, PL_ERR_INPUT, "%s: colloids/md_step = %lld; allowed >= 0", path, c->md_step);
    return 0;
}

int pl_ckpt_colloid_read(hid_t f, pl_colloid_t *c, const pl_scene_t *scene, const char *path,
                         pl_err_t *err)
{
    hid_t g = H5Lexists(f, "colloids", H5P_DEFAULT) > 0 ? H5Gopen2(f, "colloids", H5P_DEFAULT) : -1;
    if (g < 0) return pl_err_set(err, PL_ERR_INPUT, "%s: checkpoint has no /colloids group", path);
    size_t n = c->n;
    darr_t p[NPOS], fo[NFORCE];
    int32_t *img[NIMG];
    pos_arrays(c, p);
    force_arrays(c, fo);
    image_arrays(c, img);
    int rc = 0;
    for (int k = 0; k < NPOS && !rc; ++k) rc = pl_ckpt_read_1d(g, p[k].name, H5T_NATIVE_DOUBLE, p[k].a, n, path, err);
    for (int k = 0; k < NIMG && !rc; ++k)
        rc = pl_ckpt_read_1d(g, img_names[k], H5T_NATIVE_INT32, img[k], n, path, err);
    if (!rc) rc = pl_ckpt_read_1d(g, "md_step", H5T_NATIVE_LLONG, &c->md_step, 1, path, err);
    if (!rc) rc = check_state(c, p, img, path, err);
    /* cells sized for the restored radii; forces, energies, e0 recomputed ... */
    if (!rc) rc = pl_colloid_setup(c, scene, err);
    /* ... and forces, torques, e0 replaced by the stored ones */
    for (int k = 0; k < NFORCE && !rc; ++k)
        rc = pl_ckpt_read_1d(g, fo[k].name, H5T_NATIVE_DOUBLE, fo[k].a, n, path, err);
    if (!rc) rc = pl_ckpt_read_1d(g, "e0", H5T_NATIVE_DOUBLE, &c->e0, 1, path, err);
    for (size_t i = 0; i < n && !rc; ++i)
        for (int k = 0; k < NFORCE && !rc; ++k)
            if (!isfinite(fo[k].a[i]))
                rc = pl_err_set(err, PL_ERR_INPUT, "%s: colloids/%s[%zu] = %g is not finite (corrupt checkpoint)",
                                path, fo[k].name, i, fo[k].a[i]);
    if (!rc && !isfinite(c->e0))
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: colloids/e0 = %g is not finite (corrupt checkpoint)", path, c->e0);
    H5Gclose(g);
    return rc;
}
