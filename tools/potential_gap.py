"""The potential coupling's friction against the resolution (validation/RULES_potential_gap.md G1-G2, fixed before
the runs): the section "The potential coupling's friction against the resolution" of validation/REPORT.md, written
between its markers, and its plot.

Per point (model units): the pinned sphere's friction xi = F / v_inf from thermo.tsv (tools/validation/pl_drag.py's
blocks after two flow-development times), against PL Eqs. 40-41 in an infinite box with the point-force (Hasimoto)
images, xi_pf(L) = 1 / (1/xi_PL - 2.837 / (6 pi eta L)): the excess e = xi / xi_pf - 1.  G1: e falls to zero with
sigma_cf / a0; G2: the sigma_cf = 2 a0 point's unbounded friction against the two shipped diffusion calibrations at
that resolution.

    python3 tools/potential_gap.py OUT/STUDY REPORT.md [COMMIT]     (prints the section; exit 0)"""
import json
import math
import os
import sys

from validation.common import load, pyplot, save_figure
from validation.pl_drag import drag_blocks, drag_theory
from validation.report_section import sections_in, study_section_main

BEGIN = "<!-- potential gap: {} (tools/potential_gap.py) -->"  # .format(study name)
END = "<!-- end of the potential gap section: {} -->"
STUDIES = ("potential_gap_resolution",)
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# the shipped calibrations at sigma_cf = 2 a0 in this fluid (src/app/calibrate_mode.c's THEORY_ROWS)
CALIBRATIONS = ("calibration-8e44d09ea885fe0d.json", "calibration-a20491e8dee69f67.json")


def sections(text):
    """The potential-gap sections in a report's text, each from its begin to its end marker."""
    return sections_in(text, STUDIES, BEGIN, END)


def rows_of(study):
    sw = load(os.path.dirname(os.path.normpath(study)), os.path.basename(os.path.normpath(study)))
    if sw is None:
        raise SystemExit(f"potential_gap: no sweep.json in {study}")
    rows = []
    for p in sw["points"]:
        s = p["summary"]
        if not s:
            continue
        fb = drag_blocks(sw["_out"], p)
        if not fb:
            continue
        sig, L = s["scene"]["coupling"]["sigma_cf"], s["scene"]["box"]["cells"][0]
        v0 = s["scene"]["coupling"]["flow_velocity"][0]
        eta = s["derived"]["eta"]
        F, F_se, nb, first = fb
        xi, xi_se = F / v0, F_se / v0
        xi_pl_box, xi_pf = drag_theory(s)  # PL's finite-box form; PL Eqs. 40-41 with the point-force images
        img = 2.837 / (6.0 * math.pi * eta * L)
        xi_inf = 1.0 / (1.0 / xi_pf + img)  # PL Eqs. 40-41, unbounded
        rows.append(dict(sig=sig, L=L, v0=v0, eta=eta, nu=s["derived"]["nu"], xi=xi, xi_se=xi_se, nb=nb, first=first,
                         xi_inf=xi_inf, xi_pf=xi_pf, xi_pl_box=xi_pl_box, img=img, e=xi / xi_pf - 1.0,
                         e_se=xi_se / xi_pf, cpu=s.get("cpu_seconds", 0.0), rev=s["peloid"]["git_revision"]))
    rows.sort(key=lambda r: r["sig"])
    return rows


def calibrations():
    """The shipped calibrations' kT / D_inf (kT = 1) and its SE, pooled by 1/SE^2: (xi, se, [(xi, se)])."""
    each = []
    for name in CALIBRATIONS:
        c = json.load(open(os.path.join(ROOT, "calibration", name)))
        d, sd = c["d_inf"], c["d_inf_se"]
        each.append((1.0 / d, sd / d ** 2))
    w = [1.0 / se ** 2 for _, se in each]
    xi = sum(wi * x for wi, (x, _) in zip(w, each)) / sum(w)
    return xi, 1.0 / math.sqrt(sum(w)), each


def plot(rows, path):
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    x = [r["sig"] for r in rows]
    ax.errorbar(x, [100 * r["e"] for r in rows], yerr=[100 * r["e_se"] for r in rows], fmt="o", color="k",
                capsize=3, label="peloid: ξ / ξ_pf(L) − 1 (block SE)")
    ax.plot(x, [100 * (r["xi"] / r["xi_pl_box"] - 1) for r in rows], "s", mfc="none", color="C0",
            label="against PL's own finite-box form (Eqs. 42–43)")
    ax.axhline(0.0, color="0.4", lw=0.8)
    ax.fill_between([1.5, 6.5], [-5, -5], [5, 5], color="0.9", label="G1's ± 5 % at σ_cf = 6 a0")
    ax.set_xlim(1.5, 6.5)
    ax.set_xlabel("σ_cf / a0  (box 8 σ_cf, Re ≈ 0.4)")
    ax.set_ylabel("friction over PL Eqs. 40–41 + images − 1 (%)")
    ax.set_title("Potential coupling: pinned-sphere friction against the resolution (G1)", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    save_figure(plt, fig, path)


def section(study, commit, png):
    rows = rows_of(study)
    name = os.path.basename(os.path.normpath(study))
    by = {r["sig"]: r for r in rows}
    lines = [BEGIN.format(name), "",
             "## The potential coupling's friction against the resolution (PL Eqs. 40–41)", "",
             f"Measured by `peloid sweep studies/{name}.cfg --jobs 1 --threads 1` (runs of "
             f"{', '.join(sorted({r['rev'] for r in rows}))}; {sum(r['cpu'] for r in rows):.0f} CPU-s) and "
             f"`python3 tools/potential_gap.py out/studies/{name} validation/REPORT.md` (section written at {commit}).  "
             "Rules G1–G2 of validation/RULES_potential_gap.md, committed with the study before its runs: one colloid "
             "pinned in a held flow (scenes/coupling_drag.cfg: γ = 5, α = 90°, λ = 0.1, ε_cf = 2.5 kT, 4 MD substeps) "
             "in a box of 8 σ_cf at Re ≈ 0.4; ξ = F/v∞ from 1000-step blocks after two flow-development times; "
             "ξ_PL = PL Eq. 40 ∥ 4πη σ_cf (Eq. 41) unbounded, ξ_pf(L) = 1/(1/ξ_PL − 2.837/(6πηL)) (the force "
             "monopole's images, whatever the surface); e = ξ/ξ_pf − 1.", "",
             "| σ_cf (a0) | L (a0) | v∞ (a0/t0) | Re | ξ (blocks) | ξ_PL unbounded | ξ_pf(L) | e | PL's finite-box form | "
             "a_eff = ξ/(4πη) | CPU-s |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['sig']:g} | {r['L']} | {r['v0']:.4f} | {r['v0'] * r['sig'] / r['nu']:.2f} | "
                     f"{r['xi']:.1f} ± {r['xi_se']:.1f} ({r['nb']} from step {r['first']}) | {r['xi_inf']:.1f} | "
                     f"{r['xi_pf']:.1f} | {100 * r['e']:+.1f} ± {100 * r['e_se']:.1f} % | {r['xi_pl_box']:.1f} "
                     f"({100 * (r['xi'] / r['xi_pl_box'] - 1):+.1f} %) | {r['xi'] / (4 * math.pi * r['eta']):.2f} | "
                     f"{r['cpu']:.0f} |")
    lines.append("")
    if 2.0 in by and 6.0 in by:
        a, b = by[2.0], by[6.0]
        gap = a["e"] > 2 * a["e_se"]
        falls = a["e"] - b["e"] > 2 * math.hypot(a["e_se"], b["e_se"])
        near = abs(b["e"]) <= 0.05 + 2 * b["e_se"]
        v = "explained — resolution" if gap and falls and near else "not explained"
        lines.append(f"- **G1: {v}.**  e = {100 * a['e']:+.1f} ± {100 * a['e_se']:.1f} % at σ_cf = 2 a0 (the gap "
                     f"{'is' if gap else 'is not'} there by 2 SE), {100 * b['e']:+.1f} ± {100 * b['e_se']:.1f} % at "
                     f"6 a0 ({'below' if falls else 'not below'} it by 2 combined SE; "
                     f"{'within' if near else 'outside'} 5 % + 2 SE of zero)" +
                     "".join(f"; {100 * by[s]['e']:+.1f} ± {100 * by[s]['e_se']:.1f} % at {s:g} a0" for s in (3.0, 4.0)
                             if s in by) + ".")
    else:
        lines.append(f"- G1: {len(rows)} of 4 points finished; not decided.")
    if 2.0 in by:
        a = by[2.0]
        xi_inf = 1.0 / (1.0 / a["xi"] + a["img"])
        xi_inf_se = a["xi_se"] * (xi_inf / a["xi"]) ** 2
        xc, xc_se, each = calibrations()
        z = (xi_inf - xc) / math.hypot(xi_inf_se, xc_se)
        v2 = "agrees" if abs(z) <= 2 else "disagrees"
        lines.append(f"- **G2: {v2}.**  The σ_cf = 2 a0 drag's unbounded friction 1/(1/ξ + 2.837/(6πηL)) = "
                     f"{xi_inf:.1f} ± {xi_inf_se:.1f} against the shipped diffusion calibrations' kT/D∞ "
                     + ", ".join(f"{x:.1f} ± {s:.1f}" for x, s in each) + f" (pooled {xc:.1f} ± {xc_se:.1f}): "
                     f"{z:+.1f} combined SE; PL Eqs. 40–41 give {a['xi_inf']:.1f}.  "
                     + ("The calibration measures the coupling's own friction: its D 0.86–0.87 of the theory is the "
                        "friction the drag shows, not the MSD estimator's." if v2 == "agrees" else
                        "The calibration's D and the drag disagree: the estimator is suspect."))
    lines += ["- Stated by G2, not corrected: the calibrations' colloids are free (reduced mass 0.994–0.997 m_f "
              "against the pinned drag's m_f in PL Eq. 40: under 0.6 % in ξ_E).", "",
              f"![{os.path.basename(png)[:-4]}]({os.path.basename(png)})", "", END.format(name)]
    plot(rows, png)
    return lines


def main():
    study_section_main(section, BEGIN, END, sys.argv)


if __name__ == "__main__":
    main()
