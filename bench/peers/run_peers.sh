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
#   bench/peers/run_peers.sh [L] [STEPS] [REPS]     (defaults 64 50 5)
# Needs: Debian package `lammps` (lmp with the SRD package), bin/peloid.
set -eu
cd "$(dirname "$0")/../.."
. bench/common.sh
L=${1:-64}; STEPS=${2:-50}; REPS=${3:-5}
OUT=bench/out; mkdir -p "$OUT"; TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
TSV=$OUT/peers.tsv
command -v lmp >/dev/null || { echo "lmp not found: apt-get install -y lammps" >&2; exit 1; }
lmp -h | grep -qw SRD || { echo "lmp has no SRD package" >&2; exit 1; }
[ -x bin/peloid ] || make bin/peloid >/dev/null
N=$((10 * L * L * L))
sed "s/cells = \[32, 32, 32\]/cells = [$L, $L, $L]/; s/steps = 100/steps = $STEPS/" \
    bench/peers/srd_fluid.cfg > "$TMP/scene.cfg"

lammps_rate() { # deck P rep -> updates/s per core (Loop time covers the steps only, setup excluded)
  OMP_NUM_THREADS=1 $MPIRUN -np "$2" lmp -in "bench/peers/in.srd_fluid$1" -var L "$L" -var STEPS "$STEPS" \
      -log none -screen "$TMP/lmp$1.$2.$3" >/dev/null 2>&1 || { echo "LAMMPS failed:" >&2; tail "$TMP/lmp$1.$2.$3" >&2; exit 1; }
  awk -v n=$N -v s=$STEPS -v p="$2" '/^Loop time of/ {print n*s/$4/p}' "$TMP/lmp$1.$2.$3"
}

echo "# run_peers: L=$L ($N SRD particles), $STEPS steps, $REPS interleaved reps, $(lammps_version), checkout $(git rev-parse --short HEAD 2>/dev/null || echo unknown), $(date -u +%FT%TZ), load $(cut -d' ' -f1-3 /proc/loadavg)"
printf "code\tranks_or_threads\tparticles\tsteps\tupdates_per_s_per_core_median\tmin\tmax\tper_rep\n" | tee "$TSV"
for P in 1 2; do
  : > "$TMP/pure.$P"; : > "$TMP/big.$P"; : > "$TMP/pl.$P"
  for r in $(seq "$REPS"); do
    lammps_rate _pure "$P" "$r" >> "$TMP/pure.$P"
    lammps_rate "" "$P" "$r" >> "$TMP/big.$P"
    # peloid: wall time of the step loop (summary.json)
    bin/peloid run "$TMP/scene.cfg" --out "$TMP/pl.$P.$r" --threads "$P" --steps "$STEPS" >/dev/null 2>&1
    sed -n 's/.*"particle_updates_per_second": \([0-9.e+]*\).*/\1/p' "$TMP/pl.$P.$r/summary.json" \
        | awk -v p=$P '{print $1/p}' >> "$TMP/pl.$P"
  done
  for c in pure big pl; do
    read -r m lo hi < <(med < "$TMP/$c.$P")
    name=$( [ $c = pl ] && echo peloid || echo "lammps_$c" )
    printf "%s\t%d\t%d\t%d\t%s\t%s\t%s\t%s\n" "$name" "$P" "$N" "$STEPS" "$m" "$lo" "$hi" \
        "$(awk '{printf "%s%.3g", (NR>1?",":""), $1}' "$TMP/$c.$P")" | tee -a "$TSV"
  done
  for c in pure big; do
    paste "$TMP/pl.$P" "$TMP/$c.$P" | awk '{print $1/$2}' > "$TMP/ratio.$c.$P"
    read -r m lo hi < <(med < "$TMP/ratio.$c.$P")
    printf "# %d core(s), LAMMPS %s deck: peloid / LAMMPS per core, median %.1f, per pair %s, min %.1f\n" \
        "$P" "$c" "$m" "$(awk '{printf "%s%.1f", (NR>1?", ":""), $1}' "$TMP/ratio.$c.$P")" "$lo" | tee -a "$TSV"
  done
done
sed -n 's/.*"git_revision": "\([^"]*\)".*/# peloid binary built from \1/p' "$TMP/pl.1.1/summary.json" | head -1 | tee -a "$TSV"
