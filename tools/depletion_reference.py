#!/usr/bin/python3
"""Independent reference for tests/physics/test_depletion.c: the depletion potential
that an ideal fluid with the colloid-fluid WCA potential of PL Eq. 17 induces
between two colloids (PL Eqs. 22-23),
    Phi(d) = -n_f kT  Int f(|r|) f(|r - d z|) d^3r,   f = exp(-phi_cf/kT) - 1,
integrated here in cylindrical coordinates (rho, z) with scipy's dblquad,
independently of the bipolar-coordinate quadrature of src/colloid/depletion.c; and
PL Eq. 24 for hard spheres.  Prints the values the test checks."""
import numpy as np
from scipy.integrate import dblquad


def mayer(r, sigma, eps, kT=1.0, n=6.0):
    rc = 2.0 ** (1.0 / n) * sigma
    if r >= rc:
        return 0.0
    if r < 1e-3 * sigma:
        return -1.0
    s = (sigma / r) ** n
    return np.expm1(-4.0 * eps * (s * s - s + 0.25) / kT)


def phi_depl(d, sigma, eps, density, kT=1.0, n=6.0):
    rc = 2.0 ** (1.0 / n) * sigma
    if d >= 2.0 * rc:
        return 0.0
    zlo, zhi = d - rc, rc  # the lens: |r| < rc and |r - d z| < rc

    def integrand(rho, z):
        return 2.0 * np.pi * rho * mayer(np.hypot(rho, z), sigma, eps, kT, n) * \
            mayer(np.hypot(rho, z - d), sigma, eps, kT, n)

    def rho_max(z):
        return np.sqrt(max(0.0, min(rc * rc - z * z, rc * rc - (z - d) ** 2)))

    val, err = dblquad(integrand, zlo, zhi, lambda z: 0.0, rho_max, epsabs=1e-11, epsrel=1e-11)
    return -density * kT * val


def phi_hs(d, sigma, density, kT=1.0):
    """PL Eq. 24."""
    if d >= 2.0 * sigma:
        return 0.0
    return -density * kT * 4.0 / 3.0 * np.pi * sigma ** 3 * (1 - 3 * d / (4 * sigma) + d ** 3 / (16 * sigma ** 3))


def main():
    sigma, eps, gamma = 2.0, 2.5, 5.0
    for d in [0.0, 1.0, 2.0, 3.0, 3.5, 3.9, 4.0, 4.1, 4.2, 4.3, 4.4, 4.45, 4.49]:
        print("sigma_cf=%g eps_cf=%g gamma=%g d=%-5g  Phi_WCA = %.10g kT   Phi_HS (Eq. 24) = %.10g kT"
              % (sigma, eps, gamma, d, phi_depl(d, sigma, eps, gamma), phi_hs(d, sigma, gamma)))


if __name__ == "__main__":
    main()
