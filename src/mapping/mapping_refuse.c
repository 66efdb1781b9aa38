/* The mapping's refusals (DESIGN.md "Units and mapping", "Errors"): a derived
 * key given in a physical scene, and a pair term without its material
 * constants, each one line naming the key, what it comes from and what to do;
 * and the provenance lines of the colloid mapping. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>

#include "mapping_refuse.h"

#define OFF(m) offsetof(pl_scene_t, m)

void pl_mapping_prov(pl_mapping_colloid_t *c, const char *fmt, ...)
{
    if (c->nprov >= (int)(sizeof c->prov / sizeof c->prov[0])) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->prov[c->nprov++], sizeof c->prov[0], fmt, ap);
    va_end(ap);
}

int pl_mapping_given(const pl_scene_t *s, size_t off) { return pl_scene_line_of(s, off) > 0; }

int pl_mapping_refuse_derived(pl_scene_t *s, pl_err_t *err, size_t off, const char *key, const char *from,
                              double given_v, double derived, const char *shown)
{
    const int time_unit = off == OFF(colloids.substeps) || off == OFF(colloids.min_substeps) ||
                          off == OFF(colloids.slow_interval) || off == OFF(colloids.gravity);
    pl_scene_mapping_t *mp = &s->mapping;
    if (pl_mapping_given(s, off) && mp->provisional && time_unit &&
        mp->nheld < (int)(sizeof mp->held / sizeof mp->held[0])) {
        mp->held[mp->nheld].off = off;
        mp->held[mp->nheld].key = key;
        mp->held[mp->nheld].from = from;
        mp->held[mp->nheld].given = given_v;
        mp->held[mp->nheld++].derived = derived;
    }
    if (!pl_mapping_given(s, off) || fabs(given_v - derived) <= 1e-12 * fabs(derived)) return 0;
    if (mp->provisional && time_unit) return 0;
    char v[64];
    if (shown) snprintf(v, sizeof v, "\"%s\"", shown);
    else snprintf(v, sizeof v, "%.6g", derived);
    return pl_scene_fail(s, err, off, key,
                         "is derived from %s (value %s here); remove it, a scene with physical{} "
                         "gives the real suspension once (or remove physical{} and give model units)",
                         from, v);
}

int pl_mapping_refuse_missing(const pl_scene_t *s, pl_err_t *err, size_t off, const char *key, const char *term,
                              const char *needs, const char *missing)
{
    if (!missing[0]) return 0;
    return pl_scene_fail(s, err, off, key, "the %s pair term needs the material constants %s; missing: %s (no "
                         "material defaults: give them in physical{})", term, needs, missing);
}
