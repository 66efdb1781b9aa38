/* From a uniform (square-well) velocity distribution the fluid relaxes to
 * Maxwell-Boltzmann at the set temperature (Hecht Sec. IX.A, Fig. 2).
 *
 * Chi-square test of all 3N velocity components against N(0, kT) in 40
 * equiprobable bins; the fit is rejected at significance 1e-3.  The same
 * test must reject the initial uniform distribution (so it can fail). */
#include <gsl/gsl_cdf.h>
#include <math.h>

#include "support.h"

enum { NBINS = 40 };

static double chi2_pvalue(const pl_sim_t *sim, double kT)
{
    long counts[NBINS] = {0};
    size_t n = sim->fluid.n;
    for (int d = 0; d < 3; ++d)
        for (size_t i = 0; i < n; ++i) {
            double P = gsl_cdf_gaussian_P(sim->fluid.v[d][i], sqrt(kT));
            int b = (int)(P * NBINS);
            counts[b < NBINS ? b : NBINS - 1]++;
        }
    double expect = 3.0 * (double)n / NBINS, chi2 = 0.0;
    for (int b = 0; b < NBINS; ++b) {
        double dev = (double)counts[b] - expect;
        chi2 += dev * dev / expect;
    }
    return gsl_cdf_chisq_Q(chi2, NBINS - 1);
}

Test(maxwell, uniform_relaxes_to_maxwell_boltzmann)
{
    pl_sim_t *sim = pl_test_sim("seed = 8;\nbox: { cells = [16, 16, 16]; };\n"
                                "fluid: { density = 5.0; temperature = 1.3; init_velocity = \"uniform\"; };\n"
                                "srd: { dt = 0.5; alpha = 130.0; };\n",
                                2);
    double p0 = chi2_pvalue(sim, 1.3);
    cr_assert_lt(p0, 1e-6, "the uniform start must fail the test (p = %g)", p0);
    pl_test_steps(sim, 60); /* Hecht: Gaussian after some tens of steps */
    double p = chi2_pvalue(sim, 1.3);
    cr_assert_gt(p, 1e-3, "velocities are not Maxwell-Boltzmann at kT = 1.3 (p = %g)", p);
    pl_sim_free(sim);
}
