/* --calibrate never|auto|always (src/app/main.c): how a physical scene gets the
 * colloid D its time unit is matched on, and the scene loader that applies
 * it.  auto: the shipped calibration or the cache, else a calibration run
 * (src/app/calibrate.c); always: a calibration run whatever is stored;
 * never: the coupling's theory, 1 / xi_sim (PL Eqs. 39-41, Hecht Eq. 28),
 * with the relative error below, marked in every output (params, the run's
 * log, summary.json "calibration", src/mapping/mapping_diffusion.c).
 *
 * The theory's error: each shipped calibration (calibration/calibration-KEY.json) measured
 * D_inf for a shipped scene whose theory D it replaces; the relative error
 * stated for a coupling is the root mean square of D_meas / D_theory - 1
 * over that coupling's rows of THEORY_ROWS, their range given beside it.
 * The theory is biased rather than noisy (coupling II's points move ~2x
 * faster than its friction says, the potential coupling ~14 % slower), so
 * the figure is a size of the error, not a standard error; a coupling with
 * no shipped row has none (NaN: "unknown").  tests/cli/calibrate_modes.sh
 * recomputes the rows from `peloid params --json` of the scenes named. */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <string.h>

#include "peloid/run.h"

/* D_meas / D_theory of the shipped calibrations (the file's key; a scene
 * that reads it) */
static const struct {
    int method;
    const char *key, *scene;
    double ratio;
} THEORY_ROWS[] = {
    {PL_COUPLE_HECHT2, "a4a3daaa6940db36", "scenes/sediment.cfg", 1.9359241},
    {PL_COUPLE_HECHT2, "d167f1e23f5b9f45", "scenes/quickstart.cfg", 2.0804166},
    {PL_COUPLE_HECHT1, "9aa595c8f7cdb515", "scenes/hecht_table1.cfg", 1.2726526},
    {PL_COUPLE_POTENTIAL, "8e44d09ea885fe0d", "scenes/pl_potential_physical.cfg", 0.86104972},
    {PL_COUPLE_POTENTIAL, "a20491e8dee69f67", "tests/calibration/pl_potential_settle.cfg", 0.87359489},
};

int pl_calibrate_shipped(int k, int *method, const char **key, const char **scene, double *ratio)
{
    if (k < 0 || k >= (int)(sizeof THEORY_ROWS / sizeof THEORY_ROWS[0])) return -1;
    *method = THEORY_ROWS[k].method;
    *key = THEORY_ROWS[k].key;
    *scene = THEORY_ROWS[k].scene;
    *ratio = THEORY_ROWS[k].ratio;
    return 0;
}

int pl_calibrate_mode_parse(const char *s, int *mode)
{
    for (int k = 0; s && k < PL_CALIBRATE_NMODES; ++k)
        if (!strcmp(s, pl_calibrate_mode_name(k))) {
            *mode = k;
            return 0;
        }
    return -1;
}

void pl_calibrate_theory(const pl_scene_t *sc, pl_mapping_calibration_t *cal)
{
    double sum = 0.0, lo = INFINITY, hi = -INFINITY;
    int n = 0;
    for (size_t k = 0; k < sizeof THEORY_ROWS / sizeof THEORY_ROWS[0]; ++k) {
        if (THEORY_ROWS[k].method != sc->coupling.method) continue;
        const double r = THEORY_ROWS[k].ratio;
        sum += (r - 1.0) * (r - 1.0);
        lo = fmin(lo, r);
        hi = fmax(hi, r);
        ++n;
    }
    cal->theory_files = n;
    cal->theory_error = n > 0 ? sqrt(sum / n) : NAN;
    cal->theory_lo = n > 0 ? lo : NAN;
    cal->theory_hi = n > 0 ? hi : NAN;
}

int pl_scene_load_coupling_true(const char *path, unsigned flags, const char *shipped_dir, int nthreads,
                                const pl_calibrate_opts_t *o, pl_scene_t *scene, pl_err_t *err)
{
    /* a first pass to plan the calibration (the time unit from theory), the
     * final one with the measured diffusion; without a calibration the
     * scene loads once more in full (derived keys compared) */
    int rc = pl_scene_load_flags(path, flags | PL_SCENE_PROVISIONAL, scene, err);
    if (rc || !scene->mapping.enabled) return rc;
    if (!pl_calibration_needed(scene)) return pl_scene_load_flags(path, flags, scene, err);
    pl_mapping_calibration_t cal;
    memset(&cal, 0, sizeof cal);
    if (o->mode != PL_CALIBRATE_NEVER &&
        (rc = pl_calibrate(scene, shipped_dir, nthreads > 0 ? nthreads : omp_get_max_threads(), o, &cal, err)))
        return rc;
    /* never, or stored with nothing stored (pl_calibrate left source NONE):
     * d_inf 0, the mapping keeps the theory's D, final */
    if (o->mode == PL_CALIBRATE_NEVER || cal.source == PL_CALSRC_NONE) {
        memset(&cal, 0, sizeof cal);
        cal.mode = o->mode;
        cal.source = PL_CALSRC_THEORY;
        cal.d_theory = scene->mapping.map.d_col_theory;
        pl_calibrate_theory(scene, &cal);
    }
    return pl_scene_load_calibrated(path, flags, &cal, scene, err);
}
