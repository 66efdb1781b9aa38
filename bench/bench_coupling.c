/* Cost of each colloid-solvent coupling against the bare fluid step, next to
 * the STREAM triad measured in the same run.
 *
 * Scene: periodic box of L = 32 cells, gamma = 5 fluid particles per cell,
 * alpha = 130 deg, dt = 0.1, grid shift on, no thermostat; 64 colloids of
 * radius 2 a0 on a simple cubic lattice (volume fraction 6.5 %), neutrally
 * buoyant (mass density gamma), Hertz contacts, 4 MD steps per collision
 * step.  Cases: the bare fluid (no colloids), the colloids with no coupling
 * (MD only), and the couplings hecht1 (stick_stochastic, entry placement),
 * hecht2 and potential (sigma_cf = 2 a0, epsilon_cf = 2.5 kT; colloid WCA
 * of PL Eq. 16 with sigma_cc = 4.3 a0), and potential-1: the potential
 * coupling with a single colloid (its cost where colloids are few), and
 * hecht1-R6: one coupling I colloid of radius 6 a0 (its events' order).
 *
 * Per case and thread count: median (min..max) over `reps` repetitions of the
 * wall time per step per fluid particle, fluid particle-updates/s (per core),
 * the ratio to the bare fluid of the same thread count (median (min..max)
 * over the rounds of each rep's time against the fluid's rep of the same
 * round: the cases' simulations exist together and each round runs one rep
 * of every case, so that host noise of seconds moves both), the effective GB/s
 * of the bare step's byte model (248 B per particle in double, see
 * bench_srd.c: the couplings move more, so this is the bandwidth-equivalent
 * rate), and the share of the time each coupling stage takes.
 *
 * Output: one TSV line per case on stdout and in bench/out/coupling.tsv; its
 * last column, stage_ns, the median ns per particle of each stage.
 * Usage: bench_coupling [--quick] [--threads N] [--reps R] [--out DIR]
 *                       [--cases a,b,...]
 *        (PL_BENCH_QUICK=1 = --quick: L = 24, 3 reps; --cases: only those
 *        cases, and the fluid, which the ratios need) */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bench_common.h"
#include "peloid/sim.h"
#include "peloid_build.h" /* PL_GIT_REV, PL_CFLAGS (generated) */

enum { MAX_REPS = 32 };

typedef struct {
    const char *name;
    const char *text; /* scene tail after the common head */
    int colloids;     /* -1: the run's count (64; quick 27) */
} case_t;

static const char *HEAD =
    "seed = 11;\n"
    "box: { cells = [%d, %d, %d]; };\n"
    "fluid: { density = 5.0; temperature = 1.0; };\n"
    "srd: { dt = 0.1; rule = \"random_axis\"; alpha = 130.0; grid_shift = true; };\n"
    "output: { thermo_interval = 1000000; };\n";

#define COLLOIDS(pairs)                                                                        \
    "colloids: { count = %d; radius = 2.0; mass_density = 5.0; temperature = 1.0;\n"           \
    "  init = \"lattice\"; pairs = \"" pairs "\"; substeps = 4; };\n"

#define POTENTIAL                                                                              \
    COLLOIDS("wca") "wca: { epsilon = 2.5; sigma = 4.3; n = 24.0; };\n"                         \
                    "coupling: { method = \"potential\"; sigma_cf = 2.0; epsilon_cf = 2.5; };\n"

static const case_t CASES[] = {
    {"fluid", "", 0},
    {"colloid-md", COLLOIDS("hertz") "coupling: { method = \"none\"; };\n", -1},
    {"hecht1",
     COLLOIDS("hertz") "coupling: { method = \"hecht1\"; boundary = \"stick_stochastic\"; placement = \"entry\"; };\n",
     -1},
    {"hecht2", COLLOIDS("hertz") "coupling: { method = \"hecht2\"; };\n", -1},
    {"potential", POTENTIAL, -1},
    /* one colloid: the selection's cost where colloids are few */
    {"potential-1", POTENTIAL, 1},
    /* one large coupling I colloid (R = 6 a0, 905 cells): its events' order,
     * O(n^2) in the n events a colloid has a step, n ~ R^2 */
    {"hecht1-R6",
     "colloids: { count = %d; radius = 6.0; mass_density = 5.0; temperature = 1.0;\n"
     "  init = \"lattice\"; pairs = \"\"; substeps = 4; };\n"
     "coupling: { method = \"hecht1\"; boundary = \"stick_stochastic\"; placement = \"entry\"; };\n",
     1},
};
enum { NCASES = sizeof CASES / sizeof CASES[0] };

static int make_sim(const case_t *c, int L, int ncolloids, int nt, pl_sim_t **sim, pl_scene_t *sc)
{
    char text[2048], tail[1024];
    int n = snprintf(text, sizeof text, HEAD, L, L, L);
    snprintf(tail, sizeof tail, c->text, ncolloids);
    snprintf(text + n, sizeof text - (size_t)n, "%s", tail);
    pl_err_t err;
    memset(&err, 0, sizeof err);
    if (pl_scene_load_string(text, "bench_coupling", sc, &err) || pl_sim_create(sc, nt, sim, &err)) {
        fprintf(stderr, "bench_coupling: %s: %s\n", c->name, err.msg);
        return 1;
    }
    return 0;
}

enum { MAX_STAGES = 64 };

/* One case's simulation and its timings, rep by rep. */
typedef struct {
    pl_scene_t sc;
    pl_sim_t *sim;
    long steps;                        /* per rep: ~rep_seconds */
    double ns[MAX_REPS];               /* whole step, per fluid particle */
    double share[MAX_REPS];            /* of the coupling stages */
    double st_ns[MAX_STAGES][MAX_REPS];
} timed_case_t;

/* Creates the case's simulation, settles the first sorts and sizes a rep. */
static int case_setup(const case_t *c, int L, int ncolloids, int nt, double rep_seconds, timed_case_t *tc)
{
    if (make_sim(c, L, ncolloids, nt, &tc->sim, &tc->sc)) return 1;
    pl_err_t err;
    memset(&err, 0, sizeof err);
    int rc = 0;
    for (int s = 0; s < 20 && !rc; ++s) rc = pl_sim_step(tc->sim, &err);
    double t0 = omp_get_wtime();
    for (int s = 0; s < 3 && !rc; ++s) rc = pl_sim_step(tc->sim, &err);
    const double per_step = (omp_get_wtime() - t0) / 3.0;
    tc->steps = (long)ceil(rep_seconds / (per_step > 1e-7 ? per_step : 1e-7));
    if (tc->steps < 3) tc->steps = 3;
    if (rc) fprintf(stderr, "bench_coupling: %s: %s\n", c->name, err.msg);
    return rc;
}

/* Rep r of a case: ns per fluid particle and step of the whole step, the
 * share of the coupling stages (any stage not in the bare fluid plan), and
 * each stage's ns. */
static int case_rep(const case_t *c, timed_case_t *tc, int r)
{
    pl_sim_t *sim = tc->sim;
    pl_err_t err;
    memset(&err, 0, sizeof err);
    int rc = 0;
    const double n = (double)sim->fluid.n;
    const int nst = sim->nstages < MAX_STAGES ? sim->nstages : MAX_STAGES;
    for (int k = 0; k < sim->nstages; ++k) sim->stages[k].seconds = 0.0;
    const double t0 = omp_get_wtime();
    for (long s = 0; s < tc->steps && !rc; ++s) rc = pl_sim_step(sim, &err);
    const double wall = omp_get_wtime() - t0;
    double cs = 0.0;
    for (int k = 0; k < sim->nstages; ++k) {
        const char *nm = sim->stages[k].name;
        if (strcmp(nm, "stream+bin") && strcmp(nm, "sort") && strcmp(nm, "collide")) cs += sim->stages[k].seconds;
        if (k < nst) tc->st_ns[k][r] = 1e9 * sim->stages[k].seconds / (double)tc->steps / n;
    }
    tc->ns[r] = 1e9 * wall / (double)tc->steps / n;
    tc->share[r] = cs / wall;
    if (rc) fprintf(stderr, "bench_coupling: %s: %s\n", c->name, err.msg);
    return rc;
}

/* The case's stage names and median stage ns, as "name=ns,..." lists. */
static void case_stages(const timed_case_t *tc, int reps, char *stages, size_t ssz, char *stage_ns, size_t nsz)
{
    const pl_sim_t *sim = tc->sim;
    const int nst = sim->nstages < MAX_STAGES ? sim->nstages : MAX_STAGES;
    stages[0] = 0;
    for (int k = 0; k < sim->nstages; ++k) {
        size_t used = strlen(stages);
        snprintf(stages + used, ssz - used, "%s%s", k ? "," : "", sim->stages[k].name);
    }
    stage_ns[0] = 0;
    for (int k = 0; k < nst; ++k) {
        double v[MAX_REPS], med, smin, smax;
        memcpy(v, tc->st_ns[k], (size_t)reps * sizeof *v);
        bench_stats(v, reps, &med, &smin, &smax);
        size_t used = strlen(stage_ns);
        snprintf(stage_ns + used, nsz - used, "%s%s=%.2f", k ? "," : "", sim->stages[k].name, med);
    }
}

/* Whether name is an item of the comma-separated list. */
static int listed(const char *list, const char *name)
{
    const size_t n = strlen(name);
    for (const char *p = list; p && *p;) {
        const char *e = strchr(p, ',');
        const size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len == n && !strncmp(p, name, n)) return 1;
        p = e ? e + 1 : NULL;
    }
    return 0;
}

int main(int argc, char **argv)
{
    bench_pin_or_reexec(argv);
    int quick = getenv("PL_BENCH_QUICK") && atoi(getenv("PL_BENCH_QUICK"));
    int max_threads = omp_get_max_threads(), reps = 5;
    const char *outdir = "bench/out", *only = NULL;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--quick")) quick = 1;
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) max_threads = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--reps") && i + 1 < argc) reps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--out") && i + 1 < argc) outdir = argv[++i];
        else if (!strcmp(argv[i], "--cases") && i + 1 < argc) only = argv[++i];
        else {
            fprintf(stderr, "usage: bench_coupling [--quick] [--threads N] [--reps R] [--out DIR] [--cases a,b]\n");
            return 2;
        }
    }
    if (quick) reps = 3;
    if (reps < 3) reps = 3;
    if (reps > MAX_REPS) reps = MAX_REPS;
    if (max_threads < 1) max_threads = 1;
    /* L = 32 with 64 colloids (R = 2: phi = 6.5 %); quick: L = 24 with 27 */
    const int L = quick ? 24 : 32, ncolloids = quick ? 27 : 64;
    const double rep_seconds = quick ? 0.3 : 0.6;
    const double step_bytes = 30.0 * (double)sizeof(pl_real) + 8.0; /* bench_srd.c byte model */

    mkdir(outdir, 0777);
    char path[512];
    snprintf(path, sizeof path, "%s/coupling.tsv", outdir);
    FILE *tsv = fopen(path, "w");
    if (!tsv) {
        fprintf(stderr, "bench_coupling: cannot write %s\n", path);
        return 1;
    }
    printf("# bench_coupling  peloid %s  cflags %s  real %s  L %d  colloids %d\n", PL_GIT_REV, PL_CFLAGS,
           PL_REAL_NAME, L, ncolloids);
    bench_print_topology(stdout);
    const char *hdr = "case\tL\tthreads\tfluid_particles\tcolloids\tns_per_particle\tns_min\tns_max"
                      "\tupdates_per_s\tupdates_per_s_per_core\tratio_to_fluid\tratio_min\tratio_max\tcoupling_stage_share"
                      "\teff_GBps\tstream_GBps\tpct_of_stream_bound\treps\tstages\tstage_ns\n";
    printf("%s", hdr);
    fputs(hdr, tsv);
    int rc = 0;
    /* Per thread count, every case's simulation exists at once and the reps
     * go round the cases (fluid, case 1, case 2, ..., fluid, ...): each
     * case's ratio to the bare fluid is the median over reps of its rep
     * against the fluid's rep of the same round, seconds apart, so that a
     * noisy host moves both. */
    static timed_case_t tcs[NCASES];
    for (int t = 1; t <= max_threads && !rc; ++t) {
        double slo, shi;
        const double stream = bench_stream_triad((size_t)1 << 25, t, 3, &slo, &shi);
        int used[NCASES] = {0};
        for (int k = 0; k < NCASES && !rc; ++k) {
            if (k > 0 && only && !listed(only, CASES[k].name)) continue;
            const int nc = CASES[k].colloids < 0 ? ncolloids : CASES[k].colloids;
            memset(&tcs[k], 0, sizeof tcs[k]);
            rc = case_setup(&CASES[k], L, nc, t, rep_seconds, &tcs[k]);
            used[k] = !rc;
        }
        for (int r = 0; r < reps && !rc; ++r)
            for (int k = 0; k < NCASES && !rc; ++k)
                if (used[k]) rc = case_rep(&CASES[k], &tcs[k], r);
        for (int k = 0; k < NCASES && !rc; ++k) {
            if (!used[k]) continue;
            double ns[MAX_REPS], ratio[MAX_REPS], med, lo, hi, rmed, rlo, rhi, share, slo2, shi2;
            for (int r = 0; r < reps; ++r) ratio[r] = tcs[k].ns[r] / tcs[0].ns[r];
            memcpy(ns, tcs[k].ns, (size_t)reps * sizeof *ns);
            bench_stats(ns, reps, &med, &lo, &hi);
            bench_stats(ratio, reps, &rmed, &rlo, &rhi);
            bench_stats(tcs[k].share, reps, &share, &slo2, &shi2);
            char stages[512], stage_ns[1024];
            case_stages(&tcs[k], reps, stages, sizeof stages, stage_ns, sizeof stage_ns);
            const double ups = 1e9 / med, gbs = step_bytes / med;
            const int nc = CASES[k].colloids < 0 ? ncolloids : CASES[k].colloids;
            char line[2048];
            snprintf(line, sizeof line,
                     "%s\t%d\t%d\t%.0f\t%d\t%.3f\t%.3f\t%.3f\t%.4g\t%.4g\t%.3f\t%.3f\t%.3f\t%.3f\t%.2f\t%.2f\t%.1f\t%d\t%s\t%s\n",
                     CASES[k].name, L, t, (double)tcs[k].sim->fluid.n, k ? nc : 0, med, lo, hi, ups, ups / t, rmed,
                     rlo, rhi, share, gbs, stream, 100.0 * gbs / stream, reps, stages, stage_ns);
            fputs(line, stdout);
            fputs(line, tsv);
            fflush(stdout);
        }
        for (int k = 0; k < NCASES; ++k)
            if (tcs[k].sim) {
                pl_sim_free(tcs[k].sim);
                tcs[k].sim = NULL;
            }
    }
    fclose(tsv);
    return rc;
}
