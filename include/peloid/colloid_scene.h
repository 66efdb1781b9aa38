/* Scene structs of the colloid module (sections colloids, dlvo, hertz,
 * lubrication, wca; schema in src/scene/scene_keys_colloid.c).  Included by
 * scene.h; plain data only. */
#ifndef PELOID_COLLOID_SCENE_H
#define PELOID_COLLOID_SCENE_H

enum { PL_CINIT_LATTICE = 0, PL_CINIT_RANDOM = 1, PL_CINIT_FILE = 2 };
enum { PL_CINT_VERLET = 0, PL_CINT_BROWNIAN = 1 };
/* wca.sigma_rule: sigma_cc as given, or PL's rule against spurious depletion
 * (PL Sec. III.C.1, see depletion.h). */
enum { PL_SIGMA_FIXED = 0, PL_SIGMA_PL = 1 };
/* colloids.table_interpolation: from the file's rows onto the internal table */
enum { PL_TABLE_LINEAR = 0, PL_TABLE_SPLINE = 1 };

typedef struct {
    double eps_r, psi0_mV, z, temperature_K, kappa_per_m, hamaker_J, length_unit_m;
    double primary_depth, primary_gap, cutoff_energy;
} pl_scene_dlvo_t;

typedef struct {
    double K, beta, gamma_t;
} pl_scene_hertz_t;

typedef struct {
    double viscosity, min_gap, cutoff_gap;
    int thermal; /* bool: the random partner of the squeeze friction (fluctuation-dissipation) */
} pl_scene_lub_t;

typedef struct {
    double epsilon, sigma, n;
    int sigma_rule; /* PL_SIGMA_* */
} pl_scene_wca_t;

typedef struct {
    long long count;
    double radius, polydispersity, mass_density, temperature;
    int init;              /* PL_CINIT_* */
    char init_file[128];   /* relative to the scene file's directory */
    char pairs[128];       /* comma-separated subset of dlvo, hertz, lubrication, wca,
                              depletion_comp */
    int integrator;        /* PL_CINT_* */
    long long substeps;    /* MD steps per collision step */
    long long slow_interval; /* MD steps per outer step of the slow DLVO share (1: one time step) */
    double slow_gap;       /* a0: surface gap where the slow share starts (full at 2x) */
    int adaptive_substeps; /* bool: per collision step the fewest MD steps the pairs present need */
    long long min_substeps; /* adaptive: the fewest MD steps per collision step */
    double adaptive_margin; /* adaptive: kT added to each pair's energy (third bodies, walls) */
    double gravity[3];
    double bd_viscosity;
    double wall_epsilon, wall_n;
    double max_overlap, min_contact_steps, max_energy_drift;
    long long guard_interval;     /* MD steps between energy-drift checks */
    double neighbor_skin;         /* Verlet-list skin / largest pair cut-off */
    long long trajectory_interval; /* collision steps; 0 = no trajectory */
    pl_scene_dlvo_t dlvo;
    pl_scene_hertz_t hertz;
    pl_scene_lub_t lub;
    pl_scene_wca_t wca;
    /* the table pair term (src/colloid/colloid_pair_table.c) */
    char table_file[128];      /* relative to the scene file's directory */
    int table_interpolation;   /* PL_TABLE_* */
    double table_force_tolerance; /* allowed |F + dV/dr| / max |F| of the file */
} pl_scene_colloids_t;

#endif
