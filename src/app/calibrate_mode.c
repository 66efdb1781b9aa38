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
 * faster than its friction says, the potential coupling ~14 % slower at
 * sigma_cf = 2 a0: its friction there, as a pinned sphere's drag shows too,
 * falling to the theory's by sigma_cf = 3-6 a0; validation/REPORT.md), so
 * the figure is a size of the error, not a standard error; a coupling with
 * no shipped row has none (NaN: "unknown").  tests/cli/calibrate_modes.sh
 * recomputes the rows from `peloid params --json` of the scenes named. */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
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

/* Before a calibration: the time-unit keys the file gives (colloids.substeps,
 * min_substeps, slow_interval, gravity: MD step counts and g t0^2 / a0) are
 * compared in the calibrated pass, which needs the measured D; a value that
 * no D from BRACKET[0] to BRACKET[1] times the coupling's theory derives is
 * refused now, before the wait (the shipped calibrations measured 0.86 to
 * 2.08 times theirs, THEORY_ROWS; the coarse coupling II suspension of
 * tests/support/calibration_coarse_ii.inc 4.8: the bracket catches a unit
 * slip or a stray digit, not a fine mismatch).  Its two provisional passes
 * give the derived values at its ends (each key's is monotonic in t0); a
 * pass that fails there (a check that the extreme t0 trips) leaves the
 * comparison to the calibrated pass, as before. */
static const double BRACKET[2] = {0.1, 10.0};

static int bracket_held(const char *path, unsigned flags, const pl_scene_t *scene, pl_err_t *err)
{
    const pl_scene_mapping_t *mp = &scene->mapping;
    if (mp->nheld == 0 || !(mp->map.d_col_theory > 0)) return 0;
    pl_scene_t *b = malloc(2 * sizeof *b);
    if (!b) return 0; /* an early answer only: the calibrated pass compares anyway */
    int ends = 0;
    for (int e = 0; e < 2; ++e) {
        pl_mapping_calibration_t cal;
        memset(&cal, 0, sizeof cal);
        cal.d_theory = mp->map.d_col_theory;
        cal.d_inf = BRACKET[e] * mp->map.d_col_theory;
        pl_err_t ignored;
        memset(&ignored, 0, sizeof ignored);
        ends += !pl_scene_load_calibrated(path, flags | PL_SCENE_PROVISIONAL, &cal, b + e, &ignored) &&
                b[e].mapping.nheld == mp->nheld;
    }
    int rc = 0;
    for (int k = 0; ends == 2 && k < mp->nheld && !rc; ++k) {
        const double d0 = b[0].mapping.held[k].derived, d1 = b[1].mapping.held[k].derived;
        const double lo = fmin(d0, d1), hi = fmax(d0, d1), g = mp->held[k].given;
        if (g >= lo - 1e-9 * fabs(lo) && g <= hi + 1e-9 * fabs(hi)) continue;
        char range[160];
        if (hi - lo <= 1e-9 * fabs(hi)) snprintf(range, sizeof range, "value %.6g here, whatever D it measures", lo);
        else snprintf(range, sizeof range, "between %.6g and %.6g for any D from %g to %g times the coupling's "
                      "theory", lo, hi, BRACKET[0], BRACKET[1]);
        rc = pl_scene_fail(scene, err, mp->held[k].off, mp->held[k].key,
                           "%.6g is derived from %s and the time unit the calibration sets from the measured colloid "
                           "D (%s); remove it (a scene with physical{} gives the real suspension once), or give "
                           "--calibrate never to compare it with the theory's value",
                           g, mp->held[k].from, range);
    }
    free(b);
    return rc;
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
    if (o->mode != PL_CALIBRATE_NEVER && (rc = bracket_held(path, flags, scene, err))) return rc;
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
