#!/bin/bash
# Interleaved timing of the colloid MD per collision step (issue 38: one
# parallel region per collision step against one per pass): ROUNDS rounds,
# each running every build at every thread count of THREADS in turn,
# `peloid run SCENE --steps STEPS`; the colloid-md stage seconds of
# summary.json over STEPS.  Prints per build and thread count the median,
# min and max over the rounds in ms, the first build's median over each
# build's, and the load average before and after.
#
#   bench/omp_region_ab.sh SCENE BIN_A BIN_B [MORE_BIN...]
#   environment: ROUNDS (7), STEPS (30), THREADS ("1 2")
set -eu
cd "$(dirname "$0")/.."
[ $# -ge 3 ] || { echo "usage: $0 SCENE BIN_A BIN_B [MORE_BIN...]" >&2; exit 2; }
SCENE=$1; shift
ROUNDS=${ROUNDS:-7}; STEPS=${STEPS:-30}; THREADS=${THREADS:-1 2}
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
echo "# omp_region_ab: $SCENE, $STEPS collision steps, $ROUNDS rounds, threads $THREADS; load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for r in $(seq "$ROUNDS"); do
  k=0
  for b in "$@"; do
    for t in $THREADS; do
      "$b" run "$SCENE" --steps "$STEPS" --threads "$t" --out "$TMP/o" --force > "$TMP/log" 2>&1 \
        || { echo "run failed: $b t=$t: $(tail -2 "$TMP/log")" >&2; exit 1; }
      /usr/bin/python3 -c "import json,sys; d=json.load(open('$TMP/o/summary.json')); print($k, $t, d['stage_seconds']['colloid-md'] / $STEPS)" >> "$TMP/lines"
    done
    k=$((k + 1))
  done
done
echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)"
/usr/bin/python3 - "$TMP/lines" "$@" <<'PY'
import collections, statistics as st, sys
t = collections.defaultdict(list)
for line in open(sys.argv[1]):
    k, th, s = line.split()
    t[(int(th), int(k))].append(1e3 * float(s))
names = sys.argv[2:]
print("threads\tbuild\tms_per_collision_step_median\tmin\tmax\tfirst_over_this")
for th in sorted({k[0] for k in t}):
    base = st.median(t[(th, 0)])
    for k, name in enumerate(names):
        a = t[(th, k)]
        print("%d\t%s\t%.2f\t%.2f\t%.2f\t%.3f" % (th, name, st.median(a), min(a), max(a), base / st.median(a)))
PY
