/* Multiple-tau correlator: the owning object, the schedule of the levels and
 * the results (rules and sources in include/peloid/mtau.h; the per-particle
 * update is kernels/mtau_push.c).
 *
 * Level l receives a sample when (average) the m^l samples of one of its
 * values are complete, (t + 1) mod m^l = 0, or (every m-th) when the sample
 * is the first of such a block, t mod m^l = 0.  Either way the receiving
 * levels are 0..nrecv-1, and lag slot j of level l has had one origin more
 * whenever that level received a value with at least j before it. */
#include "peloid/mtau.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct pl_mtau {
    pl_mtau_params_t par;
    size_t stride;
    double *state;   /* n x stride, see kernels/mtau_push.c */
    /* the counters, one allocation so that a checkpoint sees one array:
     * count[levels x p] (origins of each lag slot), nrecv[levels] (values
     * each level has received), nsamp[1] (samples added) */
    uint64_t *ctr;
    size_t nctr;
    uint64_t *count, *nrecv, *nsamp;
};

int pl_mtau_levels_for(uint64_t nsamples, int p, int m)
{
    int s = 1;
    double maxlag = (double)(p - 1);
    while (maxlag < (double)nsamples - 1.0 && s < PL_MTAU_MAX_LEVELS) {
        maxlag *= (double)m;
        s++;
    }
    return s;
}

int pl_mtau_create(const pl_mtau_params_t *par, pl_mtau_t **out, pl_err_t *err)
{
    *out = NULL;
    if (par->n < 1) return pl_err_set(err, PL_ERR_INPUT, "mtau: no particles");
    if (par->m < 2 || par->p < 2 || par->p % par->m)
        return pl_err_set(err, PL_ERR_INPUT,
                          "mtau: p = %d, m = %d; need m >= 2 and p a multiple of m", par->p, par->m);
    if (par->levels < 1 || par->levels > PL_MTAU_MAX_LEVELS)
        return pl_err_set(err, PL_ERR_INPUT, "mtau: levels = %d, allowed 1..%d", par->levels,
                          PL_MTAU_MAX_LEVELS);
    if (par->kind != PL_MTAU_AUTO && par->kind != PL_MTAU_MSD)
        return pl_err_set(err, PL_ERR_INPUT, "mtau: unknown kind %d", (int)par->kind);
    if (!(par->dt > 0.0)) return pl_err_set(err, PL_ERR_INPUT, "mtau: dt = %g, need > 0", par->dt);
    size_t stride = (size_t)par->levels * (6 * (size_t)par->p + 3);
    if (stride > (size_t)INT32_MAX || par->n > SIZE_MAX / sizeof(double) / stride)
        return pl_err_set(err, PL_ERR_INPUT, "mtau: %zu particles x %zu values is too large", par->n,
                          stride);
    pl_mtau_t *c = calloc(1, sizeof *c);
    if (!c) return pl_err_set(err, PL_ERR_NOMEM, "mtau: out of memory");
    c->par = *par;
    c->stride = stride;
    c->state = calloc(par->n * stride, sizeof(double));
    size_t nslot = (size_t)par->levels * (size_t)par->p;
    c->nctr = nslot + (size_t)par->levels + 1;
    c->ctr = calloc(c->nctr, sizeof(uint64_t));
    if (!c->state || !c->ctr) {
        pl_mtau_free(c);
        return pl_err_set(err, PL_ERR_NOMEM, "mtau: out of memory for %zu x %zu values", par->n,
                          stride);
    }
    c->count = c->ctr;
    c->nrecv = c->ctr + nslot;
    c->nsamp = c->nrecv + par->levels;
    *out = c;
    return PL_OK;
}

void pl_mtau_free(pl_mtau_t *c)
{
    if (!c) return;
    free(c->state);
    free(c->ctr);
    free(c);
}

void pl_mtau_add(pl_mtau_t *c, const double *x, const double *y, const double *z, int nthreads)
{
    const pl_mtau_params_t *par = &c->par;
    const uint64_t t = *c->nsamp, m = (uint64_t)par->m;
    int nr = 1;
    if (!par->average && t == 0) {
        nr = par->levels;
    } else {
        uint64_t w = 1, key = par->average ? t + 1 : t;
        while (nr < par->levels && w <= key / m) {
            w *= m;
            if (key % w) break;
            nr++;
        }
    }
    pl_mtau_push_t pp = {.nrecv = nr, .p = par->p, .m = par->m, .levels = par->levels,
                         .average = par->average, .kind = (int)par->kind,
                         .stride = (int)c->stride};
    for (int l = 0; l < nr; ++l) {
        pp.head[l] = (int)(c->nrecv[l] % (uint64_t)par->p);
        pp.jmin[l] = l ? par->p / par->m : 0;
        pp.jmax[l] = c->nrecv[l] < (uint64_t)(par->p - 1) ? (int)c->nrecv[l] : par->p - 1;
    }
    pl_mtau_push(&pp, par->n, x, y, z, c->state, nthreads);
    for (int l = 0; l < nr; ++l) {
        for (int j = pp.jmin[l]; j <= pp.jmax[l]; ++j) c->count[(size_t)l * (size_t)par->p + (size_t)j]++;
        c->nrecv[l]++;
    }
    (*c->nsamp)++;
}

pl_mtau_state_t pl_mtau_state(pl_mtau_t *c)
{
    return (pl_mtau_state_t){.values = c->state, .nvalues = c->par.n * c->stride,
                             .counters = c->ctr, .ncounters = c->nctr};
}

int pl_mtau_levels(const pl_mtau_t *c) { return c->par.levels; }

int pl_mtau_grow(const pl_mtau_t *c, int levels, pl_mtau_t **out, pl_err_t *err)
{
    *out = NULL;
    const int L = c->par.levels, p = c->par.p, m = c->par.m;
    if (levels < L) return pl_err_set(err, PL_ERR_INPUT, "mtau grow: %d levels < %d", levels, L);
    if (c->par.average && levels > L)
        return pl_err_set(err, PL_ERR_INPUT, "mtau grow: the averaging rule cannot add levels");
    if (levels > L && c->nrecv[L - 1] > (uint64_t)p)
        return pl_err_set(err, PL_ERR_INPUT,
                          "mtau grow: the top level received %llu values, more than its %d slots",
                          (unsigned long long)c->nrecv[L - 1], p);
    pl_mtau_params_t par = c->par;
    par.levels = levels;
    pl_mtau_t *g;
    int rc = pl_mtau_create(&par, &g, err);
    if (rc) return rc;
    const size_t lstride = 6 * (size_t)p + 3, n = c->par.n;
    for (size_t i = 0; i < n; ++i)
        memcpy(g->state + i * g->stride, c->state + i * c->stride, c->stride * sizeof(double));
    memcpy(g->count, c->count, (size_t)L * (size_t)p * sizeof(uint64_t));
    memcpy(g->nrecv, c->nrecv, (size_t)L * sizeof(uint64_t));
    *g->nsamp = *c->nsamp;
    /* level l >= L: the values of level L-1 at receive indices k m^(l-L+1),
     * pushed in order exactly as pl_mtau_push does (every-m-th rule) */
    const uint64_t top = c->nrecv[L - 1];
    uint64_t w = 1;
    for (int l = L; l < levels; ++l) {
        w *= (uint64_t)m;
        uint64_t nr = 0;
        const int jmin = p / m;
        for (uint64_t r = 0; r < top; r += w) {
            const int h = (int)(nr % (uint64_t)p);
            const int jmax = nr < (uint64_t)(p - 1) ? (int)nr : p - 1;
            for (size_t i = 0; i < n; ++i) {
                const double *src = c->state + i * c->stride + (size_t)(L - 1) * lstride + 6 * (size_t)r;
                double *b = g->state + i * g->stride + (size_t)l * lstride;
                double v[3] = {src[0], src[1], src[2]};
                for (int d = 0; d < 3; ++d) b[6 * h + d] = v[d];
                for (int j = jmin; j <= jmax; ++j) {
                    int k = h - j < 0 ? h - j + p : h - j;
                    for (int d = 0; d < 3; ++d) {
                        if (c->par.kind == PL_MTAU_MSD) {
                            double u = v[d] - b[6 * k + d];
                            b[6 * j + 3 + d] += u * u;
                        } else {
                            b[6 * j + 3 + d] += v[d] * b[6 * k + d];
                        }
                    }
                }
            }
            for (int j = jmin; j <= jmax; ++j) g->count[(size_t)l * (size_t)p + (size_t)j]++;
            g->nrecv[l] = ++nr;
        }
    }
    *out = g;
    return PL_OK;
}

uint64_t pl_mtau_samples(const pl_mtau_t *c)
{
    return *c->nsamp;
}

size_t pl_mtau_nlags(const pl_mtau_t *c)
{
    size_t p = (size_t)c->par.p;
    return p + (size_t)(c->par.levels - 1) * (p - p / (size_t)c->par.m);
}

/* Lag slot k -> (level, index j). */
static void slot_of(const pl_mtau_t *c, size_t k, int *l, int *j)
{
    size_t p = (size_t)c->par.p, per = p - p / (size_t)c->par.m;
    if (k < p) {
        *l = 0;
        *j = (int)k;
    } else {
        *l = 1 + (int)((k - p) / per);
        *j = (int)(p / (size_t)c->par.m + (k - p) % per);
    }
}

/* Time average of column col of particle i at slot (l, j). */
static double particle_value(const pl_mtau_t *c, size_t i, int l, int j, int col, double cnt)
{
    const double *a = c->state + i * c->stride + (size_t)l * (6 * (size_t)c->par.p + 3) +
                      6 * (size_t)j + 3;
    double s = col < 3 ? a[col] : a[0] + a[1] + a[2];
    return s / cnt;
}

void pl_mtau_result(const pl_mtau_t *c, double *lag, uint64_t *origins, double *value, double *se)
{
    const size_t n = c->par.n, nl = pl_mtau_nlags(c);
    for (size_t k = 0; k < nl; ++k) {
        int l, j;
        slot_of(c, k, &l, &j);
        uint64_t cnt = c->count[(size_t)l * (size_t)c->par.p + (size_t)j];
        if (lag) lag[k] = (double)j * pow((double)c->par.m, (double)l) * c->par.dt;
        if (origins) origins[k] = cnt;
        for (int col = 0; col < PL_MTAU_COLS; ++col) {
            double mean = NAN, err = NAN;
            if (cnt) {
                double s = 0.0;
                for (size_t i = 0; i < n; ++i) s += particle_value(c, i, l, j, col, (double)cnt);
                mean = s / (double)n;
                if (n > 1) {
                    double s2 = 0.0;
                    for (size_t i = 0; i < n; ++i) {
                        double u = particle_value(c, i, l, j, col, (double)cnt) - mean;
                        s2 += u * u;
                    }
                    err = sqrt(s2 / (double)(n - 1) / (double)n);
                }
            }
            if (value) value[PL_MTAU_COLS * k + (size_t)col] = mean;
            if (se) se[PL_MTAU_COLS * k + (size_t)col] = err;
        }
    }
}

int pl_mtau_slope(const pl_mtau_t *c, double tmin, double tmax, double slope[PL_MTAU_COLS],
                  double se[PL_MTAU_COLS], pl_err_t *err)
{
    const size_t n = c->par.n, nl = pl_mtau_nlags(c);
    double tbar = 0.0, stt = 0.0;
    size_t nk = 0;
    for (int pass = 0; pass < 2; ++pass) {
        for (size_t k = 0; k < nl; ++k) {
            int l, j;
            slot_of(c, k, &l, &j);
            double t = (double)j * pow((double)c->par.m, (double)l) * c->par.dt;
            if (t < tmin || t > tmax || !c->count[(size_t)l * (size_t)c->par.p + (size_t)j]) continue;
            if (pass == 0) {
                tbar += t;
                nk++;
            } else {
                stt += (t - tbar) * (t - tbar);
            }
        }
        if (pass == 0 && nk) tbar /= (double)nk;
    }
    if (nk < 2 || !(stt > 0.0))
        return pl_err_set(err, PL_ERR_INPUT, "mtau slope: %zu lags with data in [%g, %g], need 2",
                          nk, tmin, tmax);
    for (int col = 0; col < PL_MTAU_COLS; ++col) {
        double s = 0.0, s2 = 0.0;
        for (int pass = 0; pass < 2; ++pass) {
            double mean = s / (double)n;
            for (size_t i = 0; i < n; ++i) {
                double num = 0.0;
                for (size_t k = 0; k < nl; ++k) {
                    int l, j;
                    slot_of(c, k, &l, &j);
                    double t = (double)j * pow((double)c->par.m, (double)l) * c->par.dt;
                    uint64_t cnt = c->count[(size_t)l * (size_t)c->par.p + (size_t)j];
                    if (t < tmin || t > tmax || !cnt) continue;
                    num += (t - tbar) * particle_value(c, i, l, j, col, (double)cnt);
                }
                double b = num / stt;
                if (pass == 0) s += b;
                else s2 += (b - mean) * (b - mean);
            }
        }
        slope[col] = s / (double)n;
        se[col] = n > 1 ? sqrt(s2 / (double)(n - 1) / (double)n) : NAN;
    }
    return PL_OK;
}

int pl_mtau_integral(const pl_mtau_t *c, double tmax, double integral[PL_MTAU_COLS],
                     double se[PL_MTAU_COLS], pl_err_t *err)
{
    const size_t n = c->par.n, nl = pl_mtau_nlags(c);
    size_t nk = 0;
    for (size_t k = 0; k < nl; ++k) {
        int l, j;
        slot_of(c, k, &l, &j);
        double t = (double)j * pow((double)c->par.m, (double)l) * c->par.dt;
        if (t <= tmax && c->count[(size_t)l * (size_t)c->par.p + (size_t)j]) nk++;
    }
    if (nk < 2)
        return pl_err_set(err, PL_ERR_INPUT, "mtau integral: %zu lags with data in [0, %g], need 2", nk,
                          tmax);
    for (int col = 0; col < PL_MTAU_COLS; ++col) {
        double s = 0.0, s2 = 0.0;
        for (int pass = 0; pass < 2; ++pass) {
            double mean = s / (double)n;
            for (size_t i = 0; i < n; ++i) {
                double q = 0.0, tprev = 0.0, cprev = 0.0;
                int have = 0;
                for (size_t k = 0; k < nl; ++k) {
                    int l, j;
                    slot_of(c, k, &l, &j);
                    double t = (double)j * pow((double)c->par.m, (double)l) * c->par.dt;
                    uint64_t cnt = c->count[(size_t)l * (size_t)c->par.p + (size_t)j];
                    if (t > tmax || !cnt) continue;
                    double v = particle_value(c, i, l, j, col, (double)cnt);
                    if (have) q += 0.5 * (v + cprev) * (t - tprev);
                    tprev = t;
                    cprev = v;
                    have = 1;
                }
                if (pass == 0) s += q;
                else s2 += (q - mean) * (q - mean);
            }
        }
        integral[col] = s / (double)n;
        se[col] = n > 1 ? sqrt(s2 / (double)(n - 1) / (double)n) : NAN;
    }
    return PL_OK;
}
