/* The run: build the simulation, open the outputs (its own thermo.tsv and
 * scene.cfg, then the writer rows of src/app/writers.c), add the writers to
 * the plan, walk it, then the writers' last writes (trajectory, checkpoint,
 * fields), each module's outputs and the summary.  Order matters for "nothing written on bad input": the
 * scene is validated, the sim built and any restart checkpoint read before
 * the output directory is created. */
#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "json_build.h"
#include "observables_si.h"
#include "peloid/checkpoint.h"
#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/io.h"
#include "peloid/mapping.h"
#include "peloid/module.h"
#include "peloid/topology.h"
#include "peloid/progress.h"
#include "peloid/run.h"
#include "peloid/srd_theory.h"
#include "peloid/thermo.h"
#include "peloid/writer.h"
#include "peloid_build.h" /* PL_GIT_REV, PL_CFLAGS (generated) */

typedef struct {
    char dir[PATH_MAX]; /* resolved output directory (pl_outdir_prepare) */
    char thermo_path[PATH_MAX + 16];
    FILE *thermo;
    pl_thermo_table_t columns;
    double t_last_row;
    long long step_last_row;
    int interrupted; /* the signal that ended the run early (0: none) */
} writer_t;

/* Writer stage: one thermo.tsv row, flushed.  PL_ERR_IO naming the file and
 * the system error when the row did not reach the file (a full disk must not
 * lose rows silently). */
static int stage_thermo(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    writer_t *w = ctx;
    double now = omp_get_wtime();
    double steps = (double)(sim->step - w->step_last_row);
    double rate = now > w->t_last_row && steps > 0 ? steps * (double)sim->fluid.n / (now - w->t_last_row) / 1e6 : 0.0;
    pl_thermo_sample_t smp;
    pl_thermo_sample(sim, rate, &smp);
    errno = 0;
    int bad = pl_thermo_row(&w->columns, &smp, w->thermo) < 0;
    bad |= fflush(w->thermo) != 0;
    bad |= ferror(w->thermo) != 0;
    w->t_last_row = now;
    w->step_last_row = sim->step;
    if (bad)
        return pl_err_set(err, PL_ERR_IO, "%s: writing the row of step %lld failed: %s", w->thermo_path, sim->step,
                          errno ? strerror(errno) : "stream error");
    return 0;
}

/* The plan moves colloids by MD (not pinned): MD steps/s is worth showing. */
static int colloid_md_moves(const pl_sim_t *sim)
{
    for (int k = 0; k < sim->nstages; ++k)
        if (sim->stages[k].colloid_md) return 1;
    return 0;
}

/* The part of summary.json known before the run (build info, scene, derived
 * parameters, mapping, boundaries, colloid pair settings): built before the
 * output directory is created, so that a non-finite value is bad input with
 * nothing written. */
static int summary_head(const pl_sim_t *sim, json_t **out, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    pl_json_t b = {err, sc->path, "", 0};
    json_t *doc = json_object(), *o = json_object(), *v = NULL;
    pl_json_str(&b, o, "git_revision", PL_GIT_REV);
    pl_json_str(&b, o, "compiler", __VERSION__);
    pl_json_str(&b, o, "cflags", PL_CFLAGS);
    pl_json_str(&b, o, "real", PL_REAL_NAME);
    pl_json_set(&b, doc, "peloid", o);
    pl_json_str(&b, doc, "scene_file", sc->path);
    int rc = 0;
    if (!b.failed && !(rc = pl_scene_json(sc, &v, err))) pl_json_set(&b, doc, "scene", v);
    if (!b.failed && !rc && !(rc = pl_params_json(sc, &v, err))) pl_json_set(&b, doc, "derived", v);
    if (!b.failed && !rc && !(rc = pl_mapping_report_json(sc, &v, err))) pl_json_set(&b, doc, "mapping", v);
    if (!b.failed && !rc && sc->mapping.enabled) {
        const pl_mapping_t *m = &sc->mapping.map;
        b.prefix = "units_si";
        o = json_object();
        pl_json_real(&b, o, "a0_m", m->a0);
        pl_json_real(&b, o, "t0_s", m->t0);
        pl_json_real(&b, o, "m_f_kg", m->m_f);
        pl_json_real(&b, o, "kT_J", m->kT_model);
        pl_json_real(&b, o, "model_temperature_K", m->kT_model / PL_KB);
        pl_json_real(&b, o, "real_temperature_K", sc->mapping.physical.temperature);
        pl_json_set(&b, doc, "units_si", o);
        json_t *cal = pl_mapping_calibration_json(m); /* where t0's colloid D came from (--calibrate) */
        if (cal) pl_json_set(&b, doc, "calibration", cal);
    }
    int walls[3]; /* each axis: periodic, or noslip / slip walls at 0 and L */
    pl_scene_box_walls(&sc->box, walls);
    o = json_object();
    pl_json_str(&b, o, "x", pl_scene_boundary_name(walls[0]));
    pl_json_str(&b, o, "y", pl_scene_boundary_name(walls[1]));
    pl_json_str(&b, o, "z", pl_scene_boundary_name(walls[2]));
    pl_json_set(&b, doc, "boundaries", o);
    for (int m = 0; !rc && !b.failed && pl_modules[m]; ++m) /* each module's entries */
        if (pl_modules[m]->summary) rc = pl_modules[m]->summary(sim, doc, err);
    if (rc || b.failed || !doc) {
        json_decref(doc);
        return rc ? rc : b.failed ? err->code : pl_err_set(err, PL_ERR_NOMEM, "out of memory building JSON");
    }
    *out = doc;
    return 0;
}

/* CPU time of this process, all threads (user + system), for the cost of a
 * run next to its wall time. */
static double process_cpu_seconds(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts)) return 0.0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* summary.json: the head and what the run measured. */
static int write_summary(const writer_t *w, json_t *doc, const pl_sim_t *sim, long long first, double wall,
                         double cpu, pl_err_t *err)
{
    char path[PATH_MAX], tmp[PATH_MAX + 8], topo[256];
    pl_topology_summary(topo, sizeof topo);
    double updates = (double)(sim->step - first) * (double)sim->fluid.n;
    pl_json_t b = {err, path, "", 0};
    pl_path_join(path, sizeof path, w->dir, pl_outputs[PL_OUT_SUMMARY].name);
    pl_json_int(&b, doc, "threads", sim->nthreads);
    pl_json_str(&b, doc, "topology", topo);
    pl_json_int(&b, doc, "fluid_particles", (long long)sim->fluid.n);
    pl_json_int(&b, doc, "first_step", first);
    pl_json_int(&b, doc, "last_step", sim->step);
    pl_json_set(&b, doc, "interrupted", json_boolean(w->interrupted != 0)); /* by a signal, at last_step */
    if (w->interrupted) pl_json_int(&b, doc, "interrupted_signal", w->interrupted);
    pl_json_real(&b, doc, "wall_seconds", wall);
    pl_json_real(&b, doc, "cpu_seconds", cpu); /* the step loop's process CPU time, all threads */
    pl_json_real(&b, doc, "particle_updates_per_second", wall > 0 ? updates / wall : 0.0);
    long long field_samples;
    if (pl_srd_fields(sim->srd, &field_samples)) /* 0: no sample was taken, no fields.h5 */
        pl_json_int(&b, doc, "field_samples", field_samples);
    json_t *st = json_object();
    b.prefix = "stage_seconds";
    for (int k = 0; k < sim->nstages; ++k) pl_json_real(&b, st, sim->stages[k].name, sim->stages[k].seconds);
    pl_json_set(&b, doc, "stage_seconds", st);
    const pl_colloid_t *c = sim->colloids;
    if (c && c->adaptive) { /* this run's collision steps (a restart counts its own) */
        json_t *a = json_object();
        b.prefix = "adaptive_substeps";
        pl_json_int(&b, a, "collision_steps", c->adapt_steps);
        pl_json_int(&b, a, "md_steps", c->adapt_md);
        pl_json_real(&b, a, "mean", c->adapt_steps ? (double)c->adapt_md / (double)c->adapt_steps : 0.0);
        pl_json_int(&b, a, "min", c->adapt_steps ? c->adapt_lo : 0);
        pl_json_int(&b, a, "max", c->adapt_hi);
        pl_json_int(&b, a, "bound_min", c->sub_min);
        pl_json_int(&b, a, "bound_max", c->substeps);
        /* null: no MD step met a contact (or none ran) */
        pl_json_real_or_null(&b, a, "fewest_contact_steps", isfinite(c->adapt_worst) ? c->adapt_worst : NAN);
        pl_json_int(&b, a, "refined_steps", c->adapt_refined);
        pl_json_set(&b, doc, "adaptive_substeps", a);
    }
    { /* the counting sort's narrow histogram rows (pl_fluid_bands_t): sorts that
       * used them, and those that counted whole rows again (a particle out of
       * its band); none with one thread (its band is the whole row) */
        json_t *sb = json_object();
        b.prefix = "sort_bands";
        pl_json_int(&b, sb, "sorts", (long long)sim->fluid.bands.sorts);
        pl_json_int(&b, sb, "recounts", (long long)sim->fluid.bands.recounts);
        pl_json_int(&b, sb, "margin_planes",
                    (long long)(sim->fluid.bands.margin ? sim->fluid.bands.margin : PL_BAND_MARGIN));
        pl_json_set(&b, doc, "sort_bands", sb);
    }
    json_t *units = json_object(); /* thermo.tsv's columns and their units, from the same table */
    b.prefix = "thermo_units";
    for (int k = 0; k < w->columns.n; ++k) pl_json_str(&b, units, w->columns.col[k].name, w->columns.col[k].unit);
    pl_json_set(&b, doc, "thermo_units", units);
    json_t *obs = json_object_get(doc, "observables"); /* every module's entries are in: their SI side */
    b.prefix = "observables";
    if (obs && sim->scene.mapping.enabled) pl_obs_si_json(&b, obs, &sim->scene.mapping.map, pl_mapping_t0_relative_error(&sim->scene.mapping.map));
    if (b.failed) return err->code;
    FILE *f = pl_file_begin(path, tmp, sizeof tmp, err);
    if (!f) return PL_ERR_IO;
    if (pl_json_dump(doc, f, tmp, err)) {
        fclose(f);
        remove(tmp);
        return PL_ERR_IO;
    }
    return pl_file_commit(f, tmp, path, err);
}

/* The copy of colloids.init_file in the run directory: the directory holds
 * everything its scene.cfg needs, so that scene.cfg loads back (and a
 * restart from the directory works) wherever the original file went. */
#define INIT_COPY (pl_outputs[PL_OUT_INIT_COPY].name)
#define TABLE_COPY (pl_outputs[PL_OUT_TABLE_COPY].name) /* the same for colloids.table_file */

static int uses_init_file(const pl_scene_t *sc) { return sc->colloids.count > 0 && sc->colloids.init == PL_CINIT_FILE; }
static int uses_table_file(const pl_scene_t *sc) { return sc->colloids.count > 0 && sc->colloids.table_file[0]; }

/* src copied into the run directory as `name`, which the echo's key (key,
 * n bytes) then names. */
static int copy_named(const writer_t *w, const char *src, const char *name, char *key, size_t n, pl_err_t *err)
{
    char path[PATH_MAX];
    pl_path_join(path, sizeof path, w->dir, name);
    if (pl_file_copy(src, path, err)) return err->code;
    snprintf(key, n, "%s", name);
    return 0;
}

/* scene.cfg: the effective scene, every key; with an init file or a pair
 * table, the file copied as INIT_COPY or TABLE_COPY and named by the echo. */
static int write_scene_echo(const writer_t *w, const pl_scene_t *sc, pl_err_t *err)
{
    char path[PATH_MAX], tmp[PATH_MAX + 8];
    pl_scene_t *echo = malloc(sizeof *echo);
    if (!echo) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    *echo = *sc;
    if (sc->mapping.enabled) { /* the choices the mapping made where the file left them open */
        echo->mapping.cg.boundary = sc->mapping.map.cg.boundary;
        echo->mapping.cg.enskog = sc->mapping.map.cg.enskog;
    }
    char src[PATH_MAX];
    int rc = 0;
    if (uses_init_file(sc)) {
        pl_scene_init_file_path(sc, src, sizeof src);
        rc = copy_named(w, src, INIT_COPY, echo->colloids.init_file, sizeof echo->colloids.init_file, err);
    }
    if (!rc && uses_table_file(sc)) {
        pl_scene_table_file_path(sc, src, sizeof src);
        rc = copy_named(w, src, TABLE_COPY, echo->colloids.table_file, sizeof echo->colloids.table_file, err);
    }
    if (rc) {
        free(echo);
        return rc;
    }
    pl_path_join(path, sizeof path, w->dir, pl_outputs[PL_OUT_SCENE].name);
    FILE *f = pl_file_begin(path, tmp, sizeof tmp, err);
    if (!f) {
        free(echo);
        return PL_ERR_IO;
    }
    fprintf(f, "# effective scene of %s (every key, defaults filled in)\n", sc->path);
    if (uses_init_file(sc)) fprintf(f, "# colloids.init_file: %s copied as %s\n", sc->colloids.init_file, INIT_COPY);
    if (uses_table_file(sc))
        fprintf(f, "# colloids.table_file: %s copied as %s\n", sc->colloids.table_file, TABLE_COPY);
    pl_scene_print(echo, f);
    free(echo);
    errno = 0;
    if (fflush(f) || ferror(f) || fsync(fileno(f))) { /* name the system error */
        int e = errno;
        fclose(f);
        unlink(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: write failed: %s", tmp, e ? strerror(e) : "stream error");
    }
    return pl_file_commit(f, tmp, path, err);
}

/* The thermo rows join the plan as an after-step stage: every
 * output.thermo_interval steps, on the start state and on the last (the
 * writer rows' stages follow: src/app/writers.c). */
static int add_thermo(pl_sim_t *sim, writer_t *w, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    pl_stage_t thermo = {.name = "thermo", .fn = stage_thermo, .ctx = w, .interval = sc->output.thermo_interval,
                         .phase = PL_PHASE_AFTER, .slot = PL_SLOT_WRITE, .at_start = 1, .at_end = 1, .writes = 1};
    return pl_sim_add_stage(sim, &thermo, err);
}

/* Walks the plan from the present step to `last` (or to the step the
 * stopping rule ends it at).  Before each step the writers hold what a
 * guard stop inside the step writes (the colloid trajectory: the last good
 * frame).  The driver's signal flag is polled between steps: a signal
 * during a step ends the run when that step is complete. */
static int loop(pl_sim_t *sim, writer_t *w, const pl_writers_t *ws, pl_progress_t *pg, long long last,
                const volatile sig_atomic_t *interrupt, pl_err_t *err)
{
    w->t_last_row = omp_get_wtime();
    w->step_last_row = sim->step;
    int rc = pl_sim_begin(sim, last, err);
    while (!rc && sim->step < last && !sim->stop_requested) {
        if (interrupt && *interrupt) {
            w->interrupted = (int)*interrupt;
            char why[64];
            snprintf(why, sizeof why, "interrupted by signal %d", w->interrupted);
            return pl_sim_end_here(sim, why, err);
        }
        pl_writers_hold(sim, ws);
        rc = pl_sim_step(sim, err);
        if (rc == PL_ERR_GUARD) pl_writers_guard_stop(sim, ws);
        pl_progress_update(pg, sim->step);
    }
    return rc;
}

/* The files the run leaves in its directory, read from the directory (what
 * the writers wrote, not a list kept beside them): those the list of
 * outputs names as listed (peloid/outputs.h) in its order, then any other
 * by name; not the lock or a *.tmp. */
static void list_outputs(pl_progress_t *pg, const char *dir)
{
    size_t nlisted = 0;
    while (pl_outputs[nlisted].name && pl_outputs[nlisted].listed) ++nlisted;
    struct dirent **e = NULL;
    const int n = scandir(dir, &e, NULL, alphasort);
    for (size_t pass = 0; pass <= nlisted; ++pass) /* pass < nlisted: pl_outputs[pass]; then the others */
        for (int k = 0; k < n; ++k) {
            const char *name = e[k]->d_name;
            const size_t len = strlen(name);
            if (name[0] == '.' || e[k]->d_type == DT_DIR || (len > 4 && !strcmp(name + len - 4, ".tmp"))) continue;
            size_t u = 0;
            while (u < nlisted && strcmp(name, pl_outputs[u].name)) ++u;
            if (pass < nlisted ? u == pass : u == nlisted) pl_progress_file(pg, dir, name);
        }
    for (int k = 0; k < n; ++k) free(e[k]);
    free(e);
}

/* Resume in place: the restart checkpoint lies in the output directory
 * (an existing one).  The run then continues that directory's thermo.tsv
 * and trajectories after their rows and frames before the checkpoint's
 * step, as if it had not been interrupted, instead of replacing them; the
 * directory need not be --force'd and is not cleared. */
static int restart_in_place(const char *restart, const char *out_dir)
{
    char ck[PATH_MAX], ck_dir[PATH_MAX], out[PATH_MAX];
    if (!realpath(restart, ck) || !realpath(out_dir, out)) return 0;
    char *slash = strrchr(ck, '/');
    snprintf(ck_dir, sizeof ck_dir, "%.*s", slash == ck ? 1 : (int)(slash - ck), ck);
    return strcmp(ck_dir, out) == 0;
}

int pl_run(const pl_scene_t *scene, const pl_run_opts_t *o, pl_err_t *err)
{
    pl_sim_t *sim = NULL;
    json_t *summary = NULL;
    pl_progress_t *pg = NULL;
    int lock_fd = -1;
    long long last = 0; /* the step the run ends at */
    writer_t w;
    memset(&w, 0, sizeof w);
    pl_writers_t ws;
    memset(&ws, 0, sizeof ws);
    pl_writer_out_t wout = {.dir = w.dir};
    int rc = pl_sim_create(scene, o->threads, &sim, err);
    if (rc) return rc;
    if (o->restart_changed && !o->restart) {
        rc = pl_err_set(err, PL_ERR_INPUT, "--restart-changed needs --restart CHECKPOINT");
        goto done;
    }
    if (o->restart_changed && (rc = pl_checkpoint_changed_keys_valid(o->restart_changed, err))) goto done;
    if (o->restart && (rc = pl_checkpoint_restart(sim, o->restart, o->restart_changed, err))) goto done;
    long long first = sim->step, nsteps = o->steps >= 0 ? o->steps : scene->run.steps;
    if (__builtin_add_overflow(first, nsteps, &last) || last > PL_RUN_MAX_STEP) {
        rc = pl_err_set(err, PL_ERR_INPUT,
                        "%s: checkpoint step %lld + %lld steps passes the largest step %lld; allowed: a step "
                        ">= 0 whose run ends by step %lld", o->restart ? o->restart : scene->path, first, nsteps,
                        (long long)PL_RUN_MAX_STEP, (long long)PL_RUN_MAX_STEP);
        goto done;
    }
    long long md_last; /* the colloid MD step counter: substeps per collision step */
    if (sim->colloids && (__builtin_mul_overflow(nsteps, (long long)scene->colloids.substeps, &md_last) ||
                          __builtin_add_overflow(md_last, sim->colloids->md_step, &md_last) ||
                          md_last > PL_RUN_MAX_STEP)) {
        rc = pl_err_set(err, PL_ERR_INPUT,
                        "%s: colloid MD step %lld + %lld steps x %lld substeps passes the largest step %lld",
                        o->restart ? o->restart : scene->path, sim->colloids->md_step, nsteps,
                        (long long)scene->colloids.substeps, (long long)PL_RUN_MAX_STEP);
        goto done;
    }
    if (o->steps >= 0 && o->log) { /* the scene's own steps passed check; an override is the user's call */
        size_t off;
        const char *key;
        char why[400];
        if (pl_observe_span_problem(scene, last, &off, &key, why, sizeof why))
            fprintf(o->log, "peloid: warning: with --steps %lld, %s = %s\n", nsteps, key, why);
    }
    /* a restarted state must pass the fluid guard before anything is written */
    if (o->restart && pl_fluid_guard_check(sim, first, 1, err)) {
        char why[sizeof err->msg];
        snprintf(why, sizeof why, "%s", err->msg);
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: the checkpointed state fails the fluid guard: %.700s", o->restart,
                        why);
        goto done;
    }
    if ((rc = summary_head(sim, &summary, err))) goto done;
    char given[PATH_MAX];
    if (o->out_dir && strlen(o->out_dir) >= sizeof given) {
        rc = pl_err_set(err, PL_ERR_INPUT, "--out %.80s...: %zu characters; allowed: < %d", o->out_dir,
                        strlen(o->out_dir), PATH_MAX - 32);
        goto done;
    }
    if (o->out_dir) snprintf(given, sizeof given, "%s", o->out_dir);
    else snprintf(given, sizeof given, "out/%s", scene->run.name);
    int in_place = o->restart && restart_in_place(o->restart, given);
    if ((rc = pl_thermo_table_build(sim, &w.columns, err))) goto done; /* before anything is written */
    if ((rc = pl_outdir_prepare(given, o->force || in_place, scene->path, w.dir, sizeof w.dir, err))) goto done;
    if ((rc = pl_outdir_lock(w.dir, &lock_fd, err))) goto done;
    if (!in_place && (rc = pl_outdir_clean(w.dir, err))) goto done;
    if (in_place && (rc = pl_outdir_resume_check(w.dir, first, err))) goto done;
    pl_path_join(w.thermo_path, sizeof w.thermo_path, w.dir, pl_outputs[PL_OUT_THERMO].name);
    /* first: a thermo.tsv to continue in place with other columns is refused before anything is written */
    if ((rc = pl_thermo_open(&w.columns, w.thermo_path, in_place ? first : -1, &w.thermo, err))) goto done;
    if ((rc = write_scene_echo(&w, &sim->scene, err))) goto done;
    if ((rc = add_thermo(sim, &w, err))) goto done;
    wout.in_place = in_place;
    wout.first = first;
    if ((rc = pl_writers_open(sim, &wout, &ws, err))) goto done;
    FILE *log = o->log; /* the driver's stream; NULL: quiet */
    if (log) pl_mapping_warnings_print(scene, log); /* after every refusal: a refused run prints one line */
    const int cores = log ? pl_threads_cores() : 0;
    if (cores > 0 && sim->nthreads > cores)
        fprintf(log, "peloid: warning: %d OpenMP threads on %d cores (hwloc): the threads beyond the cores slow "
                     "the run down (its results do not depend on the count); --threads %d\n",
                sim->nthreads, cores, cores);
    if (log)
        fprintf(log, "peloid: %s: %zu fluid particles, %d thread(s), steps %lld..%lld -> %s/\n",
                scene->run.name, sim->fluid.n, sim->nthreads, first, last, w.dir);
    char cal[800] = "";
    if (log && scene->mapping.enabled) pl_mapping_calibration_line(&scene->mapping.map, cal, sizeof cal);
    if (cal[0]) fprintf(log, "peloid: %s\n", cal);
    const char *afresh;
    if (log && pl_sim_observers_resumed(sim, &afresh) == 0) fprintf(log, "peloid: %s\n", afresh);
    for (int m = 0; log && pl_modules[m]; ++m) /* what each module wants the user to know */
        if (pl_modules[m]->describe) pl_modules[m]->describe(sim, log);
    pl_progress_params_t pp = {.out = o->log, .terminal = o->progress, .interval_s = scene->output.progress_s,
                               .first = first, .last = last, .dt = scene->srd.dt,
                               .t0_s = scene->mapping.enabled ? scene->mapping.map.t0 : 0.0,
                               .fluid_n = (double)sim->fluid.n,
                               .md_per_step = colloid_md_moves(sim) ? (double)scene->colloids.substeps : 0.0};
    pg = pl_progress_create(&pp);
    wout.pg = pg;
    double t0 = omp_get_wtime(), c0 = process_cpu_seconds();
    rc = loop(sim, &w, &ws, pg, last, o->interrupt, err);
    double wall = omp_get_wtime() - t0, cpu = process_cpu_seconds() - c0;
    errno = 0;
    int thermo_bad = fflush(w.thermo) != 0 || fsync(fileno(w.thermo)) != 0;
    int thermo_errno = errno;
    thermo_bad |= fclose(w.thermo) != 0;
    w.thermo = NULL;
    if (rc) goto done; /* the last good checkpoint stays as it was */
    if (thermo_bad) {
        rc = pl_err_set(err, PL_ERR_IO, "%s: closing failed: %s", w.thermo_path,
                        strerror(thermo_errno ? thermo_errno : errno));
        goto done;
    }
    /* the writers' last writes: trajectory frame, checkpoint, fields */
    if ((rc = pl_writers_finish(sim, &ws, &wout, err))) goto done;
    for (int m = 0; pl_modules[m]; ++m) /* each module's outputs and measured values */
        if (pl_modules[m]->finish && (rc = pl_modules[m]->finish(sim, w.dir, summary, err))) goto done;
    rc = write_summary(&w, summary, sim, first, wall, cpu, err);
    if (!rc) {
        list_outputs(pg, w.dir);
        if (sim->stop_requested && !w.interrupted)
            pl_progress_note(pg, "stopped at step %lld: %s", sim->step, sim->stop_reason);
        char why[600];
        for (int k = 0; pl_observe_unmeasured(sim, k, why, sizeof why); ++k) /* summary.json "not_measured" too */
            pl_progress_note(pg, "warning: %s", why);
        pl_progress_finish(pg, sim->step);
    }
    if (!rc && w.interrupted)
        rc = pl_err_set(err, PL_ERR_INTERRUPTED, "interrupted by signal %d at step %lld of %lld", w.interrupted,
                        sim->step, last);
done:
    if (o->end && sim) {
        o->end->step = sim->step;
        o->end->last = last;
        snprintf(o->end->dir, sizeof o->end->dir, "%s", w.dir);
    }
    pl_progress_free(pg);
    if (w.thermo) fclose(w.thermo);
    json_decref(summary);
    pl_writers_close(&ws);      /* a trajectory left open keeps its frames */
    pl_sim_free(sim);
    if (lock_fd >= 0) close(lock_fd); /* the directory is free when every output is closed */
    return rc;
}
