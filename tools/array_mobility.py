"""Hasimoto's box correction at coupling I's matched resolution (validation/RULES_hindered_settling.md H11, fixed
before the runs): the section "Collective hydrodynamics at the matched resolution: the periodic array's mobility"
of validation/REPORT.md and its plot.

    python3 tools/array_mobility.py OUT/array_mobility_c1_matched REPORT.md [COMMIT]   (prints the section)

One colloid in a periodic cube is a simple cubic array of itself.  Each box (the study's three and rule R8's 80^3
run, read from the study's sibling folder rh_resolution_c1_hecht_matched) gives R_h through Sangani & Acrivos's
series for the array's drag, with the superficial velocity (1 - phi) u; the rule asks whether the boxes agree on
one R_h and whether R8's box predicts the others' velocities.  The h5py reading and the window's halves (R1, R2)
are tools/rh_resolution.py's."""
import math
import os
import sys

import numpy as np
from scipy import optimize, stats

from rh_resolution import array_inverse_drag, run_row, settled, settling_runs
from validation.common import pyplot, save_figure
from validation.report_section import sections_in, study_section_main

BEGIN = "<!-- array mobility: {} (tools/array_mobility.py) -->"  # .format(study name)
END = "<!-- end of the array mobility section: {} -->"
STUDIES = ("array_mobility_c1_matched",)
R8_STUDY = "rh_resolution_c1_hecht_matched"
AGREE = 0.05  # each box against R8's prediction: |u/u_pred - 1| <= 0.05 + 2 SE
P_MIN = 0.01  # the boxes' R_h/R one value: chi2 p > 0.01
# How the study's runs were made (stated, not read from the runs): the binary's string names 58b784d-dirty
PROVENANCE = ("The three runs' binary was built from 58b784d's source with three kernel edits then under trial and "
              "reverted before any commit (a division skipped inside the box in pl_colloid_wrap, the guard's "
              "finiteness test as a tree, fmax/fmin written as compares); a clean build of 58b784d writes a "
              "byte-identical checkpoint after 400 steps of the 40³ point at 2 threads.")
# H10's U/U0 at phi = 0.0492, R = 10 a0 (REPORT.md; N = 8 pooled over two seeds), stated by H11 and H12
H10 = {8: (0.530, 0.008), 27: (0.541, 0.004)}  # colloids: (U/U0, SE)
HASIMOTO = 2.837  # the leading box term, Hasimoto 1959: 1.7601 (4 pi / 3)^(1/3)


def sections(text):
    """The array-mobility sections in a report's text, each from its begin to its end marker."""
    return sections_in(text, STUDIES, BEGIN, END)


def chi_of(radius, L):
    return (4.0 * math.pi / 3.0) ** (1.0 / 3.0) * radius / L


def hydrodynamic_radius(xi_box, eta, L):
    """R_h of a sphere whose array drag is xi_box: the root of 6 pi eta R_h K(chi(R_h, L)) = xi_box, by bisection
    (brentq) between chi = 0 and 0.65 (the array drag rises monotonically there).  R8's fixed-point iteration
    (tools/rh_resolution.py, unbounded) does not converge here: its map's slope is about -1.76 chi / K^-1, past
    -1 in boxes below ~6 R."""
    def excess(rh):
        return 6.0 * math.pi * eta * rh / array_inverse_drag(chi_of(rh, L)) - xi_box
    top = 0.65 * L / (4.0 * math.pi / 3.0) ** (1.0 / 3.0)
    return optimize.brentq(excess, 1e-9 * top, top, xtol=1e-14 * top, rtol=1e-14)


def boxes(study):
    """Every finished box of the study and R8's run: R, L, phi, u and its SE, R_h/R and its SE (H11's data), the
    h5py reading and halves (R1, R2), cost."""
    rows = []
    r8 = os.path.join(os.path.dirname(os.path.normpath(study)), R8_STUDY)
    for folder, origin in ((study, "H11"), (r8, "R8")):
        for run, s, sv in settling_runs(folder):
            if s["scene"]["colloids"]["count"] != 1:
                continue
            r = run_row(run, s, sv)
            R, L, eta, F, u, u_se = r["R"], r["L"], r["eta"], r["F"], r["u"], r["u_se"]
            phi = 4.0 / 3.0 * math.pi * R ** 3 / L ** 3
            rh = lambda v: hydrodynamic_radius(F / ((1.0 - phi) * v), eta, L) / R  # noqa: E731
            r.update(origin=origin, phi=phi, xi_box=F / ((1.0 - phi) * u), rh=rh(u),
                     rh_se=abs(rh(u + u_se) - rh(u - u_se)) / 2.0)
            rows.append(r)
    rows.sort(key=lambda r: r["L"])
    return rows


def velocity(radius_h, r):
    """The slip velocity a sphere of hydrodynamic radius radius_h has in box r under r's force."""
    return r["F"] / (6.0 * math.pi * r["eta"] * radius_h * (1.0 - r["phi"])) * array_inverse_drag(chi_of(radius_h, r["L"]))


def predicted(r80, r):
    """H11: box r's u as R8's box predicts it, with the prediction's SE from R8's R_h SE."""
    rh, se = r80["rh"] * r80["R"], r80["rh_se"] * r80["R"]
    up = velocity(rh, r)
    return up, abs(velocity(rh + se, r) - velocity(rh - se, r)) / 2.0


def consistency(rows):
    """The boxes' weighted mean R_h/R, its SE, chi2 and p (len - 1 dof)."""
    y, s = np.array([r["rh"] for r in rows]), np.array([r["rh_se"] for r in rows])
    w = 1.0 / s ** 2
    m = float((w * y).sum() / w.sum())
    chi2 = float((w * (y - m) ** 2).sum())
    dof = len(rows) - 1
    return m, float(1.0 / math.sqrt(w.sum())), chi2, dof, float(stats.chi2.sf(chi2, dof)) if dof > 0 else 1.0


def plot(rows, mean, path):
    plt = pyplot()
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11.0, 4.4))
    for r in rows:
        col = "C3" if r["origin"] == "R8" else "C0"
        a1.errorbar([r["R"] / r["L"]], [r["rh"]], yerr=[r["rh_se"]], fmt="s" if r["origin"] == "R8" else "o",
                    capsize=3, color=col)
    m, m_se = mean[0], mean[1]
    a1.axhspan(m - m_se, m + m_se, color="C0", alpha=0.2, label=f"weighted mean {m:.3f} ± {m_se:.3f}")
    a1.errorbar([], [], fmt="o", color="C0", label="H11's boxes (40³, 44³, 56³)")
    a1.errorbar([], [], fmt="s", color="C3", label="R8's box (80³)")
    a1.set_xlabel("R / L")
    a1.set_ylabel("R_h / R through the array's drag (Sangani & Acrivos)")
    a1.set_xlim(0.0, 0.3)
    a1.legend(fontsize=8, loc="lower left")
    a1.set_title("one colloid a box: R_h from each box", fontsize=9)
    R = rows[0]["R"]
    ff = np.linspace(0.0, 0.08, 200)
    rh = m * R
    chi = (ff * (rh / R) ** 3) ** (1.0 / 3.0)
    a2.plot(ff, [array_inverse_drag(c) for c in chi], "C0-", lw=1,
            label="simple cubic array, Sangani & Acrivos, at the mean R_h")
    a2.plot(ff, 1.0 - HASIMOTO * (ff * (rh / R) ** 3 * 3.0 / (4.0 * math.pi)) ** (1.0 / 3.0), "C7--", lw=1,
            label="Hasimoto's leading term alone")
    for r in rows:
        U0 = r["F"] / (6.0 * math.pi * r["eta"] * rh)
        a2.errorbar([r["phi"]], [(1.0 - r["phi"]) * r["u"] / U0], yerr=[(1.0 - r["phi"]) * r["u_se"] / U0],
                    fmt="s" if r["origin"] == "R8" else "o", capsize=3, color="C3" if r["origin"] == "R8" else "C0")
    phi44 = 4.0 / 3.0 * math.pi / 44.0 ** 3 * 1000.0
    for k, (n, (v, se)) in enumerate(H10.items()):
        a2.errorbar([phi44 + 0.0015 * (k + 1)], [v], yerr=[se], fmt="^", capsize=3, color=f"C{k + 1}",
                    label=f"H10's random suspension, N = {n} (its own box)")
    a2.set_xlabel("φ")
    a2.set_ylabel("U / U0 = (1 − φ) u / (F / 6πη R_h)")
    a2.set_xlim(0.0, 0.08)
    a2.set_ylim(0.0, 1.05)
    a2.set_title("the box's velocity against φ (U0 with the mean R_h)", fontsize=9)
    for a in (a1, a2):
        a.grid(alpha=0.3)
    a2.legend(fontsize=7.5, loc="upper right")
    fig.suptitle("Coupling I at the matched resolution (R = 10 a0, Hecht's fluid): one colloid in a periodic cube, "
                 "a simple cubic array (rule H11)", fontsize=10)
    save_figure(plt, fig, path)


def section(study, commit, png):
    rows = boxes(study)
    name = os.path.basename(os.path.normpath(study))
    if not rows:
        raise SystemExit(f"array_mobility: no finished box in {study}")
    r80 = next((r for r in rows if r["origin"] == "R8"), None)
    new = [r for r in rows if r["origin"] == "H11"]
    mean = consistency(rows)
    plot(rows, mean, png)
    tab = ["| box | L (a0) | φ | Re | u (a0/t0), observer | u, colloids.h5 | halves | fluid kT | ξ_box | R_h/R | "
           "u / u_pred (R8's box) | CPU-s |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    verdicts = []
    for r in rows:
        pred = "—"
        if r80 is not None and r is not r80:
            up, up_se = predicted(r80, r)
            q, q_se = r["u"] / up, math.hypot(r["u_se"] / up, r["u"] * up_se / up ** 2)
            ok = abs(q - 1.0) <= AGREE + 2 * q_se
            pred = f"{q:.3f} ± {q_se:.3f}"
            verdicts.append((r, q, q_se, ok))
        tab.append(f"| {r['origin']} | {r['L']:g} | {r['phi']:.4f} | {r['Re']:.2f} | {r['u']:.5f} ± {r['u_se']:.5f} | "
                   f"{r['u5']:.5f} ± {r['u5_se']:.5f} | {r['h1']:.5f}, {r['h2']:.5f} | {r['kT']:.3f} | "
                   f"{r['xi_box']:.1f} | **{r['rh']:.3f} ± {r['rh_se']:.3f}** | {pred} | {r['cpu']:.0f} |")
    bad = [r for r in rows if not settled(r)]
    m, m_se, chi2, dof, p = mean
    one = "not settled" if bad else ("agrees" if p > P_MIN else "disagrees — peloid")
    lines = [f"- **Hasimoto's box correction at this resolution (H11): {one}.**  The {len(rows)} boxes' R_h/R: "
             f"weighted mean {m:.3f} ± {m_se:.3f}, χ² = {chi2:.2f} for {dof} dof (p = {p:.2f}; the rule asks p > "
             f"{P_MIN})."]
    for r, q, q_se, ok in verdicts:
        v = "not settled" if (not settled(r) or not settled(r80)) else ("agrees" if ok else "disagrees — peloid")
        lines.append(f"- **The {r['L']:g}³ box against R8's (H11): {v}.**  u = {r['u']:.5f} ± {r['u_se']:.5f} a0/t0 "
                     f"is {q:.3f} ± {q_se:.3f} of what R8's box predicts ({(q - 1) * 100:+.1f} %; the bound "
                     f"{AGREE * 100:.0f} % + 2 SE).")
    lo, hi = rows[0], rows[-1]
    slope = float("nan") if lo is hi else (1.0 / lo["xi_box"] - 1.0 / hi["xi_box"]) / (1.0 / lo["L"] - 1.0 / hi["L"])
    slope_se = 0.0 if lo is hi else math.hypot(lo["u_se"] / lo["u"] / lo["xi_box"], hi["u_se"] / hi["u"] / hi["xi_box"]) / (
        1.0 / lo["L"] - 1.0 / hi["L"])
    theory = -HASIMOTO / (6.0 * math.pi * lo["eta"])
    rh_m = m * lo["R"]
    chord = float("nan") if lo is hi else (
        (array_inverse_drag(chi_of(rh_m, lo["L"])) - array_inverse_drag(chi_of(rh_m, hi["L"]))) /
        (6.0 * math.pi * lo["eta"] * rh_m * (1.0 / lo["L"] - 1.0 / hi["L"])))
    lines.append(f"- Beside it, deciding nothing: the slope of 1/ξ_box against 1/L between the {lo['L']:g}³ and "
                 f"{hi['L']:g}³ boxes, {slope:.5f} ± {slope_se:.5f} a0·t0/m_f, against Hasimoto's "
                 f"leading −2.837/(6πη) = {theory:.5f} ({slope / theory:.3f} of it) and the whole series' chord "
                 f"between the same boxes at the mean R_h, {chord:.5f}.")
    lowest, highest = min(rows, key=lambda r: r["rh"]), max(rows, key=lambda r: r["rh"])
    lines.append(f"- Beside it, deciding nothing (written after the runs): R_h/R runs from {lowest['rh']:.3f} ± {lowest['rh_se']:.3f} "
                 f"({lowest['L']:g}³) to {highest['rh']:.3f} ± {highest['rh_se']:.3f} ({highest['L']:g}³); "
                 f"χ²'s p = {p:.2f} does not reject one value, and a trend with L, if real, would be a box term "
                 f"{'weaker' if lowest['L'] < highest['L'] else 'stronger'} than Hasimoto's at R_h in the smaller "
                 "boxes.")
    oseen = [(r["L"], r["L"] * r["u"] / r["nu"]) for r in rows]
    far = max(oseen, key=lambda o: o[1])
    lines.append("- Beside it, deciding nothing (written after the runs): each box in units of the Oseen length ν/u "
                 "of its slip velocity, " + ", ".join(f"{L:g}³: {x:.2f}" for L, x in oseen) + ".  H10's aside "
                 "(its boxes 2.0–3.0 ν/u long; a plausible inertial cut-off of the box term) finds no support in one "
                 f"colloid's box term up to {far[1]:.1f} ν/u ({far[0]:g}³): a cut-off would make the longest boxes read "
                 "the lowest R_h, and the boxes agree on one R_h" +
                 (f" with the {highest['L']:g}³ box reading the highest." if highest["L"] == far[0] else "."))
    b44 = next((r for r in new if r["L"] == 44), None)
    if b44 is not None:
        U0 = b44["F"] / (6.0 * math.pi * b44["eta"] * m * b44["R"])
        x, x_se = (1.0 - b44["phi"]) * b44["u"] / U0, (1.0 - b44["phi"]) * b44["u_se"] / U0
        lines.append(f"- Beside it, deciding nothing: at φ = {b44['phi']:.4f}, one colloid a box (an array) settles "
                     f"at U/U0 = {x:.3f} ± {x_se:.3f} (U0 with the mean R_h); H10's random suspensions at the same φ, "
                     + ", ".join(f"N = {n}: {v:.3f} ± {se:.3f}" for n, (v, se) in H10.items()) + ".")
    revs = ", ".join(sorted({r["rev"] for r in new}))
    return [
        BEGIN.format(name), "",
        "## Collective hydrodynamics at the matched resolution: the periodic array's mobility (Hasimoto)", "",
        f"Measured by `peloid sweep studies/{name}.cfg --jobs 2 --threads 1` (runs of {revs}, one core each of the "
        f"2-core machine; {sum(r['cpu'] for r in new):.0f} CPU-s) and `python3 tools/array_mobility.py "
        f"out/studies/{name} validation/REPORT.md` (section written at {commit}).  Rule H11 of "
        "validation/RULES_hindered_settling.md, committed with the study before its runs: one colloid of rule R8's "
        "(coupling I, R = 10 a0, Hecht's fluid, R8's force and seed) in periodic cubes of 40³, 44³ and 56³ cells "
        "(its images are a simple cubic array), and R8's own 80³ run read the same way.  Data: U = (1 − φ) u, the "
        "superficial velocity through the array; ξ_box = F/U; R_h from Sangani & Acrivos's series for the simple "
        "cubic array's drag, K⁻¹ = 1 − 1.7601χ + χ³ − 1.5593χ⁶ + 3.9799χ⁸ − 3.0734χ¹⁰, χ = (4π/3)^{1/3} R_h/L "
        "(Zick & Homsy's table within 0.1 %).  R8's box read this way differs from R8's own figure (0.969) by its "
        "frame (u there, (1 − φ) u here) and the series' two last terms; R8's verdict is R8's.  R_h is the root of "
        "the array's drag equation, found by bisection (R8's fixed-point iteration does not converge in boxes "
        "below ~6 R).  " + PROVENANCE, ""] + tab + [
        ""] + lines + [
        f"- **Read again from colloids.h5, stationary (R1, R2):** {len(rows) - len(bad)} of {len(rows)} boxes agree "
        "with the observer within 3 SE and have window halves within 3 SE.",
        "- What H11 does not test: the many-colloid suspension's finite-size term and Batchelor's K (H10); it tests "
        "the box term of one sphere and its images at this resolution and Reynolds number.", "",
        f"![{os.path.basename(png)[:-4]}]({os.path.basename(png)})", "", END.format(name)]


def main():
    study_section_main(section, BEGIN, END, sys.argv)


if __name__ == "__main__":
    main()
