"""Accuracy-cost guides of the SRD fluid: the shear viscosity (PL Eqs. 9-15) and the self-diffusion (PL Eq. 6).

Part of tools/validation_report.py (validation/REPORT.md); each evaluator takes a loaded sweep and
returns (value, verdict[, details, plot])."""
import os
from validation.common import guide_axes, pyplot, save_figure


def accuracy_viscosity(sw):
    """Accuracy-cost guide for the Green-Kubo viscosity (studies/accuracy_viscosity.cfg).

    For each setting (particles per cell, lambda) and run length: the
    deviation from PL Eqs. 9-15, the SE, the CPU seconds.  A run reaches
    accuracy a when |deviation| <= a and 2 SE <= a.  Where no measured run
    reaches a, the cost is extrapolated from the setting's longest run by SE
    ~ CPU^(-1/2), for settings whose longest run deviates by less than a.
    Returns the row, the verdict, a markdown table and draws the plot."""
    runs = {}
    for p in sw["points"]:
        s = p["summary"]
        if not s:
            continue
        e = s["observables"]["fluid_viscosity"]
        th = e["theory"]
        key = (p["params"]["fluid.density"], p["params"]["srd.dt"])
        runs.setdefault(key, []).append({"steps": p["params"]["steps"], "dev": e["value"] / th - 1.0,
                                         "se": e["stderr"] / th, "cpu": s.get("cpu_seconds", s["wall_seconds"]),
                                         "eta": e["value"], "eta_se": e["stderr"], "th": th})
    for r in runs.values():
        r.sort(key=lambda x: x["steps"])
    if not runs:
        return "no point finished", "incomplete", "", None
    # agreement with PL at the longest run of each setting
    agree = sorted(k for k, r in runs.items() if abs(r[-1]["dev"]) <= 3 * r[-1]["se"])
    off = sorted(k for k, r in runs.items() if abs(r[-1]["dev"]) > 3 * r[-1]["se"])
    def name(k):
        return f"ρ = {k[0]:g}, λ = {k[1]:g}"
    guide = []
    for a in (0.10, 0.03, 0.01):
        # a setting qualifies only when its longest run resolves its bias below a (|dev| + SE <= a): a short run
        # that lands near the reference by chance does not recommend a setting whose long run deviates
        hit = [(x["cpu"], k, x) for k, r in runs.items() if abs(r[-1]["dev"]) + r[-1]["se"] <= a
               for x in r if abs(x["dev"]) <= a and 2 * x["se"] <= a]
        if hit:
            cpu, k, x = min(hit, key=lambda h: h[0])
            guide.append((f"{100 * a:g} %", f"{name(k)}, {x['steps']} steps", f"{cpu:.1f} s",
                          f" (measured: {100 * x['dev']:+.1f} ± {100 * x['se']:.1f} %)"))
            continue
        ext = []
        for k, r in runs.items():
            x = r[-1]
            if abs(x["dev"]) + x["se"] < a:
                cpu = x["cpu"] * (2 * x["se"] / a) ** 2
                ext.append((cpu, k, x))
        if ext:
            cpu, k, x = min(ext, key=lambda h: h[0])
            guide.append((f"{100 * a:g} %", f"{name(k)}, ~{x['steps'] * (2 * x['se'] / a) ** 2:.0f} steps",
                          f"~{cpu:.0f} s",
                          f" (extrapolated from its {x['steps']}-step run, {100 * x['dev']:+.1f} ± "
                          f"{100 * x['se']:.1f} %, by SE ∝ CPU^−½; the deviation from PL is not resolved below "
                          f"{100 * x['se']:.1f} %)"))
        else:
            guide.append((f"{100 * a:g} %", "none of these settings (deviation from PL Eqs. 9–15 larger)", "–", ""))
    table = ["| ρ (particles/cell) | λ (a0) | PL Eqs. 9–15 η | " +
             " | ".join(f"{x['steps']} steps: dev ± SE, CPU s" for x in runs[min(runs)]) + " |",
             "|---|---|---|" + "---|" * len(runs[min(runs)])]
    for k in sorted(runs):
        r = runs[k]
        table.append(f"| {k[0]:g} | {k[1]:g} | {r[0]['th']:.4f} | " + " | ".join(
            f"{100 * x['dev']:+.1f} ± {100 * x['se']:.1f} %, {x['cpu']:.1f}" for x in r) + " |")
    details = ("**Accuracy–cost guide, SRD shear viscosity** (`studies/accuracy_viscosity.cfg`: 10³ cells, "
               "α = 130°, kT = 1, Green–Kubo from the stress observer, SE by blocking; CPU seconds = the step "
               "loop's process CPU time, `cpu_seconds` in summary.json, one thread per run).  Deviation = "
               "η / η_PL − 1 against PL Eqs. 9–15.\n\n" + "\n".join(table) +
               "\n\nCheapest setting for an accuracy a (|deviation| ≤ a and 2 SE ≤ a, for a setting whose longest run "
               "deviates by at most a − its SE; cost for this box, "
               "1000 ρ particles: the cost scales with the particle count):\n\n"
               "| accuracy | setting | CPU seconds |\n|---|---|---|\n"
               + "\n".join(f"| {acc} | {setting} | {cost}{note} |" for acc, setting, cost, note in guide) + "\n\n"
               + (f"Settings whose longest run deviates from PL Eqs. 9–15 by more than 3 SE: "
                  + ", ".join(f"{name(k)} ({100 * runs[k][-1]['dev']:+.1f} ± {100 * runs[k][-1]['se']:.1f} %)"
                              for k in off)
                  + ": there the Green–Kubo sum has its plateau (summary.json `plateau`) and the SE is "
                  "below 1 %, so a longer run does not close the gap; it is the difference between the SRD "
                  "fluid and PL's molecular-chaos formulas at that λ, and it bounds the accuracy of PL Eqs. "
                  "9–15 as a reference there." if off else
                  "Every setting's longest run agrees with PL Eqs. 9–15 within 3 SE."))
    value = (f"{len(agree)} of {len(runs)} settings agree with PL Eqs. 9–15 within 3 SE at their longest run; "
             + "; ".join(f"{acc}: {setting}, {cost}" for acc, setting, cost, _ in guide))
    verdict = ("agrees" if not off else f"**disagrees** at {', '.join(name(k) for k in off)}") + \
        " (per setting, within 3 SE at the longest run)"

    def plot(path):
        plt = pyplot()
        fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
        for k in sorted(runs):
            r = runs[k]
            cpu = [x["cpu"] for x in r]
            ax[0].errorbar(cpu, [100 * x["dev"] for x in r], yerr=[100 * x["se"] for x in r], marker="o",
                           capsize=2, label=name(k))
            ax[1].plot(cpu, [100 * x["se"] for x in r], marker="o", label=name(k))
        c = [x["cpu"] for r in runs.values() for x in r]
        c0 = min(c)
        ref = [100 * max(x["se"] for r in runs.values() for x in r if x["cpu"] == c0)]
        ax[1].plot([c0, max(c)], [ref[0], ref[0] * (c0 / max(c)) ** 0.5], "k--", label="∝ CPU^−½")
        guide_axes(ax, "η / η_PL − 1 (%), bars: SE; dotted: ±1, 3, 10 %", "SE / η_PL (%)")
        ax[0].set_title("error against PL Eqs. 9–15")
        ax[1].set_title("statistical error")
        ax[1].legend(fontsize=7, ncol=2)
        save_figure(plt, fig, path)
    return value, verdict, details, plot


# Fluid self-diffusion from thermo.tsv's msd column (output.track_fluid): the mean over all N fluid particles
# of |r(t) - r(0)|^2 from one time origin.  D from its increments after DF_T1 collision steps (the velocity
# correlation of a collision decays within a few steps at alpha = 130 deg), the span split into DF_BLOCKS
# equal blocks, D = the mean of the blocks' slopes / 6, SE = their standard deviation / sqrt(DF_BLOCKS).  With
# one time origin the blocks' increments are uncorrelated but their variance grows with time (the cross term
# 2 (r(t) - r(0)) . dr), so the SE does not fall with the run length: for N independent Gaussian walkers
# (SE / D)^2 = 2 / (3 N) (1 + 2 t1 / (T - t1)) over [t1, T] (df_walker_se); the knobs that lower it are the
# particle count and replicas.  (Weighting the early blocks more, 1 / (1 + 2 t / w), would gain a factor
# ~(ln K)^1/2 at K blocks of length w; not done: the early blocks are the ones nearest the velocity
# correlation.)
DF_T1 = 20
DF_BLOCKS = 16
DF_PREFIXES = (100, 200, 400, 800, 1600, 3200)


def df_walker_se(N, T):
    """SE / D of D over steps [DF_T1, T] from one time origin for N independent Gaussian walkers."""
    return (2.0 / (3.0 * N) * (1.0 + 2.0 * DF_T1 / (T - DF_T1))) ** 0.5


def fluid_msd(out, p):
    """(step, time, msd) of a point's thermo.tsv."""
    import numpy as np
    path = os.path.join(out, p["id"], "thermo.tsv")
    head = open(path).readline().rstrip("\n").split("\t")
    a = np.loadtxt(path, skiprows=1, ndmin=2)
    return a[:, head.index("step")], a[:, head.index("time")], a[:, head.index("msd")]


def fluid_D(step, time, msd, last):
    """D and its SE from the msd increments over steps [DF_T1, last] in DF_BLOCKS equal blocks; None when
    the span holds fewer thermo rows than blocks."""
    import numpy as np
    idx = np.where((step >= DF_T1) & (step <= last))[0]
    if len(idx) < DF_BLOCKS + 1:
        return None
    edges = idx[np.round(np.linspace(0, len(idx) - 1, DF_BLOCKS + 1)).astype(int)]
    d = np.array([(msd[b] - msd[a]) / (6.0 * (time[b] - time[a])) for a, b in zip(edges[:-1], edges[1:])])
    w = np.diff(time[edges])  # equal up to rounding to whole thermo rows
    D = float(np.sum(d * w) / np.sum(w))
    return D, float(d.std(ddof=1) / len(d) ** 0.5)


def accuracy_fluid_diffusion(sw):
    """Accuracy-cost guide for the fluid self-diffusion coefficient (studies/accuracy_fluid_diffusion.cfg).

    For each setting (lambda, particle count), run length (prefixes of the run) and replica count (one seed,
    or all seeds pooled): D / D_PL - 1 against PL Eq. 6 (summary.json derived.D_f), its SE, the CPU seconds
    (the prefix's share of cpu_seconds, summed over pooled replicas).  Accuracy a is reached when |deviation|
    <= a and 2 SE <= a; where no measured run reaches a, the cost is extrapolated from the setting's pooled
    longest run by SE ~ CPU^(-1/2) (more particles or replicas: longer runs do not lower this SE), for
    settings whose pooled deviation is below a by more than its SE.  Verdict: PL Eq. 6 within 3 SE at lambda = 1
    (largest box, replicas pooled); the deviations at smaller lambda are reported, PL Sec. II expects them."""
    import numpy as np
    runs = {}
    for p in sw["points"]:
        s = p["summary"]
        if not s:
            continue
        step, time, msd = fluid_msd(sw["_out"], p)
        lam = s["derived"]["lambda"]
        key = (lam, s["fluid_particles"])
        total = s["last_step"] - s["first_step"]
        for T in DF_PREFIXES + (total,):
            if T > total or (T != total and T > 0.8 * total):
                continue
            e = fluid_D(step, time, msd, T)
            if e:
                runs.setdefault(key, {}).setdefault(T, []).append(
                    {"D": e[0], "se": e[1], "cpu": s["cpu_seconds"] * T / total, "th": s["derived"]["D_f"],
                     "seed": s["scene"]["seed"]})
    if not runs:
        return "no point finished", "incomplete", "", None
    est = {}  # (setting, steps, replicas) -> deviation, SE, cpu
    for k, byT in runs.items():
        for T, reps in byT.items():
            th = reps[0]["th"]
            first = min(reps, key=lambda r: r["seed"])
            est[(k, T, 1)] = {"dev": first["D"] / th - 1, "se": first["se"] / th, "cpu": first["cpu"], "D": first["D"]}
            if len(reps) > 1:
                n = len(reps)
                D = sum(r["D"] for r in reps) / n
                est[(k, T, n)] = {"dev": D / th - 1, "se": (sum(r["se"] ** 2 for r in reps)) ** 0.5 / n / th,
                                  "cpu": sum(r["cpu"] for r in reps), "D": D}
    settings = sorted(runs)
    longest = {k: max(runs[k]) for k in settings}
    nrep = {k: len(runs[k][longest[k]]) for k in settings}
    pooled = {k: est[(k, longest[k], nrep[k])] for k in settings}

    def name(k, T=None, n=1):
        return (f"λ = {k[0]:g}, N = {k[1]}" + (f", {T} steps" if T else "") +
                (f", {n} replicas" if n > 1 else ""))
    # the SE check: the replicas' scatter about their mean against their blocking SEs (chi^2 per dof)
    chi2, dof = 0.0, 0
    for k in settings:
        reps = runs[k][longest[k]]
        if len(reps) > 1:
            m = sum(r["D"] for r in reps) / len(reps)
            chi2 += sum((r["D"] - m) ** 2 / r["se"] ** 2 for r in reps) * (len(reps) - 1) / len(reps)
            dof += len(reps) - 1
    walker = {k: float(np.mean([r["se"] / r["D"] for r in runs[k][longest[k]]])) / df_walker_se(k[1], longest[k])
              for k in settings}
    guide = []
    for a in (0.10, 0.03, 0.01):
        hit = [(x["cpu"], key, x) for key, x in est.items() if abs(x["dev"]) <= a and 2 * x["se"] <= a
               and abs(pooled[key[0]]["dev"]) + pooled[key[0]]["se"] <= a]  # the setting's bias resolved below a
        if hit:
            cpu, (k, T, n), x = min(hit, key=lambda h: h[0])
            guide.append((f"{100 * a:g} %", name(k, T, n), f"{cpu:.2g} s",
                          f" (measured: {100 * x['dev']:+.1f} ± {100 * x['se']:.1f} %)"))
            continue
        ext = [(pooled[k]["cpu"] * (2 * pooled[k]["se"] / a) ** 2, k) for k in settings
               if abs(pooled[k]["dev"]) + pooled[k]["se"] < a]
        if ext:
            cpu, k = min(ext)
            x = pooled[k]
            guide.append((f"{100 * a:g} %", f"λ = {k[0]:g}, ~{k[1] * (2 * x['se'] / a) ** 2 * nrep[k]:.0f} particle"
                          f"-runs of {longest[k]} steps", f"~{cpu:.1f} s",
                          f" (extrapolated from {name(k, longest[k], nrep[k])}, {100 * x['dev']:+.1f} ± "
                          f"{100 * x['se']:.1f} %, by SE ∝ CPU^−½ through more particles or replicas)"))
        else:
            guide.append((f"{100 * a:g} %", "none of these settings (deviation from PL Eq. 6 larger)", "–", ""))
    Ts = sorted({T for (k, T, n) in est})
    table = ["| λ (a0) | N | PL Eq. 6 D_f | " + " | ".join(f"{T} steps" for T in Ts) +
             f" | {max(nrep.values())} replicas, longest |", "|---|---|---|" + "---|" * (len(Ts) + 1)]
    for k in settings:
        cells = [(f"{100 * est[(k, T, 1)]['dev']:+.1f} ± {100 * est[(k, T, 1)]['se']:.1f} %, "
                  f"{est[(k, T, 1)]['cpu']:.2g}" if (k, T, 1) in est else "–") for T in Ts]
        x = pooled[k]
        table.append(f"| {k[0]:g} | {k[1]} | {runs[k][longest[k]][0]['th']:.4f} | " + " | ".join(cells) +
                     f" | {100 * x['dev']:+.2f} ± {100 * x['se']:.2f} %, {x['cpu']:.3g} |")
    at1 = [k for k in settings if abs(k[0] - 1.0) < 1e-9]
    if not at1:
        return "λ = 1 did not finish", "incomplete", "", None
    k1 = max(at1, key=lambda k: k[1])
    x1 = pooled[k1]
    z1 = x1["dev"] / x1["se"]
    others = [k for k in settings if k[0] < 1.0 - 1e-9 and k[1] == k1[1]]
    details = ("**Accuracy–cost guide, fluid self-diffusion D_f** (`studies/accuracy_fluid_diffusion.cfg`: ρ = 5, "
               "α = 130°, kT = 1, boxes of 5³, 10³, 20³ cells, 4 seeds, 3000-step runs; D from the increments of "
               f"thermo.tsv's msd column (output.track_fluid) after {DF_T1} collision steps, SE from {DF_BLOCKS} "
               "blocks; shorter runs are prefixes of the same runs, their CPU seconds the prefix's share of "
               "`cpu_seconds`, one thread).  Deviation = D / D_PL − 1 against PL Eq. 6; cells: deviation ± SE, "
               "CPU s (first seed); last column: all seeds pooled, CPU summed.\n\n" + "\n".join(table) +
               "\n\nWith one time origin (the msd column is |r(t) − r(0)|² from step 0) the SE does **not** fall "
               "with the run length: each block's increment carries the cross term 2 (r(t) − r(0))·Δr, whose "
               "variance grows with t, so for N independent Gaussian walkers (SE / D)² = (2 / 3N) (1 + 2 t1 / "
               "(T − t1)) over [t1, T]: √(2 / 3N) whatever the length once T ≫ t1 (weighting the early blocks "
               "more would gain only a factor ~(ln K)^½ at K blocks).  Measured blocking SE / that formula at "
               "the longest run: "
               + ", ".join(f"{name(k)}: {walker[k]:.2f}" for k in settings) +
               f".  The SE checked against the replicas' scatter: χ²/dof = {chi2 / max(dof, 1):.2f} over {dof} "
               "degrees of freedom (1 when the blocking SE is right).  The knob for precision is the particle "
               "count (box size, or replicas); the run length needs only to pass the velocity correlation.\n\n"
               "Cheapest setting for an accuracy a (|deviation| ≤ a and 2 SE ≤ a, for a setting whose pooled runs deviate "
               "by at most a − their SE; CPU seconds on one thread; two "
               "replicas run side by side on the 2 cores in half the wall time):\n\n"
               "| accuracy | setting | CPU seconds |\n|---|---|---|\n"
               + "\n".join(f"| {acc} | {setting} | {cost}{note} |" for acc, setting, cost, note in guide)
               + "\n\nPL Sec. II: Eq. 6 (random-collision approximation) holds for λ ≳ 0.6 and underestimates D at "
               "small λ (Ripoll et al.: +25 % at λ = 0.1).  Here, largest box, replicas pooled: "
               + ", ".join(f"λ = {k[0]:g}: {100 * pooled[k]['dev']:+.2f} ± {100 * pooled[k]['se']:.2f} %"
                           for k in sorted(others + [k1])) + ".  By box (replicas pooled): "
               + "; ".join(f"λ = {lam:g}: " + ", ".join(f"N = {k[1]} {100 * pooled[k]['dev']:+.1f} ± "
                                                       f"{100 * pooled[k]['se']:.1f} %" for k in settings if k[0] == lam)
                           for lam in sorted({k[0] for k in settings}))
               + "; a smaller periodic box cuts off the collective (hydrodynamic) part of the enhancement that "
               "Ripoll et al. describe, so at small λ the excess over Eq. 6 may grow with the box; these runs "
               "do not resolve that beyond the numbers given.")
    value = (f"λ = 1, N = {k1[1]}, {nrep[k1]} replicas: D = {x1['D']:.4f} ± {x1['se'] * runs[k1][longest[k1]][0]['th']:.4f} "
             f"vs PL Eq. 6 {runs[k1][longest[k1]][0]['th']:.4f} ({100 * x1['dev']:+.2f} ± {100 * x1['se']:.2f} %); "
             + "; ".join(f"λ = {k[0]:g}: {100 * pooled[k]['dev']:+.2f} ± {100 * pooled[k]['se']:.2f} %" for k in sorted(others))
             + "; " + "; ".join(f"{acc}: {setting}, {cost}" for acc, setting, cost, _ in guide))
    verdict = (("agrees" if abs(z1) <= 3 else "**disagrees**") + f" at λ = 1 ({z1:+.1f} SE)"
               + "".join(f"; λ = {k[0]:g}: {pooled[k]['dev'] / pooled[k]['se']:+.1f} SE "
                         f"({'above' if pooled[k]['dev'] > 0 else 'below'} Eq. 6)" for k in sorted(others))
               + " (PL: Eq. 6 holds for λ ≳ 0.6)")

    def plot(path):
        plt = pyplot()
        fig, ax = plt.subplots(1, 2, figsize=(11, 4.4))
        lams = sorted({k[0] for k in settings})
        ns = sorted({k[1] for k in settings})
        styles = ["-", "--", ":", "-."]
        for k in settings:
            c = f"C{lams.index(k[0])}"
            ls = styles[ns.index(k[1]) % len(styles)]
            xs = [est[(k, T, 1)] for T in Ts if (k, T, 1) in est]
            ax[0].errorbar([x["cpu"] for x in xs], [100 * x["dev"] for x in xs], yerr=[100 * x["se"] for x in xs],
                           color=c, ls=ls, marker="o", ms=3, capsize=2, label=f"λ = {k[0]:g}, N = {k[1]}")
            ax[1].plot([x["cpu"] for x in xs], [100 * x["se"] for x in xs], color=c, ls=ls, marker="o", ms=3)
            x = pooled[k]
            ax[0].errorbar([x["cpu"]], [100 * x["dev"]], yerr=[100 * x["se"]], color=c, marker="s", mfc="none",
                           capsize=2)
            ax[1].plot([x["cpu"]], [100 * x["se"]], color=c, marker="s", mfc="none")
        for N in ns:
            y = 100 * df_walker_se(N, 1e30)
            ax[1].axhline(y, color="grey", lw=0.6, ls="--")
            ax[1].text(min(x["cpu"] for x in est.values()), y, f"N = {N}",
                       va="bottom", fontsize=7, color="grey")
        guide_axes(ax, "D / D_PL − 1 (%), bars: SE; dotted: ±1, 3, 10 %",
                   "SE / D_PL (%); dashed: √(2/3N), walkers, long runs", se_lines=False)
        ax[1].set_yticks([0.2, 0.5, 1, 2, 5])
        ax[1].set_yticklabels(["0.2", "0.5", "1", "2", "5"])
        ax[0].set_title("error against PL Eq. 6 (points along a line: prefixes 100–3000 steps;\n"
                        "squares: 4 replicas of 3000 steps pooled)", fontsize=9)
        ax[1].set_title("statistical error: flat in run length, ∝ N^−½", fontsize=9)
        ax[0].legend(fontsize=7, ncol=1)
        save_figure(plt, fig, path)
    return value, verdict, details, plot


def reduced_accuracy_viscosity(sw):
    """studies/reduced/accuracy_viscosity.cfg: within 3 SE of PL at 12000 steps; SE(12000)/SE(3000) in 0.3-0.8."""
    import math
    se, good, msg = {}, True, []
    for p in sw["points"]:
        e = p["summary"]["observables"]["fluid_viscosity"]
        lam, steps = p["params"]["srd.dt"], p["params"]["steps"]
        se[(lam, steps)] = e["stderr"]
        if steps == 12000:
            dev = (e["value"] - e["theory"]) / e["stderr"]
            good &= abs(dev) <= 3
            msg.append(f"lambda {lam:g}: eta {e['value']:.3f} +- {e['stderr']:.3f} vs PL {e['theory']:.3f} ({dev:+.1f} SE)")
    lams = sorted({k[0] for k in se})
    ratio = math.exp(sum(math.log(se[(l, 12000)] / se[(l, 3000)]) for l in lams) / len(lams))
    good &= 0.3 <= ratio <= 0.8
    msg.append(f"SE(12000) / SE(3000) = {ratio:.2f} (expected 0.5)")
    return good, "; ".join(msg)


def reduced_accuracy_fluid_diffusion(sw):
    """studies/reduced/accuracy_fluid_diffusion.cfg (lambda = 1, 625 and 5000 particles, 1000 steps): D within
    3 SE of PL Eq. 6 for 5000 particles (0.3 % chance failure); SE(625) / SE(5000) in 1.6-4.5 (expected
    sqrt(8) = 2.83: SE ~ N^-1/2; each 16-block SE scatters by ~18 %, the ratio by ~26 %: the bounds are ~2
    sigma of that below and above); and SE(1000 steps) / SE(250-step prefix) of the 5000 particles in
    0.6-1.6 (expected 0.94, df_walker_se: with one time origin the SE does not fall with the run length; 0.5 would be
    SE ~ T^-1/2)."""
    se, good, msg = {}, True, []
    for p in sw["points"]:
        s = p["summary"]
        step, time, msd = fluid_msd(sw["_out"], p)
        n, th = s["fluid_particles"], s["derived"]["D_f"]
        D, e = fluid_D(step, time, msd, s["last_step"])
        se[n] = e
        if n == 5000:
            dev = (D - th) / e
            good &= abs(dev) <= 3
            e4 = fluid_D(step, time, msd, s["last_step"] // 4)[1]
            msg.append(f"N {n}: D {D:.4f} +- {e:.4f} vs PL Eq. 6 {th:.4f} ({dev:+.1f} SE); SE(1000 steps) / "
                       f"SE(250) = {e / e4:.2f} (expected {df_walker_se(n, 1000) / df_walker_se(n, 250):.2f})")
            good &= 0.6 <= e / e4 <= 1.6
    ratio = se[625] / se[5000]
    good &= 1.6 <= ratio <= 4.5
    msg.append(f"SE(625) / SE(5000) = {ratio:.2f} (expected 2.83)")
    return good, "; ".join(msg)
