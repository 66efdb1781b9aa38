/* The observer table (DESIGN.md "Observables and their errors"): one row per
 * observer of the observe module (src/observe/observers.c), each in its own
 * file under src/observe/.  A row says which scene keys switch the observer
 * on, checks its part of the scene, creates, samples, writes its groups of
 * observables.h5 and its summary.json entries, checkpoints its state and
 * names the estimates (value and SE against run time) that the
 * error-against-time report and the stopping rule (stop.observable) use.
 * The dispatcher, src/observe/observe_module.c, owns the run span, the
 * stages, observables.h5 and the checkpoint group /observe.  Adding an
 * observable is its file, its row and its keys (src/scene/scene_keys_observe.c,
 * peloid/observe_scene.h). */
#ifndef PELOID_OBSERVER_H
#define PELOID_OBSERVER_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/blocking.h"
#include "peloid/error.h"
#include "peloid/sim.h"

struct pl_json;
struct json_t;
struct pl_obs_point; /* an estimate at a run fraction (src/observe/observables_out.h) */

/* What every observer's hooks share: the run and its span. */
typedef struct pl_obs_run {
    pl_sim_t *sim;
    long long first, last; /* the (combined) run's steps, known from the first after-step stage on */
    long long resume_step; /* the checkpoint's step (-1: none) */
} pl_obs_run_t;

/* Samples from `start` to the run's last step, every `interval` (the room a
 * series needs; at least 1). */
uint64_t pl_obs_expected(const pl_obs_run_t *run, long long start, long long interval);
/* Grows a series buffer *p from n to cap elements of size sz, the new part
 * zero (a resumed run that samples longer); 0 or -1 (out of memory). */
int pl_obs_grow(void **p, size_t n, size_t cap, size_t sz);

/* One estimate of an observer: a number with its standard error. */
typedef struct pl_obs_estimate {
    const char *name; /* summary.json key and stop.observable choice */
    /* its index in the checkpoint's ept_* datasets (the first observers'
     * layout, kept byte for byte); -1: datasets <name>_ept_* of its own */
    int ckpt_slot;
    /* sets p's value, se, valid and plateau from the observer's state
     * (NULL: the observer is off); what it leaves as it is, or sets when
     * there is no estimate, is part of the checkpoint's bytes */
    void (*get)(const void *state, struct pl_obs_point *p);
    /* why the stopping rule cannot use it with this scene (NULL: it can) */
    const char *(*unusable)(const pl_scene_t *sc);
} pl_obs_estimate_t;

/* A summary hook's context: the builder, summary.json "observables", the
 * observer's sampling wall seconds, its estimates' points. */
typedef struct pl_obs_sum {
    struct pl_json *b;
    struct json_t *all;
    double wall, target;
    const struct pl_obs_point *ept; /* [estimate x PL_OBS_NFRAC + fraction] */
} pl_obs_sum_t;

/* The standard entry of the observer's estimate k (value, stderr,
 * n_independent, [statistical_inefficiency], plateau, wall_s, unit,
 * se_vs_time, wall_s_for_target); the caller adds to it and sets it. */
struct json_t *pl_obs_entry(pl_obs_sum_t *s, int k, double value, double se, double n_indep, double ineff,
                            int plateau, const char *unit);

typedef struct pl_observer {
    const char *name;  /* in messages ("g(r)") */
    const char *stage; /* plan stage */
    size_t interval, start; /* its keys in pl_scene_observe_t (offsetof) */
    const char *interval_key, *start_key;
    int at_start; /* samples the run's start state */
    long long need; /* fewest samples with a result */
    /* 1: it measures pairs of colloids, so a scene with one colloid is
     * refused at check (pl_observe_validate_scene) */
    int pairs;
    /* what keeps its estimates from a value when it sampled (the end-of-run
     * warning, pl_observe_unmeasured; NULL: the samples alone) */
    const char *none_why;
    /* its scene checks beyond one key's range (NULL: none); PL_ERR_INPUT
     * via pl_scene_fail (file:line:key) */
    int (*check)(const pl_scene_t *sc, pl_err_t *err);
    /* its state (calloc'ed), when the observer is on */
    int (*create)(pl_obs_run_t *run, void **state, pl_err_t *err);
    /* at the run's first after-step stage, after a resume (NULL: nothing) */
    int (*begin)(pl_obs_run_t *run, void *state, pl_err_t *err);
    int (*sample)(pl_obs_run_t *run, void *state, pl_err_t *err);
    /* its groups in /observables (an hid_t); 0 or -1 */
    int (*write)(int64_t obs, const pl_sim_t *sim, void *state);
    int (*summary)(pl_obs_sum_t *s, const pl_sim_t *sim, void *state);
    /* checkpoint (group /observe): the first observers' slots of the
     * positional meta (meta_slot, nmeta; -1, 0 for later observers, which
     * keep named datasets only); ckpt_meta fills them (state NULL: off) */
    int meta_slot, nmeta;
    void (*ckpt_meta)(const void *state, long long *m);
    /* datasets before every observer's, written when off too (state NULL; the
     * first observers' layout); NULL: none */
    int (*ckpt_head)(int64_t g, const void *state);
    int (*ckpt_write)(int64_t g, const void *state);
    /* reads back what ckpt_write wrote (m: its meta slots); errors name path */
    int (*ckpt_read)(int64_t g, pl_obs_run_t *run, void *state, const long long *m, const char *path,
                     pl_err_t *err);
    /* after a restart, the combined run's span known: room for it (NULL: none) */
    int (*resume)(pl_obs_run_t *run, void *state, pl_err_t *err);
    void (*free)(void *state);
    const pl_obs_estimate_t *estimates;
    int nestimates;
    /* its summary.json "observables" entries with a value that are not
     * estimates (NULL-terminated; NULL: none): its summary writes them
     * under these names, and a study's plot.y may name them */
    const char *const *entries;
} pl_observer_t;

/* The rows, in the order of their stages, outputs and checkpoint items. */
extern const pl_observer_t *const pl_observers[];
extern const int pl_nobservers;

/* The summary.json "observables" entries with a value of the fluid stress
 * module (src/observe/stress_output.c writes them), no row of the table:
 * on with observe.stress_interval (NULL-terminated). */
extern const char *const pl_stress_entries[];

/* Whether scene sc measures the summary.json "observables" entry `name`
 * (an estimate or entry of a row, or a stress entry): 0, or PL_ERR_INPUT
 * and why (n bytes, "...; allowed: ..." with the names sc measures), when
 * no observer writes it or its observer is off in sc.  sc NULL: whether
 * any observer writes it (allowed: every name).  src/observe/observe_names.c */
int pl_observe_named(const pl_scene_t *sc, const char *name, char *why, size_t n);

/* Observer r (its state, on) with none of its estimates valid at the end
 * of steps first..last: 1 and why (n bytes: its interval key, what it
 * could not measure, row none_why), else 0 (src/observe/observe_span.c). */
int pl_obs_unmeasured(const pl_observer_t *r, const void *state, long long first, long long last, char *why,
                      size_t n);

/* A checkpoint's /observe/meta error: "path: /observe/meta: why (corrupt
 * checkpoint)", PL_ERR_INPUT. */
int pl_obs_ckpt_corrupt(pl_err_t *err, const char *path, const char *why);
/* n blocking accumulators from dataset /observe/<name> of g (an hid_t),
 * their level counts in range; errors name path. */
int pl_obs_blocking_read(int64_t g, const char *name, pl_blocking_t *b, size_t n, const char *path, pl_err_t *err);

#endif
