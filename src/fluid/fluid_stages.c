/* The SRD fluid module (peloid/module.h): its stages (streaming with
 * binning, counting sort, collision with or without the Heyes thermostat,
 * the rescaling thermostat, the fluid guard, field sampling, the guard's
 * scan before an output) and its thermo columns (temperature, momentum,
 * kinetic energy, tracked MSD, wall stresses; for physical scenes time in s
 * and the temperature in K).  PL Eqs. 3, 13, A1-A2; Hecht Eqs. 12, 33. */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/collision_rule.h"
#include "peloid/coupling.h"
#include "peloid/mapping.h"
#include "peloid/module.h"

/* ---- stages ------------------------------------------------------------ */

void pl_sim_stream_params(const pl_sim_t *sim, pl_stream_params_t *p)
{
    const pl_scene_t *sc = &sim->scene;
    memset(p, 0, sizeof *p);
    p->dt = sc->srd.dt;
    for (int d = 0; d < 3; ++d) /* + Hecht Sec. VIII.A (iii) compensation */
        p->accel[d] = sc->fluid.body_force[d] + (sim->coupling ? sim->coupling->fluid_accel[d] : 0.0);
    memcpy(p->wall_u, sim->wall_u, sizeof p->wall_u);
}

static int stage_stream(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    (void)err;
    const pl_scene_t *sc = &sim->scene;
    sim->fluid_sorted = 0;
    pl_grid_draw_shift(&sim->grid, (uint64_t)sc->run.seed, (uint64_t)sim->step, sc->srd.grid_shift);
    pl_stream_params_t p;
    pl_sim_stream_params(sim, &p);
    p.wall_acc = sim->wall_acc; /* NULL without walls */
    if (sim->stream_hook && sim->stream_hook_step == sim->step) {
        p.hook = sim->stream_hook;
        p.hook_ctx = sim->stream_hook_ctx;
    }
    if (sim->stream_pre_hook && sim->stream_pre_hook_step == sim->step) {
        p.pre_hook = sim->stream_pre_hook;
        p.pre_hook_ctx = sim->stream_pre_hook_ctx;
    }
    pl_srd_stream_bin(&sim->fluid, &sim->grid, &p, sim->hist, sim->nthreads);
    sim->stream_hook = sim->stream_pre_hook = NULL; /* ran (or stale) */
    if (sim->wall_acc) { /* integer sums: the same for any thread count */
        int64_t acc[PL_WALL_ACC_N] = {0};
        for (int t = 0; t < sim->nthreads; ++t)
            for (int k = 0; k < PL_WALL_ACC_N; ++k) {
                const int64_t a = sim->wall_acc[(size_t)t * PL_WALL_ACC_STRIDE + (size_t)k];
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
    (void)ctx;
    (void)err;
    const long long k = sim->scene.srd.sort_interval;
    sim->fluid_indexed = k > 1 && sim->step % k != 0;
    if (sim->fluid_indexed) {
        pl_srd_sort_index(&sim->fluid, sim->hist, sim->cell_start, sim->grid.ncells, sim->nthreads);
        sim->fluid_sorted = 0;
        return 0;
    }
    pl_srd_sort(&sim->fluid, sim->hist, sim->cell_start, sim->grid.ncells, sim->nthreads);
    pl_fluid_swap(&sim->fluid);
    sim->fluid_sorted = 1;
    return 0;
}

/* The collision's parameters, fixed for the run: computed once when the
 * plan is built (only the step changes). */
static void collide_params(const pl_sim_t *sim, pl_collide_params_t *p)
{
    const pl_scene_t *sc = &sim->scene;
    memset(p, 0, sizeof *p);
    p->rule = pl_collision_rule(sc->srd.rule)->srd_rotation;
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
    p->wall_dp = p->wall_ghosts ? sim->wall_dp : NULL;
}

/* PL Eqs. A1-A2 and the virtual particles' push, summed in block order
 * (deterministic) */
static void collide_sums(pl_sim_t *sim, const pl_collide_params_t *p)
{
    size_t nb = (sim->grid.ncells + PL_CELL_BLOCK - 1) / PL_CELL_BLOCK;
    for (size_t b = 0; p->wall_dp && b < nb; ++b) pl_sim_wall_add_momentum(sim, p->wall_dp + PL_WALL_ACC_N * b);
    double s2 = 0.0, dof = 0.0;
    for (size_t b = 0; b < nb; ++b) {
        s2 += sim->block_sum[2 * b];
        dof += sim->block_sum[2 * b + 1];
    }
    sim->last_kT_meas = dof > 0 ? s2 / dof : 0.0;
}

/* The step, and the fluid guard's speed test done inside the collision
 * (src/fluid/fluid_guard.c uses the flags when nothing moved the fluid
 * between the collision and the guard). */
static void collide_guard(pl_sim_t *sim)
{
    sim->collide.step = (uint64_t)sim->step;
    sim->collide.guard_bad = sim->guard_bad;
    sim->collide.guard_vmax2 = sim->guard_vmax * sim->guard_vmax;
    sim->collide.order = sim->fluid_indexed ? sim->fluid.order : NULL;
    sim->guard_bad_step = sim->step;
}

/* ctx: the collision rule's row (peloid/collision_rule.h) */
static int stage_collide(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    const pl_collision_rule_t *rule = ctx;
    collide_guard(sim);
    rule->collide(&sim->fluid, &sim->grid, sim->cell_start, &sim->collide, sim->block_sum, sim->nthreads);
    collide_sums(sim, &sim->collide);
    return 0;
}

/* The collision with the Heyes thermostat (Hecht Sec. VIII.B): the plan's
 * variant on multiples of thermostat.interval. */
static int stage_collide_heyes(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    const pl_collision_rule_t *rule = ctx;
    collide_guard(sim);
    rule->collide_heyes(&sim->fluid, &sim->grid, sim->cell_start, &sim->collide, sim->block_sum, sim->nthreads);
    collide_sums(sim, &sim->collide);
    return 0;
}

static int stage_rescale(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    (void)err;
    if (sim->last_kT_meas <= 0.0) return 0;
    double factor = sqrt(sim->scene.thermostat.temperature / sim->last_kT_meas); /* PL App. A */
    pl_srd_rescale(&sim->fluid, sim->cell_start, sim->grid.ncells, factor, sim->nthreads);
    sim->last_kT_meas = sim->scene.thermostat.temperature;
    return 0;
}

static int stage_fields(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    (void)err;
    if (sim->step < sim->scene.output.fields_start) return 0;
    pl_srd_fields_accumulate(&sim->fluid, sim->grid.L, sim->field_acc, sim->nthreads);
    sim->field_samples++;
    return 0;
}

/* After-step stage: before any output is written, the fluid guard's
 * particle scan on the state it writes (the fluid-guard stage scanned this
 * state already on multiples of its scan interval). */
static int stage_output_guard(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    if (sim->step % PL_FLUID_GUARD_SCAN_INTERVAL == 0) return 0;
    for (int k = 0; k < sim->nstages; ++k) {
        const pl_stage_t *s = &sim->stages[k];
        if (s->phase == PL_PHASE_AFTER && s->writes && pl_sim_stage_due(sim, s, sim->step))
            return pl_fluid_guard_check(sim, sim->step, 1, err);
    }
    return 0;
}

/* The fluid's stages, each at its slot; none without fluid particles. */
static int fluid_stages(pl_sim_t *sim, pl_err_t *err)
{
    int rc;
    const pl_scene_t *sc = &sim->scene;
    if (sim->fluid.n == 0) return 0;
    pl_stage_t og = {.name = "output-guard", .fn = stage_output_guard, .phase = PL_PHASE_AFTER,
                     .slot = PL_SLOT_OUTPUT_GUARD};
    pl_stage_t stream = {.name = "stream+bin", .fn = stage_stream, .slot = PL_SLOT_STREAM};
    pl_stage_t sort = {.name = "sort", .fn = stage_sort, .slot = PL_SLOT_SORT};
    if ((rc = pl_sim_add_stage(sim, &og, err))) return rc;
    if ((rc = pl_sim_add_stage(sim, &stream, err))) return rc;
    if ((rc = pl_sim_add_stage(sim, &sort, err))) return rc;
    collide_params(sim, &sim->collide);
    /* the row's validate refused the Heyes thermostat where collide_heyes is NULL */
    void *rule = (void *)pl_collision_rule(sc->srd.rule);
    pl_stage_t plain = {.name = "collide", .fn = stage_collide, .ctx = rule, .slot = PL_SLOT_COLLIDE};
    pl_stage_t heyes = {.name = "collide+heyes", .fn = stage_collide_heyes, .ctx = rule, .slot = PL_SLOT_COLLIDE};
    if ((rc = pl_sim_add_collide_stage(sim, &plain, &heyes, err))) return rc;
    if (sc->thermostat.type == PL_THERMO_RESCALE) {
        pl_stage_t r = {.name = "thermostat-rescale", .fn = stage_rescale, .interval = sc->thermostat.interval,
                        .slot = PL_SLOT_THERMOSTAT};
        if ((rc = pl_sim_add_stage(sim, &r, err))) return rc;
    }
    /* last before anything samples or moves the fluid again: nothing
     * non-finite reaches an output or the next stream */
    pl_stage_t g = {.name = "fluid-guard", .fn = pl_fluid_guard_stage, .interval = PL_FLUID_GUARD_INTERVAL,
                    .slot = PL_SLOT_GUARD};
    if ((rc = pl_sim_add_stage(sim, &g, err))) return rc;
    if (sc->output.fields_interval > 0) {
        pl_stage_t f = {.name = "fields", .fn = stage_fields, .interval = sc->output.fields_interval,
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
    return s->sim->last_kT_meas;
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

/* The fluid's arrays and grid belong to every simulation (pl_sim_create
 * makes them); the module's own state is the fluid guard's bounds, which
 * depend on the scene alone. */
static int fluid_create(pl_sim_t *sim, pl_err_t *err)
{
    (void)err;
    pl_fluid_guard_setup(sim);
    return 0;
}

/* The collision rule's own check (peloid/collision_rule.h), and those every
 * rule gets: a rule without a Heyes kernel refuses the Heyes thermostat, a
 * rule that is a thermostat refuses a second one, coupling II needs a
 * rotation rule. */
static int fluid_validate(const pl_scene_t *sc, pl_err_t *err)
{
    const pl_collision_rule_t *rule = pl_collision_rule(sc->srd.rule);
    const int t = sc->thermostat.type;
    if (rule->thermostat && t != PL_THERMO_NONE)
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, thermostat.type), "thermostat.type",
                             "a thermostat with srd.rule = \"%s\", which is itself one (it draws the relative "
                             "velocities at fluid.temperature); allowed: \"none\"", rule->name);
    if (t == PL_THERMO_HEYES && !rule->collide_heyes)
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, thermostat.type), "thermostat.type",
                             "\"heyes\" with srd.rule = \"%s\", which has no Heyes collision; allowed: "
                             "\"none\" or \"rescale\"", rule->name);
    if (sc->coupling.method == PL_COUPLE_HECHT2 && rule->srd_rotation < 0)
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, srd.rule), "srd.rule",
                             "\"%s\" with coupling II, which rotates the cells that hold colloids by the SRD "
                             "rotation; allowed with coupling II: a rotation rule (random_axis, hecht_axes)",
                             rule->name);
    if (sc->srd.sort_interval > 1) { /* what reads the cells as contiguous arrays */
        const int coupled = sc->coupling.method != PL_COUPLE_NONE && sc->colloids.count > 0;
        const char *why = rule->collide != pl_srd_collide
                              ? "the rule's kernel reads each cell's particles contiguous (only random_axis and "
                                "hecht_axes read through the index)"
                          : t == PL_THERMO_RESCALE ? "thermostat.type = \"rescale\" reads each cell's particles "
                                                     "contiguous"
                          : coupled ? "a coupling reads the fluid in cell order"
                                    : NULL;
        if (why)
            return pl_scene_fail(sc, err, offsetof(pl_scene_t, srd.sort_interval), "srd.sort_interval",
                                 "%lld: %s; allowed here: 1", sc->srd.sort_interval, why);
    }
    return rule->validate ? rule->validate(sc, err) : 0;
}

const pl_module_t pl_fluid_module = {
    .name = "fluid",
    .validate_scene = fluid_validate,
    .create = fluid_create,
    .add_stages = fluid_stages,
    .thermo_columns = fluid_columns,
};
