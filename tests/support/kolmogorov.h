/* The Kolmogorov-flow viscosity measurement shared by test_viscosity and
 * test_mpc_viscosity: a body force F sin(k z) on v_x (k = 2 pi / Lz,
 * F = 0.25 nu k^2 for an amplitude ~0.25 at the theory's nu) applied each
 * step, 3 relaxation times tau = 1/(nu k^2) to settle, then ntau of them
 * in nblocks consecutive blocks; the amplitude of sin(k z) in v_x every 4th
 * step gives nu = F / (k^2 amplitude) per block; mean and SE over blocks. */
#ifndef PELOID_TEST_KOLMOGOROV_H
#define PELOID_TEST_KOLMOGOROV_H

#include <math.h>

#include "support.h"

enum { PL_KOLMOGOROV_MAXBLOCKS = 16 };

/* sim: a periodic fluid of height Lz (cells) and SRD step lambda; returns
 * the steps run. */
static inline long long pl_test_kolmogorov_nu(pl_sim_t *sim, double nu_theory, int Lz, double lambda, double ntau,
                                              int nblocks, double *mean, double *sem)
{
    cr_assert(nblocks >= 2 && nblocks <= PL_KOLMOGOROV_MAXBLOCKS, "nblocks %d", nblocks);
    const double k = 2.0 * M_PI / Lz, A = 0.25, F = A * nu_theory * k * k; /* target amplitude ~ A */
    const double tau = 1.0 / (nu_theory * k * k);
    const long long n_eq = (long long)(3.0 * tau / lambda), n_avg = (long long)(ntau * tau / lambda);
    const long long per_block = n_avg / nblocks;
    double block[PL_KOLMOGOROV_MAXBLOCKS] = {0};
    for (long long s = 0; s < n_eq + nblocks * per_block; ++s) {
        pl_real *vx = sim->fluid.v[0], *z = sim->fluid.r[2];
#pragma omp parallel for schedule(static) num_threads(sim->nthreads)
        for (size_t i = 0; i < sim->fluid.n; ++i) vx[i] += (pl_real)(F * lambda * sin(k * z[i]));
        pl_test_steps(sim, 1);
        if (s < n_eq || s % 4) continue;
        vx = sim->fluid.v[0]; /* the sort swapped the arrays */
        z = sim->fluid.r[2];
        double a = 0.0;
#pragma omp parallel for schedule(static) num_threads(sim->nthreads) reduction(+ : a)
        for (size_t i = 0; i < sim->fluid.n; ++i) a += vx[i] * sin(k * z[i]);
        block[(s - n_eq) / per_block] += 2.0 * a / (double)sim->fluid.n / (double)((per_block + 3) / 4);
    }
    double sum = 0, sum2 = 0;
    for (int b = 0; b < nblocks; ++b) {
        double nu = F / (k * k * block[b]);
        sum += nu;
        sum2 += nu * nu;
    }
    *mean = sum / nblocks;
    *sem = sqrt((sum2 / nblocks - *mean * *mean) / (nblocks - 1));
    return n_eq + nblocks * per_block;
}

#endif
