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
 * New velocity relative to the surface velocity U = V + w x c (c the contact
 * point from the centre), normal n, kT the surface temperature, m_f = 1:
 *   slip             v_n from p(v_n) ~ v_n exp(-v_n^2 / 2kT) (Hecht Eq. 13),
 *                    tangential relative velocity kept: normal impulse only;
 *   stick_stochastic v_n as above, both tangential components Gaussian with
 *                    variance kT (Hecht Eq. 14 = PL Eqs. 20-21);
 *   stick_bounce     v - U -> -(v - U) (bounce-back, PL Sec. III.B).
 * A new position inside another colloid repeats the reflection there, up to
 * N_max times (Hecht Sec. IV); a particle still inside after that is left
 * where it is and counted as a truncation.
 *
 * Race freedom and determinism: thread t handles the particles of its static
 * chunk pl_chunk(t) (the chunk whose histogram row it filled while
 * streaming) and accumulates colloid impulses in its own 64-bit fixed-point
 * row; integer sums do not depend on the order, so the result is bitwise the
 * same for any thread count.  Random numbers: Philox (seed, PL_RNG_COUPLING
 * + 2), counter (step, particle index, reflection number); particle indices
 * are those of the last (thread-independent) counting sort. */
#include <math.h>
#include <omp.h>

#include "peloid/coupling_kernels.h"
#include "peloid/rng.h"
#include "peloid/scene.h"
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
 * with velocity v; writes the new relative position p and velocity v and
 * the contact point cpt. */
static void reflect_one(const pl_coupling1_params_t *prm, const pl_coupling_colloids_t *c,
                        int32_t k, uint64_t idx, uint64_t nref, double p[3], double v[3],
                        double cpt[3])
{
    const double R = c->rad[k], V[3] = {c->vx[k], c->vy[k], c->vz[k]};
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
    double n[3];
    if (s > 0.0) {
        for (int d = 0; d < 3; ++d) cpt[d] = p[d] - w[d] * s;
    } else { /* Hecht method (i) */
        s = 0.5 * prm->dt;
        for (int d = 0; d < 3; ++d) cpt[d] = p[d];
        if (cpt[0] == 0.0 && cpt[1] == 0.0 && cpt[2] == 0.0) cpt[2] = 1.0;
    }
    double cn = sqrt(cpt[0] * cpt[0] + cpt[1] * cpt[1] + cpt[2] * cpt[2]);
    for (int d = 0; d < 3; ++d) {
        n[d] = cpt[d] / cn;
        cpt[d] = R * n[d];
    }
    double U[3], wc[3];
    cross(W, cpt, wc);
    for (int d = 0; d < 3; ++d) U[d] = V[d] + (prm->boundary == PL_BOUND_SLIP ? 0.0 : wc[d]);
    double rel[3] = {v[0] - U[0], v[1] - U[1], v[2] - U[2]};
    if (prm->boundary == PL_BOUND_STICK_BOUNCE) {
        for (int d = 0; d < 3; ++d) rel[d] = -rel[d];
    } else {
        pl_rand4_t r = pl_rng_uniform4(prm->seed, PL_RNG_COUPLING + 2, prm->step, idx, nref);
        double vn = sqrt(-2.0 * prm->kT * log(r.u[0])); /* Hecht Eq. 13 */
        double rn = rel[0] * n[0] + rel[1] * n[1] + rel[2] * n[2];
        if (prm->boundary == PL_BOUND_SLIP) {
            for (int d = 0; d < 3; ++d) rel[d] += (vn - rn) * n[d];
        } else { /* Hecht Eq. 14 / PL Eq. 21: tangential Gaussian */
            double a[3] = {fabs(n[0]) < 0.9 ? 1.0 : 0.0, fabs(n[0]) < 0.9 ? 0.0 : 1.0, 0.0};
            double t1[3], t2[3];
            cross(a, n, t1);
            double tn = sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
            for (int d = 0; d < 3; ++d) t1[d] /= tn;
            cross(n, t1, t2);
            double g1, g2, sd = sqrt(prm->kT);
            pl_rng_gauss2(r.u[1], r.u[2], &g1, &g2);
            for (int d = 0; d < 3; ++d) rel[d] = vn * n[d] + sd * (g1 * t1[d] + g2 * t2[d]);
        }
    }
    for (int d = 0; d < 3; ++d) {
        v[d] = U[d] + rel[d];
        /* just outside the surface, then the rest of the time in the frame
         * moving with the colloid */
        p[d] = cpt[d] * (1.0 + 1e-12) + (v[d] - V[d]) * s;
    }
}

static void reflect_range(pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *prm,
                          const pl_coupling_colloids_t *c, const int32_t *lk_start,
                          const int32_t *lk_list, uint32_t *restrict h, size_t lo, size_t hi,
                          int64_t *restrict acc, uint64_t *restrict cnt)
{
    const double L[3] = {g->L[0], g->L[1], g->L[2]};
    const int walls = g->walls_z != PL_WALLS_NONE;
    const double fix = ldexp(1.0, PL_COUPLING_FIX_BITS), unfix = ldexp(1.0, -PL_COUPLING_FIX_BITS);
    for (size_t i = lo; i < hi; ++i) {
        double r[3] = {f->r[0][i], f->r[1][i], f->r[2][i]}, p[3];
        int32_t k = pl_coupling_inside(c, g->L, g->walls_z, lk_start, lk_list, r, p);
        if (k < 0) continue;
        const double r_old[3] = {r[0], r[1], r[2]};
        double v[3] = {f->v[0][i], f->v[1][i], f->v[2][i]};
        int nref = 0;
        while (k >= 0 && nref < prm->max_refl) {
            double v_old[3] = {v[0], v[1], v[2]}, cpt[3], dq[3];
            reflect_one(prm, c, k, i, (uint64_t)nref, p, v, cpt);
            /* quantised impulse: the fluid gets exactly what the colloid loses */
            for (int d = 0; d < 3; ++d) {
                int64_t q = (int64_t)llround((v[d] - v_old[d]) * fix);
                dq[d] = (double)q * unfix;
                v[d] = v_old[d] + dq[d];
                acc[(size_t)k * 6 + (size_t)d] -= q;
            }
            if (prm->boundary != PL_BOUND_SLIP) { /* torque about the centre: c x (-dp) */
                double l[3];
                cross(cpt, dq, l);
                for (int d = 0; d < 3; ++d) acc[(size_t)k * 6 + 3 + (size_t)d] -= (int64_t)llround(l[d] * fix);
            }
            double X[3] = {c->x[k], c->y[k], c->z[k]};
            for (int d = 0; d < 3; ++d) r[d] = X[d] + p[d];
            if (walls && (r[2] < 0.0 || r[2] > L[2])) { /* mirror into the box */
                r[2] = r[2] < 0.0 ? -r[2] : 2.0 * L[2] - r[2];
                if (r[2] < 0.0 || r[2] > L[2]) r[2] = 0.5 * L[2];
                v[2] = -v[2];
            }
            r[0] = wrap(r[0], L[0]);
            r[1] = wrap(r[1], L[1]);
            if (!walls) r[2] = wrap(r[2], L[2]);
            cnt[0]++;
            nref++;
            k = pl_coupling_inside(c, g->L, g->walls_z, lk_start, lk_list, r, p);
        }
        if (k >= 0) cnt[1]++;
        if (f->tracked)
            for (int d = 0; d < 3; ++d) {
                double dd = r[d] - r_old[d];
                if (d < 2 || !walls) dd -= L[d] * nearbyint(dd / L[d]);
                f->disp[d][i] += dd;
            }
        for (int d = 0; d < 3; ++d) {
            f->r[d][i] = (pl_real)r[d];
            f->v[d][i] = (pl_real)v[d];
        }
        uint32_t cell = pl_coupling_cell_of(g, f->r[0][i], f->r[1][i], f->r[2][i]);
        h[f->cell[i]]--;
        h[cell]++;
        f->cell[i] = cell;
    }
}

void pl_coupling1_reflect(pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *p,
                          const pl_coupling_colloids_t *c, const int32_t *lk_start,
                          const int32_t *lk_list, uint32_t *hist, int nthreads, int64_t *acc,
                          uint64_t *counts)
{
    /* Same static chunks as the streaming: thread t owns histogram row t. */
#pragma omp parallel num_threads(nthreads)
    {
        int t = omp_get_thread_num();
        size_t lo, hi;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        int64_t *a = acc + (size_t)t * c->n * 6;
        for (size_t j = 0; j < c->n * 6; ++j) a[j] = 0;
        uint64_t *cnt = counts + (size_t)t * 8;
        cnt[0] = cnt[1] = 0;
        reflect_range(f, g, p, c, lk_start, lk_list, hist + (size_t)t * g->ncells, lo, hi, a, cnt);
    }
}
