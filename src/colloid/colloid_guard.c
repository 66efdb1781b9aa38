/* Stability guards of the colloid MD (the papers' criteria made checks,
 * DESIGN.md "Errors, bad input, guards"):
 *   - overlap (R_i+R_j-r)/(R_i+R_j) beyond colloids.max_overlap (Hecht Sec. II: ~10%)
 *   - a collision resolved by fewer than colloids.min_contact_steps MD steps
 *     (Hecht Sec. II: ~20), estimated from the actual stiffness as the half
 *     period pi sqrt(m_red / U'') of the pair at its present separation
 *   - a dissipative rate zeta/m_red with dt zeta/m_red > 0.5 (explicit
 *     damping overshoots; the friction would reverse the relative velocity)
 *   - NaN/Inf in position, velocity, force
 *   - an image counter beyond PL_COLLOID_IMAGE_MAX (the drift saturates it
 *     before its int32 could overflow)
 *   - drift of the total energy in undamped NVE runs beyond
 *     colloids.max_energy_drift kT per colloid (Hecht Sec. IX.A)
 * Each message names step, particles, quantity, bound and the parameter to
 * change.  The per-particle maxima come from the force kernel.  Every MD step
 * runs one parallel pass (maxima and flags: exact, so independent of the
 * thread count; kernels/colloid_guard_scan.c, or the fused step's close);
 * only when it finds a bound exceeded does the serial scan in
 * index order run, which names the lowest-index offender, so the message is
 * the same for any thread count. */
#include <math.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/colloid.h"
#include "peloid/colloid_kernels.h"

static size_t argmax(const double *a, size_t n)
{
    size_t w = 0;
    for (size_t i = 1; i < n; ++i)
        if (a[i] > a[w]) w = i;
    return w;
}

/* The tests both scans apply, per colloid or on a maximum (the per-colloid
 * ones shared with the fused MD step, kernels/colloid_verlet.h). */
static inline int state_finite(const pl_colloid_t *c, size_t i)
{
    return pl_colloid_state_finite(c->x[i], c->y[i], c->z[i], c->vx[i], c->vy[i], c->vz[i],
                                   c->fx[i], c->fy[i], c->fz[i], c->wx[i], c->wy[i], c->wz[i]);
}
static inline int image_axis_out(const pl_colloid_t *c, size_t i)
{
    return pl_colloid_image_axis_out(c->ix[i], c->iy[i], c->iz[i]);
}
/* MD steps resolving the collision of a pair with stiffness om2 = U''/m_red. */
static inline double contact_steps(double dt, double om2) { return PL_PI / sqrt(om2) / dt; }
static inline int contact_trips(const pl_colloid_t *c, double dt, double om2)
{
    return c->min_contact_steps > 0.0 && om2 > 0.0 && contact_steps(dt, om2) < c->min_contact_steps;
}
static inline int damping_trips(double dt, double damp) { return damp * dt > 0.5; }

/* Drift of the total energy in undamped NVE runs (every guard_interval). */
static int energy_check(pl_colloid_t *c, pl_err_t *err)
{
    pl_colloid_energy_t e;
    pl_colloid_energy(c, &e);
    double drift = fabs(e.total - c->e0) / (double)c->n;
    if (!(drift <= c->max_energy_drift))
        return pl_err_set(err, PL_ERR_GUARD,
                          "guard energy_drift: MD step %lld: all %zu colloids: |E - E0|/N = "
                          "%.4g kT (E0 = %.6g, E = %.6g); bound colloids.max_energy_drift = "
                          "%g; raise colloids.substeps (smaller dt_MD)",
                          c->md_step, c->n, drift, c->e0, e.total, c->max_energy_drift);
    return 0;
}

/* The serial scan: the first bound exceeded, with its lowest-index offender. */
static int guard_report(const pl_colloid_t *c, pl_err_t *err)
{
    size_t n = c->n;
    long long st = c->md_step;
    for (size_t i = 0; i < n; ++i) {
        if (!state_finite(c, i)) { /* name the first non-finite component */
            static const char *const nm[12] = {"x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz", "wx", "wy", "wz"};
            const double v[12] = {c->x[i],  c->y[i],  c->z[i],  c->vx[i], c->vy[i], c->vz[i],
                                  c->fx[i], c->fy[i], c->fz[i], c->wx[i], c->wy[i], c->wz[i]};
            int k = 0;
            while (k < 11 && isfinite(v[k])) ++k;
            return pl_err_set(err, PL_ERR_GUARD,
                              "guard nan: MD step %lld: colloid %zu has a non-finite position, "
                              "velocity or force (%s = %g; r = (%g, %g, %g), v = (%g, %g, %g), f = (%g, %g, %g)); "
                              "bound: finite; reduce the time step (srd.dt or raise colloids.substeps)",
                              st, i, nm[k], v[k], v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
        }
    }
    for (size_t i = 0; i < n; ++i) {
        const int d = image_axis_out(c, i);
        if (d >= 0)
            return pl_err_set(err, PL_ERR_GUARD,
                              "guard image: MD step %lld: colloid %zu crossed the periodic box more than "
                              "%d times along %c (image counter int32); bound %d; the colloid is running "
                              "away: lower colloids.gravity or srd.dt, or raise colloids.substeps",
                              st, i, PL_COLLOID_IMAGE_MAX, "xyz"[d], PL_COLLOID_IMAGE_MAX);
    }
    size_t w = argmax(c->g_overlap, n);
    if (c->g_overlap[w] > c->max_overlap)
        return pl_err_set(err, PL_ERR_GUARD,
                          "guard overlap: MD step %lld: colloids %zu and %d overlap by %.4g of "
                          "R_i+R_j; bound colloids.max_overlap = %g; raise hertz.K (or the "
                          "repulsion), or lower the approach speed / gravity",
                          st, w, c->g_partner[w], c->g_overlap[w], c->max_overlap);
    w = argmax(c->g_omega2, n);
    const double om2 = c->g_omega2[w];
    if (contact_trips(c, c->dt, om2))
        return pl_err_set(err, PL_ERR_GUARD,
                          "guard contact_steps: MD step %lld: colloids %zu and %d: the "
                          "collision time pi sqrt(m_red/U'') = %.4g t0 is resolved by "
                          "%.3g MD steps of dt = %.4g; bound colloids.min_contact_steps = "
                          "%g; raise colloids.substeps (physical{}: it is derived, raise "
                          "coarse_graining.reach_energy) or lower hertz.K / the stiffest term, "
                          "e.g. dlvo.primary_depth",
                          st, w, c->g_partner[n + w], PL_PI / sqrt(om2), contact_steps(c->dt, om2), c->dt,
                          c->min_contact_steps);
    w = argmax(c->g_damp, n);
    if (damping_trips(c->dt, c->g_damp[w]))
        return pl_err_set(err, PL_ERR_GUARD,
                          "guard damping: MD step %lld: colloids %zu and %d: dt zeta/m_red = %.4g "
                          "(dissipative rate %.4g /t0); bound 0.5; raise lubrication.min_gap or "
                          "colloids.substeps, or lower hertz.beta / hertz.gamma_t",
                          st, w, c->g_partner[2 * n + w], c->g_damp[w] * c->dt, c->g_damp[w]);
    return 0;
}

/* The guard's pass (maxima and flags: the same as the close of the fused MD
 * step computes). */
static void guard_max(const pl_colloid_t *c, pl_colloid_guard_max_t *g)
{
    const pl_colloid_guard_view_t v = {
        .n = c->n, .x = c->x, .y = c->y, .z = c->z, .vx = c->vx, .vy = c->vy, .vz = c->vz,
        .fx = c->fx, .fy = c->fy, .fz = c->fz, .wx = c->wx, .wy = c->wy, .wz = c->wz,
        .ix = c->ix, .iy = c->iy, .iz = c->iz,
        .g_overlap = c->g_overlap, .g_omega2 = c->g_omega2, .g_damp = c->g_damp};
    pl_colloid_guard_scan(&v, g, c->nthreads);
}

int pl_colloid_guard_trips(const pl_colloid_t *c, double dt, const pl_colloid_guard_max_t *g)
{
    /* the same tests as guard_report, on the maxima (a NaN guard quantity
     * sends it to guard_report too) */
    return c->n && (g->bad || g->overlap > c->max_overlap || contact_trips(c, dt, g->omega2) ||
                    damping_trips(dt, g->damp));
}

int pl_colloid_guard_max(pl_colloid_t *c, const pl_colloid_guard_max_t *g, int check_energy,
                         pl_err_t *err)
{
    if (!c->n) return 0;
    if (pl_colloid_guard_trips(c, c->dt, g)) {
        int rc = guard_report(c, err);
        if (rc) return rc;
    }
    return check_energy ? energy_check(c, err) : 0;
}

int pl_colloid_guard(pl_colloid_t *c, int check_energy, pl_err_t *err)
{
    if (!c->n) return 0;
    pl_colloid_guard_max_t g;
    guard_max(c, &g);
    return pl_colloid_guard_max(c, &g, check_energy, err);
}
