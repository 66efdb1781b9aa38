#!/usr/bin/env bash
# Issue 18: a full disk.  Every output write is checked: on a 200 KiB tmpfs
# a run stops with exit 4 and one line naming the file and the system error
# ("No space left on device"), with no HDF5 error stack, no crash in HDF5's
# exit handler (before: exit 139 after ~100 lines of HDF5 diagnostics) and
# no partial checkpoint.h5.tmp left behind; thermo.tsv rows are never lost
# silently (before: exit 0 with the file cut mid-number).  Needs root (mount).
set -u
PELOID=$(realpath "${1:-bin/peloid}")

# Without root: the issue-15 writers (colloids.xyz, fields.xdmf) on a full
# device, their temporary file a link to /dev/full (every write fails with
# ENOSPC): exit 4, one line naming the file and the system error.
D=$(mktemp -d /tmp/peloid-devfull.XXXXXX)
dpass=0; dfail=0
devfull() { # devfull NAME TMPNAME SCENE_TEXT NEEDLE...
  local name=$1 tmpname=$2 text=$3; shift 3
  printf '%b' "$text" > "$D/$name.cfg"
  mkdir -p "$D/$name" && ln -sf /dev/full "$D/$name/$tmpname"
  "$PELOID" run "$D/$name.cfg" --out "$D/$name" --force 2> "$D/err.txt"; local rc=$?
  local okk=1
  [ $rc -eq 4 ] || okk=0
  [ "$(grep -c 'peloid: error' "$D/err.txt")" -eq 1 ] || okk=0
  for n in "$@"; do grep -qF -- "$n" "$D/err.txt" || okk=0; done
  if [ $okk = 1 ]; then dpass=$((dpass+1)); echo "  ok   $name: $(grep 'peloid: error' "$D/err.txt")"
  else dfail=$((dfail+1)); echo "  FAIL $name (rc=$rc): $(head -c 600 "$D/err.txt")"; fi
}
echo "== output writes on /dev/full"
devfull xyz colloids.xyz.tmp 'seed = 1;\nsteps = 20;\nbox: { cells = [8, 8, 8]; };\nfluid: { density = 0.0; };\ncolloids: { count = 8; radius = 1.0; pairs = ""; trajectory_interval = 5; };\noutput: { colloids_xyz = true; };\n' \
  "colloids.xyz.tmp: writing the frame of step 0 failed: No space left on device"
devfull xdmf fields.xdmf.tmp 'seed = 1;\nsteps = 4;\nbox: { cells = [4, 4, 4]; };\noutput: { fields_interval = 2; };\n' \
  "fields.xdmf.tmp: write failed: No space left on device"
rm -rf "$D"
echo "full_disk.sh (/dev/full): $dpass passed, $dfail failed"
if [ "$(id -u)" != 0 ]; then echo "skipped: full-disk test (needs root)"; [ $dfail -eq 0 ]; exit; fi
T=$(mktemp -d /tmp/peloid-full.XXXXXX)
M="$T/disk"
mkdir -p "$M"
if ! mount -t tmpfs -o size=200k tmpfs "$M" 2> /dev/null; then
  echo "skipped: full-disk test (cannot mount a tmpfs here)"; rm -rf "$T"; exit 0
fi
trap 'umount "$M"; rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }

# full NAME SCENE_TEXT NEEDLE...: exit 4, exactly one error line with the
# needles and nothing else but the start line, no .tmp file left
full() {
  local name=$1 text=$2; shift 2
  rm -rf "$M"/*
  printf '%b' "$text" > "$name.cfg"
  "$PELOID" run "$name.cfg" --out "$M/$name" 2> err.txt; local rc=$?
  local okk=1
  [ $rc -eq 4 ] || okk=0
  [ "$(grep -c 'peloid: error' err.txt)" -eq 1 ] || okk=0
  [ "$(grep -vc '^peloid: ' err.txt)" -eq 0 ] || okk=0  # no HDF5 diagnostics
  for n in "$@"; do grep -qF -- "$n" err.txt || okk=0; done
  [ -e "$M/$name/checkpoint.h5.tmp" ] && okk=0  # the partial trajectory .tmp may stay
  if [ $okk = 1 ]; then ok "$name: $(grep 'peloid: error' err.txt)"; else bad "$name (rc=$rc): $(head -c 600 err.txt)"; fi
}

echo "== full-disk tests (200 KiB tmpfs)"
full checkpoint 'seed = 1;\nsteps = 3;\nbox: { cells = [24, 24, 24]; };\nfluid: { density = 5.0; };\n' \
  "checkpoint.h5.tmp: writing the checkpoint failed: No space left on device"
full thermo 'seed = 1;\nsteps = 20000;\nbox: { cells = [4, 4, 4]; };\nfluid: { density = 2.0; };\noutput: { thermo_interval = 1; };\n' \
  "thermo.tsv: writing the row of step" "No space left on device"
full trajectory 'seed = 1;\nsteps = 2000;\nbox: { cells = [16, 16, 16]; };\nfluid: { density = 0.0; };\ncolloids: { count = 64; radius = 1.0; pairs = ""; trajectory_interval = 1; };\noutput: { thermo_interval = 1000; };\n' \
  "colloids.h5.tmp: writing the frame of step" "No space left on device"

echo "full_disk.sh: $pass passed, $fail failed"
[ $fail -eq 0 ] && [ $dfail -eq 0 ]
