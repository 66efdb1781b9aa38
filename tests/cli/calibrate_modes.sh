#!/usr/bin/env bash
# --calibrate never|auto|always (src/app/calibrate_mode.c, src/app/calibrate.c).
# The calibrating scene is tests/cli/calibration_cache.sh's coarse coupling II
# scene (320 steps of a 16^3 box, ~0.3 s), with output.progress_s = 0.02 so
# that its calibration prints progress lines; PELOID_CACHE is a fresh folder
# and PELOID_NO_SHIPPED_CALIBRATION=1, so nothing is stored before the suite.
#  1. never: check, params and run of a scene with no calibration exit 0 at
#     once (< 5 s) and store nothing; params (text, --json), the run's log
#     and summary.json "calibration" name mode never, source theory and the
#     coupling's relative error; the potential coupling at a density no
#     calibration was made for checks in < 5 s, with --calibrate never and
#     with check's default (stored: nothing measured or stored, the theory's
#     error stated and that run calibrates first; it calibrated for 50 s
#     before), and check reads a calibration the cache has;
#  2. auto, empty cache: a calibration runs, prints its estimated duration
#     before it starts and progress lines (percent, elapsed, ETA); stored;
#     auto again reads the cache (no calibration, source "cache", same D);
#  3. always: recalibrates with the entry present (the entry rewritten:
#     its wall_s changes; D bitwise the same, calibrations are
#     deterministic); a run with always and with auto give the same
#     thermo.tsv bits, and never another t0, marked;
#  4. a bad value (--calibrate sometimes, or none) for run, check, params and
#     sweep: exit 2, one line naming --calibrate and the allowed values,
#     nothing written;
#  5. sweep --calibrate never reaches its points' runs (summary.json of the
#     point) and the Slurm script;
#  6. the theory's stated error: the ratios of src/app/calibrate_mode.c
#     equal measured / theory of `peloid params --json` of the scenes named
#     there (shipped calibrations), and the relative error never states is
#     their RMS per coupling;
#  7. a hand-typed time-unit key (colloids.substeps) that no colloid D from
#     1/10 to 10 times the theory derives: run --calibrate auto exits 2 in
#     < 5 s with one line, before any calibration (the binary of 162a85d
#     calibrated first: progress lines, a cache entry), and a calibrated
#     run folder's echo still loads.
# Shown to fail before --calibrate existed (cases 1-5: the option is
# refused as unknown; 2: no estimate, no progress lines; 6: no
# "calibration" object).
set -u
PELOID=$(realpath "${1:-bin/peloid}")
PY=/usr/bin/python3
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
T=$(mktemp -d /tmp/peloid-calmodes.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
echo "== --calibrate never|auto|always"
export PELOID_NO_SHIPPED_CALIBRATION=1 PELOID_CACHE="$T/cache"

cat > s.cfg <<CFG
name = "modes";
seed = 7;
steps = 4;
output: { progress_s = 0.02; };
$(cat "$ROOT/tests/support/calibration_coarse_ii.inc")
CFG
# cal FILE KEY: summary.json / params --json "calibration" KEY (repr; "-" when absent)
cal() { $PY -c "import json,sys; print(repr(json.load(open(sys.argv[1])).get('calibration',{}).get(sys.argv[2],'-')))" "$1" "$2" 2>/dev/null || echo "-"; }
entry() { ls "$T"/cache/calibration-*.json 2>/dev/null | head -1; }
field() { $PY -c "import json,sys; print(repr(json.load(open(sys.argv[1]))[sys.argv[2]]))" "$1" "$2" 2>/dev/null; }
now() { date +%s.%N; }
nowall() { awk -F'\t' -v OFS='\t' '{NF--; print}' "$1"; } # thermo.tsv less its last column, mupdates_per_s (wall time)
fast() { $PY -c "import sys; sys.exit(0 if float(sys.argv[2]) - float(sys.argv[1]) < 5 else 1)" "$1" "$2"; }

# 1. never
a=$(now); "$PELOID" check s.cfg --calibrate never > n.out 2> n.err; rc=$?; b=$(now)
if [ $rc = 0 ] && fast "$a" "$b" && [ -z "$(entry)" ] && ! grep -q "calibrating" n.err \
   && grep -q "calibration: --calibrate never: .*theory.*relative error 1" n.err; then
  ok "check --calibrate never: exit 0 in $($PY -c "print(round($b - $a, 2))") s, nothing stored, the error stated"
else bad "check --calibrate never: rc $rc, entry '$(entry)': $(tr '\n' '|' < n.err | cut -c1-300)"; fi
"$PELOID" params s.cfg --calibrate never > np.txt 2> np.err; rc=$?
"$PELOID" params --json s.cfg --calibrate never > np.json 2>> np.err; rc2=$?
if [ $rc = 0 ] && [ $rc2 = 0 ] && grep -q "calibration: --calibrate never" np.txt && grep -q "theory (PL Eqs. 39-41, --calibrate never)" np.txt \
   && [ "$(cal np.json mode)" = "'never'" ] && [ "$(cal np.json source)" = "'theory'" ] \
   && [ "$(cal np.json relative_error | cut -c1-5)" = "1.010" ]; then
  ok "params (text, --json) mark never: source theory, relative error $(cal np.json relative_error)"
else bad "params never: rc $rc/$rc2 mode $(cal np.json mode) source $(cal np.json source): $(tail -2 np.err)"; fi
"$PELOID" run s.cfg --calibrate never --out rn --threads 1 > rn.log 2>&1; rc=$?
if [ $rc = 0 ] && [ "$(cal rn/summary.json mode)" = "'never'" ] && [ "$(cal rn/summary.json source)" = "'theory'" ] \
   && grep -q "^peloid: calibration: --calibrate never" rn.log && [ -z "$(entry)" ]; then
  ok "run --calibrate never: summary.json calibration {mode never, source theory}, the log line"
else bad "run never: rc $rc mode $(cal rn/summary.json mode): $(tail -2 rn.log)"; fi
sed 's/particle_density = 1.0e3;/particle_density = 1.05e3;/; s/name = "pl_potential_physical"/name = "pot"/' \
  "$ROOT/scenes/pl_potential_physical.cfg" > pot.cfg
a=$(now); "$PELOID" check pot.cfg --calibrate never > pot.out 2> pot.err; rc=$?; b=$(now)
if [ $rc = 0 ] && fast "$a" "$b" && grep -q "relative error 0.13" pot.err && [ -z "$(entry)" ]; then
  ok "potential coupling at a new density: check --calibrate never in $($PY -c "print(round($b - $a, 2))") s (error 0.13 stated)"
else bad "potential never: rc $rc: $(tr '\n' '|' < pot.err | cut -c1-300)"; fi
# check's default (stored): a new suspension is checked at once with the theory and its error, nothing
# measured or stored, and the user told that run calibrates first (before: check calibrated, 50 s here)
a=$(now); "$PELOID" check pot.cfg > pd.out 2> pd.err; rc=$?; b=$(now)
if [ $rc = 0 ] && fast "$a" "$b" && [ -z "$(entry)" ] && ! grep -q "calibrating" pd.err \
   && grep -q "calibration: --calibrate stored, none stored for this model: .*theory.*relative error 0.13.*peloid run. measures the calibration first" pd.err; then
  ok "check (default stored) of the potential coupling at a new density: $($PY -c "print(round($b - $a, 2))") s, the theory's error 0.13 stated, run calibrates first"
else bad "check default: rc $rc, entry '$(entry)': $(tr '\n' '|' < pd.err | cut -c1-300)"; fi

# 2. auto: a calibration with its estimate and progress, then the cache
"$PELOID" params --json s.cfg > a1.json 2> a1.err; rc=$?
E=$(entry); D=$(field "$E" d_inf); W=$(field "$E" wall_s)
est=$(grep -n "calibration: the first .* steps took .* estimated duration" a1.err | head -1 | cut -d: -f1)
prog=$(grep -n "calibration: step [0-9]*/[0-9]* *[0-9.]*%  elapsed .*ETA" a1.err | head -1 | cut -d: -f1)
if [ $rc = 0 ] && [ -n "$E" ] && [ -n "$est" ] && [ -n "$prog" ] && [ "$est" -lt "$prog" ] \
   && [ "$(cal a1.json mode)" = "'auto'" ] && [ "$(cal a1.json source)" = "'calibration run'" ]; then
  ok "auto, empty cache: calibrated and stored; estimate first: $(sed -n "${est}p" a1.err | cut -c1-110)...; $(grep -c 'calibration: step' a1.err) progress line(s)"
else bad "auto calibration: rc $rc entry '$E' estimate line '$est' progress line '$prog': $(tr '\n' '|' < a1.err | cut -c1-400)"; fi
"$PELOID" params --json s.cfg --calibrate auto > a2.json 2> a2.err; rc=$?
if [ $rc = 0 ] && ! grep -q "calibrating" a2.err && [ "$(cal a2.json source)" = "'cache'" ] \
   && [ "$(cal a2.json d_a0_2_t0)" = "$(cal a1.json d_a0_2_t0)" ] && [ "$(field "$E" wall_s)" = "$W" ]; then
  ok "auto again: read from the cache (no calibration; D $(cal a2.json d_a0_2_t0))"
else bad "auto cached: rc $rc source $(cal a2.json source): $(tr '\n' '|' < a2.err | cut -c1-300)"; fi
"$PELOID" check s.cfg > sd.out 2> sd.err; rc=$?
if [ $rc = 0 ] && ! grep -q "calibrating" sd.err && grep -q "calibration: --calibrate stored: the colloid D measured, .*read from the cache" sd.err; then
  ok "check (default stored) with the calibration in the cache: reads it"
else bad "check stored cached: rc $rc: $(tr '\n' '|' < sd.err | cut -c1-300)"; fi

# 3. always: a fresh calibration over the entry, the same bits
sleep 0.05
"$PELOID" params --json s.cfg --calibrate always > w.json 2> w.err; rc=$?
if [ $rc = 0 ] && grep -q "calibrating .*--calibrate always" w.err && [ "$(cal w.json source)" = "'calibration run'" ] \
   && [ "$(cal w.json mode)" = "'always'" ] && [ "$(field "$E" wall_s)" != "$W" ] && [ "$(field "$E" d_inf)" = "$D" ] \
   && [ "$(cal w.json d_a0_2_t0)" = "$(cal a1.json d_a0_2_t0)" ]; then
  ok "always: recalibrated over the cached entry (wall_s $W -> $(field "$E" wall_s)), D bitwise the same ($D)"
else bad "always: rc $rc source $(cal w.json source) wall_s $W -> $(field "$E" wall_s) D $D -> $(field "$E" d_inf): $(tail -2 w.err)"; fi
"$PELOID" run s.cfg --calibrate always --out rw --threads 1 > rw.log 2>&1; rc=$?
"$PELOID" run s.cfg --out ra --threads 2 > ra.log 2>&1; rc2=$?
t_n=$(field rn/summary.json units_si | $PY -c "import sys,ast; print(ast.literal_eval(sys.stdin.read())['t0_s'])")
t_a=$(field ra/summary.json units_si | $PY -c "import sys,ast; print(ast.literal_eval(sys.stdin.read())['t0_s'])")
if [ $rc = 0 ] && [ $rc2 = 0 ] && [ -s rw/thermo.tsv ] && cmp -s <(nowall rw/thermo.tsv) <(nowall ra/thermo.tsv) && [ "$(cal ra/summary.json source)" = "'cache'" ] \
   && [ "$(cal rw/summary.json mode)" = "'always'" ] && [ -n "$t_n" ] && [ "$t_n" != "$t_a" ]; then
  ok "run always (1 thread) and auto (2 threads, cached): thermo.tsv bitwise equal (less the wall-time column); never's t0 $t_n s differs from $t_a s"
else bad "runs: rc $rc/$rc2, thermo equal: $(cmp -s <(nowall rw/thermo.tsv) <(nowall ra/thermo.tsv) && echo yes || echo no), t0 $t_n / $t_a"; fi

# 4. a bad value: exit 2, one line, nothing written
for c in "run s.cfg --out bad --calibrate sometimes" "check s.cfg --calibrate sometimes" \
         "params s.cfg --calibrate sometimes" "params --json s.cfg --calibrate" "sweep study.cfg --calibrate sometimes"; do
  "$PELOID" $c > b.out 2> b.err; rc=$?
  if [ $rc = 2 ] && [ "$(wc -l < b.err)" = 1 ] && grep -q -- "--calibrate .*allowed: never, auto, always" b.err \
     && [ ! -s b.out ] && [ ! -e bad ]; then
    ok "$(echo "$c" | cut -d' ' -f1) ...: exit 2: $(cat b.err)"
  else bad "'$c': rc $rc: $(tr '\n' '|' < b.err)"; fi
done

# 5. sweep passes the mode to its points' runs (and the Slurm script)
cat > study.cfg <<'CFG'
name = "modes_sweep";
scene = "s.cfg";
out = "out/sweep";
grid = ( { key = "seed"; values = [3]; } );
CFG
"$PELOID" sweep study.cfg --calibrate never --jobs 1 --threads 1 > sw.log 2>&1; rc=$?
S=$(ls out/sweep/*/summary.json 2>/dev/null | head -1)
"$PELOID" sweep study.cfg --calibrate never --slurm --out slurm > sl.log 2>&1; rc2=$?
if [ $rc = 0 ] && [ -n "$S" ] && [ "$(cal "$S" mode)" = "'never'" ] && [ -z "$(ls "$T"/cache/*.json | grep -v "$E")" ] \
   && [ $rc2 = 0 ] && grep -q -- "--calibrate never$" slurm/sweep.sbatch; then
  ok "sweep --calibrate never: the point's summary.json marks never; the Slurm script passes it"
else bad "sweep: rc $rc/$rc2 summary '$S' mode $(cal "$S" mode): $(tail -2 sw.log) $(tail -1 sl.log)"; fi

# 6. the theory's stated error rests on the shipped calibrations
unset PELOID_NO_SHIPPED_CALIBRATION
if $PY - "$PELOID" "$ROOT" <<'PY'
import json, math, re, subprocess, sys
peloid, root = sys.argv[1], sys.argv[2]
src = open(root + "/src/app/calibrate_mode.c").read()
rows = re.findall(r'\{PL_COUPLE_(\w+), "([0-9a-f]{16})", "([^"]+)", ([0-9.]+)\}', src)
assert len(rows) >= 3, rows
by = {}
for method, key, scene, ratio in rows:
    d = json.loads(subprocess.run([peloid, "params", "--json", root + "/" + scene], capture_output=True, text=True,
                                  check=True, cwd=root).stdout)
    cd, c = d["mapping"]["colloid_diffusion"], d["calibration"]
    assert c["source"] == "shipped" and c["file"].endswith(key + ".json"), (scene, c)
    r = cd["calibration"]["d_inf_a0_2_t0"] / cd["d_theory_a0_2_t0"]
    assert abs(r / float(ratio) - 1) < 1e-6, (scene, r, ratio)
    by.setdefault(method, []).append((r, scene))
for method, rs in by.items():
    rms = math.sqrt(sum((r - 1) ** 2 for r, _ in rs) / len(rs))
    d = json.loads(subprocess.run([peloid, "params", "--json", root + "/" + rs[0][1], "--calibrate", "never"],
                                  capture_output=True, text=True, check=True, cwd=root).stdout)["calibration"]
    assert d["source"] == "theory" and abs(d["relative_error"] / rms - 1) < 1e-5, (method, d, rms)
    print("    coupling %s: measured/theory %s, stated error %.3g" % (method, ", ".join("%.4f" % r for r, _ in rs), rms))
PY
then ok "the stated theory errors equal the RMS of measured/theory - 1 over the shipped calibrations"
else bad "the theory error table does not match the shipped calibrations"; fi

# 7. a time-unit key given outside what any colloid D from 1/10 to 10 times the
#    theory derives is refused before the calibration runs (it was refused
#    only after it, its progress lines first); its run folder's echo, with
#    the calibrated value, still loads
export PELOID_NO_SHIPPED_CALIBRATION=1 PELOID_CACHE="$T/cache7"
sed 's/colloids: { init = "lattice"; pairs = "hertz"; };/colloids: { init = "lattice"; pairs = "hertz"; substeps = 1000; };/' \
  s.cfg > tu.cfg
t1=$(now); "$PELOID" run tu.cfg --out tu_out --calibrate auto > tu.log 2>&1; rc=$?; t2=$(now)
if [ $rc = 2 ] && [ "$(wc -l < tu.log)" = 1 ] && grep -q "tu.cfg:[0-9]*: key 'colloids.substeps': 1000 .*between" tu.log &&
   ! grep -q "calibration:" tu.log && [ ! -e tu_out ] && [ -z "$(ls "$T/cache7" 2>/dev/null)" ] && fast "$t1" "$t2"; then
  ok "a hand-typed colloids.substeps no calibration could derive: exit 2 at once, one line, nothing calibrated or written"
else bad "substeps = 1000 (rc $rc): $(head -c 400 tu.log)"; fi
if "$PELOID" run s.cfg --out plain_out --calibrate auto > plain.log 2>&1 &&
   "$PELOID" check plain_out/scene.cfg --calibrate auto > echo.log 2>&1; then
  ok "the run folder's echo (the calibrated time-unit keys in it) loads"
else bad "echo of a calibrated run: $(tail -1 plain.log) / $(tail -1 echo.log)"; fi

echo "calibrate modes: $pass passed, $fail failed"
[ $fail = 0 ]
