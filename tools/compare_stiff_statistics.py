#!/usr/bin/python3
"""Statistical agreement of the derived multiple time stepping with the
default MD on issue 38's stiff suspension.

Runs bench/scenes/silica_10mM.cfg (silica, R = 0.3 um, 10 mM salt, phi =
0.10, walls, coupling II; adaptive substeps, the default) for 1 s of real
time (1818 collision steps) from the lattice, once as it is ("old") and once
with coarse_graining.multiple_time_stepping = true ("new"), seed by seed
(interleaved, 1 thread each), observers from collision step 300, and compares
over the seeds (mean +- SE of the seed-to-seed scatter; z = difference over
the combined SE, |z| < 3 is agreement), from each run's outputs as a user
reads them (summary.json, observables.h5, thermo.tsv):
  - D: the colloids' diffusion coefficient (summary.json colloid_D, a0^2/t0),
  - msd_0.1s: their mean squared displacement at a lag of 0.1 s (a0^2),
  - g_peak: g(r)'s first peak; g_shell: g(r) over r in (1.24, 1.34) a0, the
    secondary minimum's shell,
  - bonds, clusters: pairs within gap 0.1 a0 and their clusters (means),
  - u_dlvo: the colloids' DLVO energy (kT, thermo c_dlvo, mean from step 300),
  - kT_colloid: their translational kinetic temperature (thermo c_kin_trans
    / (3/2 N), mean from step 300; the fluid's kT is 1),
  - md_steps, fewest: MD steps per collision step and the fewest MD steps
    per collision time met (summary.json adaptive_substeps),
  - md_over_rest: the colloid MD's wall time over all other stages' (cost,
    not physics; noisy where other processes run).
Then the same differences paired by seed.

usage: tools/compare_stiff_statistics.py PELOID [SEEDS] [FIRST_SEED]
"""
import csv
import json
import math
import os
import sys

import h5py
import numpy as np

import statistics_compare

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "bench", "scenes", "silica_10mM.cfg")
OBSERVE = ("observe: { rdf_interval = 5; rdf_start = 300; rdf_bins = 300; rdf_rmax = 3.0; msd_interval = 1; "
           "msd_start = 300; clusters_interval = 5; clusters_start = 300; clusters_gap = 0.1; };\n")
QUANTITIES = ["D", "msd_0.1s", "g_peak", "g_shell", "bonds", "clusters", "u_dlvo", "kT_colloid", "md_steps",
              "fewest", "md_over_rest"]
NOT_PHYSICS = ("md_steps", "fewest", "md_over_rest")


def scene_text(seed, mts):
    with open(SCENE) as f:
        text = f.read()
    text = text.replace("seed = 38;", "seed = %d;" % seed, 1).replace("steps = 200;", "steps = 1818;", 1)
    if mts:
        text = text.replace("coarse_graining: {", "coarse_graining: { multiple_time_stepping = true;", 1)
    return text + OBSERVE


def observables(out):
    s = json.load(open(os.path.join(out, "summary.json")))
    ob = s["observables"]
    v = {"D": ob["colloid_D"]["value"], "g_peak": ob["rdf_peak"]["value"]}
    with h5py.File(os.path.join(out, "observables.h5"), "r") as f:
        o = f["observables"]
        v["msd_0.1s"] = float(np.interp(0.1, o["colloid_msd/lag_si"][:], o["colloid_msd/value"][:, -1]))
        r, g = o["colloid_rdf/r"][:], o["colloid_rdf/value"][0]
        v["g_shell"] = float(g[(r > 1.24) & (r < 1.34)].mean())
        v["bonds"] = float(o["cluster_bonds/value"][:].mean())
        v["clusters"] = float(o["cluster_number/value"][:].mean())
    with open(os.path.join(out, "thermo.tsv")) as f:
        rows = [x for x in csv.DictReader(f, delimiter="\t") if int(x["step"]) >= 300]
    v["u_dlvo"] = float(np.mean([float(x["c_dlvo"]) for x in rows]))
    n = s["scene"]["colloids"]["count"]
    v["kT_colloid"] = float(np.mean([float(x["c_kin_trans"]) for x in rows])) / (1.5 * n)
    a = s["adaptive_substeps"]
    v["md_steps"], v["fewest"] = a["mean"], a["fewest_contact_steps"]
    st = s["stage_seconds"]
    v["md_over_rest"] = st["colloid-md"] / sum(x for k, x in st.items() if k != "colloid-md")
    return v


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    binary = os.path.abspath(sys.argv[1])
    seeds = int(sys.argv[2]) if len(sys.argv) > 2 else 8
    first = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    rows = statistics_compare.interleaved(
        range(first, first + seeds),
        [("old", binary, lambda s: scene_text(s, False)), ("new", binary, lambda s: scene_text(s, True))],
        observables, 1)
    print("# bench/scenes/silica_10mM.cfg, seeds %d..%d x 1818 collision steps (1 s): old = the default "
          "(adaptive substeps), new = coarse_graining.multiple_time_stepping = true" % (first, first + seeds - 1))
    statistics_compare.table(rows, QUANTITIES, NOT_PHYSICS)
    print("\n| quantity | new - old, paired by seed (mean +- SE) | z |")
    print("|---|---|---|")
    for q in QUANTITIES:
        d = np.array([b[q] - a[q] for a, b in zip(rows["old"], rows["new"])])
        se = d.std(ddof=1) / math.sqrt(len(d))
        print("| %s | %+.4g +- %.2g | %+.2f |" % (q, d.mean(), se, d.mean() / se if se > 0 else 0.0))
    return 0


if __name__ == "__main__":
    sys.exit(main())
