/* Padding & Louis 2006: transport coefficients (Sec. II.B), Table VI
 * (sigma_cf = 2 a0 and 10 a0), Table V (real colloids in water) and the
 * Sec. VII mapping examples 1-3.
 *
 * Tolerance: Table V/VI and Sec. VII print "approximately" values; they are
 * checked to one unit of the last printed digit (EXPECT_WITHIN), exact
 * values (f_kin, f_col, nu_kin, nu_col, Kn, Ma) to the printed rounding.
 * Where the paper contradicts itself the comment says which value peloid
 * follows and why. */
#include <string.h>

#include "mapping_testutil.h"

#include "peloid/mapping.h"
#include "peloid/srd_theory.h"

static pl_mapping_cg_t pl_choice(void)
{
    pl_mapping_cg_t c = {0};
    c.match = PL_MATCH_DIFFUSION;
    c.viscosity = PL_RULE_RANDOM_AXIS; /* PL Eqs. 9-12 */
    c.boundary = PL_BOUNDARY_STICK; /* Table VI: stick-boundary colloid */
    c.enskog = 1;                   /* Table VI includes the Enskog friction */
    c.gamma = 5;
    c.lambda = 0.1;
    c.alpha = M_PI / 2;
    c.cell_over_R = 0.5; /* sigma_cf = 2 a0 */
    c.md_resolution = 20;
    return c;
}

Test(pl, transport_sec2b)
{
    EXPECT_PRINTED(pl_srd_f_kin(5, M_PI / 2), 1.620, 0.001);
    EXPECT_PRINTED(pl_srd_f_col(5, M_PI / 2), 0.801, 0.001);
    EXPECT_PRINTED(pl_mapping_nu_kin(0.1, 5, M_PI / 2), 0.054, 0.001);
    EXPECT_PRINTED(pl_mapping_nu_col(0.1, 5, M_PI / 2), 0.45, 0.01);
    /* Large gamma: f_kin, f_col -> 1 at alpha = pi/2 (Sec. II.B.3). */
    EXPECT_WITHIN(pl_srd_f_kin(1e6, M_PI / 2), 1.0, 1e-5);
    EXPECT_WITHIN(pl_srd_f_col(1e6, M_PI / 2), 1.0, 1e-5);
    /* Eq. 6 at gamma -> infinity, alpha = pi/2: D_f = lambda. */
    EXPECT_WITHIN(pl_mapping_d_fluid(0.1, 1e6, M_PI / 2), 0.1, 1e-6);
    /* Table IV: c_s = 1.29 a0/t0 (PL Sec. IV.B), as the SRD theory computes it */
    pl_srd_theory_t th;
    pl_srd_theory(5.0, PL_RULE_RANDOM_AXIS, M_PI / 2, 0.1, 1.0, &th);
    EXPECT_PRINTED(th.c_s, 1.29, 0.01);
}

Test(pl, table6_sigma2)
{
    pl_mapping_cg_t c = pl_choice();
    pl_mapping_t m = {0};
    pl_mapping_pl_colloid(2.0, 1.0, 0.05, &c, &m);
    EXPECT_WITHIN(m.mass_sim, 168, 1);
    EXPECT_WITHIN(m.xi_enskog_sim / m.xi_stokes_sim, 1.8, 0.1);
    /* xi_S: the paper prints ~96; 6 pi eta a with eta = gamma nu from
     * Eqs. 9-12 (the "more accurate nu" the caption promises) is 94.1, and
     * the paper's own D_col = 0.0165 and Re = 0.2 columns need 94.1 (with 96,
     * D_col = 0.0163).  Formula followed: 2 % below the print. */
    EXPECT_REL(m.xi_stokes_sim, 96, 0.025);
    EXPECT_PRINTED(m.d_col_sim, 0.0165, 0.0001);
    /* Pe: 0.05 * 2 / 0.01646 = 6.07; paper ~6.2 (2 % off, same cause). */
    EXPECT_REL(m.num_model.Pe, 6.2, 0.025);
    EXPECT_PRINTED(m.num_model.Re, 0.2, 0.1);
    EXPECT_PRINTED(m.num_model.Kn, 0.05, 0.01);
    EXPECT_PRINTED(m.num_model.Ma, 0.039, 0.001);
    EXPECT_WITHIN(m.pl_model.tau_D, 242, 1);
    /* t_S = sigma/v_S = 40 t0 with the caption's v_S = 0.05 a0/t0; the
     * paper prints ~31 = 2/(1.29 * 0.05), i.e. it used v = c_s * 0.05 while
     * its caption says Ma = 0.039.  peloid follows t_S = a/v_S (Eq. 30). */
    EXPECT_WITHIN(m.pl_model.t_S, 40, 1e-9);
    EXPECT_WITHIN(m.pl_model.tau_nu, 8.0, 0.1);
    /* tau_B = M/xi_S = 1.78 with xi_S = 94.1 (paper 1.75 from its 96). */
    EXPECT_REL(m.pl_model.tau_B, 1.75, 0.02);
    EXPECT_WITHIN(m.pl_model.tau_B, 2.0 / 9.0 * m.pl_model.tau_nu, 1e-9); /* Eq. 51, rho_c = rho_f */
    EXPECT_PRINTED(m.pl_model.tau_E, 0.98, 0.01);
    EXPECT_PRINTED(m.pl_model.t_cs, 1.55, 0.01);
    /* Eq. 57 hierarchy holds for Table VI's colloid. */
    const pl_mapping_pl_times_t *t = &m.pl_model;
    cr_expect(t->tau_E < t->tau_nu && t->tau_B < t->tau_nu && 10 * t->tau_nu < t->tau_D);
}

Test(pl, table6_sigma10)
{
    pl_mapping_cg_t c = pl_choice();
    pl_mapping_t m = {0};
    pl_mapping_pl_colloid(10.0, 1.0, 0.05, &c, &m);
    EXPECT_PRINTED(m.mass_sim, 2.09e4, 0.01e4);
    /* xi_E/xi_S = 9.13 with xi_S = 470.5 (paper ~9.0 and ~478: same ~1.6 %
     * viscosity discrepancy as for sigma = 2; D_col below needs 470.5). */
    EXPECT_REL(m.xi_enskog_sim / m.xi_stokes_sim, 9.0, 0.02);
    EXPECT_REL(m.xi_stokes_sim, 478, 0.02);
    EXPECT_PRINTED(m.d_col_sim, 0.00236, 0.00001);
    EXPECT_WITHIN(m.num_model.Pe, 212, 1);
    EXPECT_WITHIN(m.num_model.Re, 1.0, 0.01);
    EXPECT_PRINTED(m.num_model.Kn, 0.01, 0.001);
    EXPECT_PRINTED(m.pl_model.tau_D, 4.2e4, 0.1e4);
    EXPECT_WITHIN(m.pl_model.t_S, 200, 1e-9); /* paper ~155: see sigma = 2 */
    EXPECT_WITHIN(m.pl_model.tau_nu, 200, 1);
    EXPECT_WITHIN(m.pl_model.tau_B, 44, 1);
    EXPECT_PRINTED(m.pl_model.tau_E, 4.9, 0.1);
    /* t_cs = 10/1.291 = 7.75: the paper prints ~7.8 (its 0.78 sigma
     * scaling); one unit. */
    EXPECT_WITHIN(m.pl_model.t_cs, 7.8, 0.1);
}

/* Real colloids of radius 1 um and 10 nm in water (Table V), v_S = 10 um/s. */
static pl_mapping_system_t water_colloid(double R)
{
    pl_mapping_system_t r = {0};
    r.radius = R;
    r.rho_p = 1e3;
    r.rho_f = 1e3;
    r.nu = 1e-6;
    r.kT = PL_KB * 298.15;
    r.buoyancy = 1;
    return r;
}

static const pl_mapping_solvent_t water = {10e-6, 1.48e3, 3e-10, 2.35e-9};

Test(pl, table5_real)
{
    pl_mapping_pl_times_t t;
    pl_mapping_numbers_t n;
    pl_mapping_system_t big = water_colloid(1e-6), small = water_colloid(1e-8);
    pl_mapping_pl_real(&big, &water, 10e-6, PL_BOUNDARY_STICK, &t, &n);
    EXPECT_WITHIN(t.tau_D, 5, 1);      /* ~5 s */
    EXPECT_WITHIN(n.Pe, 50, 10);       /* ~50 */
    EXPECT_PRINTED(n.Re, 1e-5, 0.1e-5);
    EXPECT_PRINTED(n.Kn, 0.0003, 0.0001);
    EXPECT_PRINTED(t.t_S, 0.1, 0.01);
    EXPECT_WITHIN(t.tau_nu, 1e-6, 0.1e-6);
    EXPECT_WITHIN(t.tau_B, 2.2e-7, 0.1e-7);
    EXPECT_WITHIN(t.t_cs, 6.7e-10, 0.1e-10);
    EXPECT_WITHIN(n.Sc, 425, 1); /* Table IV: Sc ~ 425 */
    /* Ma = v/c_s = 1e-5/1480 = 6.8e-9.  Table V prints 6.8e-10 although its
     * own scaling column reads 6.76e-10 v_S with v_S = 10 um/s: the factor
     * v_S was dropped.  peloid follows Eq. 28. */
    EXPECT_PRINTED(n.Ma, 6.8e-9, 0.1e-9);
    pl_mapping_pl_real(&small, &water, 10e-6, PL_BOUNDARY_STICK, &t, &n);
    EXPECT_WITHIN(t.tau_D, 5e-6, 1e-6);
    EXPECT_WITHIN(n.Pe, 0.005, 0.001);
    EXPECT_PRINTED(n.Kn, 0.03, 0.01);
    EXPECT_PRINTED(t.t_S, 0.001, 0.0001);
    EXPECT_WITHIN(t.tau_B, 2.2e-11, 0.1e-11);
}

/* Example 1 (tau_D mapped) and 3 (mass), through pl_mapping_derive. */
Test(pl, sec7_example1_and_3)
{
    pl_mapping_cg_t c = pl_choice();
    pl_mapping_t m;
    pl_err_t err = {0};
    pl_mapping_system_t big = water_colloid(1e-6), small = water_colloid(1e-8);
    cr_assert_eq(pl_mapping_derive(&big, &water, &c, &m, &err), 0, "%s", err.msg);
    EXPECT_PRINTED(m.a0, 0.5e-6, 0.1e-6);
    EXPECT_WITHIN(m.t0, 0.02, 0.01); /* t0 = 0.02 s */
    /* With the paper's round tau_D = 5 s: t0 = 5/243 = 0.0206 s, and its
     * Example 2 tau_nu = 8.0 t0 = 0.16-0.17 s. */
    double t0_5s = 5.0 / m.pl_model.tau_D * m.t0;
    EXPECT_PRINTED(t0_5s, 0.02, 0.01);
    EXPECT_WITHIN(m.pl_model.tau_nu / m.t0 * t0_5s, 0.17, 0.01);
    EXPECT_WITHIN(m.model.nu, 6e-12, 1e-12); /* "nu = 6 um^2/s" */
    /* Example 3: m_f = 2.5e-14 g ~ 8e8 water molecules. */
    EXPECT_PRINTED(m.m_f * 1e3, 2.5e-14, 0.1e-14);
    EXPECT_WITHIN(m.m_f / (18.015e-3 / PL_NA), 8e8, 1e8);
    double nu_big = m.model.nu;

    cr_assert_eq(pl_mapping_derive(&small, &water, &c, &m, &err), 0, "%s", err.msg);
    EXPECT_PRINTED(m.a0, 5e-9, 1e-9);
    EXPECT_WITHIN(5e-6 / m.pl_model.tau_D * m.t0, 2e-8, 1e-8);
    EXPECT_WITHIN(m.pl_model.tau_nu / m.pl_model.tau_D * 5e-6, 1.7e-7, 0.1e-7);
    EXPECT_PRINTED(m.m_f * 1e3, 2.5e-20, 0.1e-20);
    EXPECT_WITHIN(m.m_f / (18.015e-3 / PL_NA), 800, 100);
    /* Example 2 claims nu = 6e-3 um^2/s for the 10 nm system, but nu =
     * nu_sim a0^2/t0 scales as a0^2/a0^3 = 1/a: 100 x the 1 um value, 600
     * um^2/s.  The paper's number scales the wrong way; peloid follows nu0. */
    EXPECT_REL(m.model.nu / nu_big, 100.0, 1e-9);
}

/* Example 2: tau_nu mapped. */
Test(pl, sec7_example2_kinematic)
{
    pl_mapping_cg_t c = pl_choice();
    c.match = PL_MATCH_KINEMATIC;
    pl_mapping_t m;
    pl_err_t err = {0};
    pl_mapping_system_t big = water_colloid(1e-6), small = water_colloid(1e-8);
    cr_assert_eq(pl_mapping_derive(&big, &water, &c, &m, &err), 0, "%s", err.msg);
    /* 1e-6 s / 8.01 t0 = 1.248e-7 s (paper: 1e-6/8.0 = 1.25 -> "1.3"). */
    EXPECT_WITHIN(m.t0, 1.3e-7, 0.1e-7);
    EXPECT_PRINTED(m.pl_model.tau_D, 3e-5, 1e-5);
    EXPECT_REL(m.model.nu, 1e-6, 1e-12); /* nu takes the physical value */
    int peclet = 0;
    for (int i = 0; i < m.nwarn; ++i) peclet |= !strcmp(m.warn[i].name, "PECLET");
    cr_expect(peclet, "mapping tau_nu must flag that Pe is not reproduced");
    cr_assert_eq(pl_mapping_derive(&small, &water, &c, &m, &err), 0, "%s", err.msg);
    EXPECT_WITHIN(m.t0, 1.3e-11, 0.1e-11);
    EXPECT_PRINTED(m.pl_model.tau_D, 3e-9, 1e-9);
}
