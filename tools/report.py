#!/usr/bin/python3
"""The report of a run: OUTDIR/report.md with a PNG plot of every observable
the run measured, each with its error bars, and the error-against-time table.

    /usr/bin/python3 tools/report.py OUTDIR        (or: peloid report OUTDIR)

Reads OUTDIR/summary.json, OUTDIR/observables.h5 (H5MD /observables, written
by the observers of the scene's observe{} section) and OUTDIR/thermo.tsv.

  g(r)       colloid_rdf: mean +- SE per bin, the contact-geometry distances
             2R, (4/3) sqrt(6) R, 2 sqrt(3) R and 4R of touching spheres
             (Hecht Sec. IX.C) marked.
  MSD        colloid_msd: summed over axes, +- SE, with 6 D t of the fitted D
             over its fit window.
  g_ab(r)    colloid_rdf_classes: each size-class partial +- SE.
  S(q)       colloid_sq: mean +- SE per |q| bin (bins with wave vectors).
  C_FF       colloid_cff: the fluid-force autocorrelation normalised by its
             t = 0 value (PL Eq. 50, Fig. 10), +- SE, with the Green-Kubo
             friction and the lag it is integrated to.
  clusters   cluster_number, largest_cluster, mean_cluster_size over time;
             with energy bonds, the primary- and secondary-minimum bonds.
  sediment   phi(z, t) and the mean height with the settling velocity.
  velocities fluid and colloid velocity distributions against Maxwell-
             Boltzmann, with the chi^2 p-value.
  colloid    a physical scene's model colloid: its hydrodynamic radius
             R_h/R (summary.json mapping.colloid) and, for the potential
             coupling, the hard-core volume fraction phi_c.
  thermo     the temperature (and, with colloids, the colloid kinetic
             energy and centre-of-mass height) over time.

A physical scene (summary.json "units_si") is plotted in the real system's
units: lengths in um, times in s, velocities in um/s, D in um^2/s, MSD in
um^2, q in 1/um, viscosity in Pa s, pressure in Pa, friction in kg/s,
temperature in K (DESIGN.md "Units and mapping"); a model scene in a0, t0,
m_f, kT.  Energies stay in kT (the same number in both systems).
"""
import json
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from system_title import system_title  # noqa: E402


class Units:
    """Factors and names that turn the model values of observables.h5 into
    the units a plot shows: SI-scaled (um, s, ...) for a physical scene, the
    model units (factor 1) otherwise."""

    def __init__(self, summary):
        u = summary.get("units_si")
        self.physical = bool(u)
        self.title = system_title(summary)
        if not u:
            self.f = {k: (1.0, n) for k, n in MODEL.items()}
            return
        a0, t0, mf, kT = u["a0_m"] * 1e6, u["t0_s"], u["m_f_kg"], u["kT_J"]
        a0m = u["a0_m"]
        self.f = {"len": (a0, "µm"), "time": (t0, "s"), "area": (a0 * a0, "µm²"), "vel": (a0 / t0, "µm/s"),
                  "D": (a0 * a0 / t0, "µm²/s"), "invlen": (1 / a0, "1/µm"), "visc": (mf / (a0m * t0), "Pa s"),
                  "press": (kT / a0m**3, "Pa"), "fric": (mf / t0, "kg/s")}

    def __call__(self, kind, x):
        return np.asarray(x) * self.f[kind][0] if not np.isscalar(x) else x * self.f[kind][0]

    def name(self, kind):
        return self.f[kind][1]


def save(fig, u, outdir, name):
    """Writes the figure; a physical scene's carries the system it shows (material, R, phi, salt, coupling)."""
    if u.physical:
        fig.suptitle(u.title, fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, name), dpi=120)


MODEL = {"len": "a0", "time": "t0", "area": "a0²", "vel": "a0/t0", "D": "a0²/t0", "invlen": "1/a0",
         "visc": "m_f/(a0 t0)", "press": "kT/a0^3", "fric": "m_f/t0"}


def radius(summary):
    try:
        return float(summary["scene"]["colloids"]["radius"])
    except (KeyError, TypeError, ValueError):
        return None


def plot_rdf(f, summary, u, outdir, lines):
    g = f["observables/colloid_rdf"]
    r, v, se = u("len", g["r"][:]), g["value"][0], g["value_se"][0]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.errorbar(r, v, yerr=se, fmt=".-", ms=3, lw=0.8, elinewidth=0.6, capsize=0, label="g(r) +- SE")
    R = radius(summary)
    if R:
        R = u("len", R)
        for d, name in ((2 * R, "2R"), (4 / 3 * math.sqrt(6) * R, "(4/3)√6 R"), (2 * math.sqrt(3) * R, "2√3 R"),
                        (4 * R, "4R")):
            if d < r[-1]:
                ax.axvline(d, color="grey", ls=":", lw=0.8)
                ax.text(d, ax.get_ylim()[1] * 0.95, name, rotation=90, va="top", ha="right", fontsize=7)
    ax.axhline(1.0, color="k", lw=0.5)
    ax.set_xlabel(f"r [{u.name('len')}]")
    ax.set_ylabel("g(r)")
    ax.set_title(f"colloid g(r), {int(g['samples'][()])} samples")
    ax.legend(fontsize=8)
    save(fig, u, outdir, "rdf.png")
    plt.close(fig)
    lines += ["## Colloid g(r)", "", "![g(r)](rdf.png)", ""]


def plot_rdf_classes(f, u, outdir, lines):
    g = f["observables/colloid_rdf_classes"]
    r, v, se, pairs = u("len", g["r"][:]), g["value"][0], g["value_se"][0], g["pairs"][:]
    crad = u("len", g["class_radius"][:])
    fig, ax = plt.subplots(figsize=(6, 4))
    for p, (a, b) in enumerate(pairs):
        ax.errorbar(r, v[p], yerr=se[p], fmt=".-", ms=2, lw=0.7, elinewidth=0.5, capsize=0,
                    label=f"g_{a}{b}: R {crad[a][0]:.3g}-{crad[a][1]:.3g} with {crad[b][0]:.3g}-{crad[b][1]:.3g}")
    ax.axhline(1.0, color="k", lw=0.5)
    ax.set_xlabel(f"r [{u.name('len')}]")
    ax.set_ylabel("g_ab(r)")
    ax.set_title(f"g(r) per size class (radius rank, R in {u.name('len')}), {int(g['samples'][()])} samples")
    ax.legend(fontsize=6)
    save(fig, u, outdir, "rdf_classes.png")
    plt.close(fig)
    lines += ["## Colloid g(r) per size class", "", "![g_ab(r)](rdf_classes.png)", ""]


def plot_sq(f, obs, u, outdir, lines):
    g = f["observables/colloid_sq"]
    q, v, se, nv = u("invlen", g["q_mean"][:]), g["value"][0], g["value_se"][0], g["vectors"][:]
    m = nv > 0
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.errorbar(q[m], v[m], yerr=se[m], fmt=".-", ms=3, lw=0.8, elinewidth=0.6, capsize=0, label="S(q) +- SE")
    ax.axhline(1.0, color="k", lw=0.5)
    ax.set_xlabel(f"|q| [{u.name('invlen')}]")
    ax.set_ylabel("S(q)")
    e = obs.get("sq_peak")
    ax.set_title(f"colloid S(q), {int(g['samples'][()])} samples"
                 + (f"; peak {e['value']:.3g} ± {e['stderr']:.2g} at q = {u('invlen', e['q']):.3g} {u.name('invlen')}"
                    if e else ""), fontsize=9)
    ax.legend(fontsize=8)
    save(fig, u, outdir, "sq.png")
    plt.close(fig)
    lines += ["## Colloid S(q)", "", "![S(q)](sq.png)", ""]


def plot_cff(f, obs, u, outdir, lines):
    g = f["observables/colloid_cff"]
    lag, v, se = u("time", g["lag"][:]), g["value"][:, 3], g["value_se"][:, 3]
    e = obs.get("colloid_friction_green_kubo")
    tmax = 20 * u("time", e["integrated_to_t0"]) if e else lag[-1]
    m = lag <= tmax
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.errorbar(lag[m], v[m] / v[0], yerr=se[m] / v[0], fmt=".-", ms=3, lw=0.8, elinewidth=0.6, capsize=0,
                label="C_FF(t) / C_FF(0) +- SE")
    ax.axhline(0.0, color="k", lw=0.5)
    if e:
        ax.axvline(u("time", e["integrated_to_t0"]), color="r", ls=":", lw=0.8,
                   label=f"ξ = {u('fric', e['value']):.4g} ± {u('fric', e['stderr']):.2g} {u.name('fric')} "
                         "(integral to here)")
    ax.set_xlabel(f"lag [{u.name('time')}]")
    ax.set_ylabel("C_FF(t) / C_FF(0)")
    ax.set_title("fluid-force autocorrelation (step-mean force)", fontsize=9)
    ax.legend(fontsize=8)
    save(fig, u, outdir, "cff.png")
    plt.close(fig)
    lines += ["## Fluid-force autocorrelation C_FF", "", "![C_FF](cff.png)", ""]


def window_start(g, e, u):
    """Where the summary's average of series group g starts (display time)
    and how it was chosen (summary.json average_from_step, window_source;
    None: the entry predates analysis windows)."""
    if not e or "average_from_step" not in e:
        return None, ""
    st, t = g["step"][:], g["time"][:]
    k = min(int(np.searchsorted(st, e["average_from_step"])), len(t) - 1)
    return u("time", float(t[k])), e["window_source"]


def window_band(ax, g, e, u, col, label, conv=lambda x: x):
    """The mean +- SE band of entry e over its averaging window only, the
    window's start marked (a dashed line) unless it is the whole run."""
    t = u("time", g["time"][:])
    t0, src = window_start(g, e, u)
    x0 = t[0] if t0 is None else t0
    v, se = conv(e["value"]), conv(e["stderr"])
    ax.fill_between([x0, t[-1]], v - se, v + se, color=col, alpha=0.15, label=label)
    ax.hlines(v, x0, t[-1], color=col, lw=0.6)
    if t0 is not None and src != "whole run":
        ax.axvline(t0, color=col, ls="--", lw=0.7, label=f"averaged from {t0:.3g} {u.name('time')} ({src})")


def plot_bonds(f, obs, u, outdir, lines):
    fig, ax = plt.subplots(figsize=(6, 3.5))
    for name, col in (("cluster_bonds_primary", "C0"), ("cluster_bonds_secondary", "C1")):
        g = f["observables/" + name]
        e = obs.get(name)
        lab = name.replace("cluster_bonds_", "") + " minimum"
        if e:
            lab += f": mean {e['value']:.4g} ± {e['stderr']:.2g}"
        ax.plot(u("time", g["time"][:]), g["value"][:], lw=0.8, color=col, label=lab)
        if e:
            window_band(ax, g, e, u, col, None)
    fr = obs.get("cluster_primary_fraction")
    ax.set_title("energy bonds" + (f"; primary fraction {fr['value']:.3g} ± {fr['stderr']:.2g}" if fr else ""),
                 fontsize=9)
    ax.set_xlabel(f"time [{u.name('time')}]")
    ax.set_ylabel("bonds")
    ax.legend(fontsize=7)
    save(fig, u, outdir, "bonds.png")
    plt.close(fig)
    lines += ["## Bonds by pair energy", "", "![bonds](bonds.png)", ""]


def plot_msd(f, obs, u, outdir, lines):
    g = f["observables/colloid_msd"]
    lag, v, se = u("time", g["lag"][:]), u("area", g["value"][:, 3]), u("area", g["value_se"][:, 3])
    m = lag > 0
    local = "D_local" in g
    fig, axs = plt.subplots(1, 2 if local else 1, figsize=(11 if local else 6, 4), squeeze=False)
    ax = axs[0][0]
    ax.errorbar(lag[m], v[m], yerr=se[m], fmt=".", ms=3, elinewidth=0.6, label="MSD (x+y+z) +- SE")
    d = obs.get("colloid_D")
    if d:
        t = u("time", np.array(d["fit_window_t0"]))
        D, De = u("D", d["value"]), u("D", d["stderr"])
        ax.plot(lag[m], 6 * D * lag[m], "r-", lw=0.8, label=f"6 D t, D = {D:.4g} ± {De:.2g} {u.name('D')}")
        ax.axvspan(t[0], t[1], color="r", alpha=0.08, label="fit window")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(f"lag [{u.name('time')}]")
    ax.set_ylabel(f"MSD [{u.name('area')}]")
    ax.legend(fontsize=8)
    if local:  # D(t) = d MSD / (6 dt): converged where it levels off
        ax = axs[0][1]
        dl, dle = u("D", g["D_local"][:]), u("D", g["D_local_se"][:])
        k = np.isfinite(dl) & m
        ax.errorbar(lag[k], dl[k], yerr=dle[k], fmt=".", ms=3, elinewidth=0.6, label="local slope / 6 ± SE")
        if d:
            ax.axhspan(D - De, D + De, color="r", alpha=0.15, label="D of the fit")
            ax.axvspan(t[0], t[1], color="r", alpha=0.08)
        ax.set_xscale("log")
        ax.set_xlabel(f"lag [{u.name('time')}]")
        ax.set_ylabel(f"D(t) [{u.name('D')}]")
        ax.legend(fontsize=8)
    save(fig, u, outdir, "msd.png")
    plt.close(fig)
    lines += ["## Colloid MSD and D", "", "![MSD](msd.png)", ""]


def bond_rule(summary):
    """The cluster observer's bond rule as the run used it: the mapping's line where a physical scene states
    it (observe.clusters_gap in a0 and m, given or derived from the pair potential), else the scene's keys."""
    o = (summary.get("scene") or {}).get("observe") or {}
    if o.get("clusters_bond") == "energy":
        return f"pair energy below \u2212{o.get('clusters_energy')} kT (observe.clusters_bond = \"energy\")"
    prov = ((summary.get("mapping") or {}).get("colloid") or {}).get("derived_keys") or []
    line = next((x for x in prov if isinstance(x, str) and x.startswith("observe.clusters_gap")), None)
    return line or f"surface gap below observe.clusters_gap = {o.get('clusters_gap')} a0"


def plot_clusters(f, obs, u, outdir, lines, summary=None):
    fig, axs = plt.subplots(3, 1, figsize=(6, 6), sharex=True)
    for ax, name in zip(axs, ("cluster_number", "largest_cluster", "mean_cluster_size")):
        g = f["observables/" + name]
        ax.plot(u("time", g["time"][:]), g["value"][:], lw=0.8)
        e = obs.get(name)
        if e:
            window_band(ax, g, e, u, "r",
                        f"mean {e['value']:.4g} ± {e['stderr']:.2g}" + ("" if e["plateau"] else " (no plateau)"))
            ax.legend(fontsize=7)
        ax.set_ylabel(name.replace("_", " "), fontsize=8)
    axs[-1].set_xlabel(f"time [{u.name('time')}]")
    save(fig, u, outdir, "clusters.png")
    plt.close(fig)
    lines += ["## Clusters", "", f"Bond: {bond_rule(summary or {})}.", "", "![clusters](clusters.png)", ""]


def plot_vdist(f, obs, u, outdir, lines):
    names = [n for n in ("fluid_velocity_distribution", "colloid_velocity_distribution") if n in f["observables"]]
    fig, ax = plt.subplots(figsize=(6, 4))
    edges = np.linspace(-4, 4, 61)
    mid, w = 0.5 * (edges[1:] + edges[:-1]), edges[1] - edges[0]
    for n in names:
        h = f["observables/" + n + "/value"][3].astype(float)  # all axes
        tot = h.sum()
        dens = h[1:-1] / (tot * w)
        err = np.sqrt(h[1:-1]) / (tot * w)
        key = n.replace("_distribution", "_chi2")
        p = obs.get(key, {}).get("p_value")
        ax.errorbar(mid, dens, yerr=err, fmt=".", ms=3, elinewidth=0.6,
                    label=n.split("_")[0] + (f" (chi² p = {p:.3g})" if p is not None else ""))
    x = np.linspace(-4, 4, 400)
    ax.plot(x, np.exp(-x * x / 2) / math.sqrt(2 * math.pi), "k-", lw=0.8, label="Maxwell-Boltzmann")
    ax.set_yscale("log")
    ax.set_ylim(1e-5, 1)
    ax.set_xlabel("(v - <v>) sqrt(M / kT)")
    ax.set_ylabel("probability density")
    ax.legend(fontsize=8)
    save(fig, u, outdir, "vdist.png")
    plt.close(fig)
    lines += ["## Velocity distributions", "", "![velocity distributions](vdist.png)", ""]


def plot_sediment(f, obs, u, outdir, lines):
    g = f["observables/colloid_phi_z"]
    t, z, phi = u("time", g["time"][:]), u("len", g["z"][:]), g["value"][:]
    fig, axs = plt.subplots(1, 2, figsize=(9, 3.8))
    im = axs[0].imshow(phi.T, origin="lower", aspect="auto", extent=[t[0], t[-1], 0, z[-1] + z[0]], cmap="viridis")
    fig.colorbar(im, ax=axs[0], label="phi")
    axs[0].set_xlabel(f"time [{u.name('time')}]")
    axs[0].set_ylabel(f"z [{u.name('len')}]")
    axs[0].set_title("colloid volume fraction phi(z, t)")
    h = f["observables/colloid_height"]
    ht, hv = u("time", h["time"][:]), u("len", h["value"][:])
    axs[1].plot(ht, hv, lw=0.8, label="mean height")
    e = obs.get("settling_velocity")
    if e and e.get("plateau", True):  # the window's mean means something only when it is steady
        vs, vse = u("vel", e["value"]), u("vel", e["stderr"])
        down = -1.0 if e.get("positive") == "down" else 1.0  # dz/dt before the sign was stated (issue 45)
        t0, src = window_start(f["observables/settling_velocity"], e, u)
        k = 0 if t0 is None else int(np.searchsorted(ht, t0))
        tw = ht[k:]
        axs[1].plot(tw, hv[k] + down * vs * (tw - ht[k]), "r--", lw=0.8,
                    label=f"mean settling v = {down * -vs:.4g} ± {vse:.2g} {u.name('vel')}" + (f" from {t0:.3g} {u.name('time')} ({src})" if t0 is not None and src != "whole run" else ""))
    ini, text = obs.get("initial_settling_velocity"), []
    if ini and "value" in ini:  # the homogeneous fall: its window and the references
        k = min(int(ini["samples"]), len(ht) - 1)
        tw = ht[: k + 1]
        vi, vie = u("vel", ini["value"]), u("vel", ini["stderr"])
        axs[1].plot(tw, hv[0] - vi * (tw - ht[0]), "C3-", lw=2,
                    label=f"initial v = {vi:.3g} ± {vie:.2g} {u.name('vel')}")
        if ini.get("stokes") is not None:
            st = u("vel", ini["stokes"])
            axs[1].plot(tw, hv[0] - st * (tw - ht[0]), "k--", lw=0.8, label=f"Stokes {st:.3g} {u.name('vel')}")
        lines_ini = (f"initial settling velocity {vi:.4g} ± {vie:.2g} {u.name('vel')} over the first {k} samples "
                     f"(homogeneous: halves within {ini['drift_z']:.2f} SE)")
        if ini.get("stokes") is not None:
            lines_ini += (f"; Stokes {u('vel', ini['stokes']):.4g}, Richardson-Zaki (1 - phi)^4.65 at phi = "
                          f"{ini['volume_fraction']:.3g}: {u('vel', ini['richardson_zaki_4.65']):.4g} {u.name('vel')}")
        text = [lines_ini, ""]
    axs[1].set_xlabel(f"time [{u.name('time')}]")
    axs[1].set_ylabel(f"height [{u.name('len')}]")
    axs[1].legend(fontsize=8)
    save(fig, u, outdir, "sediment_phi.png")
    plt.close(fig)
    lines += ["## Sedimentation", "", "![phi(z, t)](sediment_phi.png)", ""] + text


def plot_viscosity(f, obs, u, outdir, lines):
    g = f["observables/fluid_viscosity_gk"]
    lag, eta = u("time", g["lag"][:]), u("visc", g["value"][:])
    e = obs.get("fluid_viscosity", {})
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(lag, eta, "o-", ms=3, label="running Green-Kubo sum")
    if e:
        ev, es, et = u("visc", e["value"]), u("visc", e["stderr"]), u("visc", e["theory"])
        ax.axhspan(ev - es, ev + es, color="C0", alpha=0.2, label=f"eta = {ev:.4g} +- {es:.2g}")
        ax.axhline(et, color="k", ls="--", label=f"{e.get('theory_source', 'theory')}: {et:.4g}")
    ax.set_xlabel(f"truncation lag [{u.name('time')}]")
    ax.set_ylabel(f"eta [{u.name('visc')}]")
    ax.legend(fontsize=8)
    save(fig, u, outdir, "viscosity.png")
    plt.close(fig)
    lines += ["## Fluid shear viscosity (Green-Kubo)", "", "![viscosity](viscosity.png)", ""]
    if e:
        lines += [f"eta = {u('visc', e['value']):.5g} +- {u('visc', e['stderr']):.2g} {u.name('visc')} "
                  f"({e.get('theory_source', 'theory')}: {u('visc', e['theory']):.5g}), over {e['samples']} steps", ""]
    p = obs.get("fluid_pressure")
    if p:
        lines += [f"pressure {u('press', p['value']):.6g} +- {u('press', p['stderr']):.2g} {u.name('press')} "
                  f"(ideal gas {u('press', p['ideal_gas']):.6g})", ""]


def plot_thermo(outdir, u, lines):
    path = os.path.join(outdir, "thermo.tsv")
    if not os.path.exists(path):
        return
    data = np.genfromtxt(path, names=True, delimiter="\t")
    if data.size < 2:
        return
    names = data.dtype.names
    # a physical scene's thermo.tsv has time_s and temperature_K beside the model columns
    si = u.physical and "time_s" in names and "temperature_K" in names
    temp = ("temperature_K", "temperature [K]") if si else ("temperature", "temperature [kT]")
    cols = [c for c in (temp, ("c_kin_trans", "c_kin_trans [kT]"), ("c_zcm", f"c_zcm [{u.name('len')}]"))
            if c[0] in names]
    fig, axs = plt.subplots(len(cols), 1, figsize=(6, 1.8 * len(cols) + 0.6), sharex=True, squeeze=False)
    for ax, (c, label) in zip(axs[:, 0], cols):
        ax.plot(data["time_s"] if si else data["time"], u("len", data[c]) if c == "c_zcm" else data[c], lw=0.8)
        ax.set_ylabel(label, fontsize=8)
    axs[-1, 0].set_xlabel("time [s]" if si else "time [t0]")
    save(fig, u, outdir, "thermo.png")
    plt.close(fig)
    lines += ["## Thermo", "", "![thermo](thermo.png)", ""]


def error_table(obs, lines):
    rows = [(k, v) for k, v in obs.items() if isinstance(v, dict) and "se_vs_time" in v]
    if not rows:
        return
    lines += ["## Error against run time", "",
              "The value averages the samples from the window's start on (observe.average_from: given, or "
              "detected by Chodera's equilibration test); the SE against run time is over the whole run so far.",
              "",
              "| observable | value ± SE | averaged from | SE at 1/8, 1/4, 1/2, 1 of the run (wall s) | "
              "wall s for the target |",
              "|---|---|---|---|---|"]
    for k, v in rows:
        pts = ", ".join(f"{p['stderr']:.3g} ({p['wall_s']:.3g} s)" for p in v["se_vs_time"])
        need = v.get("wall_s_for_target")
        tgt = (f"{need:.3g} s for {100 * v['target_rel_error']:.3g} %"
               + ("" if v.get("extrapolation_reliable", True) else " (no plateau: a lower bound)")) if need else "-"
        val = f"{v['value']:.5g} ± {v['stderr']:.2g}" + ("" if v["unit"] in ("1", "") else f" {v['unit']}")
        if "unit_si" in v and v["unit_si"] != "1":  # a physical scene: the SI value beside
            val += f" = {v['value_si']:.5g} ± {v['stderr_si']:.2g} {v['unit_si']}"
            if "stderr_total_si" in v:  # t0 rests on the calibrated colloid D: its error, then both combined
                val += (f" ± {v['stderr_mapping_si']:.2g} (calibration of t0) = ± {v['stderr_total_si']:.2g} "
                        f"{v['unit_si']} combined")
        win = (f"{v['average_from_time']:.4g} {v['average_from_time_unit']} (step {v['average_from_step']}, "
               f"{v['window_source']})" if "window_source" in v else "-")
        lines.append(f"| {k} | {val} | {win} | {pts} | {tgt} |")
    lines.append("")


class InputError(Exception):
    """An input of the report (FILE: what is wrong) that cannot be read."""


def read_summary(path):
    try:
        with open(path) as f:
            summary = json.load(f)
    except OSError as e:
        raise InputError(f"{path}: {e.strerror}") from None
    except (ValueError, UnicodeDecodeError) as e:  # json.JSONDecodeError is a ValueError
        raise InputError(f"{path}: not valid JSON ({e}); allowed: the summary.json peloid run writes") from None
    if not isinstance(summary, dict):
        raise InputError(f"{path}: not a JSON object; allowed: the summary.json peloid run writes")
    return summary


def plot_observables(h5, summary, obs, u, outdir, lines):
    with h5py.File(h5, "r") as f:
        have = f["observables"] if "observables" in f else {}
        if "colloid_rdf" in have:
            plot_rdf(f, summary, u, outdir, lines)
        if "colloid_rdf_classes" in have:
            plot_rdf_classes(f, u, outdir, lines)
        if "colloid_sq" in have:
            plot_sq(f, obs, u, outdir, lines)
        if "colloid_msd" in have:
            plot_msd(f, obs, u, outdir, lines)
        if "colloid_cff" in have:
            plot_cff(f, obs, u, outdir, lines)
        if "cluster_number" in have:
            plot_clusters(f, obs, u, outdir, lines, summary)
        if "cluster_bonds_primary" in have:
            plot_bonds(f, obs, u, outdir, lines)
        if "colloid_phi_z" in have:
            plot_sediment(f, obs, u, outdir, lines)
        if "fluid_velocity_distribution" in have or "colloid_velocity_distribution" in have:
            plot_vdist(f, obs, u, outdir, lines)
        if "fluid_viscosity_gk" in have:
            plot_viscosity(f, obs, u, outdir, lines)


def mapping_lines(summary, lines):
    """A physical scene's model colloid as the mapping states it (summary.json
    "mapping" "colloid"): the hydrodynamic radius R_h/R (its friction in the
    model fluid, xi = k pi eta R_h) and, for the potential coupling, the
    volume fraction of the colloid-colloid hard cores."""
    mp = summary.get("mapping")
    col = mp.get("colloid") if isinstance(mp, dict) else None
    if not isinstance(col, dict) or not isinstance(col.get("hydrodynamic_radius_over_R"), (int, float)):
        return
    rh, se = col["hydrodynamic_radius_over_R"], col.get("hydrodynamic_radius_over_R_se")
    pm = f" ± {se:.2g}" if isinstance(se, (int, float)) else ""
    lines += ["## Model colloid", "",
              f"hydrodynamic radius R_h/R = {rh:.4g}{pm} ({col.get('hydrodynamic_radius_source')}, "
              f"{col.get('hydrodynamic_radius_boundary')} surface): box corrections, hindered settling and "
              "lubrication have the strength of that sphere", ""]
    phic, core = col.get("volume_fraction_hard_core"), col.get("hard_core_radius_over_R")
    if isinstance(phic, (int, float)) and isinstance(core, (int, float)):
        lines += [f"hard-core volume fraction φ_c = {phic:.4g} (radius {core:.4g} R) beside the stated "
                  f"φ = {col.get('volume_fraction_given')}", ""]


def report(outdir):
    summary = read_summary(os.path.join(outdir, "summary.json"))
    obs = summary.get("observables", {})
    if not isinstance(obs, dict):
        raise InputError(f"{outdir}/summary.json: \"observables\" is not a JSON object")
    try:
        u = Units(summary)
    except (KeyError, TypeError, ValueError, ZeroDivisionError) as e:
        raise InputError(f"{outdir}/summary.json: \"units_si\" unreadable ({type(e).__name__}: {e})") from None
    lines = [f"# Report of {summary.get('scene_file', outdir)}", "",
             f"steps {summary.get('first_step')}..{summary.get('last_step')}, "
             f"{summary.get('wall_seconds', 0):.3g} s wall, {summary.get('threads')} thread(s)", ""]
    mapping_lines(summary, lines)
    h5 = os.path.join(outdir, "observables.h5")
    if os.path.exists(h5):
        # a truncated or corrupt file (OSError), a missing dataset or
        # attribute (KeyError), or one of another shape than the observers
        # write (ValueError, TypeError, IndexError): the file is to blame
        try:
            plot_observables(h5, summary, obs, u, outdir, lines)
        except (OSError, KeyError, ValueError, TypeError, IndexError) as e:
            raise InputError(f"{h5}: unreadable ({type(e).__name__}: {e}); allowed: the observables.h5 "
                             "peloid run writes") from None
    thermo = os.path.join(outdir, "thermo.tsv")
    try:
        plot_thermo(outdir, u, lines)
    except (OSError, KeyError, ValueError, TypeError, IndexError) as e:
        raise InputError(f"{thermo}: unreadable ({type(e).__name__}: {e}); allowed: the thermo.tsv "
                         "peloid run writes") from None
    try:
        error_table(obs, lines)
    except (KeyError, TypeError, ValueError) as e:
        raise InputError(f"{outdir}/summary.json: an observable's error table unreadable "
                         f"({type(e).__name__}: {e})") from None
    out_path = os.path.join(outdir, "report.md")
    try:
        with open(out_path, "w") as out:
            out.write("\n".join(lines))
    except OSError as e:
        raise InputError(f"{out_path}: cannot write: {e.strerror}") from None
    print(f"report: {out_path}")


def main(argv):
    if len(argv) != 2 or argv[1].startswith("-"):
        print("usage: report.py OUTDIR", file=sys.stderr)
        return 2
    try:
        report(argv[1])
    except InputError as e:
        # one line, no traceback: the file and what is wrong with it
        print(f"peloid report: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
