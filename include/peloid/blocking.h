/* Standard error of a time average by on-the-fly blocking (DESIGN.md
 * "Observables and their errors").
 *
 * Flyvbjerg & Petersen, J. Chem. Phys. 91, 461 (1989): the series x_1..x_N is
 * repeatedly halved into block means of 2^k samples; the naive standard error
 * of the block means, SE_k = sqrt(s_k^2 / n_k) with s_k^2 the sample variance
 * of the n_k blocks of level k, grows with k until the blocks are longer than
 * the correlation time and then stays on a plateau whose value is the SE of
 * the mean (their Eqs. 26-28; the error of SE_k itself is
 * SE_k / sqrt(2 (n_k - 1))).  The levels are built on the fly as in DDDA
 * (Kent, Muller & Ceperley, Comput. Phys. Commun. 177, 2007): each level keeps
 * the running mean and sum of squared deviations of its completed block
 * means (Welford) and one pending half block, so memory is O(log N) and a
 * sample costs O(1) amortised.
 *
 * Plateau rule (Wolff 2004; Lee, Drummond & Needs, Phys. Rev. E 83, 066706,
 * 2011, as in pyblock): the chosen level is the smallest k with
 *
 *     (2^k)^3 > 2 N (SE_k / SE_0)^4     and    n_k >= PL_BLOCKING_MIN_BLOCKS,
 *
 * i.e. the block is long enough that the bias from correlations between
 * neighbouring blocks, ~tau/B, is smaller than the statistical error of SE_k,
 * ~1/sqrt(n_k).  The second condition (ours) keeps the rule off the top
 * levels, whose few blocks of a run shorter than its correlation time are
 * nearly equal and fake a small SE; 16 blocks know SE_k to 18 %.  (An
 * unconverged level has (SE_k/SE_0)^2 ~ 2^k, which fails the first condition
 * for any block shorter than 2N.)  When no
 * level satisfies both (a run shorter than some tens of correlation times)
 * the result carries plateau = 0 and the SE of the highest level with at
 * least 16 blocks (level 0 if none), which is then a lower bound.
 *
 * Derived numbers: statistical inefficiency s = N SE^2 / s_0^2 (1 for
 * uncorrelated data, 2 tau_int in general), independent samples N / s.
 * Error against run time: SE ~ 1/sqrt(t), so reaching a target SE from (SE,
 * t) needs t (SE / target)^2 of wall time in all.
 *
 * Determinism: pl_blocking_add is a fixed sequence of double operations;
 * pl_blocking_merge combines level statistics by Chan et al.'s pairwise
 * formula in the fixed order (a, then b), so a fixed merge tree (e.g. over
 * threads by index) gives bitwise reproducible results for any thread count.
 */
#ifndef PELOID_BLOCKING_H
#define PELOID_BLOCKING_H

#include <stdint.h>

#define PL_BLOCKING_LEVELS 64     /* 2^64 samples: never the limit */
#define PL_BLOCKING_MIN_BLOCKS 16 /* fewest blocks of a plateau level */

typedef struct {
    uint64_t n;     /* completed blocks of this level */
    double mean;    /* running mean of the block means (Welford) */
    double m2;      /* sum of squared deviations from the mean */
    double pending; /* the first half of the next block of the level above */
    uint64_t has_pending;
} pl_blocking_level_t;

/* Plain struct without padding bytes: checkpointable and comparable bytewise
 * as is, no allocation.  Zero-initialise it (or call pl_blocking_init). */
typedef struct {
    uint64_t n;   /* samples added */
    int64_t nlev; /* levels with at least one block */
    pl_blocking_level_t lev[PL_BLOCKING_LEVELS];
} pl_blocking_t;

typedef struct {
    double mean;         /* mean of all N samples */
    double se;           /* SE of the mean at the chosen level */
    double se_err;       /* its own error, se / sqrt(2 (n_k - 1)) */
    double se_naive;     /* SE_0 = s_0 / sqrt(N) (uncorrelated assumption) */
    double inefficiency; /* s = (se / se_naive)^2 */
    double n_indep;      /* N / s */
    int level;           /* chosen level k (block of 2^k samples); -1 if N < 2 */
    int plateau;         /* 1 when the rule above found a level */
} pl_blocking_result_t;

void pl_blocking_init(pl_blocking_t *b);
void pl_blocking_add(pl_blocking_t *b, double x);
/* Adds b's statistics into a, as if b's samples had followed a's.  Exact (up
 * to rounding) when a->n is a multiple of 2^L with 2^L > b->n, i.e. when no
 * block of a is left open at a level b reaches; otherwise the open blocks of a
 * and b at a level are paired into one block (the pairing of two stretches of
 * data that were not adjacent, harmless when both are much longer than the
 * correlation time, as for per-thread or per-replica partial sums). */
void pl_blocking_merge(pl_blocking_t *a, const pl_blocking_t *b);

double pl_blocking_mean(const pl_blocking_t *b);
/* Blocks of level k, their naive SE and that SE's error (NAN when n_k < 2). */
uint64_t pl_blocking_level_count(const pl_blocking_t *b, int k);
double pl_blocking_level_se(const pl_blocking_t *b, int k);
double pl_blocking_level_se_err(const pl_blocking_t *b, int k);
/* The plateau SE and the numbers derived from it (rule in the file header). */
pl_blocking_result_t pl_blocking_result(const pl_blocking_t *b);

/* Wall time in all (not the remainder) at which the SE reaches target_se,
 * from the SE se reached after wall time t: t (se / target_se)^2.
 * For a relative error r of a mean mu pass target_se = r |mu|. */
double pl_blocking_time_for_se(double se, double t, double target_se);

#endif
