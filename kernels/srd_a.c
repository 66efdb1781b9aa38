/* SRD+a: the SRD rotation of PL Eq. 3 (random axis, angle alpha; the same
 * rotation the random_axis rule draws for the cell: Philox (seed,
 * PL_RNG_COLLIDE), counter (step, cell)) followed by the rigid rotation
 * that gives the cell back its angular momentum about its centre of mass
 * (peloid/cell_angular.h; Noguchi & Gompper, PRE 78, 016706 (2008)),
 *   v_i' = u + R (v_i - u) + Pi^-1 [sum_j r_j x (v_j - u - R (v_j - u))] x r_i,
 * then the cell's kinetic energy brought back (energy_back below: the part
 * of v' - u that is not the kept rigid rotation scaled), cell by cell
 * (peloid/cell_collide.h: blocks, fixed-order sums, the same bits for any
 * thread count).  The cell's inertia tensor is built once for both the
 * restore and the kept rigid rotation. */
#include <math.h>

#include "peloid/cell_angular.h"
#include "peloid/cell_collide.h"
#include "peloid/srd_a.h"
#include "peloid/srd_rules.h"

/* The cell's relative kinetic energy back to 2 E = before2: the relative velocities are the kept rigid rotation
 * w x r plus a part d with no momentum and (to the rounding of w) no angular momentum, whose energy the two
 * rotations changed; d is scaled by k, the root of sum |w x r + k d|^2 = before2 near 1 (the sums as computed,
 * so the energy comes back to rounding whatever the conditioning of Pi). */
static inline void energy_back(pl_fluid_t *f, const pl_grid_t *g, size_t s, size_t e, const double rc[3],
                               const double w[3], const double u[3], double before2)
{
    double A = 0.0, B = 0.0, C = 0.0; /* sum |d|^2, sum (w x r) . d, sum |w x r|^2 */
    for (size_t i = s; i < e; ++i) {
        double o[3];
        pl_cell_spin(f, g, s, i, rc, w, o);
        for (int d = 0; d < 3; ++d) {
            const double dv = (double)f->v[d][i] - u[d] - o[d];
            A += dv * dv;
            B += o[d] * dv;
            C += o[d] * o[d];
        }
    }
    const double disc = B * B + A * (before2 - C);
    if (A <= 1e-12 * before2 || disc < 0.0) return; /* nothing but the rigid rotation (or no real root) */
    const double k = (sqrt(disc) - B) / A;
    for (size_t i = s; i < e; ++i) {
        double o[3];
        pl_cell_spin(f, g, s, i, rc, w, o);
        for (int d = 0; d < 3; ++d) f->v[d][i] = (pl_real)(u[d] + o[d] + k * ((double)f->v[d][i] - u[d] - o[d]));
    }
}

static inline double srd_a_cell(pl_fluid_t *f, const pl_grid_t *g, const pl_collide_params_t *p, size_t c, size_t s,
                                size_t e)
{
    pl_cell_angular_t a;
    pl_cell_angular_before(f, g, s, e, &a);
    pl_cell_inertia_t I;
    pl_cell_inertia(f, g, s, e, a.rc, &I);
    double w[3] = {0.0, 0.0, 0.0}, R[3][3], P[3] = {0.0, 0.0, 0.0};
    const int turns = pl_cell_inertia_solve(&I, a.L, w); /* the cell's rigid rotation, kept */
    pl_srd_rotation(p->rule, p->cos_a, p->sin_a, p->seed, PL_RNG_COLLIDE, p->step, c, R);
    for (size_t i = s; i < e; ++i)
        for (int d = 0; d < 3; ++d) P[d] += f->v[d][i];
    const double u[3] = {P[0] / (double)(e - s), P[1] / (double)(e - s), P[2] / (double)(e - s)};
    double before2 = 0.0; /* sum |v - u|^2 */
    for (size_t i = s; i < e; ++i) {
        const double x = f->v[0][i] - u[0], y = f->v[1][i] - u[1], z = f->v[2][i] - u[2];
        before2 += x * x + y * y + z * z;
        f->v[0][i] = (pl_real)(u[0] + R[0][0] * x + R[0][1] * y + R[0][2] * z);
        f->v[1][i] = (pl_real)(u[1] + R[1][0] * x + R[1][1] * y + R[1][2] * z);
        f->v[2][i] = (pl_real)(u[2] + R[2][0] * x + R[2][1] * y + R[2][2] * z);
    }
    pl_cell_angular_restore_with(f, g, s, e, &a, &I);
    if (turns) energy_back(f, g, s, e, a.rc, w, u, before2);
    return pl_cell_relative_sum2(f, s, e);
}

void pl_srd_a_collide(pl_fluid_t *f, const pl_grid_t *g, const uint32_t *cell_start, const pl_collide_params_t *p,
                      double *block_sum, int nthreads)
{
    pl_cell_collide_blocks(f, g, cell_start, p, block_sum, nthreads, srd_a_cell);
}
