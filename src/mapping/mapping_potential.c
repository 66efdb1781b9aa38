/* The potential coupling's colloid hard core in a physical scene (PL Sec.
 * III.A, III.C.1).
 *
 * PL's colloid-colloid repulsion is the WCA of PL Eq. 16 (n = 24, eps_cc =
 * 2.5 kT) with sigma_cc from PL's rule against spurious depletion (Sec.
 * III.C.1): phi_cc = 2.5 kT at twice the colloid-fluid cut-off 2^{1/6}
 * sigma_cf, so that two colloids never come close enough for the fluid's
 * depletion attraction (PL Eqs. 22-24) to act.  With sigma_cf = R (PL Sec.
 * VII) this is sigma_cc = 2^{7/6} R = 2.245 R: the colloids collide as hard
 * spheres of radius sigma_cc / 2 = 1.12 R, and the volume fraction of those
 * hard cores, phi_c = phi (sigma_cc / 2R)^3 = 1.41 phi, sets their
 * structure and collisions (g(r), S(q), D(phi)).  phi_c is reported beside
 * phi and warned (HARD_CORE_PHI) when phi_c / phi leaves 1 +- 10 %.
 *
 * DLVO (Hecht Eqs. 1-2) is a function of the gap h = r - 2R between the
 * stated surfaces.  Beside the wca term, every gap below sigma_cc - 2R =
 * 0.245 R (for R = 1 um: 245 nm, where the primary minimum, the barrier and
 * the secondary minimum of a salted suspension lie) is inside the hard core:
 * the colloids would touch at the radius sigma_cc / 2, not R, silently.
 * Measuring the DLVO gaps from the hard-core surface instead would make the
 * charged colloid a sphere of 1.12 R, and sigma_cc = 2R would leave the
 * spurious depletion well uncompensated (PL Sec. III.C.1): none of these is
 * the stated suspension, so the front end refuses DLVO with the potential
 * coupling's wca term, naming the key that switched DLVO on.  What is
 * derived instead (src/mapping/mapping_colloids.c, when colloids.pairs is
 * not given): "dlvo, hertz, depletion_comp", the contact at 2R by Hertz
 * (Hecht Eq. 3, from the material constants) and PL's other remedy, the
 * compensating potential -Phi_depl of PL Eqs. 22-23 (approximate, as PL say:
 * tests/validation/test_coupling_depletion.c), so the colloids are spheres
 * of R: phi_c = phi and the DLVO gaps those of the stated surfaces. */
#include <jansson.h>
#include <math.h>
#include <stdio.h>

#include "peloid/colloid.h"
#include "peloid/mapping.h"
#include "peloid/scene.h"

#define OFF(m) offsetof(pl_scene_t, m)

/* The key that switched the DLVO term on: colloids.pairs where the file
 * gives it, else the physical key the derived pairs come from. */
static size_t dlvo_key(const pl_scene_t *s, const char **key)
{
    const size_t off[] = {OFF(colloids.pairs), OFF(mapping.physical.surface_potential), OFF(mapping.physical.hamaker)};
    const char *name[] = {"colloids.pairs", "physical.surface_potential", "physical.hamaker"};
    for (int i = 0; i < 3; ++i)
        if (pl_scene_line_of(s, off[i]) > 0) {
            *key = name[i];
            return off[i];
        }
    *key = name[0];
    return off[0];
}

int pl_mapping_potential_core(pl_scene_t *s, unsigned pairs, pl_err_t *err)
{
    pl_mapping_colloid_t *c = &s->mapping.colloid;
    const pl_mapping_t *m = &s->mapping.map;
    const double R = m->sigma; /* a0 */
    double core = R;           /* without the wca term: the contact repulsion at 2R */
    if (pairs & PL_CT_WCA) {
        pl_colloid_pair_params_t p = {0};
        pl_colloid_dlvo_info_t info = {0};
        (void)pl_colloid_term_setup_wca(s, &p, &info, err); /* sigma_cc by PL's rule, as the run sets it up */
        core = 0.5 * p.wca_sigma;
    }
    if ((pairs & PL_CT_WCA) && (pairs & PL_CT_DLVO)) {
        const char *key;
        const size_t off = dlvo_key(s, &key);
        return pl_scene_fail(s, err, off, key,
                             "switches the DLVO pair term on, but with coarse_graining.coupling = \"potential\" the "
                             "colloids repel by PL Eq. 16 with sigma_cc = %.4g R (PL's rule against spurious "
                             "depletion, Sec. III.C.1): DLVO gaps below %.4g m would be inside that hard core and the "
                             "colloids would touch at the radius %.4g m instead of R = %.4g m; allowed: colloids.pairs = "
                             "\"dlvo, hertz, depletion_comp\" (what the potential coupling derives with DLVO when "
                             "colloids.pairs is not given: the contact at 2R and PL's compensating depletion "
                             "potential), coarse_graining.coupling = \"I\" or \"II\", or no DLVO",
                             2.0 * core / R, (2.0 * core - 2.0 * R) * m->a0, core * m->a0, R * m->a0);
    }
    c->core_radius = core;
    c->phi_core = c->phi_realised * pow(core / R, 3.0);
    const double ratio = pow(core / R, 3.0); /* phi_c / phi */
    if (fabs(ratio - 1.0) > PL_CORE_PHI_TOL)
        pl_mapping_warn(&s->mapping.map, PL_SEV_WARNING, "HARD_CORE_PHI", c->phi_core,
                        "phi_c = %.4g of the colloids' hard cores (radius sigma_cc / 2 = %.4g R, PL Eq. 16 at PL's "
                        "sigma_cc rule, Sec. III.C.1) against the stated phi = %g: x %.3g; the colloids exclude "
                        "volume, collide and order (g(r), D(phi)) as spheres of %.4g R (coarse_graining.coupling = "
                        "\"potential\"); rule: |phi_c / phi - 1| > %g",
                        c->phi_core, core / R, c->phi_given, ratio, core / R, PL_CORE_PHI_TOL);
    return 0;
}

void pl_mapping_core_print(const pl_mapping_colloid_t *c, FILE *f)
{
    if (!(c->core_radius > 0)) return;
    fprintf(f, "           hard core: radius %.4g a0 = %.4g R (%s): phi_c = %.4g beside the stated phi = %g "
               "(realised %.5g)\n",
            c->core_radius, c->core_radius / c->radius,
            c->core_radius != c->radius ? "sigma_cc / 2 of PL Eq. 16 at PL's sigma_cc rule, PL Sec. III.C.1"
                                        : "no wca term: the contact at 2R",
            c->phi_core, c->phi_given, c->phi_realised);
}

void pl_mapping_core_json(const pl_mapping_colloid_t *c, json_t *o)
{
    if (!(c->core_radius > 0)) return;
    json_object_set_new(o, "hard_core_radius_a0", json_real(c->core_radius));
    json_object_set_new(o, "hard_core_radius_over_R", json_real(c->core_radius / c->radius));
    json_object_set_new(o, "volume_fraction_hard_core", json_real(c->phi_core));
}
