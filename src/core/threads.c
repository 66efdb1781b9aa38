/* The OpenMP thread count of a run or a check, validated before anything
 * is allocated, and the OpenMP settings that would make a region's team
 * differ from it.
 *
 * A count far beyond the machine either fails inside libgomp (a team of
 * 100000 threads crashes in the first parallel region) or runs orders of
 * magnitude slower and allocates threads x cells histograms.
 *
 * The kernels size per-thread arrays (histogram rows, buffers) for the
 * count resolved here and split their work into that many parts; each
 * region hands the parts round-robin to the team it actually got
 * (kernels/omp_parts.h), so a smaller team gives the same bits.  The runtime
 * is still told not to shrink teams (OMP_DYNAMIC, whose libgomp form follows
 * the load average) and the count is capped at OMP_THREAD_LIMIT: a run then
 * gets the team it asked for, which a probe region checks.  Worker threads
 * with too little stack (OMP_STACKSIZE=16K) overflow it inside a kernel, so
 * the probe also measures their stack and refuses one below
 * PL_THREAD_STACK_MIN. */
#include <hwloc.h>
#include <omp.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>

#include "peloid/threads.h"

/* The least stack of an OpenMP worker thread: the shipped scenes need up
 * to 48 KiB at 2 threads (OMP_STACKSIZE=32K fails on scenes/hecht_fig14.cfg,
 * 48K passes), and the kernels' arrays over threads add 4 B per thread
 * (16 KiB at PL_THREADS_MAX): 256 KiB leaves a margin of four. */
#define PL_THREAD_STACK_MIN ((size_t)256 << 10)

int pl_threads_cores(void)
{
    hwloc_topology_t topo;
    if (hwloc_topology_init(&topo)) return 0;
    int n = hwloc_topology_load(topo) ? 0 : hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_CORE);
    hwloc_topology_destroy(topo);
    return n > 0 ? n : 0;
}

/* The stack of the calling thread in bytes (0: unknown). */
static size_t own_stack(void)
{
    pthread_attr_t a;
    size_t s = 0;
    if (pthread_getattr_np(pthread_self(), &a)) return 0;
    if (pthread_attr_getstacksize(&a, &s)) s = 0;
    pthread_attr_destroy(&a);
    return s;
}

/* A region of n threads: the team it got and its workers' least stack
 * (SIZE_MAX without workers; the master runs on the process stack). */
static void probe(int n, int *team, size_t *stack)
{
    int got = 0;
    size_t least = SIZE_MAX;
#pragma omp parallel num_threads(n) reduction(min : least)
    {
        if (omp_get_thread_num() == 0) got = omp_get_num_threads();
        else {
            const size_t s = own_stack();
            if (s && s < least) least = s;
        }
    }
    *team = got;
    *stack = least;
}

int pl_threads_resolve(int requested, int *nthreads, pl_err_t *err)
{
    omp_set_dynamic(0); /* OMP_DYNAMIC=true: libgomp would size teams by the load average */
    int n = requested;
    if (requested > 0) {
        if (requested > PL_THREADS_MAX)
            return pl_err_set(err, PL_ERR_INPUT, "--threads %d: allowed: 1..%d", requested, PL_THREADS_MAX);
    } else {
        n = omp_get_max_threads(); /* OMP_NUM_THREADS (its first entry), else the CPUs */
        if (n < 1 || n > PL_THREADS_MAX) {
            const char *env = getenv("OMP_NUM_THREADS");
            return pl_err_set(err, PL_ERR_INPUT,
                              "OMP_NUM_THREADS=%.40s: %d OpenMP threads; allowed: 1..%d (or --threads N, which "
                              "overrides it)",
                              env ? env : "(unset)", n, PL_THREADS_MAX);
        }
    }
    const int limit = omp_get_thread_limit(); /* OMP_THREAD_LIMIT, else INT_MAX */
    if (limit >= 1 && n > limit) n = limit;
    int team;
    size_t stack;
    probe(n, &team, &stack);
    if (team != n)
        return pl_err_set(err, PL_ERR_INPUT,
                          "OpenMP gave a team of %d of the %d threads asked (OMP_DYNAMIC=%.20s, "
                          "OMP_THREAD_LIMIT=%.20s); allowed: a runtime that grants the count (--threads N or "
                          "OMP_NUM_THREADS)",
                          team, n, getenv("OMP_DYNAMIC") ? getenv("OMP_DYNAMIC") : "(unset)",
                          getenv("OMP_THREAD_LIMIT") ? getenv("OMP_THREAD_LIMIT") : "(unset)");
    if (stack < PL_THREAD_STACK_MIN) {
        const char *env = getenv("OMP_STACKSIZE") ? getenv("OMP_STACKSIZE") : getenv("GOMP_STACKSIZE");
        return pl_err_set(err, PL_ERR_INPUT,
                          "OMP_STACKSIZE=%.40s: OpenMP threads get %zu KiB of stack; allowed: at least %zu KiB "
                          "(unset it, or e.g. OMP_STACKSIZE=1M)",
                          env ? env : "(unset)", stack >> 10, PL_THREAD_STACK_MIN >> 10);
    }
    *nthreads = n;
    return 0;
}
