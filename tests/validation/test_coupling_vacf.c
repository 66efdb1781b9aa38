/* Colloid velocity autocorrelation and diffusion with the potential coupling
 * (PL Sec. VI, Fig. 10; App. B), PL's set-up: sigma_cf = 2 a0, eps_cf =
 * 2.5 kT, gamma = 5, alpha = 90 deg, lambda = 0.1, neutrally buoyant
 * colloids M_c = gamma 4/3 pi sigma_cf^3 m_f = 167.6 m_f (PL Table VI),
 * 4 MD steps per collision step, cell-rescaling thermostat.  Eight colloids
 * on a 2^3 lattice in L = 16 a0 (spacing 8 a0, volume fraction phi =
 * 8 (4/3) pi sigma_cf^3 / L^3 = 0.065) give 24 velocity components per step;
 * colloid-colloid WCA sigma_cc = 4.3 a0, n = 24 (PL Sec. III.C.1).
 *
 * enskog_time: the normalised VACF C(t) = <V(t)V(0)> / <V^2> (PL Eq. 52)
 * after the initial non-Markovian quadratic part (t > 2 dt_c, PL's
 * tau_FP = 0.09 t0 ~ dt_c) is fitted over 0.2 <= t <= 1.2 t0 (up to tau_E,
 * below the sonic time t_cs = 1.55 t0) by PL Eq. B11, C = exp(-t / tau)
 * (amplitude fixed by equipartition), and tau is compared with tau_E =
 * M_c / xi_E (PL Eq. 53, xi_E from PL Eq. 40 with the reduced mass M_c m_f /
 * (M_c + m_f): 1.257 t0) within 15% (the issue's).  A free amplitude is not
 * used: the local decay time -1 / (d ln C / dt) is not constant but grows
 * from 1.0 t0 (t = 0.3) to 2.0 t0 (t = 1.1) as the slower hydrodynamic part
 * (PL Eq. B5) takes over, so a two-parameter fit moves by +-20% with the
 * window while the one-parameter fit moves by < 5% (1.29 / 1.34 t0 on
 * [0.3, 1.0] / [0.3, 1.3], single colloid, 8e4 steps).  Standard error from
 * 8 blocks (logged, must be < 5%): 1.3% at 8000 steps.  Measured
 * (2026-11-29): tau = 1.212 +- 0.016 t0 against tau_E = 1.257 t0 (-3.6%),
 * M <V^2> / kT = 0.963 over these 800 t0 (the same scene over 4000 t0:
 * 0.989 +- 0.006, 10 blocks); doubling M_c in the prediction (tau_E =
 * 2.51 t0) fails (-51%).  One thread: ~10 s CPU.
 *
 * diffusion: one colloid (the single-colloid set-up, seed 11) in L =
 * 16 a0; D from the slope of the mean-square displacement between lags 40
 * and 100 t0 (PL Sec. VI.C: MSD = 2 D t per component), against kT / xi
 * (PL Eq. 54) with xi from PL Eqs. 40-43 as PL evaluate them (Enskog PL Eq.
 * 40 with the reduced mass, in parallel (Eq. 41) with 4 pi eta sigma_cf /
 * (1 - 2.837 sigma_cf / L), Eqs. 42-43; see test_coupling_drag): 0.01779.
 * The window starts after the box's slowest shear mode, L^2 / (4 pi^2 nu) =
 * 13 t0, has decayed (e^-3): D(t) still grows after 20 t0 (the
 * transverse-mode sum (kT / rho L^3) sum_k (1 - k_x^2 / k^2) / (nu k^2)
 * exp(-nu k^2 t) leaves 0.0019 after 10 t0), and a 20-60 t0 window reads
 * 3% low (0.01668 +- 0.00050 against 0.01722 +- 0.00055 at 40-100 t0,
 * seeds 71-73).  4e5 steps (~100 s on 2 threads), standard error from 16
 * blocks of 2500 t0, logged, must be below 5%.  Tolerance 15%: 3.6 standard
 * errors of the test's run, 2.5 of the run-to-run scatter (below).
 * Measured: seed 11, 0.01619 +- 0.00066 (-9.0%); seeds 71-74, 2e5 steps
 * each: 0.0187, 0.0161, 0.0169, 0.0143 (scatter 11% per run, larger than
 * the blocks' 6%), mean 0.0165 +- 0.0009.  All five, weighted by length:
 * 8 +- 5% below PL's kT / xi and 4 +- 5% below kT / xi of the pinned drag
 * (1 / 58.4 = 0.01712, test_coupling_drag): the Einstein relation holds
 * within the statistics.
 * Other measures of the same mobility: a colloid driven by a force, U / F =
 * 0.0170 +- 0.0004 (4 or 16 MD substeps, with or without the thermostat;
 * coupling I slip as control: 0.0173 +- 0.0006); the transient response to
 * a switched-on force matches D(t) / kT within 3% up to 10 t0; M <V^2> / kT
 * = 0.995 +- 0.006.  The test fails without the finite-size correction
 * (kT / xi_inf = 0.0234, +32%) or without hydrodynamics (kT / xi_E =
 * 0.0075). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/srd_theory.h"
#include "support.h"

static const char *SCENE =
    "seed = 11;\n"
    "box: { cells = [16, 16, 16]; };\n"
    "fluid: { density = 5.0; temperature = 1.0; };\n"
    "srd: { dt = 0.1; rule = \"random_axis\"; alpha = 90.0; };\n"
    "thermostat: { type = \"rescale\"; temperature = 1.0; };\n"
    "colloids: { count = 8; radius = 2.0; mass_density = 5.0; temperature = 1.0;\n"
    "  init = \"lattice\"; pairs = \"wca\"; substeps = 4; };\n"
    "wca: { epsilon = 2.5; sigma = 4.3; n = 24.0; };\n"
    "coupling: { method = \"potential\"; sigma_cf = 2.0; epsilon_cf = 2.5; };\n";

static const char *SCENE_ONE =
    "seed = 11;\n"
    "box: { cells = [16, 16, 16]; };\n"
    "fluid: { density = 5.0; temperature = 1.0; };\n"
    "srd: { dt = 0.1; rule = \"random_axis\"; alpha = 90.0; };\n"
    "thermostat: { type = \"rescale\"; temperature = 1.0; };\n"
    "colloids: { count = 1; radius = 2.0; mass_density = 5.0; temperature = 1.0;\n"
    "  init = \"lattice\"; pairs = \"\"; substeps = 4; };\n"
    "coupling: { method = \"potential\"; sigma_cf = 2.0; epsilon_cf = 2.5; };\n";

static const double GAMMA = 5.0, SIGMA = 2.0, DT = 0.1, L = 16.0;
static const double PI = 3.14159265358979323846;
enum { NB = 8 };

/* Runs `steps` collision steps after `burn`, storing every step the colloid
 * velocities (v) or unwrapped positions (r), component-major per step:
 * buf[(s * n + k) * 3 + d]. */
static double *record(pl_sim_t *sim, long long burn, long long steps, int positions)
{
    pl_test_steps(sim, burn);
    const pl_colloid_t *c = sim->colloids;
    double *buf = malloc((size_t)steps * c->n * 3 * sizeof(double));
    cr_assert_not_null(buf);
    for (long long s = 0; s < steps; ++s) {
        pl_test_steps(sim, 1);
        double *b = buf + (size_t)s * c->n * 3;
        for (size_t k = 0; k < c->n; ++k) {
            if (positions) {
                b[3 * k] = c->x[k] + c->ix[k] * c->box[0];
                b[3 * k + 1] = c->y[k] + c->iy[k] * c->box[1];
                b[3 * k + 2] = c->z[k] + c->iz[k] * c->box[2];
            } else {
                b[3 * k] = c->vx[k];
                b[3 * k + 1] = c->vy[k];
                b[3 * k + 2] = c->vz[k];
            }
        }
    }
    return buf;
}

static void mean_se(const double *x, int n, double *mean, double *se)
{
    double m = 0.0, v = 0.0;
    for (int i = 0; i < n; ++i) m += x[i] / n;
    for (int i = 0; i < n; ++i) v += (x[i] - m) * (x[i] - m) / (n - 1);
    *mean = m;
    *se = sqrt(v / n);
}

/* PL Eq. 53 with PL Eq. 40 (reduced mass). */
static double tau_enskog(double M) { return M / pl_srd_xi_enskog(GAMMA, 1.0, SIGMA, M); }

Test(coupling_vacf, potential_enskog_time, .timeout = 600)
{
    int quick = pl_test_quick();
    long long steps = quick ? 80 : 8000;
    enum { KMAX = 12, K0 = 2 }; /* fit window 0.2 .. 1.2 t0 */
    pl_sim_t *sim = pl_test_sim(SCENE, 1);
    size_t m = 3 * sim->colloids->n;
    double M = sim->colloids->mass[0];
    double *v = record(sim, 200, steps, 0);
    pl_sim_free(sim);
    double tau[NB], C[NB][KMAX + 1];
    long long bl = steps / NB;
    for (int b = 0; b < NB; ++b) {
        /* origins in block b; lags may reach into the next block */
        for (int k = 0; k <= KMAX; ++k) {
            double s = 0.0;
            long long n = 0;
            for (long long t = b * bl; t < (b + 1) * bl && t + k < steps; ++t, ++n)
                for (size_t j = 0; j < m; ++j) s += v[(size_t)t * m + j] * v[(size_t)(t + k) * m + j];
            C[b][k] = s / ((double)n * (double)m);
        }
        /* PL Eq. B11: ln C = -t / tau, least squares through the origin */
        double stt = 0.0, stl = 0.0;
        for (int k = K0; k <= KMAX; ++k) {
            double t = k * DT;
            stt += t * t;
            stl += t * log(C[b][k] / C[b][0]);
        }
        tau[b] = -stt / stl;
    }
    free(v);
    double tm, tse;
    mean_se(tau, NB, &tm, &tse);
    double c0 = 0.0, ch = 0.0;
    for (int b = 0; b < NB; ++b) {
        c0 += C[b][0] / NB;
        ch += C[b][KMAX / 2] / C[b][0] / NB;
    }
    double tE = tau_enskog(M);
    cr_log_info("VACF: tau = %.3f +- %.3f t0, tau_E (PL Eqs. 40, 53) %.3f: %+.1f%%; "
                "M <V^2> / kT = %.3f; C(%.1f) = %.3f (exp(-t/tau_E) %.3f)",
                tm, tse, tE, 100.0 * (tm / tE - 1.0), M * c0, KMAX / 2 * DT, ch,
                exp(-KMAX / 2 * DT / tE));
    PL_SKIP_IF_QUICK("a statistical check of the full run");
    cr_expect_lt(tse / tm, 0.05, "VACF too noisy to judge: %.3f +- %.3f", tm, tse);
    cr_expect_lt(fabs(tm / tE - 1.0), 0.15, "decay time %.3f vs tau_E %.3f (PL Eq. 53)", tm, tE);
    cr_expect_lt(fabs(M * c0 - 1.0), 0.05, "equipartition: M <V^2> / kT = %.3f", M * c0);
}

Test(coupling_vacf, potential_diffusion, .timeout = 900)
{
    int quick = pl_test_quick();
    enum { NBD = 16 };
    long long steps = quick ? 1600 : 400000;
    long long l1 = quick ? 40 : 400, l2 = quick ? 100 : 1000; /* 40 .. 100 t0 */
    pl_sim_t *sim = pl_test_sim(SCENE_ONE, 2);
    size_t m = 3 * sim->colloids->n;
    double M = sim->colloids->mass[0];
    double *r = record(sim, 200, steps, 1);
    pl_sim_free(sim);
    double D[NBD];
    long long bl = steps / NBD;
    for (int b = 0; b < NBD; ++b) {
        double s1 = 0.0, s2 = 0.0;
        long long n1 = 0, n2 = 0;
        for (long long t = b * bl; t < (b + 1) * bl; ++t)
            for (size_t j = 0; j < m; ++j) {
                double x0 = r[(size_t)t * m + j];
                if (t + l1 < steps) {
                    double d = r[(size_t)(t + l1) * m + j] - x0;
                    s1 += d * d;
                    n1++;
                }
                if (t + l2 < steps) {
                    double d = r[(size_t)(t + l2) * m + j] - x0;
                    s2 += d * d;
                    n2++;
                }
            }
        /* per Cartesian component: MSD = 2 D t (PL Sec. VI.C) */
        D[b] = (s2 / (double)n2 - s1 / (double)n1) / (2.0 * (double)(l2 - l1) * DT);
    }
    free(r);
    double Dm, Dse;
    mean_se(D, NBD, &Dm, &Dse);
    pl_srd_theory_t th;
    pl_srd_theory(GAMMA, PL_RULE_RANDOM_AXIS, 0.5 * PI, DT, 1.0, &th);
    double xi_E = pl_srd_xi_enskog(GAMMA, 1.0, SIGMA, M);                          /* PL Eq. 40 */
    double xi_pl = pl_srd_xi_parallel(pl_srd_xi_stokes_pl(th.eta, SIGMA, L), xi_E); /* PL Eqs. 41-43 */
    double xi_pf = pl_srd_xi_hasimoto(pl_srd_xi_parallel(4.0 * PI * th.eta * SIGMA, xi_E), th.eta, L);
    cr_log_info("MSD 40-100 t0: D = %.5f +- %.5f; kT / xi (PL Eqs. 40-43) %.5f: %+.1f%%; point-force "
                "finite-size form %.5f; pinned-drag friction 1 / 58.4 = %.5f",
                Dm, Dse, 1.0 / xi_pl, 100.0 * (Dm * xi_pl - 1.0), 1.0 / xi_pf, 1.0 / 58.4);
    PL_SKIP_IF_QUICK("a statistical check of the full run");
    cr_expect_lt(Dse / Dm, 0.05, "MSD too noisy to judge: %.5f +- %.5f", Dm, Dse);
    cr_expect_lt(fabs(Dm * xi_pl - 1.0), 0.15, "D %.5f vs kT / xi %.5f (PL Eqs. 40-43)", Dm, 1.0 / xi_pl);
}
