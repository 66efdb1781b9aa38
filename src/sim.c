/* Simulation object: state allocation, the plan (ordered stages, each with an
 * interval) and the step loop.  A stage the scene does not need is not in
 * the plan (DESIGN.md "Scene -> plan"): no thermostat stage without a
 * thermostat, no fluid stages without fluid. */
#include <hwloc.h>
#include <limits.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/sim.h"

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
    pl_srd_stream_bin(&sim->fluid, &sim->grid, &p, sim->hist, sim->nthreads);
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

void pl_sim_wall_add(pl_sim_t *sim, const int64_t acc[PL_WALL_ACC_N])
{
    for (int k = 0; k < PL_WALL_ACC_N; ++k) {
        if (acc[k] == PL_WALL_ACC_OVERFLOW) { /* the fluid guard stops the run */
            sim->wall_acc_overflow = 1;
            continue;
        }
        sim->wall_impulse[k / 3][k % 3] += ldexp((double)acc[k], -PL_FIELD_FIXED_SHIFT);
    }
}

void pl_sim_wall_add_momentum(pl_sim_t *sim, const double dp[PL_WALL_ACC_N])
{
    for (int k = 0; k < PL_WALL_ACC_N; ++k) sim->wall_impulse[k / 3][k % 3] += dp[k];
}

int pl_sim_wall_ghosts(const pl_sim_t *sim, double *density, double *kT_wall)
{
    const pl_scene_t *sc = &sim->scene;
    *density = sc->fluid.density;
    *kT_wall = pl_scene_kT(sc);
    return sc->box.walls_z == PL_WALLS_NOSLIP || sc->box.walls_xy == PL_WALLS_NOSLIP;
}

double pl_sim_wall_stress(const pl_sim_t *sim, int wall, int d)
{
    const int *L = sim->grid.L;
    const double t = (double)sim->step * sim->scene.srd.dt;
    if (!(t > 0.0)) return 0.0;
    if (wall == 2) /* the x/y walls: force the fluid exerts on them per area */
        return -sim->wall_impulse[2][d] / (2.0 * ((double)L[0] + L[1]) * L[2] * t);
    return (wall ? 1.0 : -1.0) * sim->wall_impulse[wall][d] / ((double)L[0] * L[1] * t);
}

/* pl_srd_stream_count + pl_srd_stream_sort (drift inside the scatter) leave
 * the same state with one pass less over the particle arrays (192 against
 * 248 B per particle), but on the 2-core development machine, where these
 * kernels are latency bound, it measured slower at 1 thread and equal at 2
 * (bench/RESULTS.md); bench_srd times both pipelines. */
static int stage_sort(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    (void)err;
    pl_srd_sort(&sim->fluid, sim->hist, sim->cell_start, sim->grid.ncells, sim->nthreads);
    sim->fluid_sorted = 1;
    return 0;
}

/* The collision's parameters, fixed for the run: computed once when the
 * plan is built (only the step changes). */
static void collide_params(const pl_sim_t *sim, pl_collide_params_t *p)
{
    const pl_scene_t *sc = &sim->scene;
    memset(p, 0, sizeof *p);
    p->rule = sc->srd.rule;
    p->cos_a = cos(sc->srd.alpha_deg * PL_PI / 180.0);
    p->sin_a = sin(sc->srd.alpha_deg * PL_PI / 180.0);
    p->seed = (uint64_t)sc->run.seed;
    p->kT_target = sc->thermostat.temperature;
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

static int stage_collide(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    (void)err;
    sim->collide.step = (uint64_t)sim->step;
    pl_srd_collide(&sim->fluid, &sim->grid, sim->cell_start, &sim->collide, sim->block_sum, sim->nthreads);
    collide_sums(sim, &sim->collide);
    return 0;
}

/* The collision with the Heyes thermostat (Hecht Sec. VIII.B): the plan's
 * variant on multiples of thermostat.interval. */
static int stage_collide_heyes(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    (void)err;
    sim->collide.step = (uint64_t)sim->step;
    pl_srd_collide_heyes(&sim->fluid, &sim->grid, sim->cell_start, &sim->collide, sim->block_sum, sim->nthreads);
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

/* Colloid MD: colloids.substeps MD steps of dt_MD = srd.dt / substeps. */
static int stage_colloid_md(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    return pl_colloid_advance(sim->colloids, sim->step, err);
}

static int stage_colloid_traj(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)ctx;
    if (!sim->colloid_traj) return 0;
    return pl_colloid_traj_write(sim->colloid_traj, sim->colloids, sim->step,
                                 (double)sim->step * sim->scene.srd.dt, err);
}

static void add_stage(pl_sim_t *sim, const char *name, pl_stage_fn fn, long long interval)
{
    pl_stage_t s = {.name = name, .fn = fn, .interval = interval, .phase = PL_PHASE_STEP};
    pl_sim_add_stage(sim, &s, NULL); /* the built-in stages fit PL_MAX_STAGES */
}

int pl_sim_add_stage(pl_sim_t *sim, const pl_stage_t *stage, pl_err_t *err)
{
    if (sim->nstages >= PL_MAX_STAGES)
        return err ? pl_err_set(err, PL_ERR_INTERNAL, "plan full: %d stages, stage %s left out", PL_MAX_STAGES,
                                stage->name)
                   : PL_ERR_INTERNAL;
    pl_stage_t *s = &sim->stages[sim->nstages++];
    *s = *stage;
    if (s->interval <= 0) s->interval = 1;
    s->seconds = 0.0;
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

/* The step's plan: the fluid's and colloids' stages in the order their
 * data flow needs (the couplings' stages between them); writers and
 * observers add after-step stages when the run opens its outputs. */
static void build_plan(pl_sim_t *sim)
{
    const pl_scene_t *sc = &sim->scene;
    sim->nstages = 0;
    if (sim->fluid.n > 0) { /* first of the after-step stages */
        pl_stage_t g = {.name = "output-guard", .fn = stage_output_guard, .interval = 1, .phase = PL_PHASE_AFTER};
        pl_sim_add_stage(sim, &g, NULL);
    }
    if (sim->colloids) {
        if (sc->colloids.trajectory_interval > 0) {
            pl_stage_t t = {.name = "colloid-trajectory", .fn = stage_colloid_traj,
                            .interval = sc->colloids.trajectory_interval, .phase = PL_PHASE_AFTER,
                            .at_start = 1, .at_end = 1, .writes = 1};
            pl_sim_add_stage(sim, &t, NULL);
        }
        /* pinned colloids do not move; the potential coupling runs the
         * colloid MD together with the fluid near them */
        if (!(sim->coupling && (sim->coupling->pinned || sim->coupling->method == PL_COUPLE_POTENTIAL)))
            add_stage(sim, "colloid-md", stage_colloid_md, 1);
    }
    if (sim->fluid.n > 0) {
        int m = sim->coupling ? sim->coupling->method : PL_COUPLE_NONE;
        if (m == PL_COUPLE_POTENTIAL) add_stage(sim, "potential-select", pl_coupling_stage_select, 1);
        add_stage(sim, "stream+bin", stage_stream, 1);
        if (m == PL_COUPLE_POTENTIAL) add_stage(sim, "potential-md", pl_coupling_stage_potential_md, 1);
        if (m == PL_COUPLE_HECHT1) add_stage(sim, "coupling1-reflect", pl_coupling_stage_reflect, 1);
        add_stage(sim, "sort", stage_sort, 1);
        if (m == PL_COUPLE_HECHT2) add_stage(sim, "coupling2-save", pl_coupling_stage_save, 1);
        collide_params(sim, &sim->collide);
        if (sc->thermostat.type == PL_THERMO_HEYES) { /* one of the two variants each step */
            const long long k = sc->thermostat.interval;
            pl_stage_t plain = {.name = "collide", .fn = stage_collide, .interval = 1, .except = k};
            pl_stage_t heyes = {.name = "collide+heyes", .fn = stage_collide_heyes, .interval = k};
            if (k > 1) pl_sim_add_stage(sim, &plain, NULL);
            pl_sim_add_stage(sim, &heyes, NULL);
            if (m == PL_COUPLE_HECHT2) {
                pl_stage_t c2 = {.name = "coupling2-collide", .fn = pl_coupling_stage_collide, .interval = 1,
                                 .except = k};
                pl_stage_t c2h = {.name = "coupling2-collide+heyes", .fn = pl_coupling_stage_collide_heyes,
                                  .interval = k};
                if (k > 1) pl_sim_add_stage(sim, &c2, NULL);
                pl_sim_add_stage(sim, &c2h, NULL);
            }
        } else {
            add_stage(sim, "collide", stage_collide, 1);
            if (m == PL_COUPLE_HECHT2) add_stage(sim, "coupling2-collide", pl_coupling_stage_collide, 1);
        }
        if (sc->thermostat.type == PL_THERMO_RESCALE)
            add_stage(sim, "thermostat-rescale", stage_rescale, sc->thermostat.interval);
        /* last before anything samples or moves the fluid again: nothing
         * non-finite reaches an output or the next stream */
        add_stage(sim, "fluid-guard", pl_fluid_guard_stage, PL_FLUID_GUARD_INTERVAL);
        if (sc->output.fields_interval > 0)
            add_stage(sim, "fields", stage_fields, sc->output.fields_interval);
        const double *fv = sc->coupling.flow_velocity;
        if (sim->coupling && sim->coupling->pinned && (fv[0] != 0.0 || fv[1] != 0.0 || fv[2] != 0.0))
            add_stage(sim, "flow-hold", pl_coupling_stage_flow, 1);
        /* momentum is not conserved with walls: nothing to remove */
        if (sim->coupling && sc->coupling.drift_interval > 0 && !sim->grid.any_walls)
            add_stage(sim, "drift-removal", pl_coupling_stage_drift, sc->coupling.drift_interval);
    }
}

/* ---- lifetime ---------------------------------------------------------- */

/* Pins OpenMP thread t to the t-th of nthreads core sets spread over the
 * machine by hwloc_distrib (packages first), unless the user chose a binding
 * (OMP_PROC_BIND) or set PL_NO_BIND.  Done before the allocations, whose
 * first touch then places each thread's pages on its own NUMA node. */
static void bind_threads(int nthreads)
{
    if (nthreads < 2 || omp_get_proc_bind() != omp_proc_bind_false || getenv("PL_NO_BIND")) return;
    hwloc_topology_t topo;
    if (hwloc_topology_init(&topo)) return;
    if (hwloc_topology_load(topo)) {
        hwloc_topology_destroy(topo);
        return;
    }
    int ncores = hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_CORE);
    if (ncores >= nthreads && nthreads <= 1024) {
        hwloc_bitmap_t sets[1024];
        hwloc_obj_t root = hwloc_get_root_obj(topo);
        if (hwloc_distrib(topo, &root, 1, sets, (unsigned)nthreads, INT_MAX, 0) == 0) {
            /* the one parallel region outside kernels/: topology set-up (each
             * thread of the team binds itself), not a loop over data */
#pragma omp parallel num_threads(nthreads)
            {
                hwloc_bitmap_t set = sets[omp_get_thread_num()];
                hwloc_bitmap_singlify(set);
                hwloc_set_cpubind(topo, set, HWLOC_CPUBIND_THREAD);
            }
            for (int t = 0; t < nthreads; ++t) hwloc_bitmap_free(sets[t]);
        }
    }
    hwloc_topology_destroy(topo);
}

int pl_sim_create(const pl_scene_t *scene, int nthreads, pl_sim_t **out, pl_err_t *err)
{
    pl_sim_t *sim = calloc(1, sizeof *sim);
    if (!sim) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    sim->scene = *scene;
    sim->nthreads = nthreads > 0 ? nthreads : omp_get_max_threads();
    /* before any allocation: first touch (pl_alloc) runs on the bound
     * threads.  No process-wide thread count is set: every kernel and
     * pl_alloc are given sim->nthreads (num_threads clauses). */
    bind_threads(sim->nthreads);
    int walls[3];
    pl_scene_box_walls(&scene->box, walls);
    pl_grid_init(&sim->grid, scene->box.cells, walls);
    double volume = (double)scene->box.cells[0] * scene->box.cells[1] * scene->box.cells[2];
    size_t n = (size_t)llround(scene->fluid.density * volume);
    int rc = pl_fluid_create(n, scene->output.track_fluid, sim->nthreads, &sim->fluid, err);
    if (rc) {
        free(sim);
        return rc;
    }
    size_t nc = sim->grid.ncells, L3 = (size_t)scene->box.cells[0] * (size_t)scene->box.cells[1] *
                                          (size_t)scene->box.cells[2];
    size_t nb = (nc + PL_CELL_BLOCK - 1) / PL_CELL_BLOCK;
    sim->hist = pl_alloc((size_t)sim->nthreads * nc * sizeof(uint32_t), sim->nthreads);
    sim->cell_start = pl_alloc((nc + 1) * sizeof(uint32_t), sim->nthreads);
    sim->block_sum = pl_alloc(2 * nb * sizeof(double), sim->nthreads);
    sim->obs_scratch = pl_alloc(pl_srd_observe_scratch(n) * sizeof(double), sim->nthreads);
    if (scene->output.fields_interval > 0) sim->field_acc = pl_alloc(4 * L3 * sizeof(int64_t), sim->nthreads);
    /* the momentum each wall exchanges (wall stress) */
    const int any_walls = sim->grid.any_walls;
    if (any_walls) {
        sim->wall_acc = pl_alloc((size_t)sim->nthreads * PL_WALL_ACC_STRIDE * sizeof(int64_t), sim->nthreads);
        sim->wall_dp = pl_alloc(PL_WALL_ACC_N * nb * sizeof(double), sim->nthreads);
    }
    memcpy(sim->wall_u, scene->box.wall_velocity, sizeof sim->wall_u); /* shear, Hecht Sec. VIII.C */
    if (!sim->hist || !sim->cell_start || !sim->block_sum || !sim->obs_scratch ||
        (scene->output.fields_interval > 0 && !sim->field_acc) || (any_walls && (!sim->wall_acc || !sim->wall_dp))) {
        pl_sim_free(sim);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the cell arrays (%zu cells)", nc);
    }
    pl_fluid_init(&sim->fluid, scene, sim->nthreads);
    if (scene->colloids.count > 0 && (rc = pl_colloid_create(scene, sim->nthreads, &sim->colloids, err))) {
        pl_sim_free(sim);
        return rc;
    }
    if (sim->colloids && n > 0 &&
        (scene->coupling.method != PL_COUPLE_NONE || scene->coupling.drift_interval > 0) &&
        (rc = pl_coupling_create(sim, &sim->coupling, err))) {
        pl_sim_free(sim);
        return rc;
    }
    pl_fluid_guard_setup(sim);
    build_plan(sim);
    *out = sim;
    return 0;
}

void pl_sim_free(pl_sim_t *sim)
{
    if (!sim) return;
    pl_fluid_free(&sim->fluid);
    pl_colloid_traj_close(sim->colloid_traj, NULL);
    pl_coupling_free(sim->coupling);
    pl_colloid_free(sim->colloids);
    pl_free(sim->hist);
    pl_free(sim->cell_start);
    pl_free(sim->block_sum);
    pl_free(sim->obs_scratch);
    pl_free(sim->field_acc);
    pl_free(sim->wall_acc);
    pl_free(sim->wall_dp);
    free(sim);
}

int pl_sim_stage_due(const pl_sim_t *sim, const pl_stage_t *s, long long step)
{
    if (s->except > 0 && step % s->except == 0) return 0;
    return step % s->interval == 0 || (s->phase == PL_PHASE_AFTER && s->at_end && step == sim->last_step);
}

static int run_stage(pl_sim_t *sim, pl_stage_t *s, pl_err_t *err)
{
    double t0 = omp_get_wtime();
    int rc = s->fn(sim, s->ctx, err);
    s->seconds += omp_get_wtime() - t0;
    return rc;
}

int pl_sim_begin(pl_sim_t *sim, long long last, pl_err_t *err)
{
    sim->first_step = sim->step;
    sim->last_step = last;
    for (int k = 0; k < sim->nstages; ++k) {
        pl_stage_t *s = &sim->stages[k];
        int rc;
        if (s->phase == PL_PHASE_AFTER && s->at_start && sim->step % s->interval == 0 &&
            (rc = run_stage(sim, s, err)))
            return rc;
    }
    return 0;
}

int pl_sim_step(pl_sim_t *sim, pl_err_t *err)
{
    int rc;
    for (int k = 0; k < sim->nstages; ++k) {
        pl_stage_t *s = &sim->stages[k];
        if (s->phase == PL_PHASE_STEP && pl_sim_stage_due(sim, s, sim->step) && (rc = run_stage(sim, s, err)))
            return rc;
    }
    sim->step++;
    for (int k = 0; k < sim->nstages; ++k) {
        pl_stage_t *s = &sim->stages[k];
        if (s->phase == PL_PHASE_AFTER && pl_sim_stage_due(sim, s, sim->step) && (rc = run_stage(sim, s, err)))
            return rc;
    }
    return 0;
}

void pl_sim_observe(const pl_sim_t *sim, pl_fluid_obs_t *obs, double *kT)
{
    pl_srd_observe(&sim->fluid, sim->obs_scratch, obs, sim->nthreads);
    /* kT = sum m (v - V)^2 / (3 (N - 1)), V the centre-of-mass velocity */
    size_t n = sim->fluid.n;
    if (n < 2) {
        *kT = 0.0;
        return;
    }
    double p2 = 0.0;
    for (int d = 0; d < 3; ++d) p2 += obs->momentum[d] * obs->momentum[d];
    *kT = (2.0 * obs->kinetic - p2 / (double)n) / (3.0 * (double)(n - 1));
}
