/* Verlet neighbour lists of the colloids, built from the linked cells
 * (kernels/colloid_cells.c) with a skin: a pair is listed when its centres are
 * closer than rlist = (largest pair cut-off) + skin, and the list stays valid
 * until some colloid has moved by more than skin / 2 since the build (then no
 * pair can have come from beyond rlist to inside the cut-off).  The caller
 * (src/colloid/colloid_state.c) checks the displacement before every force
 * evaluation and rebuilds when it is exceeded.
 *
 * Why the trajectory does not depend on when the list was built: the force
 * kernel adds, for each colloid, its own pairs in ascending partner index and
 * then its reverse pairs in ascending owner index, and a listed pair beyond
 * its cut-off adds exactly +0.0.  Any valid list (any superset of the pairs
 * inside the cut-off, in that order) therefore gives the same bits: a restart,
 * which rebuilds the list from the checkpointed positions, continues bitwise.
 *
 * Threads: the count and fill passes are parallel over colloids, each writing
 * only its own count / slots (static blocks; slot ranges come from the prefix
 * sum, so the list is the same for any thread count), as orphaned loops
 * (_loop: the MD region of kernels/colloid_md_region.c runs them inside its
 * team) or each in a region of its own.  The reverse entries
 * come from a serial counting transpose (O(pairs), only at a build). */
#include <math.h>

#include "peloid/colloid_pair_terms.h"


/* The own partners of i within rlist, from the 27 (or fewer) cells around
 * i's cell; written to out (when non-NULL) in ascending index. */
static size_t scan_cells(const pl_colloid_cells_t *c, const double box[3], const int periodic[3],
                         double rl2, const double *x, const double *y, const double *z, size_t i,
                         int32_t *out)
{
    const int *nc = c->nc;
    int lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {
        lo[d] = nc[d] == 1 ? 0 : -1;
        hi[d] = nc[d] == 1 ? 0 : 1;
    }
    int32_t ci = c->cell[i];
    int cx = ci % nc[0], cy = (ci / nc[0]) % nc[1], cz = ci / (nc[0] * nc[1]);
    size_t m = 0;
    for (int oz = lo[2]; oz <= hi[2]; ++oz) {
        int zz = cz + oz;
        if (zz < 0 || zz >= nc[2]) {
            if (!periodic[2]) continue;
            zz = (zz + nc[2]) % nc[2];
        }
        for (int oy = lo[1]; oy <= hi[1]; ++oy) {
            int yy = cy + oy;
            if (yy < 0 || yy >= nc[1]) {
                if (!periodic[1]) continue;
                yy = (yy + nc[1]) % nc[1];
            }
            for (int ox = lo[0]; ox <= hi[0]; ++ox) {
                int xx = cx + ox;
                if (xx < 0 || xx >= nc[0]) {
                    if (!periodic[0]) continue;
                    xx = (xx + nc[0]) % nc[0];
                }
                int32_t cc = (zz * nc[1] + yy) * nc[0] + xx;
                for (int32_t k = c->start[cc]; k < c->start[cc + 1]; ++k) {
                    size_t j = (size_t)c->list[k];
                    if (j == i || !pl_colloid_pair_owner(i, j)) continue;
                    double dx = pl_min_image(x[i] - x[j], box[0], periodic[0]);
                    double dy = pl_min_image(y[i] - y[j], box[1], periodic[1]);
                    double dz = pl_min_image(z[i] - z[j], box[2], periodic[2]);
                    if (dx * dx + dy * dy + dz * dz >= rl2) continue;
                    if (out) {
                        /* insertion into the ascending run out[0..m) */
                        size_t q = m;
                        while (q > 0 && out[q - 1] > (int32_t)j) {
                            out[q] = out[q - 1];
                            --q;
                        }
                        out[q] = (int32_t)j;
                    }
                    ++m;
                }
            }
        }
    }
    return m;
}

/* Reverse entries (counting transpose, owners in ascending order) and the
 * slot count, from start and nbr. */
static void reverse_entries(pl_colloid_nlist_t *nl, int nthreads)
{
    const size_t n = nl->n;
    nl->npairs = (size_t)nl->start[n];
    int32_t *rs = nl->rstart;
    for (size_t i = 0; i <= n; ++i) rs[i] = 0;
    for (size_t p = 0; p < nl->npairs; ++p) rs[nl->nbr[p] + 1]++;
    for (size_t i = 0; i < n; ++i) rs[i + 1] += rs[i];
    for (size_t i = 0; i < n; ++i)
        for (int32_t p = nl->start[i]; p < nl->start[i + 1]; ++p) {
            const int32_t r = rs[nl->nbr[p]]++;
            nl->rslot[r] = p;
            nl->spos[p] = r;
        }
    for (size_t i = n; i > 0; --i) rs[i] = rs[i - 1];
    rs[0] = 0;
    /* the layout of the pair results (pl_colloid_nlist_t): by reverse entry
     * where the kernels' regions run on several threads */
    nl->by_entry = nthreads > 1 && n >= PL_COLLOID_OMP_MIN;
    nl->builds++;
}

double pl_colloid_nlist_max_disp2(const pl_colloid_nlist_t *nl, const double box[3],
                                  const int periodic[3], const double *x, const double *y,
                                  const double *z, int nthreads)
{
    double m = 0.0;
    size_t n = nl->n;
    /* max is exact, so the reduction order does not matter */
#pragma omp parallel for schedule(static) num_threads(nthreads) reduction(max : m) if (n >= PL_COLLOID_OMP_MIN)
    for (size_t i = 0; i < n; ++i) {
        double d2 = pl_colloid_nlist_disp2(nl, box, periodic, x, y, z, i);
        /* a non-finite position forces a rebuild; the NaN guard reports it */
        if (!(d2 <= m)) m = isnan(d2) ? INFINITY : d2;
    }
    return m;
}

void pl_colloid_nlist_count_loop(pl_colloid_nlist_t *nl, const pl_colloid_cells_t *cells,
                                 const double box[3], const int periodic[3], const double *x,
                                 const double *y, const double *z)
{
    size_t n = nl->n;
    double rl2 = nl->rlist * nl->rlist;
#pragma omp for schedule(static)
    for (size_t i = 0; i < n; ++i) {
        if (i == 0) nl->start[0] = 0; /* by one thread */
        nl->start[i + 1] = (int32_t)scan_cells(cells, box, periodic, rl2, x, y, z, i, NULL);
    }
}

void pl_colloid_nlist_count(pl_colloid_nlist_t *nl, const pl_colloid_cells_t *cells,
                            const double box[3], const int periodic[3], const double *x,
                            const double *y, const double *z, int nthreads)
{
#pragma omp parallel num_threads(nthreads) if (nl->n >= PL_COLLOID_OMP_MIN)
    pl_colloid_nlist_count_loop(nl, cells, box, periodic, x, y, z);
}

void pl_colloid_nlist_fill_loop(pl_colloid_nlist_t *nl, const pl_colloid_cells_t *cells,
                                const double box[3], const int periodic[3], const double *x,
                                const double *y, const double *z)
{
    size_t n = nl->n;
    double rl2 = nl->rlist * nl->rlist;
#pragma omp for schedule(static)
    for (size_t i = 0; i < n; ++i) {
        scan_cells(cells, box, periodic, rl2, x, y, z, i, nl->nbr + nl->start[i]);
        nl->x0[i] = x[i];
        nl->y0[i] = y[i];
        nl->z0[i] = z[i];
    }
}

void pl_colloid_nlist_finish(pl_colloid_nlist_t *nl, int nthreads) { reverse_entries(nl, nthreads); }

void pl_colloid_nlist_fill(pl_colloid_nlist_t *nl, const pl_colloid_cells_t *cells,
                           const double box[3], const int periodic[3], const double *x,
                           const double *y, const double *z, int nthreads)
{
#pragma omp parallel num_threads(nthreads) if (nl->n >= PL_COLLOID_OMP_MIN)
    pl_colloid_nlist_fill_loop(nl, cells, box, periodic, x, y, z);
    reverse_entries(nl, nthreads);
}

/* The near list of multiple time stepping: the pairs of the full list
 * (same owners, same ascending order) that may feel a fast force before the
 * next build, i.e. closer than fast_cut + skin (the full list's skin, so the
 * full list's displacement check keeps both valid). */
static double fast_cut(const pl_colloid_pair_params_t *p, double d)
{
    /* every term's cut-off but DLVO's, whose fast share ends at mts_hout */
    return pl_colloid_pair_rc_from(p, p->terms & ~(unsigned)PL_CT_DLVO, d, d + p->mts_hout);
}

static size_t near_scan(pl_colloid_nlist_t *near, const pl_colloid_nlist_t *full,
                        const pl_colloid_pair_params_t *p, const double *x, const double *y,
                        const double *z, const double *rad, size_t i, int fill)
{
    size_t m = 0;
    for (int32_t s = full->start[i]; s < full->start[i + 1]; ++s) {
        size_t j = (size_t)full->nbr[s];
        double dx = pl_min_image(x[i] - x[j], p->box[0], p->periodic[0]);
        double dy = pl_min_image(y[i] - y[j], p->box[1], p->periodic[1]);
        double dz = pl_min_image(z[i] - z[j], p->box[2], p->periodic[2]);
        double rl = fast_cut(p, rad[i] + rad[j]) + full->skin;
        if (dx * dx + dy * dy + dz * dz >= rl * rl) continue;
        if (fill) near->nbr[near->start[i] + (int32_t)m] = (int32_t)j;
        ++m;
    }
    return m;
}

void pl_colloid_nlist_near_count_loop(pl_colloid_nlist_t *near, const pl_colloid_nlist_t *full,
                                      const pl_colloid_pair_params_t *p, const double *x,
                                      const double *y, const double *z, const double *rad)
{
    size_t n = full->n;
#pragma omp for schedule(static)
    for (size_t i = 0; i < n; ++i) {
        if (i == 0) near->start[0] = 0; /* by one thread */
        near->start[i + 1] = (int32_t)near_scan(near, full, p, x, y, z, rad, i, 0);
    }
}

void pl_colloid_nlist_near_count(pl_colloid_nlist_t *near, const pl_colloid_nlist_t *full,
                                 const pl_colloid_pair_params_t *p, const double *x,
                                 const double *y, const double *z, const double *rad, int nthreads)
{
#pragma omp parallel num_threads(nthreads) if (full->n >= PL_COLLOID_OMP_MIN)
    pl_colloid_nlist_near_count_loop(near, full, p, x, y, z, rad);
}

void pl_colloid_nlist_near_fill_loop(pl_colloid_nlist_t *near, const pl_colloid_nlist_t *full,
                                     const pl_colloid_pair_params_t *p, const double *x,
                                     const double *y, const double *z, const double *rad)
{
    size_t n = full->n;
#pragma omp for schedule(static)
    for (size_t i = 0; i < n; ++i) near_scan(near, full, p, x, y, z, rad, i, 1);
}

void pl_colloid_nlist_near_fill(pl_colloid_nlist_t *near, const pl_colloid_nlist_t *full,
                                const pl_colloid_pair_params_t *p, const double *x,
                                const double *y, const double *z, const double *rad, int nthreads)
{
#pragma omp parallel num_threads(nthreads) if (full->n >= PL_COLLOID_OMP_MIN)
    pl_colloid_nlist_near_fill_loop(near, full, p, x, y, z, rad);
    near->skin = full->skin;
    reverse_entries(near, nthreads);
}
