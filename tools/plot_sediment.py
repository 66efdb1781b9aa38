#!/usr/bin/python3
"""Sedimentation plot of a colloid run: height profile vs time and the
colloids' centre-of-mass height with the expected settling lines.

    /usr/bin/python3 tools/plot_sediment.py [OUTDIR] [--png FILE]

OUTDIR (default out/quickstart) holds colloids.h5 (H5MD trajectory, needs
colloids.trajectory_interval > 0) and summary.json.  Writes OUTDIR/sediment.png
and prints the measured initial settling speed next to

  Stokes (Hecht Eq. 16):  v_S  = M g / xi, the friction the mapping matched:
                           xi = kT / D with the colloid D of summary.json's
                           mapping.colloid_diffusion (calibrated for couplings
                           I and II), else 6 pi eta R, eta = gamma nu (PL Eqs. 9-15)
  coupling II (one cell):  v_II = M g / xi_II, xi_II = 2/3 (1 - cos alpha) mu / dt,
                           mu = M gamma / (M + gamma) (src/coupling/coupling.c)

M g is the colloid weight minus buoyancy (colloids.gravity).  The measured
speed is the slope of the centre-of-mass height over the first stretch of
the run, where every colloid still falls: the run's own estimate
(summary.json initial_settling_velocity, the sedimentation observer: the
number report.md shows) where it has one, else a fit to the centre of mass
until it has gone a quarter of the way down to its final height.
"""
import argparse
import json
import math
import os
import sys

import numpy as np

import h5md_colloids
from system_title import system_title


def load(outdir):
    path = os.path.join(outdir, "summary.json")
    try:
        with open(path) as f:
            summ = json.load(f)
    except OSError as e:
        raise h5md_colloids.InputError(f"{path}: {e.strerror}") from None
    except (ValueError, UnicodeDecodeError) as e:
        raise h5md_colloids.InputError(f"{path}: not valid JSON ({e})") from None
    c = h5md_colloids.load(os.path.join(outdir, "colloids.h5"))
    pos, img, t, edges, mass, rad = c["pos"], c["img"], c["t"], c["edges"], c["mass"], c["rad"]
    z = pos[:, :, 2] + img[:, :, 2] * edges[2]
    return summ, t, z, edges, mass, rad


def predictions(summ, mass, rad):
    sc = summ["scene"]
    g = math.sqrt(sum(x * x for x in sc["colloids"]["gravity"]))
    M, R = float(np.mean(mass)), float(np.mean(rad))
    eta = summ["derived"]["eta"]
    gamma = sc["fluid"]["density"]
    dt = sc["srd"]["dt"]
    cos_a = 0.0 if sc["srd"]["rule"] == "hecht_axes" else math.cos(math.radians(sc["srd"]["alpha"]))
    mu = M * gamma / (M + gamma)
    xi2 = 2.0 / 3.0 * (1.0 - cos_a) * mu / dt
    xis = 6.0 * math.pi * eta * R
    cd = (summ.get("mapping") or {}).get("colloid_diffusion")
    if cd:  # the mapping's friction kT / D (kT = 1): the real Stokes velocity, as mapped
        xis = 1.0 / cd["d_a0_2_t0"]
    return {"M": M, "R": R, "g": g, "xi_stokes": xis, "xi_II": xi2,
            "v_stokes": M * g / xis, "v_II": M * g / xi2,
            "stokes_label": "Stokes v = M g D / kT (mapped D)" if cd else "Stokes v = M g / 6 pi eta R"}


def measure(t, zcm):
    """Slope of z_cm over the first quarter of the way down."""
    drop = zcm[0] - zcm.min()
    below = np.nonzero(zcm < zcm[0] - 0.25 * drop)[0]
    n = max(int(below[0]) if len(below) else len(zcm), 3)
    p = np.polyfit(t[:n], zcm[:n], 1)
    res = zcm[:n] - np.polyval(p, t[:n])
    se = math.sqrt(np.sum(res ** 2) / max(n - 2, 1) / np.sum((t[:n] - t[:n].mean()) ** 2))
    return -p[0], se, t[n - 1], p


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir", nargs="?", default="out/quickstart")
    ap.add_argument("--png", default=None)
    a = ap.parse_args()
    try:
        summ, t, z, edges, mass, rad = load(a.outdir)
    except h5md_colloids.InputError as e:  # one line naming the file, no traceback
        sys.exit(f"plot_sediment: {e}")
    if len(t) < 4:
        sys.exit("plot_sediment: fewer than 4 trajectory frames in %s" % a.outdir)
    try:
        pr = predictions(summ, mass, rad)
    except (KeyError, TypeError, ValueError, AttributeError) as e:
        sys.exit(f"plot_sediment: {a.outdir}/summary.json: a scene value is missing or malformed "
                 f"({type(e).__name__}: {e})")
    zcm = (z * mass[None, :]).sum(1) / mass.sum()
    v, se, t_fit, p = measure(t, zcm)
    source = "fit of colloids.h5's centre of mass over the first quarter of the way down"
    ini = (summ.get("observables") or {}).get("initial_settling_velocity") or {}
    if ini.get("value") is not None:  # the run's own estimate: the same number as report.md
        dt = summ["scene"]["srd"]["dt"]
        v, se, t_fit = ini["value"], ini["stderr"], ini["last_step"] * dt
        p = np.array([-v, zcm[0] + v * t[0]])
        source = "summary.json initial_settling_velocity (the sedimentation observer, relative to the fluid)"

    si = summ.get("units_si") or None
    ts, ls, vs = (si["t0_s"], si["a0_m"] * 1e6, si["a0_m"] * 1e6 / si["t0_s"]) if si else (1.0, 1.0, 1.0)
    tu, lu, vu = ("s", "µm", "µm/s") if si else ("t0", "a0", "a0/t0")

    print("plot_sediment: %s: %d colloids, R = %.4g a0, M = %.4g m_f, g = %.4g a0/t0^2"
          % (a.outdir, z.shape[1], pr["R"], pr["M"], pr["g"]))
    print("  measured initial settling speed  %.4g +- %.2g %s  (%.4g a0/t0, to t = %.4g %s; %s)"
          % (v * vs, se * vs, vu, v, t_fit * ts, tu, source))
    print("  %s, xi = %-7.4g  %.4g %s  (measured / Stokes = %.2f)"
          % (pr["stokes_label"], pr["xi_stokes"], pr["v_stokes"] * vs, vu, v / pr["v_stokes"] if pr["v_stokes"] else math.nan))
    print("  coupling II, xi_II = %-12.4g  %.4g %s  (measured / v_II = %.2f)"
          % (pr["xi_II"], pr["v_II"] * vs, vu, v / pr["v_II"] if pr["v_II"] else math.nan))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.4), constrained_layout=True)
    Lz = edges[2]
    nb = max(8, int(round(Lz / pr["R"])))
    bins = np.linspace(0.0, Lz, nb + 1)
    H = np.array([np.histogram(zz, bins=bins)[0] for zz in z])
    phi = H * (4.0 / 3.0 * math.pi * pr["R"] ** 3) / (edges[0] * edges[1] * (bins[1] - bins[0]))
    im = ax1.imshow(phi.T, origin="lower", aspect="auto", cmap="viridis",
                    extent=[t[0] * ts, t[-1] * ts, 0.0, Lz * ls], interpolation="nearest")
    fig.colorbar(im, ax=ax1, label="volume fraction in the layer")
    ax1.plot(t * ts, zcm * ls, "w-", lw=1.2, label="centre of mass")
    ax1.set_xlabel("time [%s]" % tu)
    ax1.set_ylabel("height z [%s]" % lu)
    ax1.set_title("colloid height profile")
    ax1.legend(loc="upper right", fontsize=8)

    ax2.plot(t * ts, zcm * ls, "k.", ms=3, label="centre of mass (run)")
    tt = np.linspace(0.0, t[-1], 200)
    for key, style, lab in (("v_stokes", "C0--", pr["stokes_label"]),
                            ("v_II", "C1:", "coupling II v = M g / xi_II")):
        zz = zcm[0] - pr[key] * tt
        keep = zz >= zcm.min() - 0.05 * (zcm[0] - zcm.min())
        ax2.plot(tt[keep] * ts, zz[keep] * ls, style, label="%s = %.3g %s" % (lab, pr[key] * vs, vu))
    tf = np.linspace(0.0, t_fit, 20)
    ax2.plot(tf * ts, np.polyval(p, tf) * ls, "C3-", lw=2, label="initial v = %.3g ± %.2g %s" % (v * vs, se * vs, vu))
    ax2.set_xlabel("time [%s]" % tu)
    ax2.set_ylabel("centre-of-mass height [%s]" % lu)
    ax2.set_title("settling of the centre of mass")
    ax2.legend(fontsize=8)
    fig.suptitle(system_title(summ), fontsize=10)
    png = a.png or os.path.join(a.outdir, "sediment.png")
    fig.savefig(png, dpi=110)
    print("  wrote %s" % png)


if __name__ == "__main__":
    main()
