#!/usr/bin/env bash
# The layers of src/ and kernels/ (issue 46; README "What each layer may
# touch"): tools/layers.py reads every library object's calls (nm) and fails on
# a use that breaks README's rules and is not in its list of known ones (each
# with its reason), and on a listed one the code no longer makes.  A selftest
# first: a use from kernels/ into src/fluid/ planted in a copy of the objects
# must be reported as new.
# Usage: bash tests/cli/layers.sh [BIN] (BIN unused: make check passes it)
set -u
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
PY=/usr/bin/python3
fail=0
if ! out=$($PY tools/layers.py "$BUILD" 2>&1); then
    echo "$out" | grep -v '^  known'
    echo "FAIL layers: the library breaks README's layer rules (above)"
    fail=1
else
    echo "ok   layers: $(echo "$out" | tail -1 | sed 's/^layers: //')"
fi
# selftest: a kernel object that calls the fluid's pl_srd_kept
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/src" "$tmp/kernels"
cp -r "$BUILD"/src/* "$tmp/src/"
cp "$BUILD"/kernels/*.o "$tmp/kernels/"
printf 'struct pl_srd; void pl_srd_kept(struct pl_srd *); void planted(struct pl_srd *s) { pl_srd_kept(s); }\n' > "$tmp/planted.c"
gcc -c -o "$tmp/kernels/planted.o" "$tmp/planted.c"
if out=$($PY tools/layers.py "$tmp" 2>&1) || ! echo "$out" | grep -q 'NEW   kernels -> src/fluid: pl_srd_kept (planted.o)'; then
    echo "$out" | tail -3
    echo "FAIL layers selftest: a planted kernels -> src/fluid call was not reported as new"
    fail=1
else
    echo "ok   layers selftest: a planted kernels -> src/fluid call is reported and fails the check"
fi
exit $fail
