/* g(r) accumulator: geometry checks, the ideal-gas normalisation of each
 * sample and the per-bin blocking (equations in include/peloid/rdf.h; the
 * pair count is kernels/rdf_count.c). */
#include "peloid/real.h" /* PL_PI */
#include "peloid/rdf.h"

#include <math.h>
#include <stdlib.h>

#include "peloid/blocking.h"


struct pl_rdf {
    pl_rdf_params_t par;
    int nthreads;
    double *pb;          /* nbins: ideal-gas probability of each bin */
    uint64_t *hist;      /* nbins: this sample */
    uint64_t *total;     /* nbins + 1: all samples, then the sample count */
    uint64_t *scratch;   /* nthreads x nbins */
    pl_blocking_t *blk;  /* nbins */
};

/* G(r) = int_0^r 4 pi s^2 F(s) ds for the slab of thickness h. */
static double slab_G(double r, double h)
{
    if (r <= h) return 4.0 * PL_PI * (r * r * r / 3.0 - r * r * r * r / (8.0 * h));
    return 5.0 * PL_PI * h * h * h / 6.0 + PL_PI * h * (r * r - h * h);
}

double pl_rdf_ideal_fraction(const pl_rdf_params_t *par, double r1, double r2)
{
    const double Lx = par->box[0], Ly = par->box[1];
    if (!par->z_walls) return 4.0 * PL_PI / 3.0 * (r2 * r2 * r2 - r1 * r1 * r1) / (Lx * Ly * par->box[2]);
    double h = par->zhi - par->zlo;
    return (slab_G(r2, h) - slab_G(r1, h)) / (Lx * Ly * h);
}

int pl_rdf_create(const pl_rdf_params_t *par, int nthreads, pl_rdf_t **out, pl_err_t *err)
{
    *out = NULL;
    if (par->nbins < 1) return pl_err_set(err, PL_ERR_INPUT, "rdf: nbins = 0");
    if (!(par->rmax > 0.0)) return pl_err_set(err, PL_ERR_INPUT, "rdf: rmax = %g, need > 0", par->rmax);
    for (int d = 0; d < 3; ++d) {
        if (!(par->box[d] > 0.0))
            return pl_err_set(err, PL_ERR_INPUT, "rdf: box[%d] = %g, need > 0", d, par->box[d]);
        if ((d < 2 || !par->z_walls) && par->rmax > 0.5 * par->box[d])
            return pl_err_set(err, PL_ERR_INPUT,
                              "rdf: rmax = %g exceeds half the periodic box length %g (axis %d)",
                              par->rmax, par->box[d], d);
    }
    if ((par->class_a < 0) != (par->class_b < 0))
        return pl_err_set(err, PL_ERR_INPUT, "rdf: classes (%d, %d): both -1 or both >= 0",
                          par->class_a, par->class_b);
    if (par->z_walls && !(par->zhi > par->zlo))
        return pl_err_set(err, PL_ERR_INPUT, "rdf: slab [%g, %g] is empty", par->zlo, par->zhi);
    if (nthreads < 1) nthreads = 1;
    pl_rdf_t *r = calloc(1, sizeof *r);
    if (!r) return pl_err_set(err, PL_ERR_NOMEM, "rdf: out of memory");
    r->par = *par;
    r->nthreads = nthreads;
    size_t nb = par->nbins;
    r->pb = malloc(nb * sizeof *r->pb);
    r->hist = calloc(nb, sizeof *r->hist);
    r->total = calloc(nb + 1, sizeof *r->total);
    r->scratch = calloc(nb * (size_t)nthreads, sizeof *r->scratch);
    r->blk = calloc(nb, sizeof *r->blk);
    if (!r->pb || !r->hist || !r->total || !r->scratch || !r->blk) {
        pl_rdf_free(r);
        return pl_err_set(err, PL_ERR_NOMEM, "rdf: out of memory for %zu bins", nb);
    }
    double dr = par->rmax / (double)nb;
    for (size_t b = 0; b < nb; ++b)
        r->pb[b] = pl_rdf_ideal_fraction(par, dr * (double)b, dr * (double)(b + 1));
    *out = r;
    return PL_OK;
}

void pl_rdf_free(pl_rdf_t *r)
{
    if (!r) return;
    free(r->pb);
    free(r->hist);
    free(r->total);
    free(r->scratch);
    free(r->blk);
    free(r);
}

void pl_rdf_sample(pl_rdf_t *r, size_t n, const double *x, const double *y, const double *z,
                   const int32_t *cls)
{
    const size_t nb = r->par.nbins;
    const int ca = r->par.class_a, cb = r->par.class_b, classes = ca >= 0;
    double npairs = 0.5 * (double)n * ((double)n - 1.0);
    if (classes) {
        size_t na = 0, nbb = 0;
        for (size_t i = 0; i < n; ++i) {
            na += cls[i] == ca;
            nbb += cls[i] == cb;
        }
        npairs = ca == cb ? 0.5 * (double)na * ((double)na - 1.0) : (double)na * (double)nbb;
    }
    if (!(npairs > 0.0)) return;
    pl_rdf_geom_t g = {.box = {r->par.box[0], r->par.box[1], r->par.box[2]},
                       .periodic_z = !r->par.z_walls, .rmax = r->par.rmax, .nbins = nb,
                       .cls = classes ? cls : NULL, .ca = ca, .cb = cb};
    for (size_t b = 0; b < nb; ++b) r->hist[b] = 0;
    pl_rdf_count(&g, n, x, y, z, r->hist, r->scratch, r->nthreads);
    for (size_t b = 0; b < nb; ++b) {
        r->total[b] += r->hist[b];
        pl_blocking_add(&r->blk[b], (double)r->hist[b] / (npairs * r->pb[b]));
    }
    r->total[nb]++;
}

void pl_rdf_result(const pl_rdf_t *r, double *rmid, double *g, double *se, int *plateau)
{
    double dr = r->par.rmax / (double)r->par.nbins;
    for (size_t b = 0; b < r->par.nbins; ++b) {
        pl_blocking_result_t res = pl_blocking_result(&r->blk[b]);
        if (rmid) rmid[b] = dr * ((double)b + 0.5);
        if (g) g[b] = res.mean;
        if (se) se[b] = res.se;
        if (plateau) plateau[b] = res.plateau;
    }
}

const uint64_t *pl_rdf_counts(const pl_rdf_t *r)
{
    return r->total;
}

pl_rdf_state_t pl_rdf_state(pl_rdf_t *r)
{
    return (pl_rdf_state_t){.counts = r->total, .ncounts = r->par.nbins + 1, .blocking = r->blk,
                            .nblocking = r->par.nbins};
}

uint64_t pl_rdf_samples(const pl_rdf_t *r)
{
    return r->total[r->par.nbins];
}
