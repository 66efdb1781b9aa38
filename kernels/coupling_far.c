/* Potential coupling (PL Sec. III.A): the selected fluid particles that stay
 * beyond the cut-off of PL Eq. 17 through the whole MD step.
 *
 * The selection shell (cut-off + margin) holds about three times as many
 * particles as can reach the cut-off within one collision step: the margin
 * covers 8 thermal speeds, a typical particle flies one.  A particle that
 * cannot reach the cut-off of any of its pair colloids feels a force of
 * exactly +0 at every evaluation (each pair's term is +-0 beyond the
 * cut-off, and so is its reaction), so its MD step is free flight under the
 * fluid acceleration: done here in one pass, in registers, with the same
 * operations in the same order as the evaluations would do them
 * (pl_coupling_potential_force_step); the evaluations then run over the
 * near particles only, copied in order into their blocks.  Adding +-0 to a
 * sum that starts at +0 changes no bit, so the forces, reactions and energy
 * are those of all the particles, bit for bit.
 *
 * "Cannot reach": the distance at the selection less the longest free
 * flight (|v| T + |g| T^2 over T = S dtm, rounding covered by 1e-9) less
 * the cut-off exceeds a budget for the colloids' moves; the caller checks
 * the budget at every evaluation (the largest colloid move since the
 * selection) and resumes all the particles (pl_coupling_far_resume) at the
 * first evaluation that exceeds it.  Deterministic: each particle is
 * handled by one iteration; the sums over threads are maxima and integer
 * counts. */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "peloid/coupling_kernels.h"

/* Evaluation e of the plan on a particle whose force is +0: the kicks
 * v += h (0 + g) (once for e = 0 and e = S, twice between) and, for e < S,
 * the drift r += v dtm.  Returns |r - r0|^2 after the drift (0 without). */
static inline double free_eval(const pl_coupling_md_plan_t *p, const double k[3], int e, double r[3], double v[3],
                               const double r0[3])
{
    const int twice = e > 0 && e < p->S;
    for (int d = 0; d < 3; ++d) {
        v[d] = v[d] + k[d];
        if (twice) v[d] = v[d] + k[d];
    }
    if (e == p->S) return 0.0;
    for (int d = 0; d < 3; ++d) r[d] = r[d] + v[d] * p->dtm;
    const double a = r[0] - r0[0], b = r[1] - r0[1], c = r[2] - r0[2];
    return a * a + b * b + c * c;
}

/* The kick of a force +0 (as the evaluations compute it: h (f + g), f = +0). */
static void free_kick(const pl_coupling_md_plan_t *p, double k[3])
{
    for (int d = 0; d < 3; ++d) k[d] = p->h * (0.0 + p->g[d]);
}

size_t pl_coupling_far_split(const pl_coupling_near_t *nb, const pl_coupling_md_plan_t *plan, double rc,
                             double budget, size_t nblk, int nthreads, pl_coupling_near_t *sub, size_t *blk,
                             uint32_t *map, uint8_t *far, double *d2call, double *scratch)
{
    enum { CH = 256 }; /* particles at a time, their state in L1 */
    const size_t nn = nb->n, S = (size_t)plan->S;
    const double T = (double)plan->S * plan->dtm, dtm = plan->dtm;
    const double gmag = sqrt(plan->g[0] * plan->g[0] + plan->g[1] * plan->g[1] + plan->g[2] * plan->g[2]);
    const double reach = budget + 1e-9;
    double k[3];
    free_kick(plan, k);
    size_t nfar = 0;
    for (size_t e = 0; e <= S; ++e) d2call[e] = 0.0;
#pragma omp parallel num_threads(nthreads) reduction(+ : nfar)
    {
        double *mx = scratch + (size_t)omp_get_thread_num() * (S + 1);
        for (size_t e = 0; e <= S; ++e) mx[e] = 0.0;
        double X[3][CH], V[3][CH];
        int is_far[CH], near_u[CH];
#pragma omp for schedule(dynamic, 1)
        for (size_t b = 0; b < nblk; ++b) {
            const size_t lo = nn * b / nblk, hi = nn * (b + 1) / nblk;
            size_t i = lo;
            uint32_t q = nb->pstart[lo];
            for (size_t s0 = lo; s0 < hi; s0 += CH) {
                const size_t len = hi - s0 < CH ? hi - s0 : CH;
                const double *restrict vx = nb->v[0] + s0, *restrict vy = nb->v[1] + s0;
                const double *restrict vz = nb->v[2] + s0;
                const double *restrict d2m = nb->d2min + s0;
                /* far: its distance less the longest flight and the cut-off
                 * beyond the colloids' budget (1e-9: rounding) */
#pragma omp simd
                for (size_t u = 0; u < len; ++u) {
                    const double speed = sqrt(vx[u] * vx[u] + vy[u] * vy[u] + vz[u] * vz[u]);
                    const double flight = (T * speed + T * T * gmag) * (1.0 + 1e-9);
                    is_far[u] = sqrt(d2m[u]) - rc - flight > reach;
                }
                int m = 0;
                for (size_t u = 0; u < len; ++u) { /* branch-free append */
                    far[s0 + u] = (uint8_t)is_far[u];
                    near_u[m] = (int)u;
                    m += !is_far[u];
                }
                nfar += len - (size_t)m;
                /* the near ones to sub, in order, with their pairs */
                for (int t = 0; t < m; ++t, ++i) {
                    const size_t j = s0 + (size_t)near_u[t];
                    for (int d = 0; d < 3; ++d) {
                        sub->r[d][i] = nb->r[d][j];
                        sub->v[d][i] = nb->v[d][j];
                        sub->r0[d][i] = nb->r0[d][j];
                    }
                    sub->k0[i] = nb->k0[j];
                    map[i] = (uint32_t)j;
                    sub->pstart[i] = q;
                    for (uint32_t p = nb->pstart[j]; p < nb->pstart[j + 1]; ++p, ++q) {
                        sub->pk[q] = nb->pk[p];
                        sub->pj[q] = (uint32_t)i;
                    }
                }
                /* the whole MD step of each particle as free flight (in
                 * L1, vectorised: the near ones' too, but only the far
                 * ones' displacements count and only their rows are
                 * written back), the start velocity kept in the f rows */
                for (int d = 0; d < 3; ++d)
                    for (size_t u = 0; u < len; ++u) {
                        X[d][u] = nb->r[d][s0 + u];
                        V[d][u] = nb->v[d][s0 + u];
                        nb->f[d][s0 + u] = V[d][u];
                    }
                const double *restrict x0 = nb->r0[0] + s0, *restrict y0 = nb->r0[1] + s0;
                const double *restrict z0 = nb->r0[2] + s0;
                for (size_t e = 0; e <= S; ++e) { /* free_eval, vectorised */
                    for (int kick = 0; kick < (e > 0 && e < S ? 2 : 1); ++kick)
                        for (int d = 0; d < 3; ++d) {
                            double *restrict w = V[d];
                            const double kd = k[d];
#pragma omp simd
                            for (size_t u = 0; u < len; ++u) w[u] = w[u] + kd;
                        }
                    if (e == S) break;
                    double top = 0.0;
#pragma omp simd reduction(max : top)
                    for (size_t u = 0; u < len; ++u) {
                        const double px = X[0][u] + V[0][u] * dtm, py = X[1][u] + V[1][u] * dtm;
                        const double pz = X[2][u] + V[2][u] * dtm;
                        X[0][u] = px;
                        X[1][u] = py;
                        X[2][u] = pz;
                        const double a = px - x0[u], bb = py - y0[u], c = pz - z0[u];
                        const double d2 = is_far[u] ? a * a + bb * bb + c * c : 0.0;
                        top = d2 > top ? d2 : top;
                    }
                    mx[e] = top > mx[e] ? top : mx[e];
                }
                for (int d = 0; d < 3; ++d) {
                    double *restrict r = nb->r[d] + s0, *restrict w = nb->v[d] + s0;
#pragma omp simd
                    for (size_t u = 0; u < len; ++u) { /* the far ones only: nb keeps the near ones' start */
                        r[u] = is_far[u] ? X[d][u] : r[u];
                        w[u] = is_far[u] ? V[d][u] : w[u];
                    }
                }
            }
            /* the block's end; a full block's is the next block's start,
             * which that block writes (the same value) */
            if (i < hi || b + 1 == nblk) sub->pstart[i] = q;
            blk[2 * b] = lo;
            blk[2 * b + 1] = i;
        }
#pragma omp critical
        for (size_t e = 0; e <= S; ++e) d2call[e] = mx[e] > d2call[e] ? mx[e] : d2call[e];
    }
    d2call[S] = 0.0;
    sub->n = nn;
    sub->blk = blk;
    sub->nblk = nblk;
    return nfar;
}

void pl_coupling_far_join(const pl_coupling_near_t *sub, const uint32_t *map, const pl_coupling_near_t *nb,
                          int nthreads)
{
#pragma omp parallel for schedule(dynamic, 1) num_threads(nthreads)
    for (size_t b = 0; b < sub->nblk; ++b)
        for (size_t i = sub->blk[2 * b]; i < sub->blk[2 * b + 1]; ++i) {
            const uint32_t j = map[i];
            for (int d = 0; d < 3; ++d) {
                nb->r[d][j] = sub->r[d][i];
                nb->v[d][j] = sub->v[d][i];
            }
        }
}

void pl_coupling_far_resume(const pl_coupling_near_t *sub, const uint32_t *map, const uint8_t *far,
                            const pl_coupling_md_plan_t *plan, int done, const pl_coupling_near_t *nb, int nthreads)
{
    double k[3];
    free_kick(plan, k);
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t j = 0; j < nb->n; ++j) {
        if (!far[j]) continue;
        double r[3], v[3], r0[3];
        for (int d = 0; d < 3; ++d) {
            r[d] = r0[d] = nb->r0[d][j];
            v[d] = nb->f[d][j];
        }
        for (int e = 0; e < done; ++e) (void)free_eval(plan, k, e, r, v, r0);
        for (int d = 0; d < 3; ++d) {
            nb->r[d][j] = r[d];
            nb->v[d][j] = v[d];
        }
    }
    pl_coupling_far_join(sub, map, nb, nthreads);
}
