"""Hindered settling of coupling I at its matched resolution (validation/RULES_hindered_settling.md H5, fixed before
the runs): the section "Collective hydrodynamics at the matched resolution" of validation/REPORT.md, written between
its markers, and its plot.

Per point (model units): the sedimentation observer's slip velocity u (summary.json, a0/t0, positive down) and, read
independently with h5py from colloids.h5, the colloids' mean fall turned into u by the zero total momentum (H3,
tools/h5md_settling.py); U = u (1 - phi); U0 = F / (6 pi eta R_h) with rule R8's measured R_h (the law file's
"check", calibration/rh_resolution-c1_hecht.json); y = 1 - R_h (2.837/L + 6 pi eta U/F) fitted as K phi.

    python3 tools/hindered_matched.py OUT/STUDY REPORT.md [COMMIT]     (prints the section; exit 0)"""
import json
import math
import os
import sys

import numpy as np

from hindered_settling import HASIMOTO, K_BATCHELOR, N_RZ, h5_slip, k_rp
from rh_resolution import law_path, settling_runs
from validation.report_section import sections_in, study_section_main

BEGIN = "<!-- hindered matched: {} (tools/hindered_matched.py) -->"  # .format(study name)
END = "<!-- end of the hindered matched section: {} -->"
STUDIES = ("hindered_settling_c1_matched",)
# how the study's points were run, where summary.json cannot say it (a resumed point names only the binary that
# finished it)
RESUMED = ("two points were stopped once by a signal at a checkpoint and resumed by `peloid sweep` with the "
           "binary of f434858's source (the string 5f2ba63-dirty: built before that commit), whose coupling I event "
           "order gives the same bits as the first part's binary (e0d8eab-dirty, the source of 162a85d; "
           "bench/RESULTS.md)")
RZ_SUFFIX = "_rz"  # rule H6's points: the study name + this
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
    for run, s, sv in settling_runs(study):
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


def fit_n(rows, rh, rh_se, box=True):
    """H6: ln(U/U0 + box term) = ln v_inf + n ln(1 - phi), weighted; SE scaled by sqrt(chi2/dof) above 1 and
    combined with n's shift under R_h +- SE.  Returns (n, SE, v_inf/U0, chi2/dof)."""
    def n_at(x):
        y, sy = np.array([y_of(r, x) for r in rows]).T
        if not box:  # the fit without the box term: U/U0 alone
            y = y + np.array([HASIMOTO * x * r["R"] / r["L"] for r in rows])
        v = 1.0 - y
        z, sz = np.log(v), sy / v
        X = np.vstack([np.ones(len(rows)), np.log(1.0 - np.array([r["phi"] for r in rows]))]).T
        w = 1.0 / sz ** 2
        C = np.linalg.inv(X.T @ (X * w[:, None]))
        b = C @ (X.T @ (w * z))
        dof = max(len(rows) - 2, 1)
        chi = float((w * (z - X @ b) ** 2).sum()) / dof
        return float(b[1]), float(math.sqrt(C[1, 1]) * max(1.0, math.sqrt(chi))), float(math.exp(b[0])), chi
    n, se, vinf, chi = n_at(rh)
    shift = abs(n_at(rh + rh_se)[0] - n_at(rh - rh_se)[0]) / 2.0
    return n, math.hypot(se, shift), vinf, chi


def plot(rows, K, rh, path, all_rows=(), nfit=None):
    """Left: y against phi with K (H5); right, with H6's points: U_inf/U0 against 1 - phi, log-log, with n."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2 if nfit else 1, figsize=(11.5 if nfit else 6.4, 4.4), squeeze=False)
    ax = axes[0][0]
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
    ax.set_title("K (H5): 8 colloids of R = 10 a0, Hecht's fluid,\n"
                 "U0 and the box term with R8's R_h", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    if nfit:
        n, n_se, vinf = nfit[:3]
        ax = axes[0][1]
        ph = np.array([r["phi"] for r in all_rows])
        yy, ss = np.array([y_of(r, rh) for r in all_rows]).T
        ax.errorbar(1.0 - ph, 1.0 - yy, yerr=ss, fmt="o", color="C0", capsize=3,
                    label="peloid: U/U0 + box term (observer)")
        q = np.linspace(0.65, 1.0, 100)
        ax.plot(q, vinf * q ** n, "C0-", lw=1, label=f"fit (H6): n = {n:.2f} ± {n_se:.2f}, v∞/U0 = {vinf:.2f}")
        raw = 1.0 - yy - np.array([HASIMOTO * rh * r["R"] / r["L"] for r in all_rows])
        ax.plot(1.0 - ph, raw, "s", mfc="none", color="0.45", label="U/U0 without the box term (for information)")
        if len(nfit) > 3:
            ax.plot(q, nfit[4] * q ** nfit[3], "-", color="0.45", lw=0.8,
                    label=f"its fit: n = {nfit[3]:.2f}, v∞/U0 = {nfit[4]:.2f}")
        ax.plot(q, q ** N_RZ, "k--", lw=1, label=f"Richardson–Zaki: (1 − φ)^{N_RZ}")
        ax.plot(q, q ** 3.61, "C1:", lw=1.2, label="coupling I at a0 = R/2 (H2): n = 3.61")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("1 − φ")
        ax.set_ylabel("U∞ / U0 = U/U0 + box term")
        ax.set_title("Richardson–Zaki's n (H6), log-log", fontsize=9)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def section(study, commit, png):
    rows = points(study)
    name = os.path.basename(os.path.normpath(study))
    if len(rows) < 2:
        raise SystemExit(f"hindered_matched: {len(rows)} finished point(s) in {study}; rule H5 needs both")
    rz_dir = os.path.normpath(study) + RZ_SUFFIX  # rule H6's two points, a study of their own
    rz = points(rz_dir) if os.path.isdir(rz_dir) else []
    rh, rh_se, r8 = r8_radius()
    K, K_se, K_stat, K_rh, chi2 = fit_k(rows, rh, rh_se)
    all_rows = sorted(rows + rz, key=lambda r: r["phi"])
    bad = lambda rr: [r for r in rr if abs(r["h1"] - r["h2"]) > 3 * math.sqrt(2) * r["hse"] or  # noqa: E731
                      abs(r["u5"] - r["u"]) > 3 * math.hypot(r["u5_se"], r["u_se"])]
    stat_bad = [r for r in all_rows if abs(r["h1"] - r["h2"]) > 3 * math.sqrt(2) * r["hse"]]
    h5_bad = [r for r in all_rows if abs(r["u5"] - r["u"]) > 3 * math.hypot(r["u5_se"], r["u_se"])]
    v = "agrees" if abs(K - K_BATCHELOR) <= 0.15 * K_BATCHELOR + 2 * K_se else "disagrees — peloid"
    if bad(rows):
        v = f"not settled ({v})"
    n_lines = []
    if len(rz) == 2:
        n, n_se, vinf, nchi = fit_n(all_rows, rh, rh_se)
        n0, n0_se, vinf0, _ = fit_n(all_rows, rh, rh_se, box=False)
        vn = "agrees" if abs(n - N_RZ) <= 0.10 * N_RZ + 2 * n_se else "disagrees — peloid"
        if bad(all_rows):
            vn = f"not settled ({vn})"
        n_lines = [f"- **Richardson–Zaki's n at the matched resolution (H6): {vn}.**  n = {n:.2f} ± {n_se:.2f} over "
                   f"φ = {all_rows[0]['phi']:.3f}–{all_rows[-1]['phi']:.3f} (4 points, box term added, χ²/dof = "
                   f"{nchi:.1f}, v∞/U0 = {vinf:.3f}) against 4.65 ({(n - N_RZ) / n_se:+.1f} SE, "
                   f"{100 * (n / N_RZ - 1):+.0f} %); at a0 = R/2 the same coupling gave 3.61 ± 0.05 (H2).  For "
                   f"information, without the box term: n = {n0:.2f} ± {n0_se:.2f}, v∞/U0 = {vinf0:.3f}."]
        top = all_rows[-1]
        y_top, _ = y_of(top, rh)
        box_top = HASIMOTO * rh * top["R"] / top["L"]
        u_top = 1.0 - y_top - box_top
        if box_top > u_top:  # added after the runs, deciding nothing
            n_lines.append(
                f"- For information (added after the runs, deciding nothing): at φ = {top['phi']:.3f} the box term H6 "
                f"adds, Hasimoto's dilute {box_top:.3f}, exceeds U/U0 itself ({u_top:.3f}), and the box-corrected "
                f"U/U0 is {1.0 - y_of(all_rows[-2], rh)[0]:.3f} and {1.0 - y_top:.3f} at φ = "
                f"{all_rows[-2]['phi']:.3f} and {top['phi']:.3f}: in a concentrated box the dilute term cannot hold, "
                "and without it the N = 8 box's own hindrance is left in.  So neither fit is this model's n: with 8 "
                "colloids a box the finite-size term is as large as what is measured, and a box with many more "
                f"colloids (at 4189 cells a colloid) is what n needs.")
    else:
        n_lines = [f"- Richardson–Zaki's n (H6): {len(rz)} of its 2 points finished in {rz_dir}; not fitted."]
    plot(rows, K, rh, png, all_rows, (n, n_se, vinf, n0, vinf0) if len(rz) == 2 else None)
    tab = ["| φ | colloids | L (a0) | u (a0/t0), observer | u, colloids.h5 | halves | U/U0 | box term | "
           "y/φ | Pe | Re at U0 | fluid kT | CPU-s (from step) |", "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    # for information, added once the runs were in (deciding nothing): the box-corrected U/U0 against Batchelor's
    # line and Richardson-Zaki's curve at each phi
    info = ["| φ | U/U0 + box term | Batchelor 1 − 6.55 φ | Richardson–Zaki (1 − φ)^4.65 |", "|---|---|---|---|"]
    for r in all_rows:
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
    cpu = sum(r["cpu"] for r in all_rows)
    lo, hi = rows[0], rows[-1]
    U0_lo = lo["F"] / (6.0 * math.pi * lo["eta"] * rh * lo["R"])
    need = (1.0 - K_BATCHELOR * lo["phi"]) - lo["u"] * (1.0 - lo["phi"]) / U0_lo  # the box term Batchelor would need
    over = all(1.0 - y_of(r, rh)[0] - 2 * y_of(r, rh)[1] > max((1 - r["phi"]) ** 4.65, 1 - K_BATCHELOR * r["phi"])
               for r in all_rows)
    above = ("  The box-corrected U/U0 lies more than 2 SE above both references at every point: with Hasimoto's "
             "term, the model suspension is hindered less than a real one." if over else "")
    return [
        BEGIN.format(name), "",
        "## Collective hydrodynamics at the matched resolution: hindered settling of coupling I", "",
        f"Measured by `peloid sweep studies/{name}.cfg --jobs 2 --threads 1` (runs of "
        f"{', '.join(sorted({r['rev'] for r in all_rows}))}: the revisions the points' summary.json name; {cpu:.0f} "
        f"CPU-s) and `python3 tools/hindered_matched.py out/studies/{name} validation/REPORT.md` (section written at "
        f"{commit}).  Rule H5 of validation/RULES_hindered_settling.md, committed with the study before its runs: "
        f"8 colloids of R = 10 a0 (rule R8's colloid, fluid and force: Hecht's fluid at a0 = R/10, stick_stochastic "
        f"surfaces, hard spheres by Hertz + lubrication) at a random start in periodic cubes, averaged from the "
        f"observer's detected start.  U0 = F/(6πη R_h) and the box term 2.837 R_h/L with R_h/R = {rh:.3f} ± "
        f"{rh_se:.3f}, measured by R8 ({r8}, the section above).  CPU-s: of the process that ran the point from the "
        f"step given" + (f"; H5's {RESUMED}." if any(r["first"] > 0 for r in rows) else ".") +
        (f"  Rule H6's points (φ ≥ 0.2): `peloid sweep studies/{name}{RZ_SUFFIX}.cfg --jobs 2 --threads 1`."
         if rz else ""), ""] + tab + [
        "",
        f"- **Batchelor's K at the matched resolution: {v}.**  K = {K:.2f} ± {K_se:.2f} (the points "
        f"{K_stat:.2f}, R8's R_h {K_rh:.2f}; {len(rows)} points, χ² = {chi2:.1f}) against 6.55 "
        f"({(K - K_BATCHELOR) / K_se:+.1f} SE, {100 * (K / K_BATCHELOR - 1):+.0f} %); at a0 = R/2 the same coupling "
        f"gave 3.20 ± 0.11 (H1, R_h/R = 0.786).  For information, Rotne–Prager with excluded Stokeslets at "
        f"a_h/a = {rh:.3f}: {k_rp(rh):.2f}."] + n_lines + [
        f"- **Stationary, and read again from colloids.h5:** the h5py reading agrees with the observer within 3 SE "
        f"at {len(all_rows) - len(h5_bad)} of {len(all_rows)} points; the two halves of the window agree within 3 "
        f"SE at {len(all_rows) - len(stat_bad)} of {len(all_rows)}.",
        "- For information (added after the runs, deciding nothing): each point's box-corrected U/U0 beside "
        f"Batchelor's dilute line and Richardson–Zaki's curve.  At φ = {hi['phi']:.3f} the two references differ "
        f"by {(1 - hi['phi']) ** 4.65 - (1 - K_BATCHELOR * hi['phi']):.2f} U0 (the dilute line is not the suspension "
        "there), so H1's and H5's line through the origin over φ ≤ 0.1 reads K low even for exact hydrodynamics.  "
        f"With N = 8 the subtracted box term is as large as the hindrance: the dilute point (φ = {lo['phi']:.3f}) "
        f"meets Batchelor's line only if the finite-N term were {need:.3f} instead of Hasimoto's "
        f"{HASIMOTO * rh * lo['R'] / lo['L']:.3f}.{above}", ""] + info + ["",
        "- Stated by H5, not corrected: the box term's higher orders ((R/L)³ terms, below 0.01 of y), Re ~ 0.3, "
        "and N = 8 colloids a box (its finite-N term is the box term).  Not run at this resolution: D(φ).", "",
        f"![{os.path.basename(png)[:-4]}]({os.path.basename(png)})", "", END.format(name)]


def main():
    study_section_main(section, BEGIN, END, sys.argv)


if __name__ == "__main__":
    main()
