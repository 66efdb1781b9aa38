# Sourced by tests/validation/calibration_coupling1.sh and tests/validation/calibration_potential.sh
# (after they define PELOID, PY, ok and bad): one check of a coupling's
# coupling-true time.  Runs CFG (2 threads) into OUT, which must read its
# shipped calibration (a run that calibrates instead has a model that
# differs from the scene the calibration was made for: WHY says which), then
# judges OUT with a tools/ script as a user's analysis would read it.
#   calibrated_check RUN_LABEL LABEL CFG OUT WHY TOOL [ARGS...]
# "RUN_LABEL run: ..." when the run fails or calibrates, "LABEL: <the tool's
# line>" for the judgement (the tool's exit status decides ok or FAIL).
calibrated_check() {
  local run_label=$1 label=$2 cfg=$3 out=$4 why=$5 r
  shift 5
  if ! "$PELOID" run "$cfg" --out "$out" --threads 2 2> "$out.log"; then bad "$run_label run: $(tail -1 "$out.log")"
  elif grep -q calibrating "$out.log"; then bad "$run_label run: calibrated instead of reading calibration/$why"
  elif r=$($PY "$@"); then ok "$label: $r"
  else bad "$label: $r"; fi
}
