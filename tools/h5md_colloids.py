"""Read peloid's colloids.h5 (H5MD 1.1) back in model units (a0, t0, m_f).

A scene with physical{} writes nm, ps and kg (so that MDAnalysis converts
them); /parameters holds a0 and t0 in those units, which this divides out.
Also reads files from before the H5MD units (box/edges a plain 3-vector).
"""
import h5py
import numpy as np


class InputError(Exception):
    """A file that cannot be read as peloid's colloids.h5: "FILE: what is wrong"."""


def load(path):
    """dict: pos, vel (T x N x 3), img (T x N x 3), t, step (T), edges (3),
    mass, rad (N), all in a0, t0, m_f.  Raises InputError (one line naming
    the file) on a missing, truncated or corrupt file or a missing dataset."""
    try:
        return _load(path)
    except FileNotFoundError:
        raise InputError(f"{path}: no such file (colloids.h5 needs colloids.trajectory_interval > 0)") from None
    except (OSError, KeyError, ValueError, TypeError, IndexError) as e:
        raise InputError(f"{path}: unreadable ({type(e).__name__}: {e}); allowed: the colloids.h5 "
                         "peloid run writes") from None


def _load(path):
    with h5py.File(path, "r") as f:
        g = f["particles/colloids"]
        a0, t0, mf = 1.0, 1.0, 1.0
        if "parameters" in f:
            p = f["parameters"].attrs
            a0, t0, mf = float(p["a0"]), float(p["t0"]), float(p["m_f"])
        e = g["box/edges"]
        edges = e["value"][0] if isinstance(e, h5py.Group) else e[()]
        edges = np.diag(edges) if np.ndim(edges) == 2 else np.asarray(edges)
        # a physical scene writes kinetic masses (the model mass times
        # /parameters/energy_scale) and the real ones as an attribute
        m = g["mass"]
        mass = (np.asarray(m.attrs["real_mass_kg"]) if "real_mass_kg" in m.attrs else m[()]) / mf
        return {"pos": g["position/value"][()] / a0, "vel": g["velocity/value"][()] * t0 / a0,
                "img": g["image/value"][()], "t": g["position/time"][()] / t0,
                "step": g["position/step"][()], "edges": edges / a0, "mass": mass,
                "rad": g["radius"][()] / a0}


def unwrapped(path):
    """The colloids' unwrapped positions (T x N x 3, a0): position + image x edges."""
    c = load(path)
    return c["pos"] + c["img"] * c["edges"][None, None, :]

