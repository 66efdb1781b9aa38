"""Hindered settling of coupling I at its matched resolution (validation/RULES_hindered_settling.md H5, fixed before
the runs): the section "Collective hydrodynamics at the matched resolution" of validation/REPORT.md, written between
its markers, and its plot.

Per point (model units): the sedimentation observer's slip velocity u (summary.json, a0/t0, positive down) and, read
independently with h5py from colloids.h5, the colloids' mean fall turned into u by the zero total momentum (H3,
tools/h5md_settling.py); U = u (1 - phi); U0 = F / (6 pi eta R_h) with rule R8's measured R_h (the law file's
"check", calibration/rh_resolution-c1_hecht.json); y = 1 - R_h (2.837/L + 6 pi eta U/F) fitted as K phi.

    python3 tools/hindered_matched.py OUT/STUDY REPORT.md [COMMIT]     (prints the section; exit 0)"""
import glob
import json
import math
import os
import sys

import numpy as np

from hindered_settling import HASIMOTO, K_BATCHELOR, h5_slip, k_rp
from rh_resolution import law_path
from validation.report_section import sections_in, study_section_main

BEGIN = "<!-- hindered matched: {} (tools/hindered_matched.py) -->"  # .format(study name)
END = "<!-- end of the hindered matched section: {} -->"
STUDIES = ("hindered_settling_c1_matched",)
# how the study's points were run, where summary.json cannot say it (a resumed point names only the binary that
# finished it)
RESUMED = ("both points were stopped once by a signal at a checkpoint and resumed by `peloid sweep` with the "
           "binary of f434858's source (the string 5f2ba63-dirty: built before that commit), whose coupling I event "
           "order gives the same bits as the first part's binary (e0d8eab-dirty, the source of 162a85d; "
           "bench/RESULTS.md)")
LAW = "rh_resolution_c1_hecht"  # the resolution study whose R8 run measured R_h at this resolution


def sections(text):
    """The matched hindered-settling sections in a report's text, each from its begin to its end marker."""
    return sections_in(text, STUDIES, BEGIN, END)


def r8_radius():
    """R_h/R and its SE from rule R8's run (the law file's check), and the study that ran it."""
    doc = json.load(open(law_path(LAW)))
    p = doc["check"]["points"][0]
    return p["rh_over_R"], p["rh_over_R_se"], doc["check"]["study"]


def points(study):
    rows = []
    for sp in sorted(glob.glob(os.path.join(study, "p*", "summary.json"))):
        run = os.path.dirname(sp)
        s = json.load(open(sp))
        if s.get("interrupted") or "settling_velocity" not in s.get("observables", {}):
            continue
        sv = s["observables"]["settling_velocity"]
        c = s["scene"]["colloids"]
        R, L, N = c["radius"], s["scene"]["box"]["cells"][0], c["count"]
        vol = 4.0 / 3.0 * math.pi * R ** 3
        M = c["mass_density"] * vol
        u5, u5se, h1, h2, hse = h5_slip(run, sv["average_from_time"])
        th = np.genfromtxt(os.path.join(run, "thermo.tsv"), names=True, delimiter="\t")
        rows.append(dict(
            phi=N * vol / L ** 3, n=N, R=R, L=L, eta=s["derived"]["eta"], nu=s["derived"]["nu"],
            kT=float(th["temperature"][th["step"] >= sv["average_from_step"]].mean()),
            F=-M * c["gravity"][2], u=sv["value"], u_se=sv["stderr"], start=sv["average_from_step"],
            first=s.get("first_step", 0),
            steps=s["last_step"], u5=u5, u5_se=u5se, h1=h1, h2=h2, hse=hse, cpu=s.get("cpu_seconds", 0.0),
            rev=s["peloid"]["git_revision"]))
    rows.sort(key=lambda r: r["phi"])
    return rows


def y_of(r, rh):
    """H5: y = 1 - R_h (2.837/L + 6 pi eta U/F) at R_h/R = rh, U = u (1 - phi); and its SE from u's."""
    Rh = rh * r["R"]
    a = 6.0 * math.pi * r["eta"] * (1.0 - r["phi"]) / r["F"]
    return 1.0 - Rh * (HASIMOTO / r["L"] + a * r["u"]), Rh * a * r["u_se"]


def fit_k(rows, rh, rh_se):
    """H5: K through the origin, weights 1/SE(y)^2; SE(K) from the points and R8's R_h (shifted whole)."""
    phi = np.array([r["phi"] for r in rows])

    def k_at(x):
        y, sy = np.array([y_of(r, x) for r in rows]).T
        w = 1.0 / sy ** 2
        K = float((w * y * phi).sum() / (w * phi * phi).sum())
        return K, float(1.0 / math.sqrt((w * phi * phi).sum())), float((w * (y - K * phi) ** 2).sum())

    K, se_stat, chi2 = k_at(rh)
    se_rh = abs(k_at(rh + rh_se)[0] - k_at(rh - rh_se)[0]) / 2.0
    return K, math.hypot(se_stat, se_rh), se_stat, se_rh, chi2


def plot(rows, K, rh, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    phi = np.array([r["phi"] for r in rows])
    y, sy = np.array([y_of(r, rh) for r in rows]).T
    y5 = np.array([y_of(dict(r, u=r["u5"], u_se=r["u5_se"]), rh)[0] for r in rows])
    xx = np.linspace(0.0, 0.11, 100)
    ax.fill_between(xx, 0.85 * K_BATCHELOR * xx, 1.15 * K_BATCHELOR * xx, color="0.88", label="within 15 %")
    ax.plot(xx, K_BATCHELOR * xx, "k--", lw=1, label=f"Batchelor: K = {K_BATCHELOR}")
    ax.plot(xx, K * xx, "C0-", lw=1, label=f"fit through the origin: K = {K:.2f}")
    ax.plot(xx, 3.20 * xx, "C1:", lw=1.2, label="coupling I at a0 = R/2 (H1): K = 3.20")
    ax.plot(xx, 1.0 - (1.0 - xx) ** 4.65, "C2-.", lw=1, label="Richardson–Zaki, 1 − (1 − φ)^4.65 (for information)")
    ax.errorbar(phi, y, yerr=sy, fmt="o", color="C0", capsize=3, label="peloid, coupling I at R = 10 a0 (observer)")
    ax.plot(phi, y5, "x", color="C3", label="the same runs, colloids.h5 (h5py)")
    ax.set_xlim(0.0, 0.11)
    ax.set_ylim(0.0, 0.9)
    ax.set_xlabel("volume fraction φ")
    ax.set_ylabel("y = 1 − 2.837 R_h/L − U/U0  (zero-volume-flux frame)")
    ax.set_title("Hindered settling at the matched resolution: 8 colloids of R = 10 a0,\n"
                 "Hecht's fluid, periodic 88³ and 70³ cells (U0 and the box term with R8's R_h)", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper left")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def section(study, commit, png):
    rows = points(study)
    name = os.path.basename(os.path.normpath(study))
    if len(rows) < 2:
        raise SystemExit(f"hindered_matched: {len(rows)} finished point(s) in {study}; rule H5 needs both")
    rh, rh_se, r8 = r8_radius()
    K, K_se, K_stat, K_rh, chi2 = fit_k(rows, rh, rh_se)
    stat_bad = [r for r in rows if abs(r["h1"] - r["h2"]) > 3 * math.sqrt(2) * r["hse"]]
    h5_bad = [r for r in rows if abs(r["u5"] - r["u"]) > 3 * math.hypot(r["u5_se"], r["u_se"])]
    v = "agrees" if abs(K - K_BATCHELOR) <= 0.15 * K_BATCHELOR + 2 * K_se else "disagrees — peloid"
    if stat_bad or h5_bad:
        v = f"not settled ({v})"
    plot(rows, K, rh, png)
    tab = ["| φ | colloids | L (a0) | u (a0/t0), observer | u, colloids.h5 | halves | U/U0 | box term | "
           "y/φ | Pe | Re at U0 | fluid kT | CPU-s (from step) |", "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    # for information, added once the runs were in (deciding nothing): the box-corrected U/U0 against Batchelor's
    # line and Richardson-Zaki's curve at each phi
    info = ["| φ | U/U0 + box term | Batchelor 1 − 6.55 φ | Richardson–Zaki (1 − φ)^4.65 |", "|---|---|---|---|"]
    for r in rows:
        U0 = r["F"] / (6.0 * math.pi * r["eta"] * rh * r["R"])
        y, sy = y_of(r, rh)
        D = r["kT"] / (6.0 * math.pi * r["eta"] * rh * r["R"])
        tab.append(f"| {r['phi']:.4f} | {r['n']} | {r['L']:g} | {r['u']:.5f} ± {r['u_se']:.5f} | "
                   f"{r['u5']:.5f} ± {r['u5_se']:.5f} | {r['h1']:.5f}, {r['h2']:.5f} | "
                   f"{r['u'] * (1 - r['phi']) / U0:.3f} ± {r['u_se'] * (1 - r['phi']) / U0:.3f} | "
                   f"{HASIMOTO * rh * r['R'] / r['L']:.3f} | {y / r['phi']:.2f} ± {sy / r['phi']:.2f} | "
                   f"{U0 * r['R'] / D:.0f} | {U0 * r['R'] / r['nu']:.2f} | {r['kT']:.3f} | {r['cpu']:.0f} ({r['first']}) |")
        info.append(f"| {r['phi']:.4f} | {1.0 - y:.3f} ± {sy:.3f} | {1.0 - K_BATCHELOR * r['phi']:.3f} | "
                    f"{(1.0 - r['phi']) ** 4.65:.3f} |")
    cpu = sum(r["cpu"] for r in rows)
    lo, hi = rows[0], rows[-1]
    U0_lo = lo["F"] / (6.0 * math.pi * lo["eta"] * rh * lo["R"])
    need = (1.0 - K_BATCHELOR * lo["phi"]) - lo["u"] * (1.0 - lo["phi"]) / U0_lo  # the box term Batchelor would need
    over = all(1.0 - y_of(r, rh)[0] - 2 * y_of(r, rh)[1] > max((1 - r["phi"]) ** 4.65, 1 - K_BATCHELOR * r["phi"])
               for r in rows)
    above = ("  The box-corrected U/U0 lies more than 2 SE above both references at every point: with Hasimoto's "
             "term, the model suspension is hindered less than a real one." if over else "")
    return [
        BEGIN.format(name), "",
        "## Collective hydrodynamics at the matched resolution: hindered settling of coupling I", "",
        f"Measured by `peloid sweep studies/{name}.cfg --jobs 2 --threads 1` (runs of "
        f"{', '.join(sorted({r['rev'] for r in rows}))}: the revisions the points' summary.json name; {cpu:.0f} "
        f"CPU-s) and `python3 tools/hindered_matched.py out/studies/{name} validation/REPORT.md` (section written at "
        f"{commit}).  Rule H5 of validation/RULES_hindered_settling.md, committed with the study before its runs: "
        f"8 colloids of R = 10 a0 (rule R8's colloid, fluid and force: Hecht's fluid at a0 = R/10, stick_stochastic "
        f"surfaces, hard spheres by Hertz + lubrication) at a random start in periodic cubes, averaged from the "
        f"observer's detected start.  U0 = F/(6πη R_h) and the box term 2.837 R_h/L with R_h/R = {rh:.3f} ± "
        f"{rh_se:.3f}, measured by R8 ({r8}, the section above).  CPU-s: of the process that ran the point from the "
        f"step given" + (f"; {RESUMED}." if any(r["first"] > 0 for r in rows) else "."), ""] + tab + [
        "",
        f"- **Batchelor's K at the matched resolution: {v}.**  K = {K:.2f} ± {K_se:.2f} (the points "
        f"{K_stat:.2f}, R8's R_h {K_rh:.2f}; {len(rows)} points, χ² = {chi2:.1f}) against 6.55 "
        f"({(K - K_BATCHELOR) / K_se:+.1f} SE, {100 * (K / K_BATCHELOR - 1):+.0f} %); at a0 = R/2 the same coupling "
        f"gave 3.20 ± 0.11 (H1, R_h/R = 0.786).  For information, Rotne–Prager with excluded Stokeslets at "
        f"a_h/a = {rh:.3f}: {k_rp(rh):.2f}.",
        f"- **Stationary, and read again from colloids.h5:** the h5py reading agrees with the observer within 3 SE "
        f"at {len(rows) - len(h5_bad)} of {len(rows)} points; the two halves of the window agree within 3 SE at "
        f"{len(rows) - len(stat_bad)} of {len(rows)}.",
        "- For information (added after the runs, deciding nothing): each point's box-corrected U/U0 beside "
        f"Batchelor's dilute line and Richardson–Zaki's curve.  At φ = {hi['phi']:.3f} the two references differ "
        f"by {(1 - hi['phi']) ** 4.65 - (1 - K_BATCHELOR * hi['phi']):.2f} U0 (the dilute line is not the suspension "
        "there), so H1's and H5's line through the origin over φ ≤ 0.1 reads K low even for exact hydrodynamics.  "
        f"With N = 8 the subtracted box term is as large as the hindrance: the dilute point (φ = {lo['phi']:.3f}) "
        f"meets Batchelor's line only if the finite-N term were {need:.3f} instead of Hasimoto's "
        f"{HASIMOTO * rh * lo['R'] / lo['L']:.3f}.{above}", ""] + info + ["",
        "- Stated by H5, not corrected: the box term's higher orders ((R/L)³ terms, below 0.01 of y), Re ~ 0.3, "
        "and N = 8 colloids a box (its finite-N term is the box term).  Not run at this resolution: "
        "Richardson–Zaki's n (φ to 0.3 at 4189 cells a colloid) and D(φ).", "",
        f"![{os.path.basename(png)[:-4]}]({os.path.basename(png)})", "", END.format(name)]


def main():
    study_section_main(section, BEGIN, END, sys.argv)


if __name__ == "__main__":
    main()
