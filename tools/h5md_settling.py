"""Settling velocity of the colloids of a periodic physical run with the
fluid's counter-force (Hecht Sec. VIII.A iii), as a user's analysis would
compute it, with h5py alone and in SI: the colloids' mean -z velocity from
the unwrapped positions (position + image x box edge) of colloids.h5, in 16
blocks of the run (SE from their scatter), relative to the fluid's mean
velocity (total momentum zero: u_f = -N M v_c / N_f, masses from
summary.json); against Stokes' 2/9 (rho_p - rho_f) g R^2 / (rho_f nu) times
the box factor the mapping states (summary.json mapping.colloid_diffusion:
d_box / d_real, Hasimoto's mobility in the box).  Independent of peloid's
own observers.

    python3 tools/h5md_settling.py RUN_DIR      (prints v SE ref n_colloids frames)"""
import json
import sys

import h5py
import numpy as np


def settling(d, blocks=16):
    s = json.load(open(d + "/summary.json"))
    m = s["mapping"]
    n = m["colloid"]["n_colloids"]
    cd = m["colloid_diffusion"]
    with h5py.File(d + "/colloids.h5", "r") as f:
        g = f["particles/colloids"]
        u = {"nm": 1e-9, "um": 1e-6, "m": 1.0}
        pu = g["position/value"].attrs["unit"]
        pu = pu.decode() if isinstance(pu, bytes) else pu
        tu = g["position/time"].attrs["unit"]
        tu = tu.decode() if isinstance(tu, bytes) else tu
        Lz = np.diag(g["box/edges/value"][0])[2]
        z = (g["position/value"][()][:, :, 2] + g["image/value"][()][:, :, 2] * Lz) * u[pu]
        t = g["position/time"][()] * {"ps": 1e-12, "ns": 1e-9, "s": 1.0}[tu]
    k = len(t) // blocks
    vb = np.array([-(z[(b + 1) * k, :] - z[b * k, :]).mean() / (t[(b + 1) * k] - t[b * k]) for b in range(blocks)])
    rel = 1.0 + n * m["colloid"]["mass_m_f"] / s["fluid_particles"]  # relative to the fluid's counter-flow
    ph = s["scene"]["physical"]
    stokes = 2.0 / 9.0 * (ph["particle_density"] - ph["solvent_density"]) * ph["gravity"] * ph["radius"] ** 2 / (
        ph["solvent_density"] * ph["viscosity"])
    box = cd["d_box_m2_s"] / cd["d_real_m2_s"]
    return vb.mean() * rel, vb.std(ddof=1) / np.sqrt(blocks) * rel, stokes, box, n, len(t)


if __name__ == "__main__":
    v, se, stokes, box, n, nf = settling(sys.argv[1])
    print(v, se, stokes * box, n, nf)
