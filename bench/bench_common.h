/* Shared helpers of the benchmarks: pinning, hwloc topology print-out, the
 * STREAM triad measured in the same run, medians.  Header-only so that each
 * benchmark source stays one program (the Makefile builds each bench .c file). */
#ifndef PELOID_BENCH_COMMON_H
#define PELOID_BENCH_COMMON_H

#include <hwloc.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "peloid/fluid.h"

/* libgomp reads OMP_PLACES / OMP_PROC_BIND once, before main: set them and
 * re-execute ourselves so that every thread sweep runs pinned, one thread per
 * core, spread over sockets (bandwidth scales with the sockets used).  A
 * caller's own setting is kept. */
static inline void bench_pin_or_reexec(char **argv)
{
    if (getenv("OMP_PROC_BIND") || getenv("PL_BENCH_NO_PIN")) return;
    setenv("OMP_PLACES", "cores", 0);
    setenv("OMP_PROC_BIND", "spread", 1);
    execv("/proc/self/exe", argv);
    /* execv failed: run unpinned */
}

/* Prints the hwloc tree (packages, NUMA nodes, caches, cores, PUs). */
static inline void bench_print_topology(FILE *f)
{
    hwloc_topology_t topo;
    if (hwloc_topology_init(&topo) || hwloc_topology_load(topo)) {
        fprintf(f, "# topology: hwloc failed\n");
        return;
    }
    int depth = (int)hwloc_topology_get_depth(topo);
    fprintf(f, "# hwloc topology:\n");
    for (int d = 0; d < depth; ++d) {
        int n = (int)hwloc_get_nbobjs_by_depth(topo, d);
        hwloc_obj_t o = hwloc_get_obj_by_depth(topo, d, 0);
        char type[64], attr[128];
        hwloc_obj_type_snprintf(type, sizeof type, o, 1);
        attr[0] = 0;
        hwloc_obj_attr_snprintf(attr, sizeof attr, o, " ", 0);
        fprintf(f, "#   %*s%d x %s %s\n", 2 * d, "", n, type, attr);
    }
    for (hwloc_obj_t o = hwloc_get_next_obj_by_type(topo, HWLOC_OBJ_NUMANODE, NULL); o;
         o = hwloc_get_next_obj_by_type(topo, HWLOC_OBJ_NUMANODE, o))
        fprintf(f, "#   NUMA node %u: %llu MiB\n", o->os_index,
                (unsigned long long)(o->attr ? o->attr->numanode.local_memory >> 20 : 0));
    const char *model = hwloc_obj_get_info_by_name(hwloc_get_root_obj(topo), "CPUModel");
    if (!model) {
        hwloc_obj_t pk = hwloc_get_obj_by_type(topo, HWLOC_OBJ_PACKAGE, 0);
        model = pk ? hwloc_obj_get_info_by_name(pk, "CPUModel") : NULL;
    }
    fprintf(f, "# cpu model: %s\n", model ? model : "unknown");
    fprintf(f, "# OMP_PLACES=%s OMP_PROC_BIND=%s\n", getenv("OMP_PLACES") ? getenv("OMP_PLACES") : "-",
            getenv("OMP_PROC_BIND") ? getenv("OMP_PROC_BIND") : "-");
    hwloc_topology_destroy(topo);
}

static inline int bench_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median, min and max of v[0..n) (v is sorted in place). */
static inline void bench_stats(double *v, int n, double *med, double *lo, double *hi)
{
    qsort(v, (size_t)n, sizeof *v, bench_cmp_double);
    *med = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    *lo = v[0];
    *hi = v[n - 1];
}

/* STREAM triad a = b + s c with `nthreads` threads over n doubles per array,
 * first touch with the same static schedule.  Bytes counted as in STREAM:
 * 24 per element (read b, c; write a; write-allocate not counted).
 * Returns the median GB/s of `reps` timed repetitions (one untimed first);
 * *lo / *hi the spread. */
static inline double bench_stream_triad(size_t n, int nthreads, int reps, double *lo, double *hi)
{
    double *a = aligned_alloc(64, n * sizeof *a), *b = aligned_alloc(64, n * sizeof *b),
           *c = aligned_alloc(64, n * sizeof *c);
    if (!a || !b || !c) {
        free(a); free(b); free(c);
        *lo = *hi = 0.0;
        return 0.0;
    }
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t i = 0; i < n; ++i) {
        a[i] = 0.0;
        b[i] = 1.0;
        c[i] = 2.0;
    }
    double gbs[64];
    if (reps > 64) reps = 64;
    const double s = 3.0;
    for (int r = -1; r < reps; ++r) {
        double t0 = omp_get_wtime();
#pragma omp parallel for schedule(static) num_threads(nthreads)
        for (size_t i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
        double t = omp_get_wtime() - t0;
        if (r >= 0) gbs[r] = 24.0 * (double)n / t * 1e-9;
    }
    if (a[n / 2] != 7.0) fprintf(stderr, "stream triad: wrong result %g\n", a[n / 2]);
    free(a); free(b); free(c);
    double med;
    bench_stats(gbs, reps, &med, lo, hi);
    return med;
}

#endif
