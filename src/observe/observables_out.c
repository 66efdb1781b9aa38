/* Shared writers of the observers' outputs (observables_out.h). */
#include "observables_out.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "peloid/blocking.h"
#include "peloid/h5.h"
#include "peloid/io.h"
#include "peloid/sim.h"

const double pl_obs_fractions[PL_OBS_NFRAC] = {0.125, 0.25, 0.5, 1.0};

int pl_obs_put(hid_t g, const char *name, hid_t type, int rank, const hsize_t *dims, const void *data,
               const char *unit)
{
    if (pl_h5_write(g, name, type, rank, dims, data)) return -1;
    if (!unit) return 0;
    hid_t ds = H5Dopen2(g, name, H5P_DEFAULT);
    if (ds < 0) return -1;
    int bad = pl_h5_attr_str(ds, "unit", unit);
    if (H5Dclose(ds) < 0) bad = -1;
    return bad;
}

int pl_obs_series(hid_t obs, const char *name, size_t n, const long long *step, double dt, const double *value,
                  const char *unit)
{
    hid_t g = pl_h5_group(obs, name);
    if (g < 0) return -1;
    double *t = malloc((n ? n : 1) * sizeof(double));
    int bad = !t;
    for (size_t k = 0; t && k < n; ++k) t[k] = (double)step[k] * dt;
    hsize_t dims[1] = {n};
    bad |= pl_obs_put(g, "step", H5T_NATIVE_LLONG, 1, dims, step, NULL) != 0;
    bad |= t && pl_obs_put(g, "time", H5T_NATIVE_DOUBLE, 1, dims, t, "t0") != 0;
    bad |= pl_obs_put(g, "value", H5T_NATIVE_DOUBLE, 1, dims, value, unit) != 0;
    free(t);
    if (H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
}

void pl_obs_error_time(pl_json_t *b, json_t *e, const pl_obs_point_t pts[PL_OBS_NFRAC], double value, double se,
                       int plateau, double target)
{
    json_t *arr = json_array();
    for (int k = 0; k < PL_OBS_NFRAC; ++k) {
        const pl_obs_point_t *p = &pts[k];
        if (!p->valid) continue;
        json_t *q = json_object();
        pl_json_real(b, q, "run_fraction", pl_obs_fractions[k]);
        pl_json_int(b, q, "step", p->step);
        pl_json_real(b, q, "wall_s", p->wall_s);
        pl_json_real(b, q, "value", p->value);
        pl_json_real(b, q, "stderr", p->se);
        json_array_append_new(arr, q);
    }
    pl_json_set(b, e, "se_vs_time", arr);
    const pl_obs_point_t *last = &pts[PL_OBS_NFRAC - 1];
    if (last->valid && fabs(value) > 0 && se > 0) {
        pl_json_real(b, e, "target_rel_error", target);
        pl_json_real(b, e, "wall_s_for_target", pl_blocking_time_for_se(se, last->wall_s, target * fabs(value)));
        pl_json_set(b, e, "extrapolation_reliable", json_boolean(plateau));
    }
}

int pl_obs_h5_commit(hid_t f, int bad, const char *tmp, const char *path, const char *what, pl_err_t *err)
{
    if (bad) {
        char why[256];
        pl_h5_error_text(why, sizeof why);
        H5Fclose(f);
        remove(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: writing the %s failed: %s", tmp, what, why);
    }
    if (H5Fclose(f) < 0) {
        remove(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: closing the observables file failed", tmp);
    }
    return pl_atomic_commit(tmp, path, err);
}

json_t *pl_obs_summary_section(pl_json_t *b, json_t *doc, const struct pl_sim *sim, long long first)
{
    json_t *all = json_object_get(doc, "observables");
    if (all) return all;
    all = json_object();
    pl_json_set(b, doc, "observables", all);
    if (b->failed) return NULL;
    pl_json_int(b, all, "first_step", first);
    pl_json_int(b, all, "last_step", sim->step); /* < the scene's last step when the stopping rule ended the run */
    const char *afresh;
    const int resumed = pl_sim_observers_resumed(sim, &afresh);
    if (resumed >= 0) { /* a restarted run: resumed from the checkpoint or afresh, and why */
        pl_json_set(b, all, "resumed", json_boolean(resumed));
        if (!resumed) pl_json_str(b, all, "reason", afresh);
    }
    return all;
}
