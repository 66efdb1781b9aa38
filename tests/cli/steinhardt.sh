#!/usr/bin/env bash
# The Steinhardt observer through bin/peloid (src/observe/obs_steinhardt.c;
# the analytic lattice and ideal-gas values are tests/unit/test_steinhardt.c):
#  - free Brownian colloids (no pair terms: an ideal gas): observables.h5
#    /observables/colloid_steinhardt holds Q4, Q6, the mean local q4, q6 with
#    their SE and each colloid's q4, q6; summary.json steinhardt_Q6 etc. carry
#    value, stderr > 0 and se_vs_time at 1/8, 1/4, 1/2, 1 of the run; the
#    global Q6 of an ideal gas is noise, ~1/sqrt(bonds) (about 0.1 here:
#    64 colloids with ~4 neighbours each, bound 0.3), below the mean local
#    q6 (few neighbours: large);
#  - 400 steps == 200 + restart + 200, bitwise (observables.h5, summary.json
#    values, checkpoint);
#  - stop.observable = "steinhardt_Q6" is a choice (generated from the
#    observers' estimates); a wrong name is refused (exit 2) with the list;
#  - a run in which no pair ever comes within range (8 colloids at rest on
#    a lattice of spacing 8, steinhardt_rmax = rdf_rmax = 3) ends with exit
#    0, one stderr warning per observer naming its interval key, and
#    summary.json "observables" "not_measured" naming both, without
#    steinhardt_* or rdf_peak (the cut-offs below contact and one colloid
#    are refused at check: tests/bad_scenes/steinhardt_*.cfg).
set -u
PELOID=$(realpath "${1:-bin/peloid}")
PY=/usr/bin/python3
T=$(mktemp -d /tmp/peloid-steinhardt.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
echo "== Steinhardt observer tests"
cat > q.cfg <<'CFG'
name = "q6";
seed = 5;
steps = 400;
box: { cells = [16, 16, 16]; };
fluid: { density = 0.0; };
srd: { dt = 0.1; };
colloids: { count = 64; radius = 1.0; mass_density = 1.0; temperature = 1.0; init = "random";
  pairs = ""; integrator = "brownian"; bd_viscosity = 0.02; substeps = 1; max_overlap = 1.0; };
observe: { steinhardt_interval = 5; steinhardt_rmax = 4.0; };
CFG
if "$PELOID" run q.cfg --out full 2> err && out=$($PY - <<'PY'
import json, h5py, numpy as np
s = json.load(open("full/summary.json"))["observables"]
for k in ("steinhardt_Q4", "steinhardt_Q6", "steinhardt_q4_mean", "steinhardt_q6_mean"):
    e = s[k]
    assert e["stderr"] > 0 and np.isfinite(e["value"]), (k, e)
    assert [p["run_fraction"] for p in e["se_vs_time"]] == [0.125, 0.25, 0.5, 1.0], (k, e["se_vs_time"])
Q6, q6 = s["steinhardt_Q6"]["value"], s["steinhardt_q6_mean"]["value"]
assert 0 < Q6 < 0.3 and Q6 < q6, (Q6, q6)
with h5py.File("full/observables.h5") as f:
    g = f["observables/colloid_steinhardt"]
    assert list(g["l"][:]) == [4, 6] and g["q_last"].shape == (64, 2) and g["samples"][()] == 81
    assert np.allclose(g["Q"][:], [s["steinhardt_Q4"]["value"], Q6], rtol=0, atol=0)
    assert g["Q_se"][1] == s["steinhardt_Q6"]["stderr"]
print(f"Q6 = {Q6:.4f} +- {s['steinhardt_Q6']['stderr']:.4f}, mean local q6 = {q6:.4f}, 81 samples")
PY
); then ok "ideal gas: $out"; else bad "ideal gas: ${out:-$(tail -1 err)}"; fi

if "$PELOID" run q.cfg --steps 200 --out half 2> /dev/null &&
   "$PELOID" run q.cfg --steps 200 --restart half/checkpoint.h5 --out res 2> /dev/null &&
   cmp -s full/checkpoint.h5 res/checkpoint.h5 && out=$($PY - <<'PY'
import json, h5py, numpy as np
def walk(p):
    out = {}
    with h5py.File(p) as f:
        f.visititems(lambda n, o: out.__setitem__(n, o[()]) if isinstance(o, h5py.Dataset) else None)
    return out
A, B = walk("full/observables.h5"), walk("res/observables.h5")
assert A.keys() == B.keys() and all(np.array_equal(A[k], B[k], equal_nan=True) for k in A)
CLOCK = {"wall_s", "wall_s_for_target", "resumed", "reason"}
def strip(x):
    if isinstance(x, dict): return {k: strip(v) for k, v in x.items() if k not in CLOCK}
    if isinstance(x, list): return [strip(v) for v in x]
    return x
a, b = (strip(json.load(open(d + "/summary.json"))["observables"]) for d in ("full", "res"))
assert a == b
print(f"{len(A)} datasets, {len(a)} summary entries")
PY
); then ok "restart: 400 steps == 200 + restart + 200, bitwise (checkpoint too): $out"
else bad "restart: ${out:-run failed}"; fi

{ cat q.cfg; echo 'stop: { observable = "steinhardt_Q6"; rel_error = 0.5; check_interval = 50; };'; } > stop.cfg
{ cat q.cfg; echo 'stop: { observable = "steinhardt_Q8"; };'; } > wrong.cfg
"$PELOID" run wrong.cfg --out wrong 2> wrong.err; rc=$?
if "$PELOID" run stop.cfg --out stop 2> /dev/null &&
   $PY -c 'import json; s = json.load(open("stop/summary.json"))["stop"]; assert "steinhardt_Q6" in s["reason"], s' &&
   [ $rc -eq 2 ] && [ ! -e wrong ] && grep -q 'stop.observable.*"steinhardt_Q8".*allowed: .*"steinhardt_Q6"' wrong.err
then ok "stop.observable: steinhardt_Q6 a choice; a wrong name refused: $(head -c 160 wrong.err)..."
else bad "stop.observable: rc $rc $(cat wrong.err)"; fi
cat > none.cfg <<'CFG'
name = "none";
steps = 40;
box: { cells = [16, 16, 16]; };
fluid: { density = 0.0; };
srd: { dt = 0.1; };
colloids: { count = 8; radius = 1.0; temperature = 0.0; init = "lattice"; pairs = ""; };
observe: { steinhardt_interval = 5; steinhardt_rmax = 3.0; rdf_interval = 5; rdf_rmax = 3.0; };
CFG
"$PELOID" run none.cfg --out none 2> none.err; rc=$?
if [ $rc -eq 0 ] && [ "$(grep -c '^peloid: warning: observe\.\(steinhardt\|rdf\)_interval: .* measured nothing' none.err)" -eq 2 ] &&
   $PY - <<'PY'
import json
s = json.load(open("none/summary.json"))["observables"]
assert set(s["not_measured"]) == {"observe.steinhardt_interval", "observe.rdf_interval"}, s
assert not [k for k in s if k.startswith("steinhardt_") or k == "rdf_peak"], s
PY
then ok "no pair ever in range: exit 0, warned, summary.json not_measured: $(grep -o 'Steinhardt observer.*' none.err | head -c 150)..."
else bad "no pair ever in range: rc $rc $(head -c 600 none.err)"; fi
echo "steinhardt.sh: $pass passed, $fail failed"
[ $fail -eq 0 ]
