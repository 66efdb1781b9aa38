/* The SRD fluid module (peloid/module.h): its stages (streaming with
 * binning, counting sort, collision with or without the Heyes thermostat,
 * the thermostat row's stages (peloid/thermostat.h), the fluid guard, field
 * sampling, the guard's scan before an output) and its thermo columns (temperature, momentum,
 * kinetic energy, tracked MSD, wall stresses; for physical scenes time in s
 * and the temperature in K).  PL Eqs. 3, 13, A1-A2; Hecht Eqs. 12, 33. */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/collision_rule.h"
#include "peloid/mapping.h"
#include "peloid/module.h"
#include "peloid/thermostat.h"

#include "srd_state.h"

/* ---- stages ------------------------------------------------------------ */

void pl_sim_stream_params(const pl_sim_t *sim, pl_stream_params_t *p)
{
    const pl_scene_t *sc = &sim->scene;
    memset(p, 0, sizeof *p);
    p->dt = sc->srd.dt;
    for (int d = 0; d < 3; ++d) /* + Hecht Sec. VIII.A (iii) compensation */
        p->accel[d] = sc->fluid.body_force[d] + sim->fluid_accel[d];
    memcpy(p->wall_u, sim->wall_u, sizeof p->wall_u);
}

/* ctx of every fluid stage: the fluid's state (peloid/srd.h) */
static int stage_stream(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    pl_srd_t *fs = ctx;
    const pl_scene_t *sc = &sim->scene;
    fs->sorted = 0;
    pl_grid_draw_shift(&sim->grid, (uint64_t)sc->run.seed, (uint64_t)sim->step, sc->srd.grid_shift);
    pl_stream_params_t p;
    pl_sim_stream_params(sim, &p);
    p.wall_acc = fs->wall_acc; /* NULL without walls */
    if (sim->stream_hook && sim->stream_hook_step == sim->step) {
        p.hook = sim->stream_hook;
        p.hook_ctx = sim->stream_hook_ctx;
    }
    if (sim->stream_pre_hook && sim->stream_pre_hook_step == sim->step) {
        p.pre_hook = sim->stream_pre_hook;
        p.pre_hook_ctx = sim->stream_pre_hook_ctx;
    }
    pl_srd_stream_bin(&sim->fluid, &sim->grid, &p, fs->hist, sim->nthreads);
    sim->stream_hook = sim->stream_pre_hook = NULL; /* ran (or stale) */
    if (fs->wall_acc) { /* integer sums: the same for any thread count */
        int64_t acc[PL_WALL_ACC_N] = {0};
        for (int t = 0; t < sim->nthreads; ++t)
            for (int k = 0; k < PL_WALL_ACC_N; ++k) {
                const int64_t a = fs->wall_acc[(size_t)t * PL_WALL_ACC_STRIDE + (size_t)k];
                if (acc[k] == PL_WALL_ACC_OVERFLOW) continue;
                if (a == PL_WALL_ACC_OVERFLOW || __builtin_add_overflow(acc[k], a, &acc[k]))
                    acc[k] = PL_WALL_ACC_OVERFLOW;
            }
        pl_sim_wall_add(sim, acc);
    }
    return 0;
}

/* pl_srd_stream_count + pl_srd_stream_sort (drift inside the scatter) leave
 * the same state with one pass less over the particle arrays (192 against
 * 248 B per particle), but on the 2-core development machine, where these
 * kernels are latency bound, it measured slower at 1 thread and equal at 2
 * (bench/RESULTS.md); bench_srd times both pipelines. */
/* srd.sort_interval = k > 1: the arrays are reordered on multiples of k
 * only; in between the same stable sort is done on an index (8 B moved per
 * particle instead of 100) and the collision reads through it.  The cells'
 * members are the same, their order within a cell is that of the arrays
 * (the last full sort's), so the sums of a cell round differently than with
 * k = 1: another trajectory, the same statistics (tests/physics/
 * test_sort_interval.c).  For a given k it is deterministic: both sorts are
 * stable sorts of a thread-independent array order, and the step number
 * alone says which one runs, so a restart continues bitwise too. */
static int stage_sort(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    pl_srd_t *fs = ctx;
    const long long k = sim->scene.srd.sort_interval;
    fs->indexed = k > 1 && sim->step % k != 0;
    if (fs->indexed) {
        pl_srd_sort_index(&sim->fluid, fs->hist, fs->cell_start, sim->grid.ncells, sim->nthreads);
        fs->sorted = 0;
        return 0;
    }
    pl_srd_sort(&sim->fluid, fs->hist, fs->cell_start, sim->grid.ncells, sim->nthreads);
    pl_fluid_swap(&sim->fluid);
    fs->sorted = 1;
    return 0;
}

/* The collision's parameters, fixed for the run: computed once when the
 * plan is built (only the step changes). */
static void collide_params(const pl_sim_t *sim, const pl_srd_t *fs, pl_collide_params_t *p)
{
    const pl_scene_t *sc = &sim->scene;
    memset(p, 0, sizeof *p);
    p->rule = fs->rule->srd_rotation;
    p->cos_a = cos(sc->srd.alpha_deg * PL_PI / 180.0);
    p->sin_a = sin(sc->srd.alpha_deg * PL_PI / 180.0);
    p->seed = (uint64_t)sc->run.seed;
    p->kT_target = pl_scene_kT(sc); /* the Heyes target (thermostat.temperature when Heyes runs), or the
                                     * bath of a rule that is itself a thermostat (fluid.temperature) */
    p->heyes_eps = sc->thermostat.heyes_epsilon;
    double kT_wall;
    p->wall_ghosts = pl_sim_wall_ghosts(sim, &p->ghost_density, &kT_wall);
    p->kT_wall = kT_wall;
    memcpy(p->wall_u, sim->wall_u, sizeof p->wall_u);
    p->wall_dp = p->wall_ghosts ? fs->wall_dp : NULL;
}

/* PL Eqs. A1-A2 and the virtual particles' push, summed in block order
 * (deterministic) */
static void collide_sums(pl_sim_t *sim, pl_srd_t *fs, const pl_collide_params_t *p)
{
    size_t nb = (sim->grid.ncells + PL_CELL_BLOCK - 1) / PL_CELL_BLOCK;
    for (size_t b = 0; p->wall_dp && b < nb; ++b) pl_sim_wall_add_momentum(sim, p->wall_dp + PL_WALL_ACC_N * b);
    double s2 = 0.0, dof = 0.0;
    for (size_t b = 0; b < nb; ++b) {
        s2 += fs->block_sum[2 * b];
        dof += fs->block_sum[2 * b + 1];
    }
    fs->last_kT_meas = dof > 0 ? s2 / dof : 0.0;
}

/* The step, and the fluid guard's speed test done inside the collision
 * (src/fluid/fluid_guard.c uses the flags when nothing moved the fluid
 * between the collision and the guard). */
static void collide_guard(const pl_sim_t *sim, pl_srd_t *fs)
{
    fs->collide.step = (uint64_t)sim->step;
    fs->collide.guard_bad = fs->guard_bad;
    fs->collide.guard_vmax2 = fs->guard_vmax * fs->guard_vmax;
    fs->collide.order = fs->indexed ? sim->fluid.order : NULL;
    fs->guard_bad_step = sim->step;
}

/* The collision by the rule's kernel (fs->rule, peloid/collision_rule.h). */
static int stage_collide(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    pl_srd_t *fs = ctx;
    collide_guard(sim, fs);
    fs->rule->collide(&sim->fluid, &sim->grid, fs->cell_start, &fs->collide, fs->block_sum, sim->nthreads);
    collide_sums(sim, fs, &fs->collide);
    return 0;
}

/* The collision with the Heyes thermostat (Hecht Sec. VIII.B): the plan's
 * variant on multiples of thermostat.interval. */
static int stage_collide_heyes(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    pl_srd_t *fs = ctx;
    collide_guard(sim, fs);
    fs->rule->collide_heyes(&sim->fluid, &sim->grid, fs->cell_start, &fs->collide, fs->block_sum, sim->nthreads);
    collide_sums(sim, fs, &fs->collide);
    return 0;
}

static int stage_fields(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    pl_srd_t *fs = ctx;
    if (sim->step < sim->scene.output.fields_start) return 0;
    pl_srd_fields_accumulate(&sim->fluid, sim->grid.L, fs->field_acc, sim->nthreads);
    fs->field_samples++;
    return 0;
}

/* The fluid's stages, each at its slot; none without fluid particles. */
static int fluid_stages(pl_sim_t *sim, pl_err_t *err)
{
    int rc;
    const pl_scene_t *sc = &sim->scene;
    pl_srd_t *fs = sim->srd;
    if (sim->fluid.n == 0) return 0;
    pl_stage_t og = {.name = "output-guard", .fn = pl_fluid_output_guard_stage, .ctx = fs,
                     .phase = PL_PHASE_AFTER, .slot = PL_SLOT_OUTPUT_GUARD};
    pl_stage_t stream = {.name = "stream+bin", .fn = stage_stream, .ctx = fs, .slot = PL_SLOT_STREAM};
    pl_stage_t sort = {.name = "sort", .fn = stage_sort, .ctx = fs, .slot = PL_SLOT_SORT};
    if ((rc = pl_sim_add_stage(sim, &og, err))) return rc;
    if ((rc = pl_sim_add_stage(sim, &stream, err))) return rc;
    if ((rc = pl_sim_add_stage(sim, &sort, err))) return rc;
    collide_params(sim, fs, &fs->collide);
    /* the Heyes row's validate refused a rule whose collide_heyes is NULL */
    pl_stage_t plain = {.name = "collide", .fn = stage_collide, .ctx = fs, .slot = PL_SLOT_COLLIDE};
    pl_stage_t heyes = {.name = "collide+heyes", .fn = stage_collide_heyes, .ctx = fs, .slot = PL_SLOT_COLLIDE};
    if ((rc = pl_sim_add_collide_stage(sim, &plain, &heyes, err))) return rc;
    const pl_thermostat_t *thermostat = pl_thermostat(sc->thermostat.type);
    if (thermostat->add_stages && (rc = thermostat->add_stages(sim, fs, err))) return rc;
    /* last before anything samples or moves the fluid again: nothing
     * non-finite reaches an output or the next stream */
    pl_stage_t g = {.name = "fluid-guard", .fn = pl_fluid_guard_stage, .ctx = fs,
                    .interval = PL_FLUID_GUARD_INTERVAL, .slot = PL_SLOT_GUARD};
    if ((rc = pl_sim_add_stage(sim, &g, err))) return rc;
    if (sc->output.fields_interval > 0) {
        pl_stage_t f = {.name = "fields", .fn = stage_fields, .ctx = fs, .interval = sc->output.fields_interval,
                        .slot = PL_SLOT_SAMPLE};
        if ((rc = pl_sim_add_stage(sim, &f, err))) return rc;
    }
    return 0;
}

/* ---- thermo columns ------------------------------------------------------ */

static double v_time(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return (double)s->sim->step * s->sim->scene.srd.dt;
}
static double v_kT(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->kT;
}
static double v_kT_cell(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->sim->srd->last_kT_meas;
}
static double v_momentum(const pl_thermo_sample_t *s, int d) { return s->fluid.momentum[d]; }
static double v_kinetic(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->fluid.kinetic;
}
static double v_msd(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->fluid.msd;
}
/* physical units (Hecht Sec. VII): kT = 1 is the model temperature */
static double v_time_s(const pl_thermo_sample_t *s, int a)
{
    return v_time(s, a) * s->sim->scene.mapping.map.t0;
}
/* physical units: kT = 1 stands for the real temperature T; in the model's
 * own SI units it is kT_model (Hecht Sec. VII.B) */
static double v_temperature_K(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->kT * s->sim->scene.mapping.physical.temperature;
}
static double v_model_temperature_K(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->kT * s->sim->scene.mapping.map.kT_model / PL_KB;
}
/* arg = 3 wall + d: PL Eq. 13 stress from each wall's momentum, mean since step 0 */
static double v_wall_stress(const pl_thermo_sample_t *s, int a) { return pl_sim_wall_stress(s->sim, a / 3, a % 3); }

static const pl_thermo_column_t mapped_cols[] = {
    {.name = "time_s", .unit = "s", .value = v_time_s},
    {.name = "temperature_K", .unit = "K", .value = v_temperature_K},
    {.name = "model_temperature_K", .unit = "K", .value = v_model_temperature_K},
};
static const pl_thermo_column_t fluid_cols[] = {
    {.name = "temperature", .unit = "kT", .value = v_kT},
    {.name = "kT_cell", .unit = "kT", .value = v_kT_cell}, /* PL Eq. A1, last collision */
    {.name = "px", .unit = "m_f a0/t0", .value = v_momentum, .arg = 0},
    {.name = "py", .unit = "m_f a0/t0", .value = v_momentum, .arg = 1},
    {.name = "pz", .unit = "m_f a0/t0", .value = v_momentum, .arg = 2},
    {.name = "kinetic_energy", .unit = "kT", .value = v_kinetic},
};
static const pl_thermo_column_t tracked_cols[] = {
    {.name = "msd", .unit = "a0^2", .value = v_msd},
};
static const pl_thermo_column_t wall_cols[] = {
    {.name = "sxz_bottom", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 0},
    {.name = "sxz_top", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 3},
    {.name = "syz_bottom", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 1},
    {.name = "syz_top", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 4},
};
static const pl_thermo_column_t side_wall_cols[] = { /* force per area on the x/y walls */
    {.name = "s_side_x", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 6},
    {.name = "s_side_y", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 7},
    {.name = "s_side_z", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 8},
};

#define NCOL(a) ((int)(sizeof(a) / sizeof(a[0])))

static void fluid_columns(const pl_sim_t *sim, pl_thermo_table_t *t)
{
    const pl_scene_t *sc = &sim->scene;
    if (sc->mapping.enabled) pl_thermo_add(t, mapped_cols, NCOL(mapped_cols));
    pl_thermo_add(t, fluid_cols, NCOL(fluid_cols));
    if (sim->fluid.tracked) pl_thermo_add(t, tracked_cols, NCOL(tracked_cols));
    if (sc->box.walls_z == PL_WALLS_NOSLIP && sim->fluid.n > 0) pl_thermo_add(t, wall_cols, NCOL(wall_cols));
    if (sc->box.walls_xy == PL_WALLS_NOSLIP && sim->fluid.n > 0)
        pl_thermo_add(t, side_wall_cols, NCOL(side_wall_cols));
}

/* The fluid's state (src/fluid/fluid_state.c): the first module, so the
 * colloids and the coupling find the fluid made. */
static int fluid_create(pl_sim_t *sim, pl_err_t *err) { return pl_fluid_state_create(sim, err); }

/* The collision rule's and the thermostat's own checks
 * (peloid/collision_rule.h, peloid/thermostat.h), and those every rule
 * gets from its flags: a rule that is a thermostat refuses a second one,
 * coupling II needs a plain rotation rule (it rotates its colloids' cells
 * again by the SRD rotation alone), no-slip walls need a kernel with their
 * virtual particles. */
static int fluid_validate(const pl_scene_t *sc, pl_err_t *err)
{
    const pl_collision_rule_t *rule = pl_collision_rule(sc->srd.rule);
    const pl_thermostat_t *thermostat = pl_thermostat(sc->thermostat.type);
    if (rule->thermostat && sc->thermostat.type != PL_THERMO_NONE)
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, thermostat.type), "thermostat.type",
                             "a thermostat with srd.rule = \"%s\", which is itself one (it draws the relative "
                             "velocities at fluid.temperature); allowed: \"none\"", rule->name);
    int rc = thermostat->validate ? thermostat->validate(sc, err) : 0;
    if (rc) return rc;
    if (sc->coupling.method == PL_COUPLE_HECHT2 && (rule->srd_rotation < 0 || rule->angular))
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, srd.rule), "srd.rule",
                             "\"%s\" with coupling II, which rotates the cells that hold colloids by the SRD "
                             "rotation alone; allowed with coupling II: a rotation rule (random_axis, hecht_axes)",
                             rule->name);
    if (sc->srd.sort_interval > 1) { /* what reads the cells as contiguous arrays */
        const int coupled = sc->coupling.method != PL_COUPLE_NONE && sc->colloids.count > 0;
        const char *why = rule->collide != pl_srd_collide
                              ? "the rule's kernel reads each cell's particles contiguous (only random_axis and "
                                "hecht_axes read through the index)"
                          : coupled ? "a coupling reads the fluid in cell order"
                                    : NULL;
        if (why)
            return pl_scene_fail(sc, err, offsetof(pl_scene_t, srd.sort_interval), "srd.sort_interval",
                                 "%lld: %s; allowed here: 1", sc->srd.sort_interval, why);
    }
    if (!rule->wall_ghosts && (sc->box.walls_z == PL_WALLS_NOSLIP || sc->box.walls_xy == PL_WALLS_NOSLIP))
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, srd.rule), "srd.rule",
                             "\"%s\" with no-slip walls (box.walls_z or walls_xy = \"noslip\"): the virtual wall "
                             "particles are the SRD kernel's only; allowed: periodic or slip walls", rule->name);
    return rule->validate ? rule->validate(sc, err) : 0;
}

const pl_module_t pl_fluid_module = {
    .name = "fluid",
    .validate_scene = fluid_validate,
    .create = fluid_create,
    .destroy = pl_fluid_state_free,
    .add_stages = fluid_stages,
    .thermo_columns = fluid_columns,
    .checkpoint_attrs = pl_fluid_ckpt_attrs,
    .checkpoint_write = pl_fluid_ckpt_write,
    .checkpoint_write_last = pl_fluid_ckpt_write_last,
    .checkpoint_read = pl_fluid_ckpt_read,
};
