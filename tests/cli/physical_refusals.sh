#!/usr/bin/env bash
# Every refusal of a physical scene names a key the user wrote or can write
# (issue 49): the physical scenes of tests/bad_scenes/ and the cases of
# tests/manual/physical_extremes.sh (tests/support/physical_extremes_cases.py), each checked
# with `peloid check --calibrate never` (theory D: no calibration runs, the
# same refusals).  A refusal (exit 2) passes when the key it blames
# ("key 'K'") and every key its remedy asks to change ("raise K", "lower K",
# "set K", ...) are either written in the scene file or not derived by the
# unit mapping.  The derived keys are what the mapping says it derived:
# `peloid params --json` of the shipped physical scenes, its
# mapping.colloid.derived_keys lines marked "(derived", the DLVO parameters
# of its "dlvo:" line, srd.dt, fluid.density, fluid.temperature, and
# box.cells where physical.box is given.  And `peloid params` of the shipped
# physical scenes prints no model value in an SI unit.
#   bash tests/cli/physical_refusals.sh PELOID            the test
#   bash tests/cli/physical_refusals.sh PELOID --list     and one line a refusal
set -u
PELOID=$(realpath "${1:-bin/peloid}")
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
T=$(mktemp -d /tmp/peloid-refusals.XXXXXX)
[ -n "${PL_KEEP:-}" ] || trap 'rm -rf "$T"' EXIT
export PELOID_CACHE="$T/cache"
echo "== physical refusals name keys the user can change"
t0=$(date +%s.%N)
for s in quickstart pl_potential_physical hecht_table1 hecht_fig14 hecht_fig9 pl_colloid_1um capillary; do
  "$PELOID" params --json --calibrate never "$ROOT/scenes/$s.cfg" > "$T/params_$s.json" 2> /dev/null
done
mkdir -p "$T/cases"
/usr/bin/python3 "$ROOT/tests/support/physical_extremes_cases.py" "$ROOT/scenes" "$T/cases" > /dev/null
mkdir -p "$T/bad"
for f in "$ROOT"/tests/bad_scenes/*.cfg; do  # (*.cfg only: the set holds links to /dev/zero)
  grep -q "^ *physical *:" "$f" && cp "$f" "$T/bad/"
done
cp -r "$ROOT/tests/bad_scenes/inc" "$ROOT"/tests/bad_scenes/*.txt "$T/bad/" 2> /dev/null
: > "$T/results.tsv"
for f in "$T"/bad/*.cfg "$T"/cases/*.cfg; do
  (cd "$(dirname "$f")" && timeout 60 "$PELOID" check --calibrate never "$(basename "$f")" > /dev/null 2> "$T/err")
  printf '%s\t%s\t%s\n' "$f" "$?" "$(head -1 "$T/err" | tr '\t' ' ')" >> "$T/results.tsv"
done
/usr/bin/python3 - "$T" "${2:-}" <<'PY'
import glob, json, os, re, sys
T, mode = sys.argv[1], sys.argv[2]
derived = {"srd.dt", "fluid.density", "fluid.temperature"}
for p in glob.glob(os.path.join(T, "params_*.json")):
    try:
        doc = json.load(open(p))
    except ValueError:
        continue
    for line in ((doc.get("mapping") or {}).get("colloid") or {}).get("derived_keys") or []:
        m = re.match(r"([a-z_]+\.[a-z_]+) = .*\(derived", line)
        if m:
            derived.add(m.group(1))
        elif line.startswith("dlvo: "):
            derived |= {"dlvo." + k for k in re.findall(r"(?:^dlvo: |, )([a-z_0-9]+) = ", line)}
assert {"colloids.radius", "colloids.substeps", "coupling.method", "dlvo.kappa"} <= derived, sorted(derived)
REMEDY = r"(?:raise|lower|increase|decrease|reduce|set|give|shorten|lengthen|use a (?:larger|smaller|longer|shorter))"
def written(text, key):
    sec, _, leaf = key.rpartition(".")
    body = text
    if sec:
        m = re.search(r"(?ms)^\s*%s\s*:\s*\{(.*?)\}\s*;" % re.escape(sec), text)
        body = m.group(1) if m else ""
    return re.search(r"(?<![a-z_])%s\s*=" % re.escape(leaf), body) is not None
def settable(text, key):
    if key.split(".")[0] in ("physical", "coarse_graining") or written(text, key):
        return True
    if key == "box.cells":
        return not written(text, "physical.box")
    return key not in derived
n = refused = bad = 0
for line in open(os.path.join(T, "results.tsv")):
    path, rc, msg = line.rstrip("\n").split("\t", 2)
    n += 1
    if rc != "2":
        continue
    refused += 1
    text = re.sub(r"(?m)#.*$", "", open(path).read())
    for inc in re.findall(r'@include "([^"]+)"', text):
        try:
            text += open(os.path.join(os.path.dirname(path), inc)).read()
        except OSError:
            pass
    named = re.findall(r"key '([a-z_]+(?:\.[a-z_]+)?)'", msg)[:1]
    named += [k for k in re.findall(REMEDY + r" ([a-z_]+\.[a-z_]+)", msg)]
    wrong = [k for k in named if not settable(text, k)]
    if wrong:
        bad += 1
        print(f"  FAIL {os.path.basename(path)}: names {', '.join(wrong)} (derived by the mapping, not written): {msg[:300]}")
    elif mode == "--list":
        print(f"  ok   {os.path.basename(path)}: {', '.join(named) or '(no key)'}")
print(f"  physical refusals: {n} scenes, {refused} refused, {bad} name a derived key ({len(derived)} derived keys known)")
sys.exit(1 if bad else 0)
PY
rc=$?
# params of the shipped physical scenes: model values in model units, real ones in SI, where they differ
# their ratio; no model value printed in an SI unit (the model's gravity, Hamaker constant, viscosity,
# Lambda or time scales in m/s^2, J, m^2/s, s^2/m^5, s)
for s in quickstart pl_potential_physical hecht_table1 hecht_fig14; do
  "$PELOID" params --calibrate never "$ROOT/scenes/$s.cfg" > "$T/params_$s.txt" 2> /dev/null
  if grep -qE "(J|m/s\^2|m\^2/s) in the model|model [0-9.e+-]+ s\^2/m\^5|\(real [0-9.e+-]+\)$|model \[s\]" "$T/params_$s.txt" \
     || ! grep -q "model \[t0\]   model/real" "$T/params_$s.txt" || ! grep -q "real nu = .* m^2/s, model/real = " "$T/params_$s.txt"
  then echo "  FAIL params $s: a model value in SI units: $(grep -E 'in the model|model \[|real nu' "$T/params_$s.txt" | head -3)"; rc=1
  else echo "  ok   params $s: model values in a0, t0, m_f, kT; real ones in SI; ratios where they differ"; fi
done
echo "  ($(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }') s)"
exit $rc
