/* Analysis windows (peloid/window.h): the start of a series' time average,
 * chosen by the user or detected.
 *
 * Detection: Chodera's automated equilibration detection (J. D. Chodera,
 * J. Chem. Theory Comput. 12, 1799 (2016), Sec. 2.3-2.4): for each
 * candidate start t0 the statistical inefficiency g(t0) of the samples
 * from t0 on (Eq. 5: g = 1 + 2 tau, tau the integrated autocorrelation,
 * the sum truncated at the first non-positive correlation as in pymbar's
 * timeseries.statisticalInefficiency, lags with a growing stride as its
 * "fast" mode) and N_eff(t0) = (T - t0) / g(t0); the start maximises
 * N_eff.  Discarding a transient raises N_eff because the drift inflates
 * both the variance and the correlation time of the whole series.
 *
 * Everything here is a serial function of the stored series, so a run
 * resumed from a checkpoint (which stores the series) gets the same bits. */
#include "peloid/window.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int pl_window_parse(const char *text, pl_window_spec_t *spec)
{
    if (!strcmp(text, "auto")) {
        *spec = (pl_window_spec_t){PL_WINDOW_AUTO, 0.0};
        return 0;
    }
    if (!strcmp(text, "start")) {
        *spec = (pl_window_spec_t){PL_WINDOW_START, 0.0};
        return 0;
    }
    char *end = NULL;
    const double v = strtod(text, &end);
    if (end == text || !isfinite(v) || v < 0.0) return -1;
    while (*end == ' ') ++end;
    if (*end == '%') {
        ++end;
        while (*end == ' ') ++end;
        if (*end || !(v < 100.0)) return -1;
        *spec = (pl_window_spec_t){PL_WINDOW_PERCENT, v};
        return 0;
    }
    if (*end) return -1;
    *spec = (pl_window_spec_t){PL_WINDOW_TIME, v};
    return 0;
}

/* pymbar's shortest lag before a non-positive correlation may end the sum */
enum { MINTIME = 3, MAX_CANDIDATES = 200, MIN_SAMPLES = 8 };

double pl_window_inefficiency(const double *x, size_t n)
{
    if (n < 2) return 1.0;
    double mu = 0.0;
    for (size_t i = 0; i < n; ++i) mu += x[i];
    mu /= (double)n;
    double s2 = 0.0;
    for (size_t i = 0; i < n; ++i) s2 += (x[i] - mu) * (x[i] - mu);
    s2 /= (double)n;
    if (!(s2 > 0.0)) return 1.0;
    double g = 1.0;
    size_t t = 1, inc = 1;
    while (t < n - 1) {
        double c = 0.0;
        for (size_t i = 0; i + t < n; ++i) c += (x[i] - mu) * (x[i + t] - mu);
        c /= (double)(n - t) * s2;
        if (c <= 0.0 && t > MINTIME) break;
        g += 2.0 * c * (1.0 - (double)t / (double)n) * (double)inc;
        t += inc;
        inc++;
    }
    return g < 1.0 ? 1.0 : g;
}

size_t pl_window_detect(const double *x, size_t n, double *g, double *neff)
{
    size_t best = 0;
    double best_g = pl_window_inefficiency(x, n), best_n = (double)n / best_g;
    if (n >= MIN_SAMPLES) {
        const size_t last = n / 2, stride = last / MAX_CANDIDATES + 1;
        for (size_t t0 = stride; t0 <= last; t0 += stride) {
            const double gt = pl_window_inefficiency(x + t0, n - t0), ne = (double)(n - t0) / gt;
            if (ne > best_n) {
                best = t0;
                best_g = gt;
                best_n = ne;
            }
        }
    }
    if (g) *g = best_g;
    if (neff) *neff = best_n;
    return best;
}

long long pl_window_from_step(const pl_window_spec_t *spec, double t_model, double dt, long long run_first,
                              long long run_last)
{
    switch (spec->kind) {
    case PL_WINDOW_TIME: return (long long)ceil(t_model / dt);
    case PL_WINDOW_PERCENT:
        return run_first + (long long)ceil(spec->value / 100.0 * (double)(run_last - run_first));
    default: return run_first;
    }
}

pl_window_t pl_window_choose(const pl_window_spec_t *spec, long long from_step, const long long *step,
                             const double *x, size_t n, double *scratch)
{
    pl_window_t w = {.first = 0, .step = n ? step[0] : 0, .source = PL_WSRC_WHOLE, .g = NAN, .neff = NAN};
    if (spec->kind == PL_WINDOW_TIME || spec->kind == PL_WINDOW_PERCENT) {
        size_t i = 0;
        while (i < n && step[i] < from_step) ++i;
        w.first = i;
        w.step = i < n ? step[i] : from_step;
        w.source = PL_WSRC_USER;
        return w;
    }
    if (spec->kind != PL_WINDOW_AUTO || n == 0) return w;
    size_t m = 0; /* the finite values, in order */
    for (size_t i = 0; i < n; ++i)
        if (isfinite(x[i])) scratch[m++] = x[i];
    const size_t c = pl_window_detect(scratch, m, &w.g, &w.neff);
    if (c == 0) return w;
    size_t i = 0, seen = 0; /* the c-th finite value's index */
    for (; i < n; ++i)
        if (isfinite(x[i]) && seen++ == c) break;
    w.first = i;
    w.step = step[i];
    w.source = PL_WSRC_DETECTED;
    return w;
}

pl_blocking_result_t pl_window_blocking(const double *x, size_t n, size_t first, uint64_t *count)
{
    pl_blocking_t b;
    pl_blocking_init(&b);
    for (size_t i = first; i < n; ++i)
        if (isfinite(x[i])) pl_blocking_add(&b, x[i]);
    if (count) *count = b.n;
    return pl_blocking_result(&b);
}

const char *pl_window_source_name(pl_window_source_t s)
{
    return s == PL_WSRC_USER ? "user" : s == PL_WSRC_DETECTED ? "detected" : "whole run";
}
