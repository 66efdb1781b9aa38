/* Coupling I (Hecht Sec. IV): a fluid particle found inside a colloid after
 * streaming is moved out and given a new velocity in the frame of the
 * colloid surface; the colloid receives the opposite impulse.
 *
 * Placement: nearest (Hecht method i): onto the nearest surface point, then
 * half a step with the new velocity; entry (method ii): back along its path
 * relative to the colloid to the entry point, then the time spent inside with
 * the new velocity (falls back to nearest when the path does not cross the
 * surface within the last step, e.g. a colloid that moved onto the particle).
 *
 * New contact velocity g = v - (V + W x c) (c the contact point from the
 * centre, n the normal, kT the surface temperature, m_f = 1):
 *   slip             g_n from p(g_n) ~ g_n exp(-mu_n g_n^2 / 2kT) (Hecht Eq.
 *                    13), tangential part kept: normal impulse only;
 *   stick_stochastic g_n as above, both tangential components Gaussian with
 *                    variance kT / mu_t (Hecht Eq. 14 = PL Eqs. 20-21);
 *   stick_bounce     g -> -g (bounce-back, PL Sec. III.B), energy conserving.
 * The impulse J = mu_n dg_n n + mu_t dg_t goes to the particle, -J to the
 * colloid's momentum and -c x J to its angular momentum.  mu_n = 1/(1 + 1/M)
 * and mu_t = 1/(1 + 1/M + R^2/I) are the effective masses of the contact, so
 * the rule is the papers' thermal wall (beta = m_f / 2kT) for M >> m_f and
 * keeps detailed balance for a finite colloid mass: with beta = m_f / 2kT in
 * the colloid frame each event would add the recoil m_f^2 dv^2 / 2M and heat
 * colloids and fluid (measured: +25% and +6% at M = 67 m_f).
 * A particle the reflection pushes through a wall (z, or x/y of a capillary)
 * is mirrored back into the box with the wall's rule (bounce-back in the
 * frame of the wall, the z walls moving and the x/y walls at rest, or
 * specular); the impulse of a z wall is counted in the wall stress.
 * A new position inside another colloid repeats the reflection there, up to
 * N_max times (Hecht Sec. IV); a particle still inside after that is left
 * where it is and counted as a truncation.
 *
 * The colloid's response within the step (sequential impulses): each event
 * is a two-body collision of the particle with the colloid that sees the
 * colloid velocity (V, W) the events before it on that colloid left, in the
 * colloid's effective masses mu_n, mu_t, so it keeps the pair's canonical
 * distribution; and a colloid whose velocity changed by dv at the time s
 * before the end of the step (s from the placement: the time after the
 * contact) ends the step displaced by dv s from where the MD moved it, as
 * in an event-driven run.  Which particles hit is decided against those
 * moved end positions: a particle is inside when it is inside a colloid
 * at its moved position, so the found list holds the particles inside
 * spheres enlarged by the largest move (the caller's margin, cb), and a
 * found particle not (yet) inside waits for the next pass in case later
 * events move the colloid onto it.  With the velocities as the step found
 * them (or the events decided against the MD's end positions) the friction
 * would act explicitly: colloids hotter than the fluid by ~xi dt / 2M
 * (validation/REPORT.md).  The events of a step run in event-driven
 * order (kernels/coupling_order.c): each colloid takes next, of its
 * events not yet run, the one whose particle met it first on the path the
 * events before left it, so that an event sees the velocity and position
 * of the colloid the earlier ones left, as in an event-driven run.
 *
 * Race freedom and determinism: the detection is parallel over the
 * static chunks of the streaming (normally inside the streaming itself,
 * pl_coupling_find_block on each block just streamed: the same list, see
 * src/coupling/coupling_stages.c); the reflections (few) then run in that
 * order, each particle's cell moved in the histogram row of the thread that
 * streamed it, so the counting sort stays consistent and the result is
 * bitwise the same for any thread count.  A colloid's velocity and end
 * position depend only on its own events, in that order, so with several
 * threads (and no walls) each thread takes the events of its block of
 * colloids, each colloid's in its order (parallel_events); a particle near
 * a second colloid would tie two blocks, and the step then runs the serial
 * loop instead.  Random numbers: Philox (seed, PL_RNG_REFLECT), counter (step, particle index,
 * reflection number); particle indices are those of the last
 * (thread-independent) counting sort. */
#include <math.h>
#include <omp.h>
#include <stdlib.h>

#include "peloid/coupling_kernels.h"
#include "peloid/rng.h"
#include "peloid/srd_kernels.h"

#include "coupling_events.h"

static inline double wrap(double x, double L)
{
    x -= L * floor(x / L);
    return x >= L ? 0.0 : x;
}

static inline void cross(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* One reflection of a particle at relative position p (inside colloid k)
 * with velocity v: writes the impulse J on the particle, its new relative
 * position p and the contact point cpt (from the centre); returns the time
 * from the contact to the end of the step. */
static double reflect_one(const pl_coupling1_params_t *prm, const pl_coupling_colloids_t *c,
                          int32_t k, uint64_t idx, uint64_t nref, double p[3], const double v[3],
                          double J[3], double cpt[3])
{
    const double R = c->rad[k], M = c->mass[k], V[3] = {c->vx[k], c->vy[k], c->vz[k]};
    const double W[3] = {c->wx[k], c->wy[k], c->wz[k]};
    double w[3] = {v[0] - V[0], v[1] - V[1], v[2] - V[2]};
    double s = -1.0;
    if (prm->placement == PL_PLACE_ENTRY) { /* |p - w s| = R, s in (0, dt] */
        double ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
        double pw = p[0] * w[0] + p[1] * w[1] + p[2] * w[2];
        double pp = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
        double disc = pw * pw - ww * (pp - R * R);
        if (ww > 0.0 && disc >= 0.0) s = (pw + sqrt(disc)) / ww;
        if (!(s > 0.0 && s <= prm->dt)) s = -1.0;
    }
    if (s > 0.0) {
        for (int d = 0; d < 3; ++d) cpt[d] = p[d] - w[d] * s;
    } else { /* Hecht method (i) */
        s = 0.5 * prm->dt;
        for (int d = 0; d < 3; ++d) cpt[d] = p[d];
        if (cpt[0] == 0.0 && cpt[1] == 0.0 && cpt[2] == 0.0) cpt[2] = 1.0;
    }
    double n[3], cn = sqrt(cpt[0] * cpt[0] + cpt[1] * cpt[1] + cpt[2] * cpt[2]);
    for (int d = 0; d < 3; ++d) {
        n[d] = cpt[d] / cn;
        cpt[d] = R * n[d];
    }
    /* contact velocity g = v - (V + W x c), normal and tangential parts */
    double wc[3], g[3], gt[3];
    cross(W, cpt, wc);
    for (int d = 0; d < 3; ++d) g[d] = v[d] - V[d] - wc[d];
    double gn = g[0] * n[0] + g[1] * n[1] + g[2] * n[2];
    for (int d = 0; d < 3; ++d) gt[d] = g[d] - gn * n[d];
    /* effective masses of the contact (m_f = 1): normal 1/(1 + 1/M),
     * tangential 1/(1 + 1/M + R^2/I) */
    const double mu_n = 1.0 / (1.0 + 1.0 / M), mu_t = 1.0 / (1.0 + 1.0 / M + R * R / c->inertia[k]);
    if (prm->boundary == PL_BOUND_STICK_BOUNCE) { /* g -> -g */
        for (int d = 0; d < 3; ++d) J[d] = -2.0 * (mu_n * gn * n[d] + mu_t * gt[d]);
    } else {
        pl_rand4_t r = pl_rng_uniform4(prm->seed, PL_RNG_REFLECT, prm->step, idx, nref);
        double gn_new = sqrt(-2.0 * prm->kT / mu_n * log(r.u[0])); /* Hecht Eq. 13 */
        for (int d = 0; d < 3; ++d) J[d] = mu_n * (gn_new - gn) * n[d];
        if (prm->boundary == PL_BOUND_STICK_STOCHASTIC) { /* Hecht Eq. 14 / PL Eq. 21 */
            double a[3] = {fabs(n[0]) < 0.9 ? 1.0 : 0.0, fabs(n[0]) < 0.9 ? 0.0 : 1.0, 0.0};
            double t1[3], t2[3];
            cross(a, n, t1);
            double tn = sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
            for (int d = 0; d < 3; ++d) t1[d] /= tn;
            cross(n, t1, t2);
            double g1, g2, sd = sqrt(prm->kT / mu_t);
            pl_rng_gauss2(r.u[1], r.u[2], &g1, &g2);
            for (int d = 0; d < 3; ++d) J[d] += mu_t * (sd * (g1 * t1[d] + g2 * t2[d]) - gt[d]);
        }
    }
    /* just outside the surface, then the rest of the time relative to the
     * colloid's new velocity V - J/M */
    for (int d = 0; d < 3; ++d) p[d] = cpt[d] * (1.0 + 1e-12) + (w[d] + J[d] * (1.0 + 1.0 / M)) * s;
    return s;
}

/* r inside the enlarged sphere of a colloid other than k (cb: fixed
 * during the events, so threads may read it). */
static int near_other(const pl_c1_events_t *e, const pl_grid_t *g, const double r[3], int32_t k)
{
    const uint32_t cell = pl_coupling_cell_of(g, r[0], r[1], r[2]);
    const pl_coupling_colloids_t *cb = e->cb;
    for (uint32_t q = e->cstart[cell]; q < e->cstart[cell + 1]; ++q) {
        const int32_t o = e->clist[q];
        if (o == k) continue;
        double d[3] = {r[0] - cb->x[o], r[1] - cb->y[o], r[2] - cb->z[o]};
        for (int a = 0; a < 3; ++a)
            if (g->walls[a] == PL_WALLS_NONE) d[a] -= g->L[a] * nearbyint(d[a] / g->L[a]);
        if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < cb->rad[o] * cb->rad[o]) return 1;
    }
    return 0;
}

/* The colloid whose corrected sphere holds r (p: r - its corrected centre),
 * or -1: serial, the first of r's cell list; par, colloid k only, and -2
 * when r is near another (the pass must give up: that colloid's events
 * belong to another thread). */
static int32_t inside_now(const pl_c1_events_t *e, const pl_grid_t *g, const double r[3], double p[3], int32_t k,
                          int par)
{
    if (!par) return pl_coupling_inside_cells(&e->c, g, e->cstart, e->clist, r, p);
    if (k < 0 || near_other(e, g, r, k)) return -2;
    double d[3] = {r[0] - e->c.x[k], r[1] - e->c.y[k], r[2] - e->c.z[k]};
    for (int a = 0; a < 3; ++a)
        if (g->walls[a] == PL_WALLS_NONE) d[a] -= g->L[a] * nearbyint(d[a] / g->L[a]);
    if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] >= e->c.rad[k] * e->c.rad[k]) return -1;
    for (int a = 0; a < 3; ++a) p[a] = d[a];
    return k;
}

/* Colloid k's velocity changed by dv at the time s before the end of the
 * step: its end position moves by dv s (at most the margin cb->rad -
 * c->rad from where the MD left it; beyond, scaled back). */
static void displace(const pl_c1_events_t *e, int32_t k, const double dv[3], double s)
{
    if (!e->move) return;
    const size_t n = e->c.n;
    double *D = e->disp, dd = 0.0;
    for (int d = 0; d < 3; ++d) {
        D[(size_t)d * n + (size_t)k] += dv[d] * s;
        dd += D[(size_t)d * n + (size_t)k] * D[(size_t)d * n + (size_t)k];
    }
    const double m = (e->cb->rad[k] - e->c.rad[k]) * (1.0 - 1e-9);
    if (dd > m * m)
        for (int d = 0; d < 3; ++d) D[(size_t)d * n + (size_t)k] *= m / sqrt(dd);
    e->pos[0][k] = e->cb->x[k] + D[(size_t)k];
    e->pos[1][k] = e->cb->y[k] + D[n + (size_t)k];
    e->pos[2][k] = e->cb->z[k] + D[2 * n + (size_t)k];
}

/* Reflects particle i (inside colloid k, relative position p), its
 * reflections this step counted in *nref, up to N_max, kicking the
 * colloids and moving their end positions as it goes; returns 1 on
 * truncation, -1 (par only) when it met another colloid's events (nothing
 * of i written). */
static int reflect_particle(pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *prm,
                            const pl_c1_events_t *e, double *const vel[6], size_t i, int32_t k, double p[3],
                            uint32_t *restrict h, uint64_t *restrict cnt, int par, uint16_t *nref_io)
{
    const pl_coupling_colloids_t *c = &e->c;
    const int32_t k_first = k;
    const double L[3] = {g->L[0], g->L[1], g->L[2]};
    double r[3] = {f->r[0][i], f->r[1][i], f->r[2][i]};
    const double r_old[3] = {r[0], r[1], r[2]};
    double v[3] = {f->v[0][i], f->v[1][i], f->v[2][i]};
    int nref = *nref_io;
    while (k >= 0 && nref < prm->max_refl) {
        double J[3], cpt[3], l[3], dv[3];
        const double s = reflect_one(prm, c, k, i, (uint64_t)nref, p, v, J, cpt);
        const double M = c->mass[k], I = c->inertia[k];
        for (int d = 0; d < 3; ++d) {
            v[d] += J[d];
            dv[d] = -J[d] / M;
            vel[d][k] += dv[d]; /* momentum: exactly what the particle gains */
        }
        if (prm->boundary != PL_BOUND_SLIP) { /* angular momentum: -c x J */
            cross(cpt, J, l);
            for (int d = 0; d < 3; ++d) vel[3 + d][k] -= l[d] / I;
        }
        displace(e, k, dv, s);
        for (int d = 0; d < 3; ++d) r[d] = (d == 0 ? c->x[k] : d == 1 ? c->y[k] : c->z[k]) + p[d];
        for (int d = 0; d < 3; ++d) {
            if (g->walls[d] == PL_WALLS_NONE) {
                r[d] = wrap(r[d], L[d]);
            } else if (r[d] < 0.0 || r[d] > L[d]) { /* mirror into the box */
                const int top = r[d] > L[d];
                r[d] = r[d] < 0.0 ? -r[d] : 2.0 * L[d] - r[d];
                if (r[d] < 0.0 || r[d] > L[d]) r[d] = 0.5 * L[d];
                double dp[3] = {0.0, 0.0, 0.0};
                dp[d] = -2.0 * v[d];
                if (g->walls[d] == PL_WALLS_NOSLIP) /* bounce-back in the wall's frame, as streaming does */
                    for (int q = 0; q < 3; ++q) dp[q] = 2.0 * ((d == 2 ? prm->wall_u[top][q] : 0.0) - v[q]);
                for (int q = 0; q < 3; ++q) v[q] += dp[q];
                if (prm->wall_acc) pl_wall_acc_add(prm->wall_acc, pl_wall_slot(d, top), dp);
            }
        }
        cnt[0]++;
        nref++;
        /* par: events of other colloids run concurrently; one near a
         * second colloid would need that colloid's state at this point of
         * the order (nothing of i written yet) */
        k = inside_now(e, g, r, p, k_first, par);
        if (k == -2) return -1;
    }
    *nref_io = (uint16_t)nref;
    if (f->tracked)
        for (int d = 0; d < 3; ++d) {
            double dd = r[d] - r_old[d];
            if (g->walls[d] == PL_WALLS_NONE) dd -= L[d] * nearbyint(dd / L[d]);
            f->disp[d][i] += dd;
        }
    for (int d = 0; d < 3; ++d) {
        f->r[d][i] = (pl_real)r[d];
        f->v[d][i] = (pl_real)v[d];
    }
    uint32_t cell = pl_coupling_cell_of(g, f->r[0][i], f->r[1][i], f->r[2][i]);
    if (par) { /* rows shared between threads: integer counts, any order */
#pragma omp atomic
        h[f->cell[i]]--;
#pragma omp atomic
        h[cell]++;
    } else {
        h[f->cell[i]]--;
        h[cell]++;
    }
    f->cell[i] = cell;
    return k >= 0;
}

/* Events are few and far apart in the particle arrays: each one's position,
 * velocity and cell are fetched PF events ahead (the misses of one event
 * otherwise wait in turn). */
enum { PF = 6 };
static inline void prefetch_particle(const pl_fluid_t *f, size_t i)
{
    for (int d = 0; d < 3; ++d) {
        __builtin_prefetch(f->r[d] + i, 1, 3);
        __builtin_prefetch(f->v[d] + i, 1, 3);
    }
    __builtin_prefetch(f->cell + i, 1, 3);
}

/* A particle's cell moved in the row of thread t: outside t's band of the
 * counting sort (pl_fluid_bands_t), the next sort counts whole rows. */
static inline void band_check(pl_fluid_t *f, int t, int nthreads, size_t ncells, size_t i)
{
    uint32_t lo, len;
    pl_fluid_band(f, t, nthreads, (uint32_t)ncells, &lo, &len);
    if (pl_fluid_band_out(f->cell[i], lo, len, (uint32_t)ncells)) pl_fluid_band_overflow(f);
}

/* Passes over the events in order: a particle found (inside an
 * enlarged sphere) but outside every moved one waits for the next pass,
 * and a particle reflected may be inside again after later events moved
 * its colloid onto it (it is reflected again then, up to N_max in all);
 * at most NPASS passes (a later pass rarely finds one).  sc->done[j]:
 * particle j's reflections so far. */
enum { NPASS = 4 };

/* The events with the colloids split between the threads: thread t takes,
 * in order, the particles found inside the enlarged sphere of a
 * colloid of its static block of colloids (the first of the particle's
 * cell list), so each colloid sees the same events in the same order as in
 * the serial loop, with the same random numbers (keyed by step, particle,
 * reflection).  A particle near a second colloid stops the pass: every
 * particle handled is put back (saved state), the colloid velocities too,
 * and the caller runs the serial loop.  Only without walls (no wall
 * impulses to sum).  Returns 0 when done, -1 when it gave up. */
/* One event of the parallel loop (particle of event j, candidate colloid
 * k): 1 when reflected, 0 when not inside k's moved sphere, -1 when it met
 * another colloid (give up).  *trunc counts a truncation. */
static int par_event(pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *prm, const pl_c1_events_t *e,
                     double *const vel[6], uint32_t *hist, int nthreads, pl_coupling1_scratch_t *sc, size_t j,
                     uint64_t mine[2])
{
    const int32_t k = sc->k[j];
    const size_t i = sc->idx[j];
    const double r[3] = {f->r[0][i], f->r[1][i], f->r[2][i]};
    double q[3];
    const int32_t kin = inside_now(e, g, r, q, k, 1);
    if (kin == -1) return 0;
    if (kin < 0) return -1;
    double *sv = sc->state + 7 * j;
    if (!sc->done[j]) {
        for (int d = 0; d < 3; ++d) {
            sv[d] = f->r[d][i];
            sv[3 + d] = f->v[d][i];
        }
        sv[6] = (double)f->cell[i];
    }
    const int rc = reflect_particle(f, g, prm, e, vel, i, kin, q, hist + (size_t)sc->owner[j] * g->ncells, mine, 1,
                                    &sc->done[j]);
    band_check(f, sc->owner[j], nthreads, g->ncells, i);
    if (rc < 0) return -1;
    mine[1] += (uint64_t)rc;
    return 1;
}

/* The events with the colloids split between the threads: thread t takes
 * the chains (sc->k, sc->next) of the colloids of its static block, each
 * colloid's events chosen as in the serial loop (next_event), then the
 * further passes in order, so each colloid sees the same events in the
 * same order as in the serial loop, with the same random numbers (keyed by
 * step, particle, reflection).  A particle near a second colloid stops the
 * pass: every particle handled is put back (saved state), the colloid
 * velocities too, and the caller runs the serial loop.  Only without walls
 * (no wall impulses to sum).  Returns 0 when done, -1 when it gave up. */
static int parallel_events(pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *prm, const pl_c1_events_t *e,
                           double *const vel[6], uint32_t *hist, int nthreads, size_t total, uint64_t *counts,
                           pl_coupling1_scratch_t *sc)
{
    const size_t nc = e->c.n;
    for (int j = 0; j < 6; ++j) /* the colloid velocities before, to put back */
        for (size_t k = 0; k < nc; ++k) sc->vsave[(size_t)j * nc + k] = vel[j][k];
    int gave_up = 0;
    uint64_t cnt[2] = {0, 0};
#pragma omp parallel num_threads(nthreads) reduction(+ : cnt[:2])
    {
        const int T = omp_get_num_threads(), me = omp_get_thread_num();
        const int32_t k0 = (int32_t)(nc * (size_t)me / (size_t)T), k1 = (int32_t)(nc * (size_t)(me + 1) / (size_t)T);
        uint64_t mine[2] = {0, 0};
        int more = 1, quit = 0;
        for (int pass = 0; pass < NPASS && more && !quit; ++pass) {
            more = 0;
            for (size_t j = 0; j < total && !quit; ++j) {
                const int32_t k = sc->k[j];
                if (k < k0 || k >= k1 || sc->done[j] >= prm->max_refl) continue; /* k < 0: inside none */
                if (pass == 0 && sc->taken[j]) continue;
#pragma omp atomic read
                quit = gave_up;
                if (quit) break;
                int rc = 0;
                if (pass == 0) { /* colloid k's chain, in its event order */
                    size_t left = pl_coupling1_chain_gather(f, sc, j);
                    for (int64_t b; rc >= 0 && (b = pl_coupling1_chain_next(e, g, prm, sc, k, &left)) >= 0;) {
                        sc->taken[b] = 1;
                        rc = par_event(f, g, prm, e, vel, hist, nthreads, sc, (size_t)b, mine);
                        more |= rc > 0;
                    }
                } else {
                    rc = par_event(f, g, prm, e, vel, hist, nthreads, sc, j, mine);
                    more |= rc > 0;
                }
                if (rc < 0) {
#pragma omp atomic write
                    gave_up = 1;
                    quit = 1;
                }
            }
        }
        cnt[0] += mine[0];
        cnt[1] += mine[1];
    }
    if (!gave_up) {
        counts[0] = cnt[0];
        counts[1] = cnt[1];
        sc->parallel++;
        return 0;
    }
    sc->gave_up++;
    /* put back what was done (disp is not tracked: see the caller) */
    for (size_t j = 0; j < total; ++j) {
        if (!sc->done[j]) continue;
        const size_t i = sc->idx[j];
        const double *sv = sc->state + 7 * j;
        uint32_t *h = hist + (size_t)sc->owner[j] * g->ncells;
        for (int d = 0; d < 3; ++d) {
            f->r[d][i] = (pl_real)sv[d];
            f->v[d][i] = (pl_real)sv[3 + d];
        }
        h[f->cell[i]]--;
        f->cell[i] = (uint32_t)sv[6];
        h[f->cell[i]]++;
    }
    for (int j = 0; j < 6; ++j)
        for (size_t k = 0; k < nc; ++k) vel[j][k] = sc->vsave[(size_t)j * nc + k];
    return -1;
}

size_t pl_coupling1_found(const uint64_t *counts, int nthreads)
{
    size_t total = 0;
    for (int t = 0; t < nthreads; ++t) total += counts[(size_t)t * 8 + 2];
    return total;
}

/* The events' view (pl_c1_events_t) with no displacement yet. */
static void events_start(pl_c1_events_t *e, const pl_coupling_colloids_t *c, const pl_coupling_colloids_t *cb,
                         const uint32_t *cstart, const int32_t *clist, pl_coupling1_scratch_t *sc, int move)
{
    const size_t n = c->n;
    *e = (pl_c1_events_t){.c = *c, .cb = cb, .disp = sc->disp, .cstart = cstart, .clist = clist, .move = move};
    const double *x0[3] = {cb->x, cb->y, cb->z};
    for (int d = 0; d < 3; ++d) {
        e->pos[d] = sc->pos + (size_t)d * n;
        for (size_t k = 0; k < n; ++k) {
            e->pos[d][k] = x0[d][k];
            sc->disp[(size_t)d * n + k] = 0.0;
        }
    }
    e->c.x = e->pos[0];
    e->c.y = e->pos[1];
    e->c.z = e->pos[2];
}

/* One event of the serial loop: particle of event j reflected when it is
 * inside a colloid's moved sphere; returns whether it was. */
static int serial_event(pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *p, const pl_c1_events_t *e,
                        double *const vel[6], uint32_t *hist, int nthreads, uint64_t *counts,
                        pl_coupling1_scratch_t *sc, size_t j)
{
    const size_t i = sc->idx[j];
    const int t = sc->owner[j];
    double r[3] = {f->r[0][i], f->r[1][i], f->r[2][i]}, q[3];
    const int32_t k = inside_now(e, g, r, q, -1, 0);
    if (k < 0) return 0;
    counts[1] += (uint64_t)reflect_particle(f, g, p, e, vel, i, k, q, hist + (size_t)t * g->ncells, counts, 0,
                                            &sc->done[j]);
    band_check(f, t, nthreads, g->ncells, i);
    return 1;
}

void pl_coupling1_reflect(pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *p,
                          const pl_coupling_colloids_t *c, const pl_coupling_colloids_t *cb, double *const vel[6],
                          const uint32_t *cstart, const int32_t *clist, uint32_t *hist, int nthreads,
                          const uint32_t *found, uint64_t *counts, pl_coupling1_scratch_t *sc)
{
    const size_t total = pl_coupling1_found(counts, nthreads);
    pl_c1_events_t e;
    events_start(&e, c, cb, cstart, clist, sc, p->move);
    pl_coupling1_order(f, g, p, &e, nthreads, found, counts, total, sc);
    pl_coupling1_chains(f, g, &e, nthreads, total, sc);
    counts[0] = counts[1] = 0;
    if (nthreads > 1 && !g->any_walls && !f->tracked && !p->wall_acc && c->n >= 2 &&
        !parallel_events(f, g, p, &e, vel, hist, nthreads, total, counts, sc))
        return;
    events_start(&e, c, cb, cstart, clist, sc, p->move);
    for (size_t j = 0; j < total; ++j) sc->done[j] = sc->taken[j] = 0;
    int more = 1;
    for (int pass = 0; pass < NPASS && more; ++pass) {
        more = 0;
        for (size_t j = 0; j < total; ++j) {
            if (sc->done[j] >= p->max_refl || (pass == 0 && sc->taken[j])) continue;
            if (pass == 0 && j + PF < total) prefetch_particle(f, sc->idx[j + PF]);
            if (pass > 0 || sc->k[j] < 0) {
                more |= serial_event(f, g, p, &e, vel, hist, nthreads, counts, sc, j);
                continue;
            }
            size_t left = pl_coupling1_chain_gather(f, sc, j); /* colloid sc->k[j]'s chain */
            for (int64_t b; (b = pl_coupling1_chain_next(&e, g, p, sc, sc->k[j], &left)) >= 0;) {
                sc->taken[b] = 1;
                more |= serial_event(f, g, p, &e, vel, hist, nthreads, counts, sc, (size_t)b);
            }
        }
    }
}
