/* Scene struct of the observers (section `observe`; schema in
 * src/scene/scene_keys_observe.c).  Included by scene.h; plain data and one
 * accessor.  An interval of 0 leaves the observer out of the plan. */
#ifndef PELOID_OBSERVE_SCENE_H
#define PELOID_OBSERVE_SCENE_H

#include <stddef.h>

enum { PL_BOND_GAP = 0, PL_BOND_ENERGY = 1 }; /* observe.clusters_bond */

typedef struct {
    long long rdf_interval, rdf_start; /* colloid g(r) */
    long long rdf_bins;
    double rdf_rmax;                   /* 0: the largest the box allows */
    long long rdf_size_classes;        /* 0: off; k >= 2: partial g_ab of k radius classes */
    long long sq_interval, sq_start, sq_bins; /* colloid S(q), periodic boxes */
    double sq_qmax;                    /* 1/a0; 0: 4 pi / colloids.radius */
    long long msd_interval, msd_start; /* colloid MSD, multiple-tau */
    long long vacf_interval, vacf_start; /* colloid VACF and Green-Kubo D */
    long long cff_interval, cff_start; /* fluid force autocorrelation C_FF and Green-Kubo friction */
    long long clusters_interval, clusters_start;
    double clusters_gap;               /* bond: surface gap below this */
    int clusters_bond;                 /* PL_BOND_GAP | PL_BOND_ENERGY */
    double clusters_energy;            /* energy bond: pair energy below -this (kT_ref) */
    long long vdist_interval, vdist_start; /* velocity distributions against Maxwell-Boltzmann */
    long long sediment_interval, sediment_start, sediment_bins; /* phi(z, t), settling velocity */
    long long steinhardt_interval, steinhardt_start; /* bond-orientational order Q4, Q6 */
    double steinhardt_rmax;            /* its neighbour cut-off */
    long long stress_interval, stress_start, stress_gk_steps; /* fluid stress, Green-Kubo viscosity */
    double target_rel_error;           /* the error-against-time report's target */
    char average_from[128];            /* the time averages' window (peloid/window.h): "auto", "start", t, "p%" */
} pl_scene_observe_t;

/* The long long key at byte offset off (offsetof(pl_scene_observe_t, ...)):
 * for the observers' tables of interval and start keys. */
static inline long long pl_scene_observe_ll(const pl_scene_observe_t *so, size_t off)
{
    return *(const long long *)((const char *)so + off);
}

/* Section `stop`: end the run when an observable's relative SE reaches
 * rel_error (checked every check_interval steps, from the state only: the
 * same step for any thread count), or after max_wall_s of wall time. */
typedef struct {
    char observable[128]; /* "none", or an observer's estimate (peloid/observer.h) */
    double rel_error;
    long long check_interval;
    double max_wall_s; /* 0: no wall-time limit */
} pl_scene_stop_t;

#endif
