/* Stokes drag on a pinned sphere with the potential coupling (PL Sec. V):
 * sigma_cf = 2 a0, epsilon_cf = 2.5 kT, gamma = 5, alpha = 90 deg,
 * lambda = 0.1, fluid held at v_inf = 0.1 a0/t0 (Re = v sigma / nu = 0.4) in
 * a periodic box L = 16 a0.  The friction xi = F / v_inf is compared with the
 * parallel sum (PL Eq. 41) of the Enskog friction (PL Eq. 40, M_c -> inf for
 * a pinned colloid) and the finite-size Stokes friction 4 pi eta sigma_cf
 * (1 + 2.837 sigma_cf / L) (PL Eqs. 42-43, read so that the friction grows
 * in a periodic array, as PL's a_eff(sigma_cf = 6) = 6.11 a0 > sigma_cf
 * requires; the same reading gives a_eff(2) = 1.52 a0 at L = 32 against
 * PL's measured 1.55 a0), with eta from PL Eqs. 9-15.
 *
 * Tolerance 10% (the issue's): the force is averaged over 10 blocks after a
 * transient of 2 flow-development times (L/2)^2 / nu; the block standard
 * error (~3% of F over 2e4 steps) is logged and must itself be below 5%, so
 * the 10% comparison (~3 standard errors) is not
 * decided by noise.  Measured (L = 16, 2e4 steps): xi = 54 +- 2.5 against
 * 52.0 (+4%). */
#include <math.h>
#include <stdio.h>

#include "peloid/coupling.h"
#include "peloid/srd_theory.h"
#include "support.h"

Test(coupling_drag, pinned_sphere_potential, .timeout = 600)
{
    const double L = 16.0, sigma = 2.0, v0 = 0.1, gamma = 5.0, dt = 0.1;
    const char *text =
        "seed = 5;\n"
        "box: { cells = [16, 16, 16]; };\n"
        "fluid: { density = 5.0; temperature = 1.0; };\n"
        "srd: { dt = 0.1; rule = \"random_axis\"; alpha = 90.0; };\n"
        "thermostat: { type = \"rescale\"; temperature = 1.0; };\n"
        "colloids: { count = 1; radius = 2.0; init = \"lattice\"; pairs = \"\"; substeps = 4; };\n"
        "coupling: { method = \"potential\"; sigma_cf = 2.0; epsilon_cf = 2.5; pinned = true;\n"
        "  flow_velocity = [0.1, 0.0, 0.0]; };\n";
    int quick = pl_test_quick();
    long long burn = quick ? 20 : 2000, block = quick ? 10 : 2000;
    enum { NB = 10 };
    pl_sim_t *sim = pl_test_sim(text, 2);
    pl_test_steps(sim, burn);
    double F[NB], mean = 0.0, var = 0.0;
    for (int b = 0; b < NB; ++b) {
        double p0 = sim->coupling->impulse[0], t0 = sim->coupling->pinned_time;
        pl_test_steps(sim, block);
        F[b] = (sim->coupling->impulse[0] - p0) / (sim->coupling->pinned_time - t0);
        mean += F[b] / NB;
    }
    for (int b = 0; b < NB; ++b) var += (F[b] - mean) * (F[b] - mean) / (NB - 1);
    double se = sqrt(var / NB);
    pl_srd_theory_t th;
    pl_srd_theory(gamma, 0.5 * 3.14159265358979323846, dt, 1.0, &th);
    const double PI = 3.14159265358979323846;
    double xi_E = pl_srd_xi_enskog(gamma, 1.0, sigma, INFINITY); /* PL Eq. 40, pinned */
    double xi_S = pl_srd_xi_stokes_pl(th.eta, sigma, L);         /* PL Eqs. 42-43 */
    double xi_th = pl_srd_xi_parallel(xi_S, xi_E);               /* PL Eq. 41 */
    double xi = mean / v0;
    double a_eff = xi / (4.0 * PI * th.eta);                                    /* PL Eq. 44 */
    cr_log_info("drag: xi = %.2f +- %.2f, theory %.2f (xi_E %.1f, xi_S %.1f, eta %.4f): %+.1f%%; "
                "a_eff = %.3f a0 (theory %.3f); Re = %.2f; %llu near-particle steps",
                xi, se / v0, xi_th, xi_E, xi_S, th.eta, 100.0 * (xi / xi_th - 1.0), a_eff,
                xi_th / (4.0 * PI * th.eta), v0 * sigma / th.nu, sim->coupling->near_total);
    pl_sim_free(sim);
    if (quick) return;
    cr_expect_lt(se / mean, 0.05, "drag too noisy to judge: %.3g +- %.3g", mean, se);
    cr_expect_lt(fabs(xi / xi_th - 1.0), 0.10, "friction %.2f vs PL Eqs. 40-43 %.2f", xi, xi_th);
}
