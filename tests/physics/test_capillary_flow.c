/* Poiseuille flow in a square capillary (Hecht Sec. VIII.A option ii):
 * no-slip walls at x = 0, W and y = 0, W (box.walls_xy), periodic along z,
 * a body force g along z, viscous heating removed by the cell-rescaling
 * thermostat (PL App. A).  The steady flow in a square duct of side 2A
 * (centre at the origin) is the Boussinesq series
 *   u(x,y) = 16 A^2 g / (nu pi^3) sum_{n odd} (-1)^{(n-1)/2} n^-3
 *            [1 - cosh(n pi y / 2A) / cosh(n pi / 2)] cos(n pi x / 2A).
 * Bounce-back + virtual particles put the effective no-slip plane a slip
 * length b outside the walls (tests/physics/test_walls.c: b ~ 0.15 a0 between planar
 * walls), so A = W/2 + b.
 *
 * Measured from the time-averaged fields (fixed-point accumulator): the mean
 * velocity of all the fluid, u_mean (the flow rate over W^2), and the mean
 * velocity in the central 2x2 cell column, u_c.  Both are compared with the
 * series averaged over the same areas.  u_c / u_mean depends on b only
 * (the shape of the profile): inverting it gives b, which must lie within
 * 0.1 a0 of the planar 0.14 a0 (a slip wall gives a plug flow, ratio ~ 1).
 * With that b, u_mean gives nu, which must agree with PL Eqs. 9-12 within 5%
 * (the tolerance of the planar test; the SRD viscosity at lambda = 0.1 is
 * measured 2-3% above PL in tests/physics/test_viscosity.c).  Errors: 10 blocks,
 * 3 standard errors must fit inside the tolerances.
 *
 * Wall stress: in the steady flow the x/y walls take up the body force, so
 * the mean shear stress on them (thermo's s_side_z: the impulse they gave
 * the fluid per area 4 W Lz and time) is rho g W^2 / (4 W) = gamma g W / 4;
 * checked per block against that within 3 standard errors (the fluid's
 * momentum fluctuations, ~sqrt(N kT) over a block of 400 t0, are ~0.2% of
 * it), and the x, y components vanish (|mean| < 3 SE). */
#include <math.h>
#include <stdio.h>

#include "peloid/srd_theory.h"
#include "support.h"

enum { NB = 10 };

/* Series u(x,y) of a square duct of half-width A (g / nu = 1) averaged over
 * the square |x|, |y| <= h centred on the axis (h <= A). */
static double duct_average(double h, double A)
{
    double s = 0.0;
    for (int n = 1; n < 400; n += 2) {
        const double sn = ((n - 1) / 2) % 2 ? -1.0 : 1.0, k = n * M_PI / (2.0 * A);
        /* int_{-h}^{h} cos(kx) dx = 2 sin(kh)/k, int cosh(ky) dy = 2 sinh(kh)/k;
         * sinh/cosh written to avoid overflow of cosh(n pi / 2) */
        const double ratio = exp(k * h - n * M_PI / 2.0) * (1.0 - exp(-2.0 * k * h)) /
                             (1.0 + exp(-n * M_PI));
        s += sn / ((double)n * n * n) * (2.0 * h - 2.0 / k * ratio) * (2.0 / k) * sin(k * h);
    }
    return 16.0 * A * A / (M_PI * M_PI * M_PI) * s / (4.0 * h * h);
}

/* u_c / u_mean of the series for walls W apart and slip length b. */
static double shape_ratio(double W, double b)
{
    return duct_average(1.0, 0.5 * W + b) / duct_average(0.5 * W, 0.5 * W + b);
}

/* The slip length whose series gives shape ratio q (bisection; the ratio
 * falls monotonically with b). */
static double slip_from_ratio(double W, double q)
{
    double lo = 0.0, hi = 2.0; /* b < 0 would put fluid outside the series' duct */
    if (q >= shape_ratio(W, lo)) return lo;
    if (q <= shape_ratio(W, hi)) return hi;
    for (int it = 0; it < 60; ++it) {
        double mid = 0.5 * (lo + hi);
        if (shape_ratio(W, mid) > q) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

static void mean_sem(const double *x, double *mean, double *sem)
{
    double s = 0.0, s2 = 0.0;
    for (int b = 0; b < NB; ++b) {
        s += x[b];
        s2 += x[b] * x[b];
    }
    *mean = s / NB;
    *sem = sqrt(fmax(s2 / NB - *mean * *mean, 0.0) / (NB - 1));
}

Test(capillary, poiseuille_in_a_square_duct, .timeout = 300)
{
    const int W = 10, Lz = 8;
    const double gamma = 5, lambda = 0.1, g = 0.025, b_planar = 0.14;
    pl_srd_theory_t th;
    pl_srd_theory(gamma, PL_RULE_RANDOM_AXIS, M_PI / 2, lambda, 1.0, &th);
    char scene[512];
    snprintf(scene, sizeof scene,
             "seed = 91;\nbox: { cells = [%d, %d, %d]; walls_xy = \"noslip\"; };\n"
             "fluid: { density = %g; body_force = [0.0, 0.0, %g]; };\nsrd: { dt = %g; alpha = 90.0; };\n"
             "thermostat: { type = \"rescale\"; };\noutput: { fields_interval = 2; };\n",
             W, W, Lz, gamma, g, lambda);
    pl_sim_t *sim = pl_test_sim(scene, 2);
    /* slowest mode of the duct decays as exp(-2 pi^2 nu t / W^2): 6 times that */
    const long long relax = (long long)(6.0 * W * W / (2.0 * M_PI * M_PI * th.nu) / lambda);
    const long long per = pl_test_quick() ? 100 : 4000;
    pl_test_steps(sim, relax);
    const size_t L2 = (size_t)W * (size_t)W, L3 = L2 * (size_t)Lz;
    const double fix = 1.0 / (double)(1LL << PL_FIELD_FIXED_SHIFT);
    double um[NB], uc[NB], slip[NB], nu[NB], tau[3][NB];
    int64_t *const acc = pl_srd_kept(sim->srd).field_acc; /* the fluid's time-averaged fields */
    for (int b = 0; b < NB; ++b) {
        memset(acc, 0, 4 * L3 * sizeof(int64_t));
        double I0[3];
        for (int d = 0; d < 3; ++d) I0[d] = sim->wall_impulse[2][d];
        pl_test_steps(sim, per);
        for (int d = 0; d < 3; ++d) /* force per area on the walls */
            tau[d][b] = -(sim->wall_impulse[2][d] - I0[d]) / (4.0 * W * Lz * (double)per * lambda);
        double n_all = 0, p_all = 0, n_c = 0, p_c = 0;
        for (size_t c = 0; c < L3; ++c) {
            const int ix = (int)(c % (size_t)W), iy = (int)(c / (size_t)W % (size_t)W);
            const double cnt = (double)acc[c], pz = (double)acc[3 * L3 + c] * fix;
            n_all += cnt;
            p_all += pz;
            if (abs(2 * ix + 1 - W) <= 2 && abs(2 * iy + 1 - W) <= 2) { /* central 2x2 column */
                n_c += cnt;
                p_c += pz;
            }
        }
        um[b] = p_all / n_all;
        uc[b] = p_c / n_c;
        slip[b] = slip_from_ratio(W, uc[b] / um[b]);
        nu[b] = g * duct_average(0.5 * W, 0.5 * W + slip[b]) / um[b];
    }
    double mum, sum_, muc, suc, mb, sb, mnu, snu;
    mean_sem(um, &mum, &sum_);
    mean_sem(uc, &muc, &suc);
    mean_sem(slip, &mb, &sb);
    mean_sem(nu, &mnu, &snu);
    double mt[3], st[3];
    for (int d = 0; d < 3; ++d) mean_sem(tau[d], &mt[d], &st[d]);
    const double tau_th = gamma * g * W / 4.0;
    printf("capillary poiseuille: wall stress (x, y, z) = %.3g +- %.2g, %.3g +- %.2g, %.5f +- %.5f "
           "(gamma g W / 4 = %.5f, %+.2f%%)\n",
           mt[0], st[0], mt[1], st[1], mt[2], st[2], tau_th, 100 * (mt[2] / tau_th - 1));
    /* the series with PL's nu and the planar slip length */
    const double A = 0.5 * W + b_planar;
    const double um_th = g / th.nu * duct_average(0.5 * W, A), uc_th = g / th.nu * duct_average(1.0, A);
    printf("capillary poiseuille: u_mean = %.5f +- %.5f (series %.5f, %+.2f%%), "
           "u_c(2x2) = %.5f +- %.5f (series %.5f, %+.2f%%), u_c/u_mean = %.4f (series %.4f)\n",
           mum, sum_, um_th, 100 * (mum / um_th - 1), muc, suc, uc_th, 100 * (muc / uc_th - 1),
           muc / mum, shape_ratio(W, b_planar));
    printf("capillary poiseuille: slip length b = %.3f +- %.3f a0 (planar %.2f), "
           "nu = %.4f +- %.4f (PL %.4f, %+.2f%%)\n",
           mb, sb, b_planar, mnu, snu, th.nu, 100 * (mnu / th.nu - 1));
    if (!pl_test_quick()) {
        cr_assert_lt(3 * sb, 0.1, "statistical error of b too large: %.3f", sb);
        cr_assert_lt(3 * snu / th.nu, 0.05, "statistical error of nu too large");
        cr_assert_lt(fabs(mb - b_planar), 0.1, "slip length %.3f +- %.3f a0, planar %.2f", mb, sb, b_planar);
        cr_assert_lt(fabs(mnu / th.nu - 1), 0.05, "nu = %.4f +- %.4f vs PL %.4f", mnu, snu, th.nu);
        cr_assert_lt(fabs(mt[2] - tau_th), 3 * st[2] + 1e-12, "wall stress %.5f +- %.5f vs gamma g W / 4 = %.5f",
                     mt[2], st[2], tau_th);
        cr_assert_lt(st[2], 0.01 * tau_th, "wall stress too noisy: %.5f +- %.5f", mt[2], st[2]);
        for (int d = 0; d < 2; ++d)
            cr_assert_lt(fabs(mt[d]), 3 * st[d] + 1e-12, "wall stress component %d: %.3g +- %.2g", d, mt[d], st[d]);
    }
    pl_sim_free(sim);
}
