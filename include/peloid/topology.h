/* The machine as hwloc sees it, for the run's log and summary.json
 * (src/app/topology.c). */
#ifndef PELOID_TOPOLOGY_H
#define PELOID_TOPOLOGY_H

#include <stddef.h>

/* hwloc topology summary, e.g. "1 package, 2 cores, 2 PUs, 1 NUMA node". */
void pl_topology_summary(char *buf, size_t n);

#endif
