/* The parts of a parallel region that splits its work by thread.
 *
 * A run sizes its per-thread arrays (histogram rows, staging buffers,
 * counters) for the thread count it resolved, and a region that splits work
 * by thread splits it into that many parts: part t is the static chunk
 * pl_chunk(t) of the particles, row t of the histogram.  OpenMP may give a
 * region fewer threads than num_threads asks (OMP_DYNAMIC, OMP_THREAD_LIMIT,
 * a nested region), so the parts are handed round-robin to the team it got:
 * member m takes parts m, m + T, m + 2T, ...  Every part is then done
 * exactly once, by one thread, and the result does not depend on the team:
 * the same bits as a full team (tests/unit/test_sort.c, team_of_one). */
#ifndef PL_OMP_PARTS_H
#define PL_OMP_PARTS_H

#include <omp.h>

/* for (int t ...): the parts 0..nparts-1 of the calling team member; use
 * inside the region.  A barrier inside the body is not allowed (members may
 * take different numbers of parts): split the body into loops between
 * barriers instead. */
#define PL_FOR_PART(t, nparts) \
    for (int t = omp_get_thread_num(), t##_team = omp_get_num_threads(); t < (nparts); t += t##_team)

#endif
