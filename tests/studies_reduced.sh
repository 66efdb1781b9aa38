#!/usr/bin/env bash
# The reduced studies of studies/reduced/ (make check): each full study of
# studies/ at a size that runs in seconds, asserting its headline within a
# looser, stated bound (the full studies: make studies, validation/REPORT.md).
#  - Hecht Fig. 9 kappa (studies/reduced/hecht_fig9_kappa.cfg, ~140 colloids,
#    0.17 s mapped): suspended at kappa = 1.0e8 /m, clustered at 2.0e8 /m by
#    the full study's rule (largest cluster above 10 % of the colloids).
#    Measured: 2.1 +- 0.1 % and 97.6 +- 0.4 %: far from the 10 % either way.
#  - accuracy-cost guide (studies/reduced/accuracy_viscosity.cfg, rho = 10,
#    lambda = 0.1 and 1): at 12000 steps the Green-Kubo viscosity is within
#    3 SE of PL Eqs. 9-15 (3 SE: 0.3 % chance failure per point), and the
#    SE shrinks as CPU^-1/2: the geometric mean over both settings of SE(12000
#    steps) / SE(3000 steps) lies in 0.3-0.8 (expected 0.5; a blocking SE from
#    ~10-20 blocks scatters by ~20 %, the mean ratio by ~0.1: 2-3 sigma).
set -u
PELOID=$(realpath "${1:-bin/peloid}")
PY=/usr/bin/python3
ROOT=$(cd "$(dirname "$0")/.." && pwd)
T=$(mktemp -d /tmp/peloid-studies.XXXXXX)
trap 'rm -rf "$T"' EXIT
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
echo "== reduced studies"
for s in hecht_fig9_kappa accuracy_viscosity; do
  t0=$(date +%s)
  if ! "$PELOID" sweep "$ROOT/studies/reduced/$s.cfg" --out "$T/$s" > "$T/$s.log" 2>&1; then
    bad "$s: sweep failed: $(tail -1 "$T/$s.log")"; continue
  fi
  if out=$($PY - "$ROOT/tools" "$T" "$s" <<'PY'
import sys, math
sys.path.insert(0, sys.argv[1])
import validation_report as vr
out, name = sys.argv[2], sys.argv[3]
sw = vr.load(out, name)
pts = [p for p in sw["points"] if p["summary"]]
if len(pts) != len(sw["points"]):
    print("a point did not finish"); sys.exit(1)
if name == "hecht_fig9_kappa":
    got = {}
    for p in pts:
        k = p["params"]["physical.kappa"]
        n = p["summary"]["mapping"]["colloid"]["n_colloids"]
        lc = p["summary"]["observables"]["largest_cluster"]
        got[k] = (vr.cluster_state(lc["value"] / n), 100 * lc["value"] / n, 100 * lc["stderr"] / n)
    print("; ".join(f"kappa {k:.2g}: largest cluster {f:.1f} +- {e:.1f} % -> {s}" for k, (s, f, e) in sorted(got.items())))
    sys.exit(0 if got[1.0e8][0] == "suspended" and got[2.0e8][0] == "clustered" else 1)
else:
    se, good, msg = {}, True, []
    for p in pts:
        e = p["summary"]["observables"]["fluid_viscosity"]
        lam, steps = p["params"]["srd.dt"], p["params"]["steps"]
        se[(lam, steps)] = e["stderr"]
        if steps == 12000:
            dev = (e["value"] - e["theory_PL_Eq15"]) / e["stderr"]
            good &= abs(dev) <= 3
            msg.append(f"lambda {lam:g}: eta {e['value']:.3f} +- {e['stderr']:.3f} vs PL {e['theory_PL_Eq15']:.3f} ({dev:+.1f} SE)")
    lams = sorted({k[0] for k in se})
    ratio = math.exp(sum(math.log(se[(l, 12000)] / se[(l, 3000)]) for l in lams) / len(lams))
    good &= 0.3 <= ratio <= 0.8
    msg.append(f"SE(12000) / SE(3000) = {ratio:.2f} (expected 0.5)")
    print("; ".join(msg))
    sys.exit(0 if good else 1)
PY
  ); then ok "$s ($(( $(date +%s) - t0 )) s): $out"; else bad "$s: $out"; fi
done
echo "reduced studies: $pass passed, $fail failed"
[ $fail -eq 0 ]
