"""The section "Collective hydrodynamics: the colloid D in two boxes (Hasimoto)" of validation/REPORT.md, from
the numbers tests/validation/hasimoto_boxes.sh measured (one '|'-separated line), written between its markers
(replaced where the report has it, else appended).  tools/validation_report.py keeps the section when it
rewrites the report.

    cd tools && python3 -m validation.hydro_section REPORT.md LINE COMMIT"""
import sys

from validation.report_section import write_section

BEGIN = "<!-- collective hydrodynamics: tests/validation/hasimoto_boxes.sh -->"
END = "<!-- end of the collective hydrodynamics section -->"


def section(line, commit):
    f = line.split("|")
    (m16, s16, t16, D16, m32, s32, t32, D32, pred, z, rh16, rh32, rhc, Ic, Is, cpu) = map(float, f[:16])
    n16, n32, wall = map(int, f[16:19])
    Isi, Issi, nu, dcal, dcal_se = float(f[19]), float(f[20]), float(f[21]), float(f[22]), float(f[23])
    cells = [r.split(":") for r in f[24].split(",")] if len(f) > 24 and f[24] else []
    verdict = "agrees" if abs(z) < 3 else "disagrees"
    return [
        BEGIN, "",
        "## Collective hydrodynamics: the colloid D in two boxes (Hasimoto)", "",
        f"Measured at {commit} by `bash tests/validation/hasimoto_boxes.sh bin/peloid --md validation/REPORT.md` "
        f"({cpu:.0f} CPU-s, {wall} s wall on the 2-core machine).  The model of `scenes/quickstart.cfg` (coupling II, "
        "γ = 10, λ = 0.25, α = 130°, R = 0.62 a0, M = 39 m_f) in its calibration box (32 free colloids, 16³ cells) "
        "and in one twice as wide at the same colloid density (256 colloids, 32³); colloids.h5 read with h5py; the "
        "calibration's estimator (MSD secant slope over [6, 18] t0, 8 blocks of origins) plus the tail the window "
        "misses in that box (its transverse modes, computed by the script); SE from the scatter of the runs' blocks (8 a run).  "
        f"Rule, fixed before the runs: D_32 − D_16 against Hasimoto's kT 2.837/(6π η)(1/16 − 1/32) with ν of PL "
        f"Eqs. 9–12 ({nu:.4f} a0²/t0) within 3 SE (its first version compared D_16 − D_32, which Hasimoto makes "
        "negative, with that positive difference: a sign error of the check, mended after its first run; runs, "
        "estimator and bound unchanged).", "",
        "| box | runs | slope [6, 18] t0 | + tail | D_L (a0²/t0) | D_∞ = D_L + Hasimoto | R_h/R |",
        "|---|---|---|---|---|---|---|",
        f"| 16³, 32 colloids | {n16} | {m16:.5f} ± {s16:.5f} | {t16:.5f} | {D16:.5f} | "
        f"{D16 + (pred * 2):.5f} ± {s16:.5f} | {rh16:.3f} |",
        f"| 32³, 256 colloids | {n32} | {m32:.5f} ± {s32:.5f} | {t32:.5f} | {D32:.5f} | "
        f"{D32 + pred:.5f} ± {s32:.5f} | {rh32:.3f} |", "",
        f"**{verdict}**: D_32 − D_16 = {D32 - D16:.5f} ± {(s16 ** 2 + s32 ** 2) ** 0.5:.5f} against Hasimoto's "
        f"{pred:.5f} ({z:+.1f} SE).  Both boxes together: D_∞ = {Ic:.5f} ± {Is:.5f} a0²/t0 = {Isi:.4g} ± {Issi:.2g} "
        f"m²/s, R_h/R = {rhc:.3f} ± {rhc * Is / Ic:.3f} (the shipped calibration: D_∞ = {dcal:.5f} ± {dcal_se:.5f}, "
        f"R_h/R = {rhc * Ic / dcal:.3f}).  "
        + ("The box dependence follows the fluid's viscosity, as Hasimoto's correction assumes, and the two boxes "
           "give one D_∞ within the SE: the model colloid's hydrodynamic radius is the coupling's, not the box's.  "
           if abs(z) < 3 else
           "The box dependence does not follow Hasimoto's correction with the fluid's viscosity: D_∞ and R_h "
           "depend on the box beyond the SE.  ")
        + f"R_h/R = {rhc:.2f}: box corrections, hindered settling and lubrication have the strength of a sphere "
        "of R_h.  Not run here: coupling I and the potential coupling, and the collective settling (K, "
        "Richardson–Zaki: the Fig. 4 verdict above and the hindered-settling sections below).", ""] + cell_lines(cells, rhc, rhc * Is / Ic) + [END]


def cell_lines(cells, rhc, rse):
    """R_h/R against the cell size (the script's second part), if measured."""
    if not cells:
        return []
    top = max(float(r[1]) for r in cells)
    d = [r for r in cells if abs(float(r[0]) - 1.61) < 0.01]  # the quickstart's own a0/R, 1.612
    same = (f"  At the quickstart's own a0/R this fresh calibration (another seed stream: the cell size is given "
            f"to three digits) reads {float(d[0][1]):.3f} ± {float(d[0][2]):.3f} against {rhc:.3f} ± {rse:.3f} "
            f"from the long runs above ({(float(d[0][1]) - rhc) / float(d[0][2]):+.1f} SE of the calibration)."
            if d and float(d[0][2]) > 0 else "")
    return ["**R_h/R against the cell size** (reported, not a test): the quickstart with "
            "`coarse_graining.cell_size` = a0/R set, each calibrated afresh (`peloid params --calibrate auto`, an "
            "empty cache); the colloid's mass falls as (R/a0)³.", "",
            "| a0/R | colloid mass (m_f) | R_h/R |", "|---|---|---|"] + [
        f"| {r[0]} | {float(r[3]):.3g} | {float(r[1]):.3f} ± {float(r[2]):.3f} |" for r in cells] + [
        "", f"The largest R_h/R is {top:.2f}: the coupling II colloid is a point to the fluid (Hecht Sec. VII.C), "
        "a coarser cell makes it lighter, and R_h/R levels off as the cell grows: none of these cell sizes comes near "
        "R_h = R; the factor is what `peloid params` and `peloid plan` report." + same, ""]


def main():
    report, line, commit = sys.argv[1], sys.argv[2], sys.argv[3]
    write_section(report, BEGIN, END, "\n".join(section(line, commit)))

if __name__ == "__main__":
    main()
