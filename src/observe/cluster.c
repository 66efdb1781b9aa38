/* Clusters by union-find over linked cells (rules in include/peloid/cluster.h).
 *
 * The cells are the colloid linked cells (pl_colloid_cells_dims/build) with
 * edge >= 2 a_max + gap; a periodic axis with fewer than three cells has one,
 * and its pairs then rely on the minimum image, which create guarantees by
 * refusing 2 a_max + gap > L/2 there. */
#include "peloid/cluster.h"

#include <math.h>
#include <stdlib.h>

#include "peloid/colloid_kernels.h"

struct pl_cluster {
    pl_cluster_params_t par;
    double rc;
    pl_colloid_cells_t cells;
    double *w[3];    /* nmax: positions wrapped into [0, L) on periodic axes */
    int32_t *parent; /* nmax */
    int32_t *id;     /* nmax */
    uint64_t *hist;  /* nmax + 1 */
    size_t n, count, largest;
    size_t bonds[PL_CLUSTER_KINDS + 1];
};

int pl_cluster_create(const pl_cluster_params_t *par, pl_cluster_t **out, pl_err_t *err)
{
    *out = NULL;
    if (par->nmax < 1 || par->nmax > (size_t)INT32_MAX)
        return pl_err_set(err, PL_ERR_INPUT, "cluster: nmax = %zu, allowed 1..%d", par->nmax, INT32_MAX);
    if (!(par->rad_max >= 0.0)) return pl_err_set(err, PL_ERR_INPUT, "cluster: rad_max = %g", par->rad_max);
    double rc = 2.0 * par->rad_max + par->gap;
    if (!(rc > 0.0))
        return pl_err_set(err, PL_ERR_INPUT, "cluster: 2 rad_max + gap = %g, need > 0", rc);
    for (int d = 0; d < 3; ++d) {
        if (!(par->box[d] > 0.0))
            return pl_err_set(err, PL_ERR_INPUT, "cluster: box[%d] = %g, need > 0", d, par->box[d]);
        if (par->periodic[d] && rc > 0.5 * par->box[d])
            return pl_err_set(err, PL_ERR_INPUT,
                              "cluster: bond range 2 rad_max + gap = %g exceeds half the periodic box "
                              "length %g (axis %d)",
                              rc, par->box[d], d);
    }
    pl_cluster_t *c = calloc(1, sizeof *c);
    if (!c) return pl_err_set(err, PL_ERR_NOMEM, "cluster: out of memory");
    c->par = *par;
    c->rc = rc;
    pl_colloid_cells_dims(par->box, par->periodic, rc, c->cells.nc);
    c->cells.ncells = (size_t)c->cells.nc[0] * (size_t)c->cells.nc[1] * (size_t)c->cells.nc[2];
    for (int d = 0; d < 3; ++d) c->cells.inv_cl[d] = (double)c->cells.nc[d] / par->box[d];
    size_t n = par->nmax;
    c->cells.start = malloc((c->cells.ncells + 1) * sizeof(int32_t));
    c->cells.list = malloc(n * sizeof(int32_t));
    c->cells.cell = malloc(n * sizeof(int32_t));
    for (int d = 0; d < 3; ++d) c->w[d] = malloc(n * sizeof(double));
    c->parent = malloc(n * sizeof(int32_t));
    c->id = malloc(n * sizeof(int32_t));
    c->hist = calloc(n + 1, sizeof(uint64_t));
    if (!c->cells.start || !c->cells.list || !c->cells.cell || !c->w[0] || !c->w[1] || !c->w[2] ||
        !c->parent || !c->id || !c->hist) {
        pl_cluster_free(c);
        return pl_err_set(err, PL_ERR_NOMEM, "cluster: out of memory for %zu particles", n);
    }
    *out = c;
    return PL_OK;
}

void pl_cluster_free(pl_cluster_t *c)
{
    if (!c) return;
    free(c->cells.start);
    free(c->cells.list);
    free(c->cells.cell);
    for (int d = 0; d < 3; ++d) free(c->w[d]);
    free(c->parent);
    free(c->id);
    free(c->hist);
    free(c);
}

static int32_t find_root(int32_t *parent, int32_t i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]]; /* path halving */
        i = parent[i];
    }
    return i;
}

/* The smaller root becomes the parent: every root is its tree's minimum. */
static void unite(int32_t *parent, int32_t i, int32_t j)
{
    int32_t a = find_root(parent, i), b = find_root(parent, j);
    if (a == b) return;
    if (a < b) parent[b] = a;
    else parent[a] = b;
}


int pl_cluster_find(pl_cluster_t *c, size_t n, const double *x, const double *y, const double *z,
                    const double *rad, pl_err_t *err)
{
    const pl_cluster_params_t *par = &c->par;
    if (n > par->nmax)
        return pl_err_set(err, PL_ERR_INPUT, "cluster: %zu particles, capacity %zu", n, par->nmax);
    for (size_t i = 0; i < n; ++i)
        if (!(rad[i] <= par->rad_max))
            return pl_err_set(err, PL_ERR_INPUT, "cluster: radius %g of particle %zu exceeds rad_max %g",
                              rad[i], i, par->rad_max);
    const double *in[3] = {x, y, z};
    for (int d = 0; d < 3; ++d) {
        double L = par->box[d];
        for (size_t i = 0; i < n; ++i) {
            double u = in[d][i];
            if (par->periodic[d]) {
                u -= L * floor(u / L);
                if (u >= L) u = 0.0; /* -tiny + L rounds to L */
            }
            c->w[d][i] = u;
        }
    }
    x = c->w[0];
    y = c->w[1];
    z = c->w[2];
    pl_colloid_cells_t *cl = &c->cells;
    pl_colloid_cells_build(cl, n, x, y, z);
    for (size_t i = 0; i < n; ++i) c->parent[i] = (int32_t)i;
    for (int k = 0; k <= PL_CLUSTER_KINDS; ++k) c->bonds[k] = 0;
    const int *nc = cl->nc;
    for (int cz = 0; cz < nc[2]; ++cz)
        for (int cy = 0; cy < nc[1]; ++cy)
            for (int cx = 0; cx < nc[0]; ++cx) {
                int32_t home = (cz * nc[1] + cy) * nc[0] + cx;
                if (cl->start[home] == cl->start[home + 1]) continue; /* most cells of a dilute suspension */
                /* the distinct neighbour cells: one offset on a one-cell axis,
                 * wrapped on a periodic one, clipped at walls */
                int lo[3], hi[3], cc[3] = {cx, cy, cz};
                for (int d = 0; d < 3; ++d) {
                    lo[d] = nc[d] == 1 ? 0 : -1;
                    hi[d] = nc[d] == 1 ? 0 : 1;
                    if (!par->periodic[d]) {
                        if (cc[d] + lo[d] < 0) lo[d] = 0;
                        if (cc[d] + hi[d] >= nc[d]) hi[d] = 0;
                    }
                }
                for (int oz = lo[2]; oz <= hi[2]; ++oz)
                    for (int oy = lo[1]; oy <= hi[1]; ++oy)
                        for (int ox = lo[0]; ox <= hi[0]; ++ox) {
                            int nx = (cx + ox + nc[0]) % nc[0], ny = (cy + oy + nc[1]) % nc[1];
                            int nz = (cz + oz + nc[2]) % nc[2];
                            int32_t other = (nz * nc[1] + ny) * nc[0] + nx;
                            for (int32_t a = cl->start[home]; a < cl->start[home + 1]; ++a) {
                                int32_t i = cl->list[a];
                                for (int32_t b = cl->start[other]; b < cl->start[other + 1]; ++b) {
                                    int32_t j = cl->list[b];
                                    if (j <= i) continue;
                                    double dx = pl_min_image(x[j] - x[i], par->box[0], par->periodic[0]);
                                    double dy = pl_min_image(y[j] - y[i], par->box[1], par->periodic[1]);
                                    double dz = pl_min_image(z[j] - z[i], par->box[2], par->periodic[2]);
                                    double reach = rad[i] + rad[j] + par->gap;
                                    double r2 = dx * dx + dy * dy + dz * dz;
                                    if (!(reach > 0.0 && r2 < reach * reach)) continue;
                                    int kind = par->bond ? par->bond(par->bond_ctx, i, j, sqrt(r2)) : 1;
                                    if (kind < 1 || kind > PL_CLUSTER_KINDS) continue;
                                    c->bonds[kind]++;
                                    unite(c->parent, i, j);
                                }
                            }
                        }
            }
    for (size_t s = 0; s <= n; ++s) c->hist[s] = 0;
    /* sizes counted at the roots, kept in id[] until the labels overwrite it */
    for (size_t i = 0; i < n; ++i) c->id[i] = 0;
    for (size_t i = 0; i < n; ++i) c->id[find_root(c->parent, (int32_t)i)]++;
    c->count = 0;
    c->largest = 0;
    for (size_t i = 0; i < n; ++i)
        if (c->parent[i] == (int32_t)i) {
            size_t s = (size_t)c->id[i];
            c->hist[s]++;
            c->count++;
            if (s > c->largest) c->largest = s;
        }
    for (size_t i = 0; i < n; ++i) c->id[i] = find_root(c->parent, (int32_t)i);
    c->n = n;
    return PL_OK;
}

const int32_t *pl_cluster_ids(const pl_cluster_t *c)
{
    return c->id;
}

size_t pl_cluster_count(const pl_cluster_t *c)
{
    return c->count;
}

size_t pl_cluster_largest(const pl_cluster_t *c)
{
    return c->largest;
}

double pl_cluster_mean_size(const pl_cluster_t *c)
{
    return c->count ? (double)c->n / (double)c->count : NAN;
}

double pl_cluster_weight_mean_size(const pl_cluster_t *c)
{
    if (!c->n) return NAN;
    double s2 = 0.0;
    for (size_t s = 1; s <= c->n; ++s) s2 += (double)s * (double)s * (double)c->hist[s];
    return s2 / (double)c->n;
}

size_t pl_cluster_bonds(const pl_cluster_t *c, int kind)
{
    return kind >= 1 && kind <= PL_CLUSTER_KINDS ? c->bonds[kind] : 0;
}

const uint64_t *pl_cluster_size_hist(const pl_cluster_t *c, size_t *len)
{
    if (len) *len = c->n + 1;
    return c->hist;
}
