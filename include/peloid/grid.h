/* Collision-cell grid: box size, the random shift of the current step, walls.
 *
 * Periodic axes: cell index floor(x - s) mod L.  An axis closed by walls
 * (z = 0, Lz with walls_z; x = 0, Lx and y = 0, Ly with walls_xy) has L + 2
 * cells, index floor(x - s) + 1, so that cells cut by a wall exist and can be
 * filled with virtual wall particles (Lamura et al., EPL 56, 319). */
#ifndef PELOID_GRID_H
#define PELOID_GRID_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "peloid/kernel_enums.h" /* PL_WALLS_* */

typedef struct pl_grid {
    int L[3];        /* box edge in cells (a0 = 1): positions in [0, L) */
    int n[3];        /* cells per axis of the collision grid */
    size_t ncells;   /* n[0] * n[1] * n[2] */
    int walls[3];    /* PL_WALLS_* of each axis (PL_WALLS_NONE: periodic) */
    int any_walls;   /* some axis is closed */
    double shift[3]; /* grid shift of the current step, in [-1/2, 1/2) */
} pl_grid_t;

void pl_grid_init(pl_grid_t *grid, const int L[3], const int walls[3]);

/* The one cell-of-position rule (streaming, sort and couplings must agree
 * bitwise).  Periodic axis of n cells under shift s, x in [0, L):
 * floor(x - s) mod n. */
static inline int pl_grid_cell_periodic(double x, double s, int n)
{
    int i = (int)floor(x - s);
    if (i < 0) i += n;
    else if (i >= n) i -= n;
    return i;
}

/* Closed axis (cells 0 .. L+1, the outer ones cut by the walls):
 * floor(x - s) + 1. */
static inline int pl_grid_cell_closed(double x, double s) { return (int)floor(x - s) + 1; }

/* Draws the grid shift of collision step `step` (zero when disabled). */
void pl_grid_draw_shift(pl_grid_t *grid, uint64_t seed, uint64_t step, int enabled);

#endif
