/* Scene loading: defaults, every kind of bad input refused with
 * FILE:LINE: key '...': message (issue 2 "Bad input"). */
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>

#include "peloid/scene.h"

static pl_scene_t scene;
static pl_err_t err;

static int load(const char *text)
{
    memset(&err, 0, sizeof err);
    return pl_scene_load_string(text, "s.cfg", &scene, &err);
}

Test(scene, defaults_and_values)
{
    cr_assert_eq(load("name = \"x\";\nbox: { cells = [4, 5, 6]; };\nsrd: { alpha = 90; dt = 0.5; };\n"), 0,
                 "%s", err.msg);
    cr_assert_eq(scene.box.cells[1], 5);
    cr_assert_float_eq(scene.srd.alpha_deg, 90.0, 0.0);
    cr_assert_float_eq(scene.srd.dt, 0.5, 0.0);
    cr_assert_float_eq(scene.fluid.density, 5.0, 0.0); /* default */
    cr_assert_eq(scene.srd.grid_shift, 1);
    cr_assert_str_eq(scene.run.name, "x");
}

Test(scene, name_defaults_to_file_name)
{
    memset(&err, 0, sizeof err);
    cr_assert_eq(pl_scene_load_string("seed = 3;", "dir/my_scene.cfg", &scene, &err), 0);
    cr_assert_str_eq(scene.run.name, "my_scene");
}

static void expect_error(const char *text, const char *needle1, const char *needle2)
{
    cr_assert_eq(load(text), PL_ERR_INPUT, "accepted: %s", text);
    cr_assert(strstr(err.msg, needle1), "message '%s' lacks '%s'", err.msg, needle1);
    cr_assert(strstr(err.msg, needle2), "message '%s' lacks '%s'", err.msg, needle2);
}

Test(scene, unknown_key)
{
    expect_error("seed = 1;\nfluid: { densty = 5.0; };\n", "s.cfg:2: key 'fluid.densty'", "unknown key");
    expect_error("sead = 1;\n", "s.cfg:1: key 'sead'", "allowed here");
    expect_error("collider: { a = 1; };\n", "s.cfg:1: key 'collider'", "unknown key");
}

Test(scene, wrong_type)
{
    expect_error("\n\nfluid: { density = \"five\"; };\n", "s.cfg:3: key 'fluid.density'", "wrong type (string)");
    expect_error("box: { cells = [4, 4]; };\n", "key 'box.cells'", "array of 3 integers");
    expect_error("box: { cells = (4, \"a\", 4); };\n", "key 'box.cells'", "element 1 is a string");
    expect_error("box: { cells = [4, 4.5, 4]; };\n", "s.cfg:1", "mismatched element type"); /* libconfig */
    expect_error("steps = 10.5;\n", "key 'steps'", "expected an integer");
    expect_error("srd: { grid_shift = 1; };\n", "key 'srd.grid_shift'", "true or false");
}

Test(scene, out_of_range)
{
    expect_error("fluid: { density = -5.0; };\n", "s.cfg:1: key 'fluid.density'", "value -5 is out of range");
    expect_error("box: { cells = [8, 0, 8]; };\n", "key 'box.cells'", "value 0 is out of range");
    expect_error("srd: { dt = 0.0; };\n", "key 'srd.dt'", "> 0");
    expect_error("srd: { rule = \"spin\"; };\n", "key 'srd.rule'", "\"random_axis\" \"hecht_axes\"");
}

Test(scene, cross_key)
{
    expect_error("box: { cells = [8, 8, 1]; walls_z = \"noslip\"; };\n", "s.cfg:1: key 'box.cells'", "Lz >= 2");
    expect_error("box: { cells = [1, 1, 1]; };\nfluid: { density = 1.0; };\n", "s.cfg:2: key 'fluid.density'",
                 "at least 2");
}

Test(scene, syntax_error_and_missing_file)
{
    expect_error("\nfluid: { density = ; };\n", "s.cfg:2", "syntax error");
    memset(&err, 0, sizeof err);
    cr_assert_eq(pl_scene_load("/nonexistent/x.cfg", &scene, &err), PL_ERR_INPUT);
    cr_assert(strstr(err.msg, "/nonexistent/x.cfg: cannot open scene file"), "%s", err.msg);
}

/* The printed reference (README's scene section) against the loader: each
 * documented key with a documented default, written into a scene as the
 * reference prints it, is accepted in the section the reference names and
 * leaves the effective scene (pl_scene_print) exactly as the empty scene
 * has it.  A default shown with too few digits, a default applied somewhere
 * other than the key table, a default printed so that it does not load back
 * (a string without quotes, found by this test), or a key documented in the
 * wrong section fails.  physical{} and
 * coarse_graining{} are left out: their presence switches the unit mapping
 * on (tests/test_mapping_*.c). */
static char *effective(const char *text)
{
    if (load(text)) return NULL;
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    pl_scene_print(&scene, f);
    fclose(f);
    return buf;
}

Test(scene, reference_defaults_are_the_loaders_defaults)
{
    char *ref = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&ref, &len);
    pl_scene_print_reference(f);
    fclose(f);
    char *base = effective("");
    cr_assert(base, "empty scene refused: %s", err.msg);
    char section[64] = "";
    int checked = 0;
    for (char *line = strtok(ref, "\n"); line; line = strtok(NULL, "\n")) {
        if (!strncmp(line, "#### `", 6)) { /* #### `box` - ... or `(top level)` */
            char *e = strchr(line + 6, '`');
            snprintf(section, sizeof section, "%.*s", (int)(e - line - 6), line + 6);
            if (!strcmp(section, "(top level)")) section[0] = '\0';
            continue;
        }
        if (strncmp(line, "| `", 3) || !strcmp(section, "physical") || !strcmp(section, "coarse_graining")) continue;
        char key[64], type[32], def[128];
        if (sscanf(line, "| `%63[^`]` | %31[^|]| %127[^|]|", key, type, def) != 3) continue;
        for (char *t = def + strlen(def); t > def && t[-1] == ' ';) *--t = '\0';
        if (!strcmp(def, "(derived)") || !strcmp(def, "-") || !strcmp(def, "(none)") || !*def) continue;
        char text[512];
        if (*section) snprintf(text, sizeof text, "%s: { %s = %s; };\n", section, key, def);
        else snprintf(text, sizeof text, "%s = %s;\n", key, def);
        char *got = effective(text);
        if (!got) {
            cr_expect_fail("%s.%s = %s (documented default) refused: %s", section, key, def, err.msg);
            continue;
        }
        cr_expect_str_eq(got, base, "%s.%s = %s (documented default) changes the effective scene", section, key,
                         def);
        free(got);
        checked++;
    }
    cr_log_info("reference defaults: %d keys load back to the default scene", checked);
    cr_expect_gt(checked, 50, "only %d documented defaults checked", checked);
    free(base);
    free(ref);
}

Test(scene, printed_scene_loads_back_identically)
{
    cr_assert_eq(load("seed = 7;\nbox: { cells = [6, 7, 8]; walls_z = \"slip\"; };\n"
                      "fluid: { body_force = [0.001, 0.0, 0.0]; };\nthermostat: { type = \"heyes\"; };\n"),
                 0, "%s", err.msg);
    pl_scene_t first = scene;
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    pl_scene_print(&first, f);
    fclose(f);
    cr_assert_eq(load(buf), 0, "%s\n%s", err.msg, buf);
    cr_assert_eq(memcmp(&first.run, &scene.run, sizeof scene.run), 0);
    cr_assert_eq(memcmp(&first.box, &scene.box, sizeof scene.box), 0);
    cr_assert_eq(memcmp(&first.fluid, &scene.fluid, sizeof scene.fluid), 0);
    cr_assert_eq(memcmp(&first.thermostat, &scene.thermostat, sizeof scene.thermostat), 0);
    free(buf);
}

/* Issue 18: integers as written, in 64 bits (libconfig 1.5 alone wraps
 * 4294967296 to 0 when the L suffix is missing). */
Test(scene, integers_in_64_bits)
{
    cr_assert_eq(load("steps = 4294967296;\nseed = 4294967297;\n"), 0, "%s", err.msg);
    cr_expect_eq(scene.run.steps, 4294967296LL);
    cr_expect_eq(scene.run.seed, 4294967297LL);
    cr_assert_eq(load("seed = 0x100000001;\n"), 0, "%s", err.msg);
    cr_expect_eq(scene.run.seed, 4294967297LL);
    cr_assert_eq(load("steps = 2147483648L;\n"), 0, "%s", err.msg);
    cr_expect_eq(scene.run.steps, 2147483648LL);
    expect_error("box: { cells = [4294967328, 32, 32]; };", "s.cfg:1: key 'box.cells'", "4294967328");
    expect_error("colloids: { count = 4294967360; };", "colloids.count", "4294967360");
    expect_error("thermostat: { interval = -4294967295; };", "thermostat.interval", "-4294967295");
    expect_error("\nsteps = 99999999999999999999;", "s.cfg:2: key 'steps'", "99999999999999999999 does not fit");
}

Test(scene, names_are_safe)
{
    cr_assert_eq(load("name = \"run-1.a_b\";"), 0, "%s", err.msg);
    expect_error("name = \"..\";", "key 'name'", "\"..\"");
    expect_error("name = \"a/b\";", "key 'name'", "[A-Za-z0-9._-]");
    expect_error("name = \"a\\\"b\";", "key 'name'", "[A-Za-z0-9._-]");
}

Test(scene, strings_and_comments_closed)
{
    expect_error("seed = 1;\nname = \"abc;\nsteps = 2;\n", "s.cfg:2: key 'name'", "unterminated string");
    expect_error("seed = 1;\n/* open\nsteps = 2;\n", "s.cfg:2", "unterminated comment");
    expect_error("seed = 1;\nbox: { cells = [8, 8, 8];\n", "s.cfg:2", "end of the file");
}

Test(scene, include_is_checked)
{
    expect_error("@include \"/\"\n", "s.cfg:1", "is a directory");
    expect_error("seed = 1;\n@include \"/etc/hostname\"\n", "s.cfg:2", "outside");
    expect_error("@include \"no/such/file.cfg\"\n", "s.cfg:1", "No such file");
}
