/* The observers' lengths of a physical scene (src/mapping/mapping_observe.c):
 * physical.clusters_gap in m gives observe.clusters_gap = gap / a0, sq_qmax
 * in 1/m gives q a0; a different model value beside it is refused naming
 * observe.clusters_gap; with neither given the gap cluster observer's bond
 * gap is derived from the DLVO potential: the pair energy is -E_c there and
 * above it everywhere beyond, inside the primary well (below the barrier)
 * when the secondary minimum is shallower than E_c, at the secondary well's
 * outer edge when it is deeper (polystyrene latex R = 0.5 um, -40 mV, at
 * 1 mM and 100 mM salt). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mapping_testutil.h"

#include "peloid/colloid.h"
#include "peloid/scene.h"

static pl_scene_t *scene;
static pl_err_t err;

static void setup(void)
{
    scene = malloc(sizeof *scene);
    cr_assert_not_null(scene);
    memset(&err, 0, sizeof err);
}
static void teardown(void) { free(scene); }

/* PS latex in water (issue 49's suspension), coupling II with its theory D. */
static int load(double salt, const char *phys_extra, const char *observe_extra)
{
    char text[2048];
    snprintf(text, sizeof text,
             "name = \"ps\"; steps = 100;\n"
             "physical: { radius = 0.5e-6; particle_density = 1050.0; hamaker = 1.0e-20; surface_potential = -0.04;\n"
             "  ionic_strength = %g; volume_fraction = 0.05; box = [6e-6, 6e-6, 6e-6]; young_modulus = 3.4e9;\n"
             "  poisson_ratio = 0.35; %s };\n"
             "coarse_graining: { coupling = \"II\"; };\n"
             "observe: { clusters_interval = 10; %s };\n",
             salt, phys_extra, observe_extra);
    return pl_scene_load_string(text, "ps.cfg", scene, &err);
}

TestSuite(mapping_observe, .init = setup, .fini = teardown);

Test(mapping_observe, si_gap_and_qmax_become_model_values)
{
    cr_assert_eq(load(1e-3, "clusters_gap = 20e-9; sq_qmax = 2e7; rdf_rmax = 3e-6;", ""), 0, "%s", err.msg);
    const double a0 = scene->mapping.map.a0;
    cr_assert(a0 > 1e-7 && a0 < 1e-5, "a0 = %g m", a0);
    EXPECT_REL(scene->observe.clusters_gap, 20e-9 / a0, 1e-12);
    EXPECT_REL(scene->observe.sq_qmax, 2e7 * a0, 1e-12);
    EXPECT_REL(scene->observe.rdf_rmax, 3e-6 / a0, 1e-12);
}

Test(mapping_observe, model_gap_beside_si_gap_is_refused)
{
    cr_assert_eq(load(1e-3, "clusters_gap = 20e-9;", "clusters_gap = 0.1;"), PL_ERR_INPUT);
    cr_expect(strstr(err.msg, "ps.cfg:") && strstr(err.msg, "key 'observe.clusters_gap'") &&
                  strstr(err.msg, "physical.clusters_gap"), "%s", err.msg);
    /* the same value both ways (an echoed scene) loads */
    cr_assert_eq(load(1e-3, "clusters_gap = 20e-9;", ""), 0, "%s", err.msg);
    char given[64];
    snprintf(given, sizeof given, "clusters_gap = %.17g;", scene->observe.clusters_gap);
    cr_expect_eq(load(1e-3, "clusters_gap = 20e-9;", given), 0, "%s", err.msg);
}

/* U(2R + h) at the derived gap is -E_c, and above -E_c on a fine scan from
 * there to the cut-off. */
static void expect_bond_edge(double *h_out, pl_colloid_dlvo_info_t *info)
{
    pl_colloid_pair_params_t p;
    cr_assert_eq(pl_colloid_pair_params(scene, &p, info, &err), 0, "%s", err.msg);
    const double R = scene->colloids.radius, h = scene->observe.clusters_gap, ec = scene->observe.clusters_energy;
    cr_assert(h > 0.0, "derived gap %g a0", h);
    cr_expect(fabs(pl_colloid_pair_energy(&p, 2.0 * R + h, R, R) + ec) < 1e-4 * ec + 1e-3,
              "U(h = %g) = %g, expected -%g", h, pl_colloid_pair_energy(&p, 2.0 * R + h, R, R), ec);
    const double hc = pl_colloid_pair_cutoff(&p, R) - 2.0 * R;
    for (int k = 1; k <= 20000; ++k) {
        double g = h + (hc - h) * k / 20000.0 + 1e-8 * R;
        if (pl_colloid_pair_energy(&p, 2.0 * R + g, R, R) <= -ec) {
            cr_expect(0, "U(%g) = %g <= -%g beyond the derived gap %g", g, pl_colloid_pair_energy(&p, 2.0 * R + g, R, R),
                      ec, h);
            break;
        }
    }
    *h_out = h;
}

Test(mapping_observe, derived_gap_stable_suspension_is_in_the_primary_well)
{
    cr_assert_eq(load(1e-3, "", ""), 0, "%s", err.msg);
    double h;
    pl_colloid_dlvo_info_t info;
    expect_bond_edge(&h, &info);
    /* 1 mM: a barrier of hundreds of kT, a secondary minimum shallower than 1 kT: bonded = in the primary well */
    cr_assert(isfinite(info.barrier_h) && info.barrier_u > 10.0, "barrier %g kT", info.barrier_u);
    cr_expect(!(info.secmin_u <= -1.0), "secondary minimum %g kT", info.secmin_u);
    cr_expect(h < info.barrier_h, "gap %g a0 beyond the barrier at %g a0", h, info.barrier_h);
    cr_expect(h * scene->mapping.map.a0 < 1e-9, "gap %g m: a stable suspension counts no bonds at tens of nm",
              h * scene->mapping.map.a0);
}

Test(mapping_observe, derived_gap_deep_secondary_minimum_is_its_outer_edge)
{
    cr_assert_eq(load(0.1, "", ""), 0, "%s", err.msg);
    double h;
    pl_colloid_dlvo_info_t info;
    expect_bond_edge(&h, &info);
    cr_assert(info.secmin_u < -1.0, "secondary minimum %g kT", info.secmin_u);
    cr_expect(h > info.secmin_h, "gap %g a0 inside the secondary minimum at %g a0", h, info.secmin_h);
}

Test(mapping_observe, given_model_gap_is_kept)
{
    cr_assert_eq(load(1e-3, "", "clusters_gap = 0.1;"), 0, "%s", err.msg);
    cr_expect_eq(scene->observe.clusters_gap, 0.1);
}
