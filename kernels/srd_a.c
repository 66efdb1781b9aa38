/* SRD+a: the SRD rotation of PL Eq. 3 (random axis, angle alpha; the same
 * rotation the random_axis rule draws for the cell: Philox (seed,
 * PL_RNG_COLLIDE), counter (step, cell)) followed by the rigid rotation
 * that gives the cell back its angular momentum about its centre of mass
 * (peloid/cell_angular.h; Noguchi & Gompper, PRE 78, 016706 (2008)),
 *   v_i' = u + R (v_i - u) + Pi^-1 [sum_j r_j x (v_j - u - R (v_j - u))] x r_i,
 * cell by cell (peloid/cell_collide.h: blocks, fixed-order sums, the same
 * bits for any thread count). */
#include <math.h>

#include "peloid/cell_angular.h"
#include "peloid/cell_collide.h"
#include "peloid/srd_a.h"
#include "peloid/srd_rules.h"

static inline double srd_a_cell(pl_fluid_t *f, const pl_grid_t *g, const pl_collide_params_t *p, size_t c, size_t s,
                                size_t e)
{
    pl_cell_angular_t a;
    pl_cell_angular_before(f, g, s, e, &a);
    double R[3][3], P[3] = {0.0, 0.0, 0.0};
    pl_srd_rotation(p->rule, p->cos_a, p->sin_a, p->seed, PL_RNG_COLLIDE, p->step, c, R);
    for (size_t i = s; i < e; ++i)
        for (int d = 0; d < 3; ++d) P[d] += f->v[d][i];
    const double u[3] = {P[0] / (double)(e - s), P[1] / (double)(e - s), P[2] / (double)(e - s)};
    for (size_t i = s; i < e; ++i) {
        const double x = f->v[0][i] - u[0], y = f->v[1][i] - u[1], z = f->v[2][i] - u[2];
        f->v[0][i] = (pl_real)(u[0] + R[0][0] * x + R[0][1] * y + R[0][2] * z);
        f->v[1][i] = (pl_real)(u[1] + R[1][0] * x + R[1][1] * y + R[1][2] * z);
        f->v[2][i] = (pl_real)(u[2] + R[2][0] * x + R[2][1] * y + R[2][2] * z);
    }
    pl_cell_angular_restore(f, g, s, e, &a);
    return pl_cell_relative_sum2(f, s, e);
}

void pl_srd_a_collide(pl_fluid_t *f, const pl_grid_t *g, const uint32_t *cell_start, const pl_collide_params_t *p,
                      double *block_sum, int nthreads)
{
    pl_cell_collide_blocks(f, g, cell_start, p, block_sum, nthreads, srd_a_cell);
}
