"""Hecht et al. 2005 Fig. 4, Eq. 37: the Richardson-Zaki exponent in three frames, and its precision against CPU time.

Part of tools/validation_report.py (validation/REPORT.md); each evaluator takes a loaded sweep and
returns (value, verdict[, details, plot])."""
import os
from validation.common import guide_axes, pyplot, save_figure


def rz_fit(points):
    """Weighted least squares of ln v = ln v_inf + l ln(1 - phi): (l, SE, v_inf, SE, chi2/dof)."""
    import numpy as np
    x = np.array([np.log(1.0 - f) for f, v, e in points])
    y = np.array([np.log(v) for f, v, e in points])
    w = np.array([(v / e) ** 2 for f, v, e in points])  # SE(ln v) = SE(v) / v
    A = np.vstack([np.ones_like(x), x]).T
    cov = np.linalg.inv(A.T @ (A * w[:, None]))
    beta = cov @ (A.T @ (w * y))
    dof = len(x) - 2
    chi2 = float(np.sum(w * (y - A @ beta) ** 2)) / dof if dof > 0 else 0.0
    scale = max(1.0, chi2) ** 0.5
    return (float(beta[1]), float(cov[1, 1] ** 0.5 * scale), float(np.exp(beta[0])),
            float(np.exp(beta[0]) * cov[0, 0] ** 0.5 * scale), chi2)


# The frames of the settling velocity.  The observer gives the slip velocity u = <v_z> - (the fluid's mean),
# the colloids relative to the fluid.  Gravity compensation keeps the total momentum at zero, so in the box
# frame the colloids move at u M_f / (M_f + M_c); Richardson-Zaki's v_s is the colloids' velocity where the
# net volume flux is zero, u (1 - phi).
RZ_FRAMES = [("volume", "zero volume flux, u (1 − φ): Richardson–Zaki's frame"),
             ("momentum", "zero momentum (the simulation box), u M_f / (M_f + M_c)"),
             ("slip", "relative to the fluid, u")]


def rz_speed(summary, frame):
    """Settling speed and SE in the frame, from the point's summary.json."""
    v = summary["observables"]["settling_velocity"]
    # positive down since it says so (issue 45); dz/dt (settling along -z) before
    u, e = (v["value"] if v.get("positive") == "down" else -v["value"]), v["stderr"]
    col = summary["mapping"]["colloid"]
    if frame == "volume":
        f = 1.0 - col["volume_fraction_realised"]
    elif frame == "momentum":
        mc = col["n_colloids"] * col["mass_m_f"]
        f = summary["fluid_particles"] / (summary["fluid_particles"] + mc)
    else:
        f = 1.0
    return u * f, e * f


def fig4_rz(sw):
    """Richardson-Zaki exponent per Peclet number and frame; Hecht: l = 3.5 at Pe = 1."""
    g1 = 87.3  # Pe = 1
    fits, rows = {}, []
    for frame, what in RZ_FRAMES:
        by_pe = {}
        for p in sw["points"]:
            pe = p["params"]["physical.gravity"] / g1
            if p["summary"]:
                phi = p["summary"]["mapping"]["colloid"]["volume_fraction_realised"]
                by_pe.setdefault(pe, []).append((phi,) + rz_speed(p["summary"], frame))
            else:
                by_pe.setdefault(pe, []).append(None)
        for pe, pts in sorted(by_pe.items()):
            ok = [q for q in pts if q and q[1] > 0]
            if len(ok) < 3:
                rows.append(f"{frame}, Pe = {pe:g}: {len(ok)} of {len(pts)} points usable")
                continue
            fits[(frame, pe)] = rz_fit(ok) + (ok,)
    if ("volume", 1.0) not in fits:
        return "<br>".join(rows) or "no point finished", "incomplete: the Pe = 1 points did not finish", None, None
    for frame, what in RZ_FRAMES:
        rows.append(f"{what}: " + ", ".join(f"Pe = {pe:g}: l = {f[0]:.2f} ± {f[1]:.2f} (χ²/dof {f[4]:.1f})"
                                               for (fr, pe), f in sorted(fits.items()) if fr == frame))
    pts = fits[("slip", 1.0)][5]
    rows.append("Pe = 1, slip u (a0/t0): " + ", ".join(f"φ {q[0]:.3f}: {q[1]:.4f} ± {q[2]:.4f}" for q in pts))
    p1 = next(p for p in sw["points"] if p["summary"] and p["params"]["physical.gravity"] == g1)["summary"]
    col = p1["mapping"]["colloid"]
    stokes = col["mass_m_f"] * abs(p1["scene"]["colloids"]["gravity"][2]) / (
        6 * 3.141592653589793 * p1["derived"]["eta"] * col["radius_a0"])
    vinf = fits[("slip", 1.0)][2]
    rows.append(f"Pe = 1: fitted slip v∞ = {vinf:.4f} a0/t0, {vinf / stokes:.2f} × Stokes M_b g / (6π η R) = "
                f"{stokes:.4f} (η of PL Eqs. 9–15): the colloids' friction is {stokes / vinf:.2f} of 6π η R")
    verdicts = []
    for frame in ("volume", "momentum"):
        l, l_se = fits[(frame, 1.0)][:2]
        verdicts.append(("agrees" if abs(l - 3.5) <= 3 * l_se else "**disagrees**") +
                        f" in the {frame} frame: l = {l:.2f} ± {l_se:.2f} at Pe = 1 vs Hecht's 3.5 "
                        f"({(l - 3.5) / l_se:+.1f} SE)")
    pe_l = [fits[("volume", pe)] for pe in (0.5, 1.0, 2.0) if ("volume", pe) in fits]
    if len(pe_l) == 3:
        spread = max(f[0] for f in pe_l) - min(f[0] for f in pe_l)
        verdicts.append(f"Pe = 0.5, 1, 2 differ by {spread:.2f} in l (Hecht: similar; PL: weak Pe dependence)")

    def plot(path):
        plt = pyplot()
        import numpy as np
        fig, axes = plt.subplots(1, 2, figsize=(11, 4.3), sharey=True)
        for ax, frame in zip(axes, ("volume", "momentum")):
            for i, pe in enumerate((0.5, 1.0, 2.0)):
                if (frame, pe) not in fits:
                    continue
                l, l_se, vinf, _, _, ok = fits[(frame, pe)]
                ph = np.array([q[0] for q in ok])
                ax.errorbar(1 - ph, np.array([q[1] for q in ok]) / vinf, yerr=np.array([q[2] for q in ok]) / vinf,
                            fmt="o", color=f"C{i}", capsize=2, label=f"Pe = {pe:g}: l = {l:.2f} ± {l_se:.2f}")
                xx = np.linspace(0.6, 1.0, 50)
                ax.plot(xx, xx ** l, color=f"C{i}", lw=0.8)
            xx = np.linspace(0.6, 1.0, 50)
            ax.plot(xx, xx ** 3.5, "k--", lw=1, label="Hecht: l = 3.5")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("porosity 1 − φ")
            ax.set_title(dict(RZ_FRAMES)[frame].split(":")[0].split(",")[0], fontsize=10)
            ax.legend(fontsize=8)
            ax.grid(True, which="both", alpha=0.3)
        axes[0].set_ylabel("v_s / v∞ (fitted v∞)")
        fig.suptitle("Richardson–Zaki (Hecht Fig. 4, Eq. 37), coupling II, periodic box", fontsize=11)
        save_figure(plt, fig, path)
    return "<br>".join(rows), "; ".join(verdicts), None, plot


def blocking_se(x):
    """Mean and Flyvbjerg-Petersen blocking SE of a time series, with the rule of peloid's observers
    (src/observe/blocking.c): the first level with at least 16 blocks where (2^k)^3 > 2 N (SE_k / SE_0)^4
    (Lee et al.), else the last level with 16 blocks."""
    import numpy as np
    x = np.asarray(x, float)
    n = len(x)
    se0 = x.std(ddof=1) / n ** 0.5
    if not se0 > 0:
        return float(x.mean()), 0.0
    last, k, y = se0, 0, x
    while len(y) >= 16:
        se = y.std(ddof=1) / len(y) ** 0.5
        last = se
        if k > 0 and 2.0 ** (3 * k) > 2 * n * (se / se0) ** 4:
            return float(x.mean()), float(se)
        m = len(y) // 2
        y = 0.5 * (y[0:2 * m:2] + y[1:2 * m:2])
        k += 1
    return float(x.mean()), float(last)


RZ_PREFIXES = (1 / 16, 1 / 8, 1 / 4, 1 / 2, 1.0)


def rz_precision(sw):
    """Precision-cost guide for the Richardson-Zaki exponent (studies/hecht_fig4_rz.cfg).  No exact reference
    exists (Hecht's 3.5 and Richardson-Zaki's 4.65 are empirical), so only the SE of l is shown, not an
    error: for prefixes 1/16 ... 1 of each run, each point's settling velocity (Richardson-Zaki's frame,
    u (1 - phi)) from the samples of /observables/settling_velocity up to the prefix with the blocking SE of
    peloid's observers, l refitted (rz_fit), its cost the prefixes' share of the five runs' cpu_seconds.
    Precision a is reached when 2 SE(l) <= a |l|; where no prefix reaches it, the cost is extrapolated from
    the full runs by SE ~ CPU^(-1/2)."""
    import h5py
    g1 = 87.3
    fits, check = {}, []
    by_pe = {}
    for p in sw["points"]:
        by_pe.setdefault(p["params"]["physical.gravity"] / g1, []).append(p)
    for pe, pts in sorted(by_pe.items()):
        if any(not p["summary"] for p in pts):
            continue
        series = []
        for p in pts:
            s = p["summary"]
            h = h5py.File(os.path.join(sw["_out"], p["id"], "observables.h5"), "r")["observables/settling_velocity"]
            down = h.attrs.get("positive", b"") in (b"down", "down")  # else dz/dt (outputs before issue 45)
            series.append((s, h["step"][:], h["value"][:] * (-1.0 if down else 1.0)))
        for f in RZ_PREFIXES:
            ok, cpu = [], 0.0
            for s, step, val in series:
                last = s["last_step"] * f
                m, e = blocking_se(val[step <= last])
                fr = 1.0 - s["mapping"]["colloid"]["volume_fraction_realised"]
                ok.append((s["mapping"]["colloid"]["volume_fraction_realised"], -m * fr, e * fr))
                cpu += s["cpu_seconds"] * f
                ref = [q for q in s["observables"]["settling_velocity"].get("se_vs_time", [])
                       if abs(q["run_fraction"] - f) < 1e-9]
                if ref:  # the observer's own prefix estimates: the same samples, so the same mean
                    rd = s["observables"]["settling_velocity"].get("positive") == "down"
                    check.append((abs(-m - (ref[0]["value"] if rd else -ref[0]["value"])) / ref[0]["stderr"],
                                  e / ref[0]["stderr"]))
            if all(q[1] > 0 for q in ok):
                l, l_se, vinf, _, chi2 = rz_fit(ok)
                fits.setdefault(pe, []).append({"f": f, "l": l, "se": l_se, "cpu": cpu, "chi2": chi2,
                                                "stat": l_se / max(1.0, chi2) ** 0.5,
                                                "steps": int(round(f * series[0][0]["last_step"]))})
    if not fits:
        return "no Pe finished", "incomplete", "", None
    guide = []
    gpe = 1.0 if 1.0 in fits else min(fits)  # the guide for Pe = 1 (Hecht's headline); Pe is physics, not a knob
    for a in (0.10, 0.03, 0.01):
        hit = [(x["cpu"], pe, x) for pe, r in fits.items() for x in r if 2 * x["se"] <= a * abs(x["l"]) and pe == gpe]
        if hit:
            cpu, pe, x = min(hit, key=lambda h: h[0])
            guide.append((f"{100 * a:g} %", f"Pe = {pe:g}, {x['steps']} steps per point", f"{cpu:.0f} s",
                          f" (measured: l = {x['l']:.2f} ± {x['se']:.2f}, {100 * x['se'] / abs(x['l']):.1f} %)"))
            continue
        ext = [(r[-1]["cpu"] * (2 * r[-1]["stat"] / (a * abs(r[-1]["l"]))) ** 2, pe) for pe, r in fits.items()
               if pe == gpe]
        cpu, pe = min(ext)
        x = fits[pe][-1]
        q = (2 * x["stat"] / (a * abs(x["l"]))) ** 2
        if x["chi2"] > 2.0:  # the misfit holds the scaled SE: a longer run does not reach a
            guide.append((f"{100 * a:g} %", f"Pe = {pe:g}: not by run length", "–",
                          f" (at the full runs the scaled SE is ± {x['se']:.2f}, χ²/dof = {x['chi2']:.1f}: the five "
                          f"velocities are off one power law by more than their SEs; the statistical SE alone, ± "
                          f"{x['stat']:.2f}, would reach {100 * a:g} % at ~{q * x['steps']:.0f} steps per point, "
                          f"~{cpu:.0f} s, by SE ∝ CPU^−½)"))
        else:
            guide.append((f"{100 * a:g} %", f"Pe = {pe:g}, ~{q * x['steps']:.0f} steps per point", f"~{cpu:.0f} s",
                          f" (extrapolated from the full runs, l = {x['l']:.2f} ± {x['stat']:.2f}, by SE ∝ CPU^−½)"))
    fr = RZ_PREFIXES
    table = ["| Pe | " + " | ".join(f"{fits[min(fits)][i]['steps']} steps" for i in range(len(fits[min(fits)]))) + " |",
             "|---|" + "---|" * len(fits[min(fits)])]
    for pe, r in sorted(fits.items()):
        table.append(f"| {pe:g} | " + " | ".join(f"l = {x['l']:.2f} ± {x['se']:.2f} ({100 * x['se'] / abs(x['l']):.0f} %; "
                                                  f"statistical ± {x['stat']:.2f}), χ²/dof {x['chi2']:.1f}, "
                                                  f"{x['cpu']:.0f} s" for x in r) + " |")
    chk = (f"  The prefix means equal the observer's own (`se_vs_time` in summary.json) to "
           f"{max(c[0] for c in check):.1e} SE and the SEs are {min(c[1] for c in check):.2f}–"
           f"{max(c[1] for c in check):.2f} of the observer's ({len(check)} prefixes)." if check else "")
    details = ("**Precision–cost guide, Richardson–Zaki exponent** (`studies/hecht_fig4_rz.cfg`, Richardson–Zaki's "
               "frame u (1 − φ), five φ per Pe).  l has no exact reference: Hecht's 3.5 and Richardson–Zaki's 4.65 "
               "are empirical fits, so this guide shows **precision only, not accuracy**: the SE of l against CPU "
               "seconds (the five runs' `cpu_seconds`, one thread, times the prefix's share).  Shorter runs are "
               "prefixes of the same runs (the observer samples from step 400): each point's mean settling "
               "velocity with the blocking SE of peloid's observers, l refitted by weighted least squares (SE "
               "scaled by √(χ²/dof) when above 1, as in the Fig. 4 row; the statistical SE, unscaled, beside it)."
               + chk + "  χ²/dof grows with the run length when the five velocities do not lie on one power law "
               "(their SEs shrink, the misfit stays): then the scaled SE of l levels off at the misfit and a "
               "longer run does not make l more precise, only the statistical part falls as CPU^−½." +
               "\n\n" + "\n".join(table) +
               f"\n\nCheapest run length at Pe = {gpe:g} for a precision a (2 SE(l) ≤ a l, the scaled SE; CPU "
               "seconds for the five points on one "
               "thread, about half that in wall time with two points side by side on the 2 cores):\n\n"
               "| precision | setting | CPU seconds |\n|---|---|---|\n"
               + "\n".join(f"| {acc} | {setting} | {cost}{note} |" for acc, setting, cost, note in guide))
    value = ("SE(l) at the full runs: " + ", ".join(f"Pe = {pe:g}: {100 * r[-1]['se'] / abs(r[-1]['l']):.1f} % "
                                                     f"({r[-1]['cpu']:.0f} s)" for pe, r in sorted(fits.items()))
             + "; " + "; ".join(f"{acc}: {setting}, {cost}" for acc, setting, cost, _ in guide))
    verdict = "precision only (no exact reference for l)"

    def plot(path):
        plt = pyplot()
        fig, ax = plt.subplots(1, 2, figsize=(11, 4.3))
        for i, (pe, r) in enumerate(sorted(fits.items())):
            ax[0].errorbar([x["cpu"] for x in r], [x["l"] for x in r], yerr=[x["se"] for x in r], marker="o",
                           capsize=2, color=f"C{i}", label=f"Pe = {pe:g}")
            ax[1].plot([x["cpu"] for x in r], [100 * x["se"] / abs(x["l"]) for x in r], marker="o", color=f"C{i}",
                       label=f"Pe = {pe:g}, scaled by √(χ²/dof)")
            ax[1].plot([x["cpu"] for x in r], [100 * x["stat"] / abs(x["l"]) for x in r], marker=".", ls="--",
                       color=f"C{i}", label=f"Pe = {pe:g}, statistical")
        c = [x["cpu"] for r in fits.values() for x in r]
        r0 = fits.get(1.0, fits[min(fits)])
        y0 = 100 * r0[0]["stat"] / abs(r0[0]["l"])
        ax[1].plot([r0[0]["cpu"], max(c)], [y0, y0 * (r0[0]["cpu"] / max(c)) ** 0.5], "k--", label="∝ CPU^−½")
        ax[0].axhline(3.5, color="grey", ls="--", lw=0.8)
        ax[0].text(min(c), 3.5, " Hecht 3.5 (empirical)", va="bottom", fontsize=7)
        ax[0].axhline(4.65, color="grey", ls="-.", lw=0.8)
        ax[0].text(min(c), 4.65, " Richardson–Zaki 4.65 (empirical)", va="bottom", fontsize=7)
        guide_axes(ax, "l (Richardson–Zaki frame), bars: SE", "SE(l) / l (%); dotted: 1, 3, 10 %", dev_lines=False,
                   xlabel="CPU seconds, five points (one thread)")
        ax[0].set_title("l from prefixes of the runs (no exact reference)", fontsize=9)
        ax[1].set_title("precision (not accuracy)", fontsize=9)
        ax[0].legend(fontsize=8)
        ax[1].legend(fontsize=8)
        save_figure(plt, fig, path)
    return value, verdict, details, plot


def reduced_fig4_rz(sw):
    """studies/reduced/hecht_fig4_rz.cfg, Pe = 1 in a (4 um)^3 box: hindered settling, the slip velocity u (the
    observer's, relative to the fluid) at phi = 0.35 below that at 0.05 by more than 3 combined SE (blocking
    SEs).  The full study's drop is 41 % (0.0428 -> 0.0253 a0/t0, ~25 combined SE); these short runs in the
    small box have SEs of ~5 % at each phi, so the expected drop is ~6 combined SE and 3 SE leaves a margin
    for the finite box.  Fails if u did not fall with phi (no hindrance) or if the runs were too noisy to say."""
    got = {}
    for p in sw["points"]:
        got[p["params"]["physical.volume_fraction"]] = rz_speed(p["summary"], "slip")
    (u1, e1), (u2, e2) = got[0.05], got[0.35]
    z = (u1 - u2) / (e1 * e1 + e2 * e2) ** 0.5
    pe = sw["points"][0]["params"].get("physical.gravity", 87.3) / 87.3  # the base scene's g is Pe = 1
    msg = (f"Pe = {pe:g}: slip u = {u1:.4f} +- {e1:.4f} at phi 0.05, {u2:.4f} +- {e2:.4f} at 0.35 a0/t0; "
           f"drop {100 * (1 - u2 / u1):.0f} %, {z:.1f} combined SE (bound > 3)")
    return u2 < u1 and z > 3.0, msg
