#!/usr/bin/env bash
# Fault trials (issue 37; not part of make check: it takes about a minute):
# a 600-step colloid + coupling II scene with checkpoints every 50 steps,
# observers and trajectories is hit by SIGINT, SIGTERM or SIGKILL after a
# random 0.1-0.9 s, then resumed in place (`--restart DIR/checkpoint.h5
# --out DIR`); the trial passes when the checkpoint bytes and the thermo rows
# equal an uninterrupted run's.  A SIGKILL before the first checkpoint leaves
# nothing to resume: counted apart.
#   bash tests/fault/fault_trials.sh [PELOID] [TRIALS]
set -u
PELOID=$(realpath "${1:-bin/peloid}")
N=${2:-10}
PY=/usr/bin/python3
T=$(mktemp -d /tmp/peloid-faults.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
cat > f.cfg <<'CFG'
name = "f";
seed = 3;
steps = 600;
box: { cells = [10, 10, 10]; };
fluid: { density = 5.0; };
srd: { dt = 0.1; };
colloids: { count = 20; radius = 1.0; init = "random"; pairs = "hertz"; trajectory_interval = 10; substeps = 16; };
coupling: { method = "hecht2"; };
output: { checkpoint_interval = 50; thermo_interval = 10; colloids_xyz = true; };
observe: { rdf_interval = 10; msd_interval = 5; };
CFG
"$PELOID" run f.cfg --out ref --threads 2 > /dev/null 2>&1 || { echo "fault trials: the reference run failed"; exit 1; }
rows() { cut -f1-3 "$1"; }  # step, time, temperature (the last column is a wall-clock rate)
total_bad=0
for sig in INT TERM KILL; do
  ok=0; bad=0; none=0
  for i in $(seq 1 "$N"); do
    d=t_${sig}_$i
    "$PELOID" run f.cfg --out "$d" --threads 2 > /dev/null 2> "$d.err" & pid=$!
    sleep "0.$(( RANDOM % 9 + 1 ))"
    kill -"$sig" "$pid" 2> /dev/null; wait "$pid" 2> /dev/null; rc=$?
    if [ ! -f "$d/checkpoint.h5" ]; then none=$((none + 1)); continue; fi
    step=$($PY -c "import h5py, sys; print(int(h5py.File(sys.argv[1]).attrs['peloid_checkpoint'][0]))" "$d/checkpoint.h5")
    if "$PELOID" run f.cfg --restart "$d/checkpoint.h5" --out "$d" --threads 2 --steps $((600 - step)) > /dev/null 2>> "$d.err" \
       && cmp -s ref/checkpoint.h5 "$d/checkpoint.h5" && diff <(rows ref/thermo.tsv) <(rows "$d/thermo.tsv") > /dev/null; then
      ok=$((ok + 1))
    else bad=$((bad + 1)); echo "  $sig trial $i: exit $rc at step $step: $(tail -1 "$d.err")"; fi
  done
  total_bad=$((total_bad + bad))
  echo "SIG$sig: $ok/$((ok + bad)) resumed in place equal to the uninterrupted run ($none stopped before the first checkpoint)"
done
[ "$total_bad" -eq 0 ]
