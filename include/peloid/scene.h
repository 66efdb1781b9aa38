/* The scene: one simulation described in a libconfig file, validated into
 * plain structs in simulation units (a0 = 1, m_f = 1, kT_ref = 1).
 *
 * Parsing is schema driven: every key lives in a table (src/scene_keys*.c)
 * with its type, range, default, units and meaning.  The same table validates
 * input, fills defaults and prints the reference (`peloid keys`), so the
 * documentation cannot drift from the code.  Unknown keys are errors. */
#ifndef PELOID_SCENE_H
#define PELOID_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/colloid_scene.h"
#include "peloid/coupling_scene.h"
#include "peloid/observe_scene.h"
#include "peloid/error.h"
#include "peloid/kernel_enums.h" /* PL_WALLS_*, PL_RULE_* */
#include "peloid/mapping.h"

enum { PL_VEL_GAUSSIAN = 0, PL_VEL_UNIFORM = 1 };
/* thermostat.type: the index of a thermostat row (peloid/thermostat.h);
 * row 0 is none */
enum { PL_THERMO_NONE = 0 };

/* Largest number of steps of a run (run.steps and --steps). */
#define PL_STEPS_MAX 1000000000000000LL

typedef struct {
    char name[128];
    long long seed;
    long long steps;
} pl_scene_run_t;

typedef struct {
    int cells[3];  /* box edge lengths in cells (a0 = 1) */
    int walls_z;   /* PL_WALLS_*: planar walls at z = 0 and z = Lz */
    int walls_xy;  /* PL_WALLS_*: walls at x = 0, Lx and y = 0, Ly (a capillary) */
    double wall_velocity[2][3]; /* no-slip wall velocities (bottom, top); z = 0 */
} pl_scene_box_t;

/* Wall type (PL_WALLS_*) of each axis: walls_xy on x and y, walls_z on z.
 * Returns 1 when any axis is closed. */
static inline int pl_scene_box_walls(const pl_scene_box_t *b, int walls[3])
{
    walls[0] = walls[1] = b->walls_xy;
    walls[2] = b->walls_z;
    return b->walls_xy != PL_WALLS_NONE || b->walls_z != PL_WALLS_NONE;
}

/* Name of an axis' boundary for outputs: "periodic", "noslip" or "slip". */
static inline const char *pl_scene_boundary_name(int walls)
{
    return walls == PL_WALLS_NOSLIP ? "noslip" : walls == PL_WALLS_SLIP ? "slip" : "periodic";
}

typedef struct {
    double density;        /* gamma: mean particles per cell */
    double temperature;    /* initial kT */
    int init_velocity;     /* PL_VEL_* */
    double body_force[3];  /* acceleration on every fluid particle */
} pl_scene_fluid_t;

typedef struct {
    double dt;        /* collision time step Delta t_c (units of t0) */
    int rule;         /* PL_RULE_* */
    double alpha_deg; /* rotation angle for the random-axis rule */
    int grid_shift;   /* random shift of the cell grid each step (bool) */
    long long sort_interval; /* full sort every this many steps; between, an index sort (1: every step);
                              * the last member: the calibration key hashes the ones before it */
} pl_scene_srd_t;

typedef struct {
    int type;           /* its row (peloid/thermostat.h); PL_THERMO_NONE: none */
    double temperature; /* target kT* */
    double heyes_epsilon;
    long long interval; /* act every `interval` collision steps */
} pl_scene_thermostat_t;

typedef struct {
    long long thermo_interval;
    long long checkpoint_interval; /* 0: only at the end */
    long long fields_interval;     /* 0: no fields */
    long long fields_start;
    int track_fluid;               /* carry ids + unwrapped displacements */
    int colloids_xyz;              /* colloids.xyz beside colloids.h5 */
    double progress_s;             /* progress log interval without a terminal */
} pl_scene_output_t;

/* Where each key given in the file stood, so that cross-key checks can name
 * the line too. */
typedef struct {
    size_t offset;
    int file; /* 0: the scene file (path), i > 0: include_path[i - 1] */
    int line;
} pl_scene_origin_t;

enum { PL_SCENE_MAX_KEYS = 256, PL_SCENE_MAX_FILES = 8 /* the scene + its @include files */ };

typedef struct pl_scene {
    char path[512];
    char include_path[PL_SCENE_MAX_FILES - 1][512]; /* @include files, in reading order */
    pl_scene_origin_t origin[PL_SCENE_MAX_KEYS];
    int norigin;
    pl_scene_run_t run;
    pl_scene_box_t box;
    pl_scene_fluid_t fluid;
    pl_scene_srd_t srd;
    pl_scene_thermostat_t thermostat;
    pl_scene_output_t output;
    pl_scene_mapping_t mapping; /* physical{} + coarse_graining{} (mapping.h) */
    pl_scene_colloids_t colloids; /* colloid module (colloid_scene.h) */
    pl_scene_coupling_t coupling; /* colloid-solvent coupling (coupling_scene.h) */
    pl_scene_observe_t observe;   /* observers (observe_scene.h) */
    pl_scene_stop_t stop;         /* stopping rule (observe_scene.h) */
} pl_scene_t;

/* The one kT of a scene (model units): the thermostat's target, else the
 * fluid's initial temperature. */
static inline double pl_scene_kT(const pl_scene_t *sc)
{
    return sc->thermostat.type != PL_THERMO_NONE ? sc->thermostat.temperature : sc->fluid.temperature;
}

/* The largest of the fluid's initial and the thermostat's temperature. */
static inline double pl_scene_kT_max(const pl_scene_t *sc)
{
    const double t = sc->fluid.temperature;
    return sc->thermostat.type != PL_THERMO_NONE && sc->thermostat.temperature > t ? sc->thermostat.temperature : t;
}

/* ---- schema ---------------------------------------------------------- */

typedef enum {
    PL_KEY_INT,    /* long long */
    PL_KEY_INT3,   /* int[3] */
    PL_KEY_REAL,   /* double */
    PL_KEY_REAL3,  /* double[3] */
    PL_KEY_BOOL,   /* int */
    PL_KEY_STRING, /* char[128] */
    PL_KEY_CHOICE, /* int: min + index into choices (min: the first value, usually 0) */
} pl_key_type_t;

/* PL_KEY_SAFE_NAME: a string that names a file or directory ([A-Za-z0-9._-]).
 * PL_KEY_FP_SET: a key the checkpoint fingerprints (scene_keys,
 * observe_keys) name only when it differs from its default: a key added
 * later, so that the checkpoints written before it (and their bytes) stay
 * the same and resume. */
enum { PL_KEY_MIN_OPEN = 1u, PL_KEY_MAX_OPEN = 2u, PL_KEY_INT32 = 4u, PL_KEY_SAFE_NAME = 8u, PL_KEY_FP_SET = 16u };

typedef struct {
    const char *name;
    pl_key_type_t type;
    size_t offset;               /* of the value inside pl_scene_t */
    double min, max;             /* allowed range for numbers */
    unsigned flags;              /* PL_KEY_* */
    const char *const *choices;  /* NULL-terminated, for PL_KEY_CHOICE */
    double def;                  /* default for numbers/bool/choice index */
    const char *def_str;         /* default for strings ("" = derived) */
    const char *units;
    const char *doc;
} pl_key_t;

typedef struct {
    const char *name;  /* group name in the file; "" for top level */
    const char *doc;
    const pl_key_t *keys;
    size_t nkeys;
} pl_section_t;

/* Whether v (finite) lies in key k's allowed range, its open ends honoured:
 * the loader's test of a given number, and the echo's of a derived one. */
int pl_key_in_range(const pl_key_t *k, double v);
/* The name of value v of a PL_KEY_CHOICE key (v = min + index). */
static inline const char *pl_key_choice_name(const pl_key_t *k, int v) { return k->choices[v - (int)k->min]; }

/* All sections, in documentation order; *count receives their number. */
const pl_section_t *const *pl_scene_sections(size_t *count);

extern const pl_section_t pl_scene_section_run, pl_scene_section_box, pl_scene_section_fluid,
    pl_scene_section_srd, pl_scene_section_thermostat, pl_scene_section_output;
extern const pl_section_t pl_scene_section_physical, pl_scene_section_coarse_graining;
extern const pl_section_t pl_scene_section_colloids, pl_scene_section_dlvo, pl_scene_section_hertz,
    pl_scene_section_lubrication, pl_scene_section_wca;
extern const pl_section_t pl_scene_section_coupling;
extern const pl_section_t pl_scene_section_observe, pl_scene_section_stop;

/* Cross-key checks of the observe section (src/observe/observe_module.c). */
int pl_observe_validate_scene(const pl_scene_t *scene, pl_err_t *err);
/* ... and of observe.stress_* (src/observe/stress_module.c). */
int pl_stress_validate_scene(const pl_scene_t *scene, pl_err_t *err);
/* Whether every observer can measure something in the scene's run
 * (src/observe/observe_span.c): samples in its window, a g(r) range beyond
 * contact, inertial velocities for the VACF. */
int pl_observe_validate_measurable(const pl_scene_t *scene, pl_err_t *err);
/* The samplers' part of it for a run ending at step `last` (a --steps
 * override): 1 with the key to blame (its offset in pl_scene_t) and why,
 * 0 when every window holds enough samples. */
int pl_observe_span_problem(const pl_scene_t *scene, long long last, size_t *off, const char **key, char *why,
                            size_t n);

/* Cross-key checks of the coupling section (src/coupling_scene.c). */
int pl_coupling_validate_scene(const pl_scene_t *scene, pl_err_t *err);
/* Coupling II friction of a colloid of mass M (m_f): 2/3 (1 - cos alpha) mu / dt,
 * mu = M gamma / (M + gamma); an upper bound (src/coupling/coupling.c). */
double pl_coupling2_friction(const pl_scene_t *scene, double mass);
/* Whether the scene's coupling moves (the potential coupling's own MD
 * step, PL Sec. III) or holds (coupling.pinned) the colloids, so that the
 * colloid module adds no MD stage; n_fluid: the fluid's particle count (no
 * coupling without fluid) (src/coupling/coupling.c). */
int pl_coupling_moves_colloids(const pl_scene_t *scene, size_t n_fluid);

/* Cross-key checks of the colloid sections (src/colloid/colloid_scene.c). */
int pl_colloid_validate_scene(const pl_scene_t *scene, pl_err_t *err);

/* ---- API --------------------------------------------------------------- */

/* Fills every key with its schema default. */
void pl_scene_defaults(pl_scene_t *scene);

/* Reads and validates `path` (src/app/scene_open.c: parsed, mapped, checked
 * by the scene's and each module's checks).  On error returns PL_ERR_INPUT
 * with a one-line message "FILE:LINE: key 'a.b': <what is wrong>; <what is
 * allowed>". */
int pl_scene_load(const char *path, pl_scene_t *scene, pl_err_t *err);

/* Same, with PL_SCENE_* flags: PL_SCENE_INCLUDE_ANYWHERE lets @include name
 * files outside the scene's directory tree (--allow-include-anywhere). */
/* PL_SCENE_PROVISIONAL: a first pass whose time unit a calibration will
 * replace (pl_scene_load_coupling_true): the derived keys that depend on
 * the time unit (MD step counts, model gravity) are not yet final, so a
 * file's values of them (an echoed scene.cfg writes them) are compared in
 * the final pass only; every other key is checked before calibrating. */
enum { PL_SCENE_INCLUDE_ANYWHERE = 1u, PL_SCENE_PROVISIONAL = 2u };
int pl_scene_load_flags(const char *path, unsigned flags, pl_scene_t *scene, pl_err_t *err);

/* Same, with the colloid diffusion a calibration run measured for the
 * scene's coupling and resolution (src/app/calibrate.c), which the unit
 * mapping then matches instead of the coupling's theory (NULL: theory). */
int pl_scene_load_calibrated(const char *path, unsigned flags, const pl_mapping_calibration_t *calib,
                             pl_scene_t *scene, pl_err_t *err);

/* Same, from a string (tests); `label` stands in for the file name. */
int pl_scene_load_string(const char *text, const char *label, pl_scene_t *scene,
                         pl_err_t *err);

/* Cross-key checks that a single key's range cannot express
 * (src/app/scene_open.c).  A scene with a physical{} section first gets its
 * SRD parameters from the mapping (pl_mapping_scene_apply), hence the
 * non-const scene; then pl_scene_check_keys, then each module's
 * validate_scene. */
int pl_scene_validate(pl_scene_t *scene, pl_err_t *err);
/* The scene layer's own part of it: box, fluid and output keys across each
 * other and the memory check at 1 thread (src/scene/scene_validate.c). */
int pl_scene_check_keys(pl_scene_t *scene, pl_err_t *err);
/* The loaders' first part (src/scene/scene_load.c): the file (or text)
 * parsed into the struct, every key against the schema, nothing across keys
 * and no mapping; the loaders above then validate. */
int pl_scene_parse_calibrated(const char *path, unsigned flags, const pl_mapping_calibration_t *calib,
                              pl_scene_t *scene, pl_err_t *err);
int pl_scene_parse_string(const char *text, const char *label, pl_scene_t *scene, pl_err_t *err);
/* The memory a run of the scene at nthreads threads allocates (O(1)
 * estimate: fluid, cells, colloids) against the machine's physical memory:
 * PL_ERR_INPUT naming box.cells or fluid.density, the estimate and the
 * memory (src/scene/scene_validate.c).  Called by the loader at 1 thread,
 * by `check` and by a run at their thread counts. */
int pl_scene_memory_check(const pl_scene_t *scene, int nthreads, pl_err_t *err);
/* The estimate itself, in bytes (the sweep's plan sizes its jobs with it). */
double pl_scene_memory_bytes(const pl_scene_t *scene, int nthreads);

/* Line on which the key at `offset` (offsetof(pl_scene_t, ...)) was given,
 * or 0 when it took its default. */
int pl_scene_line_of(const pl_scene_t *scene, size_t offset);

/* Formats a cross-key error "FILE:LINE: key 'name': what" (LINE of the key at
 * `offset`); returns PL_ERR_INPUT. */
int pl_scene_fail(const pl_scene_t *scene, pl_err_t *err, size_t offset, const char *key,
                  const char *fmt, ...) __attribute__((format(printf, 5, 6)));

/* The paths colloids.init_file and colloids.table_file are opened at:
 * relative to the scene file's directory unless absolute
 * (src/scene/scene_paths.c). */
void pl_scene_init_file_path(const pl_scene_t *scene, char *buf, size_t n);
void pl_scene_table_file_path(const pl_scene_t *scene, char *buf, size_t n);

/* Markdown reference of every key (README "Scene file reference"). */
void pl_scene_print_reference(void *file_ptr);

/* Writes the effective scene as libconfig text (echoed into outputs). */
void pl_scene_print(const pl_scene_t *scene, void *file_ptr);

/* The effective scene as a jansson object (summary.json): one member per
 * key, sections as nested objects.  A non-finite number is an error naming
 * the key. */
struct json_t;
int pl_scene_json(const pl_scene_t *scene, struct json_t **out, pl_err_t *err);

#endif
