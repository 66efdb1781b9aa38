#!/usr/bin/env bash
# Coupling-true time (src/app/calibrate.c, src/mapping/mapping_diffusion.c):
#  - a calibration is bitwise the same at 1 and 2 threads, fresh or read
#    back from the cache, and the shipped calibration/ file of the quickstart
#    is what the code computes now;
#  - a dilute physical suspension (coupling II, phi = 0.02, Hertz only, no
#    gravity, periodic) diffuses as the mapping says: the lateral D measured
#    from colloids.h5 with h5py alone (tools/h5md_lateral_diffusion.py, SI)
#    equals the real Stokes-Einstein D times the periodic box's factor the
#    mapping states (summary.json mapping.colloid_diffusion.d_box_m2_s)
#    within the issue's 10 %.  Measured: 5.24e-13 +- 0.12e-13 m^2/s against
#    5.20e-13 (+0.9 %, SE 2.2 %; the calibration's own SE 1.8 %); the SE
#    must be below 3.3 % so that 10 % is 3 SE.  Shown to fail: with the
#    theory's 6 pi eta R mapping (d8cc9c3) the same scene diffused 1.9-2.1x
#    faster (9.8e-13 and 1.07e-12 m^2/s at lags of 4-12 tau_P) than the
#    5.2e-13 it was mapped to;
#  - a dilute periodic sediment settles at the real Stokes velocity times
#    that box factor (summary.json initial_settling_velocity), within 10 %.
set -u
PELOID=$(realpath "${1:-bin/peloid}")
ROOT=$(realpath "$(dirname "$0")/../..")
PY=/usr/bin/python3
T=$(mktemp -d /tmp/peloid-calib.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
echo "== coupling-true time: calibration and the diffusion it maps"

cat > dilute.cfg <<'CFG'
name = "dilute";
seed = 7;
steps = 1500;
srd: { rule = "random_axis"; alpha = 130.0; grid_shift = true; };
thermostat: { type = "heyes"; temperature = 1.0; };
physical: {
  radius = 0.4e-6;
  particle_density = 3.9e3;
  solvent_density = 1.0e3;
  temperature = 300.0;
  viscosity = 1.0e-6;
  young_modulus = 3.7e11;
  poisson_ratio = 0.22;
  volume_fraction = 0.02;
  box = [10.3e-6, 10.3e-6, 10.3e-6];
};
coarse_graining: { coupling = "II"; particles_per_cell = 10.0; mean_free_path = 0.25; hertz_K = 1000.0; };
colloids: { init = "lattice"; pairs = "hertz"; trajectory_interval = 5; };
CFG
# the same model fluid and colloid as scenes/quickstart.cfg: one calibration
calfield() { $PY -c "import json,sys; d=json.load(open(sys.argv[1]))['mapping']['colloid_diffusion']; print(repr(d.get('calibration', {}).get(sys.argv[2])) if sys.argv[2] != 'source' else d['source'])" "$@"; }

# 1. fresh calibrations at 1 and 2 threads, and from the cache: the same bits
sed 's/particles_per_cell = 10.0/particles_per_cell = 8.0/' dilute.cfg > other.cfg
for th in 1 2; do
  PELOID_CACHE=$T/c$th PELOID_NO_SHIPPED_CALIBRATION=1 "$PELOID" run other.cfg --steps 0 --threads $th --out o$th 2> e$th \
    || bad "calibration at $th threads: $(tail -1 e$th)"
done
PELOID_CACHE=$T/c1 PELOID_NO_SHIPPED_CALIBRATION=1 "$PELOID" run other.cfg --steps 0 --out o3 2> e3
a=$(calfield o1/summary.json d_inf_a0_2_t0); b=$(calfield o2/summary.json d_inf_a0_2_t0); c=$(calfield o3/summary.json d_inf_a0_2_t0)
c1=$(calfield o1/summary.json wall_s); c3=$(calfield o3/summary.json wall_s)
if [ -n "$a" ] && [ "$a" != None ] && [ "$a" = "$b" ] && [ "$a" = "$c" ] && [ "$c3" = "0.0" ] && [ "$c1" != "0.0" ] \
   && grep -q "calibrating the colloid diffusion of coupling II" e1 && ! grep -q calibrating e3; then
  ok "calibration bitwise equal at 1 and 2 threads and from the cache (D_inf = $a a0^2/t0, run once: $c1 s)"
else bad "calibration bits: 1 thread $a, 2 threads $b, cached $c (cpu $c1 / $c3)"; fi

# 2. the shipped calibration of the quickstart is what the code computes
PELOID_CACHE=$T/cq PELOID_NO_SHIPPED_CALIBRATION=1 "$PELOID" params --json "$ROOT/scenes/quickstart.cfg" > q.json 2> /dev/null
f=$(ls "$T"/cq/calibration-*.json 2>/dev/null | head -1)
if [ -n "$f" ] && [ -f "$ROOT/calibration/$(basename "$f")" ] && $PY - "$f" "$ROOT/calibration/$(basename "$f")" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
keys = ["d_inf", "d_inf_se", "d_box", "d_box_se", "tail", "hasimoto", "n_colloids", "box", "steps"]
sys.exit(0 if all(a[k] == b[k] for k in keys) else 1)
PY
then ok "calibration/$(basename "$f") (shipped) = a fresh calibration, bit for bit"
else bad "shipped quickstart calibration differs from a fresh one or is missing ($f)"; fi

# 3. the dilute suspension diffuses as mapped
export PELOID_CACHE=$T/cache
if ! "$PELOID" run dilute.cfg --out d --threads 2 2> ed; then bad "dilute run: $(tail -1 ed)"
elif r=$($PY "$ROOT/tools/h5md_lateral_diffusion.py" --check d tauP
); then ok "dilute coupling II suspension: $r"
else bad "dilute coupling II suspension: $r"; fi

# 4. a dilute periodic sediment (phi = 0.02, gravity with the fluid's
#    counter-force, Hecht Sec. VIII.A iii) settles at the real Stokes
#    velocity times the box's factor the mapping states, within 10 % with
#    SE < 3.3 %: summary.json initial_settling_velocity (relative to the
#    fluid, over its homogeneous stretch).  Measured 0.963 +- 0.022 um/s
#    against 1.0115 x 0.9459 = 0.957 um/s (+0.7 %).  Shown to fail: the
#    theory mapping (d8cc9c3) settled at 1.97 um/s (phi = 0.01), 1.9x Stokes.
sed -e 's/volume_fraction = 0.02;/volume_fraction = 0.02; gravity = 9.81;/' -e 's/^steps = 1500;/steps = 3000;/' \
    -e 's/hertz_K = 1000.0;/hertz_K = 10000.0;/' -e 's/trajectory_interval = 5; };/trajectory_interval = 0; };/' dilute.cfg > sed.cfg
printf 'coupling: { compensate_gravity = true; };\nobserve: { sediment_interval = 5; };\n' >> sed.cfg
if ! "$PELOID" run sed.cfg --out s --threads 2 2> es; then bad "dilute sediment run: $(tail -1 es)"
elif r=$($PY - s <<'PY'
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
e, box = s["observables"]["initial_settling_velocity"], s["mapping"]["colloid_diffusion"]["box_factor"]
v, se, ref = e["value_m_per_s"], e["stderr_m_per_s"], e["stokes_m_per_s"] * box
print(f"v = {v:.4g} +- {se:.2g} m/s over {e['samples']} samples vs Stokes {e['stokes_m_per_s']:.4g} x box factor "
      f"{box:.4f} = {ref:.4g}: {100 * (v / ref - 1):+.1f} %, SE {100 * se / v:.1f} %")
sys.exit(0 if abs(v / ref - 1) <= 0.10 and se / v <= 0.033 else 1)
PY
); then ok "dilute periodic sediment: $r"
else bad "dilute periodic sediment: $r"; fi

# 5. the potential coupling's shipped calibration is found, not remeasured:
#    scenes/pl_potential_physical.cfg and a dilute copy of it (another phi and
#    box, the same model) both map time on calibration/'s D (the dilute
#    copy's diffusion against Stokes-Einstein: tests/validation/calibration_potential.sh,
#    make validate-physics, several minutes)
sed -e 's/volume_fraction = 0.0995;.*/volume_fraction = 0.02;/' \
    -e 's/box = \[12.0e-6, 12.0e-6, 12.0e-6\];/box = [16.0e-6, 16.0e-6, 16.0e-6];/' \
    "$ROOT/scenes/pl_potential_physical.cfg" > potd.cfg
okp=1
for sc in "$ROOT/scenes/pl_potential_physical.cfg" potd.cfg; do
  PELOID_CACHE=$T/cp "$PELOID" params --json "$sc" > pp.json 2> pe || okp=0
  grep -q calibrating pe && okp=0
  [ "$(calfield pp.json source 2>/dev/null)" = calibration ] || okp=0
done
[ $okp = 1 ] && ok "potential coupling: scenes/pl_potential_physical.cfg and a dilute copy read the shipped calibration" \
  || bad "potential coupling: shipped calibration not used ($(tail -1 pe))"

echo "calibration: $pass passed, $fail failed"
[ $fail -eq 0 ]
