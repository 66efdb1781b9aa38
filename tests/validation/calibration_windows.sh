#!/usr/bin/env bash
# Is the coupling-true-time calibration converged and as sure as it says
# (issue 45)?  The model of scenes/quickstart.cfg (coupling II, gamma 10,
# lambda 0.25, R 0.62 a0, M 39) in its calibration box (32 free colloids,
# 16^3 periodic cells; src/app/calibrate.c), run here as an ordinary model
# scene for PL_CALW_SEEDS seeds (6) x PL_CALW_STEPS steps (40000: 10000 t0),
# colloids.h5 read with h5py alone:
#  1. The shipped calibration's d_box + tail (the tail the window misses,
#     pl_srd_tail_missed) agrees with these runs' long-lag slopes over [50,
#     150] and [150, 450] t0 (where the box's modes have decayed: the tail
#     left is below 1e-5) within 3 combined SE (its own SE 1.8 %).
#     Reported beside it, not asserted: these runs' slope over the
#     calibration's window [6, 18] t0 plus the tail against the long lags.
#     Measured (8 seeds, 2026-12-06): [6, 18] t0 0.03693 +- 0.00006, + tail
#     0.00089 = 0.03783; [18, 54] 0.03813 +- 0.00010; [50, 150] 0.03817 +-
#     0.00021; [150, 450] 0.03805 +- 0.00043; [400, 1200] 0.03788 +-
#     0.00062: the corrected window is 0.8 +- 0.5 % below the long lags,
#     without the tail 3.2 %.  The residual is real: the corrected slope
#     still rises by ~1 % between [6, 18] and [18, 54] t0 (3.7 SE), beyond
#     the asymptotic tail (the velocity's relaxation at 6 t0 is not purely
#     hydrodynamic yet), so "flat within SE" holds for the calibration's own
#     SE, not for that of these long runs, and a bound on it here would fail
#     one run in ten; a later window would need every shipped calibration
#     remeasured.  The tail itself is tested against Hasimoto's limit in
#     tests/unit/test_mapping_hydro.c.
#  2. The calibration's SE (8 blocks of origins of one 2880-step run) is
#     honest: cut into runs of the calibration's length, the scatter of their
#     [6, 18] t0 slopes over the RMS of their 8-block SEs is within 0.7-1.4
#     (the issue's bound; the ratio's own SE is ~1/sqrt(2 N), 0.08 for 78
#     runs).  Measured (8 seeds, 104 runs): 1.02 +- 0.07.
# ~4 CPU-min (1 thread per run, two at a time).
set -u
SUITE=calw; source "$(dirname "$0")/../support/validation_suite.sh"
SEEDS=${PL_CALW_SEEDS:-6}
STEPS=${PL_CALW_STEPS:-40000}
echo "== calibration: lag windows and its SE (coupling II, the quickstart's model)"
"$PELOID" params --json "$ROOT/scenes/quickstart.cfg" > q.json 2> q.err || { bad "params quickstart: $(tail -1 q.err)"; exit 1; }
for s in $(seq 1 "$SEEDS"); do
  cat > s$s.cfg <<CFG
name = "calibration_box_$s";
seed = $s;
steps = $STEPS;
box: { cells = [16, 16, 16]; };
fluid: { density = 10.0; temperature = 1.0; };
srd: { dt = 0.25; rule = "random_axis"; alpha = 130.0; grid_shift = true; };
thermostat: { type = "heyes"; temperature = 1.0; };
colloids: { count = 32; radius = 0.62035049089940009; mass_density = 39.0; temperature = 1.0; init = "random";
            pairs = ""; substeps = 1; max_overlap = 1.0; trajectory_interval = 8; };
coupling: { method = "hecht2"; };
output: { thermo_interval = 1000; };
CFG
done
for s in $(seq 1 "$SEEDS"); do
  "$PELOID" run s$s.cfg --out r$s --threads 1 > r$s.log 2>&1 &
  if (( s % 2 == 0 )); then wait; fi
done
wait
for s in $(seq 1 "$SEEDS"); do [ -f r$s/summary.json ] || bad "seed $s did not finish: $(tail -1 r$s.log)"; done
out=$($PY - "$SEEDS" <<'PY'
import json, sys
import numpy as np, h5py
seeds = int(sys.argv[1])
q = json.load(open("q.json"))
cal = q["mapping"]["colloid_diffusion"]["calibration"]
dbox, tail, se_cal = cal["d_box_a0_2_t0"], cal["tail_a0_2_t0"], cal["d_inf_se_a0_2_t0"]

def load(p):
    c = h5py.File(p, "r")["particles/colloids"]
    L = np.diag(c["box/edges/value"][0])  # the edge vectors (H5MD: a 3 x 3 matrix per frame)
    return c["position/value"][()] + c["image/value"][()] * L, c["position/time"][()]

def blocks(r, dt, t1, t2, nb=8):  # as src/app/calibrate.c: 8 blocks of origins
    l1, l2 = int(round(t1 / dt)), int(round(t2 / dt)); last = len(r) - 1 - l2
    b = []
    for k in range(nb):
        k0, k1 = (last + 1) * k // nb, (last + 1) * (k + 1) // nb
        a = r[k0:k1]
        s1 = ((r[k0 + l1:k1 + l1] - a) ** 2).sum(-1); s2 = ((r[k0 + l2:k1 + l2] - a) ** 2).sum(-1)
        b.append(((s2 - s1) / (6 * (l2 - l1) * dt)).mean())
    b = np.array(b)
    return b.mean(), b.std(ddof=1) / np.sqrt(nb)

runs = [load("r%d/colloids.h5" % s) for s in range(1, seeds + 1)]
dt = runs[0][1][1] - runs[0][1][0]
win = {}
for w in [(6, 18), (50, 150), (150, 450)]:
    d = np.array([blocks(r, dt, *w)[0] for r, t in runs])
    win[w] = (d.mean(), d.std(ddof=1) / np.sqrt(len(d)))
long = [win[(50, 150)], win[(150, 450)]]
wl = np.array([1 / s ** 2 for m, s in long]); dl = sum(w * m for w, (m, s) in zip(wl, long)) / wl.sum()
sl = wl.sum() ** -0.5
corr = dbox + tail
z = (corr - dl) / np.hypot(se_cal, sl); z0 = (dbox - dl) / np.hypot(se_cal, sl)
rel_cal = se_cal / cal["d_inf_a0_2_t0"]  # the calibration's relative SE
rw = (win[(6, 18)][0] + tail) / dl - 1; rw0 = win[(6, 18)][0] / dl - 1
print("note|-|these runs' [6, 18] t0 slope %.5f + tail %.5f vs their long lags %.5f +- %.5f ([50, 150] %.5f, [150, 450] %.5f t0): %+.1f %% (without the tail %+.1f %%; the calibration's SE %.1f %%)"
      % ( win[(6, 18)][0], tail, dl, sl, long[0][0], long[1][0], 100 * rw, 100 * rw0, 100 * rel_cal))
print("cal|%d|shipped d_box %.5f + tail %.5f = %.5f +- %.5f vs the long lags: %+.1f SE (without the tail %+.1f SE; bound 3)"
      % (abs(z) < 3, dbox, tail, corr, se_cal, z, z0))
n = int(round(720.0 / dt)) + 1  # the calibration's length: 2880 steps
ds, ses = [], []
for r, t in runs:
    for s in range(0, len(r) - n + 1, n):
        d, se = blocks(r[s:s + n], dt, 6.0, 18.0); ds.append(d); ses.append(se)
ds, ses = np.array(ds), np.array(ses)
ratio = ds.std(ddof=1) / np.sqrt((ses ** 2).mean())
print("se|%d|%d runs of 720 t0: scatter of the slope / its 8-block SE = %.2f +- %.2f (bound 0.7-1.4)"
      % (0.7 <= ratio <= 1.4, len(ds), ratio, ratio / np.sqrt(2 * (len(ds) - 1))))
PY
) || bad "analysis failed: $out"
while IFS='|' read -r what good msg; do
  [ -z "$what" ] && continue
  if [ "$what" = note ]; then echo "  note $msg"
  elif [ "$good" = 1 ]; then ok "$msg"; else bad "$msg"; fi
done <<< "$out"
echo "calibration windows: $pass passed, $fail failed"
[ $fail -eq 0 ]
