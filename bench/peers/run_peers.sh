#!/bin/bash
# LAMMPS `fix srd` and peloid on the same pure SRD fluid (10 particles per
# cell, lambda = 0.1, kT = 1, grid shift on), interleaved in one run, at 1 and
# 2 MPI ranks / OpenMP threads.  Two LAMMPS decks:
#   pure  bench/peers/in.srd_fluid_pure: fix srd with no big particles
#         (groupbig NULL, atom_style atomic), as LAMMPS users run a pure fluid;
#   big   bench/peers/in.srd_fluid: one tiny big sphere (the workaround deck).
# Every repetition runs LAMMPS pure, LAMMPS big and peloid back to back (a
# pair = one LAMMPS run and the peloid run of the same repetition), so host
# noise hits all three alike.  Prints particle-updates/s per core, the median
# (min..max) of each, the median ratio peloid / LAMMPS and the ratio of every
# pair with its minimum (the issue's "in every one of >= 5 pairs").
#
#   bench/peers/run_peers.sh [L] [STEPS] [REPS] [LABEL=BINARY[@K] ...]   (defaults 64 50 5 peloid=bin/peloid)
# Each LABEL=BINARY runs in every repetition after the LAMMPS decks (A/B of
# peloid builds interleaved with the same LAMMPS runs); @K sets
# srd.sort_interval = K in its scene.  Environment: PS="1 2" (the rank /
# thread counts), DECKS="pure big" (the LAMMPS decks), MD=FILE: the result
# also appended to FILE as a markdown section (bench/RESULTS.md).
# Needs: Debian package `lammps` (lmp with the SRD package), bin/peloid.
set -eu
cd "$(dirname "$0")/../.."
. bench/common.sh
L=${1:-64}; STEPS=${2:-50}; REPS=${3:-5}
shift $(( $# < 3 ? $# : 3 ))
VARIANTS=("$@"); [ ${#VARIANTS[@]} -gt 0 ] || VARIANTS=(peloid=bin/peloid)
PS=${PS:-1 2}; DECKS=${DECKS:-pure big}; MD=${MD:-}
OUT=bench/out; mkdir -p "$OUT"; TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
TSV=$OUT/peers.tsv
command -v lmp >/dev/null || { echo "lmp not found: apt-get install -y lammps" >&2; exit 1; }
lmp -h | grep -qw SRD || { echo "lmp has no SRD package" >&2; exit 1; }
[ -x bin/peloid ] || make bin/peloid >/dev/null
N=$((10 * L * L * L))
NAMES=(); BINS=()
for v in "${VARIANTS[@]}"; do
  name=${v%%=*}; rest=${v#*=}; bin=${rest%@*}; k=1; [ "$rest" != "$bin" ] && k=${rest##*@}
  [ -x "$bin" ] || { echo "run_peers: $bin: no such binary" >&2; exit 2; }
  sed "s/cells = \[32, 32, 32\]/cells = [$L, $L, $L]/; s/steps = 100/steps = $STEPS/;
       s/grid_shift = true;/grid_shift = true; sort_interval = $k;/" bench/peers/srd_fluid.cfg > "$TMP/scene.$name.cfg"
  [ "$k" = 1 ] && sed -i 's/ sort_interval = 1;//' "$TMP/scene.$name.cfg" # a binary without the key
  NAMES+=("$name"); BINS+=("$bin")
done

lammps_rate() { # deck P rep -> updates/s per core (Loop time covers the steps only, setup excluded)
  OMP_NUM_THREADS=1 $MPIRUN -np "$2" lmp -in "bench/peers/in.srd_fluid$1" -var L "$L" -var STEPS "$STEPS" \
      -log none -screen "$TMP/lmp$1.$2.$3" >/dev/null 2>&1 || { echo "LAMMPS failed:" >&2; tail "$TMP/lmp$1.$2.$3" >&2; exit 1; }
  awk -v n=$N -v s=$STEPS -v p="$2" '/^Loop time of/ {print n*s/$4/p}' "$TMP/lmp$1.$2.$3"
}

{
echo "# run_peers: L=$L ($N SRD particles), $STEPS steps, $REPS interleaved reps, $(lammps_version), checkout $(git rev-parse --short HEAD 2>/dev/null || echo unknown), $(date -u +%FT%TZ), load $(cut -d' ' -f1-3 /proc/loadavg)"
printf "code\tranks_or_threads\tparticles\tsteps\tupdates_per_s_per_core_median\tmin\tmax\tper_rep\n"
for P in $PS; do
  for c in $DECKS; do : > "$TMP/$c.$P"; done
  for name in "${NAMES[@]}"; do : > "$TMP/pl_$name.$P"; done
  for r in $(seq "$REPS"); do
    for c in $DECKS; do lammps_rate "$( [ $c = pure ] && echo _pure )" "$P" "$r" >> "$TMP/$c.$P"; done
    for j in "${!NAMES[@]}"; do # peloid: wall time of the step loop (summary.json)
      name=${NAMES[$j]}; o="$TMP/pl_$name.$P.$r"
      "${BINS[$j]}" run "$TMP/scene.$name.cfg" --out "$o" --threads "$P" --steps "$STEPS" >/dev/null 2>&1
      sed -n 's/.*"particle_updates_per_second": \([0-9.e+]*\).*/\1/p' "$o/summary.json" \
          | awk -v p=$P '{print $1/p}' >> "$TMP/pl_$name.$P"
      sed -n "s/.*\"git_revision\": \"\([^\"]*\)\".*/$name \1/p" "$o/summary.json" | head -1 > "$TMP/rev.$name"
    done
  done
  for c in $DECKS; do
    read -r m lo hi < <(med < "$TMP/$c.$P")
    printf "%s\t%d\t%d\t%d\t%s\t%s\t%s\t%s\n" "lammps_$c" "$P" "$N" "$STEPS" "$m" "$lo" "$hi" \
        "$(awk '{printf "%s%.3g", (NR>1?",":""), $1}' "$TMP/$c.$P")"
  done
  for name in "${NAMES[@]}"; do
    read -r m lo hi < <(med < "$TMP/pl_$name.$P")
    printf "%s\t%d\t%d\t%d\t%s\t%s\t%s\t%s\n" "$name" "$P" "$N" "$STEPS" "$m" "$lo" "$hi" \
        "$(awk '{printf "%s%.3g", (NR>1?",":""), $1}' "$TMP/pl_$name.$P")"
  done
  for name in "${NAMES[@]}"; do
    for c in $DECKS; do
      paste "$TMP/pl_$name.$P" "$TMP/$c.$P" | awk '{print $1/$2}' > "$TMP/ratio.$c.$P"
      read -r m lo hi < <(med < "$TMP/ratio.$c.$P")
      printf "# %d core(s), %s / LAMMPS %s deck per core: median %.1f, per pair %s, min %.1f\n" \
          "$P" "$name" "$c" "$m" "$(awk '{printf "%s%.1f", (NR>1?", ":""), $1}' "$TMP/ratio.$c.$P")" "$lo"
    done
  done
done
for name in "${NAMES[@]}"; do echo "# $name: peloid binary built from $(cut -d' ' -f2 "$TMP/rev.$name")"; done
} | tee "$TSV.tmp"; [ "${PIPESTATUS[0]}" = 0 ] || exit 1
mv "$TSV.tmp" "$TSV"
if [ -n "$MD" ]; then # the same figures as a markdown section
  {
    cpu=$(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1)
    echo; echo "## Fluid vs LAMMPS \`fix srd\`, $(date -u +%F) ($cpu, $(nproc) cores)"
    echo; echo "\`PS=\"$PS\" DECKS=\"$DECKS\" bench/peers/run_peers.sh $L $STEPS $REPS ${VARIANTS[*]}\`"
    echo "(particle-updates/s per core, median (min..max) of $REPS interleaved repetitions; ratio: median over the"
    echo "repetitions of peloid / LAMMPS in the same repetition, and its minimum)."
    echo; sed -n 's/^# run_peers: /Run: /p' "$TSV"
    echo; echo "| code | cores | updates/s per core | per repetition |"; echo "|---|---|---|---|"
    awk -F'\t' '!/^#/ && $1 != "code" {printf "| %s | %s | %.3g (%.3g..%.3g) | %s |\n", $1, $2, $5, $6, $7, $8}' "$TSV"
    echo; sed -n 's/^# \([0-9]* core.*\)/- \1/p; s/^# \(.*built from.*\)/- \1/p' "$TSV"
  } >> "$MD"
fi
