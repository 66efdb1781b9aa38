/* Cross-key checks of the colloid sections (called by pl_scene_validate):
 * what one key's range cannot express. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "peloid/colloid.h"

#define OFF(m) offsetof(pl_scene_t, m)

/* The softest Hertz contact that is a contact at all: Hecht Eq. 3, U = K
 * (d - r)^{5/2}, must reach the thermal energy kT before the centres of
 * two colloids of the smallest diameter d meet (overlap d), K d^{5/2} >=
 * kT; softer, a pair meeting with the mean collision energy kT (flux-
 * weighted normal motion) passes through the contact.  Blamed on the key
 * K comes from: hertz.K, or in a physical{} scene the input the mapping
 * derived it from (coarse_graining.hertz_K, physical.hertz_constant or
 * young_modulus). */
static int hertz_floor(const pl_scene_t *scene, pl_err_t *err)
{
    const pl_scene_colloids_t *cs = &scene->colloids;
    const double d = 2.0 * cs->radius * (1.0 - sqrt(3.0) * cs->polydispersity);
    const double kT = cs->temperature > 0.0 ? cs->temperature : 1.0, K = cs->hertz.K;
    const double kmin = kT / pow(d, 2.5);
    if (K >= kmin) return 0;
    const pl_mapping_colloid_t *c = &scene->mapping.colloid;
    const int mapped = scene->mapping.enabled && c->hertz_key;
    const size_t off = mapped ? c->hertz_off : OFF(colloids.hertz.K);
    char what[128];
    if (mapped)
        snprintf(what, sizeof what, "%g gives hertz.K = %.4g kT/a0^2.5", *(const double *)((const char *)scene + off),
                 K);
    else
        snprintf(what, sizeof what, "%g kT/a0^2.5", K);
    return pl_scene_fail(scene, err, off, mapped ? c->hertz_key : "hertz.K",
                         "%s: the Hertz energy K d^2.5 = %.3g kT at full overlap of colloids of diameter d = %.4g "
                         "a0 is below kT = %g, a pair meeting with the thermal energy passes through the contact "
                         "(Hecht Eq. 3); allowed: hertz.K >= kT / d^2.5 = %.4g kT/a0^2.5 (Hecht Sec. II: stiff "
                         "enough that overlaps stay near 10%%)",
                         what, K * pow(d, 2.5), d, kT, kmin);
}

int pl_colloid_validate_scene(const pl_scene_t *scene, pl_err_t *err)
{
    const pl_scene_colloids_t *cs = &scene->colloids;
    unsigned mask;
    char bad[128], all[256];
    if (pl_colloid_parse_pairs(cs->pairs, &mask, bad, sizeof bad)) {
        pl_colloid_pair_names(all, sizeof all);
        return pl_scene_fail(scene, err, OFF(colloids.pairs), "colloids.pairs",
                             "unknown pair term \"%s\"; allowed: %s (comma separated)", bad, all);
    }
    if (cs->wca.sigma_rule == PL_SIGMA_PL && cs->wca.sigma > 0.0)
        return pl_scene_fail(scene, err, OFF(colloids.wca.sigma_rule), "wca.sigma_rule",
                             "\"pl\" derives sigma_cc from coupling.sigma_cf, but wca.sigma = %g is "
                             "given too; allowed: one of them", cs->wca.sigma);
    if (cs->wca.sigma_rule == PL_SIGMA_PL && !(mask & PL_CT_WCA))
        return pl_scene_fail(scene, err, OFF(colloids.wca.sigma_rule), "wca.sigma_rule",
                             "\"pl\" sets the diameter of the wca pair term, which colloids.pairs "
                             "does not switch on; allowed: add wca to colloids.pairs");
    if ((mask & PL_CT_DEPL) &&
        (scene->coupling.method != PL_COUPLE_POTENTIAL || scene->fluid.density <= 0.0))
        return pl_scene_fail(scene, err, OFF(colloids.pairs), "colloids.pairs",
                             "depletion_comp compensates the depletion attraction of the potential "
                             "coupling's fluid (PL Sec. III.C.1); allowed only with "
                             "coupling.method = \"potential\" and fluid.density > 0");
    if (cs->count == 0) return 0;
    if ((mask & PL_CT_DLVO) && !scene->mapping.enabled) {
        /* no material defaults: Hecht Eqs. 1-2 need the suspension's own
         * constants (a physical{} scene derives them, src/mapping/mapping_colloids.c) */
        static const struct {
            size_t off;
            const char *key;
        } need[] = {{OFF(colloids.dlvo.psi0_mV), "dlvo.psi0"},
                    {OFF(colloids.dlvo.kappa_per_m), "dlvo.kappa"},
                    {OFF(colloids.dlvo.hamaker_J), "dlvo.hamaker"},
                    {OFF(colloids.dlvo.length_unit_m), "dlvo.length_unit"}};
        char miss[160] = "";
        for (size_t i = 0; i < sizeof need / sizeof need[0]; ++i)
            if (pl_scene_line_of(scene, need[i].off) <= 0) {
                if (miss[0]) strcat(miss, ", ");
                strcat(miss, need[i].key);
            }
        if (miss[0])
            return pl_scene_fail(scene, err, OFF(colloids.pairs), "colloids.pairs",
                                 "the dlvo pair term needs its material constants dlvo.psi0, dlvo.kappa, "
                                 "dlvo.hamaker and dlvo.length_unit (no material defaults); missing: %s",
                                 miss);
    }
    /* work: random placement tests each colloid against all placed before
     * it, count^2/2 distance checks at least (1e11: about an hour) */
    double checks = 0.5 * (double)cs->count * (double)cs->count;
    if (cs->init == PL_CINIT_RANDOM && checks > 1e11)
        return pl_scene_fail(scene, err, OFF(colloids.count), "colloids.count",
                             "%lld colloids placed at random take %.3g distance checks (hours); "
                             "allowed: count <= 447213 with init = \"random\", or init = \"lattice\" "
                             "or \"file\"", cs->count, checks);
    if (cs->init == PL_CINIT_FILE && !cs->init_file[0])
        return pl_scene_fail(scene, err, OFF(colloids.init), "colloids.init",
                             "\"file\" needs colloids.init_file");
    pl_colloid_pair_params_t p;
    pl_colloid_dlvo_info_t info;
    pl_err_t sub = {0, ""};
    if (pl_colloid_pair_params(scene, &p, &info, &sub)) /* the dlvo{} key the failure names */
        return info.fail_key ? pl_scene_fail(scene, err, info.fail_off, info.fail_key, "%s", sub.msg)
                             : pl_err_set(err, sub.code, "%s", sub.msg);
    if ((mask & PL_CT_HERTZ) && hertz_floor(scene, err)) return PL_ERR_INPUT;
    double rmax = cs->radius * (1.0 + sqrt(3.0) * cs->polydispersity);
    const double rc = pl_colloid_pair_cutoff(&p, rmax);
    for (int k = 0; k < 3; ++k) {
        if (!p.periodic[k]) continue;
        if (rc > 0.5 * scene->box.cells[k])
            return pl_scene_fail(scene, err, OFF(box.cells), "box.cells",
                                 "edge %d (%d a0) is shorter than twice the colloid pair cut-off "
                                 "%.4g a0 (minimum image); allowed: edges >= %.4g",
                                 k, scene->box.cells[k], rc, 2.0 * rc);
    }
    for (int k = 0; k < 3; ++k)
        if (!p.periodic[k] && 2.0 * rmax >= scene->box.cells[k])
            return pl_scene_fail(scene, err, OFF(colloids.radius), "colloids.radius",
                                 "colloid diameter %.4g does not fit between the %c walls (L%c = %d)",
                                 2.0 * rmax, "xyz"[k], "xyz"[k], scene->box.cells[k]);
    return 0;
}
