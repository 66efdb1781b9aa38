"""Shared pieces of the validation report: loading a study's sweep, run times, plot set-up, PL's colloid friction.

Part of tools/validation_report.py (validation/REPORT.md); each evaluator takes a loaded sweep and
returns (value, verdict[, details, plot])."""
import json
import math
import os


def pyplot():
    """matplotlib.pyplot on the file-only backend (the report's plots are PNGs)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def save_figure(plt, fig, path):
    """Writes a study plot as the report's PNG and frees it."""
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def guide_axes(ax, dev_label, se_label, se_lines=True, dev_lines=True, xlabel="CPU seconds (one thread)"):
    """The two panels of an accuracy-cost guide: ax[0] the deviation from the reference with its SE, ax[1] the SE,
    both against CPU seconds on log x axes, dotted lines at +-1, 3 and 10 % (on ax[1] unless se_lines is False;
    on ax[0], with the zero line, unless dev_lines is False: a panel of values, not deviations)."""
    for a in ax:
        a.set_xscale("log")
        a.set_xlabel(xlabel)
        a.grid(True, which="both", alpha=0.3)
    ax[1].set_yscale("log")
    for t in (1, 3, 10):
        if se_lines:
            ax[1].axhline(t, color="grey", lw=0.6, ls=":")
        for sgn in (1, -1) if dev_lines else ():
            ax[0].axhline(sgn * t, color="grey", lw=0.6, ls=":")
    if dev_lines:
        ax[0].axhline(0.0, color="k", lw=0.8)
    ax[0].set_ylabel(dev_label)
    ax[1].set_ylabel(se_label)


def pl_friction(kT, rho, eta, sig, L, mass=math.inf):
    """A colloid's friction as PL evaluate it: the Enskog friction of PL Eq. 40 (reduced mass M m_f / (M + m_f),
    m_f = 1; a pinned colloid, mass = inf, has m_f) in parallel (PL Eq. 41) with the slip Stokes friction 4 pi eta
    sigma_cf and its finite-box factor 1 / (1 - 2.837 sigma_cf / L) (PL Eqs. 42-43): (xi_E, xi_S, xi)."""
    mu = 1.0 / (1.0 + 1.0 / mass)
    xi_e = 8.0 / 3.0 * math.sqrt(2.0 * math.pi * kT * mu) * rho * sig * sig
    xi_s = 4.0 * math.pi * eta * sig / (1.0 - 2.837 * sig / L)
    return xi_e, xi_s, 1.0 / (1.0 / xi_s + 1.0 / xi_e)


def load(out, name):
    path = os.path.join(out, name, "sweep.json")
    if not os.path.exists(path):
        return None
    sw = json.load(open(path))
    sw["_out"] = os.path.join(out, name)
    for p in sw["points"]:
        sp = os.path.join(out, name, p["id"], "summary.json")
        p["summary"] = json.load(open(sp)) if p["status"] == "ok" and os.path.exists(sp) else None
    return sw


def load_sibling(sw, name):
    """The sweep of study `name` beside a loaded sweep (out/studies/NAME), or None when it has not run."""
    return load(os.path.dirname(os.path.normpath(sw["_out"])), name)


def run_time(sw):
    ok = [p for p in sw["points"] if p["summary"]]
    wall = sum(p["summary"]["wall_seconds"] for p in ok)
    threads = sorted({p["summary"]["threads"] for p in ok})
    return (f"{wall:.0f} s summed over {len(ok)} point(s) ({'/'.join(map(str, threads))} thread(s) each, "
            f"on the 2-core machine, at times shared with other jobs)")
