/* The machine's cost of OpenMP synchronisation at 2 threads (or
 * PL_BENCH_THREADS): an empty parallel region (fork/join) and a barrier
 * inside one region, each the median of REPS timings of 1e5 repetitions,
 * pinned as the other benchmarks are.  The colloid MD step is short (~0.2 ms
 * for the Fig. 14 model on 2 cores), so these costs, which differ by an
 * order of magnitude between bare metal and a VM, bound its thread scaling;
 * RESULTS_colloid.md quotes them next to the MD figures of the same machine.
 *   bench_omp_overhead [REPS]      (default 5)
 * One line: kernel threads region_us barrier_us (median, min..max). */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_common.h"

enum { NREP = 100000 };

int main(int argc, char **argv)
{
    bench_pin_or_reexec(argv);
    int reps = argc > 1 ? atoi(argv[1]) : 5;
    if (reps < 1 || reps > 64) reps = 5;
    int t = getenv("PL_BENCH_THREADS") ? atoi(getenv("PL_BENCH_THREADS")) : 2;
    if (t > omp_get_num_procs()) t = omp_get_num_procs();
    if (t < 1) t = 1;
    double region[64], barrier[64];
    volatile int sink = 0;
    for (int r = 0; r < reps; ++r) {
        double t0 = omp_get_wtime();
        for (int k = 0; k < NREP; ++k) {
#pragma omp parallel num_threads(t)
            {
                if (omp_get_thread_num() == 0) sink = k;
            }
        }
        double t1 = omp_get_wtime();
#pragma omp parallel num_threads(t)
        {
            for (int k = 0; k < NREP; ++k) {
#pragma omp barrier
            }
        }
        double t2 = omp_get_wtime();
        region[r] = (t1 - t0) / NREP * 1e6;
        barrier[r] = (t2 - t1) / NREP * 1e6;
    }
    (void)sink;
    double rm, rlo, rhi, bm, blo, bhi;
    bench_stats(region, reps, &rm, &rlo, &rhi);
    bench_stats(barrier, reps, &bm, &blo, &bhi);
    bench_print_topology(stdout);
    printf("kernel=omp_overhead threads=%d region_us=%.3f min=%.3f max=%.3f barrier_us=%.3f min=%.3f max=%.3f\n",
           t, rm, rlo, rhi, bm, blo, bhi);
    return 0;
}
