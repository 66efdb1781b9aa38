/* S(q) by the direct sum over the box's wave vectors (rules in include/peloid/sq.h). */
#include "peloid/sq.h"

#include <math.h>
#include <stdlib.h>

#include "peloid/real.h" /* PL_PI */

struct pl_sq {
    pl_sq_params_t par;
    int nthreads;
    int nm[3];          /* largest |n| per axis */
    size_t nvec;
    int32_t *vec;       /* 3 x nvec: n of each kept vector */
    int32_t *bin;       /* nvec */
    double *qsum;       /* nbins: sum of |q| over the bin's vectors */
    uint64_t *count;    /* nbins: vectors per bin */
    double *tab;        /* 3 axes x nmax x (2 nm + 1) x (cos, sin) */
    double *sv;         /* nvec: S of each vector in this sample */
    double *acc;        /* nbins: this sample's bin sums */
    pl_blocking_t *blk; /* nbins */
    uint64_t samples;
};

int pl_sq_create(const pl_sq_params_t *par, int nthreads, pl_sq_t **out, pl_err_t *err)
{
    *out = NULL;
    if (!(par->qmax > 0.0) || par->nbins < 1 || par->nmax < 1)
        return pl_err_set(err, PL_ERR_INPUT, "sq: qmax %g, nbins %zu, nmax %zu: need > 0", par->qmax, par->nbins,
                          par->nmax);
    pl_sq_t *s = calloc(1, sizeof *s);
    if (!s) return pl_err_set(err, PL_ERR_NOMEM, "sq: out of memory");
    s->par = *par;
    s->nthreads = nthreads > 0 ? nthreads : 1;
    double dq[3];
    for (int d = 0; d < 3; ++d) {
        dq[d] = 2.0 * PL_PI / par->box[d];
        s->nm[d] = (int)floor(par->qmax / dq[d]);
    }
    /* count, then fill, the kept half of the vectors inside qmax */
    const double dqb = par->qmax / (double)par->nbins;
    for (int pass = 0; pass < 2; ++pass) {
        size_t k = 0;
        for (int a = -s->nm[0]; a <= s->nm[0]; ++a)
            for (int b = -s->nm[1]; b <= s->nm[1]; ++b)
                for (int c = -s->nm[2]; c <= s->nm[2]; ++c) {
                    int keep = a > 0 || (a == 0 && (b > 0 || (b == 0 && c > 0)));
                    if (!keep) continue;
                    double qx = a * dq[0], qy = b * dq[1], qz = c * dq[2];
                    double q = sqrt(qx * qx + qy * qy + qz * qz);
                    if (!(q < par->qmax)) continue;
                    if (pass) {
                        s->vec[3 * k] = a, s->vec[3 * k + 1] = b, s->vec[3 * k + 2] = c;
                        size_t bb = (size_t)(q / dqb);
                        if (bb >= par->nbins) bb = par->nbins - 1;
                        s->bin[k] = (int32_t)bb;
                        s->qsum[bb] += q;
                        s->count[bb]++;
                    }
                    ++k;
                }
        if (!pass) {
            s->nvec = k;
            size_t w = 0;
            for (int d = 0; d < 3; ++d) w += (size_t)(2 * s->nm[d] + 1);
            s->vec = malloc((3 * k + 1) * sizeof *s->vec);
            s->bin = malloc((k + 1) * sizeof *s->bin);
            s->sv = malloc((k + 1) * sizeof *s->sv);
            s->qsum = calloc(par->nbins, sizeof *s->qsum);
            s->count = calloc(par->nbins, sizeof *s->count);
            s->acc = calloc(par->nbins, sizeof *s->acc);
            s->blk = calloc(par->nbins, sizeof *s->blk);
            s->tab = malloc(2 * w * par->nmax * sizeof *s->tab);
            if (!s->vec || !s->bin || !s->sv || !s->qsum || !s->count || !s->acc || !s->blk || !s->tab) {
                pl_sq_free(s);
                return pl_err_set(err, PL_ERR_NOMEM, "sq: out of memory for %zu wave vectors", k);
            }
        }
    }
    *out = s;
    return PL_OK;
}

void pl_sq_free(pl_sq_t *s)
{
    if (!s) return;
    free(s->vec);
    free(s->bin);
    free(s->sv);
    free(s->qsum);
    free(s->count);
    free(s->acc);
    free(s->blk);
    free(s->tab);
    free(s);
}

void pl_sq_sample(pl_sq_t *s, size_t n, const double *x, const double *y, const double *z)
{
    if (n > s->par.nmax) n = s->par.nmax;
    if (n == 0) return;
    const pl_sq_modes_params_t p = {.box = {s->par.box[0], s->par.box[1], s->par.box[2]},
                                    .nm = {s->nm[0], s->nm[1], s->nm[2]}, .nvec = s->nvec, .vec = s->vec};
    pl_sq_modes(&p, n, x, y, z, s->tab, s->sv, s->nthreads);
    const size_t nb = s->par.nbins;
    for (size_t b = 0; b < nb; ++b) s->acc[b] = 0.0;
    for (size_t k = 0; k < s->nvec; ++k) s->acc[s->bin[k]] += s->sv[k]; /* fixed order */
    for (size_t b = 0; b < nb; ++b)
        if (s->count[b]) pl_blocking_add(&s->blk[b], s->acc[b] / (double)s->count[b]);
    s->samples++;
}

void pl_sq_result(const pl_sq_t *s, double *qmid, double *qmean, double *S, double *se, uint64_t *nvec)
{
    const double dqb = s->par.qmax / (double)s->par.nbins;
    for (size_t b = 0; b < s->par.nbins; ++b) {
        pl_blocking_result_t r = pl_blocking_result(&s->blk[b]);
        const int any = s->count[b] > 0;
        if (qmid) qmid[b] = dqb * ((double)b + 0.5);
        if (qmean) qmean[b] = any ? s->qsum[b] / (double)s->count[b] : NAN;
        if (S) S[b] = any ? r.mean : NAN;
        if (se) se[b] = any ? r.se : NAN;
        if (nvec) nvec[b] = s->count[b];
    }
}

pl_sq_state_t pl_sq_state(pl_sq_t *s)
{
    return (pl_sq_state_t){.blocking = s->blk, .nblocking = s->par.nbins, .samples = &s->samples};
}

uint64_t pl_sq_samples(const pl_sq_t *s)
{
    return s->samples;
}

size_t pl_sq_vectors(const pl_sq_t *s)
{
    return s->nvec;
}
