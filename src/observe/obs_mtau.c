/* Observers MSD, VACF and C_FF (peloid/observer.h rows): the multiple-tau
 * correlators of mtau_observers.c, one row each.  MSD: the estimate
 * colloid_D (Hecht Eq. 36); VACF: the Green-Kubo D (Hecht Eq. 35); C_FF: the
 * fluid force's autocorrelation and the Green-Kubo friction (PL Eq. B2). */
#include <hdf5.h>
#include <jansson.h>
#include <math.h>
#include <stdlib.h>

#include "json_build.h"
#include "mtau_observers.h"
#include "observables_out.h"
#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/observer.h"

static int create_which(pl_obs_run_t *run, void **state, int which, pl_err_t *err)
{
    pl_mtobs_t *m = calloc(1, sizeof *m);
    if (!m) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the correlator observers");
    m->which = which;
    *state = m;
    (void)run;
    return 0;
}
static int create_msd(pl_obs_run_t *run, void **state, pl_err_t *err)
{
    return create_which(run, state, PL_MTOBS_MSD, err);
}
static int create_vacf(pl_obs_run_t *run, void **state, pl_err_t *err)
{
    return create_which(run, state, PL_MTOBS_VACF, err);
}
static int create_cff(pl_obs_run_t *run, void **state, pl_err_t *err)
{
    int rc = create_which(run, state, PL_MTOBS_CFF, err);
    pl_sim_t *sim = run->sim;
    if (!rc && pl_coupling_of(sim)) rc = pl_coupling_mean_force_on(pl_coupling_of(sim), sim->colloids->n, err);
    return rc;
}

static int cff_check(const pl_scene_t *sc, pl_err_t *err)
{
    if (sc->observe.cff_interval > 0 && sc->coupling.method != PL_COUPLE_POTENTIAL)
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, observe.cff_interval), "observe.cff_interval",
                             "%lld: the fluid force on the colloids is a force only with coupling.method = "
                             "\"potential\" (the collision couplings exchange impulses); allowed: 0",
                             sc->observe.cff_interval);
    return 0;
}

static void obs_free(void *state)
{
    pl_mtobs_free(state);
    free(state);
}

static int sample(pl_obs_run_t *run, void *state, pl_err_t *err)
{
    pl_mtobs_t *m = state;
    const pl_scene_observe_t *so = &run->sim->scene.observe;
    const uint64_t ns = pl_obs_expected(run, pl_mtobs_start(so, m->which), pl_mtobs_interval(so, m->which));
    return pl_mtobs_sample(m, run->sim, run->first, ns, err);
}

static int obs_write(int64_t obs, const pl_sim_t *sim, void *state)
{
    (void)sim;
    return pl_mtobs_write((hid_t)obs, state);
}

static void est_D(const void *state, pl_obs_point_t *p)
{
    double a, b;
    p->valid = state && pl_mtobs_diffusion(state, &p->value, &p->se, &a, &b);
    p->plateau = 1;
}

/* colloid_D: the slope of the MSD, in a0^2/t0 and, for a physical scene, m^2/s. */
static int msd_summary(pl_obs_sum_t *s, const pl_sim_t *sim, void *state)
{
    const pl_mtobs_t *msd = state;
    double D, se, tmin, tmax;
    if (!pl_mtobs_diffusion(msd, &D, &se, &tmin, &tmax)) return 0;
    s->wall = msd->wall;
    json_t *e = pl_obs_entry(s, 0, D, se, (double)sim->colloids->n, 0.0, 1, "a0^2/t0");
    const double fit[2] = {tmin, tmax};
    pl_json_reals(s->b, e, "fit_window_t0", fit, 2);
    if (sim->scene.mapping.enabled) { /* a0^2 / t0 -> m^2/s */
        const pl_mapping_t *m = &sim->scene.mapping.map;
        pl_json_real(s->b, e, "value_m2_per_s", D * m->a0 * m->a0 / m->t0);
        pl_json_real(s->b, e, "stderr_m2_per_s", se * m->a0 * m->a0 / m->t0);
    }
    pl_json_set(s->b, s->all, "colloid_D", e);
    return 0;
}

static int gk_summary(pl_obs_sum_t *s, const pl_sim_t *sim, void *state)
{
    pl_mtobs_summary(s->b, s->all, state, sim);
    return 0;
}

/* ---- checkpoint: meta {levels (0: not created)}; <name>_values, <name>_counters */

static void ckpt_meta(const void *state, long long *m) { m[0] = state ? pl_mtobs_levels(state) : 0; }

static int ckpt_write(int64_t g, const void *state)
{
    const pl_mtobs_t *m = state;
    return m->c ? pl_mtobs_ckpt_write((hid_t)g, m) : 0;
}

static int ckpt_read(int64_t g, pl_obs_run_t *run, void *state, const long long *m, const char *path, pl_err_t *err)
{
    return m[0] ? pl_mtobs_ckpt_read((hid_t)g, state, m[0], run->sim, path, err) : 0;
}

static int resume(pl_obs_run_t *run, void *state, pl_err_t *err)
{
    pl_mtobs_t *m = state;
    if (!m->c) return 0; /* not sampled yet */
    const pl_scene_observe_t *so = &run->sim->scene.observe;
    return pl_mtobs_grow(m, pl_obs_expected(run, pl_mtobs_start(so, m->which), pl_mtobs_interval(so, m->which)), err);
}

static const pl_obs_estimate_t msd_estimates[] = {{"colloid_D", 0, est_D, NULL}};

#define OFFS(m) offsetof(pl_scene_observe_t, m)
#define COMMON                                                                                                    \
    .sample = sample, .write = obs_write, .nmeta = 1, .ckpt_meta = ckpt_meta, .ckpt_write = ckpt_write,            \
    .ckpt_read = ckpt_read, .resume = resume, .free = obs_free

const pl_observer_t pl_observer_msd = {
    .name = "MSD", .stage = "observe-msd", .interval = OFFS(msd_interval), .start = OFFS(msd_start),
    .interval_key = "observe.msd_interval", .start_key = "observe.msd_start", .at_start = 1, .need = 5,
    .create = create_msd, .summary = msd_summary, .meta_slot = 2, .estimates = msd_estimates, .nestimates = 1,
    COMMON,
};

const pl_observer_t pl_observer_vacf = {
    .name = "VACF", .stage = "observe-vacf", .interval = OFFS(vacf_interval), .start = OFFS(vacf_start),
    .interval_key = "observe.vacf_interval", .start_key = "observe.vacf_start", .at_start = 1, .need = 5,
    .create = create_vacf, .summary = gk_summary, .meta_slot = 3, .entries = pl_mtobs_vacf_entries, COMMON,
};

const pl_observer_t pl_observer_cff = {
    .name = "C_FF", .stage = "observe-cff", .interval = OFFS(cff_interval), .start = OFFS(cff_start),
    .interval_key = "observe.cff_interval", .start_key = "observe.cff_start", .at_start = 0, .need = 5,
    .check = cff_check, .create = create_cff, .summary = gk_summary, .meta_slot = 4,
    .entries = pl_mtobs_cff_entries, COMMON,
};
