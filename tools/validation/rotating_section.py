"""The section "A rotating colloid: the torque with and without angular-momentum conservation" of
validation/REPORT.md, from the numbers tests/validation/rotating_colloid.sh measured (one '|'-separated line),
written between its markers (replaced where the report has it, else appended).  tools/validation_report.py keeps
the section when it rewrites the report.

    cd tools && python3 -m validation.rotating_section REPORT.md LINE COMMIT CPU STEPS"""
import sys

from validation.report_section import write_section

BEGIN = "<!-- rotating colloid: tests/validation/rotating_colloid.sh -->"
END = "<!-- end of the rotating colloid section -->"


def section(line, commit, cpu, steps):
    (t_n, s_n, t_a, s_a, rho, rho_se, p_asym, p_plain, asym, plain, sym_a, xi_e, eta_n, eta_rot_n, eta_a,
     nb) = map(float, line.split("|"))
    z = (rho - p_asym) / rho_se
    verdict = "agrees" if abs(z) <= 3 else "disagrees"
    return [
        BEGIN, "",
        "## A rotating colloid: the torque with and without angular-momentum conservation (MPC-AT, MPC-AT+a)", "",
        f"Measured at {commit} by `bash tests/validation/rotating_colloid.sh bin/peloid --md validation/REPORT.md` "
        f"(in `make validate-physics`; {cpu:.0f} CPU-s).  One coupling I colloid (stick_stochastic, R = 3 a0), held "
        "still and turning at Ω = 0.06/t0 (`coupling.pinned_spin`), in a periodic 16³ box of MPC-AT fluid (γ = 10, "
        f"Δt = 0.05), {steps:.0f} steps with each rule; the torque from thermo.tsv `cpl_torque_z` in {nb:.0f} blocks "
        "of 100 t0 after the first.  Theory (the script's header): the kinetic surface friction of the stochastic "
        f"reflections, ξ_E = (2π/3) n m v̄ R⁴ = {xi_e:.0f}, in series with the fluid's 8π η_rot R³.  MPC-AT+a's "
        "stress is symmetric (η_rot = η); MPC-AT relaxes the whole velocity gradient in a collision, so half of its "
        "collisional viscosity is an antisymmetric stress, which turns a rotating sphere with a third of its "
        "strength: η_rot = η_kin + ⅔ η_col.  Rule (written after one exploratory pair of runs at another seed): the "
        "ratio of the torques within 3 SE of that prediction, which the runs must tell from the plain-η one by 6 SE.",
        "",
        "| rule | η (rule's row) | η_rot | torque (kT), measured | series prediction |", "|---|---|---|---|---|",
        f"| MPC-AT | {eta_n:.3f} | {eta_rot_n:.3f} | {t_n:.1f} ± {s_n:.1f} | {asym:.1f} (with η: {plain:.1f}) |",
        f"| MPC-AT+a | {eta_a:.3f} | {eta_a:.3f} | {t_a:.1f} ± {s_a:.1f} | {sym_a:.1f} |", "",
        f"**{verdict}**: T(MPC-AT)/T(MPC-AT+a) = {rho:.4f} ± {rho_se:.4f} against {p_asym:.4f} for the "
        f"antisymmetric stress ({z:+.1f} SE) and {p_plain:.4f} for a symmetric stress with the planar-shear η "
        f"({(rho - p_plain) / rho_se:+.1f} SE).  Without angular-momentum conservation the fluid's torque on a "
        "rotating colloid is not the one its shear viscosity implies; with MPC-AT+a it is.  Each torque alone lies "
        f"{100 * (t_n / asym - 1):+.1f} % and {100 * (t_a / sym_a - 1):+.1f} % from its series prediction (the "
        "kinetic surface friction's form is an estimate; the ratio divides it out to first order).", "", END]


def main():
    report, line, commit, cpu, steps = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5])
    write_section(report, BEGIN, END, "\n".join(section(line, commit, cpu, steps)))

if __name__ == "__main__":
    main()
