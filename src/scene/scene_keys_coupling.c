/* Scene schema of the colloid-solvent coupling: section `coupling` (method,
 * surface rule and placement of coupling I, gravity compensation and drift
 * removal; Hecht Secs. IV, V, VIII.A). */
#include <stddef.h>

#include "peloid/scene.h"

#define OFF(member) offsetof(pl_scene_t, coupling.member)
#define N(a) (sizeof(a) / sizeof((a)[0]))

static const char *const method_choices[] = { /* indexed by PL_COUPLE_* */
    [PL_COUPLE_NONE] = "none", [PL_COUPLE_HECHT1] = "hecht1", [PL_COUPLE_HECHT2] = "hecht2",
    [PL_COUPLE_POTENTIAL] = "potential", NULL};
const char *const pl_coupling_boundary_names[] = {"slip", "stick_stochastic", "stick_bounce", NULL};
static const char *const placement_choices[] = {"nearest", "entry", NULL};

static const pl_key_t coupling_keys[] = {
    {"method", PL_KEY_CHOICE, OFF(method), 0, 0, 0, method_choices, PL_COUPLE_NONE, NULL,
     "-", "(physical{} scenes: derived from coarse_graining.coupling) none: colloids and fluid do not interact; hecht1: fluid particles that stream into a "
          "colloid are reflected off its surface (Hecht Sec. IV); hecht2: colloids join the SRD "
          "collision of their cell with mass-weighted mean velocity (Hecht Sec. V, Eq. 15); "
          "potential: WCA colloid-fluid forces (PL Eq. 17), integrated at the MD step for the "
          "fluid particles near colloids (radial: slip, PL Sec. III.B)"},
    {"boundary", PL_KEY_CHOICE, OFF(boundary), 0, 0, 0, pl_coupling_boundary_names,
     PL_BOUND_STICK_STOCHASTIC, NULL,
     "-", "hecht1 surface rule for the velocity g relative to the surface point: slip (new "
          "normal g from Hecht Eq. 13, tangential kept: no torque), stick_stochastic (normal "
          "Eq. 13, tangential Eq. 14 = PL Eqs. 20-21: force and torque), stick_bounce (g -> -g); "
          "beta uses the contact's effective mass (m_f for heavy colloids)"},
    {"placement", PL_KEY_CHOICE, OFF(placement), 0, 0, 0, placement_choices, PL_PLACE_ENTRY, NULL,
     "-", "hecht1 restart point: nearest (method i: nearest surface point, then half a step "
          "with the new velocity), entry (method ii: back to the entry point, then the rest of "
          "the step)"},
    {"max_reflections", PL_KEY_INT, OFF(max_reflections), 1, 1000, 0, NULL, 10, NULL,
     "-", "hecht1: N_max, reflections per particle and step when the new position lies in "
          "another colloid (Hecht Sec. IV: ~10); more are counted as truncations"},
    {"wall_temperature", PL_KEY_REAL, OFF(wall_temperature), 0, 1e6, 0, NULL, 0, NULL,
     "kT_ref", "hecht1: kT of the thermal surface, Hecht Eqs. 13-14 (0: thermostat.temperature "
               "with a thermostat, else fluid.temperature)"},
    {"compensate_gravity", PL_KEY_BOOL, OFF(compensate_gravity), 0, 1, 0, NULL, 1, NULL,
     "-", "fully periodic box: the fluid gets the opposite of the total colloid gravity "
          "(Hecht Sec. VIII.A iii), so the centre of mass stays at rest; ignored with walls"},
    {"drift_interval", PL_KEY_INT, OFF(drift_interval), 0, 1e15, 0, NULL, 0, NULL,
     "collision steps", "fully periodic box: remove the centre-of-mass velocity of fluid + "
                        "colloids every N steps (Hecht Sec. VIII.A; 0: never)"},
    {"pinned", PL_KEY_BOOL, OFF(pinned), 0, 1, 0, NULL, 0, NULL,
     "-", "colloids held fixed (zero velocity) in the flow, e.g. driven by fluid.body_force; "
          "the mean force the fluid exerts on them is written to thermo.tsv (drag, PL Sec. V)"},
    {"flow_velocity", PL_KEY_REAL3, OFF(flow_velocity), -1e3, 1e3, 0, NULL, 0, NULL,
     "a0 / t0", "pinned: the fluid's mean velocity is set to this value after every collision "
                "step (the momentum the pinned colloids take is given back uniformly), so the "
                "drag is measured at a set flow velocity v_inf (PL Eq. 39); 0: off"},
    {"pinned_spin", PL_KEY_REAL3, OFF(pinned_spin), -1e3, 1e3, PL_KEY_FP_SET, NULL, 0, NULL,
     "1 / t0", "pinned, coupling I: the colloids turn at this angular velocity, held after every "
               "collision step; the mean torque the fluid exerts on them is written to thermo.tsv "
               "(a stick sphere: -8 pi eta R^3 Omega); 0: held still"},
    {"sigma_cf", PL_KEY_REAL, OFF(sigma_cf), 0, 1e3, 0, NULL, 0, NULL,
     "a0", "potential: colloid-fluid diameter sigma_cf of PL Eq. 17 (0: colloids.radius)"},
    {"epsilon_cf", PL_KEY_REAL, OFF(epsilon_cf), 0, 1e6, PL_KEY_MIN_OPEN, NULL, 2.5, NULL,
     "kT_ref", "potential: epsilon_cf of PL Eq. 17 (PL: 2.5 kT)"},
    {"max_settling_energy", PL_KEY_REAL, OFF(max_settling_energy), 0, 1e6, 0, NULL, 0.5, NULL,
     "kT_ref", "hecht2 with gravity: largest M v_s^2 accepted, v_s = M g / xi_II the settling "
               "speed with the friction of the colloid's own cell (xi_II = 2/3 (1 - cos alpha) "
               "mu / dt, an upper bound, so v_s is a lower bound); M v_s^2 / kT = 2 Pe tau_P / "
               "tau_S (Hecht Sec. VI asks tau_P << tau_S); colloids much heavier than the fluid "
               "of their cell settle about as fast as they move thermally and run hot; 0: off"},
};

const pl_section_t pl_scene_section_coupling = {"coupling", "colloid-solvent coupling "
                                                "(Hecht Secs. IV, V, VIII.A)",
                                                coupling_keys, N(coupling_keys)};
