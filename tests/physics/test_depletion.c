/* Depletion potential of the ideal SRD fluid (PL Sec. III.C.1, Eqs. 22-24),
 * PL's sigma_cc rule and the depletion_comp pair term.
 *
 * - Hard colloid-fluid spheres: the quadrature of PL Eqs. 22-23 equals the
 *   closed form PL Eq. 24 (the lens volume) to 1e-9.
 * - PL Eq. 17 (WCA, n = 6), sigma_cf = 2, eps_cf = 2.5 kT, gamma = 5 (PL's
 *   parameters): values against an independent quadrature in cylindrical
 *   coordinates (tools/depletion_reference.py, scipy dblquad), 1e-7.
 * - PL Fig. 3 (depletion potential vs d / sigma_cf, HS and WCA): the stored
 *   text of the paper has the caption but not the curves' numbers, so the
 *   shape is checked: both attractive and monotonic, the HS curve zero from
 *   2 sigma_cf, the WCA curve reaching to 2^{7/6} sigma_cf and deeper than
 *   HS everywhere (its exclusion starts outside sigma_cf); for steeper
 *   colloid-fluid walls (exponent n -> inf) the WCA curve tends to HS as 1/n.
 * - dPhi/dd against a central difference; the table's cubic Hermite
 *   interpolation within 2e-5 kT (value) and 5e-5 kT/a0 (force) where
 *   colloids can be; the force kernel's depletion_comp term
 *   against the quadrature for two colloids.
 * - PL's rule: phi_cc(2 x 2^{1/6} sigma_cf) = 2.5 kT for the derived sigma_cc. */
#include <gsl/gsl_errno.h>
#include <math.h>

#include "peloid/colloid.h"
#include "peloid/colloid_pair.h"
#include "peloid/depletion.h"
#include "support.h"

static pl_depletion_params_t pl_params(void)
{
    pl_depletion_params_t p = {2.0, 2.5, 6.0, 0, 5.0, 1.0};
    return p;
}

static double phi_of(const pl_depletion_params_t *p, double d, double *dphi)
{
    pl_err_t err = {0, ""};
    double phi, dd;
    cr_assert_eq(pl_depletion_potential(p, d, &phi, &dd, &err), 0, "%s", err.msg);
    if (dphi) *dphi = dd;
    return phi;
}

Test(depletion, hard_sphere_is_eq24)
{
    pl_depletion_params_t p = pl_params();
    p.hard_sphere = 1;
    for (double d = 0.0; d <= 4.2; d += 0.15) {
        double q = phi_of(&p, d, NULL), ref = pl_depletion_hs(2.0, 5.0, 1.0, d);
        cr_expect(fabs(q - ref) <= 1e-9 * 167.6, "d = %g: quadrature %.12g vs PL Eq. 24 %.12g", d, q, ref);
    }
    /* Eq. 24 itself: the full sphere at d = 0, zero at contact 2 sigma_cf */
    cr_expect(fabs(pl_depletion_hs(2.0, 5.0, 1.0, 0.0) + 5.0 * 4.0 / 3.0 * M_PI * 8.0) < 1e-12);
    cr_expect(fabs(pl_depletion_hs(2.0, 5.0, 1.0, 4.0 - 1e-12)) < 1e-9);
}

/* tools/depletion_reference.py (sigma_cf 2, eps_cf 2.5 kT, gamma 5, kT 1) */
Test(depletion, wca_matches_independent_reference)
{
    static const double ref[][2] = {
        {0.0, -182.1084746}, {1.0, -124.0974651}, {2.0, -64.77236055}, {3.0, -20.96861425},
        {3.5, -7.391603204}, {3.9, -1.425950336}, {4.0, -0.6795596477}, {4.1, -0.2364114737},
        {4.2, -0.04856256386}, {4.3, -0.003978937113}, {4.4, -3.99194528e-05},
    };
    pl_depletion_params_t p = pl_params();
    for (size_t k = 0; k < sizeof ref / sizeof ref[0]; ++k) {
        double q = phi_of(&p, ref[k][0], NULL);
        cr_expect(fabs(q - ref[k][1]) <= 1e-7 * fabs(ref[k][1]) + 1e-12,
                  "d = %g: %.10g vs reference %.10g", ref[k][0], q, ref[k][1]);
    }
}

Test(depletion, fig3_shape_and_hs_limit)
{
    pl_depletion_params_t p = pl_params();
    double rc = pl_depletion_cf_cutoff(&p);
    cr_expect(fabs(rc - pow(2.0, 1.0 / 6.0) * 2.0) < 1e-14);
    double prev = -INFINITY;
    for (double d = 0.0; d < 2.0 * rc; d += 0.05) {
        double w = phi_of(&p, d, NULL), hs = pl_depletion_hs(2.0, 5.0, 1.0, d);
        cr_expect(w < 0.0 && w > prev, "d = %g: WCA depletion %.6g not attractive and increasing", d, w);
        cr_expect(w < hs, "d = %g: WCA %.6g not below HS %.6g", d, w, hs);
        prev = w;
    }
    cr_expect(phi_of(&p, 4.2, NULL) < -0.04, "no WCA tail beyond 2 sigma_cf");
    cr_expect_eq(phi_of(&p, 2.0 * rc, NULL), 0.0);
    cr_expect_eq(phi_of(&p, 2.0 * rc + 1.0, NULL), 0.0);
    /* steeper colloid-fluid walls: 4 sigma^n terms -> hard spheres, deviation ~ 1/n */
    double dev_prev = 1.0;
    for (double n = 24.0; n <= 192.0; n *= 2.0) {
        p.n = n;
        double dev = fabs(phi_of(&p, 2.0, NULL) / pl_depletion_hs(2.0, 5.0, 1.0, 2.0) - 1.0);
        cr_expect(dev < dev_prev * 0.6 && dev > dev_prev * 0.4 - 1.0 * (n == 24.0),
                  "n = %g: relative deviation from HS %.4g (previous %.4g) not ~halved", n, dev, dev_prev);
        dev_prev = dev;
    }
    cr_expect(dev_prev < 0.01, "n = 192: %.4g from HS", dev_prev);
}

Test(depletion, derivative_and_table)
{
    pl_depletion_params_t p = pl_params();
    for (double d = 0.3; d < 4.45; d += 0.37) {
        double dphi, h = 1e-4;
        phi_of(&p, d, &dphi);
        double fd = (phi_of(&p, d + h, NULL) - phi_of(&p, d - h, NULL)) / (2.0 * h);
        cr_expect(fabs(dphi - fd) < 1e-6 * (1.0 + fabs(fd)), "d = %g: dPhi/dd %.10g vs %.10g", d, dphi, fd);
    }
    enum { M = PL_COLLOID_DEPL_TABLE };
    static double u[M + 2], du[M + 2];
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_depletion_table(&p, M, u, du, &err), 0, "%s", err.msg);
    double dm = 2.0 * pl_depletion_cf_cutoff(&p), h = dm / M, worst = 0.0, worstf = 0.0;
    /* from d_match / 4 on: closer colloids are far inside the colloid-colloid
     * core (phi_cc > 1e10 kT); near d = 0 the slope error reaches 7e-4 */
    for (int k = M / 4; k < M; ++k) {
        double r = (k + 0.37) * h, dphi, v, f, k2;
        double phi = phi_of(&p, r, &dphi);
        pl_depletion_table_eval(u, du, 1.0 / h, r, &v, &f, &k2);
        worst = fmax(worst, fabs(v + phi)); /* Phi_comp = -Phi_depl */
        worstf = fmax(worstf, fabs(f - dphi)); /* force -dPhi_comp/dr = dPhi_depl/dd */
    }
    cr_expect(worst < 2e-5, "table value error %.3g kT", worst);
    cr_expect(worstf < 5e-5, "table force error %.3g kT/a0", worstf);
}

Test(depletion, sigma_cc_rule)
{
    double dm = 2.0 * pow(2.0, 1.0 / 6.0) * 2.0;
    /* eps_cc = 2.5 kT: phi_cc(sigma) = eps exactly, so sigma_cc = d_match */
    cr_expect(fabs(pl_depletion_sigma_cc(dm, 2.5, 24.0, 2.5) - dm) < 1e-12);
    for (double eps = 0.5; eps < 20.0; eps *= 2.0)
        for (double n = 6.0; n <= 48.0; n *= 2.0) {
            double s = pl_depletion_sigma_cc(dm, eps, n, 2.5);
            pl_pair_val_t v = pl_pair_wca(dm, s, eps, n);
            cr_expect(fabs(v.u - 2.5) < 1e-10 && dm < pow(2.0, 1.0 / n) * s,
                      "eps %g n %g: phi_cc(d_match) = %.12g", eps, n, v.u);
        }
}

static const char *SCENE =
    "box: { cells = [12, 12, 12]; };\n"
    "fluid: { density = 5.0; };\n"
    "colloids: { count = 2; radius = 2.0; pairs = \"%s\"; };\n"
    "wca: { epsilon = 2.5; n = 24.0; %s };\n"
    "coupling: { method = \"%s\"; sigma_cf = 2.0; };\n";

Test(depletion, scene_rule_and_kernel_term)
{
    gsl_set_error_handler_off();
    char text[1024];
    snprintf(text, sizeof text, SCENE, "wca, depletion_comp", "sigma_rule = \"pl\";", "potential");
    pl_sim_t *sim = pl_test_sim(text, 1);
    pl_colloid_t *c = sim->colloids;
    double dm = 2.0 * pow(2.0, 1.0 / 6.0) * 2.0;
    cr_expect(fabs(c->pair.wca_sigma - dm) < 1e-12, "sigma_cc %.12g", c->pair.wca_sigma);
    cr_expect(fabs(c->depl.phi_match - 2.5) < 1e-12 && c->depl.table_n == PL_COLLOID_DEPL_TABLE);
    pl_depletion_params_t p = pl_params();
    /* two colloids along x at distance r: the kernel's depletion_comp force
     * and energy against the quadrature (wca off beyond 2^{1/24} sigma_cc) */
    for (double r = 3.0; r < 4.6; r += 0.29) {
        c->x[0] = 3.0, c->y[0] = c->z[0] = 6.0;
        c->x[1] = 3.0 + r, c->y[1] = c->z[1] = 6.0;
        pl_err_t ferr;
        cr_assert_eq(pl_colloid_forces(c, &ferr), 0, "%s", ferr.msg);
        pl_colloid_energy_t e;
        pl_colloid_energy(c, &e);
        double dphi, phi = phi_of(&p, r, &dphi);
        double fwca = r < dm * pow(2.0, 1.0 / 24.0) ? pl_pair_wca(r, dm, 2.5, 24.0).f : 0.0;
        cr_expect(fabs(e.pot[PL_CE_DEPL] + phi) < 2e-5, "r %g: energy %.8g vs %.8g", r, e.pot[PL_CE_DEPL], -phi);
        /* colloid 1 is pushed along +x by repulsion: F = fwca + dPhi_depl/dd */
        cr_expect(fabs(c->fx[1] - (fwca + dphi)) < 5e-5 * (1.0 + fabs(fwca)), "r %g: fx %.8g vs %.8g", r,
                  c->fx[1], fwca + dphi);
        cr_expect(c->fx[0] == -c->fx[1]);
    }
    pl_sim_free(sim);
}

static void expect_scene_error(const char *pairs, const char *wca, const char *method, const char *key)
{
    char text[1024];
    snprintf(text, sizeof text, SCENE, pairs, wca, method);
    pl_scene_t scene;
    pl_err_t err = {0, ""};
    cr_expect_eq(pl_scene_load_string(text, "t.cfg", &scene, &err), PL_ERR_INPUT, "%s/%s accepted", pairs, wca);
    cr_expect(strstr(err.msg, key) != NULL, "message \"%s\" does not name %s", err.msg, key);
}

Test(depletion, scene_errors)
{
    expect_scene_error("wca", "sigma_rule = \"pl\"; sigma = 4.3;", "potential", "'wca.sigma_rule'");
    expect_scene_error("hertz", "sigma_rule = \"pl\";", "potential", "'wca.sigma_rule'");
    expect_scene_error("wca, depletion_comp", "sigma_rule = \"pl\";", "hecht2", "'colloids.pairs'");
    expect_scene_error("wca, depletion", "", "potential", "'colloids.pairs'");
    expect_scene_error("wca", "sigma_rule = \"auto\";", "potential", "'wca.sigma_rule'");
}
