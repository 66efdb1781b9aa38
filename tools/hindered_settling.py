"""Hindered settling of a study's colloids against Batchelor's dilute slope K and Richardson-Zaki's exponent n, by
the rules of validation/RULES_hindered_settling.md (fixed before the runs): the section "Collective hydrodynamics:
hindered settling" of validation/REPORT.md, written between its markers, and its plot.

Per point of the sweep: the sedimentation observer's slip velocity u (summary.json, SI, positive down) and, read
independently with h5py from colloids.h5, the colloids' mean fall in the box frame turned into u by the zero total
momentum (H3); the zero-volume-flux velocity U = u (1 - phi); U0 = the mapped Stokes velocity; Hasimoto's box term
2.837 R_h / L with R_h from the calibration.

    python3 tools/hindered_settling.py OUT/STUDY REPORT.md [COMMIT]     (prints the section; exit 0)

STUDY is one of STUDIES (its name is the folder's).  sections(text) lists the sections a report holds, for
tools/validation_report.py to keep."""
import json
import math
import os
import sys

import numpy as np

from h5md_settling import block_falls
from validation.common import pyplot, save_figure
from validation.report_section import sections_in, study_section_main

BEGIN = "<!-- hindered settling: {} (tools/hindered_settling.py) -->"  # .format(study name)
END = "<!-- end of the hindered settling section: {} -->"
# What each study's section says of its model and what it leaves out (the numbers come from the runs).
STUDIES = {
    "hindered_settling_c1": dict(
        coupling="coupling I", rule="H1–H3", phi_n="0.05–0.30",
        model="Al2O3, R = 0.4 µm, hecht_table1's coupling I model (a0 = R/2, M = 2.5, λ = 0.6 a0, no "
              "thermostat, its shipped calibration), hard spheres (Hertz + lubrication), a random start",
        reason="its Enskog friction acts in series with the Stokes friction, PL Eqs. 40–41",
        hot="the base scene has no thermostat (as hecht_table1); gravity's work is taken up by the colloids' "
            "thermal surfaces.  Coupling I's viscosity is mostly kinetic (∝ kT)",
        missing="D(φ) of coupling I, other Pe"),
    "hindered_settling_pot": dict(
        coupling="the potential coupling", rule="H4 (H1–H3's fits and bounds)", phi_n="0.05–0.20",
        model="polystyrene (1050 kg/m³), R = 1 µm, pl_potential_physical's model (PL Eq. 17, σ_cf = R = 2 a0, "
              "γ 5, λ 0.1 a0, 90° about random axes, the rescaling thermostat, PL's WCA between colloids: hard "
              "core 1.122 R), calibrated afresh for this colloid mass, a lattice start",
        reason="its slip surface and the Enskog friction in parallel, PL Eqs. 39–41, give the friction of a "
               "stick sphere of that radius",
        hot=None, missing="D(φ), other Pe"),
}
K_BATCHELOR, N_RZ = 6.55, 4.65
HASIMOTO = 2.837


def sections(text):
    """The hindered-settling sections in a report's text, each from its begin to its end marker."""
    return sections_in(text, STUDIES, BEGIN, END)


def k_rp(x):
    """Rotne-Prager with excluded Stokeslets at a_h/a = x (REPORT.md's form for coupling II): 5.5 at x = 1."""
    return 6.0 * x - 0.5 * x ** 3


def h5_slip(run, t_from, blocks=8):
    """u from colloids.h5 alone over t >= t_from (tools/h5md_settling.py): (u, its SE from `blocks` blocks, the mean
    of the first half of the blocks, of the second half, and the SE of each half)."""
    vb, _ = block_falls(run, blocks, t_from)
    h = blocks // 2
    return vb.mean(), vb.std(ddof=1) / math.sqrt(blocks), vb[:h].mean(), vb[h:].mean(), vb.std(ddof=1) / math.sqrt(h)


def points(study):
    sw = json.load(open(os.path.join(study, "sweep.json")))
    rows = []
    for p in sw["points"]:
        run = os.path.join(study, p["id"])
        sp = os.path.join(run, "summary.json")
        if p.get("status") != "ok" or not os.path.exists(sp):
            continue
        s = json.load(open(sp))
        sv, ini = s["observables"]["settling_velocity"], s["observables"]["initial_settling_velocity"]
        c = s["mapping"]["colloid"]
        u5, u5se, h1, h2, hse = h5_slip(run, sv["average_from_time"])
        th = np.genfromtxt(os.path.join(run, "thermo.tsv"), names=True, delimiter="\t")
        kt = float(th["temperature"][th["step"] >= sv["average_from_step"]].mean())  # fluid kT / the scene's
        rows.append(dict(
            phi=c["volume_fraction_realised"], n=c["n_colloids"], u=sv["value_si"], u_se=sv["stderr_si"],
            U0=ini["stokes_m_per_s"], cal=s["calibration"]["relative_error"],
            rh=c["hydrodynamic_radius_stick_over_R"], rh_surface=c["hydrodynamic_radius_over_R"],
            surface=c["hydrodynamic_radius_boundary"], phi_c=_phi_c(s),
            rh_se=c["hydrodynamic_radius_over_R_se"], L=s["mapping"]["colloid_diffusion"]["box_L_a0"],
            R=c["radius_a0"],
            u5=u5, u5_se=u5se, kT=kt, h1=h1, h2=h2, hse=hse, cpu=s.get("cpu_seconds", 0.0),
            rev=s["peloid"]["git_revision"]))
    rows.sort(key=lambda r: r["phi"])
    return rows


def _phi_c(s):
    """The colloids' hard-core volume fraction the mapping states beside phi (None: the stated R is the core)."""
    h = s["mapping"]["colloid"].get("volume_fraction_hard_core")
    return h


def fit_k(rows):
    """H1: K by weighted least squares through the origin over phi <= 0.10; SE with the calibration's in quadrature."""
    sel = [r for r in rows if r["phi"] <= 0.105]
    phi = np.array([r["phi"] for r in sel])
    U = np.array([r["u"] * (1 - r["phi"]) for r in sel])
    se = np.array([r["u_se"] * (1 - r["phi"]) for r in sel])
    r0 = sel[0]
    box = HASIMOTO * r0["rh"] * r0["R"] / r0["L"]
    y = 1.0 - box - U / r0["U0"]
    sy = se / r0["U0"]
    w = 1.0 / sy ** 2
    K = float((w * y * phi).sum() / (w * phi * phi).sum())
    se_stat = float(1.0 / math.sqrt((w * phi * phi).sum()))
    # the calibration: U0 ~ D_inf and R_h ~ 1/D_inf, so dy/d(ln D) = U/U0 + box
    dy = (U / r0["U0"] + box)
    dK = float((w * dy * phi).sum() / (w * phi * phi).sum()) * r0["cal"]
    chi2 = float((w * (y - K * phi) ** 2).sum())
    return K, math.hypot(se_stat, dK), se_stat, dK, box, chi2, len(sel)


def fit_n(rows):
    """H2: ln U = ln v_inf + n ln(1 - phi) over phi 0.05-0.30, SE scaled by sqrt(chi2/dof) above 1."""
    sel = [r for r in rows if 0.045 <= r["phi"]]
    x = np.log(1 - np.array([r["phi"] for r in sel]))
    U = np.array([r["u"] * (1 - r["phi"]) for r in sel])
    y = np.log(U)
    sy = np.array([r["u_se"] / r["u"] for r in sel])
    w = 1.0 / sy ** 2
    A = np.vstack([np.ones_like(x), x]).T
    C = np.linalg.inv(A.T @ (A * w[:, None]))
    b = C @ (A.T @ (w * y))
    chi2 = float((w * (y - A @ b) ** 2).sum())
    dof = max(len(sel) - 2, 1)
    scale = max(1.0, math.sqrt(chi2 / dof))
    return float(b[1]), float(math.sqrt(C[1, 1]) * scale), float(math.exp(b[0])), chi2 / dof, len(sel)


def dk(rows, box, phi):
    """The K a fluid warmer by the window's mean kT - 1 would make at phi (U ~ 1/eta ~ 1/kT)."""
    r = min(rows, key=lambda q: abs(q["phi"] - phi))
    return (r["kT"] - 1.0) * (1.0 - box) / r["phi"]


def pk(rows, box, phi):
    """The point nearest phi's own K, (1 - box - U/U0)/phi +- SE, as text."""
    r = min(rows, key=lambda q: abs(q["phi"] - phi))
    f = (1 - r["phi"]) / r["U0"] / r["phi"]
    return f"{(1 - box) / r['phi'] - r['u'] * f:.2f} ± {r['u_se'] * f:.2g}"


def verdict(value, se, ref, tol, rh):
    if abs(value - ref) <= tol * ref + 2 * se:
        return "agrees"
    return "disagrees — set-up" if abs(rh - 1.0) > 0.05 else "disagrees — peloid"


def plot(rows, K, n, vinf, box, path, what):
    plt = pyplot()
    r0 = rows[0]
    phi = np.array([r["phi"] for r in rows])
    U = np.array([r["u"] * (1 - r["phi"]) for r in rows]) / r0["U0"]
    se = np.array([r["u_se"] * (1 - r["phi"]) for r in rows]) / r0["U0"]
    U5 = np.array([r["u5"] * (1 - r["phi"]) for r in rows]) / r0["U0"]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.errorbar(phi, U, yerr=se, fmt="o", color="C0", capsize=3, label=f"peloid, {what} (observer)")
    ax.plot(phi, U5, "x", color="C3", label="the same runs, colloids.h5 (h5py)")
    xx = np.linspace(0, max(phi) * 1.07, 100)
    ax.plot(xx, 1 - box - K_BATCHELOR * xx, "k--", lw=1, label=f"Batchelor: 1 − box − {K_BATCHELOR} φ")
    ax.plot(xx, 1 - box - K * xx, "C0-", lw=1, label=f"fit (φ ≤ 0.1): K = {K:.2f}")
    ax.plot(xx, 1 - box - k_rp(r0["rh"]) * xx, "C2:", lw=1.2,
            label=f"Rotne–Prager at a_h/a = {r0['rh']:.3f}: K = {k_rp(r0['rh']):.2f}")
    ax.plot(xx, vinf / r0["U0"] * (1 - xx) ** n, "C1-.", lw=1, label=f"Richardson–Zaki fit: n = {n:.2f}")
    ax.plot(xx, vinf / r0["U0"] * (1 - xx) ** N_RZ, "C1:", lw=1, label=f"n = {N_RZ} (same v∞)")
    ax.set_xlim(0, max(phi) * 1.07)
    ax.set_ylim(0, 1.05)
    ax.set_xlabel("volume fraction φ")
    ax.set_ylabel("U / U_Stokes  (zero-volume-flux frame)")
    ax.set_title(f"Hindered settling, {what}, Pe 3, periodic L = {r0['L']:.0f} a0 (box term {box:.3f})",
                 fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper right")
    save_figure(plt, fig, path)


def section(study, commit, png):
    rows = points(study)
    name = os.path.basename(os.path.normpath(study))
    info = STUDIES[name]
    if len(rows) < 5:
        raise SystemExit(f"hindered_settling: {len(rows)} finished point(s) in {study}; the rules need all 5")
    K, K_se, K_stat, K_cal, box, k_chi2, nk = fit_k(rows)
    n, n_se, vinf, n_chi2, nn = fit_n(rows)
    r0 = rows[0]
    rh = r0["rh"]
    stat_bad = [r for r in rows if abs(r["h1"] - r["h2"]) > 3 * math.sqrt(2) * r["hse"]]
    h5_bad = [r for r in rows if abs(r["u5"] - r["u"]) > 3 * math.hypot(r["u5_se"], r["u_se"])]
    vk = verdict(K, K_se, K_BATCHELOR, 0.15, rh)
    vn = verdict(n, n_se, N_RZ, 0.10, rh)
    if stat_bad or h5_bad:
        vk, vn = "not settled (" + vk + ")", "not settled (" + vn + ")"
    plot(rows, K, n, vinf, box, png, info["coupling"])
    cpu = sum(r["cpu"] for r in rows)
    tab = ["| φ | colloids | u (µm/s), observer | u (µm/s), colloids.h5 | halves (µm/s) | U/U0 = u (1 − φ)/U0 | "
           "(1 − box − U/U0)/φ | fluid kT |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        tab.append(f"| {r['phi']:.4f} | {r['n']} | {1e6 * r['u']:.4f} ± {1e6 * r['u_se']:.4f} | "
                   f"{1e6 * r['u5']:.4f} ± {1e6 * r['u5_se']:.4f} | {1e6 * r['h1']:.3f}, {1e6 * r['h2']:.3f} | "
                   f"{r['u'] * (1 - r['phi']) / r['U0']:.4f} ± {r['u_se'] * (1 - r['phi']) / r['U0']:.4f} | "
                   f"{pk(rows, box, r['phi'])} | {r['kT']:.3f} |")
    png_name = os.path.basename(png)
    radius = (f"R_h/R = {rh:.3f} ± {r0['rh_se'] * rh / r0['rh_surface']:.3f}" if r0["surface"] == "stick" else
              f"R_h/R = {r0['rh_surface']:.3f} ± {r0['rh_se']:.3f} as a {r0['surface']} sphere, {rh:.3f} as the "
              "stick sphere of the same friction")
    core = (f"  The hard core is larger than R: φ_c = {r0['phi_c'] / r0['phi']:.2f} φ; per hard-core volume "
            f"fraction K_c = K φ/φ_c = {K * r0['phi'] / r0['phi_c']:.2f} ± {K_se * r0['phi'] / r0['phi_c']:.2f}."
            if r0["phi_c"] and abs(r0["phi_c"] / r0["phi"] - 1) > 0.01 else "")
    if info["hot"]:
        hot = (f"- Departure, stated: {info['hot']}; the fluid ran at {min(r['kT'] for r in rows):.3f}–"
               f"{max(r['kT'] for r in rows):.3f} of its kT over the averaging window, so U is low by about that "
               f"fraction; (kT − 1)(1 − box)/φ, the K that would make, is {dk(rows, box, 0.1):.2f} at φ = 0.1 and "
               f"{dk(rows, box, 0.05):.2f} at φ = 0.05: not corrected, well short of the gap to 6.55.")
    else:
        hot = (f"- The fluid ran at {min(r['kT'] for r in rows):.3f}–{max(r['kT'] for r in rows):.3f} of its kT "
               "over the averaging window (thermostat).")
    return [
        BEGIN.format(name), "",
        f"## Collective hydrodynamics: hindered settling of {info['coupling']} (Batchelor, Richardson–Zaki)", "",
        f"Measured by `peloid sweep studies/{name}.cfg --jobs 1` (runs of "
        f"{', '.join(sorted({r['rev'] for r in rows}))}: the revisions the points' summary.json name; "
        f"{cpu:.0f} CPU-s on the 2-core machine) and `python3 tools/hindered_settling.py "
        f"out/studies/{name} validation/REPORT.md` (section written at {commit}).  Rules: "
        f"validation/RULES_hindered_settling.md {info['rule']}, committed with the study before its runs.  "
        f"{info['model']} ({radius}), periodic {r0['L']:.0f}³ cells, Pe = 3, 20000 steps a point averaged from "
        f"step 2000.  U0 = the mapped Stokes velocity {1e6 * r0['U0']:.4f} µm/s (calibration error "
        f"{100 * r0['cal']:.1f} %); Hasimoto's box term 2.837 R_h/L = {box:.4f}.", ""] + tab + [
        "",
        f"- **Batchelor's K: {vk}.**  K = {K:.2f} ± {K_se:.2f} (statistical {K_stat:.2f}, calibration "
        f"{K_cal:.2f}; {nk} points, χ² = {k_chi2:.1f}) against 6.55 ({(K - K_BATCHELOR) / K_se:+.1f} SE, "
        f"{100 * (K / K_BATCHELOR - 1):+.0f} %); for information Rotne–Prager with excluded Stokeslets at "
        f"a_h/a = {rh:.3f}: {k_rp(rh):.2f} (5.5 at a_h = a).{core}  The points' own K (the table's "
        f"second-last column): {pk(rows, box, 0.02)} at φ = 0.02, {pk(rows, box, 0.05)} at φ = 0.05, "
        f"{pk(rows, box, 0.1)} at φ = 0.1 (the rule's line through the origin is as good as its χ²).",
        f"- **Richardson–Zaki's n: {vn}.**  n = {n:.2f} ± {n_se:.2f} over φ = {info['phi_n']} ({nn} points, "
        f"χ²/dof = {n_chi2:.1f}, v∞/U0 = {vinf / r0['U0']:.3f}) against 4.65 "
        f"({(n - N_RZ) / n_se:+.1f} SE, {100 * (n / N_RZ - 1):+.0f} %).",
        f"- **Stationary, and read again from colloids.h5:** the h5py reading agrees with the observer within 3 SE "
        f"at {len(rows) - len(h5_bad)} of {len(rows)} points; the two halves of the window agree within 3 SE at "
        f"{len(rows) - len(stat_bad)} of {len(rows)}.", hot,
        "",
        f"The physical reason where it disagrees: the colloid of {info['coupling']} moves fluid like a stick sphere "
        f"of R_h = {rh:.2f} R ({info['reason']}), so every many-body hydrodynamic effect has that sphere's "
        "strength; Batchelor's and Richardson–Zaki's values are for R_h = R.  Coupling II, for comparison: "
        f"K = 2.18 ± 0.05, n = 2.25 ± 0.11 (the Fig. 4 verdict).  Not run: {info['missing']}.", "",
        f"![{png_name[:-4]}]({png_name})", "", END.format(name)]


def main():
    study_section_main(section, BEGIN, END, sys.argv)


if __name__ == "__main__":
    main()
