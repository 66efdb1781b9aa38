/* peloid command-line driver: parse arguments, load the scene, dispatch.
 * Exit codes: 0 ok, 2 bad input (nothing written), 3 stability guard,
 * 4 I/O failure, 5 out of memory. */
#include <errno.h>
#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "peloid/h5.h"
#include "peloid_build.h" /* PL_TOOLS_DIR (generated) */
#include "peloid/run.h"
#include "peloid/scene.h"
#include "peloid/sweep.h"

static const char *const usage =
    "usage: peloid COMMAND [ARGS]\n"
    "\n"
    "commands:\n"
    "  run SCENE [--out DIR] [--steps N] [--threads N] [--restart CHECKPOINT]\n"
    "            [--restart-changed KEY[,KEY...]] [--force] [--allow-include-anywhere]\n"
    "        run a scene; writes DIR/{thermo.tsv, summary.json, checkpoint.h5, scene.cfg\n"
    "        [, fields.h5 + fields.xdmf] [, colloids.h5 [+ colloids.xyz]]}.  DIR\n"
    "        defaults to out/<scene name>; an existing DIR is\n"
    "        refused unless --force.  --steps N runs N steps (default: the scene's\n"
    "        steps); --restart continues from a checkpoint of the same scene: every\n"
    "        physics key (all but name, steps, output.*, colloids.trajectory_interval,\n"
    "        colloids.neighbor_skin and the colloid guard bounds) must equal the\n"
    "        checkpoint's, unless named\n"
    "        in --restart-changed (e.g. --restart-changed srd.dt,thermostat.type).\n"
    "        --threads N sets the OpenMP thread count (results do not depend on it;\n"
    "        default OMP_NUM_THREADS, else the CPUs; at most 4096; a warning when it\n"
    "        exceeds the cores).\n"
    "        A scene's @include files are resolved relative to the including file and\n"
    "        must lie in the scene's directory tree unless --allow-include-anywhere.\n"
    "  check SCENE [--allow-include-anywhere]\n"
    "        validate a scene without running it\n"
    "  params SCENE [--json] [--strict] [--allow-include-anywhere]\n"
    "        print the derived SRD parameters: lambda, nu_kin, nu_col, nu, eta, D_f,\n"
    "        Sc, tau_f (Padding & Louis 2006, Eqs. 4, 6, 9-15)\n"
    "  report OUTDIR    write OUTDIR/report.md with a plot of every observable the run\n"
    "                   measured (g(r), MSD and D, clusters, thermo) and the error-against-\n"
    "                   time table (tools/report.py with /usr/bin/python3; PELOID_TOOLS\n"
    "                   names another tools directory)\n"
    "  sweep STUDY [--out DIR] [--jobs J] [--threads T] [--point K] [--slurm] [--collect]\n"
    "        run a parameter study: every point (the study's base scene with its keys\n"
    "        set) as its own `peloid run` in DIR/ID (default: the study's out), J\n"
    "        processes of T threads (default: J = min(points, CPUs), T = CPUs / J);\n"
    "        finished points are skipped; DIR/sweep.{tsv,json,png} collect them.\n"
    "        --point K runs point K only; --slurm writes a Slurm job array\n"
    "        (DIR/sweep.sbatch, collect.sbatch, submit.sh) and runs nothing;\n"
    "        --collect only rebuilds the table and plot.  Exit 1: some points failed\n"
    "  keys             print the scene-file reference (every key) as Markdown\n"
    "  --help           this text\n"
    "\n"
    "exit codes: 0 ok, 2 bad input (nothing written), 3 stability guard tripped,\n"
    "            4 I/O error, 5 out of memory, 6 internal limit\n";

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

static int cmd_run(int argc, char **argv)
{
    pl_run_opts_t o = {.out_dir = NULL, .steps = -1, .threads = 0, .restart = NULL, .force = 0,
                       .progress = isatty(2), .log = stderr, .restart_changed = NULL};
    unsigned flags = 0;
    const char *scene_path = NULL;
    char msg[256];
    for (int i = 0; i < argc; ++i) {
        const char *a = argv[i];
        int has = i + 1 < argc;
        long long v;
        if (!strcmp(a, "--force")) o.force = 1;
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
    pl_err_t err = {0, ""};
    if (pl_threads_resolve(o.threads, &o.threads, &err)) return fail(&err);
    pl_scene_t *scene = malloc(sizeof *scene);
    int rc = scene ? pl_scene_load_flags(scene_path, flags, scene, &err) : PL_ERR_NOMEM;
    if (!rc) rc = pl_run(scene, &o, &err);
    free(scene);
    return rc ? fail(&err) : 0;
}

static int cmd_scene(int argc, char **argv, int params)
{
    const char *path = NULL;
    int json = 0, strict = 0;
    unsigned flags = 0;
    for (int i = 0; i < argc; ++i) {
        if (!strcmp(argv[i], "--allow-include-anywhere")) flags |= PL_SCENE_INCLUDE_ANYWHERE;
        else if (params && !strcmp(argv[i], "--json")) json = 1;
        else if (params && !strcmp(argv[i], "--strict")) strict = 1;
        else if (argv[i][0] != '-' && !path) path = argv[i];
        else {
            char msg[256];
            snprintf(msg, sizeof msg, "%s: unexpected argument '%.100s'", params ? "params" : "check", argv[i]);
            return bad_usage(msg);
        }
    }
    if (!path) return bad_usage("missing SCENE");
    pl_scene_t *scene = malloc(sizeof *scene);
    pl_err_t err = {0, ""};
    if (!scene) return PL_ERR_NOMEM;
    int rc = pl_scene_load_flags(path, flags, scene, &err);
    if (!rc && params && json) {
        rc = pl_params_write_json(scene, stdout, strict, &err);
    } else if (!rc && params) {
        pl_params_print(scene, stdout);
        /* A scene with physical{} adds the unit mapping report (mapping.h). */
        rc = pl_mapping_report(scene, stdout, 0, strict, &err);
    } else if (!rc) { /* check: run's validation, including the derived values summary.json gets */
        rc = pl_run_check(scene, &err);
        if (!rc) printf("%s: ok\n", path);
    }
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

/* `peloid sweep STUDY`: the study's points as a process pool of `peloid run`
 * (src/sweep/sweep.c), or a Slurm job array. */
static int cmd_sweep(int argc, char **argv)
{
    pl_sweep_opts_t o = {.point = -1, .progress_tty = isatty(2), .log = stderr};
    const char *path = NULL;
    char msg[256], self[4096], tools[4096];
    for (int i = 0; i < argc; ++i) {
        const char *a = argv[i];
        int has = i + 1 < argc;
        long long v;
        if (!strcmp(a, "--slurm")) o.slurm = 1;
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
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) return bad_usage("sweep: cannot find the peloid executable (/proc/self/exe)");
    self[n] = '\0';
    o.self = self;
    const char *t = getenv("PELOID_TOOLS");
    snprintf(tools, sizeof tools, "%s", t && *t ? t : PL_TOOLS_DIR);
    o.tools = tools;
    pl_study_t *st = NULL;
    pl_err_t err = {0, ""};
    int rc = pl_study_load(path, &st, &err);
    if (!rc) rc = pl_sweep(st, &o, &err);
    pl_study_free(st);
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
    if (!strcmp(cmd, "keys")) {
        pl_scene_print_reference(stdout);
        return 0;
    }
    char msg[256];
    snprintf(msg, sizeof msg, "unknown command '%s'", cmd);
    return bad_usage(msg);
}
