#!/bin/bash
# Interleaved A/B of the coupling costs of two builds: ROUNDS alternating
# runs (A B A B ...) of bench_coupling --threads 2 --reps 7 (1 and 2 threads;
# each run's ratio is already the median over its reps of the case's rep
# against the bare fluid's rep of the same round).  Prints, per case and
# thread count, the median (min..max) over the runs of the run's ns per
# fluid particle and of its ratio to the bare fluid, and for the potential
# coupling the sum of its stages' ns (potential-select + stream+bin +
# potential-md: the streaming carries its selection).
#
#   bench/ab_coupling.sh OLD_BUILD_DIR NEW_BUILD_DIR [ROUNDS]   (default 5)
#   e.g. git worktree add /tmp/old <rev> && make -C /tmp/old build/bench/bench_coupling
#        bench/ab_coupling.sh /tmp/old/build build 5
set -eu
cd "$(dirname "$0")/.."
. bench/common.sh
A=$1; B=$2; ROUNDS=${3:-5}
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
echo "# ab_coupling: A = $A, B = $B, $ROUNDS interleaved rounds; $(date -u +%Y-%m-%dT%H:%MZ); load $(cut -d' ' -f1 /proc/loadavg)"
for r in $(seq "$ROUNDS"); do
  for x in A B; do
    dir=$A; [ $x = B ] && dir=$B
    "$dir/bench/bench_coupling" --threads 2 --reps 7 --cases potential,hecht1,hecht2 --out "$TMP/$x.$r" > /dev/null 2>&1
    # case, threads, ns, ratio, the potential coupling's stage sum
    awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
                { n = split($c["stage_ns"], s, ","); sum = 0
                  for (i = 1; i <= n; ++i) { split(s[i], kv, "=")
                    if (kv[1] == "potential-select" || kv[1] == "stream+bin" || kv[1] == "potential-md") sum += kv[2] }
                  print $c["case"] "\t" $c["threads"] "\t" $c["ns_per_particle"] "\t" $c["ratio_to_fluid"] "\t" sum }' \
        "$TMP/$x.$r/coupling.tsv" >> "$TMP/$x.all"
  done
done
printf "case\tthreads\tA_ns\tA_ratio\tB_ns\tB_ratio\tA_stage_sum\tB_stage_sum\n"
cut -f1,2 "$TMP/A.all" | sort -u | sort -k2,2n -s | while IFS=$'\t' read -r k t; do
  col() { awk -F'\t' -v k="$k" -v t="$t" -v c="$2" '$1 == k && $2 == t { print $c }' "$TMP/$1.all" | med | awk '{printf "%s (%s..%s)", $1, $2, $3}'; }
  sa="-"; sb="-"
  [ "$k" = potential ] && sa=$(col A 5) && sb=$(col B 5)
  printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" "$k" "$t" "$(col A 3)" "$(col A 4)" "$(col B 3)" "$(col B 4)" "$sa" "$sb"
done
