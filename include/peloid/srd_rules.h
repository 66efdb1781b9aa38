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

/* Marsaglia's method (Ann. Math. Stat. 43, 645 (1972)) on one draw of four
 * uniforms: two points (a, b) uniform in [-1, 1]^2; returns s = a^2 + b^2
 * of the first inside the unit disc, with its (a, b) (s >= 1: neither is,
 * probability (1 - pi/4)^2 = 0.046, and the caller draws again). */
static inline double pl_srd_disc_point(double u0, double u1, double u2, double u3, double *a, double *b)
{
    const double a0 = 2.0 * u0 - 1.0, b0 = 2.0 * u1 - 1.0;
    const double a1 = 2.0 * u2 - 1.0, b1 = 2.0 * u3 - 1.0;
    const double s0 = a0 * a0 + b0 * b0, s1 = a1 * a1 + b1 * b1;
    const int first = s0 < 1.0; /* selects, not branches: the usual case is cheap */
    *a = first ? a0 : a1;
    *b = first ? b0 : b1;
    return first ? s0 : s1;
}

/* Rotation by alpha (cos_a, sin_a) about the axis n = (2a sqrt(1-s),
 * 2b sqrt(1-s), 1-2s) of a disc point (uniform on the sphere; PL Eq. 3,
 * Rodrigues' formula): element (i, j) in R[(3 i + j) * stride]. */
static inline void pl_srd_rodrigues(double a, double b, double s, double cos_a, double sin_a, double *R,
                                    size_t stride)
{
    const double q = 2.0 * sqrt(1.0 - s);
    const double n0 = a * q, n1 = b * q, n2 = 1.0 - 2.0 * s;
    const double ca = cos_a, sa = sin_a, oc = 1.0 - ca;
    R[0 * stride] = ca + n0 * n0 * oc;
    R[1 * stride] = n0 * n1 * oc - n2 * sa;
    R[2 * stride] = n0 * n2 * oc + n1 * sa;
    R[3 * stride] = n1 * n0 * oc + n2 * sa;
    R[4 * stride] = ca + n1 * n1 * oc;
    R[5 * stride] = n1 * n2 * oc - n0 * sa;
    R[6 * stride] = n2 * n0 * oc - n1 * sa;
    R[7 * stride] = n2 * n1 * oc + n0 * sa;
    R[8 * stride] = ca + n2 * n2 * oc;
}

/* Hecht's rotation (Hecht Sec. III) from a uniform u: +-90 deg about
 * coordinate axis a, k = floor(6 u) = 2 a + (sign < 0): e_b -> s e_c,
 * e_c -> -s e_b (b = a + 1, c = a + 2 mod 3), element (i, j) in R[(3 i + j)
 * * stride]; written out for a = 0, 1, 2 so that it vectorises (64-bit
 * integers: the lanes of the doubles). */
static inline void pl_srd_hecht_matrix(double u, double *R, size_t stride)
{
    int64_t k = (int64_t)(u * 6.0);
    k = k > 5 ? 5 : k;
    const int64_t a = k >> 1;
    const double sg = (k & 1) ? -1.0 : 1.0;
    R[0 * stride] = a == 0 ? 1.0 : 0.0; /* R[a][a] = 1 */
    R[4 * stride] = a == 1 ? 1.0 : 0.0;
    R[8 * stride] = a == 2 ? 1.0 : 0.0;
    R[7 * stride] = a == 0 ? sg : 0.0; /* R[c][b] = s, R[b][c] = -s */
    R[5 * stride] = a == 0 ? -sg : 0.0;
    R[2 * stride] = a == 1 ? sg : 0.0;
    R[6 * stride] = a == 1 ? -sg : 0.0;
    R[3 * stride] = a == 2 ? sg : 0.0;
    R[1 * stride] = a == 2 ? -sg : 0.0;
}

/* The random axis of a cell whose first draw (s0 >= 1) had no disc point:
 * draws 1, 2, ... of its stream until one has. */
static inline double pl_srd_disc_redraw(uint64_t seed, uint64_t purpose, uint64_t step, uint64_t cell, double *a,
                                        double *b)
{
    double s = 1.0;
    for (uint64_t draw = 1; !(s < 1.0); ++draw) {
        const pl_rand4_t r = pl_rng_uniform4(seed, purpose, step, cell, draw);
        s = pl_srd_disc_point(r.u[0], r.u[1], r.u[2], r.u[3], a, b);
    }
    return s;
}

/* Rotation matrix of one cell's collision, from the caller's counter-based
 * stream (seed, purpose, step, cell) (draw 0, and draw 1, 2, ... only when
 * needed).  PL_RULE_RANDOM_AXIS: rotation by alpha (cos_a, sin_a) about an
 * axis uniform on the sphere (PL Eq. 3, Rodrigues' formula); the axis by
 * Marsaglia's method, which needs no trigonometric function.  One draw
 * gives two (a, b) pairs; the first inside the disc is used (the second
 * only when the first is not: probability 1 - pi/4), a further draw when
 * neither is (0.046).  PL_RULE_HECHT_AXES: +-90 deg about one of the three
 * coordinate axes, each of the 6 with probability 1/6 (Hecht Sec. III),
 * from the first uniform. */
static inline void pl_srd_rotation(int rule, double cos_a, double sin_a, uint64_t seed,
                                   uint64_t purpose, uint64_t step, uint64_t cell, double R[3][3])
{
    pl_rand4_t r = pl_rng_uniform4(seed, purpose, step, cell, 0);
    if (rule == PL_RULE_HECHT_AXES) {
        pl_srd_hecht_matrix(r.u[0], &R[0][0], 1);
        return;
    }
    double a, b, s = pl_srd_disc_point(r.u[0], r.u[1], r.u[2], r.u[3], &a, &b);
    if (!(s < 1.0)) s = pl_srd_disc_redraw(seed, purpose, step, cell, &a, &b);
    pl_srd_rodrigues(a, b, s, cos_a, sin_a, &R[0][0], 1);
}

/* pl_srd_rotation of the PL_RNG_LANES cells cell0, cell0 + 1, ..., bit for
 * bit, element (i, j) of cell cell0 + l in R[3 i + j][l].  PL_RULE_RANDOM_AXIS
 * runs the first draw, the disc test and Rodrigues' formula in vector lanes
 * (the same operations in the same order); a cell whose first draw has no
 * disc point (0.046) draws again alone.  PL_RULE_HECHT_AXES: the axis and
 * sign from the first uniform, in lanes too. */
static inline void pl_srd_rotations(int rule, double cos_a, double sin_a, uint64_t seed, uint64_t purpose,
                                    uint64_t step, uint64_t cell0, double R[9][PL_RNG_LANES])
{
    enum { NL = PL_RNG_LANES };
    _Static_assert(PL_RNG_LANES <= 32, "one bit per lane in a uint32_t");
    double u[4][NL];
    pl_rng_uniform4_lanes(seed, purpose, step, cell0, 0, u);
    if (rule == PL_RULE_HECHT_AXES) { /* pl_srd_rotation's matrix, written out for a = 0, 1, 2 */
#pragma omp simd
        for (size_t l = 0; l < NL; ++l) pl_srd_hecht_matrix(u[0][l], &R[0][l], NL);
        return;
    }
    uint32_t redo = 0; /* bit l: lane l draws again */
    /* gcc vectorises this loop only when asked; clang unasked, where sqrt
     * sets no errno (srd_collide.o), and asked it warns where it does */
#if !defined(__clang__)
#pragma omp simd reduction(| : redo)
#endif
    for (size_t l = 0; l < NL; ++l) {
        double a, b;
        const double s = pl_srd_disc_point(u[0][l], u[1][l], u[2][l], u[3][l], &a, &b);
        redo |= (uint32_t)!(s < 1.0) << l;
        pl_srd_rodrigues(a, b, s < 1.0 ? s : 0.0, cos_a, sin_a, &R[0][l], NL); /* s >= 1: redone below */
    }
    for (; redo; redo &= redo - 1) { /* ~1.5 lanes of 32 */
        const size_t l = (size_t)__builtin_ctz(redo);
        double a, b;
        const double s = pl_srd_disc_redraw(seed, purpose, step, cell0 + l, &a, &b);
        pl_srd_rodrigues(a, b, s, cos_a, sin_a, &R[0][l], NL);
    }
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

/* An interval [*lo, *hi] that holds log(1 + e) for |e| <= 1/4 (e exact),
 * and the value libm's log returns for it (within 1e-13 relative): the
 * alternating series to e^5 (its tail below |e|^6 / (6 (1 - |e|))).
 * Returns 0 for larger |e| (or a NaN). */
static inline int pl_log1p_bracket(double e, double *lo, double *hi)
{
    const double ae = fabs(e);
    if (!(ae <= 0.25)) return 0;
    /* log(1 + e) = e (1 - e (1/2 - e (1/3 - e (1/4 - e / 5)))) + tail */
    const double s = e * (1.0 - e * (0.5 - e * (1.0 / 3.0 - e * (0.25 - e * 0.2))));
    const double e2 = ae * ae, e6 = e2 * e2 * e2;
    const double w = e6 * (1.0 / 6.0) * (1.0 / 0.75) * 1.001 + 1e-13 * fabs(s) + 1e-300;
    *lo = s - w;
    *hi = s + w;
    return 1;
}

/* Heyes Monte Carlo scale factor (Hecht Sec. VIII.B, Eq. 33) for a cell of
 * nbody bodies with relative kinetic energy K = sum m (v-u)^2 / 2, from three
 * uniforms: eps = eps_max u0; zeta = 1+eps or 1/(1+eps) (u1 < 1/2), accepted
 * (u2) with probability min(1, zeta^{3(nbody-1)} exp(-(zeta^2-1) K/kT*)).
 * With Hecht's T = m sum (v-u)^2 / (2 (M-1) k_B) this is his Eq. 33 exactly.
 * Returns 1 when rejected.
 *
 * The decision is that of log_acc = dof log(zeta) - (zeta^2 - 1) K / kT*
 * >= 0 or log(u2) < log_acc, with libm's log.  The two logarithms were a
 * large share of the thermostat's collision (bench/RESULTS.md); the
 * decision is taken without them where intervals settle it (most cells):
 * log(zeta) within pl_log1p_bracket (rounding is
 * monotone, so dof lo - B <= log_acc <= dof hi - B for the computed
 * log_acc), log(u2) within [1 - 1/u2, u2 - 1] widened by 1e-13 relative
 * and 1e-15.  Where they do not (near a boundary), both logarithms as
 * before: the same decisions, the same bits (collide::heyes_decision_
 * equals_the_logarithms). */
static inline double pl_heyes_zeta(double eps_max, double kT_target, double nbody, double K,
                                   double u0, double u1, double u2)
{
    double eps = eps_max * u0;
    double zeta = u1 < 0.5 ? 1.0 + eps : 1.0 / (1.0 + eps);
    double dof = 3.0 * (nbody - 1.0);
    const double B = (zeta * zeta - 1.0) * K / kT_target;
    double Llo, Lhi;
    if (dof >= 0.0 && pl_log1p_bracket(zeta - 1.0, &Llo, &Lhi)) { /* zeta - 1: exact (Sterbenz) */
        const double acc_lo = dof * Llo - B, acc_hi = dof * Lhi - B;
        const double ulo = 1.0 - 1.0 / u2, uhi = u2 - 1.0;
        /* flags, not branches: one branch, taken in most cells */
        const int neg = acc_hi < 0.0;
        const int accept = (acc_lo >= 0.0) | (neg & (uhi + 1e-13 * fabs(uhi) + 1e-15 < acc_lo));
        const int reject = neg & (ulo - 1e-13 * fabs(ulo) - 1e-15 >= acc_hi);
        if (accept | reject) return accept ? zeta : 1.0;
    }
    double log_acc = dof * log(zeta) - B;
    return (log_acc >= 0.0 || log(u2) < log_acc) ? zeta : 1.0;
}

#endif
