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
 * 8 blocks (logged, must be < 5%): 1.1% at 8000 steps.  Measured: tau =
 * 1.240 +- 0.014 t0 against tau_E = 1.257 t0 (-1.4%), M <V^2> / kT = 0.994;
 * doubling M_c in the prediction (tau_E = 2.51 t0) fails (-51%).  One
 * thread: ~10 s CPU.
 *
 * diffusion: D from the slope of the mean-square displacement between lags
 * 20 and 60 t0 (the VACF has decayed: tau_B = 3.9 t0, slowest shear mode of
 * the box L^2 / (4 pi^2 nu) = 13 t0) against kT / xi_L, where xi_L is the
 * unbounded friction of PL Eq. 41 (Enskog PL Eq. 40 in parallel with the
 * slip Stokes friction 4 pi eta sigma_cf, PL Eq. 42 with f = 1) corrected
 * for the periodic box as for a freely moving sphere with zero total
 * momentum (Hasimoto: 1 / xi_L = 1 / xi_inf - 2.837 / (6 pi eta L), -16% in
 * D at L = 16, whatever the surface; PL Eq. 43 applied to xi_S alone gives
 * 2% less), times 1 - 1.1795 phi for the other colloids (PL Sec. VI.C, -7.7%).
 * Expected accuracy ~10%: the phi term is a dilute-limit
 * estimate, SE ~3% from 8 blocks.
 *
 * DISABLED: the expectation, not the coupling, is off.  D is 15-20%
 * below PL Eqs. 40-43 (8 colloids: 0.01449 +- 0.0006 with seed 11, 0.0153
 * +- 0.0006 with seed 81, against 0.01816), but so is every other friction
 * measured for this colloid; the Einstein relation holds:
 *  - one colloid, L = 16, thermal: D = 0.0158 +- 0.0007 (MSD slope 20-60
 *    t0 = plateau of the VACF integral, PL Eq. 58; 6 runs of 6e4-8e4
 *    steps; seed 11 (4 and 16 MD substeps, same random streams) 0.0142,
 *    0.0141, seeds 71-74 0.0168, 0.0178, 0.0170, 0.0148: the run-to-run
 *    scatter is 1.5x the block standard errors, and the earlier "17 +- 4%
 *    violation" came from seed-11 runs only); M <V^2> / kT = 0.995 +-
 *    0.006;
 *  - one colloid driven (gravity F = 2, 5 kT/a0, compensated on the fluid):
 *    U / F = 0.0170 +- 0.0004 (4 or 16 MD substeps, with or without the
 *    thermostat), so D xi_U/F / kT = 0.93 +- 0.05 (hecht1 slip as control:
 *    thermal 0.0191 +- 0.0012, U / F 0.0173 +- 0.0006);
 *  - transient response to F switched on (+-F from the same state, 1220
 *    trials): R(t) = D(t) / kT within 3% for t <= 5 t0, 0.0141 +- 0.0003
 *    against 0.0141 +- 0.0003 (seeds 71-74) at 10 t0;
 *  - pinned sphere in fluid at rest, Green-Kubo int <F F> / kT: 132 at
 *    0.5 t0 (Enskog xi_E = 133.7, PL Eq. 40), plateau 60 +- 3 at 15-40 t0
 *    (1 / xi = 0.0167); pinned drag at v = 0.1 (test_coupling_drag, 4 seeds)
 *    58.4 +- 0.5; theory 50.8 (Hasimoto) to 52.0 (PL Eq. 43 on xi_S);
 *  - the window is diffusive: after 10 t0 D(t) adds 0.0013 (seed 11) to
 *    0.0025 (seeds 71-74) +- 0.0005, the driven response 0.0029; the
 *    transverse-mode sum of the periodic box (kT / rho L^3) sum_k (1 -
 *    k_x^2 / k^2) / (nu k^2) exp(-nu k^2 t) gives 0.0019; equilibrium near
 *    the colloid is right (density in the WCA shell = Boltzmann, shell
 *    temperatures 0.99-1.00, <V . v_i> at its Gibbs value -kT / M_total,
 *    total momentum exact); with 8 colloids D(t) still rises by ~5%
 *    between 30 and 50 t0 (PL Fig. 11: slower convergence at finite phi).
 * So the parallel sum of PL Eq. 41 with 4 pi eta sigma_cf overestimates the
 * mobility of this small (sigma_cf = 2 a0) slip colloid by ~15% (measured
 * xi ~ 60 against 51-52; the short-time Enskog part is right, the
 * hydrodynamic part acts like 1 / xi_S ~ 0.0093 instead of ~0.012).  No
 * paper-derived correction is known to us, and an Einstein-relation test
 * (D against kT / xi measured in the same run) needs ~3% on each side, i.e.
 * several minutes: more than the ~60 s budget of make check.  Enable with
 * such a comparison, or with a better prediction.  The pinned-sphere drag
 * one size up (sigma_cf = 3 a0, test_coupling_drag) agrees with PL Eqs.
 * 40-43 (-1.3 +- 2.7%), so the excess is a discretisation effect of
 * sigma_cf = 2 a0; a diffusion test at sigma_cf = 3 costs ~3.4x more. */
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
    if (quick) return;
    cr_expect_lt(tse / tm, 0.05, "VACF too noisy to judge: %.3f +- %.3f", tm, tse);
    cr_expect_lt(fabs(tm / tE - 1.0), 0.15, "decay time %.3f vs tau_E %.3f (PL Eq. 53)", tm, tE);
    cr_expect_lt(fabs(M * c0 - 1.0), 0.05, "equipartition: M <V^2> / kT = %.3f", M * c0);
}

Test(coupling_vacf, potential_diffusion, .timeout = 600, .disabled = true)
{
    int quick = pl_test_quick();
    long long steps = quick ? 800 : 40000;
    long long l1 = quick ? 20 : 200, l2 = quick ? 60 : 600; /* 20 .. 60 t0 */
    pl_sim_t *sim = pl_test_sim(SCENE, 1);
    size_t n = sim->colloids->n, m = 3 * n;
    double M = sim->colloids->mass[0];
    double *r = record(sim, 200, steps, 1);
    pl_sim_free(sim);
    double D[NB];
    long long bl = steps / NB;
    for (int b = 0; b < NB; ++b) {
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
    mean_se(D, NB, &Dm, &Dse);
    pl_srd_theory_t th;
    pl_srd_theory(GAMMA, 0.5 * PI, DT, 1.0, &th);
    double xi_E = pl_srd_xi_enskog(GAMMA, 1.0, SIGMA, M);                   /* PL Eq. 40 */
    double xi_inf = pl_srd_xi_parallel(4.0 * PI * th.eta * SIGMA, xi_E);     /* PL Eqs. 41-42 */
    double xi_L = pl_srd_xi_hasimoto(xi_inf, th.eta, L);
    double phi = (double)n * 4.0 / 3.0 * PI * SIGMA * SIGMA * SIGMA / (L * L * L);
    double D_th = (1.0 / xi_L) * (1.0 - 1.1795 * phi);                        /* PL Sec. VI.C */
    cr_log_info("MSD: D = %.5f +- %.5f, theory %.5f (kT/xi_inf %.5f, Hasimoto %.5f, phi %.3f): "
                "%+.1f%%; PL Eq. 43 reading %.5f",
                Dm, Dse, D_th, 1.0 / xi_inf, 1.0 / xi_L, phi, 100.0 * (Dm / D_th - 1.0),
                (1.0 - 1.1795 * phi) /
                    pl_srd_xi_parallel(pl_srd_xi_stokes_pl(th.eta, SIGMA, L), xi_E));
    if (quick) return;
    cr_expect_lt(Dse / Dm, 0.05, "MSD too noisy to judge: %.5f +- %.5f", Dm, Dse);
    cr_expect_lt(fabs(Dm / D_th - 1.0), 0.10, "D %.5f vs kT / xi %.5f (PL Eqs. 40-43)", Dm, D_th);
}
