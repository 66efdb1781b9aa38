/* Whether each observer the scene asks for can measure something in the
 * run's span: a sampler whose window [start, last step] holds no sample, a
 * correlator too short for the lag its estimate reads (MSD and VACF
 * diffusion and the C_FF friction read lags up to T/4 of the sampled span T:
 * five samples give one such lag), a g(r) range that ends at or below
 * contact, a VACF of colloids without inertial velocities (the Brownian
 * integrator draws a new velocity each step: its VACF is a delta and its
 * Green-Kubo D is the step's, not the colloid's).  Without these checks the
 * observable is absent or meaningless and the run still exits 0.
 *
 * The samplers take their samples at the multiples of their interval from
 * their start on (at step 0 too, except C_FF, whose force is an average
 * over a collision step), to the last step. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>

#include "peloid/observe_scene.h"
#include "peloid/scene.h"

#define OFFS(m) offsetof(pl_scene_t, observe.m)

static const struct {
    const char *what;
    size_t interval, start; /* in pl_scene_t */
    const char *interval_key, *start_key;
    int at_start;    /* samples at step 0 */
    long long need;  /* fewest samples with a result */
} spans[] = {
    {"g(r)", OFFS(rdf_interval), OFFS(rdf_start), "observe.rdf_interval", "observe.rdf_start", 1, 1},
    {"S(q)", OFFS(sq_interval), OFFS(sq_start), "observe.sq_interval", "observe.sq_start", 1, 1},
    {"MSD", OFFS(msd_interval), OFFS(msd_start), "observe.msd_interval", "observe.msd_start", 1, 5},
    {"VACF", OFFS(vacf_interval), OFFS(vacf_start), "observe.vacf_interval", "observe.vacf_start", 1, 5},
    {"C_FF", OFFS(cff_interval), OFFS(cff_start), "observe.cff_interval", "observe.cff_start", 0, 5},
    {"cluster", OFFS(clusters_interval), OFFS(clusters_start), "observe.clusters_interval",
     "observe.clusters_start", 1, 1},
    {"velocity-distribution", OFFS(vdist_interval), OFFS(vdist_start), "observe.vdist_interval",
     "observe.vdist_start", 1, 1},
    {"sedimentation", OFFS(sediment_interval), OFFS(sediment_start), "observe.sediment_interval",
     "observe.sediment_start", 1, 2},
};

static long long ll_at(const pl_scene_t *sc, size_t off) { return *(const long long *)((const char *)sc + off); }

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
    for (size_t k = 0; k < sizeof spans / sizeof spans[0]; ++k) {
        const long long iv = ll_at(sc, spans[k].interval), st = ll_at(sc, spans[k].start);
        if (iv <= 0) continue;
        const long long got = samples_in(st, iv, last, spans[k].at_start);
        if (got >= spans[k].need) continue;
        const int late = st > last;
        *off = late ? spans[k].start : spans[k].interval;
        *key = late ? spans[k].start_key : spans[k].interval_key;
        if (late)
            snprintf(why, n, "%lld is after the run's last step %lld: the %s observer would take no sample; "
                             "allowed: a start <= %lld", st, last, spans[k].what, last);
        else
            snprintf(why, n, "%lld from step %lld to the run's last step %lld gives %lld sample(s); the %s "
                             "observer needs %lld%s; allowed: an interval of at most about %lld, or a longer run "
                             "(steps)",
                     iv, st, last, got, spans[k].what, spans[k].need,
                     spans[k].need > 2 ? " (its estimate reads lags up to a quarter of the sampled span)" : "",
                     (last - st) / (spans[k].need > 1 ? spans[k].need - 1 : 1));
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
    if (o->vacf_interval > 0 && sc->colloids.integrator == PL_CINT_BROWNIAN)
        return pl_scene_fail(sc, err, OFFS(vacf_interval), "observe.vacf_interval",
                             "%lld with colloids.integrator = \"brownian\": Brownian dynamics has no inertial "
                             "velocities (a new one each step), so the VACF and its Green-Kubo D measure the "
                             "step, not the colloid; allowed: 0 (observe.msd_interval gives D)",
                             o->vacf_interval);
    if (o->rdf_interval > 0 && o->rdf_rmax > 0) {
        /* the closest pair: two of the smallest radii the scene can draw */
        const double rmin = sc->colloids.radius * (1.0 - sqrt(3.0) * sc->colloids.polydispersity);
        if (sc->colloids.init != PL_CINIT_FILE && o->rdf_rmax <= 2.0 * rmin)
            return pl_scene_fail(sc, err, OFFS(rdf_rmax), "observe.rdf_rmax",
                                 "%g a0 is at or below contact (2 x the smallest radius, %g a0): g(r) would count "
                                 "no pair; allowed: 0 (half the box) or > %g a0",
                                 o->rdf_rmax, 2.0 * rmin, 2.0 * rmin);
    }
    return 0;
}
