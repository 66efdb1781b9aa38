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
 *  3. pl_coupling1_chain_next: a colloid's next event is, of those not
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
#include <string.h>

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

/* The time within the step, as a fraction of it, at which a particle at p
 * (relative to colloid k's moved end position, minimum image taken) moving
 * at w (relative to the colloid's velocity now) met k's sphere of radius R:
 * 1 when outside it (in the margin: met, if at all, once the events have
 * moved the colloid), 1/2 when its path does not cross the surface within
 * the step dt (placed as Hecht method i).  Selects, no branch: chain_times
 * runs it in SIMD lanes, where a lane that does not cross computes on
 * harmless operands; the same values as a scalar call (no fused
 * multiply-adds: -ffp-contract=off; division and square root are IEEE's in
 * either). */
static inline __attribute__((always_inline)) double meet_of(double px, double py, double pz, double wx, double wy,
                                                            double wz, double R, double dt)
{
    const double pp = px * px + py * py + pz * pz;
    const double ww = wx * wx + wy * wy + wz * wz, pw = px * wx + py * wy + pz * wz;
    const double disc = pw * pw - ww * (pp - R * R);
    const int cross = ww > 0.0 && disc >= 0.0;
    const double s = cross ? (pw + sqrt(cross ? disc : 0.0)) / (cross ? ww : 1.0) : -1.0;
    const double tin = s > 0.0 && s <= dt ? 1.0 - s / dt : 0.5;
    return pp >= R * R ? 1.0 : tin;
}

/* The minimum image of a separation p on an axis of length L (h = L/2;
 * pL = L, or 0 on a closed axis, which subtracts nothing): |p| < 3L/2
 * here (both ends within a margin of the box), where p - L nearbyint(p / L)
 * is p - L exactly when p > L/2 (p / L then rounds above 1/2: p - L/2 is at
 * least an ulp of L/2, more than 2^-54 L, and 1/2's upper neighbour is
 * 1/2 + 2^-53), p + L when p < -L/2, else p (1/2 itself rounds to even):
 * the same values without a division. */
static inline __attribute__((always_inline)) double near_image(double p, double h, double pL)
{
    return p > h ? p - pL : p < -h ? p + pL : p;
}

/* meet_of for the particle at r (velocity v) and colloid k as the events
 * so far left it (e: its moved end position, its velocity now).  A function
 * of colloid k and the particle alone, so a colloid's events choose the
 * same way in the serial and the parallel loop. */
static double meet_time(const pl_c1_events_t *e, const pl_grid_t *g, const pl_coupling1_params_t *prm, int32_t k,
                        const double r[3], const double v[3])
{
    double p[3] = {r[0] - e->c.x[k], r[1] - e->c.y[k], r[2] - e->c.z[k]};
    for (int a = 0; a < 3; ++a)
        if (g->walls[a] == PL_WALLS_NONE) p[a] = near_image(p[a], 0.5 * g->L[a], g->L[a]);
    return meet_of(p[0], p[1], p[2], v[0] - e->c.vx[k], v[1] - e->c.vy[k], v[2] - e->c.vz[k], e->c.rad[k], prm->dt);
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

/* The meet times (meet_time) of a chain's m untaken particles (r, v: its
 * gathered copies, t: out) for colloid k as the events so far left it, in
 * SIMD lanes (meet_of; the minimum image as meet_time's). */
static void chain_times(const pl_c1_events_t *e, const pl_grid_t *g, const pl_coupling1_params_t *prm, int32_t k,
                        double *const r[7], size_t m)
{
    const double X = e->c.x[k], Y = e->c.y[k], Z = e->c.z[k];
    const double VX = e->c.vx[k], VY = e->c.vy[k], VZ = e->c.vz[k];
    const double R = e->c.rad[k], dt = prm->dt;
    /* meet_time's minimum image (near_image); a closed axis subtracts nothing, as meet_time's skip */
    double pL[3], h[3];
    for (int a = 0; a < 3; ++a) {
        pL[a] = g->walls[a] == PL_WALLS_NONE ? g->L[a] : 0.0;
        h[a] = 0.5 * g->L[a];
    }
    const double *restrict rx = r[0], *restrict ry = r[1], *restrict rz = r[2];
    const double *restrict vx = r[3], *restrict vy = r[4], *restrict vz = r[5];
    double *restrict t = r[6];
    /* gcc vectorises this loop only when asked; clang, asked, warns where
     * its sqrt may set errno (as in peloid/srd_rules.h) */
#if !defined(__clang__)
#pragma omp simd
#endif
    for (size_t q = 0; q < m; ++q) {
        double px = rx[q] - X, py = ry[q] - Y, pz = rz[q] - Z;
        px = near_image(px, h[0], pL[0]);
        py = near_image(py, h[1], pL[1]);
        pz = near_image(pz, h[2], pL[2]);
        t[q] = meet_of(px, py, pz, vx[q] - VX, vy[q] - VY, vz[q] - VZ, R, dt);
    }
}

/* Colloid sc->k[j]'s chain from its head j: its untaken events' particles
 * (r, v) copied in chain order to the chain's own part of sc->chain and
 * sc->cq (sc->cbeg: threads taking other colloids write elsewhere); their
 * number.  The copies stay true while the chain runs: an event changes its
 * own particle only, and each particle is one event's. */
size_t pl_coupling1_chain_gather(const pl_fluid_t *f, pl_coupling1_scratch_t *sc, size_t j)
{
    const int64_t base = sc->cbeg[sc->k[j]];
    size_t m = 0;
    for (int64_t q = (int64_t)j; q >= 0; q = sc->next[q]) {
        if (sc->taken[q]) continue;
        const size_t i = sc->idx[q], s = (size_t)base + m++;
        for (int d = 0; d < 3; ++d) {
            sc->chain[(size_t)d * sc->cap + s] = f->r[d][i];
            sc->chain[(size_t)(3 + d) * sc->cap + s] = f->v[d][i];
        }
        sc->cq[s] = q;
    }
    return m;
}

/* The next event of colloid k's gathered chain (*m untaken left): of
 * those, the one that met the colloid first on its path as the events so
 * far left it (meet_time; ties: the first in the chain's order), as an
 * event-driven run would take them: an event changes the colloid's path,
 * and with it the times at which the later particles met it (ordered by
 * the MD's path alone, light colloids ran cold by ~(xi dt / M)^2 / 20: 0.8
 * % at M = 33.5 m_f, R = 2 a0, dt = 0.1, stick).  It is taken out of the
 * chain (the rest keep their order); -1 when the chain is done.  O(*m) per
 * event, in SIMD lanes over contiguous copies: the linked chain's scattered
 * reads of the fluid arrays, n^2 / 2 of them a step, were the cost of
 * large colloids (bench/RESULTS.md). */
int64_t pl_coupling1_chain_next(const pl_c1_events_t *e, const pl_grid_t *g, const pl_coupling1_params_t *prm,
                                pl_coupling1_scratch_t *sc, int32_t k, size_t *m)
{
    if (*m == 0) return -1;
    const size_t base = (size_t)sc->cbeg[k], n = *m;
    double *r[7];
    for (int d = 0; d < 7; ++d) r[d] = sc->chain + (size_t)d * sc->cap + base;
    chain_times(e, g, prm, k, r, n);
    /* the first minimum: the least time, in eight independent lanes (a min is exact in any order; no time is
     * NaN), then the first particle in chain order that has it */
    const double *restrict tq = r[6];
    double lane[8];
    for (size_t l = 0; l < 8; ++l) lane[l] = tq[0];
    size_t q = 0;
    for (; q + 8 <= n; q += 8)
        for (size_t l = 0; l < 8; ++l) lane[l] = tq[q + l] < lane[l] ? tq[q + l] : lane[l];
    for (; q < n; ++q) lane[0] = tq[q] < lane[0] ? tq[q] : lane[0];
    double tb = lane[0];
    for (size_t l = 1; l < 8; ++l) tb = lane[l] < tb ? lane[l] : tb;
    size_t best = 0;
    while (tq[best] != tb) ++best;
    const int64_t b = sc->cq[base + best];
    for (int d = 0; d < 6; ++d) memmove(r[d] + best, r[d] + best + 1, (n - best - 1) * sizeof *r[d]);
    memmove(sc->cq + base + best, sc->cq + base + best + 1, (n - best - 1) * sizeof *sc->cq);
    *m = n - 1;
    return b;
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
    for (size_t k = 0; k <= e->c.n; ++k) sc->head[k] = -1, sc->cbeg[k] = 0;
    for (size_t j = total; j-- > 0;) {
        const int32_t k = sc->k[j];
        sc->next[j] = k >= 0 ? sc->head[k] : -1;
        if (k >= 0) sc->head[k] = (int64_t)j, sc->cbeg[k + 1]++;
        sc->taken[j] = 0;
        sc->done[j] = 0;
    }
    for (size_t k = 0; k < e->c.n; ++k) sc->cbeg[k + 1] += sc->cbeg[k]; /* the chains' parts of sc->chain */
}

