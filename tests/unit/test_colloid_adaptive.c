/* Adaptive MD substeps (colloids.adaptive_substeps, src/colloid/colloid_adaptive.c):
 * the choice follows the stiffest contact the pair present can reach (its
 * potential plus approach kinetic energy, against an independent scan of
 * the potential), and a head-on collision that the smallest step would
 * miss is resolved: the contact guard (min_contact_steps = 20) never trips
 * and the energy comes back.  Thread count and restart: the adaptive scene
 * of tests/unit/test_colloid_restart.c. */
#include <math.h>

#include "colloid_test_util.h"
#include "peloid/colloid_pair.h"
#include "peloid/real.h"

/* Hecht Fig. 14's DLVO in model units (as tests/unit/test_colloid_mts.c: a
 * 222 kT barrier at gap 0.0036 a0), two colloids, no fluid, no coupling:
 * the colloids' own conservative MD. */
static void two_scene(char *buf, size_t n, int substeps, int min_substeps, int adaptive, double margin)
{
    snprintf(buf, n,
             "seed = 3;\nbox: { cells = [8, 8, 8]; };\nfluid: { density = 0.0; };\nsrd: { dt = 0.1; };\n"
             "colloids: { count = 2; radius = 0.62; mass_density = 39.0; temperature = 0.0;\n"
             "  pairs = \"dlvo, hertz\"; substeps = %d; min_substeps = %d; adaptive_substeps = %s;\n"
             "  adaptive_margin = %g; max_energy_drift = 0.0; min_contact_steps = 20.0; };\n"
             "dlvo: { psi0 = 50.0; kappa = 3.0e8; hamaker = 4.76e-20; length_unit = 4.03e-7; primary_depth = 6.0; };\n"
             "hertz: { K = 1000.0; };\n",
             substeps, min_substeps, adaptive ? "true" : "false", margin);
}

/* colloid 0 at rest at (2, 4, 4), colloid 1 at gap h on +x, approaching at
 * speed v; the list rebuilt and the forces evaluated there */
static void place(pl_colloid_t *c, double h, double v)
{
    const double d = c->rad[0] + c->rad[1];
    c->x[0] = 2.0;
    c->x[1] = 2.0 + d + h;
    for (int i = 0; i < 2; ++i) {
        c->y[i] = c->z[i] = 4.0;
        c->vx[i] = c->vy[i] = c->vz[i] = 0.0;
    }
    c->vx[1] = -v;
    c->nlist.builds = 0;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_colloid_forces(c, &err), 0, "%s", err.msg);
}

static pl_pair_val_t pot(const pl_colloid_pair_params_t *p, double d, double h)
{
    pl_pair_val_t s = {0.0, 0.0, 0.0};
    if (h < p->dlvo_hcut) s = pl_pair_dlvo(d + h, d, p->coul_C, p->kappa, p->hamaker, p->prim_hm, p->prim_h0, p->dlvo_shift);
    if (h < 0.0) {
        pl_pair_val_t v = pl_pair_hertz(-h, p->hertz_K);
        s.u += v.u;
        s.k2 += v.k2;
    }
    return s;
}

/* The MD steps the rule asks for, from a direct scan of the potential on a
 * grid of its own: the pair's energy E = U(h) + m_red v^2 / 2 + margin (at
 * least the highest U outward of it), the gaps reachable from outside with
 * E, the largest U'' there. */
static double expected(const pl_colloid_t *c, double h, double v, double margin)
{
    const pl_colloid_pair_params_t *p = &c->pair;
    const double d = c->rad[0] + c->rad[1], mred = 0.5 * c->mass[0], dg = 2e-6;
    double umax = -INFINITY;
    for (double g = p->gap_cut; g >= h; g -= dg) umax = fmax(umax, pot(p, d, g).u);
    double e = fmax(pot(p, d, h).u + 0.5 * mred * v * v + margin, umax), k2 = 0.0;
    for (double g = p->gap_cut; g > -0.1 * d; g -= dg) {
        pl_pair_val_t s = pot(p, d, g);
        if (s.u > e) break;
        k2 = fmax(k2, s.k2);
    }
    return ceil(1.05 * 20.0 * 0.1 * sqrt(k2 / mred) / PL_PI);
}

Test(colloid_adaptive, substeps_follow_the_stiffest_pair_present)
{
    char sc[1024];
    two_scene(sc, sizeof sc, 2000, 4, 1, 0.0);
    pl_sim_t *s = pl_test_sim(sc, 1);
    pl_colloid_t *c = s->colloids;
    /* at rest beyond the secondary minimum (it reaches the wall where U = 0,
     * the highest U outward of it), then up the wall; then at the
     * secondary minimum with approach energies of 5, 20, 60 kT */
    const double gaps[] = {0.5, 0.025, 0.02, 0.015, 0.05, 0.05, 0.05};
    const double kin[] = {0.0, 0.0, 0.0, 0.0, 5.0, 20.0, 60.0};
    int last = 0;
    for (int k = 0; k < 7; ++k) {
        const double v = sqrt(2.0 * kin[k] / (0.5 * c->mass[0]));
        place(c, gaps[k], v);
        const int n = pl_colloid_adaptive_substeps(c);
        const double want = fmax(4.0, expected(c, gaps[k], v, 0.0));
        cr_log_info("gap %g, approach %g kT: %d MD steps (scan: %g)", gaps[k], kin[k], n, want);
        /* the table is rounded inward by one node (conservative): at most one more */
        cr_assert(n >= want && n <= want + 1, "gap %g a0, approach %g kT: %d MD steps, the scan asks %g",
                  gaps[k], kin[k], n, want);
        if (k != 4) cr_assert_gt(n, last, "gap %g a0, approach %g kT: %d MD steps, not more than %d",
                                 gaps[k], kin[k], n, last);
        last = n;
    }
    /* the margin adds to the pair's energy */
    c->adapt_margin = 20.0;
    place(c, 0.05, 0.0);
    const int n20 = pl_colloid_adaptive_substeps(c);
    cr_assert(n20 >= expected(c, 0.05, 0.0, 20.0) && n20 <= expected(c, 0.05, 0.0, 20.0) + 1, "%d", n20);
    pl_sim_free(s);
}

/* Head-on at 40 kT from gap 0.3 a0: the pair climbs the Coulomb wall to
 * ~0.02 a0 and comes back.  Adaptive (4 .. 2000 MD steps per collision step,
 * margin 0): the contact guard checks every MD step that the collision is
 * resolved by >= 20 of them, so a choice that ignored the approach would
 * trip it, as 4 fixed MD steps do (checked); the energy after the bounce
 * comes back to velocity Verlet's error at 20+ steps per collision
 * ((pi/20)^2 / 8 of the 40 kT at the turning point, 0.12 kT; bound 0.5). */
Test(colloid_adaptive, a_head_on_collision_is_resolved)
{
    char sc[1024];
    for (int adaptive = 1; adaptive >= 0; --adaptive) {
        two_scene(sc, sizeof sc, adaptive ? 2000 : 4, 4, adaptive, 0.0);
        pl_sim_t *s = pl_test_sim(sc, 1);
        pl_colloid_t *c = s->colloids;
        const double v = sqrt(2.0 * 40.0 / (0.5 * c->mass[0]));
        place(c, 0.3, v);
        pl_colloid_energy_t e;
        pl_colloid_energy(c, &e);
        const double e0 = e.total;
        pl_err_t err = {0, ""};
        int rc = 0;
        double emax = 0.0;
        long long md0 = c->md_step;
        for (int k = 0; k < 6 && !rc; ++k) {
            rc = pl_sim_step(s, &err);
            pl_colloid_energy(c, &e);
            emax = fmax(emax, fabs(e.total - e0));
        }
        if (!adaptive) {
            cr_assert_eq(rc, PL_ERR_GUARD, "4 fixed MD steps should trip the contact guard: rc %d", rc);
            cr_assert(strstr(err.msg, "contact_steps"), "%s", err.msg);
        } else {
            cr_assert_eq(rc, 0, "%s", err.msg);
            cr_assert_gt(c->vx[1] - c->vx[0], 0.0, "the pair did not bounce back");
            const double want = expected(c, 0.3, v, 0.0);
            cr_assert_geq((double)c->adapt_hi, want, "MD steps up to %lld; the approach asks %g", c->adapt_hi, want);
            cr_log_info("head-on 40 kT: |E - E0| <= %g kT, MD steps %lld .. %lld (%lld in all; the approach asks %g)",
                        emax, c->adapt_lo, c->adapt_hi, c->md_step - md0, want);
            cr_assert_leq(emax, 0.5, "energy error %g kT", emax);
        }
        pl_sim_free(s);
    }
}

/* The safety net: a choice that falls short (here made so by a margin of
 * -35 kT, as if the 40 kT pair had 5 kT: fewer MD steps than the approach
 * asks, checked) is caught before the guard's bound: a contact within 25 %
 * of min_contact_steps finishes its collision step at colloids.substeps, so
 * the collision is still resolved by >= 20 MD steps and the guard does not
 * trip (without the refinement it does, as 4 fixed MD steps do above). */
Test(colloid_adaptive, a_short_choice_is_refined_before_the_guard_trips)
{
    char sc[1024];
    two_scene(sc, sizeof sc, 2000, 4, 1, 0.0);
    pl_sim_t *s = pl_test_sim(sc, 1);
    pl_colloid_t *c = s->colloids;
    c->adapt_margin = -35.0;
    const double v = sqrt(2.0 * 40.0 / (0.5 * c->mass[0]));
    place(c, 0.3, v);
    const int n0 = pl_colloid_adaptive_substeps(c);
    cr_assert_lt(n0, expected(c, 0.3, v, 0.0), "the choice %d is not short", n0);
    pl_err_t err = {0, ""};
    int rc = 0;
    for (int k = 0; k < 6 && !rc; ++k) rc = pl_sim_step(s, &err);
    cr_assert_eq(rc, 0, "%s", err.msg);
    cr_assert_gt(c->adapt_refined, 0, "no collision step was refined");
    cr_assert_geq(c->adapt_worst, 20.0, "fewest MD steps per collision %g", c->adapt_worst);
    cr_assert_gt(c->vx[1] - c->vx[0], 0.0, "the pair did not bounce back");
    cr_log_info("short choice %d (the approach asks %g): %lld refined collision steps, fewest MD steps per "
                "collision %g", n0, expected(c, 0.3, v, 0.0), c->adapt_refined, c->adapt_worst);
    pl_sim_free(s);
}
