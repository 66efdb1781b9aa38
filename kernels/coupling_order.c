/* The order of coupling I's events within a step (kernels/coupling_reflect.c
 * runs them).  An event-driven run takes a colloid's collisions in the
 * order they happen, and each changes the colloid's path and with it the
 * times at which the later particles meet it; so do these:
 *
 *  1. pl_coupling1_order: every particle found by the time it met its
 *     colloid on the paths the MD and the streaming took (entry_time,
 *     2^-32 steps), ties (the particles met only after the events moved
 *     the colloid, and Hecht method i's) in the order of hash(seed,
 *     PL_RNG_REFLECT_ORDER, step, particle), then the particle.  Not a
 *     spatial order: in the counting sort's (z-major) order the lower
 *     events pushed the colloid up before the upper ones met it, and
 *     colloids drifted towards -z (tests/physics/test_coupling_momentum.c).
 *  2. pl_coupling1_chains: the events of each colloid (its candidate: the
 *     first whose enlarged sphere holds the particle) in that order.
 *  3. pl_coupling1_next_event: a colloid's next event is, of those not
 *     taken, the one whose particle met it first on the path the events so
 *     far left it (its moved end position and its velocity now; meet_time),
 *     ties in the chain's order: event-driven order, O(n^2) in the
 *     colloid's n events of a step.  Ordered by the MD's path alone (1
 *     only), light colloids ran cold by ~(xi dt / M)^2 / 20
 *     (validation/REPORT.md, the coupling I note).
 *
 * The order is a function of the particles' state and the colloid's own
 * events: the same for any thread count.  The keys of 1 are found in
 * parallel over the threads' lists, the candidates of 2 over the events;
 * the sort and the chains are serial (events are few). */
#include <math.h>
#include <stdlib.h>

#include "peloid/coupling_kernels.h"
#include "peloid/rng.h"
#include "peloid/srd_kernels.h"

#include "coupling_events.h"

static int cmp_pair(const void *a, const void *b)
{
    const uint64_t *x = a, *y = b;
    return x[0] != y[0] ? (x[0] > y[0]) - (x[0] < y[0]) : (x[1] > y[1]) - (x[1] < y[1]);
}

/* The thread whose static chunk of the streaming (pl_chunk) holds particle i. */
static int chunk_owner(size_t n, int nthreads, size_t i)
{
    int t = (int)((double)i * nthreads / (double)n);
    if (t >= nthreads) t = nthreads - 1;
    for (size_t lo, hi;;) {
        pl_chunk(n, t, nthreads, &lo, &hi);
        if (i < lo) --t;
        else if (i >= hi) ++t;
        else return t;
    }
}

/* The time within the step, as a fraction of it, at which the particle at
 * r (velocity v) met colloid k on the path the events so far left it (e:
 * its moved end position, its velocity now): 1 when outside k (in the
 * margin: met, if at all, once the events have moved the colloid), 1/2
 * when its path does not cross the surface within the step (placed as
 * Hecht method i).  A function of colloid k and the particle alone, so a
 * colloid's events choose the same way in the serial and the parallel
 * loop. */
static double meet_time(const pl_c1_events_t *e, const pl_grid_t *g, const pl_coupling1_params_t *prm, int32_t k,
                        const double r[3], const double v[3])
{
    double p[3] = {r[0] - e->c.x[k], r[1] - e->c.y[k], r[2] - e->c.z[k]};
    for (int a = 0; a < 3; ++a)
        if (g->walls[a] == PL_WALLS_NONE) p[a] -= g->L[a] * nearbyint(p[a] / g->L[a]);
    const double R = e->c.rad[k], pp = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
    if (pp >= R * R) return 1.0;
    const double w[3] = {v[0] - e->c.vx[k], v[1] - e->c.vy[k], v[2] - e->c.vz[k]};
    const double ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2], pw = p[0] * w[0] + p[1] * w[1] + p[2] * w[2];
    const double disc = pw * pw - ww * (pp - R * R);
    const double s = ww > 0.0 && disc >= 0.0 ? (pw + sqrt(disc)) / ww : -1.0;
    return s > 0.0 && s <= prm->dt ? 1.0 - s / prm->dt : 0.5;
}

/* meet_time for the colloid the particle is inside (the first of its
 * cell list), 1 when none. */
static double entry_time(const pl_c1_events_t *e, const pl_grid_t *g, const pl_coupling1_params_t *prm,
                         const double r[3], const double v[3])
{
    double p[3];
    const int32_t k = pl_coupling_inside_cells(&e->c, g, e->cstart, e->clist, r, p);
    return k < 0 ? 1.0 : meet_time(e, g, prm, k, r, v);
}

/* The next event of colloid sc->k[j]'s chain (j its first event not yet
 * taken): of those not taken, the one that met the colloid first on its
 * path as the events so far left it (meet_time; ties: the first in the
 * order), as an event-driven run would take them: an event changes the
 * colloid's path, and with it the times at which the later particles met
 * it (ordered by the MD's path alone, light colloids ran cold by ~(xi dt /
 * M)^2 / 20: 0.8 % at M = 33.5 m_f, R = 2 a0, dt = 0.1, stick).  -1 when
 * the chain is done.  O(events of the colloid) per event. */
int64_t pl_coupling1_next_event(const pl_c1_events_t *e, const pl_grid_t *g, const pl_coupling1_params_t *prm,
                                const pl_fluid_t *f, const pl_coupling1_scratch_t *sc, size_t j)
{
    const int32_t k = sc->k[j];
    int64_t best = -1;
    double tb = INFINITY;
    for (int64_t q = (int64_t)j; q >= 0; q = sc->next[q]) {
        if (sc->taken[q]) continue;
        const size_t i = sc->idx[q];
        const double r[3] = {f->r[0][i], f->r[1][i], f->r[2][i]}, v[3] = {f->v[0][i], f->v[1][i], f->v[2][i]};
        const double t = meet_time(e, g, prm, k, r, v);
        if (t < tb) {
            tb = t;
            best = q;
        }
    }
    return best;
}

/* The step's first order (1 of the file header): by the time each
 * particle met its colloid (entry_time, 2^-32 steps), then by the key
 * hash(seed, PL_RNG_REFLECT_ORDER, step, particle), then by particle;
 * sc->idx[j] the particle, sc->owner[j] the thread whose histogram row
 * holds its cell, for j < total.  The keys are found in parallel over the
 * threads' lists (e: no event yet, the colloids where the MD left them);
 * the sort is serial (events are few). */
void pl_coupling1_order(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *prm,
                        const pl_c1_events_t *e, int nthreads, const uint32_t *found, const uint64_t *counts,
                        size_t total, pl_coupling1_scratch_t *sc)
{
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (int t = 0; t < nthreads; ++t) {
        size_t lo, hi, j = 0;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        for (int u = 0; u < t; ++u) j += counts[(size_t)u * 8 + 2];
        const size_t nt = counts[(size_t)t * 8 + 2];
        for (size_t s = 0; s < nt; ++s) {
            const uint64_t i = found[lo + s];
            const double r[3] = {f->r[0][i], f->r[1][i], f->r[2][i]}, v[3] = {f->v[0][i], f->v[1][i], f->v[2][i]};
            const double tq = ldexp(entry_time(e, g, prm, r, v), 32);
            philox4x64_ctr_t ctr = {{prm->step, i, 0, 0}};
            philox4x64_key_t key = {{prm->seed, PL_RNG_REFLECT_ORDER}};
            sc->key[2 * (j + s)] = (tq >= 0x1p32 ? 0xffffffffu : (uint64_t)tq) << 32 | philox4x64(ctr, key).v[0] >> 32;
            sc->key[2 * (j + s) + 1] = i;
        }
    }
    qsort(sc->key, total, 2 * sizeof *sc->key, cmp_pair);
    for (size_t j = 0; j < total; ++j) {
        sc->idx[j] = (uint32_t)sc->key[2 * j + 1];
        sc->owner[j] = chunk_owner(f->n, nthreads, sc->idx[j]);
    }
}

/* Each event's candidate colloid sc->k (the first whose enlarged sphere
 * holds the particle: cb does not change) and the chains of the colloids'
 * events in order (sc->next, -1 at the end; sc->head: scratch), none
 * taken yet. */
void pl_coupling1_chains(const pl_fluid_t *f, const pl_grid_t *g, const pl_c1_events_t *e, int nthreads,
                         size_t total, pl_coupling1_scratch_t *sc)
{
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t j = 0; j < total; ++j) {
        const size_t i = sc->idx[j];
        const double r[3] = {f->r[0][i], f->r[1][i], f->r[2][i]};
        double q[3];
        sc->k[j] = pl_coupling_inside_cells(e->cb, g, e->cstart, e->clist, r, q);
    }
    for (size_t k = 0; k < e->c.n; ++k) sc->head[k] = -1;
    for (size_t j = total; j-- > 0;) {
        const int32_t k = sc->k[j];
        sc->next[j] = k >= 0 ? sc->head[k] : -1;
        if (k >= 0) sc->head[k] = (int64_t)j;
        sc->taken[j] = 0;
        sc->done[j] = 0;
    }
}

