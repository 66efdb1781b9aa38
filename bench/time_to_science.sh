#!/bin/bash
# Time to science: wall seconds per second of real (physical) time for the
# scenes of the papers' production runs, at 1 and 2 threads.
#
#   bench/time_to_science.sh [STEPS] [REPS]     (defaults 40 3)
#
# Each scene runs STEPS collision steps REPS times per thread count (median
# of the run loop's wall time from summary.json); the wall time of one real
# second is that per step times the steps of one real second:
#   - bench/scenes/fig9_model.cfg, fig14_model.cfg: model-unit copies of
#     Hecht's Fig. 9 and Fig. 14 conditions, whose `steps` (3380) is one
#     second at the mapping of their physical scenes (scenes/hecht_fig9.cfg,
#     hecht_fig14.cfg: srd.dt = 0.296 ms);
#   - scenes/quickstart.cfg (physical units): 1 / (srd.dt t0), t0 from the
#     mapping in summary.json.
# A short run extrapolated: in the clustering scenes the pair count, and so
# the cost per step, changes as clusters form (measured from the start).
set -eu
cd "$(dirname "$0")/.."
STEPS=${1:-40}; REPS=${2:-3}
[ -x bin/peloid ] || make bin/peloid >/dev/null
OUT=bench/out; mkdir -p "$OUT"; TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
TSV=$OUT/time_to_science.tsv
printf "scene\tthreads\tsteps_per_real_s\twall_s_per_step_median\tmin\tmax\twall_s_per_real_s\n" | tee "$TSV"
# The Fig. 14 model also with multiple time stepping (colloids.slow_interval
# = 5, the DLVO tail on outer steps of 5 MD steps; its accuracy:
# tools/mts_error.py, tools/compare_mts_statistics.py), as a copy with that
# key added.
MTS=$TMP/fig14_model_slow5.cfg
sed 's/^  substeps = 125;/  substeps = 125;\n  slow_interval = 5;/' bench/scenes/fig14_model.cfg > "$MTS"
grep -q 'slow_interval = 5' "$MTS" || { echo "time_to_science: could not add slow_interval to the Fig. 14 copy" >&2; exit 1; }
for scene in bench/scenes/fig9_model.cfg bench/scenes/fig14_model.cfg "$MTS" scenes/quickstart.cfg; do
  for t in 1 2; do
    : > "$TMP/w"
    for r in $(seq "$REPS"); do
      bin/peloid run "$scene" --steps "$STEPS" --threads "$t" --out "$TMP/o" --force >/dev/null 2>&1
      /usr/bin/python3 - "$TMP/o/summary.json" "$STEPS" "$scene" >> "$TMP/w" <<'EOF'
import json, re, sys
d = json.load(open(sys.argv[1]))
m = d.get("mapping") or {}
u = m.get("units") if isinstance(m, dict) else None
if u:
    per_s = 1.0 / (d["scene"]["srd"]["dt"] * u["t0_s"])
else:  # the scene file's own steps = one real second
    per_s = int(re.search(r"^steps\s*=\s*(\d+)", open(sys.argv[3]).read(), re.M).group(1))
print(d["wall_seconds"] / int(sys.argv[2]), per_s)
EOF
    done
    label=$scene; [ "$scene" = "$MTS" ] && label="bench/scenes/fig14_model.cfg + slow_interval 5"
    sort -g "$TMP/w" | awk -v s="$label" -v t="$t" '{w[NR]=$1; p=$2}
      END{m=(NR%2)?w[(NR+1)/2]:(w[NR/2]+w[NR/2+1])/2;
          printf "%s\t%d\t%.4g\t%.4g\t%.4g\t%.4g\t%.4g\n", s, t, p, m, w[1], w[NR], m*p}' | tee -a "$TSV"
  done
done
