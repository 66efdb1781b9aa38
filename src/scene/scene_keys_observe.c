/* Scene schema of the observers: section `observe` (colloid g(r), colloid
 * MSD and diffusion coefficient, clusters; Hecht Sec. IX, PL Sec. VI).  No
 * key here changes the trajectory: the checkpoint's scene fingerprint leaves
 * the section out (src/core/checkpoint_scene.c). */
#include <stddef.h>

#include "peloid/scene.h"

#define OFF(member) offsetof(pl_scene_t, observe.member)
#define N(a) (sizeof(a) / sizeof((a)[0]))

static const char *const bond_choices[] = {"gap", "energy", NULL}; /* PL_BOND_* */

static const pl_key_t observe_keys[] = {
    {"rdf_interval", PL_KEY_INT, OFF(rdf_interval), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "colloid radial distribution function g(r) every this many steps (0: off); mean and SE per bin by "
     "blocking over samples; normalised by the ideal gas of the accessible region (slab between z walls)"},
    {"rdf_start", PL_KEY_INT, OFF(rdf_start), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "first step g(r) samples (equilibration before it)"},
    {"rdf_bins", PL_KEY_INT, OFF(rdf_bins), 1, 1e6, 0, NULL, 200, NULL, "-", "g(r) bins over [0, rdf_rmax)"},
    {"rdf_rmax", PL_KEY_REAL, OFF(rdf_rmax), 0, 1e6, 0, NULL, 0, NULL, "a0",
     "largest distance of g(r) (0: half the shortest periodic box edge, or the box edge with walls on all "
     "axes but z); else above contact (2 x the smallest radius); a physical scene may give it in m as physical.rdf_rmax"},
    {"rdf_size_classes", PL_KEY_INT, OFF(rdf_size_classes), 0, 16, 0, NULL, 0, NULL, "-",
     "partial g_ab(r) of size classes (0: off; k in 2..16): the colloids ranked by radius (ties by index) and "
     "cut into k classes of equal count, class floor(rank k / N); every class pair a <= b, normalised by its "
     "own pair count; needs colloids.polydispersity > 0 or radii from colloids.init_file"},
    {"sq_interval", PL_KEY_INT, OFF(sq_interval), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "colloid static structure factor S(q) = |sum_j exp(i q.r_j)|^2 / N every this many steps (0: off; all "
     "axes periodic), direct sum over the box's wave vectors q = 2 pi (n_x/L_x, n_y/L_y, n_z/L_z), 0 < |q| < "
     "sq_qmax, binned by |q|; mean and SE per bin by blocking over samples; costs N x (2 pi / 3) "
     "(sq_qmax L / 2 pi)^3 terms per sample, at most 1e10 (refused above)"},
    {"sq_start", PL_KEY_INT, OFF(sq_start), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "first step S(q) samples"},
    {"sq_bins", PL_KEY_INT, OFF(sq_bins), 1, 1e6, 0, NULL, 100, NULL, "-", "S(q) bins over [0, sq_qmax)"},
    {"sq_qmax", PL_KEY_REAL, OFF(sq_qmax), 0, 1e3, 0, NULL, 0, NULL, "1/a0",
     "largest |q| of S(q) (0: 4 pi / colloids.radius, past the first peak near 2 pi / (2R)); a physical scene may give it in 1/m as physical.sq_qmax"},
    {"msd_interval", PL_KEY_INT, OFF(msd_interval), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "colloid mean-squared displacement of the unwrapped positions every this many steps (0: off), by a "
     "multiple-tau correlator (16 points per level, factor 2) up to the run length; D from its slope"},
    {"msd_start", PL_KEY_INT, OFF(msd_start), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "first step the MSD samples"},
    {"vacf_interval", PL_KEY_INT, OFF(vacf_interval), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "colloid velocity autocorrelation <v(0).v(t)> every this many steps (0: off; velocity Verlet colloids), "
     "multiple-tau up to the run length; Green-Kubo D = (1/3) of its integral up to a quarter of the "
     "sampled span (Hecht Eq. 35, Fig. 3; PL Eq. 58)"},
    {"vacf_start", PL_KEY_INT, OFF(vacf_start), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "first step the VACF samples"},
    {"cff_interval", PL_KEY_INT, OFF(cff_interval), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "autocorrelation C_FF(t) = <F(0).F(t)> of the fluid force on each colloid (PL Eq. 50, Fig. 10) every "
     "this many steps (0: off; coupling.method = \"potential\" only: the collision couplings exchange "
     "impulses, no force), F the force's mean over each collision step (trapezoid over the MD steps; its "
     "correlation integrates to the same friction as the instantaneous force's), multiple-tau up to the run "
     "length; Green-Kubo friction xi = (1/3kT) of its integral up to its first zero (PL Eq. B2)"},
    {"cff_start", PL_KEY_INT, OFF(cff_start), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "first step C_FF samples"},
    {"clusters_interval", PL_KEY_INT, OFF(clusters_interval), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "colloid clusters (bond: surface gap below clusters_gap; union-find) every this many steps (0: off): "
     "number of clusters, largest, mean size over time, their averages with SE, the final size distribution"},
    {"clusters_start", PL_KEY_INT, OFF(clusters_start), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "first step the clusters are counted"},
    {"clusters_gap", PL_KEY_REAL, OFF(clusters_gap), -1e6, 1e6, 0, NULL, 0.1, NULL, "a0",
     "two colloids are bonded when their surface gap r - R_i - R_j is below this (clusters_bond = \"gap\"); "
     "a physical scene takes it in m as physical.clusters_gap, and with neither given derives it from the pair "
     "potential (the largest gap bound by more than clusters_energy; peloid params states it)"},
    {"clusters_bond", PL_KEY_CHOICE, OFF(clusters_bond), 0, 0, 0, bond_choices, PL_BOND_GAP, NULL, "-",
     "the bond rule of the cluster observer: \"gap\" (surface gap below clusters_gap) or \"energy\" (the "
     "conservative pair energy of colloids.pairs below -clusters_energy; a bond closer than the DLVO barrier "
     "is a primary-minimum bond, one beyond it a secondary-minimum bond; needs a pair minimum deeper than "
     "-clusters_energy)"},
    {"clusters_energy", PL_KEY_REAL, OFF(clusters_energy), 0, 1e6, PL_KEY_MIN_OPEN, NULL, 1.0, NULL, "kT_ref",
     "E_c of the energy bond: two colloids are bonded when their pair energy is below -E_c"},
    {"vdist_interval", PL_KEY_INT, OFF(vdist_interval), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "velocity components of the fluid and of the colloids every this many steps (0: off), each scaled by "
     "sqrt(M / kT) (kT of the thermostat, else of the fluid) minus the mean: histograms and chi^2 against "
     "the unit Gaussian of Maxwell-Boltzmann (Hecht Figs. 2, 8); samples closer than the velocity "
     "correlation time are not independent"},
    {"vdist_start", PL_KEY_INT, OFF(vdist_start), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "first step the velocity distributions sample"},
    {"sediment_interval", PL_KEY_INT, OFF(sediment_interval), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "sedimentation every this many steps (0: off): the colloid volume-fraction profile phi(z) (exact sphere "
     "slices), the mean height (unwrapped z), <v_z> and the settling velocity of the colloids' mean height "
     "relative to the fluid's mean (positive down); its time average with the blocking SE is the (hindered) "
     "settling velocity of Hecht Eq. 37"},
    {"sediment_start", PL_KEY_INT, OFF(sediment_start), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "first step the sedimentation observer samples"},
    {"sediment_bins", PL_KEY_INT, OFF(sediment_bins), 0, 1e6, 0, NULL, 0, NULL, "-",
     "slabs of phi(z) over the box height (0: one per collision cell)"},
    {"steinhardt_interval", PL_KEY_INT, OFF(steinhardt_interval), 0, 1e15, PL_KEY_FP_SET, NULL, 0, NULL,
     "collision steps",
     "Steinhardt bond-orientational order of the colloids every this many steps (0: off): local q_l(i) = "
     "sqrt(4 pi / (2l+1) sum_m |q_lm(i)|^2), q_lm(i) the mean of Y_lm over the neighbours closer than "
     "steinhardt_rmax, and the global Q_l of the colloid-averaged q_lm, l = 4 and 6 (fcc: Q4 0.191, Q6 0.575; "
     "an ideal gas: Q_l ~ 1/sqrt(bonds)); time averages with SE; O(N^2) per sample"},
    {"steinhardt_start", PL_KEY_INT, OFF(steinhardt_start), 0, 1e15, PL_KEY_FP_SET, NULL, 0, NULL,
     "collision steps", "first step the Steinhardt order samples"},
    {"steinhardt_rmax", PL_KEY_REAL, OFF(steinhardt_rmax), 0, 1e6, PL_KEY_FP_SET, NULL, 0, NULL, "a0",
     "neighbour cut-off of the Steinhardt order (needed with steinhardt_interval > 0; e.g. the first minimum "
     "of g(r)), above contact (2 x the smallest radius) and at most half the periodic box edge; a physical scene may give it in m as physical.steinhardt_rmax"},
    {"stress_interval", PL_KEY_INT, OFF(stress_interval), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "fluid stress (momentum flux) tensor, kinetic + collisional parts, accumulated every step and written "
     "as its mean over every this many steps (0: off); the shear viscosity from the Green-Kubo sum of the "
     "off-diagonal parts (Helfand form, PL Eqs. 9-15 to compare) and the pressure, each with its blocking SE; "
     "pure fluid in a periodic box"},
    {"stress_start", PL_KEY_INT, OFF(stress_start), 0, 1e15, 0, NULL, 0, NULL, "collision steps",
     "first step the stress is accumulated"},
    {"stress_gk_steps", PL_KEY_INT, OFF(stress_gk_steps), 0, 1e5, 0, NULL, 0, NULL, "collision steps",
     "lags of the stress autocorrelation the Green-Kubo sum includes (0: ten kinetic stress relaxation "
     "times 1 / (1 - f) from PL Eq. 9, at least 10); each lag adds noise, too few cut the integral: the "
     "running sum against the lag is written so that its plateau can be checked"},
    {"average_from", PL_KEY_STRING, OFF(average_from), 0, 0, 0, NULL, 0, "auto", "-",
     "where the time averages of the cluster and sedimentation series (summary.json values and SEs) start: "
     "\"auto\" (per series, Chodera's automated equilibration detection, J. Chem. Theory Comput. 12, 1799 "
     "(2016): the start in the first half that maximises the effective number of uncorrelated samples), "
     "\"start\" (the whole run), a time \"t\" (seconds in a scene with physical{}, t0 otherwise; e.g. \"12.5\") "
     "or a percentage of the run \"p%\" (e.g. \"75%\": the last quarter); each summary.json entry states the "
     "start (average_from_step, average_from_time, window_source); a time beyond the run's end is refused"},
    {"target_rel_error", PL_KEY_REAL, OFF(target_rel_error), 0, 1, PL_KEY_MIN_OPEN, NULL, 0.01, NULL, "-",
     "relative standard error the end-of-run report extrapolates the needed wall time to (SE ~ 1/sqrt(t))"},
};

const pl_section_t pl_scene_section_observe = {"observe", "observers: measured quantities with error bars",
                                               observe_keys, N(observe_keys)};

#undef OFF
#define OFF(member) offsetof(pl_scene_t, stop.member)

static const pl_key_t stop_keys[] = {
    {"observable", PL_KEY_STRING, OFF(observable), 0, 0, 0, NULL, 0, "none", "-",
     "end the run (final checkpoint and outputs written) once this observable's standard error is below "
     "rel_error of its value: \"none\", or an estimate of an observer that is on (the summary.json "
     "\"observables\" entries with a se_vs_time, e.g. \"colloid_D\", \"rdf_peak\", \"cluster_number\"; another "
     "name is refused with the list)"},
    {"rel_error", PL_KEY_REAL, OFF(rel_error), 0, 1, 0, NULL, 0.01, NULL, "-",
     "the relative standard error that ends the run"},
    {"check_interval", PL_KEY_INT, OFF(check_interval), 1, 1e15, 0, NULL, 100, NULL, "collision steps",
     "the rule is checked every this many steps (from the state only: the same step for any thread count)"},
    {"max_wall_s", PL_KEY_REAL, OFF(max_wall_s), 0, 1e12, 0, NULL, 0, NULL, "s",
     "end the run after this much wall time (0: no limit); reported, and the one rule that depends on the "
     "machine"},
};

const pl_section_t pl_scene_section_stop = {"stop", "stopping rule: end a run at a requested error", stop_keys,
                                            N(stop_keys)};
