/* The settling velocities a user of the sedimentation observer means
 * (issue 35): the initial velocity of the homogeneous fall, over the window
 * the data show to be homogeneous, and the comparison with Stokes (Hecht
 * Eq. 16, with the friction the mapping matched) and Richardson-Zaki (Hecht
 * Eq. 37) at the scene's volume fraction.
 *
 * The samples are the settling velocities of the colloids' mean height
 * between consecutive observer samples, v_k = -(h_k - h_{k-1}) / dt_k (less
 * the fluid's mean velocity; positive down, gravity along -z); over samples
 * a few colloid relaxation times apart they are independent (the mean
 * height is a random walk with drift).  The
 * fall is homogeneous while the drift does not change: the window is the
 * longest prefix of the series whose first and second halves agree within 2
 * combined standard errors (a z test; a settling layer slows the second
 * half); prefixes of 16, 24, 32, ... samples are tried and the longest that
 * passes is kept, so its SE shrinks as the data allow and never mixes the
 * settled state in.  The SE is from blocking over the window (which also
 * covers correlated samples). */
#include <jansson.h>
#include <math.h>
#include <stddef.h>

#include "json_build.h"
#include "peloid/blocking.h"
#include "peloid/real.h" /* PL_PI */
#include "peloid/scene.h"
#include "peloid/srd_theory.h"
#include "peloid/colloid_integrator.h"
#include "sediment_fit.h"

/* mean and SE (blocking) of v[a, b) */
static void mean_se(const double *v, size_t a, size_t b, double *mean, double *se)
{
    pl_blocking_t bl;
    pl_blocking_init(&bl);
    for (size_t k = a; k < b; ++k) pl_blocking_add(&bl, v[k]);
    pl_blocking_result_t r = pl_blocking_result(&bl);
    *mean = r.mean;
    *se = r.se;
}

/* |first half - second half| / combined SE of v[0, n) */
static double drift_z(const double *v, size_t n)
{
    double m1, s1, m2, s2;
    mean_se(v, 0, n / 2, &m1, &s1);
    mean_se(v, n / 2, n, &m2, &s2);
    const double s = sqrt(s1 * s1 + s2 * s2);
    return s > 0 ? fabs(m1 - m2) / s : (m1 == m2 ? 0.0 : INFINITY);
}

int pl_sediment_initial(const double *v, size_t n, pl_sediment_fit_t *out)
{
    enum { MIN_WINDOW = 16, STEP = 8 };
    *out = (pl_sediment_fit_t){.window = 0, .z_whole = n >= 4 ? drift_z(v, n) : NAN};
    if (n < MIN_WINDOW) return -1;
    size_t best = 0;
    double zbest = NAN;
    for (size_t w = MIN_WINDOW; w <= n; w += STEP) {
        const double z = drift_z(v, w);
        if (z < 2.0) {
            best = w;
            zbest = z;
        }
    }
    if (!best) return -1;
    out->window = best;
    out->z_window = zbest;
    mean_se(v, 0, best, &out->value, &out->se);
    return 0;
}

/* ---- summary.json ---------------------------------------------------------- */

/* Stokes velocity of one colloid (Hecht Eq. 16) with the friction the scene
 * gives it: kT / D of the mapping (the calibrated or theory colloid D) for
 * a physical scene, else 6 pi eta R (eta of PL Eqs. 9-15 / Hecht Eq. 28; of
 * colloids.bd_viscosity for Brownian dynamics; none without fluid);
 * and the colloid volume fraction of the box.  Model units. */
static void references(const pl_scene_t *sc, double *v_stokes, double *phi)
{
    const pl_scene_colloids_t *c = &sc->colloids;
    const double R = c->radius, vol = 4.0 / 3.0 * PL_PI * R * R * R, M = c->mass_density * vol;
    const double g = sqrt(c->gravity[0] * c->gravity[0] + c->gravity[1] * c->gravity[1] +
                          c->gravity[2] * c->gravity[2]);
    double xi;
    if (!pl_colloid_integrator(c->integrator)->inertial) { /* the Stokes friction BD uses */
        xi = 6.0 * PL_PI * c->bd_viscosity * R;
    } else if (sc->mapping.enabled) {
        xi = pl_scene_kT(sc) / sc->mapping.map.d_col_sim;
    } else if (sc->fluid.density <= 0) {
        xi = NAN; /* no solvent, no friction to compare with */
    } else {
        pl_srd_theory_t th;
        pl_srd_theory_of(sc, &th);
        xi = 6.0 * PL_PI * th.eta * R;
    }
    *v_stokes = M * g / xi;
    const int *n = sc->box.cells;
    *phi = (double)c->count * vol / ((double)n[0] * n[1] * n[2]);
}

const char *const pl_sediment_entries[] = {"initial_settling_velocity", NULL};

void pl_sediment_summary(pl_json_t *b, json_t *all, const pl_scene_t *sc, const double *v, const long long *step,
                         size_t n)
{
    pl_sediment_fit_t f;
    const int found = pl_sediment_initial(v, n, &f) == 0;
    json_t *whole = json_object_get(all, "settling_velocity");
    if (whole) { /* what the run's mean is, honestly */
        pl_json_str(b, whole, "over", "every sample: the fall and, in a closed vessel, the settled state");
        pl_json_real_or_null(b, whole, "drift_z", f.z_whole);
        if (!(f.z_whole < 2.0)) pl_json_set(b, whole, "plateau", json_false());
    }
    double vs, phi;
    references(sc, &vs, &phi);
    const double to_si = sc->mapping.enabled ? sc->mapping.map.a0 / sc->mapping.map.t0 : NAN;
    json_t *e = json_object();
    if (found) {
        pl_json_real(b, e, "value", f.value);
        pl_json_real(b, e, "stderr", f.se);
        pl_json_int(b, e, "samples", (long long)f.window);
        pl_json_int(b, e, "first_step", step[0]);
        pl_json_int(b, e, "last_step", step[f.window - 1]);
        pl_json_real(b, e, "drift_z", f.z_window);
        pl_json_str(b, e, "unit", "a0/t0");
    } else { /* no value: the references alone, in a0/t0 (and m/s) */
        pl_json_str(b, e, "why_none", n < 16 ? "fewer than 16 samples" : "no homogeneous first stretch of 16 samples");
        pl_json_str(b, e, "reference_unit", "a0/t0");
    }
    pl_json_str(b, e, "meaning", "initial settling speed (down positive) of the colloids' mean height relative to "
                                 "the fluid, over the longest first stretch whose halves agree within 2 SE");
    pl_json_real(b, e, "volume_fraction", phi);
    pl_json_real_or_null(b, e, "stokes", vs);
    /* Richardson & Zaki 1954 for Re < 0.2: (1 - phi)^4.65; Hecht Eq. 37 */
    pl_json_real_or_null(b, e, "richardson_zaki_4.65", vs * pow(1.0 - phi, 4.65));
    pl_json_str(b, e, "positive", "down");
    if (found && vs != 0.0) pl_json_real_or_null(b, e, "over_stokes", f.value / vs);
    if (vs == 0.0) pl_json_str(b, e, "note", "no gravity: no Stokes settling to compare with");
    if (sc->mapping.enabled) {
        if (found) {
            pl_json_real(b, e, "value_m_per_s", f.value * to_si);
            pl_json_real(b, e, "stderr_m_per_s", f.se * to_si);
        }
        pl_json_real_or_null(b, e, "stokes_m_per_s", vs * to_si);
        pl_json_real_or_null(b, e, "richardson_zaki_4.65_m_per_s", vs * pow(1.0 - phi, 4.65) * to_si);
    }
    pl_json_set(b, all, pl_sediment_entries[0], e);
}
