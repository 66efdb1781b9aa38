/* The observers' checks beyond one key's range, where they need the
 * colloids themselves or an estimate of the work (src/observe/observe_check.c). */
#ifndef PELOID_OBSERVE_CHECK_H
#define PELOID_OBSERVE_CHECK_H

#include "peloid/cluster.h"
#include "peloid/colloid.h"

/* The cluster search's box, largest radius and bond range for colloids c
 * (energy bonds: every pair within the pair cut-off). */
pl_cluster_params_t pl_observe_cluster_params(const pl_scene_t *scene, const pl_colloid_t *c);

/* The bond range pl_cluster_create would refuse, as PL_ERR_INPUT naming
 * observe.clusters_gap (or clusters_bond); run at `check` and when a run
 * creates its observers, before any output. */
int pl_observe_check_colloids(const pl_scene_t *scene, const pl_colloid_t *c, pl_err_t *err);

/* S(q)'s terms per sample, N x the wave vectors of |q| < sq_qmax (O(1)):
 * above 1e10 PL_ERR_INPUT naming observe.sq_qmax. */
int pl_observe_sq_cost_check(const pl_scene_t *scene, pl_err_t *err);

#endif
