#!/bin/bash
# Cost of each observer at the intervals a scene uses: the stage's wall time
# (summary.json stage_seconds) as a fraction of the run's step time, in the
# same run, median of REPS runs.  Issue 14's budget: <= 5 % of the step of
# scenes/quickstart.cfg each.
#
#   bench/observer_cost.sh [STEPS] [REPS]     (defaults 1200 5)
#
# Runs: the quickstart as shipped (g(r), MSD, clusters, sedimentation) with
# the VACF and velocity distributions added at the same interval as its
# g(r) (20 steps; S(q) needs a periodic box, the quickstart has walls);
# and a pure-fluid periodic box (32^3 cells, 10 per cell) with the stress
# observer, whose Green-Kubo sum needs every step.
set -eu
cd "$(dirname "$0")/.."
STEPS=${1:-1200}; REPS=${2:-5}
[ -x bin/peloid ] || make bin/peloid >/dev/null
OUT=bench/out; mkdir -p "$OUT"; TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
sed 's/^  rdf_interval = 20;/  rdf_interval = 20;\n  vacf_interval = 20;\n  vdist_interval = 20;/' \
  scenes/quickstart.cfg > "$TMP/quick_all.cfg"
cat > "$TMP/fluid_stress.cfg" <<'CFG'
seed = 3;
box: { cells = [32, 32, 32]; };
fluid: { density = 10; };
srd: { dt = 0.1; alpha = 130; };
observe: { stress_interval = 100; };
CFG
TSV=$OUT/observer_cost.tsv
printf "scene\tthreads\tstage\tseconds_median\tfraction_of_run_median\n" > "$TSV"
for scene in "$TMP/quick_all.cfg" "$TMP/fluid_stress.cfg"; do
  for t in 1 2; do
    : > "$TMP/rows"
    for r in $(seq "$REPS"); do
      bin/peloid run "$scene" --steps "$STEPS" --threads "$t" --out "$TMP/o" --force >/dev/null 2>&1
      /usr/bin/python3 - "$TMP/o/summary.json" >> "$TMP/rows" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
total = d["wall_seconds"]
for k, v in d["stage_seconds"].items():
    if k.startswith(("observe-", "stress")):
        print(k, v, v / total)
PY
    done
    /usr/bin/python3 - "$TMP/rows" "$(basename "$scene" .cfg)" "$t" >> "$TSV" <<'PY'
import sys, statistics
rows = {}
for line in open(sys.argv[1]):
    k, s, f = line.split()
    rows.setdefault(k, []).append((float(s), float(f)))
for k, v in sorted(rows.items()):
    print(f"{sys.argv[2]}\t{sys.argv[3]}\t{k}\t{statistics.median(x[0] for x in v):.4g}\t"
          f"{statistics.median(x[1] for x in v):.4%}")
PY
  done
done
column -t -s $'\t' "$TSV"
