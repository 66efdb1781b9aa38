"""Hecht et al. 2005 Figs. 5-7: the g(r) peaks A-D of the contact geometry and the first peak at the secondary minimum.

Part of tools/validation_report.py (validation/REPORT.md); each evaluator takes a loaded sweep and
returns (value, verdict[, details, plot])."""
import json
import os
import re
from validation.common import pyplot, save_figure


# Hecht Fig. 5's labelled peaks as multiples of the contact distance d (2R for touching spheres, 2R plus
# the gap of the minimum that holds the pair otherwise): A two in contact (d), B two in contact with the
# same three mutually touching ((2/3) sqrt(6) d = (4/3) sqrt(6) R), C two in contact with the same two
# touching, in a plane (sqrt(3) d = 2 sqrt(3) R), D two in contact with one, on a line (2 d = 4R).  The
# search windows split the gaps between them (B and C are 6 % apart).
FIG5_PEAKS = [("B", 2.0 / 3.0 * 6 ** 0.5, (1.55, 1.68)), ("C", 3 ** 0.5, (1.68, 1.80)), ("D", 2.0, (1.88, 2.12))]


def rdf_peak(x, g, se, lo, hi, rng, draws=400):
    """The highest local maximum of g with its bin in [lo, hi]: the parabola through that bin and its
    neighbours; its SE by redrawing g within its per-bin SE; its significance: its height above the chord
    between the bins just outside the window, in SE.  None when the window holds no local maximum."""
    import numpy as np
    idx = np.where((x >= lo) & (x <= hi))[0]
    idx = idx[(idx > 0) & (idx < len(g) - 1)]
    if len(idx) == 0 or idx[0] < 1 or idx[-1] > len(g) - 2:
        return None

    def vertex(gg):
        loc = [k for k in idx if gg[k] >= gg[k - 1] and gg[k] >= gg[k + 1]]
        if not loc:
            return None, None
        k = max(loc, key=lambda q: gg[q])
        y0, y1, y2 = gg[k - 1], gg[k], gg[k + 1]
        den = y0 - 2 * y1 + y2
        off = 0.5 * (y0 - y2) / den if den < 0 else 0.0
        return k, x[k] + max(-1.0, min(1.0, off)) * (x[k + 1] - x[k])
    i, pos = vertex(g)
    if i is None:
        return None
    a, b = idx[0] - 1, idx[-1] + 1
    base = g[a] + (g[b] - g[a]) * (x[i] - x[a]) / (x[b] - x[a])
    sig = (g[i] - base) / max(1e-300, (se[i] ** 2 + 0.5 * (se[a] ** 2 + se[b] ** 2)) ** 0.5)
    sims = [q for q in (vertex(g + rng.normal(0.0, 1.0, len(g)) * se)[1] for _ in range(draws)) if q is not None]
    return pos, float(np.std(sims)) if sims else float("nan"), sig, float(x[1] - x[0])


def rdf_of(sw, p):
    """The point's final g(r): r / R, value, SE (observables.h5)."""
    import h5py
    h = h5py.File(os.path.join(sw["_out"], p["id"], "observables.h5"), "r")["observables/colloid_rdf"]
    return h["r_over_R"][:], h["value"][-1], h["value_se"][-1]


def contact_peaks(x, g, se, rng):
    """The first peak of g(r) (r in R, 1.8-3 R) and Hecht's peaks B-D in windows scaled by its position:
    (first, {label: (position, SE, significance) or None})."""
    first = rdf_peak(x, g, se, 1.8, 3.0, rng)
    if not first:
        return None, {lab: None for lab, _, _ in FIG5_PEAKS}
    d = first[0]
    return first, {lab: rdf_peak(x, g, se, lo * d, hi * d, rng) for lab, _, (lo, hi) in FIG5_PEAKS}


# A peak is present when it stands 5 SE above its window's chord: each window takes the highest of its
# ~5-10 bins' local maxima, so noise alone reaches 3 SE in a window far more often than a single bin would.
PEAK_SE = 5.0


def present(pk):
    return pk is not None and pk[2] >= PEAK_SE


def describe_peaks(first, peaks):
    if not first:
        return "no first peak in 1.8–3 R"
    parts = [f"first peak (A) {first[0]:.3f} ± {first[1]:.3f} R (SE of the position from the bin values; bins of "
             f"{first[3]:.3f} R)"]
    for lab, f, _ in FIG5_PEAKS:
        pk = peaks[lab]
        if present(pk):
            parts.append(f"{lab} {pk[0]:.3f} ± {pk[1]:.3f} R (= {pk[0] / first[0]:.3f} A; geometry {f:.3f} A, "
                         f"Hecht {2 * f:.3f} R; {pk[2]:.0f} SE high)")
        else:
            parts.append(f"{lab} absent" + (f" ({pk[2]:.1f} SE)" if pk else ""))
    return ", ".join(parts)


def fig5_rdf(sw):
    """Peaks A-D of Hecht Fig. 5 in the attractive point, their absence and the first peak at the secondary
    minimum in the repulsive one (Figs. 6-7)."""
    import re
    import numpy as np
    rng = np.random.default_rng(5)
    rows, found = [], {}
    for p in sw["points"]:
        k = p["params"]["physical.kappa"]
        if not p["summary"]:
            rows.append(f"κ = {k:.2g} /m: {p['status']} ({p['message']})")
            continue
        x, g, se = rdf_of(sw, p)
        R = p["summary"]["mapping"]["colloid"]["radius_a0"]
        m = re.search(r"secondary minimum (-?[0-9.e+-]+) kT at gap ([0-9.e+-]+) a0", json.dumps(p["summary"]))
        r_sec = 2.0 + float(m.group(2)) / R if m else None
        first, peaks = contact_peaks(x, g, se, rng)
        found[k] = (peaks, first, r_sec)
        rows.append(f"κ = {k:.2g} /m: " + describe_peaks(first, peaks) +
                    (f"; secondary minimum at {r_sec:.3f} R ({m.group(1)} kT)" if r_sec else ""))
    verdicts = []
    if 3.0e8 in found:
        peaks, first, r_sec = found[3.0e8]
        have = [lab for lab, _, _ in FIG5_PEAKS if present(peaks[lab])]
        verdicts.append(("agrees" if len(have) == 3 else "**disagrees**") +
                        f" at 3e8: peaks {', '.join(['A'] + have) if first else 'none'} of A–D present")
    if 7.3e7 in found:
        peaks, first, r_sec = found[7.3e7]
        none = [lab for lab, _, _ in FIG5_PEAKS if not present(peaks[lab])]
        at_sec = first and r_sec and abs(first[0] - r_sec) <= max(3 * first[1], 0.05)
        verdicts.append(("agrees" if len(none) == 3 and at_sec else "**disagrees**") +
                        f" at 7.3e7: B–D {'absent' if len(none) == 3 else 'not all absent'}, first peak "
                        + (f"{first[0]:.3f} R vs the secondary minimum {r_sec:.3f} R (within 3 SE or 0.05 R: "
                           f"{'yes' if at_sec else 'no'})" if first and r_sec else "not found"))

    def plot(path):
        plt = pyplot()
        pts = [q for q in sw["points"] if q["summary"]]
        fig, ax = plt.subplots(len(pts), 1, figsize=(8, 3.3 * len(pts)), sharex=True, squeeze=False)
        for a, p in zip(ax[:, 0], pts):
            x, g, se = rdf_of(sw, p)
            k = p["params"]["physical.kappa"]
            psi = p["params"].get("physical.surface_potential", p["summary"]["scene"]["physical"]["surface_potential"])
            a.fill_between(x, g - se, g + se, color="C0", alpha=0.3, lw=0)
            a.plot(x, g, "C0", lw=1, label=f"peloid, Ψ0 = {1000 * psi:g} mV, κ = {k:.2g} /m")
            for lab, want in [("A", 2.0)] + [(lab, 2 * f) for lab, f, _ in FIG5_PEAKS]:
                a.axvline(want, color="grey", ls=":", lw=0.8)
                a.text(want, 1.0, lab, transform=a.get_xaxis_transform(), ha="center", va="bottom", fontsize=8)
            peaks, first, r_sec = found[k]
            for lab, pk in peaks.items():
                if present(pk):
                    a.plot([pk[0]], [np.interp(pk[0], x, g)], "v", color="C1", ms=6)
            if r_sec:
                a.axvline(r_sec, color="C3", ls="--", lw=0.8, label="secondary minimum")
            a.set_ylabel("g(r)")
            a.set_yscale("log" if g.max() > 10 else "linear")
            a.set_ylim(bottom=0.05 if g.max() > 10 else 0)
            a.legend(fontsize=8)
        ax[-1, 0].set_xlabel("r / R (dotted: Hecht's peaks A–D for touching spheres; triangles: peaks found)")
        save_figure(plt, fig, path)
    return "<br>".join(rows), "; ".join(verdicts) or "incomplete", None, plot


def reduced_fig5_rdf(sw):
    """studies/reduced/hecht_fig5_rdf.cfg (140 colloids, g(r) over steps 285-570): the full study's headline by
    its machinery (contact_peaks, present: a peak 5 SE above its window's chord), loosened to the smaller run.
    Bound: at least one of B-D present at kappa = 3e8 /m (the full study asks all three; with ~1/7 of its pair
    samples each peak's height in SE is ~2.6x lower, and C, the smallest, falls under 5 SE), none at 7.3e7 /m,
    and there the first peak at the DLVO secondary minimum within 3 SE or 0.05 R (the full rule; its SE is from
    this run).  Fails if the attractive run showed only the first peak, or the repulsive one contact peaks."""
    import numpy as np
    rng = np.random.default_rng(5)
    got = {}
    for p in sw["points"]:
        k = p["params"]["physical.kappa"]
        first, peaks = contact_peaks(*rdf_of(sw, p), rng)
        m = re.search(r"secondary minimum (-?[0-9.e+-]+) kT at gap ([0-9.e+-]+) a0", json.dumps(p["summary"]))
        r_sec = 2.0 + float(m.group(2)) / p["summary"]["mapping"]["colloid"]["radius_a0"] if m else None
        got[k] = (first, peaks, [lab for lab, _, _ in FIG5_PEAKS if present(peaks[lab])], r_sec)
    if 3.0e8 not in got or 7.3e7 not in got:
        return False, "a point at kappa = 3e8 or 7.3e7 /m is missing"
    (_, pk_a, have_a, _), (first_r, pk_r, have_r, r_sec) = got[3.0e8], got[7.3e7]
    at_sec = bool(first_r and r_sec and abs(first_r[0] - r_sec) <= max(3 * first_r[1], 0.05))

    def peaks_text(pk):
        return ", ".join(f"{lab} {pk[lab][2]:.1f}" if pk[lab] else f"{lab} -" for lab, _, _ in FIG5_PEAKS)
    msg = (f"kappa 3e8: B-D present {','.join(have_a) or 'none'} (SE high: {peaks_text(pk_a)}; bound >= 1 at 5 SE); "
           f"kappa 7.3e7: present {','.join(have_r) or 'none'} ({peaks_text(pk_r)}; bound none), first peak "
           + (f"{first_r[0]:.3f} +- {first_r[1]:.3f} R vs secondary minimum {r_sec:.3f} R" if first_r and r_sec
              else "or secondary minimum not found"))
    return len(have_a) >= 1 and not have_r and at_sec, msg
