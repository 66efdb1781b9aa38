#!/usr/bin/python3
"""Statistical agreement of multiple time stepping with the one-step MD on
Hecht's Fig. 14 suspension.

Runs bench/scenes/fig14_model.cfg's system (1155 DLVO + Hertz colloids, R =
0.62 a0, phi = 0.34, Psi0 = 50 mV, kappa = 3e8 /m, SRD fluid with coupling
II and the Heyes thermostat, 125 MD steps per collision step) from the
lattice start, once with colloids.slow_interval = 1 and once with K (default
5), over several seeds, and compares, averaged over seeds with the standard
error of the seed-to-seed scatter:
  - the colloids' kinetic temperature (translational, second half),
  - their DLVO energy per colloid (second half; clustering into the 6.3 kT
    secondary minimum drives it down),
  - the number of bonds per colloid (pairs within gap 0.1 a0, i.e. in the
    secondary minimum's well, last frame),
  - the colloid g(r) at its first peak (second half of the frames),
  - the colloids' mean squared displacement at the end,
  - the fluid's kinetic temperature,
  - the wall seconds per collision step (the cost; not physics).
Each difference is printed in units of the combined SE (|z| < 3 is agreement).

usage: tools/compare_mts_statistics.py PELOID [SEEDS] [STEPS] [K] [THREADS] [FIRST_SEED]

Each run's values are also appended to bench/out/mts_statistics.tsv (tag,
seed, steps, k, quantities), so that runs of other seeds can be pooled.
"""
import json
import math
import os
import sys

import numpy as np

import h5md_colloids
import statistics_compare

SCENE = """name = "mts_compare";
seed = {seed};
steps = {steps};
box: {{ cells = [15, 15, 15]; }};
fluid: {{ density = 10.0; temperature = 1.0; }};
srd: {{ dt = 0.1; rule = "hecht_axes"; grid_shift = true; }};
thermostat: {{ type = "heyes"; temperature = 1.0; heyes_epsilon = 0.1; }};
colloids: {{ count = 1155; radius = 0.62; mass_density = 39.0; temperature = 1.0; init = "lattice";
  pairs = "dlvo, hertz"; substeps = 125; slow_interval = {k}; trajectory_interval = 20; }};
dlvo: {{ psi0 = 50.0; kappa = 3.0e8; hamaker = 4.76e-20; length_unit = 4.03e-7; primary_depth = 6.0; }};
hertz: {{ K = 1000.0; }};
coupling: {{ method = "hecht2"; }};
output: {{ thermo_interval = 20; }};
"""
N = 1155


def observables(out, steps):
    th = np.genfromtxt(os.path.join(out, "thermo.tsv"), names=True, delimiter="\t")
    half = len(th) // 2
    res = {"kT_colloid": np.mean(th["c_kin_trans"][half:]) / (1.5 * N),
           "u_dlvo": np.mean(th["c_dlvo"][half:]) / N,
           "T_fluid": np.mean(th["temperature"][half:])}
    gr, _, _, _ = statistics_compare.colloid_structure(out, N, np.linspace(1.2, 3.0, 91))
    res["g_peak"] = float(np.max(gr))
    c = h5md_colloids.load(os.path.join(out, "colloids.h5"))
    pos, img, L = c["pos"], c["img"], c["edges"]
    d = pos[-1][:, None, :] - pos[-1][None, :, :]
    d -= L * np.rint(d / L)
    r = np.sqrt((d * d).sum(-1))[np.triu_indices(N, 1)]
    res["bonds_per_colloid"] = 2.0 * np.count_nonzero(r < 2 * 0.62 + 0.1) / N
    xu = pos + img * L
    res["msd_end"] = float(np.mean(np.sum((xu[-1] - xu[0]) ** 2, axis=-1)))
    with open(os.path.join(out, "summary.json")) as f:
        res["wall_s_per_step"] = json.load(f)["wall_seconds"] / steps
    return res


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    binary = os.path.abspath(sys.argv[1])
    seeds = int(sys.argv[2]) if len(sys.argv) > 2 else 4
    steps = int(sys.argv[3]) if len(sys.argv) > 3 else 300
    k = int(sys.argv[4]) if len(sys.argv) > 4 else 5
    threads = int(sys.argv[5]) if len(sys.argv) > 5 else 2
    first = int(sys.argv[6]) if len(sys.argv) > 6 else 1
    tsv = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "bench", "out",
                       "mts_statistics.tsv")
    os.makedirs(os.path.dirname(tsv), exist_ok=True)
    kk = {"old": 1, "new": k}

    def record(tag, s, values):
        with open(tsv, "a") as f:
            f.write("\t".join([tag, str(s), str(steps), str(kk[tag])] +
                               ["%s=%.10g" % kv for kv in sorted(values.items())]) + "\n")

    rows = statistics_compare.interleaved(
        range(first, first + seeds),
        [(tag, binary, lambda s, kt=kk[tag]: SCENE.format(seed=s, steps=steps, k=kt)) for tag in ("old", "new")],
        lambda out: observables(out, steps), threads, record)
    print("# Fig. 14 model suspension, %d seeds x %d collision steps: old = slow_interval 1, new = %d"
          % (seeds, steps, k))
    statistics_compare.table(rows, ["kT_colloid", "u_dlvo", "bonds_per_colloid", "g_peak", "msd_end",
                                    "T_fluid", "wall_s_per_step"], not_physics=("wall_s_per_step",))
    return 0


if __name__ == "__main__":
    sys.exit(main())
