"""Settling velocity of the colloids of a periodic physical run with the
fluid's counter-force (Hecht Sec. VIII.A iii), as a user's analysis would
compute it, with h5py alone and in SI: the colloids' mean -z velocity from
the unwrapped positions (position + image x box edge) of colloids.h5, in 16
blocks of the run (SE from their scatter), relative to the fluid's mean
velocity (total momentum zero: u_f = -N M v_c / N_f, the masses of
colloids.h5 and its /parameters, N_f from summary.json); against Stokes'
2/9 (rho_p - rho_f) g R^2 / (rho_f nu) times the box factor the mapping
states (summary.json mapping.colloid_diffusion: d_box / d_real,
Hasimoto's mobility in the box).  Independent of peloid's
own observers.

    python3 tools/h5md_settling.py RUN_DIR      (one line: v +- SE against the reference; exit 1
                                                unless within 10 % with SE < 3.3 %: the tests' rule)"""
import json
import sys

import h5py
import numpy as np

from h5md_lateral_diffusion import unwrapped


def block_falls(d, blocks=16, t_from=-np.inf):
    """The colloids' mean fall (-z, m/s) relative to the fluid in `blocks` equal blocks of the frames at t >= t_from
    (s), and the frame count: the box-frame fall times 1 + N M / N_f (total momentum zero).  A model-unit run: a0/t0."""
    with h5py.File(d + "/colloids.h5", "r") as f:  # kinetic masses: the model's times the energy scale, as m_f's
        m_c = f["particles/colloids/mass"][()].sum()
        m_f = float(f["parameters"].attrs["m_f"]) * float(f["parameters"].attrs.get("energy_scale", 1.0))
    t, r = unwrapped(d + "/colloids.h5")
    sel = t >= t_from
    t, z = t[sel], r[sel, :, 2]
    k = (len(t) - 1) // blocks  # the last block ends at the last frame (n - 1), n a multiple of blocks too
    vb = np.array([-(z[(b + 1) * k, :] - z[b * k, :]).mean() / (t[(b + 1) * k] - t[b * k]) for b in range(blocks)])
    rel = 1.0 + m_c / (json.load(open(d + "/summary.json"))["fluid_particles"] * m_f)  # the fluid's counter-flow
    return vb * rel, len(t)


def settling(d, blocks=16):
    s = json.load(open(d + "/summary.json"))
    m = s["mapping"]
    n = m["colloid"]["n_colloids"]
    cd = m["colloid_diffusion"]
    vb, nf = block_falls(d, blocks)
    ph = s["scene"]["physical"]
    stokes = 2.0 / 9.0 * (ph["particle_density"] - ph["solvent_density"]) * ph["gravity"] * ph["radius"] ** 2 / (
        ph["solvent_density"] * ph["viscosity"])
    box = cd["d_box_m2_s"] / cd["d_real_m2_s"]
    return vb.mean(), vb.std(ddof=1) / np.sqrt(blocks), stokes, box, n, nf


if __name__ == "__main__":
    v, se, stokes, box, n, nf = settling(sys.argv[1])
    ref = stokes * box
    print(f"v = {v:.4g} +- {se:.2g} m/s from colloids.h5 ({n} colloid(s), {nf} frames) vs Stokes {stokes:.4g} x box "
          f"factor {box:.4f} = {ref:.4g}: {100 * (v / ref - 1):+.1f} %, SE {100 * se / v:.1f} %")
    sys.exit(0 if abs(v / ref - 1) <= 0.10 and se / v <= 0.033 else 1)
