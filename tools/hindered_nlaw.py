"""The finite-size law of hindered settling at phi = 0.049 with three box sizes (validation/RULES_hindered_settling.md
H12, fixed before the runs): the section "Collective hydrodynamics: the finite-size law with three boxes" of
validation/REPORT.md and its plot.

    python3 tools/hindered_nlaw.py OUT/hindered_settling_c1_r5_nlaw REPORT.md [COMMIT]   (prints the section)

Each run is read as tools/hindered_matched.py reads its points (the observer's slip velocity, H3's halves and h5py
reading); U0 = F/(6 pi eta R_h) with R_h from the resolution law of rh_resolution_c1_hecht at the runs' R."""
import json
import math
import os
import sys

import numpy as np
from scipy import stats

from array_mobility import H10
from hindered_matched import points
from hindered_settling import HASIMOTO, K_BATCHELOR
from rh_matched import predicted
from rh_resolution import law_path, settled
from validation.common import pyplot, save_figure
from validation.report_section import sections_in, study_section_main

BEGIN = "<!-- hindered nlaw: {} (tools/hindered_nlaw.py) -->"  # .format(study name)
END = "<!-- end of the hindered nlaw section: {} -->"
STUDIES = ("hindered_settling_c1_r5_nlaw",)
LAW = "rh_resolution_c1_hecht"
P_MIN = 0.01  # the law holds: chi2 (1 dof) p > 0.01
# H10 at R = 10 a0 (REPORT.md, stated by H12): c = 0.067 +- 0.052 against the dilute term's 0.625
H10_RATIO = (0.067 / 0.625, 0.052 / 0.625)


def sections(text):
    """The finite-size-law sections in a report's text, each from its begin to its end marker."""
    return sections_in(text, STUDIES, BEGIN, END)


def line_fit(x, y, s):
    """Weighted least squares y = a - c x: (a, c), their covariance, chi2, dof, p."""
    A = np.vstack([np.ones_like(x), -x]).T
    W = np.diag(1.0 / s ** 2)
    cov = np.linalg.inv(A.T @ W @ A)
    p = cov @ A.T @ W @ y
    chi2 = float(((y - A @ p) ** 2 / s ** 2).sum())
    dof = len(x) - 2
    return p, cov, chi2, dof, float(stats.chi2.sf(chi2, dof)) if dof > 0 else 1.0


def plot(rows, fit, cd, cd_eta, path):
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.8, 4.6))
    x = np.array([r["x"] for r in rows])
    ax.errorbar(x, [r["U"] for r in rows], yerr=[r["U_se"] for r in rows], fmt="o", capsize=3, color="C0",
                label="R = 5 a0 (H12): 8, 27, 64 colloids")
    (a, c), _, chi2, dof, p = fit
    xx = np.linspace(0.0, 0.55, 50)
    ax.plot(xx, a - c * xx, "C0-", lw=1, label=f"fit U∞ − c N^(−1/3): c = {c:.3f}, χ² = {chi2:.2f} ({dof} dof)")
    ax.plot(xx, a - cd * xx, "C7--", lw=1, label=f"through U∞ with the dilute box term, c_d = {cd:.3f}")
    ax.plot(xx, a - cd_eta * xx, "C7:", lw=1, label=f"… viscosity-scaled, c_d η0/η = {cd_eta:.3f}")
    ax.errorbar([n ** (-1.0 / 3.0) for n in H10], [v for v, _ in H10.values()],
                yerr=[se for _, se in H10.values()], fmt="^", capsize=3, color="C3",
                label="R = 10 a0 (H10, the matched resolution): 8, 27 colloids")
    ax.set_xlim(0.0, 0.55)
    ax.set_xlabel("N^(−1/3)  (the box of N colloids at φ = 0.049)")
    ax.set_ylabel("U / U0  (volume frame)")
    ax.set_title("Coupling I, Hecht's fluid, φ = 0.049: the settling velocity against the box (rule H12)",
                 fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7.5, loc="lower left")
    save_figure(plt, fig, path)


def section(study, commit, png):
    rows = points(study)
    name = os.path.basename(os.path.normpath(study))
    if len(rows) < 2:
        raise SystemExit(f"hindered_nlaw: fewer than two finished runs in {study}")
    law = json.load(open(law_path(LAW)))["law"]
    R = rows[0]["R"]
    y, y_se = predicted(law, R)
    rh = y * R
    for r in rows:
        U0 = r["F"] / (6.0 * math.pi * r["eta"] * rh)
        r["U"], r["U_se"] = (1.0 - r["phi"]) * r["u"] / U0, (1.0 - r["phi"]) * r["u_se"] / U0
        r["x"] = r["n"] ** (-1.0 / 3.0)
        r["L1"] = r["L"] * r["x"]
    rows.sort(key=lambda r: r["n"])
    x, U, s = (np.array([r[k] for r in rows]) for k in ("x", "U", "U_se"))
    fit = line_fit(x, U, s)
    (a, c), cov, chi2, dof, p = fit
    a_se, c_se = math.sqrt(cov[0, 0]), math.sqrt(cov[1, 1])
    phi = float(np.mean([r["phi"] for r in rows]))
    cd = HASIMOTO * rh / float(np.mean([r["L1"] for r in rows]))
    eta_ratio = 1.0 + 2.5 * phi + 6.2 * phi ** 2
    ratio, ratio_se = c / cd, c_se / cd
    bad = [r for r in rows if not settled(r)]
    form = ("not settled" if bad else "not tested (two boxes)" if dof == 0 else
            "the law holds" if p > P_MIN else "the law fails")
    z = math.hypot(ratio_se, H10_RATIO[1])
    if bad:
        again = "not settled"
    elif abs(ratio - H10_RATIO[0]) <= 2 * z:
        again = "reproduced"
    elif ratio - H10_RATIO[0] > 3 * z:
        again = "not reproduced"
    else:
        again = "not decided"
    plot(rows, fit, cd, cd / eta_ratio, png)
    tab = ["| N | L (a0) | φ | u (a0/t0), observer | u, colloids.h5 | halves | fluid kT | U/U0 | L in ν/u | "
           "CPU-s |", "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        tab.append(f"| {r['n']} | {r['L']:g} | {r['phi']:.4f} | {r['u']:.5f} ± {r['u_se']:.5f} | "
                   f"{r['u5']:.5f} ± {r['u5_se']:.5f} | {r['h1']:.5f}, {r['h2']:.5f} | {r['kT']:.3f} | "
                   f"**{r['U']:.3f} ± {r['U_se']:.3f}** | {r['L'] * r['u'] / r['nu']:.2f} | {r['cpu']:.0f} |")
    two = [r for r in rows if r["n"] in (8, 27)]
    lines = [
        f"- **The law's form (H12): {form}.**  U_N = U∞ − c N^(−1/3) through the {len(rows)} boxes: U∞/U0 = "
        f"{a:.3f} ± {a_se:.3f}, c = {c:.3f} ± {c_se:.3f}, χ² = {chi2:.2f} for {dof} dof (p = {p:.2f}; the rule asks "
        f"p > {P_MIN}).",
        f"- **H10's weak box term, again (H12): {again}.**  c over the dilute term c_d = 2.837 R_h/L_1 = {cd:.3f}: "
        f"{ratio:.2f} ± {ratio_se:.2f}, against H10's {H10_RATIO[0]:.2f} ± {H10_RATIO[1]:.2f} at R = 10 a0 "
        f"({(ratio - H10_RATIO[0]) / z:+.1f} combined SE)."]
    if len(two) == 2:
        c2 = 6.0 * (two[1]["U"] - two[0]["U"])
        c2_se = 6.0 * math.hypot(two[1]["U_se"], two[0]["U_se"])
        lines.append(f"- Beside it, deciding nothing: c from the 8- and 27-colloid boxes alone (H10's estimator) "
                     f"{c2:.3f} ± {c2_se:.3f} ({c2 / cd:.2f} ± {c2_se / cd:.2f} of c_d).")
    phi_h = phi * y ** 3
    lines.append(f"- Beside it, deciding nothing: (1 − U∞/U0)/φ = {(1 - a) / phi:.2f} ± {a_se / phi:.2f} with φ by R "
                 f"({phi:.4f}), {(1 - a) / phi_h:.2f} ± {a_se / phi_h:.2f} with φ by R_h ({phi_h:.4f}), beside "
                 f"Batchelor's {K_BATCHELOR} (a line through U0 at one φ: no K, as H9 says of φ = 0.1); c against the "
                 f"viscosity-scaled dilute term c_d η0/η = {cd / eta_ratio:.3f}: {c * eta_ratio / cd:.2f} of it.")
    revs = ", ".join(sorted({r["rev"] for r in rows}))
    return [
        BEGIN.format(name), "",
        "## Collective hydrodynamics: the finite-size law of hindered settling with three boxes (coupling I, R = 5 a0)",
        "",
        f"Measured by `peloid sweep studies/{name}.cfg` (runs of {revs}, one core each of the 2-core machine, at "
        f"times shared with the CI run; {sum(r['cpu'] for r in rows):.0f} CPU-s) and `python3 tools/hindered_nlaw.py "
        f"out/studies/{name} validation/REPORT.md` (section written at {commit}).  Rule H12 of "
        "validation/RULES_hindered_settling.md, committed with the study before its runs: coupling I colloids of "
        f"R = {R:g} a0 in Hecht's fluid (R_h/R = {y:.3f} ± {y_se:.3f} by the resolution law of {LAW}, not within 5 %: "
        "not the matched mode), R8's force, H5's scene otherwise, 8, 27 and 64 colloids at φ = 0.049.  U = (1 − φ) u, "
        "U0 = F/(6πη R_h).", ""] + tab + [""] + lines + [
        f"- **Stationary, and read again from colloids.h5 (H3):** {len(rows) - len(bad)} of {len(rows)} runs.",
        f"- What H12 does not test: K in the matched mode (R_h/R is {y:.2f} here); Batchelor's K needs U∞ at two "
        "dilute φ or the second-order term (H10).", "",
        f"![{os.path.basename(png)[:-4]}]({os.path.basename(png)})", "", END.format(name)]


def main():
    study_section_main(section, BEGIN, END, sys.argv)


if __name__ == "__main__":
    main()
