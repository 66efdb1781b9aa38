#!/usr/bin/env bash
# The fluid stress observer (src/observe/stress_module.c) through bin/peloid:
#  - Green-Kubo shear viscosity of the pure SRD fluid (10^3 cells, gamma = 10,
#    alpha = 130 deg) against PL Eqs. 9-12, 14-15 at lambda = 1 (kinetic part
#    dominant) and lambda = 0.1 (collisional part dominant): within 3 SE of
#    the blocking over the per-step Green-Kubo estimator (3 SE: 0.3 % chance
#    failure per point for a Gaussian estimate), with 3 SE below 12 % of the
#    value (make check, STEPS = 12000) or 5 % (make validate, STEPS = 80000)
#    so that the comparison means something.  PL Eqs. 9-12 assume molecular
#    chaos; at these parameters they hold to ~2 % (tests/physics/test_viscosity.c,
#    Kolmogorov flow), below both bounds.  Measured at 12000 steps: lambda 1
#    5.602 +- 0.188 (PL 5.684, -0.4 SE), lambda 0.1 8.885 +- 0.210 (PL 8.700,
#    +0.9 SE).  Shown to fail: without the collisional part lambda 1 gives
#    4.78 (-5.2 SE) and lambda 0.1 0.525 (-450 SE); without the kinetic part
#    lambda 1 gives 0.88 (-200 SE) and the pressure 0.0002 (ideal 9.999);
#  - the running Green-Kubo sum has its plateau: at the last lag within 3 SE
#    of its value at half the lags;
#  - the pressure equals the ideal gas (N - 1) kT / V (SRD's equation of state;
#    N - 1: the box's momentum is fixed) within 4 SE, and its SE is below 1e-3
#    of it;
#  - the Couette cell's viscosity from the wall stress (below);
#  - the observables are bitwise the same at 1 and 2 threads.
set -u
PELOID=$(realpath "${1:-bin/peloid}")
STEPS=${2:-12000}
case $STEPS in 12000) REL=0.12;; *) REL=0.05;; esac
PY=/usr/bin/python3
T=$(mktemp -d /tmp/peloid-stress.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
echo "== stress observer tests ($STEPS steps)"

# hecht_axes (Hecht's +-90 deg rotations about the coordinate axes, the
# fluid of scenes/hecht_fig9.cfg): against Hecht Eq. 28, 5.333; PL Eqs.
# 9-15 at srd.alpha = 130 deg, which that rule ignores, give 8.70 (shown to
# fail: the reference was 8.70 before the theory followed the rule).
for case in 1.0:random_axis 0.1:random_axis 0.1:hecht_axes; do
  lam=${case%%:*}; rule=${case#*:}
  [ "$rule" = random_axis ] || lam=$lam-$rule
  cat > gk$lam.cfg <<CFG
seed = 17;
steps = $STEPS;
box: { cells = [10, 10, 10]; };
fluid: { density = 10; };
srd: { dt = ${case%%:*}; alpha = 130; rule = "$rule"; };
observe: { stress_interval = 100; };
CFG
  if ! "$PELOID" run gk$lam.cfg --threads 2 --out o$lam 2> err$lam; then
    bad "lambda $lam run: $(tail -1 err$lam)"; continue
  fi
  if out=$($PY - o$lam $REL <<'PY'
import json, sys, h5py
d = json.load(open(sys.argv[1] + "/summary.json"))["observables"]
rel = float(sys.argv[2])
e, p = d["fluid_viscosity"], d["fluid_pressure"]
v, se, th = e["value"], e["stderr"], e["theory"]
gk = h5py.File(sys.argv[1] + "/observables.h5")["observables/fluid_viscosity_gk/value"][:]
K = len(gk) - 1
msg = (f"eta {v:.4f} +- {se:.4f} vs {e['theory_source']} {th:.4f} ({(v - th) / th * 100:+.1f} %, {(v - th) / se:+.2f} SE); "
       f"GK sum at lag {K // 2}: {gk[K // 2]:.4f}, at {K}: {gk[K]:.4f}; "
       f"P {p['value']:.6f} +- {p['stderr']:.1e} vs ideal {p['ideal_gas']:.6f}")
good = (abs(v - th) <= 3 * se and 3 * se <= rel * th and e["plateau"]
        and abs(gk[K] - gk[K // 2]) <= 3 * se
        and abs(p["value"] - p["ideal_gas"]) <= 4 * p["stderr"] and p["stderr"] < 1e-3 * p["value"])
print(msg)
sys.exit(0 if good else 1)
PY
  ); then ok "lambda $lam: $out"; else bad "lambda $lam: $out"; fi
done

# Couette cell (tests/physics/test_shear.c's): 8 x 8 x 16, gamma 5, lambda 0.1,
# alpha 90, walls at -/+ 0.5, rescale thermostat; after 4000 steps (> 5
# momentum-diffusion times Lz^2 / (pi^2 nu)) eta = wall stress / measured
# shear rate against the viscosity of these (lambda, gamma, alpha) measured
# independently by Kolmogorov flow, tests/physics/test_viscosity.c: PL Eqs. 14-15
# x (1.023 +- 0.004) (the molecular-chaos formula is 2.3 % low here); within
# 3 combined SE, and 3 SE below REL.  Measured: 24000 steps 2.592 +- 0.063,
# 120000 steps 2.575 +- 0.028 (reference 2.553 +- 0.010; PL alone 2.496,
# which the 120000-step run sits 2.9 SE above); tests/physics/test_shear.c, with
# blocks of its own, gets 2.531 +- 0.033.
CSTEPS=$(( STEPS == 12000 ? 24000 : 120000 ))
cat > couette.cfg <<CFG
seed = 21;
steps = $CSTEPS;
box: { cells = [8, 8, 16]; walls_z = "noslip"; wall_velocity_bottom = [-0.5, 0.0, 0.0];
  wall_velocity_top = [0.5, 0.0, 0.0]; };
fluid: { density = 5; };
srd: { dt = 0.1; alpha = 90.0; };
thermostat: { type = "rescale"; };
observe: { stress_interval = 20; stress_start = 4000; };
CFG
if ! "$PELOID" run couette.cfg --threads 2 --out oc 2> errc; then
  bad "Couette run: $(tail -1 errc)"
elif out=$($PY - oc $REL <<'PY'
import json, sys
e = json.load(open(sys.argv[1] + "/summary.json"))["observables"]["couette_viscosity"]
rel = float(sys.argv[2])
v, se, th = e["value"], e["stderr"], e["theory"]
ref, ref_se = 1.023 * th, 0.004 * th  # Kolmogorov flow, tests/physics/test_viscosity.c (lambda 0.1, gamma 5, alpha 90)
tot = (se * se + ref_se * ref_se) ** 0.5
print(f"eta {v:.4f} +- {se:.4f} vs Kolmogorov-flow reference {ref:.4f} +- {ref_se:.4f} ({(v - ref) / tot:+.2f} SE; "
      f"PL alone {th:.4f}); stress {e['wall_shear_stress']['value']:.4f} +- {e['wall_shear_stress']['stderr']:.4f}, "
      f"rate {e['shear_rate']['value']:.5f} +- {e['shear_rate']['stderr']:.5f} (nominal {e['shear_rate']['nominal']:.5f})")
sys.exit(0 if abs(v - ref) <= 3 * tot and 3 * se <= rel * th else 1)
PY
); then ok "Couette: $out"; else bad "Couette: $out"; fi

sed -i "s/^steps = .*/steps = 5000;/" couette.cfg
"$PELOID" run couette.cfg --threads 1 --out c1 2> /dev/null && "$PELOID" run couette.cfg --threads 2 --out c2 2> /dev/null
if $PY - <<'PY'
import json, sys
sa, sb = (json.load(open(f"{d}/summary.json"))["observables"]["couette_viscosity"] for d in ("c1", "c2"))
sys.exit(0 if sa["value"] == sb["value"] and sa["stderr"] == sb["stderr"] else 1)
PY
then ok "Couette viscosity bitwise equal at 1 and 2 threads"; else bad "Couette viscosity differs between 1 and 2 threads"; fi

# One observables.h5 for both modules: a Couette cell with colloids and
# g(r) has the colloid and the stress groups; rerunning into the same
# directory (--force) writes a fresh file, not one appended to the old.
cat > both.cfg <<'CFG'
seed = 5;
steps = 200;
box: { cells = [8, 8, 12]; walls_z = "noslip"; wall_velocity_bottom = [-0.2, 0.0, 0.0];
  wall_velocity_top = [0.2, 0.0, 0.0]; };
fluid: { density = 5; };
srd: { dt = 0.1; };
colloids: { count = 4; radius = 1.0; init = "random"; };
coupling: { method = "hecht2"; };
observe: { rdf_interval = 10; stress_interval = 10; };
CFG
for k in 1 2; do "$PELOID" run both.cfg --threads 2 --out both --force 2> errb || bad "Couette + g(r) run $k: $(tail -1 errb)"; done
if $PY - <<'PY'
import sys, h5py
o = h5py.File("both/observables.h5")["observables"]
need = {"colloid_rdf", "wall_shear_stress", "shear_rate", "fluid_velocity_profile", "fluid_density_profile"}
sys.exit(0 if need <= set(o) and len(o["shear_rate/value"]) == 20 else 1)
PY
then ok "one observables.h5 with the colloid and stress groups, fresh on a rerun"; else bad "observables.h5 of a Couette + g(r) run"; fi

sed -i "s/^steps = .*/steps = 2000;/" gk0.1.cfg
"$PELOID" run gk0.1.cfg --threads 1 --out t1 2> /dev/null && "$PELOID" run gk0.1.cfg --threads 2 --out t2 2> /dev/null
# rerun into the same directory: observables.h5 written afresh (was: appended to the old file and failed)
"$PELOID" run gk0.1.cfg --threads 2 --out t2 --force 2> errt || bad "stress rerun with --force: $(tail -1 errt)"
if $PY - <<'PY'
import json, sys, h5py, numpy as np
a, b = (h5py.File(f"{d}/observables.h5")["observables"] for d in ("t1", "t2"))
same = all(np.array_equal(a[k][:], b[k][:]) for k in ("fluid_stress/value", "fluid_viscosity_gk/value"))
sa, sb = (json.load(open(f"{d}/summary.json"))["observables"] for d in ("t1", "t2"))
for k in ("fluid_viscosity", "fluid_pressure"):
    same &= sa[k]["value"] == sb[k]["value"] and sa[k]["stderr"] == sb[k]["stderr"]
sys.exit(0 if same else 1)
PY
then ok "stress observables bitwise equal at 1 and 2 threads"; else bad "stress observables differ between 1 and 2 threads"; fi

echo "stress: $pass passed, $fail failed"
[ $fail -eq 0 ]
