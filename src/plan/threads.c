/* The OpenMP thread count of a run or a check, validated before anything
 * is allocated: a count far beyond the machine either fails inside libgomp
 * (a team of 100000 threads crashes in the first parallel region) or runs
 * orders of magnitude slower and allocates threads x cells histograms. */
#include <hwloc.h>
#include <omp.h>
#include <stdlib.h>

#include "peloid/run.h"

int pl_threads_cores(void)
{
    hwloc_topology_t topo;
    if (hwloc_topology_init(&topo)) return 0;
    int n = hwloc_topology_load(topo) ? 0 : hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_CORE);
    hwloc_topology_destroy(topo);
    return n > 0 ? n : 0;
}

int pl_threads_resolve(int requested, int *nthreads, pl_err_t *err)
{
    if (requested > 0) {
        if (requested > PL_THREADS_MAX)
            return pl_err_set(err, PL_ERR_INPUT, "--threads %d: allowed: 1..%d", requested, PL_THREADS_MAX);
        *nthreads = requested;
        return 0;
    }
    int n = omp_get_max_threads(); /* OMP_NUM_THREADS (its first entry), else the CPUs */
    if (n < 1 || n > PL_THREADS_MAX) {
        const char *env = getenv("OMP_NUM_THREADS");
        return pl_err_set(err, PL_ERR_INPUT,
                          "OMP_NUM_THREADS=%.40s: %d OpenMP threads; allowed: 1..%d (or --threads N, which "
                          "overrides it)",
                          env ? env : "(unset)", n, PL_THREADS_MAX);
    }
    *nthreads = n;
    return 0;
}
