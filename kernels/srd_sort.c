/* Counting sort of fluid particles by collision cell (DESIGN.md "Data").
 *
 * Input: fluid->cell and the per-thread histograms hist[t * ncells + c] that
 * pl_srd_stream_bin filled for the static chunks pl_chunk(t).  A prefix sum
 * over (cell, thread) gives every (cell, thread) pair its first slot; each
 * thread then scatters its own chunk in order.  No atomics, and the result is
 * the stable sort by cell, hence independent of the thread count. */
#include <omp.h>
#include <string.h>

#include "peloid/srd_kernels.h"

static void scatter_real(pl_real *restrict dst, const pl_real *restrict src, size_t i, size_t j)
{
    dst[j] = src[i];
}

void pl_srd_sort(pl_fluid_t *f, uint32_t *hist, uint32_t *cell_start, size_t ncells, int nthreads)
{
#pragma omp parallel num_threads(nthreads)
    {
        /* pass 1: per-cell totals into cell_start[c] */
#pragma omp for schedule(static)
        for (size_t c = 0; c < ncells; ++c) {
            uint32_t sum = 0;
            for (int t = 0; t < nthreads; ++t) sum += hist[(size_t)t * ncells + c];
            cell_start[c] = sum;
        }
        /* pass 2: exclusive scan over cells (serial: one add per cell) */
#pragma omp single
        {
            uint32_t acc = 0;
            for (size_t c = 0; c < ncells; ++c) {
                uint32_t cnt = cell_start[c];
                cell_start[c] = acc;
                acc += cnt;
            }
            cell_start[ncells] = acc;
        }
        /* pass 3: hist[t][c] := first slot of (cell c, thread t) */
#pragma omp for schedule(static)
        for (size_t c = 0; c < ncells; ++c) {
            uint32_t off = cell_start[c];
            for (int t = 0; t < nthreads; ++t) {
                uint32_t cnt = hist[(size_t)t * ncells + c];
                hist[(size_t)t * ncells + c] = off;
                off += cnt;
            }
        }
        /* pass 4: stable scatter of each thread's own chunk */
        int t = omp_get_thread_num();
        size_t lo, hi;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        uint32_t *restrict h = hist + (size_t)t * ncells;
        const uint32_t *restrict cell = f->cell;
        for (size_t i = lo; i < hi; ++i) {
            size_t j = h[cell[i]]++;
            for (int d = 0; d < 3; ++d) {
                scatter_real(f->r_alt[d], f->r[d], i, j);
                scatter_real(f->v_alt[d], f->v[d], i, j);
            }
            if (f->tracked) {
                f->id_alt[j] = f->id[i];
                for (int d = 0; d < 3; ++d) f->disp_alt[d][j] = f->disp[d][i];
            }
        }
    }
    pl_fluid_swap(f);
}
