/* Collision-cell grid: box size, the random shift of the current step, walls.
 *
 * Periodic axes: cell index floor(x - s) mod L.  With walls in z the grid has
 * Lz + 2 layers, index floor(z - s_z) + 1, so that cells cut by a wall exist
 * and can be filled with virtual wall particles (Lamura et al., EPL 56, 319). */
#ifndef PELOID_GRID_H
#define PELOID_GRID_H

#include <stddef.h>
#include <stdint.h>

typedef struct pl_grid {
    int L[3];        /* box edge in cells (a0 = 1): positions in [0, L) */
    int n[3];        /* cells per axis of the collision grid */
    size_t ncells;   /* n[0] * n[1] * n[2] */
    int walls_z;     /* PL_WALLS_* */
    double shift[3]; /* grid shift of the current step, in [-1/2, 1/2) */
} pl_grid_t;

void pl_grid_init(pl_grid_t *grid, const int L[3], int walls_z);

/* Draws the grid shift of collision step `step` (zero when disabled). */
void pl_grid_draw_shift(pl_grid_t *grid, uint64_t seed, uint64_t step, int enabled);

#endif
