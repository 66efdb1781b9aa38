/* The observers' lengths of a physical scene.  physical{} gives them in SI
 * like every other input of the real suspension: physical.clusters_gap,
 * rdf_rmax, steinhardt_rmax in m, sq_qmax in 1/m; the mapping writes
 * observe.<same key> in a0 (1/a0), and a different model value given beside
 * one is refused (one source for a number).  With the gap cluster observer
 * on and no gap given either way, the bond gap is derived from the pair
 * potential instead of the schema's 0.1 a0 (81 nm under coupling II and 25
 * nm under the potential coupling for R = 0.5 µm: a fixed model length is no
 * physical criterion): two colloids are bonded when their surface gap is
 * below the largest gap at which the conservative pair energy (DLVO + the
 * contact terms, Hecht Eqs. 1-3) is below -observe.clusters_energy, i.e.
 * when they are bound by more than that energy, in the primary minimum, or
 * in the secondary one where it is as deep: the same criterion as the
 * energy bond rule (clusters_bond = "energy") with the same E_c, as a gap.
 * Every choice is a provenance line of the mapping (params, summary.json
 * mapping.derived_keys). */
#include <math.h>
#include <stddef.h>

#include "peloid/colloid.h"
#include "peloid/mapping.h"
#include "peloid/scene.h"

#include "mapping_refuse.h"

#define OFF(m) offsetof(pl_scene_t, m)

/* One row per observer length key: its SI twin in physical{} and the power
 * of a0 that converts it (1: a length, -1: an inverse length). */
static const struct {
    const char *key; /* the same leaf name in physical{} and observe{} */
    size_t phys, obs;
    int power;
} rows[] = {
    {"clusters_gap", OFF(mapping.physical.clusters_gap), OFF(observe.clusters_gap), 1},
    {"rdf_rmax", OFF(mapping.physical.rdf_rmax), OFF(observe.rdf_rmax), 1},
    {"steinhardt_rmax", OFF(mapping.physical.steinhardt_rmax), OFF(observe.steinhardt_rmax), 1},
    {"sq_qmax", OFF(mapping.physical.sq_qmax), OFF(observe.sq_qmax), -1},
};

static double *at(pl_scene_t *s, size_t off) { return (double *)((char *)s + off); }

int pl_mapping_bond_gap(const pl_scene_t *s, double e_bond, double *h, pl_err_t *err)
{
    pl_colloid_pair_params_t p;
    pl_colloid_dlvo_info_t info;
    *h = -1.0;
    int rc = pl_colloid_pair_params(s, &p, &info, err);
    if (rc) return rc;
    const double R = s->colloids.radius, d = 2.0 * R, step = 1e-3 * R;
    const double hmax = pl_colloid_pair_cutoff(&p, R) - d;
    /* from the cut-off inwards: the first gap bound by more than e_bond is
     * the outer edge of the bound region */
    for (double hi = hmax; hi > 0.0; hi -= step) {
        double lo = hi - step > 0.0 ? hi - step : 0.0;
        if (!(pl_colloid_pair_energy(&p, d + lo, R, R) <= -e_bond)) continue;
        while (hi - lo > 1e-9 * R) { /* U(lo) <= -e_bond < U(hi) */
            double mid = 0.5 * (lo + hi);
            if (pl_colloid_pair_energy(&p, d + mid, R, R) <= -e_bond) lo = mid;
            else hi = mid;
        }
        *h = lo;
        return 0;
    }
    return 0;
}

int pl_mapping_observe_apply(pl_scene_t *s, pl_err_t *err)
{
    pl_mapping_colloid_t *c = &s->mapping.colloid;
    const double a0 = s->mapping.map.a0;
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; ++i) {
        const double si = *at(s, rows[i].phys), model = rows[i].power > 0 ? si / a0 : si * a0;
        const char *unit = rows[i].power > 0 ? "m" : "1/m", *munit = rows[i].power > 0 ? "a0" : "1/a0";
        if (si == 0.0) {
            if (pl_mapping_given(s, rows[i].obs)) /* a model value in a physical scene: its SI value beside it */
                pl_mapping_prov(c, "observe.%s = %.6g %s (given in model units; = %.4g %s, physical.%s takes it in "
                                   "%s)", rows[i].key, *at(s, rows[i].obs), munit,
                                rows[i].power > 0 ? *at(s, rows[i].obs) * a0 : *at(s, rows[i].obs) / a0, unit,
                                rows[i].key, unit);
            continue;
        }
        const double have = *at(s, rows[i].obs);
        if (pl_mapping_given(s, rows[i].obs) && !(fabs(have - model) <= 1e-12 * fabs(model))) {
            char key[64];
            snprintf(key, sizeof key, "observe.%s", rows[i].key);
            return pl_scene_fail(s, err, rows[i].obs, key, "%g %s given beside physical.%s = %g %s (= %.6g %s); "
                                 "allowed: one of them (physical.%s in %s, or observe.%s in %s)", have, munit,
                                 rows[i].key, si, unit, model, munit, rows[i].key, unit, rows[i].key, munit);
        }
        *at(s, rows[i].obs) = model;
        pl_mapping_prov(c, "observe.%s = %.6g %s (derived: physical.%s = %.4g %s)", rows[i].key, model, munit,
                        rows[i].key, si, unit);
    }
    pl_scene_observe_t *o = &s->observe;
    if (!(o->clusters_interval > 0 && o->clusters_bond == PL_BOND_GAP) ||
        pl_mapping_given(s, OFF(observe.clusters_gap)) ||
        s->mapping.physical.clusters_gap != 0.0 || s->colloids.count <= 0)
        return 0;
    double h;
    int rc = pl_mapping_bond_gap(s, o->clusters_energy, &h, err);
    if (rc) return rc;
    if (h < 0.0) {
        pl_mapping_prov(c, "observe.clusters_gap = %.6g a0 = %.4g m (the schema's default: the pair energy never "
                           "falls below -observe.clusters_energy = -%g kT beyond contact, so no gap binds; give "
                           "physical.clusters_gap in m)", o->clusters_gap, o->clusters_gap * a0, o->clusters_energy);
        return 0;
    }
    o->clusters_gap = h;
    pl_mapping_prov(c, "observe.clusters_gap = %.6g a0 = %.4g m (derived: the largest surface gap at which the pair "
                       "energy is below -observe.clusters_energy = -%g kT, the outer edge of the bound pairs; give "
                       "physical.clusters_gap in m to choose another)", h, h * a0, o->clusters_energy);
    return 0;
}
