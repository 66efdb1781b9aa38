/* Counting sort of fluid particles by collision cell (DESIGN.md "Data"), and
 * the same sort with the drift done inside the scatter.
 *
 * Input: the per-thread histograms hist[t * ncells + c] filled for the
 * static chunks pl_chunk(t) (pl_srd_bin / pl_srd_stream_bin, or
 * pl_srd_stream_count), each row only in its thread's band of z planes
 * (pl_fluid_bands_t: the sort sets the bands of the next step and counts
 * the whole rows again when a count fell outside one).  A prefix sum over (cell, thread) gives every
 * (cell, thread) pair its first slot; each thread then scatters its own chunk
 * in order.  No atomics, and the result is the stable sort by cell, hence
 * independent of the thread count.  The sorted particles are left in the
 * twin arrays (r_alt, v_alt, ...): the caller swaps them in (pl_fluid_swap),
 * so that a kernel calls nothing of src/.  The index sort (srd.sort_interval)
 * is the same stable sort with the scatter writing each slot's particle
 * index into f->order instead of moving the particles.
 *
 * The prefix sum is parallel: part t sums its block of cells, the block
 * totals are added up (nthreads terms), then every part writes the slots of
 * its block.  Integer sums: the same result as a serial scan.  The parts are
 * the thread count the histogram was counted for; the team takes them
 * round-robin (omp_parts.h), so a team smaller than asked gives the same
 * bits. */
#include <omp.h>
#include <string.h>

#include "omp_parts.h"
#include "srd_drift.h"

/* The rows whose band meets cell block [c0, c1): only they hold counts
 * there (every particle of part u lies in u's band, so another row's count
 * there is 0).  Returns how many, in rows[]. */
static int rows_of_block(int nthreads, size_t ncells, size_t c0, size_t c1, const uint32_t *blo,
                         const uint32_t *blen, int *rows)
{
    int nr = 0;
    for (int u = 0; u < nthreads; ++u) {
        const size_t a = blo[u], e = a + blen[u]; /* [a, e), e > ncells: wrapped to [0, e - ncells) */
        if (blen[u] && ((a < c1 && e > c0) || (e > ncells && e - ncells > c0))) rows[nr++] = u;
    }
    return nr;
}

/* Scan, first half: part[t] := the particles in part t's block of cells,
 * read from the rows whose band covers a cell only. */
static void prefix_total(const uint32_t *hist, size_t ncells, int nthreads, int t, uint32_t *part,
                         const uint32_t *blo, const uint32_t *blen)
{
    size_t c0, c1;
    pl_chunk(ncells, t, nthreads, &c0, &c1);
    int rows[nthreads];
    const int nr = rows_of_block(nthreads, ncells, c0, c1, blo, blen, rows);
    const uint32_t nc = (uint32_t)ncells;
    uint32_t tot = 0;
    for (int k = 0; k < nr; ++k) {
        const int u = rows[k];
        const uint32_t *restrict hu = hist + (size_t)u * ncells;
        if (blen[u] == nc) { /* the whole row: no test */
            for (size_t c = c0; c < c1; ++c) tot += hu[c];
            continue;
        }
        for (size_t c = c0; c < c1; ++c)
            if (!pl_fluid_band_out((uint32_t)c, blo[u], blen[u], nc)) tot += hu[c];
    }
    part[t] = tot;
}

/* Scan, second half (every part[] complete): hist[u][c] := the first slot
 * of (cell c, part u), in (cell, part) order, for part t's block of cells. */
static void prefix_slots(uint32_t *hist, uint32_t *cell_start, size_t ncells, int nthreads, int t,
                         const uint32_t *part, const uint32_t *blo, const uint32_t *blen)
{
    size_t c0, c1;
    pl_chunk(ncells, t, nthreads, &c0, &c1);
    int rows[nthreads];
    const int nr = rows_of_block(nthreads, ncells, c0, c1, blo, blen, rows);
    const uint32_t nc = (uint32_t)ncells;
    uint32_t off = 0;
    for (int u = 0; u < t; ++u) off += part[u];
    for (size_t c = c0; c < c1; ++c) {
        cell_start[c] = off;
        for (int k = 0; k < nr; ++k) {
            const int u = rows[k];
            if (blen[u] != nc && pl_fluid_band_out((uint32_t)c, blo[u], blen[u], nc)) continue;
            const uint32_t cnt = hist[(size_t)u * ncells + c];
            hist[(size_t)u * ncells + c] = off;
            off += cnt;
        }
    }
    if (t == nthreads - 1) cell_start[ncells] = off;
}

/* The band of the next step for thread t's chunk [lo, hi) of the sorted
 * particles (cell_start complete): the z planes of its first and last
 * particle's cells and b->margin planes each side (PL_BAND_MARGIN at first:
 * a grid shift moves a particle's plane by at most 1, a drift of less than a
 * cell by at most 1 more; doubled after each step where that fell short, as
 * with long mean free paths or a coupling's moves), wrapped around a
 * periodic z axis; the whole row where that covers every plane. */
static void next_band(const pl_fluid_bands_t *b, const uint32_t *cell_start, size_t ncells, size_t lo,
                      size_t hi, uint32_t *blo, uint32_t *blen)
{
    *blo = 0;
    *blen = (uint32_t)ncells;
    if (hi <= lo || !b->plane || (size_t)b->plane * b->nz != ncells) return;
    size_t ends[2] = {lo, hi - 1}, cells[2];
    for (int k = 0; k < 2; ++k) { /* the last cell whose start is <= the slot */
        size_t a = 0, e = ncells; /* cell_start[a] <= slot < cell_start[e] */
        while (e - a > 1) {
            size_t m = a + (e - a) / 2;
            if (cell_start[m] <= ends[k]) a = m;
            else e = m;
        }
        cells[k] = a;
    }
    const long long M = b->margin ? b->margin : PL_BAND_MARGIN, nz = b->nz;
    long long p0 = (long long)(cells[0] / b->plane) - M, p1 = (long long)(cells[1] / b->plane) + M;
    if (!b->z_periodic) {
        p0 = p0 < 0 ? 0 : p0;
        p1 = p1 > nz - 1 ? nz - 1 : p1;
    }
    if (p1 - p0 + 1 >= nz) return;
    if (p0 < 0) p0 += nz;
    *blo = (uint32_t)p0 * b->plane;
    *blen = (uint32_t)(p1 - (p0 > p1 ? p0 - nz : p0) + 1) * b->plane;
}

enum { PF = 48 }; /* prefetch distance of the scatter, in particles (48 > 24 > 8, 96 no better) */

/* Stable scatter of [lo, hi): particle i goes to slot h[cell]++.  With
 * drift != NULL the particle is drifted first (bitwise as pl_srd_stream_bin
 * would) and its cell recomputed, else the cell is read from f->cell. */
static void scatter(pl_fluid_t *f, const pl_drift_t *drift, uint32_t *restrict h, size_t lo,
                    size_t hi)
{
    const pl_real *restrict x = f->r[0], *restrict y = f->r[1], *restrict z = f->r[2];
    const pl_real *restrict vx = f->v[0], *restrict vy = f->v[1], *restrict vz = f->v[2];
    pl_real *restrict xa = f->r_alt[0], *restrict ya = f->r_alt[1], *restrict za = f->r_alt[2];
    pl_real *restrict vxa = f->v_alt[0], *restrict vya = f->v_alt[1], *restrict vza = f->v_alt[2];
    if (!f->tracked && drift && !drift->walls) {
        double rb[3][PL_DRIFT_BLOCK], vb[3][PL_DRIFT_BLOCK];
        uint32_t cb[PL_DRIFT_BLOCK];
        for (size_t i = lo; i < hi; i += PL_DRIFT_BLOCK) {
            const size_t m = hi - i < PL_DRIFT_BLOCK ? hi - i : PL_DRIFT_BLOCK;
            pl_drift_block_periodic(drift, x + i, y + i, z + i, vx + i, vy + i, vz + i, m, rb, vb, cb);
            for (size_t k = 0; k < m; ++k) {
                const size_t j = h[cb[k]]++;
                xa[j] = (pl_real)rb[0][k]; ya[j] = (pl_real)rb[1][k]; za[j] = (pl_real)rb[2][k];
                vxa[j] = (pl_real)vb[0][k]; vya[j] = (pl_real)vb[1][k]; vza[j] = (pl_real)vb[2][k];
            }
        }
        return;
    }
    if (!f->tracked && drift) {
        for (size_t i = lo; i < hi; ++i) {
            double r[3] = {x[i], y[i], z[i]}, v[3] = {vx[i], vy[i], vz[i]}, dr[3];
            const size_t j = h[pl_drift_one(drift, r, v, dr, NULL)]++;
            xa[j] = (pl_real)r[0]; ya[j] = (pl_real)r[1]; za[j] = (pl_real)r[2];
            vxa[j] = (pl_real)v[0]; vya[j] = (pl_real)v[1]; vza[j] = (pl_real)v[2];
        }
        return;
    }
    if (!f->tracked) {
        /* Two passes, positions then velocities (12 write streams each
         * instead of 24; the first keeps each particle's slot in f->cell,
         * which nothing reads after the sort), with software prefetch of
         * the slot particle i + PF will take (its cell's current count: the
         * same line or the one before).  The random-order first sort of a
         * run gains most.  Same stores, same result. */
        uint32_t *slot = f->cell; /* cell[i] in, slot of i out */
        for (size_t i = lo; i < hi; ++i) {
            if (i + PF < hi) {
                const size_t jp = h[slot[i + PF]];
                __builtin_prefetch(xa + jp, 1, 3);
                __builtin_prefetch(ya + jp, 1, 3);
                __builtin_prefetch(za + jp, 1, 3);
            }
            const uint32_t j = h[slot[i]]++;
            slot[i] = j;
            xa[j] = x[i]; ya[j] = y[i]; za[j] = z[i];
        }
        for (size_t i = lo; i < hi; ++i) {
            if (i + PF < hi) {
                const size_t jp = slot[i + PF];
                __builtin_prefetch(vxa + jp, 1, 3);
                __builtin_prefetch(vya + jp, 1, 3);
                __builtin_prefetch(vza + jp, 1, 3);
            }
            const size_t j = slot[i];
            vxa[j] = vx[i]; vya[j] = vy[i]; vza[j] = vz[i];
        }
        return;
    }
    const uint32_t *restrict cell = f->cell;
    const uint32_t *restrict id = f->id;
    uint32_t *restrict ida = f->id_alt;
    const double *restrict dx = f->disp[0], *restrict dy = f->disp[1], *restrict dz = f->disp[2];
    double *restrict dxa = f->disp_alt[0], *restrict dya = f->disp_alt[1], *restrict dza = f->disp_alt[2];
    for (size_t i = lo; i < hi; ++i) {
        double r[3] = {x[i], y[i], z[i]}, v[3] = {vx[i], vy[i], vz[i]}, dr[3] = {0.0, 0.0, 0.0};
        const size_t j = drift ? h[pl_drift_one(drift, r, v, dr, NULL)]++ : h[cell[i]]++;
        xa[j] = (pl_real)r[0]; ya[j] = (pl_real)r[1]; za[j] = (pl_real)r[2];
        vxa[j] = (pl_real)v[0]; vya[j] = (pl_real)v[1]; vza[j] = (pl_real)v[2];
        ida[j] = id[i];
        if (drift) {
            dxa[j] = dx[i] + dr[0]; dya[j] = dy[i] + dr[1]; dza[j] = dz[i] + dr[2];
        } else {
            dxa[j] = dx[i]; dya[j] = dy[i]; dza[j] = dz[i];
        }
    }
}

/* The index sort's scatter (pl_srd_sort_index): slot h[cell[i]]++ takes
 * particle i: it writes 4 B per particle where the full scatter writes 52. */
static void scatter_index(const uint32_t *restrict cell, uint32_t *restrict order, uint32_t *restrict h,
                          size_t lo, size_t hi)
{
    for (size_t i = lo; i < hi; ++i) order[h[cell[i]]++] = (uint32_t)i;
}

/* The counts of [lo, hi) into the whole row h again (a count fell outside a
 * band): the cells the scatter will use, f->cell or the drift's. */
static void recount(const pl_fluid_t *f, const pl_drift_t *drift, uint32_t *restrict h, size_t ncells,
                    size_t lo, size_t hi)
{
    memset(h, 0, ncells * sizeof *h);
    if (!drift) {
        for (size_t i = lo; i < hi; ++i) h[f->cell[i]]++;
        return;
    }
    const pl_real *x = f->r[0], *y = f->r[1], *z = f->r[2], *vx = f->v[0], *vy = f->v[1], *vz = f->v[2];
    if (!f->tracked && !drift->walls) { /* as the scatter's periodic blocks */
        double rb[3][PL_DRIFT_BLOCK], vb[3][PL_DRIFT_BLOCK];
        uint32_t cb[PL_DRIFT_BLOCK];
        for (size_t i = lo; i < hi; i += PL_DRIFT_BLOCK) {
            const size_t m = hi - i < PL_DRIFT_BLOCK ? hi - i : PL_DRIFT_BLOCK;
            pl_drift_block_periodic(drift, x + i, y + i, z + i, vx + i, vy + i, vz + i, m, rb, vb, cb);
            for (size_t k = 0; k < m; ++k) h[cb[k]]++;
        }
        return;
    }
    for (size_t i = lo; i < hi; ++i) {
        double r[3] = {x[i], y[i], z[i]}, v[3] = {vx[i], vy[i], vz[i]}, dr[3];
        h[pl_drift_one(drift, r, v, dr, NULL)]++;
    }
}

/* index_only: the permutation into f->order, the arrays and the bands left
 * as they are (the arrays keep the order the bands were set for). */
static void sort(pl_fluid_t *f, const pl_drift_t *drift, uint32_t *hist, uint32_t *cell_start,
                 size_t ncells, int nthreads, int index_only)
{
    uint32_t part[nthreads];            /* particles in each thread's block of cells */
    uint32_t blo[nthreads], blen[nthreads]; /* the bands the rows were counted in */
    const int whole = f->bands.overflow;  /* a count fell outside a band: whole rows */
    for (int t = 0; t < nthreads; ++t) {
        pl_fluid_band(f, t, nthreads, (uint32_t)ncells, &blo[t], &blen[t]);
        if (whole) {
            blo[t] = 0;
            blen[t] = (uint32_t)ncells;
        }
    }
    const int banded = nthreads <= PL_BAND_MAX_THREADS;
    if (f->bands.threads == nthreads) {
        f->bands.sorts++;
        f->bands.recounts += (uint64_t)whole;
        if (whole) { /* the next bands twice as wide */
            const uint32_t m = f->bands.margin ? f->bands.margin : PL_BAND_MARGIN;
            f->bands.margin = m < f->bands.nz ? 2 * m : m;
        }
    }
    /* One region: part t scans its block of cells, then scatters the
     * particle chunk pl_chunk(n, t) whose histogram row it filled, and sets
     * its band of the next step.  Parts, not threads, between the barriers:
     * a smaller team takes several each (omp_parts.h). */
    const int recount_rows = whole && f->bands.threads == nthreads; /* the bands were in use: rows not whole */
#pragma omp parallel num_threads(nthreads)
    {
        if (recount_rows) {
            PL_FOR_PART(t, nthreads) {
                size_t lo, hi;
                pl_chunk(f->n, t, nthreads, &lo, &hi);
                recount(f, drift, hist + (size_t)t * ncells, ncells, lo, hi);
            }
#pragma omp barrier
        }
        PL_FOR_PART(t, nthreads) prefix_total(hist, ncells, nthreads, t, part, blo, blen);
#pragma omp barrier
        PL_FOR_PART(t, nthreads) prefix_slots(hist, cell_start, ncells, nthreads, t, part, blo, blen);
#pragma omp barrier
        PL_FOR_PART(t, nthreads) {
            size_t lo, hi;
            pl_chunk(f->n, t, nthreads, &lo, &hi);
            if (index_only) {
                scatter_index(f->cell, f->order, hist + (size_t)t * ncells, lo, hi);
                continue;
            }
            scatter(f, drift, hist + (size_t)t * ncells, lo, hi);
            if (banded) next_band(&f->bands, cell_start, ncells, lo, hi, &f->bands.lo[t], &f->bands.len[t]);
        }
    }
    if (!index_only) f->bands.threads = banded ? nthreads : 0;
    f->bands.overflow = 0;
}

void pl_srd_sort(pl_fluid_t *f, uint32_t *hist, uint32_t *cell_start, size_t ncells, int nthreads)
{
    sort(f, NULL, hist, cell_start, ncells, nthreads, 0);
}

void pl_srd_sort_index(pl_fluid_t *f, uint32_t *hist, uint32_t *cell_start, size_t ncells, int nthreads)
{
    sort(f, NULL, hist, cell_start, ncells, nthreads, 1);
}

void pl_srd_stream_sort(pl_fluid_t *f, const pl_grid_t *g, const pl_stream_params_t *p,
                        uint32_t *hist, uint32_t *cell_start, int nthreads)
{
    pl_drift_t c;
    pl_drift_init(&c, g, p, 1);
    sort(f, &c, hist, cell_start, g->ncells, nthreads, 0);
}
