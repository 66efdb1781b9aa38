/* Planar walls and the body force (issue 2).
 *
 * Poiseuille flow between no-slip walls, viscous heating removed by the
 * cell-rescaling thermostat (PL App. A, "thermostating under flow"), (bounce-back + virtual particles in
 * the cells the shifted grid cuts, Lamura et al. 2001): the steady profile is
 * v_x(z) = g z (Lz - z) / (2 nu).  The time-averaged layer velocities from
 * the fixed-point field accumulator are fitted with a + b z + c (z^2 + 1/12)
 * (cell averages of a parabola) over the layers not touching a wall; the
 * curvature gives nu = -g / (2c), compared with PL Eqs. 9-12 within 5% (3
 * standard errors from 10 blocks must fit inside; the periodic Kolmogorov
 * measurement of tests/physics/test_viscosity.c finds the same +2-3% at lambda 0.1).
 * No-slip: the slip length b = v(wall) / v'(wall) of the fitted parabola must
 * be below 0.3 a0 (we measure ~0.15 a0; with the walls' virtual particles
 * removed the fluid slips much more).
 * Slip walls (specular): the x-momentum grows by exactly N g dt per step. */
#include <math.h>
#include <stdio.h>

#include "peloid/srd_theory.h"
#include "support.h"

enum { NB = 10 };

static void fit_profile(const double *v, int Lz, double coef[3])
{
    /* least squares on basis (1, z, z^2 + 1/12), z = layer centre */
    double A[3][4] = {{0}};
    for (int k = 1; k < Lz - 1; ++k) {
        double z = k + 0.5, phi[3] = {1.0, z, z * z + 1.0 / 12.0};
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) A[i][j] += phi[i] * phi[j];
            A[i][3] += phi[i] * v[k];
        }
    }
    for (int i = 0; i < 3; ++i) /* Gauss-Jordan, well conditioned for Lz ~ 10 */
        for (int r = 0; r < 3; ++r) {
            if (r == i) continue;
            double f = A[r][i] / A[i][i];
            for (int c = 0; c < 4; ++c) A[r][c] -= f * A[i][c];
        }
    for (int i = 0; i < 3; ++i) coef[i] = A[i][3] / A[i][i];
}

Test(walls, poiseuille_between_noslip_walls, .timeout = 300)
{
    const int L = 12, Lz = 12;
    const double gamma = 5, lambda = 0.1, g = 0.012; /* v_max ~ 0.43: Ma ~ 0.3, uniform along x */
    pl_srd_theory_t th;
    pl_srd_theory(gamma, PL_RULE_RANDOM_AXIS, M_PI / 2, lambda, 1.0, &th);
    char scene[512];
    snprintf(scene, sizeof scene,
             "seed = 77;\nbox: { cells = [%d, %d, %d]; walls_z = \"noslip\"; };\n"
             "fluid: { density = %g; body_force = [%g, 0.0, 0.0]; };\nsrd: { dt = %g; alpha = 90.0; };\n"
             "thermostat: { type = \"rescale\"; };\noutput: { fields_interval = 2; };\n",
             L, L, Lz, gamma, g, lambda);
    pl_sim_t *sim = pl_test_sim(scene, 2);
    const long long relax = (long long)(3.0 * Lz * Lz / (M_PI * M_PI * th.nu) / lambda);
    const long long per = pl_test_quick() ? 100 : 1000;
    pl_test_steps(sim, relax);
    size_t L2 = (size_t)L * (size_t)L, L3 = L2 * (size_t)Lz;
    double nu[NB], slip[NB];
    int64_t *const acc = pl_srd_kept(sim->srd).field_acc; /* the fluid's time-averaged fields */
    for (int b = 0; b < NB; ++b) {
        memset(acc, 0, 4 * L3 * sizeof(int64_t));
        pl_test_steps(sim, per);
        double v[64];
        for (int k = 0; k < Lz; ++k) {
            double cnt = 0, px = 0;
            for (size_t c = (size_t)k * L2; c < (size_t)(k + 1) * L2; ++c) {
                cnt += (double)acc[c];
                px += (double)acc[L3 + c] / (double)(1LL << PL_FIELD_FIXED_SHIFT);
            }
            v[k] = px / cnt;
        }
        double co[3];
        fit_profile(v, Lz, co);
        nu[b] = -g / (2.0 * co[2]);
        if (getenv("PL_DEBUG") && b == NB - 1)
            for (int k = 0; k < Lz; ++k) printf("z=%4.1f v=%.5f theory=%.5f\n", k + 0.5, v[k], g / (2 * th.nu) * ((k + 0.5) * (Lz - k - 0.5) + 1.0 / 12.0));
        /* slip length at both walls, averaged: v(0)/v'(0) and v(Lz)/-v'(Lz) */
        double v0 = co[0], vL = co[0] + co[1] * Lz + co[2] * Lz * Lz;
        slip[b] = 0.5 * (v0 / co[1] + vL / -(co[1] + 2.0 * co[2] * Lz));
    }
    double s = 0, s2 = 0, sl = 0;
    for (int b = 0; b < NB; ++b) {
        s += nu[b];
        s2 += nu[b] * nu[b];
        sl += slip[b] / NB;
    }
    double mean = s / NB, sem = sqrt((s2 / NB - mean * mean) / (NB - 1));
    printf("poiseuille: nu = %.4f +- %.4f (PL %.4f, %+.2f%%), slip length %.3f a0\n", mean, sem,
           th.nu, 100 * (mean / th.nu - 1), sl);
    if (!pl_test_quick()) {
        cr_assert_lt(3 * sem / th.nu, 0.05, "statistical error too large");
        cr_assert_lt(fabs(mean / th.nu - 1), 0.05, "nu = %.4f +- %.4f vs %.4f", mean, sem, th.nu);
        cr_assert_lt(fabs(sl), 0.3, "slip length %.3f a0", sl);
    }
    pl_sim_free(sim);
}

Test(walls, slip_walls_body_force_accelerates_exactly)
{
    pl_sim_t *sim = pl_test_sim("seed = 4;\nbox: { cells = [6, 6, 6]; walls_z = \"slip\"; };\n"
                                "fluid: { body_force = [0.01, 0.0, 0.0]; };\nsrd: { dt = 0.5; };\n",
                                2);
    pl_fluid_obs_t o0, o1;
    double kT;
    pl_sim_observe(sim, &o0, &kT);
    pl_test_steps(sim, 100);
    pl_sim_observe(sim, &o1, &kT);
    double expect = (double)sim->fluid.n * 0.01 * 0.5 * 100;
    cr_assert(fabs(o1.momentum[0] - o0.momentum[0] - expect) < 1e-9 * expect, "P_x gained %.12g, expected %.12g",
              o1.momentum[0] - o0.momentum[0], expect);
    cr_assert(fabs(o1.momentum[1] - o0.momentum[1]) < 1e-9 * expect, "P_y changed");
    for (size_t i = 0; i < sim->fluid.n; ++i)
        cr_assert(sim->fluid.r[2][i] >= 0 && sim->fluid.r[2][i] <= 6, "particle %zu left the slab", i);
    pl_sim_free(sim);
}
