#!/bin/bash
# OpenMP fork/joins and synchronisations per collision step of the colloid
# MD (issue 38): runs `peloid run SCENE` for S1 and then S2 collision steps
# under the counting shim bench/shim/gomp_count.c (LD_PRELOAD) and prints the
# difference over S2 - S1 steps per call site in the colloid code (the
# kernels pl_colloid_*; the rest, fluid and coupling, summed in one line):
#   fork_join: GOMP_parallel calls (one per parallel region);
#   barrier:   GOMP_barrier calls / threads (team barriers: the implicit
#              ones of worksharing loops and single, and explicit ones);
#   single:    GOMP_single_start calls / threads (single constructs);
#   atomic (GOMP_atomic_start: reduction combines, per thread),
#   critical: calls.
#   bench/omp_counts.sh BIN SCENE [THREADS (2)] [S1 (2)] [S2 (12)]
set -eu
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: $0 BIN SCENE [THREADS] [S1] [S2]" >&2; exit 2; }
BIN=$1; SCENE=$2; T=${3:-2}; S1=${4:-2}; S2=${5:-12}
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
gcc -O2 -shared -fPIC -o "$TMP/gomp_count.so" bench/shim/gomp_count.c -ldl -lpthread
for s in "$S1" "$S2"; do
  GOMP_COUNT_OUT="$TMP/c$s" LD_PRELOAD="$TMP/gomp_count.so" OMP_NUM_THREADS=$T \
    "$BIN" run "$SCENE" --steps "$s" --threads "$T" --out "$TMP/o$s" > "$TMP/log$s" 2>&1 \
    || { echo "peloid run failed: $(tail -2 "$TMP/log$s")" >&2; exit 1; }
done
/usr/bin/python3 - "$BIN" "$T" "$S1" "$S2" "$TMP/c$S1" "$TMP/c$S2" "$SCENE" <<'PY'
import collections, subprocess, sys
binp, T, s1, s2, f1, f2, scene = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5], sys.argv[6], sys.argv[7]
def load(path):
    rows = []
    for line in open(path):
        entry, obj, off, cnt = line.split()
        rows.append((entry, obj, int(off, 16), int(cnt)))
    return rows
r1, r2 = load(f1), load(f2)
offs = sorted({o for _, obj, o, _ in r1 + r2 if ".so" not in obj})
names = {}
if offs:
    out = subprocess.run(["addr2line", "-f", "-e", binp] + [hex(o) for o in offs],
                         capture_output=True, text=True).stdout.split("\n")
    names = {o: out[2 * k] for k, o in enumerate(offs)}
KIND = {"GOMP_parallel": "fork_join", "GOMP_barrier": "barrier", "GOMP_single_start": "single",
        "GOMP_atomic_start": "atomic", "GOMP_critical_start": "critical"}
tab = collections.defaultdict(lambda: collections.Counter())
for sign, rows in ((-1, r1), (1, r2)):
    for entry, obj, off, cnt in rows:
        fn = names.get(off, "?") if ".so" not in obj else "(inside libgomp)"
        fn = fn.split("._omp_fn")[0]
        if not fn.startswith("pl_colloid") and fn != "(inside libgomp)":
            fn = "(other: fluid, coupling, output)"
        k = KIND.get(entry, entry)
        tab[fn][k] += sign * cnt
steps = s2 - s1
cols = ["fork_join", "barrier", "single", "atomic", "critical"]
print("# %s, %d threads, per collision step (runs of %d and %d steps)" % (scene, T, s1, s2))
print("site\t" + "\t".join(cols))
tot = collections.Counter()
for fn in sorted(tab):
    c = tab[fn]
    row = [c["fork_join"] / steps, c["barrier"] / T / steps, c["single"] / T / steps, c["atomic"] / steps,
           c["critical"] / steps]
    if not any(row):
        continue
    if fn.startswith("pl_colloid"):
        for k, v in zip(cols, row):
            tot[k] += v
    print(fn + "\t" + "\t".join("%.1f" % v for v in row))
print("COLLOID TOTAL\t" + "\t".join("%.1f" % tot[k] for k in cols))
PY
