/* Kinematic viscosity from steady Kolmogorov flow in a periodic box
 * (issue 2: the method is ours to choose; we chose this one).
 *
 * A body force f_x(z) = F sin(k z), k = 2 pi / Lz, applied as a kick each
 * step, drives the steady Navier-Stokes solution v_x = F/(nu k^2) sin(k z)
 * (PL Eq. 8 with a source).  The amplitude a = (2/N) sum v_x sin(k z) is
 * time-averaged after 3 momentum-diffusion times; nu = F / (k^2 <a>).  The
 * cell-rescaling thermostat (PL App. A) removes the viscous heating; it
 * scales relative velocities only and leaves the flow alone.
 *
 * Statistical error: 16 consecutive blocks of the averaging window, each
 * longer than the flow's relaxation time 1/(nu k^2), give the standard error.
 * A steady measurement beats fitting a decaying shear wave: the mode's own
 * thermal fluctuations (std sqrt(2 kT / N m), correlated over the same
 * relaxation time) average out instead of biasing one transient.
 * Bound: the 5% of PL Eqs. 9-12 (Hecht Eq. 28 for hecht_axes); the test also requires 3 standard
 * errors < 5%, so the bound is a statement about the physics, not noise. */
#include <math.h>
#include <stdio.h>

#include "peloid/srd_theory.h"
#include "kolmogorov.h"
#include "support.h"

enum { NBLOCKS = 16 };

static void check_viscosity(double lambda, double gamma, int rule, double alpha_deg, int Lxy, int Lz, double ntau)
{
    pl_srd_theory_t th;
    pl_srd_theory(gamma, rule, alpha_deg * M_PI / 180.0, lambda, 1.0, &th);
    char scene[512];
    snprintf(scene, sizeof scene,
             "seed = 17;\nbox: { cells = [%d, %d, %d]; };\nfluid: { density = %g; };\n"
             "srd: { dt = %g; alpha = %g; rule = \"%s\"; };\nthermostat: { type = \"rescale\"; };\n",
             Lxy, Lxy, Lz, gamma, lambda, alpha_deg, rule == PL_RULE_HECHT_AXES ? "hecht_axes" : "random_axis");
    pl_sim_t *sim = pl_test_sim(scene, 2);
    double mean, sem;
    pl_test_kolmogorov_nu(sim, th.nu, Lz, lambda, ntau, NBLOCKS, &mean, &sem);
    double rel = mean / th.nu - 1.0;
    printf("viscosity rule=%d lambda=%g gamma=%g alpha=%g box %dx%dx%d: nu = %.4f +- %.4f (PL: %.4f = kin %.4f + col "
           "%.4f), deviation %+.2f%% +- %.2f%%\n",
           rule, lambda, gamma, alpha_deg, Lxy, Lxy, Lz, mean, sem, th.nu, th.nu_kin, th.nu_col, 100 * rel,
           100 * sem / th.nu);
    cr_assert_lt(3.0 * sem / th.nu, 0.05, "statistical error %.3g too large to test 5%%", sem / th.nu);
    cr_assert_lt(fabs(rel), 0.05, "nu = %.4f +- %.4f vs PL Eqs. 9-12: %.4f", mean, sem, th.nu);
    pl_sim_free(sim);
}

Test(viscosity, kolmogorov_small_lambda, .timeout = 300)
{
    /* PL Sec. II.B.4: nu_kin = 0.054, nu_col = 0.45 at lambda = 0.1 */
    check_viscosity(0.1, 5.0, PL_RULE_RANDOM_AXIS, 90.0, 16, 32, pl_test_quick() ? 4 : 20);
}

Test(viscosity, kolmogorov_large_lambda, .timeout = 300)
{
    check_viscosity(1.0, 5.0, PL_RULE_RANDOM_AXIS, 90.0, 8, 64, pl_test_quick() ? 4 : 20);
}

Test(viscosity, kolmogorov_hecht_axes, .timeout = 300)
{
    /* Hecht's +-90 deg rotations about the coordinate axes, at lambda = 1
     * where the kinetic part dominates: Hecht Eq. 28 gives nu = 0.482, PL
     * Eqs. 9-12 at 90 deg 0.583 (21 % apart) and at srd.alpha's 130 deg,
     * which the axes rule ignores, 0.369; the 5 % bound separates them. */
    check_viscosity(1.0, 5.0, PL_RULE_HECHT_AXES, 130.0, 8, 64, pl_test_quick() ? 4 : 20);
}
