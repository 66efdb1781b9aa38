/* The stress observer's results (src/observe/stress_module.c): its
 * estimates (Green-Kubo, Couette), the stress groups it adds to
 * observables.h5 and its summary.json entries (PL Eqs. 9-15 beside them). */
#include <hdf5.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "json_build.h"
#include "observables_out.h"
#include "observables_si.h"
#include "peloid/h5.h"
#include "peloid/io.h"
#include "peloid/observer.h"
#include "peloid/collision_rule.h"
#include "peloid/outputs.h"
#include "peloid/real.h"
#include "peloid/srd_theory.h"
#include "stress_priv.h"

/* The estimate and SE of eta after what was sampled; 0 when there is none. */
int pl_stress_eta_estimate(const pl_stress_t *o, double *v, double *se, pl_blocking_result_t *res)
{
    if (o->eta.n < 2) return 0;
    pl_blocking_result_t r = pl_blocking_result(&o->eta);
    if (res) *res = r;
    *v = r.mean;
    *se = r.se;
    return isfinite(r.mean) && isfinite(r.se);
}

/* Couette: eta = <sigma> / <rate> and its SE; 0 when there is none. */
int pl_stress_couette_estimate(const pl_stress_t *o, double *v, double *se, pl_blocking_result_t *rs,
                            pl_blocking_result_t *rr)
{
    if (o->sigma.n < 2 || o->rate.n < 2) return 0;
    pl_blocking_result_t a = pl_blocking_result(&o->sigma), b = pl_blocking_result(&o->rate);
    if (rs) *rs = a;
    if (rr) *rr = b;
    *v = a.mean / b.mean;
    *se = fabs(*v) * hypot(a.se / a.mean, b.se / b.mean);
    return isfinite(*v) && isfinite(*se);
}

/* ---- outputs ----------------------------------------------------------- */

/* Copies src to dst byte for byte; 0 or -1. */
static int copy_file(const char *src, const char *dst)
{
    FILE *in = fopen(src, "rb"), *out = in ? fopen(dst, "wb") : NULL;
    int bad = !in || !out;
    char buf[1 << 16];
    size_t n;
    while (!bad && (n = fread(buf, 1, sizeof buf, in)) > 0) bad |= fwrite(buf, 1, n, out) != n;
    if (in) bad |= ferror(in) != 0, fclose(in);
    if (out && fclose(out)) bad = 1;
    return bad ? -1 : 0;
}

/* Adds the stress groups to observables.h5: to the file the observe module
 * wrote in this run's finish (it runs first, pl_modules), else to a new one
 * (never to a file left by an earlier run); atomically. */
static int write_h5(const pl_sim_t *sim, const pl_stress_t *o, const char *path, pl_err_t *err)
{
    char tmp[4200];
    pl_atomic_tmp(path, tmp, sizeof tmp);
    pl_h5_quiet();
    hid_t f;
    if (pl_observe_running(sim)) { /* the observe module wrote observables.h5 of this run just before */
        if (copy_file(path, tmp)) {
            remove(tmp);
            return pl_err_set(err, PL_ERR_IO, "%s: cannot copy the observables file", tmp);
        }
        f = H5Fopen(tmp, H5F_ACC_RDWR, H5P_DEFAULT);
    } else {
        f = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
        if (f >= 0 && pl_h5_h5md_header(f)) {
            H5Fclose(f);
            f = -1;
        }
    }
    if (f < 0) {
        remove(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot create the observables file", tmp);
    }
    hid_t obs = H5Lexists(f, "observables", H5P_DEFAULT) > 0 ? H5Gopen2(f, "observables", H5P_DEFAULT)
                                                             : pl_h5_group(f, "observables");
    int bad = obs < 0;
    const double dt = sim->scene.srd.dt;
    if (!bad && o->couette) {
        bad |= pl_obs_series(obs, "wall_shear_stress", o->ts_n, o->ts_step, dt, o->ts_sigma, "kT/a0^3") != 0;
        bad |= pl_obs_series(obs, "shear_rate", o->ts_n, o->ts_step, dt, o->ts_rate, "1/t0") != 0;
        static const char *const pname[2] = {"fluid_velocity_profile", "fluid_density_profile"};
        static const char *const punit[2] = {"a0/t0", "1/a0^3"};
        const size_t nl = (size_t)o->nlayers;
        double *buf = malloc((o->ts_n ? o->ts_n : 1) * nl * sizeof(double) + nl * sizeof(double));
        bad |= !buf;
        for (int p = 0; !bad && p < 2; ++p) {
            double *z = buf + o->ts_n * nl;
            for (size_t k = 0; k < o->ts_n; ++k) memcpy(buf + k * nl, o->ts_prof + (2 * k + (size_t)p) * nl, nl * sizeof(double));
            for (size_t k = 0; k < nl; ++k) z[k] = (double)k + 0.5;
            hid_t g = pl_h5_group(obs, pname[p]);
            bad |= g < 0;
            double *t = malloc((o->ts_n ? o->ts_n : 1) * sizeof(double));
            bad |= !t;
            for (size_t k = 0; t && k < o->ts_n; ++k) t[k] = (double)o->ts_step[k] * dt;
            hsize_t d1[1] = {o->ts_n}, d2[2] = {o->ts_n, nl}, dz[1] = {nl};
            if (!bad) {
                bad |= pl_obs_put(g, "step", H5T_NATIVE_LLONG, 1, d1, o->ts_step, NULL) != 0;
                bad |= pl_obs_put(g, "time", H5T_NATIVE_DOUBLE, 1, d1, t, "t0") != 0;
                bad |= pl_obs_put(g, "value", H5T_NATIVE_DOUBLE, 2, d2, buf, punit[p]) != 0;
                bad |= pl_obs_put(g, "z", H5T_NATIVE_DOUBLE, 1, dz, z, "a0") != 0;
                bad |= pl_h5_attr_str(g, "meaning", p ? "fluid particles per a0^3 in each 1 a0 layer of z, at the "
                                                        "sample" : "mean fluid velocity along the walls' relative "
                                                                   "velocity in each 1 a0 layer of z, at the sample") != 0;
            }
            free(t);
            if (g >= 0 && H5Gclose(g) < 0) bad = 1;
        }
        free(buf);
    }
    if (!bad && !o->couette) { /* the tensor, mean over each output window */
        hid_t g = pl_h5_group(obs, "fluid_stress");
        bad |= g < 0;
        double *t = malloc((o->ts_n ? o->ts_n : 1) * sizeof(double));
        bad |= !t;
        for (size_t k = 0; t && k < o->ts_n; ++k) t[k] = (double)o->ts_step[k] * dt;
        hsize_t d1[1] = {o->ts_n}, d3[3] = {o->ts_n, 3, 3};
        if (!bad) {
            bad |= pl_obs_put(g, "step", H5T_NATIVE_LLONG, 1, d1, o->ts_step, NULL) != 0;
            bad |= pl_obs_put(g, "time", H5T_NATIVE_DOUBLE, 1, d1, t, "t0") != 0;
            bad |= pl_obs_put(g, "value", H5T_NATIVE_DOUBLE, 3, d3, o->ts_val, "kT/a0^3") != 0;
            bad |= pl_h5_attr_str(g, "meaning", "pressure tensor P_ab (flux of a-momentum along b): kinetic + "
                                                "collisional, mean over the steps since the previous sample") != 0;
        }
        free(t);
        if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    }
    if (!bad && o->ncorr > 0) { /* running Green-Kubo sum against the truncation lag */
        hid_t g = pl_h5_group(obs, "fluid_viscosity_gk");
        bad |= g < 0;
        const size_t n = (size_t)o->K + 1;
        double *lag = malloc(2 * n * sizeof(double));
        bad |= !lag;
        if (!bad) {
            double *eta = lag + n, run = 0.0;
            const double norm = 1.0 / (2.0 * o->V * o->kT * o->dt * NOFF * (double)o->ncorr);
            for (size_t k = 0; k < n; ++k) {
                run += (k ? 2.0 : 1.0) * o->cacc[k];
                lag[k] = (double)k * dt;
                eta[k] = run * norm;
            }
            hsize_t d1[1] = {n};
            bad |= pl_obs_put(g, "lag", H5T_NATIVE_DOUBLE, 1, d1, lag, "t0") != 0;
            bad |= pl_obs_put(g, "value", H5T_NATIVE_DOUBLE, 1, d1, eta, "m_f/(a0 t0)") != 0;
            bad |= pl_h5_attr_str(g, "meaning", "shear viscosity: Green-Kubo sum truncated at lag (steps of dt); "
                                                "the plateau is eta") != 0;
        }
        free(lag);
        if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    }
    if (obs >= 0 && H5Gclose(obs) < 0) bad = 1;
    if (!bad && sim->scene.mapping.enabled) bad = pl_obs_si_h5(f, &sim->scene.mapping.map, pl_mapping_t0_relative_error(&sim->scene.mapping.map)) != 0;
    return pl_obs_h5_commit(f, bad, tmp, path, "stress observables", err);
}

/* {value, stderr, ..., se_vs_time, wall_s_for_target} of a viscosity. */
static json_t *viscosity_entry(pl_json_t *b, const pl_stress_t *o, const pl_sim_t *sim, double v, double se,
                               const pl_blocking_result_t *r, double theory)
{
    const pl_scene_t *sc = &sim->scene;
    json_t *e = json_object();
    pl_json_real(b, e, "value", v);
    pl_json_real(b, e, "stderr", se);
    pl_json_real(b, e, "n_independent", r->n_indep);
    pl_json_real(b, e, "statistical_inefficiency", r->inefficiency);
    pl_json_set(b, e, "plateau", json_boolean(r->plateau));
    pl_json_real(b, e, "wall_s", o->wall);
    pl_json_str(b, e, "unit", "m_f/(a0 t0)");
    pl_json_int(b, e, "samples", (long long)(o->couette ? o->sigma.n : o->eta.n));
    pl_json_real(b, e, "theory", theory);
    pl_json_str(b, e, "theory_source", pl_collision_rule(sc->srd.rule)->theory_ref);
    pl_json_real(b, e, "kinematic_value", v / sc->fluid.density);
    pl_json_real(b, e, "kinematic_stderr", se / sc->fluid.density);
    if (sc->mapping.enabled) { /* m_f / (a0 t0) -> Pa s */
        const pl_mapping_t *m = &sc->mapping.map;
        pl_json_real(b, e, "value_Pa_s", v * m->m_f / (m->a0 * m->t0));
        pl_json_real(b, e, "stderr_Pa_s", se * m->m_f / (m->a0 * m->t0));
    }
    pl_obs_error_time(b, e, o->ept, v, se, r->plateau, sc->observe.target_rel_error);
    return e;
}

/* summary.json names: [0] Couette, [1] Green-Kubo viscosity, [2] pressure */
const char *const pl_stress_entries[] = {"couette_viscosity", "fluid_viscosity", "fluid_pressure", NULL};

int pl_stress_finish(pl_sim_t *sim, const char *dir, json_t *doc, pl_err_t *err)
{
    pl_stress_t *o = pl_stress_of(sim);
    if (!o) return 0;
    char path[4096];
    pl_path_join(path, sizeof path, dir, pl_outputs[PL_OUT_OBSERVABLES].name);
    int rc = write_h5(sim, o, path, err);
    if (rc) return rc;
    pl_json_t b = {err, path, "observables", 0};
    json_t *all = pl_obs_summary_section(&b, doc, sim, o->first);
    if (!all) return err->code;
    const pl_scene_t *sc = &sim->scene;
    pl_srd_theory_t th;
    pl_srd_theory_of(sc, &th);
    double v, se;
    pl_blocking_result_t r, rr;
    if (o->couette && pl_stress_couette_estimate(o, &v, &se, &r, &rr)) {
        json_t *e = viscosity_entry(&b, o, sim, v, se, &r, th.eta);
        json_t *q = json_object();
        pl_json_real(&b, q, "value", r.mean);
        pl_json_real(&b, q, "stderr", r.se);
        pl_json_real(&b, q, "n_independent", r.n_indep);
        pl_json_set(&b, q, "plateau", json_boolean(r.plateau));
        pl_json_str(&b, q, "unit", "kT/a0^3");
        pl_json_set(&b, e, "wall_shear_stress", q);
        q = json_object();
        pl_json_real(&b, q, "value", rr.mean);
        pl_json_real(&b, q, "stderr", rr.se);
        pl_json_real(&b, q, "n_independent", rr.n_indep);
        pl_json_set(&b, q, "plateau", json_boolean(rr.plateau));
        pl_json_real(&b, q, "nominal", o->du / (double)o->nlayers);
        pl_json_str(&b, q, "unit", "1/t0");
        pl_json_set(&b, e, "shear_rate", q);
        pl_json_real(&b, e, "apparent_value", r.mean * (double)o->nlayers / o->du);
        pl_json_set(&b, all, pl_stress_entries[0], e);
    }
    if (!o->couette && pl_stress_eta_estimate(o, &v, &se, &r)) {
        json_t *e = viscosity_entry(&b, o, sim, v, se, &r, th.eta);
        pl_json_int(&b, e, "green_kubo_lags", o->K);
        pl_json_set(&b, all, pl_stress_entries[1], e);
    }
    if (o->pressure.n >= 2) {
        pl_blocking_result_t p = pl_blocking_result(&o->pressure);
        json_t *e = json_object();
        pl_json_real(&b, e, "value", p.mean);
        pl_json_real(&b, e, "stderr", p.se);
        pl_json_real(&b, e, "n_independent", p.n_indep);
        pl_json_real(&b, e, "statistical_inefficiency", p.inefficiency);
        pl_json_set(&b, e, "plateau", json_boolean(p.plateau));
        pl_json_str(&b, e, "unit", "kT/a0^3");
        pl_json_real(&b, e, "ideal_gas", (o->N - 1.0) * o->kT / o->V);
        pl_json_set(&b, all, pl_stress_entries[2], e);
    }
    return b.failed ? err->code : 0;
}
