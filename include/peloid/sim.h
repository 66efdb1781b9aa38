/* A simulation: scene + state + plan.  The plan is an ordered list of stages,
 * each with an interval; a stage the scene does not need is not in the plan
 * (DESIGN.md "Scene -> plan").  pl_sim_step walks the plan once per step. */
#ifndef PELOID_SIM_H
#define PELOID_SIM_H

#include <stdint.h>
#include <stdio.h>

#include "peloid/error.h"
#include "peloid/fluid.h"
#include "peloid/grid.h"
#include "peloid/scene.h"
#include "peloid/srd.h"
#include "peloid/srd_kernels.h"

typedef struct pl_sim pl_sim_t;
/* A stage acts on the simulation; ctx is the registering component's own
 * state (the fluid's pl_srd_t, the colloids, the coupling, an observer's
 * accumulators, the stopping rule's settings), which every stage uses. */
typedef int (*pl_stage_fn)(pl_sim_t *sim, void *ctx, pl_err_t *err);

typedef enum {
    PL_PHASE_STEP,  /* advances the state of step `step` (stream, collide, MD, ...) */
    PL_PHASE_AFTER, /* samples or writes the state once step `step` is complete */
} pl_stage_phase_t;

/* Where a stage runs within its phase: the plan is ordered by (phase,
 * slot), stages of one slot in the order they were added (module order,
 * src/core/modules.c).  The step's data flow: colloid MD, then the fluid's
 * stream, sort and collision with the couplings' stages around them. */
typedef enum {
    /* PL_PHASE_STEP */
    PL_SLOT_COLLOID_MD = 10,   /* colloid MD substeps (velocity Verlet or BD) */
    PL_SLOT_PRE_STREAM = 20,   /* potential coupling: select the fluid near colloids */
    PL_SLOT_STREAM = 30,       /* fluid streaming + cell binning */
    PL_SLOT_POST_STREAM = 40,  /* potential coupling MD; coupling I reflections */
    PL_SLOT_SORT = 50,         /* counting sort into collision cells */
    PL_SLOT_PRE_COLLIDE = 60,  /* coupling II: keep the fluid velocities */
    PL_SLOT_COLLIDE = 70,      /* SRD collision (with the Heyes thermostat variant) */
    PL_SLOT_POST_COLLIDE = 80, /* coupling II: collide the colloids' cells again */
    PL_SLOT_THERMOSTAT = 90,   /* rescaling thermostat */
    PL_SLOT_GUARD = 100,       /* fluid guard: nothing non-finite moves on */
    PL_SLOT_SAMPLE = 110,      /* time-averaged fields */
    PL_SLOT_CONSTRAIN = 120,   /* flow hold, drift removal */
    /* PL_PHASE_AFTER */
    PL_SLOT_OUTPUT_GUARD = 10, /* the fluid guard's scan of a state about to be written */
    PL_SLOT_OBSERVE = 20,      /* observers sample the completed step */
    PL_SLOT_FRAMES = 25,       /* trajectory frames (with what the observers found) */
    PL_SLOT_WRITE = 30,        /* writers: trajectory, thermo, checkpoint */
} pl_stage_slot_t;

typedef struct {
    const char *name;
    pl_stage_fn fn;
    void *ctx;
    long long interval; /* run when step % interval == 0 */
    long long except;   /* > 0: not when step % except == 0 (another variant runs then) */
    pl_stage_phase_t phase;
    pl_stage_slot_t slot;
    int at_start;       /* PL_PHASE_AFTER: also on the state a run starts from */
    int at_end;         /* PL_PHASE_AFTER: also on the run's last state */
    int writes;         /* writes an output: the fluid guard scans the state first */
    int colloid_md;     /* advances the colloids by MD steps (the progress line counts them) */
    double seconds;     /* wall time spent (profile in summary.json) */
} pl_stage_t;

enum { PL_MAX_STAGES = 32, PL_MAX_MODULES = 8 };

struct pl_sim {
    pl_scene_t scene;
    int nthreads;
    long long step;   /* completed collision steps */
    /* the fluid: its particles and grid, the view every component reads;
     * the rest of its state is its component's (peloid/srd.h) */
    pl_fluid_t fluid;
    pl_grid_t grid;
    struct pl_srd *srd;   /* src/fluid/fluid_state.c */
    double wall_u[2][3];  /* wall velocities (bottom, top): box.wall_velocity_* */
    /* an acceleration of the fluid besides fluid.body_force that another
     * component asks for (the coupling's gravity compensation, Hecht Sec.
     * VIII.A (iii)); 0 without */
    double fluid_accel[3];
    /* the wall-impulse sink (src/fluid/fluid_walls.c, pl_sim_wall_add): impulse
     * the walls gave fluid (and colloids) since step 0, (bottom z wall, top
     * z wall, the x/y walls together) x (x, y, z); checkpointed.  The wall
     * stress (PL Eq. 13). */
    double wall_impulse[3][3];
    int wall_acc_overflow; /* a fixed-point wall impulse sum overflowed (guard) */
    /* a pass the streaming of step stream_hook_step runs on what it streamed
     * (pl_stream_params_t.hook), set by a stage before it (coupling I's
     * detection); the streaming clears stream_hook once it ran it */
    pl_stream_hook_fn stream_hook;
    void *stream_hook_ctx;
    long long stream_hook_step;
    /* the same for a pass on what the streaming is about to store
     * (pl_stream_params_t.pre_hook: the potential coupling's selection) */
    pl_stream_hook_fn stream_pre_hook;
    void *stream_pre_hook_ctx;
    long long stream_pre_hook_step;
    /* colloids (NULL without; src/colloid_*.c) */
    struct pl_colloid *colloids;
    /* per-colloid ids another component offers every trajectory frame
     * (the clusters observer's cluster ids; pl_traj_ids_fn of
     * peloid/colloid.h), NULL: none; the trajectory writer
     * (src/app/writer_colloids.c) adds them */
    const int32_t *(*frame_ids)(void *ctx, long long step, int compute);
    void *frame_ids_ctx;
    /* what each module's create made (the coupling, the observers, the
     * stress observer), one slot per row of pl_modules, NULL where it made
     * none: read and written only by the module that owns it, through
     * pl_module_state (peloid/module.h) */
    void *module_state[PL_MAX_MODULES];
    /* a restart's outcome for the observers, core's own: written and read
     * through pl_sim_observers_afresh / pl_sim_observers_resumed below */
    struct {
        int observers;  /* -1: no restart; 1: resumed from the checkpoint; 0: afresh, note says why */
        char note[384];
    } restart;
    /* plan */
    pl_stage_t stages[PL_MAX_STAGES];
    int nstages;
    long long first_step, last_step; /* of the present run (pl_sim_begin) */
    /* a stage ended the run at this step (the stopping rule); the
     * after-step stages that write the last state see it at once */
    int stop_requested;
    char stop_reason[160];
    double run_wall_start; /* wall clock at pl_sim_begin */
};

/* Builds state (fresh initialisation) and plan from a validated scene. */
int pl_sim_create(const pl_scene_t *scene, int nthreads, pl_sim_t **out, pl_err_t *err);
void pl_sim_free(pl_sim_t *sim);

/* Adds a stage to the plan at its (phase, slot), after the stages already
 * there (writers and observers register theirs after the simulation is
 * built); PL_ERR_INTERNAL when the plan is full. */
int pl_sim_add_stage(pl_sim_t *sim, const pl_stage_t *stage, pl_err_t *err);
/* A collision stage in its two variants: with a thermostat that runs
 * inside the collision (its row's in_collision: Heyes, Hecht Sec. VIII.B)
 * `in_collision` every thermostat.interval steps and `plain` on the others,
 * else `plain` every step (the fluid's collision and coupling II's share
 * this choice; src/fluid/thermostats.c). */
int pl_sim_add_collide_stage(pl_sim_t *sim, const pl_stage_t *plain, const pl_stage_t *in_collision,
                             pl_err_t *err);

/* Whether stage s runs when the state is at step `step`. */
int pl_sim_stage_due(const pl_sim_t *sim, const pl_stage_t *s, long long step);

/* Starts a run to step `last`: the after-step stages that want the start
 * state (at_start, interval dividing the first step) run on it. */
int pl_sim_begin(pl_sim_t *sim, long long last, pl_err_t *err);

/* Ends the run at the present step before its last (an interrupt): sets
 * stop_requested with `reason`, then runs the after-step stages that want
 * the last state (at_end) and did not run on it by their interval, after
 * the output guard's scan (PL_SLOT_OUTPUT_GUARD), as a normal end does. */
int pl_sim_end_here(pl_sim_t *sim, const char *reason, pl_err_t *err);

/* One collision step: the step stages due at `step`, then step + 1, then
 * the after-step stages due at the new step. */
int pl_sim_step(pl_sim_t *sim, pl_err_t *err);

/* Drift parameters of the current step (dt, body force, wall velocities). */
void pl_sim_stream_params(const pl_sim_t *sim, pl_stream_params_t *p);

/* Adds fixed-point wall impulses (PL_WALL_ACC_N slots: bottom xyz, top xyz,
 * x/y walls xyz; 2^-PL_FIELD_FIXED_SHIFT) to sim->wall_impulse. */
void pl_sim_wall_add(pl_sim_t *sim, const int64_t acc[PL_WALL_ACC_N]);
/* The same in double (slots as above): the virtual particles' push. */
void pl_sim_wall_add_momentum(pl_sim_t *sim, const double dp[PL_WALL_ACC_N]);

/* Virtual wall particles of the collision (Lamura et al. 2001; walls:
 * Hecht Sec. VIII.A): 1 when a no-slip wall needs them, with the density
 * they fill a cut cell to and their temperature.  The fluid collision and
 * coupling II take them from here. */
int pl_sim_wall_ghosts(const pl_sim_t *sim, double *density, double *kT_wall);

/* wall 0, 1: shear stress sigma_{dz} (d = x, y) from the momentum z wall
 * `wall` gave the fluid since step 0, per wall area and time (PL Eq. 13):
 * +F_top / A and -F_bottom / A, so both walls measure the same stress.
 * wall 2: the force per area (component d) the fluid exerts on the x/y walls
 * of a capillary together, -F / (2 (Lx + Ly) Lz): for flow along z, the mean
 * wall shear stress.  0 before the first step. */
double pl_sim_wall_stress(const pl_sim_t *sim, int wall, int d);

/* The restart's outcome for the observers (core's record, src/core/sim.c):
 * pl_sim_observers_resume says an observer resumed from the checkpoint;
 * pl_sim_observers_afresh that they start afresh and why (the first reason
 * is kept; afresh stays afresh); pl_sim_observers_resumed is -1 without a
 * restart, 1 resumed, 0 afresh with *why the reason (why NULL: not wanted). */
void pl_sim_observers_resume(pl_sim_t *sim);
void pl_sim_observers_afresh(pl_sim_t *sim, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
int pl_sim_observers_resumed(const pl_sim_t *sim, const char **why);

/* Observables of the current state (fixed-order reductions). */
void pl_sim_observe(const pl_sim_t *sim, pl_fluid_obs_t *obs, double *kT);

/* ---- fluid guard (src/fluid/fluid_guard.c) ---------------------------------- */
/* The guard stage runs every step, after the collision and thermostat: the
 * speeds and the O(1) checks every step, the positions too every
 * PL_FLUID_GUARD_SCAN_INTERVAL steps and before every output (src/app/run.c). */
enum { PL_FLUID_GUARD_INTERVAL = 1, PL_FLUID_GUARD_SCAN_INTERVAL = 10 };
/* Speed bound: PL_FLUID_GUARD_SIGMAS thermal speeds sqrt(kT_max / m_f) plus
 * twice the fastest wall or imposed flow (a bounce-back off a wall moving
 * with U gives 2U - v); kT_max is the largest temperature the scene names
 * (fluid, thermostat, walls).  Never below a0 / srd.dt (one cell per step). */
#define PL_FLUID_GUARD_SIGMAS 20.0
/* Temperature band with a thermostat: the collision-cell temperature kT_cell
 * (PL Eq. A1) must stay within [min(T0, T*) / F, max(T0, T*) F], T0 the
 * initial and T* the target temperature, F = PL_FLUID_GUARD_KT_FACTOR. */
#define PL_FLUID_GUARD_KT_FACTOR 10.0
/* Computes the bounds into sim from sim->scene (the fluid module's create,
 * src/fluid/fluid_stages.c). */
void pl_fluid_guard_setup(pl_sim_t *sim);
/* The stage: PL_ERR_GUARD naming step, particle, quantity, bound and the
 * parameter to change, for a position outside the box or non-finite, a speed
 * beyond guard_vmax, kT_cell outside the band, or an overflowed wall impulse
 * accumulator. */
int pl_fluid_guard_stage(pl_sim_t *sim, void *ctx, pl_err_t *err);
/* The scan before an output (PL_SLOT_OUTPUT_GUARD): positions too, unless
 * the guard stage scanned this state already. */
int pl_fluid_output_guard_stage(pl_sim_t *sim, void *ctx, pl_err_t *err);
/* The same checks on the current state outside the plan (before an output,
 * after a restart); scan = 0 leaves out the positions. */
int pl_fluid_guard_check(const pl_sim_t *sim, long long step, int scan, pl_err_t *err);

/* The fluid component's state from sim->scene: grid, particles (initial
 * state below), sim->srd, the guard's bounds; PL_ERR_NOMEM naming what is
 * missing; and its release (src/fluid/fluid_state.c; the fluid module's
 * create and destroy). */
int pl_fluid_state_create(pl_sim_t *sim, pl_err_t *err);
void pl_fluid_state_free(pl_sim_t *sim);

/* Initial fluid: uniform positions, uniform or Gaussian velocities with zero
 * total momentum and exactly the scene temperature (src/fluid/fluid_init.c), on
 * nthreads threads (the result does not depend on them). */
void pl_fluid_init(pl_fluid_t *fluid, const pl_scene_t *scene, int nthreads);

#endif
