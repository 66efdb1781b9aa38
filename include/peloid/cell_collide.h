/* The loop of a collision rule that works cell by cell (MPC-AT and its
 * angular-momentum form; peloid/collision_rule.h): blocks of PL_CELL_BLOCK
 * cells, each block's partial sums in its own slot (summed by the caller in
 * block order: the same bits for any thread count), the fluid guard's speed
 * flag per block.  The rule gives the step of one cell with >= 2 particles,
 * which returns sum (v' - u)^2 over the cell after it.
 *
 * Cells are independent and own their particles (contiguous after the
 * counting sort), so a static loop over blocks is race-free. */
#ifndef PELOID_CELL_COLLIDE_H
#define PELOID_CELL_COLLIDE_H

#include "peloid/srd_kernels.h"

/* The step of cell c, particles [s, e), e - s >= 2. */
typedef double (*pl_cell_collide_fn)(pl_fluid_t *fluid, const pl_grid_t *grid, const pl_collide_params_t *p,
                                     size_t c, size_t s, size_t e);

/* Runs `cell` (a constant at each call site: it is inlined) on every cell
 * with >= 2 particles; block_sum[2b], [2b+1]: sum (v' - u)^2 and 3 (M - 1)
 * of block b (the contract of pl_srd_collide). */
static inline __attribute__((always_inline)) void pl_cell_collide_blocks(pl_fluid_t *f, const pl_grid_t *g,
                                                                         const uint32_t *cell_start,
                                                                         const pl_collide_params_t *p,
                                                                         double *block_sum, int nthreads,
                                                                         pl_cell_collide_fn cell)
{
    const size_t ncells = g->ncells, nblocks = (ncells + PL_CELL_BLOCK - 1) / PL_CELL_BLOCK;
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t b = 0; b < nblocks; ++b) {
        const pl_real *vx = f->v[0], *vy = f->v[1], *vz = f->v[2];
        const size_t c_hi = (b + 1) * PL_CELL_BLOCK < ncells ? (b + 1) * PL_CELL_BLOCK : ncells;
        double sum2 = 0.0, dof = 0.0;
        int bad = 0;
        for (size_t c = b * PL_CELL_BLOCK; c < c_hi; ++c) {
            const size_t s = cell_start[c], e = cell_start[c + 1];
            if (e - s >= 2) {
                sum2 += cell(f, g, p, c, s, e);
                dof += 3.0 * (double)(e - s - 1);
            }
            if (p->guard_bad) /* the fluid guard's speed test (srd_guard.c), per particle */
                for (size_t i = s; i < e; ++i) {
                    const double x = vx[i], y = vy[i], z = vz[i];
                    bad |= !(x * x + y * y + z * z <= p->guard_vmax2);
                }
        }
        if (p->guard_bad) p->guard_bad[b] = (unsigned char)bad;
        block_sum[2 * b] = sum2;
        block_sum[2 * b + 1] = dof;
    }
}

#endif
