/* Velocity histograms and their chi^2 and KS tests against Maxwell-Boltzmann
 * (rules in include/peloid/vdist.h). */
#include "peloid/vdist.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>

struct pl_vdist {
    pl_vdist_params_t par;
    uint64_t *count; /* 4 x (nbins + 2): axes x, y, z, all */
};

int pl_vdist_create(const pl_vdist_params_t *par, pl_vdist_t **out, pl_err_t *err)
{
    *out = NULL;
    if (par->nbins < 1) return pl_err_set(err, PL_ERR_INPUT, "vdist: nbins = 0");
    if (!(par->vmax > 0.0)) return pl_err_set(err, PL_ERR_INPUT, "vdist: vmax = %g, need > 0", par->vmax);
    pl_vdist_t *h = calloc(1, sizeof *h);
    if (!h) return pl_err_set(err, PL_ERR_NOMEM, "vdist: out of memory");
    h->par = *par;
    h->count = calloc(4 * (par->nbins + 2), sizeof *h->count);
    if (!h->count) {
        free(h);
        return pl_err_set(err, PL_ERR_NOMEM, "vdist: out of memory for %zu bins", par->nbins);
    }
    *out = h;
    return PL_OK;
}

void pl_vdist_free(pl_vdist_t *h)
{
    if (!h) return;
    free(h->count);
    free(h);
}

static size_t bin_of(double v, double vmax, size_t nbins)
{
    if (v < -vmax) return 0;
    if (v >= vmax) return nbins + 1;
    size_t b = (size_t)((v + vmax) * ((double)nbins / (2.0 * vmax)));
    return 1 + (b < nbins ? b : nbins - 1);
}

void pl_vdist_sample(pl_vdist_t *h, size_t n, const double *vx, const double *vy, const double *vz)
{
    const size_t nb = h->par.nbins, stride = nb + 2;
    const double *v[3] = {vx, vy, vz};
    for (int d = 0; d < 3; ++d)
        for (size_t i = 0; i < n; ++i) {
            size_t b = bin_of(v[d][i], h->par.vmax, nb);
            h->count[(size_t)d * stride + b]++;
            h->count[3 * stride + b]++;
        }
}

const uint64_t *pl_vdist_counts(const pl_vdist_t *h, int axis)
{
    return h->count + (size_t)axis * (h->par.nbins + 2);
}

pl_vdist_state_t pl_vdist_state(pl_vdist_t *h)
{
    return (pl_vdist_state_t){.counts = h->count, .ncounts = 4 * (h->par.nbins + 2)};
}

int pl_vdist_chi2(const pl_vdist_t *h, int axis, double sigma, double *chi2, int *dof, double *p,
                  pl_err_t *err)
{
    if (axis < 0 || axis > 3) return pl_err_set(err, PL_ERR_INPUT, "vdist: axis %d, allowed 0..3", axis);
    const size_t nb = h->par.nbins;
    const uint64_t *c = pl_vdist_counts(h, axis);
    double ntot = 0.0;
    for (size_t b = 0; b < nb + 2; ++b) ntot += (double)c[b];
    const double vmax = h->par.vmax, w = 2.0 * vmax / (double)nb;
    /* Slots left to right (lower tail, bins, upper tail); a group closes once
     * its expectation reaches 5; a short remainder joins the last group. */
    double x2 = 0.0, eacc = 0.0, oacc = 0.0, elast = 0.0, olast = 0.0;
    int bins = 0;
    for (size_t b = 0; b < nb + 2; ++b) {
        double lo = b == 0 ? -INFINITY : -vmax + w * (double)(b - 1);
        double hi = b == nb + 1 ? INFINITY : -vmax + w * (double)b;
        eacc += ntot * (gsl_cdf_gaussian_P(hi, sigma) - gsl_cdf_gaussian_P(lo, sigma));
        oacc += (double)c[b];
        if (eacc >= 5.0) {
            if (bins) x2 += (olast - elast) * (olast - elast) / elast;
            elast = eacc;
            olast = oacc;
            eacc = oacc = 0.0;
            bins++;
        }
    }
    if (bins) {
        elast += eacc;
        olast += oacc;
        x2 += (olast - elast) * (olast - elast) / elast;
    }
    if (bins < 2) return pl_err_set(err, PL_ERR_INPUT, "vdist chi2: %d bins with expected counts >= 5", bins);
    *chi2 = x2;
    *dof = bins - 1;
    *p = gsl_cdf_chisq_Q(x2, (double)(bins - 1));
    return PL_OK;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Kolmogorov distribution, Q(lambda) = 2 sum_k (-1)^(k-1) exp(-2 k^2 lambda^2). */
static double kolmogorov_q(double lam)
{
    if (lam < 0.2) return 1.0;
    double s = 0.0, sign = 1.0;
    for (int k = 1; k <= 100; ++k) {
        double t = exp(-2.0 * k * k * lam * lam);
        s += sign * t;
        sign = -sign;
        if (t < 1e-16) break;
    }
    double q = 2.0 * s;
    return q < 0.0 ? 0.0 : (q > 1.0 ? 1.0 : q);
}

void pl_vdist_ks(double *v, size_t n, double sigma, double *D, double *p)
{
    qsort(v, n, sizeof *v, cmp_double);
    double d = 0.0, dn = (double)n;
    for (size_t i = 0; i < n; ++i) {
        double F = gsl_cdf_gaussian_P(v[i], sigma);
        double a = F - (double)i / dn, b = (double)(i + 1) / dn - F;
        if (a > d) d = a;
        if (b > d) d = b;
    }
    double sq = sqrt(dn);
    *D = d;
    *p = kolmogorov_q((sq + 0.12 + 0.11 / sq) * d);
}
