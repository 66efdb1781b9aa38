/* Potential coupling (PL Sec. III.A): fluid particles near colloids feel the
 * WCA repulsion of PL Eq. 17,
 *   phi_cf(r) = 4 eps [(sigma/r)^12 - (sigma/r)^6 + 1/4],  r <= 2^{1/6} sigma,
 * a radial force: slip surfaces (PL Sec. III.B).  Only the particles near a
 * colloid are integrated at the MD step (the order of the step:
 * src/coupling/coupling_potential.c).  This file finds them (parallel over the
 * streaming's static chunks; from the colloids near each collision cell
 * while the fluid is sorted, then inside the streaming, on each block it
 * has read and not yet stored), gathers them with their (particle, colloid)
 * pairs, takes back their free streaming, kicks and drifts them (PL Eqs.
 * 18-19, per particle) and writes them back, and evaluates the forces in
 * parallel over fixed blocks of particles: each block sums its reactions on
 * the colloids in particle order into its own row, and the rows are added
 * in block order, so the result depends on the number of selected particles
 * and colloids but not on the thread count.  The forces over the pairs
 * (vectorised, no lookup per evaluation) are fused with the kicks and the
 * drift around them (pl_coupling_potential_force_step): one pass over the
 * selected particles per MD step instead of four, the same bits (each
 * particle's and each colloid's operations in the same order). */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "peloid/coupling_kernels.h"
#include "peloid/srd_kernels.h"

/* The box for the minimum image: sides, and half sides on periodic axes
 * (INFINITY on closed ones: never exceeded). */
typedef struct {
    int L[3];
    double h[3];
} image_box_t;

static image_box_t image_box(const int L[3], const int walls[3])
{
    image_box_t q;
    for (int d = 0; d < 3; ++d) {
        q.L[d] = L[d];
        q.h[d] = walls[d] == PL_WALLS_NONE ? 0.5 * L[d] : INFINITY;
    }
    return q;
}

/* Minimum image of a separation d along an axis: one conditional shift
 * (separations here stay within one box side). */
static inline double min_image(double d, double h, int L) { return d > h ? d - L : (d < -h ? d + L : d); }

/* pl_coupling_inside's test, written out for the selection: the cell is a
 * truncation clamped to [0, L) (= floor + clip), the minimum image one
 * conditional shift on periodic axes (positions there are wrapped into
 * [0, L)), and no early exit, so the outcome is appended without a branch.
 * The same selections as pl_coupling_inside (checkpoints of periodic, z-wall
 * and capillary scenes bitwise equal); select stage 14 -> 10 ns/particle at
 * 1 thread, 7.5 -> 5.5 at 2 (bench_coupling's potential case). */
static inline __attribute__((always_inline)) double dist2_to(const image_box_t *q, double cx, double cy, double cz,
                                                            double x, double y, double z)
{
    const double dx = min_image(x - cx, q->h[0], q->L[0]);
    const double dy = min_image(y - cy, q->h[1], q->L[1]);
    const double dz = min_image(z - cz, q->h[2], q->L[2]);
    return dx * dx + dy * dy + dz * dz;
}

static inline double dist2(const image_box_t *q, const pl_coupling_colloids_t *c, int32_t k, double x, double y,
                           double z)
{
    return dist2_to(q, c->x[k], c->y[k], c->z[k], x, y, z);
}

static inline int hit(const image_box_t *q, const pl_coupling_colloids_t *c, int32_t k, double x, double y,
                      double z)
{
    return dist2(q, c, k, x, y, z) < c->rad[k] * c->rad[k];
}

/* The unit cell of a position (the lookup's). */
static inline size_t unit_cell(const image_box_t *q, double x, double y, double z)
{
    int ix = (int)x, iy = (int)y, iz = (int)z;
    ix = ix < 0 ? 0 : ix < q->L[0] ? ix : q->L[0] - 1;
    iy = iy < 0 ? 0 : iy < q->L[1] ? iy : q->L[1] - 1;
    iz = iz < 0 ? 0 : iz < q->L[2] ? iz : q->L[2] - 1;
    return ((size_t)iz * (size_t)q->L[1] + (size_t)iy) * (size_t)q->L[0] + (size_t)ix;
}

/* The number of colloids of the list [b, e) of lk_list whose sphere holds
 * the point. */
static inline int near_count(const image_box_t *q, const pl_coupling_colloids_t *c, const int32_t *lk_list,
                             int32_t b, int32_t e, double x, double y, double z)
{
    int in = 0;
    for (int32_t p = b; p < e; ++p) in += hit(q, c, lk_list[p], x, y, z);
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
    const image_box_t q = image_box(g->L, g->walls);
#pragma omp parallel num_threads(nthreads)
    {
        int t = omp_get_thread_num();
        size_t lo, hi, m = 0, np = 0;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        for (size_t i = lo; i < hi; ++i) {
            const double x = f->r[0][i], y = f->r[1][i], z = f->r[2][i];
            const size_t cell = unit_cell(&q, x, y, z);
            const double R2 = reach ? reach2(reach, f->v[0][i], f->v[1][i], f->v[2][i]) : INFINITY;
            int in = 0, sel = 0;
            for (int32_t p = lk_start[cell]; p < lk_start[cell + 1]; ++p) {
                const int32_t k = lk_list[p];
                const double d2 = dist2(&q, c, k, x, y, z);
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
    image_box_t q;
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

/* sel[u] for particles b + u, u < lenv, against the one candidate k: hit()
 * and, with_reach, within the particle's reach (the expressions of the
 * general case below, the same bits). */
static inline __attribute__((always_inline)) void test_one(const select_run_t *s, int32_t k, size_t b, size_t lenv,
                                                           int with_reach, int *restrict sel)
{
    const pl_real *restrict x = s->f->r[0], *restrict y = s->f->r[1], *restrict z = s->f->r[2];
    const pl_real *restrict vx = s->f->v[0], *restrict vy = s->f->v[1], *restrict vz = s->f->v[2];
    const pl_coupling_colloids_t *c = s->c;
    const double cx = c->x[k], cy = c->y[k], cz = c->z[k], r2 = c->rad[k] * c->rad[k];
    const image_box_t q = s->q;
#pragma omp simd
    for (size_t u = 0; u < lenv; ++u) {
        const double R2 = with_reach ? reach2(s->reach, vx[b + u], vy[b + u], vz[b + u]) : INFINITY;
        const double d2 = dist2_to(&q, cx, cy, cz, x[b + u], y[b + u], z[b + u]);
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
            const image_box_t q = s->q;
            for (uint32_t e = kb; e < ke; ++e) { /* hit(), with its operands in registers */
                const int32_t k = s->clist[e];
                const double cx = c->x[k], cy = c->y[k], cz = c->z[k], r2 = c->rad[k] * c->rad[k];
#pragma omp simd
                for (size_t u = 0; u < lenv; ++u) {
                    const double d2 = dist2_to(&q, cx, cy, cz, x[b + u], y[b + u], z[b + u]);
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
    {
        const int t = omp_get_thread_num();
        size_t lo, hi;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        select_run_t s = {.q = image_box(g->L, g->walls), .c = c, .reach = reach, .f = f, .cstart = cstart,
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
    select_run_t s = {.q = image_box(x->g->L, x->g->walls), .c = &x->c, .reach = &x->reach, .f = x->f,
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
static inline void keep_inside(const image_box_t *q, const pl_coupling_colloids_t *c, const int32_t *clist,
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
    const image_box_t q = image_box(g->L, g->walls);
    const uint32_t *restrict cell = f->cell;
#pragma omp parallel num_threads(nthreads)
    {
        int t = omp_get_thread_num();
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
    const image_box_t q = image_box(x->g->L, x->g->walls);
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

size_t pl_coupling_wca_blocks(size_t nn, size_t ncolloids)
{
    enum { BLOCK = 2048 };
    const size_t row = 3 * ncolloids + 1, cap = (size_t)1 << 20; /* doubles of partial sums */
    size_t nblk = (nn + BLOCK - 1) / BLOCK, most = cap / row;
    if (nblk > most) nblk = most;
    return nblk ? nblk : 1;
}

/* Forces on particles [lo, hi); reactions summed into row (3 nc + 1: x, y,
 * z per colloid, then the energy). */
static void wca_block(const pl_coupling_wca_t *w, size_t lo, size_t hi, const double *x, const double *y,
                      const double *z, double *fx, double *fy, double *fz, const pl_coupling_colloids_t *c,
                      const int32_t *lk_start, const int32_t *lk_list, double *row)
{
    const double s2 = w->sigma * w->sigma, rc2 = s2 * cbrt(2.0); /* (2^{1/6} sigma)^2 */
    const int *L = w->L;
    const size_t nc = c->n;
    const image_box_t q = image_box(w->L, w->walls);
    double epot = 0.0;
    for (size_t j = lo; j < hi; ++j) {
        double r[3] = {x[j], y[j], z[j]}, F[3] = {0.0, 0.0, 0.0};
        int ic[3];
        for (int d = 0; d < 3; ++d) {
            /* the lookup cell (positions here are unwrapped by at most one
             * step's drift; closed axes clipped): any cell next to the
             * particle lists every colloid within the cut-off (lookup radii:
             * cut-off + margin) */
            const double u = q.h[d] == INFINITY ? r[d] : r[d] < 0.0 ? r[d] + L[d] : r[d] >= L[d] ? r[d] - L[d] : r[d];
            ic[d] = (int)u;
            ic[d] = ic[d] < 0 ? 0 : ic[d] < L[d] ? ic[d] : L[d] - 1;
        }
        size_t cell = ((size_t)ic[2] * (size_t)L[1] + (size_t)ic[1]) * (size_t)L[0] + (size_t)ic[0];
        for (int32_t p = lk_start[cell]; p < lk_start[cell + 1]; ++p) {
            int32_t k = lk_list[p];
            double dv[3] = {r[0] - c->x[k], r[1] - c->y[k], r[2] - c->z[k]};
            /* equal to dv - L nearbyint(dv / L) wherever the pair can be
             * within the cut-off (|dv| < L / 2 + rc, L > 2 rc) */
            for (int a = 0; a < 3; ++a) dv[a] = min_image(dv[a], q.h[a], L[a]);
            double d2 = dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2];
            if (d2 >= rc2) continue;
            double sr6 = s2 / d2;
            sr6 = sr6 * sr6 * sr6;
            /* PL Eq. 17: F = 24 eps (2 (s/r)^12 - (s/r)^6) / r^2 * dv */
            double ff = 24.0 * w->eps * (2.0 * sr6 * sr6 - sr6) / d2;
            epot += 4.0 * w->eps * (sr6 * sr6 - sr6 + 0.25);
            for (int a = 0; a < 3; ++a) {
                F[a] += ff * dv[a];
                row[(size_t)a * nc + (size_t)k] -= ff * dv[a];
            }
        }
        fx[j] = F[0];
        fy[j] = F[1];
        fz[j] = F[2];
    }
    row[3 * nc] = epot;
}

double pl_coupling_wca_forces(const pl_coupling_wca_t *w, size_t nn, const double *x, const double *y,
                              const double *z, double *fx, double *fy, double *fz,
                              const pl_coupling_colloids_t *c, const int32_t *lk_start,
                              const int32_t *lk_list, double *cfx, double *cfy, double *cfz,
                              int nthreads, double *partial)
{
    const size_t nc = c->n, row = 3 * nc + 1, nblk = pl_coupling_wca_blocks(nn, nc);
#pragma omp parallel num_threads(nthreads)
    {
#pragma omp for schedule(dynamic, 1)
        for (size_t b = 0; b < nblk; ++b) {
            double *rb = partial + b * row;
            for (size_t q = 0; q < row; ++q) rb[q] = 0.0;
            wca_block(w, nn * b / nblk, nn * (b + 1) / nblk, x, y, z, fx, fy, fz, c, lk_start, lk_list, rb);
        }
        double *cf[3] = {cfx, cfy, cfz};
#pragma omp for schedule(static)
        for (size_t q = 0; q < 3 * nc; ++q) /* in block order */
            for (size_t b = 0; b < nblk; ++b) cf[q / nc][q % nc] += partial[b * row + q];
    }
    double epot = 0.0;
    for (size_t b = 0; b < nblk; ++b) epot += partial[b * row + 3 * nc];
    return epot;
}

/* PL Eq. 17 for one pair at separation (dx, dy, dz) (minimum image taken
 * here): the force on the particle and the energy, 0 beyond the cut-off
 * (selected, not multiplied: the same bits as wca_block's skip once
 * summed). */
static inline void wca_pair(double dx, double dy, double dz, double s2, double rc2, double e24, double e4,
                            const double h[3], const double L[3], double *gx, double *gy, double *gz, double *ge)
{
    dx = dx > h[0] ? dx - L[0] : (dx < -h[0] ? dx + L[0] : dx);
    dy = dy > h[1] ? dy - L[1] : (dy < -h[1] ? dy + L[1] : dy);
    dz = dz > h[2] ? dz - L[2] : (dz < -h[2] ? dz + L[2] : dz);
    const double d2 = dx * dx + dy * dy + dz * dz;
    double sr6 = s2 / d2;
    sr6 = sr6 * sr6 * sr6;
    /* PL Eq. 17: F = 24 eps (2 (s/r)^12 - (s/r)^6) / r^2 * dv */
    const double ff = e24 * (2.0 * sr6 * sr6 - sr6) / d2, e = e4 * (sr6 * sr6 - sr6 + 0.25);
    const int in = d2 < rc2;
    const double fin = in ? ff : 0.0;
    *gx = fin * dx;
    *gy = fin * dy;
    *gz = fin * dz;
    *ge = in ? e : 0.0;
}

/* Block of particles [lo, hi): forces into nb->f, reactions and energy into
 * its row rb (3 nc + 1).  The first pair of each particle (its first
 * candidate) vectorised over the particles, its force written straight into
 * f as the sum's first term (0 + g) and its energy into ge[j]; the further
 * ones (scratch g*[nb->n + p]) over their list; then the sums of wca_block,
 * in particle order, each particle's pairs in colloid order.  A particle
 * with one pair (nearly all) takes its reaction from f: -(0 + g) subtracts
 * the same as -g (they differ only for g = -0, and no row holds -0: it
 * starts at +0 and a sum is -0 only when both terms are); one with further
 * pairs has its first pair evaluated again (the same bits) for the sum. */
static void pair_block(const pl_coupling_wca_t *w, const pl_coupling_near_t *nb, const pl_coupling_colloids_t *c,
                       size_t lo, size_t hi, double *rb, double *restrict gx, double *restrict gy,
                       double *restrict gz, double *restrict ge)
{
    const size_t nc = c->n, row = 3 * nc + 1, nn = nb->n;
    for (size_t q = 0; q < row; ++q) rb[q] = 0.0;
    const double s2 = w->sigma * w->sigma, rc2 = s2 * cbrt(2.0); /* (2^{1/6} sigma)^2 */
    const double e24 = 24.0 * w->eps, e4 = 4.0 * w->eps;
    const image_box_t q = image_box(w->L, w->walls);
    const double h[3] = {q.h[0], q.h[1], q.h[2]}, L[3] = {q.L[0], q.L[1], q.L[2]};
    const double *restrict x = nb->r[0], *restrict y = nb->r[1], *restrict z = nb->r[2];
    const double *restrict cx = c->x, *restrict cy = c->y, *restrict cz = c->z;
    const int32_t *restrict k0 = nb->k0, *restrict pk = nb->pk;
    const uint32_t *restrict pj = nb->pj, *restrict ps = nb->pstart;
    double *restrict fx = nb->f[0], *restrict fy = nb->f[1], *restrict fz = nb->f[2];
#pragma omp simd
    for (size_t j = lo; j < hi; ++j) {
        const int32_t k = k0[j];
        double a, b, d;
        wca_pair(x[j] - cx[k], y[j] - cy[k], z[j] - cz[k], s2, rc2, e24, e4, h, L, &a, &b, &d, ge + j);
        fx[j] = 0.0 + a;
        fy[j] = 0.0 + b;
        fz[j] = 0.0 + d;
    }
    for (uint32_t p = ps[lo]; p < ps[hi]; ++p) {
        const uint32_t j = pj[p];
        const int32_t k = pk[p];
        wca_pair(x[j] - cx[k], y[j] - cy[k], z[j] - cz[k], s2, rc2, e24, e4, h, L, gx + nn + p, gy + nn + p,
                 gz + nn + p, ge + nn + p);
    }
    /* the reaction on the colloid of the last first pair (kc) is held in
     * registers (a run of particles near one colloid: no round trip through
     * memory per particle); the same subtractions in the same order */
    double epot = 0.0;
    double *rx = rb, *ry = rb + nc, *rz = rb + 2 * nc;
    int32_t kc = lo < hi ? k0[lo] : 0;
    double ax = 0.0, ay = 0.0, az = 0.0; /* = row of kc, all 0 at the start */
    for (size_t j = lo; j < hi; ++j) {
        const int32_t k = k0[j];
        if (k != kc) {
            rx[kc] = ax;
            ry[kc] = ay;
            rz[kc] = az;
            kc = k;
            ax = rx[k];
            ay = ry[k];
            az = rz[k];
        }
        epot += ge[j];
        if (ps[j] == ps[j + 1]) { /* one pair: f = 0 + g */
            ax -= fx[j];
            ay -= fy[j];
            az -= fz[j];
            continue;
        }
        double g0, g1, g2, e0;
        wca_pair(x[j] - cx[k], y[j] - cy[k], z[j] - cz[k], s2, rc2, e24, e4, h, L, &g0, &g1, &g2, &e0);
        double F0 = 0.0 + g0, F1 = 0.0 + g1, F2 = 0.0 + g2;
        ax -= g0;
        ay -= g1;
        az -= g2;
        for (uint32_t p = ps[j]; p < ps[j + 1]; ++p) {
            const int32_t kp = pk[p];
            const size_t e = nn + p;
            epot += ge[e];
            F0 += gx[e];
            F1 += gy[e];
            F2 += gz[e];
            rx[kp] -= gx[e]; /* kp > k0[j] = kc: not held */
            ry[kp] -= gy[e];
            rz[kp] -= gz[e];
        }
        fx[j] = F0;
        fy[j] = F1;
        fz[j] = F2;
    }
    if (lo < hi) {
        rx[kc] = ax;
        ry[kc] = ay;
        rz[kc] = az;
    }
    rb[3 * nc] = epot;
}

/* The reactions of the blocks' rows added in block order, and their energy. */
static double rows_sum(size_t nc, size_t nblk, const double *partial, double *cfx, double *cfy, double *cfz)
{
    const size_t row = 3 * nc + 1;
    double *cf[3] = {cfx, cfy, cfz};
    for (size_t q = 0; q < 3 * nc; ++q) /* in block order */
        for (size_t b = 0; b < nblk; ++b) cf[q / nc][q % nc] += partial[b * row + q];
    double epot = 0.0;
    for (size_t b = 0; b < nblk; ++b) epot += partial[b * row + 3 * nc];
    return epot;
}

double pl_coupling_wca_pair_forces(const pl_coupling_wca_t *w, const pl_coupling_near_t *nb,
                                   const pl_coupling_colloids_t *c, double *cfx, double *cfy, double *cfz,
                                   int nthreads, double *partial, double *pair_buf, size_t pair_cap)
{
    const size_t nn = nb->n, nc = c->n, row = 3 * nc + 1, nblk = pl_coupling_wca_blocks(nn, nc);
    double *gx = pair_buf, *gy = pair_buf + pair_cap, *gz = pair_buf + 2 * pair_cap, *ge = pair_buf + 3 * pair_cap;
#pragma omp parallel for schedule(dynamic, 1) num_threads(nthreads)
    for (size_t b = 0; b < nblk; ++b)
        pair_block(w, nb, c, nn * b / nblk, nn * (b + 1) / nblk, partial + b * row, gx, gy, gz, ge);
    return rows_sum(nc, nblk, partial, cfx, cfy, cfz);
}

/* Drift of particle j (PL Eq. 18) with the streaming's wall bounce; returns
 * |r - r0|^2. */
static inline double drift_one(const pl_coupling_near_t *nb, const pl_grid_t *g, const double wall_u[2][3],
                               double dt, size_t j, int64_t acc[PL_WALL_ACC_N])
{
    double *const *r = nb->r, *const *v = nb->v, *const *disp = nb->disp, *const *rs = nb->r0;
    const double r0[3] = {r[0][j], r[1][j], r[2][j]};
    for (int d = 0; d < 3; ++d) {
        r[d][j] += v[d][j] * dt;
        if (disp[0]) disp[d][j] += v[d][j] * dt;
    }
    if (g->any_walls) {
        /* the streaming's wall bounce (earliest wall first) */
        double rr[3] = {r[0][j], r[1][j], r[2][j]}, vv[3] = {v[0][j], v[1][j], v[2][j]};
        if (pl_srd_wall_bounce(g, wall_u, dt, r0, rr, vv, acc))
            for (int d = 0; d < 3; ++d) {
                if (disp[0]) disp[d][j] += rr[d] - r[d][j];
                r[d][j] = rr[d];
                v[d][j] = vv[d];
            }
    }
    const double a = r[0][j] - rs[0][j], b = r[1][j] - rs[1][j], e = r[2][j] - rs[2][j];
    return a * a + b * b + e * e;
}

double pl_coupling_potential_force_step(const pl_coupling_wca_t *w, const pl_coupling_near_t *nb,
                                        const pl_coupling_colloids_t *c, const pl_grid_t *g,
                                        const double wall_u[2][3], double h, const double ga[3], int kicks,
                                        double dt, double *cfx, double *cfy, double *cfz, int nthreads,
                                        double *partial, double *pair_buf, size_t pair_cap,
                                        int64_t acc[PL_WALL_ACC_N], double *far2)
{
    const size_t nn = nb->n, nc = c->n, row = 3 * nc + 1, nblk = pl_coupling_wca_blocks(nn, nc);
    double *gx = pair_buf, *gy = pair_buf + pair_cap, *gz = pair_buf + 2 * pair_cap, *ge = pair_buf + 3 * pair_cap;
    double *const *v = nb->v, *const *F = nb->f;
    const double g0 = ga[0], g1 = ga[1], g2 = ga[2];
    double far = 0.0;
    /* integer impulses: the sum is exact in any order; max is exact.
     * Static blocks: a thread keeps its blocks, and their particles in its
     * L2, over the MD steps of a collision step (the gather filled them in
     * the same halves); the bits do not depend on which thread runs a block */
#pragma omp parallel for schedule(static) num_threads(nthreads) reduction(+ : acc[:PL_WALL_ACC_N]) \
    reduction(max : far)
    for (size_t b = 0; b < nblk; ++b) {
        const size_t lo = nn * b / nblk, hi = nn * (b + 1) / nblk;
        pair_block(w, nb, c, lo, hi, partial + b * row, gx, gy, gz, ge);
        /* per particle, as pl_coupling_potential_kick (kicks times), then
         * pl_coupling_potential_drift */
        double *restrict vx = v[0], *restrict vy = v[1], *restrict vz = v[2];
        const double *restrict fx = F[0], *restrict fy = F[1], *restrict fz = F[2];
        if (dt > 0.0 && !g->any_walls && !nb->disp[0] && (kicks == 1 || kicks == 2)) {
            /* the kicks and drift_one in one vectorised pass, the velocity
             * kept in registers between them: the same operations on each
             * particle in the same order */
            double *restrict x = nb->r[0], *restrict y = nb->r[1], *restrict z = nb->r[2];
            const double *restrict x0 = nb->r0[0], *restrict y0 = nb->r0[1], *restrict z0 = nb->r0[2];
            const int twice = kicks == 2;
            /* the squared displacements of a chunk go to a buffer and their
             * maximum is taken after the vectorised loop (clang does not
             * vectorise the max inside it) */
            enum { CH = 256 };
            double d2b[CH];
            for (size_t j0 = lo; j0 < hi; j0 += CH) {
                const size_t j1 = hi - j0 < CH ? hi : j0 + CH;
#pragma omp simd
                for (size_t j = j0; j < j1; ++j) {
                    const double kx = h * (fx[j] + g0), ky = h * (fy[j] + g1), kz = h * (fz[j] + g2);
                    double ux = vx[j] + kx, uy = vy[j] + ky, uz = vz[j] + kz;
                    if (twice) {
                        ux += kx;
                        uy += ky;
                        uz += kz;
                    }
                    vx[j] = ux;
                    vy[j] = uy;
                    vz[j] = uz;
                    const double px = x[j] + ux * dt, py = y[j] + uy * dt, pz = z[j] + uz * dt;
                    x[j] = px;
                    y[j] = py;
                    z[j] = pz;
                    const double a = px - x0[j], bb = py - y0[j], e = pz - z0[j];
                    d2b[j - j0] = a * a + bb * bb + e * e;
                }
                for (size_t k = 0; k < j1 - j0; ++k) far = d2b[k] > far ? d2b[k] : far;
            }
            continue;
        }
        for (int q = 0; q < kicks; ++q) {
#pragma omp simd
            for (size_t j = lo; j < hi; ++j) {
                vx[j] += h * (fx[j] + g0);
                vy[j] += h * (fy[j] + g1);
                vz[j] += h * (fz[j] + g2);
            }
        }
        if (dt > 0.0 && !g->any_walls && !nb->disp[0]) { /* drift_one, vectorised */
            double *restrict x = nb->r[0], *restrict y = nb->r[1], *restrict z = nb->r[2];
            const double *restrict x0 = nb->r0[0], *restrict y0 = nb->r0[1], *restrict z0 = nb->r0[2];
#pragma omp simd reduction(max : far)
            for (size_t j = lo; j < hi; ++j) {
                x[j] += vx[j] * dt;
                y[j] += vy[j] * dt;
                z[j] += vz[j] * dt;
                const double a = x[j] - x0[j], bb = y[j] - y0[j], e = z[j] - z0[j];
                const double d2 = a * a + bb * bb + e * e;
                far = d2 > far ? d2 : far;
            }
        } else if (dt > 0.0) {
            for (size_t j = lo; j < hi; ++j) {
                const double d2 = drift_one(nb, g, wall_u, dt, j, acc);
                far = d2 > far ? d2 : far;
            }
        }
    }
    *far2 = far;
    return rows_sum(nc, nblk, partial, cfx, cfy, cfz);
}

/* ---- the selected particles at the MD step ----------------------------- */
/* Each particle is handled by one iteration and writes only its own slots
 * (and, in the scatter, the histogram row of its owner thread); the wall
 * impulses are integers: the results are the same for any thread count. */

void pl_coupling_potential_gather(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling_colloids_t *c,
                                  const uint32_t *found, const uint32_t *found_cell, const uint64_t *counts,
                                  const uint32_t *cstart, const int32_t *clist,
                                  const pl_coupling_stage_t *stage, int nthreads, const pl_coupling_near_t *nb)
{
    const image_box_t q = image_box(g->L, g->walls);
    /* thread t's chunk goes after those of 0..t-1: particle order */
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (int t = 0; t < nthreads; ++t) {
        size_t lo, hi, j = 0, p = 0;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        for (int u = 0; u < t; ++u) {
            j += counts[(size_t)u * 8 + 2];
            p += counts[(size_t)u * 8 + 3] - counts[(size_t)u * 8 + 2]; /* pairs beyond the first */
        }
        for (size_t s = 0; s < counts[(size_t)t * 8 + 2]; ++s, ++j) {
            size_t i = found[lo + s];
            nb->idx[j] = (uint32_t)i;
            nb->owner[j] = t;
            if (stage) { /* the state the selection saw, before the streaming */
                const double *w = stage[t].buf + s * (size_t)stage[t].width;
                for (int d = 0; d < 3; ++d) {
                    nb->r[d][j] = nb->r0[d][j] = w[d];
                    nb->v[d][j] = w[3 + d];
                    if (nb->disp[0]) nb->disp[d][j] = stage[t].width > 6 ? w[6 + d] : 0.0;
                }
            } else
                for (int d = 0; d < 3; ++d) {
                    nb->r[d][j] = nb->r0[d][j] = f->r[d][i];
                    nb->v[d][j] = f->v[d][i];
                    if (nb->disp[0]) nb->disp[d][j] = f->tracked ? f->disp[d][i] : 0.0;
                }
            /* its pairs: the colloids of the selection's test, in order:
             * the first, then the further ones */
            nb->pstart[j] = (uint32_t)p;
            const uint32_t cl = found_cell[lo + s];
            if (cstart[cl + 1] - cstart[cl] == 1) { /* a listed particle with one candidate: its only pair */
                nb->k0[j] = clist[cstart[cl]];
                continue;
            }
            int first = 1;
            for (uint32_t e = cstart[cl]; e < cstart[cl + 1]; ++e) {
                const int32_t k = clist[e];
                if (!hit(&q, c, k, nb->r[0][j], nb->r[1][j], nb->r[2][j])) continue;
                if (first) {
                    nb->k0[j] = k;
                    first = 0;
                    continue;
                }
                nb->pk[p] = k;
                nb->pj[p] = (uint32_t)j;
                p++;
            }
        }
        if (t == nthreads - 1) nb->pstart[j] = (uint32_t)p;
    }
}

void pl_coupling_potential_unstream(const pl_coupling_near_t *nb, pl_fluid_t *f, const pl_grid_t *g,
                                    const pl_stream_params_t *sp, int nthreads, int64_t acc[PL_WALL_ACC_N])
{
    const size_t nn = nb->n;
    /* integer impulses: the sum is exact in any order */
#pragma omp parallel for schedule(static) num_threads(nthreads) reduction(+ : acc[:PL_WALL_ACC_N])
    for (size_t j = 0; j < nn; ++j) {
        size_t i = nb->idx[j];
        if (f->tracked)
            for (int d = 0; d < 3; ++d) f->disp[d][i] = nb->disp[d][j];
        if (sp) {
            const double r0[3] = {nb->r[0][j], nb->r[1][j], nb->r[2][j]};
            const double v0[3] = {nb->v[0][j], nb->v[1][j], nb->v[2][j]};
            pl_srd_stream_wall_impulse(g, sp, r0, v0, acc);
        }
    }
}

void pl_coupling_potential_kick(const pl_coupling_near_t *nb, double h, const double g[3], int nthreads)
{
    const size_t nn = nb->n;
    double *const *v = nb->v;
    double *const *F = nb->f;
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t j = 0; j < nn; ++j)
        for (int d = 0; d < 3; ++d) v[d][j] += h * (F[d][j] + g[d]);
}

/* Walls: the streaming's bounce (pl_srd_wall_bounce: to the wall at the
 * crossing time, bounce-back or specular, the rest of the step; earliest wall
 * first), so a particle near a colloid meets the same wall as any other.  A
 * per-axis mirror of the end point with a bounce-back velocity made the
 * equilibrium force of a pinned colloid near a no-slip wall 7 % too strong
 * (tests/test_coupling_wall.c: the exact Boltzmann force). */
double pl_coupling_potential_drift(const pl_coupling_near_t *nb, const pl_grid_t *g, const double wall_u[2][3],
                                   double dt, int nthreads, int64_t acc[PL_WALL_ACC_N])
{
    const size_t nn = nb->n;
    double far = 0.0;
    /* integer impulses: the sum is exact in any order; max is exact */
#pragma omp parallel for schedule(static) num_threads(nthreads) reduction(+ : acc[:PL_WALL_ACC_N]) \
    reduction(max : far)
    for (size_t j = 0; j < nn; ++j) {
        const double d2 = drift_one(nb, g, wall_u, dt, j, acc);
        far = d2 > far ? d2 : far;
    }
    return far;
}

/* First index of the selected list whose owner is >= t (owners ascend). */
static size_t owner_start(const pl_coupling_near_t *nb, int t)
{
    size_t lo = 0, hi = nb->n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (nb->owner[mid] < t) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

void pl_coupling_potential_scatter(const pl_coupling_near_t *nb, pl_fluid_t *f, const pl_grid_t *g,
                                   uint32_t *hist, int nthreads)
{
    const double L[3] = {g->L[0], g->L[1], g->L[2]};
    const double inner[3] = {L[0] * (1.0 - 0x1p-50), L[1] * (1.0 - 0x1p-50), L[2] * (1.0 - 0x1p-50)};
    /* the particles of one owner (a contiguous run of the list) and its
     * histogram row are handled by one thread */
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (int t = 0; t < nthreads; ++t) {
        size_t j = owner_start(nb, t), end = owner_start(nb, t + 1);
        uint32_t *hrow = hist + (size_t)t * g->ncells;
        for (; j < end; ++j) {
            size_t i = nb->idx[j];
            for (int d = 0; d < 3; ++d) {
                double x = nb->r[d][j];
                /* x - L floor(x / L) is x where floor(x / L) = 0 for sure:
                 * 0 < x < L (1 - 2^-50) (x = -0 becomes +0) */
                if (g->walls[d] == PL_WALLS_NONE && !(x > 0.0 && x < inner[d])) {
                    x -= L[d] * floor(x / L[d]);
                    if (x >= L[d]) x = 0.0;
                }
                f->r[d][i] = (pl_real)x;
                f->v[d][i] = (pl_real)nb->v[d][j];
                if (f->tracked) f->disp[d][i] = nb->disp[d][j];
            }
            uint32_t cell = pl_coupling_cell_of(g, f->r[0][i], f->r[1][i], f->r[2][i]);
            hrow[f->cell[i]]--;
            hrow[cell]++;
            f->cell[i] = cell;
        }
    }
}
