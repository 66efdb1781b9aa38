#!/usr/bin/env bash
# peloid sweep and signals (src/app/sweep.c, src/app/main.c): a SIGTERM to the
# sweep is forwarded to its running points (each in its own process group),
# which stop at a checkpoint; the sweep writes sweep.tsv (status
# "interrupted"), prints one line and exits 143, and no `peloid run` outlives
# it.  The next sweep resumes each interrupted point from its own checkpoint
# (first_step > 0) to the scene's last step, exit 0.  Two signals in a row
# kill the points at once: exit 128 + the first, none left running; the next sweep
# resumes them from their last periodic checkpoint.  Each wait is for a
# condition (thermo.tsv rows, a process gone), bounded by a timeout.
set -u
PELOID=$(realpath "${1:-bin/peloid}")
PY=/usr/bin/python3
T=$(mktemp -d /tmp/peloid-sweepsig.XXXXXX)
# the runs get the default action of the signals under test even when this
# suite was started with them ignored (a background job of a non-interactive
# shell, nohup): peloid keeps a signal its caller ignores, as it should
printf '#!/bin/sh\nexec env --default-signal=INT,TERM,HUP "%s" "$@"\n' "$PELOID" > "$T/peloid-default-signals"
chmod +x "$T/peloid-default-signals"
PELOID=$T/peloid-default-signals
T=$(realpath "$T")
# the points a sweep of this test left running (cwd $T): none, unless it fails
alive() {
  for p in /proc/[0-9]*; do
    [ "$(readlink "$p/cwd" 2>/dev/null)" = "$T" ] || continue
    tr '\0' ' ' < "$p/cmdline" 2>/dev/null | grep -q " run out/" && echo "${p#/proc/}"
  done
}
cleanup() { for p in $(alive); do kill -KILL "$p" 2>/dev/null; done; rm -rf "$T"; }
trap cleanup EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
echo "== sweep signal tests"
t0=$(date +%s.%N)
# until COND holds or SECONDS pass: 0 if it holds
wait_for() { local end=$(( $(date +%s) + $1 )); shift; until eval "$1"; do [ "$(date +%s)" -ge "$end" ] && return 1; sleep 0.02; done; }
rows() { [ "$(cat out/$1/p000/thermo.tsv 2>/dev/null | wc -l)" -ge 3 ] && [ "$(cat out/$1/p001/thermo.tsv 2>/dev/null | wc -l)" -ge 3 ]; }

# 2 points of a Brownian scene of 20000 steps (~0.7 s a point): the signal
# comes once both have thermo rows, long before either ends
cat > bd.cfg <<'CFG'
name = "bd";
seed = 11;
steps = 20000;
box: { cells = [8, 8, 8]; };
fluid: { density = 0.0; };
srd: { dt = 0.1; };
colloids: { count = 16; radius = 1.0; mass_density = 1.0; temperature = 1.0; init = "random";
  pairs = ""; integrator = "brownian"; bd_viscosity = 0.02; substeps = 1; max_overlap = 1.0; };
output: { thermo_interval = 100; };
CFG
sed 's/^output: { thermo_interval = 100; };/output: { thermo_interval = 100; checkpoint_interval = 500; };/' bd.cfg > bdk.cfg
printf 'scene = "bd.cfg"; out = "out/sig";\ngrid = ( { key = "seed"; values = [1, 2]; } );\n' > sig.cfg
printf 'scene = "bdk.cfg"; out = "out/kill";\ngrid = ( { key = "seed"; values = [1, 2]; } );\n' > kill.cfg

# 1. SIGTERM: forwarded, points stop at a checkpoint, table, one line, 143
"$PELOID" sweep sig.cfg --jobs 2 --threads 1 2> sig.err & sp=$!
if wait_for 20 "rows sig"; then
  kill -TERM $sp
  wait_for 20 "! kill -0 $sp 2>/dev/null"; wait $sp; rc=$?
  left=$(alive | tr "\n" " ")
  if [ $rc = 143 ] && [ -z "$left" ]; then ok "SIGTERM: sweep exit 143, no point left running"
  else bad "SIGTERM: exit $rc, still running: ${left:-none}; $(tail -2 sig.err)"; fi
  if $PY - <<'PY'
import json
rows = [l.rstrip("\n").split("\t") for l in open("out/sig/sweep.tsv")][1:]
assert [(r[0], r[1], r[2]) for r in rows] == [("p000", "interrupted", "143"), ("p001", "interrupted", "143")], rows
for k in ("p000", "p001"):
    s = json.load(open(f"out/sig/{k}/summary.json"))
    assert s["interrupted"] and 0 < s["last_step"] < 20000, s["last_step"]
PY
  then ok "sweep.tsv: both points 'interrupted' (143), each summary.json interrupted before step 20000"
  else bad "sweep.tsv after SIGTERM: $(cat out/sig/sweep.tsv 2>&1 | cut -c1-200)"; fi
  tail -1 sig.err | grep -q "^peloid: sweep sig: interrupted by signal 15: 2 point(s) stopped at a checkpoint.*resume with: peloid sweep sig.cfg --out out/sig" \
    && ok "one line: $(tail -1 sig.err | cut -c1-140)" || bad "last line: $(tail -1 sig.err)"
else bad "the points wrote no thermo rows in 20 s: $(tail -2 sig.err)"; kill -KILL $sp 2>/dev/null; fi

# 2. the next sweep resumes each interrupted point from its checkpoint
for p in $(alive); do kill -KILL "$p"; done # what the old code left behind
timeout 60 "$PELOID" sweep sig.cfg --jobs 2 --threads 1 2> resume.err; rc=$?
if [ $rc = 0 ] && grep -q "0 finished before, 2 to run (2 from its checkpoint)" resume.err && $PY - <<'PY'
import json
for k in ("p000", "p001"):
    s = json.load(open(f"out/sig/{k}/summary.json"))
    assert not s["interrupted"] and 0 < s["first_step"] and s["last_step"] == 20000, (k, s["first_step"], s["last_step"])
rows = [l.rstrip("\n").split("\t") for l in open("out/sig/sweep.tsv")][1:]
assert [(r[0], r[1]) for r in rows] == [("p000", "ok"), ("p001", "ok")], rows
PY
then ok "resume: both points continued from their checkpoints (first_step > 0) to step 20000, exit 0"
else bad "resume (rc $rc): $(tail -2 resume.err)"; fi

# 3. two signals in a row: the points are killed at once (each has written a
#    checkpoint every 500 steps), and the next sweep resumes them from it
"$PELOID" sweep kill.cfg --jobs 2 --threads 1 2> kill.err & sp=$!
if wait_for 20 "rows kill && [ -f out/kill/p000/checkpoint.h5 ] && [ -f out/kill/p001/checkpoint.h5 ]"; then
  # two different signals, both pending when the sweep goes on (two equal
  # ones would merge into one; SIGINT is ignored in a background job of a
  # script): the handler sees both before the sweep's loop
  kill -STOP $sp; kill -TERM $sp; kill -HUP $sp; kill -CONT $sp
  wait_for 10 "! kill -0 $sp 2>/dev/null"; wait $sp; rc=$?
  left=$(alive | tr "\n" " ")
  if { [ $rc = 129 ] || [ $rc = 143 ]; } && [ -z "$left" ] && grep -q "^137	killed: a second signal" out/kill/status/p000.tsv \
     && tail -1 kill.err | grep -q "killed by a second signal"; then
    ok "two signals: the points killed, exit $rc, none left running"
  else bad "two signals: exit $rc, still running: ${left:-none}; $(tail -1 kill.err)"; fi
  timeout 60 "$PELOID" sweep kill.cfg --jobs 2 --threads 1 2> kresume.err; rc=$?
  if [ $rc = 0 ] && grep -q "0 finished before, 2 to run (2 from its checkpoint)" kresume.err && $PY - <<'PY'
import json
for k in ("p000", "p001"):
    s = json.load(open(f"out/kill/{k}/summary.json"))
    assert not s["interrupted"] and 0 < s["first_step"] and s["last_step"] == 20000, (k, s["first_step"], s["last_step"])
PY
  then ok "killed points (no summary.json) resume from their last checkpoint (first_step > 0) to step 20000, exit 0"
  else bad "resume after kill (rc $rc): $(tail -2 kresume.err)"; fi
else bad "kill: no thermo rows or checkpoints in 20 s"; kill -KILL $sp 2>/dev/null; fi
# 4. a signal to one point alone (not through the sweep): that point stops at
#    a checkpoint, the sweep goes on and exits 1, the table says interrupted
#    (a point far longer than the test: it cannot end on its own between the
#    wait and the signal, as a 20000-step BD point could on an idle machine)
sed 's/^steps = 20000;/steps = 100000000;/' bd.cfg > bdlong.cfg
printf 'scene = "bdlong.cfg"; out = "out/one";\ngrid = ( { key = "seed"; values = [1]; } );\n' > one.cfg
"$PELOID" sweep one.cfg --jobs 1 --threads 1 2> one.err & sp=$!
if wait_for 20 '[ "$(cat out/one/p000/thermo.tsv 2>/dev/null | wc -l)" -ge 3 ] && [ -n "$(alive)" ]'; then
  kill -TERM $(alive)
  wait_for 20 "! kill -0 $sp 2>/dev/null"; wait $sp; rc=$?
  st=$(awk -F'\t' '$1 == "p000" { print $2 }' out/one/sweep.tsv 2>/dev/null)
  [ $rc = 1 ] && [ "$st" = interrupted ] && ok "a point signalled alone: table 'interrupted', sweep exit 1" \
    || bad "a point signalled alone: exit $rc, table '$st': $(tail -1 one.err)"
else bad "one: no thermo rows in 20 s"; kill -KILL $sp 2>/dev/null; fi
echo "  sweep signal tests: $pass passed, $fail failed ($(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }') s)"
[ $fail = 0 ]
