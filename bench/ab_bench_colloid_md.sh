#!/bin/bash
# Interleaved A/B of two builds of build/bench/bench_colloid_md (the colloid
# MD alone, no fluid): ROUNDS rounds, each running A then B (then any further
# builds) for STEPS MD steps, 3 timings each (the bench's median of 3);
# per thread count the median, min and max over the rounds, the ratio of the
# medians and the ratio of every round (first build over each build).
#
#   bench/ab_bench_colloid_md.sh OLD_BENCH NEW_BENCH [MORE_BENCH...]
#   environment: ROUNDS (10), STEPS (500), SCENE (bench/scenes/fig14_model.cfg);
#   PL_BENCH_ONLY_THREADS=1 PL_BENCH_THREADS=2: only 2 threads
# Build the old one in a worktree:
#   git worktree add /tmp/old REV && make -C /tmp/old build/bench/bench_colloid_md
set -eu
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: $0 OLD_BENCH NEW_BENCH [MORE_BENCH...]" >&2; exit 2; }
ROUNDS=${ROUNDS:-10}; STEPS=${STEPS:-500}; SCENE=${SCENE:-bench/scenes/fig14_model.cfg}
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
echo "# ab_bench_colloid_md: $SCENE, $STEPS MD steps, $ROUNDS rounds; builds: $*"
for r in $(seq "$ROUNDS"); do
  k=0
  for b in "$@"; do
    "$b" "$SCENE" "$STEPS" 3 2>/dev/null | grep '^kernel=' | sed "s|\$| BUILD=$k|" >> "$TMP/lines"
    k=$((k + 1))
  done
done
/usr/bin/python3 - "$TMP/lines" "$@" <<'EOF'
import collections, statistics as st, sys
t = collections.defaultdict(list)
for line in open(sys.argv[1]):
    kv = dict(w.split("=", 1) for w in line.split() if "=" in w)
    t[(kv["threads"], int(kv["BUILD"]))].append(float(kv["time_s_median"]))
names = sys.argv[2:]
print("threads\tbuild\tmedian_s\tmin\tmax\tfirst_over_this\tper_round")
for th in sorted({k[0] for k in t}, key=int):
    base = t[(th, 0)]
    for k, name in enumerate(names):
        a = t[(th, k)]
        if not a:
            continue
        rounds = ",".join("%.2f" % (x / y) for x, y in zip(base, a))
        print("%s\t%s\t%.4f\t%.4f\t%.4f\t%.3f\t%s" % (th, name, st.median(a), min(a), max(a),
                                                    st.median(base) / st.median(a), rounds))
EOF
