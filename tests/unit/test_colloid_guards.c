/* Stiff and extreme cases: each runs stably or trips the right guard
 * (PL_ERR_GUARD, exit code 3) with a message naming step, particles,
 * quantity, bound and the parameter to change -- never a silent NaN.  Also
 * bad input refused with the scene loader's FILE:LINE: key message (code 2). */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "colloid_test_util.h"

/* Runs up to `steps` MD steps; returns the first non-zero status. */
static int run_steps(pl_colloid_t *c, int steps, pl_err_t *err)
{
    for (int k = 0; k < steps; ++k) {
        int rc = pl_colloid_md_step(c, err);
        if (rc) return rc;
    }
    return 0;
}

static void all_finite(const pl_colloid_t *c)
{
    for (size_t i = 0; i < c->n; ++i)
        cr_assert(isfinite(c->x[i] + c->vx[i] + c->fx[i] + c->q0[i]), "colloid %zu not finite", i);
}

/* Two colloids approaching head-on at speed v (x axis), gap g. */
static pl_colloid_t *head_on(const char *body, double v, double gap)
{
    pl_scene_t s;
    scene_from(body, &s);
    pl_colloid_t *c;
    pl_err_t err;
    cr_assert_eq(pl_colloid_create(&s, omp_get_max_threads(), &c, &err), 0, "%s", err.msg);
    double d = c->rad[0] + c->rad[1];
    for (int i = 0; i < 2; ++i) {
        c->x[i] = 20.0 + (i ? 0.5 : -0.5) * (d + gap), c->y[i] = c->z[i] = 20.0;
        c->vx[i] = i ? -v : v, c->vy[i] = c->vz[i] = c->wx[i] = c->wy[i] = c->wz[i] = 0;
    }
    pl_colloid_forces(c, &err);
    pl_colloid_energy_t e;
    pl_colloid_energy(c, &e);
    c->e0 = e.total; /* reference of the energy-drift guard for the new state */
    return c;
}

Test(colloid_guards, huge_hertz_K_trips_contact_steps)
{
    pl_colloid_t *c = head_on("box: { cells = [40, 40, 40]; }; fluid: { density = 0.0; };\n"
                              "colloids: { count = 2; pairs = \"hertz\"; };\nhertz: { K = 1e9; };\n", 1.0, 0.2);
    pl_err_t err = {0, ""};
    int rc = run_steps(c, 2000, &err);
    cr_expect_eq(rc, PL_ERR_GUARD, "rc %d: %s", rc, err.msg);
    cr_expect(strstr(err.msg, "guard contact_steps: MD step") && strstr(err.msg, "colloids 0 and 1") &&
                  strstr(err.msg, "min_contact_steps = 20") && strstr(err.msg, "colloids.substeps") &&
                  strstr(err.msg, "coarse_graining.reach_energy"),
              "message: %s", err.msg);
    all_finite(c);
    pl_colloid_free(c);
}

/* The same collision with a reasonable K is resolved and runs stably. */
Test(colloid_guards, moderate_hertz_K_runs)
{
    pl_colloid_t *c = head_on("box: { cells = [40, 40, 40]; }; fluid: { density = 0.0; };\n"
                              "colloids: { count = 2; pairs = \"hertz\"; substeps = 10; };\nhertz: { K = 1e3; };\n",
                              0.3, 0.2);
    pl_err_t err = {0, ""};
    cr_expect_eq(run_steps(c, 2000, &err), 0, "%s", err.msg);
    cr_expect(c->vx[0] < 0 && c->vx[1] > 0, "bounced");
    all_finite(c);
    pl_colloid_free(c);
}

/* Primary minimum of 30 kT (Hecht: the real depth) at contact: either the run is
 * stable (finite, energy guard quiet) or the contact-step guard names the
 * stiff term. */
Test(colloid_guards, primary_minimum_30kT)
{
    pl_colloid_t *c = head_on("box: { cells = [40, 40, 40]; }; fluid: { density = 0.0; };\n"
                              "colloids: { count = 2; pairs = \"dlvo, hertz\"; temperature = 0.0; };\n"
                              "dlvo: { primary_depth = 30.0; psi0 = 20.0; kappa = 1.4e8; hamaker = 4.76e-20; length_unit = 1.25e-7; };\n",
                              0.0, 0.01);
    pl_err_t err = {0, ""};
    int rc = run_steps(c, 4000, &err);
    if (rc) {
        cr_expect_eq(rc, PL_ERR_GUARD, "%s", err.msg);
        cr_expect(strstr(err.msg, "guard contact_steps") && strstr(err.msg, "dlvo.primary_depth"), "%s", err.msg);
    } else {
        cr_log_info("30 kT primary minimum ran stably");
    }
    all_finite(c);
    pl_colloid_free(c);
}

/* Head-on approach at high speed with lubrication limited at a small gap: the
 * explicit damping would overshoot; the damping guard trips naming
 * lubrication.min_gap. */
Test(colloid_guards, fast_head_on_lubrication)
{
    pl_colloid_t *c = head_on("box: { cells = [40, 40, 40]; }; fluid: { density = 0.0; };\n"
                              "colloids: { count = 2; pairs = \"hertz, lubrication\"; };\n"
                              "lubrication: { viscosity = 2.5; min_gap = 0.001; cutoff_gap = 1.0; };\n",
                              20.0, 0.9);
    pl_err_t err = {0, ""};
    int rc = run_steps(c, 2000, &err);
    cr_expect_eq(rc, PL_ERR_GUARD, "rc %d: %s", rc, err.msg);
    cr_expect(strstr(err.msg, "guard damping") && strstr(err.msg, "lubrication.min_gap"), "%s", err.msg);
    all_finite(c);
    pl_colloid_free(c);
}

/* A time step 10x too large (srd.dt 1.0 instead of 0.1) in an undamped run:
 * a guard trips (contact resolution or energy drift), never NaN. */
Test(colloid_guards, dt_ten_times_too_large)
{
    pl_scene_t s;
    scene_from("box: { cells = [16, 16, 16]; }; fluid: { density = 0.0; }; srd: { dt = 1.0; };\n"
               "colloids: { count = 27; temperature = 5.0; pairs = \"hertz\"; guard_interval = 10; };\n"
               "hertz: { K = 1000.0; };\n", &s);
    pl_colloid_t *c;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_colloid_create(&s, omp_get_max_threads(), &c, &err), 0, "%s", err.msg);
    int rc = run_steps(c, 20000, &err);
    cr_expect_eq(rc, PL_ERR_GUARD, "rc %d: %s", rc, err.msg);
    cr_expect(strstr(err.msg, "guard contact_steps") || strstr(err.msg, "guard energy_drift") ||
                  strstr(err.msg, "guard overlap"), "%s", err.msg);
    cr_expect(strstr(err.msg, "MD step") != NULL, "%s", err.msg);
    all_finite(c);
    pl_colloid_free(c);
}

Test(colloid_guards, nan_and_overlap)
{
    pl_colloid_t *c = head_on("box: { cells = [40, 40, 40]; }; fluid: { density = 0.0; };\n"
                              "colloids: { count = 2; pairs = \"wca\"; min_contact_steps = 0.0; };\n", 0.0, 1.0);
    pl_err_t err = {0, ""};
    c->vy[1] = NAN;
    cr_expect_eq(pl_colloid_md_step(c, &err), PL_ERR_GUARD);
    cr_expect(strstr(err.msg, "guard nan: MD step 1: colloid 1") != NULL, "%s", err.msg);
    /* the message names a non-finite component (x, v and f of colloid 1 alone can all be finite) */
    cr_expect(strstr(err.msg, "y = nan;") != NULL || strstr(err.msg, "vy = nan;") != NULL, "%s", err.msg);
    c->vy[1] = 0, c->y[1] = 20, c->x[1] = c->x[0] + 0.8 * (c->rad[0] + c->rad[1]);
    c->vx[0] = c->vx[1] = 0;
    pl_colloid_forces(c, &err);
    cr_expect_eq(pl_colloid_guard(c, 0, &err), PL_ERR_GUARD);
    cr_expect(strstr(err.msg, "guard overlap") && strstr(err.msg, "0.2 of R_i+R_j") &&
                  strstr(err.msg, "colloids.max_overlap = 0.1"), "%s", err.msg);
    pl_colloid_free(c);
}

/* ---- bad input ---------------------------------------------------------- */

static void refused(const char *body, const char *want1, const char *want2)
{
    pl_scene_t s;
    pl_err_t err = {0, ""};
    int rc = pl_scene_load_string(body, "bad.cfg", &s, &err);
    if (rc == 0) { /* some checks need the state (initial overlap) */
        pl_colloid_t *c = NULL;
        rc = pl_colloid_create(&s, omp_get_max_threads(), &c, &err);
        pl_colloid_free(c);
    }
    cr_expect_eq(rc, PL_ERR_INPUT, "rc %d for %s", rc, body);
    cr_expect(strstr(err.msg, want1) && strstr(err.msg, want2), "message: %s", err.msg);
}

Test(colloid_guards, bad_input_refused)
{
    refused("fluid: { density = 0.0; };\ncolloids: { count = 2; radius = -1.0; };\n",
            "bad.cfg:2: key 'colloids.radius'", "allowed: > 0");
    refused("fluid: { density = 0.0; };\ncolloids: { count = 2; pairs = \"dlvo\"; };\ndlvo: { kappa = 0.0; };\n",
            "bad.cfg:3: key 'dlvo.kappa'", "allowed: > 0");
    refused("fluid: { density = 0.0; };\ncolloids: { count = 2;\n  pairs = \"hertz, coulomb\"; };\n",
            "bad.cfg:3: key 'colloids.pairs'", "unknown pair term \"coulomb\"");
    refused("fluid: { density = 0.0; };\ncolloids: { count = 1000;\n init = \"lattice\"; };\n",
            "bad.cfg:3: key 'colloids.init'", "overlap by");
    refused("fluid: { density = 0.0; };\ncolloids: { count = 2; integrator = \"leapfrog\"; };\n",
            "bad.cfg:2: key 'colloids.integrator'", "unknown value \"leapfrog\"");
}
