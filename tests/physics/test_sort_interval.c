/* srd.sort_interval (src/fluid/fluid_stages.c): the fluid arrays reordered
 * every k steps only, the collision reading through a sorted index in
 * between.  The cells and their rotations are those of k = 1; only the
 * order of a cell's particles in its sums differs (rounding), so the
 * trajectory changes and the statistics must not.
 *
 * 1. Conservation: without thermostat and force, each cell's rotation
 *    keeps its momentum and kinetic energy; 300 steps at k = 7 keep the
 *    total momentum within 1e-9 (per particle, kT = 1 units) and the
 *    kinetic energy within 1e-9 relative (rounding of ~3e5 updates per
 *    particle-sum is ~1e-12); 1e-6 with float storage (make
 *    DEFS=-DPL_SINGLE: each stored velocity rounds by ~6e-8, measured
 *    2e-9 per particle in momentum).  A collision that wrote a cell's new
 *    velocities to the wrong particles would still conserve both; the
 *    viscosity below catches that (cells mixed across space: no shear
 *    stress, nu -> nu_kin).
 * 2. Viscosity and temperature: Kolmogorov flow (tests/support/kolmogorov.h)
 *    at lambda = 0.1, gamma = 5, alpha = 90 deg with the Heyes thermostat,
 *    k = 1 and k = 8 (same seed): nu against PL Eqs. 9-12 within 5 %
 *    (3 SE < 5 % required, as tests/physics/test_viscosity.c), and the two
 *    nu within 3 combined SE of each other; the mean kinetic temperature
 *    of the last 8 blocks of 64 steps (flow included) within 3 combined SE.
 *    SE of nu: 8 blocks of one relaxation time each (~0.8 % measured); of
 *    T: the spread of the 8 block means (~2e-4). */
#include <math.h>
#include <stdio.h>

#include "peloid/srd_theory.h"
#include "kolmogorov.h"
#include "support.h"

Test(sort_interval, conserves_momentum_and_energy)
{
    pl_sim_t *sim = pl_test_sim("seed = 3;\nbox: { cells = [10, 9, 8]; };\nfluid: { density = 7.0; };\n"
                                "srd: { dt = 0.2; sort_interval = 7; };\n",
                                2);
    pl_fluid_obs_t a, b;
    pl_srd_observe(&sim->fluid, pl_srd_scratch_observe(sim->srd), &a, sim->nthreads);
    pl_test_steps(sim, 300);
    pl_srd_observe(&sim->fluid, pl_srd_scratch_observe(sim->srd), &b, sim->nthreads);
    const double n = (double)sim->fluid.n, tol = sizeof(pl_real) == sizeof(float) ? 1e-6 : 1e-9;
    for (int d = 0; d < 3; ++d)
        cr_assert_lt(fabs(b.momentum[d] - a.momentum[d]) / n, tol, "momentum[%d]: %.17g -> %.17g", d, a.momentum[d],
                     b.momentum[d]);
    cr_assert_lt(fabs(b.kinetic / a.kinetic - 1.0), tol, "kinetic energy %.17g -> %.17g", a.kinetic, b.kinetic);
    pl_sim_free(sim);
}

/* nu (mean, SE) and the kinetic temperature (mean, SE of 8 blocks of 64
 * steps after the flow measurement) at sort_interval k. */
static void kolmogorov(int k, double nu_theory, double *nu, double *nu_se, double *T, double *T_se)
{
    char scene[512];
    snprintf(scene, sizeof scene,
             "seed = 17;\nbox: { cells = [16, 16, 32]; };\nfluid: { density = 5.0; };\n"
             "srd: { dt = 0.1; alpha = 90.0; sort_interval = %d; };\n"
             "thermostat: { type = \"heyes\"; heyes_epsilon = 0.05; };\n",
             k);
    pl_sim_t *sim = pl_test_sim(scene, 2);
    pl_test_kolmogorov_nu(sim, nu_theory, 32, 0.1, 8.0, 8, nu, nu_se);
    double s = 0.0, s2 = 0.0;
    for (int blk = 0; blk < 8; ++blk) {
        double m = 0.0;
        for (int st = 0; st < 64; ++st) {
            pl_test_steps(sim, 1);
            pl_fluid_obs_t o;
            pl_srd_observe(&sim->fluid, pl_srd_scratch_observe(sim->srd), &o, sim->nthreads);
            m += 2.0 * o.kinetic / (3.0 * (double)sim->fluid.n) / 64.0;
        }
        s += m;
        s2 += m * m;
    }
    *T = s / 8.0;
    *T_se = sqrt((s2 / 8.0 - *T * *T) / 7.0);
    pl_sim_free(sim);
}

Test(sort_interval, viscosity_and_temperature_as_every_step, .timeout = 600)
{
    pl_srd_theory_t th;
    pl_srd_theory(5.0, PL_RULE_RANDOM_AXIS, 90.0 * M_PI / 180.0, 0.1, 1.0, &th);
    double nu[2], se[2], T[2], Tse[2];
    const int ks[2] = {1, 8};
    for (int j = 0; j < 2; ++j) {
        kolmogorov(ks[j], th.nu, &nu[j], &se[j], &T[j], &Tse[j]);
        printf("sort_interval %d: nu = %.4f +- %.4f (PL Eqs. 9-12: %.4f, %+.2f %%), kT = %.5f +- %.5f\n", ks[j], nu[j],
               se[j], th.nu, 100.0 * (nu[j] / th.nu - 1.0), T[j], Tse[j]);
    }
    cr_assert_lt(3.0 * se[1] / th.nu, 0.05, "statistical error %.3g too large to test 5%%", se[1] / th.nu);
    cr_assert_lt(fabs(nu[1] / th.nu - 1.0), 0.05, "k = 8: nu = %.4f +- %.4f vs PL %.4f", nu[1], se[1], th.nu);
    const double dnu = nu[1] - nu[0], snu = sqrt(se[0] * se[0] + se[1] * se[1]);
    cr_assert_lt(fabs(dnu), 3.0 * snu, "nu: k = 8 %.4f, k = 1 %.4f, 3 SE = %.4f", nu[1], nu[0], 3.0 * snu);
    const double dT = T[1] - T[0], sT = sqrt(Tse[0] * Tse[0] + Tse[1] * Tse[1]);
    cr_assert_lt(fabs(dT), 3.0 * sT, "kT: k = 8 %.5f, k = 1 %.5f, 3 SE = %.5f", T[1], T[0], 3.0 * sT);
}
