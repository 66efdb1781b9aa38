/* The random partner of the lubrication friction (lubrication.thermal,
 * kernels/colloid_forces.c): with it, colloids that interact only through
 * the squeeze friction of Hecht Eqs. 4-5 and a repulsion, with no fluid,
 * reach equipartition <M v^2> = 3 kT per degree of freedom (fluctuation-
 * dissipation theorem, as DPD's dissipative and random forces: Espanol &
 * Warren 1995); without it the same colloids cool.  Bitwise equality for 1
 * and 2 threads and across a restart: tests/unit/test_colloid_restart.c and
 * tests/unit/test_coupling_restart.c (scenes with lubrication). */
#include <math.h>
#include <string.h>

#include "colloid_test_util.h"

/* 125 colloids R = 2 a0 on a simple cubic lattice of spacing 4.4 a0 (box
 * 22^3): surface gaps 0.4 a0 to the six neighbours, inside the lubrication
 * cut-off gap of 1 a0; WCA (sigma = R_i + R_j, n = 24, 2.5 kT) keeps them
 * apart; no fluid, so the lubrication pairs are the colloids' only bath.
 * M = 5 x 4/3 pi 8 = 167.6, dt_MD = 0.025 t0; a pair at the lattice gap
 * has zeta / m_red = 0.71 /t0, at contact 10.7 /t0 (dt zeta / m_red = 0.27,
 * below the damping guard's 0.5).  %s: the thermal key. */
static const char *SCENE =
    "seed = 21;\nbox: { cells = [22, 22, 22]; };\nfluid: { density = 0.0; };\nsrd: { dt = 0.1; };\n"
    "colloids: { count = 125; radius = 2.0; temperature = 1.0; substeps = 4;\n"
    "  pairs = \"wca, lubrication\"; };\n"
    "lubrication: { viscosity = 2.5; min_gap = 0.05; cutoff_gap = 1.0; thermal = %s; };\n";

/* 2 sum M v^2 / 2 over 3 (N - 1) (total momentum zero: pair forces only). */
static double kinetic_T(const pl_colloid_t *c)
{
    double s = 0.0;
    for (size_t i = 0; i < c->n; ++i) s += c->mass[i] * (c->vx[i] * c->vx[i] + c->vy[i] * c->vy[i] + c->vz[i] * c->vz[i]);
    return s / (3.0 * (double)(c->n - 1));
}

enum { BURN = 800, SAMPLES = 5000, EVERY = 4, BLOCKS = 20 };

/* The kinetic temperature sampled every EVERY MD steps (one collision
 * step) over SAMPLES samples (500 t0) after BURN MD steps (20 t0), its mean
 * and the standard error from BLOCKS block means (a block is 250 samples =
 * 25 t0, long against the temperature's correlation time, ~3 t0 as the
 * SE shows: one sample's relative spread is sqrt(2 / (3 (N - 1))) = 0.073,
 * the measured SE ~0.006 is that of ~150 independent samples).  cold:
 * velocities zeroed at the start, so the temperature the run reaches is
 * what the noise gives. */
static void run(const char *thermal, int cold, double *mean, double *se)
{
    char text[1024];
    snprintf(text, sizeof text, SCENE, thermal);
    pl_scene_t s;
    scene_from(text, &s);
    pl_colloid_t *c;
    pl_err_t err;
    cr_assert_eq(pl_colloid_create(&s, 1, &c, &err), 0, "%s", err.msg);
    if (cold) {
        memset(c->vx, 0, c->n * sizeof(double));
        memset(c->vy, 0, c->n * sizeof(double));
        memset(c->vz, 0, c->n * sizeof(double));
    }
    for (int k = 0; k < BURN; ++k) cr_assert_eq(pl_colloid_md_step(c, &err), 0, "%s", err.msg);
    double blk[BLOCKS] = {0};
    for (int k = 0; k < SAMPLES; ++k) {
        for (int q = 0; q < EVERY; ++q) cr_assert_eq(pl_colloid_md_step(c, &err), 0, "%s", err.msg);
        blk[k / (SAMPLES / BLOCKS)] += kinetic_T(c) / (SAMPLES / BLOCKS);
    }
    double m = 0.0, v = 0.0;
    for (int b = 0; b < BLOCKS; ++b) m += blk[b] / BLOCKS;
    for (int b = 0; b < BLOCKS; ++b) v += (blk[b] - m) * (blk[b] - m) / (BLOCKS - 1);
    *mean = m;
    *se = sqrt(v / BLOCKS);
    pl_colloid_free(c);
}

/* With the noise: from rest, the kinetic temperature reaches kT = 1 within
 * 4 SE (SE from the block means, ~0.006; the test asks SE < 0.02 so that
 * 4 SE stays a sharp bound: half the noise variance gives 0.50, no noise
 * 0.00).  The discretisation: for the friction alone the full-step
 * velocities of this velocity Verlet (forces at the half-kicked
 * velocities, the random force of a time level shared by its two half
 * kicks) have exactly kT for any dt zeta / m_red < 2; with the WCA,
 * substeps = 8 (half the MD step) gave the same within its SE.  Without
 * the noise, from kT: the friction takes the temperature far below (< 0.3
 * kT over the same window), so the first check is not passed by a friction
 * too weak to matter. */
Test(colloid_lub_thermal, equipartition_with_noise_cools_without, .timeout = 60)
{
    double m, se;
    run("true", 1, &m, &se);
    cr_log_info("lubrication.thermal = true, from rest: T = %.4f +- %.4f kT", m, se);
    cr_expect_lt(se, 0.02, "SE %.4f too large for the bound", se);
    cr_expect_lt(fabs(m - 1.0), 4.0 * se, "T = %.4f +- %.4f, expected 1 (kT)", m, se);
    run("false", 0, &m, &se);
    cr_log_info("lubrication.thermal = false, from kT: T = %.4f +- %.4f kT", m, se);
    cr_expect_lt(m, 0.3, "without the noise the colloids should cool: T = %.4f", m);
}
