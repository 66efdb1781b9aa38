#!/usr/bin/env bash
# peloid sweep (src/app/): a 4-point grid over a tiny Brownian scene (16
# colloids, 300 steps, ~0.05 s a point) runs and is collected into
# sweep.{tsv,json,png}; a re-run skips the finished points; a point whose
# value trips a guard at run time fails alone and is recorded with its exit
# code and message; an invalid override, an unknown key, an empty grid and
# a plot.y that no observer writes or a point does not measure are refused
# before anything is written (exit 2, one line naming file:line and key);
# --point K runs exactly point K; --slurm writes the job array; the
# throughput plan (OUT/plan.json, the log line, sweep.json "plan", the
# threads column) is within the sweep's cores, its jobs' CPU sets disjoint,
# --jobs/--threads override it, and each point's results are bitwise the
# same under the plan and under --jobs 1 --threads 2; a physical study's
# sweep.tsv is in SI with units in its header (model values beside, cluster
# sizes as fractions of N); replicas = 3 runs seeds seed + 0..2 of each point
# and pools them (mean, SE between replicas, within-run SE, flag), refused
# beside a swept seed; the pooling passes its unit test on synthetic
# replicas of known variance (tools/test_sweep_pool.py); `peloid run SCENE
# --replicas N` pools N seeds of one scene into sweep.tsv and report.md, a
# bad N refused.
set -u
PELOID=$(realpath "${1:-bin/peloid}")
PY=/usr/bin/python3
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
T=$(mktemp -d /tmp/peloid-sweep.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
echo "== sweep tests"
t0=$(date +%s.%N)

cat > bd.cfg <<'CFG'
name = "bd";
seed = 11;
steps = 300;
box: { cells = [8, 8, 8]; };
fluid: { density = 0.0; };
srd: { dt = 0.1; };
colloids: { count = 16; radius = 1.0; mass_density = 1.0; temperature = 1.0; init = "random";
  pairs = ""; integrator = "brownian"; bd_viscosity = 0.02; substeps = 1; max_overlap = 1.0; };
observe: { msd_interval = 1; };
CFG
cat > grid.cfg <<'CFG'
name = "grid";
scene = "bd.cfg";
out = "out/grid";
grid = ( { key = "colloids.bd_viscosity"; values = [0.02, 0.04]; },
         { key = "seed"; values = [1, 2]; } );
plot = { x = "colloids.bd_viscosity"; y = ["colloid_D"]; series = "seed"; };
CFG

# 1. the grid runs and is collected
if "$PELOID" sweep grid.cfg 2> grid.err; then ok "4-point grid sweep ran (exit 0)"; else bad "grid sweep: $(tail -1 grid.err)"; fi
if $PY - <<'PY'
import json
rows = [l.rstrip("\n").split("\t") for l in open("out/grid/sweep.tsv")]
h = rows[0]; rows = rows[1:]
assert len(rows) == 4, rows
c = {k: h.index(k) for k in ("id", "status", "colloids.bd_viscosity", "seed", "last_step", "colloid_D", "colloid_D_se")}
got = [(r[c["id"]], r[c["status"]], float(r[c["colloids.bd_viscosity"]]), int(r[c["seed"]]), int(r[c["last_step"]])) for r in rows]
assert got == [("p000", "ok", 0.02, 1, 300), ("p001", "ok", 0.02, 2, 300), ("p002", "ok", 0.04, 1, 300),
               ("p003", "ok", 0.04, 2, 300)], got
for r in rows:
    assert float(r[c["colloid_D"]]) > 0 and float(r[c["colloid_D_se"]]) > 0
j = json.load(open("out/grid/sweep.json"))
assert [p["params"]["seed"] for p in j["points"]] == [1, 2, 1, 2]
assert j["key_units"] == {"colloids.bd_viscosity": "m_f / (a0 t0)"}, j["key_units"]  # the plot's x axis unit
import os; assert os.path.getsize("out/grid/sweep.png") > 5000
for k, (v, s) in enumerate([(0.02, 1), (0.02, 2), (0.04, 1), (0.04, 2)]):
    t = open(f"out/grid/scenes/p{k:03d}.cfg").read()
    assert f"bd_viscosity = {v};" in t and f"seed = {s};" in t, t
PY
then ok "sweep.tsv: 4 rows, keys per point, colloid_D +- SE; sweep.json, sweep.png, each point's scene"; else bad "sweep table"; fi
grep -q "peloid sweep grid: 4/4 done (0 skipped), 0 failed, 0 running, .* elapsed, ETA" grid.err \
  && ok "one progress line per event (done/failed/running, elapsed, ETA)" || bad "progress line: $(cat grid.err)"

# 2. a re-run skips the finished points
m0=$(stat -c %Y.%N out/grid/p001/summary.json)
"$PELOID" sweep grid.cfg 2> rerun.err
if grep -q "4 finished before, 0 to run" rerun.err && [ "$(stat -c %Y.%N out/grid/p001/summary.json)" = "$m0" ]; then
  ok "re-run skipped the 4 finished points (summary.json untouched)"; else bad "re-run: $(cat rerun.err)"; fi
rm out/grid/p002/summary.json
"$PELOID" sweep grid.cfg 2> resume.err
grep -q "3 finished before, 1 to run" resume.err && [ -f out/grid/p002/summary.json ] \
  && ok "a point without a complete summary.json is run again" || bad "resume: $(cat resume.err)"

# a finished point whose status still records an earlier failure (a run that
# failed while another held its folder, which then finished it): the table and
# the exit code agree, the point is ok
printf '2\tpeloid: error: out/grid/p001: another peloid run is writing into this output directory\n' > out/grid/status/p001.tsv
"$PELOID" sweep grid.cfg 2> stale.err; rc=$?
st=$(awk -F'\t' '$1 == "p001" { print $2 }' out/grid/sweep.tsv)
[ $rc = 0 ] && [ "$st" = ok ] && ok "a finished point's stale failure status is cleared: table ok, exit 0" \
  || bad "stale status: exit $rc, table says '$st'"

# 3. a point whose value trips a guard fails alone and is recorded
cat > fails.cfg <<'CFG'
scene = "bd.cfg";
out = "out/fails";
points = { keys = ["colloids.max_overlap", "seed"];
           values = ( (1.0, 1), (0.01, 2), (1.0, 3), (1.0, 4) ); };
CFG
"$PELOID" sweep fails.cfg 2> fails.err; rc=$?
if [ $rc = 1 ] && $PY - <<'PY'
rows = [l.rstrip("\n").split("\t") for l in open("out/fails/sweep.tsv")][1:]
st = [(r[0], r[1], r[2]) for r in rows]
assert st == [("p000", "ok", "0"), ("p001", "failed", "3"), ("p002", "ok", "0"), ("p003", "ok", "0")], st
assert "guard overlap" in rows[1][3] and "max_overlap" in rows[1][3], rows[1][3]
PY
then ok "point 1 (max_overlap = 0.01) failed alone: exit 3 and its guard message recorded, exit 1"
else bad "failing point (rc $rc): $(tail -2 fails.err)"; fi

# 4. bad input: refused before anything is written, exit 2, one line
refuse() { # name, study text, expected message part
  printf '%s\n' "$2" > "$1.cfg"
  "$PELOID" sweep "$1.cfg" > /dev/null 2> "$1.err"; rc=$?
  if [ $rc = 2 ] && [ "$(wc -l < "$1.err")" = 1 ] && grep -q -- "$3" "$1.err" && [ ! -e "out/$1" ]; then
    ok "refused $1: $(cut -c1-150 "$1.err")"
  else bad "$1: rc $rc, $(cat "$1.err")"; [ -e "out/$1" ] && echo "    out/$1 was written"; fi
}
refuse badvalue 'scene = "bd.cfg"; out = "out/badvalue"; grid = ( { key = "colloids.bd_viscosity"; values = [0.02, -1.0]; } );' \
  "badvalue.cfg:1: point 1 (colloids.bd_viscosity = -1.0) is not a valid scene.*key 'colloids.bd_viscosity': value -1 is out of range; allowed: > 0"
refuse badkey 'scene = "bd.cfg"; out = "out/badkey";
grid = ( { key = "colloids.bd_viscosty"; values = [0.02]; } );' \
  "badkey.cfg:2: key 'grid.\[0\]': \"colloids.bd_viscosty\" is not a scene key"
refuse empty 'scene = "bd.cfg"; out = "out/empty"; grid = ( { key = "seed"; values = []; } );' \
  "empty.cfg:1: key 'grid.\[0\]': values: expected a non-empty array"
refuse dupgrid 'scene = "bd.cfg"; out = "out/dupgrid";
grid = ( { key = "seed"; values = [1, 2]; },
  { key = "colloids.bd_viscosity"; values = [0.02, 0.04, 0.02]; } );' \
  "dupgrid.cfg:3: key 'grid.\[1\]': \"colloids.bd_viscosity\": value 0.02 is given twice (values 0 and 2)"
refuse duppoints 'scene = "bd.cfg"; out = "out/duppoints";
points = { keys = ["seed", "colloids.bd_viscosity"];
  values = ( (1, 0.02),
             (2, 0.02),
             (1, 0.02) ); };' \
  "duppoints.cfg:5: key 'points.values': points 0 and 2 are the same (seed = 1, colloids.bd_viscosity = 0.02)"
refuse sweepname 'scene = "bd.cfg"; out = "out/sweepname";
grid = ( { key = "name"; values = ["a", "b"]; } );' \
  "sweepname.cfg:2: key 'grid.\[0\]': \"name\" names the run, it is not swept.*allowed: "
refuse repseed 'scene = "bd.cfg"; out = "out/repseed";
grid = ( { key = "seed"; values = [1, 2]; } );
replicas = 3;' \
  "repseed.cfg:3: key 'replicas': replicas = 3 with \"seed\" swept (repseed.cfg:2); allowed: one of them, not both"
refuse repzero 'scene = "bd.cfg"; out = "out/repzero"; grid = ( { key = "steps"; values = [10]; } ); replicas = 0;' \
  "repzero.cfg:1: key 'replicas': value 0; allowed: an integer from 1 to"
refuse badstudy 'scene = "bd.cfg"; out = "out/badstudy"; gird = ( );' "badstudy.cfg:1: key 'gird': unknown study key"
refuse ploty_unknown 'scene = "bd.cfg"; out = "out/ploty_unknown";
grid = ( { key = "seed"; values = [1, 2]; } );
plot = { x = "seed"; y = ["colloid_D", "colloid_DD"]; };' \
  "ploty_unknown.cfg:3: key 'plot.y': \"colloid_DD\" is no observer's summary.json observable; allowed: .*\"colloid_D\".*\"steinhardt_Q6\".*\"fluid_viscosity\""
refuse ploty_unmeasured 'scene = "bd.cfg"; out = "out/ploty_unmeasured";
grid = ( { key = "seed"; values = [1, 2]; } );
plot = { x = "seed";
  y = "rdf_peak"; };' \
  "ploty_unmeasured.cfg:4: key 'plot.y': point 0: \"rdf_peak\" is measured by the g(r) observer, which is off (observe.rdf_interval = 0); allowed: what the scene measures: \"colloid_D\"$"
refuse ploty_point 'scene = "bd.cfg"; out = "out/ploty_point";
grid = ( { key = "observe.sq_interval"; values = [10, 0]; } );
plot = { x = "observe.sq_interval"; y = ["colloid_D", "sq_peak"]; };' \
  "ploty_point.cfg:3: key 'plot.y': point 1: \"sq_peak\" is measured by the S(q) observer, which is off (observe.sq_interval = 0)"

# 5. --point K runs exactly point K (what a Slurm array task runs)
sed 's#out/grid#out/one#' grid.cfg > one.cfg
"$PELOID" sweep one.cfg --point 2 2> one.err
n=$(ls out/one/*/summary.json 2>/dev/null | wc -l)
if [ "$n" = 1 ] && [ -f out/one/p002/summary.json ] && grep -q "^seed = 1;" out/one/p002/scene.cfg \
   && grep -Eq "bd_viscosity = 0\.0400000" out/one/p002/scene.cfg; then ok "--point 2 ran point 2 only"
else bad "--point 2: $n summaries, $(tail -1 one.err)"; fi

# 6. --slurm writes the array script and runs nothing
sed 's#out/grid#out/sl#' grid.cfg > sl.cfg
"$PELOID" sweep sl.cfg --slurm --threads 1 2> sl.err
if grep -q -- "--array=0-3" out/sl/sweep.sbatch && grep -q -- "--point \"\$SLURM_ARRAY_TASK_ID\"" out/sl/sweep.sbatch \
   && grep -q -- "--collect" out/sl/collect.sbatch && ! ls out/sl/p0* > /dev/null 2>&1; then
  ok "--slurm: sweep.sbatch (--array=0-3, task K runs --point K), collect.sbatch, nothing run"
else bad "--slurm: $(cat sl.err)"; fi
# ... and each array index runs its point locally, as Slurm would
for k in 0 1 2 3; do SLURM_ARRAY_TASK_ID=$k SLURM_CPUS_PER_TASK=1 bash out/sl/sweep.sbatch 2> /dev/null; done
"$PELOID" sweep sl.cfg --out out/sl --collect 2> /dev/null
[ "$(grep -c '	ok	0	' out/sl/sweep.tsv)" = 4 ] && ok "the 4 array tasks run locally (SLURM_ARRAY_TASK_ID=0..3), collected" \
  || bad "array tasks run locally"
# --collect where no sweep ran (an empty folder, none, a file): one clear
# line (no Python errno), exit 2, nothing written there
mkdir -p out/empty_collect; : > out/file_collect
for d in out/empty_collect out/none_collect out/file_collect; do
  "$PELOID" sweep sl.cfg --out "$d" --collect 2> ec.err; rc=$?
  if [ $rc = 2 ] && [ "$(wc -l < ec.err)" = 1 ] && grep -q "sweep --collect: $d has no points.json" ec.err \
     && ! grep -q "Errno" ec.err && [ ! -e "$d/sweep.tsv" ] && [ ! -e out/none_collect ]; then
    ok "--collect on $d: $(cut -c1-110 ec.err)"
  else bad "--collect on $d: rc $rc, $(cat ec.err)"; fi
done
# 7. a point's scene loses nothing: with the base's own value it reproduces
#    the base run bitwise (scenes/quickstart.cfg: physical units, @-free, many reals)
QS="$ROOT/scenes/quickstart.cfg"
# (the point is named same-p000: so is the base's copy run here)
printf 'scene = "%s"; out = "out/same";\npoints = { keys = ["seed"]; values = ( (20261123) ); };\n' \
  "$QS" > same.cfg
sed 's/^name = "quickstart";/name = "same-p000";/' "$QS" > qs.cfg
"$PELOID" sweep same.cfg --slurm 2> /dev/null  # writes the point's scene, runs nothing
# (--steps, not steps = 5 in the file: quickstart's observers need more
# samples than 5 steps give, which check refuses in a scene file)
"$PELOID" run out/same/scenes/p000.cfg --steps 5 --out pt --threads 1 2> /dev/null
"$PELOID" run qs.cfg --steps 5 --out base --threads 1 2> /dev/null
if [ -f pt/checkpoint.h5 ] && [ "$(sha256sum < pt/checkpoint.h5)" = "$(sha256sum < base/checkpoint.h5)" ]; then
  ok "a point with the base's values reproduces the base run bitwise (quickstart, 5 steps, checkpoint.h5)"
else bad "point scene differs from its base (checkpoint.h5 hashes)"; fi
# 8. arrays, strings and 64-bit integers survive into a point's scene (the
#    base's 5000000000 without L is read as written, not wrapped to 32 bits)
sed 's/^steps = 300;/steps = 5000000000;/' bd.cfg > bdbig.cfg
printf 'scene = "bdbig.cfg"; out = "out/arr";\ngrid = ( { key = "box.cells"; values = ([8,8,8], [10,10,10]); },\n  { key = "colloids.init"; values = ["lattice", "random"]; } );\n' > arr.cfg
"$PELOID" sweep arr.cfg --slurm 2> /dev/null
if grep -q "^  cells = \[10, 10, 10\];" out/arr/scenes/p003.cfg && grep -q '^  init = "random";' out/arr/scenes/p003.cfg \
   && grep -q "^steps = 5000000000L;" out/arr/scenes/p003.cfg && "$PELOID" check out/arr/scenes/p003.cfg > /dev/null 2>&1; then
  ok "array, string and 64-bit integer values written into the point's scene, which checks ok"
else bad "array/string/int64 values in a point's scene"; fi
# 9. the throughput plan: jobs x threads within the cores the sweep may use,
#    each job on cores of its own, the choice and why in one line, plan.json,
#    sweep.json and the threads column; --jobs/--threads override it
if $PY - <<'PY'
import json, os
p = json.load(open("out/grid/plan.json"))
m = p["machine"]
assert p["points_to_run"] >= 1 and p["jobs"] >= 1 and p["threads"] >= 1 and p["why"], p
assert sum(m["domain_cores"]) == m["cores"] == len(os.sched_getaffinity(0)) // (m["pus"] // m["cores"]), (m, os.sched_getaffinity(0))
if p["jobs"] * p["threads"] <= m["cores"]:
    sets = [set() for _ in p["cpusets"]]
    for s, txt in zip(sets, p["cpusets"]):
        for part in txt.split(","):
            a, _, b = part.partition("-")
            s.update(range(int(a), int(b or a) + 1))
    assert len(sets) == p["jobs"] and all(s <= os.sched_getaffinity(0) for s in sets), p["cpusets"]
    assert all(not (x & y) for i, x in enumerate(sets) for y in sets[i + 1:]), p["cpusets"]
j = json.load(open("out/grid/sweep.json"))
assert j["plan"]["jobs"] == p["jobs"], j.get("plan")
PY
then ok "plan.json: jobs x threads within the sweep's cores, disjoint CPU sets inside its binding; sweep.json has the plan"
else bad "plan.json: $(cat out/grid/plan.json 2>&1 | head -c 400)"; fi
grep -Eq "4 to run \(0 from its checkpoint\): [0-9]+ job\(s\) x [0-9]+ thread\(s\) on [0-9]+ core\(s\): .*(one single-thread job per core|spare cores).*memory: .* -> out/grid/" grid.err \
  && ok "one log line: jobs x threads, cores, why, memory" || bad "plan line: $(head -1 grid.err)"
if command -v taskset > /dev/null && taskset -c 0 true 2> /dev/null; then
  sed 's#out/grid#out/ts#' grid.cfg > ts.cfg
  taskset -c 0 "$PELOID" sweep ts.cfg 2> ts.err
  $PY -c 'import json; p = json.load(open("out/ts/plan.json")); assert (p["jobs"], p["threads"], p["cpusets"], p["machine"]["cores"]) == (1, 1, ["0"], 1), p' \
    && ok "under taskset -c 0 the sweep plans 1 x 1 on core 0 (the machine as its binding shows it)" || bad "taskset: $(head -1 ts.err)"
fi

# 10. a point's results do not depend on jobs x threads: a small fluid
#     swept by the plan and by --jobs 1 --threads 2, bitwise
cat > fl.cfg <<'CFG'
name = "fl";
seed = 5;
steps = 40;
box: { cells = [10, 10, 10]; };
fluid: { density = 10.0; };
srd: { dt = 0.1; };
output: { checkpoint_interval = 40; };
CFG
printf 'name = "fl"; scene = "fl.cfg"; out = "out/fa";\ngrid = ( { key = "seed"; values = [1, 2]; } );\n' > fa.cfg
sed 's#out/fa#out/fb#' fa.cfg > fb.cfg
"$PELOID" sweep fa.cfg 2> fa.err; ra=$?
"$PELOID" sweep fb.cfg --jobs 1 --threads 2 2> fb.err; rb=$?
same=0
for k in p000 p001; do
  [ -f out/fa/$k/checkpoint.h5 ] && [ "$(sha256sum < out/fa/$k/checkpoint.h5)" = "$(sha256sum < out/fb/$k/checkpoint.h5)" ] \
    && [ "$(cut -f1-8 out/fa/$k/thermo.tsv | sha256sum)" = "$(cut -f1-8 out/fb/$k/thermo.tsv | sha256sum)" ] \
    && [ "$(head -1 out/fa/$k/thermo.tsv | cut -f9)" = mupdates_per_s ] && same=$((same + 1))
done
tb=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "threads") c = i } NR > 1 { print $c }' out/fb/sweep.tsv | sort -u)
if [ $ra = 0 ] && [ $rb = 0 ] && [ $same = 2 ] && [ "$tb" = 2 ] && grep -q "1 job(s) x 2 thread(s) on .*--jobs 1 --threads 2 as given" fb.err; then
  ok "both points bitwise equal (checkpoint.h5, thermo.tsv but its wall-clock rate) under $(sed -n 's/.*checkpoint): \([0-9]* job(s) x [0-9]* thread(s)\).*/\1/p' fa.err) and --jobs 1 --threads 2 (threads column: 2)"
else bad "jobs x threads determinism: exit $ra/$rb, $same of 2 points equal, threads column '$tb'"; fi
# 11. a physical study (quickstart at 300 steps, observers every 10) in SI:
#     every observable's column and the swept key with its unit, the model
#     value beside, the largest cluster as a fraction of the colloids
sed -e 's/^steps = 2400;/steps = 300;/' -e 's/_interval = 20;/_interval = 10;/' "$QS" > qs300.cfg
printf 'scene = "qs300.cfg"; out = "out/si";\ngrid = ( { key = "physical.kappa"; values = [3.0e7, 1.0e8]; } );\n' > si.cfg
"$PELOID" sweep si.cfg 2> si.err; rc=$?
if [ $rc = 0 ] && $PY - <<'PY'
import json
rows = [l.rstrip("\n").split("\t") for l in open("out/si/sweep.tsv")]
h = rows[0]
for c in ("physical.kappa [1/m]", "wall_seconds [s]", "colloid_D [m^2/s]", "colloid_D_se [m^2/s]",
          "colloid_D_model [a0^2/t0]", "colloid_D_model_se [a0^2/t0]", "settling_velocity [m/s]",
          "settling_velocity_model [a0/t0]", "largest_cluster_fraction [1]", "largest_cluster_fraction_se [1]",
          "largest_cluster_model [colloids]", "rdf_peak [1]"):
    assert c in h, (c, h)
assert "colloid_D" not in h and "largest_cluster" not in h, h
for r in rows[1:]:
    c = dict(zip(h, r))
    s = json.load(open(f"out/si/{c['id']}/summary.json"))
    o = s["observables"]
    assert float(c["colloid_D [m^2/s]"]) == o["colloid_D"]["value_si"]
    assert float(c["colloid_D_model [a0^2/t0]"]) == o["colloid_D"]["value"]
    n = s["scene"]["colloids"]["count"]
    assert abs(float(c["largest_cluster_fraction [1]"]) - o["largest_cluster"]["value"] / n) < 1e-15, (c, n)
    assert 0 < float(c["largest_cluster_fraction [1]"]) <= 1
    assert 1e-14 < float(c["colloid_D [m^2/s]"]) < 1e-11, c  # ~0.5 um^2/s
print("    header:", " | ".join(h[4:16]), "...")
PY
then ok "physical study: sweep.tsv in SI with units (colloid_D [m^2/s] beside colloid_D_model [a0^2/t0], largest_cluster_fraction [1])"
else bad "physical study SI table (rc $rc): $(tail -1 si.err); $(head -1 out/si/sweep.tsv 2>/dev/null | cut -c1-300)"; fi

# 12. replicas = 3: each point runs seeds 11, 12, 13 (the base's 11 + r) as
#     its own run p00Kr0..r2, pooled into one row per point
printf 'scene = "bd.cfg"; out = "out/rep";\ngrid = ( { key = "colloids.bd_viscosity"; values = [0.02, 0.03]; } );\nreplicas = 3;\n' > rep.cfg
"$PELOID" sweep rep.cfg 2> rep.err; rc=$?
if [ $rc = 0 ] && $PY - <<'PY'
import json, math, statistics
runs = [l.rstrip("\n").split("\t") for l in open("out/rep/sweep_replicas.tsv")]
hr = runs[0]; runs = [dict(zip(hr, r)) for r in runs[1:]]
assert [(r["id"], r["status"], r["seed"]) for r in runs] == [
    ("p000r0", "ok", "11"), ("p000r1", "ok", "12"), ("p000r2", "ok", "13"),
    ("p001r0", "ok", "11"), ("p001r1", "ok", "12"), ("p001r2", "ok", "13")], runs
for r in runs:
    t = open(f"out/rep/{r['id']}/scene.cfg").read()
    assert f"seed = {r['seed']};" in t, t
pts = [l.rstrip("\n").split("\t") for l in open("out/rep/sweep.tsv")]
h = pts[0]; pts = [dict(zip(h, r)) for r in pts[1:]]
assert [p["id"] for p in pts] == ["p000", "p001"] and all(p["replicas"] == "3" for p in pts), pts
for c in ("colloid_D", "colloid_D_se", "colloid_D_se_within", "colloid_D_se_flag"):
    assert c in h, (c, h)
for k, p in enumerate(pts):
    xs = [float(r["colloid_D"]) for r in runs[3 * k:3 * k + 3]]
    ses = [float(r["colloid_D_se"]) for r in runs[3 * k:3 * k + 3]]
    assert len(set(xs)) == 3, xs  # three seeds, three results
    assert abs(float(p["colloid_D"]) - statistics.fmean(xs)) < 1e-12 * abs(statistics.fmean(xs))
    assert abs(float(p["colloid_D_se"]) - statistics.stdev(xs) / math.sqrt(3)) < 1e-12 * float(p["colloid_D_se"])
    assert abs(float(p["colloid_D_se_within"]) - statistics.fmean(ses) / math.sqrt(3)) < 1e-12 * float(p["colloid_D_se_within"])
    assert p["colloid_D_se_flag"] in ("ok", "high", "low"), p
j = json.load(open("out/rep/sweep.json"))
assert j["replicas"] == 3 and len(j["pooled"]) == 2 and len(j["points"]) == 6, j.keys()
print("    p000: D = %s +- %s (between) / %s (within), %s" % tuple(pts[0][c] for c in
      ("colloid_D", "colloid_D_se", "colloid_D_se_within", "colloid_D_se_flag")))
PY
then ok "replicas = 3: 6 runs (seeds 11-13 per point), one pooled row per point: mean, SE between, within-run SE, flag"
else bad "replicas (rc $rc): $(tail -1 rep.err)"; fi

# 12b. peloid run SCENE --replicas N: the scene's seeds 11..14 as a study of
#      one point, pooled into sweep.tsv, report.md (mean +- SE between the
#      replicas beside the within-run SE and the flag) and sweep.png; a bad N
#      or an option a replica set cannot take is refused (exit 2), nothing written
"$PELOID" run bd.cfg --replicas 4 --out out/runrep 2> runrep.err; rc=$?
if [ $rc = 0 ] && $PY - <<'PY'
import math, statistics
runs = [l.rstrip("\n").split("\t") for l in open("out/runrep/sweep_replicas.tsv")]
hr = runs[0]; runs = [dict(zip(hr, r)) for r in runs[1:]]
assert [(r["id"], r["seed"]) for r in runs] == [("p000r%d" % k, str(11 + k)) for k in range(4)], runs
pts = [l.rstrip("\n").split("\t") for l in open("out/runrep/sweep.tsv")]
p = dict(zip(pts[0], pts[1]))
assert len(pts) == 2 and p["id"] == "p000" and p["replicas"] == "4", pts
xs = [float(r["colloid_D"]) for r in runs]
mean, se = statistics.fmean(xs), statistics.stdev(xs) / 2
assert abs(float(p["colloid_D"]) - mean) < 1e-12 * mean and abs(float(p["colloid_D_se"]) - se) < 1e-12 * se, p
rep = open("out/runrep/report.md").read()
row = [l for l in rep.splitlines() if l.startswith("| colloid_D |")]
assert len(row) == 1 and "\u00b1" in row[0] and p["colloid_D_se_flag"] in row[0], rep
cells = [c.strip() for c in row[0].strip("|").split("|")]
m, s = (float(v) for v in cells[2].split("\u00b1"))
# the SE to two significant digits, the mean to its place
assert abs(m - mean) <= 0.1 * se and abs(s - se) <= 0.05 * se, (cells, mean, se)
assert abs(float(cells[3]) - float(p["colloid_D_se_within"])) < 0.005 * float(p["colloid_D_se_within"]), cells
import os; assert os.path.getsize("out/runrep/sweep.png") > 5000
print("    report.md:", row[0])
PY
then ok "run --replicas 4: seeds 11-14, pooled row (mean, SE between) in sweep.tsv and report.md beside the within-run SE and flag"
else bad "run --replicas (rc $rc): $(tail -1 runrep.err)"; fi
for a in "--replicas 1" "--replicas 2x" "--replicas 100001" "--replicas 3 --steps 10" "--replicas 3 --restart x.h5"; do
  # shellcheck disable=SC2086
  "$PELOID" run bd.cfg $a --out out/runbad 2> runbad.err; rc=$?
  if [ $rc = 2 ] && [ ! -e out/runbad ] && [ "$(grep -c 'peloid: error:' runbad.err)" = 1 ] && grep -q -- "--replicas" runbad.err
  then ok "run bd.cfg $a: refused (exit 2, one line, nothing written)"
  else bad "run bd.cfg $a: rc $rc, $(head -1 runbad.err)"; fi
done

# 13. the pooling on synthetic replicas of known variance
if $PY "$ROOT/tools/test_sweep_pool.py" > pool.out 2>&1; then
  ok "pooling unit test (tools/test_sweep_pool.py): SE between replicas ~ sigma/sqrt(N), flag rate 5 % with right SEs, fires on 3x understated"
else bad "pooling unit test: $(grep -v '^  ok' pool.out | head -5)"; fi
sed 's/^/    /' pool.out | grep -E "N = 3: SEs|N = 20: SEs|1000 replicas"

echo "  sweep tests: $pass passed, $fail failed ($(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }') s)"
[ $fail = 0 ]
