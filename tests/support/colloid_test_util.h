/* Shared helpers of the colloid tests: scenes from strings, env PL_QUICK. */
#ifndef COLLOID_TEST_UTIL_H
#define COLLOID_TEST_UTIL_H

#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>

#include "peloid/colloid.h"
#include "support.h"

static inline int quick(void) { return pl_test_quick(); }

/* Loads a scene from `body`, asserting success. */
static inline void scene_from(const char *body, pl_scene_t *s)
{
    pl_err_t err = {0, ""};
    int rc = pl_scene_load_string(body, "test.cfg", s, &err);
    cr_assert_eq(rc, 0, "scene refused: %s", err.msg);
}

#endif
