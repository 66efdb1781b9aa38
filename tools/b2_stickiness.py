#!/usr/bin/python3
"""Equilibrium stickiness of Hecht's DLVO pair potential (issue 39, validation/RULES_disagreements.md R1-R2).

    /usr/bin/python3 tools/b2_stickiness.py [--png PATH]             the tables (and the plot)
    /usr/bin/python3 tools/b2_stickiness.py --selftest                 checks against analytic cases

V(r) = Hecht Eq. 1 + Eq. 2 in SI units, the constants of studies/hecht_fig9_base.cfg as `peloid params`
derives them (R = 0.25 um, A_H = 4.76e-20 J, T = 300 K, eps_r of water at 300 K = 77.6481, z = 1).
Hard core at the barrier: r_b = the centre distance of V's maximum, V = inf inside.
  B2 = 2 pi int_0^inf (1 - exp(-V/kT)) r^2 dr,  B2_HS = (2 pi / 3) r_b^3,  B2* = B2 / B2_HS,
  Baxter's stickiness tau from B2* = 1 - 1/(4 tau)  (adhesive hard spheres of diameter r_b),
  tau_c = 0.0976 (Baxter's critical point), tau_p(phi) = (19 phi^2 - 2 phi + 1) / (12 (1 - phi)^2)
  (Chiew & Glandt 1983, Percus-Yevick percolation of adhesive spheres).
Escape from the secondary minimum (relative diffusion D_rel = 2 D0, D0 = kT / (6 pi eta R), the mapped D):
outward V has no saddle, so the mean first-passage time of radial Smoluchowski diffusion (reflecting at
r_b) to the well's edge (V = V_min / 10) and to r_min + d; inward, Kramers over the barrier;
Smoluchowski collision time of one colloid at number density n: t_coll = 1 / (4 pi D_rel r_b n)."""
import math
import sys

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

E, KB, EPS0 = 1.602176634e-19, 1.380649e-23, 8.8541878128e-12
TAU_C = 0.0976  # Baxter 1968: critical stickiness of adhesive hard spheres

# studies/hecht_fig9_base.cfg through `peloid params` (physical.permittivity derived: water at 300 K)
SCENE = dict(R=0.25e-6, A=4.76e-20, T=300.0, epsr=77.6481, z=1, eta=1.0e-3, phi=0.14)


def tau_p(phi):
    """Chiew & Glandt 1983: percolation stickiness of PY adhesive hard spheres."""
    return (19 * phi * phi - 2 * phi + 1) / (12 * (1 - phi) ** 2)


def tau_of_b2(b2s):
    """Baxter: B2* = 1 - 1 / (4 tau)."""
    return 1.0 / (4.0 * (1.0 - b2s))


class Dlvo:
    """Hecht Eqs. 1-2 in kT; r the centre distance in m."""

    def __init__(self, psi0, kappa, R=SCENE["R"], A=SCENE["A"], T=SCENE["T"], epsr=SCENE["epsr"], z=SCENE["z"],
                 cut_gap=None):
        self.d, self.kappa, self.A, self.kT = 2 * R, kappa, A, KB * T
        self.pre = math.pi * epsr * EPS0 * (4 * self.kT / (z * E) * math.tanh(z * E * psi0 / (4 * self.kT))) ** 2
        self.cut = None if cut_gap is None else self.d + cut_gap

    def v(self, r):
        d = self.d
        vc = self.pre * d * d / r * np.exp(-self.kappa * (r - d))
        vv = -self.A / 12 * (d * d / (r * r - d * d) + d * d / (r * r) + 2 * np.log((r * r - d * d) / (r * r)))
        out = (vc + vv) / self.kT
        if self.cut is not None:
            out = np.where(r > self.cut, 0.0, out)
        return out

    def dv(self, r):
        d = self.d
        vc = self.pre * d * d / r * np.exp(-self.kappa * (r - d))
        return (-vc * (1 / r + self.kappa) + self.A * d ** 6 / (6 * r ** 3 * (r * r - d * d) ** 2)) / self.kT

    def d2v(self, r, h=None):
        h = h or 1e-4 * (r - self.d)
        return (self.dv(r + h) - self.dv(r - h)) / (2 * h)

    def extrema(self):
        """(r_barrier, r_secondary_min) from the roots of V' (None where V has no barrier)."""
        d = self.d
        h = np.geomspace(1e-11, 3e-7, 200001)
        g = self.dv(d + h)
        idx = np.where(np.sign(g[:-1]) != np.sign(g[1:]))[0]
        roots = [brentq(lambda x: self.dv(d + x), h[i], h[i + 1], xtol=1e-22, rtol=1e-14) for i in idx]
        if len(roots) < 2:
            return None, None
        return d + roots[0], d + roots[1]


def mfpt(pot, r_b, r_m, drel, r_e):
    """Mean first-passage time (s) of the pair separation from r_m to r_e by radial Smoluchowski diffusion
    in V, reflecting at the barrier r_b: int_{r_m}^{r_e} dr e^{V(r)} / (D r^2) int_{r_b}^{r} e^{-V(s)} s^2 ds
    (escape outward from the secondary well, where V has no outer saddle, so no Kramers saddle formula)."""
    inner = lambda r: quad(lambda s: math.exp(-float(pot.v(s))) * s * s, r_b, r, limit=200, epsrel=1e-8)[0]
    return quad(lambda r: math.exp(float(pot.v(r))) / (drel * r * r) * inner(r), r_m, r_e, limit=200,
                epsrel=1e-6)[0]


def t_inward(pot, r_b, r_m, drel):
    """Kramers time (s) of the inward escape over the barrier into the primary minimum (high friction):
    2 pi / (D sqrt(V''(r_m) |V''(r_b)|)) e^{V(r_b) - V(r_m)}, V in kT, curvatures in kT/m^2."""
    return 2 * math.pi / (drel * math.sqrt(pot.d2v(r_m) * abs(pot.d2v(r_b)))) * math.exp(float(pot.v(r_b) - pot.v(r_m)))


def b2_star(pot, r_b, rmax=None):
    """B2* with a hard core at r_b: 1 + (3 / r_b^3) int_{r_b}^inf (1 - exp(-V)) r^2 dr."""
    rmax = rmax or r_b + 40.0 / getattr(pot, "kappa", 1.0)
    f = lambda r: (1.0 - math.exp(-float(pot.v(r)))) * r * r
    pts = [r_b, r_b * (1 + 1e-3), r_b * (1 + 1e-2), r_b * 1.1, rmax]
    tot = sum(quad(f, a, b, limit=400, epsabs=0, epsrel=1e-10)[0] for a, b in zip(pts[:-1], pts[1:]) if b > a)
    return 1.0 + 3.0 * tot / r_b ** 3


def point(psi0, kappa, cut_gap=None, phi=SCENE["phi"], eta=SCENE["eta"]):
    """All numbers of one (Psi0, kappa): dict."""
    p = Dlvo(psi0, kappa)
    rb, rm = p.extrema()
    if rb is None:
        return dict(psi0=psi0, kappa=kappa, barrier=None)
    pc = Dlvo(psi0, kappa, cut_gap=cut_gap) if cut_gap else p
    b2 = b2_star(pc, rb, rmax=(p.d + cut_gap) if cut_gap else None)
    vb, vm = float(p.v(rb)), float(p.v(rm))
    R = p.d / 2
    d0 = p.kT / (6 * math.pi * eta * R)
    drel = 2 * d0
    t_edge, t_away = mfpt(p, rb, rm, drel, brentq(lambda r: float(p.v(r)) - vm / 10.0, rm, rm + 1e-6)), None
    t_away = mfpt(p, rb, rm, drel, rm + p.d)
    t_in = t_inward(p, rb, rm, drel)
    n = phi / (4.0 / 3.0 * math.pi * R ** 3)
    t_coll = 1.0 / (4 * math.pi * drel * rb * n)
    return dict(psi0=psi0, kappa=kappa, r_b=rb, gap_b=rb - p.d, V_b=vb, gap_m=rm - p.d, V_m=vm, b2=b2,
                b2_d=1.0 + (b2 - 1.0) * rb ** 3 / p.d ** 3,
                tau=tau_of_b2(b2) if b2 < 1 else float("inf"), t_edge=t_edge, t_away=t_away, t_in=t_in, t_coll=t_coll, D0=d0)


def crossing(kappas, taus, target):
    """kappa where tau(kappa) crosses target (tau falls with kappa), by linear interpolation in log tau."""
    for i in range(len(kappas) - 1):
        a, b = taus[i], taus[i + 1]
        if (a - target) * (b - target) <= 0 and a != b:
            x = (math.log(target) - math.log(a)) / (math.log(b) - math.log(a))
            return kappas[i] + x * (kappas[i + 1] - kappas[i])
    return None


def fig9_table(psi0=0.020, kappas=None, cut_gap=None):
    kappas = kappas or [0.8e8, 0.9e8, 1.0e8, 1.1e8, 1.2e8, 1.25e8, 1.3e8, 1.4e8, 1.5e8, 1.6e8, 1.8e8, 2.0e8]
    return [point(psi0, k, cut_gap) for k in kappas]


def boundary_eps81(target):
    """kappa where tau crosses target at eps_r = 81 (the dlvo section's model-unit default; Hecht gives no eps_r):
    how much the boundary depends on the solvent's permittivity."""
    ks = [1.0e8, 1.1e8, 1.2e8, 1.3e8, 1.4e8, 1.5e8]
    taus = []
    for k in ks:
        p = Dlvo(0.020, k, epsr=81.0)
        rb, _ = p.extrema()
        taus.append(tau_of_b2(b2_star(p, rb)))
    return crossing(ks, taus, target)


def selftest():
    """Analytic checks: (1) square well of depth e and range lambda sigma: B2* = 1 - (lambda^3 - 1)(e^e - 1);
    (2) Baxter's limit of a narrow deep well: tau = 1 / (12 (lambda - 1) (e^e - 1)) (to first order in the
    width); (3) Chiew-Glandt at phi = 0.14 = 0.1231; (4) Hecht Eqs. 1-2 against tools/dlvo_reference.py's
    numbers at 20 mV, 1.4e8 /m with eps_r = 81 (tests/unit/test_colloid_forces.c: barrier 10.1, secondary minimum
    -3.0 kT, both recomputed here independently)."""
    ok = True

    class SW:
        def __init__(self, e, lam):
            self.e, self.lam, self.kappa = e, lam, 1.0

        def v(self, r):
            return -self.e if r < self.lam else 0.0

    for e, lam in [(1.0, 1.5), (2.0, 1.1), (0.5, 1.05)]:
        got = 1.0 + 3.0 * quad(lambda r: (1 - math.exp(-SW(e, lam).v(r))) * r * r, 1.0, lam,
                               epsabs=0, epsrel=1e-12)[0]
        exact = 1.0 - (lam ** 3 - 1) * (math.exp(e) - 1)
        ok &= abs(got - exact) < 1e-9
        print(f"square well e = {e}, lambda = {lam}: B2* = {got:.10f}, analytic {exact:.10f}")
        got_b = b2_star(SW(e, lam), 1.0, rmax=lam)
        ok &= abs(got_b - exact) < 1e-8
        print(f"  b2_star(): {got_b:.10f}")
    e, lam = 4.0, 1.001
    tau = tau_of_b2(1.0 - (lam ** 3 - 1) * (math.exp(e) - 1))
    baxter = 1.0 / (12 * (lam - 1) * (math.exp(e) - 1))
    ok &= abs(tau / baxter - 1) < 0.01
    print(f"Baxter limit: tau = {tau:.6f}, 1/(12 (lambda-1)(e^e-1)) = {baxter:.6f}")
    ok &= abs(tau_p(0.14) - 0.12307) < 1e-4
    print(f"Chiew-Glandt tau_p(0.14) = {tau_p(0.14):.5f}")
    p = Dlvo(0.020, 1.4e8, epsr=81.0)
    rb, rm = p.extrema()
    print(f"Hecht Eqs. 1-2, eps_r = 81: barrier {float(p.v(rb)):.3f} kT at gap {(rb - p.d) * 1e9:.2f} nm, "
          f"secondary minimum {float(p.v(rm)):.3f} kT at gap {(rm - p.d) * 1e9:.2f} nm")
    ok &= rb < rm and float(p.v(rb)) > 0 > float(p.v(rm))
    # peloid params studies/hecht_fig9_base.cfg (eps_r 77.6481): barrier 9.994 kT, secondary -2.935 kT
    q = Dlvo(0.020, 1.4e8)
    rb, rm = q.extrema()
    print(f"scene eps_r: barrier {float(q.v(rb)):.3f} kT (peloid params 9.994), secondary {float(q.v(rm)):.3f} kT "
          f"(peloid params -2.935), gap {(rm - q.d) / 4.02998e-7:.5f} a0 (0.07332)")
    ok &= abs(float(q.v(rb)) - 9.994) < 0.01 and abs(float(q.v(rm)) + 2.935) < 0.002
    print("selftest:", "ok" if ok else "FAILED")
    return ok


def tables():
    """The markdown lines of the report's stickiness tables (Fig. 9 at 20 mV, Fig. 11 at 2e8 /m)."""
    lines = []
    tp = tau_p(SCENE["phi"])
    lines.append(f"Hecht Eqs. 1–2, Ψ0 = 20 mV, scene constants (ε_r = {SCENE['epsr']}, 300 K), hard core at the barrier; "
                 f"τ_c = {TAU_C}, τ_p(φ = {SCENE['phi']}) = {tp:.4f}; mapped D0 = kT/6πηR.")
    lines.append("")
    lines.append("| κ (1e8 /m) | barrier kT (gap nm) | secondary min kT (gap nm) | B2* | B2* (d³ norm.) | τ | "
                 "B2* (V cut at 50 nm) | τ (cut) | escape to the well's edge ms | escape by one d ms | "
                 "over the barrier s | collision ms |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
    tab, tabc = fig9_table(), fig9_table(cut_gap=50e-9)
    for a, c in zip(tab, tabc):
        lines.append(f"| {a['kappa'] / 1e8:.2f} | {a['V_b']:.2f} ({a['gap_b'] * 1e9:.1f}) | {a['V_m']:.3f} "
                     f"({a['gap_m'] * 1e9:.1f}) | {a['b2']:.3f} | {a['b2_d']:.3f} | {a['tau']:.4f} | {c['b2']:.3f} | "
                     f"{c['tau']:.4f} | {a['t_edge'] * 1e3:.2f} | {a['t_away'] * 1e3:.1f} | {a['t_in']:.3g} | "
                     f"{a['t_coll'] * 1e3:.1f} |")
    ks = [a["kappa"] for a in tab]
    kp = crossing(ks, [a["tau"] for a in tab], tp)
    kc = crossing(ks, [a["tau"] for a in tab], TAU_C)
    kpc = crossing(ks, [a["tau"] for a in tabc], tp)
    kcc = crossing(ks, [a["tau"] for a in tabc], TAU_C)
    f = lambda x: "none in range" if x is None else f"{x / 1e8:.3f}e8 /m"
    lines.append("")
    lines.append(f"κ_p (τ = τ_p): {f(kp)}; κ_c (τ = τ_c): {f(kc)}; with V cut at 50 nm: κ_p {f(kpc)}, κ_c {f(kcc)}; with "
                 f"ε_r = 81 instead: κ_p {f(boundary_eps81(tp))}, κ_c {f(boundary_eps81(TAU_C))}.  "
                 "The issue's B2* (−0.25, −1.15, −2.77, −6.2 at 1.0, 1.2, 1.4, 1.6e8) differ by definition: "
                 "normalised by d³ (not r_b³) at 293 K with ε_r = 80.1 they are " + ", ".join(
                     f"{issue_b2(k):.2f}" for k in (1.0e8, 1.2e8, 1.4e8, 1.6e8)) + ".")
    lines.append("")
    lines.append("| Fig. 11, κ = 2e8 /m: Ψ0 (mV) | tanh² factor | highest point between the minima kT | "
                 "secondary min kT | B2* | τ |")
    lines.append("|---|---|---|---|---|---|")
    for psi in (0.020, 0.035, 0.050):
        a = point(psi, 2.0e8)
        t = math.tanh(E * psi / (4 * KB * SCENE["T"])) ** 2
        lines.append(f"| {psi * 1e3:.0f} | {t:.5f} | {a['V_b']:.2f} | {a['V_m']:.3f} | {a['b2']:.3f} | {a['tau']:.4f} |")
    return lines


def issue_b2(kappa):
    """B2* as issue 39 quotes it (reproduced, not used by a rule): hard core at the barrier, normalised by the
    contact diameter d, 293 K, eps_r = 80.1."""
    p = Dlvo(0.020, kappa, T=293.0, epsr=80.1)
    rb, _ = p.extrema()
    return 1.0 + (b2_star(p, rb) - 1.0) * rb ** 3 / p.d ** 3


def main_plot(png):
    """Fig. 9's tau(kappa) beside Fig. 11's potentials."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    tp = tau_p(SCENE["phi"])
    tab, tabc = fig9_table(), fig9_table(cut_gap=50e-9)
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    kk = np.array([a["kappa"] for a in tab]) / 1e8
    ax[0].semilogy(kk, [a["tau"] for a in tab], "o-", label="τ, Hecht Eqs. 1–2 (20 mV)")
    ax[0].semilogy(kk, [c["tau"] for c in tabc], "s--", label="τ, V cut at a 50 nm gap")
    ax[0].axhline(tp, color="g", ls=":", label=f"τ_p(φ=0.14) = {tp:.3f} (Chiew–Glandt)")
    ax[0].axhline(TAU_C, color="r", ls=":", label="τ_c = 0.0976 (Baxter)")
    ax[0].axvspan(1.0, 1.4, color="C0", alpha=0.12, label="peloid's boundary bracket")
    ax[0].axvspan(1.4, 1.6, color="C3", alpha=0.12, label="Hecht's boundary bracket")
    ax[0].set_xlabel("κ (1e8 /m)")
    ax[0].set_ylabel("Baxter stickiness τ")
    ax[0].legend(fontsize=7)
    ax[0].set_title("Fig. 9, 20 mV: stickiness of Eqs. 1–2")
    for psi in (20, 35, 50):
        a = point(psi / 1e3, 2.0e8)
        p = Dlvo(psi / 1e3, 2.0e8)
        h = np.linspace(0.5e-9, 40e-9, 400)
        ax[1].plot(h * 1e9, p.v(p.d + h), label=f"Ψ0 = {psi} mV: min {a['V_m']:.2f} kT, max {a['V_b']:.1f} kT")
    ax[1].set_ylim(-8, 40)
    ax[1].axhline(0, color="k", lw=0.5)
    ax[1].set_xlabel("surface gap (nm)")
    ax[1].set_ylabel("V / kT")
    ax[1].set_title("Fig. 11, κ = 2e8 /m: Eqs. 1–2")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def main():
    if "--selftest" in sys.argv:
        sys.exit(0 if selftest() else 1)
    print("\n".join(tables()))
    if "--png" in sys.argv:
        main_plot(sys.argv[sys.argv.index("--png") + 1])


if __name__ == "__main__":
    main()
