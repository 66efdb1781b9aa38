#!/usr/bin/env bash
# Adversarial set of physical extremes (issue 48, blame): each physical{} /
# coarse_graining{} key of scenes/quickstart.cfg, pl_potential_physical.cfg
# and hecht_table1.cfg pushed to a tiny and a huge value, one key per case
# (141 cases), checked with `peloid check` (own calibration cache, 30 s a
# case) and classified:
#   clean     exit 2, one stderr line with FILE:LINE:, the key blamed is the
#             key the case changed
#   vague     any other refusal (another key blamed, no line, a guard's exit)
#   accepted  exit 0 (a warning may have been printed: IMPLAUSIBLE, audit)
#   hang      still running after 30 s (a calibration of absurd length)
#   crash     killed by a signal
# Not part of make check (minutes: the calibrations run to their timeout).
#   bash tests/manual/physical_extremes.sh PELOID            the table
#   bash tests/manual/physical_extremes.sh PELOID --list     and one line a case
set -u
PELOID=$(realpath "${1:-bin/peloid}")
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
T=$(mktemp -d /tmp/peloid-extremes.XXXXXX)
trap 'rm -rf "$T"' EXIT
export PELOID_CACHE="$T/cache"
/usr/bin/python3 "$ROOT/tests/support/physical_extremes_cases.py" "$ROOT/scenes" "$T"
cd "$T"
declare -A count=([clean]=0 [vague]=0 [accepted]=0 [hang]=0 [crash]=0)
while IFS=$'\t' read -r n k v; do
  timeout 30 "$PELOID" check "$n.cfg" > /dev/null 2> err; rc=$?
  bl=$(grep -o "key '[^']*'" err | head -1 | sed "s/key '//;s/'//")
  if [ $rc = 124 ]; then c=hang; elif [ $rc -ge 128 ]; then c=crash; elif [ $rc = 0 ]; then c=accepted
  elif [ $rc = 2 ] && [ "$(grep -c . err)" = 1 ] && grep -qE "cfg:[0-9]+:" err && [ "$bl" = "$k" ]; then c=clean
  else c=vague; fi
  count[$c]=$((count[$c]+1))
  [ "${2:-}" = --list ] && printf '  %-8s %-62s %s: %s\n' "$c" "$n" "$rc" "$(head -c 160 err | tr '\n' ' ')"
done < cases.tsv
echo "physical extremes: $(wc -l < cases.tsv): clean ${count[clean]}, vague ${count[vague]}, accepted ${count[accepted]}, crash ${count[crash]}, hang ${count[hang]}"
