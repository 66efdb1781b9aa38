/* The model colloid's hydrodynamic radius and the potential coupling's hard
 * core (issue 45).
 *
 * Hydrodynamic radius: R_h = kT / (k pi eta D), k = 6 stick / 4 slip (PL
 * Eq. 39), checked against a hand computation with eta = gamma (nu_kin +
 * nu_col) from PL Eqs. 9-10 written out here (gamma = 5, lambda = 0.1, alpha
 * = 90 deg: eta = 2.49592 m_f/(a0 t0)), for a known calibrated D with its SE
 * (relative SE of R_h = relative SE of D), the warning rule |R_h/R - 1| - 2
 * SE > 0.05 on both sides of its threshold, and the theory case: the
 * potential coupling's slip + Enskog friction (PL Eqs. 39-41) gives R_h/R =
 * xi_E / (xi_S + xi_E) = 0.680 for sigma_cf = 2 a0, coupling II's Stokes
 * theory exactly 1.  Tolerance 1e-9 relative: the same formulas in another
 * order, rounding only.
 *
 * Hard core: PL's sigma_cc rule at sigma_cf = R, eps = 2.5 kT, n = 24 gives
 * sigma_cc = 2^{7/6} R (Sec. III.C.1), so phi_c = phi 2^{1/2}; DLVO beside
 * that WCA is refused naming the key that switched it on.
 *
 * The hydrodynamic tail of the calibration: see tail_unbounded below. */
#include <jansson.h>
#include <math.h>
#include <string.h>

#include "mapping_testutil.h"

#include "peloid/colloid.h"
#include "peloid/mapping.h"
#include "peloid/scene.h"
#include "peloid/srd_theory.h"

#define REL_EQ(a, b) (fabs((a) / (b) - 1.0) <= 1e-9)

/* PL Eqs. 9-10 at a0 = m_f = kT = 1, dt = lambda, times gamma (PL Eq. 13) */
static double eta_hand(double gamma, double lambda, double alpha)
{
    const double g1 = gamma - 1.0 + exp(-gamma);
    const double nu_kin = 0.5 * lambda * (5.0 * gamma / (g1 * (2.0 - cos(alpha) - cos(2.0 * alpha))) - 1.0);
    const double nu_col = (1.0 - cos(alpha)) / (18.0 * lambda) * g1 / gamma;
    return gamma * (nu_kin + nu_col);
}

static pl_mapping_system_t water_1um(void)
{
    pl_mapping_system_t r = {0};
    r.radius = 1e-6;
    r.rho_p = r.rho_f = 1e3;
    r.nu = 1e-6;
    r.kT = PL_KB * 298.15;
    return r;
}

static pl_mapping_cg_t cg_of(int coupling, int boundary, double d, double d_se)
{
    pl_mapping_cg_t c = {0};
    c.coupling = coupling;
    c.match = PL_MATCH_DIFFUSION;
    c.viscosity = PL_RULE_RANDOM_AXIS; /* PL Eqs. 9-12 */
    c.boundary = boundary;
    c.gamma = 5.0;
    c.lambda = 0.1;
    c.alpha = M_PI / 2;
    c.cell_over_R = 0.5; /* R = 2 a0 */
    c.md_resolution = 20;
    c.d_col_calibrated = d;
    c.d_col_calibrated_se = d_se;
    return c;
}

static const pl_mapping_warning_t *find_warn(const pl_mapping_t *m, const char *name)
{
    for (int i = 0; i < m->nwarn; ++i)
        if (!strcmp(m->warn[i].name, name)) return &m->warn[i];
    return NULL;
}

static void derive(const pl_mapping_cg_t *cg, pl_mapping_t *m)
{
    const pl_mapping_system_t r = water_1um();
    const pl_mapping_solvent_t sv = {0};
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_mapping_derive(&r, &sv, cg, m, &err), 0, "%s", err.msg);
}

/* a calibrated D = 0.02 +- 0.0005 a0^2/t0: stick R_h/R = 1 / (6 pi eta 2 D) = 0.53138, SE 2.5 % of it; slip 1.5x */
Test(hydro, calibrated_stick_and_slip)
{
    static pl_mapping_t m;
    const double eta = eta_hand(5.0, 0.1, M_PI / 2);
    cr_expect(fabs(eta - 2.49592) < 1e-5, "eta = %.8g", eta);
    pl_mapping_cg_t c = cg_of(PL_COUPLE_HECHT2, PL_BOUNDARY_STICK, 0.02, 0.0005);
    derive(&c, &m);
    const double stick = 1.0 / (6.0 * M_PI * eta * 2.0 * 0.02);
    cr_expect(REL_EQ(m.rh_over_R, stick), "R_h/R = %.10g, hand %.10g", m.rh_over_R, stick);
    cr_expect(fabs(stick - 0.53138) < 1e-5, "hand value %.8g", stick);
    cr_expect(REL_EQ(m.rh_over_R_se, stick * 0.025), "SE %.10g, hand %.10g", m.rh_over_R_se, stick * 0.025);
    cr_expect(REL_EQ(m.rh_stick_over_R, stick));
    const pl_mapping_warning_t *w = find_warn(&m, "HYDRODYNAMIC_RADIUS");
    cr_assert(w, "no HYDRODYNAMIC_RADIUS warning at R_h/R = %g", m.rh_over_R);
    cr_expect_eq(w->severity, PL_SEV_WARNING);
    cr_expect(REL_EQ(w->value, stick));
    cr_expect(strstr(w->text, "sphere of 0.531 R") != NULL, "%s", w->text);

    c.boundary = PL_BOUNDARY_SLIP;
    derive(&c, &m);
    cr_expect(REL_EQ(m.rh_over_R, 1.5 * stick), "slip R_h/R = %.10g, hand %.10g", m.rh_over_R, 1.5 * stick);
    cr_expect(REL_EQ(m.rh_stick_over_R, stick), "the stick sphere of the same friction");
    cr_expect(REL_EQ(m.rh_over_R_se, 1.5 * stick * 0.025));
}

/* the rule |R_h/R - 1| - 2 SE > 0.05 on both sides: R_h/R = 1.06 +- 0.01 (0.04: quiet), 1.08 +- 0.01 (0.06:
 * warned), 1.08 +- 0.02 (0.04: quiet), 0.93 +- 0.005 (0.06: warned) */
Test(hydro, warning_rule)
{
    static pl_mapping_t m;
    const double eta = eta_hand(5.0, 0.1, M_PI / 2);
    const struct { double ratio, se; int warned; } cases[] = {
        {1.06, 0.01, 0}, {1.08, 0.01, 1}, {1.08, 0.02, 0}, {0.93, 0.005, 1}, {1.0, 0.0, 0}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        const double d = 1.0 / (6.0 * M_PI * eta * 2.0 * cases[i].ratio); /* the D that gives the ratio */
        pl_mapping_cg_t c = cg_of(PL_COUPLE_HECHT1, PL_BOUNDARY_STICK, d, d * cases[i].se / cases[i].ratio);
        derive(&c, &m);
        cr_expect(REL_EQ(m.rh_over_R, cases[i].ratio), "case %zu: %.10g", i, m.rh_over_R);
        cr_expect(fabs(m.rh_over_R_se - cases[i].se) < 1e-12, "case %zu: SE %.10g", i, m.rh_over_R_se);
        cr_expect_eq(find_warn(&m, "HYDRODYNAMIC_RADIUS") != NULL, cases[i].warned, "case %zu: R_h/R %g +- %g", i,
                     cases[i].ratio, cases[i].se);
    }
}

/* theory (no calibration): the potential coupling's slip Stokes + Enskog in
 * parallel (PL Eqs. 39-41), xi_E = 8/3 sqrt(2 pi mu) gamma sigma^2 (PL Eq. 40,
 * mu = M / (M + 1), M = gamma 4/3 pi sigma^3 neutrally buoyant): R_h/R (slip)
 * = xi_E / (xi_S + xi_E) = 0.680, no SE; coupling II's theory is Stokes: 1 */
Test(hydro, theory)
{
    static pl_mapping_t m;
    const double eta = eta_hand(5.0, 0.1, M_PI / 2);
    pl_mapping_cg_t c = cg_of(PL_COUPLE_POTENTIAL, PL_BOUNDARY_SLIP, 0.0, 0.0);
    c.enskog = 1;
    derive(&c, &m);
    const double M = 5.0 * 4.0 / 3.0 * M_PI * 8.0, mu = M / (M + 1.0);
    const double xi_e = 8.0 / 3.0 * sqrt(2.0 * M_PI * mu) * 5.0 * 4.0, xi_s = 4.0 * M_PI * eta * 2.0;
    const double hand = xi_e / (xi_s + xi_e);
    cr_expect(fabs(hand - 0.680) < 5e-4, "hand %.6g", hand);
    cr_expect(REL_EQ(m.rh_over_R, hand), "theory R_h/R = %.10g, hand %.10g", m.rh_over_R, hand);
    cr_expect(isnan(m.rh_over_R_se), "theory has no SE: %g", m.rh_over_R_se);
    const pl_mapping_warning_t *w = find_warn(&m, "HYDRODYNAMIC_RADIUS");
    cr_assert(w, "theory 0.68 not warned");
    cr_expect(strstr(w->text, "theory") && strstr(w->text, "slip"), "%s", w->text);

    c = cg_of(PL_COUPLE_HECHT2, PL_BOUNDARY_STICK, 0.0, 0.0);
    derive(&c, &m);
    cr_expect(REL_EQ(m.rh_over_R, 1.0), "coupling II Stokes theory: %.12g", m.rh_over_R);
    cr_expect(find_warn(&m, "HYDRODYNAMIC_RADIUS") == NULL);
}

/* The scene path: a calibration handed to the loader reaches R_h with its SE
 * (scenes/pl_potential_physical.cfg, slip), and params --json carries it and
 * the hard core; without one, the theory is marked */
Test(hydro, scene_report)
{
    static pl_scene_t scene;
    pl_err_t err = {0, ""};
    pl_mapping_calibration_t cal = {0};
    cal.d_inf = 0.019957;
    cal.d_inf_se = 0.0011;
    cr_assert_eq(pl_scene_load_calibrated("scenes/pl_potential_physical.cfg", 0, &cal, &scene, &err), 0, "%s",
                 err.msg);
    const pl_mapping_t *m = &scene.mapping.map;
    const double eta = eta_hand(5.0, 0.1, M_PI / 2);
    const double hand = 1.0 / (4.0 * M_PI * eta * 2.0 * 0.019957);
    cr_expect(REL_EQ(m->rh_over_R, hand), "R_h/R %.10g, hand %.10g", m->rh_over_R, hand);
    cr_expect(REL_EQ(m->rh_over_R_se, hand * 0.0011 / 0.019957), "SE %.10g", m->rh_over_R_se);
    json_t *doc = NULL;
    cr_assert_eq(pl_mapping_report_json(&scene, &doc, &err), 0, "%s", err.msg);
    json_t *col = json_object_get(doc, "colloid");
    cr_expect(REL_EQ(json_real_value(json_object_get(col, "hydrodynamic_radius_over_R")), hand));
    cr_expect(REL_EQ(json_real_value(json_object_get(col, "hydrodynamic_radius_over_R_se")), hand * 0.0011 / 0.019957));
    cr_expect(REL_EQ(json_real_value(json_object_get(col, "hydrodynamic_radius_m")), hand * 1e-6));
    cr_expect_str_eq(json_string_value(json_object_get(col, "hydrodynamic_radius_source")), "calibration");
    cr_expect_str_eq(json_string_value(json_object_get(col, "hydrodynamic_radius_boundary")), "slip");
    cr_expect(REL_EQ(json_real_value(json_object_get(col, "volume_fraction_hard_core")),
                     scene.mapping.colloid.phi_realised * sqrt(2.0)));
    json_decref(doc);

    cr_assert_eq(pl_scene_load("scenes/pl_potential_physical.cfg", &scene, &err), 0, "%s", err.msg);
    cr_assert_eq(pl_mapping_report_json(&scene, &doc, &err), 0, "%s", err.msg);
    col = json_object_get(doc, "colloid");
    cr_expect_str_eq(json_string_value(json_object_get(col, "hydrodynamic_radius_source")), "theory");
    cr_expect(json_is_null(json_object_get(col, "hydrodynamic_radius_over_R_se")), "theory: SE null");
    json_decref(doc);
}

/* PL's sigma_cc rule at sigma_cf = R = 2 a0: sigma_cc = 2 2^{1/6} sigma_cf (1/2 + sqrt(2.5 / 10))^{1/24} =
 * 2^{7/6} R, hard-core radius 2^{1/6} R, phi_c = 2^{1/2} phi: 0.1406 for scenes/pl_potential_physical.cfg
 * (41 colloids, phi 0.099387), warned HARD_CORE_PHI */
Test(hydro, potential_hard_core)
{
    static pl_scene_t scene;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_scene_load("scenes/pl_potential_physical.cfg", &scene, &err), 0, "%s", err.msg);
    const pl_mapping_colloid_t *c = &scene.mapping.colloid;
    cr_expect(REL_EQ(c->core_radius, 2.0 * pow(2.0, 1.0 / 6.0)), "core %.10g a0", c->core_radius);
    cr_expect(REL_EQ(c->phi_core, c->phi_realised * sqrt(2.0)), "phi_c %.10g", c->phi_core);
    cr_expect(fabs(c->phi_core - 0.1406) < 1e-4, "phi_c %.6g", c->phi_core);
    const pl_mapping_warning_t *w = find_warn(&scene.mapping.map, "HARD_CORE_PHI");
    cr_assert(w, "no HARD_CORE_PHI warning");
    cr_expect(strstr(w->text, "1.122 R") != NULL, "%s", w->text);
}

/* DLVO with the potential coupling (issue 45): never a silently resized
 * colloid.  Derived (colloids.pairs not given): "dlvo, hertz,
 * depletion_comp", the contact at 2R and PL's compensating depletion
 * potential (PL Sec. III.C.1), so the hard core is R and phi_c = phi, no
 * HARD_CORE_PHI warning; Hertz then needs the material constants (refused
 * naming physical.young_modulus without them).  Given with the wca term
 * ("dlvo, wca"): refused naming colloids.pairs, the coupling, sigma_cc and
 * the derived alternative. */
Test(hydro, potential_dlvo_derived_or_refused)
{
    static pl_scene_t scene;
    const char *base = "physical: { radius = 1.0e-6; volume_fraction = 0.02; box = [12.0e-6, 12.0e-6, 12.0e-6];\n"
                       "  hamaker = 1.0e-20; surface_potential = 0.05; ionic_strength = 0.001;%s };\n"
                       "coarse_graining: { coupling = \"potential\"; };\n%s";
    const char *material = " young_modulus = 3.4e9; poisson_ratio = 0.35;";
    char text[1024];
    pl_err_t err = {0, ""};
    snprintf(text, sizeof text, base, material, "");
    cr_assert_eq(pl_scene_load_string(text, "pd.cfg", &scene, &err), 0, "%s", err.msg);
    unsigned mask = 0;
    char bad[64];
    cr_assert_eq(pl_colloid_parse_pairs(scene.colloids.pairs, &mask, bad, sizeof bad), 0, "%s", scene.colloids.pairs);
    cr_expect_eq(mask, PL_CT_DLVO | PL_CT_HERTZ | PL_CT_DEPL, "pairs \"%s\"", scene.colloids.pairs);
    const pl_mapping_colloid_t *c = &scene.mapping.colloid;
    cr_expect(REL_EQ(c->core_radius, scene.mapping.map.sigma), "core %.10g a0, R %.10g a0", c->core_radius,
              scene.mapping.map.sigma);
    cr_expect(REL_EQ(c->phi_core, c->phi_realised), "phi_c %.10g, phi %.10g", c->phi_core, c->phi_realised);
    cr_expect(find_warn(&scene.mapping.map, "HARD_CORE_PHI") == NULL, "HARD_CORE_PHI warned");

    /* the material constants missing: refused, naming them */
    err = (pl_err_t){0, ""};
    snprintf(text, sizeof text, base, "", "");
    cr_expect_eq(pl_scene_load_string(text, "pm.cfg", &scene, &err), PL_ERR_INPUT, "accepted: %s", text);
    cr_expect(strstr(err.msg, "pm.cfg:") && strstr(err.msg, "physical.young_modulus"), "%s", err.msg);

    /* the wca term given beside DLVO: refused */
    err = (pl_err_t){0, ""};
    snprintf(text, sizeof text, base, material, "colloids: { pairs = \"dlvo, wca\"; };\n");
    cr_expect_eq(pl_scene_load_string(text, "pw.cfg", &scene, &err), PL_ERR_INPUT, "accepted: %s", text);
    cr_expect(strstr(err.msg, "pw.cfg:") && strstr(err.msg, "key 'colloids.pairs'") &&
                  strstr(err.msg, "sigma_cc = 2.245 R") && strstr(err.msg, "coarse_graining.coupling = \"potential\"") &&
                  strstr(err.msg, "dlvo, hertz, depletion_comp"),
              "%s", err.msg);
    /* without DLVO the same suspension loads with PL's wca core */
    err = (pl_err_t){0, ""};
    cr_expect_eq(pl_scene_load_string("physical: { radius = 1.0e-6; volume_fraction = 0.02; box = [12.0e-6, 12.0e-6, "
                                      "12.0e-6]; };\ncoarse_graining: { coupling = \"potential\"; };\n",
                                      "p.cfg", &scene, &err),
                 0, "%s", err.msg);
    cr_expect_str_eq(scene.colloids.pairs, "wca");
}

/* The hydrodynamic tail a calibration's MSD slope misses in its periodic box
 * (pl_srd_tail_missed, src/app/calibrate.c).  Independent of its lattice
 * sum: (1) where the box is much wider than the fluid's diffusion length
 * sqrt(a t2), the unbounded tail (2/3)(kT/rho)(4 pi a)^-3/2 4 / (sqrt t1 +
 * sqrt t2) exceeds it by the box's cut-off, which is Hasimoto's periodic
 * images' share kT 2.837297 / (6 pi rho a L) (a = nu: eta = rho a), up to
 * O(a t / L^2): Richardson's (4 c(2L) - c(L)) / 3 of c = (unbounded - box) 6
 * pi rho a L / kT is 2.837297 to 1e-3 (measured 2.8373 at L = 16, 32; the
 * O(L^-2) term 3 % at L = 16); a factor 2/3 -> 1 (all three polarisations),
 * a lost k = 0 exclusion or a wrong k spacing misses by far more.  (2) Once
 * every mode has decayed (t1 = 40 L^2 / (4 pi^2 a)) nothing is missed (below
 * 1e-12 of the t1 = 1 value), and the tail is linear in kT / rho. */
static double tail_unbounded(double a, double t1, double t2)
{
    return 2.0 / 3.0 * pow(4.0 * M_PI * a, -1.5) * 4.0 / (sqrt(t1) + sqrt(t2));
}

Test(hydro, tail_is_hasimoto_in_a_wide_box)
{
    const double a = 1.0, t1 = 1.0, t2 = 3.0, H = 2.837297;
    double c[2];
    for (int k = 0; k < 2; ++k) {
        const double L = 32.0 * (k + 1);
        c[k] = (tail_unbounded(a, t1, t2) - pl_srd_tail_missed(1.0, 1.0, a, L, t1, t2)) * 6.0 * M_PI * a * L;
    }
    const double rich = (4.0 * c[1] - c[0]) / 3.0;
    cr_expect(fabs(rich / H - 1.0) < 1e-3, "Richardson limit %.6f (L 32: %.6f, L 64: %.6f) vs Hasimoto %.6f", rich,
              c[0], c[1], H);
}

Test(hydro, tail_decays_and_scales)
{
    const double L = 16.0, a = 0.5, late = 40.0 * L * L / (4.0 * M_PI * M_PI * a);
    const double t = pl_srd_tail_missed(1.0, 10.0, a, L, 1.0, 3.0);
    cr_expect(t > 0.0);
    cr_expect(pl_srd_tail_missed(1.0, 10.0, a, L, late, 3.0 * late) < 1e-12 * t);
    cr_expect(REL_EQ(pl_srd_tail_missed(2.0, 5.0, a, L, 1.0, 3.0), 4.0 * t));
    cr_expect_eq(pl_srd_tail_missed(1.0, 10.0, a, L, 3.0, 1.0), 0.0); /* t2 <= t1: none */
}
