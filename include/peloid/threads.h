/* The OpenMP team of a run (kernels/thread_bind.c): its default size and its
 * binding to cores.  Every kernel is given the thread count (num_threads
 * clauses); nothing sets a process-wide count. */
#ifndef PELOID_THREADS_H
#define PELOID_THREADS_H

/* The thread count when the user gives none (OMP_NUM_THREADS, else the
 * cores the runtime sees). */
int pl_threads_default(void);

/* Pins OpenMP thread t to the t-th of nthreads core sets spread over the
 * cores of the process's CPU binding (the machine when unbound) by
 * hwloc_distrib (packages first), unless the user chose a binding
 * (OMP_PROC_BIND) or set PL_NO_BIND.  Call before the allocations, whose
 * first touch then places each thread's pages on its own NUMA node. */
void pl_threads_bind(int nthreads);

#endif
