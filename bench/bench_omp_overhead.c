/* The machine's cost of OpenMP synchronisation at 2 threads (or
 * PL_BENCH_THREADS): an empty parallel region (fork/join) and a barrier
 * inside one region, each the median of REPS timings of 1e5 repetitions,
 * pinned as the other benchmarks are.  The colloid MD step is short (~0.2 ms
 * for the Fig. 14 model on 2 cores), so these costs, which differ by an
 * order of magnitude between bare metal and a VM, bound its thread scaling;
 * RESULTS_colloid.md quotes them next to the MD figures of the same machine.
 * Also the round trip of one cache line between threads 0 and 1 (a flag
 * bounced NPING times, each side waiting for the other's store): the cost
 * of every value one thread writes and another then reads, such as the
 * colloid pair forces read back in pass 2, which a VM's vCPUs on distant
 * cores make several times the on-chip latency.
 *   bench_omp_overhead [REPS]      (default 5)
 * One line: kernel threads region_us barrier_us pingpong_ns (median,
 * min..max). */
#include <omp.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_common.h"

enum { NREP = 100000, NPING = 100000 };

/* Round trip in ns of a cache line between threads 0 and 1 of a team of t
 * (> 1): thread 0 stores odd values and waits for the next even one. */
static double pingpong_ns(int t)
{
    _Atomic long flag = 0;
    double ns = 0.0;
#pragma omp parallel num_threads(t)
    {
        const int me = omp_get_thread_num();
#pragma omp barrier
        if (me == 0) {
            double t0 = omp_get_wtime();
            for (long k = 0; k < NPING; ++k) {
                atomic_store_explicit(&flag, 2 * k + 1, memory_order_release);
                while (atomic_load_explicit(&flag, memory_order_acquire) != 2 * k + 2) {
                }
            }
            ns = (omp_get_wtime() - t0) / NPING * 1e9;
        } else if (me == 1) {
            for (long k = 0; k < NPING; ++k) {
                while (atomic_load_explicit(&flag, memory_order_acquire) != 2 * k + 1) {
                }
                atomic_store_explicit(&flag, 2 * k + 2, memory_order_release);
            }
        }
    }
    return ns;
}

int main(int argc, char **argv)
{
    bench_pin_or_reexec(argv);
    int reps = argc > 1 ? atoi(argv[1]) : 5;
    if (reps < 1 || reps > 64) reps = 5;
    int t = getenv("PL_BENCH_THREADS") ? atoi(getenv("PL_BENCH_THREADS")) : 2;
    if (t > omp_get_num_procs()) t = omp_get_num_procs();
    if (t < 1) t = 1;
    double region[64], barrier[64], ping[64];
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
        ping[r] = t > 1 ? pingpong_ns(t) : 0.0;
    }
    (void)sink;
    double rm, rlo, rhi, bm, blo, bhi, pm, plo, phi;
    bench_stats(region, reps, &rm, &rlo, &rhi);
    bench_stats(barrier, reps, &bm, &blo, &bhi);
    bench_stats(ping, reps, &pm, &plo, &phi);
    bench_print_topology(stdout);
    printf("kernel=omp_overhead threads=%d region_us=%.3f min=%.3f max=%.3f barrier_us=%.3f min=%.3f max=%.3f "
           "pingpong_ns=%.1f min=%.1f max=%.1f\n",
           t, rm, rlo, rhi, bm, blo, bhi, pm, plo, phi);
    return 0;
}
