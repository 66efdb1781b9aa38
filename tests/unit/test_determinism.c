/* Determinism (issue 2): the same scene and seed give bitwise identical
 * state for 1, 2 and 3 threads, and 2N steps == N steps + checkpoint +
 * restart + N steps, bitwise.  Every feature that touches the state is on:
 * grid shift, no-slip walls with virtual particles, body force, Heyes or
 * rescale thermostat, tracking, fields; x/y walls (a capillary, and a box
 * closed on every axis); the collision rules other than the SRD rotation
 * (peloid/collision_rule.h), which draw per particle. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "peloid/checkpoint.h"
#include "peloid/io.h"
#include "support.h"

static const char *scenes[] = {
    "seed = 42;\nbox: { cells = [6, 5, 7]; walls_z = \"noslip\"; };\n"
    "fluid: { density = 4.0; body_force = [0.01, 0.0, 0.0]; init_velocity = \"uniform\"; };\n"
    "srd: { dt = 0.3; alpha = 120.0; };\nthermostat: { type = \"heyes\"; heyes_epsilon = 0.2; };\n"
    "output: { track_fluid = true; fields_interval = 3; };\n",
    "seed = 43;\nbox: { cells = [7, 6, 5]; walls_z = \"slip\"; };\n"
    "fluid: { density = 6.0; };\nsrd: { dt = 1.0; rule = \"hecht_axes\"; };\n"
    "thermostat: { type = \"rescale\"; temperature = 0.8; interval = 2; };\n",
    "seed = 44;\nbox: { cells = [8, 8, 8]; };\nfluid: { density = 3.0; };\nsrd: { dt = 0.1; };\n",
    "seed = 45;\nbox: { cells = [5, 7, 6]; walls_xy = \"noslip\"; };\n"
    "fluid: { density = 4.0; body_force = [0.0, 0.0, 0.02]; };\n"
    "srd: { dt = 0.4; alpha = 120.0; };\nthermostat: { type = \"heyes\"; heyes_epsilon = 0.2; };\n"
    "output: { track_fluid = true; fields_interval = 2; };\n",
    "seed = 46;\nbox: { cells = [6, 5, 4]; walls_xy = \"slip\"; walls_z = \"noslip\"; };\n"
    "fluid: { density = 5.0; body_force = [0.01, -0.02, 0.01]; };\nsrd: { dt = 0.8; rule = \"hecht_axes\"; };\n"
    "thermostat: { type = \"rescale\"; };\noutput: { track_fluid = true; };\n",
    "seed = 47;\nbox: { cells = [6, 5, 7]; walls_z = \"slip\"; };\n" /* MPC-AT (a thermostat itself) */
    "fluid: { density = 4.0; body_force = [0.01, 0.0, 0.0]; temperature = 0.9; };\n"
    "srd: { dt = 0.3; rule = \"mpc_at\"; };\noutput: { track_fluid = true; };\n",
    "seed = 48;\nbox: { cells = [5, 6, 4]; };\nfluid: { density = 5.0; };\nsrd: { dt = 0.5; rule = \"mpc_at_a\"; };\n",
    ("seed = 51;\nbox: { cells = [6, 5, 4]; walls_z = \"slip\"; };\nfluid: { density = 5.0; };\n" /* SRD+a */
     "srd: { dt = 0.3; rule = \"srd_a\"; alpha = 120.0; };\nthermostat: { type = \"rescale\"; };\n"),
    /* srd.sort_interval: the index sort between full sorts (a restart between two of them too) */
    "seed = 49;\nbox: { cells = [6, 5, 7]; walls_z = \"noslip\"; };\n"
    "fluid: { density = 4.0; body_force = [0.01, 0.0, 0.0]; };\n"
    "srd: { dt = 0.3; alpha = 120.0; sort_interval = 3; };\nthermostat: { type = \"heyes\"; heyes_epsilon = 0.2; };\n"
    "output: { track_fluid = true; fields_interval = 3; };\n",
    ("seed = 50;\nbox: { cells = [7, 6, 5]; walls_xy = \"slip\"; };\nfluid: { density = 6.0; };\n"
     "srd: { dt = 1.0; rule = \"hecht_axes\"; sort_interval = 4; };\n"),
};

Test(determinism, thread_count_does_not_change_results)
{
    long long steps = pl_test_quick() ? 10 : 60;
    for (size_t s = 0; s < sizeof scenes / sizeof *scenes; ++s) {
        pl_sim_t *ref = pl_test_sim(scenes[s], 1);
        pl_test_steps(ref, steps);
        for (int t = 2; t <= 3; ++t) {
            pl_sim_t *other = pl_test_sim(scenes[s], t);
            pl_test_steps(other, steps);
            pl_test_assert_same_fluid(ref, other, "threads");
            pl_sim_free(other);
        }
        pl_sim_free(ref);
    }
}

Test(determinism, restart_continues_bitwise)
{
    long long N = pl_test_quick() ? 5 : 40;
    char path[] = "/tmp/peloid_test_ckpt_XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    close(fd);
    for (size_t s = 0; s < sizeof scenes / sizeof *scenes; ++s) {
        pl_err_t err = {0, ""};
        pl_sim_t *full = pl_test_sim(scenes[s], 2);
        pl_test_steps(full, 2 * N);
        pl_sim_t *half = pl_test_sim(scenes[s], 1);
        pl_test_steps(half, N);
        cr_assert_eq(pl_checkpoint_write(half, path, &err), 0, "%s", err.msg);
        pl_sim_free(half);
        pl_sim_t *resumed = pl_test_sim(scenes[s], 2);
        cr_assert_eq(pl_checkpoint_read(resumed, path, &err), 0, "%s", err.msg);
        cr_assert_eq(resumed->step, N);
        pl_test_steps(resumed, N);
        pl_test_assert_same_fluid(full, resumed, "restart");
        pl_sim_free(full);
        pl_sim_free(resumed);
    }
    unlink(path);
}

Test(determinism, checkpoint_of_another_scene_is_refused)
{
    char path[] = "/tmp/peloid_test_ckpt_XXXXXX";
    int fd = mkstemp(path);
    close(fd);
    pl_err_t err = {0, ""};
    pl_sim_t *a = pl_test_sim(scenes[2], 1);
    cr_assert_eq(pl_checkpoint_write(a, path, &err), 0, "%s", err.msg);
    pl_sim_t *b = pl_test_sim(scenes[1], 1);
    cr_assert_eq(pl_checkpoint_read(b, path, &err), PL_ERR_INPUT);
    cr_assert(strstr(err.msg, "does not match the scene"), "%s", err.msg);
    pl_sim_free(a);
    pl_sim_free(b);
    unlink(path);
}

/* The plan refuses a stage past its PL_MAX_STAGES slots with an error
 * naming the stage (issue 36: a stage never vanishes silently). */
static int noop_stage(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)sim, (void)ctx, (void)err;
    return 0;
}

Test(determinism, a_full_plan_refuses_a_stage_by_name)
{
    pl_sim_t *sim = pl_test_sim(scenes[2], 1);
    int added = sim->nstages, rc = 0;
    pl_err_t err = {0};
    while (!rc && added < PL_MAX_STAGES + 4) {
        pl_stage_t s = {.name = "extra-stage", .fn = noop_stage, .slot = PL_SLOT_SAMPLE};
        if (!(rc = pl_sim_add_stage(sim, &s, &err))) ++added;
    }
    cr_assert_eq(rc, PL_ERR_INTERNAL);
    cr_assert_eq(added, PL_MAX_STAGES);
    cr_assert(strstr(err.msg, "extra-stage") && strstr(err.msg, "plan full"), "%s", err.msg);
    pl_sim_free(sim);
}
