/* The OpenMP team of a run: its default size and its binding to cores
 * (src/core/thread_bind.c), its validated count (src/core/threads.c).  Every
 * kernel is given the thread count (num_threads clauses); nothing sets a
 * process-wide count. */
#ifndef PELOID_THREADS_H
#define PELOID_THREADS_H

#include "peloid/error.h"

/* The thread count when the user gives none (OMP_NUM_THREADS, else the
 * cores the runtime sees). */
int pl_threads_default(void);

/* Pins OpenMP thread t to the t-th of nthreads core sets spread over the
 * cores of the process's CPU binding (the machine when unbound) by
 * hwloc_distrib (packages first), unless the user chose a binding
 * (OMP_PROC_BIND) or set PL_NO_BIND.  Call before the allocations, whose
 * first touch then places each thread's pages on its own NUMA node. */
void pl_threads_bind(int nthreads);

/* The most OpenMP threads a run or check uses (--threads, OMP_NUM_THREADS). */
#define PL_THREADS_MAX 4096

/* The thread count of a run: `requested` (--threads) when > 0, else the
 * OpenMP default (OMP_NUM_THREADS, else the CPUs); above PL_THREADS_MAX
 * PL_ERR_INPUT naming --threads or OMP_NUM_THREADS (src/core/threads.c). */
int pl_threads_resolve(int requested, int *nthreads, pl_err_t *err);
/* The cores hwloc reports (0: unknown): more threads than cores only slow a
 * run down (its results do not depend on the count). */
int pl_threads_cores(void);

#endif
