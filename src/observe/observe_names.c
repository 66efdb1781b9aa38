/* The observables a name may choose (a study's plot.y): the summary.json
 * "observables" entries with a value, taken from the observer table (each
 * row's estimates and entries, peloid/observer.h) and from the fluid stress
 * module (pl_stress_entries), never from a list of their own; and whether a
 * scene measures one: its observer on, and for an estimate usable with the
 * scene (pl_obs_estimate_t.unusable). */
#include <stdio.h>
#include <string.h>

#include "peloid/observe_scene.h"
#include "peloid/observer.h"

/* The stress module in the place of a row: -1. */
#define STRESS (-1)

/* Whether observer k (or STRESS) is on in sc. */
static int on(const pl_scene_t *sc, int k, const char **key, long long *iv)
{
    *key = k == STRESS ? "observe.stress_interval" : pl_observers[k]->interval_key;
    *iv = k == STRESS ? sc->observe.stress_interval : pl_scene_observe_ll(&sc->observe, pl_observers[k]->interval);
    return *iv > 0;
}

/* Calls fn on every name (its observer k, its estimate or NULL); stops at a
 * nonzero return and gives it back. */
static int each(int (*fn)(void *ctx, const char *name, int k, const pl_obs_estimate_t *e), void *ctx)
{
    int rc = 0;
    for (int k = 0; !rc && k < pl_nobservers; ++k) {
        const pl_observer_t *r = pl_observers[k];
        for (int j = 0; !rc && j < r->nestimates; ++j) rc = fn(ctx, r->estimates[j].name, k, &r->estimates[j]);
        for (const char *const *e = r->entries; !rc && e && *e; ++e) rc = fn(ctx, *e, k, NULL);
    }
    for (const char *const *e = pl_stress_entries; !rc && *e; ++e) rc = fn(ctx, *e, STRESS, NULL);
    return rc;
}

/* Whether sc (NULL: any scene) measures the name: its observer on and, for
 * an estimate, usable (why: the first reason it does not). */
static int measured(const pl_scene_t *sc, int k, const pl_obs_estimate_t *e, const char **why_not)
{
    const char *key;
    long long iv;
    *why_not = NULL;
    if (!sc) return 1;
    if (!on(sc, k, &key, &iv)) return 0;
    *why_not = e && e->unusable ? e->unusable(sc) : NULL;
    return !*why_not;
}

typedef struct {
    const pl_scene_t *sc;
    const char *name;
    char *list;
    size_t n, len;
    int k, count;
    const pl_obs_estimate_t *e;
} find_t;

static int find(void *ctx, const char *name, int k, const pl_obs_estimate_t *e)
{
    find_t *f = ctx;
    if (strcmp(name, f->name)) return 0;
    f->k = k;
    f->e = e;
    return 1;
}

static int list(void *ctx, const char *name, int k, const pl_obs_estimate_t *e)
{
    find_t *f = ctx;
    const char *why;
    if (!measured(f->sc, k, e, &why)) return 0;
    if (f->len < f->n)
        f->len += (size_t)snprintf(f->list + f->len, f->n - f->len, "%s\"%s\"", f->count ? ", " : "", name);
    f->count++;
    return 0;
}

int pl_observe_named(const pl_scene_t *sc, const char *name, char *why, size_t n)
{
    char names[700] = "";
    find_t f = {.sc = sc, .name = name, .list = names, .n = sizeof names, .k = STRESS - 1};
    each(list, &f);
    if (!f.count) snprintf(names, sizeof names, "none: the scene switches on no observer with a value");
    if (!each(find, &f)) {
        snprintf(why, n, "\"%.80s\" is no observer's summary.json observable; allowed: %s", name, names);
        return PL_ERR_INPUT;
    }
    const char *key, *why_not;
    long long iv;
    if (measured(sc, f.k, f.e, &why_not)) return 0;
    if (why_not)
        snprintf(why, n, "\"%s\" %s; allowed: what the scene measures: %s", name, why_not, names);
    else {
        on(sc, f.k, &key, &iv);
        snprintf(why, n, "\"%s\" is measured by the %s observer, which is off (%s = %lld); allowed: what the scene "
                         "measures: %s", name, f.k == STRESS ? "fluid stress" : pl_observers[f.k]->name, key, iv,
                 names);
    }
    return PL_ERR_INPUT;
}
