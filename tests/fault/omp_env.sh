#!/usr/bin/env bash
# OpenMP settings a batch scheduler or a user may set (issue 48): a team
# smaller than asked (OMP_DYNAMIC, OMP_THREAD_LIMIT), lists, binding and
# waiting policies give the same checkpoint bits as a plain 2-thread run;
# a worker stack too small for the kernels (OMP_STACKSIZE=16K, which
# overflowed it) is refused: exit 2, one line naming OMP_STACKSIZE, nothing
# written.  Three scenes: the pure fluid (sort, stream), coupling I
# (reflections) and the potential coupling (selection), short runs.
set -u
PELOID=$(realpath "${1:-bin/peloid}")
ROOT=$(realpath "$(dirname "$0")/../..")
T=$(mktemp -d /tmp/peloid-omp.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }

echo "== OpenMP settings: the same bits or a clear refusal"
printf 'name = "f";\nseed = 5;\nsteps = 30;\nbox: { cells = [16, 12, 20]; };\nfluid: { density = 10.0; };\nsrd: { dt = 0.1; grid_shift = true; };\n' > fluid.cfg
sed -e 's/steps = 2000;/steps = 6;/' -e 's/\[24, 24, 24\]/[16, 16, 16]/' -e 's/count = 27;/count = 8;/' \
  "$ROOT/scenes/coupling_hecht1.cfg" > hecht1.cfg
sed -e 's/steps = 2000;/steps = 4;/' "$ROOT/scenes/coupling_potential.cfg" > potential.cfg
for s in fluid hecht1 potential; do
  env -u OMP_DYNAMIC -u OMP_THREAD_LIMIT -u OMP_NUM_THREADS -u OMP_STACKSIZE \
    "$PELOID" run $s.cfg --out ref_$s --threads 2 > /dev/null 2> err.txt \
    || { bad "$s: the plain run failed: $(tail -1 err.txt)"; continue; }
  # setting | --threads
  while IFS='|' read -r setting threads; do
    out="o_${s}_$(echo "$setting$threads" | tr -c 'A-Za-z0-9' _)"
    env $setting "$PELOID" run $s.cfg --out "$out" $threads > /dev/null 2> err.txt; rc=$?
    if [ $rc -eq 0 ] && cmp -s ref_$s/checkpoint.h5 "$out/checkpoint.h5"; then
      ok "$s: $setting $threads: bitwise the plain run$(grep -o 'note:.*' err.txt | head -1 | sed 's/^/ (/;s/$/)/')"
    else
      bad "$s: $setting $threads: rc $rc, $(tail -1 err.txt)"
    fi
  done <<'LIST'
OMP_DYNAMIC=true|--threads 2
OMP_DYNAMIC=true|
OMP_THREAD_LIMIT=1|--threads 3
OMP_THREAD_LIMIT=2|--threads 3
OMP_NUM_THREADS=3,2|
OMP_NUM_THREADS=2,1,1|
OMP_STACKSIZE=1M|--threads 2
OMP_PROC_BIND=spread OMP_PLACES=cores|--threads 2
OMP_WAIT_POLICY=passive GOMP_SPINCOUNT=0|--threads 2
OMP_MAX_ACTIVE_LEVELS=1 OMP_NESTED=false|--threads 3
LIST
done

# too little stack for a worker thread: refused before anything is written
for st in 16K 100K; do
  OMP_STACKSIZE=$st "$PELOID" run fluid.cfg --out stack_$st --threads 2 > /dev/null 2> err.txt; rc=$?
  if [ $rc -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] && grep -q "OMP_STACKSIZE=$st" err.txt && [ ! -e stack_$st ]; then
    ok "OMP_STACKSIZE=$st refused: $(cat err.txt)"
  else
    bad "OMP_STACKSIZE=$st: rc $rc, out $([ -e stack_$st ] && echo written || echo absent): $(cat err.txt)"
  fi
done
# one thread runs on the process stack: the setting does not matter there
OMP_STACKSIZE=16K "$PELOID" run fluid.cfg --out stack_one --threads 1 > /dev/null 2> err.txt \
  && cmp -s ref_fluid/checkpoint.h5 stack_one/checkpoint.h5 && ok "OMP_STACKSIZE=16K with --threads 1: bitwise the plain run" \
  || bad "OMP_STACKSIZE=16K --threads 1: $(tail -1 err.txt)"

echo "omp_env: $pass passed, $fail failed"
[ $fail -eq 0 ]
