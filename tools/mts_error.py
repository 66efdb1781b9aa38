#!/usr/bin/python3
"""Multiple time stepping (colloids.slow_interval): error against run time.

    tools/mts_error.py PELOID [STEPS] [THREADS] [INTERVALS] [SEEDS]

Hecht's Fig. 14 colloids (bench/scenes/fig14_model.cfg: 1155 DLVO + Hertz
colloids, R = 0.62 a0, phi = 0.34) alone (no fluid: NVE, so the energy is a
constant of the exact motion), from the lattice start, STEPS collision
steps of 0.1 t0 (default 100; at least 20) at 125 MD substeps (rounded up to a
multiple of k), for each slow_interval k in INTERVALS (default 1,5,10,25), SEEDS seeds (default 2; the seed draws
the initial velocities).  Reported per k, mean over seeds:
  - wall seconds per collision step (the run loop, summary.json);
  - the largest energy drift max |E(t) - E(0)| / N over the run (kT per
    colloid, thermo every collision step);
  - the RMS position error against a reference run of the same seed with
    4x finer MD step (500 substeps, k = 1) at t = 0.5, 1 and 2 t0 (the
    single-step row is velocity Verlet's own error; any difference then
    grows chaotically, by ~10x per t0 here, and saturates near 1.7 a0 by
    10 t0, so later times compare nothing).
Prints a markdown table and writes it to bench/out/mts_error.tsv."""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

import h5md_colloids

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

SCENE = """name = "mts_error";
seed = {seed};
box: {{ cells = [15, 15, 15]; }};
fluid: {{ density = 0.0; }};
srd: {{ dt = 0.1; }};
colloids: {{
  count = 1155; radius = 0.62; mass_density = 39.0; temperature = 1.0; init = "lattice";
  pairs = "dlvo, hertz"; substeps = {sub}; slow_interval = {k}; max_energy_drift = 0.0;
  trajectory_interval = {traj};
}};
dlvo: {{ psi0 = 50.0; kappa = 3.0e8; hamaker = 4.76e-20; length_unit = 4.03e-7; primary_depth = 6.0; }};
hertz: {{ K = 1000.0; }};
output: {{ thermo_interval = 1; }};
"""


def run(peloid, tmp, seed, sub, k, steps, threads):
    tag = "s%d_n%d_k%d" % (seed, sub, k)
    cfg = os.path.join(tmp, tag + ".cfg")
    out = os.path.join(tmp, tag)
    with open(cfg, "w") as f:
        f.write(SCENE.format(seed=seed, sub=sub, k=k, traj=5))
    subprocess.run([peloid, "run", cfg, "--steps", str(steps), "--threads", str(threads),
                    "--out", out, "--force"], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    summ = json.load(open(os.path.join(out, "summary.json")))
    th = np.genfromtxt(os.path.join(out, "thermo.tsv"), names=True, delimiter="\t")
    e = th["c_total"]
    pos = h5md_colloids.unwrapped(os.path.join(out, "colloids.h5"))
    return {"wall": summ["wall_seconds"] / steps, "drift": np.max(np.abs(e - e[0])) / 1155.0, "pos": pos}


def rms(a, b):
    return float(np.sqrt(np.mean(np.sum((a - b) ** 2, axis=-1))))


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    peloid = os.path.abspath(sys.argv[1])
    steps = int(sys.argv[2]) if len(sys.argv) > 2 else 100
    threads = int(sys.argv[3]) if len(sys.argv) > 3 else 2
    ks = [int(x) for x in (sys.argv[4] if len(sys.argv) > 4 else "1,5,10,25").split(",")]
    seeds = int(sys.argv[5]) if len(sys.argv) > 5 else 2
    rows = {k: [] for k in ks}
    with tempfile.TemporaryDirectory() as tmp:
        for s in range(seeds):
            seed = 14 + s
            ref = run(peloid, tmp, seed, 500, 1, steps, threads)
            for k in ks:
                # 125 MD steps per collision step, rounded up to a multiple of k
                r = run(peloid, tmp, seed, -(-125 // k) * k, k, steps, threads)
                r["sub"] = -(-125 // k) * k
                r["err"] = [rms(r["pos"][f], ref["pos"][f]) for f in (1, 2, 4)]
                rows[k].append(r)
    lines = ["| slow_interval | MD substeps | wall s per collision step | max energy drift (kT/colloid) | "
             "RMS position error at 0.5 t0 (a0) | at 1 t0 | at 2 t0 |",
             "|---|---|---|---|---|---|---|"]
    tsv = ["k\tsubsteps\twall_s_per_step\tdrift\terr_0.5t0\terr_1t0\terr_2t0"]
    for k in ks:
        w = np.mean([r["wall"] for r in rows[k]])
        d = np.mean([r["drift"] for r in rows[k]])
        e = np.mean([r["err"] for r in rows[k]], axis=0)
        lines.append("| %d | %d | %.4f | %.2e | %.2e | %.2e | %.2e |" % (k, rows[k][0]["sub"], w, d, *e))
        tsv.append("%d\t%d\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g" % (k, rows[k][0]["sub"], w, d, *e))
    print("\n".join(lines))
    os.makedirs(os.path.join(ROOT, "bench", "out"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "out", "mts_error.tsv"), "w") as f:
        f.write("\n".join(tsv) + "\n")


if __name__ == "__main__":
    main()
