#!/usr/bin/env bash
# The reduced studies of studies/reduced/ (make check): each full study of
# studies/ at a size that runs in seconds, asserting its headline within a
# looser, stated bound (the full studies: make studies, validation/REPORT.md).
# Each study's check and its bound live beside the full study's evaluation in
# tools/validation_report.py (REDUCED: NAME -> check(sweep) -> (passed,
# message)); this script runs studies/reduced/NAME.cfg for every NAME there.
#  - Hecht Fig. 9 kappa (~140 colloids, 0.17 s mapped): suspended at kappa =
#    1.0e8 /m, clustered at 2.0e8 /m by the full study's rule (largest cluster
#    above 10 % of the colloids); measured 2.1 +- 0.1 % and 97.6 +- 0.4 %.
#  - Hecht Figs. 12-13 bond kinds (the same reduced box, kappa = 1.4e8 /m):
#    the energy bonds are secondary-minimum bonds, >= 0.5 per colloid and
#    primary ones at most a tenth of them; measured 1.240 +- 0.014 and 0.
#  - Hecht Fig. 9 diagram (the same reduced box, kappa = 2e8 /m): the full
#    study's Psi0 direction, clustered at 20 mV and the largest cluster at
#    50 mV more than 30 points below; measured 97.6 +- 0.4 % and 34.5 +- 2.0 %.
#  - Hecht Figs. 5-7 g(r) (the same reduced box, Psi0 = 50 mV): at least
#    one contact peak B-D 5 SE high at kappa = 3e8 /m (the full study: all
#    three), none at 7.3e7 /m, there the first peak at the secondary minimum
#    within 3 SE or 0.05 R; measured B 6.2, D 12.7 SE (C 4.7); 0.4-0.9 SE;
#    2.435 +- 0.038 R vs 2.459 R.
#  - Hecht Fig. 14 MSD ((3.2 um)^3, 179 colloids, phi = 0.35, 240 steps): D
#    over steps 180-240 below D over 0-60 by more than 3 combined SE;
#    measured 0.00151 +- 0.00012 vs 0.00626 +- 0.00025 a0^2/t0 (17.1 SE).
#  - accuracy-cost guide (rho = 10, lambda = 0.1 and 1): within 3 SE of PL
#    Eqs. 9-15 at 12000 steps (0.3 % chance failure per point), and SE(12000
#    steps) / SE(3000 steps) in 0.3-0.8 (expected 0.5; a blocking SE from
#    ~10-20 blocks scatters by ~20 %, the mean ratio by ~0.1: 2-3 sigma).
#  - fluid self-diffusion guide (lambda = 1, 625 and 5000 particles, 1000
#    steps): D within 3 SE of PL Eq. 6 at 5000 particles; SE(625) / SE(5000)
#    in 1.6-4.5 (expected sqrt(8) = 2.83); SE(1000 steps) / SE(250-step
#    prefix) in 0.6-1.6 (expected 1: one time origin, the SE does not fall
#    with the run length).
#  - PL Figs. 10/13 VACF (8 colloids in L = 16, 2 x 3000 steps): the Enskog
#    decay time (0.2-1.2 t0 fit) within 25 % of tau_E (SE ~3 %, the fit form's
#    window systematic ~5 %; a doubled M_c gives -50 %), C(1 t0) below the
#    Langevin form, C_FF's decay time below 0.3 t0; measured tau = 1.253 +-
#    0.032 vs 1.257, C(1) = 0.449 vs 0.715, tau_FP = 0.124 t0.
#  - PL Fig. 4 g(r) (8 colloids in 12^3, SRD with depletion_comp 5000 steps
#    vs BD): contact peak within 5 combined SE, chi^2 p >= 1e-4, combined
#    peak SE < 0.25; measured -1.1 SE, p = 0.99 (SRD at sigma_cc = 4.1
#    against BD at 4.3 fails it: p = 6e-10).
#  - PL Fig. 11 D(phi) (L = 16 a0, N = 8 and 27, 3000 / 1600 steps): D from
#    the MSD over lags 4-10 t0 lower at phi = 0.22 than at 0.065 by more than
#    2 combined SE (8 blocks); measured -25 %, 3.9 SE.
#  - Hecht Fig. 4 R-Z (Pe = 1, (4 um)^3, phi = 0.05 for 1800 steps and 0.35
#    for 1000): hindered settling, the slip velocity at phi = 0.35 below that
#    at 0.05 by more than 3 combined SE; measured 0.0266 +- 0.0012 vs 0.0401
#    +- 0.0020 a0/t0, 5.8 SE (4.5 s CPU).
#  - PL Figs. 5-6 drag (sigma_cf = 2, L = 16, 8000 steps: 5 blocks after the
#    flow development): xi within 25 % of PL Eqs. 40-43 (~3 SE of 5 blocks);
#    measured 54.0 +- 6.9 vs 56.3, -4 % (5.0 s CPU).
#  - Hecht Figs. 12-13 phi (kappa = 1.4e8 /m, (4 um)^3 box, 0.17 s): the
#    largest cluster's fraction at phi = 0.21 above that at 0.07 by more
#    than 30 points; measured 69.7 +- 1.6 % vs 10.0 +- 0.5 % (3 s).
#  - Issue 39, E2 (lubrication, kappa = 1.4e8 /m, (4 um)^3 box, 0.32 s): the
#    lubricated colloids' translational kinetic energy within 10 % of
#    equipartition; measured 0.998, with lubrication.thermal = false 0.502
#    (the check fails on the noise-free lubrication) (5.8 s CPU).
set -u
PELOID=$(realpath "${1:-bin/peloid}")
PY=/usr/bin/python3
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
T=$(mktemp -d /tmp/peloid-studies.XXXXXX)
trap 'rm -rf "$T"' EXIT
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
echo "== reduced studies"
# every study with a reduced check in tools/validation_report.py (REDUCED)
# (run from tools/, where its modules are: Python imports from the current folder)
for s in $(cd "$ROOT/tools" && $PY -c "import validation_report as vr; print(' '.join(vr.REDUCED))"); do
  t0=$(date +%s)
  if ! "$PELOID" sweep "$ROOT/studies/reduced/$s.cfg" --out "$T/$s" > "$T/$s.log" 2>&1; then
    bad "$s: sweep failed: $(tail -1 "$T/$s.log")"; continue
  fi
  if out=$(cd "$ROOT/tools" && $PY - "$T" "$s" <<'PY'
import sys
import validation_report as vr
out, name = sys.argv[1], sys.argv[2]
sw = vr.load(out, name)
if any(not p["summary"] for p in sw["points"]):
    print("a point did not finish"); sys.exit(1)
good, msg = vr.REDUCED[name](sw)
print(msg)
sys.exit(0 if good else 1)
PY
  ); then ok "$s ($(( $(date +%s) - t0 )) s): $out"; else bad "$s: $out"; fi
done
echo "reduced studies: $pass passed, $fail failed"
[ $fail -eq 0 ]
