/* The multiple-tau correlator observers of the observer module
 * (observe_module.c; DESIGN.md "Observables and their errors"): three
 * correlations of the colloids, each a pl_mtau_t (peloid/mtau.h, every-m-th
 * coarse-graining: unbiased at every lag) with one row in `rows` below, so
 * that one piece of code creates, samples, checkpoints, grows and writes
 * them all.
 *
 *   MSD   unwrapped colloid positions; D = slope / 6 of the summed-axis MSD,
 *         least squares over the lags in [T/40, T/4] of the sampled span T
 *         (the long-time regime with at least 4 independent origins per
 *         lag; Hecht Eq. 36, PL Sec. VI.C), its SE over colloids.
 *   VACF  <v(0).v(t)> of the colloid velocities (AUTO) and the Green-Kubo
 *         D = (1/3) of its integral to T/4 (Hecht Eq. 35).
 *   C_FF  <F(0).F(t)> of the fluid force on the colloids, averaged over each
 *         collision step (potential coupling: pl_coupling_mean_force), and
 *         the Green-Kubo friction (1/3kT) of its integral to its first zero
 *         (PL Eq. B2).
 *
 * The observer module owns the run span (first and last step, the restart
 * step) and the error-against-time report; it hands each call what it
 * needs of them. */
#include <math.h>
#include <omp.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include "checkpoint_h5.h"
#include "mtau_observers.h"
#include "observables_out.h"
#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/h5.h"
#include "peloid/module.h"

enum { MT_P = 16, MT_M = 2 }; /* correlator points per level, coarse-graining factor */

#define OFFO(m) offsetof(pl_scene_observe_t, m)

/* What differs between the observers; the order is PL_MTOBS_*. */
static const struct {
    const char *name;    /* checkpoint items <name>_values, <name>_counters */
    const char *stage;   /* plan stage */
    const char *group;   /* /observables/<group> */
    const char *unit;    /* of the correlation */
    pl_mtau_kind_t kind;
    size_t interval, start; /* in pl_scene_observe_t */
    int at_start;
} rows[PL_MTOBS_N] = {
    {"msd", "observe-msd", "colloid_msd", "a0^2", PL_MTAU_MSD, OFFO(msd_interval), OFFO(msd_start), 1},
    {"vacf", "observe-vacf", "colloid_vacf", "a0^2/t0^2", PL_MTAU_AUTO, OFFO(vacf_interval), OFFO(vacf_start), 1},
    {"cff", "observe-cff", "colloid_cff", "(kT/a0)^2", PL_MTAU_AUTO, OFFO(cff_interval), OFFO(cff_start), 0},
};

long long pl_mtobs_interval(const pl_scene_observe_t *so, int which)
{
    return pl_scene_observe_ll(so, rows[which].interval);
}
long long pl_mtobs_start(const pl_scene_observe_t *so, int which)
{
    return pl_scene_observe_ll(so, rows[which].start);
}

pl_stage_t pl_mtobs_stage(const pl_scene_observe_t *so, int which)
{
    return (pl_stage_t){.name = rows[which].stage, .interval = pl_mtobs_interval(so, which),
                        .phase = PL_PHASE_AFTER, .slot = PL_SLOT_OBSERVE, .at_start = rows[which].at_start};
}

void pl_mtobs_free(pl_mtobs_t *m)
{
    pl_mtau_free(m->c);
    for (int d = 0; d < 3; ++d) free(m->u[d]);
}

/* The correlator with `levels` levels and the observer's scratch. */
static int mtobs_create(pl_mtobs_t *m, const pl_sim_t *sim, int levels, pl_err_t *err)
{
    const size_t n = sim->colloids->n;
    m->dt = (double)pl_mtobs_interval(&sim->scene.observe, m->which) * sim->scene.srd.dt;
    pl_mtau_params_t p = {.n = n, .p = MT_P, .m = MT_M, .levels = levels, .kind = rows[m->which].kind,
                          .average = 0, .dt = m->dt};
    int rc = pl_mtau_create(&p, &m->c, err);
    if (rc || m->which != PL_MTOBS_MSD) return rc;
    for (int d = 0; d < 3; ++d)
        if (!(m->u[d] = malloc(n * sizeof(double))))
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the MSD observer");
    return 0;
}

int pl_mtobs_sample(pl_mtobs_t *m, pl_sim_t *sim, long long first, uint64_t expected, pl_err_t *err)
{
    if (sim->step < pl_mtobs_start(&sim->scene.observe, m->which)) return 0;
    if (m->which == PL_MTOBS_CFF && (sim->step <= first || !pl_coupling_mean_force(pl_coupling_of(sim)))) return 0;
    const double t0 = omp_get_wtime();
    const pl_colloid_t *c = sim->colloids;
    if (!m->c) {
        int rc = mtobs_create(m, sim, pl_mtau_levels_for(expected, MT_P, MT_M), err);
        if (rc) return rc;
    }
    const double *x = c->vx, *y = c->vy, *z = c->vz;
    if (m->which == PL_MTOBS_MSD) {
        const double *r[3] = {c->x, c->y, c->z};
        const int32_t *im[3] = {c->ix, c->iy, c->iz};
        for (int d = 0; d < 3; ++d)
            for (size_t i = 0; i < c->n; ++i) m->u[d][i] = r[d][i] + (double)im[d][i] * c->box[d];
        x = m->u[0], y = m->u[1], z = m->u[2];
    } else if (m->which == PL_MTOBS_CFF) {
        const double *f = pl_coupling_mean_force(pl_coupling_of(sim));
        x = f, y = f + c->n, z = f + 2 * c->n;
    }
    pl_mtau_add(m->c, x, y, z, sim->nthreads);
    m->wall += omp_get_wtime() - t0;
    return 0;
}

int pl_mtobs_grow(pl_mtobs_t *m, uint64_t expected, pl_err_t *err)
{
    const int need = pl_mtau_levels_for(expected, MT_P, MT_M);
    if (need <= pl_mtau_levels(m->c)) return 0;
    pl_mtau_t *g;
    int rc = pl_mtau_grow(m->c, need, &g, err);
    if (rc) return rc;
    pl_mtau_free(m->c);
    m->c = g;
    return 0;
}

/* ---- checkpoint (group /observe, observe_module.c) --------------------- */

long long pl_mtobs_levels(const pl_mtobs_t *m) { return m->c ? pl_mtau_levels(m->c) : 0; }

static void item_names(const pl_mtobs_t *m, char a[64], char b[64])
{
    snprintf(a, 64, "%s_values", rows[m->which].name);
    snprintf(b, 64, "%s_counters", rows[m->which].name);
}

int pl_mtobs_ckpt_write(hid_t g, const pl_mtobs_t *m)
{
    char a[64], b[64];
    item_names(m, a, b);
    pl_mtau_state_t st = pl_mtau_state(m->c);
    return pl_ckpt_write_1d(g, a, H5T_NATIVE_DOUBLE, st.values, st.nvalues) |
           pl_ckpt_write_1d(g, b, H5T_NATIVE_UINT64, st.counters, st.ncounters);
}

int pl_mtobs_ckpt_read(hid_t g, pl_mtobs_t *m, long long levels, const pl_sim_t *sim, const char *path,
                       pl_err_t *err)
{
    if (levels < 1 || levels > PL_MTAU_MAX_LEVELS)
        return pl_err_set(err, PL_ERR_INPUT, "%s: /observe/meta: %s correlator with %lld levels; allowed 1..%d "
                                             "(corrupt checkpoint)", path, rows[m->which].name, levels,
                          PL_MTAU_MAX_LEVELS);
    int rc = mtobs_create(m, sim, (int)levels, err);
    if (rc) return rc;
    char a[64], b[64];
    item_names(m, a, b);
    pl_mtau_state_t st = pl_mtau_state(m->c);
    rc = pl_ckpt_read_1d(g, a, H5T_NATIVE_DOUBLE, st.values, st.nvalues, path, err);
    if (!rc) rc = pl_ckpt_read_1d(g, b, H5T_NATIVE_UINT64, st.counters, st.ncounters, path, err);
    return rc;
}

/* ---- outputs ----------------------------------------------------------- */

/* D(t) = d MSD / (6 dt) as a local slope (MSD group datasets D_local,
 * D_local_se beside lag): at lag k the least-squares slope of the summed MSD
 * over lags k-1..k+1 (one-sided at the first and last lag), fitted per
 * colloid and averaged with the SE of that mean (pl_mtau_slope, as
 * colloid_D over its fit window).  A D(t) that levels off shows the
 * diffusive regime that colloid_D's fit window assumes. */
static int local_D(hid_t g, const pl_mtau_t *c, const double *lag, size_t n)
{
    double *d = malloc(2 * (n ? n : 1) * sizeof *d);
    if (!d) return -1;
    double *e = d + n;
    for (size_t k = 0; k < n; ++k) {
        double s[PL_MTAU_COLS], se[PL_MTAU_COLS];
        pl_err_t ignore = {0, ""};
        const double lo = lag[k ? k - 1 : 0], hi = lag[k + 1 < n ? k + 1 : k];
        d[k] = e[k] = NAN;
        if (pl_mtau_slope(c, lo, hi, s, se, &ignore)) continue;
        d[k] = s[3] / 6.0;
        e[k] = se[3] / 6.0;
    }
    hsize_t d1[1] = {n};
    int bad = pl_obs_put(g, "D_local", H5T_NATIVE_DOUBLE, 1, d1, d, "a0^2/t0") != 0;
    bad |= pl_obs_put(g, "D_local_se", H5T_NATIVE_DOUBLE, 1, d1, e, "a0^2/t0") != 0;
    free(d);
    return bad ? -1 : 0;
}

int pl_mtobs_write(hid_t obs, const pl_mtobs_t *m)
{
    if (!m->c || pl_mtau_samples(m->c) <= 1) return 0;
    const pl_mtau_t *c = m->c;
    const size_t nl = pl_mtau_nlags(c);
    double *lag = malloc(nl * (1 + 2 * PL_MTAU_COLS) * sizeof(double));
    uint64_t *org = malloc(nl * sizeof(uint64_t));
    hid_t g = pl_h5_group(obs, rows[m->which].group);
    int bad = !lag || !org || g < 0;
    if (!bad) {
        double *val = lag + nl, *se = val + nl * PL_MTAU_COLS;
        pl_mtau_result(c, lag, org, val, se);
        size_t n = 0; /* the lags with an origin */
        while (n < nl && org[n] > 0) ++n;
        for (size_t k = 0; k < n * PL_MTAU_COLS; ++k)
            if (!isfinite(se[k])) se[k] = 0.0; /* one colloid: no spread */
        hsize_t d1[1] = {n}, d2[2] = {n, PL_MTAU_COLS};
        const char *unit = rows[m->which].unit;
        bad |= pl_obs_put(g, "lag", H5T_NATIVE_DOUBLE, 1, d1, lag, "t0") != 0;
        bad |= pl_obs_put(g, "origins", H5T_NATIVE_UINT64, 1, d1, org, NULL) != 0;
        bad |= pl_obs_put(g, "value", H5T_NATIVE_DOUBLE, 2, d2, val, unit) != 0;
        bad |= pl_obs_put(g, "value_se", H5T_NATIVE_DOUBLE, 2, d2, se, unit) != 0;
        bad |= pl_h5_attr_str(g, "columns", "x y z sum") != 0;
        if (m->which == PL_MTOBS_MSD && !bad) bad |= local_D(g, c, lag, n) != 0;
    }
    if (g >= 0 && H5Gclose(g) < 0) bad = 1;
    free(lag);
    free(org);
    return bad ? -1 : 0;
}

int pl_mtobs_diffusion(const pl_mtobs_t *msd, double *D, double *se, double *tmin, double *tmax)
{
    if (!msd->c || pl_mtau_samples(msd->c) < 8) return 0;
    const double T = (double)(pl_mtau_samples(msd->c) - 1) * msd->dt;
    *tmax = 0.25 * T;
    *tmin = 0.1 * *tmax;
    double s[PL_MTAU_COLS], e[PL_MTAU_COLS];
    pl_err_t ignore = {0, ""};
    if (pl_mtau_slope(msd->c, *tmin, *tmax, s, e, &ignore)) return 0;
    *D = s[3] / 6.0;
    *se = e[3] / 6.0;
    return isfinite(*D) && isfinite(*se);
}

/* The summed-axis integral of the correlation to tmax, divided by `by`. */
static int integral(const pl_mtobs_t *m, double tmax, double by, double *value, double *se)
{
    double s[PL_MTAU_COLS], e[PL_MTAU_COLS];
    pl_err_t ignore = {0, ""};
    if (pl_mtau_integral(m->c, tmax, s, e, &ignore)) return 0;
    *value = s[3] / by;
    *se = e[3] / by;
    return isfinite(*value) && isfinite(*se);
}

/* Green-Kubo D = (1/3) int_0^{T/4} <v(0).v(t)> dt (Hecht Eq. 35). */
static int green_kubo(const pl_mtobs_t *vacf, double *D, double *se, double *tmax)
{
    *tmax = 0.25 * (double)(pl_mtau_samples(vacf->c) - 1) * vacf->dt;
    return integral(vacf, *tmax, 3.0, D, se);
}

/* Green-Kubo friction xi = (1/3kT) int_0^{t1} <F(0).F(t)> dt (PL Eq. B2; the
 * Kirkwood formula of a fixed colloid), t1 the first lag where the summed
 * C_FF is <= 0 (its decay: PL Fig. 10; beyond it the integral of a finite
 * run only adds noise, and for a free colloid it tends to 0), else a quarter
 * of the sampled span.  Also <F.F>(0). */
static int friction(const pl_mtobs_t *cff, double kT, double *xi, double *se, double *t1, double *f2)
{
    const size_t nl = pl_mtau_nlags(cff->c);
    double *lag = malloc(nl * (1 + PL_MTAU_COLS) * sizeof(double));
    if (!lag) return 0;
    double *val = lag + nl;
    pl_mtau_result(cff->c, lag, NULL, val, NULL);
    *f2 = val[3];
    *t1 = 0.25 * (double)(pl_mtau_samples(cff->c) - 1) * cff->dt;
    for (size_t k = 1; k < nl && lag[k] <= *t1; ++k)
        if (isfinite(val[PL_MTAU_COLS * k + 3]) && val[PL_MTAU_COLS * k + 3] <= 0.0) {
            *t1 = lag[k];
            break;
        }
    free(lag);
    return integral(cff, *t1, 3.0 * kT, xi, se);
}

const char *const pl_mtobs_vacf_entries[] = {"colloid_D_green_kubo", NULL};
const char *const pl_mtobs_cff_entries[] = {"colloid_friction_green_kubo", NULL};

void pl_mtobs_summary(pl_json_t *b, json_t *all, const pl_mtobs_t *m, const pl_sim_t *sim)
{
    if (!m->c || pl_mtau_samples(m->c) < 8 || m->which == PL_MTOBS_MSD) return;
    double v, se, t1, f2 = 0.0;
    const int ok = m->which == PL_MTOBS_VACF ? green_kubo(m, &v, &se, &t1)
                                             : friction(m, pl_scene_kT(&sim->scene), &v, &se, &t1, &f2);
    if (!ok) return;
    json_t *e = json_object();
    pl_json_real(b, e, "value", v);
    pl_json_real(b, e, "stderr", se);
    pl_json_real(b, e, "n_independent", (double)sim->colloids->n);
    pl_json_real(b, e, "integrated_to_t0", t1);
    if (m->which == PL_MTOBS_VACF) {
        pl_json_real(b, e, "wall_s", m->wall);
        pl_json_str(b, e, "unit", "a0^2/t0");
        pl_json_set(b, all, pl_mtobs_vacf_entries[0], e);
        return;
    }
    pl_json_real(b, e, "force_variance", f2);
    pl_json_str(b, e, "force_variance_unit", "(kT/a0)^2");
    pl_json_real(b, e, "wall_s", m->wall);
    pl_json_str(b, e, "unit", "m_f/t0");
    pl_json_str(b, e, "definition", "(1/3kT) int_0^t1 <F(0).F(t)> dt, F the fluid force averaged over each "
                                    "collision step, t1 the first zero of C_FF");
    pl_json_set(b, all, pl_mtobs_cff_entries[0], e);
}
