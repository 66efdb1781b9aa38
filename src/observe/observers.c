/* The observer table (peloid/observer.h): one row per observer, in the
 * order of their plan stages, observables.h5 groups, summary.json entries
 * and checkpoint items.  Adding an observer is its file and one row here
 * (and its keys). */
#include "peloid/observer.h"

extern const pl_observer_t pl_observer_rdf, pl_observer_sq, pl_observer_msd, pl_observer_vacf, pl_observer_cff,
    pl_observer_clusters, pl_observer_vdist, pl_observer_sediment, pl_observer_steinhardt;

const pl_observer_t *const pl_observers[] = {
    &pl_observer_rdf,      /* obs_rdf.c: g(r), rdf_peak */
    &pl_observer_sq,       /* obs_sq.c: S(q) */
    &pl_observer_msd,      /* obs_mtau.c: MSD, colloid_D */
    &pl_observer_vacf,     /* obs_mtau.c: VACF, Green-Kubo D */
    &pl_observer_cff,      /* obs_mtau.c: C_FF, Green-Kubo friction */
    &pl_observer_clusters, /* obs_clusters.c: clusters */
    &pl_observer_vdist,    /* obs_vdist.c: velocity distributions */
    &pl_observer_sediment, /* obs_sediment.c: phi(z), settling velocity */
    &pl_observer_steinhardt, /* obs_steinhardt.c: bond order Q4, Q6 */
};
const int pl_nobservers = (int)(sizeof pl_observers / sizeof pl_observers[0]);
