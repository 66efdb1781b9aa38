/* Whole-fluid velocity kernels outside the collision: the initial state
 * (uniform positions; uniform or Gaussian velocities with zero total
 * momentum and exactly the set temperature) and the uniform velocity shift
 * of the drift removal and the flow hold (Hecht Sec. VIII.A).
 *
 * Every particle's initial draws are keyed by its index and each particle is
 * written by one iteration; the momentum and v^2 sums of the initial state
 * are serial in particle order: the results do not depend on the thread
 * count. */
#include <math.h>

#include "peloid/rng.h"
#include "peloid/srd_kernels.h"

void pl_srd_init(pl_fluid_t *f, const pl_srd_init_params_t *p, int nthreads)
{
    const uint64_t seed = p->seed;
    const double kT = p->kT;
    const int uniform = p->uniform;
    const double L[3] = {p->L[0], p->L[1], p->L[2]};
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t i = 0; i < f->n; ++i) {
        pl_rand4_t rp = pl_rng_uniform4(seed, PL_RNG_INIT_POS, 0, i, 0);
        pl_rand4_t q = pl_rng_uniform4(seed, PL_RNG_INIT_VEL, 0, i, 0);
        double v[4];
        if (uniform) {
            for (int d = 0; d < 3; ++d) v[d] = (q.u[d] - 0.5) * sqrt(12.0 * kT); /* Hecht Fig. 2 */
        } else {
            pl_rng_gauss2(q.u[0], q.u[1], &v[0], &v[1]);
            pl_rng_gauss2(q.u[2], q.u[3], &v[2], &v[3]);
            for (int d = 0; d < 3; ++d) v[d] *= sqrt(kT);
        }
        for (int d = 0; d < 3; ++d) {
            double x = rp.u[d] * L[d];
            f->r[d][i] = (pl_real)(x >= L[d] ? 0.0 : x);
            f->v[d][i] = (pl_real)v[d];
        }
        if (f->tracked) {
            f->id[i] = (uint32_t)i;
            for (int d = 0; d < 3; ++d) f->disp[d][i] = 0.0;
        }
    }
    if (f->n < 2) return;
    /* zero total momentum, then exact temperature kT = sum v^2 / (3 (N-1)) */
    double P[3] = {0, 0, 0};
    for (size_t i = 0; i < f->n; ++i)
        for (int d = 0; d < 3; ++d) P[d] += f->v[d][i];
    double S = 0.0;
    for (size_t i = 0; i < f->n; ++i)
        for (int d = 0; d < 3; ++d) {
            double w = f->v[d][i] - P[d] / (double)f->n;
            S += w * w;
        }
    double scale = sqrt(kT * 3.0 * (double)(f->n - 1) / S);
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t i = 0; i < f->n; ++i)
        for (int d = 0; d < 3; ++d)
            f->v[d][i] = (pl_real)((f->v[d][i] - P[d] / (double)f->n) * scale);
}

void pl_srd_velocity_add(pl_fluid_t *f, const double du[3], int nthreads)
{
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t i = 0; i < f->n; ++i)
        for (int d = 0; d < 3; ++d) f->v[d][i] = (pl_real)(f->v[d][i] + du[d]);
}
