/* Counting sort: particles grouped by cell, stable, cell_start correct, and
 * the result identical for 1, 2 and 3 threads (DESIGN.md "Data"). */
#include <criterion/criterion.h>
#include <math.h>
#include <omp.h>
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

/* The narrow histogram rows (pl_fluid_bands_t, issue 38): a thermal fluid
 * streamed and sorted for 40 steps with 1 thread and with 4 and 7 (each
 * thread counting only its band of z planes, periodic z where the bands
 * wrap, and z walls) is bitwise the same, cell_start included; the bands
 * are in use every step after the first and count whole rows again almost
 * never (here: never); a particle thrown across the box between two steps
 * (outside its thread's band) makes that step's sort count whole rows, and
 * the result is still the same. */
static void bands_run(int nthreads, int walls, pl_fluid_t *f, uint32_t *start, pl_grid_t *g, int throw_at)
{
    pl_err_t err;
    const int L[3] = {9, 8, 23};
    pl_grid_init(g, L, (const int[3]){PL_WALLS_NONE, PL_WALLS_NONE, walls ? PL_WALLS_NOSLIP : PL_WALLS_NONE});
    const size_t n = 10 * 9 * 8 * 23;
    cr_assert_eq(pl_fluid_create(n, 0, nthreads, f, &err), 0);
    for (size_t i = 0; i < n; ++i) {
        pl_rand4_t r = pl_rng_uniform4(11, 2, 0, i, 0), s = pl_rng_uniform4(11, 3, 0, i, 0);
        for (int d = 0; d < 3; ++d) { /* unit variance: kT = m = 1 */
            f->r[d][i] = (pl_real)(r.u[d] * L[d]);
            f->v[d][i] = (pl_real)((s.u[d] - 0.5) * 2.0 * sqrt(3.0));
        }
    }
    uint32_t *hist = pl_alloc((size_t)nthreads * g->ncells * sizeof(uint32_t), nthreads);
    pl_stream_params_t p;
    memset(&p, 0, sizeof p);
    p.dt = 0.1;
    for (int step = 0; step < 40; ++step) {
        if (step == throw_at) f->r[2][n / 2] = (pl_real)(fmod(f->r[2][n / 2] + 0.5 * L[2], L[2]));
        pl_grid_draw_shift(g, 5, (uint64_t)step, 1);
        pl_srd_stream_bin(f, g, &p, hist, nthreads);
        pl_srd_sort(f, hist, start, g->ncells, nthreads);
        pl_fluid_swap(f);
    }
    pl_free(hist);
}

Test(sort, narrow_bands_bitwise_and_recount)
{
    for (int walls = 0; walls <= 1; ++walls) {
        pl_fluid_t ref, f;
        pl_grid_t g;
        uint32_t *ref_start = pl_alloc((9 * 8 * 25 + 1) * sizeof(uint32_t), 1);
        uint32_t *start = pl_alloc((9 * 8 * 25 + 1) * sizeof(uint32_t), 1);
        bands_run(1, walls, &ref, ref_start, &g, -1);
        const size_t n = ref.n, nc = g.ncells;
        for (int t = 4; t <= 7; t += 3)
            for (int thrown = 0; thrown <= 1; ++thrown) {
                bands_run(t, walls, &f, start, &g, thrown ? 25 : -1);
                cr_assert_eq(f.bands.threads, t);
                cr_expect_eq(f.bands.sorts, 39, "walls %d, %d threads: bands in %llu sorts", walls, t,
                             (unsigned long long)f.bands.sorts);
                cr_expect_eq(f.bands.recounts, (uint64_t)thrown, "walls %d, %d threads, thrown %d: %llu recounts",
                             walls, t, thrown, (unsigned long long)f.bands.recounts);
                int narrow = 0;
                for (int u = 0; u < t; ++u) narrow += f.bands.len[u] < nc;
                cr_expect_eq(narrow, t, "walls %d, %d threads: %d narrow bands", walls, t, narrow);
                if (!thrown) {
                    cr_assert_eq(memcmp(start, ref_start, (nc + 1) * sizeof *start), 0, "cell_start, %d threads", t);
                    for (int d = 0; d < 3; ++d) {
                        cr_assert_eq(memcmp(f.r[d], ref.r[d], n * sizeof(pl_real)), 0, "r, walls %d, %d threads", walls, t);
                        cr_assert_eq(memcmp(f.v[d], ref.v[d], n * sizeof(pl_real)), 0, "v, walls %d, %d threads", walls, t);
                    }
                }
                pl_fluid_free(&f);
            }
        /* the thrown run against its own 1-thread reference */
        pl_fluid_free(&ref);
        bands_run(1, walls, &ref, ref_start, &g, 25);
        bands_run(7, walls, &f, start, &g, 25);
        cr_assert_eq(memcmp(start, ref_start, (nc + 1) * sizeof *start), 0, "cell_start, thrown");
        for (int d = 0; d < 3; ++d) {
            cr_assert_eq(memcmp(f.r[d], ref.r[d], n * sizeof(pl_real)), 0, "r, thrown, walls %d", walls);
            cr_assert_eq(memcmp(f.v[d], ref.v[d], n * sizeof(pl_real)), 0, "v, thrown, walls %d", walls);
        }
        pl_fluid_free(&f);
        pl_fluid_free(&ref);
        pl_free(start);
        pl_free(ref_start);
    }
}

/* A team smaller than the thread count the arrays were sized for
 * (OMP_DYNAMIC, OMP_THREAD_LIMIT or a nested region give one): the stream,
 * the banded sort and a recount after a thrown particle, 7 parts run by a
 * team of one (the kernels called from one thread of an active outer
 * region of two, nesting off), are bitwise the 1-thread result.  Each part is a chunk of
 * particles and a histogram row; a kernel that took its team for its parts
 * would leave 6 of 7 chunks unsorted (or overflow a row). */
Test(sort, team_of_one_takes_every_part)
{
    omp_set_max_active_levels(1);
    for (int walls = 0; walls <= 1; ++walls)
        for (int thrown = 0; thrown <= 1; ++thrown) {
            pl_fluid_t ref, f;
            pl_grid_t g;
            uint32_t *ref_start = pl_alloc((9 * 8 * 25 + 1) * sizeof(uint32_t), 1);
            uint32_t *start = pl_alloc((9 * 8 * 25 + 1) * sizeof(uint32_t), 1);
            bands_run(1, walls, &ref, ref_start, &g, thrown ? 25 : -1);
            int team = 0;
#pragma omp parallel num_threads(2)
#pragma omp single
            {
                bands_run(7, walls, &f, start, &g, thrown ? 25 : -1);
#pragma omp parallel num_threads(7)
#pragma omp single
                team = omp_get_num_threads();
            }
            cr_assert_eq(team, 1, "the kernels' team inside the outer region: %d", team);
            cr_expect_eq(f.bands.recounts, (uint64_t)thrown, "walls %d thrown %d: %llu recounts", walls, thrown,
                         (unsigned long long)f.bands.recounts);
            cr_assert_eq(memcmp(start, ref_start, (g.ncells + 1) * sizeof *start), 0, "cell_start, walls %d", walls);
            for (int d = 0; d < 3; ++d) {
                cr_assert_eq(memcmp(f.r[d], ref.r[d], ref.n * sizeof(pl_real)), 0, "r, walls %d thrown %d", walls, thrown);
                cr_assert_eq(memcmp(f.v[d], ref.v[d], ref.n * sizeof(pl_real)), 0, "v, walls %d thrown %d", walls, thrown);
            }
            pl_fluid_free(&f);
            pl_fluid_free(&ref);
            pl_free(start);
            pl_free(ref_start);
        }
}

/* The index sort (srd.sort_interval) is the same stable sort as the full
 * one: cell_start equal, and slot j's particle order[j] is the particle the
 * full sort put at slot j, for 1..3 threads, after one full sort (bands in
 * use) and from the random first order.  Fails if the index were built
 * from another count or not stably. */
Test(sort, index_sort_is_the_full_sort_permutation)
{
    const size_t n = 20000;
    for (int presorted = 0; presorted <= 1; ++presorted)
        for (int t = 1; t <= 3; ++t) {
            pl_fluid_t f;
            pl_grid_t g;
            uint32_t *start;
            fill(&f, &g, n, 7);
            f.order = pl_alloc(n * sizeof(uint32_t), t);
            if (presorted) { /* a full sort, then the particles move a little under a new shift */
                sort_with(t, &f, &g, &start);
                pl_free(start);
                for (size_t i = 0; i < n; ++i) /* up to 0.3 cells along x, wrapped */
                    f.r[0][i] = (pl_real)fmod(f.r[0][i] + 0.3 * sin((double)i) + g.L[0], g.L[0]);
                pl_grid_draw_shift(&g, 1, 1, 1);
            }
            uint32_t *hist = pl_alloc((size_t)t * g.ncells * sizeof(uint32_t), t);
            uint32_t *istart = pl_alloc((g.ncells + 1) * sizeof(uint32_t), t);
            start = pl_alloc((g.ncells + 1) * sizeof(uint32_t), t);
            pl_srd_bin(&f, &g, hist, t);
            pl_srd_sort_index(&f, hist, istart, g.ncells, t);
            uint32_t *id_before = pl_alloc(n * sizeof(uint32_t), 1);
            memcpy(id_before, f.id, n * sizeof(uint32_t));
            pl_srd_bin(&f, &g, hist, t);
            pl_srd_sort(&f, hist, start, g.ncells, t);
            pl_fluid_swap(&f);
            cr_assert_eq(memcmp(start, istart, (g.ncells + 1) * sizeof *start), 0, "cell_start, %d threads", t);
            for (size_t j = 0; j < n; ++j)
                cr_assert_eq(id_before[f.order[j]], f.id[j], "slot %zu: index %u, full sort id %u (%d threads)", j,
                             id_before[f.order[j]], f.id[j], t);
            pl_free(id_before);
            pl_free(hist);
            pl_free(istart);
            pl_free(start);
            pl_fluid_free(&f);
        }
}
