/* A cell's angular momentum kept through a collision (the "+a" of MPC-AT+a
 * and SRD+a: Noguchi, Kikuchi & Gompper, EPL 78, 10005 (2007); Noguchi &
 * Gompper, PRE 78, 016706 (2008)): after the collision each particle gets
 *   v_i += Pi^-1 [sum_j m r_j x (v_j - v_j')] x r_i,
 * r_j the position relative to the centre of mass r_c of the cell's
 * particles (unwrapped across a periodic boundary in the shifted grid), v
 * before and v' after the collision, Pi = sum_j m (r_j^2 I - r_j r_j^T) their
 * moment-of-inertia tensor about r_c.  The rigid rotation gives back the
 * angular momentum the collision took (sum r x (w x r) = Pi w) and no
 * momentum (sum r_j = 0).  A cell of 2 particles, or collinear ones, has a
 * singular Pi: its angular momentum is perpendicular to the line, where
 * Pi = (tr Pi / 2) (I - n n^T), so w = 2 Delta L / tr Pi.  m = 1. */
#ifndef PELOID_CELL_ANGULAR_H
#define PELOID_CELL_ANGULAR_H

#include "peloid/srd_kernels.h"

typedef struct {
    double rc[3]; /* centre of mass, relative to the cell's first particle */
    double L[3];  /* angular momentum about rc before the collision */
} pl_cell_angular_t;

/* Position of particle i relative to particle s (the cell's first): the
 * nearest image along periodic axes (a cell is one a0 wide). */
static inline void pl_cell_rel(const pl_fluid_t *f, const pl_grid_t *g, size_t s, size_t i, double x[3])
{
    for (int d = 0; d < 3; ++d) {
        double a = (double)f->r[d][i] - (double)f->r[d][s];
        const double L = g->L[d];
        if (g->walls[d] == PL_WALLS_NONE) a = a > 0.5 * L ? a - L : a < -0.5 * L ? a + L : a;
        x[d] = a;
    }
}

/* Angular momentum of particles [s, e) about rc (relative to particle s). */
static inline void pl_cell_L(const pl_fluid_t *f, const pl_grid_t *g, size_t s, size_t e, const double rc[3],
                             double L[3])
{
    L[0] = L[1] = L[2] = 0.0;
    for (size_t i = s; i < e; ++i) {
        double x[3];
        pl_cell_rel(f, g, s, i, x);
        const double a = x[0] - rc[0], b = x[1] - rc[1], c = x[2] - rc[2];
        const double vx = f->v[0][i], vy = f->v[1][i], vz = f->v[2][i];
        L[0] += b * vz - c * vy;
        L[1] += c * vx - a * vz;
        L[2] += a * vy - b * vx;
    }
}

/* Before the collision of particles [s, e): their centre of mass and
 * angular momentum. */
static inline void pl_cell_angular_before(const pl_fluid_t *f, const pl_grid_t *g, size_t s, size_t e,
                                          pl_cell_angular_t *a)
{
    double R[3] = {0.0, 0.0, 0.0};
    for (size_t i = s; i < e; ++i) {
        double x[3];
        pl_cell_rel(f, g, s, i, x);
        R[0] += x[0]; R[1] += x[1]; R[2] += x[2];
    }
    for (int d = 0; d < 3; ++d) a->rc[d] = R[d] / (double)(e - s);
    pl_cell_L(f, g, s, e, a->rc, a->L);
}

/* The moment-of-inertia tensor Pi of particles [s, e) about rc, kept as
 * what solving Pi w = L needs: its adjugate and determinant, and tr S
 * (S = sum r r^T, tr Pi = 2 tr S) for 2 particles or collinear ones. */
typedef struct {
    double c00, c01, c02, c11, c12, c22; /* adj(Pi), symmetric */
    double det, tr;
} pl_cell_inertia_t;

static inline void pl_cell_inertia(const pl_fluid_t *f, const pl_grid_t *g, size_t s, size_t e, const double rc[3],
                                   pl_cell_inertia_t *I)
{
    double S[6] = {0, 0, 0, 0, 0, 0}; /* S = sum r r^T: xx yy zz xy xz yz */
    for (size_t i = s; i < e; ++i) {
        double x[3];
        pl_cell_rel(f, g, s, i, x);
        const double p = x[0] - rc[0], q = x[1] - rc[1], r = x[2] - rc[2];
        S[0] += p * p; S[1] += q * q; S[2] += r * r;
        S[3] += p * q; S[4] += p * r; S[5] += q * r;
    }
    const double tr = S[0] + S[1] + S[2];
    /* Pi = tr(S) I - S */
    const double a00 = tr - S[0], a11 = tr - S[1], a22 = tr - S[2], a01 = -S[3], a02 = -S[4], a12 = -S[5];
    I->c00 = a11 * a22 - a12 * a12;
    I->c01 = a02 * a12 - a01 * a22;
    I->c02 = a01 * a12 - a02 * a11;
    I->c11 = a00 * a22 - a02 * a02;
    I->c12 = a01 * a02 - a00 * a12;
    I->c22 = a00 * a11 - a01 * a01;
    I->det = a00 * I->c00 + a01 * I->c01 + a02 * I->c02;
    I->tr = tr;
}

/* The angular velocity w = Pi^-1 L of the rigid rotation that carries
 * angular momentum L (see above: 2 particles or collinear ones,
 * w = 2 L / tr Pi); 0 when all sit at one point. */
static inline int pl_cell_inertia_solve(const pl_cell_inertia_t *I, const double L[3], double w[3])
{
    const double t3 = I->tr * I->tr * I->tr; /* tr Pi = 2 tr S */
    if (I->det > 1e-9 * t3) { /* Pi^-1 = adj(Pi) / det */
        w[0] = (I->c00 * L[0] + I->c01 * L[1] + I->c02 * L[2]) / I->det;
        w[1] = (I->c01 * L[0] + I->c11 * L[1] + I->c12 * L[2]) / I->det;
        w[2] = (I->c02 * L[0] + I->c12 * L[1] + I->c22 * L[2]) / I->det;
    } else if (I->tr > 0.0) { /* 2 particles or collinear ones */
        for (int d = 0; d < 3; ++d) w[d] = L[d] / I->tr; /* 2 L / tr Pi, tr Pi = 2 tr S */
    } else {
        return 0; /* all at one point: no angular momentum to keep */
    }
    return 1;
}

/* w x (x_i - rc) of particle i (x_i relative to particle s). */
static inline void pl_cell_spin(const pl_fluid_t *f, const pl_grid_t *g, size_t s, size_t i, const double rc[3],
                                const double w[3], double o[3])
{
    double x[3];
    pl_cell_rel(f, g, s, i, x);
    const double p = x[0] - rc[0], q = x[1] - rc[1], r = x[2] - rc[2];
    o[0] = w[1] * r - w[2] * q;
    o[1] = w[2] * p - w[0] * r;
    o[2] = w[0] * q - w[1] * p;
}

/* After the collision: the rigid rotation that gives back the angular
 * momentum a->L, with the cell's inertia I (pl_cell_inertia about a->rc). */
static inline void pl_cell_angular_restore_with(pl_fluid_t *f, const pl_grid_t *g, size_t s, size_t e,
                                                const pl_cell_angular_t *a, const pl_cell_inertia_t *I)
{
    double L[3], w[3];
    pl_cell_L(f, g, s, e, a->rc, L);
    const double dL[3] = {a->L[0] - L[0], a->L[1] - L[1], a->L[2] - L[2]};
    if (!pl_cell_inertia_solve(I, dL, w)) return;
    for (size_t i = s; i < e; ++i) {
        double o[3];
        pl_cell_spin(f, g, s, i, a->rc, w, o);
        for (int d = 0; d < 3; ++d) f->v[d][i] = (pl_real)(f->v[d][i] + o[d]);
    }
}

/* The same, the inertia computed here. */
static inline void pl_cell_angular_restore(pl_fluid_t *f, const pl_grid_t *g, size_t s, size_t e,
                                           const pl_cell_angular_t *a)
{
    pl_cell_inertia_t I;
    pl_cell_inertia(f, g, s, e, a->rc, &I);
    pl_cell_angular_restore_with(f, g, s, e, a, &I);
}

/* sum (v - u)^2 of particles [s, e) (u their mean velocity). */
static inline double pl_cell_relative_sum2(const pl_fluid_t *f, size_t s, size_t e)
{
    double P[3] = {0.0, 0.0, 0.0}, S = 0.0;
    for (size_t i = s; i < e; ++i)
        for (int d = 0; d < 3; ++d) {
            P[d] += f->v[d][i];
            S += (double)f->v[d][i] * f->v[d][i];
        }
    return S - (P[0] * P[0] + P[1] * P[1] + P[2] * P[2]) / (double)(e - s);
}

#endif
