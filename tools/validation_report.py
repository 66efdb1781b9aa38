#!/usr/bin/python3
"""validation/REPORT.md from the outputs of the studies in studies/ (make
validation-report; the studies run with make studies, i.e. peloid sweep on
each studies/*.cfg).

    /usr/bin/python3 tools/validation_report.py [OUT_STUDIES] [REPORT]
    /usr/bin/python3 tools/validation_report.py --verdicts-only [OUT_STUDIES] [REPORT]

    /usr/bin/python3 tools/validation_report.py --update NAME[,NAME...] [OUT_STUDIES] [REPORT]
    /usr/bin/python3 tools/validation_report.py --notes-only [OUT_STUDIES] [REPORT]

--verdicts-only rewrites only the section "Verdicts of the disagreement rows" (tools/validation/verdicts.py, between its
markers) of an existing REPORT, leaving the rest as the last full generation wrote it (make
validation-verdicts: for a report whose studies' outputs are not on this machine); a verdict row whose own
studies have no outputs in OUT_STUDIES is kept from the section as last written, marked so.

--notes-only is --update with no entries: the notes (NOTES) alone, every row kept (make
validation-notes).

--update rewrites, in an existing REPORT, the rows of the named STUDIES entries (their table row, their
details paragraph: the one that opens with the same bold title, and their plot) from OUT_STUDIES and the
notes (NOTES) (the verdict section: --verdicts-only), and adds the runs' git revisions to the report's line naming them;
every other row stays as the last generation wrote it (make validation-update ENTRIES=...: rerun some
studies without the CPU hours of all of them).

For each study below: the paper's figure and value, peloid's value +- SE
from the study's sweep.json and each point's summary.json, the run time
(the points' wall seconds, and the threads they ran with), and a verdict
computed by a stated rule; the study's plot is copied beside the report.  A
study that has not been run gets a row saying so; nothing is filled in by
hand.  The evaluations live in tools/validation/, one module per paper figure
or guide; this file holds the table of studies (STUDIES), the reduced checks
of make check (REDUCED), the notes and the report's assembly.
"""
import os
import shutil
import subprocess
import sys

from validation.common import load, run_time
from validation.fluid_guides import accuracy_fluid_diffusion, accuracy_viscosity, reduced_accuracy_fluid_diffusion, reduced_accuracy_viscosity
from validation.hecht_clusters import (fig14_msd, fig9_bonds, fig9_diagram, fig9_kappa, fig9_phi, reduced_fig14_msd,
                                       reduced_fig9_bonds, reduced_fig9_diagram, reduced_fig9_kappa, reduced_fig9_phi)
from validation.hecht_rdf import fig5_rdf, reduced_fig5_rdf
from validation import hydro_section, rotating_section, verdicts
import array_mobility
import fluid_equilibrium
import hindered_matched
import hindered_nlaw
import hindered_settling
import potential_gap
import rh_matched
import rh_resolution
from validation.hecht_rz import fig4_rz, reduced_fig4_rz, rz_precision
from validation.pl_drag import pl_drag_guide, pl_fig6_drag, reduced_pl_fig6_drag
from validation.pl_fig10 import pl_fig10_vacf, reduced_pl_fig10_vacf
from validation.pl_fig11 import pl_fig11_dphi, reduced_pl_fig11_dphi
from validation.pl_fig4 import pl_fig4_rdf, reduced_pl_fig4_rdf


STUDIES = [
    {
        "name": "hecht_fig9_kappa",
        "study": "studies/hecht_fig9_kappa.cfg",
        "figure": "Hecht 2005 Figs. 9, 12–13",
        "paper": "Ψ0 = 20 mV, φ = 0.14, 1 s: suspended at κ = 1.4e8 /m, clustered at 1.6e8 /m",
        "size": "Hecht's system: (6 µm)³ box (15³ cells, 33750 fluid particles), 472 colloids "
                "(Hecht 462: box rounded to whole cells), scenes/hecht_fig9.cfg's 1140 steps, seed 9",
        "eval": fig9_kappa,
    },
    {
        "name": "hecht_fig9_kappa_replica",
        "study": "studies/hecht_fig9_kappa_replica.cfg",
        "figure": "Hecht 2005 Figs. 12–13 (replica)",
        "paper": "as above: suspended at κ = 1.4e8 /m, clustered at 1.6e8 /m",
        "size": "as above, seed 10",
        "eval": fig9_kappa,
    },
    {
        "name": "hecht_fig9_kappa_1s",
        "study": "studies/hecht_fig9_kappa_1s.cfg",
        "figure": "Hecht 2005 Figs. 12–13 (1 s)",
        "paper": "κ = 1.4e8 /m, Ψ0 = 20 mV, 1 s: suspended",
        "size": "as above, seed 9, 1788 steps, observers over steps 894–1788",
        "eval": fig9_kappa,
    },
    {
        "name": "hecht_fig9_bonds",
        "study": "studies/hecht_fig9_bonds.cfg",
        "figure": "Hecht 2005 Figs. 12–13 (bond kinds)",
        "paper": "κ = 1.4e8 /m suspended, 1.6e8 /m clustered (Ψ0 = 20 mV)",
        "size": "as hecht_fig9_kappa, seed 9, energy bonds (pair energy < −1 kT; primary when closer than the barrier)",
        "eval": fig9_bonds,
    },
    {
        "name": "hecht_fig9_diagram",
        "study": "studies/hecht_fig9_diagram.cfg",
        "figure": "Hecht 2005 Figs. 9–11",
        "paper": "φ = 0.14: clustering in the upper left of Fig. 9 (S1: κ = 2e8, 20 mV), suspended in the lower right "
                 "(S2: 7.3e7, 50 mV); S3: at 20 mV the boundary between κ = 1.4e8 and 1.6e8 /m (Figs. 10, 12–13); "
                 "S4: at κ = 2e8 clustering grows with Ψ0 (Fig. 11)",
        "size": "as hecht_fig9_kappa (472 colloids, 1140 steps), seed 9, κ = 7.3e7–3e8 /m × Ψ0 = 10–50 mV (24 points)",
        "eval": fig9_diagram,
    },
    {
        "name": "hecht_fig9_phi",
        "study": "studies/hecht_fig9_phi.cfg",
        "figure": "Hecht 2005 Figs. 12–13",
        "paper": "Ψ0 = 20 mV, φ = 0.07–0.35: suspended at κ = 1.4e8 /m (S5), clustered at 1.6e8 /m (S6)",
        "size": "(6 µm)³ box (15³ cells), 236–1181 colloids, 1140 steps, seed 9",
        "eval": fig9_phi,
    },
    {
        "name": "hecht_fig5_rdf",
        "study": "studies/hecht_fig5_rdf.cfg",
        "figure": "Hecht 2005 Figs. 5–7",
        "paper": "Ψ0 = 50 mV; κ = 3e8 /m: peaks at 2R (A), (4/3)√6 R (B), 2√3 R (C), 4R (D); κ = 7.3e7 /m: "
                 "those absent, first peak at the secondary minimum",
        "size": "as hecht_fig9_kappa (φ = 0.14, 472 colloids, 1140 steps), seed 9, g(r) in bins of 0.032 R",
        "eval": fig5_rdf,
    },
    {
        "name": "hecht_fig4_rz",
        "study": "studies/hecht_fig4_rz.cfg",
        "figure": "Hecht 2005 Fig. 4, Eq. 37",
        "paper": "v_s(φ) = v∞ (1 − φ)^l, periodic, coupling II, Pe = 1: l = 3.5; Pe = 0.5 and 2 similar",
        "size": "(6 µm)³ periodic box (15³ cells), R = 0.25 µm, φ = 0.05–0.35, Hertz repulsion only, "
                "Hertz K = 1e5 kT/a0^2.5, 9600 steps (40 τ_D) per point, seed 4",
        "eval": fig4_rz,
    },
    {
        "name": "hecht_fig14_msd",
        "study": "studies/hecht_fig14_msd.cfg",
        "figure": "Hecht 2005 Fig. 14",
        "paper": "Ψ0 = 50 mV, κ = 3e8 /m, φ = 0.35: diffusion, then a cluster-induced slow-down",
        "size": "scenes/hecht_fig14.cfg: (6 µm)³, 1181 colloids, coupling II; D from the MSD over the first and the "
                "last quarter of 1140 steps, seed 14",
        "eval": fig14_msd,
    },
    {
        "name": "pl_fig6_drag",
        "study": "studies/pl_fig6_drag.cfg",
        "figure": "PL 2006 Figs. 5–6, Eqs. 40–44",
        "paper": "friction of a pinned slip sphere = Stokes (finite box) ∥ Enskog; a_eff = 1.55 a0 at σ_cf = 2 a0 "
                 "in L = 16 σ_cf",
        "size": "scenes/coupling_drag.cfg (γ = 5, α = 90°, λ = 0.1, ε_cf = 2.5 kT, Re ≈ 0.4), 26000 steps, seed 5",
        "eval": pl_fig6_drag,
    },
    {
        "name": "pl_fig4_rdf",
        "study": "studies/pl_fig4_rdf.cfg",
        "figure": "PL 2006 Fig. 4, Sec. III.C.1",
        "paper": "g(r) of SRD (potential coupling, compensating potential) and BD virtually indistinguishable "
                 "within statistical errors; without the compensation SRD's g(r) noticeably higher at contact",
        "size": "studies/pl_fig4_rdf_base.cfg: 73 colloids in 24³ a0³ (φ_c = 0.22), SRD 30000 steps with and 24000 "
                "without depletion_comp, BD 200000 steps, g(r) from step 3000 (300 t0), seed 4; companion "
                "studies/pl_fig4_rdf_bd_dt.cfg: BD at ½ and ¼ of the step (~100 s CPU more)",
        "eval": pl_fig4_rdf,
    },
    {
        "name": "accuracy_viscosity",
        "study": "studies/accuracy_viscosity.cfg",
        "figure": "PL Eqs. 9–15 (the guide)",
        "paper": "η of the SRD fluid from PL's kinetic + collisional theory",
        "size": "10³ cells, ρ = 3, 5, 10, λ = 0.1, 0.3, 1, 3000–192000 steps, seed 21",
        "eval": accuracy_viscosity,
    },
    {
        "name": "pl_fig11_dphi",
        "study": "studies/pl_fig11_dphi.cfg",
        "figure": "PL 2006 Fig. 11, Eq. 58 (+ guide)",
        "paper": "D(φ) = D0 (1 − 1.1795 φ) at low φ (slip spheres, PL ref. [90]); a colloid's D vs kT/ξ",
        "size": "L = 16 a0 (γ = 5, α = 90°, λ = 0.1, σ_cf = 2 a0, ε_cf = 2.5 kT, σ_cc = 4.3 a0), N = 1, 4, 8, 16, 27 "
                "(φ = 0.008–0.22), 30000–330000 steps (3000–33000 t0), seeds 111–127; D from the MSD over lags 40–100 t0; "
                "studies/pl_fig11_dphi_solvent.cfg: N = 4, 8, 16, 27 with γ = 5 in the free volume, the same steps (N = 16: 60000)",
        "eval": pl_fig11_dphi,
    },
    {
        "name": "accuracy_fluid_diffusion",
        "study": "studies/accuracy_fluid_diffusion.cfg",
        "figure": "PL Eq. 6 (the guide)",
        "paper": "D_f of the SRD fluid in the random-collision approximation (holds for λ ≳ 0.6, PL Sec. II)",
        "size": "ρ = 5, α = 130°, 5³, 10³, 20³ cells (625–40000 particles), λ = 0.3, 0.6, 1, 3000 steps and "
                "prefixes, 4 seeds",
        "eval": accuracy_fluid_diffusion,
    },
    {
        "name": "pl_fig6_drag_guide",
        "sweep": "pl_fig6_drag",
        "study": "studies/pl_fig6_drag.cfg",
        "figure": "PL Eqs. 40–43 (the guide)",
        "paper": "friction of a pinned slip sphere, PL Eqs. 40–43 as PL evaluate them",
        "size": "as pl_fig6_drag, and its σ_cf = 2, L = 16 point at 1, 2 and 8 MD substeps "
                "(studies/accuracy_drag_substeps.cfg); run length from prefixes of the runs",
        "eval": pl_drag_guide,
    },
    {
        "name": "hecht_fig4_rz_precision",
        "sweep": "hecht_fig4_rz",
        "study": "studies/hecht_fig4_rz.cfg",
        "figure": "Hecht Fig. 4, Eq. 37 (the guide: precision only)",
        "paper": "no exact reference for l (Hecht 3.5, Richardson–Zaki 4.65: empirical)",
        "size": "as hecht_fig4_rz; run length from prefixes of its runs",
        "eval": rz_precision,
    },
    {
        "name": "pl_fig10_vacf",
        "study": "studies/pl_fig10_vacf.cfg",
        "figure": "PL 2006 Figs. 10, 13, Eqs. 50–57, B3–B13",
        "paper": "VACF decays first as exp(−t/τ_E), τ_E = M_c/ξ_E (1.26 t0), faster than Langevin exp(−t/τ_B), then "
                 "as the hydrodynamic tail kT/(12ρ(πνt)^3/2), above Langevin; C_FF decays within ~Δt_c (τ_FP ≈ "
                 "0.09 t0); τ_FP ≪ τ_E, τ_B < τ_ν ≪ τ_D",
        "size": "scenes/coupling_potential.cfg, PL's L = 32 a0 (163840 fluid particles), 8 colloids (φ = 0.008), "
                "6 runs × 18000 steps (seeds 101–106)",
        "eval": pl_fig10_vacf,
    },
]


# The reduced studies of make check (tests/cli/studies_reduced.sh runs studies/reduced/NAME.cfg for every NAME
# here and asserts the check): each returns (passed, one-line message).
REDUCED = {
    "hecht_fig9_kappa": reduced_fig9_kappa,
    "hecht_fig9_bonds": reduced_fig9_bonds,
    "hecht_fig9_diagram": reduced_fig9_diagram,
    "hecht_fig5_rdf": reduced_fig5_rdf,
    "hecht_fig14_msd": reduced_fig14_msd,
    "accuracy_viscosity": reduced_accuracy_viscosity,
    "accuracy_fluid_diffusion": reduced_accuracy_fluid_diffusion,
    "pl_fig10_vacf": reduced_pl_fig10_vacf,
    "pl_fig4_rdf": reduced_pl_fig4_rdf,
    "pl_fig11_dphi": reduced_pl_fig11_dphi,
    "hecht_fig4_rz": reduced_fig4_rz,
    "pl_fig6_drag": reduced_pl_fig6_drag,
    "hecht_fig9_phi": reduced_fig9_phi,
    "hecht_fig9_lub": verdicts.reduced_fig9_lub,
}


def mapped_time(sw):
    """Real time the runs covered: steps x srd.dt x t0 (summary.json units_si)."""
    ts = set()
    for p in sw["points"]:
        s = p["summary"]
        if s and "units_si" in s:
            ts.add(round(s["last_step"] * s["scene"]["srd"]["dt"] * s["units_si"]["t0_s"], 3))
    return ", ".join(f"{t:g} s" for t in sorted(ts))


NOTES = [
    "**PL Fig. 4 (g(r), SRD vs BD).**  By the rule fixed before the runs (χ² of the difference from contact, "
    "p ≥ 0.001, and the contact peak within 3 SE) peloid *disagrees*: χ²/dof = 203/78.  Two bins carry it: "
    "4.2–4.3 a0 (SRD 0.0247 ± 0.0010 vs BD 0.0343 ± 0.0003, −9.7 SE) and 4.3–4.4 a0 (+4.2 SE), the steep rise "
    "of g where the WCA falls from ~16 to ~1 kT.  There the BD reference at PL's step (0.025 t0, 0.023 a0 rms "
    "per step) is not converged: at ½ and ¼ of the step the 4.2–4.3 bin falls to 0.0284 and 0.0259 "
    "(−17 and −21 SE), extrapolating to 0.0233 ± 0.0006, within 1.2 SE of SRD, whose colloids move ~0.002 "
    "a0 per MD step.  Against that extrapolation (post hoc, not the rule) SRD with the compensation still "
    "gives χ²/dof ≈ 2 (p ≈ 5e-7): its first peak (4.3–5.0 a0) lies 2–3.5 SE (~3–5 %) above BD; SRD without "
    "the compensation gives p ≈ 0.02, and the two SRD runs agree with each other (p ≈ 0.02) — beyond 4.49 a0 "
    "their potentials are identical, so their χ²/dof of ~1.4 there measures how far the blocking SEs of a "
    "2700 t0 SRD run understate the scatter.  Hence: PL's 'indistinguishable' holds beyond the first peak; at "
    "the peak SRD is a few per cent higher than BD, at 2–3 SE per bin, which these runs (≈ 10 min CPU) cannot "
    "settle.  PL's contact excess without the compensation is not resolved, as expected at σ_cc = 4.3 a0, "
    "where the depletion potential of PL Eqs. 22–23 is ≤ 0.004 kT at the distances pairs reach.  Checked: the "
    "BD step (two more runs), equilibration (MSD over the 300 t0 before sampling ≈ σ_cc² for SRD, 0.7 σ_cc² "
    "for BD; the highest bin at half and all of the run agree within SE).  Not checked: the SRD MD step, a "
    "longer SRD run, other φ_c.  No parameter was tuned.",
    "",
    "**Hecht Figs. 9, 12–13.**  Two rules.  The *cluster rule*, fixed before the first runs: a point is "
    "clustered when its largest cluster (bond: surface gap < 0.1 a0; time average over the second half of "
    "the run, ± SE from blocking) holds more than 10 % of the colloids.  Hecht's own *g(r) rule* (Hecht "
    "Sec. X.B: suspended particles show only the first peak of g(r), clustering ones more), added after "
    "the first runs: a peak of the contact geometry B, C or D of Fig. 5 (windows scaled by the first "
    "peak's position) standing 5 SE above its window's chord (5, not 3: each window takes its highest "
    "local maximum); the windows come from the Fig. 5 geometry; with 3 SE the verdicts at 1.4e8 and 1.6e8 "
    "are the same (those peaks stand 10–15 SE high), the 1.0e8 point's D window reaches 3.0 SE.  The runs cover the scene's 1140 steps = 0.64 s of mapped time (steps × "
    "srd.dt × t0, at the coupling-true time); `studies/hecht_fig9_kappa_1s.cfg` runs κ = 1.4e8 /m for the whole second (1788 steps).  "
    "Where the verdict says *disagrees*, peloid clusters at κ = 1.4e8 /m where Hecht reports a suspension, "
    "by both rules; it is suspended at 1.0e8 and clustered at 1.6e8 and 2.0e8, so peloid's boundary at "
    "Ψ0 = 20 mV lies between 1.0e8 and 1.4e8 /m, below Hecht's.  Checked: the replica seed (the same within "
    "the SEs); the 1 s run (clustering grows); which minimum holds the clusters "
    "(`studies/hecht_fig9_bonds.cfg`: at 1.4e8 every bond is a secondary-minimum bond, depth −2.9 kT at a "
    "gap of 0.073 a0, behind a 10 kT barrier; Hecht's footnote 4 says they did not distinguish the two, so "
    "secondary-minimum flocs count as clusters for Hecht too).  Hence dlvo.primary_depth and "
    "coarse_graining.hertz_K, which shape only the primary minimum and the contact, cannot move this "
    "boundary; the depth of the secondary minimum is the DLVO of Hecht Eqs. 1–2 with Hecht's constants "
    "(`peloid params`).  Not checked: Hecht's own resolution (λ = 0.5 a0, M = 60, δt = 2.05 ms, Hecht "
    "Sec. VII.C) against the scene's (λ = 0.1, 10 per cell), which changes the colloids' hydrodynamics and "
    "so the rate at which flocs form within the run.  No parameter was tuned.",
    "",
    "**Hecht Fig. 9 as a diagram, Figs. 10–13.**  The same two rules, per point, seed 9, the scene's 1140 steps "
    "(0.64 s of mapped time at the coupling-true time; Hecht ran 1 s).  Axes: Hecht gives Fig. 9's values only in its pictures; the text "
    "fixes its left column (Ψ0 = 20 mV, κ varying: Fig. 10) and its first row (κ = 2e8 /m, Ψ0 varying: Fig. "
    "11), and Figs. 5–7 and 14 use 50 mV at 7.3e7–3e8 /m.  The grid: κ = 7.3e7, 1.0e8, 1.4e8, 1.6e8, 2.0e8, "
    "3.0e8 /m × Ψ0 = 20, 35, 50 mV and 10 mV (left of the left column).  The orientation is read from the text, "
    "not stated by it: *upper* = larger κ (at 20 mV Hecht clusters at the larger κ and the first row is 2e8), "
    "*right* = larger Ψ0 (the left column is 20 mV); S1 and S2 test its corners.  So read, S1–S2 (suspended at "
    "high Ψ0) and S4 (Fig. 11: clustering grows with Ψ0) point in opposite directions.  Hecht's Eq. 1 makes the "
    "repulsion grow with Ψ0 (its tanh² prefactor), so with Eqs. 1–2 the secondary minimum becomes shallower and "
    "the barrier higher as Ψ0 rises (at 2e8 /m: −6.3, −3.8, −3.1 kT at 20, 35, 50 mV, `peloid params`); peloid "
    "uses Eqs. 1–2 as written and its clustering falls with Ψ0.  The 20 mV points reproduce hecht_fig9_kappa's "
    "and the 50 mV points at 7.3e7 and 3e8 hecht_fig5_rdf's (same scene and seed: the same trajectories), so S3 "
    "repeats that study's disagreement.  Failed points: without a DLVO barrier (10 mV at κ ≥ 1.4e8, 20 mV at "
    "3e8) the colloids fall into the parabolic primary minimum and overlap past the 10 % guard "
    "(colloids.max_overlap) with hertz_K = 1000 kT/a0^2.5, early in the run (the MD step is in each failed cell); they are kept as "
    "failed, not re-run with a stiffer K (at 7.3e7 and 1.0e8 the 10 mV points ran and cluster).  The two rules "
    "differ at one point near the boundary (1.6e8 /m, 35 mV: largest cluster 3.5 %, but a D peak).  One seed per "
    "point; the SEs are from blocking within the run.  Figs. 12–13 (studies/hecht_fig9_phi.cfg): the colloid "
    "count follows φ in the same 15³-cell box (236–1181 colloids); its φ = 0.14 points are the grid's.  Not run: "
    "Hecht's whole second (only κ = 1.4e8 at 20 mV has it, hecht_fig9_kappa_1s), other seeds for the grid, and "
    "Hecht's long-range g(r) statements of Figs. 12–13 (peaks at 6–8 R growing with φ: in the plot, not judged).  "
    "No parameter was tuned.",
    "",
    "**Hecht Fig. 4 (Richardson–Zaki).**  The sedimentation observer measures the slip velocity u "
    "(colloids relative to the fluid's mean).  The exponent depends on the frame, and Hecht does not say "
    "which he used: in Richardson–Zaki's frame (zero volume flux, u (1 − φ)) peloid's l is about 2.2–2.4 at "
    "every Pe, well below Hecht's 3.5; the colloids' velocity in the simulation box (zero total momentum: "
    "the fluid carries the colloids' weight, Hecht Sec. VIII.A iii, and with it their momentum; u M_f / "
    "(M_f + M_c), M_c / M_f = 3.9 φ for Al2O3) gives l ≈ 2.9–3.1 and is near Hecht's 3.5, but a single power "
    "law fits it poorly (χ²/dof ≫ 1; the SE is scaled by √(χ²/dof)).  The Pe dependence is weak, as Hecht "
    "and PL say.  The colloids' friction is below 6π η R (0.60 of it, the row's v∞ line, η of the rule): coupling II couples a "
    "point colloid to its cell's collision, so its hydrodynamic radius is not R, and hindered settling, "
    "which is a hydrodynamic effect, is weaker.  Not checked: Hecht's own coupling II resolution (M = 60, "
    "λ = 0.5 a0, Hecht Sec. VII.C), which sets that friction; Hertz K = 1e5 kT/a0^2.5 (stiffer than the "
    "Fig. 9 scenes, whose 1000 lets thermal collisions overlap past the 10 % guard without DLVO "
    "repulsion).  No parameter was tuned.",
    "",
    "**Coupling I at the fluid's temperature (issue 45).**  Not a study: the scene of "
    "tests/validation/test_coupling_thermal.c (8 colloids, R = 2 a0, 14³ cells, γ = 5, Δt = 0.1, entry placement, Hertz "
    "pairs with 10 MD substeps, colloids started at kT, no thermostat) and one colloid in 8³ cells (the same fluid, "
    "400000 steps, 1 thread, a stand-alone driver of pl_sim_step).  The colloids' kinetic temperature counts their "
    "degrees of freedom as the fluid's does: the periodic box conserves the total momentum, so in equilibrium "
    "M ⟨|V − U|²⟩ = 3 kT (1 − M/M_tot) (U, M_tot: centre-of-mass velocity and mass of fluid and colloids); T_c = "
    "Σ M |V − U|² / 3 Σ (1 − M/M_tot).  History: every reflection of a step read the colloid velocity the step found "
    "(the friction explicit): T_c/T_f = 1.46, 1.28 (stick_stochastic, slip, M = 33.5 m_f), 1.053, 1.031 (M = 168), "
    "the fluid guard tripped with stick_bounce → sequential impulses in the order of the entry times on the MD's path,"
    " end positions moved by dv s: 3 N_c degrees of freedom read 0.990, 0.988, 0.974 (stick_stochastic, M = 33.5, 168,"
    " 300), 0.997, 0.991, 0.987 (slip), 0.985, 0.989, 0.988 (stick_bounce), ± 0.002–0.005: the \"cold colloids\".  "
    "Two causes, measured apart: (1) most of it, growing with M, is the factor 1 − M/M_tot = 0.9976, 0.9889, 0.9814 "
    "in that box; one colloid in 8³ cells shows it alone (3 degrees of freedom, measured against 1 − M/M_tot): slip "
    "M = 33.5, 100.5, 301.6, 1005: 0.983 ± 0.002 / 0.987, 0.964 ± 0.004 / 0.962, 0.888 ± 0.005 / 0.895, 0.706 ± "
    "0.005 / 0.718; stick_stochastic M = 100.5, 301.6: 0.961 ± 0.003 / 0.962, 0.896 ± 0.005 / 0.895; in 16³ cells M "
    "= 33.5: 0.997 ± 0.005 / 0.998.  (2) The rest, for light colloids, grows as (ξΔt/M)²: the events ordered by the"
    " MD's path alone; an event changes the colloid's path and with it the times at which later particles meet it.  "
    "One colloid, 8³ cells, T_c/T_f over 1 − M/M_tot, stick_stochastic M = 33.5: Δt = 0.05: 0.9989 ± 0.0017, Δt = 0.1:"
    " 0.9921 ± 0.0020, Δt = 0.2: 0.9756 ± 0.0012; M = 10, Δt = 0.1: 0.968 ± 0.002 (fluid 1.008); stick_bounce M = "
    "33.5: 0.9894 ± 0.0015; slip M = 33.5: 0.9962 ± 0.0020, M = 10: 0.9885 ± 0.0017 (fluid 1.0097).  Now "
    "(kernels/coupling_order.c: each colloid takes next the event whose particle met it first on the path the events"
    " before left it): M = 33.5, Δt = 0.1: stick_stochastic 1.0001 ± 0.0026 (T_rot 0.9971 ± 0.0019), slip 0.9970 ± "
    "0.0019, stick_bounce 1.0028 ± 0.0017; M = 10 (the test's one-colloid case, 200000 steps): 0.9999 ± 0.0023, fluid"
    " 0.9978 ± 0.0010, against 0.9654 ± 0.0017 and 1.0076 on the code before (the test fails there).  "
    "The test's own runs (2 threads, 20 blocks; 40000, 60000, 80000 steps at M = 33.5, 168, 302): stick_stochastic "
    "1.0034 ± 0.0016, 1.0076 ± 0.0035, 1.0049 ± 0.0042 (T_rot 1.0000, 0.9994, 1.0067); slip 0.9961 ± 0.0019, 0.9935 ± "
    "0.0043, 0.9985 ± 0.0040; stick_bounce 0.9988 ± 0.0028, 1.0021 ± 0.0035 (T_rot 0.9989, 1.0034); fluid 0.9987–1.0022"
    " for the thermal walls.  Open: stick_stochastic with 8 colloids reads 0.3–0.8 % warm (1.2–2.2 SE each, ~3 SE "
    "together), one colloid does not (1.0001 ± 0.0026, M = 33.5); T_rot of one light colloid 0.997 ± 0.002; "
    "stick_bounce conserves energy and the colloids' Hertz contacts under the end-position moves heat its fluid "
    "(1.0150 ± 0.0023 over 40000 steps at M = 33.5; nothing with one colloid).  "
    "Drift: the mean colloid velocity is within 4 SE of zero on every axis in every run, and "
    "tests/physics/test_coupling_momentum.c passes with this order (6/6).  The shipped coupling I"
    " calibration (Hecht Table I's resolution, scenes/hecht_table1.cfg: γ = 2.5, λ = 0.6, M = 327) checked with this "
    "order (tests/validation/calibration_coupling1.sh): the dilute suspension diffuses at D = 4.314e-13 ± 0.11e-13 m²/s"
    " against the mapping's 4.274e-13 (+0.9 %, SE 2.5 %; before: +2.1 %, SE 2.9 %), a lone colloid settles at 7.91e-6 ±"
    " 0.10e-6 m/s against 8.18e-6 (−3.3 %, SE 1.2 %; before: 8.05e-6 ± 0.18e-6, −1.6 %; the two runs differ by −1.7 ±"
    " 2.6 %): kept.",
    "",
    "**PL Figs. 10, 13 (VACF).**  The rules were fixed (and committed) before the runs.  The tail: over "
    "τ_ν–L²/(4π²ν) the measured C(t) runs parallel to t^−3/2 but about 1.66 × the mode-coupling amplitude of PL "
    "Eq. B6 (the same in 8–16 and 16–32 t0), so the verdict is *disagrees* for MCT and for the box's "
    "transverse-mode sum alike (they differ by only 1–18 % here, almost all of it the zero-momentum offset).  "
    "Checked, not the cause: the normalisation (M⟨V²⟩/kT = 1.000 ± 0.003); momentum conservation (the fluid "
    "momentum in thermo.tsv fluctuates with the r.m.s. √(8 M_c kT) ≈ 37 of the colloids' momentum and does not "
    "drift); ν of this fluid (α = 90°, random axis, ρ = 5, λ = 0.1, rescale thermostat; a separate 10³ Green–Kubo "
    "run of 30000 steps, 2026-12-02: η = 2.474 ± 0.040 against PL Eqs. 9–15's 2.496, so ν_eff would have to be 30 % "
    "lower to explain the factor); sound in the periodic box (the longitudinal-mode sum with c_s = √(5/3), "
    "damping ≈ (4/3)ν k² stays below 0.002 beyond 8 t0, against the excess of 0.04 at τ_ν).  Found after the runs "
    "(no rule, for information): the continuum VACF of a neutrally buoyant slip sphere with the Enskog friction "
    "in parallel at every frequency (PL Eq. 41 as a memory function; `pl10_slip`) approaches the t^−3/2 "
    "asymptote from above, 1.7 × at τ_ν and still 1.2 × at 32 t0, and follows the measured tail (its A is "
    "given in the details): the asymptote itself is not reached inside PL's L = 32 box; PL Eq. B5 (stick) "
    "approaches it from below.  Not checked: that the factor falls to 1 after ~50 t0, which needs a bigger box "
    "and far longer runs (32–52 t0: 1.4 ± 0.5).  The Langevin rule fails only at its fixed time τ_ν, where C crosses exp(−t/τ_B) (τ_B = 3.45 t0 "
    "of PL Eqs. 40–43, finite box; PL quote 2.5 t0); it lies 6 and 4 SE above it at 2τ_ν and 4τ_ν.  The Enskog "
    "time agrees only through the fit form's window systematic (statistically τ is 15 SE above τ_E): the "
    "one-parameter fit takes up part of the hydrodynamic decay, which is larger in this box than in "
    "tests/validation/test_coupling_vacf.c's L = 16 (1.21–1.25 t0 there).  No parameter was tuned.",
]


def study_row(s, out, rdir):
    """One STUDIES entry evaluated: (its table row, its details paragraph or None, the runs' git revisions);
    its plot copied beside the report."""
    sdir = s.get("sweep", s["name"])  # an entry may evaluate another entry's sweep
    sw = load(out, sdir)
    if sw is None:
        return (f"| `{s['study']}` | {s['figure']} | {s['paper']} | not run | {s['size']} | – | "
                f"not run: `peloid sweep {s['study']}` |"), None, set()
    res = s["eval"](sw)
    value, verdict = res[0], res[1]
    detail = res[2] if len(res) > 2 and res[2] else None
    if len(res) > 3 and res[3]:
        guide = os.path.join(out, sdir, "guide.png" if sdir == s["name"] else s["name"] + ".png")
        res[3](guide)
        shutil.copyfile(guide, os.path.join(rdir, s["name"] + ".png"))
    revs = {p["summary"]["peloid"]["git_revision"] for p in sw["points"] if p["summary"]}
    size = s["size"] + (f" = {mapped_time(sw)} of mapped real time" if mapped_time(sw) else "")
    row = f"| `{s['study']}` | {s['figure']} | {s['paper']} | {value} | {size} | {run_time(sw)} | {verdict} |"
    png = os.path.join(out, sdir, "sweep.png")
    if os.path.exists(png) and not (len(res) > 3 and res[3]):
        shutil.copyfile(png, os.path.join(rdir, s["name"] + ".png"))
    return row, detail, revs


def bold_title(paragraph):
    """The opening **...** of a details paragraph (how --update finds the old one)."""
    return paragraph[:paragraph.index("**", 2) + 2] if paragraph.startswith("**") and "**" in paragraph[2:] else None


def update(names, out, report):
    """Rewrites the named entries' rows, details and plots, the notes and the verdicts of an existing report."""
    rdir = os.path.dirname(report) or "."
    lines = open(report).read().split("\n")
    known = {s["name"]: s for s in STUDIES}
    bad = [n for n in names if n not in known]
    if bad:
        raise SystemExit(f"--update: unknown entries {', '.join(bad)}; known: {', '.join(known)}")
    revs = set()
    for n in names:
        s = known[n]
        if load(out, s.get("sweep", n)) is None:
            raise SystemExit(f"--update {n}: {out}/{s.get('sweep', n)} has no sweep.json (run `peloid sweep {s['study']}`)")
        row, detail, rv = study_row(s, out, rdir)
        revs |= rv
        # the table row: the first line of the table naming this study with this figure
        key = f"| `{s['study']}` | {s['figure']} |"
        hits = [i for i, l in enumerate(lines) if l.startswith(key)]
        if len(hits) != 1:
            raise SystemExit(f"--update {n}: {len(hits)} table rows open with {key!r} in {report}")
        lines[hits[0]] = row
        if detail:
            t = bold_title(detail)
            hits = [i for i, l in enumerate(lines) if t and l.startswith(t)]
            if len(hits) != 1:
                raise SystemExit(f"--update {n}: {len(hits)} paragraphs open with {t!r} in {report}")
            # the old details run to the next bold title (its tables and blank lines included)
            a = hits[0]
            b = next((i for i in range(a + 1, len(lines)) if lines[i].startswith("**") or
                      lines[i].startswith("<!-- verdicts") or lines[i].startswith("## ")), len(lines))
            while b > a + 1 and not lines[b - 1].strip():
                b -= 1
            lines[a:b] = detail.rstrip("\n").split("\n")
    # the notes: from the first to the last NOTES paragraph, as NOTES is now
    first, last = bold_title(NOTES[0]), bold_title([x for x in NOTES if x][-1])
    a = next(i for i, l in enumerate(lines) if first and l.startswith(first))
    b = next(i for i, l in enumerate(lines) if last and l.startswith(last))
    lines[a:b + 1] = NOTES[:len(NOTES) - next(i for i, x in enumerate(reversed(NOTES)) if x)]
    # the revisions line
    i = next(i for i, l in enumerate(lines) if l.startswith("Runs made by peloid "))
    old = lines[i][len("Runs made by peloid "):lines[i].index(" (the git revision")]
    allrev = sorted(set(x.strip() for x in old.split(",") if x.strip() and x.strip() != "(none)") | revs)
    try:
        rev = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    except OSError:
        rev = "unknown"
    what = f"the rows of {', '.join(names)}" if names else "the notes"
    lines[i] = (f"Runs made by peloid {', '.join(allrev)} (the git revision each point's summary.json names); "
                f"report written at {rev}, {what} rewritten then (the others as before).")
    tmp = report + ".tmp"
    open(tmp, "w").write("\n".join(lines))
    os.replace(tmp, report)
    print(f"updated {', '.join(names)} in {report}", file=sys.stderr)


VERDICTS_BEGIN = "<!-- verdicts of the disagreement rows: tools/validation/verdicts.py -->"
VERDICTS_END = "<!-- end of the verdicts of the disagreement rows -->"


def verdict_lines(out, rdir, previous=None):
    return [VERDICTS_BEGIN, ""] + verdicts.section(out, rdir, previous) + ["", VERDICTS_END]


def verdicts_only(out, report):
    """Replaces the verdict section of an existing report (appends it when the report has none)."""
    rdir = os.path.dirname(report) or "."
    text = open(report).read()
    has = VERDICTS_BEGIN in text and VERDICTS_END in text
    if has:
        a, b = text.index(VERDICTS_BEGIN), text.index(VERDICTS_END) + len(VERDICTS_END)
    new = "\n".join(verdict_lines(out, rdir, text[a:b] if has else None))
    if has:
        text = text[:a] + new + text[b:]
    else:
        text = text.rstrip("\n") + "\n\n" + new + "\n"
    tmp = report + ".tmp"
    open(tmp, "w").write(text)
    os.replace(tmp, report)
    print(f"wrote the verdicts of {report}", file=sys.stderr)


def main():
    argv, names = sys.argv[1:], None
    if "--update" in argv:
        k = argv.index("--update")
        if k + 1 >= len(argv):
            raise SystemExit("--update needs NAME[,NAME...]")
        names = [n for n in argv[k + 1].split(",") if n]
        argv = argv[:k] + argv[k + 2:]
    args = [a for a in argv if a not in ("--verdicts-only", "--notes-only")]
    out = args[0] if len(args) > 0 else "out/studies"
    report = args[1] if len(args) > 1 else "validation/REPORT.md"
    if names or "--notes-only" in argv:
        return update(names or [], out, report)
    if "--verdicts-only" in sys.argv:
        return verdicts_only(out, report)
    rdir = os.path.dirname(report) or "."
    os.makedirs(rdir, exist_ok=True)
    try:
        rev = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    except OSError:
        rev = "unknown"
    lines = ["# peloid validation report", "",
             "Generated by `make validation-report` (tools/validation_report.py) from the outputs of "
             "`make studies` (`peloid sweep` on each study in `studies/`); do not edit by hand.", ""]
    table = ["| study | paper figure | paper value | peloid value ± SE | size run | run time | verdict |",
             "|---|---|---|---|---|---|---|"]
    revs = set()
    details = []
    for s in STUDIES:
        row, detail, rv = study_row(s, out, rdir)
        table.append(row)
        if detail:
            details.append(detail)
        revs |= rv
    lines.append(f"Runs made by peloid {', '.join(sorted(revs)) or '(none)'} (the git revision each point's "
                 f"summary.json names); report written at {rev}.")
    lines += [""] + table + [""]
    for s in STUDIES:
        if os.path.exists(os.path.join(rdir, s["name"] + ".png")):
            lines += [f"![{s['name']}]({s['name']}.png)", ""]
    lines += NOTES + [""] + [d + "\n" for d in details]
    lines += verdict_lines(out, rdir) + [""]
    # the sections other tools write between their markers (tools/validation/hydro_section.py,
    # tools/hindered_settling.py, tools/rh_resolution.py, tools/rh_matched.py, tools/hindered_matched.py,
    # tools/array_mobility.py, tools/hindered_nlaw.py, tools/potential_gap.py, tools/fluid_equilibrium.py), kept
    old = open(report).read() if os.path.exists(report) else ""
    if hydro_section.BEGIN in old and hydro_section.END in old:
        lines += [old[old.index(hydro_section.BEGIN):old.index(hydro_section.END) + len(hydro_section.END)], ""]
    for sec in hindered_settling.sections(old):
        lines += [sec, ""]
    for sec in (rh_resolution.sections(old) + rh_matched.sections(old) + hindered_matched.sections(old) +
                array_mobility.sections(old) + hindered_nlaw.sections(old) + potential_gap.sections(old)):
        lines += [sec, ""]
    if rotating_section.BEGIN in old and rotating_section.END in old:
        lines += [old[old.index(rotating_section.BEGIN):old.index(rotating_section.END) + len(rotating_section.END)], ""]
    for sec in fluid_equilibrium.sections(old):
        lines += [sec, ""]
    tmp = report + ".tmp"
    open(tmp, "w").write("\n".join(lines))
    os.replace(tmp, report)
    print(f"wrote {report}", file=sys.stderr)


if __name__ == "__main__":
    main()