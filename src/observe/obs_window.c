/* The analysis window in a run (obs_window.h): observe.average_from
 * resolved against the run's span (a time in seconds with physical{}, in
 * t0 otherwise; a percentage of the combined run, first to last step, so
 * that a resumed run gets the uninterrupted run's window) and stated in
 * summary.json and observables.h5. */
#include "obs_window.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/h5.h"
#include "peloid/scene.h"

/* The user's time in model units t0. */
static double time_model(const pl_scene_t *sc, double t)
{
    return sc->mapping.enabled ? t / sc->mapping.map.t0 : t;
}

static const char *time_unit(const pl_scene_t *sc) { return sc->mapping.enabled ? "s" : "t0"; }

int pl_obs_window_problem(const pl_scene_t *sc, long long last, char *why, size_t n)
{
    pl_window_spec_t s;
    const char *txt = sc->observe.average_from;
    if (pl_window_parse(txt, &s)) {
        const double v = strtod(txt, NULL);
        snprintf(why, n, "\"%.100s\" %s; allowed: \"auto\", \"start\", a time >= 0 in %s (\"12.5\") "
                         "or a percentage of the run in [0, 100) (\"75%%\")", txt,
                 v < 0.0 ? "is negative" : v >= 100.0 && strchr(txt, '%') ? "is not below 100%" : "is not a window",
                 time_unit(sc));
        return 1;
    }
    /* a provisional pass's t0 is the theory's: the calibrated pass checks */
    if (s.kind != PL_WINDOW_TIME || (sc->mapping.enabled && sc->mapping.provisional)) return 0;
    const double end = (double)last * sc->srd.dt * (sc->mapping.enabled ? sc->mapping.map.t0 : 1.0);
    if (time_model(sc, s.value) >= (double)last * sc->srd.dt) {
        snprintf(why, n, "\"%.100s\" %s is at or after the run's end (%g %s, step %lld): nothing would be averaged; "
                         "allowed: a time in [0, %g) %s", txt, time_unit(sc), end, time_unit(sc), last, end,
                 time_unit(sc));
        return 1;
    }
    return 0;
}

pl_window_t pl_obs_window(const pl_obs_run_t *run, const long long *step, const double *x, size_t n)
{
    const pl_scene_t *sc = &run->sim->scene;
    pl_window_spec_t s = {PL_WINDOW_START, 0.0};
    if (pl_window_parse(sc->observe.average_from, &s)) s.kind = PL_WINDOW_START; /* refused at check */
    const long long from =
        pl_window_from_step(&s, time_model(sc, s.value), sc->srd.dt, run->first, run->last);
    double *scratch = s.kind == PL_WINDOW_AUTO && n ? malloc(n * sizeof *scratch) : NULL;
    if (s.kind == PL_WINDOW_AUTO && !scratch) s.kind = PL_WINDOW_START; /* no room: the whole run, stated */
    pl_window_t w = pl_window_choose(&s, from, step, x, n, scratch);
    free(scratch);
    return w;
}

static double step_time(const pl_sim_t *sim, long long step)
{
    const pl_scene_t *sc = &sim->scene;
    return (double)step * sc->srd.dt * (sc->mapping.enabled ? sc->mapping.map.t0 : 1.0);
}

void pl_obs_window_json(pl_json_t *b, json_t *e, const pl_sim_t *sim, const pl_window_t *w)
{
    pl_json_int(b, e, "average_from_step", w->step);
    pl_json_real(b, e, "average_from_time", step_time(sim, w->step));
    pl_json_str(b, e, "average_from_time_unit", time_unit(&sim->scene));
    pl_json_str(b, e, "window_source", pl_window_source_name(w->source));
    if (w->source == PL_WSRC_DETECTED) {
        pl_json_real(b, e, "window_inefficiency", w->g);
        pl_json_real(b, e, "window_n_eff", w->neff);
    }
}

int pl_obs_window_h5(hid_t obs, const char *name, const pl_sim_t *sim, const pl_window_t *w)
{
    hid_t g = H5Gopen2(obs, name, H5P_DEFAULT);
    if (g < 0) return -1;
    const double v[2] = {(double)w->step, step_time(sim, w->step)};
    int bad = pl_h5_attr_doubles(g, "average_from_step_time", v, 2) != 0;
    bad |= pl_h5_attr_str(g, "average_from_time_unit", time_unit(&sim->scene)) != 0;
    bad |= pl_h5_attr_str(g, "window_source", pl_window_source_name(w->source)) != 0;
    if (H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
}
