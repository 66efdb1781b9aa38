"""Coupling I at the matched resolution, run (validation/RULES_rh_resolution.md R8, fixed before the run): the
section "Coupling I at the matched resolution" of validation/REPORT.md, its plot, and the run's figure added to the
fluid's law file (calibration/rh_resolution-X.json, key "check"), which `peloid plan` prints beside the resolution
the law names (src/app/advise_match.c).

    python3 tools/rh_matched.py OUT/STUDY REPORT.md [COMMIT]     (prints the section; exit 0)

STUDY is rh_resolution_X_matched; its law is the one tools/rh_resolution.py wrote for rh_resolution_X.  Each point
is read as the resolution study reads its points (R1-R3: tools/rh_resolution.py), then held against the law's
prediction at its R (R8), and its settling velocity against Stokes's for the radius R with the periodic box's
term (the dilute sediment)."""
import json
import math
import os
import sys

import numpy as np

from rh_resolution import array_mobility, finish_plot, law_path, matched, point_table, points, settled, write_json
from validation.common import pyplot
from validation.report_section import sections_in, study_section_main

BEGIN = "<!-- rh matched: {} (tools/rh_matched.py) -->"  # .format(study name)
END = "<!-- end of the rh matched section: {} -->"
STUDIES = ("rh_resolution_c1_hecht_matched",)
SUFFIX = "_matched"


def sections(text):
    """The matched-resolution sections in a report's text, each from its begin to its end marker."""
    return sections_in(text, STUDIES, BEGIN, END)


def law_of(name):
    """The law file of the resolution study this run checks, and its path."""
    path = law_path(name[:-len(SUFFIX)])
    return json.load(open(path)), path


def predicted(law, R):
    """R8: R_h/R = 1 / (1 + b + c a0/R) by the law at R/a0 = R, and its SE from the law's covariance."""
    b, c, C = law["b"], law["c"], np.array(law["covariance"])
    y = 1.0 / (1.0 + b + c / R)
    g = np.array([-y * y / R]) if len(C) == 1 else np.array([-y * y, -y * y / R])  # dy/d(params)
    return y, math.sqrt(float(g @ C @ g))


def stokes_ratio(r):
    """The dilute sediment: u against Stokes's velocity for the radius R, F / (6 pi eta R), times the periodic
    array's mobility at R (rh_resolution.array_mobility); with its SE."""
    ref = r["F"] / (6.0 * math.pi * r["eta"] * r["R"]) * array_mobility(r["R"], r["L"])
    return r["u"] / ref, r["u_se"] / ref


def plot(rows, doc, path, title):
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    pts = doc["points"]
    ax.errorbar([1.0 / p["R_over_a0"] for p in pts], [p["rh_over_R"] for p in pts],
                yerr=[p["rh_over_R_se"] for p in pts], fmt="o", capsize=3, color="C0",
                label=f"the resolution study ({doc['study']})")
    ax.errorbar([1.0 / r["R"] for r in rows], [r["rh"] for r in rows], yerr=[r["rh_se"] for r in rows], fmt="s",
                capsize=3, color="C3", label="the run at the law's matched resolution")
    law = doc["law"]
    xx = np.linspace(0.0, 0.55, 200)
    ax.plot(xx, 1.0 / (1.0 + law["b"] + law["c"] * xx), "C0-", lw=1,
            label=f"the law, R/R_h − 1 = {law['form']} (c = {law['c']:.3f}), fitted to the study's points")
    ax.axhspan(0.95, 1.05, color="0.85", label="matched: within 5 %")
    finish_plot(fig, ax, (0.0, 0.55), (0.7, 1.06), title, path)


def section(study, commit, png):
    rows = points(study)
    name = os.path.basename(os.path.normpath(study))
    if not rows:
        raise SystemExit(f"rh_matched: no finished point in {study}")
    doc, path = law_of(name)
    law_rel = os.path.relpath(path, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    plot(rows, doc, png, "Coupling I at the matched resolution the law names, Hecht's fluid\n"
                         "one free colloid settling through a periodic cube of side 8 R")
    tab, bad = point_table(rows)
    lines = []
    for r in rows:
        y, se = predicted(doc["law"], r["R"])
        z = (r["rh"] - y) / math.hypot(r["rh_se"], se)
        s, s_se = stokes_ratio(r)
        lines += [
            f"- **R8 at R = {r['R']:g} a0: {matched(r)}{'' if settled(r) else ' (not settled: R1 or R2)'}.**  "
            f"R_h/R = {r['rh']:.3f} ± {r['rh_se']:.3f}; the law predicts {y:.3f} ± {se:.3f}: {z:+.1f} combined SE, "
            f"{'agrees' if abs(z) <= 3 else 'differs'} (R8).",
            f"- **The dilute sediment at R = {r['R']:g} a0:** u = {s:.3f} ± {s_se:.3f} of Stokes's velocity for the "
            f"radius R, F/(6πηR), times the periodic array's mobility at R ({r['u']:.5f} ± {r['u_se']:.5f} a0/t0, "
            f"Re = {r['Re']:.2f}).",
            f"- **Cost:** {r['cpu']:.0f} CPU-s for {r['steps']} steps of {r['L']:g}³ cells; the colloid "
            f"takes {4.0 / 3.0 * math.pi * r['R'] ** 3:.0f} cells against 33.5 at R = 2 a0."]
    return [
        BEGIN.format(name), "",
        "## Coupling I at the matched resolution: Hecht's fluid, run", "",
        f"Measured by `peloid sweep studies/{name}.cfg --jobs 1` (run of "
        f"{', '.join(sorted({r['rev'] for r in rows}))}, one core of the 2-core machine) and `python3 "
        f"tools/rh_matched.py out/studies/{name} validation/REPORT.md` (section written at {commit}).  Rule R8 of "
        "validation/RULES_rh_resolution.md, committed with the study before its run: the resolution that the law "
        f"of {doc['study']} (its section above; {law_rel}) names for R_h/R = 0.95, rounded to whole "
        "cells, run instead of trusted.  The same colloid, fluid, data and R1–R3 as that study.", ""] + tab + [
        ""] + lines + [
        f"- **Read again from colloids.h5, stationary (R1, R2):** {len(rows) - len(bad)} of {len(rows)} points "
        "agree with the observer within 3 SE and have window halves within 3 SE.", "",
        f"![{os.path.basename(png)[:-4]}]({os.path.basename(png)})", "", END.format(name)]


def check_file(study, commit):
    """The run's figures into the law file of the fluid (key "check"), atomically."""
    name = os.path.basename(os.path.normpath(study))
    doc, path = law_of(name)
    doc["check"] = {"study": name, "written_at": commit, "rule": "validation/RULES_rh_resolution.md R8",
                    "points": [{"R_over_a0": r["R"], "rh_over_R": r["rh"], "rh_over_R_se": r["rh_se"],
                                "predicted": predicted(doc["law"], r["R"])[0], "verdict": matched(r),
                                "settled": settled(r), "cpu_seconds": r["cpu"]} for r in points(study)]}
    write_json(path, doc)


def main():
    study, commit = study_section_main(section, BEGIN, END, sys.argv)
    check_file(study, commit)


if __name__ == "__main__":
    main()
