/* SRD step benchmark: each kernel of the plan (stream+bin, sort, collide) and
 * the whole step, for box sizes in and out of cache and a thread sweep 1..N,
 * next to the STREAM triad bandwidth measured in the same run.
 *
 * Scene: pure SRD fluid, 10 particles per cell, alpha = 130 deg, random axis,
 * grid shift on, dt = 0.1, no thermostat (HOOMD-blue's published 3D scene).
 *
 * Byte model (bytes of particle state each kernel must read + write per
 * particle; D = sizeof(pl_real), 8 for double, 4 for float; write-allocate
 * not counted, the STREAM convention):
 *   plan (src/core/sim.c)
 *     stream+bin   read r, v (6D), write r (3D), write cell index (4)      9D + 4
 *                  (no body force: v is not written back, srd_stream.c)
 *     sort         read cell (4), r, v (6D); write twins r', v' (6D)       12D + 4
 *     collide      read v (3D), write v (3D) (a cell stays in cache)        6D
 *     step                                                                27D + 8
 *   stream-in-scatter pipeline (lines "fused:*", same state)
 *     count        read r, v (6D); cells counted in the histogram only      6D
 *     stream+sort  read r, v (6D), drift, write the twins r', v' (6D)      12D
 *     collide      as above                                                 6D
 *     step                                                                24D
   srd.sort_interval = k (lines "kK:*", --sort-interval K): the full sort on
   one step in k, the index sort (read cell 4, write the slot's index 4) on
   the others, whose collision also reads the index (4); the mean over k:
     sort         (12D + 4) / k + 8 (1 - 1/k)
     collide      6D + 4 (1 - 1/k)
 * = 224 B / 192 B (double), 116 B / 96 B (float); with k = 8 the step is
 * 9D + 4 + 1.5D + 7.5 + 6D + 3.5 = 147 B (double).  Cell arrays (per-thread
 * histograms, cell_start: O(nthreads x ncells) words, ~ 0.4 (3 nthreads + 2)
 * B per particle at 10 per cell) are left out of the model: they are part of
 * the overhead the measurement shows against it.
 * Effective GB/s = model bytes / time; % of bound = effective / STREAM triad
 * measured (3 repetitions, median) just before the case.
 *
 * Output: one TSV line per case on stdout and in bench/out/srd.tsv
 * (bench/out/stream.tsv: the triad sweep).  Median of `reps` repetitions,
 * min and max as the spread.
 *
 * Usage: bench_srd [--quick] [--sizes 16,64,120] [--threads N | --thread-list 1,2,4]
 *                  [--reps R] [--rep-seconds S] [--out DIR] [--no-stream] [--sort-interval K]
 *                  (PL_BENCH_QUICK=1 = --quick; --help prints this) */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bench_common.h"
#include "peloid/sim.h"
#include "peloid_build.h" /* PL_GIT_REV, PL_CFLAGS (generated) */
#include "../src/fluid/srd_state.h" /* the fluid's kernels on its own scratch (hist, cell_start) */

enum { MAX_SIZES = 8, MAX_REPS = 32, MAX_KERN = PL_MAX_STAGES + 1, MAX_TLIST = 64, MAX_THREADS = 1024 };

static const char usage[] =
    "usage: bench_srd [--quick] [--sizes 16,64,120] [--threads N | --thread-list 1,2,4]\n"
    "                 [--reps R] [--rep-seconds S] [--out DIR] [--no-stream] [--sort-interval K]\n"
    "  --sort-interval K also the plan with srd.sort_interval = K (lines kK:*; K > 1)\n"
    "  --threads N       thread sweep 1..N (default: the CPUs)\n"
    "  --thread-list L   these thread counts only (comma-separated)\n"
    "  --reps R          repetitions per case, median and min..max (3..32; default 5, quick 3)\n"
    "  --rep-seconds S   target duration of one repetition (default 0.4, quick 0.15; >= 2 steps)\n"
    "  --no-stream       skip the STREAM triad\n";

typedef struct {
    int sizes[MAX_SIZES], nsizes;
    int max_threads, reps;
    int tlist[MAX_TLIST], ntl; /* thread counts of the sweep */
    double rep_seconds; /* target duration of one repetition */
    const char *outdir;
    int no_stream; /* skip the triad (A/B runs of kernels only) */
    int sort_interval; /* > 1: also the plan with srd.sort_interval = this */
} options_t;

/* Byte model of a plan stage at srd.sort_interval k (see the file
 * comment); 0 when unknown. */
static double model_bytes_k(const char *stage, int k)
{
    const double D = (double)sizeof(pl_real), f = 1.0 / k;
    if (!strcmp(stage, "sort")) return (12 * D + 4) * f + 8 * (1 - f);
    if (!strcmp(stage, "collide")) return 6 * D + 4 * (1 - f);
    if (!strcmp(stage, "stream+bin")) return 9 * D + 4;
    return 0.0;
}

/* Byte model of a plan stage (see the file comment); 0 when unknown. */
static double model_bytes(const char *stage)
{
    const double D = (double)sizeof(pl_real);
    if (!strcmp(stage, "count")) return 6 * D;
    if (!strcmp(stage, "stream+sort")) return 12 * D;
    if (!strcmp(stage, "stream+bin")) return 9 * D + 4; /* the bench scene has no body force */
    if (!strcmp(stage, "sort")) return 12 * D + 4;
    if (!strcmp(stage, "collide") || !strcmp(stage, "collide+guards")) return 6 * D;
    return 0.0;
}

static void parse(int argc, char **argv, options_t *o)
{
    int quick = getenv("PL_BENCH_QUICK") && atoi(getenv("PL_BENCH_QUICK"));
    for (int i = 1; i < argc; ++i)
        if (!strcmp(argv[i], "--quick")) quick = 1;
    o->nsizes = 0;
    if (quick) {
        o->sizes[o->nsizes++] = 16;
        o->sizes[o->nsizes++] = 64;
    } else {
        o->sizes[o->nsizes++] = 8;
        o->sizes[o->nsizes++] = 16;
        o->sizes[o->nsizes++] = 32;
        o->sizes[o->nsizes++] = 64;
        o->sizes[o->nsizes++] = 120;
    }
    o->max_threads = omp_get_num_procs();
    o->reps = quick ? 3 : 5;
    o->rep_seconds = quick ? 0.15 : 0.4;
    o->outdir = "bench/out";
    o->no_stream = 0;
    o->sort_interval = 1;
    o->ntl = 0;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            fputs(usage, stdout);
            exit(0);
        }
        if (!strcmp(argv[i], "--sizes") && i + 1 < argc) {
            o->nsizes = 0;
            for (char *s = strtok(argv[++i], ","); s && o->nsizes < MAX_SIZES; s = strtok(NULL, ","))
                o->sizes[o->nsizes++] = atoi(s);
        } else if (!strcmp(argv[i], "--threads") && i + 1 < argc) {
            o->max_threads = atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--thread-list") && i + 1 < argc) {
            for (char *s = strtok(argv[++i], ","); s && o->ntl < MAX_TLIST; s = strtok(NULL, ","))
                if (atoi(s) >= 1 && atoi(s) <= MAX_THREADS) o->tlist[o->ntl++] = atoi(s);
        } else if (!strcmp(argv[i], "--rep-seconds") && i + 1 < argc) {
            o->rep_seconds = atof(argv[++i]);
        } else if (!strcmp(argv[i], "--reps") && i + 1 < argc) {
            o->reps = atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--no-stream")) {
            o->no_stream = 1;
        } else if (!strcmp(argv[i], "--sort-interval") && i + 1 < argc) {
            o->sort_interval = atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--out") && i + 1 < argc) {
            o->outdir = argv[++i];
        }
    }
    if (o->reps < 3) o->reps = 3;
    if (o->reps > MAX_REPS) o->reps = MAX_REPS;
    if (o->max_threads < 1) o->max_threads = 1;
    if (o->max_threads > MAX_THREADS) o->max_threads = MAX_THREADS;
    if (!(o->rep_seconds > 0.0)) o->rep_seconds = 0.01;
    if (o->ntl == 0) /* 1..max_threads; beyond MAX_TLIST counts, a stride */
        for (int t = 1; t <= o->max_threads; t += 1 + (o->max_threads - 1) / MAX_TLIST) o->tlist[o->ntl++] = t;
    else
        for (int k = 0; k < o->ntl; ++k)
            if (o->tlist[k] > o->max_threads) o->max_threads = o->tlist[k];
}

static void hoomd_scene(pl_scene_t *sc, int L)
{
    pl_scene_defaults(sc);
    snprintf(sc->run.name, sizeof sc->run.name, "bench_L%d", L);
    sc->run.seed = 12345;
    for (int d = 0; d < 3; ++d) sc->box.cells[d] = L;
    sc->fluid.density = 10.0;
    sc->fluid.temperature = 1.0;
    sc->srd.dt = 0.1;
    sc->srd.rule = PL_RULE_RANDOM_AXIS;
    sc->srd.alpha_deg = 130.0;
    sc->srd.grid_shift = 1;
    sc->thermostat.type = PL_THERMO_NONE;
    sc->output.fields_interval = 0;
}

static size_t alloc_bytes(const pl_sim_t *sim)
{
    size_t nc = sim->grid.ncells, nb = (nc + PL_CELL_BLOCK - 1) / PL_CELL_BLOCK;
    return pl_fluid_bytes(&sim->fluid) * sim->fluid.n + (size_t)sim->nthreads * nc * 4 +
           (nc + 1) * 4 + 2 * nb * 8 + pl_srd_observe_scratch(sim->fluid.n) * 8;
}

/* One step of the stream-in-scatter pipeline (pl_srd_stream_count +
 * pl_srd_stream_sort, then the plan's collide stage): the same state as
 * the plan's stream+bin, sort, collide.  sec[0..2] accumulate stage times. */
static int fused_step(pl_sim_t *sim, pl_err_t *err, double sec[3])
{
    const pl_scene_t *sc = &sim->scene;
    double t0 = omp_get_wtime();
    pl_grid_draw_shift(&sim->grid, (uint64_t)sc->run.seed, (uint64_t)sim->step, sc->srd.grid_shift);
    pl_stream_params_t p;
    pl_sim_stream_params(sim, &p);
    pl_srd_stream_count(&sim->fluid, &sim->grid, &p, sim->srd->hist, sim->nthreads);
    double t1 = omp_get_wtime();
    pl_srd_stream_sort(&sim->fluid, &sim->grid, &p, sim->srd->hist, sim->srd->cell_start, sim->nthreads);
    pl_fluid_swap(&sim->fluid);
    double t2 = omp_get_wtime();
    int rc = 0;
    for (int k = 0; k < sim->nstages && !rc; ++k) /* the plan's other stages: collide, the guards */
        if (strcmp(sim->stages[k].name, "stream+bin") && strcmp(sim->stages[k].name, "sort"))
            rc = sim->stages[k].fn(sim, sim->stages[k].ctx, err);
    double t3 = omp_get_wtime();
    sec[0] += t1 - t0;
    sec[1] += t2 - t1;
    sec[2] += t3 - t2;
    sim->step++;
    return rc;
}

static void print_line(FILE *tsv, const char *name, int L, int nt, double n, double *ns, int reps,
                       double mb, double ab, double stream_gbs, long steps)
{
    double med, lo, hi;
    bench_stats(ns, reps, &med, &lo, &hi);
    double ups = 1e9 / med, gbs = mb / med;
    char line[512];
    snprintf(line, sizeof line,
             "%s\t%d\t%d\t%.0f\t%.4f\t%.4f\t%.4f\t%.4g\t%.4g\t%.3f\t%.3f\t%.1f\t%.0f\t%.1f\t%s\t%d\t%ld\n",
             name, L, nt, n, med, lo, hi, ups, ups / nt, gbs, stream_gbs, 100.0 * gbs / stream_gbs,
             mb, ab / n, PL_REAL_NAME, reps, steps);
    fputs(line, stdout);
    fputs(line, tsv);
}

/* The load of the machine (other users' processes distort timings). */
static void print_loadavg(const char *when)
{
    char buf[128] = "?";
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (!fgets(buf, sizeof buf, f)) buf[0] = 0;
        fclose(f);
    }
    buf[strcspn(buf, "\n")] = 0;
    printf("# loadavg at %s: %s\n", when, buf);
}

/* Runs one (size, threads) case: the plan (each stage and the whole step),
 * then the stream-in-scatter pipeline; prints one line per kernel.  k > 1:
 * the plan with srd.sort_interval = k only (lines "kK:*"). */
static int run_case(const options_t *o, int L, int nt, double stream_gbs, FILE *tsv, int sort_k)
{
    pl_scene_t sc;
    hoomd_scene(&sc, L);
    sc.srd.sort_interval = sort_k;
    pl_err_t err;
    memset(&err, 0, sizeof err);
    pl_sim_t *sim;
    if (pl_sim_create(&sc, nt, &sim, &err)) {
        fprintf(stderr, "bench_srd: L=%d: %s\n", L, err.msg);
        return 1;
    }
    const double n = (double)sim->fluid.n;
    /* warm-up: the first sorts reorder a random initial state */
    for (int s = 0; s < 3; ++s) pl_sim_step(sim, &err);
    double t0 = omp_get_wtime();
    pl_sim_step(sim, &err);
    double per_step = omp_get_wtime() - t0;
    long steps = (long)ceil(o->rep_seconds / (per_step > 1e-7 ? per_step : 1e-7));
    if (steps < 2) steps = 2;
    steps = (steps + sort_k - 1) / sort_k * sort_k; /* whole sort intervals */
    const int nk = sim->nstages + 1; /* every stage, then the whole step */
    double ns[MAX_KERN][MAX_REPS], nf[4][MAX_REPS];
    int rc = 0;
    for (int r = 0; r < o->reps && !rc; ++r) {
        for (int k = 0; k < sim->nstages; ++k) sim->stages[k].seconds = 0.0;
        t0 = omp_get_wtime();
        for (long s = 0; s < steps && !rc; ++s) rc = pl_sim_step(sim, &err);
        double wall = omp_get_wtime() - t0;
        for (int k = 0; k < sim->nstages; ++k) ns[k][r] = 1e9 * sim->stages[k].seconds / (double)steps / n;
        ns[nk - 1][r] = 1e9 * wall / (double)steps / n;
    }
    /* the pure-fluid plan: stream+bin, sort, collide and the fluid's guards */
    int fused = !rc && sort_k == 1;
    for (int k = 0; k < sim->nstages; ++k) {
        const char *nm = sim->stages[k].name;
        if (strcmp(nm, "stream+bin") && strcmp(nm, "sort") && strcmp(nm, "collide") &&
            strcmp(nm, "fluid-guard") && strcmp(nm, "output-guard"))
            fused = 0;
    }
    for (int r = 0; r < o->reps && fused && !rc; ++r) {
        double sec[3] = {0.0, 0.0, 0.0};
        t0 = omp_get_wtime();
        for (long s = 0; s < steps && !rc; ++s) rc = fused_step(sim, &err, sec);
        double wall = omp_get_wtime() - t0;
        for (int k = 0; k < 3; ++k) nf[k][r] = 1e9 * sec[k] / (double)steps / n;
        nf[3][r] = 1e9 * wall / (double)steps / n;
    }
    if (rc) {
        fprintf(stderr, "bench_srd: %s\n", err.msg);
        pl_sim_free(sim);
        return 1;
    }
    const double ab = (double)alloc_bytes(sim);
    double step_bytes = 0.0, stage_mb[MAX_KERN];
    for (int j = 0; j < sim->nstages; ++j) {
        stage_mb[j] = sort_k > 1 ? model_bytes_k(sim->stages[j].name, sort_k) : model_bytes(sim->stages[j].name);
        step_bytes += stage_mb[j];
    }
    for (int j = 0; j < nk; ++j) {
        char name[64];
        const char *stage = j < sim->nstages ? sim->stages[j].name : "step";
        if (sort_k > 1) snprintf(name, sizeof name, "k%d:%s", sort_k, stage);
        else snprintf(name, sizeof name, "%s", stage);
        print_line(tsv, name, L, nt, n, ns[j], o->reps, j < sim->nstages ? stage_mb[j] : step_bytes, ab, stream_gbs,
                   steps);
    }
    if (fused) {
        const char *names[4] = {"count", "stream+sort", "collide+guards", "step"};
        char name[64];
        for (int k = 0; k < 4; ++k) {
            snprintf(name, sizeof name, "fused:%s", names[k]);
            double mb = k < 3 ? model_bytes(names[k]) : model_bytes("count") + model_bytes("stream+sort") +
                                                          model_bytes("collide");
            print_line(tsv, name, L, nt, n, nf[k], o->reps, mb, ab, stream_gbs, steps);
        }
    }
    fflush(stdout);
    fflush(tsv);
    pl_sim_free(sim);
    return 0;
}

int main(int argc, char **argv)
{
    bench_pin_or_reexec(argv);
    options_t o;
    parse(argc, argv, &o);
    mkdir(o.outdir, 0777);
    char path[512];
    snprintf(path, sizeof path, "%s/srd%s.tsv", o.outdir, sizeof(pl_real) == 4 ? "_float" : "");
    FILE *tsv = fopen(path, "w");
    snprintf(path, sizeof path, "%s/stream%s.tsv", o.outdir, sizeof(pl_real) == 4 ? "_float" : "");
    FILE *stsv = fopen(path, "w");
    if (!tsv || !stsv) {
        fprintf(stderr, "bench_srd: cannot write into %s\n", o.outdir);
        return 1;
    }
    printf("# bench_srd  peloid %s  cflags %s  real %s  max threads %d\n", PL_GIT_REV, PL_CFLAGS,
           PL_REAL_NAME, o.max_threads);
    printf("# threads:");
    for (int k = 0; k < o.ntl; ++k) printf(" %d", o.tlist[k]);
    printf("  reps %d  rep seconds %g\n", o.reps, o.rep_seconds);
    bench_print_topology(stdout);
    print_loadavg("start");

    /* STREAM triad sweep: 3 arrays of 2^25 doubles (768 MiB, >> any L3). */
    const size_t n_stream = (size_t)1 << 25;
    const char *shdr = "kernel\tthreads\tn\tGBps_median\tGBps_min\tGBps_max\n";
    printf("%s", shdr);
    fputs(shdr, stsv);
    for (int k = 0; k < o.ntl; ++k) {
        const int t = o.tlist[k];
        double lo = NAN, hi = NAN;
        const double g = o.no_stream ? NAN : bench_stream_triad(n_stream, t, o.reps, &lo, &hi);
        printf("triad\t%d\t%zu\t%.3f\t%.3f\t%.3f\n", t, n_stream, g, lo, hi);
        fprintf(stsv, "triad\t%d\t%zu\t%.3f\t%.3f\t%.3f\n", t, n_stream, g, lo, hi);
    }
    fclose(stsv);

    const char *hdr = "kernel\tL\tthreads\tparticles\tns_per_particle\tns_min\tns_max\tupdates_per_s"
                      "\tupdates_per_s_per_core\teff_GBps\tstream_GBps\tpct_of_stream_bound"
                      "\tmodel_bytes_per_particle\talloc_bytes_per_particle\treal\treps\tsteps_per_rep\n";
    printf("%s", hdr);
    fputs(hdr, tsv);
    int rc = 0;
    /* The triad is measured again right before each case: on a shared
     * machine the bandwidth left to us changes during the run. */
    for (int s = 0; s < o.nsizes; ++s)
        for (int k = 0; k < o.ntl; ++k) {
            double lo, hi;
            double sg = o.no_stream ? NAN : bench_stream_triad(n_stream, o.tlist[k], 3, &lo, &hi);
            rc |= run_case(&o, o.sizes[s], o.tlist[k], sg, tsv, 1);
            if (o.sort_interval > 1) rc |= run_case(&o, o.sizes[s], o.tlist[k], sg, tsv, o.sort_interval);
        }
    fclose(tsv);
    print_loadavg("end");
    return rc;
}
