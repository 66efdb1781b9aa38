/* The SRD collision rule and the Heyes acceptance, shared by the fluid
 * collision (kernels/srd_collide.c) and coupling II (kernels/coupling_collide.c).
 * Pure functions of the caller's counter-based stream key or of uniforms it
 * drew (each caller keys its own stream). */
#ifndef PELOID_SRD_RULES_H
#define PELOID_SRD_RULES_H

#include <math.h>

#include "peloid/grid.h"
#include "peloid/kernel_enums.h" /* PL_RULE_*, PL_WALLS_* */
#include "peloid/rng.h"

/* Rotation matrix of one cell's collision, from the caller's counter-based
 * stream (seed, purpose, step, cell) (draw 0, and draw 1, 2, ... only when
 * needed).  PL_RULE_RANDOM_AXIS: rotation by alpha (cos_a, sin_a) about an
 * axis uniform on the sphere (PL Eq. 3, Rodrigues' formula); the axis by
 * Marsaglia's method (Ann. Math. Stat. 43, 645 (1972)): (a, b) uniform in the
 * unit disc, s = a^2 + b^2, n = (2a sqrt(1-s), 2b sqrt(1-s), 1-2s), which
 * needs no trigonometric function.  One draw gives two (a, b) pairs; the
 * first inside the disc is used (the second only when the first is not:
 * probability 1 - pi/4), a further draw when neither is (0.046).
 * PL_RULE_HECHT_AXES: +-90 deg about one of the three coordinate axes, each
 * of the 6 with probability 1/6 (Hecht Sec. III), from the first uniform. */
static inline void pl_srd_rotation(int rule, double cos_a, double sin_a, uint64_t seed,
                                   uint64_t purpose, uint64_t step, uint64_t cell, double R[3][3])
{
    pl_rand4_t r = pl_rng_uniform4(seed, purpose, step, cell, 0);
    if (rule == PL_RULE_HECHT_AXES) {
        int k = (int)(r.u[0] * 6.0); /* 0..5: axis k/2, sign by parity */
        if (k > 5) k = 5;
        int a = k >> 1;
        double s = (k & 1) ? -1.0 : 1.0;
        int b = (a + 1) % 3, c = (a + 2) % 3;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) R[i][j] = 0.0;
        /* rotation by s*90 deg about axis a: e_b -> s e_c, e_c -> -s e_b */
        R[a][a] = 1.0;
        R[c][b] = s;
        R[b][c] = -s;
        return;
    }
    double a, b, s;
    for (uint64_t draw = 1;; ++draw) {
        const double a0 = 2.0 * r.u[0] - 1.0, b0 = 2.0 * r.u[1] - 1.0;
        const double a1 = 2.0 * r.u[2] - 1.0, b1 = 2.0 * r.u[3] - 1.0;
        const double s0 = a0 * a0 + b0 * b0, s1 = a1 * a1 + b1 * b1;
        const int first = s0 < 1.0; /* selects, not branches: the usual case is cheap */
        a = first ? a0 : a1;
        b = first ? b0 : b1;
        s = first ? s0 : s1;
        if (s < 1.0) break;
        r = pl_rng_uniform4(seed, purpose, step, cell, draw);
    }
    const double q = 2.0 * sqrt(1.0 - s);
    double n[3] = {a * q, b * q, 1.0 - 2.0 * s};
    double ca = cos_a, sa = sin_a, oc = 1.0 - ca;
    R[0][0] = ca + n[0] * n[0] * oc;
    R[0][1] = n[0] * n[1] * oc - n[2] * sa;
    R[0][2] = n[0] * n[2] * oc + n[1] * sa;
    R[1][0] = n[1] * n[0] * oc + n[2] * sa;
    R[1][1] = ca + n[1] * n[1] * oc;
    R[1][2] = n[1] * n[2] * oc - n[0] * sa;
    R[2][0] = n[2] * n[0] * oc - n[1] * sa;
    R[2][1] = n[2] * n[1] * oc + n[0] * sa;
    R[2][2] = ca + n[2] * n[2] * oc;
}

/* Virtual wall particles of collision cell c holding M >= 1 real bodies of
 * the fluid: 0 when no no-slip wall cuts the cell, else enough to fill it to
 * the mean density gamma (Lamura et al. 2001; the walls are Hecht Sec.
 * VIII.A options i, ii); *wall receives the z wall whose velocity they
 * carry (0 bottom, 1 top) or -1 for a cell cut by x/y walls only (at
 * rest). */
static inline int pl_srd_ghost_count(const pl_grid_t *g, double gamma, size_t c, size_t M, int *wall)
{
    const size_t n0 = (size_t)g->n[0], n1 = (size_t)g->n[1];
    int cut = 0;
    *wall = -1;
    for (int d = 0; d < 3; ++d) {
        if (g->walls[d] != PL_WALLS_NOSLIP) continue;
        const size_t i = d == 0 ? c % n0 : d == 1 ? c / n0 % n1 : c / (n0 * n1); /* cell index on axis d */
        double lo = (double)i - 1.0 + g->shift[d], hi = lo + 1.0, L = g->L[d];
        if (lo >= 0.0 && hi <= L) continue;
        cut = 1;
        if (d == 2) *wall = lo < 0.0 ? 0 : 1;
    }
    if (!cut) return 0;
    int target = (int)lround(gamma);
    return (int)M < target ? target - (int)M : 0;
}

/* Thermal part of the momentum the ng virtual particles of cell c bring
 * (they add ng U + noise): a Maxwell-Boltzmann sum at kT_wall, one draw of
 * the wall-ghost stream. */
static inline void pl_srd_ghost_noise(uint64_t seed, uint64_t step, uint64_t c, int ng, double kT_wall,
                                      double noise[3])
{
    pl_rand4_t r = pl_rng_uniform4(seed, PL_RNG_WALL_GHOST, step, c, 0);
    double gs[4], sd = sqrt((double)ng * kT_wall);
    pl_rng_gauss2(r.u[0], r.u[1], &gs[0], &gs[1]);
    pl_rng_gauss2(r.u[2], r.u[3], &gs[2], &gs[3]);
    for (int d = 0; d < 3; ++d) noise[d] = sd * gs[d];
}

/* Heyes Monte Carlo scale factor (Hecht Sec. VIII.B, Eq. 33) for a cell of
 * nbody bodies with relative kinetic energy K = sum m (v-u)^2 / 2, from three
 * uniforms: eps = eps_max u0; zeta = 1+eps or 1/(1+eps) (u1 < 1/2), accepted
 * (u2) with probability min(1, zeta^{3(nbody-1)} exp(-(zeta^2-1) K/kT*)).
 * With Hecht's T = m sum (v-u)^2 / (2 (M-1) k_B) this is his Eq. 33 exactly.
 * Returns 1 when rejected. */
static inline double pl_heyes_zeta(double eps_max, double kT_target, double nbody, double K,
                                   double u0, double u1, double u2)
{
    double eps = eps_max * u0;
    double zeta = u1 < 0.5 ? 1.0 + eps : 1.0 / (1.0 + eps);
    double dof = 3.0 * (nbody - 1.0);
    double log_acc = dof * log(zeta) - (zeta * zeta - 1.0) * K / kT_target;
    return (log_acc >= 0.0 || log(u2) < log_acc) ? zeta : 1.0;
}

#endif
