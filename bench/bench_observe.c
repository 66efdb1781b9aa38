/* Throughput of the observable kernels (issue 14), for 1 and 2 threads (the
 * serial ones once): g(r) pair count (ns per pair distance), the
 * multiple-tau update (ns per particle and sample), cluster search (ns per
 * particle), blocking (ns per sample).  Uniform random colloids.  One line
 * per case, median of 5 repetitions:
 *   kernel threads n ns_per_<unit> */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_common.h"
#include "peloid/blocking.h"
#include "peloid/cluster.h"
#include "peloid/mtau.h"
#include "peloid/rdf.h"
#include "peloid/rng.h"

enum { REPS = 5 };

static double median(double *v)
{
    double med, lo, hi;
    bench_stats(v, REPS, &med, &lo, &hi);
    return med;
}

int main(int argc, char **argv)
{
    (void)argc;
    bench_pin_or_reexec(argv);
    const size_t n = 4096;
    const double L = 32.0;
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *z = malloc(n * sizeof *z);
    double *rad = malloc(n * sizeof *rad);
    for (size_t i = 0; i < n; ++i) {
        pl_rand4_t u = pl_rng_uniform4(14, 1, 0, i, 0);
        x[i] = L * u.u[0], y[i] = L * u.u[1], z[i] = L * u.u[2];
        rad[i] = 0.5 + 0.25 * u.u[3];
    }
    pl_err_t err = {0, ""};
    double t[REPS];
    int maxt = omp_get_num_procs() < 2 ? 1 : 2;
    for (int th = 1; th <= maxt; ++th) {
        pl_rdf_params_t rp = {.box = {L, L, L}, .rmax = 8.0, .nbins = 200, .class_a = -1, .class_b = -1};
        pl_rdf_t *r;
        if (pl_rdf_create(&rp, th, &r, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
        for (int k = 0; k < REPS; ++k) {
            double t0 = omp_get_wtime();
            pl_rdf_sample(r, n, x, y, z, NULL);
            t[k] = omp_get_wtime() - t0;
        }
        printf("kernel=rdf_count threads=%d n=%zu ns_per_pair=%.3f\n", th, n,
               median(t) * 1e9 / (0.5 * (double)n * (double)(n - 1)));
        pl_rdf_free(r);

        pl_mtau_params_t mp = {.n = n, .p = 16, .m = 2, .levels = 16, .kind = PL_MTAU_MSD, .dt = 1.0};
        pl_mtau_t *c;
        if (pl_mtau_create(&mp, &c, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
        const int ns = 1024;
        for (int k = 0; k < REPS; ++k) {
            double t0 = omp_get_wtime();
            for (int s = 0; s < ns; ++s) pl_mtau_add(c, x, y, z, th);
            t[k] = omp_get_wtime() - t0;
        }
        printf("kernel=mtau_push threads=%d n=%zu ns_per_particle_sample=%.3f\n", th, n,
               median(t) * 1e9 / ((double)n * ns));
        pl_mtau_free(c);
    }
    pl_cluster_params_t cp = {.box = {L, L, L}, .periodic = {1, 1, 1}, .gap = 0.1, .rad_max = 0.75, .nmax = n};
    pl_cluster_t *cl;
    if (pl_cluster_create(&cp, &cl, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
    for (int k = 0; k < REPS; ++k) {
        double t0 = omp_get_wtime();
        pl_cluster_find(cl, n, x, y, z, rad, &err);
        t[k] = omp_get_wtime() - t0;
    }
    printf("kernel=cluster_find threads=1 n=%zu ns_per_particle=%.3f clusters=%zu\n", n,
           median(t) * 1e9 / (double)n, pl_cluster_count(cl));
    pl_cluster_free(cl);
    pl_blocking_t b;
    const size_t nb = (size_t)1 << 22;
    for (int k = 0; k < REPS; ++k) {
        pl_blocking_init(&b);
        double t0 = omp_get_wtime();
        for (size_t i = 0; i < nb; ++i) pl_blocking_add(&b, x[i & (n - 1)]);
        t[k] = omp_get_wtime() - t0;
    }
    printf("kernel=blocking_add threads=1 n=%zu ns_per_sample=%.3f se=%.3g\n", nb, median(t) * 1e9 / (double)nb,
           pl_blocking_result(&b).se);
    free(x), free(y), free(z), free(rad);
    return 0;
}
