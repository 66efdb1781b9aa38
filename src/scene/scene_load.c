/* Scene loading: libconfig file -> validated pl_scene_t.
 *
 * The file and its @include files are first expanded by src/scene/scene_text.c
 * (includes relative to the including file, inside the scene's directory
 * tree), then parsed by libconfig.  Every setting is matched against the
 * schema (scene_keys.c); unknown keys, wrong types and out-of-range values
 * are refused with "FILE:LINE: key 'section.key': problem; allowed: ...".
 * Integers are range-checked in 64 bits as written in the file (libconfig
 * 1.5 wraps values without the L suffix to 32 bits). */
#include <errno.h>
#include <libconfig.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "peloid/scene.h"
#include "scene_text.h"

static const char *type_name(int t)
{
    switch (t) {
    case CONFIG_TYPE_INT: case CONFIG_TYPE_INT64: return "integer";
    case CONFIG_TYPE_FLOAT: return "number";
    case CONFIG_TYPE_STRING: return "string";
    case CONFIG_TYPE_BOOL: return "boolean";
    case CONFIG_TYPE_ARRAY: return "array";
    case CONFIG_TYPE_LIST: return "list";
    case CONFIG_TYPE_GROUP: return "group";
    default: return "unknown";
    }
}

static const char *expected_name(pl_key_type_t t)
{
    switch (t) {
    case PL_KEY_INT: return "an integer";
    case PL_KEY_REAL: return "a number";
    case PL_KEY_BOOL: return "true or false";
    case PL_KEY_STRING: return "a string";
    case PL_KEY_CHOICE: return "a string";
    case PL_KEY_INT3: return "an array of 3 integers [a, b, c]";
    case PL_KEY_REAL3: return "an array of 3 numbers [a, b, c]";
    }
    return "?";
}

typedef struct {
    const pl_scene_text_t *text; /* expanded text: file and line of each setting */
    pl_err_t *err;
} ctx_t;

static int where_fail(const ctx_t *c, const config_setting_t *s, const char *sec,
                      const char *key, const char *what)
{
    int line;
    int fi = pl_scene_text_where(c->text, (int)config_setting_source_line(s), &line);
    return pl_err_set(c->err, PL_ERR_INPUT, "%s:%d: key '%s%s%s': %s", c->text->files[fi], line, sec,
                      *sec ? "." : "", key, what);
}

static void range_text(const pl_key_t *k, char *buf, size_t n)
{
    const char *lo = (k->flags & PL_KEY_MIN_OPEN) ? ">" : ">=";
    const char *hi = (k->flags & PL_KEY_MAX_OPEN) ? "<" : "<=";
    snprintf(buf, n, "%s %g and %s %g", lo, k->min, hi, k->max);
}

int pl_key_in_range(const pl_key_t *k, double v)
{
    if (!isfinite(v)) return 0;
    if ((k->flags & PL_KEY_MIN_OPEN) ? !(v > k->min) : !(v >= k->min)) return 0;
    if ((k->flags & PL_KEY_MAX_OPEN) ? !(v < k->max) : !(v <= k->max)) return 0;
    return 1;
}

static int is_number(int t) { return t == CONFIG_TYPE_INT || t == CONFIG_TYPE_INT64 || t == CONFIG_TYPE_FLOAT; }
static int is_integer(int t) { return t == CONFIG_TYPE_INT || t == CONFIG_TYPE_INT64; }

static double number_of(const config_setting_t *s)
{
    int t = config_setting_type(s);
    if (t == CONFIG_TYPE_FLOAT) return config_setting_get_float(s);
    return (double)config_setting_get_int64(s);
}

static int check_number(const ctx_t *c, const config_setting_t *s, const char *sec,
                        const pl_key_t *k, int elem, double v)
{
    if (pl_key_in_range(k, v)) return 0;
    char range[128], what[512], lit[64];
    range_text(k, range, sizeof range);
    if (isfinite(v) || pl_scene_text_token(c->text, (int)config_setting_source_line(s), config_setting_name(s),
                                           elem, lit, sizeof lit))
        snprintf(lit, sizeof lit, "%g", v);
    char el[32] = "";
    if (elem >= 0) snprintf(el, sizeof el, "element %d: ", elem);
    snprintf(what, sizeof what, "%svalue %s is out of range%s; allowed: %s%s%s%s", el, lit,
             isfinite(v) ? "" : " (not a finite double)", range,
             *k->units && strcmp(k->units, "-") ? " (" : "", strcmp(k->units, "-") ? k->units : "",
             *k->units && strcmp(k->units, "-") ? ")" : "");
    return where_fail(c, s, sec, k->name, what);
}

static void units_text(const pl_key_t *k, char *buf, size_t n)
{
    if (*k->units && strcmp(k->units, "-")) snprintf(buf, n, " (%s)", k->units);
    else buf[0] = '\0';
}

/* An integer setting (or element `elem` of an integer array) as written in
 * the file, range-checked in 64 bits. */
static int get_integer(const ctx_t *c, const config_setting_t *s, const config_setting_t *e, const char *sec,
                       const pl_key_t *k, int elem, long long *out)
{
    long long libval = config_setting_get_int64(e), v = libval;
    char lit[64], range[128], units[64], what[512];
    int rc = pl_scene_text_integer(c->text, (int)config_setting_source_line(s), config_setting_name(s), elem,
                                   libval, &v, lit, sizeof lit);
    snprintf(range, sizeof range, "%s %.0f and %s %.0f", (k->flags & PL_KEY_MIN_OPEN) ? ">" : ">=", k->min,
             (k->flags & PL_KEY_MAX_OPEN) ? "<" : "<=", k->max);
    units_text(k, units, sizeof units);
    char el[32] = "";
    if (elem >= 0) snprintf(el, sizeof el, "element %d: ", elem);
    if (rc == 1) {
        snprintf(what, sizeof what, "%svalue %s does not fit in a 64-bit integer; allowed: %s%s", el, lit, range,
                 units);
        return where_fail(c, s, sec, k->name, what);
    }
    if (rc < 0) snprintf(lit, sizeof lit, "%lld", libval);
    if (!pl_key_in_range(k, (double)v)) {
        snprintf(what, sizeof what, "%svalue %s is out of range; allowed: %s%s", el, lit, range, units);
        return where_fail(c, s, sec, k->name, what);
    }
    *out = v;
    return 0;
}

/* Scene names name the output directory out/<name>: a safe character set. */
static const char *bad_name(const char *v)
{
    if (!strcmp(v, ".") || !strcmp(v, "..")) return "is a directory reference";
    if (strspn(v, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789._-") != strlen(v))
        return "contains a character outside [A-Za-z0-9._-]";
    if (v[0] == '-') return "starts with '-'";
    return NULL;
}

static int apply_key(const ctx_t *c, const config_setting_t *s, const char *sec,
                     const pl_key_t *k, pl_scene_t *scene)
{
    char *base = (char *)scene + k->offset;
    int t = config_setting_type(s);
    char what[512];
    if (scene->norigin < PL_SCENE_MAX_KEYS) {
        scene->origin[scene->norigin].offset = k->offset;
        int line;
        scene->origin[scene->norigin].file = pl_scene_text_where(c->text, (int)config_setting_source_line(s), &line);
        scene->origin[scene->norigin].line = line;
        scene->norigin++;
    }
    int bad_type = 0;
    switch (k->type) {
    case PL_KEY_INT:
        if (!is_integer(t)) { bad_type = 1; break; }
        return get_integer(c, s, s, sec, k, -1, (long long *)base);
    case PL_KEY_REAL:
        if (!is_number(t)) { bad_type = 1; break; }
        {
            double v = number_of(s);
            if (check_number(c, s, sec, k, -1, v)) return PL_ERR_INPUT;
            *(double *)base = v;
        }
        return 0;
    case PL_KEY_BOOL:
        if (t != CONFIG_TYPE_BOOL) { bad_type = 1; break; }
        *(int *)base = config_setting_get_bool(s);
        return 0;
    case PL_KEY_STRING:
        if (t != CONFIG_TYPE_STRING) { bad_type = 1; break; }
        {
            const char *v = config_setting_get_string(s);
            const char *why = (k->flags & PL_KEY_SAFE_NAME) && *v ? bad_name(v) : NULL;
            if (why) {
                snprintf(what, sizeof what, "\"%.200s\" %s; allowed: letters, digits, '.', '_', '-' "
                         "(not \".\" or \"..\", not starting with '-')", v, why);
                return where_fail(c, s, sec, k->name, what);
            }
            if (strlen(v) >= 128 || strchr(v, '/')) {
                snprintf(what, sizeof what, "\"%.200s\" is %zu characters%s; allowed: a string shorter than 128 "
                         "characters without '/'", v, strlen(v), strchr(v, '/') ? " with '/'" : "");
                return where_fail(c, s, sec, k->name, what);
            }
            snprintf(base, 128, "%s", v);
        }
        return 0;
    case PL_KEY_CHOICE:
        if (t != CONFIG_TYPE_STRING) { bad_type = 1; break; }
        {
            const char *v = config_setting_get_string(s);
            for (int i = 0; k->choices[i]; ++i)
                if (!strcmp(v, k->choices[i])) { *(int *)base = (int)k->min + i; return 0; }
            size_t len = (size_t)snprintf(what, sizeof what, "unknown value \"%s\"; allowed:", v);
            for (int i = 0; k->choices[i] && len < sizeof what; ++i)
                len += (size_t)snprintf(what + len, sizeof what - len, " \"%s\"", k->choices[i]);
            return where_fail(c, s, sec, k->name, what);
        }
    case PL_KEY_INT3:
    case PL_KEY_REAL3:
        if ((t != CONFIG_TYPE_ARRAY && t != CONFIG_TYPE_LIST) || config_setting_length(s) != 3) {
            bad_type = 1;
            break;
        }
        for (int i = 0; i < 3; ++i) {
            const config_setting_t *e = config_setting_get_elem(s, (unsigned)i);
            int et = config_setting_type(e);
            if (k->type == PL_KEY_INT3 ? !is_integer(et) : !is_number(et)) {
                snprintf(what, sizeof what, "element %d is a %s; expected %s", i, type_name(et),
                         expected_name(k->type));
                return where_fail(c, s, sec, k->name, what);
            }
            if (k->type == PL_KEY_INT3) {
                long long v;
                if (get_integer(c, s, e, sec, k, i, &v)) return PL_ERR_INPUT;
                ((int *)base)[i] = (int)v; /* the schema bounds INT3 keys to int */
            } else {
                double v = number_of(e);
                if (check_number(c, s, sec, k, i, v)) return PL_ERR_INPUT;
                ((double *)base)[i] = v;
            }
        }
        return 0;
    }
    if (bad_type) {
        snprintf(what, sizeof what, "wrong type (%s); expected %s", type_name(t), expected_name(k->type));
        return where_fail(c, s, sec, k->name, what);
    }
    return 0;
}

static const pl_key_t *find_key(const pl_section_t *sec, const char *name)
{
    for (size_t i = 0; i < sec->nkeys; ++i)
        if (!strcmp(sec->keys[i].name, name)) return &sec->keys[i];
    return NULL;
}

static int unknown_key(const ctx_t *c, const config_setting_t *s, const char *sec,
                       const pl_section_t *known)
{
    char what[2048];
    size_t len = (size_t)snprintf(what, sizeof what, "unknown key; allowed here:");
    if (known) {
        for (size_t i = 0; i < known->nkeys && len < sizeof what; ++i)
            len += (size_t)snprintf(what + len, sizeof what - len, " %s", known->keys[i].name);
    }
    size_t ns;
    const pl_section_t *const *all = pl_scene_sections(&ns);
    if (!*sec) {
        for (size_t i = 1; i < ns && len < sizeof what; ++i)
            len += (size_t)snprintf(what + len, sizeof what - len, " %s{}", all[i]->name);
    }
    return where_fail(c, s, sec, config_setting_name(s) ? config_setting_name(s) : "?", what);
}

static int apply_section(const ctx_t *c, const config_setting_t *group, const pl_section_t *sec,
                         pl_scene_t *scene)
{
    int n = config_setting_length(group);
    for (int i = 0; i < n; ++i) {
        const config_setting_t *s = config_setting_get_elem(group, (unsigned)i);
        const pl_key_t *k = find_key(sec, config_setting_name(s));
        if (!k) return unknown_key(c, s, sec->name, sec);
        if (apply_key(c, s, sec->name, k, scene)) return PL_ERR_INPUT;
    }
    return 0;
}

static int apply_root(const ctx_t *c, const config_setting_t *root, pl_scene_t *scene)
{
    size_t ns;
    const pl_section_t *const *all = pl_scene_sections(&ns);
    int n = config_setting_length(root);
    for (int i = 0; i < n; ++i) {
        const config_setting_t *s = config_setting_get_elem(root, (unsigned)i);
        const char *name = config_setting_name(s);
        if (config_setting_type(s) == CONFIG_TYPE_GROUP) {
            const pl_section_t *sec = NULL;
            for (size_t j = 1; j < ns; ++j)
                if (!strcmp(all[j]->name, name)) sec = all[j];
            if (!sec) return unknown_key(c, s, "", all[0]);
            if (apply_section(c, s, sec, scene)) return PL_ERR_INPUT;
        } else {
            const pl_key_t *k = find_key(all[0], name);
            if (!k) return unknown_key(c, s, "", all[0]);
            if (apply_key(c, s, "", k, scene)) return PL_ERR_INPUT;
        }
    }
    return 0;
}

void pl_scene_defaults(pl_scene_t *scene)
{
    memset(scene, 0, sizeof *scene);
    size_t ns;
    const pl_section_t *const *all = pl_scene_sections(&ns);
    for (size_t j = 0; j < ns; ++j) {
        for (size_t i = 0; i < all[j]->nkeys; ++i) {
            const pl_key_t *k = &all[j]->keys[i];
            char *base = (char *)scene + k->offset;
            switch (k->type) {
            case PL_KEY_INT: *(long long *)base = (long long)k->def; break;
            case PL_KEY_REAL: *(double *)base = k->def; break;
            case PL_KEY_BOOL: case PL_KEY_CHOICE: *(int *)base = (int)k->def; break;
            case PL_KEY_STRING: snprintf(base, 128, "%s", k->def_str ? k->def_str : ""); break;
            case PL_KEY_INT3: for (int d = 0; d < 3; ++d) ((int *)base)[d] = (int)k->def; break;
            case PL_KEY_REAL3: for (int d = 0; d < 3; ++d) ((double *)base)[d] = k->def; break;
            }
        }
    }
}

static int default_name(pl_scene_t *scene, const char *label, pl_err_t *err)
{
    if (scene->run.name[0]) return 0;
    const char *slash = strrchr(label, '/');
    const char *b = slash ? slash + 1 : label;
    snprintf(scene->run.name, sizeof scene->run.name, "%s", b);
    char *dot = strrchr(scene->run.name, '.');
    if (dot && dot != scene->run.name) memset(dot, 0, sizeof scene->run.name - (size_t)(dot - scene->run.name));
    const char *why = strlen(b) >= sizeof scene->run.name ? "is 128 characters or longer" : bad_name(scene->run.name);
    if (why)
        return pl_err_set(err, PL_ERR_INPUT, "%s: key 'name' (default: the file name) \"%.200s\" %s; allowed: "
                          "letters, digits, '.', '_', '-'; set name = \"...\" in the scene", label,
                          scene->run.name, why);
    return 0;
}

static int load_text(const pl_scene_text_t *text, const char *label, const pl_mapping_calibration_t *calib, unsigned flags,
                     pl_scene_t *scene, pl_err_t *err)
{
    config_t cfg;
    config_init(&cfg);
    int rc = 0;
    if (config_read_string(&cfg, text->text) != CONFIG_TRUE) {
        int line;
        int fi = pl_scene_text_where(text, config_error_line(&cfg), &line);
        char src[80];
        int el = config_error_line(&cfg);
        if (el > (int)text->nlines) { /* libconfig met the end of the text */
            fi = pl_scene_text_where(text, (int)text->nlines, &line);
            rc = pl_err_set(err, PL_ERR_INPUT, "%s:%d: syntax error: %s at the end of the file; allowed: every "
                            "'{', '[', '(' closed", text->files[fi], line, config_error_text(&cfg));
        } else {
            pl_scene_text_line(text, el, src, sizeof src);
            rc = pl_err_set(err, PL_ERR_INPUT, "%s:%d: syntax error: %s in \"%s\"; allowed: settings "
                            "`key = value;` and groups `name: { ... };`", text->files[fi], line,
                            config_error_text(&cfg), src);
        }
    }
    if (!rc) {
        pl_scene_defaults(scene);
        snprintf(scene->path, sizeof scene->path, "%s", label);
        if (calib) scene->mapping.calib = *calib; /* the mapping (in validate) reads it */
        scene->mapping.provisional = (flags & PL_SCENE_PROVISIONAL) != 0;
        for (int i = 1; i < text->nfiles && i < PL_SCENE_MAX_FILES; ++i)
            snprintf(scene->include_path[i - 1], sizeof scene->include_path[i - 1], "%s", text->files[i]);
        ctx_t c = {text, err};
        if (apply_root(&c, config_root_setting(&cfg), scene) || default_name(scene, label, err)) rc = PL_ERR_INPUT;
    }
    config_destroy(&cfg);
    return rc;
}

int pl_scene_parse_calibrated(const char *path, unsigned flags, const pl_mapping_calibration_t *calib,
                              pl_scene_t *scene, pl_err_t *err)
{
    if (strlen(path) >= sizeof scene->path)
        return pl_err_set(err, PL_ERR_INPUT, "%.100s...: scene path longer than %zu characters", path,
                          sizeof scene->path - 1);
    pl_scene_text_t text;
    int rc = pl_scene_text_read(&text, path, (flags & PL_SCENE_INCLUDE_ANYWHERE) != 0, err);
    if (!rc) rc = load_text(&text, path, calib, flags, scene, err);
    pl_scene_text_free(&text);
    return rc;
}

int pl_scene_parse_string(const char *text, const char *label, pl_scene_t *scene, pl_err_t *err)
{
    pl_scene_text_t t;
    int rc = pl_scene_text_string(&t, text, label, err);
    if (!rc) rc = load_text(&t, label, NULL, 0, scene, err);
    pl_scene_text_free(&t);
    return rc;
}
