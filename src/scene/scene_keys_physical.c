/* Scene schema of the physical front end: physical{} describes the real
 * suspension in SI units, coarse_graining{} the choices that map it onto
 * SRD + MD (Hecht Sec. VII, PL Sec. VII).  A scene with physical{} gets
 * srd.dt, fluid.density, fluid.temperature (and box.cells when physical.box
 * is given) from the mapping (src/mapping/mapping_scene.c), and with
 * physical.volume_fraction its colloids, pair terms, coupling method and MD
 * substeps (src/mapping/mapping_colloids.c). */
#include <stddef.h>

#include "peloid/scene.h"

#define OFF(member) offsetof(pl_scene_t, member)
#define N(a) (sizeof(a) / sizeof((a)[0]))
#define P(m) OFF(mapping.physical.m)
#define C(m) OFF(mapping.cg.m)

/* values PL_COUPLE_HECHT1.. (the key's min): the one coupling enum of coupling_scene.h */
static const char *const coupling_choices[] = {"I", "II", "potential", NULL};
static const char *const match_choices[] = {"diffusion", "kinematic", NULL};
static const char *const boundary_choices[] = {"stick", "slip", NULL};

static const pl_key_t physical_keys[] = {
    {"radius", PL_KEY_REAL, P(radius), 0, 1e-2, PL_KEY_MIN_OPEN, NULL, 1e-6, NULL,
     "m", "colloid radius R (required: its presence switches the physical front end on)"},
    {"particle_density", PL_KEY_REAL, P(particle_density), 0, 1e5, PL_KEY_MIN_OPEN, NULL, 1000, NULL,
     "kg/m^3", "colloid mass density rho_m (Hecht Table I: 3.9e3 for Al2O3)"},
    {"solvent_density", PL_KEY_REAL, P(solvent_density), 0, 1e5, PL_KEY_MIN_OPEN, NULL, 1000, NULL,
     "kg/m^3", "solvent mass density rho_w; kept by the model (rho_f = gamma m_f / a0^3)"},
    {"temperature", PL_KEY_REAL, P(temperature), 0, 1e4, PL_KEY_MIN_OPEN, NULL, 298.15, NULL,
     "K", "temperature T of the real system (kT with k_B = 1.380649e-23 J/K)"},
    {"viscosity", PL_KEY_REAL, P(viscosity), 0, 1e3, PL_KEY_MIN_OPEN, NULL, 1e-6, NULL,
     "m^2/s", "kinematic viscosity nu of the solvent (water: 1e-6)"},
    {"gravity", PL_KEY_REAL, P(gravity), 0, 1e4, 0, NULL, 0, NULL,
     "m/s^2", "gravitational acceleration along -z (0: none); sedimentation needs particle_density > solvent_density"},
    {"hamaker", PL_KEY_REAL, P(hamaker), 0, 1e-15, 0, NULL, 0, NULL,
     "J", "Hamaker constant A_H (Hecht Eq. 2); scaled with the model temperature"},
    {"surface_potential", PL_KEY_REAL, P(surface_potential), -1, 1, 0, NULL, 0, NULL,
     "V", "effective surface potential Psi0 (Hecht Eq. 1; 0: no screened Coulomb term)"},
    {"kappa", PL_KEY_REAL, P(kappa), 0, 1e11, 0, NULL, 0, NULL,
     "1/m", "inverse Debye length; 0: from ionic_strength by Debye-Hueckel, kappa^2 = 2 N_A e^2 I / (eps_r eps0 kT)"},
    {"ionic_strength", PL_KEY_REAL, P(ionic_strength), 0, 10, 0, NULL, 0, NULL,
     "mol/L", "I = 1/2 sum c_i z_i^2 (a z:z salt of concentration c: I = c z^2); used when kappa = 0"},
    {"valence", PL_KEY_INT, P(valence), 1, 4, PL_KEY_INT32, NULL, 1, NULL,
     "-", "ion charge number z in Hecht Eq. 1"},
    {"permittivity", PL_KEY_REAL, P(permittivity), 1, 1e3, 0, NULL, 0, NULL,
     "-", "relative permittivity eps_r of the solvent; not given: water at physical.temperature "
          "(Malmberg & Maryott 1956: 78.3 at 25 C, 77.6 at 300 K; refused outside 0-100 C)"},
    {"primary_minimum", PL_KEY_REAL, P(primary_minimum), 0, 1e-3, 0, NULL, 0, NULL,
     "m", "distance l from the surface to the primary minimum (Hecht Table I: 8e-9); sets tau_V, Hecht Eq. 26"},
    {"young_modulus", PL_KEY_REAL, P(young_modulus), 0, 1e13, 0, NULL, 0, NULL,
     "Pa", "Young's modulus E of the colloid material (0: not given); with poisson_ratio gives the Hertz constant "
           "K = 4 E sqrt(R/2) / (15 (1 - nu_P^2)) of Hecht Eq. 3 (Al2O3: ~3.7e11)"},
    {"poisson_ratio", PL_KEY_REAL, P(poisson_ratio), -1, 0.5, PL_KEY_MIN_OPEN, NULL, 0, NULL,
     "-", "Poisson ratio nu_P of the colloid material (with young_modulus; Al2O3: ~0.22)"},
    {"hertz_constant", PL_KEY_REAL, P(hertz_constant), 0, 1e30, 0, NULL, 0, NULL,
     "J/m^2.5", "(0: not given) Hertz constant K of Hecht Eq. 3 directly (instead of young_modulus + poisson_ratio)"},
    {"volume_fraction", PL_KEY_REAL, P(volume_fraction), 0, 0.74, 0, NULL, 0, NULL,
     "-", "colloid volume fraction phi; with the box gives the number of colloids"},
    {"box", PL_KEY_REAL3, P(box), 0, 1, 0, NULL, 0, NULL,
     "m", "box edge lengths; 0: keep box.cells (else box.cells = L / a0 rounded to the nearest whole number, box.cells must not be set; the colloid count follows phi in the box used, BOX_ROUNDED note)"},
    {"flow_velocity", PL_KEY_REAL, P(flow_velocity), 0, 1e3, 0, NULL, 0, NULL,
     "m/s", "typical colloid or flow velocity for Re, Pe, Ma when there is no gravity (PL Table V: 1e-5)"},
    {"sound_speed", PL_KEY_REAL, P(sound_speed), 0, 1e5, PL_KEY_MIN_OPEN, NULL, 1480, NULL,
     "m/s", "speed of sound of the solvent (real Ma, t_cs; water 1480)"},
    {"mean_free_path", PL_KEY_REAL, P(mean_free_path), 0, 1, PL_KEY_MIN_OPEN, NULL, 3e-10, NULL,
     "m", "molecular mean free path of the solvent (real Kn; water ~3e-10, PL Table IV)"},
    {"self_diffusion", PL_KEY_REAL, P(self_diffusion), 0, 1, PL_KEY_MIN_OPEN, NULL, 2.35e-9, NULL,
     "m^2/s", "self-diffusion coefficient of a solvent molecule (real Sc; water 2.35e-9, PL Table IV)"},
    {"clusters_gap", PL_KEY_REAL, P(clusters_gap), -1e-3, 1e-3, PL_KEY_FP_SET, NULL, 0, NULL,
     "m", "observe.clusters_gap in SI: two colloids are bonded when their surface gap is below this (0: not "
          "given; with the gap cluster observer on and neither given, derived from the pair potential: the "
          "largest gap at which the pair energy is below -observe.clusters_energy, i.e. bound in the primary "
          "minimum, or in the secondary one where that is as deep; peloid params states it)"},
    {"rdf_rmax", PL_KEY_REAL, P(rdf_rmax), 0, 1, PL_KEY_FP_SET, NULL, 0, NULL,
     "m", "observe.rdf_rmax in SI (0: not given)"},
    {"steinhardt_rmax", PL_KEY_REAL, P(steinhardt_rmax), 0, 1, PL_KEY_FP_SET, NULL, 0, NULL,
     "m", "observe.steinhardt_rmax in SI (0: not given)"},
    {"sq_qmax", PL_KEY_REAL, P(sq_qmax), 0, 1e12, PL_KEY_FP_SET, NULL, 0, NULL,
     "1/m", "observe.sq_qmax in SI (0: not given)"},
};

static const pl_key_t cg_keys[] = {
    {"coupling", PL_KEY_CHOICE, C(coupling), PL_COUPLE_HECHT1, 0, 0, coupling_choices, PL_COUPLE_HECHT1, NULL,
     "-", "I: fluid reflected off colloid surfaces (Hecht Sec. IV); II: colloids join the collision (Hecht Sec. V); "
          "potential: WCA colloid-fluid forces (PL Sec. III.A, Eq. 17) with PL Sec. VII's choices: sigma_cf = R = 2 a0, "
          "epsilon_cf = 2.5 kT, colloid-colloid WCA n = 24 with PL's sigma_cc rule, slip surface + Enskog theory"},
    {"time_match", PL_KEY_CHOICE, C(time_match), 0, 0, 0, match_choices, PL_MATCH_DIFFUSION, NULL,
     "-", "time kept equal to reality: diffusion (colloid D and tau_D: Hecht Eq. 30, PL example 1) or "
          "kinematic (tau_nu = R^2/nu: PL example 2)"},
    {"cell_size", PL_KEY_REAL, C(cell_size), 0, 100, 0, NULL, 0, NULL,
     "R", "cell size a0 / R; 0: 0.5 for coupling I (Hecht: a = R/2) and potential (PL: sigma_cf = 2 a0), (4 pi/3)^(1/3) "
          "for II (cell volume = colloid volume)"},
    {"particles_per_cell", PL_KEY_REAL, C(particles_per_cell), 1, 1e4, PL_KEY_MIN_OPEN, NULL, 5, NULL,
     "-", "gamma (Hecht: M), mean fluid particles per cell; becomes fluid.density"},
    {"mean_free_path", PL_KEY_REAL, C(mean_free_path), 0, 10, PL_KEY_MIN_OPEN, NULL, 0.1, NULL,
     "a0", "lambda = dt sqrt(kT/m_f) / a0 (PL Eq. 4); becomes srd.dt in t0"},
    {"boundary", PL_KEY_CHOICE, C(boundary), 0, 0, 0, boundary_choices, PL_BOUNDARY_STICK, NULL,
     "-", "colloid surface: stick (Stokes 6 pi eta R) or slip (4 pi eta R), PL Eq. 39"},
    {"enskog", PL_KEY_BOOL, C(enskog), 0, 1, 0, NULL, 0, NULL,
     "-", "add the Enskog friction in parallel (PL Eqs. 40-41) to the model colloid friction"},
    {"fluid_gravity", PL_KEY_BOOL, C(fluid_gravity), 0, 1, 0, NULL, 0, NULL,
     "-", "gravity also on the fluid (buoyancy; audit numbers only, refused with colloids); false: Hecht Eq. 31, the colloid alone feels a reduced gravity"},
    {"srd_dt", PL_KEY_REAL, C(srd_dt), 0, 1e6, 0, NULL, 0, NULL,
     "s", "SRD step; 0: derived from time_match (Hecht Eq. 30); set it to use a rounded step"},
    {"md_dt", PL_KEY_REAL, C(md_dt), 0, 1e6, 0, NULL, 0, NULL,
     "s", "MD step; 0: min(tau_V, tau_P) of the model / md_resolution; rounded to divide the SRD step "
          "(longer than it: refused); made finer where the contact or damping guard needs it (note MD_DT_REFINED)"},
    {"md_resolution", PL_KEY_REAL, C(md_resolution), 1, 1e6, 0, NULL, 20, NULL,
     "steps", "MD steps per shortest colloid time (Hecht Sec. II: ~20 steps per collision)"},
    {"hertz_K", PL_KEY_REAL, C(hertz_K), 0, 1e15, 0, NULL, 0, NULL,
     "kT/a0^2.5", "model Hertz constant chosen softer than the material (Hecht Sec. II: K is chosen so "
                  "that overlaps stay below ~10% and a collision takes ~20 MD steps, not from the elastic "
                  "modulus); 0 / not given: K of physical.young_modulus / hertz_constant in kT/a0^2.5.  Refused below "
                  "kT / (2R)^2.5, where a pair meeting with the energy kT passes through the contact"},
    {"reach_energy", PL_KEY_REAL, C(reach_energy), 10, 1e6, 0, NULL, 40, NULL,
     "kT", "the MD substeps resolve every gap a colliding pair can reach with this energy above the lowest "
           "pair energy further out (Boltzmann factor e^-40 by default); a DLVO barrier higher than this "
           "shields the primary minimum and the Hertz contact (note CONTACT_SHIELDED).  At least 10 kT: "
           "a collision's energy along the line of centres exceeds E with probability e^-E/kT, so below "
           "10 kT more than 1 collision in 22000 reaches gaps the MD step does not resolve"},
    {"multiple_time_stepping", PL_KEY_BOOL, C(multiple_time_stepping), 0, 1, PL_KEY_FP_SET, NULL, 0, NULL,
     "-", "stiff DLVO suspensions: the colloid MD by multiple time stepping (r-RESPA) with colloids.slow_gap "
          "= the outer edge (inflection point) of the DLVO secondary minimum's well (the stiff near field "
          "inside it on every MD step, the smooth tail beyond on outer steps) and colloids.slow_interval = the longest outer step whose slow forces "
          "the contact guard's rule still resolves (at most a quarter of the fewest MD steps per SRD step); "
          "see peloid params"},
    {"strict", PL_KEY_BOOL, C(strict), 0, 1, 0, NULL, 0, NULL,
     "-", "treat every audit warning (Ma, Re, Kn, Sc, Pe, time-scale hierarchy) as an error (like --strict)"},
};

const pl_section_t pl_scene_section_physical = {
    "physical", "the real suspension in SI units (switches the unit mapping on)", physical_keys,
    N(physical_keys)};
const pl_section_t pl_scene_section_coarse_graining = {
    "coarse_graining", "how the physical{} system is mapped onto SRD + MD (Hecht Sec. VII, PL Sec. VII)",
    cg_keys, N(cg_keys)};
