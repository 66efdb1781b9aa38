#!/usr/bin/env bash
# peloid plan SCENE --target REL (src/app/advise.c): the guide to choosing
# the model for the shipped quickstart suspension (coupling II, its shipped
# calibration) prints each coupling with its hydrodynamic radius, marks the
# scene's own, recommends the coupling whose measured R_h/R is nearest 1
# (coupling I: 0.79 from its shipped calibration, against II's 0.49 and the
# potential coupling's 0.54-0.55), names the cheapest, sizes the box by
# Hasimoto's 2.837 R_h / L, and turns the colloid D's SE ~0.35/sqrt(N) into
# the replicas the target needs (1 %: 8 runs of 173 colloids) with the
# `peloid run --replicas` line, and names the matched resolution of coupling
# I from the measured law of the scene's fluid with the run made at it; a
# bad --target, a missing one and a scene without a physical{} suspension
# are refused with exit 2 and one line.
set -u
PELOID=$(realpath "${1:-bin/peloid}")
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
T=$(mktemp -d /tmp/peloid-plan.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$ROOT"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
echo "== plan tests"

if "$PELOID" plan scenes/quickstart.cfg --target 1% > "$T/plan.txt" 2> "$T/plan.err" && /usr/bin/python3 - "$T/plan.txt" <<'PY'
import math, re, sys
t = open(sys.argv[1]).read()
rows = {m.group(1): m.group(0) for m in re.finditer(r"(?m)^   (I|II|potential) +[0-9.]+ .*$", t)}
assert set(rows) == {"I", "II", "potential"}, rows
assert "<- this scene" in rows["II"] and "(this scene)" in rows["II"] and "done (shipped)" in rows["II"], rows["II"]
assert re.search(r"\b0\.79 \(1 shipped\)", rows["I"]), rows["I"]
assert 'recommended: coupling I (coarse_graining.coupling = "I")' in t, t
assert "cheapest: coupling II" in t, t
rh = float(re.search(r"R_h = ([0-9.e+-]+) um, this scene.s calibration\)", t).group(1))
need = float(re.search(r"below the target \(1 %\) from L >= ([0-9.e+-]+) um", t).group(1))
assert abs(need - 2.837 * rh / 0.01) < 1e-3 * need, (need, rh)
se = 0.35 / math.sqrt(173)
k = math.ceil((se / 0.01) ** 2)
assert k == 8 and f"peloid run scenes/quickstart.cfg --replicas {k}" in t, t
assert "settling velocity" in t and 'observable = "rdf_peak"' in t, t
PY
then ok "plan quickstart --target 1%: three couplings with R_h/R, this scene's II marked, I recommended, II cheapest, box L >= 2.837 R_h / 1 %, 8 replicas"
else bad "plan quickstart: $(head -3 "$T/plan.err")"; sed 's/^/    /' "$T/plan.txt" | head -20; fi
"$PELOID" plan scenes/quickstart.cfg --target 0.05 > "$T/p5.txt" 2>&1 && grep -q "one run meets the target" "$T/p5.txt" \
  && ! grep -q -- "--replicas" "$T/p5.txt" && ok "plan --target 0.05: one run of 173 colloids (2.7 %) meets it" \
  || bad "plan --target 0.05: $(grep 'Run length' "$T/p5.txt")"

# the matched resolution (src/app/advise_match.c): coupling I in Hecht's fluid (hecht_table1) reads the law of
# calibration/rh_resolution-c1_hecht.json and names the cell size at R_h/R = 0.95 (checked here from the file's
# b and c); the default fluid of a physical coupling I scene names its study and why it has no match; a fluid
# no study measured says so; coupling II says the matched mode is coupling I's
"$PELOID" plan scenes/hecht_table1.cfg --target 5% > "$T/h.txt" 2>&1
if /usr/bin/python3 - "$T/h.txt" calibration/rh_resolution-c1_hecht.json <<'PY'
import json, re, sys
t, d = open(sys.argv[1]).read(), json.load(open(sys.argv[2]))
m = re.search(r"study c1_hecht: .*\n +R_h/R = 0\.95 at R = ([0-9.]+) \+- [0-9.e-]+ a0: coarse_graining.cell_size = ([0-9.]+)", t)
assert m, t
law = d["law"]
R = law["c"] / (1 / 0.95 - 1 - law["b"])
assert abs(float(m.group(1)) - R) < 0.01 * R and abs(float(m.group(2)) - 1 / R) < 0.01 / R, (m.groups(), R)
PY
then ok "plan hecht_table1: matched R_h = R at the law's R/a0 (calibration/rh_resolution-c1_hecht.json)"
else bad "plan hecht_table1 matched: $(grep -A1 matched "$T/h.txt" | head -3)"; fi
# the run at that resolution (rule R8, tools/rh_matched.py: the law file's "check") printed beside it,
# as the file has it
if /usr/bin/python3 - "$T/h.txt" calibration/rh_resolution-c1_hecht.json <<'PY'
import json, re, sys
t, c = open(sys.argv[1]).read(), json.load(open(sys.argv[2]))["check"]["points"][0]
m = re.search(r"\n +run at R = ([0-9.]+) a0: R_h/R = ([0-9.]+) \+- ([0-9.]+), (matched|not matched)", t)
assert m, t
assert (float(m.group(1)), m.group(4)) == (c["R_over_a0"], c["verdict"]), m.groups()
assert abs(float(m.group(2)) - c["rh_over_R"]) < 6e-4 and abs(float(m.group(3)) - c["rh_over_R_se"]) < 6e-4, m.groups()
PY
then ok "plan hecht_table1: the run at the matched resolution and its verdict (the law file's check)"
else bad "plan hecht_table1 run at the matched resolution: $(grep -A2 'R_h/R = 0.95' "$T/h.txt" | head -3)"; fi
grep -v -e '^srd:' -e 'particles_per_cell' -e 'mean_free_path' scenes/hecht_table1.cfg > "$T/default_fluid.cfg"
sed 's/particles_per_cell = 2.5;/particles_per_cell = 3.0;/' scenes/hecht_table1.cfg > "$T/other_fluid.cfg"
"$PELOID" plan "$T/default_fluid.cfg" --target 5% --calibrate never > "$T/d.txt" 2>&1
"$PELOID" plan "$T/other_fluid.cfg" --target 5% --calibrate never > "$T/o.txt" 2>&1
if grep -q "study c1_default: R_h/R = " "$T/d.txt" && grep -q "no matched resolution: the accepted law's offset" "$T/d.txt" \
   && grep -q "no resolution law measured for this scene's fluid" "$T/o.txt" \
   && grep -q "matched R_h = R: measured for coupling I only" "$T/p5.txt"; then
  ok "plan: the default fluid names its study and why it has no matched resolution; an unmeasured fluid and coupling II say so"
else bad "plan matched lines: $(grep matched "$T/d.txt" "$T/o.txt" "$T/p5.txt" | head -4)"; fi

for a in "--target 0" "--target -5%" "--target abc" "--target 60%" "--target 0.6" "--target 5%%" "--target" ""; do
  # shellcheck disable=SC2086
  "$PELOID" plan scenes/quickstart.cfg $a > "$T/out" 2> "$T/err"; rc=$?
  if [ $rc = 2 ] && [ ! -s "$T/out" ] && [ "$(grep -c 'peloid: error:' "$T/err")" = 1 ] && grep -q -- "--target" "$T/err"
  then ok "plan quickstart ${a:-(no --target)}: refused (exit 2, one line naming --target)"
  else bad "plan quickstart $a: rc $rc: $(head -2 "$T/err")"; fi
done
"$PELOID" plan scenes/fluid.cfg --target 5% > "$T/out" 2> "$T/err"; rc=$?
if [ $rc = 2 ] && grep -q "scenes/fluid.cfg has no physical{} suspension" "$T/err"; then
  ok "plan of a model-unit scene: refused (exit 2): $(head -c 120 "$T/err")"
else bad "plan fluid.cfg: rc $rc: $(head -2 "$T/err")"; fi
echo "  plan tests: $pass passed, $fail failed"
[ $fail = 0 ]
