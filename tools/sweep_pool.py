"""Pooling the replicas of a sweep's point (study key `replicas`, tools/sweep_collect.py).

A point run N times with independent seeds gives N estimates x_i of an
observable, each with its within-run standard error SE_i (the observer's
blocking or fit SE).  pool() returns

  mean       the mean of the x_i
  se         the SE from the scatter between the replicas, sd(x) / sqrt(N)
             (sd with N - 1; None for N < 2): it needs no model of the
             run's correlations, only that the replicas are independent
  se_within  mean(SE_i) / sqrt(N): the SE of the mean if each run's own SE
             is right
  ratio      se / se_within
  flag       "ok", "high" (the replicas scatter more than their SEs say:
             the within-run SE is understated, e.g. a correlation time
             longer than its blocks, or a drift), "low" (less), or ""
             (N < 2, or a within-run SE missing)

The flag's interval (ratio_interval) is where the ratio falls 95 % of the
time when the within-run SEs are right, from the chi-square distribution
of the sample variance.
"""
import functools
import math

from scipy.stats import chi2

LEVEL = 0.95


@functools.lru_cache(maxsize=None)
def ratio_interval(n, level=LEVEL):
    """The central `level` interval of se / se_within for n >= 2 replicas whose within-run SE is right.

    Each replica's value is x_i ~ Normal(mu, sigma^2), sigma the within-run SE (a run's estimate is a mean over
    many samples, so normal by the central limit theorem).  The sample variance s^2 over n replicas then has
    (n - 1) s^2 / sigma^2 ~ chi^2 with n - 1 degrees of freedom, and se / se_within = s / sigma lies in
    [sqrt(q_lo / (n - 1)), sqrt(q_hi / (n - 1))] with probability `level`, q_lo and q_hi the chi^2_{n-1}
    quantiles at (1 - level) / 2 and (1 + level) / 2.  For n = 3: [0.16, 1.92]; n = 10: [0.55, 1.45];
    n = 30: [0.74, 1.26].  The interval takes the within-run SE as exact; it is itself an estimate (a
    blocking SE from 10-30 blocks scatters by 15-25 %, their mean over n replicas by that / sqrt(n)), so a
    sound SE is flagged somewhat more often than 1 - level."""
    df = n - 1
    return math.sqrt(chi2.ppf((1.0 - level) / 2.0, df) / df), math.sqrt(chi2.ppf((1.0 + level) / 2.0, df) / df)


def _finite(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def pool(values, ses, level=LEVEL):
    """Pools one observable over a point's replicas: values[i] and ses[i] of replica i (None: not measured;
    a replica without a finite value is left out).  Returns a dict with n (the replicas pooled), mean, se,
    se_within, ratio, flag and interval (the flag's bounds on the ratio; None for n < 2), see the module."""
    pairs = [(v, s) for v, s in zip(values, ses) if _finite(v)]
    n = len(pairs)
    out = {"n": n, "mean": None, "se": None, "se_within": None, "ratio": None, "flag": "", "interval": None}
    if n == 0:
        return out
    mean = math.fsum(v for v, _ in pairs) / n
    out["mean"] = mean
    if all(_finite(s) for _, s in pairs):
        out["se_within"] = math.fsum(s for _, s in pairs) / n / math.sqrt(n)
    if n < 2:
        return out
    sd = math.sqrt(math.fsum((v - mean) ** 2 for v, _ in pairs) / (n - 1))
    out["se"] = sd / math.sqrt(n)
    out["interval"] = ratio_interval(n, level)
    w = out["se_within"]
    if w is None:
        return out
    if w > 0.0:
        out["ratio"] = out["se"] / w
    elif out["se"] > 0.0:
        out["ratio"] = math.inf
    else:
        out["flag"] = "ok"  # no scatter and none expected (e.g. a count that never changed)
        return out
    lo, hi = out["interval"]
    out["flag"] = "high" if out["ratio"] > hi else "low" if out["ratio"] < lo else "ok"
    return out
