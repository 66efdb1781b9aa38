/* The hydrodynamic radius of the model colloid: the sphere whose classical
 * friction in the model fluid equals the friction the coupling realises.
 *
 * The colloid's friction is xi = kT / D with D its unbounded diffusion
 * coefficient (PL Eq. 54): the calibrated D where a calibration measured it
 * (src/app/calibrate.c), else the coupling's theory (PL Eqs. 39-41).  A
 * sphere of radius R_h in a fluid of shear viscosity eta = rho_f nu (PL Eq.
 * 13, nu of PL Eqs. 9-12 or Hecht Eq. 28) has xi = k pi eta R_h, k = 6 for a
 * stick and 4 for a slip surface (PL Eq. 39), so
 *     R_h = kT / (k pi eta D),
 * with k of the boundary the mapping gives the coupling (the potential
 * coupling is slip, PL Sec. III.B; couplings I and II follow
 * coarse_graining.boundary).  R_h is inversely proportional to D, so its
 * relative standard error is that of the calibrated D.
 *
 * Every many-body hydrodynamic effect (periodic-image and wall corrections,
 * hindered settling, D(phi), lubrication between colloids) has the strength
 * of a sphere of R_h, whatever R the pair forces use: R_h/R away from 1 is a
 * model colloid that is hydrodynamically another sphere than the stated one.
 * Units: a0, t0, m_f, kT_model = 1. */
#include <jansson.h>
#include <math.h>
#include <stdio.h>

#include "peloid/mapping.h"
#include "peloid/real.h" /* PL_PI */

static int slip(const pl_mapping_t *m) { return m->cg.boundary == PL_BOUNDARY_SLIP; }
static int calibrated(const pl_mapping_t *m) { return m->cg.d_col_calibrated > 0; }

void pl_mapping_hydrodynamic_radius(pl_mapping_t *m)
{
    const double eta = m->cg.gamma * m->nu_sim; /* PL Eq. 13, m_f / (a0 t0) */
    const double xi = 1.0 / m->d_col_sim;       /* kT / D, kT = 1 */
    const double k = slip(m) ? 4.0 : 6.0;       /* PL Eq. 39 */
    m->rh_over_R = xi / (k * PL_PI * eta * m->sigma);
    m->rh_stick_over_R = xi / (6.0 * PL_PI * eta * m->sigma);
    m->rh_over_R_se = calibrated(m) ? m->rh_over_R * m->cg.d_col_calibrated_se / m->cg.d_col_calibrated : NAN;
    /* warned beyond the tolerance by more than two standard errors (a
     * calibration that cannot tell is not warned); the theory has no SE */
    const double se = isfinite(m->rh_over_R_se) ? m->rh_over_R_se : 0.0;
    if (fabs(m->rh_over_R - 1.0) - 2.0 * se <= PL_RH_TOL) return;
    char pm[48] = "";
    if (calibrated(m)) snprintf(pm, sizeof pm, " +- %.2g", m->rh_over_R_se);
    pl_mapping_warn(m, PL_SEV_WARNING, "HYDRODYNAMIC_RADIUS", m->rh_over_R,
                    "R_h/R = %.3g%s (%s, %s: R_h = kT / (%g pi eta D)): the model colloid moves fluid like a sphere "
                    "of %.3g R: box corrections, hindered settling and lubrication have that sphere's strength; rule: "
                    "|R_h/R - 1| - 2 SE > %g; the factor follows the coupling and its resolution "
                    "(coarse_graining.coupling, coarse_graining.cell_size, coarse_graining.mean_free_path, "
                    "coarse_graining.particles_per_cell)",
                    m->rh_over_R, pm, calibrated(m) ? "calibration" : "theory", slip(m) ? "slip" : "stick", k,
                    m->rh_over_R, PL_RH_TOL);
}

void pl_mapping_hydro_print(const pl_mapping_t *m, FILE *f)
{
    fprintf(f, "    hydrodynamic radius: R_h = kT / (%d pi eta D) = %.4g", slip(m) ? 4 : 6, m->rh_over_R);
    if (isfinite(m->rh_over_R_se)) fprintf(f, " +- %.2g", m->rh_over_R_se);
    fprintf(f, " R = %.4g m (%s; %s surface, PL Eq. 39, eta = gamma nu = %.4g m_f/(a0 t0))",
            m->rh_over_R * m->real.radius,
            !calibrated(m) ? "theory, from the coupling's friction"
            : m->calib.source == PL_CALSRC_TABLE ? "from the D of the shipped resolution table" : "from the calibrated D",
            slip(m) ? "slip" : "stick", m->cg.gamma * m->nu_sim);
    if (slip(m)) fprintf(f, "; a stick sphere of the same friction: %.4g R", m->rh_stick_over_R);
    if (m->cg.coupling == PL_COUPLE_HECHT2) fprintf(f, "; coupling II colloids are points in the collision, the "
                                                     "surface is the one the mapping assumes");
    fprintf(f, "\n");
}

/* NaN (no SE: theory) as JSON null */
static void set_real(json_t *o, const char *key, double v)
{
    json_object_set_new(o, key, isfinite(v) ? json_real(v) : json_null());
}

void pl_mapping_hydro_json(const pl_mapping_t *m, json_t *o)
{
    set_real(o, "hydrodynamic_radius_over_R", m->rh_over_R);
    set_real(o, "hydrodynamic_radius_over_R_se", m->rh_over_R_se);
    set_real(o, "hydrodynamic_radius_m", m->rh_over_R * m->real.radius);
    set_real(o, "hydrodynamic_radius_stick_over_R", m->rh_stick_over_R);
    json_object_set_new(o, "hydrodynamic_radius_source", json_string(!calibrated(m) ? "theory"
                                                                     : m->calib.source == PL_CALSRC_TABLE ? "table"
                                                                                                           : "calibration"));
    json_object_set_new(o, "hydrodynamic_radius_boundary", json_string(slip(m) ? "slip" : "stick"));
}
