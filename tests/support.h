/* Helpers shared by the Criterion suites: build a sim from scene text, run
 * steps, and read PL_QUICK (shrinks physics runs under the sanitizers). */
#ifndef PELOID_TEST_SUPPORT_H
#define PELOID_TEST_SUPPORT_H

#include <criterion/criterion.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/scene.h"
#include "peloid/sim.h"

static inline int pl_test_quick(void)
{
    const char *q = getenv("PL_QUICK");
    return q && *q && strcmp(q, "0");
}

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

#endif
