#!/usr/bin/python3
"""The stiff suspension's colloid MD: error against run time of its integrator variants.

    tools/stiff_error.py PELOID [STEPS] [SEEDS] [THREADS]

The colloids of bench/scenes/silica_10mM.cfg (issue 38: silica, R = 0.3 um,
10 mM salt, phi = 0.10, walls) alone, in the model units its mapping derives
(read from `peloid run SCENE --steps 0`, summary.json "scene"): the same DLVO
+ Hertz pairs, walls and gravity, no fluid and no coupling, so the MD
conserves the energy exactly and every difference is the integrator's.  From
the lattice start, STEPS collision steps of the scene's SRD step (default
300), SEEDS seeds (default 2; the seed draws the initial velocities), per
variant:
  - fixed    the contact guard's fixed substeps (colloids.adaptive_substeps = false)
  - A5       adaptive substeps, margin 5 kT (the default)
  - A5+MTS   A5 + multiple time stepping as coarse_graining.multiple_time_stepping
             derives it for the scene (slow_gap, slow_interval read from its
             summary.json)
  - A5M12    A5 + multiple time stepping, slow_gap = 0.1 a0, slow_interval = 12
and a reference of 4x the fixed substeps.  Reported, mean over seeds: MD
steps per collision step, wall seconds per collision step, the largest
energy drift max |E(t) - E(0)| / N (kT per colloid, thermo every collision
step) and the RMS position error against the reference at 0.5, 1 and 2
collision steps' worth of t0 multiples (trajectory frames every collision
step; differences grow chaotically afterwards, so later times compare
nothing).  Prints a markdown table; writes bench/out/stiff_error.tsv."""
import argparse
import json
import os
import subprocess
import tempfile

import numpy as np

import h5md_colloids

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "bench", "scenes", "silica_10mM.cfg")


def model(peloid, tmp, mts=False):
    """The scene's model units (summary.json "scene"), with mts its derived multiple time stepping."""
    scene, out = SCENE, os.path.join(tmp, "derive%d" % mts)
    if mts:
        scene = os.path.join(tmp, "mts.cfg")
        with open(SCENE) as f:
            text = f.read()
        with open(scene, "w") as f:
            f.write(text.replace("coarse_graining: {", "coarse_graining: { multiple_time_stepping = true;", 1))
    subprocess.run([peloid, "run", scene, "--steps", "0", "--out", out, "--force"], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return json.load(open(os.path.join(out, "summary.json")))["scene"]


def variants(peloid, tmp):
    c = model(peloid, tmp, True)["colloids"]
    k, gap = int(c["slow_interval"]), c["slow_gap"]
    return [("fixed", "adaptive_substeps = false;", 1),
            ("A5", "adaptive_substeps = true;", 1),
            ("A5+MTS (k = %d, slow_gap = %.4g)" % (k, gap),
             "adaptive_substeps = true; slow_interval = %d; slow_gap = %r;" % (k, gap), k),
            ("A5M12", "adaptive_substeps = true; slow_interval = 12; slow_gap = 0.1;", 12)]


def scene_text(m, seed, sub, nmin, keys):
    c, d, h = m["colloids"], m["dlvo"], m["hertz"]
    b = m["box"]
    return f"""name = "stiff_error";
seed = {seed};
box: {{ cells = [{b['cells'][0]}, {b['cells'][1]}, {b['cells'][2]}]; walls_z = "{b['walls_z']}"; }};
fluid: {{ density = 0.0; }};
srd: {{ dt = {m['srd']['dt']!r}; }};
colloids: {{
  count = {c['count']}; radius = {c['radius']!r}; mass_density = {c['mass_density']!r}; temperature = 1.0;
  init = "lattice"; pairs = "{c['pairs']}"; gravity = [{c['gravity'][0]!r}, {c['gravity'][1]!r}, {c['gravity'][2]!r}];
  substeps = {sub}; min_substeps = {nmin}; max_energy_drift = 0.0; trajectory_interval = 1; {keys}
}};
dlvo: {{ psi0 = {abs(d['psi0'])!r}; kappa = {d['kappa']!r}; hamaker = {d['hamaker']!r}; length_unit = {d['length_unit']!r};
        eps_r = {d['eps_r']!r}; temperature = {d['temperature']!r}; primary_depth = {d['primary_depth']!r}; z = {d['z']!r}; }};
hertz: {{ K = {h['K']!r}; }};
output: {{ thermo_interval = 1; }};
"""


def run(peloid, tmp, m, tag, seed, sub, nmin, keys, steps, threads):
    cfg = os.path.join(tmp, "%s_%d.cfg" % (tag, seed))
    out = os.path.join(tmp, "%s_%d" % (tag, seed))
    with open(cfg, "w") as f:
        f.write(scene_text(m, seed, sub, nmin, keys))
    subprocess.run([peloid, "run", cfg, "--steps", str(steps), "--threads", str(threads), "--out", out,
                    "--force"], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    summ = json.load(open(os.path.join(out, "summary.json")))
    th = np.genfromtxt(os.path.join(out, "thermo.tsv"), names=True, delimiter="\t")
    e = th["c_total"]
    n = m["colloids"]["count"]
    pos = h5md_colloids.unwrapped(os.path.join(out, "colloids.h5"))
    a = summ.get("adaptive_substeps") or {}
    return {"wall": summ["wall_seconds"] / steps, "drift": float(np.max(np.abs(e - e[0]))) / n, "pos": pos,
            "md": a.get("mean", float(sub))}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("peloid")
    ap.add_argument("steps", nargs="?", type=int, default=300)
    ap.add_argument("seeds", nargs="?", type=int, default=2)
    ap.add_argument("threads", nargs="?", type=int, default=1)
    a = ap.parse_args()
    peloid, steps, seeds, threads = os.path.abspath(a.peloid), a.steps, a.seeds, a.threads
    with tempfile.TemporaryDirectory() as tmp:
        m = model(peloid, tmp)
        vs = variants(peloid, tmp)
        rows = {v[0]: [] for v in vs}
        sub, nmin = int(m["colloids"]["substeps"]), int(m["colloids"]["min_substeps"])
        dt = m["srd"]["dt"]
        frames = [max(1, int(round(t / dt))) for t in (0.5, 1.0, 2.0)]
        for s in range(seeds):
            seed = 1 + s
            ref = run(peloid, tmp, m, "ref", seed, 4 * sub, 4 * sub, "adaptive_substeps = false;", steps, threads)
            for i, (tag, keys, k) in enumerate(vs):
                ks, kn = -(-sub // k) * k, -(-nmin // k) * k
                r = run(peloid, tmp, m, "v%d" % i, seed, ks, kn, keys, steps, threads)
                r["err"] = [float(np.sqrt(np.mean(np.sum((r["pos"][f] - ref["pos"][f]) ** 2, axis=-1)))) for f in frames]
                rows[tag].append(r)
        ref_drift = ref["drift"]
    lines = ["| variant | MD steps / collision step | wall s per collision step | max energy drift (kT/colloid) | "
             "RMS position error at 0.5 t0 (a0) | at 1 t0 | at 2 t0 |",
             "|---|---|---|---|---|---|---|",
             "| reference (%d fixed) | %d | - | %.2e | 0 | 0 | 0 |" % (4 * sub, 4 * sub, ref_drift)]
    tsv = ["variant\tmd_steps\twall_s_per_step\tdrift\terr_0.5t0\terr_1t0\terr_2t0"]
    for tag, _, _ in vs:
        md = np.mean([r["md"] for r in rows[tag]])
        w = np.mean([r["wall"] for r in rows[tag]])
        d = np.mean([r["drift"] for r in rows[tag]])
        e = np.mean([r["err"] for r in rows[tag]], axis=0)
        lines.append("| %s | %.1f | %.4f | %.2e | %.2e | %.2e | %.2e |" % (tag, md, w, d, *e))
        tsv.append("%s\t%.2f\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g" % (tag, md, w, d, *e))
    print("\n".join(lines))
    os.makedirs(os.path.join(ROOT, "bench", "out"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "out", "stiff_error.tsv"), "w") as f:
        f.write("\n".join(tsv) + "\n")


if __name__ == "__main__":
    main()
