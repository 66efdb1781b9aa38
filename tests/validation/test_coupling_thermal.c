/* Equipartition (Hecht Sec. IX.A, Fig. 2b): colloids started cold reach the
 * fluid temperature through each coupling.  The colloid kinetic temperature
 * T_c = 2 K_trans / (3 N_c) (and 2 K_rot / (3 N_c) for stick surfaces) is
 * averaged over the run after a burn-in and compared with the time-averaged
 * fluid temperature.
 *
 * Tolerances: coupling II 3%, coupling I 7%, potential 5% (4000 steps, SE
 * ~1.3%; no thermostat, so the fluid itself warms by ~1-2% from the MD
 * integration of PL Eq. 17 and T_c is compared with the measured fluid T).  The standard error of T_c from
 * 10 block averages is logged (8000 steps: ~0.4% coupling II, ~1% coupling
 * I), so 3% is > 5 standard errors, and 7% is ~4 standard errors plus the
 * expected bias of coupling I: which particles hit
 * a colloid during a collision step is decided with its velocity at the
 * start of the step (explicit friction), which heats colloids by about
 * xi_E dt / 2M (PL Eq. 40: ~4% for R = 2 a0, M = 167 m_f, dt = 0.1; 11%
 * measured at M = 67 m_f).  A wrong coupling (no thermalisation, a missing
 * mass factor in Hecht Eq. 15, the colloid recoil left out of the thermal
 * wall: +25%) misses by far more.  Colloids are neutrally buoyant (mass
 * density = gamma, PL's choice). */
#include <math.h>
#include <stdio.h>

#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "support.h"

typedef struct {
    double tc, tc_se, tr, tf;
} temps_t;

static temps_t measure(const char *scene, long long steps, long long burn)
{
    pl_sim_t *sim = pl_test_sim(scene, 2);
    enum { NB = 10 };
    double blk[NB] = {0}, blkn[NB] = {0}, tr = 0.0, tf = 0.0;
    long long ns = 0;
    pl_test_steps(sim, burn);
    for (long long s = 0; s < steps; s += 5) {
        pl_test_steps(sim, 5);
        pl_colloid_energy_t e;
        pl_colloid_energy(sim->colloids, &e);
        double n3 = 3.0 * (double)sim->colloids->n;
        int b = (int)(s * NB / steps);
        blk[b] += 2.0 * e.kin_trans / n3;
        blkn[b] += 1.0;
        tr += 2.0 * e.kin_rot / n3;
        pl_fluid_obs_t o;
        double kT;
        pl_sim_observe(sim, &o, &kT);
        tf += kT;
        ns++;
    }
    pl_sim_free(sim);
    temps_t t = {0, 0, tr / (double)ns, tf / (double)ns};
    double m[NB], mean = 0.0, var = 0.0;
    for (int b = 0; b < NB; ++b) mean += (m[b] = blk[b] / blkn[b]) / NB;
    for (int b = 0; b < NB; ++b) var += (m[b] - mean) * (m[b] - mean) / (NB - 1);
    t.tc = mean;
    t.tc_se = sqrt(var / NB);
    return t;
}

static const char *BASE =
    "seed = 5;\n"
    "fluid: { density = 5.0; temperature = 1.0; };\n"
    "srd: { dt = 0.1; };\n";

Test(coupling_thermal, hecht1_stick_equipartition, .timeout = 300)
{
    char text[2048];
    snprintf(text, sizeof text,
             "%sbox: { cells = [14, 14, 14]; };\n"
             "colloids: { count = 8; radius = 2.0; mass_density = 5.0; temperature = 0.1;\n"
             "  init = \"lattice\"; pairs = \"hertz\"; substeps = 4; };\n"
             "coupling: { method = \"hecht1\"; boundary = \"stick_stochastic\"; };\n", BASE);
    long long steps = pl_test_quick() ? 100 : 8000;
    temps_t t = measure(text, steps, 200);
    cr_log_info("hecht1 stick: T_c = %.4f +- %.4f, T_rot = %.4f, T_fluid = %.4f", t.tc, t.tc_se,
                t.tr, t.tf);
    PL_SKIP_IF_QUICK("a statistical check of the full run");
    cr_expect_lt(fabs(t.tc / t.tf - 1.0), 0.07, "T_c %.4f vs fluid %.4f", t.tc, t.tf);
    cr_expect_lt(fabs(t.tr / t.tf - 1.0), 0.07, "T_rot %.4f vs fluid %.4f", t.tr, t.tf);
    cr_expect_lt(fabs(t.tf - 1.0), 0.03, "fluid held at the wall temperature: %.4f", t.tf);
}

Test(coupling_thermal, hecht1_slip_equipartition, .timeout = 300)
{
    char text[2048];
    snprintf(text, sizeof text,
             "%sbox: { cells = [14, 14, 14]; };\n"
             "colloids: { count = 8; radius = 2.0; mass_density = 5.0; temperature = 0.1;\n"
             "  init = \"lattice\"; pairs = \"hertz\"; substeps = 4; };\n"
             "coupling: { method = \"hecht1\"; boundary = \"slip\"; placement = \"entry\"; };\n",
             BASE);
    long long steps = pl_test_quick() ? 100 : 8000;
    temps_t t = measure(text, steps, 200);
    cr_log_info("hecht1 slip: T_c = %.4f +- %.4f, T_fluid = %.4f", t.tc, t.tc_se, t.tf);
    PL_SKIP_IF_QUICK("a statistical check of the full run");
    cr_expect_lt(fabs(t.tc / t.tf - 1.0), 0.07, "T_c %.4f vs fluid %.4f", t.tc, t.tf);
}

Test(coupling_thermal, hecht2_equipartition, .timeout = 300)
{
    char text[2048];
    snprintf(text, sizeof text,
             "%sbox: { cells = [12, 12, 12]; };\n"
             "colloids: { count = 27; radius = 1.0; mass_density = 5.0; temperature = 0.1;\n"
             "  init = \"lattice\"; pairs = \"\"; substeps = 1; max_overlap = 1.0; };\n"
             "coupling: { method = \"hecht2\"; };\n", BASE);
    long long steps = pl_test_quick() ? 100 : 8000;
    temps_t t = measure(text, steps, 200);
    cr_log_info("hecht2: T_c = %.4f +- %.4f, T_fluid = %.4f", t.tc, t.tc_se, t.tf);
    PL_SKIP_IF_QUICK("a statistical check of the full run");
    cr_expect_lt(fabs(t.tc / t.tf - 1.0), 0.03, "T_c %.4f vs fluid %.4f", t.tc, t.tf);
}

Test(coupling_thermal, potential_equipartition, .timeout = 300)
{
    char text[2048];
    snprintf(text, sizeof text,
             "%sbox: { cells = [14, 14, 14]; };\n"
             "colloids: { count = 8; radius = 2.0; mass_density = 5.0; temperature = 0.1;\n"
             "  init = \"lattice\"; pairs = \"hertz\"; substeps = 4; };\n"
             "coupling: { method = \"potential\"; sigma_cf = 2.0; };\n", BASE);
    long long steps = pl_test_quick() ? 100 : 4000;
    temps_t t = measure(text, steps, 200);
    cr_log_info("potential: T_c = %.4f +- %.4f, T_fluid = %.4f", t.tc, t.tc_se, t.tf);
    PL_SKIP_IF_QUICK("a statistical check of the full run");
    cr_expect_lt(fabs(t.tc / t.tf - 1.0), 0.05, "T_c %.4f vs fluid %.4f", t.tc, t.tf);
}

/* scenes/sediment.cfg as shipped: colloids settle under gravity into a layer
 * on the bottom no-slip wall (coupling II, DLVO + Hertz, Heyes thermostat)
 * and must then move at the fluid temperature (equipartition, Hecht Sec.
 * VIII.B).  The former scene (R = 2 a0 colloids of 653 m_f, each coupled to
 * the 5 fluid particles of one cell) gave T_c = 1.3-1.4 here: the energy
 * released by settling and by DLVO aggregation left the colloids only on
 * tau_E ~ 19 t0.  Burn-in 2000 steps (the layer forms by ~2000), then 2500
 * steps sampled every 5; the colloid velocity relaxes in tau_P = M/xi ~ 0.7
 * t0, so the samples are nearly independent: SE ~ sqrt(2/(3 N_c n)) ~ 0.4%,
 * logged from 10 blocks (measured 0.5%); 3% is > 5 SE. */
Test(coupling_thermal, hecht2_settled_on_wall, .timeout = 300)
{
    static pl_scene_t scene;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_scene_load("scenes/sediment.cfg", &scene, &err), 0, "%s", err.msg);
    pl_sim_t *sim = NULL;
    cr_assert_eq(pl_sim_create(&scene, 1, &sim, &err), 0, "%s", err.msg);
    long long burn = pl_test_quick() ? 10 : 2000, steps = pl_test_quick() ? 20 : 2500;
    pl_test_steps(sim, burn);
    enum { NB = 10 };
    double blk[NB] = {0}, blkn[NB] = {0}, tf = 0.0, zmean = 0.0, vz = 0.0;
    long long ns = 0;
    pl_colloid_t *c = sim->colloids; /* pl_colloid_energy evaluates the pair energies */
    for (long long s = 0; s < steps; s += 5) {
        pl_test_steps(sim, 5);
        pl_colloid_energy_t e;
        pl_colloid_energy(c, &e);
        int b = (int)(s * NB / steps);
        blk[b] += 2.0 * e.kin_trans / (3.0 * (double)c->n);
        blkn[b] += 1.0;
        for (size_t k = 0; k < c->n; ++k) {
            zmean += c->z[k] / (double)c->n;
            vz += c->vz[k] / (double)c->n;
        }
        pl_fluid_obs_t o;
        double kT;
        pl_sim_observe(sim, &o, &kT);
        tf += kT;
        ns++;
    }
    double R = scene.colloids.radius;
    pl_sim_free(sim);
    double m[NB], tc = 0.0, var = 0.0;
    for (int b = 0; b < NB; ++b) tc += (m[b] = blk[b] / blkn[b]) / NB;
    for (int b = 0; b < NB; ++b) var += (m[b] - tc) * (m[b] - tc) / (NB - 1);
    tf /= (double)ns;
    zmean /= (double)ns;
    vz /= (double)ns;
    cr_log_info("sediment settled: T_c = %.4f +- %.4f, T_fluid = %.4f, mean height %.3f a0 "
                "(R = %g), mean v_z %.2g", tc, sqrt(var / NB), tf, zmean, R, vz);
    PL_SKIP_IF_QUICK("a statistical check of the full run");
    cr_expect_lt(zmean, 3.0 * R, "colloids not settled: mean height %.3f a0", zmean);
    cr_expect_lt(fabs(tc / tf - 1.0), 0.03, "settled colloids at T_c %.4f vs fluid %.4f", tc, tf);
    cr_expect_lt(fabs(tf - 1.0), 0.01, "fluid held at the thermostat: %.4f", tf);
}
