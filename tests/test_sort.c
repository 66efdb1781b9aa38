/* Counting sort: particles grouped by cell, stable, cell_start correct, and
 * the result identical for 1, 2 and 3 threads (DESIGN.md "Data"). */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "peloid/rng.h"
#include "peloid/scene.h"
#include "peloid/srd_kernels.h"

static void fill(pl_fluid_t *f, pl_grid_t *g, size_t n, int L)
{
    pl_err_t err;
    int Ls[3] = {L, L + 1, L + 2};
    pl_grid_init(g, Ls, (const int[3]){PL_WALLS_NONE, PL_WALLS_NONE, PL_WALLS_NONE});
    cr_assert_eq(pl_fluid_create(n, 1, 1, f, &err), 0);
    for (size_t i = 0; i < n; ++i) {
        pl_rand4_t r = pl_rng_uniform4(7, 1, 0, i, 0);
        for (int d = 0; d < 3; ++d) {
            f->r[d][i] = (pl_real)(r.u[d] * Ls[d]);
            f->v[d][i] = (pl_real)i; /* original index, to check stability */
        }
        f->id[i] = (uint32_t)i;
    }
    pl_grid_draw_shift(g, 1, 0, 1);
}

static void sort_with(int nthreads, pl_fluid_t *f, pl_grid_t *g, uint32_t **start)
{
    uint32_t *hist = pl_alloc((size_t)nthreads * g->ncells * sizeof(uint32_t), nthreads);
    *start = pl_alloc((g->ncells + 1) * sizeof(uint32_t), nthreads);
    pl_srd_bin(f, g, hist, nthreads);
    pl_srd_sort(f, hist, *start, g->ncells, nthreads);
    pl_fluid_swap(f);
    pl_free(hist);
}

Test(sort, grouped_stable_and_thread_independent)
{
    const size_t n = 20000;
    pl_fluid_t ref;
    pl_grid_t g;
    uint32_t *ref_start;
    fill(&ref, &g, n, 7);
    sort_with(1, &ref, &g, &ref_start);
    cr_assert_eq(ref_start[g.ncells], n);
    /* every particle lies in its cell, and within a cell ids increase */
    uint32_t *hist = pl_alloc(g.ncells * sizeof(uint32_t), 1);
    pl_srd_bin(&ref, &g, hist, 1); /* recompute cells of the sorted order */
    for (size_t c = 0; c < g.ncells; ++c)
        for (size_t i = ref_start[c]; i < ref_start[c + 1]; ++i) {
            cr_assert_eq(ref.cell[i], c, "particle %zu in cell %u, listed in %zu", i, ref.cell[i], c);
            if (i > ref_start[c]) cr_assert_lt(ref.id[i - 1], ref.id[i], "not stable in cell %zu", c);
            cr_assert_eq(ref.v[0][i], (double)ref.id[i], "velocity did not travel with the particle");
        }
    pl_free(hist);
    for (int t = 2; t <= 3; ++t) {
        pl_fluid_t f;
        uint32_t *start;
        fill(&f, &g, n, 7);
        sort_with(t, &f, &g, &start);
        cr_assert_eq(memcmp(start, ref_start, (g.ncells + 1) * sizeof *start), 0, "cell_start, %d threads", t);
        for (int d = 0; d < 3; ++d) {
            cr_assert_eq(memcmp(f.r[d], ref.r[d], n * sizeof(pl_real)), 0, "positions, %d threads", t);
            cr_assert_eq(memcmp(f.v[d], ref.v[d], n * sizeof(pl_real)), 0, "velocities, %d threads", t);
        }
        cr_assert_eq(memcmp(f.id, ref.id, n * sizeof(uint32_t)), 0, "ids, %d threads", t);
        pl_fluid_free(&f);
        pl_free(start);
    }
    pl_fluid_free(&ref);
    pl_free(ref_start);
}

/* The streaming of an untracked periodic fluid without body force stores a
 * velocity only where the kick v + 0 changes its bits (kernels/srd_stream.c):
 * the state is bitwise the one the general per-particle path (a tracked
 * fluid) leaves, -0.0 velocities (which become +0.0) included; the kick
 * -0.0 too.  Fails if the velocities are simply not written back. */
Test(stream, kick_free_store_is_bitwise_the_kick)
{
    const size_t n = 3000;
    for (int neg = 0; neg < 2; ++neg) {
        pl_fluid_t a, b;
        pl_grid_t g;
        fill(&a, &g, n, 5);
        fill(&b, &g, n, 5);
        a.tracked = 0; /* the block path; b keeps the per-particle one */
        for (size_t i = 0; i < n; ++i)
            for (int d = 0; d < 3; ++d) {
                pl_rand4_t r = pl_rng_uniform4(9, 2, 0, i, 0);
                const double v = i % 7 == 0 ? -0.0 : i % 11 == 0 ? 0.0 : 2.0 * r.u[d] - 1.0;
                a.v[d][i] = b.v[d][i] = (pl_real)v;
            }
        pl_stream_params_t p;
        memset(&p, 0, sizeof p);
        p.dt = 0.1;
        for (int d = 0; d < 3; ++d) p.accel[d] = neg ? -0.0 : 0.0;
        uint32_t *ha = pl_alloc(2 * g.ncells * sizeof(uint32_t), 2), *hb = pl_alloc(2 * g.ncells * sizeof(uint32_t), 2);
        pl_srd_stream_bin(&a, &g, &p, ha, 2);
        pl_srd_stream_bin(&b, &g, &p, hb, 2);
        for (int d = 0; d < 3; ++d) {
            cr_assert_eq(memcmp(a.r[d], b.r[d], n * sizeof(pl_real)), 0, "positions, accel %s0", neg ? "-" : "+");
            cr_assert_eq(memcmp(a.v[d], b.v[d], n * sizeof(pl_real)), 0, "velocities, accel %s0", neg ? "-" : "+");
        }
        cr_assert_eq(memcmp(a.cell, b.cell, n * sizeof(uint32_t)), 0);
        cr_assert_eq(memcmp(ha, hb, 2 * g.ncells * sizeof(uint32_t)), 0);
        cr_assert(!neg || signbit(a.v[0][0]), "-0.0 + -0.0 stays -0.0");
        cr_assert(neg || !signbit(a.v[0][0]), "-0.0 + 0.0 is +0.0");
        a.tracked = 1;
        pl_fluid_free(&a);
        pl_fluid_free(&b);
        pl_free(ha);
        pl_free(hb);
    }
}
