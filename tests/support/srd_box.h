/* A periodic cube of SRD fluid for the collision tests (test_collide,
 * test_collision_rules): L^3 cells of gamma particles at deterministic
 * uniform positions with velocities uniform in [-1, 1) plus a mean flow
 * (0, 0.3, 0.6), binned and sorted on a shifted grid (cells straddle the
 * periodic boundary), with the collision kernels' scratch arrays. */
#ifndef PELOID_TEST_SRD_BOX_H
#define PELOID_TEST_SRD_BOX_H

#include <criterion/criterion.h>

#include "peloid/rng.h"
#include "peloid/srd_kernels.h"

typedef struct {
    pl_fluid_t f;
    pl_grid_t g;
    uint32_t *hist, *start;
    double *block;
    int nthreads;
} pl_test_box_t;

static inline void pl_test_box_make(pl_test_box_t *b, int L, double gamma, int nthreads)
{
    pl_err_t err;
    int Ls[3] = {L, L, L};
    pl_grid_init(&b->g, Ls, (const int[3]){PL_WALLS_NONE, PL_WALLS_NONE, PL_WALLS_NONE});
    size_t n = (size_t)(gamma * L * L * L);
    b->nthreads = nthreads;
    cr_assert_eq(pl_fluid_create(n, 0, nthreads, &b->f, &err), 0);
    for (size_t i = 0; i < n; ++i) {
        pl_rand4_t r = pl_rng_uniform4(99, 1, 0, i, 0), q = pl_rng_uniform4(99, 2, 0, i, 0);
        for (int d = 0; d < 3; ++d) {
            b->f.r[d][i] = (pl_real)(r.u[d] * L);
            b->f.v[d][i] = (pl_real)(2.0 * q.u[d] - 1.0 + 0.3 * d); /* a mean flow too */
        }
    }
    b->hist = pl_alloc((size_t)nthreads * b->g.ncells * sizeof(uint32_t), nthreads);
    b->start = pl_alloc((b->g.ncells + 1) * sizeof(uint32_t), nthreads);
    b->block = pl_alloc(2 * (b->g.ncells / PL_CELL_BLOCK + 1) * sizeof(double), nthreads);
    pl_grid_draw_shift(&b->g, 5, 0, 1); /* cells straddle the periodic boundary */
    pl_srd_bin(&b->f, &b->g, b->hist, nthreads);
    pl_srd_sort(&b->f, b->hist, b->start, b->g.ncells, nthreads);
    pl_fluid_swap(&b->f);
}

static inline void pl_test_box_free(pl_test_box_t *b)
{
    pl_fluid_free(&b->f);
    pl_free(b->hist);
    pl_free(b->start);
    pl_free(b->block);
}

#endif
