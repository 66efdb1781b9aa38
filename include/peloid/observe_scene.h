/* Scene struct of the observers (section `observe`; schema in
 * src/scene_keys_observe.c).  Included by scene.h; plain data only.  An
 * interval of 0 leaves the observer out of the plan. */
#ifndef PELOID_OBSERVE_SCENE_H
#define PELOID_OBSERVE_SCENE_H

typedef struct {
    long long rdf_interval, rdf_start; /* colloid g(r) */
    long long rdf_bins;
    double rdf_rmax;                   /* 0: the largest the box allows */
    long long msd_interval, msd_start; /* colloid MSD, multiple-tau */
    long long clusters_interval, clusters_start;
    double clusters_gap;               /* bond: surface gap below this */
    double target_rel_error;           /* the error-against-time report's target */
} pl_scene_observe_t;

#endif
