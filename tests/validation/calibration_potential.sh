#!/usr/bin/env bash
# Coupling-true time of PL's potential coupling (src/app/calibrate.c,
# src/mapping/mapping_colloids.c; several minutes on 2 cores, so in `make
# validate-physics`, not `make check`):
# a dilute physical suspension (phi = 0.02, PL's WCA repulsion, no gravity, periodic)
# with the model of scenes/pl_potential_physical.cfg (its shipped calibration:
# nothing is calibrated here) diffuses sideways, measured from colloids.h5
# with h5py alone (tools/h5md_lateral_diffusion.py, SI), as the mapping
# states: the real Stokes-Einstein D times the box factor (Hasimoto and the
# scene's 1 - 1.1795 phi, PL Sec. VI.C, summary.json
# mapping.colloid_diffusion.d_box_m2_s), within the issue's 10 % with SE <
# 3.3 % (10 % = 3 SE), over the lags the calibration fits (4-12 x 2 M
# D_theory).  PL_POT_STEPS overrides the run length (12000 steps, 20
# colloids; 28 min wall at load ~15 on the shared 2 cores, 4.3 CPU-min).
# Measured: 1.900e-13 +- 0.045e-13 m^2/s against 2.184e-13 x 0.8814 =
# 1.925e-13 (-1.3 %, SE 2.4 %); at 4-12 tau_P the same run gives -8.3 %.
# Since the calibration adds the hydrodynamic tail its lags miss (its d_inf
# +1.15 %), the mapping's D is the long-time one, which these lags also
# miss in this box: 1.878e-13 +- 0.044e-13 against 1.927e-13 (-2.6 %, SE
# 2.4 %; 2026-12-06).
set -u
SUITE=calpot; source "$(dirname "$0")/../support/validation_suite.sh"
export PELOID_CACHE=$T/cache
. "$ROOT/tests/support/calibrated_check.sh"
echo "== coupling-true time of the potential coupling"

sed -e 's/^name = .*/name = "dilute_potential";/' -e 's/^steps = .*/steps = POTSTEPS;/' \
    -e 's/volume_fraction = 0.0995;.*/volume_fraction = 0.02;/' -e 's/box = \[12.0e-6, 12.0e-6, 12.0e-6\];/box = [16.0e-6, 16.0e-6, 16.0e-6];/' \
    -e 's/trajectory_interval = [0-9]*;/trajectory_interval = 10;/' \
    -e '/^observe:/d' -e '/^output:/d' "$ROOT/scenes/pl_potential_physical.cfg" | sed "s/POTSTEPS/${PL_POT_STEPS:-12000}/" > pot.cfg
calibrated_check "dilute potential" "dilute potential-coupling suspension" pot.cfg p \
  " (model differs from scenes/pl_potential_physical.cfg)" "$ROOT/tools/h5md_lateral_diffusion.py" --check p calibration

# 2. a lone sedimenting colloid of the same resolution (rho_p = 2 rho_f, 1 g,
#    Pe ~ 10; its own shipped calibration, the colloid mass being part of
#    the model) settles in the periodic 16^3 box (with the fluid's
#    counter-force, Hecht Sec. VIII.A iii) at the real Stokes velocity times
#    the box factor the mapping states (tools/h5md_settling.py: colloids.h5
#    with h5py, relative to the fluid's counter-flow), within 10 % with SE
#    < 3.3 % (16 blocks).  PL_POT_SETTLE_STEPS overrides the run length
#    (70000 steps ~ 160 s of real time: SE ~ sqrt(2 D / T) / v ~ 3 %; 44000
#    steps gave +5.6 % +- 3.9 %; 70000: +5.3 % +- 2.3 %, 1.85e-6 against
#    2.18e-6 x 0.8059 = 1.76e-6 m/s, 2.2 CPU-min).
sed -e "s/^steps = .*/steps = ${PL_POT_SETTLE_STEPS:-70000};/" "$ROOT/tests/calibration/pl_potential_settle.cfg" > ps.cfg
calibrated_check "settling potential" "settling potential-coupling colloid" ps.cfg s "" "$ROOT/tools/h5md_settling.py" s

echo "calibration_potential: $pass passed, $fail failed"
[ $fail -eq 0 ]
