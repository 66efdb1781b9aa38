/* The colloid diffusion coefficient the unit mapping matches (DESIGN.md
 * "Units and mapping": never claim a match that was not verified): where it
 * comes from (a calibration run of the coupling, src/app/calibrate.c, or
 * the coupling's theory, PL Eqs. 39-41), its standard error, how far it is
 * from that theory, and what the scene's own periodic box leaves of it
 * (Hasimoto 1959, PL Eq. 43: D_L = D - 2.837 kT / (6 pi eta L)). */
#include <jansson.h>
#include <math.h>
#include <stdio.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/scene.h"
#include "peloid/srd_theory.h"


double pl_mapping_concentration_c(const struct pl_scene *s)
{
    /* a physical scene: its coarse_graining (the coupling keys are derived after the box) */
    const pl_mapping_t *mp = &s->mapping.map;
    const int ph = s->mapping.enabled;
    const int pot = ph ? mp->cg.coupling == PL_COUPLE_POTENTIAL : s->coupling.method == PL_COUPLE_POTENTIAL;
    const int one = ph ? mp->cg.coupling == PL_COUPLE_HECHT1 : s->coupling.method == PL_COUPLE_HECHT1;
    const int slip = ph ? mp->cg.boundary == PL_BOUNDARY_SLIP : s->coupling.boundary == PL_BOUND_SLIP;
    if (pot || (one && slip)) return 1.1795;
    return one ? 1.8315 : 0.0;
}

void pl_mapping_diffusion_box(struct pl_scene *s)
{
    pl_mapping_t *m = &s->mapping.map;
    m->calib = s->mapping.calib;
    const int *n = s->box.cells;
    m->box_L = cbrt((double)n[0] * n[1] * n[2]);
    m->box_periodic = s->box.walls_z == PL_WALLS_NONE && s->box.walls_xy == PL_WALLS_NONE;
    const double eta = m->cg.gamma * m->nu_sim; /* m_f / (a0 t0), kT = 1 */
    /* finite colloids (the potential coupling, coupling I) slow each other:
     * D (1 - c phi); coupling II's points: 1 */
    m->conc_factor = 1.0 - pl_mapping_concentration_c(s) * s->mapping.colloid.phi_realised;
    m->d_col_box = m->box_periodic ? m->d_col_sim * m->conc_factor - pl_srd_hasimoto_mobility(eta, m->box_L)
                                   : NAN; /* kT = 1 */
}

/* m^2/s per a0^2/t0 */
static double si(const pl_mapping_t *m) { return m->a0 * m->a0 / m->t0; }

static const char *source(const pl_mapping_t *m)
{
    return m->calib.d_inf > 0 ? "calibration"
           : m->calib.source == PL_CALSRC_THEORY ? "theory (PL Eqs. 39-41, --calibrate never)"
                                                 : "theory (PL Eqs. 39-41, not verified)";
}

static const char *const SOURCE_NAMES[] = {[PL_CALSRC_NONE] = "none", [PL_CALSRC_SHIPPED] = "shipped",
                                           [PL_CALSRC_CACHE] = "cache", [PL_CALSRC_RUN] = "calibration run",
                                           [PL_CALSRC_THEORY] = "theory", [PL_CALSRC_TABLE] = "table"};

static const char *source_name(int s)
{
    return s >= 0 && s < (int)(sizeof SOURCE_NAMES / sizeof SOURCE_NAMES[0]) ? SOURCE_NAMES[s] : "?";
}

const char *pl_calibrate_mode_name(int mode)
{
    static const char *const names[PL_CALIBRATE_NMODES] = {[PL_CALIBRATE_AUTO] = "auto", [PL_CALIBRATE_NEVER] = "never",
                                                           [PL_CALIBRATE_ALWAYS] = "always",
                                                           [PL_CALIBRATE_STORED] = "stored"};
    return mode >= 0 && mode < PL_CALIBRATE_NMODES ? names[mode] : "?";
}

double pl_mapping_t0_relative_error(const pl_mapping_t *m)
{
    if (m->cg.srd_dt > 0 || m->cg.match != PL_MATCH_DIFFUSION) return 0.0; /* t0 is not the colloid D's */
    const pl_mapping_calibration_t *c = &m->calib;
    if (c->source == PL_CALSRC_THEORY) return c->theory_error;
    return c->d_inf > 0 ? c->d_inf_se / c->d_inf : 0.0;
}

void pl_mapping_calibration_line(const pl_mapping_t *m, char *buf, size_t n)
{
    const pl_mapping_calibration_t *c = &m->calib;
    if (n) buf[0] = '\0';
    if (c->source == PL_CALSRC_NONE || !n) return;
    if (c->source == PL_CALSRC_THEORY)
        snprintf(buf, n, "calibration: %s: the colloid D is the coupling's theory 1/xi = %.5g "
                 "a0^2/t0, relative error %.2g (RMS of measured/theory - 1 over %d shipped calibration(s) of this "
                 "coupling: measured/theory %.3g..%.3g); t0 and every SI time and rate carry it%s",
                 c->mode == PL_CALIBRATE_STORED ? "--calibrate stored, none stored for this model" : "--calibrate never",
                 m->d_col_sim, c->theory_error, c->theory_files, c->theory_lo, c->theory_hi,
                 c->mode == PL_CALIBRATE_STORED ? "; `peloid run` measures the calibration first (once, cached; "
                                                  "its size and estimated duration printed), --calibrate auto "
                                                  "measures it here" : "");
    else if (c->source == PL_CALSRC_TABLE)
        snprintf(buf, n, "calibration: --calibrate %s: the colloid D from the shipped resolution table %s (coupling I "
                 "in this fluid, R/R_h - 1 = b + c a0/R fitted to R/a0 = %g..%g): R_h/R = %.4g here, D = kT / (6 pi "
                 "eta R_h) = %.5g +- %.2g a0^2/t0 (relative error %.2g, the law's standard error); no calibration "
                 "run (--calibrate always measures it)", pl_calibrate_mode_name(c->mode), c->cache, c->table_R_lo,
                 c->table_R_hi, c->table_rh_over_R, c->d_inf, c->d_inf_se, c->d_inf_se / c->d_inf);
    else
        snprintf(buf, n, "calibration: --calibrate %s: the colloid D measured, %.5g +- %.2g a0^2/t0 (relative "
                 "error %.2g), %s %s", pl_calibrate_mode_name(c->mode), c->d_inf, c->d_inf_se, c->d_inf_se / c->d_inf,
                 c->source == PL_CALSRC_RUN ? "run now, stored in" : "read from the", c->source == PL_CALSRC_RUN
                 ? (c->cache[0] ? c->cache : "nowhere") : c->source == PL_CALSRC_SHIPPED ? "shipped set" : "cache");
}

json_t *pl_mapping_calibration_json(const pl_mapping_t *m)
{
    const pl_mapping_calibration_t *c = &m->calib;
    if (c->source == PL_CALSRC_NONE) return NULL;
    json_t *o = json_object();
    const int th = c->source == PL_CALSRC_THEORY;
    json_object_set_new(o, "mode", json_string(pl_calibrate_mode_name(c->mode)));
    json_object_set_new(o, "source", json_string(source_name(c->source)));
    json_object_set_new(o, "d_a0_2_t0", json_real(m->d_col_sim));
    if (th && !isfinite(c->theory_error)) { /* no shipped calibration of this coupling */
        json_object_set_new(o, "relative_error", json_null());
    } else {
        json_object_set_new(o, "relative_error", json_real(th ? c->theory_error : c->d_inf_se / c->d_inf));
    }
    if (th) {
        json_object_set_new(o, "relative_error_of", json_string("RMS of D_measured / D_theory - 1 over the shipped "
                                                                "calibrations of this coupling"));
        json_object_set_new(o, "shipped_calibrations", json_integer(c->theory_files));
        if (c->theory_files > 0) {
            json_object_set_new(o, "measured_over_theory_min", json_real(c->theory_lo));
            json_object_set_new(o, "measured_over_theory_max", json_real(c->theory_hi));
        }
    } else {
        const int tab = c->source == PL_CALSRC_TABLE;
        json_object_set_new(o, "relative_error_of", json_string(tab ? "standard error of the resolution table's R_h "
                                                                      "at this R/a0 (its law's covariance)"
                                                                    : "standard error of the measured D"));
        json_object_set_new(o, "file", json_string(c->cache));
        json_object_set_new(o, "wall_s", json_real(c->wall_s));
        if (tab) {
            json_object_set_new(o, "table_rh_over_R", json_real(c->table_rh_over_R));
            json_object_set_new(o, "table_R_over_a0_min", json_real(c->table_R_lo));
            json_object_set_new(o, "table_R_over_a0_max", json_real(c->table_R_hi));
        }
    }
    return o;
}

void pl_mapping_diffusion_print(const pl_mapping_t *m, FILE *f)
{
    const pl_mapping_calibration_t *c = &m->calib;
    const double d_real = m->hecht_real.D;
    fprintf(f, "  colloid D: %.5g a0^2/t0 = %.4g m^2/s (%s)", m->d_col_sim, m->d_col_sim * si(m), source(m));
    if (c->d_inf > 0)
        fprintf(f, " +- %.2g (%.1f %%)", c->d_inf_se, 100.0 * c->d_inf_se / c->d_inf);
    fprintf(f, "; real kT/(6 pi eta R) = %.4g m^2/s: model/real = %.4g%s\n", d_real, m->d_col_sim * si(m) / d_real,
            m->cg.match == PL_MATCH_DIFFUSION && m->cg.srd_dt <= 0 ? " (time matched on it)" : "");
    if (c->d_inf > 0 && c->source != PL_CALSRC_TABLE)
        fprintf(f, "    calibration: %d colloid(s) in %d^3 periodic cells (phi %.3g), %lld steps: D_box = %.5g +- %.2g, "
                   "+ %.4g hydrodynamic tail beyond the lags, + %.4g periodic images (Hasimoto); the coupling's theory "
                   "1/xi = %.5g (measured/theory %.3g); %s %s\n",
                c->n_colloids, c->box, c->phi, c->steps, c->d_box, c->d_box_se, c->tail, c->hasimoto, c->d_theory,
                c->d_inf / c->d_theory, c->wall_s > 0 ? "run now, cached in" : "read from", c->cache);
    char line[800];
    pl_mapping_calibration_line(m, line, sizeof line);
    if (line[0]) fprintf(f, "    %s\n", line);
    if (c->d_inf > 0 && c->concentration > 0 && c->concentration != 1.0)
        fprintf(f, "    calibration concentration correction: D_box + images = D (1 - c phi) = D x %.4f, c = %.4f "
                   "(slip spheres 1.1795, PL Sec. VI.C; stick spheres 1.8315, Batchelor 1976)\n",
                c->concentration, c->phi > 0 ? (1.0 - c->concentration) / c->phi : 0.0);
    pl_mapping_hydro_print(m, f);
    if (m->box_periodic)
        fprintf(f, "    in this scene's periodic box (L = %.4g a0) a dilute colloid diffuses with D_L = %.5g a0^2/t0 "
                   "= %.4g m^2/s, %.4g of the real D (periodic images, Hasimoto%s; compare D_L with a measured D)\n",
                m->box_L, m->d_col_box, m->d_col_box * si(m), m->d_col_box / m->d_col_sim,
                m->conc_factor != 1.0 ? ", and the scene's phi: 1 - c phi" : "");
    else
        fprintf(f, "    the scene's box has walls: a measured D is also slowed by them (not corrected here)\n");
}

json_t *pl_mapping_diffusion_json(const pl_mapping_t *m)
{
    const pl_mapping_calibration_t *c = &m->calib;
    json_t *o = json_object();
    json_object_set_new(o, "source", json_string(c->d_inf > 0 ? "calibration" : "theory"));
    json_object_set_new(o, "d_a0_2_t0", json_real(m->d_col_sim));
    json_object_set_new(o, "d_m2_s", json_real(m->d_col_sim * si(m)));
    json_object_set_new(o, "d_real_m2_s", json_real(m->hecht_real.D));
    json_object_set_new(o, "model_over_real", json_real(m->d_col_sim * si(m) / m->hecht_real.D));
    json_object_set_new(o, "d_theory_a0_2_t0", json_real(m->d_col_theory));
    if (c->d_inf > 0) {
        json_t *k = json_object();
        json_object_set_new(k, "d_inf_a0_2_t0", json_real(c->d_inf));
        json_object_set_new(k, "d_inf_se_a0_2_t0", json_real(c->d_inf_se));
        json_object_set_new(k, "d_box_a0_2_t0", json_real(c->d_box));
        json_object_set_new(k, "tail_a0_2_t0", json_real(c->tail));
        json_object_set_new(k, "hasimoto_a0_2_t0", json_real(c->hasimoto));
        json_object_set_new(k, "colloids", json_integer(c->n_colloids));
        json_object_set_new(k, "box_cells", json_integer(c->box));
        json_object_set_new(k, "steps", json_integer(c->steps));
        json_object_set_new(k, "phi", json_real(c->phi));
        json_object_set_new(k, "wall_s", json_real(c->wall_s));
        if (c->concentration != 1.0) json_object_set_new(k, "concentration_factor", json_real(c->concentration));
        json_object_set_new(k, "cache", json_string(c->cache));
        json_object_set_new(o, "calibration", k);
    }
    if (m->box_periodic) {
        json_object_set_new(o, "box_L_a0", json_real(m->box_L));
        json_object_set_new(o, "d_box_a0_2_t0", json_real(m->d_col_box));
        json_object_set_new(o, "d_box_m2_s", json_real(m->d_col_box * si(m)));
        json_object_set_new(o, "box_factor", json_real(m->d_col_box / m->d_col_sim));
        if (m->conc_factor != 1.0) json_object_set_new(o, "concentration_factor", json_real(m->conc_factor));
    } else {
        json_object_set_new(o, "box_note", json_string("walls: not corrected"));
    }
    return o;
}
