#!/usr/bin/env bash
# The shipped resolution table of coupling I (src/app/calibration_table.c,
# issue 45: a new suspension in seconds).  Scenes: scenes/hecht_table1.cfg's
# suspension (Hecht's fluid, whose table is calibration/rh_resolution-c1_hecht.json,
# measured at R/a0 = 2, 3, 4, 6) at resolutions no shipped calibration was
# made for, PELOID_CACHE an empty folder:
#  1. R/a0 = 3: `params --calibrate auto` answers in < 5 s without a
#     calibration run, names source "table", and its D equals kT/(6 pi eta
#     R_h) with R_h from the law recomputed here from the JSON file (the
#     covariance scaled as the code states) to 1e-9, its relative error the
#     law's propagated SE; `check` (stored) reads the table too; nothing is
#     stored in the cache;
#  2. against an independent measurement: at R/a0 = 2 with the particle
#     density 0.26 % higher (another cache key, the same table) the table's D
#     agrees with the shipped MSD calibration of scenes/hecht_table1.cfg
#     (calibration/calibration-9aa595c8f7cdb515.json, 8 colloids, Hasimoto
#     removed) within 3 combined SE (law from settling friction, calibration
#     from diffusion: the Einstein relation between them);
#  3. off the table, `--calibrate stored` gives the theory (source "theory"),
#     never the table: R/a0 = 8 (beyond the measured 6), a colloid of 84 m_f
#     (below the 100 m_f the table asks), another mean free path (no table
#     for that fluid), and PELOID_NO_SHIPPED_CALIBRATION=1;
#  4. a run's summary.json carries source "table" and its relative error.
# Before the table, case 1 had source "theory" under stored and a
# calibration run (minutes) under auto.
set -u
PELOID=$(realpath "${1:-bin/peloid}")
PY=/usr/bin/python3
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
T=$(mktemp -d /tmp/peloid-caltable.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
echo "== coupling I resolution table"
export PELOID_CACHE="$T/cache"
unset PELOID_NO_SHIPPED_CALIBRATION

# scene CELL_SIZE BOX_EDGE_M [SED...]: Hecht Table I's suspension at a0 = R * CELL_SIZE
scene() {
  local cs=$1 box=$2; shift 2
  sed -e "s/cell_size = 0.5;.*/cell_size = $cs;/" \
      -e "s/box = \[6.4e-6, 6.4e-6, 12.8e-6\];.*/box = [$box, $box, $box];/" \
      -e 's/^steps = .*/steps = 20;/' "$@" "$ROOT/scenes/hecht_table1.cfg"
}
scene 0.3333333333333333 4.8e-6 > t3.cfg
s=$(date +%s.%N)
"$PELOID" params t3.cfg --json --calibrate auto > t3.json 2> t3.err; rc=$?
e=$($PY -c "print(f'{$(date +%s.%N) - $s:.2f}')")
if [ $rc -eq 0 ] && ! grep -q calibrating t3.err && r=$($PY - "$ROOT/calibration/rh_resolution-c1_hecht.json" t3.json <<'PY'
import json, math, sys
law = json.load(open(sys.argv[1]))["law"]
p = json.load(open(sys.argv[2]))
cal = p["calibration"]
R = p["mapping"]["colloid"]["radius_a0"]
eta = p["srd"]["eta"]
x = 1.0 / R
b = law["b"] if law["form"] == "b + c a0/R" else 0.0
rh = R / (1.0 + b + law["c"] * x)
g = [-rh * rh / R, -rh * rh / R * x]
C = law["covariance"]
var = g[1] ** 2 * C[0][0] if len(C) == 1 else sum(g[i] * g[j] * C[i][j] for i in range(2) for j in range(2))
if law["dof"] > 0 and law["chi2"] > law["dof"]:
    var *= law["chi2"] / law["dof"]
d = 1.0 / (6.0 * math.pi * eta * rh)
rel = math.sqrt(var) / rh
assert cal["source"] == "table", cal["source"]
assert abs(cal["d_a0_2_t0"] / d - 1) < 1e-9, (cal["d_a0_2_t0"], d)
assert abs(cal["relative_error"] / rel - 1) < 1e-6, (cal["relative_error"], rel)
assert abs(cal["table_rh_over_R"] - rh / R) < 1e-9
print(f"R/a0 = {R:g}: D = {d:.6g} a0^2/t0, R_h/R = {rh / R:.4f}, relative error {rel:.2g}")
PY
); then
  if awk "BEGIN{exit !($e < 5)}" && [ -z "$(ls -A cache 2>/dev/null)" ]; then ok "auto reads the table in ${e} s, nothing stored: $r"
  else bad "auto: ${e} s or the cache written: $(ls cache 2>/dev/null)"; fi
else bad "auto at R/a0 = 3: rc $rc: $(tail -1 t3.err) $r"; fi
if "$PELOID" check t3.cfg > c3.out 2>&1 && grep -q "shipped resolution table" c3.out; then ok "check (stored) reads the table"
else bad "check: $(grep -i calibration c3.out | head -2)"; fi

# 2. the table against the MSD calibration of the same model (particle density + 0.26 %)
scene 0.5 4.8e-6 -e 's/particle_density = 3.9e3;/particle_density = 3.91e3;/' > t2.cfg
if "$PELOID" params t2.cfg --json --calibrate stored > t2.json 2> t2.err && r=$($PY - "$ROOT/calibration/calibration-9aa595c8f7cdb515.json" t2.json <<'PY'
import json, math, sys
m = json.load(open(sys.argv[1]))
p = json.load(open(sys.argv[2]))["calibration"]
assert p["source"] == "table", p["source"]
dm, sm = m["d_inf"], m["d_inf_se"]
dt, st = p["d_a0_2_t0"], p["d_a0_2_t0"] * p["relative_error"]
z = (dt - dm) / math.hypot(sm, st)
msg = f"table {dt:.5g} +- {st:.2g}, MSD calibration {dm:.5g} +- {sm:.2g} a0^2/t0: {z:+.2f} combined SE"
assert abs(z) <= 3, msg
print(msg)
PY
); then ok "R/a0 = 2: $r"
else bad "R/a0 = 2 against the shipped calibration: $(tail -1 t2.err) $r"; fi

# 3. off the table: the theory under stored
src() { $PY -c "import json,sys; print(json.load(open(sys.argv[1]))['calibration']['source'])" "$1" 2>/dev/null || echo "-"; }
scene 0.125 4.8e-6 > t8.cfg
scene 0.5 4.8e-6 -e 's/particle_density = 3.9e3;/particle_density = 1.0e3;/' > light.cfg
scene 0.3333333333333333 4.8e-6 -e 's/mean_free_path = 0.6;/mean_free_path = 0.5;/' > lambda.cfg
for c in t8 light lambda; do
  "$PELOID" params $c.cfg --json --calibrate stored > $c.json 2> $c.err
  if [ "$(src $c.json)" = theory ]; then ok "$c: off the table, the theory"
  else bad "$c: source $(src $c.json): $(tail -1 $c.err)"; fi
done
PELOID_NO_SHIPPED_CALIBRATION=1 "$PELOID" params t3.cfg --json --calibrate stored > ns.json 2> ns.err
if [ "$(src ns.json)" = theory ]; then ok "PELOID_NO_SHIPPED_CALIBRATION=1: no table"
else bad "PELOID_NO_SHIPPED_CALIBRATION=1: source $(src ns.json)"; fi

# 4. a run's summary.json
scene 0.3333333333333333 4.8e-6 -e 's/^steps = .*/steps = 2;/' > run.cfg
if "$PELOID" run run.cfg --out r --threads 1 2> run.err && r=$($PY - r/summary.json <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))["calibration"]
assert c["source"] == "table" and 0 < c["relative_error"] < 0.05, c
print(f"source {c['source']}, relative error {c['relative_error']:.2g}")
PY
); then ok "run: summary.json $r"
else bad "run: $(tail -1 run.err) $r"; fi

echo "calibration_table: $pass passed, $fail failed"
[ $fail -eq 0 ]
