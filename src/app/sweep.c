/* `peloid sweep`: the points of a study (src/app/study.c) as independent
 * `peloid run` processes, a process pool of `jobs` processes with `threads`
 * OpenMP threads each, each process bound to cores of its own (pl_sweep_plan),
 * resumable, or as a Slurm job array.
 *
 * OUT/points.json        the study: keys, plot, each point's id and values
 * OUT/scenes/ID.cfg      point ID's scene (base + its values)
 * OUT/ID/                its run (summary.json, thermo.tsv, ...)
 * OUT/logs/ID.log        its stdout + stderr
 * OUT/status/ID.tsv      "exit_code<TAB>last line of its stderr"
 * OUT/sweep.{tsv,json,png}  the table and plot (tools/sweep_collect.py)
 * OUT/plan.json          jobs x threads, why, each job's CPU set (sweep_plan.c)
 *
 * A point is finished when OUT/ID/summary.json is complete JSON with its
 * last_step (run.c writes it atomically at the end) and OUT/scenes/ID.cfg is
 * the scene the study gives it now; a finished point is not run again.  A
 * point whose summary says "interrupted" (a signal stopped it after a step
 * and it wrote its checkpoint there) resumes in place from OUT/ID/checkpoint.h5
 * for the steps it had left.  A failed point keeps its exit code and message
 * and the others go on.  Processes, not threads: a point that trips a guard
 * or runs out of memory takes only itself down.
 *
 * Signals (the driver's flag, pl_sweep_opts_t.interrupt): each point runs in
 * its own process group, so a terminal's ^C reaches the sweep alone; the
 * sweep forwards a first signal to every running point's group (each ends
 * after its step with a checkpoint, exit 128 + signal), starts no new point,
 * waits for them and writes the table; at a second signal it kills the
 * points' groups (SIGKILL) and returns at once.  No point outlives the sweep. */
#include <errno.h>
#include <jansson.h>
#include <libconfig.h>
#include <sched.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "peloid/checkpoint.h"
#include "peloid/io.h"
#include "peloid/sweep.h"
#include "sweep_priv.h"

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int mkdir_p(const char *path, pl_err_t *err)
{
    char b[4096];
    snprintf(b, sizeof b, "%s", path);
    for (char *p = b + 1; ; ++p) {
        if (*p == '/' || !*p) {
            char c = *p;
            *p = '\0';
            if (mkdir(b, 0777) && errno != EEXIST)
                return pl_err_set(err, PL_ERR_IO, "%s: cannot create directory: %s", b, strerror(errno));
            if (!c) break;
            *p = c;
        }
    }
    return 0;
}

#define write_text pl_sweep_write_text
#define read_text pl_sweep_read_text

/* A finished point's summary: complete, and not of a run a signal ended
 * early (that point runs again). */
static int summary_complete(const char *path)
{
    json_t *j = json_load_file(path, 0, NULL);
    int ok = j && json_is_integer(json_object_get(j, "last_step")) && json_object_get(j, "wall_seconds") &&
             !json_is_true(json_object_get(j, "interrupted"));
    json_decref(j);
    return ok;
}

/* Last non-empty line of a file, control characters dropped. */
/* A point's summary says a signal ended its run early. */
static int summary_interrupted(const char *path)
{
    json_t *j = json_load_file(path, 0, NULL);
    int yes = json_is_true(json_object_get(j, "interrupted"));
    json_decref(j);
    return yes;
}

/* Steps a point a signal stopped has left, -1 when it runs from step 0.
 * Interrupted: its summary.json says so at last_step (where run.c wrote
 * checkpoint.h5) of the scene's steps.  Killed (a second signal): no
 * summary.json, and checkpoint.h5 at the step of its last write, of the
 * `steps` of its scene `text`. */
static long long steps_left(const char *sum, const char *ck, const char *text)
{
    struct stat sb;
    if (stat(ck, &sb)) return -1;
    long long left = -1, at, steps;
    json_t *j = json_load_file(sum, 0, NULL);
    if (j) {
        json_t *last = json_object_get(j, "last_step"), *st = json_object_get(json_object_get(j, "scene"), "steps");
        if (json_is_true(json_object_get(j, "interrupted")) && json_is_integer(last) && json_is_integer(st))
            left = json_integer_value(st) - json_integer_value(last);
        json_decref(j);
    } else if (stat(sum, &sb) && !pl_checkpoint_step(ck, &at)) {
        config_t c;
        config_init(&c);
        if (config_read_string(&c, text) == CONFIG_TRUE && config_lookup_int64(&c, "steps", &steps) == CONFIG_TRUE)
            left = steps - at;
        config_destroy(&c);
    }
    return left < 0 ? -1 : left;
}

/* The driver's signal flag: 0, S (a first signal) or -S (a second). */
static int signal_seen(const pl_sweep_opts_t *o)
{
    return o->interrupt ? (int)*o->interrupt : 0;
}

static void last_line(const char *path, char *buf, size_t n)
{
    char *s = read_text(path);
    buf[0] = '\0';
    if (!s) return;
    size_t len = strlen(s);
    while (len && (s[len - 1] == '\n' || s[len - 1] == '\r' || s[len - 1] == ' ')) s[--len] = '\0';
    char *l = strrchr(s, '\n');
    l = l ? l + 1 : s;
    char *r = strrchr(l, '\r'); /* a progress line redrawn with \r: its last state */
    if (r) l = r + 1;
    size_t k = 0;
    for (; *l && k + 1 < n; ++l)
        if ((unsigned char)*l >= 0x20 && *l != 0x7f && *l != '\t') buf[k++] = *l;
    buf[k] = '\0';
    free(s);
}

static void point_path(const sweep_t *s, int k, const char *fmt, char *buf, size_t n)
{
    char id[32];
    pl_study_point_id(s->st, k, id, sizeof id);
    char rel[128];
    snprintf(rel, sizeof rel, fmt, id);
    snprintf(buf, n, "%s/%s", s->out, rel);
}

/* Writes point k's scene; *done: its run is finished (same scene); *left:
 * the steps it has left after an interruption (same scene), else -1. */
static int prepare_point(const sweep_t *s, int k, int *done, long long *left, pl_err_t *err)
{
    char id[32], name[192], path[4096], sum[4096], ck[4096];
    pl_study_point_id(s->st, k, id, sizeof id);
    snprintf(name, sizeof name, "%s-%s", pl_study_name(s->st), id);
    char *text = NULL;
    int rc = pl_study_point_scene(s->st, k, name, &text, err);
    if (rc) return rc;
    point_path(s, k, "scenes/%s.cfg", path, sizeof path);
    point_path(s, k, "%s/summary.json", sum, sizeof sum);
    point_path(s, k, "%s/checkpoint.h5", ck, sizeof ck);
    char *old = read_text(path);
    int same = old && !strcmp(old, text);
    free(old);
    *done = same && summary_complete(sum);
    *left = same && !*done ? steps_left(sum, ck, text) : -1;
    if (!same) rc = write_text(path, text, err);
    if (!rc) { /* the files it reads beside it */
        char dir[4096];
        point_path(s, k, "scenes", dir, sizeof dir);
        rc = pl_study_point_files(s->st, dir, err);
    }
    free(text);
    if (!rc && *done) { /* its summary is the proof: a failure recorded before (its status) is past */
        point_path(s, k, "status/%s.tsv", path, sizeof path);
        char *st = read_text(path);
        if (!st || strncmp(st, "0\t", 2)) rc = write_text(path, "0\tok\n", err);
        free(st);
    }
    return rc;
}

static void record(const sweep_t *s, int k, int code, const char *msg)
{
    char path[4096];
    pl_err_t e;
    point_path(s, k, "status/%s.tsv", path, sizeof path);
    char line[1200];
    snprintf(line, sizeof line, "%d\t%s\n", code, msg);
    write_text(path, line, &e);
}

/* Starts point k in a process group of its own (the sweep forwards signals
 * to it); left >= 0: resumes it in place from its checkpoint for `left`
 * steps (its log is appended to). */
static pid_t start_point(const sweep_t *s, int k, int threads, long long left, const cpu_set_t *cpus)
{
    char scene[4096], dir[4096], log[4096], th[16], ck[4096], ls[32];
    point_path(s, k, "scenes/%s.cfg", scene, sizeof scene);
    point_path(s, k, "%s", dir, sizeof dir);
    point_path(s, k, "logs/%s.log", log, sizeof log);
    point_path(s, k, "%s/checkpoint.h5", ck, sizeof ck);
    snprintf(th, sizeof th, "%d", threads);
    snprintf(ls, sizeof ls, "%lld", left);
    /* a summary of an earlier run of this point (other values, or the
     * interruption the resume continues) must not survive a failure */
    char sum[4096];
    point_path(s, k, "%s/summary.json", sum, sizeof sum);
    unlink(sum);
    fflush(NULL);
    pid_t pid = fork();
    if (pid > 0) setpgid(pid, pid); /* as the child does: whichever runs first, the group exists before a kill */
    if (pid != 0) return pid;
    setpgid(0, 0);
    /* the sweep's handlers end at exec: a signal before `run` installs its
     * own takes the default action, and one the inherited handler noted
     * before the reset ends the point here; an ignored signal stays so */
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    for (size_t j = 0; j < sizeof sigs / sizeof *sigs; ++j) {
        struct sigaction old;
        if (!sigaction(sigs[j], NULL, &old) && old.sa_handler != SIG_IGN) signal(sigs[j], SIG_DFL);
    }
    if (signal_seen(s->o)) _exit(128 + abs(signal_seen(s->o)));
    if (cpus) sched_setaffinity(0, sizeof *cpus, cpus); /* its run's threads spread inside (thread_bind.c) */
    FILE *f = freopen(log, left >= 0 ? "a" : "w", stderr);
    if (!f || dup2(fileno(stderr), 1) < 0) _exit(PL_ERR_IO);
    const char *av[16] = {s->o->self, "run", scene, "--out", dir, "--threads", th};
    int n = 7;
    if (left >= 0) {
        av[n++] = "--restart";
        av[n++] = ck;
        av[n++] = "--steps";
        av[n++] = ls;
    } else av[n++] = "--force";
    if (s->o->calibrate) {
        av[n++] = "--calibrate";
        av[n++] = s->o->calibrate;
    }
    av[n] = NULL;
    execv(s->o->self, (char *const *)av);
    fprintf(stderr, "peloid sweep: cannot run %s: %s\n", s->o->self, strerror(errno));
    _exit(PL_ERR_IO);
}

static void fmt_time(double t, char *b, size_t n)
{
    long long s = (long long)(t + 0.5);
    if (s >= 3600) snprintf(b, n, "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
    else snprintf(b, n, "%lld:%02lld", s / 60, s % 60);
}

static void progress(const sweep_t *s, int done, int failed, int running, int skipped, int todo, double t0,
                     int last)
{
    char el[32], eta[32] = "?";
    double t = now_s() - t0;
    fmt_time(t, el, sizeof el);
    int finished = done + failed - skipped; /* points this sweep ran to the end */
    if (finished > 0) fmt_time(t / finished * (todo - finished), eta, sizeof eta);
    if (todo == finished) snprintf(eta, sizeof eta, "0:00");
    fprintf(s->o->log, "%speloid sweep %s: %d/%d done (%d skipped), %d failed, %d running, %s elapsed, ETA %s%s",
            s->o->progress_tty ? "\r" : "", pl_study_name(s->st), done, s->total, skipped, failed, running, el, eta,
            s->o->progress_tty && !last ? "   " : "\n");
    fflush(s->o->log);
}

/* What run_points ended with: points failed, interrupted by the forwarded
 * signal, not started; the signal (0: none; -S: a second one killed them). */
typedef struct {
    int failed, interrupted, pending, sig;
} tally_t;

/* A second signal: every running point's group is killed (SIGKILL), reaped
 * and recorded. */
static void kill_points(const sweep_t *s, int first, int n, int *state, const pid_t *pids, tally_t *t)
{
    for (int i = 0; i < n; ++i)
        if (state[i] == 1) kill(-pids[i], SIGKILL);
    for (int i = 0; i < n; ++i) {
        if (state[i] != 1) continue;
        int status;
        while (waitpid(pids[i], &status, 0) < 0 && errno == EINTR) {}
        record(s, first + i, 128 + SIGKILL, "killed: a second signal to the sweep");
        state[i] = 3;
        ++t->failed;
    }
}

/* Runs points [first, last) that are not finished, until done or signalled
 * (s->o->interrupt); *t: how it ended. */
static int run_points(sweep_t *s, int first, int last, tally_t *t, pl_err_t *err)
{
    int n = last - first, todo = 0;
    s->total = n;
    int *state = calloc((size_t)n, sizeof *state); /* 0 todo, 1 running, 2 done, 3 failed, 4 interrupted */
    pid_t *pids = calloc((size_t)n, sizeof *pids);
    long long *left = calloc((size_t)n, sizeof *left);
    if (!state || !pids || !left) {
        free(state);
        free(pids);
        free(left);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory starting the sweep");
    }
    int rc = 0, skipped = 0, resumed = 0;
    for (int i = 0; !rc && i < n; ++i) {
        int done;
        rc = prepare_point(s, first + i, &done, &left[i], err);
        if (!rc && done) {
            state[i] = 2;
            ++skipped;
        } else ++todo;
        if (!rc && left[i] >= 0) ++resumed;
    }
    sweep_plan_t pl = {0};
    if (!rc) rc = pl_sweep_plan_points(s, first, n, state, todo, &pl, err);
    const int jobs = pl.plan ? pl.plan->jobs : 1, threads = pl.plan ? pl.plan->threads : 1;
    char *busy = calloc((size_t)jobs, 1);
    int *slot = calloc((size_t)n, sizeof *slot);
    if (!rc && (!busy || !slot)) rc = pl_err_set(err, PL_ERR_NOMEM, "out of memory starting the sweep");
    if (!rc)
        fprintf(s->o->log, "peloid sweep %s: %d point(s), %d finished before, %d to run (%d from its checkpoint): "
                "%d job(s) x %d thread(s) on %d core(s): %s -> %s/\n", pl_study_name(s->st), n, skipped, todo,
                resumed, jobs, threads, pl.machine.cores, pl.plan->why, s->out);
    double t0 = now_s(), last_draw = 0;
    int running = 0, done = skipped, failed = 0, next = 0, draw = 0;
    *t = (tally_t){0, 0, 0, 0};
    while (!rc) {
        int seen = signal_seen(s->o);
        if (seen < 0) { /* a second signal: nothing waits any more */
            kill_points(s, first, n, state, pids, t);
            t->sig = seen;
            break;
        }
        if (seen > 0 && !t->sig) { /* a first: each running point ends after its step */
            t->sig = seen;
            for (int i = 0; i < n; ++i)
                if (state[i] == 1) kill(-pids[i], seen);
        }
        while (!t->sig && running < jobs && next < n) {
            if (state[next] == 0) {
                int j = 0;
                while (j < jobs - 1 && busy[j]) ++j;
                pids[next] = start_point(s, first + next, threads, left[next], pl.sets ? &pl.sets[j] : NULL);
                if (pids[next] < 0) {
                    rc = pl_err_set(err, PL_ERR_IO, "cannot start a point: fork: %s", strerror(errno));
                    break;
                }
                state[next] = 1;
                busy[j] = 1;
                slot[next] = j;
                ++running;
            }
            ++next;
        }
        if (draw && !rc) { /* a point ended: the line after its successor started */
            progress(s, done, failed, running, skipped, todo, t0, running == 0 && next >= n);
            last_draw = now_s();
            draw = 0;
        }
        if (rc || (running == 0 && (next >= n || t->sig))) break;
        int status;
        /* polled, not blocking: a signal is seen within 50 ms whenever it comes */
        pid_t pid = waitpid(-1, &status, WNOHANG);
        if (pid == 0) {
            if (s->o->progress_tty && now_s() - last_draw >= 1.0) { /* a terminal: redraw every second */
                progress(s, done, failed, running, skipped, todo, t0, 0);
                last_draw = now_s();
            }
            usleep(50000);
            continue;
        }
        if (pid < 0) {
            if (errno == EINTR) continue;
            rc = pl_err_set(err, PL_ERR_INTERNAL, "waitpid: %s", strerror(errno));
            break;
        }
        int i = 0;
        while (i < n && !(state[i] == 1 && pids[i] == pid)) ++i;
        if (i == n) continue;
        --running;
        busy[slot[i]] = 0;
        int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
        char log[4096], msg[1024], sum[4096];
        point_path(s, first + i, "logs/%s.log", log, sizeof log);
        point_path(s, first + i, "%s/summary.json", sum, sizeof sum);
        if (code == 0 && !summary_complete(sum)) code = PL_ERR_IO; /* exit 0 without a summary: not finished */
        last_line(log, msg, sizeof msg);
        if (WIFSIGNALED(status)) snprintf(msg, sizeof msg, "killed by signal %d", WTERMSIG(status));
        record(s, first + i, code, code ? msg : "ok");
        int stopped = code && (summary_interrupted(sum) || (t->sig && code == 128 + t->sig));
        state[i] = code ? (stopped ? 4 : 3) : 2;
        if (stopped) ++t->interrupted;
        else if (code) ++failed;
        else ++done;
        draw = 1;
    }
    if (!rc && todo == 0) progress(s, done, failed, running, skipped, todo, t0, 1);
    for (int i = 0; i < n; ++i) t->pending += state[i] == 0;
    t->failed += failed;
    free(state);
    free(pids);
    free(left);
    free(busy);
    free(slot);
    pl_sweep_plan_free(&pl);
    return rc;
}

static int collect(const sweep_t *s, pl_err_t *err)
{
    char script[4096];
    snprintf(script, sizeof script, "%s/sweep_collect.py", s->o->tools);
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        char self[4096]; /* the keys' units for the plot's axis: `peloid keys` of this binary */
        ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
        if (n > 0) {
            self[n] = '\0';
            setenv("PELOID_BIN", self, 1);
        }
        execl("/usr/bin/python3", "python3", script, s->out, (char *)NULL);
        fprintf(stderr, "peloid: error: sweep: cannot run /usr/bin/python3 %s: %s\n", script, strerror(errno));
        _exit(PL_ERR_IO);
    }
    int status = 0;
    pid_t got = pid;
    while (pid > 0 && (got = waitpid(pid, &status, WNOHANG)) == 0) {
        if (signal_seen(s->o) < 0) { /* a second signal: the table is left as it is */
            kill(pid, SIGKILL);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
            return pl_err_set(err, PL_ERR_INTERRUPTED, "sweep %s: a second signal: stopped writing %s/sweep.tsv",
                              pl_study_name(s->st), s->out);
        }
        usleep(50000);
    }
    if (pid < 0 || got < 0 || !WIFEXITED(status) || WEXITSTATUS(status))
        return pl_err_set(err, PL_ERR_IO, "sweep: collecting %s with %s failed (its message is above)", s->out, script);
    return 0;
}

static int sweep_points(sweep_t *sp, pl_err_t *err);

int pl_sweep(pl_study_t *st, const pl_sweep_opts_t *o, pl_err_t *err)
{
    sweep_t s = {.st = st, .o = o, .n = pl_study_npoints(st)};
    snprintf(s.out, sizeof s.out, "%s", o->out_dir ? o->out_dir : pl_study_out(st));
    if (o->point >= s.n)
        return pl_err_set(err, PL_ERR_INPUT, "sweep: --point %lld: study %s has %d point(s); allowed: 0..%d",
                          o->point, pl_study_path(st), s.n, s.n - 1);
    struct stat sb;
    char marker[4096];
    snprintf(marker, sizeof marker, "%s/points.json", s.out);
    if (o->collect_only && (stat(marker, &sb) || !S_ISREG(sb.st_mode))) /* one line, before the script runs */
        return pl_err_set(err, PL_ERR_INPUT, "sweep --collect: %s has no points.json (%s), nothing to collect; "
                          "allowed: the output folder of a sweep of %s (run `peloid sweep %s` first, or give it "
                          "with --out DIR)", s.out, stat(s.out, &sb) ? "no such folder" : !S_ISDIR(sb.st_mode)
                          ? "not a folder" : "not a sweep's output", pl_study_path(st), pl_study_path(st));
    if (o->collect_only) return collect(&s, err);
    if (!stat(s.out, &sb) && stat(marker, &sb))
        return pl_err_set(err, PL_ERR_INPUT, "sweep: %s exists and is not a sweep's output (no points.json); "
                          "allowed: a new directory or a previous output of a sweep (--out DIR)", s.out);
    s.cost = calloc((size_t)s.n, sizeof *s.cost);
    if (!s.cost) return pl_err_set(err, PL_ERR_NOMEM, "out of memory checking the study's points");
    int rc = pl_study_check_points(st, s.out, s.cost, err); /* every point, before anything is written */
    if (!rc) rc = sweep_points(&s, err);
    free(s.cost);
    return rc;
}

/* pl_sweep after the check: the directories, points.json, the pool (or the
 * Slurm scripts) and the table. */
static int sweep_points(sweep_t *sp, pl_err_t *err)
{
    sweep_t s = *sp;
    const pl_sweep_opts_t *o = s.o;
    pl_study_t *st = s.st;
    int rc = 0;
    static const char *const sub[] = {"", "/scenes", "/logs", "/status"};
    for (int i = 0; !rc && i < 4; ++i) {
        char d[4096];
        snprintf(d, sizeof d, "%s%s", s.out, sub[i]);
        rc = mkdir_p(d, err);
    }
    if (!rc) rc = pl_sweep_write_points(&s, err);
    if (!rc && o->slurm) {
        for (int k = 0; !rc && k < s.n; ++k) {
            int done;
            long long left;
            rc = prepare_point(&s, k, &done, &left, err);
        }
        return rc ? rc : pl_sweep_write_slurm(&s, err);
    }
    tally_t t = {0, 0, 0, 0};
    if (!rc && o->point >= 0) rc = run_points(&s, (int)o->point, (int)o->point + 1, &t, err);
    else if (!rc) rc = run_points(&s, 0, s.n, &t, err);
    if (!rc && o->point < 0 && t.sig >= 0) rc = collect(&s, err); /* a second signal: at once, no table */
    if (rc) return rc;
    if (t.sig)
        return pl_err_set(err, PL_ERR_INTERRUPTED, "sweep %s: %s signal %d: %d point(s) stopped at a checkpoint, "
                          "%d failed or killed, %d not started%s; resume with: peloid sweep %s --out %s",
                          pl_study_name(st), t.sig > 0 ? "interrupted by" : "killed by a second", t.sig > 0 ? t.sig : -t.sig,
                          t.interrupted, t.failed, t.pending, t.sig > 0 && o->point < 0 ? " (table: sweep.tsv)" : "",
                          pl_study_path(st), s.out);
    if (t.failed || t.interrupted) /* a point a signal to it alone stopped is not finished either */
        return pl_err_set(err, 1, "sweep %s: %d point(s) failed, %d interrupted (the next sweep resumes them), the "
                          "others ran (exit code and last message of each: %s/status/, %s/sweep.tsv)",
                          pl_study_name(st), t.failed, t.interrupted, s.out, s.out);
    return 0;
}
