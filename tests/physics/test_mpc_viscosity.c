/* The viscosity of the MPC-AT rules (srd.rule = "mpc_at", "mpc_at_a")
 * against their rows' theories (src/fluid/rule_mpc_at.c: the published
 * MPC-AT expressions; src/fluid/rule_mpc_at_a.c: derived there, the
 * published +a ones could not be read), measured by steady Kolmogorov flow
 * as tests/physics/test_viscosity.c measures SRD's: a kick F sin(k z) each step,
 * nu = F / (k^2 <a>) from the time-averaged amplitude a = (2/N) sum v_x
 * sin(k z) after 3 momentum-diffusion times 1/(nu k^2).  The rules are
 * thermostats themselves: no other thermostat removes the viscous heating.
 *
 * (srd_a: see the end of this comment.)
 *
 * Statistical error: 16 consecutive blocks of the averaging window of ntau
 * (20 or 40) relaxation times 1/(nu k^2) (8 blocks of 8 in the short runs:
 * a block no shorter than the relaxation time, or the blocks are
 * correlated and the SE too small) give the standard error SE.  Bound: 3 %
 * of the theory, and 3 SE < 3 % so that the bound is about the physics,
 * not the noise (the full runs: MPC_VISC_FULL=1, make validate-physics).
 * Without it (make check) short mpc_at runs in smaller boxes check the
 * same within 4 SE (SE ~ 2-3 %, required < 5 %): no 3 % statement; the
 * mpc_at_a runs need long boxes (their viscosity depends on the
 * wavelength: +9 +- 2.5 % in a 16-cell box at gamma 10, lambda 0.05) and
 * run in make validate-physics only; make check tests +a through the
 * angular momentum (tests/unit/test_collision_rules.c).
 *
 * Parameter sets: mpc_at at gamma = 5, lambda = 0.1 and gamma = 10,
 * lambda = 0.05 (collisional part 90 and 98 % of nu); mpc_at_a at gamma =
 * 10, lambda = 0.05 (collisional, 95 %) and gamma = 10, lambda = 1
 * (kinetic, 95 %; validate-physics only: the box must be 8 x 8 x 64).
 * Measured, not tested: mpc_at at gamma = 10, lambda = 1 (8 x 8 x 64):
 * 0.7082 +- 0.0036 against 0.6861 (+3.2 %), a Knudsen effect of k lambda =
 * 0.1 or the theory's; mpc_at_a at gamma = 5, lambda = 0.1 (12 x 12 x 24):
 * 0.3807 +- 0.0042 against the derived 0.350 (+8.7 %), not understood.
 *
 * SRD+a (srd.rule = "srd_a", src/fluid/rule_srd_a.c, validate-physics
 * only): against random_axis at the same parameters, both with the
 * rescaling thermostat (the forcing's viscous heat: SRD and SRD+a keep
 * the energy), as the ratio of the viscosities (see
 * the test; it prints both viscosities, their theories and the ratio). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "peloid/collision_rule.h"
#include "peloid/srd_theory.h"
#include "kolmogorov.h"
#include "support.h"

static int rule_index(const char *name)
{
    for (int k = 0; pl_collision_rule(k); ++k)
        if (!strcmp(pl_collision_rule(k)->name, name)) return k;
    cr_assert_fail("no collision rule %s", name);
    return -1;
}

static int full_run(void) { return getenv("MPC_VISC_FULL") && strcmp(getenv("MPC_VISC_FULL"), "0"); }

/* The Kolmogorov viscosity of `rule` (mean, sem; its theory's nu in *nu_th), printed beside the theory.
 * extra: scene text after the fluid's (srd_a: the rescaling thermostat it needs); alpha_deg 0: a rule
 * without an angle. */
static void measure_viscosity(const char *rule, double lambda, double gamma, int Lxy, int Lz, double ntau, int nblocks,
                              double alpha_deg, const char *extra, double *mean, double *sem, double *nu_th)
{
    pl_srd_theory_t th;
    pl_srd_theory(gamma, rule_index(rule), alpha_deg * M_PI / 180.0, lambda, 1.0, &th);
    char scene[640], angle[64] = "";
    if (alpha_deg > 0) snprintf(angle, sizeof angle, " alpha = %g;", alpha_deg);
    snprintf(scene, sizeof scene,
             "seed = 23;\nbox: { cells = [%d, %d, %d]; };\nfluid: { density = %g; };\n"
             "srd: { dt = %g; rule = \"%s\";%s };\n%s",
             Lxy, Lxy, Lz, gamma, lambda, rule, angle, extra);
    pl_sim_t *sim = pl_test_sim(scene, 2);
    const long long steps = pl_test_kolmogorov_nu(sim, th.nu, Lz, lambda, ntau, nblocks, mean, sem);
    printf("viscosity %s lambda=%g gamma=%g box %dx%dx%d, %lld steps: nu = %.4f +- %.4f (%s: %.4f = kin %.4f + col "
           "%.4f), deviation %+.2f%% +- %.2f%%\n",
           rule, lambda, gamma, Lxy, Lxy, Lz, steps, *mean, *sem,
           pl_collision_rule(rule_index(rule))->theory_ref, th.nu, th.nu_kin, th.nu_col, 100 * (*mean / th.nu - 1.0),
           100 * *sem / th.nu);
    *nu_th = th.nu;
    pl_sim_free(sim);
}

static void check_viscosity(const char *rule, double lambda, double gamma, int Lxy, int Lz, double ntau, int nblocks)
{
    double mean, sem, nu;
    measure_viscosity(rule, lambda, gamma, Lxy, Lz, ntau, nblocks, 0.0, "", &mean, &sem, &nu);
    const double rel = mean / nu - 1.0;
    if (full_run()) {
        cr_assert_lt(3.0 * sem / nu, 0.03, "statistical error %.3g too large to test 3%%", sem / nu);
        cr_assert_lt(fabs(rel), 0.03, "nu = %.4f +- %.4f vs %.4f", mean, sem, nu);
    } else {
        cr_assert_lt(sem / nu, 0.05, "statistical error %.3g too large", sem / nu);
        cr_assert_lt(fabs(rel), 4.0 * sem / nu, "nu = %.4f +- %.4f vs %.4f", mean, sem, nu);
    }
}

/* make check: short (8 relaxation times, 8 blocks); make validate-physics
 * sets MPC_VISC_FULL=1 (ntau relaxation times, 16 blocks) */
#define RUN(rule, lambda, gamma, Lxy_full, Lz_full, ntau, Lxy_quick, Lz_quick)                                    \
    do {                                                                                                         \
        PL_SKIP_IF_QUICK("a viscosity run");                                                                     \
        if (full_run()) check_viscosity(rule, lambda, gamma, Lxy_full, Lz_full, ntau, 16);                        \
        else check_viscosity(rule, lambda, gamma, Lxy_quick, Lz_quick, 8, 8);                                     \
    } while (0)

Test(mpc_viscosity, mpc_at_small_lambda, .timeout = 3600) { RUN("mpc_at", 0.1, 5.0, 16, 24, 40, 8, 16); }
Test(mpc_viscosity, mpc_at_dense, .timeout = 3600) { RUN("mpc_at", 0.05, 10.0, 12, 24, 40, 4, 16); }
Test(mpc_viscosity, mpc_at_a_dense, .timeout = 3600)
{
    /* the short run's 4 x 4 x 16 box measured +9 +- 2.5 %: +a's viscosity depends on the wavelength more
     * than MPC-AT's (k a = 0.39 there, 0.26 here); a 24-cell box is too long for make check */
    if (!full_run()) cr_skip_test("MPC_VISC_FULL=1 only (make validate-physics)");
    RUN("mpc_at_a", 0.05, 10.0, 8, 24, 40, 4, 16);
}
Test(mpc_viscosity, mpc_at_a_kinetic, .timeout = 3600)
{
    /* lambda = 1 needs a box of 8 x 8 x 64 (a smaller one measured MPC-AT 18 % high): validate-physics only */
    if (!full_run()) cr_skip_test("MPC_VISC_FULL=1 only (make validate-physics)");
    RUN("mpc_at_a", 1.0, 10.0, 8, 64, 20, 4, 32);
}
Test(mpc_viscosity, srd_a_over_srd, .timeout = 3600)
{
    /* SRD+a against SRD at the same gamma = 10, lambda = 0.05, alpha = 130 deg (collisional 97 %), box and
     * thermostat (rescale: both keep the energy, the forcing heats them): the ratio of the viscosities against
     * the ratio of the theories, src/fluid/rule_srd_a.c's derived nu_col = 2/3 (1 - cos alpha) x MPC-AT+a's over PL Eq. 10.  The ratio,
     * not nu itself: at this lambda PL Eqs. 9-12 overestimate SRD's own nu by a few per cent (printed beside
     * it: the correlations of successive collisions the mean-field theory leaves out), and that part is
     * common to both rules.  Bound: 3 combined SE, the SE below 1.5 %.  The box of mpc_at_a_dense (+a's viscosity
     * depends on the wavelength): validate-physics only. */
    if (!full_run()) cr_skip_test("MPC_VISC_FULL=1 only (make validate-physics)");
    PL_SKIP_IF_QUICK("a viscosity run");
    const char *rescale = "thermostat: { type = \"rescale\"; };\n";
    double m_a, s_a, t_a, m_s, s_s, t_s;
    measure_viscosity("srd_a", 0.05, 10.0, 8, 24, 160, 16, 130.0, rescale, &m_a, &s_a, &t_a);
    measure_viscosity("random_axis", 0.05, 10.0, 8, 24, 160, 16, 130.0, rescale, &m_s, &s_s, &t_s);
    const double r = m_a / m_s, r_se = r * hypot(s_a / m_a, s_s / m_s), r_th = t_a / t_s;
    printf("nu(srd_a) / nu(random_axis) = %.4f +- %.4f against the theories' %.4f: %+.2f%% (%+.1f SE)\n", r, r_se,
           r_th, 100 * (r / r_th - 1), (r - r_th) / r_se);
    cr_assert_lt(r_se / r, 0.015, "the ratio's SE %.3g too large to test", r_se / r);
    cr_assert_lt(fabs(r - r_th), 3.0 * r_se, "ratio %.4f +- %.4f vs %.4f", r, r_se, r_th);
}
