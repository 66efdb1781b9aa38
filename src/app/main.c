/* peloid command-line driver: parse arguments, load the scene, dispatch.
 * Exit codes: 0 ok, 2 bad input (nothing written), 3 stability guard,
 * 4 I/O failure, 5 out of memory, 6 internal limit, 128 + N a run ended
 * by signal N (SIGHUP 129, SIGINT 130, SIGTERM 143) with its outputs
 * complete. */
#include <errno.h>
#include <gsl/gsl_errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "peloid/h5.h"
#include "peloid_build.h" /* PL_TOOLS_DIR, PL_CALIBRATION_DIR (generated) */
#include "peloid/run.h"
#include "peloid/scene.h"
#include "peloid/sweep.h"

static const char *const usage =
    "usage: peloid COMMAND [ARGS]\n"
    "\n"
    "commands:\n"
    "  run SCENE [--out DIR] [--steps N] [--threads N] [--restart CHECKPOINT]\n"
    "            [--restart-changed KEY[,KEY...]] [--force] [--strict] [--allow-include-anywhere]\n"
    "            [--calibrate never|auto|always|stored]\n"
    "        run a scene; writes DIR/{thermo.tsv, summary.json, checkpoint.h5, scene.cfg\n"
    "        [, fields.h5 + fields.xdmf] [, colloids.h5 [+ colloids.xyz]]}.  DIR\n"
    "        defaults to out/<scene name>; an existing DIR is\n"
    "        refused unless --force.  --steps N runs N steps (default: the scene's\n"
    "        steps); --restart continues from a checkpoint of the same scene: every\n"
    "        physics key (all but name, steps, output.*, colloids.trajectory_interval,\n"
    "        colloids.neighbor_skin and the colloid guard bounds) must equal the\n"
    "        checkpoint's, unless named\n"
    "        in --restart-changed (e.g. --restart-changed srd.dt,thermostat.type).\n"
    "        --restart DIR/checkpoint.h5 --out DIR resumes in place: thermo.tsv and the\n"
    "        trajectories keep what precedes the checkpoint's step and continue after it.\n"
    "        --force first removes the files an earlier run wrote into DIR; a DIR another\n"
    "        run is writing (lock DIR/.peloid.lock) is refused even with --force.\n"
    "        --threads N sets the OpenMP thread count (results do not depend on it;\n"
    "        default OMP_NUM_THREADS, else the CPUs; at most 4096; a warning when it\n"
    "        exceeds the cores).\n"
    "        A scene's @include files are resolved relative to the including file and\n"
    "        must lie in the scene's directory tree unless --allow-include-anywhere.\n"
    "        --calibrate (also for check and params): where a physical scene's colloid D\n"
    "        (coupling I, II, potential) comes from: auto (default) the shipped calibration\n"
    "        or the cache, else a calibration run (its estimated duration and progress on\n"
    "        stderr); always a calibration run, stored in the cache; never the coupling's\n"
    "        theory with its stated relative error, marked in params, the run's log and\n"
    "        summary.json \"calibration\" (t0 and every SI time then carry that error);\n"
    "        stored the shipped calibration or the cache, else the theory (never a run:\n"
    "        check's default)\n"
    "  run SCENE --replicas N [--out DIR] [--threads T] [--calibrate MODE]\n"
    "        N runs of the scene with seeds seed + 0 .. N - 1 (DIR/p000r0 ...), run and\n"
    "        resumed as a sweep runs a study; DIR/sweep.tsv, report.md and sweep.png give each\n"
    "        observable pooled: the mean +- the SE between the replicas, beside the\n"
    "        within-run SE and a flag where they disagree\n"
    "  check SCENE [--strict] [--allow-include-anywhere] [--calibrate MODE]\n"
    "        validate a scene without running it, in seconds (--calibrate stored by\n"
    "        default: a suspension no calibration is stored for is checked with the\n"
    "        coupling's theory and its stated error); a physical scene's audit warnings\n"
    "        (a dimensionless number out of the papers' range, an implausible input\n"
    "        with its likely unit mistake) are printed, and refused with --strict\n"
    "        (also for run and params)\n"
    "  params SCENE [--json] [--strict] [--allow-include-anywhere] [--calibrate MODE]\n"
    "        print the derived SRD parameters: lambda, nu_kin, nu_col, nu, eta, D_f,\n"
    "        Sc, tau_f (Padding & Louis 2006, Eqs. 4, 6, 9-15)\n"
    "  plan SCENE --target REL [--calibrate MODE] [--allow-include-anywhere]\n"
    "        a guide to the model for a physical scene's suspension: each coupling at its\n"
    "        default resolution with its hydrodynamic radius R_h/R and calibration cost, the\n"
    "        box against Hasimoto's correction, the MD settings, the run length, replicas and\n"
    "        CPU time for a relative SE REL of the colloid D (0.05 or 5%; and of the settling\n"
    "        velocity under gravity), and the recommended coupling\n"
    "  report OUTDIR    write OUTDIR/report.md with a plot of every observable the run\n"
    "                   measured (g(r), MSD and D, clusters, thermo) and the error-against-\n"
    "                   time table (tools/report.py with /usr/bin/python3; PELOID_TOOLS\n"
    "                   names another tools directory)\n"
    "  sweep STUDY [--out DIR] [--jobs J] [--threads T] [--point K] [--slurm] [--collect]\n"
    "              [--calibrate MODE]\n"
    "        run a parameter study: every point (the study's base scene with its keys\n"
    "        set) as its own `peloid run` in DIR/ID (default: the study's out), J\n"
    "        processes of T threads, each bound to cores of its own (default, C\n"
    "        cores: J = min(points, C); with fewer points than cores T = C / J, at\n"
    "        most what the points' size uses; J shrinks to fit the memory; the\n"
    "        choice and why: one line and DIR/plan.json);\n"
    "        finished points are skipped; DIR/sweep.{tsv,json,png} collect them.\n"
    "        --point K runs point K only; --slurm writes a Slurm job array\n"
    "        (DIR/sweep.sbatch, collect.sbatch, submit.sh) and runs nothing;\n"
    "        --collect only rebuilds the table and plot; --calibrate MODE is passed to\n"
    "        every point's run.  Exit 1: some points failed.\n"
    "        A signal (SIGINT/SIGTERM/SIGHUP) is forwarded to the running points (each\n"
    "        in its own process group), which stop after their step with a checkpoint;\n"
    "        the table is written, exit 128 + signal; a second signal kills them at\n"
    "        once.  The next sweep resumes an interrupted point from its checkpoint\n"
    "  keys             print the scene-file reference (every key) as Markdown\n"
    "  --help           this text\n"
    "\n"
    "exit codes: 0 ok, 2 bad input (nothing written), 3 stability guard tripped,\n"
    "            4 I/O error, 5 out of memory, 6 internal limit,\n"
    "            129 / 130 / 143 run interrupted by SIGHUP / SIGINT / SIGTERM: the step in\n"
    "            progress is finished, then the checkpoint, summary.json (\"interrupted\":\n"
    "            true) and every output are written as at a normal end; a second signal\n"
    "            exits at once\n";

/* One line: control characters a message quotes from the input (a newline
 * in a scene string) are shown escaped. */
static int fail(const pl_err_t *err)
{
    fputs("peloid: error: ", stderr);
    for (const unsigned char *c = (const unsigned char *)err->msg; *c; ++c) {
        if (*c >= 0x20 && *c != 0x7f) fputc(*c, stderr);
        else if (*c == '\n') fputs("\\n", stderr);
        else fprintf(stderr, "\\x%02x", *c);
    }
    fputc('\n', stderr);
    return err->code ? err->code : 1;
}

static int bad_usage(const char *what)
{
    fprintf(stderr, "peloid: error: %s\n(see peloid --help)\n", what);
    return PL_ERR_INPUT;
}

/* A decimal integer in [lo, hi]; anything else (empty, trailing text, out of
 * the range of long long) is refused. */
static int parse_ll(const char *s, long long lo, long long hi, long long *out)
{
    char *end;
    errno = 0;
    long long v = strtoll(s, &end, 10);
    if (*s == '\0' || *end != '\0' || errno == ERANGE || v < lo || v > hi) return -1;
    *out = v;
    return 0;
}

/* --calibrate VALUE (NULL: missing) into *mode; else one line naming the
 * option, the value and the allowed ones, and exit 2. */
static int calibrate_opt(const char *v, int *mode)
{
    if (v && !pl_calibrate_mode_parse(v, mode)) return 0;
    fprintf(stderr, "peloid: error: --calibrate %.100s: allowed: never, auto, always, stored\n", v ? v : "(no value)");
    return PL_ERR_INPUT;
}

/* The signal that asked the run to stop (0: none).  The one mutable
 * file-scope variable: a signal handler can reach the run only through a
 * variable of static storage, and only a volatile sig_atomic_t may be
 * written there (C11 7.14.1.1).  The run polls it between steps, the sweep
 * between waits for its points. */
static volatile sig_atomic_t interrupt_signal;

/* First signal: note it, the run ends after the present step.  Second: exit
 * at once (_exit is async-signal-safe; the outputs of the step loop stay as
 * they are, the last checkpoint included). */
static void on_signal(int sig)
{
    if (interrupt_signal) {
        static const char msg[] = "peloid: second signal: exiting at once\n";
        ssize_t ignored = write(2, msg, sizeof msg - 1);
        (void)ignored;
        _exit(128 + sig);
    }
    interrupt_signal = sig;
}

/* `peloid sweep`: a first signal is noted (S), a second turns the flag
 * negative (-S, the first's number kept for the exit code); the sweep polls
 * the flag, forwards the first to its points and kills them at the second
 * (src/app/sweep.c), so this handler cannot exit itself. */
static void on_sweep_signal(int sig)
{
    interrupt_signal = interrupt_signal > 0 ? -interrupt_signal : interrupt_signal < 0 ? interrupt_signal : sig;
}

/* SIGINT, SIGTERM, SIGHUP end a run or sweep cleanly (`handler`), unless the
 * signal is ignored on entry (nohup, a background job of a shell without job
 * control): then it stays ignored. */
static void catch_signals(void (*handler)(int))
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = handler;
    sa.sa_flags = SA_RESTART;
    sigemptyset(&sa.sa_mask);
    for (size_t k = 0; k < sizeof sigs / sizeof *sigs; ++k) {
        struct sigaction old;
        if (sigaction(sigs[k], NULL, &old) == 0 && old.sa_handler != SIG_IGN) sigaction(sigs[k], &sa, NULL);
    }
}

static const char *signal_name(int sig)
{
    return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : sig == SIGHUP ? "SIGHUP" : "a signal";
}

/* One line: where the interrupted run stopped and the command that continues
 * it in place to the step it was to reach. */
static int interrupted(const char *scene_path, unsigned flags, const pl_run_end_t *end)
{
    int sig = (int)interrupt_signal;
    fprintf(stderr, "peloid: interrupted by %s at step %lld of %lld; resume with: peloid run %s --restart "
                    "%s/checkpoint.h5 --out %s --steps %lld%s\n",
            signal_name(sig), end->step, end->last, scene_path, end->dir, end->dir, end->last - end->step,
            flags & PL_SCENE_INCLUDE_ANYWHERE ? " --allow-include-anywhere" : "");
    return 128 + sig;
}

static int sweep_study(pl_study_t *st, pl_sweep_opts_t *o, pl_err_t *err);

/* `peloid run SCENE --replicas N`: the study of the scene's N seeds
 * (pl_study_of_scene) run and pooled as `peloid sweep` runs a study. */
static int run_replicas(const char *scene, int n, const char *out_dir, int threads, int calibrate)
{
    pl_sweep_opts_t o = {.point = -1, .progress_tty = isatty(2), .log = stderr, .interrupt = &interrupt_signal,
                         .out_dir = out_dir, .threads = threads, .calibrate = pl_calibrate_mode_name(calibrate)};
    pl_study_t *st = NULL;
    pl_err_t err = {0, ""};
    int rc = pl_study_of_scene(scene, n, out_dir, &st, &err);
    if (!rc) rc = sweep_study(st, &o, &err);
    char out[1024];
    snprintf(out, sizeof out, "%s", st ? pl_study_out(st) : "");
    pl_study_free(st);
    if (rc == PL_ERR_INTERRUPTED) {
        int sig = interrupt_signal < 0 ? -(int)interrupt_signal : (int)interrupt_signal;
        fprintf(stderr, "peloid: run --replicas %d interrupted (%s); resume with: peloid run %s --replicas %d "
                        "--out %s\n", n, signal_name(sig), scene, n, out_dir ? out_dir : out);
        return 128 + sig;
    }
    return rc ? fail(&err) : 0;
}

static int cmd_run(int argc, char **argv)
{
    pl_run_end_t end = {0, 0, ""};
    pl_run_opts_t o = {.out_dir = NULL, .steps = -1, .threads = 0, .restart = NULL, .force = 0,
                       .progress = isatty(2), .log = stderr, .restart_changed = NULL,
                       .interrupt = &interrupt_signal, .end = &end};
    unsigned flags = 0;
    int strict = 0, rc, replicas = 0, other = 0; /* other: an option --replicas cannot take */
    const char *scene_path = NULL;
    char msg[256];
    pl_calibrate_opts_t co = {.mode = PL_CALIBRATE_AUTO, .log = stderr, .terminal = o.progress};
    for (int i = 0; i < argc; ++i) {
        const char *a = argv[i];
        int has = i + 1 < argc;
        long long v;
        other |= !strcmp(a, "--force") || !strcmp(a, "--restart") || !strcmp(a, "--restart-changed") ||
                 !strcmp(a, "--steps") || !strcmp(a, "--strict") || !strcmp(a, "--allow-include-anywhere");
        if (!strcmp(a, "--force")) o.force = 1;
        else if (!strcmp(a, "--replicas") && has) {
            if (parse_ll(argv[++i], 2, PL_STUDY_MAX_POINTS, &v)) {
                snprintf(msg, sizeof msg, "run --replicas %.100s: expected an integer in 2..%d (the scene's seed "
                         "+ 0 .. N - 1, pooled)", argv[i], PL_STUDY_MAX_POINTS);
                return bad_usage(msg);
            }
            replicas = (int)v;
        } else if (!strcmp(a, "--calibrate")) {
            if ((rc = calibrate_opt(has ? argv[++i] : NULL, &co.mode))) return rc;
        }
        else if (!strcmp(a, "--strict")) strict = 1;
        else if (!strcmp(a, "--allow-include-anywhere")) flags |= PL_SCENE_INCLUDE_ANYWHERE;
        else if (!strcmp(a, "--out") && has) o.out_dir = argv[++i];
        else if (!strcmp(a, "--restart") && has) o.restart = argv[++i];
        else if (!strcmp(a, "--restart-changed") && has) o.restart_changed = argv[++i];
        else if (!strcmp(a, "--steps") && has) {
            if (parse_ll(argv[++i], 0, PL_STEPS_MAX, &o.steps)) {
                snprintf(msg, sizeof msg, "--steps %.100s: expected an integer in 0..%lld", argv[i],
                         (long long)PL_STEPS_MAX);
                return bad_usage(msg);
            }
        } else if (!strcmp(a, "--threads") && has) {
            if (parse_ll(argv[++i], 1, PL_THREADS_MAX, &v)) {
                snprintf(msg, sizeof msg, "--threads %.100s: expected an integer in 1..%d", argv[i], PL_THREADS_MAX);
                return bad_usage(msg);
            }
            o.threads = (int)v;
        } else if (a[0] == '-') {
            snprintf(msg, sizeof msg, "run: unknown or incomplete option '%.100s'", a);
            return bad_usage(msg);
        } else if (!scene_path) scene_path = a;
        else {
            snprintf(msg, sizeof msg, "run: unexpected argument '%.100s'", a);
            return bad_usage(msg);
        }
    }
    if (!scene_path) return bad_usage("run: missing SCENE");
    if (replicas && other)
        return bad_usage("run --replicas: allowed with --out, --threads and --calibrate only (a directory it wrote "
                         "is resumed: finished replicas are skipped)");
    if (replicas) return run_replicas(scene_path, replicas, o.out_dir, o.threads, co.mode);
    pl_err_t err = {0, ""};
    const int asked = o.threads;
    if (pl_threads_resolve(o.threads, &o.threads, &err)) return fail(&err);
    if (asked > o.threads) /* capped at OMP_THREAD_LIMIT: the same bits, fewer threads */
        fprintf(stderr, "peloid: note: --threads %d: OMP_THREAD_LIMIT=%s allows %d; running %d (results do not "
                        "depend on the count)\n",
                asked, getenv("OMP_THREAD_LIMIT") ? getenv("OMP_THREAD_LIMIT") : "?", o.threads, o.threads);
    pl_scene_t *scene = malloc(sizeof *scene);
    rc = scene ? pl_scene_load_coupling_true(scene_path, flags, PL_CALIBRATION_DIR, o.threads, &co, scene, &err)
               : PL_ERR_NOMEM;
    if (!rc) rc = pl_mapping_report_strict(scene, strict, &err); /* --strict: the audit's warnings refused */
    if (!rc) { /* the audit's warnings: pl_run prints them once nothing refuses the run */
        catch_signals(on_signal);
        rc = pl_run(scene, &o, &err);
    }
    free(scene);
    if (rc == PL_ERR_INTERRUPTED) return interrupted(scene_path, flags, &end);
    return rc ? fail(&err) : 0;
}

static int cmd_scene(int argc, char **argv, int params)
{
    const char *path = NULL;
    int json = 0, strict = 0, rc;
    unsigned flags = 0;
    /* check never waits for a calibration run (stored, else the theory with
     * its error); params measures one (auto), announced with its duration */
    pl_calibrate_opts_t co = {.mode = params ? PL_CALIBRATE_AUTO : PL_CALIBRATE_STORED, .log = stderr,
                              .terminal = isatty(2)};
    for (int i = 0; i < argc; ++i) {
        if (!strcmp(argv[i], "--allow-include-anywhere")) flags |= PL_SCENE_INCLUDE_ANYWHERE;
        else if (!strcmp(argv[i], "--calibrate")) {
            if ((rc = calibrate_opt(i + 1 < argc ? argv[++i] : NULL, &co.mode))) return rc;
        }
        else if (params && !strcmp(argv[i], "--json")) json = 1;
        else if (!strcmp(argv[i], "--strict")) strict = 1;
        else if (argv[i][0] != '-' && !path) path = argv[i];
        else {
            char msg[256];
            snprintf(msg, sizeof msg, "%s: unexpected argument '%.100s'", params ? "params" : "check", argv[i]);
            return bad_usage(msg);
        }
    }
    if (!path) return bad_usage("missing SCENE");
    pl_err_t err = {0, ""};
    int nthreads; /* of a calibration run: OMP_NUM_THREADS, checked first */
    if (pl_threads_resolve(0, &nthreads, &err)) return fail(&err);
    pl_scene_t *scene = malloc(sizeof *scene);
    if (!scene) return PL_ERR_NOMEM;
    rc = pl_scene_load_coupling_true(path, flags, PL_CALIBRATION_DIR, nthreads, &co, scene, &err);
    if (!rc && params && json) {
        rc = pl_params_write_json(scene, stdout, strict, &err);
    } else if (!rc && params) {
        pl_params_print(scene, stdout);
        /* A scene with physical{} adds the unit mapping report (mapping.h). */
        rc = pl_mapping_report(scene, stdout, 0, strict, &err);
    } else if (!rc) { /* check: run's validation, including the derived values summary.json gets */
        rc = pl_run_check(scene, &err);
        if (!rc) rc = pl_mapping_report_strict(scene, strict, &err);
        if (!rc) pl_mapping_warnings_print(scene, stderr);
        char cal[800] = ""; /* where the colloid D came from, and how sure it is */
        if (!rc && scene->mapping.enabled) pl_mapping_calibration_line(&scene->mapping.map, cal, sizeof cal);
        if (cal[0]) fprintf(stderr, "peloid: %s\n", cal);
        if (!rc) printf("%s: ok\n", path);
    }
    free(scene);
    return rc ? fail(&err) : 0;
}

/* --target REL: a relative SE as a fraction (0.05) or a percentage (5%),
 * in (0, 0.5]; -1 for anything else. */
static double parse_target(const char *v)
{
    char *end;
    errno = 0;
    double t = strtod(v, &end);
    if (end != v && *end == '%' && end[1] == '\0') t /= 100.0, ++end;
    return end == v || *end || errno || !(t > 0.0 && t <= 0.5) ? -1.0 : t;
}

/* `peloid plan SCENE --target REL`: a guide to the model for the scene's
 * suspension (src/app/advise.c). */
static int cmd_plan(int argc, char **argv)
{
    const char *path = NULL;
    double target = -2.0;
    unsigned flags = 0;
    int rc;
    pl_calibrate_opts_t co = {.mode = PL_CALIBRATE_AUTO, .log = stderr, .terminal = isatty(2)};
    char msg[256];
    for (int i = 0; i < argc; ++i) {
        if (!strcmp(argv[i], "--allow-include-anywhere")) flags |= PL_SCENE_INCLUDE_ANYWHERE;
        else if (!strcmp(argv[i], "--calibrate")) {
            if ((rc = calibrate_opt(i + 1 < argc ? argv[++i] : NULL, &co.mode))) return rc;
        } else if (!strcmp(argv[i], "--target")) {
            const char *v = i + 1 < argc ? argv[++i] : "(no value)";
            if ((target = parse_target(v)) < 0) {
                snprintf(msg, sizeof msg, "plan --target %.100s: expected the relative SE wanted of the colloid D, "
                         "a number in (0, 0.5] or a percentage in (0%%, 50%%] (e.g. 0.05 or 5%%)", v);
                return bad_usage(msg);
            }
        } else if (argv[i][0] != '-' && !path) path = argv[i];
        else {
            snprintf(msg, sizeof msg, "plan: unexpected argument '%.100s'", argv[i]);
            return bad_usage(msg);
        }
    }
    if (!path) return bad_usage("plan: missing SCENE");
    if (target < 0) return bad_usage("plan: missing --target REL (the relative SE wanted of the colloid D, e.g. 5%)");
    pl_err_t err = {0, ""};
    int nthreads;
    if (pl_threads_resolve(0, &nthreads, &err)) return fail(&err);
    pl_scene_t *scene = malloc(sizeof *scene);
    if (!scene) return PL_ERR_NOMEM;
    rc = pl_scene_load_coupling_true(path, flags, PL_CALIBRATION_DIR, nthreads, &co, scene, &err);
    if (!rc) rc = pl_plan_advise(scene, path, target, PL_CALIBRATION_DIR, stdout, &err);
    free(scene);
    return rc ? fail(&err) : 0;
}

/* `peloid report OUTDIR`: the plotting script of the tools directory. */
static int cmd_report(int argc, char **argv)
{
    if (argc != 1 || argv[0][0] == '-') return bad_usage("report: expected OUTDIR");
    const char *tools = getenv("PELOID_TOOLS");
    char script[4096];
    snprintf(script, sizeof script, "%s/report.py", tools && *tools ? tools : PL_TOOLS_DIR);
    execl("/usr/bin/python3", "python3", script, argv[0], (char *)NULL);
    fprintf(stderr, "peloid: error: report: cannot run /usr/bin/python3 %s: %s\n", script, strerror(errno));
    return PL_ERR_INPUT;
}

/* Runs a loaded study (o: the options but self and tools, filled here). */
static int sweep_study(pl_study_t *st, pl_sweep_opts_t *o, pl_err_t *err)
{
    char self[4096], tools[4096]; /* the options point here while pl_sweep runs */
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) return pl_err_set(err, PL_ERR_INPUT, "sweep: cannot find the peloid executable (/proc/self/exe)");
    self[n] = '\0';
    o->self = self;
    const char *t = getenv("PELOID_TOOLS");
    snprintf(tools, sizeof tools, "%s", t && *t ? t : PL_TOOLS_DIR);
    o->tools = tools;
    catch_signals(on_sweep_signal);
    return pl_sweep(st, o, err);
}

/* `peloid sweep STUDY`: the study's points as a process pool of `peloid run`
 * (src/app/sweep.c), or a Slurm job array. */
static int cmd_sweep(int argc, char **argv)
{
    pl_sweep_opts_t o = {.point = -1, .progress_tty = isatty(2), .log = stderr, .interrupt = &interrupt_signal};
    const char *path = NULL;
    char msg[256];
    for (int i = 0; i < argc; ++i) {
        const char *a = argv[i];
        int has = i + 1 < argc;
        long long v;
        int mode;
        if (!strcmp(a, "--slurm")) o.slurm = 1;
        else if (!strcmp(a, "--calibrate")) {
            int rc = calibrate_opt(has ? argv[++i] : NULL, &mode);
            if (rc) return rc;
            o.calibrate = pl_calibrate_mode_name(mode);
        }
        else if (!strcmp(a, "--collect")) o.collect_only = 1;
        else if (!strcmp(a, "--out") && has) o.out_dir = argv[++i];
        else if ((!strcmp(a, "--jobs") || !strcmp(a, "--threads") || !strcmp(a, "--point")) && has) {
            long long hi = !strcmp(a, "--point") ? PL_STUDY_MAX_POINTS - 1 : PL_THREADS_MAX;
            if (parse_ll(argv[++i], !strcmp(a, "--point") ? 0 : 1, hi, &v)) {
                snprintf(msg, sizeof msg, "sweep: %s %.100s: expected an integer in %d..%lld", a, argv[i],
                         !strcmp(a, "--point") ? 0 : 1, hi);
                return bad_usage(msg);
            }
            if (!strcmp(a, "--jobs")) o.jobs = (int)v;
            else if (!strcmp(a, "--threads")) o.threads = (int)v;
            else o.point = v;
        } else if (a[0] == '-' || path) {
            snprintf(msg, sizeof msg, "sweep: unexpected argument '%.100s'", a);
            return bad_usage(msg);
        } else path = a;
    }
    if (!path) return bad_usage("sweep: missing STUDY");
    if (o.slurm + o.collect_only + (o.point >= 0) > 1)
        return bad_usage("sweep: --slurm, --collect and --point exclude each other");
    pl_study_t *st = NULL;
    pl_err_t err = {0, ""};
    int rc = pl_study_load(path, &st, &err);
    if (!rc) rc = sweep_study(st, &o, &err);
    pl_study_free(st);
    if (rc == PL_ERR_INTERRUPTED) { /* one line: what stopped, how to resume; exit 128 + the first signal */
        int sig = interrupt_signal < 0 ? -(int)interrupt_signal : (int)interrupt_signal;
        fprintf(stderr, "peloid: %s (%s)\n", err.msg, signal_name(sig));
        return 128 + sig;
    }
    return rc ? fail(&err) : 0;
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    pl_h5_init_process();
    if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        fputs(usage, argc < 2 ? stderr : stdout);
        return argc < 2 ? PL_ERR_INPUT : 0;
    }
    const char *cmd = argv[1];
    if (!strcmp(cmd, "run")) return cmd_run(argc - 2, argv + 2);
    if (!strcmp(cmd, "check")) return cmd_scene(argc - 2, argv + 2, 0);
    if (!strcmp(cmd, "params")) return cmd_scene(argc - 2, argv + 2, 1);
    if (!strcmp(cmd, "sweep")) return cmd_sweep(argc - 2, argv + 2);
    if (!strcmp(cmd, "report")) return cmd_report(argc - 2, argv + 2);
    if (!strcmp(cmd, "plan")) return cmd_plan(argc - 2, argv + 2);
    if (!strcmp(cmd, "keys")) {
        pl_scene_print_reference(stdout);
        return 0;
    }
    char msg[256];
    snprintf(msg, sizeof msg, "unknown command '%s'", cmd);
    return bad_usage(msg);
}
