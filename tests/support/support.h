/* Helpers shared by the Criterion suites: build a sim from scene text, run
 * steps, read PL_QUICK (shrinks physics runs under the sanitizers), and
 * compare two fluids bitwise. */
#ifndef PELOID_TEST_SUPPORT_H
#define PELOID_TEST_SUPPORT_H

#include <criterion/criterion.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/scene.h"
#include "peloid/sim.h"

/* The one quick-mode switch: PL_QUICK set and not "0" (sanitizer runs). */
static inline int pl_test_quick(void)
{
    const char *q = getenv("PL_QUICK");
    return q && *q && strcmp(q, "0");
}

/* A physics check that needs the full run reports "skipped" under PL_QUICK,
 * never "passed". */
#define PL_SKIP_IF_QUICK(why)                                                                                   \
    do {                                                                                                        \
        if (pl_test_quick()) cr_skip_test("skipped under PL_QUICK: %s", why);                                  \
    } while (0)

static inline pl_sim_t *pl_test_sim(const char *scene_text, int nthreads)
{
    static pl_scene_t scene; /* test-local: each test binary is one process */
    pl_err_t err = {0, ""};
    int rc = pl_scene_load_string(scene_text, "test.cfg", &scene, &err);
    cr_assert_eq(rc, 0, "scene: %s", err.msg);
    pl_sim_t *sim = NULL;
    rc = pl_sim_create(&scene, nthreads, &sim, &err);
    cr_assert_eq(rc, 0, "sim: %s", err.msg);
    return sim;
}

static inline void pl_test_steps(pl_sim_t *sim, long long n)
{
    pl_err_t err = {0, ""};
    for (long long i = 0; i < n; ++i) cr_assert_eq(pl_sim_step(sim, &err), 0, "%s", err.msg);
}

/* Bitwise equality of the step, the fluid (positions, velocities, tracked
 * displacements), the accumulated fields and the wall impulses. */
static inline void pl_test_assert_same_fluid(const pl_sim_t *a, const pl_sim_t *b, const char *what)
{
    cr_assert_eq(a->step, b->step, "%s: step", what);
    size_t n = a->fluid.n;
    cr_assert_eq(n, b->fluid.n, "%s: fluid size", what);
    for (int d = 0; d < 3; ++d) {
        cr_assert_eq(memcmp(a->fluid.r[d], b->fluid.r[d], n * sizeof(pl_real)), 0, "%s: r[%d]", what, d);
        cr_assert_eq(memcmp(a->fluid.v[d], b->fluid.v[d], n * sizeof(pl_real)), 0, "%s: v[%d]", what, d);
        if (a->fluid.tracked)
            cr_assert_eq(memcmp(a->fluid.disp[d], b->fluid.disp[d], n * sizeof(double)), 0, "%s: disp", what);
    }
    long long sa, sb;
    const int64_t *fa = pl_srd_fields(a->srd, &sa), *fb = pl_srd_fields(b->srd, &sb);
    if (fa) {
        size_t L3 = (size_t)a->grid.L[0] * (size_t)a->grid.L[1] * (size_t)a->grid.L[2];
        cr_assert_eq(memcmp(fa, fb, 4 * L3 * sizeof(int64_t)), 0, "%s: fields", what);
    }
    cr_assert_eq(memcmp(a->wall_impulse, b->wall_impulse, sizeof a->wall_impulse), 0, "%s: wall impulses", what);
}

#endif
