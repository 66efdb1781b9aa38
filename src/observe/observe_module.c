/* The observe module (peloid/module.h; DESIGN.md "Observables and their
 * errors"): a dispatcher over the observer table (peloid/observer.h,
 * src/observe/observers.c).  It checks the scene through the rows, creates
 * the observers the scene switches on, adds one after-step stage per
 * observer, opens observables.h5 (H5MD /observables) once and lets each row
 * write its groups, collects the rows' summary.json "observables" entries,
 * and keeps the checkpoint group /observe.  An observer that ends with none
 * of its estimates valid is listed in summary.json "observables"
 * "not_measured" (its interval key: why) and the run warns of it.
 *
 * Error against run time: at 1/8, 1/4, 1/2 and all of the run the current
 * estimate and SE of every row's estimates are recorded with the wall time
 * spent; the summary extrapolates (SE ~ 1/sqrt(t)) the wall time that
 * observe.target_rel_error would need, flagged when the blocking found no
 * plateau.  The stopping rule (stop.observable) chooses among the same
 * estimates, by name.
 *
 * Restart: the accumulated state is the checkpoint group /observe (section
 * "checkpoint" below); with the same observe section the observers resume
 * and cover the whole history since they started (first_step the original
 * start, fractions of the combined run), with another one, or from a
 * checkpoint without the group, they start afresh and say so (README
 * "Observables", restart). */
#include <hdf5.h>
#include <jansson.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint_h5.h"
#include "json_build.h"
#include "observables_out.h"
#include "observables_si.h"
#include "peloid/checkpoint.h"
#include "peloid/coupling.h"
#include "peloid/h5.h"
#include "peloid/io.h"
#include "peloid/module.h"
#include "peloid/observe_check.h"
#include "peloid/observer.h"
#include "peloid/outputs.h"

enum { NFRAC = PL_OBS_NFRAC };
#define fractions pl_obs_fractions
#define NOBS pl_nobservers
#define ROW(k) pl_observers[k]

typedef pl_obs_point_t ept_t;

/* A stage's context: the module and the row. */
typedef struct {
    struct pl_observe *o;
    int k;
} obs_stage_t;

typedef struct pl_observe {
    pl_obs_run_t run;
    double t_start;      /* wall clock at the run's start */
    void **st;           /* NOBS: each row's state (NULL: off) */
    double *wall;        /* NOBS: sampling wall seconds */
    int *est0;           /* NOBS + 1: a row's first estimate in the flat list */
    obs_stage_t *ctx;    /* NOBS */
    int nest;            /* estimates of all rows */
    ept_t (*ept)[NFRAC]; /* nest: error against run time */
    int next_frac, begun;
    ept_t (*ept_saved)[NFRAC]; /* restart: the checkpoint's points */
    int nept_saved;
} pl_observe_t;

static pl_observe_t *observe_of(const pl_sim_t *sim) { return pl_module_state(sim, &pl_observe_module); }
int pl_observe_running(const pl_sim_t *sim) { return observe_of(sim) != NULL; }

int pl_obs_grow(void **p, size_t n, size_t cap, size_t sz)
{
    void *q = realloc(*p, cap * sz);
    if (!q) return -1;
    memset((char *)q + n * sz, 0, (cap - n) * sz);
    *p = q;
    return 0;
}

uint64_t pl_obs_expected(const pl_obs_run_t *r, long long start, long long interval)
{
    long long a = r->first > start ? r->first : start;
    if (a % interval) a += interval - a % interval;
    return a > r->last ? 1 : (uint64_t)((r->last - a) / interval + 1);
}

static long long row_interval(const pl_scene_t *sc, int k) { return pl_scene_observe_ll(&sc->observe, ROW(k)->interval); }

/* ---- estimates (error against time, stop.observable) ------------------- */

/* Row and estimate of the flat index e. */
static const pl_obs_estimate_t *estimate_at(int e, int *row)
{
    for (int k = 0; k < NOBS; ++k) {
        if (e < ROW(k)->nestimates) {
            if (row) *row = k;
            return &ROW(k)->estimates[e];
        }
        e -= ROW(k)->nestimates;
    }
    return NULL;
}

static const pl_obs_estimate_t *estimate_named(const char *name, int *row)
{
    for (int k = 0; k < NOBS; ++k)
        for (int j = 0; j < ROW(k)->nestimates; ++j)
            if (!strcmp(ROW(k)->estimates[j].name, name)) {
                *row = k;
                return &ROW(k)->estimates[j];
            }
    return NULL;
}

int pl_observe_estimate(const pl_sim_t *sim, const char *name, double *value, double *se)
{
    const pl_observe_t *o = observe_of(sim);
    int k;
    const pl_obs_estimate_t *e = estimate_named(name, &k);
    if (!o || !e || !o->st[k]) return 0;
    ept_t p = {0};
    e->get(o->st[k], &p);
    *value = p.value;
    *se = p.se;
    return p.valid;
}

/* Row k on, with none of its estimates valid: why (n bytes). */
static int row_unmeasured(const pl_sim_t *sim, int k, char *why, size_t n)
{
    const pl_observe_t *o = observe_of(sim);
    return o && o->st[k] && pl_obs_unmeasured(ROW(k), o->st[k], o->run.first, sim->step, why, n);
}

int pl_observe_unmeasured(const pl_sim_t *sim, int k, char *why, size_t n)
{
    for (int r = 0; r < NOBS; ++r)
        if (row_unmeasured(sim, r, why, n) && k-- == 0) return 1;
    return 0;
}

/* ---- scene checks ------------------------------------------------------ */

static int stop_check(const pl_scene_t *sc, pl_err_t *err)
{
    const char *name = sc->stop.observable;
    const size_t off = offsetof(pl_scene_t, stop.observable);
    if (!strcmp(name, "none")) return 0;
    int k;
    const pl_obs_estimate_t *e = estimate_named(name, &k);
    if (!e) {
        char allowed[1024];
        size_t len = (size_t)snprintf(allowed, sizeof allowed, "\"none\"");
        for (int r = 0; r < NOBS; ++r)
            for (int j = 0; j < ROW(r)->nestimates && len < sizeof allowed; ++j)
                len += (size_t)snprintf(allowed + len, sizeof allowed - len, ", \"%s\"", ROW(r)->estimates[j].name);
        return pl_scene_fail(sc, err, off, "stop.observable", "\"%s\" is no observer's estimate; allowed: %s", name,
                             allowed);
    }
    const char *why = e->unusable ? e->unusable(sc) : NULL;
    if (why) return pl_scene_fail(sc, err, off, "stop.observable", "\"%s\" %s", name, why);
    if (row_interval(sc, k) <= 0)
        return pl_scene_fail(sc, err, off, "stop.observable", "\"%s\" needs its observer: %s > 0", name,
                             ROW(k)->interval_key);
    if (!(sc->stop.rel_error > 0))
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, stop.rel_error), "stop.rel_error",
                             "%g with stop.observable; allowed: > 0", sc->stop.rel_error);
    return 0;
}

int pl_observe_validate_scene(const pl_scene_t *sc, pl_err_t *err)
{
    for (int k = 0; k < NOBS; ++k) {
        const long long iv = row_interval(sc, k);
        if (iv > 0 && sc->colloids.count < (ROW(k)->pairs ? 2 : 1))
            return pl_scene_fail(sc, err, offsetof(pl_scene_t, observe) + ROW(k)->interval, ROW(k)->interval_key,
                                 "%lld: the %s observer needs %s (colloids.count = %lld); allowed: 0 with fewer "
                                 "than %d colloids", iv, ROW(k)->name, ROW(k)->pairs ? "pairs of colloids" : "colloids",
                                 sc->colloids.count, ROW(k)->pairs ? 2 : 1);
    }
    int rc = stop_check(sc, err);
    for (int k = 0; !rc && k < NOBS; ++k)
        if (ROW(k)->check) rc = ROW(k)->check(sc, err);
    return rc ? rc : pl_observe_validate_measurable(sc, err);
}

/* ---- lifetime ---------------------------------------------------------- */

static void observe_destroy(pl_sim_t *sim)
{
    pl_observe_t *o = observe_of(sim);
    if (!o) return;
    for (int k = 0; o->st && k < NOBS; ++k)
        if (o->st[k]) ROW(k)->free(o->st[k]);
    void *owned[] = {o->st, o->wall, o->est0, o->ctx, o->ept, o->ept_saved, o};
    for (size_t k = 0; k < sizeof owned / sizeof *owned; ++k) free(owned[k]);
    pl_module_set_state(sim, &pl_observe_module, NULL);
}

static int observe_create(pl_sim_t *sim, pl_err_t *err)
{
    int any = 0;
    for (int k = 0; k < NOBS; ++k) any |= row_interval(&sim->scene, k) > 0;
    if (!sim->colloids || !any) return 0;
    pl_observe_t *o = calloc(1, sizeof *o);
    if (!o) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the observers");
    pl_module_set_state(sim, &pl_observe_module, o);
    o->run = (pl_obs_run_t){.sim = sim, .resume_step = -1};
    o->st = calloc((size_t)NOBS, sizeof *o->st);
    o->wall = calloc((size_t)NOBS, sizeof *o->wall);
    o->est0 = calloc((size_t)NOBS + 1, sizeof *o->est0);
    o->ctx = calloc((size_t)NOBS, sizeof *o->ctx);
    for (int k = 0; o->est0 && k < NOBS; ++k) o->est0[k + 1] = o->est0[k] + ROW(k)->nestimates;
    o->nest = o->est0 ? o->est0[NOBS] : 0;
    o->ept = calloc((size_t)o->nest + 1, sizeof *o->ept);
    o->ept_saved = calloc((size_t)o->nest + 1, sizeof *o->ept_saved);
    if (!o->st || !o->wall || !o->est0 || !o->ctx || !o->ept || !o->ept_saved) {
        observe_destroy(sim);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the observers");
    }
    int rc = 0;
    for (int k = 0; !rc && k < NOBS; ++k) {
        o->ctx[k] = (obs_stage_t){o, k};
        if (row_interval(&sim->scene, k) > 0) rc = ROW(k)->create(&o->run, &o->st[k], err);
    }
    if (!rc) rc = pl_observe_check_colloids(&sim->scene, sim->colloids, err); /* before any output */
    return rc;
}

/* ---- stages ------------------------------------------------------------ */

/* Records the estimates at the fractions of the run (1/8, 1/4, 1/2, 1). */
static int stage_error_time(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    pl_observe_t *o = ctx;
    if (sim->step == o->run.resume_step) return 0; /* recorded before the checkpoint */
    while (o->next_frac < NFRAC) {
        const long long at =
            o->run.first + (long long)ceil(fractions[o->next_frac] * (double)(o->run.last - o->run.first));
        if (sim->step < at) break;
        const double wall = omp_get_wtime() - o->t_start;
        for (int e = 0; e < o->nest; ++e) {
            int k;
            const pl_obs_estimate_t *es = estimate_at(e, &k);
            ept_t *p = &o->ept[e][o->next_frac];
            p->step = sim->step;
            p->wall_s = wall;
            es->get(o->st[k], p);
        }
        o->next_frac++;
    }
    return 0;
}

static int observe_resume(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err);

/* The run's first state is known when the after-step stages first run. */
static int stage_begin(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    pl_observe_t *o = ctx;
    if (o->begun) return 0;
    o->begun = 1;
    o->run.last = sim->last_step;
    o->t_start = omp_get_wtime(); /* no clock reading is checkpointed */
    int rc = 0;
    if (o->run.resume_step < 0) o->run.first = sim->first_step;
    else rc = observe_resume(sim, o, err);
    for (int k = 0; !rc && k < NOBS; ++k)
        if (o->st[k] && ROW(k)->begin) rc = ROW(k)->begin(&o->run, o->st[k], err);
    return rc;
}

/* A row's stage: not at the checkpoint's step (sampled before it) nor
 * before its start step; its wall time to o->wall. */
static int stage_sample(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    const obs_stage_t *s = ctx;
    pl_observe_t *o = s->o;
    if (sim->step == o->run.resume_step || sim->step < pl_scene_observe_ll(&sim->scene.observe, ROW(s->k)->start))
        return 0;
    const double t0 = omp_get_wtime();
    const int rc = ROW(s->k)->sample(&o->run, o->st[s->k], err);
    o->wall[s->k] += omp_get_wtime() - t0;
    return rc;
}

static int observe_stages(pl_sim_t *sim, pl_err_t *err)
{
    pl_observe_t *o = observe_of(sim);
    if (!o) return 0;
    pl_stage_t b = {.name = "observe-begin", .fn = stage_begin, .ctx = o, .interval = 1,
                    .phase = PL_PHASE_AFTER, .slot = PL_SLOT_OBSERVE, .at_start = 1};
    int rc = pl_sim_add_stage(sim, &b, err);
    for (int k = 0; !rc && k < NOBS; ++k) {
        if (!o->st[k]) continue;
        pl_stage_t s = {.name = ROW(k)->stage, .fn = stage_sample, .ctx = &o->ctx[k],
                        .interval = row_interval(&sim->scene, k), .phase = PL_PHASE_AFTER,
                        .slot = PL_SLOT_OBSERVE, .at_start = ROW(k)->at_start};
        rc = pl_sim_add_stage(sim, &s, err);
    }
    pl_stage_t e = {.name = "observe-error-time", .fn = stage_error_time, .ctx = o, .interval = 1,
                    .phase = PL_PHASE_AFTER, .slot = PL_SLOT_OBSERVE, .at_start = 1};
    return rc ? rc : pl_sim_add_stage(sim, &e, err);
}

/* ---- outputs ----------------------------------------------------------- */

static int write_h5(const pl_sim_t *sim, const pl_observe_t *o, const char *path, pl_err_t *err)
{
    char tmp[4200];
    pl_atomic_tmp(path, tmp, sizeof tmp);
    pl_h5_quiet();
    hid_t f = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (f < 0) return pl_err_set(err, PL_ERR_IO, "%s: cannot create the observables file", tmp);
    int bad = pl_h5_h5md_header(f) != 0;
    hid_t obs = pl_h5_group(f, "observables");
    bad |= obs < 0;
    for (int k = 0; !bad && k < NOBS; ++k)
        if (o->st[k]) bad |= ROW(k)->write(obs, sim, o->st[k]) != 0;
    if (obs >= 0 && H5Gclose(obs) < 0) bad = 1;
    if (!bad && sim->scene.mapping.enabled) bad = pl_obs_si_h5(f, &sim->scene.mapping.map, pl_mapping_t0_relative_error(&sim->scene.mapping.map)) != 0;
    return pl_obs_h5_commit(f, bad, tmp, path, "observables", err);
}

json_t *pl_obs_entry(pl_obs_sum_t *s, int k, double value, double se, double n_indep, double ineff, int plateau,
                     const char *unit)
{
    pl_json_t *b = s->b;
    json_t *e = json_object();
    pl_json_real(b, e, "value", value);
    pl_json_real(b, e, "stderr", se);
    pl_json_real(b, e, "n_independent", n_indep);
    if (ineff > 0) pl_json_real(b, e, "statistical_inefficiency", ineff);
    pl_json_set(b, e, "plateau", json_boolean(plateau));
    pl_json_real(b, e, "wall_s", s->wall);
    pl_json_str(b, e, "unit", unit);
    pl_obs_error_time(b, e, s->ept + (size_t)k * NFRAC, value, se, plateau, s->target);
    return e;
}

static int observe_finish(pl_sim_t *sim, const char *dir, json_t *doc, pl_err_t *err)
{
    pl_observe_t *o = observe_of(sim);
    if (!o) return 0;
    char path[4096];
    pl_path_join(path, sizeof path, dir, pl_outputs[PL_OUT_OBSERVABLES].name);
    int rc = write_h5(sim, o, path, err);
    if (rc) return rc;
    pl_json_t b = {err, path, "observables", 0};
    json_t *all = pl_obs_summary_section(&b, doc, sim, o->run.first);
    if (!all) return err->code;
    for (int k = 0; !b.failed && k < NOBS; ++k) {
        if (!o->st[k]) continue;
        pl_obs_sum_t s = {&b, all, o->wall[k], sim->scene.observe.target_rel_error,
                          o->ept[o->est0[k]]};
        if ((rc = ROW(k)->summary(&s, sim, o->st[k]))) return rc;
    }
    json_t *none = NULL; /* "not_measured": {interval key: why} */
    for (int k = 0; !b.failed && k < NOBS; ++k) {
        char why[600];
        if (!row_unmeasured(sim, k, why, sizeof why)) continue;
        if (!none) pl_json_set(&b, all, "not_measured", none = json_object());
        pl_json_str(&b, none, ROW(k)->interval_key, why);
    }
    return b.failed ? err->code : 0;
}

/* ---- checkpoint -------------------------------------------------------- */

/* Group /observe of the checkpoint (src/observe/checkpoint_observe.c gives it the
 * observer fingerprint): everything the observers accumulated, so that a
 * restarted run's observables equal those of the uninterrupted run bitwise.
 * The objects are read back as they were (correlators with the levels the
 * first run planned for); observe_resume, at the restart's first step, sizes
 * them for the combined run.  Datasets: meta (int64: the first step, the
 * next run fraction, the first observers' slots (pl_observer_t meta_slot),
 * the step), the error-against-time points of the first observers'
 * estimates (ckpt_slot), the rows' head datasets, then each row's own.  A
 * later observer keeps named datasets only (its estimates' <name>_ept_*).
 * No clock reading is stored (the same state gives the same bytes): after a
 * restart the wall times (wall_s) count the restarted run's, and the points
 * of se_vs_time taken over from the first run carry wall_s = 0. */
enum { OCK_FIRST, OCK_NEXT_FRAC, OCK_STEP = 13, OCK_N, NLEGACY = 10 };

/* The points of estimates e (n of them) as ept_step, ept_flags, ept_values
 * (prefix "": the first observers' slots) or read back. */
static int ept_write(hid_t g, const char *prefix, ept_t (*const *pts)[NFRAC], int n)
{
    const size_t m = (size_t)n * NFRAC;
    long long *st = malloc(3 * m * sizeof *st);
    double *val = malloc(2 * m * sizeof *val);
    int bad = !st || !val;
    for (size_t k = 0; !bad && k < m; ++k) {
        const ept_t *e = &(*pts[k / NFRAC])[k % NFRAC];
        st[k] = e->step;
        st[m + 2 * k] = e->valid;
        st[m + 2 * k + 1] = e->plateau;
        val[2 * k] = e->value;
        val[2 * k + 1] = e->se;
    }
    char a[160], b[160], c[160];
    snprintf(a, sizeof a, "%sept_step", prefix);
    snprintf(b, sizeof b, "%sept_flags", prefix);
    snprintf(c, sizeof c, "%sept_values", prefix);
    if (!bad) {
        bad |= pl_ckpt_write_1d(g, a, H5T_NATIVE_LLONG, st, m);
        bad |= pl_ckpt_write_1d(g, b, H5T_NATIVE_LLONG, st + m, 2 * m);
        bad |= pl_ckpt_write_1d(g, c, H5T_NATIVE_DOUBLE, val, 2 * m);
    }
    free(st);
    free(val);
    return bad;
}

static int ept_read(hid_t g, const char *prefix, ept_t (*const *pts)[NFRAC], int n, const char *path, pl_err_t *err)
{
    const size_t m = (size_t)n * NFRAC;
    long long *st = malloc(3 * m * sizeof *st);
    double *val = malloc(2 * m * sizeof *val);
    if (!st || !val) {
        free(st);
        free(val);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory reading %s", path);
    }
    char a[160], b[160], c[160];
    snprintf(a, sizeof a, "%sept_step", prefix);
    snprintf(b, sizeof b, "%sept_flags", prefix);
    snprintf(c, sizeof c, "%sept_values", prefix);
    int rc = pl_ckpt_read_1d(g, a, H5T_NATIVE_LLONG, st, m, path, err);
    if (!rc) rc = pl_ckpt_read_1d(g, b, H5T_NATIVE_LLONG, st + m, 2 * m, path, err);
    if (!rc) rc = pl_ckpt_read_1d(g, c, H5T_NATIVE_DOUBLE, val, 2 * m, path, err);
    for (size_t k = 0; !rc && k < m; ++k)
        (*pts[k / NFRAC])[k % NFRAC] = (ept_t){.step = st[k], .valid = (int)st[m + 2 * k],
                                               .plateau = (int)st[m + 2 * k + 1], .wall_s = 0.0,
                                               .value = val[2 * k], .se = val[2 * k + 1]};
    free(st);
    free(val);
    return rc;
}

/* The points of the first observers' estimates in slot order (their
 * pointers into pts). */
static void legacy_points(const pl_observe_t *o, ept_t (*pts)[NFRAC], ept_t (**by_slot)[NFRAC])
{
    for (int e = 0; e < o->nest; ++e) {
        const pl_obs_estimate_t *es = estimate_at(e, NULL);
        if (es->ckpt_slot >= 0 && es->ckpt_slot < NLEGACY) by_slot[es->ckpt_slot] = &pts[e];
    }
}

static int observe_ckpt_write(int64_t file, const pl_sim_t *sim)
{
    pl_observe_t *o = observe_of(sim);
    if (!o) return 0;
    hid_t g = pl_ckpt_observe_group_write((hid_t)file, "observe", &sim->scene);
    if (g < 0) return -1;
    long long meta[OCK_N] = {0};
    meta[OCK_FIRST] = o->begun ? o->run.first : sim->step;
    meta[OCK_NEXT_FRAC] = o->next_frac;
    meta[OCK_STEP] = sim->step;
    for (int k = 0; k < NOBS; ++k)
        if (ROW(k)->meta_slot >= 0) ROW(k)->ckpt_meta(o->st[k], meta + ROW(k)->meta_slot);
    ept_t(*slot[NLEGACY])[NFRAC] = {0};
    legacy_points(o, o->ept, slot);
    int bad = pl_ckpt_write_1d(g, "meta", H5T_NATIVE_LLONG, meta, OCK_N);
    bad |= ept_write(g, "", slot, NLEGACY);
    for (int k = 0; k < NOBS; ++k) /* an off row's too (NULL) */
        if (ROW(k)->ckpt_head) bad |= ROW(k)->ckpt_head(g, o->st[k]);
    for (int k = 0; k < NOBS; ++k) {
        if (!o->st[k]) continue;
        bad |= ROW(k)->ckpt_write(g, o->st[k]);
        for (int j = 0; j < ROW(k)->nestimates; ++j)
            if (ROW(k)->estimates[j].ckpt_slot < 0) {
                char pre[128];
                ept_t(*p[1])[NFRAC] = {&o->ept[o->est0[k] + j]};
                snprintf(pre, sizeof pre, "%s_", ROW(k)->estimates[j].name);
                bad |= ept_write(g, pre, p, 1);
            }
    }
    if (H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
}

int pl_obs_ckpt_corrupt(pl_err_t *err, const char *path, const char *why)
{
    return pl_err_set(err, PL_ERR_INPUT, "%s: /observe/meta: %s (corrupt checkpoint)", path, why);
}

int pl_obs_blocking_read(int64_t g, const char *name, pl_blocking_t *b, size_t n, const char *path, pl_err_t *err)
{
    int rc = pl_ckpt_read_1d((hid_t)g, name, H5T_NATIVE_UCHAR, b, n * sizeof *b, path, err);
    for (size_t k = 0; !rc && k < n; ++k)
        if (b[k].nlev < 0 || b[k].nlev > PL_BLOCKING_LEVELS)
            rc = pl_err_set(err, PL_ERR_INPUT, "%s: /observe/%s: a blocking level count is out of range (corrupt "
                                               "checkpoint)", path, name);
    return rc;
}

static int observe_ckpt_read_group(hid_t g, pl_sim_t *sim, pl_observe_t *o, const char *path, pl_err_t *err)
{
    long long m[OCK_N];
    int rc = pl_ckpt_read_1d(g, "meta", H5T_NATIVE_LLONG, m, OCK_N, path, err);
    ept_t(*slot[NLEGACY])[NFRAC] = {0};
    legacy_points(o, o->ept_saved, slot);
    if (!rc) rc = ept_read(g, "", slot, NLEGACY, path, err);
    if (rc) return rc;
    /* what the observe section allows (the fingerprint matched, so only a
     * corrupt file has more) */
    const char *why = m[OCK_STEP] != sim->step ? "step differs from the checkpoint's"
                      : m[OCK_FIRST] < 0 || m[OCK_FIRST] > sim->step ? "first step out of range"
                      : m[OCK_NEXT_FRAC] < 0 || m[OCK_NEXT_FRAC] > NFRAC ? "next_frac out of range"
                                                                       : NULL;
    for (int k = 0; !why && k < NOBS; ++k) { /* an off row's slots hold what it writes when off */
        long long off[OCK_N];
        if (o->st[k] || ROW(k)->meta_slot < 0) continue;
        ROW(k)->ckpt_meta(NULL, off);
        if (memcmp(off, m + ROW(k)->meta_slot, (size_t)ROW(k)->nmeta * sizeof *off))
            why = "an observer the scene does not switch on";
    }
    if (why) return pl_obs_ckpt_corrupt(err, path, why);
    o->nept_saved = (int)m[OCK_NEXT_FRAC];
    o->run.first = m[OCK_FIRST];
    o->run.resume_step = sim->step;
    for (int k = 0; !rc && k < NOBS; ++k) {
        if (!o->st[k]) continue;
        rc = ROW(k)->ckpt_read(g, &o->run, o->st[k], ROW(k)->meta_slot >= 0 ? m + ROW(k)->meta_slot : NULL, path,
                               err);
        for (int j = 0; !rc && j < ROW(k)->nestimates; ++j)
            if (ROW(k)->estimates[j].ckpt_slot < 0) {
                char pre[128];
                ept_t(*p[1])[NFRAC] = {&o->ept_saved[o->est0[k] + j]};
                snprintf(pre, sizeof pre, "%s_", ROW(k)->estimates[j].name);
                rc = ept_read(g, pre, p, 1, path, err);
            }
    }
    return rc;
}

/* The observers' state from group /observe; without the group, or with
 * another observe section, they start afresh (pl_sim_observers_afresh). */
static int observe_ckpt_read(int64_t file, pl_sim_t *sim, const char *path, pl_err_t *err)
{
    pl_observe_t *o = observe_of(sim);
    if (!o) return 0;
    hid_t g = pl_ckpt_observe_group_open((hid_t)file, "observe", sim);
    if (g < 0) return 0;
    int rc = observe_ckpt_read_group(g, sim, o, path, err);
    H5Gclose(g);
    return rc;
}

/* At the restarted run's first step (its last step now known): each row
 * gets the room the combined run needs (what an uninterrupted run would
 * have created), and the error-against-time points are those of the
 * combined run from first to last: a point the first run recorded at that
 * step is taken over, one it did not record (its step fell between the
 * first run's fractions) is left out of se_vs_time. */
static int observe_resume(pl_sim_t *sim, pl_observe_t *o, pl_err_t *err)
{
    (void)sim;
    for (int k = 0; k < NOBS; ++k)
        if (o->st[k] && ROW(k)->resume) {
            int rc = ROW(k)->resume(&o->run, o->st[k], err);
            if (rc) return rc;
        }
    memset(o->ept, 0, (size_t)o->nest * sizeof *o->ept);
    o->next_frac = NFRAC;
    for (int k = NFRAC - 1; k >= 0; --k) {
        const long long at = o->run.first + (long long)ceil(fractions[k] * (double)(o->run.last - o->run.first));
        if (at > o->run.resume_step) {
            o->next_frac = k;
            continue;
        }
        for (int j = 0; j < o->nept_saved; ++j)
            if (o->ept_saved[0][j].step == at) {
                for (int e = 0; e < o->nest; ++e) o->ept[e][k] = o->ept_saved[e][j];
                break;
            }
    }
    return 0;
}

const pl_module_t pl_observe_module = {
    .name = "observe",
    .validate_scene = pl_observe_validate_scene,
    .create = observe_create,
    .destroy = observe_destroy,
    .add_stages = observe_stages,
    .finish = observe_finish,
    .checkpoint_write = observe_ckpt_write,
    .checkpoint_read = observe_ckpt_read,
};
