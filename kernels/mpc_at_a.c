/* MPC-AT+a: the Andersen-thermostat collision (peloid/mpc_at.h) followed by
 * the rigid rotation that keeps each cell's angular momentum
 * (peloid/cell_angular.h; Noguchi, Kikuchi & Gompper, EPL 78, 10005 (2007)),
 * cell by cell (peloid/cell_collide.h: blocks, fixed-order sums,
 * the same bits for any thread count). */
#include <math.h>

#include "peloid/cell_angular.h"
#include "peloid/cell_collide.h"
#include "peloid/mpc_at.h"
#include "peloid/mpc_at_a.h"

static inline double at_a_cell(pl_fluid_t *f, const pl_grid_t *g, const pl_collide_params_t *p, size_t c, size_t s,
                               size_t e)
{
    pl_cell_angular_t a;
    pl_cell_angular_before(f, g, s, e, &a);
    pl_mpc_at_cell(f->v[0], f->v[1], f->v[2], s, e, sqrt(p->kT_target), p->seed, p->step, c);
    pl_cell_angular_restore(f, g, s, e, &a);
    return pl_cell_relative_sum2(f, s, e);
}

void pl_mpc_at_a_collide(pl_fluid_t *f, const pl_grid_t *g, const uint32_t *cell_start,
                         const pl_collide_params_t *p, double *block_sum, int nthreads)
{
    pl_cell_collide_blocks(f, g, cell_start, p, block_sum, nthreads, at_a_cell);
}
