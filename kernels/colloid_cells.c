/* Linked cells for the colloids (DESIGN.md "Colloid neighbours use linked cells
 * sized by the interaction cut-off").
 *
 * The cell edge is >= the largest pair cut-off, so every partner of a particle
 * lies in its own or one of the 26 adjacent cells.  A periodic axis with fewer
 * than 3 such cells is given a single cell (the neighbour offsets -1, 0, +1
 * would otherwise name the same cell twice); the pair loop then relies on the
 * minimum image, which the set-up guarantees by refusing rc > L/2.
 *
 * The build is a serial counting sort: colloid numbers are small (10^2-10^5)
 * and a serial, stable sort makes every cell list its particles in index
 * order, which is what makes the force sums bitwise reproducible. */
#include <math.h>

#include "peloid/colloid_kernels.h"

void pl_colloid_cells_dims(const double box[3], const int periodic[3], double rc, int nc[3])
{
    for (int d = 0; d < 3; ++d) {
        double m = floor(box[d] / rc);
        if (m > 64.0) m = 64.0; /* cap: cells of tiny colloids in a huge box */
        int c = m < 1.0 ? 1 : (int)m;
        if (periodic[d] && c < 3) c = 1;
        nc[d] = c;
    }
}

static int32_t axis_cell(double x, double inv, int nc)
{
    int c = (int)floor(x * inv);
    if (c < 0) c = 0; /* walls: a particle pushed just outside [0, L] */
    if (c >= nc) c = nc - 1;
    return c;
}

void pl_colloid_cells_build(pl_colloid_cells_t *cells, size_t n, const double *x, const double *y,
                            const double *z)
{
    int32_t *start = cells->start;
    for (size_t c = 0; c <= cells->ncells; ++c) start[c] = 0;
    for (size_t i = 0; i < n; ++i) {
        int32_t cx = axis_cell(x[i], cells->inv_cl[0], cells->nc[0]);
        int32_t cy = axis_cell(y[i], cells->inv_cl[1], cells->nc[1]);
        int32_t cz = axis_cell(z[i], cells->inv_cl[2], cells->nc[2]);
        int32_t c = (cz * cells->nc[1] + cy) * cells->nc[0] + cx;
        cells->cell[i] = c;
        start[c + 1]++;
    }
    for (size_t c = 0; c < cells->ncells; ++c) start[c + 1] += start[c];
    /* scatter: start[c] is used as the fill pointer, then restored */
    for (size_t i = 0; i < n; ++i) cells->list[start[cells->cell[i]]++] = (int32_t)i;
    for (size_t c = cells->ncells; c > 0; --c) start[c] = start[c - 1];
    start[0] = 0;
}
