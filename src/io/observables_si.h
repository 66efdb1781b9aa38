/* The SI side of the observers' outputs for a scene with physical{}
 * (DESIGN.md "Units and mapping": outputs of physical scenes speak the real
 * system beside the model units).  Scheme: the model datasets and summary
 * values stay as they are; each one in a model unit gets an SI twin.
 *   observables.h5: dataset X with model `unit` U gets X_si = X * to_si,
 *     attributes `unit` (SI, variable-length string), `to_si` (the factor)
 *     and `model_unit` (U); /parameters holds a0_m, t0_s, m_f_kg, kT_J.
 *   summary.json "observables": an entry with `unit` gets `unit_si` and
 *     value_si, stderr_si, ... (each of its values in that unit, also in the
 *     se_vs_time points), and where the unit holds t0 and t0 rests on a
 *     calibrated (or theoretical) colloid D, stderr_mapping_si (the share
 *     of t0's relative error t0_rel, pl_mapping_t0_relative_error, which
 *     the caller passes: io calls nothing of the mapping) and
 *     stderr_total_si (both in quadrature); a key K_t0 (K_a0) gets K_s (K_m).
 * Model units map through a0, t0, m_f and the model energy kT_model = m_f
 * a0^2 / t0^2 (Hecht Sec. VII.B), so that stress, shear rate and viscosity
 * stay consistent (sigma = eta gamma_dot in Pa, Pa s, 1/s).  Private to the
 * library. */
#ifndef PELOID_OBSERVABLES_SI_H
#define PELOID_OBSERVABLES_SI_H

#include <hdf5.h>

#include "json_build.h"
#include "peloid/mapping.h"

/* The SI unit of model unit `model` and the factor SI = model * *to_si;
 * "1" and factor 1 for a dimensionless model unit ("1", "R", "1/R"); NULL
 * when `model` is not in the table (an SI unit such as "um" included). */
const char *pl_obs_si_unit(const char *model, const pl_mapping_t *m, double *to_si);

/* Adds the SI twins of every dataset under file's /observables that has a
 * model unit and lacks its twin, and /parameters (once); 0 or -1. */
int pl_obs_si_h5(hid_t file, const pl_mapping_t *m, double t0_rel);

/* Adds unit_si and the SI values to every entry with a unit in
 * summary.json's "observables" section `all` (recursively). */
void pl_obs_si_json(pl_json_t *b, json_t *all, const pl_mapping_t *m, double t0_rel);

#endif
