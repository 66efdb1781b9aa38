#!/usr/bin/python3
"""Unit test of the replica pooling (tools/sweep_pool.py), run by tests/cli/sweep.sh:

    /usr/bin/python3 tools/test_sweep_pool.py

Synthetic points whose replicas are drawn from Normal(mu, sigma^2) with a
fixed seed (so the verdicts are reproducible), M points of N replicas each:

1. The SE between replicas estimates sigma / sqrt(N): the mean over M points
   of se^2 N / sigma^2 is 1 within 3 of its own SEs (se^2 N / sigma^2 =
   s^2 / sigma^2 ~ chi^2_{N-1} / (N - 1), variance 2 / (N - 1), so the mean
   over M points has SE sqrt(2 / ((N - 1) M))); one point of 1000 replicas
   gives sigma / sqrt(1000) within 3 of its SEs (relative SE
   1 / sqrt(2 * 999)); the mean is within 3 sigma / sqrt(N) of mu.
2. With the within-run SEs right (SE_i = sigma), the flag fires on
   1 - 0.95 of the points (the chi-square interval's level): the rate is
   within 3 binomial SEs, sqrt(0.05 * 0.95 / M), of 0.05.
3. With the within-run SEs understated 3x (SE_i = sigma / 3), the flag says
   "high" on the share of points the chi-square law predicts,
   P(chi^2_{N-1} > (N - 1) (hi / 3)^2), within 3 binomial SEs: all of them for
   N = 20, about two thirds for N = 3 (three replicas are a weak test).
Exit 0 when all hold; each check prints its numbers.
"""
import math
import sys

import numpy as np
from scipy.stats import chi2

from sweep_pool import pool, ratio_interval

MU, SIGMA, M = 5.0, 0.3, 4000
failures = []


def check(ok, what):
    print(("  ok   " if ok else "  FAIL ") + what)
    if not ok:
        failures.append(what)


rng = np.random.default_rng(20261206)

# exact cases: the arithmetic of one pool
p = pool([1.0, 2.0, 3.0], [0.3, 0.6, 0.9])
check(abs(p["mean"] - 2.0) < 1e-15 and abs(p["se"] - 1.0 / math.sqrt(3)) < 1e-15
      and abs(p["se_within"] - 0.6 / math.sqrt(3)) < 1e-15 and p["n"] == 3,
      f"pool([1, 2, 3], SE [0.3, 0.6, 0.9]): mean {p['mean']}, se {p['se']:.6f} (1/sqrt 3), "
      f"se_within {p['se_within']:.6f} (0.6/sqrt 3)")
p1 = pool([1.0, None, float("nan")], [0.1, 0.1, 0.1])
check(p1["n"] == 1 and p1["se"] is None and p1["flag"] == "",
      "one finite replica: n 1, no SE between replicas, no flag")

for n in (20, 3):
    x = rng.normal(MU, SIGMA, size=(M, n))
    lo, hi = ratio_interval(n)
    right = [pool(list(r), [SIGMA] * n) for r in x]
    se2 = np.array([q["se"] ** 2 * n / SIGMA ** 2 for q in right])
    tol = 3.0 * math.sqrt(2.0 / ((n - 1) * M))
    check(abs(se2.mean() - 1.0) < tol,
          f"N = {n}: mean of se^2 N / sigma^2 over {M} points = {se2.mean():.4f}, expected 1 +- {tol:.4f} (3 SE)")
    means = np.array([q["mean"] for q in right])
    check(abs(means[0] - MU) < 3.0 * SIGMA / math.sqrt(n),
          f"N = {n}: one point's mean {means[0]:.4f} within 3 sigma/sqrt(N) = {3 * SIGMA / math.sqrt(n):.4f} of {MU}")
    rate = np.mean([q["flag"] != "ok" for q in right])
    btol = 3.0 * math.sqrt(0.05 * 0.95 / M)
    check(abs(rate - 0.05) < btol,
          f"N = {n}: SEs right: flag fires on {rate:.4f} of the points, expected 0.05 +- {btol:.4f} "
          f"(interval [{lo:.3f}, {hi:.3f}])")
    under = [pool(list(r), [SIGMA / 3.0] * n) for r in x]
    expect = chi2.sf((n - 1) * (hi / 3.0) ** 2, n - 1)
    rate = np.mean([q["flag"] == "high" for q in under])
    btol = 3.0 * math.sqrt(max(expect * (1 - expect), 1.0 / M) / M)
    ratios = np.array([q["ratio"] for q in under])
    check(abs(rate - expect) < btol,
          f"N = {n}: SEs understated 3x: flag 'high' on {rate:.4f} of the points, expected {expect:.4f} +- "
          f"{btol:.4f}; median ratio {np.median(ratios):.2f}")

big = pool(list(rng.normal(MU, SIGMA, size=1000)), [SIGMA] * 1000)
want = SIGMA / math.sqrt(1000)
rel = 3.0 / math.sqrt(2 * 999)
check(abs(big["se"] / want - 1.0) < rel,
      f"1000 replicas: se {big['se']:.6f} vs sigma/sqrt(N) {want:.6f} (ratio {big['se'] / want:.4f}, "
      f"3 SE = {rel:.4f}); flag {big['flag']}")
print(f"  sweep_pool tests: {len(failures)} failed")
sys.exit(1 if failures else 0)
