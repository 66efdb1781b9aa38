/* Thread placement (DESIGN.md "Performance contract"): the OpenMP team of a
 * run is bound to cores spread over the machine before the first allocation
 * (over the process's own CPU binding: a sweep's job, taskset, a Slurm task),
 * whose first touch (src/core/first_touch.c) then places each thread's pages
 * on its own NUMA node.  The one parallel region of peloid that is not a loop
 * over data: each thread of the team binds itself. */
#include <hwloc.h>
#include <limits.h>
#include <omp.h>
#include <stdlib.h>

#include "peloid/threads.h"

int pl_threads_default(void)
{
    return omp_get_max_threads();
}

void pl_threads_bind(int nthreads)
{
    if (nthreads < 2 || omp_get_proc_bind() != omp_proc_bind_false || getenv("PL_NO_BIND")) return;
    hwloc_topology_t topo;
    if (hwloc_topology_init(&topo)) return;
    if (hwloc_topology_load(topo)) {
        hwloc_topology_destroy(topo);
        return;
    }
    /* only the cores this process may run on: two sweep jobs of 2 threads
     * each must not both spread over the whole machine */
    hwloc_bitmap_t own = hwloc_bitmap_alloc();
    if (own && !hwloc_get_cpubind(topo, own, HWLOC_CPUBIND_PROCESS) && !hwloc_bitmap_iszero(own))
        hwloc_topology_restrict(topo, own, 0);
    hwloc_bitmap_free(own);
    int ncores = hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_CORE);
    if (ncores >= nthreads && nthreads <= 1024) {
        hwloc_bitmap_t sets[1024];
        hwloc_obj_t root = hwloc_get_root_obj(topo);
        if (hwloc_distrib(topo, &root, 1, sets, (unsigned)nthreads, INT_MAX, 0) == 0) {
            /* a region, not a loop: hwloc binds the calling thread, so each
             * thread of the team binds itself, and the runtime keeps these
             * threads for the kernels' regions that follow */
#pragma omp parallel num_threads(nthreads)
            {
                hwloc_bitmap_t set = sets[omp_get_thread_num()];
                hwloc_bitmap_singlify(set);
                hwloc_set_cpubind(topo, set, HWLOC_CPUBIND_THREAD);
            }
            for (int t = 0; t < nthreads; ++t) hwloc_bitmap_free(sets[t]);
        }
    }
    hwloc_topology_destroy(topo);
}
