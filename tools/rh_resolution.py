"""Coupling I's hydrodynamic radius against the resolution R/a0, by the rules of validation/RULES_rh_resolution.md
(fixed before the runs): the section "Coupling I's hydrodynamic radius against the resolution" of
validation/REPORT.md for one study, written between its markers, and its plot.

Per point (one free colloid settling under a constant force M g in a periodic cube, model units): the
sedimentation observer's slip velocity u (summary.json) and, read independently with h5py from colloids.h5, the
colloid's fall relative to the fluid (R1, R2); the friction xi_box = M g / u, corrected to the unbounded fluid by
Hasimoto's and Zick & Homsy's series for a sphere in a periodic cubic array, R_h = xi / (6 pi eta) with the SRD
theory's eta (R3); the law R/R_h - 1 against a0/R and the resolution a 5 % match needs (R4); the shipped
calibration's R_h/R beside the point at R = 2 a0 (R5).

    python3 tools/rh_resolution.py OUT/STUDY REPORT.md [COMMIT]     (prints the section; exit 0)

STUDY is one of STUDIES (its name is the folder's).  It also writes calibration/rh_resolution-X.json (X: the
study's name after rh_resolution_): the fluid, the points and the law (or null, with the reason), which
`peloid plan` reads to name the resolution a 5 % match needs for a scene in that fluid (src/app/advise_match.c).
sections(text) lists the sections a report holds, for tools/validation_report.py to keep."""
import functools
import glob
import json
import math
import os
import sys

import numpy as np
from scipy import stats

from h5md_settling import block_falls
from validation.common import pyplot, save_figure
from validation.report_section import sections_in, study_section_main

BEGIN = "<!-- rh resolution: {} (tools/rh_resolution.py) -->"  # .format(study name)
END = "<!-- end of the rh resolution section: {} -->"
STUDIES = {
    "rh_resolution_c1_hecht": dict(
        departure=None,
        rerun="p000 (R = 2 a0) run again with a binary built on 119db37 with the C changes of 4af349f and "
              "ee18494: thermo.tsv (all but the timing column) and colloids.h5's positions bit for bit the same as "
              "the study's",
        short="Hecht's fluid",
        fluid="Hecht's fluid (scenes/hecht_table1.cfg: M = 2.5 per cell, λ = 0.6 a0, ±90° about the axes, no grid "
              "shift)", calibration="calibration/calibration-9aa595c8f7cdb515.json"),
    "rh_resolution_c1_default": dict(
        departure=None,
        rerun="p000 (R = 2 a0) run again with a binary built on 119db37 with the C changes of 4af349f and "
              "ee18494: thermo.tsv (all but the timing column) bit for bit the same as the study's",
        short="the default fluid",
        fluid="the default fluid of a physical coupling I scene (5 per cell, λ = 0.1 a0, 130° about random axes, "
              "grid shift)", calibration=None),
    "rh_resolution_c1_default_a": dict(
        rerun="the runs' revision string reads 08d2d6e-dirty: the binary was built from the source committed as "
              "2202939 before that commit", short="the default fluid with SRD+a", departure=None,
        note="these are R9's runs, with SRD+a as mended in 2202939 (each cell's kinetic energy kept by scaling the "
             "part of its relative velocities that is not the kept rigid rotation).  R6's first runs, with the "
             "earlier SRD+a, read 0.847 ± 0.012 and 0.900 ± 0.011 at R = 2, 3 a0; their R = 4 a0 point was stopped "
             "by the fluid guard, and a pure fluid of that rule with the rescaling thermostat was not at "
             "equilibrium (a pure fluid of these parameters, 32³ cells, 6000 steps, read with "
             "tools/fluid_equilibrium.py: its cells' mean velocities at 1.16 ± 0.05 kT, velocity kurtosis "
             "3.83 ± 0.02).  The mended rule's pure fluid is at equipartition with a kurtosis slightly above "
             "Maxwell's (the section 'A pure fluid at equilibrium' below).  The viscosity used for R_h is SRD+a's "
             "derived one (its ratio to SRD's checked by tests/physics/test_mpc_viscosity.c, +0.7 ± 0.7 %)",
        fluid="the default fluid (5 per cell, λ = 0.1 a0, 130° about random axes, "
              "grid shift) with SRD+a, the rotation that keeps each cell's angular momentum (its own viscosity)",
        calibration=None),
    "rh_resolution_c1_mpc_at": dict(
        departure=None, rerun=None, short="MPC-AT (γ 10, λ 0.05)",
        fluid="a collisional MPC-AT fluid (10 per cell, λ = 0.05 a0, grid shift, Andersen thermostat: no angular "
              "momentum kept)", calibration=None),
    "rh_resolution_c1_mpc_at_a": dict(
        departure=None, rerun=None, short="MPC-AT+a (γ 10, λ 0.05)",
        fluid="a collisional MPC-AT+a fluid (10 per cell, λ = 0.05 a0, grid shift, Andersen thermostat, each cell's "
              "angular momentum kept)", calibration=None),
}
MATCH = 0.05  # R3: |R_h/R - 1| <= 0.05 + 2 SE
Y95 = 1.0 / 0.95 - 1.0  # R4: R/R_h - 1 at R_h/R = 0.95


def sections(text):
    """The rh-resolution sections in a report's text, each from its begin to its end marker."""
    return sections_in(text, STUDIES, BEGIN, END)


# K^-1 of a simple cubic array of spheres, 1 + sum c chi^p (Hasimoto 1959; Sangani & Acrivos 1982, whose five terms
# give Zick & Homsy's table within 0.1 % up to phi = 0.125): F = 6 pi eta a K U, U the superficial velocity
SIMPLE_CUBIC = ((1, -1.7601), (3, 1.0), (6, -1.5593), (8, 3.9799), (10, -3.0734))


def array_inverse_drag(chi, terms=len(SIMPLE_CUBIC)):
    """K^-1 of the simple cubic array by the first `terms` terms of SIMPLE_CUBIC, chi = (4 pi/3)^(1/3) a/L."""
    k = 1.0
    for p, c in SIMPLE_CUBIC[:terms]:
        k += c * chi ** p
    return k


def array_mobility(radius, L):
    """The mobility of a sphere of `radius` in a periodic cubic array of side L over the unbounded one's (Hasimoto
    1959, Zick & Homsy 1982): 1 - 1.7601 chi + chi^3 - 1.5593 chi^6, chi = (4 pi/3)^(1/3) radius/L (R1-R8's
    three terms of array_inverse_drag; the same rounding as that sum written out)."""
    return array_inverse_drag((4.0 * math.pi / 3.0) ** (1.0 / 3.0) * radius / L, 3)


def unbounded(xi_box, eta, L):
    """xi in the unbounded fluid from xi_box of a sphere in a periodic cube of side L: xi_box / xi =
    1 / array_mobility(R_h, L), R_h = xi / (6 pi eta), by iteration."""
    xi = xi_box
    for _ in range(200):
        new = xi_box * array_mobility(xi / (6.0 * math.pi * eta), L)
        if abs(new - xi) < 1e-13 * xi:
            break
        xi = new
    return xi


def settling_runs(study):
    """The study's finished runs with a settling velocity, in point order: (run folder, its summary.json, the
    summary's settling_velocity); also tools/hindered_matched.py's."""
    for sp in sorted(glob.glob(os.path.join(study, "p*", "summary.json"))):
        s = json.load(open(sp))
        if s.get("interrupted") or "settling_velocity" not in s.get("observables", {}):
            continue
        yield os.path.dirname(sp), s, s["observables"]["settling_velocity"]


def run_row(run, s, sv):
    """One free colloid's settling run (a settling_runs triple): its colloid, box, force and slip velocity u,
    and R1's and R2's reading of colloids.h5 with h5py alone (16 blocks of the fall from the observer's window
    start: their mean u5 and its SE, the halves h1, h2 and the SE of each half hse); also
    tools/array_mobility.py's."""
    c = s["scene"]["colloids"]
    R, L, nu = c["radius"], s["scene"]["box"]["cells"][0], s["derived"]["nu"]
    M = c["mass_density"] * 4.0 / 3.0 * math.pi * R ** 3
    u = sv["value"]
    vb, _ = block_falls(run, 16, sv["average_from_time"])
    return dict(
        R=R, L=L, eta=s["derived"]["eta"], nu=nu, M=M, F=-M * c["gravity"][2], u=u, u_se=sv["stderr"],
        Re=u * R / nu, u5=float(vb.mean()), u5_se=float(vb.std(ddof=1) / 4.0), h1=float(vb[:8].mean()),
        h2=float(vb[8:].mean()), hse=float(vb.std(ddof=1) / math.sqrt(8.0)), kT=_window_kt(run, sv),
        start=sv["average_from_step"], steps=s["last_step"], cpu=s.get("cpu_seconds", 0.0),
        rev=s["peloid"]["git_revision"])


@functools.lru_cache(maxsize=None)
def points(study):
    """The study's finished points (read once per study: the section and the law file share them)."""
    rows = []
    for run, s, sv in settling_runs(study):
        r = run_row(run, s, sv)
        R, L, eta, F, u, u_se = r["R"], r["L"], r["eta"], r["F"], r["u"], r["u_se"]
        rh = lambda v: unbounded(F / v, eta, L) / (6.0 * math.pi * eta * R)  # noqa: E731
        r.update(xi_box=F / u, rh=rh(u), rh_se=abs(rh(u + u_se) - rh(u - u_se)) / 2.0)
        rows.append(r)
    rows.sort(key=lambda r: r["R"])
    return rows


def _window_kt(run, sv):
    th = np.genfromtxt(os.path.join(run, "thermo.tsv"), names=True, delimiter="\t")
    return float(th["temperature"][th["step"] >= sv["average_from_step"]].mean())


def fits(rows):
    """R4: y = R/R_h - 1 against x = a0/R; (a) y = c x, (b) y = b + c x: [(params, covariance, chi2, dof, p)]."""
    x = np.array([1.0 / r["R"] for r in rows])
    y = np.array([1.0 / r["rh"] - 1.0 for r in rows])
    sy = np.array([r["rh_se"] / r["rh"] ** 2 for r in rows])
    w = 1.0 / sy ** 2
    out = []
    for A in (x[:, None], np.vstack([np.ones_like(x), x]).T):
        if len(x) <= A.shape[1]:
            out.append(None)
            continue
        C = np.linalg.inv(A.T @ (A * w[:, None]))
        b = C @ (A.T @ (w * y))
        chi2 = float((w * (y - A @ b) ** 2).sum())
        dof = len(x) - A.shape[1]
        out.append((b, C, chi2, dof, float(stats.chi2.sf(chi2, dof))))
    return out


def law_of(rows):
    """R4: the fits, the accepted form with fewer parameters (None: neither) and the R/a0 it names for 0.95."""
    fa, fb = fits(rows)
    choice = next((f for f in (fa, fb) if f and f[4] > 0.05), None)
    return fa, fb, choice, needed(choice) if choice else None


def needed(fit):
    """R/a0 at which R_h/R = 0.95, and its SE, from a fit of fits(); None when the fluid cannot reach it."""
    b, C, *_ = fit
    off, c = (0.0, b[0]) if len(b) == 1 else (b[0], b[1])
    if off >= Y95 or c <= 0:
        return None
    x = (Y95 - off) / c
    g = np.array([-1.0 / c * x]) if len(b) == 1 else np.array([-1.0 / c, -x / c])  # dx/d(params)
    se_x = math.sqrt(float(g @ C @ g))
    return 1.0 / x, se_x / x ** 2


def calibration_rh(info, rows):
    """R5: R_h/R of the shipped calibration of this fluid at R = 2 a0 (D_inf = kT / xi, kT = 1), with the point's
    eta; None without one."""
    path = info["calibration"] and os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", info["calibration"])
    if not path or not os.path.exists(path):
        return None
    c = json.load(open(path))
    r2 = [r for r in rows if abs(r["R"] - 2.0) < 1e-9]
    if not r2:
        return None
    k = 1.0 / (6.0 * math.pi * r2[0]["eta"] * 2.0)
    return k / c["d_inf"], k * c["d_inf_se"] / c["d_inf"] ** 2, r2[0]


def plot(rows, fa, fb, need, path, title):
    plt = pyplot()
    x = np.array([1.0 / r["R"] for r in rows])
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.errorbar(x, [r["rh"] for r in rows], yerr=[r["rh_se"] for r in rows], fmt="o", capsize=3, color="C0",
                label="peloid: free colloid, observer's u")
    h5 = [unbounded(r["F"] / r["u5"], r["eta"], r["L"]) / (6 * math.pi * r["eta"] * r["R"]) for r in rows]
    ax.plot(x, h5, "x", color="C3", label="the same runs, colloids.h5 (h5py)")
    xx = np.linspace(0.0, max(x) * 1.1, 200)
    if fa:
        ax.plot(xx, 1.0 / (1.0 + fa[0][0] * xx), "C0-", lw=1,
                label=f"R/R_h − 1 = c a0/R: c = {fa[0][0]:.3f} (p = {fa[4]:.2f})")
    if fb:
        ax.plot(xx, 1.0 / (1.0 + fb[0][0] + fb[0][1] * xx), "C2--", lw=1,
                label=f"R/R_h − 1 = b + c a0/R: b = {fb[0][0]:.3f}, c = {fb[0][1]:.3f} (p = {fb[4]:.2f})")
    ax.axhspan(1 - MATCH, 1 + MATCH, color="0.85", label="matched: within 5 %")
    if need:
        ax.axvline(1.0 / need[0], color="k", lw=0.8, ls=":", label=f"R_h/R = 0.95 at a0/R = {1.0 / need[0]:.3f}")
    finish_plot(fig, ax, (0.0, max(x) * 1.1), (0.5, 1.08), title, path)


def finish_plot(fig, ax, xlim, ylim, title, path):
    """The axes of an R_h/R against a0/R plot (this tool's and tools/rh_matched.py's), saved to path."""
    plt = pyplot()
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_xlabel("a0 / R  (cell size over colloid radius)")
    ax.set_ylabel("R_h / R  (stick sphere of the same friction)")
    ax.set_title(title, fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7.5, loc="lower left")
    save_figure(plt, fig, path)


def _fit_text(name, f):
    if not f:
        return f"{name}: too few points"
    b, C, chi2, dof, p = f
    par = ", ".join(f"{k} = {v:.4f} ± {math.sqrt(C[i, i]):.4f}" for i, (k, v) in
                    enumerate(zip(("c",) if len(b) == 1 else ("b", "c"), b)))
    ok = "acceptable" if p > 0.05 else "rejected"
    return f"{name}: {par}, χ² = {chi2:.2f} on {dof} dof (p = {p:.3f}, {ok})"


def offset_note(fa, fb):
    """A sentence when form (b)'s offset is accepted and lies more than 3 SE above 0 while (a) is rejected."""
    if not fb or fb[4] <= 0.05 or (fa and fa[4] > 0.05):
        return ""
    b, se = fb[0][0], math.sqrt(fb[1][0, 0])
    if b <= 3 * se:
        return ""
    return (f"  In this fluid a part does not shrink with the resolution: b = {b:.3f} ± {se:.3f}, a limit "
            f"R_h/R → {1 / (1 + b):.3f} as a0/R → 0 (an extrapolation: over a factor 2 in R a constant and a "
            "curvature in a0/R look alike).  Rules R6 and R7 test whether it is the antisymmetric collisional "
            "stress of a rule that keeps no angular momentum (the SRD+a and MPC-AT+a sections); a viscosity that "
            "depends on the wavelength would also show here, as the flow around a colloid of a few cells is not "
            "the long-wavelength flow the theory's η is for (tests/physics/test_mpc_viscosity.c notes such a "
            "dependence for MPC-AT+a).")


def point_table(rows):
    """The points' table (R1-R3 per point) and the points R1 or R2 leaves not settled."""
    tab = ["| R/a0 | L/a0 | M (m_f) | Re | u (a0/t0), observer | u, colloids.h5 | halves | fluid kT | ξ_box | "
           "R_h/R | verdict (R3) |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    bad = []
    for r in rows:
        v = matched(r)
        if not settled(r):
            v = "not settled (" + v + ")"
            bad.append(r)
        tab.append(f"| {r['R']:g} | {r['L']:g} | {r['M']:.0f} | {r['Re']:.2f} | {r['u']:.5f} ± {r['u_se']:.5f} | "
                   f"{r['u5']:.5f} ± {r['u5_se']:.5f} | {r['h1']:.4f}, {r['h2']:.4f} | {r['kT']:.3f} | "
                   f"{r['xi_box']:.1f} | **{r['rh']:.3f} ± {r['rh_se']:.3f}** | {v} |")
    return tab, bad


def matched(r):
    """R3's verdict of one point."""
    return "matched" if abs(r["rh"] - 1) <= MATCH + 2 * r["rh_se"] else "not matched"


def settled(r):
    """R1 (the h5py reading agrees with the observer) and R2 (the window's halves agree), each within 3 SE; also
    H3's test of tools/hindered_matched.py, tools/hindered_nlaw.py and R1/R2 of tools/array_mobility.py."""
    return (abs(r["u5"] - r["u"]) <= 3 * math.hypot(r["u5_se"], r["u_se"]) and
            abs(r["h1"] - r["h2"]) <= 3 * math.sqrt(2) * r["hse"])


def section(study, commit, png):
    rows = points(study)
    name = os.path.basename(os.path.normpath(study))
    info = STUDIES[name]
    if len(rows) < 2:
        raise SystemExit(f"rh_resolution: {len(rows)} finished point(s) in {study}; the rules need two or more")
    fa, fb, choice, need = law_of(rows)
    plot(rows, fa, fb, None if info["departure"] else need, png,
         f"Coupling I: R_h/R against the resolution, {info['short']}\n"
         "one free colloid settling through a periodic cube of side 8 R")
    tab, bad = point_table(rows)
    if choice is None:
        law = "Neither form of the law is acceptable (p ≤ 0.05): no resolution for a 5 % match is read off."
    elif need is None:
        law = (f"By the accepted form ({'(a)' if choice is fa else '(b)'}) this fluid cannot reach R_h/R = 0.95 at "
               "any resolution.")
    else:
        Rn, Rn_se = need
        cells = 4.0 / 3.0 * math.pi * Rn ** 3
        law = (f"By the accepted form ({'(a)' if choice is fa else '(b)'}), R_h/R = 0.95 needs **R = {Rn:.1f} ± "
               f"{Rn_se:.1f} a0** (a0/R = {1 / Rn:.3f}): {cells:.0f} cells per colloid volume against 33.5 at "
               f"R = 2 a0, {cells / 33.51:.0f}× the fluid per colloid at the same volume fraction." +
               ("  Not settled (the departure below): no resolution is read off." if info["departure"] else ""))
    cal = calibration_rh(info, rows)
    if cal:
        rc, rc_se, r2 = cal
        z = (r2["rh"] - rc) / math.hypot(r2["rh_se"], rc_se)
        cal_line = (f"- **The calibration's cross-check (R5):** at R = 2 a0 this study reads {r2['rh']:.3f} ± "
                    f"{r2['rh_se']:.3f}; the shipped calibration ({info['calibration']}: D of 8 colloids, "
                    f"Hasimoto's term) gives {rc:.3f} ± {rc_se:.3f} ({z:+.1f} combined SE: "
                    f"{'agree' if abs(z) <= 3 else 'differ'}).")
    else:
        cal_line = "- No shipped calibration of this fluid to compare with (R5 does not apply)."
    cpu = sum(r["cpu"] for r in rows)
    r6 = []
    if name == "rh_resolution_c1_default_a":  # R6: the antisymmetric stress as the default fluid's offset
        b, C = (fb[0][0], math.sqrt(fb[1][0, 0])) if fb else (float("nan"), float("nan"))
        v6 = ("supported" if (fa and fa[4] > 0.05) or (fb and abs(b) <= 2 * C) else
              "refuted" if fb and b > 3 * C else "not decided")
        if info["departure"]:
            v6 = f"not settled ({v6} by the rule)"
        off = f"form (b)'s offset is b = {b:.3f} ± {C:.3f}" if fb else "form (b) has too few points"
        r6 = [f"- **R6, the default fluid's offset as SRD's antisymmetric stress: {v6}.**  With SRD+a {off} (the "
              f"default fluid's SRD: b = 0.142 ± 0.022, RULES R6); form (a) "
              f"{'accepted' if fa and fa[4] > 0.05 else 'rejected'}; at R = 2 and 3 a0 SRD+a's colloid has "
              f"R_h/R {rows[0]['rh']:.3f} and {rows[1]['rh']:.3f} against SRD's 0.655 and 0.712."]
    if name == "rh_resolution_c1_mpc_at_a":  # R7: against MPC-AT's offset
        other = os.path.join(os.path.dirname(os.path.normpath(study)), "rh_resolution_c1_mpc_at")
        ra = points(other) if os.path.isdir(other) else []
        fat = fits(ra)[1] if len(ra) >= 3 else None
        if fat and fb:
            b_at, se_at = fat[0][0], math.sqrt(fat[1][0, 0])
            b_a, se_a = fb[0][0], math.sqrt(fb[1][0, 0])
            a_ok = (fa and fa[4] > 0.05) or abs(b_a) <= 2 * se_a
            v7 = ("the antisymmetric stress accounts for the offset" if b_at > 3 * se_at and a_ok else
                  "it does not" if b_a > 3 * se_a else "not decided")
            rhs = ", ".join("%.3f" % r["rh"] for r in ra)
            Rs = ", ".join("%g" % r["R"] for r in ra)
            r6.append(f"- **R7, MPC-AT against MPC-AT+a: {v7}.**  Form (b)'s offset: MPC-AT b = {b_at:.3f} ± "
                      f"{se_at:.3f} (R_h/R {rhs} at R = {Rs} a0), MPC-AT+a b = {b_a:.3f} ± {se_a:.3f}; MPC-AT+a's "
                      f"form (a) {'accepted' if fa and fa[4] > 0.05 else 'rejected'}.")
        else:
            r6.append("- **R7, MPC-AT against MPC-AT+a:** not evaluated (both studies need their three points).")
    if info["departure"]:
        r6.append(f"- **Departure, stated:** {info['departure']}.")
    if info.get("note"):
        r6.append(f"- **Stated (R9):** {info['note']}.")
    return [
        BEGIN.format(name), "",
        f"## Coupling I's hydrodynamic radius against the resolution: {info['short']}", "",
        f"Measured by `peloid sweep studies/{name}.cfg --jobs 1` (runs of "
        f"{', '.join(sorted({r['rev'] for r in rows}))}; {cpu:.0f} CPU-s on the 2-core machine) and `python3 "
        f"tools/rh_resolution.py out/studies/{name} validation/REPORT.md` (section written at {commit}).  Rules: "
        "validation/RULES_rh_resolution.md, committed with the study before its runs.  One free coupling I colloid "
        f"(stick_stochastic surface, Al2O3's mass density) in {info['fluid']}, settling under a constant force "
        "through a periodic cube of side L = 8 R; ξ_box = M g / u, corrected to the unbounded fluid by Hasimoto's "
        "and Zick & Homsy's series for a periodic array (the χ³ term's radius and the frame of u: ≤ 0.8 %, not "
        "added); R_h = ξ/(6πη) with the collision rule's theory η (summary.json derived.eta)." + (f"  Revision check: {info['rerun']}." if info["rerun"] else
                                                           ""), ""] + tab + [
        "",
        f"- **Matched (R3):** {sum(1 for r in rows if matched(r) == 'matched')} of {len(rows)} "
        "points within 5 % (+ 2 SE) of R.",
        f"- **The resolution law (R4):** {_fit_text('(a) through the origin', fa)}; "
        f"{_fit_text('(b) with an offset', fb)}.  {law}",
        cal_line] + r6 + [
        f"- **Read again from colloids.h5, stationary (R1, R2):** {len(rows) - len(bad)} of {len(rows)} points "
        "agree with the observer within 3 SE and have window halves within 3 SE.",
        "",
        "The physical reason a coarse model falls short: the fluid's collisions with the surface give a finite "
        "(Enskog) friction ∝ n R² that acts in series with the Stokes friction ∝ η R (PL Eqs. 40–41, Sec. VIII: "
        "'using small σ_cf/a0 ... leads to a relatively larger contribution of the Enskog friction'), so "
        "R/R_h − 1 falls like a0/R and only a fine resolution removes it." + offset_note(fa, fb), "",
        f"![{os.path.basename(png)[:-4]}]({os.path.basename(png)})", "", END.format(name)]


def law_file(study, commit):
    """calibration/rh_resolution-X.json: what `peloid plan` needs (src/app/advise_match.c), written atomically."""
    rows = points(study)
    name = os.path.basename(os.path.normpath(study))
    s = json.load(open(glob.glob(os.path.join(study, "p*", "summary.json"))[0]))
    sc = s["scene"]
    _, _, choice, need = law_of(rows)
    unsettled = STUDIES[name]["departure"]
    if unsettled:  # a law a departure leaves not settled names no resolution
        need = None
    law = None
    if choice:
        b, C, chi2, dof, p = choice
        law = {"form": "c a0/R" if len(b) == 1 else "b + c a0/R", "b": 0.0 if len(b) == 1 else float(b[0]),
               "c": float(b[-1]), "covariance": C.tolist(), "chi2": chi2, "dof": dof, "p": p}
    doc = {
        "version": 1,
        "about": "coupling I's hydrodynamic radius against the resolution in one fluid: R/R_h - 1 = b + c a0/R "
                 "(tools/rh_resolution.py, rules validation/RULES_rh_resolution.md, section in validation/REPORT.md)",
        "study": name, "revision": sorted({r["rev"] for r in rows}), "written_at": commit,
        "fluid": {"particles_per_cell": sc["fluid"]["density"],
                  "mean_free_path": sc["srd"]["dt"] * math.sqrt(sc["fluid"]["temperature"]),
                  "rule": sc["srd"]["rule"], "alpha_deg": sc["srd"]["alpha"], "grid_shift": sc["srd"]["grid_shift"],
                  "boundary": sc["coupling"]["boundary"], "mass_density": sc["colloids"]["mass_density"]},
        "points": [{"R_over_a0": r["R"], "rh_over_R": r["rh"], "rh_over_R_se": r["rh_se"]} for r in rows],
        "law": law,
        "matched_R_over_a0": need[0] if need else None,
        "matched_R_over_a0_se": need[1] if need else None,
        "settled": not unsettled,
        "reason": None if need else (
            f"not settled: see the section of {name} in validation/REPORT.md" if unsettled
            else "neither form of the law is acceptable over the measured resolutions" if not choice
            else "the accepted law's offset b leaves R_h/R below 0.95 at any resolution"),
    }
    path = law_path(name)
    before = json.load(open(path)) if os.path.exists(path) else {}
    if "check" in before:  # the run at the matched resolution (tools/rh_matched.py) stays
        doc["check"] = before["check"]
    write_json(path, doc)


def law_path(name):
    """calibration/rh_resolution-X.json of the study `name` (X: the name after rh_resolution_)."""
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "calibration",
                        f"rh_resolution-{name[len('rh_resolution_'):]}.json")


def write_json(path, doc):
    """doc into path, atomically (a temporary file renamed over it)."""
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    os.replace(tmp, path)


def main():
    study, commit = study_section_main(section, BEGIN, END, sys.argv)
    law_file(study, commit)


if __name__ == "__main__":
    main()
