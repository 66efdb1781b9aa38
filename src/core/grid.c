/* Collision-cell grid geometry and its random shift (Hecht Sec. III). */
#include "peloid/grid.h"

#include "peloid/rng.h"
#include "peloid/scene.h"

void pl_grid_init(pl_grid_t *grid, const int L[3], const int walls[3])
{
    grid->any_walls = 0;
    for (int d = 0; d < 3; ++d) {
        grid->L[d] = L[d];
        grid->walls[d] = walls[d];
        grid->n[d] = walls[d] != PL_WALLS_NONE ? L[d] + 2 : L[d];
        grid->shift[d] = 0.0;
        grid->any_walls |= walls[d] != PL_WALLS_NONE;
    }
    grid->ncells = (size_t)grid->n[0] * (size_t)grid->n[1] * (size_t)grid->n[2];
}

void pl_grid_draw_shift(pl_grid_t *grid, uint64_t seed, uint64_t step, int enabled)
{
    /* Hecht Sec. III: all particles shifted by the same random vector with
     * components in [-a/2, a/2]; consecutive shifts uncorrelated. */
    pl_rand4_t r = pl_rng_uniform4(seed, PL_RNG_GRID_SHIFT, step, 0, 0);
    for (int d = 0; d < 3; ++d) grid->shift[d] = enabled ? r.u[d] - 0.5 : 0.0;
}
