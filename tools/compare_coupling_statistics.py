#!/usr/bin/python3
"""Statistical agreement of two peloid builds on a potential-coupling scene.

A change that alters which fluid particles the potential coupling's MD step
integrates (e.g. the selection by each particle's own reach) changes
trajectories bit for bit; this script shows that the physics is unchanged.
It runs scenes/coupling_potential.cfg's suspension (64 WCA colloids of
radius 2 a0 in 32^3 cells of SRD fluid, PL Eq. 17 coupling, 4 MD steps per
collision step, rescaling thermostat) with both binaries over several seeds
and compares, averaged over seeds with the standard error of the
seed-to-seed scatter:
  - the colloids' kinetic temperature (translational, second half),
  - their WCA energy per colloid (second half),
  - the fluid's kinetic temperature (thermo column, second half),
  - the colloids' diffusion coefficient from the MSD slope,
  - the colloid g(r) at its first peak,
  - the selected particle-steps per collision step (the cost; not physics).
Each difference is printed in units of the combined SE (|z| < 3 is agreement).

usage: tools/compare_coupling_statistics.py OLD_PELOID NEW_PELOID [SEEDS] [STEPS]
"""
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import h5md_colloids  # noqa: E402

SCENE = """name = "coupling_compare";
seed = {seed};
steps = {steps};
box: {{ cells = [32, 32, 32]; }};
fluid: {{ density = 5.0; temperature = 1.0; }};
srd: {{ dt = 0.1; rule = "random_axis"; alpha = 90.0; }};
thermostat: {{ type = "rescale"; temperature = 1.0; }};
colloids: {{ count = 64; radius = 2.0; mass_density = 5.0; temperature = 1.0; init = "lattice";
  pairs = "wca"; substeps = 4; trajectory_interval = 20; }};
wca: {{ epsilon = 2.5; sigma = 4.3; n = 24.0; }};
coupling: {{ method = "potential"; sigma_cf = 2.0; epsilon_cf = 2.5; }};
output: {{ thermo_interval = 20; }};
"""
N = 64


def run(binary, tag, seed, steps, tmp):
    cfg = os.path.join(tmp, "s%d.cfg" % seed)
    with open(cfg, "w") as f:
        f.write(SCENE.format(seed=seed, steps=steps))
    out = os.path.join(tmp, "%s_%d" % (tag, seed))
    subprocess.run([binary, "run", cfg, "--out", out, "--force", "--threads", "2"], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return out


def observables(out, steps):
    th = np.genfromtxt(os.path.join(out, "thermo.tsv"), names=True, delimiter="\t")
    half = len(th) // 2
    res = {"kT_colloid": np.mean(th["c_kin_trans"][half:]) / (1.5 * N),
           "u_wca": np.mean(th["c_wca"][half:]) / N,
           "T_fluid": np.mean(th["temperature"][half:])}
    c = h5md_colloids.load(os.path.join(out, "colloids.h5"))
    pos, img, t, L = c["pos"], c["img"], c["t"], c["edges"]
    edges = np.linspace(3.5, 12.0, 69)
    hist = np.zeros(len(edges) - 1)
    frames = range(len(t) // 2, len(t))
    for k in frames:
        d = pos[k][:, None, :] - pos[k][None, :, :]
        d -= L * np.rint(d / L)
        r = np.sqrt((d * d).sum(-1))[np.triu_indices(N, 1)]
        hist += np.histogram(r, edges)[0]
    shell = 4.0 / 3.0 * math.pi * (edges[1:] ** 3 - edges[:-1] ** 3)
    gr = hist / (len(frames) * N * (N - 1) / 2 / np.prod(L) * shell)
    res["g_peak"] = np.max(gr)
    xu = pos + img * L
    lags = np.arange(1, len(t) // 2)
    msd = np.array([np.mean(np.sum((xu[l:] - xu[:-l]) ** 2, axis=-1)) for l in lags])
    dt = t[1] - t[0]
    sel = lags >= len(lags) // 2
    res["D"] = np.polyfit(lags[sel] * dt, msd[sel], 1)[0] / 6.0
    with open(os.path.join(out, "summary.json")) as f:
        cpl = json.load(f).get("coupling", {})
    res["selected_per_step"] = cpl.get("selected_particle_steps", float("nan")) / steps
    return res


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    old, new = sys.argv[1], sys.argv[2]
    seeds = range(1, 1 + (int(sys.argv[3]) if len(sys.argv) > 3 else 6))
    steps = int(sys.argv[4]) if len(sys.argv) > 4 else 3000
    with tempfile.TemporaryDirectory() as tmp:
        rows = {"old": [], "new": []}
        for s in seeds:  # interleaved
            rows["old"].append(observables(run(old, "old", s, steps, tmp), steps))
            rows["new"].append(observables(run(new, "new", s, steps, tmp), steps))
    print("# %d seeds x %d collision steps, 64 WCA colloids in 32^3 cells of SRD fluid, potential coupling"
          % (len(seeds), steps))
    print("| quantity | old (mean +- SE) | new (mean +- SE) | z |")
    print("|---|---|---|---|")
    worst = 0.0
    for q in ["kT_colloid", "u_wca", "T_fluid", "D", "g_peak", "selected_per_step"]:
        a = np.array([r[q] for r in rows["old"]])
        b = np.array([r[q] for r in rows["new"]])
        sa, sb = a.std(ddof=1) / math.sqrt(len(a)), b.std(ddof=1) / math.sqrt(len(b))
        z = (b.mean() - a.mean()) / math.hypot(sa, sb) if sa + sb > 0 else 0.0
        if q != "selected_per_step":
            worst = max(worst, abs(z))
        print("| %s | %.5g +- %.2g | %.5g +- %.2g | %+.2f |" % (q, a.mean(), sa, b.mean(), sb, z))
    print("# largest |z| (physics rows) = %.2f" % worst)
    return 0


if __name__ == "__main__":
    sys.exit(main())
