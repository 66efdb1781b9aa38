#!/bin/bash
# Colloid MD side by side: LAMMPS (`pair_style table` of peloid's own DLVO +
# Hertz pair, `fix nve`, neighbour skin 0.3) and peloid's colloid MD
# (build/bench/bench_colloid_md: analytic pair, velocity Verlet with
# rotation, guards) on the same colloids, cut-off, time step and number of
# steps, interleaved in one run (LAMMPS, peloid, LAMMPS, ... per repetition),
# at 1 and 2 MPI ranks / OpenMP threads (CORES="1" for one core only).
# Prints colloid-steps/s per core (median, min, max of REPS), the ratio of
# the medians and of each interleaved pair (peloid / LAMMPS), the STREAM
# triad bandwidth measured by bench_colloid_md after each of its runs
# (median, min, max), the date and the CPU model.
#
#   bench/peers/run_colloid_peers.sh [SCENE] [STEPS] [REPS]
#   (defaults bench/scenes/fig14_model.cfg 3200 5); environment CORES
#   (default "1 2")
# Needs: Debian package `lammps`, build/bench/bench_colloid_md.
set -eu
cd "$(dirname "$0")/../.."
. bench/common.sh
SCENE=${1:-bench/scenes/fig14_model.cfg}; STEPS=${2:-3200}; REPS=${3:-5}; CORES=${CORES:-1 2}
OUT=bench/out; mkdir -p "$OUT"; TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
TSV=$OUT/colloid_peers.tsv
command -v lmp >/dev/null || { echo "lmp not found: apt-get install -y lammps" >&2; exit 1; }
[ -x build/bench/bench_colloid_md ] || make build/bench/bench_colloid_md >/dev/null
read -r RC DT < <(build/bench/bench_colloid_md --lammps "$TMP" "$SCENE")
N=$(awk '/ atoms$/ {print $1}' "$TMP/colloids.data")

echo "# run_colloid_peers: $SCENE, $N colloids, cut-off $RC a0, dt $DT, $STEPS steps, $REPS reps, $(lammps_version)"
echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), peloid $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
printf "code\tranks_or_threads\tcolloids\tsteps\tcolloid_steps_per_s_per_core_median\tmin\tmax\tneighbors_per_colloid\n" | tee "$TSV"
for P in $CORES; do
  for r in $(seq "$REPS"); do
    OMP_NUM_THREADS=1 $MPIRUN -np "$P" lmp -in bench/peers/in.colloid_md -var DIR "$TMP" -var RC "$RC" \
        -var DT "$DT" -var STEPS "$STEPS" -log none -screen "$TMP/lmp.$P.$r" >/dev/null 2>&1 \
        || { echo "LAMMPS failed:"; tail "$TMP/lmp.$P.$r"; exit 1; }
    awk -v n="$N" -v s="$STEPS" -v p="$P" '/^Loop time of/ {print n*s/$4/p}' "$TMP/lmp.$P.$r" >> "$TMP/lmp.$P"
    awk '/^Ave neighs\/atom/ {print $4}' "$TMP/lmp.$P.$r" > "$TMP/lmp.neigh"
    PL_BENCH_THREADS=$P PL_BENCH_ONLY_THREADS=1 build/bench/bench_colloid_md "$SCENE" "$STEPS" 1 > "$TMP/pl.$P.$r"
    sed -n 's/.*colloid_steps_per_s=\([0-9.e+]*\).*/\1/p' "$TMP/pl.$P.$r" | awk -v p="$P" '{print $1/p}' >> "$TMP/pl.$P"
    sed -n 's/.*stream_gbs=\([0-9.e+]*\).*/\1/p' "$TMP/pl.$P.$r" >> "$TMP/stream.$P"
    paste "$TMP/pl.$P" "$TMP/lmp.$P" | tail -1 | awk '{printf "%.2f\n", $1 / $2}' >> "$TMP/ratio.$P"
    PAIRS=$(sed -n 's/.*pairs_in_cutoff=\([0-9]*\).*/\1/p' "$TMP/pl.$P.$r")
  done
  read -r lm llo lhi < <(med < "$TMP/lmp.$P")
  read -r pm plo phi < <(med < "$TMP/pl.$P")
  printf "lammps\t%d\t%d\t%d\t%s\t%s\t%s\t%s\n" "$P" "$N" "$STEPS" "$lm" "$llo" "$lhi" "$(cat "$TMP/lmp.neigh")" | tee -a "$TSV"
  printf "peloid\t%d\t%d\t%d\t%s\t%s\t%s\t%s\n" "$P" "$N" "$STEPS" "$pm" "$plo" "$phi" \
      "$(awk -v a="$PAIRS" -v n="$N" 'BEGIN{printf "%.1f", a/n}')" | tee -a "$TSV"
  read -r sm slo shi < <(med < "$TMP/stream.$P")
  awk -v a="$pm" -v b="$lm" -v p=$P -v r="$(paste -sd, "$TMP/ratio.$P")" -v s="$sm ($slo-$shi)" \
      'BEGIN{printf "# %d core(s): peloid / LAMMPS per core = %.2f (medians; per interleaved pair %s); STREAM triad %s GB/s\n", p, a/b, r, s}' | tee -a "$TSV"
done
