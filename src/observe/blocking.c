/* On-the-fly Flyvbjerg-Petersen blocking; the rule and the sources are in
 * include/peloid/blocking.h.
 *
 * Each level holds the Welford mean and sum of squared deviations of its
 * completed block means.  A completed block of level k is added to level k
 * and, with the pending block of that level, completes one block of level
 * k + 1 (the mean of the two): the cascade of DDDA. */
#include "peloid/blocking.h"

#include <math.h>
#include <string.h>

_Static_assert(sizeof(pl_blocking_level_t) == 5 * 8 && sizeof(pl_blocking_t) == 16 + 40 * PL_BLOCKING_LEVELS,
               "pl_blocking_t must have no padding (bytewise checkpoints and comparisons)");

void pl_blocking_init(pl_blocking_t *b)
{
    memset(b, 0, sizeof *b);
}

static void level_add(pl_blocking_level_t *l, double v)
{
    l->n++;
    double d = v - l->mean;
    l->mean += d / (double)l->n;
    l->m2 += d * (v - l->mean);
}

/* A completed block of value v at level k, and the cascade above it. */
static void push(pl_blocking_t *b, int k, double v)
{
    for (; k < PL_BLOCKING_LEVELS; ++k) {
        pl_blocking_level_t *l = &b->lev[k];
        level_add(l, v);
        if (k + 1 > b->nlev) b->nlev = k + 1;
        if (!l->has_pending) {
            l->pending = v;
            l->has_pending = 1;
            return;
        }
        v = 0.5 * (l->pending + v);
        l->has_pending = 0;
    }
}

void pl_blocking_add(pl_blocking_t *b, double x)
{
    b->n++;
    push(b, 0, x);
}

/* Chan, Golub & LeVeque: pooled mean and squared deviations of two sets. */
static void level_combine(pl_blocking_level_t *a, const pl_blocking_level_t *b)
{
    if (b->n == 0) return;
    if (a->n == 0) {
        a->n = b->n;
        a->mean = b->mean;
        a->m2 = b->m2;
        return;
    }
    double na = (double)a->n, nb = (double)b->n, n = na + nb;
    double d = b->mean - a->mean;
    a->mean += d * (nb / n);
    a->m2 += b->m2 + d * d * (na * nb / n);
    a->n += b->n;
}

void pl_blocking_merge(pl_blocking_t *a, const pl_blocking_t *b)
{
    for (int k = 0; k < b->nlev; ++k) level_combine(&a->lev[k], &b->lev[k]);
    if (b->nlev > a->nlev) a->nlev = b->nlev;
    a->n += b->n;
    /* Open blocks, level by level in the order (a, b, carried from below):
     * the first two complete a block of the next level, a third stays open. */
    int has_carry = 0;
    double carry = 0.0;
    for (int k = 0; k < PL_BLOCKING_LEVELS; ++k) {
        double cand[3];
        int nc = 0;
        if (a->lev[k].has_pending) cand[nc++] = a->lev[k].pending;
        if (b->lev[k].has_pending) cand[nc++] = b->lev[k].pending;
        if (has_carry) cand[nc++] = carry;
        if (k >= a->nlev && nc == 0) break;
        a->lev[k].has_pending = 0;
        has_carry = 0;
        if (nc >= 2) {
            carry = 0.5 * (cand[0] + cand[1]);
            has_carry = 1;
            if (k + 1 < PL_BLOCKING_LEVELS) {
                level_add(&a->lev[k + 1], carry);
                if (k + 2 > a->nlev) a->nlev = k + 2;
            }
        }
        if (nc == 1 || nc == 3) {
            a->lev[k].pending = cand[nc - 1];
            a->lev[k].has_pending = 1;
        }
    }
}

double pl_blocking_mean(const pl_blocking_t *b)
{
    return b->n ? b->lev[0].mean : NAN;
}

uint64_t pl_blocking_level_count(const pl_blocking_t *b, int k)
{
    return (k >= 0 && k < b->nlev) ? b->lev[k].n : 0;
}

double pl_blocking_level_se(const pl_blocking_t *b, int k)
{
    uint64_t n = pl_blocking_level_count(b, k);
    if (n < 2) return NAN;
    double dn = (double)n;
    return sqrt(b->lev[k].m2 / (dn - 1.0) / dn);
}

/* Flyvbjerg-Petersen Eq. 28: the SE estimate of n blocks is itself
 * uncertain by a factor 1/sqrt(2 (n - 1)). */
double pl_blocking_level_se_err(const pl_blocking_t *b, int k)
{
    uint64_t n = pl_blocking_level_count(b, k);
    if (n < 2) return NAN;
    return pl_blocking_level_se(b, k) / sqrt(2.0 * ((double)n - 1.0));
}

static void fill_result(const pl_blocking_t *b, int k, int plateau, pl_blocking_result_t *r)
{
    r->level = k;
    r->plateau = plateau;
    r->se = pl_blocking_level_se(b, k);
    r->se_err = pl_blocking_level_se_err(b, k);
    if (r->se_naive > 0.0) {
        double q = r->se / r->se_naive;
        r->inefficiency = q * q;
    } else {
        r->inefficiency = 1.0;
    }
    r->n_indep = (double)b->n / r->inefficiency;
}

pl_blocking_result_t pl_blocking_result(const pl_blocking_t *b)
{
    pl_blocking_result_t r = {.mean = pl_blocking_mean(b), .se = NAN, .se_err = NAN,
                              .se_naive = NAN, .inefficiency = NAN, .n_indep = NAN,
                              .level = -1, .plateau = 0};
    if (b->n < 2) return r;
    r.se_naive = pl_blocking_level_se(b, 0);
    if (!(r.se_naive > 0.0)) { /* constant series: no error, nothing to block */
        fill_result(b, 0, 1, &r);
        return r;
    }
    double twoN = 2.0 * (double)b->n;
    int last = 0;
    for (int k = 0; k < b->nlev; ++k) {
        if (b->lev[k].n < 2) break;
        if (k == 0 || b->lev[k].n >= PL_BLOCKING_MIN_BLOCKS) last = k;
        if (b->lev[k].n < PL_BLOCKING_MIN_BLOCKS) continue;
        double q = pl_blocking_level_se(b, k) / r.se_naive;
        if (ldexp(1.0, 3 * k) > twoN * q * q * q * q) { /* Lee et al. rule */
            fill_result(b, k, 1, &r);
            return r;
        }
    }
    fill_result(b, last, 0, &r);
    return r;
}

double pl_blocking_time_for_se(double se, double t, double target_se)
{
    if (!(target_se > 0.0)) return INFINITY;
    double q = se / target_se;
    return t * q * q;
}
