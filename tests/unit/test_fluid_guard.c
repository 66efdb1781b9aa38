/* Issue 18: the fluid guard stage (src/fluid/fluid_guard.c, kernels/srd_guard.c),
 * the wall impulse accumulator's overflow detection (pl_wall_acc_add) and
 * the colloid image counter guard.  Each case failed on the code before
 * (a NaN velocity crashed the next stream in kernels/srd_stream.c; an
 * overflowing accumulator wrapped silently; an image counter overflowed its
 * int32, undefined behaviour, before the NaN guard looked). */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <string.h>

#include "colloid_test_util.h"
#include "peloid/colloid_kernels.h"
#include "support.h"
#include "../../src/fluid/srd_state.h" /* the fluid component's own test: its guard's private state */

static const char *const FLUID = "seed = 3;\nbox: { cells = [8, 8, 8]; };\nfluid: { density = 5.0; };\n";

/* A NaN velocity, as a collision or coupling of the step could leave it:
 * the stage's every-step speed scan reports it before the next stream
 * (which, fed a NaN, computed an out-of-range cell: the segfault at
 * kernels/srd_stream.c of the issue). */
Test(fluid_guard, nan_velocity)
{
    pl_sim_t *sim = pl_test_sim(FLUID, 2);
    pl_test_steps(sim, 2);
    sim->fluid.v[1][123] = (pl_real)NAN;
    pl_err_t err;
    cr_expect_eq(pl_fluid_guard_check(sim, 3, 0, &err), PL_ERR_GUARD);
    cr_expect(strstr(err.msg, "guard fluid_nan: step 3: fluid particle 123 has a non-finite velocity") &&
                  strstr(err.msg, "srd.dt"), "%s", err.msg);
    /* and the stage itself: pl_sim_step stops before the step completes */
    int found = 0;
    for (int k = 0; k < sim->nstages && !found; ++k)
        if (!strcmp(sim->stages[k].name, "fluid-guard")) {
            found = 1;
            cr_expect_eq(sim->stages[k].fn(sim, sim->stages[k].ctx, &err), PL_ERR_GUARD);
            cr_expect(strstr(err.msg, "fluid particle 123"), "%s", err.msg);
        }
    cr_expect(found);
    pl_sim_free(sim);
}

/* A NaN position: the full scan (every 10 steps and before every output). */
Test(fluid_guard, nan_position)
{
    pl_sim_t *sim = pl_test_sim(FLUID, 3);
    sim->fluid.r[0][2500] = (pl_real)NAN;
    pl_err_t err;
    cr_expect_eq(pl_fluid_guard_check(sim, 0, 0, &err), 0); /* speeds only: fine */
    cr_expect_eq(pl_fluid_guard_check(sim, 0, 1, &err), PL_ERR_GUARD);
    cr_expect(strstr(err.msg, "guard fluid_nan: step 0: fluid particle 2500 has a non-finite position"), "%s",
              err.msg);
    pl_sim_free(sim);
}

/* A particle outside the box (as a corrupt state would put it). */
Test(fluid_guard, position_outside)
{
    pl_sim_t *sim = pl_test_sim(FLUID, 1);
    sim->fluid.r[2][7] = (pl_real)1e9;
    pl_err_t err;
    cr_expect_eq(pl_fluid_guard_check(sim, 0, 1, &err), PL_ERR_GUARD);
    cr_expect(strstr(err.msg, "guard fluid_box: step 0: fluid particle 7 is at z = 1000000000"), "%s", err.msg);
    pl_sim_free(sim);
}

/* The speed bound, and the reported particle (the lowest index failing) is
 * the same for 1, 2 and 3 threads. */
Test(fluid_guard, speed_lowest_index_any_threads)
{
    for (int t = 1; t <= 3; ++t) {
        pl_sim_t *sim = pl_test_sim(FLUID, t);
        cr_assert(pl_srd_speed_bound(sim->srd) == 20.0, "bound %g", pl_srd_speed_bound(sim->srd));
        sim->fluid.v[0][2000] = (pl_real)25.0;
        sim->fluid.v[0][1500] = (pl_real)30.0;
        sim->fluid.v[0][100] = (pl_real)19.0;
        pl_err_t err;
        cr_expect_eq(pl_fluid_guard_check(sim, 5, 1, &err), PL_ERR_GUARD);
        cr_expect(strstr(err.msg, "guard fluid_speed: step 5: fluid particle 1500 has speed |v| = 30"), "%d: %s", t,
                  err.msg);
        pl_sim_free(sim);
    }
}

/* The guard stage reads the collision's per-block speed flags (the scan
 * fused into kernels/srd_collide.c) when nothing ran between the two: a
 * runaway made inside the step (one particle at 1e3 shares its momentum
 * with its cell) is reported with the same particle and message as the full
 * scan of the same state, for 1, 2 and 3 threads. */
Test(fluid_guard, speed_flags_of_the_collision)
{
    char first[sizeof ((pl_err_t *)0)->msg] = "";
    for (int t = 1; t <= 3; ++t) {
        pl_sim_t *sim = pl_test_sim(FLUID, t);
        pl_test_steps(sim, 2);
        sim->fluid.v[2][777] = (pl_real)1e3;
        pl_err_t err, full;
        cr_assert_eq(pl_sim_step(sim, &err), PL_ERR_GUARD);
        cr_expect_eq(sim->srd->guard_bad_step, sim->step, "the flags of this step's collision were used");
        cr_expect(strstr(err.msg, "guard fluid_speed: step 3: fluid particle"), "%d: %s", t, err.msg);
        cr_expect_eq(pl_fluid_guard_check(sim, sim->step + 1, 0, &full), PL_ERR_GUARD);
        cr_expect_str_eq(err.msg, full.msg);
        if (t == 1) snprintf(first, sizeof first, "%s", err.msg);
        cr_expect_str_eq(err.msg, first, "%d threads", t);
        pl_sim_free(sim);
    }
}

/* A healthy run passes and the stage is in the plan. */
Test(fluid_guard, healthy_run_passes)
{
    pl_sim_t *sim = pl_test_sim(FLUID, 2);
    int found = 0;
    for (int k = 0; k < sim->nstages; ++k) found |= !strcmp(sim->stages[k].name, "fluid-guard");
    cr_expect(found, "no fluid-guard stage");
    pl_test_steps(sim, 20);
    pl_sim_free(sim);
}

/* The fixed-point wall accumulator: an add beyond 2^62 or a non-finite
 * impulse leaves the sticky overflow mark, and the guard reports it. */
Test(fluid_guard, wall_accumulator_overflow)
{
    int64_t acc[PL_WALL_ACC_N] = {0};
    const double small[3] = {1.0, -2.0, 0.5}, huge[3] = {2e9, 0.0, NAN};
    pl_wall_acc_add(acc, 0, small);
    cr_expect_eq(acc[0], INT64_C(1) << 32);
    cr_expect_eq(acc[1], -(INT64_C(2) << 32));
    for (int k = 0; k < 2; ++k) pl_wall_acc_add(acc, 1, huge); /* 2 x 2e9 x 2^32 > 2^62 */
    cr_expect_eq(acc[3], PL_WALL_ACC_OVERFLOW);
    cr_expect_eq(acc[5], PL_WALL_ACC_OVERFLOW);
    cr_expect_eq(acc[4], 0);
    pl_wall_acc_add(acc, 1, small); /* sticky */
    cr_expect_eq(acc[3], PL_WALL_ACC_OVERFLOW);
    pl_sim_t *sim = pl_test_sim("seed = 3;\nbox: { cells = [8, 8, 8]; walls_z = \"noslip\"; };\n", 1);
    pl_sim_wall_add(sim, acc);
    pl_err_t err;
    cr_expect_eq(pl_fluid_guard_check(sim, 9, 1, &err), PL_ERR_GUARD);
    cr_expect(strstr(err.msg, "guard wall_impulse: step 9") && strstr(err.msg, "box.wall_velocity_"), "%s",
              err.msg);
    pl_sim_free(sim);
}

/* The temperature band with a thermostat: [min(T0, T*)/10, max(T0, T*) 10]. */
Test(fluid_guard, temperature_band)
{
    pl_sim_t *sim = pl_test_sim("seed = 3;\nbox: { cells = [8, 8, 8]; };\nfluid: { temperature = 2.0; };\n"
                                "thermostat: { type = \"heyes\"; temperature = 1.0; };\n", 1);
    cr_expect(fabs(sim->srd->guard_kT_lo - 0.1) < 1e-15 && fabs(sim->srd->guard_kT_hi - 20.0) < 1e-15);
    pl_err_t err;
    *pl_srd_kept(sim->srd).kT_cell = 19.0;
    cr_expect_eq(pl_fluid_guard_check(sim, 1, 1, &err), 0);
    *pl_srd_kept(sim->srd).kT_cell = 21.0;
    cr_expect_eq(pl_fluid_guard_check(sim, 1, 1, &err), PL_ERR_GUARD);
    cr_expect(strstr(err.msg, "guard fluid_temperature: step 1") && strstr(err.msg, "bound [0.1, 20]"), "%s",
              err.msg);
    *pl_srd_kept(sim->srd).kT_cell = NAN;
    cr_expect_eq(pl_fluid_guard_check(sim, 1, 1, &err), PL_ERR_GUARD);
    pl_sim_free(sim);
}

/* A colloid 1e15 box lengths away: the drift saturates its image counter
 * (no int32 overflow, clean under UBSan) and the guard stops the run. */
Test(fluid_guard, colloid_image_counter)
{
    pl_scene_t s;
    scene_from("box: { cells = [16, 16, 16]; }; fluid: { density = 0.0; };\n"
               "colloids: { count = 1; pairs = \"\"; };\n", &s);
    pl_colloid_t *c;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_colloid_create(&s, omp_get_max_threads(), &c, &err), 0, "%s", err.msg);
    c->vx[0] = 1e15 / c->dt;
    int rc = 0;
    for (int k = 0; k < 3 && !rc; ++k) rc = pl_colloid_md_step(c, &err);
    cr_expect_eq(rc, PL_ERR_GUARD, "rc %d: %s", rc, err.msg);
    cr_expect(strstr(err.msg, "guard image: MD step") && strstr(err.msg, "colloid 0") && strstr(err.msg, "along x"),
              "%s", err.msg);
    cr_expect(c->ix[0] == PL_COLLOID_IMAGE_MAX + 1, "ix %d", c->ix[0]);
    cr_expect(c->x[0] >= 0.0 && c->x[0] <= 16.0, "x %g", c->x[0]);
    pl_colloid_free(c);
}
