/* Plane Couette flow between moving no-slip walls (shear, Hecht Sec. VIII.C).
 *
 * 8 x 8 x 16 cells, walls at z = 0 and Lz moving with -u/2 and +u/2 along x
 * (bounce-back in the wall frame + virtual particles moving with the wall),
 * viscous heating removed by a thermostat acting on velocities relative to
 * the cell mean.  After a transient of 5 momentum-diffusion times
 * Lz^2 / (pi^2 nu), NB blocks of time-averaged layer velocities v_x(z) (field
 * accumulator) and wall impulses.  Per block: least-squares line through the
 * layers not touching a wall, and the shear stress from each wall's momentum
 * (PL Eq. 13).  Statistical errors: standard error of the NB block means.
 *
 *  - linearity: chi^2 of the block-mean profile about its line, with each
 *    layer's own block SE, below the 0.1% quantile of chi^2 with Lz - 4
 *    degrees of freedom;
 *  - slope = u / (Lz + 2 b) with the slip length b = 0.14 a0 of the
 *    Poiseuille test (tests/physics/test_walls.c), within 3 SE (the slope SE is
 *    ~0.4%; b = 0 would be 1.75% off);
 *  - both walls measure the same stress, within 3 SE of the difference;
 *  - eta = stress / slope vs PL Eqs. 14-15: within 5%, the known accuracy
 *    of PL Eqs. 9-12 at lambda = 0.1 (tests/physics/test_viscosity.c: +2.3 +- 0.6%
 *    for Kolmogorov flow), with 3 SE < 5% required so that the comparison
 *    means something.
 * Measured (2-core machine, ~18 s per thermostat): rescale: slope 0.06132 +-
 * 0.00046 (slip 0.155 +- 0.061 a0), stress 0.1550 +- 0.0018 (bottom) and
 * 0.1552 +- 0.0020 (top), eta 2.531 +- 0.033 vs PL 2.496 (+1.4%); Heyes:
 * slip 0.22 +- 0.04 a0, eta 2.572 +- 0.029 (+3.0%).
 * Shown to fail: virtual particles not moving with the wall (slope 0.0197);
 * the virtual particles' push left out of the stress (eta -56%).  Not
 * resolvable here: a rescale thermostat acting on absolute velocities (at this
 * shear rate its factor differs from 1 by ~6e-5 per step, a friction 30x
 * slower than the momentum diffusion); that Heyes leaves each cell's momentum
 * is tested in tests/unit/test_collide.c, rescale scales v - u_cell (PL App. A). */
#include <math.h>
#include <stdio.h>

#include "peloid/coupling.h"
#include "peloid/srd_theory.h"
#include "support.h"

enum { NB = 10, LZ = 16 };

typedef struct {
    double slope, icpt, stress[2], v[LZ];
} block_t;

static double mean_se(const double *x, int n, size_t stride, double *se)
{
    double s = 0, s2 = 0;
    for (int b = 0; b < n; ++b) {
        double v = x[(size_t)b * stride];
        s += v;
        s2 += v * v;
    }
    double m = s / n;
    *se = sqrt(fmax(s2 / n - m * m, 0.0) / (n - 1));
    return m;
}

/* Line a + b z through layers 1 .. Lz-2 (centres z = k + 1/2). */
static void fit_line(const double *v, double *a, double *b)
{
    double n = 0, sz = 0, sv = 0, szz = 0, szv = 0;
    for (int k = 1; k < LZ - 1; ++k) {
        double z = k + 0.5;
        n += 1; sz += z; sv += v[k]; szz += z * z; szv += z * v[k];
    }
    *b = (n * szv - sz * sv) / (n * szz - sz * sz);
    *a = (sv - *b * sz) / n;
}

static void run_couette(const char *thermostat, double u, double *eta_out)
{
    const int L = 8;
    const double gamma = 5, lambda = 0.1;
    pl_srd_theory_t th;
    pl_srd_theory(gamma, PL_RULE_RANDOM_AXIS, M_PI / 2, lambda, 1.0, &th);
    char scene[768];
    snprintf(scene, sizeof scene,
             "seed = 21;\nbox: { cells = [%d, %d, %d]; walls_z = \"noslip\";\n"
             "  wall_velocity_bottom = [%g, 0.0, 0.0]; wall_velocity_top = [%g, 0.0, 0.0]; };\n"
             "fluid: { density = %g; };\nsrd: { dt = %g; alpha = 90.0; };\n"
             "thermostat: { type = \"%s\"; };\noutput: { fields_interval = 2; };\n",
             L, L, LZ, -0.5 * u, 0.5 * u, gamma, lambda, thermostat);
    pl_sim_t *sim = pl_test_sim(scene, 2);
    const long long relax = (long long)(5.0 * LZ * LZ / (M_PI * M_PI * th.nu) / lambda);
    const long long per = pl_test_quick() ? 100 : 2000;
    pl_test_steps(sim, pl_test_quick() ? 200 : relax);
    size_t L2 = (size_t)L * (size_t)L, L3 = L2 * LZ;
    block_t bl[NB];
    int64_t *const acc = pl_srd_kept(sim->srd).field_acc; /* the fluid's time-averaged fields */
    for (int b = 0; b < NB; ++b) {
        memset(acc, 0, 4 * L3 * sizeof(int64_t));
        double imp0[2] = {sim->wall_impulse[0][0], sim->wall_impulse[1][0]};
        pl_test_steps(sim, per);
        for (int k = 0; k < LZ; ++k) {
            double cnt = 0, px = 0;
            for (size_t c = (size_t)k * L2; c < (size_t)(k + 1) * L2; ++c) {
                cnt += (double)acc[c];
                px += (double)acc[L3 + c] / (double)(1LL << PL_FIELD_FIXED_SHIFT);
            }
            bl[b].v[k] = px / cnt;
        }
        fit_line(bl[b].v, &bl[b].icpt, &bl[b].slope);
        const double at = (double)L2 * (double)per * lambda; /* wall area x block time */
        bl[b].stress[0] = -(sim->wall_impulse[0][0] - imp0[0]) / at; /* sigma_xz from F_bottom */
        bl[b].stress[1] = (sim->wall_impulse[1][0] - imp0[1]) / at;  /* ... and from F_top */
    }
    const size_t st = sizeof(block_t) / sizeof(double);
    double se_slope, se_s0, se_s1, se_d, diff[NB], eta[NB], se_eta;
    const double slope = mean_se(&bl[0].slope, NB, st, &se_slope);
    const double s0 = mean_se(&bl[0].stress[0], NB, st, &se_s0);
    const double s1 = mean_se(&bl[0].stress[1], NB, st, &se_s1);
    for (int b = 0; b < NB; ++b) {
        diff[b] = bl[b].stress[1] - bl[b].stress[0];
        eta[b] = 0.5 * (bl[b].stress[0] + bl[b].stress[1]) / bl[b].slope;
    }
    const double d = mean_se(diff, NB, 1, &se_d);
    const double eta_m = mean_se(eta, NB, 1, &se_eta);
    /* linearity of the block-mean profile, each layer with its own SE */
    double vm[LZ], vse[LZ], a, bb, chi2 = 0;
    for (int k = 0; k < LZ; ++k) vm[k] = mean_se(&bl[0].v[k], NB, st, &vse[k]);
    fit_line(vm, &a, &bb);
    for (int k = 1; k < LZ - 1; ++k) chi2 += pow((vm[k] - a - bb * (k + 0.5)) / vse[k], 2);
    const double b_slip = 0.14, expect = u / (LZ + 2.0 * b_slip);
    const double b_meas = 0.5 * (u / slope - LZ), b_se = 0.5 * u * se_slope / (slope * slope);
    const double eta_pl = gamma * th.nu; /* PL Eqs. 14-15 (m_f = 1) */
    printf("couette (%s, u = %g): slope %.6f +- %.6f (u/(Lz+2b) %.6f, u/Lz %.6f) -> slip %.3f +- %.3f a0; "
           "chi2 %.1f (%d dof); stress bottom %.5f +- %.5f, top %.5f +- %.5f; eta %.4f +- %.4f vs "
           "PL %.4f (%+.2f%%); T %.4f\n",
           thermostat, u, slope, se_slope, expect, u / LZ, b_meas, b_se, chi2, LZ - 4, s0, se_s0, s1,
           se_s1, eta_m, se_eta, eta_pl, 100 * (eta_m / eta_pl - 1), *pl_srd_kept(sim->srd).kT_cell);
    if (getenv("PL_DEBUG"))
        for (int k = 0; k < LZ; ++k)
            printf("  z=%5.1f v=%+.5f +- %.5f line %+.5f\n", k + 0.5, vm[k], vse[k], a + bb * (k + 0.5));
    if (!pl_test_quick()) {
        cr_assert_lt(chi2, 32.9, "profile not linear: chi2 %.1f with %d dof", chi2, LZ - 4); /* p = 0.001 */
        cr_assert_lt(fabs(slope - expect), 3 * se_slope, "slope %.6f +- %.6f vs %.6f", slope, se_slope, expect);
        cr_assert_lt(fabs(d), 3 * se_d + 1e-12, "walls disagree: %.5f +- %.5f", d, se_d);
        cr_assert_lt(3 * se_eta / eta_pl, 0.05, "statistical error too large");
        cr_assert_lt(fabs(eta_m / eta_pl - 1), 0.05, "eta %.4f +- %.4f vs %.4f", eta_m, se_eta, eta_pl);
    }
    if (eta_out) *eta_out = eta_m;
    pl_sim_free(sim);
}

Test(shear, couette_between_moving_walls_rescale, .timeout = 300)
{
    run_couette("rescale", 1.0, NULL);
}

Test(shear, couette_between_moving_walls_heyes, .timeout = 300)
{
    run_couette("heyes", 1.0, NULL);
}

/* Momentum balance with moving walls, for the fluid alone and each coupling:
 * the tangential momentum of fluid + colloids changes by exactly the wall
 * impulse that sim->wall_impulse (the stress columns) counts: streaming
 * bounce-backs, virtual particles, coupling I pushes through a wall, the
 * potential coupling's own wall reflections minus the streaming it replaces.
 * Tolerance: the fixed-point rounding (2^-33 per event, ~1e4 events per step)
 * and double sums of momenta ~1e2: 1e-7 absolute against sqrt(M kT) ~ 1e2. */
Test(shear, wall_impulse_balances_momentum_for_every_coupling, .timeout = 120)
{
    static const char *couplings[] = {"", "coupling: { method = \"hecht1\"; };\n",
                                      "coupling: { method = \"hecht1\"; boundary = \"slip\"; placement = \"nearest\"; };\n",
                                      "coupling: { method = \"hecht2\"; };\n",
                                      "coupling: { method = \"potential\"; sigma_cf = 2.0; };\n",
                                      "coupling: { method = \"hecht2\"; };\n"};
    /* the last case: Hecht's small colloids (R = 0.62 a0), whose centres
     * enter collision cells cut by a wall, where coupling II adds the
     * virtual particles and corrects the wall's count */
    static const char *colloids[] = {"", "colloids: { count = 8; radius = 2.0; init = \"random\"; pairs = \"hertz\"; };\n",
                                     "colloids: { count = 60; radius = 0.62; init = \"random\"; pairs = \"hertz\"; substeps = 16; };\n"};
    for (size_t k = 0; k < sizeof couplings / sizeof *couplings; ++k) {
        char scene[1024];
        snprintf(scene, sizeof scene,
                 "seed = 5;\nbox: { cells = [10, 10, 10]; walls_z = \"noslip\";\n"
                 "  wall_velocity_bottom = [-0.3, 0.2, 0.0]; wall_velocity_top = [0.3, -0.1, 0.0]; };\n"
                 "fluid: { density = 5.0; };\nsrd: { dt = 0.1; };\nthermostat: { type = \"heyes\"; };\n"
                 "%s%s",
                 colloids[k == 5 ? 2 : *couplings[k] ? 1 : 0], couplings[k]);
        pl_sim_t *sim = pl_test_sim(scene, 2);
        double P0[3], P1[3], M, W0[2] = {0, 0}, B0[2];
        pl_test_steps(sim, 5);
        pl_coupling_total_momentum(sim, P0, &M);
        for (int d = 0; d < 2; ++d) {
            W0[d] = sim->wall_impulse[0][d] + sim->wall_impulse[1][d];
            B0[d] = sim->wall_impulse[0][d];
        }
        pl_test_steps(sim, pl_test_quick() ? 10 : 100);
        pl_coupling_total_momentum(sim, P1, &M);
        for (int d = 0; d < 2; ++d) {
            double W = sim->wall_impulse[0][d] + sim->wall_impulse[1][d] - W0[d];
            double B = sim->wall_impulse[0][d] - B0[d];
            cr_assert(fabs(B) > 1.0, "case %zu: the bottom wall gave no momentum (%g)", k, B);
            cr_assert(fabs(P1[d] - P0[d] - W) < 1e-7, "case %zu, d %d: momentum changed by %.12g, walls gave %.12g",
                      k, d, P1[d] - P0[d], W);
        }
        pl_sim_free(sim);
    }
}
