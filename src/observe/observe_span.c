/* Whether each observer the scene asks for can measure something in the
 * run's span: a sampler whose window [start, last step] holds no sample, a
 * correlator too short for the lag its estimate reads (MSD and VACF
 * diffusion and the C_FF friction read lags up to T/4 of the sampled span T:
 * five samples give one such lag), a g(r) range that ends at or below
 * contact (the smallest radius an init file may give too), a VACF of
 * colloids without inertial velocities (the Brownian integrator draws a new
 * velocity each step: its VACF is a delta and its Green-Kubo D is the
 * step's, not the colloid's).  Without these checks the
 * observable is absent or meaningless and the run still exits 0.
 *
 * The observers (peloid/observer.h rows: their interval and start keys,
 * whether they sample the start state, the samples they need) take their
 * samples at the multiples of their interval from
 * their start on (at step 0 too, except C_FF, whose force is an average
 * over a collision step), to the last step.
 *
 * observe.average_from must parse and start before the last step.
 *
 * At the end of a run, pl_obs_unmeasured names an observer that sampled
 * and still has no estimate (summary.json "not_measured", a warning). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>

#include "obs_window.h"
#include "observables_out.h" /* pl_obs_point_t */
#include "peloid/colloid.h"
#include "peloid/observe_scene.h"
#include "peloid/observer.h"
#include "peloid/scene.h"
#include "peloid/colloid_integrator.h"

#define OFFS(m) offsetof(pl_scene_t, observe.m)

/* Samples at the multiples of `interval` in [start, last] (from step 1 on
 * without at_start). */
static long long samples_in(long long start, long long interval, long long last, int at_start)
{
    long long a = start > 0 ? start : at_start ? 0 : 1;
    if (a % interval) a += interval - a % interval;
    return a > last ? 0 : (last - a) / interval + 1;
}

int pl_observe_span_problem(const pl_scene_t *sc, long long last, size_t *off, const char **key, char *why,
                            size_t n)
{
    for (int k = 0; k < pl_nobservers; ++k) {
        const pl_observer_t *r = pl_observers[k];
        const long long iv = pl_scene_observe_ll(&sc->observe, r->interval),
                        st = pl_scene_observe_ll(&sc->observe, r->start);
        if (iv <= 0) continue;
        const long long got = samples_in(st, iv, last, r->at_start);
        if (got >= r->need) continue;
        const int late = st > last;
        *off = offsetof(pl_scene_t, observe) + (late ? r->start : r->interval);
        *key = late ? r->start_key : r->interval_key;
        if (late)
            snprintf(why, n, "%lld is after the run's last step %lld: the %s observer would take no sample; "
                             "allowed: a start <= %lld", st, last, r->name, last);
        else
            snprintf(why, n, "%lld from step %lld to the run's last step %lld gives %lld sample(s); the %s "
                             "observer needs %lld%s; allowed: an interval of at most about %lld, or a longer run "
                             "(steps)",
                     iv, st, last, got, r->name, r->need,
                     r->need > 2 ? " (its estimate reads lags up to a quarter of the sampled span)" : "",
                     (last - st) / (r->need > 1 ? r->need - 1 : 1));
        return 1;
    }
    if (pl_obs_window_problem(sc, last, why, n)) {
        *off = OFFS(average_from);
        *key = "observe.average_from";
        return 1;
    }
    return 0;
}

int pl_observe_validate_measurable(const pl_scene_t *sc, pl_err_t *err)
{
    const pl_scene_observe_t *o = &sc->observe;
    size_t off;
    const char *key;
    char why[400];
    if (pl_observe_span_problem(sc, sc->run.steps, &off, &key, why, sizeof why))
        return pl_scene_fail(sc, err, off, key, "%s", why);
    if (o->vacf_interval > 0 && !pl_colloid_integrator(sc->colloids.integrator)->inertial)
        return pl_scene_fail(sc, err, OFFS(vacf_interval), "observe.vacf_interval",
                             "%lld with colloids.integrator = \"brownian\": Brownian dynamics has no inertial "
                             "velocities (a new one each step), so the VACF and its Green-Kubo D measure the "
                             "step, not the colloid; allowed: 0 (observe.msd_interval gives D)",
                             o->vacf_interval);
    if (o->rdf_interval > 0 && o->rdf_rmax > 0) {
        /* the closest pair: two of the smallest radii the scene can draw or read */
        const double rmin = pl_colloid_radius_min(sc);
        if (o->rdf_rmax <= 2.0 * rmin)
            return pl_scene_fail(sc, err, OFFS(rdf_rmax), "observe.rdf_rmax",
                                 "%g a0 is at or below contact (2 x the smallest radius, %g a0): g(r) would count "
                                 "no pair; allowed: 0 (half the box) or > %g a0",
                                 o->rdf_rmax, 2.0 * rmin, 2.0 * rmin);
    }
    return 0;
}

int pl_obs_unmeasured(const pl_observer_t *r, const void *state, long long first, long long last, char *why, size_t n)
{
    if (!r->nestimates) return 0;
    char names[400] = "";
    for (int j = 0, len = 0; j < r->nestimates; ++j) {
        pl_obs_point_t p = {0};
        r->estimates[j].get(state, &p);
        if (p.valid) return 0;
        if (len < (int)sizeof names)
            len += snprintf(names + len, sizeof names - (size_t)len, "%s%s", j ? ", " : "", r->estimates[j].name);
    }
    snprintf(why, n, "%s: the %s observer measured nothing in steps %lld..%lld (%s): no %s in summary.json",
             r->interval_key, r->name, first, last, r->none_why ? r->none_why : "too few samples with a result",
             names);
    return 1;
}
