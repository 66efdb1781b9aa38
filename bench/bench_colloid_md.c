/* Colloid MD throughput on a dense DLVO suspension: Hecht Fig. 14 conditions
 * in model units (bench/scenes/fig14_model.cfg: 1155 colloids, phi = 0.34,
 * Psi0 = 50 mV, kappa = 3e8 /m, cut-off 3.36 a0), colloids alone (the fluid
 * stages are not run).  For 1 and 2 threads (PL_BENCH_THREADS overrides the
 * largest; PL_BENCH_ONLY_THREADS=1 runs only that count), the median of REPS timings of STEPS MD steps, each line:
 *   kernel threads n steps substeps_per_s colloid_steps_per_s pairs_in_cutoff
 *   listed_pairs ns_per_pair gbs stream_gbs list_builds
 * pairs_in_cutoff: unordered pairs inside their cut-off at the end (each is
 * evaluated once per step); ns_per_pair: the whole MD step (kick, drift,
 * list check / rebuild, forces, guards) per such pair; gbs: the pair loop's
 * traffic model (per listed pair: 4 B index + 24 B stored force + 24 B read
 * back + 4 B reverse slot; per colloid 17 doubles read/written) over the time.
 *
 *   build/bench/bench_colloid_md [SCENE] [STEPS] [REPS]   (defaults: the
 *   scene above, 2000, 5)
 *   build/bench/bench_colloid_md --lammps DIR [SCENE]
 * The second form writes the peer's inputs for bench/peers/run_colloid_peers.sh:
 * DIR/colloids.data (the initial positions, velocities and mass of the
 * scene's colloids) and DIR/pair.table (peloid's own DLVO + Hertz pair
 * energy and force, Hecht Eqs. 1-3 with the parabolic primary minimum, at
 * 2000 points from 0.9 d to the cut-off, for LAMMPS `pair_style table`),
 * and prints "cutoff dt" for the deck (monodisperse scenes only). */
#include <math.h>
#include <stdlib.h>
#include <time.h>

#include "bench_common.h"
#include "peloid/colloid.h"
#include "peloid/colloid_pair.h"

static double cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static long long pairs_in_cutoff(const pl_colloid_t *c)
{
    const pl_colloid_nlist_t *nl = &c->nlist;
    long long m = 0;
    for (size_t i = 0; i < c->n; ++i)
        for (int32_t s = nl->start[i]; s < nl->start[i + 1]; ++s) {
            size_t j = (size_t)nl->nbr[s];
            double d[3] = {c->x[i] - c->x[j], c->y[i] - c->y[j], c->z[i] - c->z[j]}, r2 = 0.0;
            for (int k = 0; k < 3; ++k) {
                if (c->periodic[k]) d[k] -= c->box[k] * rint(d[k] / c->box[k]);
                r2 += d[k] * d[k];
            }
            double rc = c->rad[i] + c->rad[j] + c->pair.gap_cut;
            m += r2 < rc * rc;
        }
    return m;
}

/* The peer's inputs (see the file header). */
static int write_lammps(const char *dir, const pl_scene_t *s)
{
    pl_colloid_t *c;
    pl_err_t err;
    if (pl_colloid_create(s, omp_get_max_threads(), &c, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    char path[4096];
    snprintf(path, sizeof path, "%s/colloids.data", dir);
    FILE *f = fopen(path, "w");
    if (!f) return perror(path), 1;
    fprintf(f, "peloid colloids of %s\n\n%zu atoms\n1 atom types\n\n", s->path, c->n);
    fprintf(f, "0 %.17g xlo xhi\n0 %.17g ylo yhi\n0 %.17g zlo zhi\n\nMasses\n\n1 %.17g\n\nAtoms # atomic\n\n",
            c->box[0], c->box[1], c->box[2], c->mass[0]);
    for (size_t i = 0; i < c->n; ++i) fprintf(f, "%zu 1 %.17g %.17g %.17g\n", i + 1, c->x[i], c->y[i], c->z[i]);
    fprintf(f, "\nVelocities\n\n");
    for (size_t i = 0; i < c->n; ++i) fprintf(f, "%zu %.17g %.17g %.17g\n", i + 1, c->vx[i], c->vy[i], c->vz[i]);
    if (fclose(f)) return perror(path), 1;
    const pl_colloid_pair_params_t *p = &c->pair;
    double d = 2.0 * c->rad[0], rc = d + p->gap_cut, r0 = 0.9 * d;
    int npts = 2000;
    snprintf(path, sizeof path, "%s/pair.table", dir);
    if (!(f = fopen(path, "w"))) return perror(path), 1;
    fprintf(f, "# peloid DLVO + Hertz pair of %s (kT, a0)\n\nPELOID\nN %d R %.17g %.17g\n\n", s->path, npts, r0, rc);
    for (int k = 0; k < npts; ++k) {
        double r = r0 + (rc - r0) * k / (npts - 1), u = 0.0, fr = 0.0;
        if (p->terms & PL_CT_DLVO) {
            pl_pair_val_t v = pl_pair_dlvo(r, d, p->coul_C, p->kappa, p->hamaker, p->prim_hm, p->prim_h0, p->dlvo_shift);
            u += v.u, fr += v.f;
        }
        if ((p->terms & PL_CT_HERTZ) && r < d) {
            pl_pair_val_t v = pl_pair_hertz(d - r, p->hertz_K);
            u += v.u, fr += v.f;
        }
        fprintf(f, "%d %.17g %.17g %.17g\n", k + 1, r, u, fr);
    }
    if (fclose(f)) return perror(path), 1;
    printf("%.17g %.17g\n", rc, c->dt);
    pl_colloid_free(c);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc > 2 && !strcmp(argv[1], "--lammps")) {
        pl_scene_t s;
        pl_err_t err;
        if (pl_scene_load(argc > 3 ? argv[3] : "bench/scenes/fig14_model.cfg", &s, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
        return write_lammps(argv[2], &s);
    }
    bench_pin_or_reexec(argv);
    const char *path = argc > 1 ? argv[1] : "bench/scenes/fig14_model.cfg";
    long steps = argc > 2 ? atol(argv[2]) : 2000;
    int reps = argc > 3 ? atoi(argv[3]) : 5;
    pl_scene_t s;
    pl_err_t err;
    if (pl_scene_load(path, &s, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    bench_print_topology(stdout);
    int maxt = getenv("PL_BENCH_THREADS") ? atoi(getenv("PL_BENCH_THREADS")) : 2;
    if (maxt > omp_get_num_procs()) maxt = omp_get_num_procs();
    int mint = getenv("PL_BENCH_ONLY_THREADS") ? maxt : 1;
    for (int t = mint; t <= maxt; t = t < 2 ? t + 1 : 2 * t) {
        double tm[64], cpu[64], slo, shi;
        long long builds = 0, inc = 0, listed = 0;
        size_t n = 0;
        if (reps > 64) reps = 64;
        for (int r = 0; r < reps; ++r) {
            pl_colloid_t *c;
            if (pl_colloid_create(&s, t, &c, &err)) {
                fprintf(stderr, "%s\n", err.msg);
                return 1;
            }
            long long b0 = c->nlist.builds;
            double t0 = omp_get_wtime(), c0 = cpu_seconds();
            for (long k = 0; k < steps; ++k)
                if (pl_colloid_md_step(c, &err)) {
                    fprintf(stderr, "%s\n", err.msg);
                    return 1;
                }
            tm[r] = omp_get_wtime() - t0;
            cpu[r] = cpu_seconds() - c0;
            builds = c->nlist.builds - b0;
            inc = pairs_in_cutoff(c);
            listed = (long long)c->nlist.npairs;
            n = c->n;
            pl_colloid_free(c);
        }
        double med, lo, hi, cmed, clo, chi;
        bench_stats(tm, reps, &med, &lo, &hi);
        bench_stats(cpu, reps, &cmed, &clo, &chi);
        double stream = bench_stream_triad((size_t)1 << 25, t, 3, &slo, &shi);
        double bytes = (double)steps * ((double)listed * 56.0 + (double)n * 17.0 * 8.0);
        printf("kernel=colloid_md threads=%d n=%zu steps=%ld substeps_per_s=%.4g colloid_steps_per_s=%.4g "
               "pairs_in_cutoff=%lld listed_pairs=%lld ns_per_pair=%.3f gbs=%.3g stream_gbs=%.3g "
               "list_builds=%lld time_s_median=%.4g min=%.4g max=%.4g cpu_s_median=%.4g\n",
               t, n, steps, (double)steps / med, (double)steps * (double)n / med, inc, listed,
               med * 1e9 / ((double)steps * (double)inc), bytes / med / 1e9, stream, builds, med, lo, hi, cmed);
        fflush(stdout);
    }
    return 0;
}
