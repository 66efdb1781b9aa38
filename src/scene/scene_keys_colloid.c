/* Scene schema of the colloid module: sections `colloids` (particles,
 * integrator, walls, guards, output), `dlvo`, `hertz`, `lubrication`, `wca`
 * (pair terms; which of them act is listed in colloids.pairs). */
#include <float.h>
#include <stddef.h>

#include "peloid/colloid_kernels.h"
#include "peloid/scene.h"

#define OFF(member) offsetof(pl_scene_t, colloids.member)
#define N(a) (sizeof(a) / sizeof((a)[0]))

static const char *const init_choices[] = {"lattice", "random", "file", NULL};
static const char *const integ_choices[] = {"verlet", "brownian", NULL};
static const char *const sigma_rules[] = {"fixed", "pl", NULL};
static const char *const table_interps[] = {"linear", "spline", NULL};
/* the words of colloids.pairs, from the pair-term table */
#define PAIR_WORD_(ID, id, name, slot, kind) " " name

static const pl_key_t colloid_keys[] = {
    {"count", PL_KEY_INT, OFF(count), 0, 1e7, 0, NULL, 0, NULL,
     "-", "number of colloids (0: no colloids, no MD stages) (physical{} scenes: derived, see peloid params)"},
    {"radius", PL_KEY_REAL, OFF(radius), 0, 1e3, PL_KEY_MIN_OPEN, NULL, 2, NULL,
     "a0", "mean colloid radius R (also the contact radius of Hertz, DLVO, lubrication) (physical{} scenes: derived, see peloid params)"},
    {"polydispersity", PL_KEY_REAL, OFF(polydispersity), 0, 0.25, 0, NULL, 0, NULL,
     "-", "relative standard deviation of R (uniform distribution around R)"},
    {"mass_density", PL_KEY_REAL, OFF(mass_density), 0, 1e9, PL_KEY_MIN_OPEN, NULL, 5, NULL,
     "m_f / a0^3", "colloid mass density: M = density 4/3 pi R^3, I = 2/5 M R^2 (physical{} scenes: derived, see peloid params)"},
    {"temperature", PL_KEY_REAL, OFF(temperature), 0, 1e6, 0, NULL, 1, NULL,
     "kT_ref", "initial colloid temperature (Maxwell velocities, zero total momentum); BD noise kT; kT of the lubrication noise (lubrication.thermal) (physical{} scenes: derived, see peloid params)"},
    {"init", PL_KEY_CHOICE, OFF(init), 0, 0, 0, init_choices, PL_CINIT_LATTICE, NULL,
     "-", "initial positions: lattice (simple cubic filling the box), random "
          "(sequential addition without overlap, seeded by run.seed), file"},
    {"init_file", PL_KEY_STRING, OFF(init_file), 0, 0, 0, NULL, 0, "",
     "-", "init = \"file\": text file (relative to the scene file), one colloid per line: x y z [R]; "
          "read strictly (README \"Colloids, couplings and physical units\")"},
    {"pairs", PL_KEY_STRING, OFF(pairs), 0, 0, 0, NULL, 0, "hertz",
     "-", "pair terms switched on, comma separated (\"\": none), from the pair-term table:"
          PL_PAIR_TERMS(PAIR_WORD_) "; depletion_comp = -Phi_depl, the compensating potential of PL Sec. III.C.1 "
          "(PL Eqs. 22-23, tabulated at start for the run's fluid density and kT; needs "
          "coupling.method = \"potential\")"},
    {"table_file", PL_KEY_STRING, OFF(table_file), 0, 0, PL_KEY_FP_SET, NULL, 0, "",
     "-", "pairs \"table\": text file of U(r) (in the scene file's directory) in model units "
          "(r in a0, U in kT_ref, F = -dU/dr in kT_ref/a0): rows \"r U F\" or \"r U\" "
          "(F then -dU/dr of a cubic spline of U), or one LAMMPS pair_style table section (keyword "
          "line, \"N n [R lo hi | RSQ lo hi] [FPRIME fplo fphi]\" line, rows \"i r U F\"); # comments; "
          "a regular file of at most 16 MiB; r strictly increasing; "
          "cut-off = the last r (give U = 0 there for a continuous energy); below the first r the "
          "force of the first row; model-unit scenes only (README \"Colloids, couplings and physical units\")"},
    {"table_interpolation", PL_KEY_CHOICE, OFF(table_interpolation), 0, 0, PL_KEY_FP_SET, table_interps,
     PL_TABLE_SPLINE, NULL,
     "-", "pairs \"table\": U and F between the file's rows: linear or spline (GSL natural cubic "
          "spline), sampled at start onto 2048 equal intervals up to the cut-off, between which "
          "the force kernel interpolates U and F linearly"},
    {"table_force_tolerance", PL_KEY_REAL, OFF(table_force_tolerance), 0, 1, PL_KEY_MIN_OPEN | PL_KEY_FP_SET, NULL,
     0.02, NULL,
     "-", "pairs \"table\" with an F column: between any two neighbouring rows, the largest "
          "abs(U_i - U_i+1 - (r_i+1 - r_i) (F_i + F_i+1)/2) / (r_i+1 - r_i) allowed, relative to the "
          "largest abs(F) (the trapezoid rule for the work of F), and at every row abs(F_i + dU/dr) "
          "(the slope of the parabola through the row and its neighbours) within 2 x this x max abs(F) "
          "(4 x at the first and last row); a file beyond either is refused"},
    {"integrator", PL_KEY_CHOICE, OFF(integrator), 0, 0, 0, integ_choices, PL_CINT_VERLET, NULL,
     "-", "verlet: velocity Verlet + quaternions (Hecht Eqs. 7-10); brownian: overdamped "
          "Langevin with Stokes friction (reference for colloid-only scenes)"},
    {"substeps", PL_KEY_INT, OFF(substeps), 1, 1e6, 0, NULL, 4, NULL,
     "-", "MD steps per collision step: dt_MD = srd.dt / substeps (physical{} scenes: derived, see peloid params)"},
    {"slow_interval", PL_KEY_INT, OFF(slow_interval), 1, 1e4, 0, NULL, 1, NULL,
     "MD steps", "multiple time stepping (verlet, couplings none/hecht1/hecht2): the DLVO force "
                 "of pairs beyond colloids.slow_gap is applied as a kick every slow_interval MD "
                 "steps (r-RESPA), the rest every MD step; must divide colloids.substeps "
                 "(physical{} scenes: substeps rounded up to a multiple); refused when the slow "
                 "force's stiffness would leave a collision fewer than min_contact_steps outer "
                 "steps (1: off, every force every step)"},
    {"slow_gap", PL_KEY_REAL, OFF(slow_gap), 0, 100, PL_KEY_MIN_OPEN, NULL, 0.1, NULL,
     "a0", "slow_interval > 1: surface gap h_s beyond which the DLVO force starts to move to the "
           "outer steps; its share rises smoothly (cubic in r^2) to all of it at gap 2 h_s; must "
           "exceed the primary minimum's match gap"},
    {"adaptive_substeps", PL_KEY_BOOL, OFF(adaptive_substeps), 0, 1, PL_KEY_FP_SET, NULL, 0, NULL,
     "-", "verlet: each collision step runs the fewest MD steps, between colloids.min_substeps and "
          "colloids.substeps, that give min_contact_steps to the stiffest contact the pairs present "
          "can reach with their energy (pair potential + approach kinetic energy + "
          "colloids.adaptive_margin), chosen from the positions and velocities at the step's start "
          "(the same at any thread count and after a restart); false: colloids.substeps always "
          "(physical{} scenes: derived true where the contact guard sets the substeps, with "
          "velocity Verlet and equal colloids; see peloid params)"},
    {"min_substeps", PL_KEY_INT, OFF(min_substeps), 1, 1e6, PL_KEY_FP_SET, NULL, 1, NULL,
     "-", "adaptive_substeps: the fewest MD steps per collision step (physical{} scenes: derived, "
          "the mapping's MD step min(tau_V, tau_P) / md_resolution; see peloid params)"},
    {"adaptive_margin", PL_KEY_REAL, OFF(adaptive_margin), 0, 1e6, PL_KEY_FP_SET, NULL, 5, NULL,
     "kT_ref", "adaptive_substeps: energy added to each pair's own (potential + approach kinetic) "
               "for what third bodies, walls and gravity can give it within one collision step"},
    {"gravity", PL_KEY_REAL3, OFF(gravity), -1e6, 1e6, 0, NULL, 0, NULL,
     "a0 / t0^2", "acceleration on every colloid (gravity minus buoyancy) (physical{} scenes: derived, see peloid params)"},
    {"bd_viscosity", PL_KEY_REAL, OFF(bd_viscosity), 0, 1e9, PL_KEY_MIN_OPEN, NULL, 2.5, NULL,
     "m_f / (a0 t0)", "brownian: solvent viscosity eta of the Stokes friction 6 pi eta R (physical{} scenes: derived, see peloid params)"},
    {"wall_epsilon", PL_KEY_REAL, OFF(wall_epsilon), 0, 1e9, 0, NULL, 2.5, NULL,
     "kT_ref", "colloid-wall repulsion at every wall (box.walls_z, box.walls_xy), PL Eq. 16 form with sigma = R"},
    {"wall_n", PL_KEY_REAL, OFF(wall_n), 1, 200, 0, NULL, 24, NULL,
     "-", "exponent n of the colloid-wall repulsion"},
    {"max_overlap", PL_KEY_REAL, OFF(max_overlap), 0, 1, PL_KEY_MIN_OPEN, NULL, 0.1, NULL,
     "-", "guard: largest overlap (R_i+R_j-r)/(R_i+R_j) allowed (Hecht Sec. II: ~10%); "
          "also the largest overlap accepted in the initial configuration"},
    {"min_contact_steps", PL_KEY_REAL, OFF(min_contact_steps), 0, 1e6, 0, NULL, 20, NULL,
     "MD steps", "guard: a collision must last at least this many MD steps (Hecht Sec. II: "
                 "~20), estimated as pi sqrt(m_red / U'') from the actual stiffness (0: off)"},
    {"max_energy_drift", PL_KEY_REAL, OFF(max_energy_drift), 0, 1e9, 0, NULL, 0.05, NULL,
     "kT_ref per colloid", "guard: abs(E - E_0) / N allowed in undamped NVE runs (0: off)"},
    {"guard_interval", PL_KEY_INT, OFF(guard_interval), 1, 1e12, 0, NULL, 100, NULL,
     "MD steps", "interval of the energy-drift check (the other guards act every MD step)"},
    {"neighbor_skin", PL_KEY_REAL, OFF(neighbor_skin), 0, 1, 0, NULL, 0.1, NULL,
     "-", "skin of the colloid Verlet neighbour lists as a fraction of the largest pair "
          "cut-off: pairs closer than (1 + skin) r_c are listed and the lists are rebuilt "
          "when a colloid has moved by half the skin (results do not depend on it)"},
    {"trajectory_interval", PL_KEY_INT, OFF(trajectory_interval), 0, 1e15, 0, NULL, 0, NULL,
     "collision steps", "write colloids.h5 (H5MD) every N collision steps (0: off)"},
};

static const pl_key_t dlvo_keys[] = {
    {"eps_r", PL_KEY_REAL, OFF(dlvo.eps_r), 0, 1e4, PL_KEY_MIN_OPEN, NULL, 81, NULL,
     "-", "relative permittivity of the solvent (Hecht Eq. 1) (physical{} scenes: derived, see peloid params)"},
    {"psi0", PL_KEY_REAL, OFF(dlvo.psi0_mV), 0, 1e4, 0, NULL, 20, NULL,
     "mV", "effective surface potential Psi_0 (Hecht Eq. 1); required with the dlvo pair term, no material default (physical{} scenes: derived, see peloid params)"},
    {"z", PL_KEY_REAL, OFF(dlvo.z), 0, 100, PL_KEY_MIN_OPEN, NULL, 1, NULL,
     "-", "charge number of the ions (Hecht Eq. 1) (physical{} scenes: derived, see peloid params)"},
    {"temperature", PL_KEY_REAL, OFF(dlvo.temperature_K), 0, 1e5, PL_KEY_MIN_OPEN, NULL, 300, NULL,
     "K", "physical temperature T; k_B T is the energy unit kT_ref (physical{} scenes: derived, see peloid params)"},
    {"kappa", PL_KEY_REAL, OFF(dlvo.kappa_per_m), 0, 1e12, PL_KEY_MIN_OPEN, NULL, 1.4e8, NULL,
     "1/m", "inverse Debye screening length (Hecht Eq. 1); required with the dlvo pair term, no material default (physical{} scenes: derived, see peloid params)"},
    {"hamaker", PL_KEY_REAL, OFF(dlvo.hamaker_J), 0, 1e-15, 0, NULL, 4.76e-20, NULL,
     "J", "Hamaker constant A_H (Hecht Eq. 2; Al2O3 in water: 4.76e-20, Table I); required with the dlvo pair term, no material default (physical{} scenes: derived, see peloid params)"},
    {"length_unit", PL_KEY_REAL, OFF(dlvo.length_unit_m), 0, 1, PL_KEY_MIN_OPEN, NULL, 2e-7, NULL,
     "m", "physical length of a0 (Hecht Sec. VII: a = R/2 = 0.2 um); required with the dlvo pair term, no material default (physical{} scenes: derived, see peloid params)"},
    {"primary_depth", PL_KEY_REAL, OFF(dlvo.primary_depth), 0, 1e4, PL_KEY_MIN_OPEN, NULL, 6, NULL,
     "kT_ref", "depth of the parabolic primary minimum (Hecht Sec. II: some kT, e.g. 6)"},
    {"primary_gap", PL_KEY_REAL, OFF(dlvo.primary_gap), 0, 100, 0, NULL, 0, NULL,
     "a0", "surface gap r - 2R at the bottom of the primary minimum"},
    {"cutoff_energy", PL_KEY_REAL, OFF(dlvo.cutoff_energy), 0, 1, PL_KEY_MIN_OPEN, NULL, 1e-3, NULL,
     "kT_ref", "cut-off where abs(V_DLVO) has decayed below this (the truncation error, printed at start)"},
};

static const pl_key_t hertz_keys[] = {
    {"K", PL_KEY_REAL, OFF(hertz.K), 0, 1e15, PL_KEY_MIN_OPEN, NULL, 1e3, NULL,
     "kT_ref / a0^2.5", "Hertz constant (Hecht Eq. 3: V = K (d - r)^{5/2}) (physical{} scenes: derived, see peloid params); "
                         "refused below kT / d^2.5 (d the smallest diameter), where a pair meeting with the "
                         "energy kT passes through the contact"},
    {"beta", PL_KEY_REAL, OFF(hertz.beta), 0, 1e12, 0, NULL, 0, NULL,
     "m_f / (t0 a0^0.5)", "normal damping constant (Hecht Eq. 6)"},
    {"gamma_t", PL_KEY_REAL, OFF(hertz.gamma_t), 0, 1e12, 0, NULL, 0, NULL,
     "m_f / t0", "tangential viscous friction on the relative surface velocity (torques)"},
};

static const pl_key_t lub_keys[] = {
    {"viscosity", PL_KEY_REAL, OFF(lub.viscosity), 0, 1e9, PL_KEY_MIN_OPEN, NULL, 2.5, NULL,
     "m_f / (a0 t0)", "dynamic viscosity eta of the squeeze force (Hecht Eq. 4) (physical{} scenes: derived, see peloid params)"},
    {"min_gap", PL_KEY_REAL, OFF(lub.min_gap), 0, 100, PL_KEY_MIN_OPEN, NULL, 0.05, NULL,
     "a0", "limit of the 1/h divergence: force of gap h is that of h + min_gap (Hecht Sec. II)"},
    {"cutoff_gap", PL_KEY_REAL, OFF(lub.cutoff_gap), 0, 100, PL_KEY_MIN_OPEN, NULL, 1, NULL,
     "a0", "gap beyond which the squeeze force is off (shifted to zero there)"},
    {"thermal", PL_KEY_BOOL, OFF(lub.thermal), 0, 1, PL_KEY_FP_SET, NULL, 1, NULL,
     "-", "verlet: the squeeze friction zeta(h) gets its fluctuation-dissipation partner, a random "
          "pair force sqrt(2 kT zeta / dt_MD) N(0,1) along the line of centres, equal and opposite "
          "(kT = colloids.temperature; as the dissipative and random forces of DPD, Espanol & Warren "
          "1995), so that the pair's relative normal velocity is kept at the colloid temperature; "
          "false: Hecht Eq. 4 as written, friction only (it cools the colloids)"},
};

static const pl_key_t wca_keys[] = {
    {"epsilon", PL_KEY_REAL, OFF(wca.epsilon), 0, 1e9, PL_KEY_MIN_OPEN, NULL, 2.5, NULL,
     "kT_ref", "epsilon_cc of PL Eq. 16"},
    {"sigma", PL_KEY_REAL, OFF(wca.sigma), 0, 1e3, 0, NULL, 0, NULL,
     "a0", "sigma_cc of PL Eq. 16 (0: R_i + R_j per pair)"},
    {"n", PL_KEY_REAL, OFF(wca.n), 1, 200, 0, NULL, 24, NULL,
     "-", "exponent n (PL Eq. 16 uses 24; 6 gives the usual WCA)"},
    {"sigma_rule", PL_KEY_CHOICE, OFF(wca.sigma_rule), 0, 0, 0, sigma_rules, PL_SIGMA_FIXED, NULL,
     "-", "fixed: sigma_cc = wca.sigma; pl: PL Sec. III.C.1 rule against spurious depletion "
          "attraction, sigma_cc such that phi_cc = 2.5 kT at twice the colloid-fluid cut-off "
          "2^{1/6} coupling.sigma_cf (where the depletion potential vanishes); the value is "
          "logged and written to summary.json"},
};

const pl_section_t pl_scene_section_colloids = {"colloids", "colloid particles and their MD",
                                                colloid_keys, N(colloid_keys)};
const pl_section_t pl_scene_section_dlvo = {"dlvo", "DLVO colloid-colloid potential (Hecht Eqs. 1-2)",
                                            dlvo_keys, N(dlvo_keys)};
const pl_section_t pl_scene_section_hertz = {"hertz", "Hertz contact repulsion, damping, friction "
                                             "(Hecht Eqs. 3, 6)", hertz_keys, N(hertz_keys)};
const pl_section_t pl_scene_section_lubrication = {"lubrication", "squeeze-mode lubrication "
                                                   "(Hecht Eqs. 4-5)", lub_keys, N(lub_keys)};
const pl_section_t pl_scene_section_wca = {"wca", "colloid-colloid WCA repulsion (PL Eq. 16)",
                                           wca_keys, N(wca_keys)};
