/* MPC-AT, the Andersen-thermostat collision (peloid/mpc_at.h; Noguchi,
 * Kikuchi & Gompper, EPL 78, 10005 (2007)), cell by cell
 * (peloid/cell_collide.h: blocks, fixed-order sums).  The draws are keyed
 * (seed, PL_RNG_ANDERSEN, step, cell, rank in the cell): the same bits for
 * any thread count. */
#include <math.h>

#include "peloid/cell_collide.h"
#include "peloid/mpc_at.h"

static inline double at_cell(pl_fluid_t *f, const pl_grid_t *g, const pl_collide_params_t *p, size_t c, size_t s,
                             size_t e)
{
    (void)g;
    return pl_mpc_at_cell(f->v[0], f->v[1], f->v[2], s, e, sqrt(p->kT_target), p->seed, p->step, c);
}

void pl_mpc_at_collide(pl_fluid_t *f, const pl_grid_t *g, const uint32_t *cell_start,
                       const pl_collide_params_t *p, double *block_sum, int nthreads)
{
    pl_cell_collide_blocks(f, g, cell_start, p, block_sum, nthreads, at_cell);
}
