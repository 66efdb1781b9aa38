#!/bin/bash
# Interleaved A/B of the SRD and coupling benchmarks of two builds (e.g.
# before and after a refactor): PAIRS alternating runs of bench_srd (L = 64,
# 1 and 2 threads) and bench_coupling, the median ns per particle of the
# whole step and of each kernel, and the ratio A / B (1.00: the same).
#
#   bench/ab_plan.sh OLD_BUILD_DIR NEW_BUILD_DIR [PAIRS]   (default 3)
#   e.g. git worktree add /tmp/old <rev> && make -C /tmp/old build/bench/bench_srd build/bench/bench_coupling
#        bench/ab_plan.sh /tmp/old/build build 3
set -eu
cd "$(dirname "$0")/.."
. bench/common.sh
A=$1; B=$2; PAIRS=${3:-3}
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
echo "# ab_plan: A = $A, B = $B, $PAIRS interleaved pairs; $(date -u +%Y-%m-%dT%H:%MZ); load $(cut -d' ' -f1 /proc/loadavg)"
for r in $(seq "$PAIRS"); do
  for x in A B; do
    dir=$A; [ $x = B ] && dir=$B
    "$dir/bench/bench_srd" --sizes 64 --reps 3 --no-stream --out "$TMP/srd.$x.$r" > /dev/null 2>&1
    "$dir/bench/bench_coupling" --quick --out "$TMP/cpl.$x.$r" > /dev/null 2>&1
    : # (bench_coupling --quick: L = 24, 3 reps)
  done
done
printf "bench\tkernel\tthreads\tA_ns_median\tA_min\tA_max\tB_ns_median\tB_min\tB_max\tA_over_B\n"
for f in srd cpl; do
  file=srd.tsv; [ $f = cpl ] && file=coupling.tsv
  # kernel, threads -> ns_per_particle (column names from the header)
  for x in A B; do
    for r in $(seq "$PAIRS"); do
      # the case column is "kernel" (bench_srd) or "case" (bench_coupling)
      awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; k = ("kernel" in c) ? c["kernel"] : c["case"]; next }
                  { print $k "\t" $c["threads"] "\t" $c["ns_per_particle"] }' "$TMP/$f.$x.$r/$file"
    done > "$TMP/$f.$x.all"
  done
  cut -f1,2 "$TMP/$f.A.all" | sort -u | while IFS=$'\t' read -r k t; do
    grep -qP "^\Q$k\E\t$t\t" "$TMP/$f.B.all" || continue
    read -r am alo ahi < <(awk -F'\t' -v k="$k" -v t="$t" '$1 == k && $2 == t { print $3 }' "$TMP/$f.A.all" | med)
    read -r bm blo bhi < <(awk -F'\t' -v k="$k" -v t="$t" '$1 == k && $2 == t { print $3 }' "$TMP/$f.B.all" | med)
    printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%.3f\n" "$f" "$k" "$t" "$am" "$alo" "$ahi" "$bm" "$blo" "$bhi" \
        "$(awk -v a="$am" -v b="$bm" 'BEGIN{print (b > 0 ? a / b : 0)}')"
  done
done
