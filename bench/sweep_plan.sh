#!/bin/bash
# The throughput plan of `peloid sweep` against one multi-thread job (issue
# 38): a P-point study of SCENE (seeds 1..P, STEPS collision steps each) swept
# with the sweep's own plan and with --jobs 1 --threads N, interleaved, REPS
# repetitions; prints a Markdown table (median and min..max) and the plan's
# line.  Throughput: P x STEPS / the sweep command's wall time (process
# starts, scene set-up and the table/plot step included, the same for both).
#
#   bench/sweep_plan.sh [--scene FILE] [--points P] [--steps S] [--reps R] [--threads N]
#     defaults: bench/scenes/fig9_model.cfg, 4 points, 200 steps, 3 reps, N = nproc
set -u
cd "$(dirname "$0")/.." || exit 1
SCENE=bench/scenes/fig9_model.cfg; P=4; STEPS=200; REPS=3; N=$(nproc)
die() { echo "sweep_plan.sh: $*" >&2; exit 1; }
while [ $# -gt 0 ]; do
  case "$1" in
    --scene) SCENE=$2; shift 2 ;;
    --points) P=$2; shift 2 ;;
    --steps) STEPS=$2; shift 2 ;;
    --reps) REPS=$2; shift 2 ;;
    --threads) N=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown option '$1' (--help)" ;;
  esac
done
[ -x bin/peloid ] || die "bin/peloid missing (make bin/peloid)"
[ -f "$SCENE" ] || die "$SCENE: no such scene"
TMP=$(mktemp -d) || die "mktemp failed"; trap 'rm -rf "$TMP"' EXIT
printf 'name = "plan";\nscene = "%s";\ngrid = ( { key = "steps"; values = [%d]; }, { key = "seed"; values = [%s]; } );\n' \
  "$(realpath "$SCENE")" "$STEPS" "$(seq -s, 1 "$P")" > "$TMP/study.cfg"
# med FILE -> "median min max"
med() { sort -g "$1" | awk '{v[NR] = $1} END {m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; print m, v[1], v[NR]}'; }
LOAD0=$(cut -d' ' -f1-3 /proc/loadavg)
for r in $(seq "$REPS"); do
  for how in plan one; do
    opt=""; [ "$how" = one ] && opt="--jobs 1 --threads $N"
    rm -rf "$TMP/out"
    s=$(date +%s.%N)
    # shellcheck disable=SC2086
    bin/peloid sweep "$TMP/study.cfg" --out "$TMP/out" $opt > "$TMP/$how.log" 2>&1 || die "sweep ($how) failed: $(tail -1 "$TMP/$how.log")"
    e=$(date +%s.%N)
    awk -v s="$s" -v e="$e" 'BEGIN {print e - s}' >> "$TMP/$how.wall"
    # the points' run loops together (CPU-side work of the runs, no start-up)
    cat "$TMP"/out/p*/summary.json | sed -n 's/.*"wall_seconds": \([0-9.eE+-]*\).*/\1/p' | awk '{t += $1} END {print t}' >> "$TMP/$how.loops"
    [ -s "$TMP/$how.line" ] || head -1 "$TMP/$how.log" > "$TMP/$how.line"
    echo "rep $r $how: $(tail -1 "$TMP/$how.wall") s" >&2
  done
done
LOAD1=$(cut -d' ' -f1-3 /proc/loadavg)
echo "| how | sweep wall s, median (min..max) | collision steps/s in total | run loops summed, s |"
echo "|---|---|---|---|"
for how in plan one; do
  read -r m lo hi < <(med "$TMP/$how.wall"); read -r lm llo lhi < <(med "$TMP/$how.loops")
  name="its own plan: $(sed -n 's/.*from its checkpoint): \([0-9]* job(s) x [0-9]* thread(s)\) on .*/\1/p' "$TMP/$how.line")"
  [ "$how" = one ] && name="\`--jobs 1 --threads $N\`"
  awk -v n="$name" -v m="$m" -v lo="$lo" -v hi="$hi" -v s=$((P * STEPS)) -v lm="$lm" -v llo="$llo" -v lhi="$lhi" \
    'BEGIN {printf "| %s | %.2f (%.2f..%.2f) | %.1f (%.1f..%.1f) | %.2f (%.2f..%.2f) |\n", n, m, lo, hi, s / m, s / hi, s / lo, lm, llo, lhi}'
done
echo
echo "$P points of $SCENE x $STEPS steps, $REPS interleaved repetitions; /proc/loadavg $LOAD0 at the start, $LOAD1 at the end."
echo "plan line: $(sed 's/^peloid sweep plan: //' "$TMP/plan.line")"
