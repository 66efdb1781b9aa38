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
import os
import sys

import numpy as np

import statistics_compare

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


def observables(out, steps):
    th = np.genfromtxt(os.path.join(out, "thermo.tsv"), names=True, delimiter="\t")
    half = len(th) // 2
    res = {"kT_colloid": np.mean(th["c_kin_trans"][half:]) / (1.5 * N),
           "u_wca": np.mean(th["c_wca"][half:]) / N,
           "T_fluid": np.mean(th["temperature"][half:])}
    gr, _, _, res["D"] = statistics_compare.colloid_structure(out, N, np.linspace(3.5, 12.0, 69))
    res["g_peak"] = np.max(gr)
    with open(os.path.join(out, "summary.json")) as f:
        cpl = json.load(f).get("coupling", {})
    res["selected_per_step"] = cpl.get("selected_particle_steps", float("nan")) / steps
    return res


def main():
    return statistics_compare.main(
        __doc__, SCENE, 2, observables,
        "# %d seeds x %d collision steps, 64 WCA colloids in 32^3 cells of SRD fluid, potential coupling",
        ["kT_colloid", "u_wca", "T_fluid", "D", "g_peak", "selected_per_step"], not_physics=("selected_per_step",),
        seeds=6, steps=3000)


if __name__ == "__main__":
    sys.exit(main())
