#!/usr/bin/env bash
# CLI behaviour of bin/peloid (issue 2): exit codes, one-line errors naming
# file, line and key, nothing written on bad input, outputs readable, and
# bitwise determinism through the real files (threads, restart).
set -u
PELOID=$(realpath "${1:-bin/peloid}")
ROOT=$(realpath "$(dirname "$0")/../..")
PY=/usr/bin/python3
T=$(mktemp -d /tmp/peloid-cli.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }

# expect_refused NAME SCENE_TEXT NEEDLE...: exit 2, one line naming NEEDLEs, no out/
expect_refused() {
  local name=$1 text=$2; shift 2
  printf '%b' "$text" > "$name.cfg"
  "$PELOID" run "$name.cfg" --out "out_$name" 2> err.txt; local rc=$?
  local lines; lines=$(wc -l < err.txt)
  local okk=1
  [ $rc -eq 2 ] || okk=0
  [ "$lines" -eq 1 ] || okk=0
  for n in "$@"; do grep -qF -- "$n" err.txt || okk=0; done
  [ ! -e "out_$name" ] || okk=0
  if [ $okk = 1 ]; then ok "$name refused: $(cat err.txt)"; else bad "$name (rc=$rc, out exists: $([ -e out_$name ] && echo yes || echo no)): $(cat err.txt)"; fi
}

echo "== peloid CLI tests"
"$PELOID" --help > help.txt; rc=$?
if [ $rc -eq 0 ] && grep -q -- "--restart" help.txt && grep -q "params SCENE" help.txt; then ok "--help"; else bad "--help"; fi
"$PELOID" > /dev/null 2>&1; [ $? -eq 2 ] && ok "no command -> exit 2" || bad "no command"
"$PELOID" frobnicate 2> err.txt; [ $? -eq 2 ] && grep -q "unknown command" err.txt && ok "unknown command" || bad "unknown command"

GOOD='name = "small";\nseed = 9;\nsteps = 40;\nbox: { cells = [6, 6, 6]; };\nfluid: { density = 5.0; };\nsrd: { dt = 0.5; };\noutput: { thermo_interval = 10; fields_interval = 5; };\n'
printf '%b' "$GOOD" > small.cfg
"$PELOID" check small.cfg > /dev/null && ok "check accepts a good scene" || bad "check good scene"

expect_refused unknown_key 'seed = 1;\nfluid: { densty = 5.0; };\n' "unknown_key.cfg:2" "fluid.densty" "unknown key"
expect_refused wrong_type 'fluid: {\n  density = "five";\n};\n' "wrong_type.cfg:2" "fluid.density" "wrong type"
expect_refused negative_density 'fluid: { density = -1.0; };\n' "negative_density.cfg:1" "fluid.density" "out of range"
expect_refused zero_cells 'box: { cells = [8, 0, 8]; };\n' "zero_cells.cfg:1" "box.cells" "out of range"
expect_refused syntax 'box: { cells = [8, 8, 8] ;\n' "syntax.cfg" "syntax error"
"$PELOID" run missing.cfg --out out_missing 2> err.txt; rc=$?
[ $rc -eq 2 ] && grep -q "missing.cfg: cannot open scene file" err.txt && [ ! -e out_missing ] && ok "missing scene file" || bad "missing scene file: $(cat err.txt)"
"$PELOID" run small.cfg --steps x 2> err.txt; [ $? -eq 2 ] && ok "bad --steps" || bad "bad --steps"
"$PELOID" run small.cfg --threads 0 2> err.txt; [ $? -eq 2 ] && ok "bad --threads" || bad "bad --threads"
"$PELOID" run small.cfg --bogus 2> err.txt; [ $? -eq 2 ] && ok "unknown option" || bad "unknown option"

# a run and its outputs
"$PELOID" run small.cfg --out run1 --threads 1 2> log.txt
if [ $? -eq 0 ] && [ -s run1/thermo.tsv ] && [ -s run1/summary.json ] && [ -s run1/checkpoint.h5 ] && [ -s run1/fields.h5 ] && [ -s run1/scene.cfg ]; then
  ok "run writes thermo.tsv summary.json checkpoint.h5 fields.h5 scene.cfg"; else bad "run outputs: $(cat log.txt)"; fi
$PY - <<'PYEOF' && ok "outputs parse (json, tsv, h5py H5MD fields)" || bad "outputs parse"
import json, h5py, numpy as np
s = json.load(open("run1/summary.json"))
assert s["threads"] == 1 and s["last_step"] == 40 and s["particle_updates_per_second"] > 0
assert abs(s["derived"]["lambda"] - 0.5) < 1e-12
rows = np.loadtxt("run1/thermo.tsv", skiprows=1)
assert rows.shape[0] == 5 and rows[-1, 0] == 40
with h5py.File("run1/fields.h5") as f:
    assert tuple(f["h5md"].attrs["version"]) == (1, 1)
    rho = f["observables/fluid_density/value"][()]
    assert rho.shape == (1, 6, 6, 6) and abs(rho.mean() - 5.0) < 1e-9
    assert f["observables/fluid_velocity/value"].shape == (1, 6, 6, 6, 3)
with h5py.File("run1/checkpoint.h5") as f:
    assert f["fluid/x"].shape == (1080,)
PYEOF
before=$(md5sum run1/thermo.tsv)
"$PELOID" run small.cfg --out run1 2> err.txt; rc=$?
[ $rc -eq 2 ] && grep -q "exists; use --force" err.txt && [ "$(md5sum run1/thermo.tsv)" = "$before" ] && ok "existing output directory refused, untouched" || bad "existing out dir: $(cat err.txt)"
"$PELOID" run small.cfg --out run1 --force 2> err.txt && ok "--force writes into it" || bad "--force"

# output paths (issue 18): resolved before anything is created
mkdir victim && echo keep > victim/thermo.tsv
for f in "" --force; do
  "$PELOID" run small.cfg --out victim/newdir/.. $f 2> err.txt; rc=$?
  [ $rc -eq 2 ] && [ "$(cat victim/thermo.tsv)" = keep ] && [ ! -e victim/newdir ] && [ $(wc -l < err.txt) -eq 1 ] \
    && ok "--out victim/newdir/.. $f refused, victim untouched" || bad "--out victim/newdir/.. $f: rc $rc $(cat err.txt)"
done
"$PELOID" run small.cfg --out victim/. 2> err.txt; [ $? -eq 2 ] && grep -q "exists" err.txt && ok "--out victim/. refused: exists" || bad "--out victim/.: $(cat err.txt)"
"$PELOID" run small.cfg --out . --force 2> err.txt; [ $? -eq 2 ] && grep -q "working directory" err.txt && ok "--out . --force refused (holds the working directory)" || bad "--out . --force: $(cat err.txt)"
mkdir -p sc/deep && cp small.cfg sc/deep/s.cfg
"$PELOID" run sc/deep/s.cfg --out sc --force 2> err.txt; [ $? -eq 2 ] && grep -q "holds the scene" err.txt && [ ! -e sc/thermo.tsv ] && ok "--out <scene's ancestor> --force refused" || bad "--out scene ancestor: $(cat err.txt)"
long=$(printf 'd%.0s' $(seq 1 5000))
"$PELOID" run small.cfg --out "$long" 2> err.txt; [ $? -eq 2 ] && [ ! -e "${long:0:200}" ] && ok "--out of 5000 characters refused" || bad "long --out: $(cat err.txt)"
long=$(for i in $(seq 1 21); do printf 'e%.0s' $(seq 1 200); printf /; done)
"$PELOID" run small.cfg --out "lp/$long" 2> err.txt; [ $? -eq 2 ] && [ ! -e lp ] && ok "--out longer than PATH_MAX in 200-character names refused, nothing created" || bad "long --out path: $(cat err.txt)"
expect_refused dotdot_name 'name = "..";\nsteps = 1;\n' "dotdot_name.cfg:1" "'name'" '".."'
expect_refused quote_name 'name = "a\\"b";\n' "quote_name.cfg:1" "'name'" "[A-Za-z0-9._-]"
# integers in 64 bits (issue 18): libconfig 1.5 wraps values without L to 32 bits
printf 'seed = 4294967297;\nsteps = 0;\nbox: { cells = [4, 4, 4]; };\n' > wide.cfg
"$PELOID" run wide.cfg --out wide 2> err.txt && grep -q "^seed = 4294967297L;" wide/scene.cfg && ok "seed = 4294967297 kept in 64 bits" || bad "seed 4294967297: $(cat err.txt; grep seed wide/scene.cfg)"
expect_refused wrap_cells 'box: { cells = [4294967328, 32, 32]; };\n' "wrap_cells.cfg:1" "box.cells" "4294967328"
expect_refused wrap_count 'colloids: { count = 4294967360; };\n' "wrap_count.cfg:1" "colloids.count" "4294967360"
expect_refused huge_steps 'steps = 99999999999999999999;\n' "huge_steps.cfg:1" "'steps'" "99999999999999999999" "64-bit"
"$PELOID" run small.cfg --steps 99999999999999999999 --out hs 2> err.txt; [ $? -eq 2 ] && [ ! -e hs ] && ok "--steps 99999999999999999999 refused" || bad "--steps overflow: $(cat err.txt)"
# @include (issue 18): relative to the including file, inside the scene's tree
mkdir -p inc/sub && printf 'steps = 3;\n@include "sub/b.cfg"\n' > inc/a.cfg && printf '@include "c.cfg"\n' > inc/sub/b.cfg && printf 'seed = -3;\n' > inc/sub/c.cfg
"$PELOID" check inc/a.cfg 2> err.txt; [ $? -eq 2 ] && grep -q "inc/sub/c.cfg:1: key 'seed'" err.txt && ok "nested @include resolved relative to the including file; error names it" || bad "nested include: $(cat err.txt)"
printf '@include "../small.cfg"\n' > inc/up.cfg
"$PELOID" check inc/up.cfg 2> err.txt; [ $? -eq 2 ] && grep -q "outside" err.txt && ok "@include outside the scene's tree refused" || bad "include outside: $(cat err.txt)"
"$PELOID" check inc/up.cfg --allow-include-anywhere > /dev/null 2> err.txt && ok "--allow-include-anywhere accepts it" || bad "--allow-include-anywhere: $(cat err.txt)"

# determinism through the files: threads, and 2N == N + restart + N
"$PELOID" run small.cfg --out run2 --threads 2 2> /dev/null
cmp -s run1/checkpoint.h5 run2/checkpoint.h5 && ok "checkpoint bitwise identical for 1 and 2 threads" || bad "threads change the checkpoint"
cmp -s run1/fields.h5 run2/fields.h5 && ok "fields bitwise identical for 1 and 2 threads" || bad "threads change fields.h5"
"$PELOID" run small.cfg --out half --steps 20 2> /dev/null
"$PELOID" run small.cfg --out resumed --steps 20 --restart half/checkpoint.h5 --threads 2 2> /dev/null
cmp -s run1/checkpoint.h5 resumed/checkpoint.h5 && ok "40 steps == 20 + restart + 20, bitwise" || bad "restart is not bitwise"
"$PELOID" run small.cfg --out bad_restart --restart small.cfg 2> err.txt; rc=$?
[ $rc -eq 2 ] && [ ! -e bad_restart ] && ok "bad restart file refused, nothing written: $(cat err.txt)" || bad "bad restart: $(cat err.txt)"

# a scene in physical units: mapping report and SI columns in the outputs
"$PELOID" run "$ROOT/scenes/hecht_table1.cfg" --out mapped --steps 2 2> /dev/null
$PY - <<'PYEOF' && ok "physical-unit scene: summary.json has mapping + units_si, thermo.tsv has time_s, temperature_K = 300 K (real), model_temperature_K, c_zcm_m = c_zcm a0" || bad "mapped outputs"
import json
s = json.load(open("mapped/summary.json"))
assert s["mapping"] is not None and s["units_si"]["a0_m"] > 0 and s["units_si"]["t0_s"] > 0
head = open("mapped/thermo.tsv").readline().split()
assert head[:5] == ["step", "time", "time_s", "temperature_K", "model_temperature_K"], head
row = dict(zip(head, open("mapped/thermo.tsv").readlines()[-1].split()))
# temperature_K is the real one (kT = 1 <-> 300 K); the model's own is tiny (Hecht Sec. VII.B)
assert abs(float(row["temperature_K"]) / 300.0 - 1) < 0.02, row
assert float(row["model_temperature_K"]) < 0.01, row
# lengths and stresses have SI twins: c_zcm_m = c_zcm a0, s.._Pa = s.. kT_model/a0^3
a0 = s["units_si"]["a0_m"]
assert abs(float(row["c_zcm_m"]) / (float(row["c_zcm"]) * a0) - 1) < 1e-8, row
for k in [h for h in head if h.endswith("_Pa")]:
    assert k[:-3] in head, k
assert head[-1] == "mupdates_per_s", head
PYEOF

# a capillary (walls_xy): outputs name each axis' boundary, restart refused
# into another wall layout
printf 'seed = 8;\nsteps = 10;\nbox: { cells = [5, 6, 4]; walls_xy = "noslip"; };\nfluid: { body_force = [0.0, 0.0, 0.01]; };\noutput: { fields_interval = 2; };\n' > cap.cfg
"$PELOID" run cap.cfg --out cap --threads 1 2> log.txt && $PY - <<'PYEOF' && ok "capillary: boundaries in summary.json and fields.h5" || bad "capillary outputs: $(cat log.txt)"
import json, h5py
s = json.load(open("cap/summary.json"))
assert s["boundaries"] == {"x": "noslip", "y": "noslip", "z": "periodic"}, s["boundaries"]
assert s["scene"]["box"]["walls_xy"] == "noslip"
with h5py.File("cap/fields.h5") as f:
    a = f["observables"].attrs
    assert (a["boundary_x"], a["boundary_y"], a["boundary_z"]) == (b"noslip", b"noslip", b"periodic")
PYEOF
sed 's/walls_xy = "noslip"/walls_xy = "slip"/' cap.cfg > cap2.cfg
"$PELOID" run cap2.cfg --out cap2 --restart cap/checkpoint.h5 2> err.txt; rc=$?
[ $rc -eq 2 ] && grep -q "box.walls_xy" err.txt && ok "restart into another walls_xy refused" || bad "walls_xy restart: rc $rc $(cat err.txt)"
head -1 cap/thermo.tsv | grep -q "s_side_z" && ok "capillary thermo has the x/y walls' stress (s_side_z)" || bad "capillary thermo header: $(head -1 cap/thermo.tsv)"
# a capillary checkpoint from before the x/y walls' momentum was counted
cp cap/checkpoint.h5 old.h5 && $PY -c 'import h5py; f = h5py.File("old.h5", "a"); del f["side_wall_impulse"]; f.close()'
"$PELOID" run cap.cfg --out cap3 --restart old.h5 2> err.txt; rc=$?
[ $rc -eq 2 ] && grep -q "side_wall_impulse" err.txt && [ ! -e cap3 ] && ok "restart from a checkpoint without side_wall_impulse refused, nothing written" || bad "old capillary checkpoint: rc $rc $(cat err.txt)"

# the quickstart suspension (a few steps) and its plot
"$PELOID" run "$ROOT/scenes/quickstart.cfg" --out qs --steps 80 2> /dev/null
if [ $? -eq 0 ] && head -1 qs/thermo.tsv | grep -q "c_zcm" && \
   $PY "$ROOT/tools/plot_sediment.py" qs > plot.txt 2>&1 && [ -s qs/sediment.png ] && grep -q "Stokes" plot.txt; then
  ok "quickstart runs (80 steps), thermo has c_zcm, tools/plot_sediment.py draws qs/sediment.png"
else bad "quickstart / plot_sediment: $(tail -3 plot.txt 2>/dev/null)"; fi
# its real temperature: thermo temperature_K averages 300 K within 3 SE (rows
# after step 0; SE from the rows, at least the one-sample fluctuation
# 300 sqrt(2/(3 N_f)) / sqrt(rows) of the 34560 fluid particles)
qsT=$($PY - <<'PYEOF'
import math
rows = [l.split() for l in open("qs/thermo.tsv")]
k = rows[0].index("temperature_K")
T = [float(r[k]) for r in rows[2:]]
n = len(T); m = sum(T) / n
se = max(math.sqrt(sum((t - m) ** 2 for t in T) / (n - 1) / n), 300 * math.sqrt(2 / (3 * 34560)) / math.sqrt(n))
print("%.2f %.2f %d %s" % (m, se, n, "ok" if abs(m - 300) <= 3 * se else "bad"))
PYEOF
)
case "$qsT" in *ok) ok "quickstart temperature_K = ${qsT% * ok} (mean, SE, rows): 300 K within 3 SE";; *) bad "quickstart temperature_K: $qsT";; esac

# moving walls: only no-slip walls, moving in their own plane
expect_refused wall_slip 'box: { walls_z = "slip";\n  wall_velocity_top = [0.1, 0.0, 0.0]; };\n' "wall_slip.cfg:2" "box.wall_velocity_top" "noslip"
expect_refused wall_none 'box: { wall_velocity_bottom = [0.1, 0.0, 0.0]; };\n' "wall_none.cfg:1" "box.wall_velocity_bottom" "noslip"
expect_refused wall_z 'box: { walls_z = "noslip"; wall_velocity_top = [0.0, 0.0, 0.1]; };\n' "wall_z.cfg:1" "box.wall_velocity_top" "z component"

# a coupling scene with moving walls (scenes/shear.cfg: coupling I, shear):
# 2N == N + restart + N through the files, checkpoint bytes and thermo rows
# (every column but the timing; the counters and wall stresses included)
"$PELOID" run "$ROOT/scenes/shear.cfg" --out sh_full --steps 20 --threads 2 2> /dev/null
"$PELOID" run "$ROOT/scenes/shear.cfg" --out sh_half --steps 10 --threads 1 2> /dev/null
"$PELOID" run "$ROOT/scenes/shear.cfg" --out sh_resumed --steps 10 --restart sh_half/checkpoint.h5 2> /dev/null
cmp -s sh_full/checkpoint.h5 sh_resumed/checkpoint.h5 && ok "shear + coupling I: 20 steps == 10 + restart + 10, bitwise" || bad "shear restart is not bitwise"
$PY - <<'PYEOF' && ok "shear + coupling I: restarted thermo rows equal the uninterrupted run's" || bad "shear restart thermo rows differ"
import json
def rows(p):
    lines = open(p).read().split("\n")
    head = lines[0].split("\t")
    assert "sxz_top" in head and "cpl_events" in head, head
    return {l.split("\t")[0]: l.split("\t")[:-1] for l in lines[1:] if l}
full, res = rows("sh_full/thermo.tsv"), rows("sh_resumed/thermo.tsv")
assert "20" in res and set(res) <= set(full), sorted(res)
for k in res:
    assert res[k] == full[k], (k, res[k], full[k])
assert float(full["20"][open("sh_full/thermo.tsv").readline().split("\t").index("sxz_top")]) > 0
s = json.load(open("sh_full/summary.json"))
assert abs(s["derived"]["wall_shear_rate"][0] - 1.0 / 16) < 1e-12
PYEOF

# colloid neighbour lists: a restart with another skin continues bitwise (the
# forces do not depend on when or how wide the list was built)
sed 's/substeps = 4;/substeps = 4; neighbor_skin = 0.3;/' "$ROOT/scenes/colloid_dlvo.cfg" > skin03.cfg
"$PELOID" run "$ROOT/scenes/colloid_dlvo.cfg" --steps 40 --out sk_full >/dev/null 2>&1 &&
"$PELOID" run "$ROOT/scenes/colloid_dlvo.cfg" --steps 20 --out sk_half >/dev/null 2>&1 &&
"$PELOID" run skin03.cfg --steps 20 --restart sk_half/checkpoint.h5 --out sk_resumed >/dev/null 2>&1 &&
$PY - <<'PYEOF' && ok "restart with another neighbor_skin continues bitwise" || bad "restart with another neighbor_skin"
import h5py, numpy as np
a, b = h5py.File("sk_full/checkpoint.h5"), h5py.File("sk_resumed/checkpoint.h5")
names = [k for k in a["colloids"]]
assert len(names) > 20, names
for k in names:
    assert np.array_equal(a["colloids"][k][()], b["colloids"][k][()]), k
PYEOF

# params
"$PELOID" params small.cfg > params.txt && grep -q "nu_col" params.txt && grep -q "D_f" params.txt && grep -q "Sc" params.txt && ok "params" || bad "params"
"$PELOID" params small.cfg --json | $PY -c 'import json,sys; d=json.load(sys.stdin); d=d.get("srd", d); assert d["nu"] > 0' && ok "params --json" || bad "params --json"
"$PELOID" keys | grep -q '| `density` |' && ok "keys prints the reference" || bad "keys"

# JSON through jansson (issue 18): every shipped scene's check and params --json,
# and summary.json of short runs, parsed strictly (no NaN / Infinity)
STRICT='import json,sys; json.load(open(sys.argv[1]), parse_constant=lambda c: sys.exit("bad constant "+c))'
nj=0; badj=""
for s in "$ROOT"/scenes/*.cfg; do
  n=$(basename "$s" .cfg)
  "$PELOID" check "$s" > /dev/null 2> err.txt || badj="$badj $n(check: $(cat err.txt))"
  "$PELOID" params "$s" --json > "p_$n.json" 2> err.txt && $PY -c "$STRICT" "p_$n.json" || badj="$badj $n(params: $(cat err.txt))"
  nj=$((nj+1))
done
[ -z "$badj" ] && ok "check + params --json of all $nj shipped scenes: strict JSON" || bad "shipped scenes JSON:$badj"
for f in run1 mapped cap qs; do $PY -c "$STRICT" $f/summary.json || badj="$badj $f"; done
[ -z "$badj" ] && ok "summary.json of the runs above: strict JSON" || bad "summary.json strict:$badj"
printf 'srd: { dt = 1e-320; };\n' > denormal.cfg
"$PELOID" run denormal.cfg --out denormal 2> err.txt; rc=$?
[ $rc -eq 2 ] && [ ! -e denormal ] && grep -q "derived.nu_col" err.txt && ok "srd.dt = 1e-320: non-finite derived value refused before JSON, nothing written" || bad "denormal dt: rc $rc $(cat err.txt)"
"$PELOID" check denormal.cfg 2> /dev/null; [ $? -eq 2 ] && ok "check refuses it too" || bad "check denormal dt"

# Plausible physical inputs: a likely unit mistake is a warning naming it
# (check exits 0 and says ok), refused by --strict with file, line and key;
# every shipped scene passes `check --strict` or its comment says why not.
sed 's/viscosity = 1.0e-6;/viscosity = 0.89e-3;/' "$ROOT/scenes/quickstart.cfg" > visc.cfg
sed 's/ionic_strength = 0.01;/ionic_strength = 10;/' "$ROOT/scenes/hecht_table1.cfg" > ion.cfg
"$PELOID" check visc.cfg > out.txt 2> err.txt; rc=$?
[ $rc -eq 0 ] && grep -q "ok" out.txt && grep -q "IMPLAUSIBLE: physical.viscosity = 0.00089" err.txt \
  && grep -q "looks like a dynamic viscosity" err.txt && ok "viscosity 0.89e-3 m^2/s: check warns (a dynamic viscosity?)" \
  || bad "viscosity 0.89e-3: rc $rc $(cat err.txt)"
"$PELOID" check visc.cfg --strict 2> err.txt; rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] && grep -q "visc.cfg:[0-9]*: key 'physical.viscosity'" err.txt \
  && ok "... and check --strict refuses it naming file, line and key" || bad "viscosity --strict: rc $rc $(cat err.txt)"
"$PELOID" run visc.cfg --strict --out visc_out 2> err.txt; rc=$?
[ $rc -eq 2 ] && [ ! -e visc_out ] && ok "run --strict refuses it, nothing written" || bad "run --strict: rc $rc"
"$PELOID" check ion.cfg 2> err.txt > /dev/null; rc=$?
[ $rc -eq 0 ] && grep -q "physical.ionic_strength = 10 mol/L" err.txt && grep -q "millimolar" err.txt \
  && ok "ionic strength 10 mol/L: check warns (millimolar?)" || bad "ionic strength 10: rc $rc $(cat err.txt)"
nstrict=0; why=""
for f in "$ROOT"/scenes/*.cfg; do
  if "$PELOID" check --strict "$f" > /dev/null 2> err.txt; then nstrict=$((nstrict+1));
  elif ! grep -q "does not pass .check --strict." "$f"; then why="$why $(basename "$f")"; fi
done
[ -z "$why" ] && ok "$nstrict shipped scenes pass check --strict, the others say why in their comment" \
  || bad "shipped scenes failing --strict without a reason in their comment:$why"
# thread counts: OMP_NUM_THREADS above the 4096 limit is refused like
# --threads (exit 2, one line naming it, nothing written; 100000 crashed in
# libgomp, 4097 ran ~1000x slower); more threads than hwloc's cores run with
# one warning line, bitwise equal to 1 thread
printf 'name = "th";\nsteps = 5;\nbox: { cells = [8, 8, 8]; };\nfluid: { density = 2.0; };\n' > th.cfg
for n in 4097 100000; do
  OMP_NUM_THREADS=$n timeout 60 "$PELOID" run th.cfg --out th_$n > /dev/null 2> err.txt; rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] && grep -q "OMP_NUM_THREADS=$n" err.txt && [ ! -e th_$n ] \
    && ok "OMP_NUM_THREADS=$n refused: $(cat err.txt)" || bad "OMP_NUM_THREADS=$n: rc $rc $(head -c 300 err.txt)"
  OMP_NUM_THREADS=$n timeout 60 "$PELOID" check th.cfg > /dev/null 2> err.txt; rc=$?
  [ $rc -eq 2 ] && grep -q "OMP_NUM_THREADS=$n" err.txt && ok "check refuses OMP_NUM_THREADS=$n too" || bad "check OMP_NUM_THREADS=$n: rc $rc"
done
many=$(( 4 * $(nproc) + 1 ))
"$PELOID" run th.cfg --out th_many --threads $many 2> err.txt && "$PELOID" run th.cfg --out th_one --threads 1 2> /dev/null
[ "$(grep -c 'warning:' err.txt)" -eq 1 ] && grep -q "warning: $many OpenMP threads on" err.txt && cmp -s th_many/checkpoint.h5 th_one/checkpoint.h5 \
  && ok "--threads $many: one warning line, bitwise equal to 1 thread: $(grep warning: err.txt)" || bad "--threads $many: $(cat err.txt)"

# memory: check and run estimate the cells' and the fluid's bytes at the
# run's thread count (the sort's histograms are threads x cells) and refuse
# beyond physical memory naming the key; 1e9 cells at 4096 threads need ~16 TB
printf 'steps = 1;\nbox: { cells = [1000, 1000, 1000]; };\nfluid: { density = 0.0; };\n' > bigcells.cfg
OMP_NUM_THREADS=4096 timeout 60 "$PELOID" check bigcells.cfg > /dev/null 2> err.txt; rc=$?
[ $rc -eq 2 ] && grep -q "bigcells.cfg:2: key 'box.cells'" err.txt && grep -q "at 4096 thread" err.txt \
  && ok "check: 1e9 cells at 4096 threads refused by the memory estimate: $(cat err.txt)" || bad "check bigcells: rc $rc $(cat err.txt)"
timeout 60 "$PELOID" run bigcells.cfg --threads 4096 --out bigcells > /dev/null 2> err.txt; rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] && grep -q "key 'box.cells'" err.txt && [ ! -e bigcells ] \
  && ok "run --threads 4096 refuses it too, nothing written" || bad "run bigcells: rc $rc $(head -c 300 err.txt)"

# check = run under a memory limit below physical memory (ulimit -v here;
# a cgroup limit alike): both refuse 1e9 cells with the same line naming
# box.cells and the limit, nothing written (check used to pass it and the
# run to fail its allocation, exit 5, naming no key)
( ulimit -v 4000000
  timeout 60 "$PELOID" check bigcells.cfg > /dev/null 2> lim_check.txt; echo $? > lim_check.rc
  timeout 60 "$PELOID" run bigcells.cfg --out biglim > /dev/null 2> lim_run.txt; echo $? > lim_run.rc )
[ "$(cat lim_check.rc)" = 2 ] && [ "$(cat lim_run.rc)" = 2 ] && cmp -s lim_check.txt lim_run.txt && [ "$(wc -l < lim_run.txt)" -eq 1 ] \
  && grep -q "bigcells.cfg:2: key 'box.cells'" lim_run.txt && grep -q "ulimit -v" lim_run.txt && [ ! -e biglim ] \
  && ok "ulimit -v 4 GB: check and run refuse 1e9 cells with the same line: $(cat lim_run.txt)" \
  || bad "memory limit: check rc $(cat lim_check.rc) '$(cat lim_check.txt)', run rc $(cat lim_run.rc) '$(head -c 300 lim_run.txt)'"

# --strict (params --json, params, check): an audit warning without a key of
# its own is blamed on the key its remedy names where the file gives it:
# FILE:LINE: key, one line, exit 2 (params --json: nothing on stdout)
for mode in "params --json --strict" "params --strict" "check --strict"; do
  "$PELOID" ${mode%% *} "$ROOT/scenes/quickstart.cfg" ${mode#* } > strict.out 2> err.txt; rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] && { [ "$mode" != "params --json --strict" ] || [ ! -s strict.out ]; } \
    && grep -qE "quickstart.cfg:[0-9]+: key 'coarse_graining.mean_free_path': strict mapping audit: HECHT_TAU_P_G" err.txt \
    && ok "$mode names file, line and key: $(cut -c1-120 err.txt)" || bad "$mode: rc $rc $(cat err.txt)"
done

# colloids.init_file: a comment line of any length is one comment (600
# characters here; a fixed line buffer made its tail a colloid); the run
# directory's scene.cfg loads back with the original file gone (it names the
# directory's copy colloids_init.txt), and a restart from that directory
# continues bitwise (10 steps == 5 + restart + 5)
mkdir -p initsc
printf 'name = "ini";\nsteps = 10;\nbox: { cells = [16, 16, 16]; };\nfluid: { density = 2.0; };\ncolloids: { count = 2; radius = 1.0; init = "file"; init_file = "pos.txt"; };\n' > initsc/ini.cfg
{ printf '#'; head -c 600 /dev/zero | tr '\0' c; printf ' 8 8 8.5\n8 8 8\n12 8 8\n'; } > initsc/pos.txt
"$PELOID" check initsc/ini.cfg > /dev/null 2> err.txt && ok "init_file: a 601-character comment line is one comment" || bad "init_file long comment: $(cat err.txt)"
printf '8 8 8\n12 8 8\n' > initsc/pos.txt
"$PELOID" run initsc/ini.cfg --out ini10 2> err.txt && "$PELOID" run initsc/ini.cfg --out ini5 --steps 5 2>> err.txt
mv initsc/pos.txt initsc/gone.txt
"$PELOID" check ini10/scene.cfg > /dev/null 2>> err.txt && cmp -s ini10/colloids_init.txt initsc/gone.txt \
  && ok "init_file: the run directory's scene.cfg loads back (its own colloids_init.txt)" || bad "init_file scene.cfg echo: $(cat err.txt)"
"$PELOID" run ini10/scene.cfg --out ini55 --steps 5 --restart ini5/checkpoint.h5 2>> err.txt && cmp -s ini10/checkpoint.h5 ini55/checkpoint.h5 \
  && ok "init_file: restart from the run directory's scene.cfg, 10 == 5 + restart + 5 bitwise" || bad "init_file restart: $(cat err.txt)"

# the closing list of files is the directory's: a stress-only run names its
# observables.h5 (a hand-kept list left it out), every file listed exists
# and every file there is listed (no lock, no *.tmp)
printf 'seed = 3;\nsteps = 30;\nbox: { cells = [5, 5, 5]; };\nobserve: { stress_interval = 1; };\n' > stress_only.cfg
"$PELOID" run stress_only.cfg --out so 2> so.log
listed=$(sed -n 's|^peloid:   \(/[^ ]*\)  .*|\1|p' so.log | xargs -n1 basename | sort | tr '\n' ' ')
there=$(ls so | sort | tr '\n' ' ')
[ "$listed" = "$there" ] && case "$listed" in *observables.h5*) true;; *) false;; esac \
  && ok "the closing file list is what the directory holds ($listed)" || bad "file list: listed '$listed', there '$there'"

# the adversarial scene set (issue 18): each refused with exit 2, one line
# naming file, line and key, nothing written (tests/support/bad_scenes.sh)
bash "$ROOT/tests/support/bad_scenes.sh" "$PELOID" > bad.txt 2>&1 && ok "$(tail -1 bad.txt)" || bad "bad scenes: $(cat bad.txt)"

$PY "$ROOT/tools/readme_keys.py" "$PELOID" "$ROOT/README.md" --check && ok "README scene reference matches peloid keys" || bad "README reference stale (make readme)"

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
