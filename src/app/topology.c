/* Machine topology summary through hwloc (echoed in summary.json). */
#include <hwloc.h>
#include <stdio.h>

#include "peloid/topology.h"

void pl_topology_summary(char *buf, size_t n)
{
    hwloc_topology_t topo;
    if (hwloc_topology_init(&topo) || hwloc_topology_load(topo)) {
        snprintf(buf, n, "unknown (hwloc failed)");
        return;
    }
    int pk = hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_PACKAGE);
    int co = hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_CORE);
    int pu = hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_PU);
    int nu = hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_NUMANODE);
    hwloc_obj_t l3 = hwloc_get_obj_by_type(topo, HWLOC_OBJ_L3CACHE, 0);
    unsigned long long l3kb = l3 && l3->attr ? (unsigned long long)l3->attr->cache.size / 1024 : 0;
    snprintf(buf, n, "%d package(s), %d core(s), %d PU(s), %d NUMA node(s), L3 %llu KiB", pk, co, pu,
             nu, l3kb);
    hwloc_topology_destroy(topo);
}
