/* Mapping a physical suspension onto SRD + MD simulation parameters, and the
 * audit of time scales and dimensionless numbers.
 *
 * Physics: Hecht et al. 2005 Sec. VI-VII (Eqs. 16-31, Tables I-IV) and
 * Padding & Louis 2006 (PL) Sec. II.B (Eqs. 4-15), IV (Eqs. 26-38), VI
 * (Eqs. 46-57), VII and Appendix C (Tables IV-VI).
 *
 * Units.  Inputs and the "real"/"model" tables are SI.  The simulation runs
 * in a0 = 1 (cell size), m_f = 1 (fluid particle mass), kT = 1 (the model
 * temperature), so t0 = a0 sqrt(m_f/kT) and the SRD step is lambda t0
 * (PL Eq. 4).  The mapping fixes a0 (from R and the cell size), m_f (the
 * solvent mass density rho_f = gamma m_f / a0^3 is kept) and t0 (by matching
 * either the colloid diffusion time, Hecht Sec. VII / PL example 1, or the
 * kinematic time, PL example 2).  The model temperature kT_model = m_f a0^2 /
 * t0^2 then differs from the real kT; all energies are scaled with it
 * (Hecht's Lambda = rho/kT argument, PL example 3).
 *
 * Modules: mapping_srd.c (SRD transport + friction), mapping_hecht.c (Hecht
 * time scales and Sec. VII derivation), mapping_pl.c (PL colloid numbers and
 * time scales), mapping_audit.c (dimensionless numbers and warnings),
 * mapping_report.c (text + JSON), mapping_scene.c (scene front end). */
#ifndef PELOID_MAPPING_H
#define PELOID_MAPPING_H

#include <stdio.h>

#include "peloid/coupling_scene.h" /* PL_COUPLE_* */
#include "peloid/error.h"

struct pl_scene;

#define PL_KB 1.380649e-23          /* J/K (CODATA 2018, exact) */
#define PL_E_CHARGE 1.602176634e-19 /* C */
#define PL_EPS0 8.8541878128e-12    /* F/m */
#define PL_NA 6.02214076e23         /* 1/mol */

enum { PL_MATCH_DIFFUSION = 0, PL_MATCH_KINEMATIC = 1 };
enum { PL_BOUNDARY_STICK = 0, PL_BOUNDARY_SLIP = 1 };
/* Viscosity formula: Hecht Eq. 28 (rotation by +-90 deg about a coordinate
 * axis) or PL Eqs. 9-12 (rotation by alpha about a random axis). */

/* ---- SRD transport (PL Eqs. 6, 9-15; Hecht Eq. 28) ------------------- */
/* In units a0, t0, m_f; lambda = dt/t0, gamma = particles per cell. */
double pl_mapping_nu_kin(double lambda, double gamma, double alpha);    /* PL Eq. 9 */
double pl_mapping_nu_col(double lambda, double gamma, double alpha);    /* PL Eq. 10 */
double pl_mapping_d_fluid(double lambda, double gamma, double alpha);   /* PL Eq. 6 */
double pl_mapping_nu_hecht(double lambda, double gamma);                /* Hecht Eq. 28 */
/* Kinematic viscosity nu/nu0 of collision rule `rule` (srd.rule: its row's theory). */
double pl_mapping_nu(int rule, double lambda, double gamma, double alpha);
/* Fluid self-diffusion D_f/(a0^2/t0) of collision rule `rule` (its row's theory). */
double pl_mapping_d_fluid_rule(int rule, double lambda, double gamma, double alpha);
/* Enskog friction of a colloid of radius sigma and mass mc (units a0, m_f, kT,
 * t0): PL Eq. 40 (slip); stick multiplies by the rough-sphere factor
 * (1 + 2k)/(1 + k), k = 2/5 (see mapping_srd.c). */
double pl_mapping_xi_enskog(double sigma, double mc, double gamma, int boundary);

/* ---- a suspension in SI (the real system, or the model expressed in SI) - */
typedef struct {
    double radius;   /* R, m */
    double rho_p;    /* colloid mass density, kg/m^3 */
    double rho_f;    /* solvent mass density, kg/m^3 */
    double nu;       /* solvent kinematic viscosity, m^2/s */
    double kT;       /* thermal energy, J */
    double g;        /* gravitational acceleration on the colloid, m/s^2 */
    int buoyancy;    /* 1: gravity acts on (rho_p - rho_f); 0: on rho_p (model
                        without gravity on the fluid, Hecht Eq. 31) */
    double hamaker;  /* A_H, J (0: no tau_V) */
    double l_min;    /* distance to the primary minimum l, m (0: no tau_V) */
} pl_mapping_system_t;

/* Hecht Sec. VI time scales (s); NaN where undefined (e.g. no gravity). */
typedef struct {
    double v_s;   /* Stokes velocity, Hecht Eq. 16 */
    double D;     /* colloid diffusion coefficient, Hecht Eq. 18 */
    double mass;  /* colloid mass 4/3 pi R^3 rho_p */
    double tau_S, tau_D, tau_G, tau_V, tau_F, tau_P; /* Eqs. 17, 20, tau_D/16, 26, 24, 23 */
    double Pe, Re; /* Eqs. 21, 25 */
} pl_mapping_hecht_times_t;

void pl_mapping_hecht_times(const pl_mapping_system_t *s, pl_mapping_hecht_times_t *t);

/* ---- the colloid diffusion a coupling realises ------------------------- */
/* A calibration run of the model (src/app/calibrate.c): n_colloids free
 * colloids in a periodic cube of `box` cells, `steps` collision steps; the
 * MSD slope gives d_box +- d_box_se (a0^2/t0, kT = 1); the hydrodynamic
 * tail the slope's lags miss in the box (pl_srd_tail_missed) gives the box's
 * long-time D, and the periodic images' correction (Hasimoto 1959: + 2.837
 * kT / (6 pi eta L)) the unbounded d_inf, which sets t0 when time is matched
 * on diffusion.
 * d_inf = 0: none (the theory of the coupling is used, unverified). */
typedef struct {
    double d_inf, d_inf_se;   /* a0^2/t0 */
    double d_box, d_box_se;   /* as measured in the calibration box */
    double hasimoto;          /* the periodic images' correction added, a0^2/t0 */
    double tail;              /* the hydrodynamic tail beyond the slope's lags, added (pl_srd_tail_missed) */
    double d_theory;          /* the coupling's theory it replaces, a0^2/t0 */
    double phi;               /* colloid volume fraction of the calibration box */
    long long steps;
    int n_colloids, box;
    double wall_s;            /* wall time of the run (0: read from a cache) */
    double concentration;     /* 1 - c phi of the calibration box (PL Sec. VI.C; 1: not corrected) */
    char cache[640];          /* the cache file it was read from or written to */
    /* provenance (src/app/calibrate_mode.c), for every output: the mode the
     * run asked for (PL_CALIBRATE_*), where d_inf came from (PL_CALSRC_*;
     * NONE: the scene was loaded without asking, e.g. a model scene), and
     * for PL_CALSRC_THEORY the theory's stated relative error with the
     * range of measured / theory over the shipped calibrations it rests on */
    int mode, source;
    double theory_error, theory_lo, theory_hi;
    int theory_files;
    /* PL_CALSRC_TABLE: the law's R_h/R here and the measured R/a0 range it
     * interpolates (cache: the law's file) */
    double table_rh_over_R, table_R_lo, table_R_hi;
} pl_mapping_calibration_t;

/* --calibrate: AUTO the shipped set or the cache or the resolution table, else a calibration run;
 * ALWAYS a calibration run (stored in the cache); NEVER the coupling's
 * theory (d_col_theory) with its stated error; STORED the shipped set or the
 * cache, else the theory with its stated error (never a run: check's
 * default, so that a scene is checked in seconds). */
enum { PL_CALIBRATE_AUTO = 0, PL_CALIBRATE_NEVER = 1, PL_CALIBRATE_ALWAYS = 2, PL_CALIBRATE_STORED = 3,
       PL_CALIBRATE_NMODES };
/* Its --calibrate word ("?" for none of them). */
const char *pl_calibrate_mode_name(int mode);
enum { PL_CALSRC_NONE = 0, PL_CALSRC_SHIPPED, PL_CALSRC_CACHE, PL_CALSRC_RUN, PL_CALSRC_THEORY, PL_CALSRC_TABLE };

/* ---- coarse-graining choices ------------------------------------------ */
typedef struct {
    int coupling;       /* PL_COUPLE_* (coupling_scene.h) */
    int match;          /* PL_MATCH_*: which time is kept (fixes t0) */
    int viscosity;      /* the collision rule whose theory gives nu (srd.rule, peloid/collision_rule.h) */
    int boundary;       /* PL_BOUNDARY_*: Stokes 6 pi (stick) or 4 pi (slip) */
    int enskog;         /* add the Enskog friction in parallel (PL Eq. 41) */
    int fluid_gravity;  /* gravity also on the fluid (else Hecht Eq. 31) */
    double cell_over_R; /* a0 / R (> 0) */
    double gamma;       /* fluid particles per cell (M in Hecht) */
    double lambda;      /* mean free path / a0 = dt / t0 (PL Eq. 4) */
    double alpha;       /* rotation angle, rad (PL viscosity) */
    double srd_dt;      /* SRD step in s; 0: derived (Hecht Eq. 30) */
    double md_dt;       /* MD step in s; 0: derived */
    double md_resolution; /* MD steps per shortest MD time scale (Hecht Sec. II: ~20) */
    double d_col_calibrated; /* measured unbounded colloid D, a0^2/t0 (0: theory) */
    double d_col_calibrated_se; /* its standard error, a0^2/t0 */
} pl_mapping_cg_t;

/* Extra properties of the real system the audit needs. */
typedef struct {
    double flow_velocity;   /* m/s; used when there is no gravity */
    double sound_speed;     /* c_s of the solvent, m/s */
    double mean_free_path;  /* lambda_free of the solvent, m */
    double self_diffusion;  /* D_f of a solvent molecule, m^2/s */
} pl_mapping_solvent_t;

/* PL time scales (s) with a = R: t_cs (Eq. 46), tau_nu (31), tau_B (47),
 * tau_E (53), tau_D (36), t_S (30). */
typedef struct {
    double t_cs, tau_nu, tau_B, tau_E, tau_D, t_S;
} pl_mapping_pl_times_t;

/* Dimensionless numbers (PL Table II): Sc (26), Ma (28), Re (29), Kn (34), Pe (35). */
typedef struct {
    double Sc, Ma, Re, Kn, Pe;
} pl_mapping_numbers_t;

enum { PL_MAP_MAX_WARN = 24 };
enum { PL_SEV_NOTE = 0, PL_SEV_WARNING = 1 };

typedef struct {
    char name[24];   /* e.g. "MACH", "REYNOLDS" */
    int severity;    /* PL_SEV_* */
    double value;
    char text[512];  /* number, value, recommended range, source, input to change */
    /* the input key it is about (empty: a derived number) and its offset in
     * pl_scene_t, so that a refusal names file, line and key */
    char key[40];
    size_t key_off;
} pl_mapping_warning_t;

/* Full result of the mapping. */
typedef struct {
    pl_mapping_system_t real, model;
    pl_mapping_cg_t cg;
    pl_mapping_solvent_t solvent;
    /* units of the simulation in SI */
    double a0, t0, m_f, kT_model; /* m, s, kg, J */
    double energy_scale;          /* kT_real / kT_model = Lambda_model / Lambda_real */
    double lambda_real, lambda_model; /* Hecht Lambda = rho_p / kT, s^2/m^5 */
    /* SRD */
    double nu_sim;        /* nu / nu0 */
    double nu_coeff;      /* nu dt / a0^2 (Hecht Eq. 29) */
    double dt;            /* SRD step, s */
    double d_fluid_sim;   /* D_f / D0 (PL Eq. 6) */
    /* colloid in simulation units */
    double sigma;         /* R / a0 */
    double mass_sim;      /* colloid mass / m_f */
    double xi_stokes_sim, xi_enskog_sim, xi_sim; /* m_f / t0 (PL Eqs. 39-41) */
    double d_col_sim;     /* a0^2 / t0: unbounded colloid D, calibrated or 1 / xi_sim */
    double d_col_theory;  /* 1 / xi_sim, the coupling's theory */
    pl_mapping_calibration_t calib; /* where d_col_sim was measured (calib.d_inf > 0) */
    /* the colloid D the scene's own box lets it reach: d_col_sim less the
     * periodic images' 2.837 kT / (6 pi eta L) (cubic-lattice sum, L = the
     * box volume's cube root) when every axis is periodic; box_periodic 0:
     * walls, no correction stated */
    double d_col_box, box_L;
    int box_periodic;
    double conc_factor;   /* the scene's own 1 - c phi in d_col_box (potential coupling; else 1) */
    /* the hydrodynamic radius of the model colloid (mapping_hydro.c): the
     * sphere whose classical friction in the model fluid is the colloid's
     * xi = kT / d_col_sim, R_h = xi / (k pi eta), k = 6 stick / 4 slip
     * (cg.boundary, PL Eq. 39), eta = gamma nu_sim (PL Eq. 13); over R =
     * sigma, its SE from the calibration's (NaN: theory, no SE), and the
     * stick sphere of the same friction (k = 6) */
    double rh_over_R, rh_over_R_se, rh_stick_over_R;
    double g_sim;         /* gravity on the colloid, a0 / t0^2 */
    double v_sim;         /* flow / Stokes velocity, a0 / t0 */
    /* MD */
    double md_dt;         /* s, after rounding to an integer number of substeps */
    long long md_substeps;/* MD steps per SRD step */
    /* time scales */
    pl_mapping_hecht_times_t hecht_real, hecht_model;
    pl_mapping_pl_times_t pl_real, pl_model;
    pl_mapping_numbers_t num_real, num_model;
    int nwarn;
    pl_mapping_warning_t warn[PL_MAP_MAX_WARN];
} pl_mapping_t;

/* Derives everything from the real system, the solvent extras and the
 * coarse-graining choices (Hecht Sec. VII; PL Sec. VII).  Returns
 * PL_ERR_INPUT for input that admits no mapping. */
int pl_mapping_derive(const pl_mapping_system_t *real, const pl_mapping_solvent_t *solvent,
                      const pl_mapping_cg_t *cg, pl_mapping_t *out, pl_err_t *err);

/* PL quantities of a colloid in an SRD fluid, simulation units (PL Table VI):
 * fills sigma, mass_sim, xi_*, d_col_sim, nu_sim, d_fluid_sim, pl_model (in
 * t0) and num_model from (sigma, rho_p/rho_f, v_sim, cg).  Used by derive and
 * by the Table VI test. */
void pl_mapping_pl_colloid(double sigma, double rho_ratio, double v_sim, const pl_mapping_cg_t *cg,
                           pl_mapping_t *m);

/* Dimensionless numbers and time scales of the real system (PL Table V). */
void pl_mapping_pl_real(const pl_mapping_system_t *real, const pl_mapping_solvent_t *solvent,
                        double velocity, int boundary, pl_mapping_pl_times_t *t,
                        pl_mapping_numbers_t *n);

/* Fills m->warn with the named warnings and notes (mapping_audit.c). */
void pl_mapping_audit(pl_mapping_t *m);

/* Fills rh_over_R, rh_over_R_se, rh_stick_over_R from d_col_sim,
 * cg.d_col_calibrated_se, nu_sim, cg.gamma, cg.boundary and sigma, and warns
 * HYDRODYNAMIC_RADIUS when |R_h/R - 1| - 2 SE > PL_RH_TOL (SE 0 for the
 * theory) (src/mapping/mapping_hydro.c). */
#define PL_RH_TOL 0.05
void pl_mapping_hydrodynamic_radius(pl_mapping_t *m);
/* Its line in the text report and its keys in a JSON object. */
void pl_mapping_hydro_print(const pl_mapping_t *m, FILE *out);
struct json_t;
void pl_mapping_hydro_json(const pl_mapping_t *m, struct json_t *o);

/* Appends a named warning or note (ignored beyond PL_MAP_MAX_WARN). */
void pl_mapping_warn(pl_mapping_t *m, int severity, const char *name, double value, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));

/* Number of warnings of severity PL_SEV_WARNING. */
int pl_mapping_nwarnings(const pl_mapping_t *m);

/* Debye-Hueckel: kappa = sqrt(2 N_A e^2 I / (eps_r eps0 kT)), I in mol/m^3. */
double pl_mapping_debye_kappa(double ionic_strength_molar, double eps_r, double kT);

/* ---- scene front end (sections physical{} and coarse_graining{}) ------- */
typedef struct {
    double radius;            /* m */
    double particle_density;  /* kg/m^3 */
    double solvent_density;   /* kg/m^3 */
    double temperature;       /* K */
    double viscosity;         /* kinematic, m^2/s */
    double gravity;           /* m/s^2, along -z */
    double hamaker;           /* J */
    double surface_potential; /* V */
    double kappa;             /* 1/m (0: from ionic_strength) */
    double ionic_strength;    /* mol/L */
    long long valence;        /* z of the (symmetric) electrolyte */
    double permittivity;      /* relative, eps_r (0: water at the temperature) */
    double primary_minimum;   /* l, m */
    double young_modulus;     /* E, Pa (Hertz constant with poisson_ratio) */
    double poisson_ratio;     /* nu_P */
    double hertz_constant;    /* K of Hecht Eq. 3, J/m^2.5 (instead of E, nu_P) */
    double volume_fraction;
    double box[3];            /* m; 0: box.cells as given */
    double flow_velocity;     /* m/s */
    double sound_speed;       /* m/s */
    double mean_free_path;    /* m */
    double self_diffusion;    /* m^2/s */
    /* the observers' lengths in SI (0: not given; src/mapping/mapping_observe.c) */
    double clusters_gap, rdf_rmax, steinhardt_rmax; /* m */
    double sq_qmax;           /* 1/m */
} pl_scene_physical_t;

typedef struct {
    int coupling;             /* PL_COUPLE_* (coupling_scene.h) */
    int time_match;           /* PL_MATCH_* */
    int boundary;             /* PL_BOUNDARY_* */
    int enskog, fluid_gravity, strict;
    double cell_size;         /* a0/R; 0: coupling default */
    double particles_per_cell;
    double mean_free_path;    /* lambda/a0 */
    double srd_dt, md_dt;     /* s; 0: derived */
    double md_resolution;
    double hertz_K;           /* model Hertz constant, kT/a0^2.5; 0: from the material */
    double reach_energy;      /* kT: the MD step resolves the gaps a pair reaches with this energy */
    int multiple_time_stepping; /* derive colloids.slow_gap and slow_interval (r-RESPA) */
} pl_scene_cg_t;

/* Colloid parameters in simulation units, for the colloid module. */
typedef struct {
    double radius, mass, gravity;  /* a0, m_f, a0/t0^2 */
    double hamaker;                /* kT (A_H / kT_real, Hecht Sec. VII.B) */
    double coulomb;                /* kT/a0: prefactor of Hecht Eq. 1 */
    double kappa;                  /* 1/a0 */
    double primary_minimum;        /* a0 */
    double md_dt;                  /* t0 */
    long long md_substeps;
    long long n_colloids;          /* from volume_fraction and the box */
    /* physical{} -> colloids{}, dlvo{}, hertz{}, lubrication{}, coupling{}
     * (src/mapping/mapping_colloids.c) */
    double phi_given, phi_realised;  /* volume fraction asked for / of the box used */
    /* the hard core the colloid-colloid repulsion realises (potential
     * coupling: sigma_cc / 2 of PL Eq. 16; 0: not computed) and the volume
     * fraction phi_c of the colloids counted with it (mapping_potential.c) */
    double core_radius, phi_core;
    double mass_density;           /* m_f / a0^3 */
    double inertia;                /* 2/5 M R^2, m_f a0^2 */
    double hertz_K;                /* kT / a0^2.5 */
    size_t hertz_off;              /* the input key hertz_K comes from (a scene offset) and its name */
    const char *hertz_key;
    double lub_viscosity;          /* m_f / (a0 t0) */
    double contact_time;           /* pi sqrt(m_red / U''_max), t0 */
    double reach_gap;              /* smallest gap the substeps resolve, a0 */
    char substeps_reason[480];     /* which criterion chose md_substeps */
    int nprov;                     /* provenance lines of the derived keys */
    char prov[32][480];
} pl_mapping_colloid_t;

typedef struct {
    int enabled;                   /* the scene has a physical{} section */
    int provisional;               /* PL_SCENE_PROVISIONAL: time-unit keys not compared with the file */
    /* a provisional pass's time-unit keys the file gives: where, the value
     * given and the value this pass's time unit derives (pl_scene_load_coupling_true
     * brackets them before a calibration runs) */
    int nheld;
    struct {
        size_t off;
        const char *key, *from;
        double given, derived;
    } held[4];
    pl_scene_physical_t physical;
    pl_scene_cg_t cg;
    double kappa;                  /* 1/m, given or Debye-Hueckel */
    pl_mapping_calibration_t calib; /* set by the loader before the mapping (d_inf 0: none) */
    pl_mapping_t map;              /* filled by pl_mapping_scene_apply */
    pl_mapping_colloid_t colloid;
} pl_scene_mapping_t;

/* Runs the mapping for a scene with a physical{} section and writes the
 * derived values into srd.dt, fluid.density, fluid.temperature, box.cells
 * and (pl_mapping_colloids_apply) the colloid sections, refusing those keys
 * if the file also sets them.  A no-op without the section.  Called by
 * pl_scene_validate. */
int pl_mapping_scene_apply(struct pl_scene *scene, pl_err_t *err);

/* Second half of the scene front end (src/mapping/mapping_colloids.c): derives
 * colloids{} (count from phi and the box used, radius, mass density, gravity,
 * substeps), dlvo{}, hertz.K, lubrication.viscosity and coupling.method from
 * physical{} + coarse_graining{}; refuses a derived key given in the file
 * (naming it and the physical keys it comes from) and a pair term without
 * its material constants. */
int pl_mapping_colloids_apply(struct pl_scene *scene, pl_err_t *err);
/* The observers' length keys of a physical scene (src/mapping/mapping_observe.c):
 * physical.clusters_gap, rdf_rmax, steinhardt_rmax (m) and sq_qmax (1/m)
 * become observe.<same> in a0 (1/a0); a different observe value given beside
 * one is refused; with the gap cluster observer on and no gap given,
 * observe.clusters_gap is derived from the pair potential
 * (pl_mapping_bond_gap).  Each choice is a provenance line (params,
 * summary.json mapping.derived_keys).  After pl_mapping_colloids_apply. */
int pl_mapping_observe_apply(struct pl_scene *scene, pl_err_t *err);
/* The bond gap of the scene's colloid pair potential (a0, colloids of the
 * scene's radius R): the largest surface gap h in (0, cut-off) at which the
 * conservative pair energy U(2R + h) <= -e_bond (kT_ref), so that a pair
 * closer than that is bound by more than e_bond, in the primary minimum or,
 * where it is that deep, the secondary one.  Scanned in steps of 1e-3 R
 * from the cut-off inwards, then bisected to 1e-9 R.  *h gets -1 when U
 * never reaches -e_bond beyond contact; a pair set-up error is returned. */
int pl_mapping_bond_gap(const struct pl_scene *scene, double e_bond, double *h, pl_err_t *err);
/* A provenance line of a derived key (pl_mapping_colloid_t.prov). */
void pl_mapping_prov(pl_mapping_colloid_t *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Warnings (IMPLAUSIBLE) for physical{} values outside the plausible range
 * of a liquid suspension, each naming the likely unit mistake
 * (src/mapping/mapping_plausible.c). */
void pl_mapping_plausible(const struct pl_scene *scene, pl_mapping_t *m);
/* SETTLING_UNRESOLVED when a physical scene's sedimentation observer cannot
 * resolve the settling velocity over the run (src/mapping/mapping_sediment.c). */
void pl_mapping_sediment_audit(const struct pl_scene *scene, pl_mapping_t *m);
/* The key at fault for a derived value out of range: the first of the
 * physical{} keys at `offs` (the inputs the value comes from) that the file
 * gives outside its plausible range, its offset in *off and in `why` its
 * value and range ("V UNIT, outside the plausible LO..HI UNIT, gives: ", to
 * lead the message); NULL and why = "": none (the caller blames its own
 * key).  A value off by orders of magnitude is the likely cause, not the
 * other inputs it meets. */
const char *pl_mapping_blame(const struct pl_scene *scene, const size_t *offs, size_t n, size_t *off, char *why,
                             size_t nwhy);
/* The colloid diffusion the mapping matched (src/mapping/mapping_diffusion.c):
 * d_col_box from the scene's box (after the mapping set box.cells), and
 * its lines in the text report and its object in the JSON one. */
void pl_mapping_diffusion_box(struct pl_scene *scene);
/* c of D(phi) = D0 (1 - c phi) for the scene's finite colloids: 1.1795 for slip
 * spheres (PL Sec. VI.C, ref. 90: the potential coupling, coupling I's slip
 * rule), 1.8315 for stick spheres (Batchelor 1976: coupling I's stick rules);
 * 0 for coupling II's points (and no coupling). */
double pl_mapping_concentration_c(const struct pl_scene *scene);
void pl_mapping_diffusion_print(const pl_mapping_t *m, FILE *out);
struct json_t *pl_mapping_diffusion_json(const pl_mapping_t *m);
/* Where the colloid D came from, for every output (params, the run's log,
 * summary.json "calibration"): one line without a newline into buf, or the
 * object {"mode", "source", "relative_error", ...}; both empty / NULL when
 * the scene was loaded without a calibration decision (source NONE). */
void pl_mapping_calibration_line(const pl_mapping_t *m, char *buf, size_t n);
/* The relative error of t0 that the colloid D it is matched on carries: the
 * calibration's d_inf_se / d_inf, or the theory's stated error (NaN: not
 * known); 0 when t0 does not rest on a measured or theoretical colloid D
 * (kinematic matching, an SRD step given in seconds, Brownian dynamics'
 * exact Stokes D).  An SI value in a unit t0^p carries |p| times it. */
double pl_mapping_t0_relative_error(const pl_mapping_t *m);
struct json_t *pl_mapping_calibration_json(const pl_mapping_t *m);

/* The audit's warnings (not its notes) of a physical scene, one line each
 * ("peloid: warning: SCENE: NAME: text"); nothing for a model scene. */
void pl_mapping_warnings_print(const struct pl_scene *scene, FILE *out);

/* The potential coupling's MD step (PL Sec. III.A, VII): the contact time
 * pi sqrt(m_red / U''(r_1)) of a fluid particle (m_f = 1) meeting a colloid
 * of mass M through PL Eq. 17 (sigma_cf, eps_cf in kT) at the turning point
 * r_1 of the mean normal kinetic energy kT of the particles that hit a
 * surface; t0.  And the MD steps per SRD step of length dt that resolve it
 * by `resolution` steps (src/mapping/mapping_colloids.c). */
double pl_mapping_cf_contact_time(double sigma_cf, double eps_cf, double M);
long long pl_mapping_cf_substeps(double sigma_cf, double eps_cf, double M, double dt, double resolution);

/* The potential coupling's colloid hard core (src/mapping/mapping_potential.c,
 * PL Sec. III.C.1), after its derived keys: with the wca term in `pairs`
 * (PL_CT_* bits) the radius sigma_cc / 2 of PL Eq. 16 at PL's sigma_cc rule,
 * else R; sets colloid.core_radius and phi_core, warns HARD_CORE_PHI when
 * phi_c / phi leaves 1 +- PL_CORE_PHI_TOL; refuses the DLVO term beside the
 * wca term (PL_ERR_INPUT, naming the key that switched DLVO on). */
#define PL_CORE_PHI_TOL 0.10
int pl_mapping_potential_core(struct pl_scene *scene, unsigned pairs, pl_err_t *err);
/* Its line in the text report and its keys in a JSON object. */
void pl_mapping_core_print(const pl_mapping_colloid_t *c, FILE *out);
void pl_mapping_core_json(const pl_mapping_colloid_t *c, struct json_t *o);

/* Relative permittivity of water at T (K), Malmberg & Maryott 1956 fit,
 * valid 273.15-373.15 K (NaN outside). */
double pl_mapping_water_permittivity(double T);

/* Hertz constant K (J/m^2.5) of two equal elastic spheres of radius R:
 * V = K delta^{5/2} (Hecht Eq. 3) with K = (8/15) E* sqrt(R/2), E* = E / (2
 * (1 - nu_P^2)) (Hertz theory, Landau & Lifshitz Sec. 9). */
double pl_mapping_hertz_K(double E, double nu_p, double R);

/* ---- reports ----------------------------------------------------------- */
/* Readable report / one JSON object; `colloid` may be NULL. */
void pl_mapping_print_text(const pl_mapping_t *m, const pl_mapping_colloid_t *colloid, FILE *out);
struct json_t;
int pl_mapping_json(const pl_mapping_t *m, const pl_mapping_colloid_t *colloid, const char *where,
                    struct json_t **out, pl_err_t *err);

/* For `peloid params SCENE` and summary.json: when the scene has a
 * physical{} section, writes the mapping report (text or JSON) to `out`;
 * otherwise writes nothing (JSON: null).  With strict (or
 * coarse_graining.strict) any warning becomes PL_ERR_INPUT with the first
 * warning in err.  Returns 0 or PL_ERR_INPUT. */
int pl_mapping_report(const struct pl_scene *scene, FILE *out, int json, int strict, pl_err_t *err);

/* The mapping report as a jansson object (JSON null without physical{}). */
int pl_mapping_report_json(const struct pl_scene *scene, struct json_t **out, pl_err_t *err);

/* With strict (or coarse_graining.strict): the first audit warning as
 * PL_ERR_INPUT; else 0. */
int pl_mapping_report_strict(const struct pl_scene *scene, int strict, pl_err_t *err);

#endif
