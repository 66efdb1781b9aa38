#!/bin/bash
# Interleaved A/B of the collision stage on fluids with the Heyes thermostat
# (the papers' scenes): bench/peers/srd_fluid.cfg at L = 64 with
# `thermostat.heyes_epsilon = 0.1` and each rule (hecht_axes, random_axis),
# STEPS steps, ROUNDS alternating runs A B of two peloid binaries at 1 and 2
# threads.  Prints per rule and thread count the median (min..max) of the
# collide stage (ns per particle, summary.json's stage_seconds) and of the
# run's particle-updates/s.
#
#   bench/ab_collide_thermostat.sh OLD_PELOID NEW_PELOID [ROUNDS] [STEPS]   (default 4 20)
#   e.g. git worktree add /tmp/old <rev> && make -C /tmp/old bin/peloid
#        bench/ab_collide_thermostat.sh /tmp/old/bin/peloid bin/peloid 4
set -eu
cd "$(dirname "$0")/.."
. bench/common.sh
A=$1; B=$2; ROUNDS=${3:-4}; STEPS=${4:-20}
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
for rule in hecht_axes random_axis; do
  sed "s/cells = \[32, 32, 32\]/cells = [64, 64, 64]/; s/steps = 100/steps = $STEPS/; s/rule = \"random_axis\"/rule = \"$rule\"/; s/thermostat: { type = \"none\"; };/thermostat: { type = \"heyes\"; temperature = 1.0; heyes_epsilon = 0.1; };/" \
      bench/peers/srd_fluid.cfg > "$TMP/$rule.cfg"
done
echo "# ab_collide_thermostat: A = $A, B = $B, $ROUNDS interleaved rounds, L = 64, $STEPS steps; $(date -u +%Y-%m-%dT%H:%MZ); load $(cut -d' ' -f1 /proc/loadavg)"
for r in $(seq "$ROUNDS"); do for t in 1 2; do for rule in hecht_axes random_axis; do for x in A B; do
  bin=$A; [ $x = B ] && bin=$B
  rm -rf "$TMP/out"
  "$bin" run "$TMP/$rule.cfg" --threads "$t" --out "$TMP/out" > /dev/null 2>&1
  /usr/bin/python3 - "$TMP/out/summary.json" "$rule" "$t" "$x" >> "$TMP/all" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
steps, n = d["last_step"] - d["first_step"], d["fluid_particles"]
c = sum(v for k, v in d["stage_seconds"].items() if k.startswith("collide"))
print(sys.argv[2], sys.argv[3], sys.argv[4], "%.4f" % (c / steps / n * 1e9), "%.4g" % d["particle_updates_per_second"])
PY
done; done; done; done
printf "rule\tthreads\tA_collide_ns\tB_collide_ns\tA_updates_per_s\tB_updates_per_s\n"
for rule in hecht_axes random_axis; do for t in 1 2; do
  col() { awk -v r="$rule" -v t="$t" -v x="$1" -v c="$2" '$1 == r && $2 == t && $3 == x { print $c }' "$TMP/all" | med | awk '{printf "%s (%s..%s)", $1, $2, $3}'; }
  printf "%s\t%s\t%s\t%s\t%s\t%s\n" "$rule" "$t" "$(col A 4)" "$(col B 4)" "$(col A 5)" "$(col B 5)"
done; done
