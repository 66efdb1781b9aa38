/* Multiple time stepping of the colloid MD (colloids.slow_interval, r-RESPA):
 * the force split adds up to the one-step force, Newton's third law holds
 * for the slow share, and the NVE energy is conserved as well as by the
 * one-step integrator at the same inner step.  Thread-count independence and
 * restart: tests/unit/test_colloid_restart.c (its multiple time stepping scene). */
#include <math.h>

#include "colloid_test_util.h"

/* Hecht Fig. 14 colloids in model units (R = 0.62 a0, Psi0 = 50 mV, kappa =
 * 3e8 /m: a 222 kT barrier at gap 0.0036 a0 and a 6.3 kT secondary minimum
 * at 0.047 a0), no fluid, random positions (all gaps, the switching range
 * of the split included). */
static void fig14_scene_pairs(char *buf, size_t n, int count, int cells, int substeps, int k, int random,
                              const char *pairs)
{
    snprintf(buf, n,
             "seed = 3;\nbox: { cells = [%d, %d, %d]; };\nfluid: { density = 0.0; };\nsrd: { dt = 0.1; };\n"
             "colloids: { count = %d; radius = 0.62; mass_density = 39.0; temperature = 1.0;\n"
             "  init = \"%s\"; pairs = \"%s\"; substeps = %d; slow_interval = %d;\n"
             "  max_energy_drift = 0.0; min_contact_steps = %s; };\n"
             "dlvo: { psi0 = 50.0; kappa = 3.0e8; hamaker = 4.76e-20; length_unit = 4.03e-7; primary_depth = 6.0; };\n"
             "hertz: { K = 1000.0; };\n",
             cells, cells, cells, count, random ? "random" : "lattice", pairs, substeps, k,
             random ? "0.0" : "20.0" /* random gaps reach the barrier: forces only */);
}

static void fig14_scene(char *buf, size_t n, int count, int cells, int substeps, int k, int random)
{
    fig14_scene_pairs(buf, n, count, cells, substeps, k, random, "dlvo, hertz");
}

/* with and without lubrication (a velocity-dependent fast term reaching
 * beyond 2 slow_gap: lubrication.cutoff_gap = 1 a0) */
static void split_adds_up(const char *pairs)
{
    char one[1024], split[1024];
    fig14_scene_pairs(one, sizeof one, 200, 9, 10, 1, 1, pairs);
    fig14_scene_pairs(split, sizeof split, 200, 9, 10, 5, 1, pairs);
    pl_sim_t *a = pl_test_sim(one, 2), *b = pl_test_sim(split, 2);
    const pl_colloid_t *ca = a->colloids, *cb = b->colloids;
    cr_assert_eq(ca->n, cb->n);
    cr_assert(cb->fsx && !ca->fsx);
    double fbig = 0.0, smax = 0.0, sum[3] = {0, 0, 0}, asum = 0.0;
    for (size_t i = 0; i < ca->n; ++i) fbig = fmax(fbig, fmax(fabs(ca->fx[i]), fmax(fabs(ca->fy[i]), fabs(ca->fz[i]))));
    int slow_only = 0;
    for (size_t i = 0; i < ca->n; ++i) {
        const double full[3] = {ca->fx[i], ca->fy[i], ca->fz[i]};
        const double fast[3] = {cb->fx[i], cb->fy[i], cb->fz[i]};
        const double slow[3] = {cb->fsx[i], cb->fsy[i], cb->fsz[i]};
        for (int d = 0; d < 3; ++d) {
            smax = fmax(smax, fabs(slow[d]));
            sum[d] += slow[d];
            asum += fabs(slow[d]);
            /* the same pair forces grouped otherwise: rounding only.  Bound:
             * 1e-10 of the colloid's own force plus 1e-12 of the largest
             * (a colloid deep in the barrier, 1e5 kT/a0); one missed pair
             * changes a force by at least the truncation force at the
             * cut-off, 2e-3 kT/a0, far above both */
            double tol = 1e-10 * fmax(fabs(full[d]), fabs(fast[d])) + 1e-12 * fbig;
            cr_assert_leq(fabs(fast[d] + slow[d] - full[d]), tol,
                          "colloid %zu axis %d: fast %.17g + slow %.17g != full %.17g", i, d, fast[d],
                          slow[d], full[d]);
        }
        slow_only += fabs(slow[0]) > 0.0 && fast[0] == 0.0;
    }
    /* the split is not trivial: slow forces of the secondary minimum's scale
     * (kT/a0 and more), and colloids whose only forces are slow (no pair
     * within 2 slow_gap) */
    cr_assert_gt(smax, 1.0, "largest slow force %g kT/a0", smax);
    if (!strstr(pairs, "lubrication")) cr_assert_gt(slow_only, 0);
    /* Newton's third law for the slow share: the total is rounding */
    for (int d = 0; d < 3; ++d) cr_assert_leq(fabs(sum[d]), 1e-12 * asum, "sum of slow forces %g (of %g)", sum[d], asum);
    pl_sim_free(a);
    pl_sim_free(b);
}

Test(colloid_mts, fast_and_slow_shares_add_up_to_the_full_force) { split_adds_up("dlvo, hertz"); }
Test(colloid_mts, fast_and_slow_shares_add_up_with_lubrication) { split_adds_up("dlvo, hertz, lubrication"); }

static double drift(const char *scene, long long steps)
{
    pl_sim_t *s = pl_test_sim(scene, 2);
    pl_colloid_energy_t e;
    pl_colloid_energy(s->colloids, &e);
    const double e0 = e.total;
    double m = 0.0;
    for (long long k = 0; k < steps; ++k) {
        pl_test_steps(s, 1);
        pl_colloid_energy(s->colloids, &e);
        m = fmax(m, fabs(e.total - e0));
    }
    const double n = (double)s->colloids->n;
    pl_sim_free(s);
    return m / n;
}

/* NVE from the lattice (nearest gaps 0.19 a0, inside the switching range),
 * 125 MD steps of 8e-4 t0 per collision step: the one-step drift is velocity
 * Verlet's (~1e-4 kT per colloid here).  An outer step of 5 MD steps that
 * is right keeps it (tools/mts_error.py measures the same on 1155 colloids:
 * 9.7e-5 against 1.2e-4); a slow kick of the wrong length or at the wrong
 * time gives the slow force's work error, larger by orders of magnitude (a
 * 25-step outer step already gives 1e-3).  Bound: 3x the one-step drift. */
Test(colloid_mts, outer_step_of_five_conserves_energy_like_one_step, .timeout = 300)
{
    PL_SKIP_IF_QUICK("an NVE run of 2500 MD steps at two settings");
    char one[1024], split[1024];
    fig14_scene(one, sizeof one, 216, 9, 125, 1, 0);
    fig14_scene(split, sizeof split, 216, 9, 125, 5, 0);
    const double d1 = drift(one, 20), d5 = drift(split, 20);
    cr_assert_gt(d1, 0.0);
    cr_log_info("energy drift per colloid: %g (slow_interval 1), %g (5)", d1, d5);
    cr_assert_leq(d5, 3.0 * d1, "energy drift %g kT per colloid with slow_interval 5, %g with 1", d5, d1);
}

/* A physical scene derives its substeps; with slow_interval they are rounded
 * up to a multiple of it (an outer step ends with the collision step).
 * scenes/hecht_fig14.cfg derives 127 (the contact guard): 130 with k = 5. */
Test(colloid_mts, physical_scene_rounds_the_substeps_up_to_a_multiple)
{
    FILE *f = fopen("scenes/hecht_fig14.cfg", "r");
    cr_assert(f, "scenes/hecht_fig14.cfg (run from the repository root)");
    static char text[16384];
    size_t len = fread(text, 1, sizeof text - 64, f);
    fclose(f);
    text[len] = '\0';
    static pl_scene_t one, split;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_scene_load_string(text, "hecht_fig14.cfg", &one, &err), 0, "%s", err.msg);
    const char *old = "pairs = \"dlvo, hertz\"; };";
    char *at = strstr(text, old);
    cr_assert(at, "the scene's colloids{} line changed");
    memmove(at + strlen(old) - 2 + strlen(" slow_interval = 5;"), at + strlen(old) - 2, strlen(at + strlen(old) - 2) + 1);
    memcpy(at + strlen(old) - 2, " slow_interval = 5;", strlen(" slow_interval = 5;"));
    cr_assert_eq(pl_scene_load_string(text, "hecht_fig14.cfg", &split, &err), 0, "%s", err.msg);
    cr_assert_eq(split.colloids.slow_interval, 5);
    cr_assert_eq(one.colloids.substeps % 5 == 0, 0, "the test needs a derived count that is not a multiple: %lld",
                 one.colloids.substeps);
    cr_assert_eq(split.colloids.substeps, (one.colloids.substeps / 5 + 1) * 5, "%lld from %lld",
                 split.colloids.substeps, one.colloids.substeps);
}

/* With adaptive substeps a collision step's MD count need not be a multiple
 * of slow_interval: its last outer step is cut to the MD steps left, with
 * slow kicks of its own length (src/colloid/colloid_md.c).  The same NVE
 * lattice with adaptive substeps (floor 37, at most 125), slow_interval 5
 * against 1: the counts chosen include non-multiples of 5 (their sum is
 * not one), and the drift stays within 3x the one-step drift.  A cut outer
 * step with the full step's kick (5 dt / 2) fails it. */
Test(colloid_mts, adaptive_counts_cut_the_last_outer_step, .timeout = 300)
{
    PL_SKIP_IF_QUICK("two NVE runs of adaptive substeps");
    char one[1200], split[1200];
    fig14_scene(one, sizeof one, 216, 9, 125, 1, 0);
    fig14_scene(split, sizeof split, 216, 9, 125, 5, 0);
    char *scenes[2] = {one, split};
    for (int k = 0; k < 2; ++k) {
        char *at = strstr(scenes[k], "colloids: {");
        cr_assert(at != NULL);
        const char *add = " adaptive_substeps = true; min_substeps = 37;";
        at += strlen("colloids: {");
        memmove(at + strlen(add), at, strlen(at) + 1);
        memcpy(at, add, strlen(add));
    }
    pl_sim_t *s = pl_test_sim(split, 2);
    pl_test_steps(s, 20);
    const long long md = s->colloids->adapt_md, lo = s->colloids->adapt_lo, hi = s->colloids->adapt_hi;
    pl_sim_free(s);
    cr_log_info("adaptive + slow_interval 5: %lld MD steps in 20 collision steps (%lld .. %lld)", md, lo, hi);
    cr_assert_neq(md % 5, 0, "every count a multiple of 5 (%lld MD steps): the cut outer step is not exercised", md);
    const double d1 = drift(one, 20), d5 = drift(split, 20);
    cr_assert_gt(d1, 0.0);
    cr_log_info("energy drift per colloid, adaptive: %g (slow_interval 1), %g (5)", d1, d5);
    cr_assert_leq(d5, 3.0 * d1, "energy drift %g kT per colloid with slow_interval 5, %g with 1", d5, d1);
}
