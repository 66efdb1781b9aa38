/* Scene struct of the colloid-solvent coupling (section `coupling`; schema in
 * src/scene/scene_keys_coupling.c).  Included by scene.h; plain data only. */
#ifndef PELOID_COUPLING_SCENE_H
#define PELOID_COUPLING_SCENE_H

#include "peloid/kernel_enums.h"

/* PL_COUPLE_HECHT1: fluid particles reflected off colloid surfaces (Hecht
 * Sec. IV); PL_COUPLE_HECHT2: colloids join the SRD collision of their cell
 * (Hecht Sec. V); PL_COUPLE_POTENTIAL: WCA colloid-fluid forces integrated at
 * the MD step for the fluid near colloids (PL Sec. III.A, Eq. 17). */
enum { PL_COUPLE_NONE = 0, PL_COUPLE_HECHT1 = 1, PL_COUPLE_HECHT2 = 2, PL_COUPLE_POTENTIAL = 3 };
/* The one coupling enum: coupling.method of a model scene and
 * coarse_graining.coupling of a physical one (values PL_COUPLE_HECHT1..)
 * both hold it.  Its names there: */
static inline const char *pl_couple_model_name(int m)
{
    return m == PL_COUPLE_HECHT1 ? "hecht1" : m == PL_COUPLE_HECHT2 ? "hecht2" : m == PL_COUPLE_POTENTIAL ? "potential" : "none";
}
static inline const char *pl_couple_physical_name(int m)
{
    return m == PL_COUPLE_HECHT1 ? "I" : m == PL_COUPLE_HECHT2 ? "II" : m == PL_COUPLE_POTENTIAL ? "potential" : "none";
}
/* PL_BOUND_* (surface rule) and PL_PLACE_* (placement) of coupling I: in
 * kernel_enums.h, shared with kernels/coupling_reflect.c.  The surface
 * rules' names (coupling.boundary), indexed by PL_BOUND_*, NULL-terminated: */
extern const char *const pl_coupling_boundary_names[];

typedef struct {
    int method;            /* PL_COUPLE_* */
    int boundary;          /* PL_BOUND_* */
    int placement;         /* PL_PLACE_* */
    long long max_reflections; /* N_max of Hecht Sec. IV */
    double wall_temperature;   /* kT of the thermal surface (0: thermostat / fluid kT) */
    int compensate_gravity;    /* Hecht Sec. VIII.A (iii) in periodic boxes */
    long long drift_interval;  /* collision steps between centre-of-mass drift removals */
    int pinned;                /* colloids held fixed; their impulse is measured (drag) */
    double flow_velocity[3];   /* pinned: fluid mean velocity held at this value */
    double sigma_cf, epsilon_cf; /* PL Eq. 17 (sigma_cf 0: colloids.radius) */
    double max_settling_energy;  /* hecht2 + gravity: bound on M v_s^2 / kT (0: off) */
    /* pinned, coupling I: angular velocity held at this value (torque); the
     * last member: the calibration key hashes the members before it */
    double pinned_spin[3];
} pl_scene_coupling_t;

#endif
