/* Colloids: state (structure of arrays, 64-byte aligned), set-up from the
 * scene, MD / BD steps with stability guards, energies, H5MD trajectories.
 * Kernels: colloid_kernels.h; pair formulas: colloid_pair.h. */
#ifndef PELOID_COLLOID_H
#define PELOID_COLLOID_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/colloid_reach.h"
#include "peloid/colloid_kernels.h"
#include "peloid/depletion.h"
#include "peloid/error.h"
#include "peloid/scene.h"

/* What the DLVO set-up derived (reported at start; gaps h = r - d in a0). */
typedef struct {
    double C, kappa, A;        /* Eq. 1 prefactor (kT/a0), kappa (1/a0), A_H (kT) */
    double d_ref;              /* reference contact distance 2R */
    double hm, h0, curvature;  /* parabola: match gap, minimum gap, c (kT/a0^2) */
    double barrier_h, barrier_u;   /* primary maximum (NAN if none) */
    double secmin_h, secmin_u;     /* secondary minimum (NAN if none) */
    double hcut, trunc_u, trunc_f; /* cut-off gap, |V| and |F| cut off there */
    /* on a set-up error: the dlvo{} key it is blamed on (scene offset, name) */
    size_t fail_off;
    const char *fail_key;
} pl_colloid_dlvo_info_t;

/* Colloid-colloid diameter and spurious depletion (PL Sec. III.C.1),
 * reported at start and in summary.json. */
typedef struct {
    int rule;         /* PL_SIGMA_* of wca.sigma_rule */
    double sigma_cc;  /* sigma of PL Eq. 16 (0: R_i + R_j per pair) */
    double d_match;   /* twice the colloid-fluid cut-off 2^{1/6} sigma_cf */
    double phi_sigma; /* Phi_depl(sigma_cc) in kT (sigma_cc 0: at 2R); 0 unless the
                       * potential coupling acts with fluid */
    double phi_match; /* phi_cc(d_match) in kT_ref */
    int table_n;      /* intervals of the depletion_comp table (0: term off) */
} pl_colloid_depl_info_t;

/* Adaptive substeps: a collision step whose contact comes within this
 * factor of colloids.min_contact_steps runs the rest at colloids.substeps
 * (src/colloid/colloid_step.c). */
#define PL_ADAPT_REFINE 1.25

/* Nodes of the depletion_comp table over [0, d_match]: interpolation error
 * ~1e-5 kT (cubic Hermite, checked in tests/physics/test_depletion.c). */
#define PL_COLLOID_DEPL_TABLE 256

/* Names of the energy terms PL_CE_* (thermo columns), in enum order. */
extern const char *const pl_colloid_energy_names[PL_CE_NTERMS];

typedef struct {
    double kin_trans, kin_rot;
    double pot[PL_CE_NTERMS]; /* PL_CE_DLVO, _HERTZ, _WCA, _WALL, _GRAVITY, _DEPL */
    double total;
} pl_colloid_energy_t;

typedef struct pl_colloid {
    size_t n;
    int nthreads; /* threads of the colloid kernels (results do not depend on it) */
    /* checkpointable state */
    double *x, *y, *z, *vx, *vy, *vz, *wx, *wy, *wz, *q0, *q1, *q2, *q3;
    int32_t *ix, *iy, *iz; /* periodic images crossed */
    double *rad, *mass, *inertia;
    long long md_step;
    double e0;             /* energy at the start (drift guard) */
    /* forces and torques carry over between steps (velocity Verlet's second
     * half kick, Brownian step): checkpointed too (src/colloid/checkpoint_colloid.c) */
    double *fx, *fy, *fz, *tx, *ty, *tz;
    /* per-step scratch, rebuilt by the next force evaluation */
    double *zu, *epot;
    double *g_overlap, *g_omega2, *g_damp;
    int32_t *g_partner;
    pl_colloid_cells_t cells;
    pl_colloid_nlist_t nlist; /* rebuilt when the skin is used up */
    /* multiple time stepping (slow_interval > 1): the near list (built with
     * nlist) and the slow forces, functions of the positions at the end of
     * the last outer step, recomputed bitwise at a restart (not stored) */
    int slow_interval;
    int slow_phase; /* MD steps done of the current outer step */
    pl_colloid_nlist_t near;
    double *fsx, *fsy, *fsz;
    /* parameters derived from the scene */
    pl_colloid_pair_params_t pair;
    pl_colloid_ext_params_t ext;
    pl_colloid_dlvo_info_t dlvo;
    pl_colloid_depl_info_t depl;
    double *dep_table;     /* 2 x (table_n + 2): Phi_comp values, then slopes */
    double box[3];
    int periodic[3];
    int integrator, substeps;
    double dt, kT, bd_eta;
    uint64_t seed;
    double max_overlap, min_contact_steps, max_energy_drift;
    long long guard_interval;
    int nve; /* no dissipation: the energy-drift guard applies */
    /* adaptive substeps (colloids.adaptive_substeps, src/colloid/colloid_adaptive.c):
     * each collision step's MD steps, sub_min .. substeps, chosen from the
     * state at its start (no state of their own); dt is set per step */
    int adaptive, sub_min;
    double dt_coll, adapt_margin, adapt_mred;
    pl_colloid_reach_t reach;
    long long adapt_steps, adapt_md, adapt_lo, adapt_hi; /* diagnostics (summary.json) */
    double adapt_worst; /* fewest MD steps per collision time met (contact guard's measure) */
    double adapt_last;  /* the same, of the last MD step */
    long long adapt_refined; /* collision steps finished at the finest MD step */
} pl_colloid_t;

/* Pair-term mask from the colloids.pairs list; on an unknown name returns
 * PL_ERR_INPUT and copies the name into bad. */
int pl_colloid_parse_pairs(const char *list, unsigned *mask, char *bad, size_t nbad);
/* The pair-term names of that table, ", " separated (for messages). */
void pl_colloid_pair_names(char *buf, size_t n);

/* Converts the dlvo section (physical units) to simulation units, fits the
 * parabolic primary minimum for contact distance d_ref and chooses the cut-off
 * from the potential's decay (src/colloid/colloid_params.c). */
int pl_colloid_dlvo_setup(const pl_scene_dlvo_t *s, double d_ref, pl_colloid_pair_params_t *p,
                          pl_colloid_dlvo_info_t *info, pl_err_t *err);

/* The colloid-fluid potential of the scene's coupling (coupling.sigma_cf,
 * 0: colloids.radius; epsilon_cf; PL Eq. 17) with the fluid density and the
 * run's kT (thermostat target, else fluid temperature): the input of the
 * depletion potential and of PL's sigma_cc rule. */
void pl_colloid_depletion_params(const pl_scene_t *scene, pl_depletion_params_t *dp);

/* The set-up of each row of the pair-term table (PL_PAIR_TERMS,
 * colloid_kernels.h): the term's parameters from the scene, called for every
 * row in row order whether or not colloids.pairs switches it on (a row may
 * set what another row or the scene report reads; a row reads its own bit in
 * p->terms).  A failure is blamed on the scene key it names. */
#define PL_TERM_SETUP_DECL_(ID, id, name, slot, kind)                                    \
    int pl_colloid_term_setup_##id(const pl_scene_t *scene, pl_colloid_pair_params_t *p, \
                                   pl_colloid_dlvo_info_t *info, pl_err_t *err);
PL_PAIR_TERMS(PL_TERM_SETUP_DECL_)
#undef PL_TERM_SETUP_DECL_

/* Pair parameters of every term from the scene (no state needed; the
 * depletion_comp table itself is built by pl_colloid_setup). */
int pl_colloid_pair_params(const pl_scene_t *scene, pl_colloid_pair_params_t *p,
                           pl_colloid_dlvo_info_t *info, pl_err_t *err);
/* The one pair cut-off (centre distance) of the terms in p for colloids of
 * radius up to rmax: the largest row cut-off (pl_colloid_pair_rc) at
 * contact distance 2 rmax; the neighbour list and the minimum-image check
 * use it. */
double pl_colloid_pair_cutoff(const pl_colloid_pair_params_t *p, double rmax);

/* State from a validated scene: radii, masses, positions (lattice / random /
 * file), velocities, forces at t = 0.  An initial overlap beyond
 * colloids.max_overlap is PL_ERR_INPUT. */
int pl_colloid_create(const pl_scene_t *scene, int nthreads, pl_colloid_t **out, pl_err_t *err);
void pl_colloid_free(pl_colloid_t *c);
/* The colloids' port for a component that exchanges energy with them (a
 * coupling): their energy is no longer conserved, so the NVE drift guard
 * is off (src/colloid/colloid_state.c). */
void pl_colloid_exchange_energy(pl_colloid_t *c);

/* colloids.init_file read strictly into c's positions (and radii, from a
 * fourth column) for pl_colloid_create (src/colloid/colloid_init_file.c has
 * the rules); c allocated for colloids.count with box, periodic and the
 * scene's radii set.  Any malformed, missing, extra or out-of-range value
 * is PL_ERR_INPUT "FILE:LINE: column N (name): value 'TOKEN': allowed: ...". */
int pl_colloid_read_init_file(const pl_scene_t *scene, pl_colloid_t *c, pl_err_t *err);
/* The smallest radius a colloid of the scene can have: colloids.radius
 * (1 - sqrt(3) colloids.polydispersity), or with init = "file" the least
 * radius the file may give (src/colloid/colloid_init_file.c). */
double pl_colloid_radius_min(const pl_scene_t *scene);

/* Two initial colloids closer than (1 - colloids.max_overlap)(R_i + R_j)
 * found in O(N log N) (cubes of edge 2 (1 - max_overlap) R_min / sqrt 3):
 * PL_ERR_INPUT (pl_colloid_overlap_fail).  Run before the neighbour list, whose
 * cost it bounds to O(N) (src/colloid/colloid_overlap.c). */
int pl_colloid_overlap_screen(const pl_colloid_t *c, const pl_scene_t *scene, pl_err_t *err);
/* An overlapping initial configuration: the error line, "initial colloids
 * I and J overlap by F ..." (`what`), blamed on the key that set the
 * colloids: physical.volume_fraction in a physical{} scene not read from a
 * file (it gives the count), else colloids.init if the file gives it, else
 * colloids.count. */
int pl_colloid_overlap_fail(const pl_scene_t *scene, pl_err_t *err, const char *what);

/* Allocation only (n colloids, zeroed; unit quaternions); for tests that set
 * positions by hand, followed by pl_colloid_setup().  nthreads: the thread
 * count of the colloid kernels from then on (pl_colloid_create too). */
int pl_colloid_alloc(size_t n, int nthreads, pl_colloid_t **out, pl_err_t *err);
/* Derives parameters from the scene, builds cells, computes the forces. */
int pl_colloid_setup(pl_colloid_t *c, const pl_scene_t *scene, pl_err_t *err);
/* Its parts on the pair terms (src/colloid/colloid_pair_setup.c), on c with
 * its pair parameters set: c->depl (sigma_cc) and, with depletion_comp, the
 * compensation table (PL Sec. III.C.1); multiple time stepping
 * (colloids.slow_interval; reads the radii, masses, integrator, dt and
 * min_contact_steps of c): c->slow_interval and the force split, or
 * PL_ERR_INPUT where the scene cannot use it. */
int pl_colloid_depletion_setup(pl_colloid_t *c, const pl_scene_t *scene, pl_err_t *err);
int pl_colloid_mts_setup(pl_colloid_t *c, const pl_scene_t *scene, pl_err_t *err);
/* The largest stiffness |d(w F)/dr| of the slow share w F of the DLVO force
 * (Hecht Eqs. 1-2) of a pair of contact distance d split at colloids.slow_gap
 * = hin, over the gaps from hin to the DLVO cut-off, and (*h_at) the gap where
 * it is met (untouched when the share is nil): what the outer step of multiple
 * time stepping must resolve (pl_colloid_mts_setup; the mapping's derived
 * slow_interval, coarse_graining.multiple_time_stepping). */
double pl_colloid_slow_stiffness(const pl_colloid_pair_params_t *p, double d, double hin, double *h_at);
/* Adaptive substeps (colloids.adaptive_substeps): checks what they need and
 * builds the reach table (reads the pair parameters, radii, masses, integrator,
 * substeps, slow_interval of c); c->adaptive = 0 when off. */
int pl_colloid_adaptive_setup(pl_colloid_t *c, const pl_scene_t *scene, pl_err_t *err);
void pl_colloid_adaptive_free(pl_colloid_t *c);
/* The MD steps of the collision step starting now (c->adaptive), from the
 * positions and velocities and the neighbour list of c. */
int pl_colloid_adaptive_substeps(pl_colloid_t *c);
/* The choice itself from the reach maxima em, v2 (pl_colloid_reach_energy):
 * a pure function of them and c's parameters (no counters). */
int pl_colloid_adaptive_choose(const pl_colloid_t *c, double em, double v2);
/* Linked cells and neighbour list for pair cut-off rc (a0) with a skin of
 * skin_fraction rc (capped so that rc + skin <= L/2 on periodic axes); the
 * next pl_colloid_forces builds the list.  Called by pl_colloid_setup. */
int pl_colloid_neighbors_init(pl_colloid_t *c, double rc, double skin_fraction, pl_err_t *err);
/* Pair and external forces and torques of the present positions (the
 * neighbour list rebuilt first when a colloid has moved by more than half
 * the skin since its build); the external-force energy rows of epot.
 * The positions are taken as those after c->md_step MD steps: that count
 * keys the lubrication noise (lubrication.thermal), so a caller that
 * integrates counts the step before its end-of-step forces (as
 * the MD region does, kernels/colloid_md_region.c).
 * PL_ERR_NOMEM when a grown neighbour list cannot be allocated. */
int pl_colloid_forces(pl_colloid_t *c, pl_err_t *err);

/* Slot arrays of a neighbour list for at least need pairs (PL_ERR_NOMEM). */
int pl_colloid_nlist_reserve(pl_colloid_nlist_t *nl, size_t need, pl_err_t *err);
/* The MD region's view of c (kernels/colloid_md_region.c; v: its storage). */
void pl_colloid_md_region_of(pl_colloid_t *c, pl_colloid_md_region_t *r, pl_colloid_view_t *v);
/* n velocity-Verlet MD steps of c->dt in one parallel region
 * (src/colloid/colloid_md.c), each followed by the guards; n = 0: the MD
 * steps of a collision step with adaptive substeps, their count and dt chosen
 * in the region (pl_colloid_adaptive_choose), the rest possibly finished at
 * the finest MD step (pl_colloid_advance). */
int pl_colloid_verlet_run(pl_colloid_t *c, int n, pl_err_t *err);
/* n Brownian steps (colloids.integrator = "brownian") in one parallel region
 * (pl_colloid_bd_region): each the move, the forces and the guards. */
int pl_colloid_bd_run(pl_colloid_t *c, int n, pl_err_t *err);
/* One MD step (velocity Verlet + quaternions, or BD), then the guards. */
int pl_colloid_md_step(pl_colloid_t *c, pl_err_t *err);
/* The plan stage: colloids.substeps MD steps of one collision step. */
int pl_colloid_advance(pl_colloid_t *c, long long collision_step, pl_err_t *err);

/* Guards on the state after the force evaluation of MD step c->md_step
 * (src/colloid/colloid_guard.c).  PL_ERR_GUARD with the message on failure. */
int pl_colloid_guard(pl_colloid_t *c, int check_energy, pl_err_t *err);
/* The same guards, their per-colloid tests and maxima already computed (by
 * the fused MD step). */
int pl_colloid_guard_max(pl_colloid_t *c, const pl_colloid_guard_max_t *g, int check_energy,
                         pl_err_t *err);
/* Does a bound trip on these maxima at MD step dt?  (What pl_colloid_guard_max
 * reports then; a pure function of c's parameters, g and dt.) */
int pl_colloid_guard_trips(const pl_colloid_t *c, double dt, const pl_colloid_guard_max_t *g);

/* Kinetic + potential energy terms of the current state (fixed-order sums);
 * evaluates the pair energies (into epot) for the positions of the last
 * force evaluation. */
void pl_colloid_energy(pl_colloid_t *c, pl_colloid_energy_t *e);
/* Total linear momentum and angular momentum about the origin (unwrapped). */
void pl_colloid_momentum(const pl_colloid_t *c, double p[3], double l[3]);

/* H5MD trajectory (src/io/colloid_h5md.c): written to path.tmp, renamed on
 * close; with xyz_path, an extended-XYZ twin (src/io/colloid_xyz.c). */
typedef struct pl_colloid_traj pl_colloid_traj_t;
typedef struct {
    double a0_m, t0_s, m_f_kg; /* all > 0: physical scene, written in nm, ps, kg */
    /* physical scene: kg per model mass unit of the written (kinetic) masses,
     * kT_real / (kT_model (a0/t0)^2), so that 1/2 m v^2 of the written
     * velocities gives the scene's temperature */
    double mass_kg;
    double frame_dt;           /* nominal time between frames, t0 */
    const char *xyz_path;      /* colloids.xyz beside, or NULL */
    int overwrite;             /* replace an existing file */
    int resume;                /* resume in place: continue the existing file (and
                                * colloids.xyz) with its frames of steps < keep_before */
    long long keep_before;
} pl_colloid_traj_params_t;
int pl_colloid_traj_open(const char *path, const pl_colloid_t *c, const pl_colloid_traj_params_t *p,
                         pl_colloid_traj_t **out, pl_err_t *err);
/* Appends the frame of `step` (time in t0), unless the last frame is of that
 * step already. */
int pl_colloid_traj_write(pl_colloid_traj_t *t, const pl_colloid_t *c, long long step, double time,
                          pl_err_t *err);
/* Keeps a copy of the state (the start of a step that may trip a guard);
 * pl_colloid_traj_write_held appends it (c: the radii), unless written. */
void pl_colloid_traj_hold(pl_colloid_traj_t *t, const pl_colloid_t *c, long long step, double time);
int pl_colloid_traj_write_held(pl_colloid_traj_t *t, const pl_colloid_t *c, pl_err_t *err);
int pl_colloid_traj_close(pl_colloid_traj_t *t, pl_err_t *err);
/* The cluster id of each colloid with every frame from now on (H5MD
 * /particles/colloids/cluster_id/{step, time, value (T x N)}, a cluster_id
 * column of colloids.xyz): ids(ctx, step, compute) gives the ids of the
 * positions of `step` (computing them when `compute`; a held frame asks
 * without), NULL where there are none (written as -1).  0, or PL_ERR_IO. */
typedef const int32_t *(*pl_traj_ids_fn)(void *ctx, long long step, int compute);
int pl_colloid_traj_cluster_ids(pl_colloid_traj_t *t, pl_traj_ids_fn ids, void *ctx, pl_err_t *err);

#endif
