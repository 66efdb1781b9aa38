/* First touch of a fresh allocation: the pages are zeroed in parallel with
 * the static schedule the kernels use, so that on a NUMA machine each page
 * lands on the node of the thread that will stream it. */
#include <string.h>

#include "peloid/fluid.h"

void pl_first_touch(void *mem, size_t bytes, int nthreads)
{
    char *p = mem;
    const size_t page = 4096;
    size_t npages = (bytes + page - 1) / page;
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t i = 0; i < npages; ++i) {
        size_t lo = i * page, hi = lo + page < bytes ? lo + page : bytes;
        memset(p + lo, 0, hi - lo);
    }
}
