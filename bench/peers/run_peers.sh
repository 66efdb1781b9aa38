#!/bin/bash
# LAMMPS `fix srd` and peloid on the same pure SRD fluid (10 particles per
# cell, lambda = 0.1, kT = 1, grid shift on), in the same run, at 1 and 2
# MPI ranks / OpenMP threads.  Prints particle-updates/s per core for each
# and the ratio peloid / LAMMPS.  Median of REPS runs (min..max shown).
#
#   bench/peers/run_peers.sh [L] [STEPS] [REPS]     (defaults 32 100 3)
# Needs: Debian package `lammps` (lmp with the SRD package), bin/peloid.
set -eu
cd "$(dirname "$0")/../.."
. bench/common.sh
L=${1:-32}; STEPS=${2:-100}; REPS=${3:-3}
OUT=bench/out; mkdir -p "$OUT"; TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
TSV=$OUT/peers.tsv
command -v lmp >/dev/null || { echo "lmp not found: apt-get install -y lammps" >&2; exit 1; }
lmp -h | grep -qw SRD || { echo "lmp has no SRD package" >&2; exit 1; }
[ -x bin/peloid ] || make bin/peloid >/dev/null
N=$((10 * L * L * L))
sed "s/cells = \[32, 32, 32\]/cells = [$L, $L, $L]/; s/steps = 100/steps = $STEPS/" \
    bench/peers/srd_fluid.cfg > "$TMP/scene.cfg"

echo "# run_peers: L=$L ($N SRD particles), $STEPS steps, $REPS reps, $(lammps_version)"
printf "code\tranks_or_threads\tparticles\tsteps\tupdates_per_s_per_core_median\tmin\tmax\n" | tee "$TSV"
for P in 1 2; do
  for r in $(seq "$REPS"); do
    # LAMMPS: Loop time covers the run's steps only (setup excluded)
    OMP_NUM_THREADS=1 $MPIRUN -np "$P" lmp -in bench/peers/in.srd_fluid -var L "$L" -var STEPS "$STEPS" \
        -log none -screen "$TMP/lmp.$P.$r" >/dev/null 2>&1 || { echo "LAMMPS failed:"; tail "$TMP/lmp.$P.$r"; exit 1; }
    awk -v n=$N -v s=$STEPS -v p=$P '/^Loop time of/ {print n*s/$4/p}' "$TMP/lmp.$P.$r" >> "$TMP/lmp.$P"
    # peloid: wall time of the step loop (summary.json)
    bin/peloid run "$TMP/scene.cfg" --out "$TMP/pl.$P.$r" --threads "$P" --steps "$STEPS" >/dev/null 2>&1
    sed -n 's/.*"particle_updates_per_second": \([0-9.e+]*\).*/\1/p' "$TMP/pl.$P.$r/summary.json" \
        | awk -v p=$P '{print $1/p}' >> "$TMP/pl.$P"
  done
  read -r lm llo lhi < <(med < "$TMP/lmp.$P")
  read -r pm plo phi < <(med < "$TMP/pl.$P")
  printf "lammps\t%d\t%d\t%d\t%s\t%s\t%s\n" "$P" "$N" "$STEPS" "$lm" "$llo" "$lhi" | tee -a "$TSV"
  printf "peloid\t%d\t%d\t%d\t%s\t%s\t%s\n" "$P" "$N" "$STEPS" "$pm" "$plo" "$phi" | tee -a "$TSV"
  awk -v a="$pm" -v b="$lm" -v p=$P 'BEGIN{printf "# %d core(s): peloid / LAMMPS per core = %.1f\n", p, a/b}' | tee -a "$TSV"
done
