/* Printing the scene: the Markdown key reference (README), the effective
 * scene as libconfig text (echoed into every run's outputs) and as a JSON
 * object (summary.json). */
#include <stdio.h>
#include <string.h>

#include "json_build.h"
#include "peloid/scene.h"

static void default_text(const pl_key_t *k, char *buf, size_t n)
{
    switch (k->type) {
    case PL_KEY_INT: case PL_KEY_REAL: snprintf(buf, n, "%g", k->def); break;
    case PL_KEY_BOOL: snprintf(buf, n, "%s", k->def != 0 ? "true" : "false"); break;
    case PL_KEY_CHOICE: snprintf(buf, n, "\"%s\"", pl_key_choice_name(k, (int)k->def)); break;
    case PL_KEY_STRING: if (k->def_str && *k->def_str) snprintf(buf, n, "\"%s\"", k->def_str); else snprintf(buf, n, "(derived)"); break;
    case PL_KEY_INT3: case PL_KEY_REAL3: snprintf(buf, n, "[%g, %g, %g]", k->def, k->def, k->def); break;
    }
}

static const char *type_text(const pl_key_t *k)
{
    switch (k->type) {
    case PL_KEY_INT: return "integer";
    case PL_KEY_REAL: return "number";
    case PL_KEY_BOOL: return "bool";
    case PL_KEY_STRING: return "string";
    case PL_KEY_CHOICE: return "choice";
    case PL_KEY_INT3: return "3 integers";
    case PL_KEY_REAL3: return "3 numbers";
    }
    return "?";
}

void pl_scene_print_reference(void *file_ptr)
{
    FILE *f = file_ptr;
    size_t ns;
    const pl_section_t *const *all = pl_scene_sections(&ns);
    for (size_t j = 0; j < ns; ++j) {
        const pl_section_t *sec = all[j];
        fprintf(f, "\n#### `%s` — %s\n\n", *sec->name ? sec->name : "(top level)", sec->doc);
        fprintf(f, "| key | type | default | allowed | units | meaning |\n|---|---|---|---|---|---|\n");
        for (size_t i = 0; i < sec->nkeys; ++i) {
            const pl_key_t *k = &sec->keys[i];
            char def[96], allowed[1024];
            default_text(k, def, sizeof def);
            if (k->type == PL_KEY_CHOICE) {
                size_t len = 0;
                allowed[0] = '\0';
                for (int c = 0; k->choices[c] && len < sizeof allowed; ++c) /* snprintf truncates, never overruns */
                    len += (size_t)snprintf(allowed + len, sizeof allowed - len, "%s`%s`", c ? ", " : "",
                                            k->choices[c]);
            } else if (k->type == PL_KEY_BOOL || k->type == PL_KEY_STRING) {
                snprintf(allowed, sizeof allowed, "-");
            } else {
                snprintf(allowed, sizeof allowed, "%s %g, %s %g", (k->flags & PL_KEY_MIN_OPEN) ? ">" : "≥",
                         k->min, (k->flags & PL_KEY_MAX_OPEN) ? "<" : "≤", k->max);
            }
            fprintf(f, "| `%s` | %s | %s | %s | %s | %s |\n", k->name, type_text(k), def, allowed,
                    k->units, k->doc);
        }
    }
}

/* %.17g, with ".0" added to integral values so libconfig reads a float. */
static void print_real(FILE *f, double v)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%.17g", v);
    if (!strpbrk(buf, ".eni")) strcat(buf, ".0");
    fputs(buf, f);
}

static void print_value(FILE *f, const pl_key_t *k, const pl_scene_t *scene)
{
    const char *base = (const char *)scene + k->offset;
    switch (k->type) {
    case PL_KEY_INT: { /* L beyond 32 bits, as libconfig wants it */
        long long v = *(const long long *)base;
        fprintf(f, "%lld%s", v, v > 2147483647LL || v < -2147483648LL ? "L" : "");
        break;
    }
    case PL_KEY_REAL: print_real(f, *(const double *)base); break;
    case PL_KEY_BOOL: fprintf(f, "%s", *(const int *)base ? "true" : "false"); break;
    case PL_KEY_STRING: /* escaped, so that the echo loads back */
        fputc('"', f);
        for (const char *c = base; *c; ++c) {
            if (*c == '"' || *c == '\\') fputc('\\', f);
            fputc(*c, f);
        }
        fputc('"', f);
        break;
    case PL_KEY_CHOICE: fprintf(f, "\"%s\"", pl_key_choice_name(k, *(const int *)base)); break;
    case PL_KEY_INT3: {
        const int *v = (const int *)base;
        fprintf(f, "[%d, %d, %d]", v[0], v[1], v[2]);
        break;
    }
    case PL_KEY_REAL3: {
        const double *v = (const double *)base;
        for (int d = 0; d < 3; ++d) {
            fputs(d ? ", " : "[", f);
            print_real(f, v[d]);
        }
        fputs("]", f);
        break;
    }
    }
}

/* The value would load back: inside the key's allowed range (every
 * component of a triple), by the loader's own test. */
static int value_loads(const pl_key_t *k, const pl_scene_t *scene)
{
    const char *base = (const char *)scene + k->offset;
    switch (k->type) {
    case PL_KEY_INT: return pl_key_in_range(k, (double)*(const long long *)base);
    case PL_KEY_REAL: return pl_key_in_range(k, *(const double *)base);
    case PL_KEY_INT3:
        for (int d = 0; d < 3; ++d)
            if (!pl_key_in_range(k, ((const int *)base)[d])) return 0;
        return 1;
    case PL_KEY_REAL3:
        for (int d = 0; d < 3; ++d)
            if (!pl_key_in_range(k, ((const double *)base)[d])) return 0;
        return 1;
    default: return 1;
    }
}

/* Every key as `key = value;`.  A value outside the key's own range (a
 * physical scene's mapping writes one where the key has no use, e.g.
 * dlvo.kappa = 0 without DLVO, or derives a model value beyond what a file
 * may give, e.g. a Hertz constant of 8e34) is written as a comment: the
 * mapping derives it again when the echo loads, and the file still loads. */
void pl_scene_print(const pl_scene_t *scene, void *file_ptr)
{
    FILE *f = file_ptr;
    size_t ns;
    const pl_section_t *const *all = pl_scene_sections(&ns);
    for (size_t j = 0; j < ns; ++j) {
        const pl_section_t *sec = all[j];
        /* The physical front end is echoed only when the scene uses it. */
        if (!scene->mapping.enabled &&
            (sec == &pl_scene_section_physical || sec == &pl_scene_section_coarse_graining))
            continue;
        const char *indent = *sec->name ? "  " : "";
        if (*sec->name) fprintf(f, "%s: {\n", sec->name);
        for (size_t i = 0; i < sec->nkeys; ++i) {
            const int loads = value_loads(&sec->keys[i], scene);
            fprintf(f, "%s%s%s = ", indent, loads ? "" : "# ", sec->keys[i].name);
            print_value(f, &sec->keys[i], scene);
            fprintf(f, loads ? ";\n" : ";  (outside the key's range: derived, not given)\n");
        }
        if (*sec->name) fprintf(f, "};\n");
    }
}

static void put_value(pl_json_t *b, json_t *obj, const pl_key_t *k, const pl_scene_t *scene)
{
    const char *base = (const char *)scene + k->offset;
    json_t *a;
    switch (k->type) {
    case PL_KEY_INT: pl_json_int(b, obj, k->name, *(const long long *)base); return;
    case PL_KEY_REAL: pl_json_real(b, obj, k->name, *(const double *)base); return;
    case PL_KEY_BOOL: pl_json_set(b, obj, k->name, json_boolean(*(const int *)base)); return;
    case PL_KEY_STRING: pl_json_str(b, obj, k->name, base); return;
    case PL_KEY_CHOICE: pl_json_str(b, obj, k->name, pl_key_choice_name(k, *(const int *)base)); return;
    case PL_KEY_INT3:
        a = json_array();
        for (int d = 0; a && d < 3; ++d) json_array_append_new(a, json_integer(((const int *)base)[d]));
        pl_json_set(b, obj, k->name, a);
        return;
    case PL_KEY_REAL3: pl_json_reals(b, obj, k->name, (const double *)base, 3); return;
    }
}

int pl_scene_json(const pl_scene_t *scene, struct json_t **out, pl_err_t *err)
{
    pl_json_t b = {err, scene->path, "scene", 0};
    size_t ns;
    const pl_section_t *const *all = pl_scene_sections(&ns);
    json_t *root = json_object();
    for (size_t j = 0; j < ns; ++j) {
        const pl_section_t *sec = all[j];
        json_t *obj = *sec->name ? json_object() : root;
        for (size_t i = 0; i < sec->nkeys; ++i) {
            b.prefix = *sec->name ? sec->name : "scene";
            put_value(&b, obj, &sec->keys[i], scene);
        }
        if (*sec->name) pl_json_set(&b, root, sec->name, obj);
    }
    if (b.failed || !root) {
        json_decref(root);
        return b.failed ? err->code : pl_err_set(err, PL_ERR_NOMEM, "out of memory building JSON");
    }
    *out = root;
    return 0;
}
