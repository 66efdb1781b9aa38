/* Fluid guard (DESIGN.md "Errors, bad input, guards"): the SRD fluid's
 * state checked after every collision step, so that a run stops (exit 3)
 * with a message naming step, particle, quantity, bound and the parameter to
 * change instead of writing NaN or Inf, or crashing in the next stream:
 *   - every position finite and inside the box [0, L] (a NaN position gives
 *     no valid collision cell);
 *   - every speed |v| below guard_vmax: PL_FLUID_GUARD_SIGMAS thermal speeds
 *     plus twice the fastest wall / imposed flow, and at least a0 / srd.dt.
 *     A Maxwell speed beyond 20 sigma has probability ~exp(-200): a faster
 *     particle is a numerical runaway (energy pumped in by moving walls,
 *     a body force or a coupling faster than the thermostat removes it),
 *     and it would cross 20 mean free paths lambda = dt sqrt(kT) (PL Eq. 4)
 *     in one step.  (The literal "one cell per step" is not a bound: with
 *     lambda ~ a0, common in the papers' parameter sets, many thermal
 *     particles cross a cell per step, and the random grid shift keeps that
 *     correct, Ihle-Kroll.)
 *   - with a thermostat: the collision-cell temperature kT_cell (PL Eq. A1)
 *     inside [min(T0, T*) / F, max(T0, T*) F], F = PL_FLUID_GUARD_KT_FACTOR;
 *   - no overflow of the fixed-point wall impulse sums (pl_wall_acc_add).
 * The per-particle scan is kernels/srd_guard.c (lowest failing index: the
 * same for any thread count).  Every step it checks the speeds (24 B per
 * particle): the next stream then never sees a non-finite or runaway
 * velocity, and positions stay finite and in the box by induction (finite
 * r + finite v dt, wrapped or reflected).  The positions themselves (the
 * full 48 B) every PL_FLUID_GUARD_SCAN_INTERVAL steps and before every thermo
 * row, checkpoint and fields file (src/app/run.c), so nothing non-finite reaches
 * an output.  Costs: README "Fluid guard". */
#include <math.h>
#include <stdio.h>

#include "peloid/coupling_scene.h"
#include "peloid/sim.h"

#include "srd_state.h"

void pl_fluid_guard_setup(pl_sim_t *sim)
{
    const pl_scene_t *sc = &sim->scene;
    double kT = pl_scene_kT_max(sc), u = 0.0;
    if (sc->coupling.wall_temperature > kT) kT = sc->coupling.wall_temperature;
    for (int w = 0; w < 2; ++w) {
        const double *U = sc->box.wall_velocity[w];
        u = fmax(u, sqrt(U[0] * U[0] + U[1] * U[1] + U[2] * U[2]));
    }
    const double *fv = sc->coupling.flow_velocity;
    u = fmax(u, sqrt(fv[0] * fv[0] + fv[1] * fv[1] + fv[2] * fv[2]));
    sim->srd->guard_vmax = fmax(PL_FLUID_GUARD_SIGMAS * sqrt(kT) + 2.0 * u, 1.0 / sc->srd.dt);
    sim->srd->guard_kT_lo = 0.0;
    sim->srd->guard_kT_hi = INFINITY;
    if (sc->thermostat.type != PL_THERMO_NONE) {
        const double t0 = sc->fluid.temperature, ts = sc->thermostat.temperature;
        sim->srd->guard_kT_lo = fmin(t0, ts) / PL_FLUID_GUARD_KT_FACTOR;
        sim->srd->guard_kT_hi = fmax(t0, ts) * PL_FLUID_GUARD_KT_FACTOR;
    }
}

static const char *const axis[3] = {"x", "y", "z"};

/* The lowest index with a bad speed from the collision's block flags, or -1
 * when they do not describe the current velocities: the collision of this
 * step wrote them and no stage ran between it and the guard (couplings'
 * post-collision, the rescaling thermostat).  A block holding a failing
 * particle is always flagged (a flag without one is possible: the collision
 * tests each cell's sum of v^2); particles are in cell order, so the first
 * flagged block with a failing particle holds the lowest failing index. */
static long long speeds_from_collision(const pl_sim_t *sim, const pl_srd_t *fs)
{
    if (fs->guard_bad_step != sim->step) return -1;
    for (int k = 0; k < sim->nstages; ++k) {
        const pl_stage_t *s = &sim->stages[k];
        if (s->phase == PL_PHASE_STEP && s->slot > PL_SLOT_COLLIDE && s->slot < PL_SLOT_GUARD &&
            pl_sim_stage_due(sim, s, sim->step))
            return -1;
    }
    const size_t nc = sim->grid.ncells, nb = (nc + PL_CELL_BLOCK - 1) / PL_CELL_BLOCK;
    const double vmax = fs->guard_vmax;
    for (size_t b = 0; b < nb; ++b) {
        if (!fs->guard_bad[b]) continue;
        if (fs->indexed) return -1; /* a block's particles are not a range: scan them all */
        const size_t c1 = (b + 1) * PL_CELL_BLOCK < nc ? (b + 1) * PL_CELL_BLOCK : nc;
        const size_t lo = fs->cell_start[b * PL_CELL_BLOCK], hi = fs->cell_start[c1];
        const size_t i = pl_srd_guard_scan_speeds(&sim->fluid, lo, hi, vmax * vmax);
        if (i < hi) return (long long)i;
    }
    return (long long)sim->fluid.n;
}

static int guard_check(const pl_sim_t *sim, const pl_srd_t *fs, long long step, int scan, int fused,
                       pl_err_t *err)
{
    const pl_fluid_t *f = &sim->fluid;
    const pl_scene_t *sc = &sim->scene;
    if (sim->wall_acc_overflow)
        return pl_err_set(err, PL_ERR_GUARD,
                          "guard wall_impulse: step %lld: the fixed-point wall impulse sum of one step left "
                          "+-2^62 (2^-%d units); bound 2^62; lower box.wall_velocity_* or srd.dt (the fluid "
                          "is running away)", step, PL_FIELD_FIXED_SHIFT);
    const double vmax = fs->guard_vmax;
    const long long from_collision = !scan && fused ? speeds_from_collision(sim, fs) : -1;
    size_t i = from_collision >= 0 ? (size_t)from_collision
                                   : pl_srd_guard_scan(f, sc->box.cells, vmax * vmax, scan, sim->nthreads);
    if (i < f->n) {
        double r[3], v[3];
        for (int d = 0; d < 3; ++d) {
            r[d] = f->r[d][i];
            v[d] = f->v[d][i];
        }
        for (int d = 0; d < 3; ++d)
            if (!isfinite(r[d]) || !isfinite(v[d]))
                return pl_err_set(err, PL_ERR_GUARD,
                                  "guard fluid_nan: step %lld: fluid particle %zu has a non-finite %s "
                                  "(%s = %g, v%s = %g); bound: finite; lower srd.dt, fluid.body_force or "
                                  "the coupling strength", step, i, isfinite(r[d]) ? "velocity" : "position",
                                  axis[d], r[d], axis[d], v[d]);
        for (int d = 0; d < 3; ++d)
            if (!(r[d] >= 0.0 && r[d] <= sc->box.cells[d]))
                return pl_err_set(err, PL_ERR_GUARD,
                                  "guard fluid_box: step %lld: fluid particle %zu is at %s = %.17g, outside "
                                  "the box; bound [0, %d]; lower srd.dt or the wall velocities", step, i,
                                  axis[d], r[d], sc->box.cells[d]);
        const double s = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return pl_err_set(err, PL_ERR_GUARD,
                          "guard fluid_speed: step %lld: fluid particle %zu has speed |v| = %.4g (moves %.4g a0 "
                          "per step); bound %.4g a0/t0 (%g thermal speeds + 2 x wall/flow speed, at least "
                          "a0/srd.dt); lower srd.dt, box.wall_velocity_*, fluid.body_force or add a thermostat",
                          step, i, s, s * sc->srd.dt, vmax, PL_FLUID_GUARD_SIGMAS);
    }
    const double kT = fs->last_kT_meas;
    if (!isfinite(kT) || (kT > 0.0 && kT < fs->guard_kT_lo) || kT > fs->guard_kT_hi)
        return pl_err_set(err, PL_ERR_GUARD,
                          "guard fluid_temperature: step %lld: all %zu fluid particles: kT_cell = %.4g ran "
                          "away from the thermostat target %g; bound [%g, %g] (factor %g around fluid and "
                          "target temperature); raise thermostat.heyes_epsilon or lower thermostat.interval, "
                          "srd.dt or the energy input (walls, body force)", step, f->n, kT,
                          sc->thermostat.temperature, fs->guard_kT_lo, fs->guard_kT_hi,
                          PL_FLUID_GUARD_KT_FACTOR);
    return 0;
}

int pl_fluid_guard_check(const pl_sim_t *sim, long long step, int scan, pl_err_t *err)
{
    return guard_check(sim, sim->srd, step, scan, 0, err);
}

/* ctx: the fluid's state (peloid/srd.h) */
int pl_fluid_guard_stage(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    /* the stage runs inside step `step` -> step + 1: it checks the state
     * the thermo row of step + 1 would show; positions every
     * PL_FLUID_GUARD_SCAN_INTERVAL steps (the run loop adds a scan before
     * every output) */
    return guard_check(sim, ctx, sim->step + 1, (sim->step + 1) % PL_FLUID_GUARD_SCAN_INTERVAL == 0, 1, err);
}

/* After-step stage: before any output is written, the fluid guard's
 * particle scan on the state it writes (the fluid-guard stage scanned this
 * state already on multiples of its scan interval).  ctx: as above. */
int pl_fluid_output_guard_stage(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    if (sim->step % PL_FLUID_GUARD_SCAN_INTERVAL == 0) return 0;
    for (int k = 0; k < sim->nstages; ++k) {
        const pl_stage_t *s = &sim->stages[k];
        if (s->phase == PL_PHASE_AFTER && s->writes && pl_sim_stage_due(sim, s, sim->step))
            return guard_check(sim, ctx, sim->step, 1, 0, err);
    }
    return 0;
}
