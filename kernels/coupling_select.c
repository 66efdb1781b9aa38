/* Selection of the fluid particles near colloids (PL Sec. III.A: only these
 * are integrated at the potential coupling's MD step, whose order is
 * src/coupling/coupling_potential.c), shared with coupling I's detection of
 * the particles inside a colloid (pl_coupling_find_binned,
 * pl_coupling_find_block).  Parallel over the streaming's static chunks:
 * from the lookup cells (pl_coupling_find); from the colloids near each
 * collision cell while the fluid is sorted (pl_coupling_cell_candidates,
 * pl_coupling_find_sorted), then inside the streaming, on each block it has
 * read and not yet stored (pl_coupling_select_block); from the cells the
 * binning left (coupling I).  Each thread appends its chunk's particles in
 * particle order to its own part of the list: no atomics, and the lists are
 * the same for any thread count. */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "coupling_geometry.h"
#include "omp_parts.h"
#include "peloid/coupling_kernels.h"
#include "peloid/srd_kernels.h"

/* The unit cell of a position (the lookup's). */
static inline size_t unit_cell(const pl_coupling_box_t *q, double x, double y, double z)
{
    int ix = (int)x, iy = (int)y, iz = (int)z;
    ix = ix < 0 ? 0 : ix < q->L[0] ? ix : q->L[0] - 1;
    iy = iy < 0 ? 0 : iy < q->L[1] ? iy : q->L[1] - 1;
    iz = iz < 0 ? 0 : iz < q->L[2] ? iz : q->L[2] - 1;
    return ((size_t)iz * (size_t)q->L[1] + (size_t)iy) * (size_t)q->L[0] + (size_t)ix;
}

/* The number of colloids of the list [b, e) of lk_list whose sphere holds
 * the point. */
static inline int near_count(const pl_coupling_box_t *q, const pl_coupling_colloids_t *c, const int32_t *lk_list,
                             int32_t b, int32_t e, double x, double y, double z)
{
    int in = 0;
    for (int32_t p = b; p < e; ++p) in += pl_coupling_hit(q, c, lk_list[p], x, y, z);
    return in;
}

/* The squared reach of a particle of velocity (vx, vy, vz) (INFINITY
 * without a reach: the radii alone decide).  The same expression in the
 * scalar and the vectorised selection: the same bits. */
static inline double reach2(const pl_coupling_reach_t *r, double vx, double vy, double vz)
{
    const double R = r->rc + r->budget + r->tail + r->T * sqrt(vx * vx + vy * vy + vz * vz);
    return R * R;
}

void pl_coupling_find(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling_colloids_t *c,
                      const pl_coupling_reach_t *reach, const int32_t *lk_start, const int32_t *lk_list,
                      int nthreads, uint32_t *found, uint32_t *found_cell, uint64_t *counts)
{
    const pl_coupling_box_t q = pl_coupling_box(g->L, g->walls);
#pragma omp parallel num_threads(nthreads)
    PL_FOR_PART(t, nthreads) {
        size_t lo, hi, m = 0, np = 0;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        for (size_t i = lo; i < hi; ++i) {
            const double x = f->r[0][i], y = f->r[1][i], z = f->r[2][i];
            const size_t cell = unit_cell(&q, x, y, z);
            const double R2 = reach ? reach2(reach, f->v[0][i], f->v[1][i], f->v[2][i]) : INFINITY;
            int in = 0, sel = 0;
            for (int32_t p = lk_start[cell]; p < lk_start[cell + 1]; ++p) {
                const int32_t k = lk_list[p];
                const double d2 = pl_coupling_dist2(&q, c, k, x, y, z);
                const int h = d2 < c->rad[k] * c->rad[k];
                in += h;
                sel |= h & (d2 < R2);
            }
            found[lo + m] = (uint32_t)i;
            if (found_cell) found_cell[lo + m] = (uint32_t)cell;
            m += (size_t)sel;
            np += sel ? (size_t)in : 0;
        }
        counts[(size_t)t * 8 + 2] = m;
        counts[(size_t)t * 8 + 3] = np;
    }
}

/* Collision cells along one axis, under shift s, that can hold a point
 * within R of x: those of [x - R, x + R] widened by 1e-6 a0 against
 * rounding (the cells are floor(x - s) of the stored positions, the test
 * near_any's, both in double: errors ~1e-12 a0); periodic axes wrap (every
 * cell once the span covers the axis), closed axes (cells 0 .. L + 1,
 * kernels/coupling_lookup.c) are clipped.  gap2: the squared distance from
 * x to each cell along the axis (0 for the cells that hold x, for the
 * outer cells of a closed axis, which hold what lies beyond them, and for
 * every cell once the span covers a periodic axis). */
static inline int axis_cells(double x, double R, double s, int n, int periodic, int *idx, double *gap2)
{
    const double eps = 1e-6;
    int lo = (int)floor(x - R - eps - s), hi = (int)floor(x + R + eps - s);
    int all = 0, off = 0; /* off: a closed axis's cell i spans [i - 1 + s, i + s) */
    if (!periodic) {
        lo = lo + 1 < 0 ? 0 : lo + 1;
        hi = hi + 1 > n - 1 ? n - 1 : hi + 1;
        off = -1;
    } else if (hi - lo + 1 >= n) {
        lo = 0;
        hi = n - 1;
        all = 1;
    }
    int m = 0;
    for (int i = lo; i <= hi; ++i) {
        const double a = (double)(i + off) + s, b = a + 1.0;
        double gap = x < a ? a - x : (x > b ? x - b : 0.0);
        if (all || (!periodic && (i == 0 || i == n - 1))) gap = 0.0;
        gap2[m] = gap * gap;
        idx[m++] = periodic ? ((i % n) + n) % n : i;
    }
    return m;
}

/* The candidate cells of colloid k in the z planes [zlo, zhi): pass 0
 * counts them (cstart[cl + 2]), pass 1 appends k (cstart[cl + 1] the fill
 * position). */
static inline void candidate_cells(const pl_grid_t *g, const pl_coupling_colloids_t *c, size_t k, int pass,
                                   size_t zlo, size_t zhi, int *const ax[3], double *const gp[3],
                                   uint32_t *cstart, int32_t *clist)
{
    const double r[3] = {c->x[k], c->y[k], c->z[k]}, R = c->rad[k] + 1e-6;
    int m[3];
    m[2] = axis_cells(r[2], c->rad[k], g->shift[2], g->n[2], g->walls[2] == PL_WALLS_NONE, ax[2], gp[2]);
    int any = 0;
    for (int a = 0; a < m[2]; ++a) any |= (size_t)ax[2][a] >= zlo && (size_t)ax[2][a] < zhi;
    if (!any) return;
    for (int d = 0; d < 2; ++d)
        m[d] = axis_cells(r[d], c->rad[k], g->shift[d], g->n[d], g->walls[d] == PL_WALLS_NONE, ax[d], gp[d]);
    for (int a = 0; a < m[2]; ++a) {
        if ((size_t)ax[2][a] < zlo || (size_t)ax[2][a] >= zhi) continue;
        for (int b = 0; b < m[1]; ++b) {
            const double g2 = gp[2][a] + gp[1][b];
            if (!(g2 < R * R)) continue;
            const size_t row = ((size_t)ax[2][a] * (size_t)g->n[1] + (size_t)ax[1][b]) * (size_t)g->n[0];
            for (int e = 0; e < m[0]; ++e) {
                if (!(g2 + gp[0][e] < R * R)) continue;
                if (pass == 0) cstart[row + (size_t)ax[0][e] + 2]++;
                else clist[cstart[row + (size_t)ax[0][e] + 1]++] = (int32_t)k;
            }
        }
    }
}

enum { CAND_MAX_THREADS = 256 };

size_t pl_coupling_cell_candidates(const pl_grid_t *g, const pl_coupling_colloids_t *c, int *axis_buf,
                                   double *gap_buf, uint32_t *cstart, int32_t *clist, size_t cap, int nthreads)
{
    const size_t plane = (size_t)g->n[0] * (size_t)g->n[1];
    const size_t nbuf = (size_t)g->n[0] + (size_t)g->n[1] + (size_t)g->n[2];
    if (nthreads > CAND_MAX_THREADS) nthreads = CAND_MAX_THREADS;
    if (nthreads > g->n[2]) nthreads = g->n[2];
    if (nthreads < 1) nthreads = 1;
    uint32_t part[CAND_MAX_THREADS + 1];
    size_t need = 0;
    /* counts of cell cl in cstart[cl + 2]; their running sum then leaves
     * the start of cl in cstart[cl + 1], which the filling advances to its
     * end = the start of cl + 1.  A cell is a candidate's if the sphere
     * (radius + 1e-6) reaches it: about half the cells of the sphere's
     * bounding box.  In parallel over slabs of z planes (the arrays are
     * cold here, the streaming passed megabytes since): thread t counts,
     * sums and fills the cells of its planes, every colloid in index order,
     * so each cell's list is the serial loop's; its running sum is offset
     * by the slabs before (integers: the same for any thread count). */
#pragma omp parallel num_threads(nthreads)
    {
        const int t = omp_get_thread_num(), T = omp_get_num_threads();
        size_t zlo, zhi;
        pl_chunk((size_t)g->n[2], t, T, &zlo, &zhi);
        const size_t clo = zlo * plane, chi = zhi * plane;
        int *const ax[3] = {axis_buf + (size_t)t * nbuf, axis_buf + (size_t)t * nbuf + g->n[0],
                            axis_buf + (size_t)t * nbuf + g->n[0] + g->n[1]};
        double *const gp[3] = {gap_buf + (size_t)t * nbuf, gap_buf + (size_t)t * nbuf + g->n[0],
                               gap_buf + (size_t)t * nbuf + g->n[0] + g->n[1]};
        if (t == 0) cstart[0] = cstart[1] = 0;
        memset(cstart + clo + 2, 0, (chi - clo) * sizeof *cstart);
        for (size_t k = 0; k < c->n; ++k) candidate_cells(g, c, k, 0, zlo, zhi, ax, gp, cstart, clist);
        uint32_t run = 0;
        for (size_t i = clo + 2; i < chi + 2; ++i) {
            run += cstart[i];
            cstart[i] = run;
        }
        part[t + 1] = run;
#pragma omp barrier
#pragma omp single
        {
            part[0] = 0;
            for (int u = 0; u < T; ++u) part[u + 1] += part[u];
            need = part[T];
        } /* (implied barrier) */
        if (part[t])
            for (size_t i = clo + 2; i < chi + 2; ++i) cstart[i] += part[t];
#pragma omp barrier
        if (need <= cap)
            for (size_t k = 0; k < c->n; ++k) candidate_cells(g, c, k, 1, zlo, zhi, ax, gp, cstart, clist);
    }
    return need;
}

/* Whether collision cells a and b have the same candidate list. */
static inline int same_candidates(const uint32_t *cstart, const int32_t *clist, size_t a, size_t b)
{
    const uint32_t na = cstart[a + 1] - cstart[a];
    if (cstart[b + 1] - cstart[b] != na) return 0;
    for (uint32_t e = 0; e < na; ++e)
        if (clist[cstart[a] + e] != clist[cstart[b] + e]) return 0;
    return 1;
}

/* The first collision cell that ends after particle lo (cell c holds
 * [cell_start[c], cell_start[c + 1])). */
static size_t first_cell_after(const uint32_t *cell_start, size_t ncells, size_t lo)
{
    size_t a = 0, b = ncells;
    while (a < b) {
        const size_t mid = a + (b - a) / 2;
        if (cell_start[mid + 1] <= lo) a = mid + 1;
        else b = mid;
    }
    return a;
}

/* What the sorted selection reads and writes, for one thread's chunk
 * [clo, chi) of the streaming's static partition. */
typedef struct {
    pl_coupling_box_t q;
    const pl_coupling_colloids_t *c;
    const pl_coupling_reach_t *reach;
    const pl_fluid_t *f;
    const uint32_t *cstart, *cell_start;
    const int32_t *clist;
    size_t ncells, clo, readable; /* vector loops may read particles below `readable` */
    uint32_t *found, *found_cell;
    pl_coupling_stage_t *stage; /* NULL, or where the state of each listed particle goes */
    size_t m, np, overflow;
} select_run_t;

/* sel[u] for particles b + u, u < lenv, against the one candidate k:
 * pl_coupling_hit() and, with_reach, within the particle's reach (the expressions of the
 * general case below, the same bits). */
static inline __attribute__((always_inline)) void test_one(const select_run_t *s, int32_t k, size_t b, size_t lenv,
                                                           int with_reach, int *restrict sel)
{
    const pl_real *restrict x = s->f->r[0], *restrict y = s->f->r[1], *restrict z = s->f->r[2];
    const pl_real *restrict vx = s->f->v[0], *restrict vy = s->f->v[1], *restrict vz = s->f->v[2];
    const pl_coupling_colloids_t *c = s->c;
    const double cx = c->x[k], cy = c->y[k], cz = c->z[k], r2 = c->rad[k] * c->rad[k];
    const pl_coupling_box_t q = s->q;
#pragma omp simd
    for (size_t u = 0; u < lenv; ++u) {
        const double R2 = with_reach ? reach2(s->reach, vx[b + u], vy[b + u], vz[b + u]) : INFINITY;
        const double d2 = pl_coupling_dist2_to(&q, cx, cy, cz, x[b + u], y[b + u], z[b + u]);
        sel[u] = (d2 < r2) & (d2 < R2);
    }
}

/* Tests particles [i0, i1) against the candidates [kb, ke) of clist (those
 * of cell cl and of every cell of its run), appending the selected ones to
 * found (with cl in found_cell) and, with a stage, copying their state.
 * Most runs have one candidate: its test in one vector loop, and each
 * selected particle one pair. */
static inline __attribute__((always_inline)) void test_range(select_run_t *s, uint32_t kb, uint32_t ke, size_t cl,
                                                             size_t i0, size_t i1)
{
    enum { RUN = 256 }; /* particles tested at a time */
    const pl_real *restrict x = s->f->r[0], *restrict y = s->f->r[1], *restrict z = s->f->r[2];
    const pl_real *restrict vx = s->f->v[0], *restrict vy = s->f->v[1], *restrict vz = s->f->v[2];
    const pl_coupling_colloids_t *c = s->c;
    int in[RUN], sel[RUN];
    double R2[RUN];
    for (size_t b = i0; b < i1; b += RUN) {
        const size_t len = i1 - b < RUN ? i1 - b : RUN;
        /* the vector loops run over whole vectors (the runs are short: no
         * scalar remainder), reading past the run into the next particles
         * where that is allowed; only the run's len are appended */
        const size_t whole = (len + 7) & ~(size_t)7, lenv = b + whole <= s->readable ? whole : len;
        const int one = ke - kb == 1;
        if (one && s->reach) test_one(s, s->clist[kb], b, lenv, 1, sel);
        else if (one) test_one(s, s->clist[kb], b, lenv, 0, sel);
        else {
            for (size_t u = 0; u < lenv; ++u) in[u] = sel[u] = 0;
            if (s->reach) {
#pragma omp simd
                for (size_t u = 0; u < lenv; ++u) R2[u] = reach2(s->reach, vx[b + u], vy[b + u], vz[b + u]);
            } else
                for (size_t u = 0; u < lenv; ++u) R2[u] = INFINITY;
            const pl_coupling_box_t q = s->q;
            for (uint32_t e = kb; e < ke; ++e) { /* pl_coupling_hit(), with its operands in registers */
                const int32_t k = s->clist[e];
                const double cx = c->x[k], cy = c->y[k], cz = c->z[k], r2 = c->rad[k] * c->rad[k];
#pragma omp simd
                for (size_t u = 0; u < lenv; ++u) {
                    const double d2 = pl_coupling_dist2_to(&q, cx, cy, cz, x[b + u], y[b + u], z[b + u]);
                    const int h = d2 < r2;
                    in[u] += h;
                    sel[u] |= h & (d2 < R2[u]);
                }
            }
        }
        const size_t m0 = s->m;
        size_t m = m0, np = s->np;
        uint32_t *restrict found = s->found + s->clo, *restrict found_cell = s->found_cell + s->clo;
        for (size_t u = 0; u < len; ++u) { /* branch-free append */
            found[m] = (uint32_t)(b + u);
            m += (size_t)sel[u];
        }
        for (size_t j = m0; j < m; ++j) found_cell[j] = (uint32_t)cl;
        if (one) np += m - m0; /* a selected particle is inside its one candidate */
        else
            for (size_t u = 0; u < len; ++u) np += sel[u] ? (size_t)in[u] : 0;
        if (s->stage) /* the state before the streaming, in list order */
            for (size_t j = m0; j < m; ++j) {
                if (j >= s->stage->cap) {
                    s->overflow++;
                    continue;
                }
                const size_t i = found[j];
                double *w = s->stage->buf + j * (size_t)s->stage->width;
                w[0] = x[i], w[1] = y[i], w[2] = z[i];
                w[3] = vx[i], w[4] = vy[i], w[5] = vz[i];
                if (s->stage->width > 6)
                    for (int d = 0; d < 3; ++d) w[6 + d] = s->f->disp[d][i];
            }
        s->m = m;
        s->np = np;
    }
}

/* Tests the particles [lo, hi) of the sorted fluid, walking the cells from
 * cl (the cell that holds lo, or a later one when those between hold no
 * candidates) in runs of consecutive cells with the same candidates: one
 * contiguous range of particles, tested candidate by candidate (vectorised
 * over the particles), each listed with the run's first cell.  Returns the
 * cell to go on from at hi. */
static inline __attribute__((always_inline)) size_t test_cells(select_run_t *s, size_t cl, size_t lo, size_t hi)
{
    const uint32_t *cell_start = s->cell_start, *cstart = s->cstart;
    while (cl < s->ncells && cell_start[cl] < hi) {
        const uint32_t kb = cstart[cl], ke = cstart[cl + 1];
        if (kb == ke) {
            ++cl;
            continue;
        }
        size_t ce = cl + 1;
        while (ce < s->ncells && cell_start[ce] < hi && same_candidates(cstart, s->clist, cl, ce)) ++ce;
        const size_t i0 = cell_start[cl] > lo ? cell_start[cl] : lo;
        const size_t i1 = cell_start[ce] < hi ? cell_start[ce] : hi;
        test_range(s, kb, ke, cl, i0, i1);
        if (cell_start[ce] > hi) return cl; /* the run goes on beyond hi */
        cl = ce;
    }
    return cl;
}

void pl_coupling_find_sorted(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling_colloids_t *c,
                             const pl_coupling_reach_t *reach, const uint32_t *cstart, const int32_t *clist,
                             const uint32_t *cell_start, int nthreads, uint32_t *found, uint32_t *found_cell,
                             uint64_t *counts)
{
#pragma omp parallel num_threads(nthreads)
    PL_FOR_PART(t, nthreads) {
        size_t lo, hi;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        select_run_t s = {.q = pl_coupling_box(g->L, g->walls), .c = c, .reach = reach, .f = f, .cstart = cstart,
                          .cell_start = cell_start, .clist = clist, .ncells = g->ncells, .clo = lo,
                          .readable = f->n, .found = found, .found_cell = found_cell};
        (void)test_cells(&s, first_cell_after(cell_start, g->ncells, lo), lo, hi);
        counts[(size_t)t * 8 + 2] = s.m;
        counts[(size_t)t * 8 + 3] = s.np;
    }
}

void pl_coupling_select_block(void *ctx, int t, size_t lo, size_t hi)
{
    pl_coupling_select_ctx_t *x = ctx;
    uint64_t *cnt = x->counts + (size_t)t * 8;
    size_t clo, chi;
    pl_chunk(x->f->n, t, x->nthreads, &clo, &chi);
    /* slot 4: the cell to go on from + 1 (0 before the chunk's first block) */
    const size_t cl = cnt[4] ? cnt[4] - 1 : first_cell_after(x->cell_start, x->g->ncells, lo);
    select_run_t s = {.q = pl_coupling_box(x->g->L, x->g->walls), .c = &x->c, .reach = &x->reach, .f = x->f,
                      .cstart = x->cstart, .cell_start = x->cell_start, .clist = x->clist,
                      .ncells = x->g->ncells, .clo = clo,
                      .readable = chi, /* the next chunk is another thread's, streaming now */
                      .found = x->found, .found_cell = x->found_cell, .stage = &x->stage[t],
                      .m = cnt[2], .np = cnt[3]};
    cnt[4] = test_cells(&s, cl, lo, hi) + 1;
    cnt[2] = s.m;
    cnt[3] = s.np;
    cnt[5] += s.overflow;
}

/* The second step of the detection (pl_coupling_find_binned,
 * pl_coupling_find_block): of the particles out[s0 .. s1) (in cells with
 * candidates), those a candidate's sphere holds are kept in order, in place,
 * from out[*in] on; *in and the pair count *np advance. */
static inline void keep_inside(const pl_coupling_box_t *q, const pl_coupling_colloids_t *c, const int32_t *clist,
                               const uint32_t *restrict cstart, const pl_fluid_t *f, uint32_t *out, size_t s0,
                               size_t s1, size_t *in, size_t *np)
{
    const uint32_t *restrict cell = f->cell;
    size_t kept = *in, pairs = *np;
    for (size_t s = s0; s < s1; ++s) {
        const size_t i = out[s], cl = cell[i];
        const int k = near_count(q, c, clist, (int32_t)cstart[cl], (int32_t)cstart[cl + 1], f->r[0][i],
                                 f->r[1][i], f->r[2][i]);
        out[kept] = (uint32_t)i;
        kept += (size_t)(k > 0);
        pairs += (size_t)k;
    }
    *in = kept;
    *np = pairs;
}

void pl_coupling_find_binned(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling_colloids_t *c,
                             const uint32_t *cstart, const int32_t *clist, int nthreads, uint32_t *found,
                             uint64_t *counts)
{
    const pl_coupling_box_t q = pl_coupling_box(g->L, g->walls);
    const uint32_t *restrict cell = f->cell;
#pragma omp parallel num_threads(nthreads)
    PL_FOR_PART(t, nthreads) {
        size_t lo, hi, m = 0, in = 0, np = 0;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        /* the particles in cells with candidates (branch-free append) ... */
        for (size_t i = lo; i < hi; ++i) {
            found[lo + m] = (uint32_t)i;
            m += (size_t)(cstart[cell[i]] != cstart[cell[i] + 1]);
        }
        /* ... then those a candidate's sphere holds, in place */
        keep_inside(&q, c, clist, cstart, f, found + lo, 0, m, &in, &np);
        counts[(size_t)t * 8 + 2] = in;
        counts[(size_t)t * 8 + 3] = np;
    }
}

void pl_coupling_find_block(void *ctx, int t, size_t lo, size_t hi)
{
    const pl_coupling_find_ctx_t *x = ctx;
    const pl_fluid_t *f = x->f;
    const pl_coupling_box_t q = pl_coupling_box(x->g->L, x->g->walls);
    const uint32_t *restrict cell = f->cell, *restrict cstart = x->cstart;
    const uint64_t *restrict mask = x->mask;
    size_t clo, chi;
    pl_chunk(f->n, t, x->nthreads, &clo, &chi);
    uint32_t *restrict out = x->found + clo;
    uint64_t *cnt = x->counts + (size_t)t * 8;
    /* the steps of pl_coupling_find_binned on [lo, hi), appended after what
     * the chunk's earlier blocks left; the cells with candidates from a bit
     * per cell (4 KiB at L = 32: stays in L1 while the streaming passes
     * megabytes through, where the offsets cstart would come from memory) */
    const size_t m0 = cnt[2];
    size_t m = m0, in = m0, np = cnt[3];
    for (size_t i = lo; i < hi; ++i) {
        const uint32_t cl = cell[i];
        out[m] = (uint32_t)i;
        m += (size_t)((mask[cl >> 6] >> (cl & 63)) & 1u);
    }
    keep_inside(&q, &x->c, x->clist, cstart, f, out, m0, m, &in, &np);
    cnt[2] = in;
    cnt[3] = np;
}

void pl_coupling_cell_mask(const uint32_t *cstart, size_t ncells, uint64_t *mask)
{
    for (size_t w = 0; w < (ncells + 63) / 64; ++w) {
        uint64_t b = 0;
        const size_t e = ncells - 64 * w < 64 ? ncells - 64 * w : 64;
        for (size_t j = 0; j < e; ++j) b |= (uint64_t)(cstart[64 * w + j + 1] != cstart[64 * w + j]) << j;
        mask[w] = b;
    }
}
