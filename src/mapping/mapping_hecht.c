/* Hecht Sec. VI time scales and the Sec. VII derivation of the simulation
 * parameters (cell size, SRD step from the Einstein relation with the SRD
 * viscosity, model gravity, energy scale, MD step), generalised to the PL
 * choices (rotation rule, Enskog friction, kinematic-time matching).
 *
 * Hecht Eqs. 16-27 (time scales), 28-31 (coupling I/II parameters),
 * Lambda = rho/kT argument (Sec. VII.B); PL Sec. VII examples 1-3. */
#include <math.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/mapping.h"

void pl_mapping_hecht_times(const pl_mapping_system_t *s, pl_mapping_hecht_times_t *t)
{
    double R = s->radius;
    double eta = s->nu * s->rho_f;
    t->mass = 4.0 / 3.0 * PL_PI * R * R * R * s->rho_p;
    /* Stokes velocity, Hecht Eq. 16; without buoyancy (model, Eq. 31) the
     * force is m g instead of (m - m_w) g. */
    double drho = s->buoyancy ? s->rho_p - s->rho_f : s->rho_p;
    t->v_s = s->g > 0 ? 2.0 / 9.0 * R * R * s->g * drho / eta : NAN;
    t->D = s->kT / (6.0 * PL_PI * eta * R);                 /* Hecht Eq. 18 */
    t->tau_S = s->g > 0 && drho != 0 ? 2.0 * R / t->v_s : NAN; /* Hecht Eq. 17 */
    t->tau_D = 2.0 * R * R / t->D;                         /* Hecht Eq. 20 */
    t->tau_G = t->tau_D / 16.0;                            /* Hecht Sec. VI, gap R/2 */
    t->tau_P = 2.0 * R * R * s->rho_p / (9.0 * s->nu * s->rho_f); /* Hecht Eq. 23 */
    t->tau_F = 2.0 * R * R / s->nu;                        /* Hecht Eq. 24 */
    t->tau_V = s->hamaker > 0 && s->l_min > 0
                   ? 2.0 * PL_PI * sqrt(t->mass * s->l_min * s->l_min / s->hamaker) /* Hecht Eq. 26 */
                   : NAN;
    t->Pe = t->tau_D / t->tau_S; /* Hecht Eq. 21 */
    t->Re = t->tau_F / t->tau_S; /* Hecht Eq. 25 */
}

static int bad(pl_err_t *err, const char *what, double v)
{
    return pl_err_set(err, PL_ERR_INPUT, "mapping: %s (got %g)", what, v);
}

static int check_inputs(const pl_mapping_system_t *r, const pl_mapping_cg_t *cg, pl_err_t *err)
{
    if (!(r->radius > 0)) return bad(err, "particle radius must be > 0 m", r->radius);
    if (!(r->rho_p > 0)) return bad(err, "particle mass density must be > 0 kg/m^3", r->rho_p);
    if (!(r->rho_f > 0)) return bad(err, "solvent mass density must be > 0 kg/m^3", r->rho_f);
    if (!(r->nu > 0)) return bad(err, "solvent kinematic viscosity must be > 0 m^2/s", r->nu);
    if (!(r->kT > 0)) return bad(err, "temperature must be > 0 K", r->kT);
    if (r->g < 0) return bad(err, "gravity must be >= 0 m/s^2 (it points along -z)", r->g);
    if (!(cg->gamma > 1)) return bad(err, "particles per cell must be > 1 (the SRD formulas diverge at 1)", cg->gamma);
    if (!(cg->lambda > 0)) return bad(err, "mean free path lambda/a0 must be > 0", cg->lambda);
    if (!(cg->cell_over_R > 0)) return bad(err, "cell size a0/R must be > 0", cg->cell_over_R);
    if (r->g > 0 && r->rho_p < r->rho_f)
        return pl_err_set(err, PL_ERR_INPUT,
                          "mapping: particle density %g < solvent density %g kg/m^3 with gravity %g m/s^2: "
                          "the colloids would cream, not sediment (Hecht Eq. 16 gives v_S < 0 and Eq. 31 "
                          "a negative model gravity); fix the densities or set gravity = 0",
                          r->rho_p, r->rho_f, r->g);
    return 0;
}

/* t0 from the chosen matching (or the SRD step given in seconds). */
/* t0; *D_matched: the real D it matches the model colloid's D to (0 when
 * t0 comes from elsewhere) */
static double time_unit(const pl_mapping_system_t *r, const pl_mapping_cg_t *cg, const pl_mapping_t *m,
                        double *D_matched)
{
    *D_matched = 0.0;
    if (cg->srd_dt > 0) return cg->srd_dt / cg->lambda; /* PL Eq. 4 */
    if (cg->match == PL_MATCH_KINEMATIC) {
        /* PL example 2: tau_nu = R^2/nu equal in model and reality. */
        return m->a0 * m->a0 * m->nu_sim / r->nu;
    }
    /* Hecht Eq. 30 / PL example 1: the colloid diffusion coefficient (hence
     * tau_D and, with the same R, Pe) equals the real one (Hecht Eq. 18). */
    *D_matched = r->kT / (6.0 * PL_PI * r->nu * r->rho_f * r->radius);
    return m->d_col_sim * m->a0 * m->a0 / *D_matched;
}

static void md_step(pl_mapping_t *m)
{
    double dt_md = m->cg.md_dt;
    if (!(dt_md > 0)) {
        /* Shortest colloid time of the model (Hecht Eq. 26, Eq. 23), resolved
         * by md_resolution steps (Hecht Sec. II: ~20 steps per collision). */
        double shortest = m->hecht_model.tau_P;
        if (isfinite(m->hecht_model.tau_V) && m->hecht_model.tau_V < shortest) shortest = m->hecht_model.tau_V;
        double res = m->cg.md_resolution > 0 ? m->cg.md_resolution : 20.0;
        dt_md = shortest / res;
    }
    /* Integer substeps: a given MD step is rounded to the nearest divisor of
     * dt; a derived one is never coarser than the resolution asks. */
    double n = m->cg.md_dt > 0 ? floor(m->dt / dt_md + 0.5) : ceil(m->dt / dt_md - 1e-9);
    if (n < 1) n = 1;
    m->md_substeps = (long long)n;
    m->md_dt = m->dt / n;
}

int pl_mapping_derive(const pl_mapping_system_t *real, const pl_mapping_solvent_t *solvent,
                      const pl_mapping_cg_t *cg, pl_mapping_t *m, pl_err_t *err)
{
    if (check_inputs(real, cg, err)) return PL_ERR_INPUT;
    *m = (pl_mapping_t){0};
    m->real = *real;
    m->cg = *cg;
    m->solvent = *solvent;
    const double R = real->radius;

    /* Cell size: Hecht Sec. VII.B (a = R/2, coupling I) / VII.C (cell volume
     * ~ colloid volume, coupling II); here a0 = (a0/R) R. */
    m->a0 = cg->cell_over_R * R;
    /* Solvent mass density kept: rho_f = gamma m_f / a0^3 (Hecht Sec. VII.B). */
    m->m_f = real->rho_f * m->a0 * m->a0 * m->a0 / cg->gamma;

    /* Real velocity: Stokes (Hecht Eq. 16) under gravity, else the flow. */
    pl_mapping_hecht_times(real, &m->hecht_real);
    double v_real = isfinite(m->hecht_real.tau_S) ? m->hecht_real.v_s : solvent->flow_velocity;

    /* Colloid in simulation units (no t0 needed yet: PL Eqs. 9-12, 39-41). */
    m->sigma = R / m->a0;
    pl_mapping_pl_colloid(m->sigma, real->rho_p / real->rho_f, 0.0, cg, m);

    double D_matched;
    double t0 = time_unit(real, cg, m, &D_matched);
    m->t0 = t0;
    m->dt = cg->lambda * t0;                  /* PL Eq. 4 */
    m->nu_coeff = m->nu_sim * cg->lambda;     /* nu dt / a0^2, Hecht Eq. 29 */
    m->kT_model = m->m_f * m->a0 * m->a0 / (t0 * t0); /* kT = m_f (lambda a0/dt)^2 */
    m->energy_scale = real->kT / m->kT_model;
    m->lambda_real = real->rho_p / real->kT;  /* Hecht's Lambda */
    m->lambda_model = real->rho_p / m->kT_model;

    /* The model expressed in SI. */
    pl_mapping_system_t *mo = &m->model;
    *mo = *real;
    mo->nu = m->nu_sim * m->a0 * m->a0 / t0;
    mo->kT = m->kT_model;
    /* Gravity: the model colloid settles at the real Stokes velocity (Hecht
     * Eq. 16) with the friction the coupling realises, xi = kT / D (the
     * calibrated D, else the theory's 1 / xi_sim), not 6 pi eta_model R:
     * g_model = v_S xi / M_eff.  Hecht Eq. 31: no gravity on the fluid, hence
     * no buoyancy, M_eff = M; with gravity on the fluid M_eff = M - M_f. */
    mo->buoyancy = cg->fluid_gravity ? 1 : 0;
    const double m_eff = cg->fluid_gravity ? 1.0 - real->rho_f / real->rho_p : 1.0; /* M_eff / M */
    if (real->g > 0 && isfinite(m->hecht_real.v_s)) {
        const double xi = m->kT_model / (m->d_col_sim * m->a0 * m->a0 / t0); /* kg/s */
        const double mass = m->mass_sim * m->m_f * m_eff;
        mo->g = m->hecht_real.v_s * xi / mass;
    } else {
        mo->g = 0.0;
    }
    mo->hamaker = real->hamaker / m->energy_scale; /* A_H / kT kept (Sec. VII.B) */
    pl_mapping_hecht_times(mo, &m->hecht_model);
    /* The model colloid's friction is the coupling's (kT / D), not Stokes'
     * with the model viscosity: its D, relaxation and settling follow from
     * it (Hecht Eqs. 16-23 with xi = kT / D). */
    pl_mapping_hecht_times_t *h = &m->hecht_model;
    h->D = m->d_col_sim * m->a0 * m->a0 / t0;
    h->tau_D = 2.0 * R * R / h->D;                          /* Hecht Eq. 20 */
    h->tau_G = h->tau_D / 16.0;
    h->tau_P = m->mass_sim * m->m_f * h->D / m->kT_model;  /* M / xi (Hecht Eq. 23 with xi = kT / D) */
    if (mo->g > 0) {
        h->v_s = m->hecht_real.v_s;                         /* by the choice of g above */
        h->tau_S = 2.0 * R / h->v_s;                        /* Hecht Eq. 17 */
    }
    h->Pe = h->tau_D / h->tau_S;
    /* In model units g = v_S xi / M_eff = v_sim / (D_sim M_eff) (kT = 1).
     * With t0 matched on D (Hecht Eq. 30), v_sim / D_sim = v_S a0 / D_real:
     * the model gravity does not depend on the calibrated D, and computed
     * so it keeps every bit when only the calibration changes (a restart
     * with another srd.grid_shift does not see colloids.gravity change by
     * the rounding of a t0 round trip). */
    if (mo->g > 0 && D_matched > 0) {
        m->g_sim = m->hecht_real.v_s * m->a0 / (D_matched * m->mass_sim * m_eff);
    } else {
        m->g_sim = mo->g * t0 * t0 / m->a0;
    }

    double v_model = isfinite(m->hecht_model.tau_S) ? m->hecht_model.v_s : solvent->flow_velocity;
    m->v_sim = v_model * t0 / m->a0;
    /* Numbers and PL times of the model now that v is known (t0 units -> s). */
    pl_mapping_pl_colloid(m->sigma, real->rho_p / real->rho_f, m->v_sim, cg, m);
    pl_mapping_pl_times_t *p = &m->pl_model;
    p->t_cs *= t0;
    p->tau_nu *= t0;
    p->tau_B *= t0;
    p->tau_E *= t0;
    p->tau_D *= t0;
    p->t_S *= t0;
    pl_mapping_pl_real(real, solvent, v_real, PL_BOUNDARY_STICK, &m->pl_real, &m->num_real);

    md_step(m);
    pl_mapping_audit(m);
    pl_mapping_hydrodynamic_radius(m);
    return 0;
}

double pl_mapping_hertz_K(double E, double nu_p, double R)
{
    double Es = E / (2.0 * (1.0 - nu_p * nu_p));
    return 8.0 / 15.0 * Es * sqrt(0.5 * R);
}
