#!/bin/bash
# Interleaved A/B of two peloid binaries on one scene: the colloid MD stage
# seconds (summary.json stage_seconds "colloid-md") of STEPS collision steps,
# PAIRS alternating pairs at 1 and 2 threads; medians, min..max and the ratio.
#
#   bench/ab_colloid_md.sh OLD_PELOID NEW_PELOID [SCENE] [STEPS] [PAIRS]
#   (defaults bench/scenes/fig14_model.cfg 10 3)
#   RESTART=CHECKPOINT bench/ab_colloid_md.sh ...   starts both from that
#   checkpoint of SCENE (e.g. a clustered state of the Fig. 14 model after
#   800 steps, where most near pairs are in contact) instead of its start
set -eu
cd "$(dirname "$0")/.."
. bench/common.sh
A=$1; B=$2; SCENE=${3:-bench/scenes/fig14_model.cfg}; STEPS=${4:-10}; PAIRS=${5:-3}
FROM=(); [ -n "${RESTART:-}" ] && FROM=(--restart "$RESTART")
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
stage() { /usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["stage_seconds"]["colloid-md"])' "$1"; }
echo "# ab_colloid_md: $SCENE${RESTART:+ from $RESTART}, $STEPS steps, $PAIRS pairs; A = $A, B = $B"
printf "threads\tA_median_s\tA_min\tA_max\tB_median_s\tB_min\tB_max\tA_over_B\n"
for t in 1 2; do
  for r in $(seq "$PAIRS"); do
    for x in A B; do
      bin=$A; [ $x = B ] && bin=$B
      "$bin" run "$SCENE" --steps "$STEPS" --threads "$t" "${FROM[@]}" --out "$TMP/o" --force >/dev/null 2>&1
      stage "$TMP/o/summary.json" >> "$TMP/$x.$t"
    done
  done
  read -r am alo ahi < <(med < "$TMP/A.$t")
  read -r bm blo bhi < <(med < "$TMP/B.$t")
  printf "%d\t%s\t%s\t%s\t%s\t%s\t%s\t%.2f\n" "$t" "$am" "$alo" "$ahi" "$bm" "$blo" "$bhi" \
      "$(awk -v a="$am" -v b="$bm" 'BEGIN{print a/b}')"
done
