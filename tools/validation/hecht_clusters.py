"""Hecht et al. 2005 Figs. 9-14: suspended / clustered by the cluster rule and by Hecht's g(r) rule (the kappa
studies, the bond kinds, the (kappa, Psi0) diagram, the volume fractions of Figs. 12-13), the MSD slow-down of Fig. 14.

Part of tools/validation_report.py (validation/REPORT.md); each evaluator takes a loaded sweep and
returns (value, verdict[, details, plot])."""
import json
from validation.common import pyplot, save_figure
from validation.hecht_rdf import FIG5_PEAKS, contact_peaks, present, rdf_of


def cluster_state(fraction):
    """The Fig. 9 studies' rule: clustered when the largest cluster (second-half mean) holds more than 10 %
    of the colloids."""
    return "clustered" if fraction > 0.10 else "suspended"


def fig9_point(sw, p, rng):
    """One finished Fig. 9 point by both rules of fig9_kappa: the largest cluster (second-half mean) as a
    fraction of the colloids and the cluster rule's state; the contact peaks B-D of g(r) present (PEAK_SE)
    and the g(r) rule's state."""
    n = p["summary"]["mapping"]["colloid"]["n_colloids"]
    lc = p["summary"]["observables"]["largest_cluster"]
    frac, se = lc["value"] / n, lc["stderr"] / n
    first, peaks = contact_peaks(*rdf_of(sw, p), rng)
    more = [lab for lab, _, _ in FIG5_PEAKS if present(peaks[lab])]
    return {"n": n, "lc": lc, "frac": frac, "se": se, "state": cluster_state(frac), "peaks": peaks, "more": more,
            "gr_state": "clustered" if more else "suspended"}


def describe_fig9_point(q):
    lc, more, peaks = q["lc"], q["more"], q["peaks"]
    return (f"largest cluster {lc['value']:.1f} ± {lc['stderr']:.1f} of {q['n']} ({100 * q['frac']:.1f} ± "
            f"{100 * q['se']:.1f} %) → {q['state']}; g(r) peaks beyond the first: "
            + (", ".join(f"{lab} ({peaks[lab][2]:.0f} SE)" for lab in more) if more else "none")
            + f" → {q['gr_state']}")


def fig9_kappa(sw):
    """Two rules, each stated before the runs it judges: the cluster rule (clustered when the largest
    cluster, second-half mean, holds > 10 % of the colloids) and Hecht's g(r) rule (Sec. X.B: suspended
    particles show only the first peak; clustered ones more, the contact-geometry peaks B-D)."""
    import numpy as np
    rng = np.random.default_rng(9)
    rows, states, gr_states = [], {}, {}
    for p in sw["points"]:
        k = p["params"]["physical.kappa"]
        seed = p["params"].get("seed")
        if not p["summary"]:
            rows.append(f"κ = {k:.2g} /m: {p['status']} ({p['message']})")
            continue
        q = fig9_point(sw, p, rng)
        states[k], gr_states[k] = q["state"], q["gr_state"]
        rows.append(f"κ = {k:.2g} /m{f' (seed {seed})' if seed else ''}: " + describe_fig9_point(q))
    want = {1.4e8: "suspended", 1.6e8: "clustered"}
    want = {k: v for k, v in want.items() if any(p["params"]["physical.kappa"] == k for p in sw["points"])}
    if not want or not all(k in states for k in want):
        return "<br>".join(rows), "incomplete: a point at κ = 1.4e8 or 1.6e8 did not finish"
    verdicts = []
    for rule, st in (("cluster rule", states), ("g(r) rule", gr_states)):
        if all(st[k] == v for k, v in want.items()):
            verdicts.append(f"agrees ({rule}): " + ", ".join(f"{v} at {k:.2g}" for k, v in sorted(want.items())) + " /m")
        else:
            verdicts.append(f"**disagrees** ({rule}): peloid has " + ", ".join(f"{st[k]} at {k:.2g}" for k in sorted(want))
                            + " /m (Hecht: " + ", ".join(f"{v} at {k:.2g}" for k, v in sorted(want.items())) + ")")
    return "<br>".join(rows), "; ".join(verdicts)


def fig9_bonds(sw):
    """Primary vs secondary energy bonds per colloid (second-half means +- SE)."""
    rows, prim = [], {}
    for p in sw["points"]:
        k = p["params"]["physical.kappa"]
        if not p["summary"]:
            rows.append(f"κ = {k:.2g} /m: {p['status']} ({p['message']})")
            continue
        n = p["summary"]["mapping"]["colloid"]["n_colloids"]
        ob = p["summary"]["observables"]
        b1, b2, lc = ob["cluster_bonds_primary"], ob["cluster_bonds_secondary"], ob["largest_cluster"]
        prim[k] = (b1["value"] / n, b1["stderr"] / n, b2["value"] / n)
        rows.append(f"κ = {k:.2g} /m: bonds per colloid {b1['value'] / n:.3f} ± {b1['stderr'] / n:.3f} primary, "
                    f"{b2['value'] / n:.3f} ± {b2['stderr'] / n:.3f} secondary; largest cluster "
                    f"{lc['value']:.1f} ± {lc['stderr']:.1f} of {n}")
    if 1.4e8 not in prim:
        return "<br>".join(rows), "incomplete: κ = 1.4e8 /m did not finish"
    b1, se1, b2 = prim[1.4e8]
    kind = "primary" if b1 > b2 else "secondary"
    verdict = (f"at κ = 1.4e8 /m peloid's bonds are mostly {kind}-minimum bonds ({b1:.3f} primary vs "
               f"{b2:.3f} secondary per colloid)")
    return "<br>".join(rows), verdict


def reduced_fig9_bonds(sw):
    """studies/reduced/hecht_fig9_bonds.cfg, kappa = 1.4e8 /m, Psi0 = 20 mV in the (4 um)^3 box for 0.17 s: the full
    study's headline, the bonds (pair energy below -1 kT) are secondary-minimum bonds.  Bound: at least 0.5
    secondary bonds per colloid (the full study: 1.56; this run ~1.2 +- 0.01), and primary bonds at most a tenth
    of them (the full study: none).  Fails when the colloids do not bond (a repulsive scene) or bond mostly in the
    primary minimum (a barrier that no longer shields it)."""
    p = sw["points"][0]
    n = p["summary"]["mapping"]["colloid"]["n_colloids"]
    ob = p["summary"]["observables"]
    b1, b2 = ob["cluster_bonds_primary"], ob["cluster_bonds_secondary"]
    prim, sec = b1["value"] / n, b2["value"] / n
    msg = (f"kappa {p['params']['physical.kappa']:.2g}: bonds per colloid {prim:.3f} +- {b1['stderr'] / n:.3f} primary, "
           f"{sec:.3f} +- {b2['stderr'] / n:.3f} secondary (bound: secondary >= 0.5, primary <= 0.1 x secondary)")
    return sec >= 0.5 and prim <= 0.1 * sec, msg

def dlvo_shape(summary):
    """The point's DLVO (Hecht Eqs. 1-2 as `peloid params` writes it into summary.json): barrier and
    secondary-minimum depth in kT, None where the potential has none."""
    import re
    txt = json.dumps(summary)
    b = re.search(r"barrier (-?[0-9.e+-]+) kT", txt)
    m = re.search(r"secondary minimum (-?[0-9.e+-]+) kT at gap", txt)
    return (float(b.group(1)) if b else None), (float(m.group(1)) if m else None)


RANK = {"suspended": 0, "clustered": 1}
RULES = (("cluster rule", "state"), ("g(r) rule", "gr_state"))


def fig9_points(sw, keys):
    """Each point of a Fig. 9 study by both rules, keyed by its values of keys; a point that did not finish
    is {"failed": its status and exit message}."""
    import numpy as np
    rng = np.random.default_rng(9)
    pts = {}
    for p in sw["points"]:
        at = tuple(p["params"][k] for k in keys)
        if not p["summary"]:
            pts[at] = {"failed": f"{p['status']} (exit {p.get('exit_code')}): " + p["message"].replace("peloid: error: ", "")}
            continue
        q = fig9_point(sw, p, rng)
        q["barrier"], q["secondary"] = dlvo_shape(p["summary"])
        q["phi"] = p["summary"]["mapping"]["colloid"]["volume_fraction_realised"]
        pts[at] = q
    return pts


def boundaries(line, key, fmt):
    """The verdict along an ordered line [(x, point)] of finished points as runs of equal verdicts, e.g.
    'suspended 7.3e7–1e8, clustered 1.4e8–3e8' (a non-monotone line shows every run)."""
    runs = []
    for x, q in line:
        if "failed" in q:
            continue
        if runs and runs[-1][0] == q[key]:
            runs[-1][2] = x
        else:
            runs.append([q[key], x, x])
    return ", ".join(f"{st} {fmt(a)}" + (f"–{fmt(b)}" if b != a else "") for st, a, b in runs) or "no finished point"


def fmt_kappa(k):
    return f"{k:.2g}".replace("e+0", "e")


def fmt_psi(s):
    return f"{1000 * s:g} mV"


def fig9_grow(line, key):
    """Hecht Fig. 11, at one kappa: does clustering grow with Psi0 (the line ordered by Psi0)?  agrees / disagrees
    / not resolved, and why (rule S4 of studies/hecht_fig9_diagram.cfg)."""
    done = [(x, q) for x, q in line if "failed" not in q]
    if len(done) < 2:
        return None, "not judged: fewer than two finished points"
    ranks = [RANK[q[key]] for _, q in done]
    steps = [b - a for a, b in zip(ranks, ranks[1:])]
    seq = ", ".join(f"{q[key]} at {1000 * x:g} mV" for x, q in done)
    if any(d < 0 for d in steps):
        return False, f"the verdict falls from clustered to suspended as Ψ0 rises ({seq})"
    if any(d > 0 for d in steps):
        return True, f"the verdict rises from suspended to clustered ({seq})"
    if key == "state":
        (x0, a), (x1, b) = done[0], done[-1]
        d, e = b["frac"] - a["frac"], (a["se"] ** 2 + b["se"] ** 2) ** 0.5
        how = (f"{seq}; largest cluster {100 * a['frac']:.1f} ± {100 * a['se']:.1f} % at {1000 * x0:g} mV, "
               f"{100 * b['frac']:.1f} ± {100 * b['se']:.1f} % at {1000 * x1:g} mV ({d / max(e, 1e-12):+.1f} SE)")
        if d > 3 * e:
            return True, how
        if d < -3 * e:
            return False, how
        return None, how + ": within 3 SE"
    return None, f"the same verdict at every Ψ0 ({seq})"


def count_statements(res):
    """'k of n agree' over the decided statements, and how many were not (a point did not finish, or S4 not
    resolved)."""
    judged = [r for r in res if r is not None]
    return f"{sum(judged)} of {len(judged)} agree" + (f" ({len(res) - len(judged)} not decided)" if len(judged) < len(res) else "")


def verdict_word(ok):
    return "agrees" if ok else ("**disagrees**" if ok is False else "not resolved")


def fig9_diagram(sw):
    """Hecht Fig. 9 (kappa x Psi0 at phi = 0.14) by both rules; statements S1-S4 of studies/hecht_fig9_diagram.cfg,
    agreement counted per statement and rule."""
    pts = fig9_points(sw, ["physical.kappa", "physical.surface_potential"])
    kap = sorted({k for k, _ in pts})
    psi = sorted({s for _, s in pts})

    def state(k, s, key):
        q = pts.get((k, s))
        return None if q is None or "failed" in q else q[key]

    verdicts, value, counts = [], [], []
    for rule, key in RULES:
        res, words = [], []
        for name, (k, s), want, what in (("S1", (2.0e8, 0.02), "clustered", "upper left: κ = 2e8, 20 mV"),
                                          ("S2", (7.3e7, 0.05), "suspended", "lower right: κ = 7.3e7, 50 mV")):
            got = state(k, s, key)
            ok = None if got is None else got == want
            res.append(ok)
            words.append(f"{name} ({what}) " + (f"{verdict_word(ok)}: {got}" if got else "not judged: the point did not finish")
                         + f", Hecht {want}")
        a, b = state(1.4e8, 0.02, key), state(1.6e8, 0.02, key)
        ok = None if a is None or b is None else (a == "suspended" and b == "clustered")
        res.append(ok)
        words.append(f"S3 (20 mV, boundary in 1.4e8–1.6e8) {verdict_word(ok) if ok is not None else 'not judged'}: "
                     f"{a or 'not finished'} at 1.4e8, {b or 'not finished'} at 1.6e8")
        ok, why = fig9_grow([(s, pts[(2.0e8, s)]) for s in psi if s >= 0.02 and (2.0e8, s) in pts], key)
        res.append(ok)
        words.append(f"S4 (κ = 2e8, clustering grows with Ψ0, 20–50 mV) "
                     + (why if why.startswith("not judged") else f"{verdict_word(ok)}: {why}"))
        counts.append(f"{rule}: {count_statements(res)}")
        verdicts.append(f"{rule}: " + "; ".join(words))
    for rule, key in RULES:
        value.append(f"peloid's boundary by the {rule}, along κ at each Ψ0: "
                     + "; ".join(f"{fmt_psi(s)}: " + boundaries([(k, pts[(k, s)]) for k in kap if (k, s) in pts], key,
                                                                 fmt_kappa) for s in psi)
                     + "; along Ψ0 at each κ (/m): "
                     + "; ".join(f"{fmt_kappa(k)}: " + boundaries([(s, pts[(k, s)]) for s in psi if (k, s) in pts], key,
                                                                   fmt_psi) for k in kap))
    failed = [f"κ = {k:.2g}, Ψ0 = {1000 * s:g} mV: {q['failed']}" for (k, s), q in sorted(pts.items()) if "failed" in q]
    if failed:
        value.append("failed points: " + "; ".join(failed))

    # details: the diagram as a table, kappa rising upwards as in Fig. 9 (clustering upper left)
    head = "| κ (/m) \\ Ψ0 | " + " | ".join(f"{1000 * s:g} mV" for s in psi) + " |"
    lines = ["**Hecht Fig. 9 diagram (studies/hecht_fig9_diagram.cfg), every point.**  Cell: cluster rule "
             "(largest cluster, % of the colloids ± SE) / g(r) rule (contact peaks B–D present at 5 SE); the "
             "DLVO secondary minimum and barrier of the point (`peloid params`).", "", head,
             "|---|" + "---|" * len(psi)]
    for k in reversed(kap):
        cells = []
        for s in psi:
            q = pts.get((k, s))
            if q is None:
                cells.append("–")
            elif "failed" in q:
                cells.append(q["failed"])
            else:
                dl = (f"min {q['secondary']:.2g} kT" if q["secondary"] is not None else "no secondary min") + \
                     (f", barrier {q['barrier']:.3g} kT" if q["barrier"] is not None else ", no barrier")
                cells.append(f"{q['state']} {100 * q['frac']:.1f} ± {100 * q['se']:.1f} % / {q['gr_state']} "
                             f"({', '.join(q['more']) or 'no B–D'}); {dl}")
        lines.append(f"| {fmt_kappa(k)} | " + " | ".join(cells) + " |")
    details = "\n".join(lines)

    def plot(path):
        import textwrap
        plt = pyplot()
        fig, axes = plt.subplots(1, 2, figsize=(13, 6.2), sharey=True)
        col = {"clustered": "C3", "suspended": "C0"}
        for ax, (rule, key) in zip(axes, RULES):
            ax.axvspan(-0.5, 0.5, color="0.92", zorder=0) if psi and psi[0] < 0.02 else None
            for (k, s), q in pts.items():
                x, y = psi.index(s), kap.index(k)
                if "failed" in q:
                    ax.plot(x, y, "x", color="0.4", ms=12, mew=2)
                    short = ":".join(q["failed"].split(":")[:2])  # 'failed (exit N): the guard'; the table has it all
                    ax.text(x + 0.14, y, "\n".join(textwrap.wrap(short, 18)), fontsize=6.5, va="center", color="0.3")
                    continue
                ax.plot(x, y, "o", color=col[q[key]], ms=16)
                if key == "state":
                    d = 1 if q["frac"] < 0.1 else 0
                    label = f"{100 * q['frac']:.{d}f} ± {100 * q['se']:.{d}f} %"
                    sec = f"{q['secondary']:.1f} kT" if q["secondary"] is not None else "no sec. min"
                    ax.text(x + 0.14, y - 0.16, sec, fontsize=6.5, va="center", color="0.35")
                else:
                    label = ",".join(q["more"]) or "A only"
                ax.text(x + 0.14, y + 0.09, label, fontsize=8, va="center")
            # Hecht's statements
            for (k, s), lab in (((2.0e8, 0.02), "S1: Hecht clustered"), ((7.3e7, 0.05), "S2: Hecht suspended")):
                if (k, s) in pts:
                    ax.plot(psi.index(s), kap.index(k), "o", mfc="none", mec="k", ms=24, mew=1.2)
                    ax.text(psi.index(s), kap.index(k) - 0.36, lab, fontsize=7, ha="center")
            if 1.4e8 in kap and 1.6e8 in kap and 0.02 in psi:
                y = kap.index(1.4e8) + 0.5
                ax.plot([psi.index(0.02) - 0.4, psi.index(0.02) + 0.4], [y, y], "k--", lw=1.5)
                ax.text(psi.index(0.02) - 0.45, y, "S3: Hecht's boundary", fontsize=7, ha="right", va="center")
            if 2.0e8 in kap and 0.02 in psi:
                y = kap.index(2.0e8) + 0.5
                ax.annotate("", xy=(len(psi) - 1 + 0.2, y), xytext=(psi.index(0.02) + 0.2, y),
                            arrowprops=dict(arrowstyle="->", lw=1))
                ax.text(len(psi) - 1.3, y + 0.08, "S4: Hecht, clustering grows with Ψ0", fontsize=7, ha="center")
            ax.set_xticks(range(len(psi)))
            ax.set_xticklabels([f"{1000 * s:g}" for s in psi])
            ax.set_yticks(range(len(kap)))
            ax.set_yticklabels([f"{k / 1e8:.2g}" for k in kap])
            ax.set_xlim(-0.5, len(psi) - 0.1)
            ax.set_ylim(-0.6, len(kap) - 0.2)
            ax.set_xlabel("Ψ0 (mV)" + (" (grey: left of Fig. 9's left column, 20 mV)" if psi and psi[0] < 0.02 else ""))
            ax.set_title(f"{rule}: red clustered, blue suspended" + (" (largest cluster beside; grey: DLVO secondary minimum)"
                                                                      if key == "state" else " (g(r) peaks B–D beside)"),
                         fontsize=9)
        axes[0].set_ylabel("κ (10⁸ /m)")
        fig.suptitle("Hecht Fig. 9: Al2O3, R = 0.25 µm, φ = 0.14 (472 colloids), 1140 steps = 0.64 s, seed 9", fontsize=10)
        save_figure(plt, fig, path)
    return "<br>".join(value), "; ".join(counts) + "<br>" + "<br>".join(verdicts), details, plot


def fig9_phi(sw):
    """Hecht Figs. 12-13: the verdict per volume fraction at kappa = 1.4e8 (Hecht: suspended) and 1.6e8 /m
    (clustered), Psi0 = 20 mV; statements S5, S6 of studies/hecht_fig9_phi.cfg per rule."""
    pts = fig9_points(sw, ["physical.kappa", "physical.volume_fraction"])
    rows = []
    for (k, f), q in sorted(pts.items()):
        rows.append(f"κ = {fmt_kappa(k)} /m, φ = {f:g}: " + (q["failed"] if "failed" in q else
                                                      f"{q['n']} colloids, " + describe_fig9_point(q)))
    verdicts, counts = [], []
    for rule, key in RULES:
        res, words = [], []
        for name, k, want in (("S5 (Fig. 12)", 1.4e8, "suspended"), ("S6 (Fig. 13)", 1.6e8, "clustered")):
            line = [(f, q) for (kk, f), q in sorted(pts.items()) if kk == k]
            done = [(f, q[key]) for f, q in line if "failed" not in q]
            ok = None if len(done) < len(line) or not done else all(st == want for _, st in done)
            res.append(ok)
            good = sum(st == want for _, st in done)
            words.append(f"{name} {verdict_word(ok)}: {want} at κ = {fmt_kappa(k)} at {good} of {len(line)} φ ("
                         + ", ".join(f"{st} at {f:g}" for f, st in done) + ")")
        counts.append(f"{rule}: {count_statements(res)}")
        verdicts.append(f"{rule}: " + "; ".join(words))

    def plot(path):
        plt = pyplot()
        fig, ax = plt.subplots(1, 3, figsize=(14, 4.6))
        col = {"clustered": "C3", "suspended": "C0"}
        for j, (k, mk) in enumerate(((1.4e8, "o"), (1.6e8, "s"))):
            line = [(f, q) for (kk, f), q in sorted(pts.items()) if kk == k and "failed" not in q]
            if not line:
                continue
            ax[0].errorbar([q["phi"] for _, q in line], [100 * q["frac"] for _, q in line],
                           yerr=[100 * q["se"] for _, q in line], color="k", lw=0.8, capsize=2,
                           label=f"κ = {fmt_kappa(k)} /m (Hecht: {'suspended' if k < 1.5e8 else 'clustered'})", marker=mk,
                           mfc="none", mec="k", ms=9)
            for f, q in line:
                ax[0].plot(q["phi"], 100 * q["frac"], mk, color=col[q["state"]], ms=9)
                ax[0].text(q["phi"] + 0.006, 100 * q["frac"] - 1, ",".join(q["more"]) or "A only", fontsize=7, ha="left",
                           va="top", color=col[q["gr_state"]])
            p_by = {p["params"]["physical.volume_fraction"]: p for p in sw["points"]
                    if p["params"]["physical.kappa"] == k and p["summary"]}
            for i, (f, q) in enumerate(line):
                x, g, se = rdf_of(sw, p_by[f])
                ax[1 + j].plot(x, g + 2.0 * i, color=col[q["gr_state"]], lw=1)
                ax[1 + j].text(x[-1], 2.0 * i + 1.1, f"φ = {q['phi']:.3f}", fontsize=7, ha="right")
            for lab, fac, _ in [("A", 1.0, None)] + FIG5_PEAKS:
                ax[1 + j].axvline(2 * fac, color="grey", ls=":", lw=0.7)
            ax[1 + j].set_xlim(1.5, x[-1])
            ax[1 + j].set_ylim(0, 2.0 * len(line) + 6)
            ax[1 + j].set_xlabel("r / R (dotted: touching-sphere peaks A–D)")
            ax[1 + j].set_ylabel("g(r), shifted by 2 per φ (clipped)")
            ax[1 + j].set_title(f"κ = {fmt_kappa(k)} /m, Ψ0 = 20 mV (Hecht Fig. {12 if k < 1.5e8 else 13}); colour: g(r) rule",
                                fontsize=9)
        ax[0].axhline(10, color="grey", ls="--", lw=0.8)
        ax[0].set_xlabel("φ (realised)")
        ax[0].set_ylabel("largest cluster (% of colloids), second-half mean ± SE")
        ax[0].set_title("cluster rule (marker colour; dashed: 10 %); text: B–D peaks (colour: g(r) rule)", fontsize=8)
        ax[0].legend(fontsize=7)
        save_figure(plt, fig, path)
    return "<br>".join(rows), "; ".join(counts) + "<br>" + "<br>".join(verdicts), None, plot


def fig14_msd(sw):
    """D over the first and the last quarter of the run; slowed down when D(late) < D(early) by > 3 SE."""
    got = {}
    for p in sw["points"]:
        if not p["summary"]:
            return f"{p['id']}: {p['status']} ({p['message']})", "incomplete"
        d = p["summary"]["observables"]["colloid_D"]
        start = p["params"]["observe.msd_start"]
        got[start] = (d["value"], d["stderr"], start, p["params"]["steps"], p["summary"])
    if len(got) < 2:
        return "a point is missing", "incomplete"
    (e, e_se, e0, e1, se), (l, l_se, l0, l1, sl) = [got[k] for k in sorted(got)]
    t0 = se["scene"]["srd"]["dt"] * se["units_si"]["t0_s"] if "units_si" in se else None
    def span(a, b):
        return f"steps {a}–{b}" + (f" ({a * t0:.2f}–{b * t0:.2f} s)" if t0 else "")
    z = (e - l) / (e_se ** 2 + l_se ** 2) ** 0.5
    n = se["mapping"]["colloid"]["n_colloids"]
    row = (f"D over {span(e0, e1)}: {e:.3g} ± {e_se:.2g} a0²/t0; over {span(l0, l1)}: {l:.3g} ± {l_se:.2g} "
           f"({l / e:.2f} of the early value); {n} colloids")
    verdict = ("agrees" if z > 3 else "**disagrees**") + \
        f": the colloids slow down by {100 * (1 - l / e):.0f} % ({z:.1f} combined SE; Hecht: diffusion, then a slow-down as clusters form)"
    return row, verdict


def reduced_fig9_kappa(sw):
    """studies/reduced/hecht_fig9_kappa.cfg: suspended at 1.0e8 /m, clustered at 2.0e8 /m (the full rule)."""
    got = {}
    for p in sw["points"]:
        k = p["params"]["physical.kappa"]
        n = p["summary"]["mapping"]["colloid"]["n_colloids"]
        lc = p["summary"]["observables"]["largest_cluster"]
        got[k] = (cluster_state(lc["value"] / n), 100 * lc["value"] / n, 100 * lc["stderr"] / n)
    msg = "; ".join(f"kappa {k:.2g}: largest cluster {f:.1f} +- {e:.1f} % -> {s}" for k, (s, f, e) in sorted(got.items()))
    return got[1.0e8][0] == "suspended" and got[2.0e8][0] == "clustered", msg


def reduced_fig9_diagram(sw):
    """studies/reduced/hecht_fig9_diagram.cfg, the Psi0 direction along kappa = 2e8 /m (Hecht Fig. 11): the full
    study's direction, clustering falls as Psi0 rises (largest cluster 99.8 % at 20 mV, 18.4 % at 50 mV).  Bound:
    clustered at 20 mV by the full rule (> 10 %) and the largest-cluster fraction at 50 mV below that at 20 mV
    by more than 30 percentage points (the full study's gap is 81; in half the time fewer 50 mV pairs have
    crossed into the -3.1 kT secondary minimum, while 20 mV, without a barrier, clusters within 0.1 s).
    Fails if clustering grew with Psi0 as Hecht's Fig. 11 caption says, or if 20 mV did not cluster."""
    got = {}
    for p in sw["points"]:
        s = p["params"]["physical.surface_potential"]
        n = p["summary"]["mapping"]["colloid"]["n_colloids"]
        lc = p["summary"]["observables"]["largest_cluster"]
        got[s] = (lc["value"] / n, lc["stderr"] / n)
    (f20, e20), (f50, e50) = got[0.02], got[0.05]
    msg = (f"kappa 2e8: largest cluster {100 * f20:.1f} +- {100 * e20:.1f} % at 20 mV ({cluster_state(f20)}), "
           f"{100 * f50:.1f} +- {100 * e50:.1f} % at 50 mV ({cluster_state(f50)}); drop {100 * (f20 - f50):.1f} points "
           f"(bound > 30)")
    return cluster_state(f20) == "clustered" and f20 - f50 > 0.30, msg


def reduced_fig14_msd(sw):
    """studies/reduced/hecht_fig14_msd.cfg (179 colloids, 240 steps): the full study's headline and rule, the
    colloids slow down as they cluster, D from the MSD over the last quarter (steps 180-240) below D over the
    first (0-60) by more than 3 combined SE (the SEs over colloids of this run: the same rule is looser here by
    the larger SE).  Fails if the late D were not clearly lower, e.g. a repulsive scene or swapped windows."""
    got = {}
    for p in sw["points"]:
        d = p["summary"]["observables"]["colloid_D"]
        got[p["params"]["observe.msd_start"]] = (d["value"], d["stderr"], p["params"]["steps"])
    if len(got) < 2:
        return False, "a point is missing"
    (s0, (e, e_se, e1)), (s1, (l, l_se, l1)) = sorted(got.items())
    z = (e - l) / (e_se ** 2 + l_se ** 2) ** 0.5
    return z > 3, (f"D over steps {s0}-{e1} {e:.3g} +- {e_se:.2g}, over {s1}-{l1} {l:.3g} +- {l_se:.2g} a0^2/t0 "
                   f"({l / e:.2f} of early, {z:.1f} combined SE; bound > 3)")


def reduced_fig9_phi(sw):
    """studies/reduced/hecht_fig9_phi.cfg, kappa = 1.4e8 /m, Psi0 = 20 mV in the (4 um)^3 box for 0.17 s: the
    largest cluster grows with phi.  Bound: its fraction of the colloids at phi = 0.21 exceeds that at 0.07 by
    more than 30 percentage points (the full study's gap is 76 points, 6.6 % -> 82.5 %; the second-half SEs
    here are ~1-2 points, so 30 points leaves room for the smaller box and shorter run).  Fails if the
    largest cluster did not grow with phi or grew only a little."""
    got = {}
    for p in sw["points"]:
        phi = p["params"]["physical.volume_fraction"]
        n = p["summary"]["mapping"]["colloid"]["n_colloids"]
        lc = p["summary"]["observables"]["largest_cluster"]
        got[phi] = (lc["value"] / n, lc["stderr"] / n, n)
    (f1, e1, n1), (f2, e2, n2) = got[0.07], got[0.21]
    kappa = sw["points"][0]["params"]["physical.kappa"]
    msg = (f"kappa {kappa:.2g}: largest cluster {100 * f1:.1f} +- {100 * e1:.1f} % of {n1} at phi 0.07 ({cluster_state(f1)}), "
           f"{100 * f2:.1f} +- {100 * e2:.1f} % of {n2} at 0.21 ({cluster_state(f2)}); growth {100 * (f2 - f1):.1f} "
           f"points (bound > 30)")
    return f2 - f1 > 0.30, msg
