/* The coupling section of the scene: defaults, choices, cross-key checks
 * (a coupling needs colloids and fluid, and the Verlet integrator), unknown
 * keys refused; the plan holds exactly the stages the coupling needs. */
#include <string.h>

#include "peloid/coupling.h"
#include "support.h"

static int load(const char *text, pl_scene_t *s, pl_err_t *err)
{
    return pl_scene_load_string(text, "test.cfg", s, err);
}

static const char *COLL = "box: { cells = [12, 12, 12]; };\n"
                          "colloids: { count = 8; radius = 2.0; init = \"lattice\"; };\n";

Test(coupling_scene, defaults)
{
    pl_scene_t s;
    pl_err_t err = {0, ""};
    cr_assert_eq(load("", &s, &err), 0, "%s", err.msg);
    cr_expect_eq(s.coupling.method, PL_COUPLE_NONE);
    cr_expect_eq(s.coupling.boundary, PL_BOUND_STICK_STOCHASTIC);
    cr_expect_eq(s.coupling.placement, PL_PLACE_ENTRY);
    cr_expect_eq(s.coupling.max_reflections, 10);
    cr_expect_eq(s.coupling.compensate_gravity, 1);
    cr_expect_eq(s.coupling.drift_interval, 0);
}

Test(coupling_scene, refused)
{
    pl_scene_t s;
    pl_err_t err = {0, ""};
    cr_expect_neq(load("coupling: { method = \"hecht3\"; };", &s, &err), 0);
    cr_expect(strstr(err.msg, "coupling.method") != NULL, "%s", err.msg);
    cr_expect_neq(load("coupling: { metod = \"hecht1\"; };", &s, &err), 0);
    cr_expect_neq(load("coupling: { max_reflections = 0; };", &s, &err), 0);
    cr_expect_neq(load("coupling: { method = \"hecht1\"; };", &s, &err), 0, "no colloids");
    cr_expect(strstr(err.msg, "colloids") != NULL, "%s", err.msg);
    char text[1024];
    snprintf(text, sizeof text, "%sfluid: { density = 0.0; };\ncoupling: { method = \"hecht2\"; };", COLL);
    cr_expect_neq(load(text, &s, &err), 0, "no fluid");
    snprintf(text, sizeof text, "box: { cells = [12, 12, 12]; };\ncolloids: { count = 8; radius = 2.0; "
             "init = \"lattice\"; integrator = \"brownian\"; };\ncoupling: { method = \"hecht1\"; };");
    cr_expect_neq(load(text, &s, &err), 0, "brownian colloids");
}

/* Coupling II resolution (the cause of the hot colloids of the former
 * scenes/sediment.cfg): R = 2 a0 colloids of M = 653 m_f, each coupled to the
 * ~5 fluid particles of one cell, xi_II = 2/3 mu / dt = 33.1 (hecht_axes),
 * settle at v_s >= M g / xi_II = 0.079 a0/t0 under g = 0.004: M v_s^2 = 4.08
 * kT, refused (bound 0.5).  The same colloids at R = 0.62 a0 (cell volume =
 * colloid volume, Hecht Sec. VII.C) with 10 particles per cell: 0.08 kT. */
Test(coupling_scene, coupling2_settling_bound)
{
    pl_scene_t s;
    pl_err_t err = {0, ""};
    const char *fmt = "box: { cells = [24, 24, 32]; walls_z = \"noslip\"; };\n"
                      "fluid: { density = %g; };\nsrd: { dt = 0.1; rule = \"hecht_axes\"; };\n"
                      "colloids: { count = 64; radius = %g; mass_density = %g; init = \"random\";\n"
                      "  gravity = [0.0, 0.0, %.4f]; };\ncoupling: { method = \"hecht2\"; %s };\n";
    char text[1024];
    snprintf(text, sizeof text, fmt, 5.0, 2.0, 19.5, -0.004, "");
    cr_expect_neq(load(text, &s, &err), 0, "former sediment.cfg accepted");
    cr_expect(strstr(err.msg, "colloids.gravity") && strstr(err.msg, "M v_s^2 = 4.08 kT") &&
                  strstr(err.msg, "coupling.max_settling_energy"),
              "%s", err.msg);
    snprintf(text, sizeof text, fmt, 5.0, 2.0, 19.5, -0.004, "max_settling_energy = 0;");
    cr_expect_eq(load(text, &s, &err), 0, "bound 0 is off: %s", err.msg);
    snprintf(text, sizeof text, fmt, 5.0, 2.0, 19.5, 0.0, "");
    cr_expect_eq(load(text, &s, &err), 0, "no gravity, nothing to check: %s", err.msg);
    snprintf(text, sizeof text, fmt, 10.0, 0.62, 39.0, -0.062, "");
    cr_expect_eq(load(text, &s, &err), 0, "resolved coupling II refused: %s", err.msg);
    /* xi_II = 2/3 mu / dt for +-90 deg rotations, mu = M gamma / (M + gamma) */
    double m = 38.9, mu = m * 10.0 / (m + 10.0);
    cr_expect_float_eq(pl_coupling2_friction(&s, m), 2.0 / 3.0 * mu / 0.1, 1e-12);
}

static int has_stage(const pl_sim_t *sim, const char *name)
{
    for (int k = 0; k < sim->nstages; ++k)
        if (!strcmp(sim->stages[k].name, name)) return 1;
    return 0;
}

Test(coupling_scene, plan)
{
    char text[1024];
    snprintf(text, sizeof text, "%scoupling: { method = \"hecht1\"; };", COLL);
    pl_sim_t *a = pl_test_sim(text, 1);
    cr_expect(has_stage(a, "coupling1-reflect") && !has_stage(a, "coupling2-save"));
    cr_expect(!has_stage(a, "drift-removal"));
    pl_sim_free(a);
    snprintf(text, sizeof text, "%scoupling: { method = \"hecht2\"; drift_interval = 50; };", COLL);
    pl_sim_t *b = pl_test_sim(text, 1);
    cr_expect(has_stage(b, "coupling2-save") && has_stage(b, "coupling2-collide"));
    cr_expect(has_stage(b, "drift-removal") && !has_stage(b, "coupling1-reflect"));
    pl_sim_free(b);
    pl_sim_t *c = pl_test_sim(COLL, 1);
    cr_expect(pl_coupling_of(c) == NULL && !has_stage(c, "coupling1-reflect"));
    pl_sim_free(c);
}

Test(coupling_scene, hecht1_starts_with_empty_colloids)
{
    char text[1024];
    snprintf(text, sizeof text, "%scoupling: { method = \"hecht1\"; };", COLL);
    pl_sim_t *sim = pl_test_sim(text, 2);
    pl_coupling_colloids_t v = pl_coupling_view(sim->colloids);
    size_t inside = 0;
    for (size_t i = 0; i < sim->fluid.n; ++i) {
        double r[3] = {sim->fluid.r[0][i], sim->fluid.r[1][i], sim->fluid.r[2][i]}, p[3];
        inside += pl_coupling_inside(&v, sim->grid.L, sim->grid.walls, pl_coupling_of(sim)->c1->lk.start,
                                     pl_coupling_of(sim)->c1->lk.list, r, p) >= 0;
    }
    cr_expect_eq(inside, 0, "%zu fluid particles start inside colloids", inside);
    pl_sim_free(sim);
}
