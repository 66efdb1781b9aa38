#!/bin/bash
# One machine, one table: measures what a node gives peloid and appends one
# dated Markdown section to bench/RESULTS.md (issue 38):
#   1. STREAM triad GB/s at each thread count (build/bench/bench_srd);
#   2. the fluid step at L = 64 and L = 120 (bench_srd, the plan that
#      `peloid run` executes): updates/s, ns per particle, % of the triad
#      bound measured just before each case;
#   3. the dense colloid scenes bench/scenes/fig14_model.cfg and
#      fig9_model.cfg (`peloid run`, loop wall time from summary.json, as in
#      bench/time_to_science.sh): seconds per collision step;
#   4. sweep throughput: `peloid sweep` of an N-point study of the Fig. 9
#      scene (seeds 1..N) as N processes x 1 thread against one N-thread
#      run, steps/s in total; with N = nproc the sweep runs with its own
#      plan of jobs x threads (README "Parameter sweeps") and the table
#      quotes it and its reason (bench/sweep_plan.sh: the plan against
#      --jobs 1 --threads N on the same study);
#   5. LAMMPS `fix srd` on bench/peers/in.srd_fluid_pure at 1 and N MPI
#      ranks, interleaved with peloid on the same fluid and L (skipped, with
#      a line saying so, when no LAMMPS with the SRD package is installed).
# Threads: 1, 2, 4, ... below N, and N (N = nproc), or --threads LIST.
# Repeated measurements: median and min..max; the counts used are in the table.
#
#   bench/node.sh [--budget SECONDS] [--threads 1,2,4] [--dry-run] [--out FILE] [--note TEXT]
#     --budget   wall seconds for the whole script, build included (default 480)
#     --threads  thread counts (comma-separated; N = the largest)
#     --dry-run  probe the rates (a few seconds), print the plan, measure nothing
#     --out      Markdown file the section is appended to (default bench/RESULTS.md)
#     --note     a line for the section's notes (repeatable), e.g. what else ran
# One machine-readable line per case goes to bench/out/node.tsv (part, case,
# threads, median, min, max, unit, repetitions); bench_srd's own TSVs to
# bench/out/node/.
#
# Budget: the clock starts when the script starts.  After the build (if one
# is needed) it times short probes (bench_srd at L = 64 on one thread, 3
# steps of each colloid scene, one LAMMPS run at L = 32), then gives each
# part a share of the time left (fluid 30 %, colloid scenes 30 %, sweep 15 %,
# LAMMPS 25 %; without LAMMPS its share goes to the others) and picks for it
# the largest repetitions / steps whose predicted time fits (a cost model:
# set-up + steps x the probed time per step, thread speed-up assumed t/2).
# Each part is planned again from the time really left when it starts, and
# runs under `timeout`; a part that cannot fit its smallest plan is skipped
# and the table says so.  Every external run's time limit ends before the
# budget does, so the budget holds even when a probe misjudged a part.
#
# Needs: bash, coreutils (timeout), awk, sed; bin/peloid and
# build/bench/bench_srd (built here with `make -j$(nproc)` when missing:
# needs the Makefile, a C compiler and the libraries of the build); optional:
# lscpu, hwloc (lstopo-no-graphics, hwloc-calc), git, python3 (the sweep's
# collect step; the table reads the points' summary.json itself), lmp and
# mpirun (Debian: apt-get install lammps).
# To run on another machine from a copy of the tree, carry at least
#   bench/node.sh bench/common.sh bench/scenes/ bench/peers/ bin/peloid build/bench/
# (binaries built for that CPU: -march=native, and linked against the shared
# libraries of the build: hdf5, gsl, hwloc, libconfig, jansson; better copy the whole tree,
# `git archive HEAD`, and let the script build there), then run
#   bench/node.sh [--budget 480]
# from anywhere; it works in the tree that holds it.
set -u
cd "$(dirname "$0")/.." || exit 1
T0=$(date +%s)
BUDGET=480; TLIST=""; USER_T=""; DRY=0; OUTMD=bench/RESULTS.md; NOTES=()
die() { echo "node.sh: $*" >&2; exit 1; }
while [ $# -gt 0 ]; do
  case "$1" in
    --budget) [ $# -ge 2 ] || die "--budget needs SECONDS"; BUDGET=$2; shift 2 ;;
    --threads) [ $# -ge 2 ] || die "--threads needs a list"; TLIST=$2; USER_T=" --threads $2"; shift 2 ;;
    --dry-run) DRY=1; shift ;;
    --out) [ $# -ge 2 ] || die "--out needs a file"; OUTMD=$2; shift 2 ;;
    --note) [ $# -ge 2 ] || die "--note needs a text"; NOTES+=("$2"); shift 2 ;;
    -h|--help) sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown option '$1' (--help)" ;;
  esac
done
case "$BUDGET" in ''|*[!0-9]*) die "--budget: '$BUDGET' is not a whole number of seconds" ;; esac
for tool in timeout awk sed sort date nproc mktemp; do
  command -v "$tool" >/dev/null || die "'$tool' not found (coreutils, awk, sed are needed)"
done
[ -f bench/common.sh ] || die "bench/common.sh missing (run from a copy of the tree, see the header)"
. bench/common.sh
for f in bench/scenes/fig9_model.cfg bench/scenes/fig14_model.cfg bench/peers/srd_fluid.cfg bench/peers/in.srd_fluid_pure; do
  [ -f "$f" ] || die "$f missing (carry bench/scenes and bench/peers, see the header)"
done

NPROC=$(nproc)
[ -n "$TLIST" ] || { t=1; while [ "$t" -lt "$NPROC" ]; do TLIST="$TLIST,$t"; t=$((2 * t)); done; TLIST="${TLIST#,},$NPROC"; TLIST=${TLIST#,}; }
THREADS=$(echo "$TLIST" | tr ',' '\n' | awk 'NF' | sort -n | uniq)
for t in $THREADS; do case "$t" in *[!0-9]*|0) die "--threads: '$t' is not a positive integer" ;; esac; done
[ -n "$THREADS" ] || die "--threads: empty list"
NMAX=$(echo "$THREADS" | tail -1)
TCSV=$(echo "$THREADS" | paste -sd, -)

left() { echo $((T0 + BUDGET - $(date +%s))); }
# cap LIMIT: a time limit no later than the budget's end (5 s at least)
cap() { local l; l=$(( $(left) - 3 )); [ "$l" -lt 5 ] && l=5; [ "$1" -lt "$l" ] && l=$1; echo "$l"; }
now() { date -u +%H:%M:%S; }
log() { echo "[$(now) | $(left) s left] $*" >&2; }
calc() { awk "BEGIN{print ($*)}"; }

# --- build ---------------------------------------------------------------
NEED=""
[ -x bin/peloid ] || NEED="$NEED bin/peloid"
[ -x build/bench/bench_srd ] || NEED="$NEED build/bench/bench_srd"
if [ -n "$NEED" ]; then
  if [ "$DRY" = 1 ]; then
    echo "plan: would build$NEED (make -j$NPROC), then probe and plan; nothing measured (dry run)"; exit 0
  fi
  [ -f Makefile ] && command -v make >/dev/null || die "missing$NEED and no Makefile/make to build them"
  log "building$NEED"
  # shellcheck disable=SC2086
  timeout "$(left)" make -j"$NPROC" $NEED >&2 || die "build of$NEED failed (make -j$NPROC$NEED)"
fi
[ "$(left)" -ge 40 ] || die "budget spent after the build ($(left) s left; give a larger --budget)"

TMP=$(mktemp -d) || die "mktemp failed"; trap 'rm -rf "$TMP"' EXIT
LOAD0=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "?")
START_UTC=$(date -u +%FT%TZ)

# --- the machine ---------------------------------------------------------
CPU=$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)
[ -n "$CPU" ] || CPU=$(sed -n 's/^model name[[:space:]]*: *//p' /proc/cpuinfo 2>/dev/null | head -1)
[ -n "$CPU" ] || CPU=unknown
HYP=$(lscpu 2>/dev/null | sed -n 's/^Hypervisor vendor: *//p' | head -1)
if command -v hwloc-calc >/dev/null; then
  TOPO="$(hwloc-calc -N package all 2>/dev/null) package(s), $(hwloc-calc -N core all 2>/dev/null) cores, $(hwloc-calc -N pu all 2>/dev/null) PUs, $(hwloc-calc -N numanode all 2>/dev/null) NUMA node(s)"
  if command -v lstopo-no-graphics >/dev/null; then
    L3=$(lstopo-no-graphics --only l3cache 2>/dev/null | sed -n 's/.*(\(.*\)).*/\1/p' | sort | uniq -c | awk '{printf "%s%d x L3 %s", (NR>1?", ":""), $1, $2}')
    [ -n "$L3" ] && TOPO="$TOPO; $L3"
  fi
  TOPO="$TOPO (hwloc)"
else
  TOPO="$(lscpu 2>/dev/null | sed -n 's/^Socket(s): *//p') socket(s), $(lscpu 2>/dev/null | sed -n 's/^Core(s) per socket: *//p') cores per socket, $(lscpu 2>/dev/null | sed -n 's/^NUMA node(s): *//p') NUMA node(s) (lscpu; hwloc not installed)"
fi
MEM=$(awk '/^MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo 2>/dev/null)
TREE_REV=$(git rev-parse --short HEAD 2>/dev/null || echo "no git")
[ "$TREE_REV" != "no git" ] && [ -n "$(git status --porcelain --untracked-files=no 2>/dev/null)" ] && TREE_REV="$TREE_REV (uncommitted changes)"

# --- probes --------------------------------------------------------------
# pl_run SCENE STEPS THREADS DIR [LIMIT] -> "loop_seconds process_seconds"; nothing on failure
pl_run() {
  local s e
  s=$(date +%s.%N)
  timeout "$(cap "${5:-120}")" bin/peloid run "$1" --steps "$2" --threads "$3" --out "$4" --force >"$4.log" 2>&1 || return 1
  e=$(date +%s.%N)
  sed -n 's/.*"wall_seconds": \([0-9.eE+-]*\).*/\1/p' "$4/summary.json" | head -1 | awk -v s="$s" -v e="$e" '{print $1, e - s}'
}
log "probing: bench_srd L = 64, 1 thread"
s=$(date +%s.%N)
timeout "$(cap 120)" build/bench/bench_srd --sizes 64 --thread-list 1 --reps 3 --rep-seconds 0.02 --out "$TMP/probe" >"$TMP/probe.txt" 2>&1 \
  || die "bench_srd probe failed: $(tail -2 "$TMP/probe.txt")"
PW=$(calc "$(date +%s.%N) - $s")
BUILD_REV=$(sed -n 's/^# bench_srd  peloid \([^ ]*\) .*/\1/p' "$TMP/probe.txt")
BUILD_FLAGS=$(sed -n 's/.*  cflags \(.*\)  real .*/\1/p' "$TMP/probe.txt" | sed 's/ *$//')
# per step at L = 64 (s), the triad's 1-thread GB/s, and set-up = the rest of the probe's wall time
read -r T64 SPR GB1 < <(awk -F'\t' '$1=="step" {ts=$5*$4*1e-9; spr=$17} $1=="triad" {g=$4} END{print ts, spr, g}' "$TMP/probe.txt")
TRIAD=$(calc "6 * 0.805 / ($GB1 > 0.5 ? $GB1 : 0.5) + 0.3")   # one triad call: first touch + 4..6 passes of 805 MB
SET64=$(awk -v w="$PW" -v tr="$TRIAD" -v spr="$SPR" -v ts="$T64" 'BEGIN{x = w - 2 * tr - (4 + 6 * spr) * ts; print (x > 0.2 ? x : 0.2)}')
log "probing: colloid scenes, 3 steps each"
read -r L9 W9 < <(pl_run bench/scenes/fig9_model.cfg 3 1 "$TMP/p9" 60) || die "peloid run fig9_model failed: $(tail -2 "$TMP/p9.log")"
read -r L14 W14 < <(pl_run bench/scenes/fig14_model.cfg 3 1 "$TMP/p14" 120) || die "peloid run fig14_model failed: $(tail -2 "$TMP/p14.log")"
TS9=$(calc "$L9 / 3"); SU9=$(calc "$W9 - $L9")
TS14=$(calc "$L14 / 3"); SU14=$(calc "$W14 - $L14")
COMPILER=$(sed -n 's/.*"compiler": "\([^"]*\)".*/\1/p' "$TMP/p9/summary.json" | head -1)
CCV=$({ ${CC:-cc} --version 2>/dev/null || true; } | head -1)
# the build's command line (the Makefile's build/flags.stamp) without warnings, includes, libraries
FLAGS_ALL=""
[ -f build/flags.stamp ] && FLAGS_ALL=$(tr ' ' '\n' < build/flags.stamp | awk 'NF && !/^-[WILl]/ && !seen[$0]++' | paste -sd' ' -)
[ -n "$FLAGS_ALL" ] || FLAGS_ALL="${BUILD_FLAGS:-?} (optimisation flags only: no build/flags.stamp)"

LMP=""; LSKIP=""
for c in lmp lmp_serial lmp_mpi lmp_openmpi; do command -v "$c" >/dev/null && { LMP=$c; break; }; done
if [ -z "$LMP" ]; then LSKIP="skipped: no lammps (lmp, lmp_serial, lmp_mpi not found; Debian: apt-get install lammps)"
elif ! timeout 20 "$LMP" -h 2>/dev/null | grep -qw SRD; then LSKIP="skipped: $LMP has no SRD package"; fi
HAVE_MPI=0; command -v mpirun >/dev/null && HAVE_MPI=1
[ -z "$LMP" ] || [ "$LMP" = lmp_serial ] && HAVE_MPI=0
lmp_run() { # P L STEPS FILE -> loop seconds (LAMMPS "Loop time": the steps only)
  local launch=""
  [ "$HAVE_MPI" = 1 ] && launch="$MPIRUN -np $1"
  # shellcheck disable=SC2086
  OMP_NUM_THREADS=1 timeout "$(cap "${5:-120}")" $launch "$LMP" -in bench/peers/in.srd_fluid_pure -var L "$2" -var STEPS "$3" \
      -log none -screen "$4" >/dev/null 2>&1 || return 1
  awk '/^Loop time of/ {print $4}' "$4"
}
if [ -z "$LSKIP" ]; then
  log "probing: LAMMPS L = 32, 3 steps"
  s=$(date +%s.%N)
  if LL=$(lmp_run 1 32 3 "$TMP/lprobe" 60) && [ -n "$LL" ]; then
    TL32=$(calc "$LL / 3"); LSU32=$(calc "$(date +%s.%N) - $s - $LL")
    LVER=$(timeout 20 "$LMP" -h 2>/dev/null | grep -m1 'Parallel Simulator' | sed 's/.*Simulator - /LAMMPS /')
  else LSKIP="skipped: LAMMPS probe failed ($(tail -1 "$TMP/lprobe" 2>/dev/null))"; fi
fi
log "probes: L=64 step ${T64}s, set-up ${SET64}s, triad ${GB1} GB/s; fig9 ${TS9}s/step, fig14 ${TS14}s/step; ${LSKIP:-LAMMPS L=32 ${TL32}s/step}"

# --- planning --------------------------------------------------------------
# f(t): time of t threads relative to 1 (speed-up t/2 assumed, never below 1)
SPEEDUPS=$(echo "$THREADS" | awk '{printf "%s%s", (NR>1?" ":""), ($1 > 2 ? 2 / $1 : 1)}')
# share PART: the time this part may use, from what is left now
share() {
  local w_this=$1 w_rest=$2 l
  l=$(( $(left) - 8 ))
  calc "$l > 0 ? $l * $w_this / ($w_this + $w_rest) : 0"
}
W_F=30; W_C=30; W_S=15; W_L=25; [ -n "$LSKIP" ] && W_L=0

plan_fluid() { # SLICE -> "REPS REPSEC predicted" (first fit) or the smallest plan
  awk -v slice="$1" -v t64="$T64" -v set64="$SET64" -v triad="$TRIAD" -v f="$SPEEDUPS" 'BEGIN{
    nt = split(f, fr, " "); n = split("5 0.4 5 0.2 5 0.1 5 0.05 3 0.05 3 0.02 3 0.01", c, " ")
    for (k = 1; k < n; k += 2) {
      R = c[k]; RS = c[k+1]; tot = 0
      for (i = 1; i <= nt; ++i) tot += triad          # the triad sweep
      split("64 120", Ls, " ")
      for (j = 1; j <= 2; ++j) for (i = 1; i <= nt; ++i) {
        sc = (Ls[j] / 64) ^ 3; ts = t64 * sc * fr[i]
        spr = RS / ts; if (spr < 2) spr = 2; spr = int(spr + 0.999)
        tot += set64 * sc + triad + (4 + 2 * R * spr) * ts
      }
      if (tot <= slice) { print R, RS, tot; exit }
    }
    print R, RS, tot }'
}
plan_colloid() { # SLICE -> "STEPS REPS predicted"
  awk -v slice="$1" -v a="$TS9" -v b="$TS14" -v sa="$SU9" -v sb="$SU14" -v f="$SPEEDUPS" 'BEGIN{
    nt = split(f, fr, " "); n = split("200 5 100 5 60 5 40 5 40 3 20 5 20 3 10 5 10 3 5 3 3 3", c, " ")
    for (k = 1; k < n; k += 2) {
      S = c[k]; R = c[k+1]; tot = 0
      for (i = 1; i <= nt; ++i) tot += R * (sa + sb + S * (a + b) * fr[i])
      if (tot <= slice) { print S, R, tot; exit }
    }
    print S, R, tot }'
}
plan_sweep() { # SLICE -> "STEPS REPS predicted": per rep the sweep (N x 1 thread, contention 1.5) and one N-thread run
  awk -v slice="$1" -v a="$TS9" -v sa="$SU9" -v N="$NMAX" 'BEGIN{
    fN = (N > 2 ? 2 / N : 1); n = split("400 3 200 3 100 3 60 3 40 3 20 3 10 3 10 1 5 1", c, " ")
    for (k = 1; k < n; k += 2) {
      S = c[k]; R = c[k+1]
      tot = R * (sa + 2.0 + S * a * 1.5 + sa + S * a * fN)
      if (tot <= slice) { print S, R, tot; exit }
    }
    print S, R, tot }'
}
plan_lammps() { # SLICE -> "L STEPS REPS predicted"
  awk -v slice="$1" -v tl="${TL32:-0}" -v lsu="${LSU32:-0}" -v t64="$T64" -v set64="$SET64" -v N="$NMAX" 'BEGIN{
    fN = (N > 2 ? 2 / N : 1); n = split("64 20 5 64 10 5 64 5 5 32 20 5 32 10 5 64 5 3 32 5 5 32 5 3 32 3 3", c, " ")
    for (k = 1; k < n; k += 3) {
      L = c[k]; S = c[k+1]; R = c[k+2]; s32 = (L / 32) ^ 3; s64 = (L / 64) ^ 3
      # per rank count P: LAMMPS set-up + steps, peloid start + set-up + steps
      tot = 0
      for (p = 1; p <= (N > 1 ? 2 : 1); ++p) {
        fP = (p == 1 ? 1 : fN)
        tot += R * (lsu * s32 + S * tl * s32 * fP + 0.5 + set64 * s64 + S * t64 * s64 * fP)
      }
      if (tot <= slice) { print L, S, R, tot; exit }
    }
    print L, S, R, tot }'
}

if [ "$DRY" = 1 ]; then
  echo "plan ($(left) s of $BUDGET s left after the probes; threads $TCSV; shares fluid $W_F, colloid $W_C, sweep $W_S, LAMMPS $W_L):"
  sl=$(share $W_F $((W_C + W_S + W_L))); read -r R RS P < <(plan_fluid "$sl")
  echo "  1+2. bench_srd --sizes 64,120 --thread-list $TCSV --reps $R --rep-seconds $RS   (slice ${sl%.*} s, predicted ${P%.*} s)"
  sl=$(calc "$(left) * $W_C / ($W_F + $W_C + $W_S + $W_L)"); read -r S R P < <(plan_colloid "$sl")
  echo "  3.   fig14_model, fig9_model: $R reps x $S steps at threads $TCSV   (slice ~${sl%.*} s, predicted ${P%.*} s)"
  sl=$(calc "$(left) * $W_S / ($W_F + $W_C + $W_S + $W_L)"); read -r S R P < <(plan_sweep "$sl")
  echo "  4.   peloid sweep of $NMAX points x $S steps vs one $NMAX-thread run, $R reps   (slice ~${sl%.*} s, predicted ${P%.*} s)"
  if [ -n "$LSKIP" ]; then echo "  5.   LAMMPS: $LSKIP"; else
    sl=$(calc "$(left) * $W_L / ($W_F + $W_C + $W_S + $W_L)"); read -r L S R P < <(plan_lammps "$sl")
    echo "  5.   LAMMPS ($LMP, mpirun: $HAVE_MPI) and peloid, L = $L, $S steps, $R interleaved reps at 1 and $NMAX ranks/threads   (slice ~${sl%.*} s, predicted ${P%.*} s)"
  fi
  echo "  (each part is planned again from the time left when it starts; nothing measured in a dry run)"
  exit 0
fi

SEC="$TMP/section.md"; : > "$SEC"
emit() { printf '%s\n' "$*" >> "$SEC"; }
mkdir -p bench/out/node || die "cannot create bench/out/node"
TSV=bench/out/node.tsv
printf 'part\tcase\tthreads\tmedian\tmin\tmax\tunit\treps\n' > "$TSV"
tsv() { printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$@" | tee -a "$TSV"; }
PARTS=""; PT=$T0
part_done() { PARTS="$PARTS${PARTS:+, }$1 $(( $(date +%s) - PT )) s"; PT=$(date +%s); }
part_done "build + probes"

# --- 1 + 2: STREAM triad and the fluid step ---------------------------------
sl=$(share $W_F $((W_C + W_S + W_L))); read -r FR FRS FP < <(plan_fluid "$sl")
log "fluid: bench_srd --sizes 64,120 --thread-list $TCSV --reps $FR --rep-seconds $FRS (predicted ${FP%.*} s of ${sl%.*})"
FLIM=$(cap "$(calc "int($FP * 1.5 + 20)")")
timeout "$FLIM" build/bench/bench_srd --sizes 64,120 --thread-list "$TCSV" --reps "$FR" --rep-seconds "$FRS" \
    --out bench/out/node >"$TMP/srd.txt" 2>&1 || NOTES+=("bench_srd ended with status $? (limit $FLIM s): rows missing below were not measured")
emit ""
emit "**STREAM triad** (bench_srd, 3 arrays of 2^25 doubles, 24 B per element; $FR repetitions, median (min..max)):"
emit ""
emit "| threads | triad GB/s |"
emit "|---|---|"
awk -F'\t' '$1=="triad" {printf "| %d | %.1f (%.1f..%.1f) |\n", $2, $4, $5, $6}' "$TMP/srd.txt" >> "$SEC"
emit ""
emit "**Fluid step** (bench_srd: pure SRD fluid, 10 per cell, the plan \`peloid run\` executes; $FR repetitions of >= $FRS s and >= 2 steps each; 224 B per particle; the triad measured just before each case):"
emit ""
emit "| L | particles | threads | updates/s | updates/s per core | ns per particle | triad GB/s (same case) | % of the triad bound |"
emit "|---|---|---|---|---|---|---|---|"
awk -F'\t' '$1=="step" {printf "| %d | %.3g | %d | %.3g (%.3g..%.3g) | %.3g | %.2f (%.2f..%.2f) | %.1f | %.0f %% |\n",
    $2, $4, $3, 1e9 / $5, 1e9 / $7, 1e9 / $6, 1e9 / $5 / $3, $5, $6, $7, $11, $12}' "$TMP/srd.txt" >> "$SEC"
awk -F'\t' -v R="$FR" '$1=="triad" {printf "stream\ttriad\t%d\t%s\t%s\t%s\tGB/s\t%d\n", $2, $4, $5, $6, R}
    $1=="step" {printf "fluid\tL=%d step\t%d\t%s\t%s\t%s\tns/particle\t%d\n", $2, $3, $5, $6, $7, R;
                printf "fluid\tL=%d pct_of_triad\t%d\t%s\t\t\t%%\t%d\n", $2, $3, $12, R}' "$TMP/srd.txt" | tee -a "$TSV"
part_done fluid

# --- 3: the dense colloid scenes --------------------------------------------
sl=$(share $W_C $((W_S + W_L))); read -r CS CR CP < <(plan_colloid "$sl")
if [ "$(calc "$CP > $sl * 1.5 ? 1 : 0")" = 1 ]; then
  NOTES+=("colloid scenes skipped: the smallest plan (${CP%.*} s) does not fit the ${sl%.*} s left to them")
  emit ""; emit "**Dense colloid scenes**: skipped (budget)."
else
  log "colloid scenes: $CR reps x $CS steps, threads $TCSV (predicted ${CP%.*} s of ${sl%.*})"
  for r in $(seq "$CR"); do
    for sc in fig14 fig9; do
      for t in $THREADS; do
        [ "$(left)" -gt 15 ] || break 3
        if read -r lw _ < <(pl_run "bench/scenes/${sc}_model.cfg" "$CS" "$t" "$TMP/c" 300); then
          calc "$lw / $CS" >> "$TMP/c.$sc.$t"
        else NOTES+=("peloid run ${sc}_model --threads $t failed: $(tail -1 "$TMP/c.log")"); fi
      done
    done
  done
  emit ""
  emit "**Dense colloid scenes** (\`peloid run SCENE --steps $CS --threads T\`, the run loop's wall time from summary.json / $CS; $CR repetitions, interleaved; measured from the start of the scene, where the clusters have not formed):"
  emit ""
  emit "| scene | threads | s per collision step | collision steps/s | speed-up over 1 thread |"
  emit "|---|---|---|---|---|"
  for sc in fig14 fig9; do
    base=""
    for t in $THREADS; do
      [ -s "$TMP/c.$sc.$t" ] || { emit "| bench/scenes/${sc}_model.cfg | $t | not measured | | |"; continue; }
      read -r m lo hi < <(med < "$TMP/c.$sc.$t")
      [ -n "$base" ] || base=$m
      tsv colloid "${sc}_model" "$t" "$m" "$lo" "$hi" "s/step" "$(wc -l < "$TMP/c.$sc.$t")"
      emit "$(awk -v s="$sc" -v t="$t" -v m="$m" -v lo="$lo" -v hi="$hi" -v b="$base" -v n="$(wc -l < "$TMP/c.$sc.$t")" -v R="$CR" \
        'BEGIN{printf "| bench/scenes/%s_model.cfg | %d | %.4g (%.4g..%.4g)%s | %.3g | %.2f |", s, t, m, lo, hi, (n < R ? " [" n " reps]" : ""), 1 / m, b / m}')"
    done
  done
  part_done "colloid scenes"
fi

# --- 4: sweep throughput ------------------------------------------------------
sl=$(share $W_S $W_L); read -r SS SR SP < <(plan_sweep "$sl")
if [ "$(calc "$SP > $sl * 1.5 ? 1 : 0")" = 1 ]; then
  NOTES+=("sweep throughput skipped: the smallest plan (${SP%.*} s) does not fit the ${sl%.*} s left")
  emit ""; emit "**Sweep throughput**: skipped (budget)."
else
  log "sweep: $NMAX points x $SS steps vs one $NMAX-thread run, $SR reps (predicted ${SP%.*} s of ${sl%.*})"
  seeds=$(seq -s, 1 "$NMAX")
  PICK=""; WHY=""; SWOPT=""
  # N = the CPUs: the sweep's own choice (its log line says it); otherwise N x 1 forced
  [ "$NMAX" = "$NPROC" ] || SWOPT="--jobs $NMAX --threads 1"
  for r in $(seq "$SR"); do
    [ "$(left)" -gt 15 ] || break
    printf 'name = "node_sweep";\nscene = "%s/bench/scenes/fig9_model.cfg";\ngrid = ( { key = "steps"; values = [%d]; }, { key = "seed"; values = [%s]; } );\n' \
        "$PWD" "$SS" "$seeds" > "$TMP/study.cfg"
    rm -rf "$TMP/sw"
    s=$(date +%s.%N)
    # shellcheck disable=SC2086
    timeout "$(cap 300)" bin/peloid sweep "$TMP/study.cfg" --out "$TMP/sw" $SWOPT >"$TMP/sw.log" 2>&1
    src=$?; e=$(date +%s.%N)
    # the plan's line: "... to run (K from its checkpoint): J job(s) x T thread(s) on C core(s): why -> OUT/"
    [ -n "$PICK" ] || PICK=$(sed -n 's/.*from its checkpoint): \([0-9]* job(s) x [0-9]* thread(s) on [0-9]* core(s)\): .*/\1/p' "$TMP/sw.log" | head -1)
    [ -n "$WHY" ] || WHY=$(sed -n 's/.*from its checkpoint): [0-9]* job(s) x [0-9]* thread(s) on [0-9]* core(s): \(.*\) -> .*/\1/p' "$TMP/sw.log" | head -1)
    ok=$(cat "$TMP"/sw/p*/summary.json 2>/dev/null | grep -c '"wall_seconds"')
    if [ "$ok" = "$NMAX" ]; then
      cat "$TMP"/sw/p*/summary.json | sed -n 's/.*"wall_seconds": \([0-9.eE+-]*\).*/\1/p' \
        | awk -v n="$NMAX" -v S="$SS" '$1 > m {m = $1} END{print n * S / m}' >> "$TMP/sw.loop"
      calc "$NMAX * $SS / ($e - $s)" >> "$TMP/sw.e2e"
      [ "$src" = 0 ] || NOTES+=("peloid sweep exited $src with all points done (its collect/plot step; see sweep.log)")
    else NOTES+=("peloid sweep rep $r: $ok of $NMAX points finished (exit $src): $(tail -1 "$TMP/sw.log")"); fi
    s=$(date +%s.%N)
    if read -r lw _ < <(pl_run bench/scenes/fig9_model.cfg "$SS" "$NMAX" "$TMP/one" 300); then
      e=$(date +%s.%N)
      calc "$SS / $lw" >> "$TMP/one.loop"; calc "$SS / ($e - $s)" >> "$TMP/one.e2e"
    fi
  done
  emit ""
  if [ -n "$SWOPT" ]; then how="run with \`$SWOPT\` ($NMAX < the $NPROC CPUs; by itself it plans for the cores it sees, README \"Parameter sweeps\")"
  else how="its own plan: ${PICK:-?}${WHY:+ (\"$WHY\")}"; fi
  emit "**Sweep throughput** (Fig. 9 model scene, $SS collision steps per run; $SR repetitions, median (min..max)): \`peloid sweep\` of a $NMAX-point study (seeds 1..$NMAX; $how) against one \`peloid run --threads $NMAX\`. Loop: steps / the run loop's wall time (the slowest point for the sweep); end to end: steps / the command's wall time (process start, scene set-up, the sweep's collect and plot):"
  emit ""
  emit "| how | collision steps/s in total, loop | end to end |"
  emit "|---|---|---|"
  for k in sw one; do
    name="peloid sweep, $NMAX point(s): $PICK"; [ "$k" = one ] && name="1 run x $NMAX thread(s)"
    if [ -s "$TMP/$k.loop" ]; then
      read -r m lo hi < <(med < "$TMP/$k.loop"); read -r m2 lo2 hi2 < <(med < "$TMP/$k.e2e")
      emit "| $name | $m ($lo..$hi) | $m2 ($lo2..$hi2) |"
      tsv sweep "$k loop" "$NMAX" "$m" "$lo" "$hi" "steps/s" "$(wc -l < "$TMP/$k.loop")"
      tsv sweep "$k end-to-end" "$NMAX" "$m2" "$lo2" "$hi2" "steps/s" "$(wc -l < "$TMP/$k.e2e")"
    else emit "| $name | not measured | |"; fi
  done
  part_done sweep
fi

# --- 5: LAMMPS ----------------------------------------------------------------
emit ""
if [ -n "$LSKIP" ]; then
  echo "LAMMPS: $LSKIP" >&2
  emit "**LAMMPS**: $LSKIP."
else
  sl=$(calc "$(left) > 8 ? $(left) - 8 : 0"); read -r LL LS LR LP < <(plan_lammps "$sl")
  if [ "$(calc "$LP > $sl * 1.5 ? 1 : 0")" = 1 ]; then
    emit "**LAMMPS**: skipped (budget: the smallest plan, ${LP%.*} s, does not fit the ${sl%.*} s left)."
  else
    PS="1"; [ "$NMAX" -gt 1 ] && [ "$HAVE_MPI" = 1 ] && PS="1 $NMAX"
    [ "$HAVE_MPI" = 1 ] || NOTES+=("LAMMPS without mpirun: 1 rank only")
    N=$((10 * LL * LL * LL))
    sed "s/cells = \[32, 32, 32\]/cells = [$LL, $LL, $LL]/" bench/peers/srd_fluid.cfg > "$TMP/fluid.cfg"
    log "LAMMPS: L = $LL, $LS steps, $LR interleaved reps at ranks/threads $PS (predicted ${LP%.*} s of ${sl%.*})"
    for r in $(seq "$LR"); do
      for P in $PS; do
        [ "$(left)" -gt 10 ] || break 2
        if lw=$(lmp_run "$P" "$LL" "$LS" "$TMP/lmp.$P.$r" 120) && [ -n "$lw" ]; then
          calc "$N * $LS / $lw / $P" >> "$TMP/lmp.$P"
        else NOTES+=("LAMMPS at $P ranks, rep $r failed: $(tail -1 "$TMP/lmp.$P.$r" 2>/dev/null)"); continue; fi
        if read -r lw _ < <(pl_run "$TMP/fluid.cfg" "$LS" "$P" "$TMP/pf" 120); then
          calc "$N * $LS / $lw / $P" >> "$TMP/pl.$P"
          tail -1 "$TMP/pl.$P" | awk -v l="$(tail -1 "$TMP/lmp.$P")" '{print $1 / l}' >> "$TMP/ratio.$P"
        fi
      done
    done
    emit "**LAMMPS side by side** ($LVER, \`$LMP\`$( [ "$HAVE_MPI" = 1 ] && echo ", \`$MPIRUN -np P\`"), OMP_NUM_THREADS=1; deck bench/peers/in.srd_fluid_pure; peloid: bench/peers/srd_fluid.cfg at the same L, \`--threads P\`; L = $LL ($N particles), $LS steps per run, $LR interleaved repetitions (LAMMPS then peloid); particle-updates/s per core over the loop only (LAMMPS \"Loop time\", peloid summary.json), median (min..max)):"
    emit ""
    emit "| ranks / threads | LAMMPS | peloid | peloid / LAMMPS, per pair: median (min..max) |"
    emit "|---|---|---|---|"
    for P in $PS; do
      if [ -s "$TMP/lmp.$P" ] && [ -s "$TMP/pl.$P" ]; then
        read -r a alo ahi < <(med < "$TMP/lmp.$P"); read -r b blo bhi < <(med < "$TMP/pl.$P"); read -r c clo chi < <(med < "$TMP/ratio.$P")
        emit "| $P | $a ($alo..$ahi) | $b ($blo..$bhi) | $(printf '%.1f (%.1f..%.1f), %d pairs' "$c" "$clo" "$chi" "$(wc -l < "$TMP/ratio.$P")") |"
        tsv lammps "lammps L=$LL" "$P" "$a" "$alo" "$ahi" "updates/s/core" "$(wc -l < "$TMP/lmp.$P")"
        tsv lammps "peloid L=$LL" "$P" "$b" "$blo" "$bhi" "updates/s/core" "$(wc -l < "$TMP/pl.$P")"
      else emit "| $P | not measured | | |"; fi
    done
    part_done LAMMPS
  fi
fi

# --- the section -----------------------------------------------------------------
END_UTC=$(date -u +%FT%TZ); WALL=$(( $(date +%s) - T0 ))
LOAD1=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "?")
{
  echo ""
  echo "## Node: $CPU, $NPROC CPUs, $(date -u +%F) (bench/node.sh, issue 38)"
  echo ""
  echo "| | |"
  echo "|---|---|"
  echo "| CPU | \`$CPU\` (lscpu / /proc/cpuinfo)${HYP:+, $HYP guest} |"
  echo "| topology | $TOPO |"
  echo "| memory | ${MEM:-?} |"
  echo "| compiler | gcc/cc ${COMPILER:-?} (\`${CCV:-cc not found}\`), flags \`$FLAGS_ALL\`; bench_srd pinned OMP_PLACES=cores OMP_PROC_BIND=spread |"
  echo "| peloid | binaries built from ${BUILD_REV:-?}; tree $TREE_REV |"
  echo "| run | \`bench/node.sh --budget $BUDGET$USER_T\`, $START_UTC .. $END_UTC, $WALL s; threads $TCSV; /proc/loadavg start $LOAD0, end $LOAD1 |"
  cat "$SEC"
  echo ""
  echo "- Wall time per part: $PARTS (budget $BUDGET s)."
  awk -v a="${LOAD0%% *}" -v b="${LOAD1%% *}" -v n="$NPROC" 'BEGIN{if (a > 0.3 * n || b > 0.3 * n)
    printf "- Load average %s at the start, %s at the end on %d CPUs: other processes ran alongside, the figures are noisy.\n", a, b, n}'
  for n in ${NOTES[@]+"${NOTES[@]}"}; do echo "- $n"; done
} > "$TMP/out.md"
cat "$TMP/out.md" >> "$OUTMD" || die "cannot append to $OUTMD"
cat "$TMP/out.md"
log "appended to $OUTMD ($WALL s)"
