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
 * Race freedom and determinism: the detection is parallel over the
 * static chunks of the streaming (normally inside the streaming itself,
 * pl_coupling_find_block on each block just streamed: the same list, see
 * src/coupling/coupling_stages.c); the reflections (few) then run in
 * particle order, each particle's cell moved in the histogram row of the
 * thread that streamed it, so the counting sort stays consistent and the
 * result is bitwise the same for any thread count.  Every event reads the
 * colloids' velocities as the step found them (c: src/coupling/
 * coupling_stages.c freezes them; the order of the events would otherwise
 * enter the rule, and the counting sort's z-major order made colloids
 * drift) and adds its impulse to vel; the impulses on one colloid add up
 * in particle order, so with several threads (and no walls) each thread
 * takes the events of its block of colloids, in particle order
 * (parallel_events); a particle reflected into a second colloid would tie
 * two blocks, and the step then runs the serial loop instead.  Random numbers: Philox (seed,
 * PL_RNG_REFLECT), counter (step, particle index, reflection number); particle indices
 * are those of the last (thread-independent) counting sort. */
#include <math.h>
#include <omp.h>

#include "peloid/coupling_kernels.h"
#include "peloid/rng.h"
#include "peloid/srd_kernels.h"

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
 * position p and the contact point cpt (from the centre). */
static void reflect_one(const pl_coupling1_params_t *prm, const pl_coupling_colloids_t *c,
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
}

/* Reflects particle i (inside colloid k, relative position p) up to
 * N_max times, kicking the colloids as it goes; returns 1 on truncation. */
static int reflect_particle(pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *prm,
                            const pl_coupling_colloids_t *c, double *const vel[6],
                            const uint32_t *cstart, const int32_t *clist, size_t i, int32_t k,
                            double p[3], uint32_t *restrict h, uint64_t *restrict cnt, int par)
{
    const int32_t k_first = k;
    const double L[3] = {g->L[0], g->L[1], g->L[2]};
    double r[3] = {f->r[0][i], f->r[1][i], f->r[2][i]};
    const double r_old[3] = {r[0], r[1], r[2]};
    double v[3] = {f->v[0][i], f->v[1][i], f->v[2][i]};
    int nref = 0;
    while (k >= 0 && nref < prm->max_refl) {
        double J[3], cpt[3], l[3];
        reflect_one(prm, c, k, i, (uint64_t)nref, p, v, J, cpt);
        const double M = c->mass[k], I = c->inertia[k];
        for (int d = 0; d < 3; ++d) {
            v[d] += J[d];
            vel[d][k] -= J[d] / M; /* momentum: exactly what the particle gains */
        }
        if (prm->boundary != PL_BOUND_SLIP) { /* angular momentum: -c x J */
            cross(cpt, J, l);
            for (int d = 0; d < 3; ++d) vel[3 + d][k] -= l[d] / I;
        }
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
                    for (int e = 0; e < 3; ++e) dp[e] = 2.0 * ((d == 2 ? prm->wall_u[top][e] : 0.0) - v[e]);
                for (int e = 0; e < 3; ++e) v[e] += dp[e];
                if (prm->wall_acc) pl_wall_acc_add(prm->wall_acc, pl_wall_slot(d, top), dp);
            }
        }
        cnt[0]++;
        nref++;
        k = pl_coupling_inside_cells(c, g, cstart, clist, r, p);
        /* par: events of other colloids run concurrently; one inside a
         * second colloid would need that colloid's velocity at this point
         * of the particle order (nothing of i written yet) */
        if (par && k >= 0 && k != k_first && nref < prm->max_refl) return -1;
    }
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

/* The events with the colloids split between the threads: thread t takes,
 * in particle order, the particles found inside a colloid of its static
 * block of colloids, so each colloid sees the same events in the same
 * order as in the serial loop, with the same random numbers (keyed by
 * step, particle, reflection).  A particle whose reflection puts it inside
 * another colloid stops the pass: every particle handled is put back
 * (saved state), the colloid velocities too, and the caller runs the serial
 * loop.  Only without walls (no wall impulses to sum).  Returns 0 when done,
 * -1 when it gave up. */
static int parallel_events(pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *prm,
                           const pl_coupling_colloids_t *c, double *const vel[6], const uint32_t *cstart,
                           const int32_t *clist, uint32_t *hist, int nthreads, const uint32_t *found,
                           uint64_t *counts, pl_coupling1_scratch_t *sc)
{
    const size_t nc = c->n;
    size_t total = 0;
    for (int t = 0; t < nthreads; ++t) total += counts[(size_t)t * 8 + 2];
    if (total > sc->cap || 6 * nc > sc->vcap) {
        sc->need = total;
        return -1;
    }
    for (int j = 0; j < 6; ++j) /* the colloid velocities before, to put back */
        for (size_t k = 0; k < nc; ++k) sc->vsave[(size_t)j * nc + k] = vel[j][k];
    int gave_up = 0;
    uint64_t cnt[2] = {0, 0};
#pragma omp parallel num_threads(nthreads) reduction(+ : cnt[:2])
    {
        /* the first colloid of each listed particle (flat list, particle
         * order), in parallel */
#pragma omp for schedule(static)
        for (int t = 0; t < nthreads; ++t) {
            size_t lo, hi, j = 0;
            pl_chunk(f->n, t, nthreads, &lo, &hi);
            for (int u = 0; u < t; ++u) j += counts[(size_t)u * 8 + 2];
            const size_t nt = counts[(size_t)t * 8 + 2];
            for (size_t s = 0; s < nt; ++s, ++j) {
                if (s + PF < nt) prefetch_particle(f, found[lo + s + PF]);
                const size_t i = found[lo + s];
                const double r[3] = {f->r[0][i], f->r[1][i], f->r[2][i]};
                double q[3];
                sc->idx[j] = (uint32_t)i;
                sc->owner[j] = t;
                sc->k[j] = pl_coupling_inside_cells(c, g, cstart, clist, r, q);
                sc->done[j] = 0;
            }
        }
        const int T = omp_get_num_threads(), me = omp_get_thread_num();
        const int32_t k0 = (int32_t)(nc * (size_t)me / (size_t)T), k1 = (int32_t)(nc * (size_t)(me + 1) / (size_t)T);
        uint64_t mine[2] = {0, 0};
        for (size_t j = 0; j < total; ++j) {
            const int32_t k = sc->k[j];
            if ((k < 0 ? 0 : k) < k0 || (k < 0 ? 0 : k) >= k1) continue; /* none (k < 0): colloid 0's thread */
            int stop;
#pragma omp atomic read
            stop = gave_up;
            if (stop) break;
            const size_t i = sc->idx[j];
            double *sv = sc->state + 7 * j;
            for (int d = 0; d < 3; ++d) {
                sv[d] = f->r[d][i];
                sv[3 + d] = f->v[d][i];
            }
            sv[6] = (double)f->cell[i];
            const double r[3] = {f->r[0][i], f->r[1][i], f->r[2][i]};
            double q[3];
            pl_coupling_inside_cells(c, g, cstart, clist, r, q);
            const int rc = reflect_particle(f, g, prm, c, vel, cstart, clist, i, k, q,
                                            hist + (size_t)sc->owner[j] * g->ncells, mine, 1);
            band_check(f, sc->owner[j], nthreads, g->ncells, i);
            if (rc < 0) {
#pragma omp atomic write
                gave_up = 1;
                break;
            }
            sc->done[j] = 1;
            mine[1] += (uint64_t)rc;
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

void pl_coupling1_reflect(pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *p,
                          const pl_coupling_colloids_t *c, double *const vel[6],
                          const uint32_t *cstart, const int32_t *clist, uint32_t *hist, int nthreads,
                          uint32_t *found, uint64_t *counts, pl_coupling1_scratch_t *sc, int detected)
{
    /* Detection, in parallel: thread t lists the particles of its static
     * chunk (the one of the streaming) found inside a colloid, from the
     * cells the streaming binned them into (the colloids near each cell:
     * cstart, clist); usually done inside the streaming already. */
    if (!detected) pl_coupling_find_binned(f, g, c, cstart, clist, nthreads, found, counts);
    /* The events, serially in particle order: each sees the colloid velocity
     * left by the one before (collisions are sequential impulses; with a
     * stale velocity light colloids would overheat), and the order does not
     * depend on the thread count. */
    counts[0] = counts[1] = 0;
    if (sc && nthreads > 1 && !g->any_walls && !f->tracked && !p->wall_acc && c->n >= 2 &&
        !parallel_events(f, g, p, c, vel, cstart, clist, hist, nthreads, found, counts, sc))
        return;
    for (int t = 0; t < nthreads; ++t) {
        size_t lo, hi;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        uint32_t *h = hist + (size_t)t * g->ncells;
        const size_t nt = counts[(size_t)t * 8 + 2];
        for (size_t j = 0; j < nt; ++j) {
            if (j + PF < nt) prefetch_particle(f, found[lo + j + PF]);
            size_t i = found[lo + j];
            double r[3] = {f->r[0][i], f->r[1][i], f->r[2][i]}, q[3];
            int32_t k = pl_coupling_inside_cells(c, g, cstart, clist, r, q);
            counts[1] += (uint64_t)reflect_particle(f, g, p, c, vel, cstart, clist, i, k, q, h,
                                                    counts, 0);
            band_check(f, t, nthreads, g->ncells, i);
        }
    }
}
