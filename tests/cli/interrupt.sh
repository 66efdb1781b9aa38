#!/usr/bin/env bash
# Issue 37, "nothing lost, nothing misread", through bin/peloid:
#  - SIGINT, SIGTERM, SIGHUP end a run after the step in progress with its
#    outputs complete at that step: checkpoint, summary.json ("interrupted":
#    true, last_step), last thermo row and trajectory frame, no *.tmp left,
#    one line naming the signal, the step and the resume command, exit
#    128 + signal; a second signal exits at once;
#  - resuming in place (--restart DIR/checkpoint.h5 --out DIR) appends to
#    thermo.tsv and the trajectories: the folder then equals that of an
#    uninterrupted run (thermo rows but the wall-clock rate, frames, and
#    the checkpoint bitwise);
#  - one run per folder: a second run into a folder a run is writing is
#    refused (exit 2, one line) even with --force; --force removes what an
#    earlier run wrote there, so a folder never mixes two runs.
# Each signal is sent once the run has written a given thermo row (no blind
# sleeps); every wait is bounded.
set -u
PELOID=$(realpath "${1:-bin/peloid}")
PY=/usr/bin/python3
T=$(mktemp -d /tmp/peloid-interrupt.XXXXXX)
trap 'kill $(jobs -p) 2> /dev/null; rm -rf "$T"' EXIT
# the runs get the default action of the signals under test even when this
# suite was started with them ignored (a background job of a non-interactive
# shell, nohup): peloid keeps a signal its caller ignores, as it should
printf '#!/bin/sh\nexec env --default-signal=INT,TERM,HUP "%s" "$@"\n' "$PELOID" > "$T/peloid-default-signals"
chmod +x "$T/peloid-default-signals"
PELOID=$T/peloid-default-signals
cd "$T"
set -m # background runs in their own process group: SIGINT is not ignored there
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }

cat > tiny.cfg <<'EOF'
name = "tiny";
seed = 7;
steps = 400;
box: { cells = [6, 6, 6]; };
fluid: { density = 5.0; temperature = 1.0; };
srd: { dt = 0.1; rule = "hecht_axes"; };
colloids: { count = 8; radius = 0.62; mass_density = 19.5; temperature = 1.0; init = "lattice";
            pairs = ""; substeps = 1; max_overlap = 1.0; trajectory_interval = 5; };
coupling: { method = "hecht2"; };
output: { thermo_interval = 3; colloids_xyz = true; };
EOF

# wait_row FILE STEP: until FILE has a thermo row at a step >= STEP (10 s at most)
wait_row() {
  for _ in $(seq 1000); do
    [ -f "$1" ] && awk -v s="$2" 'NR > 1 && $1 + 0 >= s { f = 1 } END { exit !f }' "$1" && return 0
    sleep 0.01
  done
  return 1
}
# wait_pid PID: its exit status, or 124 when it runs on for 20 s (then killed)
wait_pid() {
  for _ in $(seq 2000); do
    kill -0 "$1" 2> /dev/null || { wait "$1" 2> /dev/null; return $?; }
    sleep 0.01
  done
  kill -KILL "$1"; wait "$1" 2> /dev/null; return 124
}
# step of a checkpoint, of the last colloids.h5 frame, of the last colloids.xyz frame
ck_step() { $PY -c "import h5py,sys; print(h5py.File(sys.argv[1])['/'].attrs['peloid_checkpoint'][0])" "$1"; }
h5_frames() { $PY -c "import h5py,sys; s=h5py.File(sys.argv[1])['particles/colloids/position/step'][:]; print(len(s), s[-1])" "$1"; }
xyz_last() { grep -o 'step=[0-9]*' "$1" | tail -1 | cut -d= -f2; }

echo "== interrupt / resume in place / one run per folder"

# interrupted SIG CODE: a long run stopped by SIG once thermo.tsv passes step 30
interrupted() {
  local sig=$1 code=$2 d=o_$1
  "$PELOID" run tiny.cfg --out "$d" --steps 1000000 2> "$d.err" &
  local pid=$!
  wait_row "$d/thermo.tsv" 30 || { bad "$sig: no thermo row at step 30"; kill -KILL $pid; return; }
  kill -s "$sig" $pid
  wait_pid $pid; local rc=$?
  local last; last=$(tail -1 "$d.err")
  local s; s=$(sed -n 's/^peloid: interrupted by SIG[A-Z]* at step \([0-9]*\) of 1000000; resume with: .*/\1/p' "$d.err")
  local why=""
  [ $rc -eq "$code" ] || why="$why exit $rc (want $code);"
  [ -n "$s" ] && [ "$(grep -c '^peloid: interrupted' "$d.err")" -eq 1 ] || why="$why no interrupt line;"
  case $last in "peloid: interrupted by SIG$sig at step $s of 1000000; resume with: peloid run tiny.cfg --restart $T/$d/checkpoint.h5 --out $T/$d --steps "*) ;;
                 *) why="$why last line: $last;"; esac
  grep -q 'error' "$d.err" && why="$why an error line;"
  [ -z "$s" ] && s=-1
  [ -f "$d/checkpoint.h5" ] && [ "$(ck_step "$d/checkpoint.h5" 2> /dev/null)" = "$s" ] || why="$why checkpoint not at step $s;"
  $PY -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(not (d['interrupted'] is True and d['last_step'] == int(sys.argv[2])))" \
      "$d/summary.json" "$s" 2> /dev/null || why="$why summary.json not interrupted at $s;"
  [ "$(tail -1 "$d/thermo.tsv" | cut -f1)" = "$s" ] || why="$why last thermo row not step $s;"
  [ -f "$d/colloids.h5" ] && [ "$(h5_frames "$d/colloids.h5" 2> /dev/null | cut -d' ' -f2)" = "$s" ] || why="$why colloids.h5 last frame not $s;"
  [ -f "$d/colloids.xyz" ] && [ "$(xyz_last "$d/colloids.xyz")" = "$s" ] || why="$why colloids.xyz last frame not $s;"
  ls "$d" | grep -q '\.tmp$' && why="$why *.tmp left: $(ls "$d" | tr '\n' ' ');"
  if [ -z "$why" ]; then ok "SIG$sig: exit $rc at step $s, outputs complete: $last"; else bad "SIG$sig:$why"; fi
}
interrupted INT 130
interrupted TERM 143
interrupted HUP 129

# a second signal exits at once: two signals pending together (the run is
# stopped while they are sent), the second ends the process without summary
"$PELOID" run tiny.cfg --out o_twice --steps 1000000 2> twice.err &
pid=$!
if wait_row o_twice/thermo.tsv 30; then
  kill -STOP $pid; kill -TERM $pid; kill -INT $pid; kill -CONT $pid
  wait_pid $pid; rc=$?
  if { [ $rc -eq 143 ] || [ $rc -eq 130 ]; } && grep -q 'second signal: exiting at once' twice.err &&
     [ ! -e o_twice/summary.json ]; then ok "second signal: exit $rc at once"
  else bad "second signal: exit $rc: $(tail -2 twice.err | tr '\n' ' ')"; fi
else bad "second signal: no thermo row at step 30"; kill -KILL $pid; fi

# resume in place: a run interrupted and resumed in its own folder ends
# with that folder equal to an uninterrupted run's (A)
sed 's/output: { thermo_interval = 3;/output: { thermo_interval = 3; checkpoint_interval = 50;/' tiny.cfg > ck.cfg
"$PELOID" run ck.cfg --out A --steps 3000 2> /dev/null || bad "uninterrupted run failed"
same_as_A() { # DIR: what differs from A (thermo without its wall-clock rate column)
  local d=$1 why=""
  cmp -s A/checkpoint.h5 "$d/checkpoint.h5" || why="$why checkpoint.h5 differs;"
  cmp -s <(awk -F'\t' -v OFS='\t' '{NF--; print}' A/thermo.tsv) <(awk -F'\t' -v OFS='\t' '{NF--; print}' "$d/thermo.tsv") ||
    why="$why thermo.tsv: $(wc -l < "$d/thermo.tsv") rows, A $(wc -l < A/thermo.tsv);"
  cmp -s A/colloids.xyz "$d/colloids.xyz" || why="$why colloids.xyz: $(grep -c step= "$d/colloids.xyz") frames, A $(grep -c step= A/colloids.xyz);"
  $PY - A/colloids.h5 "$d/colloids.h5" <<'PYEOF' || why="$why colloids.h5 frames differ;"
import sys, h5py, numpy as np
a, b = (h5py.File(p, "r")["particles/colloids"] for p in sys.argv[1:3])
for k in ("position", "velocity", "orientation", "angular_velocity", "image", "box/edges"):
    for d in ("step", "time", "value"):
        if not np.array_equal(a[k][d][()], b[k][d][()]): sys.exit(1)
PYEOF
  ls "$d" | grep -q '\.tmp$' && why="$why *.tmp left;"
  echo "$why"
}
# SIGINT, then the command the interrupt line gives
"$PELOID" run ck.cfg --out B --steps 3000 2> B.err &
pid=$!
if wait_row B/thermo.tsv 60; then
  kill -INT $pid; wait_pid $pid; rc=$?
  cmd=$(sed -n 's/^peloid: interrupted by SIGINT at step [0-9]* of 3000; resume with: peloid run //p' B.err)
  s=$(sed -n 's/^peloid: interrupted by SIGINT at step \([0-9]*\) .*/\1/p' B.err)
  if [ $rc -eq 130 ] && [ -n "$cmd" ]; then
    # shellcheck disable=SC2086
    "$PELOID" run $cmd 2> B2.err; rc=$?
    why=$(same_as_A B)
    if [ $rc -eq 0 ] && [ -z "$why" ]; then ok "interrupted at step $s, resumed in place with the printed command = uninterrupted ($(wc -l < B/thermo.tsv) rows, checkpoint bitwise)"
    else bad "resume in place after SIGINT: exit $rc ($(tail -1 B2.err)):$why"; fi
  else bad "resume in place: SIGINT exit $rc, line: $(tail -1 B.err)"; fi
else bad "resume in place: no thermo row at step 60"; kill -KILL $pid; fi
# SIGKILL (trajectories left as *.tmp, rows past the last checkpoint), then
# --restart with --force into the same folder (disowned: the shell does not
# report the killed job)
"$PELOID" run ck.cfg --out C --steps 3000 2> /dev/null &
pid=$!
disown $pid
if wait_row C/thermo.tsv 120; then
  kill -KILL $pid
  for _ in $(seq 1000); do kill -0 $pid 2> /dev/null || break; sleep 0.01; done
  s=$(ck_step C/checkpoint.h5 2> /dev/null || echo 0)
  rows=$(wc -l < C/thermo.tsv)
  "$PELOID" run ck.cfg --restart C/checkpoint.h5 --out C --force --steps $((3000 - s)) 2> C2.err; rc=$?
  why=$(same_as_A C)
  if [ $rc -eq 0 ] && [ -z "$why" ]; then ok "killed ($rows rows, checkpoint at step $s), resumed in place with --force = uninterrupted"
  else bad "resume in place after SIGKILL (checkpoint at $s): exit $rc ($(tail -1 C2.err)):$why"; fi
else bad "resume after SIGKILL: no thermo row at step 120"; kill -KILL $pid; fi

# one run per folder: a second run into a folder a run is writing is refused
# (exit 2, one line) even with --force, and the first run's files stay its own
"$PELOID" run tiny.cfg --out o_lock --steps 1000000 2> lock1.err &
pid=$!
if wait_row o_lock/thermo.tsv 30; then
  "$PELOID" run tiny.cfg --out o_lock --force --steps 20 2> lock2.err; rc=$?
  kill -TERM $pid; wait_pid $pid; rc1=$?
  if [ $rc -eq 2 ] && [ "$(wc -l < lock2.err)" -eq 1 ] && grep -q 'another peloid run' lock2.err &&
     [ $rc1 -eq 143 ] && [ "$(head -c 4 o_lock/thermo.tsv)" = step ] &&
     awk 'NR > 2 && $1 + 0 <= p { exit 1 } NR > 1 { p = $1 + 0 }' o_lock/thermo.tsv &&
     [ "$($PY -c "import json; print(json.load(open('o_lock/summary.json'))['last_step'])")" = \
       "$(tail -1 o_lock/thermo.tsv | cut -f1)" ]; then
    ok "second run into a locked folder refused: $(cat lock2.err)"
  else bad "lock: second run exit $rc ($(head -c 300 lock2.err)), first exit $rc1"; fi
else bad "lock: no thermo row at step 30"; kill -KILL $pid; fi
# ... and the lock ends with the run
"$PELOID" run tiny.cfg --out o_lock --force --steps 10 2> /dev/null && ok "the folder is free after the run" ||
  bad "a run after the locked one was refused"

# --force clears what an earlier run wrote: a fluid-only run after a colloid
# run with a report leaves no colloid file, report or temporary file behind
sed -e '/^colloids:/,/^coupling:/d' -e 's/colloids_xyz = true;/fields_interval = 5;/' tiny.cfg > fluid.cfg
"$PELOID" run tiny.cfg --out o_force --steps 20 2> /dev/null
touch o_force/report.md o_force/thermo.png o_force/msd.png o_force/checkpoint.h5.tmp o_force/notes.txt
"$PELOID" run fluid.cfg --out o_force --force --steps 20 2> force.err; rc=$?
left=$(cd o_force && ls | tr '\n' ' ')
if [ $rc -eq 0 ] && [ "$left" = "checkpoint.h5 fields.h5 fields.xdmf notes.txt scene.cfg summary.json thermo.tsv " ]; then
  ok "--force cleared the earlier run's files (left: $left)"
else bad "--force: exit $rc, left: $left"; fi

# a sweep point whose run was interrupted is not finished: the next sweep runs it again
sed 's/^steps = 400;/steps = 10;/' fluid.cfg > sweep_base.cfg
printf 'name = "s";\nscene = "sweep_base.cfg";\nout = "o_sweep";\ngrid = ( { key = "seed"; values = [1, 2]; } );\n' > study.cfg
"$PELOID" sweep study.cfg --point 0 2> /dev/null
$PY -c "import json; p='o_sweep/p000/summary.json'; d=json.load(open(p)); d['interrupted']=True; json.dump(d, open(p, 'w'))"
"$PELOID" sweep study.cfg --point 0 2> sweep.err; rc=$?
if [ $rc -eq 0 ] && $PY -c "import json,sys; sys.exit(json.load(open('o_sweep/p000/summary.json'))['interrupted'] is not False)"; then
  ok "sweep runs an interrupted point again: $(grep -o '[0-9]*/1 done ([0-9]* skipped)' sweep.err | tail -1)"
else bad "sweep after an interrupted point: exit $rc, p000 not run again"; fi

echo "interrupt: $pass passed, $fail failed"
[ $fail -eq 0 ]
