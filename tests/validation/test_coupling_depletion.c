/* Spurious depletion (PL Sec. III.C.1, Fig. 4): eight colloids with the
 * potential coupling (sigma_cf = 2 a0, epsilon_cf = 2.5 kT, PL Eq. 17) in a
 * periodic 12^3 SRD box (gamma = 5, alpha = 90 deg, dt = 0.1, dt_MD = 0.025,
 * rescaling thermostat: PL's Fig. 4 parameters), volume fraction
 * phi_c = pi/6 n sigma_cc^3 = 0.22 (PL Eq. 25) with PL's sigma_cc.  The
 * contact value of g(r) is compared with Brownian dynamics of the same
 * colloid-colloid potential (PL Eq. 16, n = 24, epsilon_cc = 2.5 kT) run by
 * peloid's own colloids-only integrator: statics do not depend on the
 * dynamics, so any difference is an effective interaction the fluid adds.
 *
 * Observable: g averaged over the contact shell [0.9 sigma_cc, 2^{1/24}
 * sigma_cc] (the range of the repulsion, where the depletion well of PL
 * Eqs. 22-23 would act), sampled every collision step; the standard error
 * (SE) from 20 block averages of 200-400 t0.
 *
 * Cost: the colloid diffusion coefficient with this coupling is D ~ kT/xi
 * ~ 0.018 a0^2/t0 (xi ~ 56, tests/validation/test_coupling_drag.c), so a colloid
 * diffuses its radius in R^2/6D ~ 40 t0 and a contact (shell width ~0.5 a0)
 * renews in ~5 t0; 4000 t0 (40000 steps) give ~100 independent
 * configurations of the 28 pairs and a contact g with ~6% SE.  A smaller
 * box is ruled out by the colloid pair cut-off (minimum image) and the
 * coupling's selection shell.
 *
 * Case 1, PL's rule (wca.sigma_rule = "pl": sigma_cc = 4.4898 a0, the
 *   depletion potential there is 0 and -0.004 kT at 4.3 a0): agreement
 *   within 3 SE.  Measured: SRD 0.3230 +- 0.0203, BD 0.2850 +- 0.0079
 *   (+13%, +1.75 SE; a 2e5-step BD run gave 0.2906 +- 0.0055).
 * Case 2, too small a diameter, sigma_cc = 2 sigma_cf = 4 a0 (plain WCA
 *   contact): the depletion well (-0.68 kT at 4.0 a0, -0.24 kT at 4.1 a0,
 *   PL Eqs. 22-23) raises the contact g by ~46% at low density (Boltzmann
 *   estimate over the shell); asserted to exceed BD by more than 3 SE, and
 *   it is the case that shows case 1's assertion can fail.  Measured (20000
 *   steps): SRD 0.4038 +- 0.0360 vs BD 0.2387 +- 0.0064, +69% = +4.5 SE
 *   (40000 steps: 0.384 +- 0.026 vs 0.238 +- 0.005, +61% = +5.5 SE).
 *
 * Run time: 60000 SRD steps of ~10^4 fluid particles + 2 x 10^6 BD steps;
 * one thread (results are bitwise the same for any thread count, and one
 * thread stays fast on a shared, oversubscribed machine, where two spinning
 * threads were measured 10x slower): ~1 ms per SRD step, ~60 s.
 * Not asserted, measured once (40000 steps): the same sigma_cc = 4 a0 with
 *   the compensating term (pairs = "wca, depletion_comp") gives 0.290 +-
 *   0.018, +22% = 2.8 SE above BD: the compensation removes most of the
 *   excess, in line with PL's remark that it is needed but approximate. */
#include <math.h>
#include <stdio.h>

#include "peloid/colloid.h"
#include "support.h"

enum { NB = 20 };

typedef struct {
    double g, se;
} gc_t;

/* g averaged over [lo, hi) from the pair counts of every collision step,
 * with the SE of the mean from NB blocks. */
static gc_t contact_g(const char *text, int threads, long long burn, long long steps, double lo,
                      double hi)
{
    pl_sim_t *sim = pl_test_sim(text, threads);
    pl_test_steps(sim, burn);
    double blk[NB] = {0}, cnt[NB] = {0};
    const pl_colloid_t *c = sim->colloids;
    const double L = c->box[0];
    for (long long s = 0; s < steps; ++s) {
        pl_test_steps(sim, 1);
        double n = 0.0;
        for (size_t i = 0; i < c->n; ++i)
            for (size_t j = i + 1; j < c->n; ++j) {
                double dx = c->x[i] - c->x[j], dy = c->y[i] - c->y[j], dz = c->z[i] - c->z[j];
                dx -= L * rint(dx / L);
                dy -= L * rint(dy / L);
                dz -= L * rint(dz / L);
                double r = sqrt(dx * dx + dy * dy + dz * dz);
                n += r >= lo && r < hi;
            }
        int b = (int)(s * NB / steps);
        blk[b] += n;
        cnt[b] += 1.0;
    }
    double pairs = 0.5 * (double)c->n * (double)(c->n - 1);
    double ideal = pairs * 4.0 / 3.0 * M_PI * (hi * hi * hi - lo * lo * lo) / (L * L * L);
    pl_sim_free(sim);
    double m[NB], mean = 0.0, var = 0.0;
    for (int b = 0; b < NB; ++b) mean += (m[b] = blk[b] / cnt[b] / ideal) / NB;
    for (int b = 0; b < NB; ++b) var += (m[b] - mean) * (m[b] - mean) / (NB - 1);
    gc_t g = {mean, sqrt(var / NB)};
    return g;
}

static const char *SRD =
    "seed = 3;\n"
    "box: { cells = [12, 12, 12]; };\n"
    "fluid: { density = 5.0; temperature = 1.0; };\n"
    "srd: { dt = 0.1; alpha = 90.0; };\n"
    "thermostat: { type = \"rescale\"; temperature = 1.0; };\n"
    "colloids: { count = 8; radius = 2.0; mass_density = 5.0; temperature = 1.0;\n"
    "  init = \"lattice\"; pairs = \"wca\"; substeps = 4; };\n"
    "wca: { epsilon = 2.5; n = 24.0; %s };\n"
    "coupling: { method = \"potential\"; sigma_cf = 2.0; epsilon_cf = 2.5; };\n";

/* BD reference: D = kT / (6 pi eta R) = 0.027 at eta = 1, dt = 0.01 (rms
 * step 0.023 a0, a tenth of the repulsion's range sigma/n = 0.19 a0; dt/2
 * changes the contact g by +1.3% +- 3%); 1e4 t0 give an SE of ~2-3%. */
static const char *BD =
    "seed = 3;\n"
    "box: { cells = [12, 12, 12]; };\n"
    "fluid: { density = 0.0; };\n"
    "srd: { dt = 0.1; };\n"
    "colloids: { count = 8; radius = 2.0; temperature = 1.0; init = \"lattice\";\n"
    "  pairs = \"wca\"; integrator = \"brownian\"; bd_viscosity = 1.0; substeps = 10; };\n"
    "wca: { epsilon = 2.5; n = 24.0; %s };\n"
    "coupling: { sigma_cf = 2.0; };\n";

static void compare(const char *wca, long long steps, double sigma, gc_t *srd, gc_t *bd)
{
    char text[2048];
    double lo = 0.9 * sigma, hi = pow(2.0, 1.0 / 24.0) * sigma;
    snprintf(text, sizeof text, BD, wca);
    *bd = contact_g(text, 1, 1000, 100000, lo, hi);
    snprintf(text, sizeof text, SRD, wca);
    *srd = contact_g(text, 1, 1000, steps, lo, hi);
    double se = hypot(srd->se, bd->se);
    cr_log_info("%s: contact g SRD %.4f +- %.4f, BD %.4f +- %.4f: %+.1f%% = %+.2f SE", wca, srd->g,
                srd->se, bd->g, bd->se, 100.0 * (srd->g / bd->g - 1.0), (srd->g - bd->g) / se);
}

Test(coupling_depletion, pl_rule_matches_bd, .timeout = 900)
{
    gc_t srd, bd;
    compare("sigma_rule = \"pl\";", 40000, 2.0 * pow(2.0, 7.0 / 6.0), &srd, &bd);
    double se = hypot(srd.se, bd.se);
    cr_expect(fabs(srd.g - bd.g) < 3.0 * se, "PL rule: contact g SRD %.4f vs BD %.4f, SE %.4f", srd.g,
              bd.g, se);
}

Test(coupling_depletion, small_sigma_shows_depletion, .timeout = 900)
{
    gc_t srd, bd;
    compare("sigma = 4.0;", 20000, 4.0, &srd, &bd);
    double se = hypot(srd.se, bd.se);
    cr_expect(srd.g - bd.g > 3.0 * se, "sigma_cc = 2 sigma_cf: contact g SRD %.4f not above BD %.4f by 3 SE %.4f",
              srd.g, bd.g, se);
}
