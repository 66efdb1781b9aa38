#!/usr/bin/python3
"""Independent reference for tests/unit/test_colloid_forces.c: barrier and secondary
minimum of the DLVO potential (Hecht Eqs. 1-2) for Hecht Fig. 1 parameters
(Al2O3, d = 0.5 um, water, 300 K), in SI units with numpy/scipy.  The minimum
is located as the root of the analytic derivative (Brent on V alone is only
sqrt(eps)-accurate in the position of a flat minimum)."""
import numpy as np
from scipy.optimize import brentq

E, KB, EPS0 = 1.602176634e-19, 1.380649e-23, 8.8541878128e-12


def v_kt(r, d, psi0, kappa, T=300.0, epsr=81.0, A=4.76e-20, z=1):
    kT = KB * T
    pre = np.pi * epsr * EPS0 * (4 * kT / (z * E) * np.tanh(z * E * psi0 / (4 * kT))) ** 2
    vc = pre * d * d / r * np.exp(-kappa * (r - d))
    vv = -A / 12 * (d * d / (r * r - d * d) + d * d / (r * r) + 2 * np.log((r * r - d * d) / (r * r)))
    return (vc + vv) / kT


def dv_kt(r, d, psi0, kappa, T=300.0, epsr=81.0, A=4.76e-20, z=1):
    kT = KB * T
    pre = np.pi * epsr * EPS0 * (4 * kT / (z * E) * np.tanh(z * E * psi0 / (4 * kT))) ** 2
    vc = pre * d * d / r * np.exp(-kappa * (r - d))
    return (-vc * (1 / r + kappa) + A * d ** 6 / (6 * r ** 3 * (r * r - d * d) ** 2)) / kT


def main():
    d, a0 = 0.5e-6, 1.25e-7
    for psi0, kappa in [(0.020, 1.4e8), (0.050, 2.0e8), (0.020, 1.0e8)]:
        h = np.linspace(1e-11, 3e-7, 300001)
        g = dv_kt(d + h, d, psi0, kappa)
        roots = [brentq(lambda x: dv_kt(d + x, d, psi0, kappa), h[i], h[i + 1], xtol=1e-22, rtol=1e-15)
                 for i in np.where(np.sign(g[:-1]) != np.sign(g[1:]))[0]]
        for x in roots:
            print("psi0=%g V kappa=%g /m: extremum at gap %.10g a0 (%.4g nm): V = %.10g kT"
                  % (psi0, kappa, x / a0, x * 1e9, v_kt(d + x, d, psi0, kappa)))


if __name__ == "__main__":
    main()
