/* The physical front end of the scene: derived keys land in srd/fluid/box,
 * keys set twice are refused, inconsistent physical input gives a clear
 * error or a named warning, strict mode turns warnings into errors, and the
 * report prints text and JSON. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mapping_testutil.h"

#include "peloid/scene.h"

#define HECHT_PHYS                                                                                      \
    "physical: { radius = 0.4e-6; temperature = 300.0;" \
    " viscosity = 1.0e-6; gravity = 9.81; hamaker = 4.76e-20; primary_minimum = 0.008e-6; %s };\n"
#define HECHT_CG \
    "coarse_graining: { coupling = \"I\"; cell_size = 0.5; particles_per_cell = 2.5; mean_free_path = 0.6; md_dt = 2e-6; %s };\n"

static pl_scene_t *scene;
static pl_err_t err;

static void setup(void)
{
    scene = malloc(sizeof *scene);
    cr_assert_not_null(scene);
    memset(&err, 0, sizeof err);
}
static void teardown(void) { free(scene); }

static int load(const char *srd, const char *phys_extra, const char *cg_extra)
{
    char text[4096];
    int n = snprintf(text, sizeof text, "srd: { rule = \"hecht_axes\"; %s };\n", srd);
    char phys[512];
    snprintf(phys, sizeof phys, "%s%s", phys_extra,
             strstr(phys_extra, "density") ? "" : " particle_density = 3.9e3; solvent_density = 1.0e3;");
    n += snprintf(text + n, sizeof text - (size_t)n, HECHT_PHYS, phys);
    snprintf(text + n, sizeof text - (size_t)n, HECHT_CG, cg_extra);
    return pl_scene_load_string(text, "test.cfg", scene, &err);
}

TestSuite(mapping_scene, .init = setup, .fini = teardown);

Test(mapping_scene, derived_keys_land_in_scene)
{
    cr_assert_eq(load("", "box = [6.4e-6, 6.4e-6, 12.8e-6];", ""), 0, "%s", err.msg);
    cr_expect(scene->mapping.enabled);
    cr_expect_float_eq(scene->srd.dt, 0.6, 1e-15);
    cr_expect_float_eq(scene->fluid.density, 2.5, 1e-15);
    cr_expect_float_eq(scene->fluid.temperature, 1.0, 1e-15);
    cr_expect_eq(scene->box.cells[0], 32);
    cr_expect_eq(scene->box.cells[2], 64);
    EXPECT_PRINTED(scene->mapping.map.dt, 0.91e-3, 0.01e-3); /* Hecht: 0.91 ms */
    cr_expect_eq(scene->mapping.colloid.md_substeps, 456);
    EXPECT_REL(scene->mapping.colloid.radius, 2.0, 1e-12);   /* R = 2 a0 */
    /* A_H / kT is what the model keeps (Hecht Sec. VII.B). */
    EXPECT_REL(scene->mapping.colloid.hamaker, 4.76e-20 / (PL_KB * 300.0), 1e-12);
}

Test(mapping_scene, no_physical_section_is_untouched)
{
    cr_assert_eq(pl_scene_load_string("srd: { dt = 0.2; };", "t.cfg", scene, &err), 0, "%s", err.msg);
    cr_expect(!scene->mapping.enabled);
    cr_expect_float_eq(scene->srd.dt, 0.2, 1e-15);
}

Test(mapping_scene, derived_key_set_twice_is_refused)
{
    cr_expect_eq(load("dt = 0.1;", "", ""), PL_ERR_INPUT);
    cr_expect(strstr(err.msg, "test.cfg:1: key 'srd.dt'") && strstr(err.msg, "derived from physical"), "%s",
              err.msg);
    cr_expect_eq(pl_scene_load_string("fluid: { density = 4.0; };\nphysical: { radius = 1e-6; };", "t.cfg",
                                      scene, &err),
                 PL_ERR_INPUT);
    cr_expect(strstr(err.msg, "t.cfg:1: key 'fluid.density'"), "%s", err.msg);
}

Test(mapping_scene, negative_density_is_an_error)
{
    cr_expect_eq(load("", "particle_density = -3.9e3; solvent_density = 1e3;", ""), PL_ERR_INPUT);
    cr_expect(strstr(err.msg, "physical.particle_density") && strstr(err.msg, "out of range"), "%s", err.msg);
}

Test(mapping_scene, lighter_particle_with_gravity_is_an_error)
{
    /* rho_m < rho_w with gravity on: no sediment; Hecht Eq. 31 would give a
     * negative model gravity. */
    cr_expect_eq(load("", "particle_density = 3.9e3; solvent_density = 4.0e3;", ""), PL_ERR_INPUT);
    cr_expect(strstr(err.msg, "cream"), "%s", err.msg);
}

static int has_warning(const char *name)
{
    for (int i = 0; i < scene->mapping.map.nwarn; ++i)
        if (!strcmp(scene->mapping.map.warn[i].name, name)) return 1;
    return 0;
}

Test(mapping_scene, kappa_R_outside_dlvo_range_warns)
{
    /* 1/kappa = 0.2 um against R = 0.4 um: kappa R = 2 < 5. */
    cr_assert_eq(load("", "surface_potential = 0.05; kappa = 5e6;", ""), 0, "%s", err.msg);
    cr_expect(has_warning("DLVO_RANGE"));
    cr_assert_eq(load("", "surface_potential = 0.05; kappa = 1e9;", ""), 0, "%s", err.msg);
    cr_expect(!has_warning("DLVO_RANGE"));
    cr_expect_eq(load("", "surface_potential = 0.05;", ""), PL_ERR_INPUT); /* no screening given */
    cr_expect_eq(load("", "surface_potential = 0.05; kappa = 1e9; ionic_strength = 0.001;", ""), PL_ERR_INPUT);
    cr_expect(strstr(err.msg, "physical.kappa"), "%s", err.msg);
}

Test(mapping_scene, debye_hueckel)
{
    /* 1 mM 1:1 salt in water at 25 C: 1/kappa = 9.6 nm (0.304 nm / sqrt(I/M)). */
    double k = pl_mapping_debye_kappa(1e-3, 78.5, PL_KB * 298.15);
    EXPECT_PRINTED(1.0 / k, 9.6e-9, 0.1e-9);
}

Test(mapping_scene, strict_turns_warnings_into_errors)
{
    /* Hecht's coupling I has Kn = 0.3 and Sc = 0.42 (PL ranges: <= 0.05, >> 1). */
    cr_assert_eq(load("", "", ""), 0, "%s", err.msg);
    cr_expect(has_warning("KNUDSEN") && has_warning("SCHMIDT"));
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    cr_expect_eq(pl_mapping_report(scene, f, 0, 0, &err), 0);
    cr_expect_eq(pl_mapping_report(scene, f, 0, 1, &err), PL_ERR_INPUT);
    fclose(f);
    cr_expect(strstr(err.msg, "KNUDSEN"), "%s", err.msg);
    cr_expect(strstr(buf, "tau_P") && strstr(buf, "warning KNUDSEN"));
    free(buf);
    cr_expect_eq(load("", "", "strict = true;"), PL_ERR_INPUT);
    cr_expect(strstr(err.msg, "coarse_graining.strict") && strstr(err.msg, "KNUDSEN"), "%s", err.msg);
}

Test(mapping_scene, report_json)
{
    cr_assert_eq(load("", "", ""), 0, "%s", err.msg);
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    cr_expect_eq(pl_mapping_report(scene, f, 1, 0, &err), 0);
    fclose(f);
    cr_expect(buf[0] == '{' && strstr(buf, "\"hecht_times\"") && strstr(buf, "\"numbers\"") &&
              strstr(buf, "\"name\": \"KNUDSEN\""));
    free(buf);
}

Test(mapping_scene, coarse_graining_alone_is_an_error)
{
    cr_expect_eq(pl_scene_load_string("coarse_graining: { particles_per_cell = 5.0; };", "t.cfg", scene, &err),
                 PL_ERR_INPUT);
    cr_expect(strstr(err.msg, "physical"), "%s", err.msg);
}

Test(mapping_scene, echoed_scene_loads_back)
{
    cr_assert_eq(load("", "box = [6.4e-6, 6.4e-6, 12.8e-6];", ""), 0, "%s", err.msg);
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    pl_scene_print(scene, f);
    fclose(f);
    pl_scene_t *again = malloc(sizeof *again);
    cr_assert_eq(pl_scene_load_string(buf, "echo.cfg", again, &err), 0, "%s", err.msg);
    cr_expect_float_eq(again->srd.dt, scene->srd.dt, 0);
    cr_expect_eq(again->box.cells[2], 64);
    cr_expect_float_eq(again->mapping.map.dt, scene->mapping.map.dt, 1e-18);
    free(again);
    free(buf);
}
