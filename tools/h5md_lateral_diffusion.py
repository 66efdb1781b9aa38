"""Lateral colloid diffusion coefficient from a colloids.h5 (H5MD) as a user's
analysis would compute it, with h5py alone and in SI: the unwrapped positions
(position + image x box edge), the mean-squared displacement in x and y
between two lags, D = [MSD(t2) - MSD(t1)] / (4 (t2 - t1)) (a slope: the
ballistic start cancels), averaged over colloids and time origins; its SE
from 8 blocks of origins.  Independent of peloid's own observers.

    python3 tools/h5md_lateral_diffusion.py colloids.h5 T1 T2      (lags in s)

prints "D SE" in m^2/s, then the frame count and the lags used.

    python3 tools/h5md_lateral_diffusion.py --check RUN_DIR {calibration|tauP}

the tests' judgement of a dilute physical run against the D its mapping states
(summary.json mapping.colloid_diffusion.d_box_m2_s): lags 4-12 x the
calibration's 2 M D_theory, or 4-12 x Hecht's tau_P; one line, exit 1 unless
the D came from a calibration and lies within 10 % with SE < 3.3 %."""
import json
import sys

import h5py
import numpy as np


def unwrapped(path):
    """(t in s, unwrapped positions in m [frame, colloid, axis]) of a colloids.h5 (of a model-unit run: t0, a0)."""
    with h5py.File(path, "r") as f:
        g = f["particles/colloids"]
        u = {"nm": 1e-9, "um": 1e-6, "m": 1.0, "a0": 1.0}  # a model-unit run stays in a0 and t0
        pu = g["position/value"].attrs.get("unit", "a0")  # H5MD: no unit attribute in a model-unit run
        pu = pu.decode() if isinstance(pu, bytes) else pu
        tu = g["position/time"].attrs.get("unit", "t0")
        tu = tu.decode() if isinstance(tu, bytes) else tu
        ls, ts = u[pu], {"ps": 1e-12, "ns": 1e-9, "s": 1.0, "t0": 1.0}[tu]
        x, img = g["position/value"][()] * ls, g["image/value"][()]
        t = g["position/time"][()] * ts
        L = np.diag(g["box/edges/value"][0]) * ls
    return t, x + img * L[None, None, :]


def lateral_d(path, tau1, tau2, blocks=8):
    t, r = unwrapped(path)
    dt = t[1] - t[0]
    k1, k2 = int(round(tau1 / dt)), int(round(tau2 / dt))
    n = len(t) - k2
    if k1 < 1 or k2 <= k1 or n < blocks:
        raise SystemExit(f"lags {tau1}..{tau2} s do not fit {len(t)} frames {dt} s apart")
    est = []
    for b in range(blocks):
        o = np.arange(n * b // blocks, n * (b + 1) // blocks)
        m1 = ((r[o + k1, :, :2] - r[o, :, :2]) ** 2).sum(-1).mean()
        m2 = ((r[o + k2, :, :2] - r[o, :, :2]) ** 2).sum(-1).mean()
        est.append((m2 - m1) / (4 * (k2 - k1) * dt))
    est = np.array(est)
    return est.mean(), est.std(ddof=1) / np.sqrt(blocks), len(t), k1 * dt, k2 * dt


def check_mapped(run, window):
    """(ok, line): the lateral D of RUN/colloids.h5 against the mapping's D in the run's box."""
    s = json.load(open(run + "/summary.json"))["mapping"]
    cd, tauP = s["colloid_diffusion"], s["hecht_times"]["tau_P"]["model_s"]
    # the calibration's window (src/app/calibrate.c: 4-12 x 2 M D_theory) or Hecht's tau_P
    tv = 2 * tauP * cd["d_theory_a0_2_t0"] / cd["d_a0_2_t0"] if window == "calibration" else tauP
    d, se, nf, t1, t2 = lateral_d(run + "/colloids.h5", 4 * tv, 12 * tv)
    ref = cd["d_box_m2_s"]
    line = (f"D = {d:.4g} +- {se:.2g} m^2/s from colloids.h5 ({nf} frames, lags {t1:.3g}..{t2:.3g} s) vs the mapping's "
            f"{ref:.4g} (real {cd['d_real_m2_s']:.4g} x box factor {cd['box_factor']:.4f}; {cd['source']}): "
            f"{100 * (d / ref - 1):+.1f} %, SE {100 * se / d:.1f} %")
    return cd["source"] == "calibration" and abs(d / ref - 1) <= 0.10 and se / d <= 0.033, line


if __name__ == "__main__":
    if sys.argv[1] == "--check":
        good, line = check_mapped(sys.argv[2], sys.argv[3])
        print(line)
        sys.exit(0 if good else 1)
    d, se, nf, a, b = lateral_d(sys.argv[1], float(sys.argv[2]), float(sys.argv[3]))
    print(f"{d:.6e} {se:.6e} {nf} frames, lags {a:.4g}..{b:.4g} s")
