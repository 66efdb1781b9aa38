/* Fluid self-diffusion from the mean-square displacement vs PL Eq. 6 at
 * lambda = 1, where the random-collision approximation holds (PL Sec.
 * II.B.2: deviations appear only for lambda < ~0.6).
 *
 * D = [MSD(t2) - MSD(t1)] / (6 (t2 - t1)) with t1 = 20 and t2 = 120 steps;
 * the velocity autocorrelation decays in a few collisions, so MSD is linear
 * past t1 (the discrete-time Green-Kubo sum that gives Eq. 6 includes the
 * ballistic first half step, Hecht Eq. 35).  Statistical error: the N
 * particles are nearly independent walkers; we use 8 independent groups of
 * particles (by id) to estimate the standard error.  Bound: the 5%,
 * with 3 standard errors required below it. */
#include <math.h>
#include <stdio.h>

#include "peloid/srd_theory.h"
#include "support.h"

enum { NGROUP = 8 };

static void group_msd(const pl_sim_t *sim, double msd[NGROUP])
{
    long cnt[NGROUP] = {0};
    for (int g = 0; g < NGROUP; ++g) msd[g] = 0.0;
    for (size_t i = 0; i < sim->fluid.n; ++i) {
        int g = (int)(sim->fluid.id[i] % NGROUP);
        double d2 = 0.0;
        for (int d = 0; d < 3; ++d) d2 += sim->fluid.disp[d][i] * sim->fluid.disp[d][i];
        msd[g] += d2;
        cnt[g]++;
    }
    for (int g = 0; g < NGROUP; ++g) msd[g] /= (double)cnt[g];
}

static void check_diffusion(double gamma, double alpha_deg)
{
    const double lambda = 1.0;
    char scene[512];
    snprintf(scene, sizeof scene,
             "seed = 23;\nbox: { cells = [16, 16, 16]; };\nfluid: { density = %g; };\n"
             "srd: { dt = %g; alpha = %g; };\noutput: { track_fluid = true; };\n",
             gamma, lambda, alpha_deg);
    pl_sim_t *sim = pl_test_sim(scene, 2);
    const int t1 = 20, t2 = pl_test_quick() ? 40 : 120;
    double m1[NGROUP], m2[NGROUP];
    pl_test_steps(sim, t1);
    group_msd(sim, m1);
    pl_test_steps(sim, t2 - t1);
    group_msd(sim, m2);
    double sum = 0, sum2 = 0;
    for (int g = 0; g < NGROUP; ++g) {
        double D = (m2[g] - m1[g]) / (6.0 * (t2 - t1) * lambda);
        sum += D;
        sum2 += D * D;
    }
    double D = sum / NGROUP, sem = sqrt((sum2 / NGROUP - D * D) / (NGROUP - 1));
    pl_srd_theory_t th;
    pl_srd_theory(gamma, PL_RULE_RANDOM_AXIS, alpha_deg * M_PI / 180.0, lambda, 1.0, &th);
    double rel = D / th.D_f - 1.0;
    printf("diffusion lambda=1 gamma=%g alpha=%g: D = %.4f +- %.4f, PL Eq. 6: %.4f, deviation %+.2f%% +- %.2f%%\n",
           gamma, alpha_deg, D, sem, th.D_f, 100 * rel, 100 * sem / th.D_f);
    cr_assert_lt(3.0 * sem / th.D_f, 0.05, "statistical error too large");
    cr_assert_lt(fabs(rel), 0.05, "D = %.4f +- %.4f vs PL Eq. 6: %.4f", D, sem, th.D_f);
    pl_sim_free(sim);
}

Test(diffusion, msd_matches_pl_eq6_alpha90, .timeout = 120) { check_diffusion(5.0, 90.0); }
Test(diffusion, msd_matches_pl_eq6_alpha130, .timeout = 120) { check_diffusion(10.0, 130.0); }
