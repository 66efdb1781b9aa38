#!/usr/bin/env bash
# Behaviour regression: every scene in scenes/ runs 50 collision steps at 1
# and at 2 threads; the sha256 of its checkpoint.h5 and thermo.tsv must equal
# the reference in tests/regression/hashes.txt.  Checkpoints carry no time
# stamps and no build information, so the same state gives the same bytes;
# thermo.tsv is hashed without its wall-clock rate column.
# A change that must alter trajectories regenerates the reference with
#   bash tests/cli/regression.sh bin/peloid --update
# and says why in its commit (with the statistical agreement it showed).
set -u
PELOID=$(realpath "${1:-bin/peloid}")
MODE=${2:-compare}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
REF="$ROOT/tests/regression/hashes.txt"
T=$(mktemp -d /tmp/peloid-regress.XXXXXX)
trap 'rm -rf "$T"' EXIT
STEPS=50
now="$T/hashes.txt"
: > "$now"
for scene in "$ROOT"/scenes/*.cfg; do
  name=$(basename "$scene" .cfg)
  for th in 1 2; do
    out="$T/$name.$th"
    if ! "$PELOID" run "$scene" --steps $STEPS --threads $th --out "$out" \
         2> "$T/err" > /dev/null; then
      echo "$name threads=$th run-failed" >> "$now"
      sed 's/^/    /' "$T/err" | tail -3
      continue
    fi
    for f in checkpoint.h5 thermo.tsv; do
      # thermo.tsv's last column (mupdates_per_s) is a wall-clock rate: cut
      if [ ! -f "$out/$f" ]; then h=absent
      elif [ $f = thermo.tsv ]; then
        h=$(awk -F'\t' -v OFS='\t' '{NF--; print}' "$out/$f" | sha256sum | cut -c1-64)
      else h=$(sha256sum < "$out/$f" | cut -c1-64); fi
      echo "$name threads=$th $f $h" >> "$now"
    done
    rm -rf "$out"
  done
done
if [ "$MODE" = "--update" ]; then
  cp "$now" "$REF"; echo "regression: reference rewritten ($(wc -l < "$REF") lines)"; exit 0
fi
if diff -u "$REF" "$now" > "$T/diff"; then
  echo "  ok   regression: $(wc -l < "$REF") checkpoint/thermo hashes of scenes/*.cfg (50 steps, 1 and 2 threads) unchanged"
  exit 0
fi
echo "  FAIL regression: hashes differ from tests/regression/hashes.txt:"
cat "$T/diff"
exit 1
