/* The scene schema: every key a scene file may contain, with type, range,
 * default, units and meaning.  Used to validate input, fill defaults and print
 * the README reference (`peloid keys`).  Other modules add their sections at
 * the end of `sections[]`. */
#include <float.h>
#include <stddef.h>

#include "peloid/collision_rule.h" /* pl_collision_rule_names */
#include "peloid/collision_rule_list.h"
#include "peloid/scene.h"
#include "peloid/thermostat.h" /* pl_thermostat_names */
#include "peloid/thermostat_list.h"

/* The choice words of srd.rule and thermostat.type, in the one list of each
 * (the rows themselves are the fluid's: src/fluid/collision_rules.c,
 * src/fluid/thermostats.c) */
#define NAME(row, name) name,
const char *const pl_collision_rule_names[] = {PL_COLLISION_RULES(NAME) NULL};
const char *const pl_thermostat_names[] = {PL_THERMOSTATS(NAME) NULL};
#undef NAME

#define OFF(member) offsetof(pl_scene_t, member)
#define N(a) (sizeof(a) / sizeof((a)[0]))
#define BIG DBL_MAX

static const char *const walls_choices[] = {"none", "noslip", "slip", NULL};
static const char *const vel_choices[] = {"gaussian", "uniform", NULL};

static const pl_key_t run_keys[] = {
    {"name", PL_KEY_STRING, OFF(run.name), 0, 0, PL_KEY_SAFE_NAME, NULL, 0, "",
     "-", "scene name: letters, digits, `.`, `_`, `-` (not `.` or `..`); names the default output directory out/<name> (default: file name without .cfg)"},
    {"seed", PL_KEY_INT, OFF(run.seed), 0, 9.2e18, 0, NULL, 1, NULL,
     "-", "seed of every random stream (Philox key); same seed => bitwise identical run"},
    {"steps", PL_KEY_INT, OFF(run.steps), 0, (double)PL_STEPS_MAX, 0, NULL, 1000, NULL,
     "collision steps", "number of SRD steps to run (`--steps` overrides)"},
};

static const pl_key_t box_keys[] = {
    {"cells", PL_KEY_INT3, OFF(box.cells), 1, 4096, PL_KEY_INT32, NULL, 16, NULL,
     "a0", "box edge lengths [Lx, Ly, Lz] in collision cells"},
    {"walls_z", PL_KEY_CHOICE, OFF(box.walls_z), 0, 0, 0, walls_choices, PL_WALLS_NONE, NULL,
     "-", "planar walls at z = 0 and z = Lz: none (periodic), noslip (bounce-back + "
          "virtual wall particles, Lamura et al.), slip (specular)"},
    {"walls_xy", PL_KEY_CHOICE, OFF(box.walls_xy), 0, 0, 0, walls_choices, PL_WALLS_NONE, NULL,
     "-", "walls at x = 0, Lx and y = 0, Ly (a square capillary along z, Hecht Sec. VIII.A "
          "option ii; with walls_z a closed box): none, noslip, slip as for walls_z; x/y walls are at rest"},
    {"wall_velocity_bottom", PL_KEY_REAL3, OFF(box.wall_velocity[0]), -1e3, 1e3, 0, NULL, 0, NULL,
     "a0 / t0", "walls_z = noslip: velocity [ux, uy, 0] of the wall at z = 0 (shear, Hecht Sec. "
                "VIII.C): bounce-back and virtual particles in its frame"},
    {"wall_velocity_top", PL_KEY_REAL3, OFF(box.wall_velocity[1]), -1e3, 1e3, 0, NULL, 0, NULL,
     "a0 / t0", "walls_z = noslip: velocity [ux, uy, 0] of the wall at z = Lz; shear rate "
                "(top - bottom) / Lz in summary.json, wall stresses in thermo.tsv"},
};

static const pl_key_t fluid_keys[] = {
    {"density", PL_KEY_REAL, OFF(fluid.density), 0, 1e4, 0, NULL, 5, NULL,
     "particles / a0^3", "gamma: mean number of fluid particles per cell (0: no fluid, colloids only)"},
    {"temperature", PL_KEY_REAL, OFF(fluid.temperature), 0, 1e6, PL_KEY_MIN_OPEN, NULL, 1, NULL,
     "kT_ref", "initial temperature kT (set exactly at start)"},
    {"init_velocity", PL_KEY_CHOICE, OFF(fluid.init_velocity), 0, 0, 0, vel_choices, PL_VEL_GAUSSIAN,
     NULL, "-", "initial velocity distribution: gaussian or uniform (square well, Hecht Fig. 2)"},
    {"body_force", PL_KEY_REAL3, OFF(fluid.body_force), -1e3, 1e3, 0, NULL, 0, NULL,
     "a0 / t0^2", "constant acceleration on every fluid particle (e.g. Poiseuille flow)"},
};

static const pl_key_t srd_keys[] = {
    {"dt", PL_KEY_REAL, OFF(srd.dt), 0, 1e3, PL_KEY_MIN_OPEN, NULL, 0.1, NULL,
     "t0", "collision time step Delta t_c; lambda = dt sqrt(kT/m_f) (PL Eq. 4)"},
    {"rule", PL_KEY_CHOICE, OFF(srd.rule), 0, 0, 0, pl_collision_rule_names, PL_RULE_RANDOM_AXIS, NULL,
     "-", "collision rule by name, a row of src/fluid/collision_rules.c whose own file (src/fluid/rule_*.c) "
          "states its equations. random_axis: rotate by alpha about a random axis (PL Eq. 3); hecht_axes: "
          "+-90 deg about one of the 3 coordinate axes (Hecht Sec. III)"},
    {"alpha", PL_KEY_REAL, OFF(srd.alpha_deg), 0, 180, PL_KEY_MIN_OPEN, NULL, 130, NULL,
     "degrees", "rotation angle of the random_axis rule"},
    {"grid_shift", PL_KEY_BOOL, OFF(srd.grid_shift), 0, 1, 0, NULL, 1, NULL,
     "-", "random shift of the cell grid in [-a0/2, a0/2]^3 each step (Ihle-Kroll)"},
    {"sort_interval", PL_KEY_INT, OFF(srd.sort_interval), 1, 1e6, PL_KEY_FP_SET, NULL, 1, NULL,
     "collision steps", "reorder the fluid arrays by cell every N steps; in between only an index is sorted "
                        "and the collision reads through it (fewer bytes a step). 1: every step. N > 1 changes "
                        "each cell's summation order, hence the trajectory (not its statistics); deterministic "
                        "for a given N; only with the SRD rotation rules, no coupling, no rescale thermostat"},
};

static const pl_key_t thermostat_keys[] = {
    {"type", PL_KEY_CHOICE, OFF(thermostat.type), 0, 0, 0, pl_thermostat_names, PL_THERMO_NONE, NULL,
     "-", "none; heyes: Monte Carlo cell thermostat (Hecht Eq. 33); rescale: cell-"
          "relative rescaling to the global T (PL Appendix A, Eqs. A1-A2)"},
    {"temperature", PL_KEY_REAL, OFF(thermostat.temperature), 0, 1e6, PL_KEY_MIN_OPEN, NULL, 1, NULL,
     "kT_ref", "target temperature kT*"},
    {"heyes_epsilon", PL_KEY_REAL, OFF(thermostat.heyes_epsilon), 0, 1, PL_KEY_MIN_OPEN, NULL, 0.1, NULL,
     "-", "heyes: scale factor zeta = 1+eps or 1/(1+eps), eps uniform in [0, heyes_epsilon]"},
    {"interval", PL_KEY_INT, OFF(thermostat.interval), 1, 1e12, 0, NULL, 1, NULL,
     "collision steps", "apply the thermostat every `interval` collision steps"},
};

static const pl_key_t output_keys[] = {
    {"thermo_interval", PL_KEY_INT, OFF(output.thermo_interval), 1, 1e15, 0, NULL, 100, NULL,
     "steps", "row interval of thermo.tsv"},
    {"checkpoint_interval", PL_KEY_INT, OFF(output.checkpoint_interval), 0, 1e15, 0, NULL, 0, NULL,
     "steps", "write checkpoint.h5 every N steps (0: only at the end)"},
    {"fields_interval", PL_KEY_INT, OFF(output.fields_interval), 0, 1e15, 0, NULL, 0, NULL,
     "steps", "sample the cell velocity/density fields every N steps into fields.h5 (0: off)"},
    {"fields_start", PL_KEY_INT, OFF(output.fields_start), 0, 1e15, 0, NULL, 0, NULL,
     "steps", "first step of the field time average (skip the transient)"},
    {"track_fluid", PL_KEY_BOOL, OFF(output.track_fluid), 0, 1, 0, NULL, 0, NULL,
     "-", "carry particle ids and unwrapped displacements (fluid MSD in thermo.tsv); costs bandwidth"},
    {"colloids_xyz", PL_KEY_BOOL, OFF(output.colloids_xyz), 0, 1, 0, NULL, 0, NULL,
     "-", "also write the colloid frames of colloids.h5 as extended XYZ (colloids.xyz: OVITO, VMD, ASE); "
          "needs colloids.trajectory_interval"},
    {"progress_s", PL_KEY_REAL, OFF(output.progress_s), 0, 1e9, PL_KEY_MIN_OPEN, NULL, 30, NULL,
     "s (wall)", "when stderr is not a terminal: one progress line every progress_s seconds"},
};

const pl_section_t pl_scene_section_run = {"", "top level", run_keys, N(run_keys)};
const pl_section_t pl_scene_section_box = {"box", "simulation box", box_keys, N(box_keys)};
const pl_section_t pl_scene_section_fluid = {"fluid", "SRD fluid particles", fluid_keys, N(fluid_keys)};
const pl_section_t pl_scene_section_srd = {"srd", "SRD collision step", srd_keys, N(srd_keys)};
const pl_section_t pl_scene_section_thermostat = {"thermostat", "fluid thermostat", thermostat_keys,
                                                  N(thermostat_keys)};
const pl_section_t pl_scene_section_output = {"output", "what a run writes", output_keys, N(output_keys)};

/* Every section, in documentation order.  A module adds its own section
 * (defined in its own src/scene_keys_<module>.c, declared in scene.h) here. */
static const pl_section_t *const sections[] = {
    &pl_scene_section_run,   &pl_scene_section_box,        &pl_scene_section_fluid,
    &pl_scene_section_srd,   &pl_scene_section_thermostat, &pl_scene_section_output,
    &pl_scene_section_physical, &pl_scene_section_coarse_graining,
    &pl_scene_section_colloids, &pl_scene_section_dlvo, &pl_scene_section_hertz,
    &pl_scene_section_lubrication, &pl_scene_section_wca, &pl_scene_section_coupling,
    &pl_scene_section_observe, &pl_scene_section_stop,
};

const pl_section_t *const *pl_scene_sections(size_t *count)
{
    *count = N(sections);
    return sections;
}
