# The common start of the validation scripts (tests/validation/*.sh), sourced
# after setting SUITE (the temporary folder's name):
#   SUITE=rot; source "$(dirname "$0")/../support/validation_suite.sh"
# It reads the script's own arguments (PELOID [--md REPORT.md]) and sets
# PELOID (the binary, absolute), MD (the report --md names, else ""), ROOT
# (the repository), PY (Debian's python3), T (a temporary folder, removed on
# exit, made the working folder), the counters pass and fail, and ok / bad,
# which print a result line and count it.
PELOID=$(realpath "${1:-bin/peloid}")
MD=""
[ "${2:-}" = "--md" ] && MD=$(realpath "$3")
ROOT=$(realpath "$(dirname "$0")/../..")
PY=/usr/bin/python3
T=$(mktemp -d "/tmp/peloid-$SUITE.XXXXXX")
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
