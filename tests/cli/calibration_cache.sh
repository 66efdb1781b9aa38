#!/usr/bin/env bash
# The calibration cache can never cost a run (src/app/calibration_cache.c,
# src/app/calibrate.c).  The scene is coupling II at a coarse resolution
# whose calibration takes ~0.3 s (3 particles per cell, mean free path 0.5,
# a neutrally buoyant colloid: 320 steps of a 16^3 box), so every case runs a
# real calibration; each run is `peloid params --json`, which calibrates and
# writes nothing else.  The tests run as root, for whom a read-only folder
# is writable, so a folder that cannot take the result is made otherwise:
#  1. PELOID_CACHE a regular file; the entry's name a directory; its .tmp a
#     directory; a full disk (file size limit 0, SIGXFSZ ignored: write
#     fails with EFBIG as on ENOSPC); /dev/null where the entry or its .tmp
#     goes; a FIFO where the entry goes: exit 0, the calibration used (the
#     same D bits as a stored one) with one warning naming the folder or the
#     entry, and, where it cannot be stored, how to fix it (PELOID_CACHE);
#  2. entries that parse but are wrong: D x 1000 (d_inf alone), 1e-300,
#     1e300, not JSON: a warning naming the entry and the value, a fresh
#     calibration, and the entry rewritten with it (the same bits);
#  3. the lock: a holder that stopped itself (SIGSTOP) is named (pid, host,
#     time, "stopped") and given up on after PELOID_CACHE_LOCK_TIMEOUT;
#     a lock held by a child that outlives the holder it records (a pid that
#     no longer exists here) is taken over and the entry stored; four
#     concurrent runs of a fresh cache calibrate once.
# Shown to fail on ba8830d (before this suite): 1 (exit 4, or a hang on the
# FIFO), 2 (the bad values used: exit 0 with D x 1000, or blamed on
# physical.gravity / mapping.energy_scale), 3 (waits until killed).
set -u
PELOID=$(realpath "${1:-bin/peloid}")
PY=/usr/bin/python3
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
T=$(mktemp -d /tmp/peloid-calcache.XXXXXX)
HOLD=""
trap '[ -n "$HOLD" ] && kill -CONT $HOLD 2>/dev/null && kill $HOLD 2>/dev/null; rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
echo "== the calibration cache never costs a run"
export PELOID_NO_SHIPPED_CALIBRATION=1
unset PELOID_CACHE_LOCK_TIMEOUT

cat > s.cfg <<CFG
name = "cache";
seed = 7;
steps = 10;
$(cat "$ROOT/tests/support/calibration_coarse_ii.inc")
CFG
dinf() { $PY -c "import json,sys; print(repr(json.load(open(sys.argv[1]))['mapping']['colloid_diffusion']['calibration']['d_inf_a0_2_t0']))" "$1" 2>/dev/null; }
entry_dinf() { [ -f "$1" ] && $PY -c "import json,sys; print(repr(json.load(open(sys.argv[1]))['d_inf']))" "$1" 2>/dev/null; }
# run CACHE TAG [timeout]: params --json with PELOID_CACHE=CACHE; TAG.json, TAG.err, $rc
run() { PELOID_CACHE=$1 timeout "${3:-20}" "$PELOID" params --json s.cfg > "$2.json" 2> "$2.err"; rc=$?; }

# the reference: a fresh calibration, stored
run "$T/ref" ref
D=$(dinf ref.json); E=$(ls "$T"/ref/calibration-*.json 2>/dev/null | head -1); NAME=$(basename "${E:-none}")
if [ $rc = 0 ] && [ -n "$D" ] && [ -f "$E" ] && [ "$(entry_dinf "$E")" = "$D" ]; then
  ok "reference calibration stored ($NAME, D = $D a0^2/t0)"
else echo "  FAIL reference calibration: rc $rc $(tail -1 ref.err)"; exit 1; fi

# 1. a folder that cannot take the result: this run uses it, with a warning naming the folder and the fix
#    (the entry's name a directory: a second warning says the entry is not one)
unstorable() { # LABEL CACHE TAG FOLDER-or-ENTRY-NAMED [FIX]
  if [ $rc = 0 ] && [ "$(dinf "$3.json")" = "$D" ] && grep -q "warning: .*$4" "$3.err" \
     && { [ -z "${5:-}" ] || grep -q "warning: .*$4.*$5" "$3.err"; }; then
    ok "$1: exit 0, D used, warning: $(grep warning "$3.err" | head -1 | cut -c1-150)..."
  else bad "$1: rc $rc, D $(dinf "$3.json"): $(tr '\n' '|' < "$3.err" | cut -c1-300)"; fi
}
: > file; run "$T/file" f1
unstorable "PELOID_CACHE a regular file" "$T/file" f1 "$T/file" "set PELOID_CACHE to a writable folder"
run "$T/file" f2   # the next run says it again, with the fix
unstorable "PELOID_CACHE a regular file, the next run" "$T/file" f2 "$T/file" "set PELOID_CACHE to a writable folder"
mkdir -p d1/"$NAME"; run "$T/d1" d1
unstorable "the entry's name a directory" "$T/d1" d1 "$T/d1" "set PELOID_CACHE to a writable folder"
mkdir -p d2/"$NAME.tmp"; run "$T/d2" d2
unstorable "the entry's .tmp a directory" "$T/d2" d2 "$T/d2" "set PELOID_CACHE to a writable folder"
mkdir -p full
# (a pipe takes stdout and stderr: the size limit holds for regular files; the warnings come first)
(trap '' XFSZ; ulimit -f 0; PELOID_CACHE=$T/full exec timeout 20 "$PELOID" params --json s.cfg 2>&1) | cat > full.out
rc=${PIPESTATUS[0]}; grep '^peloid:' full.out > full.err; grep -v '^peloid:' full.out > full.json
unstorable "a full disk (write fails: EFBIG)" "$T/full" full "$T/full" "set PELOID_CACHE to a writable folder"
# /dev/null or a FIFO as the entry: not an entry (warning), replaced by the calibration
for k in devnull fifo; do
  mkdir -p $k
  if [ $k = devnull ]; then ln -s /dev/null $k/"$NAME"; else mkfifo $k/"$NAME"; fi
  run "$T/$k" $k
  unstorable "$k as the entry" "$T/$k" $k "$NAME: not a regular file"
  [ "$(entry_dinf "$k/$NAME")" = "$D" ] && ok "$k as the entry: replaced by the calibration" \
    || bad "$k as the entry: not replaced"
done
mkdir -p tnull; ln -s /dev/null tnull/"$NAME.tmp"; run "$T/tnull" tnull
if [ $rc = 0 ] && [ "$(dinf tnull.json)" = "$D" ] && [ "$(entry_dinf "tnull/$NAME")" = "$D" ]; then
  ok "/dev/null as the .tmp: exit 0, the stale .tmp replaced and the entry stored"
else bad "/dev/null as the .tmp: rc $rc: $(tail -1 tnull.err)"; fi

# 2. an entry that parses but is wrong: recalibrated and overwritten, with a warning naming it and the value
plant() { mkdir -p "$1"; $PY - "$E" "$1/$NAME" "$2" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
if sys.argv[3] == "nojson":
    open(sys.argv[2], "w").write('{"version": 1, "d_inf": ')
    sys.exit(0)
d["d_inf"] = eval(sys.argv[3], {"d": d["d_inf"]})
json.dump(d, open(sys.argv[2], "w"), indent=2)
PY
}
i=0
for v in "d * 1000" 1e-300 1e300 nojson; do
  i=$((i+1)); tag=bad$i; plant "$T/$tag" "$v"; run "$T/$tag" $tag
  if [ $rc = 0 ] && [ "$(dinf $tag.json)" = "$D" ] && grep -q "warning: calibration cache entry $T/$tag/$NAME: .*recalibrating and overwriting it" $tag.err \
     && grep -q "calibrating the colloid" $tag.err && [ "$(entry_dinf "$tag/$NAME")" = "$D" ] \
     && { [ "$v" = nojson ] || grep -q "'d_inf' = " $tag.err; }; then
    ok "entry with d_inf = $v: recalibrated, overwritten: $(grep warning $tag.err | head -1 | sed "s|$T/||" | cut -c1-170)..."
  else bad "entry with d_inf = $v: rc $rc, D $(dinf $tag.json): $(tr '\n' '|' < $tag.err | cut -c1-300)"; fi
done

# 3a. a holder that stopped itself: named, given up on after the timeout, the run calibrates without storing
hold() { # FOLDER MODE: flock the entry's lock, record a holder, then stop (stop) or hand the lock to a child (orphan)
  mkdir -p "$1"; $PY - "$1/$NAME.lock" "$2" <<'PY' &
import fcntl, os, signal, socket, sys, time
f = open(sys.argv[1], "a+")
fcntl.flock(f, fcntl.LOCK_EX)
f.truncate(0); f.write("pid %d host %s since %d\n" % (os.getpid(), socket.gethostname(), int(time.time()) - 5)); f.flush()
if sys.argv[2] == "stop":
    os.kill(os.getpid(), signal.SIGSTOP)
    time.sleep(60)
elif os.fork() == 0:   # the child keeps the lock; the holder it records exits
    open(sys.argv[1] + ".child", "w").write(str(os.getpid()))
    time.sleep(60)
PY
  HOLD=$!
  for _ in $(seq 50); do [ -s "$1/$NAME.lock" ] && break; sleep 0.1; done
}
hold "$T/stop" stop
s=$(date +%s.%N)
PELOID_CACHE_LOCK_TIMEOUT=2 run "$T/stop" stop 15
w=$($PY -c "import sys; print('%.1f' % (float(sys.argv[2]) - float(sys.argv[1])))" "$s" "$(date +%s.%N)")
kill -CONT $HOLD 2>/dev/null; kill $HOLD 2>/dev/null; wait $HOLD 2>/dev/null; HOLD=""
if [ $rc = 0 ] && [ "$(dinf stop.json)" = "$D" ] && grep -q "waiting for the calibration cache lock .*held by pid [0-9]* on $(hostname) for [0-9]* s (stopped)" stop.err \
   && grep -q "warning: calibration cache lock .*gave up after 2 s" stop.err && [ ! -f "stop/$NAME" ]; then
  ok "a stopped lock holder: named, given up on after 2 s, calibrated without storing ($w s): $(grep waiting stop.err | head -1 | sed "s|$T/||" | cut -c1-160)..."
else bad "a stopped lock holder: rc $rc ($w s): $(tr '\n' '|' < stop.err | cut -c1-400)"; fi

# 3b. a lock whose recorded holder no longer exists here: taken over, the entry stored
hold "$T/orphan" orphan
wait $HOLD 2>/dev/null   # the recorded holder exits; its child keeps the lock
for _ in $(seq 50); do [ -s "$T/orphan/$NAME.lock.child" ] && break; sleep 0.1; done
HOLD=$(cat "$T/orphan/$NAME.lock.child" 2>/dev/null)
run "$T/orphan" orphan 15
kill $HOLD 2>/dev/null; HOLD=""
if [ $rc = 0 ] && [ "$(dinf orphan.json)" = "$D" ] && grep -q "no longer exists: taking it over" orphan.err \
   && [ "$(entry_dinf "orphan/$NAME")" = "$D" ]; then
  ok "a lock held for a holder that no longer exists: taken over, stored"
else bad "a lock held for a holder that no longer exists: rc $rc: $(tr '\n' '|' < orphan.err | cut -c1-300)"; fi

# 3c. four concurrent runs on a fresh cache: one calibration, the same D everywhere
pids=""
for i in 1 2 3 4; do PELOID_CACHE=$T/conc timeout 30 "$PELOID" params --json s.cfg > c$i.json 2> c$i.err & pids="$pids $!"; done
okc=1; for p in $pids; do wait $p || okc=0; done
n=$(cat c?.err | grep -c "calibrating the colloid")
for i in 1 2 3 4; do [ "$(dinf c$i.json)" = "$D" ] || okc=0; done
[ $okc = 1 ] && [ "$n" = 1 ] && ok "four concurrent runs on a fresh cache: one calibration, the same D" \
  || bad "four concurrent runs: ok $okc, $n calibrations: $(cat c?.err | tr '\n' '|' | cut -c1-300)"

echo "calibration_cache: $pass passed, $fail failed"
[ $fail -eq 0 ]
