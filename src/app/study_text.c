/* The text forms of a study (src/app/study.c): errors at a setting's file
 * and line, a point's value of an axis, and a libconfig settings tree
 * written back as text (a point's scene), shared by the study's reader and
 * its checks (study_check.c). */
#include <libconfig.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/error.h"
#include "scene_text.h"
#include "study_priv.h"

/* "FILE:LINE: key 'KEY': WHAT" at setting s (NULL: line 1), PL_ERR_INPUT. */
int pl_study_fail_at(const pl_study_t *st, const config_setting_t *s, pl_err_t *err, const char *key,
                     const char *what)
{
    int line = 0, fi = pl_scene_text_where(&st->stext, s ? (int)config_setting_source_line(s) : 1, &line);
    return pl_err_set(err, PL_ERR_INPUT, "%s:%d: key '%s': %s", st->stext.files[fi], line, key, what);
}
/* Value setting of axis a at point k. */
const config_setting_t *pl_study_value_of(const pl_study_t *st, int k, int a)
{
    if (st->rows) return config_setting_get_elem(config_setting_get_elem(st->rows, (unsigned)k), (unsigned)a);
    int stride = 1;
    for (int i = st->naxes - 1; i > a; --i) stride *= st->ax[i].n;
    return config_setting_get_elem(st->ax[a].values, (unsigned)((k / stride) % st->ax[a].n));
}

/* ---- libconfig text of a settings tree ------------------------------- */

/* Shortest text that reads back as the same double, always with '.' or 'e'
 * so that libconfig keeps it a float. */
static void fmt_real(double v, char *b, size_t n)
{
    for (int p = 1; p <= 17; ++p) {
        snprintf(b, n, "%.*g", p, v);
        if (strtod(b, NULL) == v) break;
    }
    if (!strpbrk(b, ".eEni")) strncat(b, ".0", n - strlen(b) - 1);
}

/* The integer as written in `text` when the setting came from it (libconfig
 * 1.5 wraps literals without L to 32 bits), else libconfig's value. */
static long long int_of(const pl_scene_text_t *text, const config_setting_t *holder, const config_setting_t *e,
                        int elem)
{
    long long lib = config_setting_get_int64(e), v;
    char lit[64];
    int line = text ? (int)config_setting_source_line(holder) : 0;
    if (line > 0 && config_setting_name(holder) &&
        !pl_scene_text_integer(text, line, config_setting_name(holder), elem, lib, &v, lit, sizeof lit))
        return v;
    return lib;
}

static void write_scalar(FILE *f, const pl_scene_text_t *text, const config_setting_t *holder,
                         const config_setting_t *e, int elem)
{
    char b[64];
    switch (config_setting_type(e)) {
    case CONFIG_TYPE_INT: case CONFIG_TYPE_INT64: {
        long long v = int_of(text, holder, e, elem);
        fprintf(f, "%lld%s", v, v > 2147483647LL || v < -2147483648LL ? "L" : "");
        break;
    }
    case CONFIG_TYPE_FLOAT: fmt_real(config_setting_get_float(e), b, sizeof b); fputs(b, f); break;
    case CONFIG_TYPE_BOOL: fputs(config_setting_get_bool(e) ? "true" : "false", f); break;
    case CONFIG_TYPE_STRING:
        fputc('"', f);
        for (const unsigned char *c = (const unsigned char *)config_setting_get_string(e); *c; ++c) {
            if (*c == '"' || *c == '\\') fprintf(f, "\\%c", *c);
            else if (*c == '\n') fputs("\\n", f);
            else if (*c == '\t') fputs("\\t", f);
            else if (*c < 0x20 || *c == 0x7f) fprintf(f, "\\x%02x", *c);
            else fputc(*c, f);
        }
        fputc('"', f);
        break;
    default: break;
    }
}

/* A value: a scalar, or an array / list of values. */
static void write_value(FILE *f, const pl_scene_text_t *text, const config_setting_t *s)
{
    int t = config_setting_type(s);
    if (t == CONFIG_TYPE_ARRAY || t == CONFIG_TYPE_LIST) {
        fputs(t == CONFIG_TYPE_ARRAY ? "[" : "(", f);
        for (int i = 0; i < config_setting_length(s); ++i) {
            const config_setting_t *e = config_setting_get_elem(s, (unsigned)i);
            if (i) fputs(", ", f);
            if (config_setting_type(e) == CONFIG_TYPE_ARRAY || config_setting_type(e) == CONFIG_TYPE_LIST)
                write_value(f, NULL, e);
            else write_scalar(f, t == CONFIG_TYPE_ARRAY ? text : NULL, s, e, i);
        }
        fputs(t == CONFIG_TYPE_ARRAY ? "]" : ")", f);
    } else write_scalar(f, text, s, s, -1);
}

void pl_study_write_group(FILE *f, const pl_scene_text_t *text, const config_setting_t *g, int depth)
{
    for (int i = 0; i < config_setting_length(g); ++i) {
        const config_setting_t *s = config_setting_get_elem(g, (unsigned)i);
        fprintf(f, "%*s%s", 2 * depth, "", config_setting_name(s));
        if (config_setting_type(s) == CONFIG_TYPE_GROUP) {
            fputs(": {\n", f);
            pl_study_write_group(f, text, s, depth + 1);
            fprintf(f, "%*s};\n", 2 * depth, "");
        } else {
            fputs(" = ", f);
            write_value(f, text, s);
            fputs(";\n", f);
        }
    }
}

int pl_study_point_value(const pl_study_t *st, int k, int a, char *buf, size_t n)
{
    return pl_study_value_text(st, k / st->replicas, a, buf, n);
}

int pl_study_value_text(const pl_study_t *st, int k, int a, char *buf, size_t n)
{
    char *s = NULL;
    size_t len;
    FILE *f = open_memstream(&s, &len);
    if (!f) return -1;
    write_value(f, NULL, pl_study_value_of(st, k, a));
    if (fclose(f)) return -1;
    snprintf(buf, n, "%s", s);
    free(s);
    return 0;
}

void pl_study_plot_json(const pl_study_t *st, char *buf, size_t n)
{
    size_t len;
    char *s = NULL;
    FILE *f = open_memstream(&s, &len);
    if (!f) {
        snprintf(buf, n, "{}");
        return;
    }
    fputc('{', f);
    for (int j = 0; st->plot && j < config_setting_length(st->plot); ++j) {
        const config_setting_t *e = config_setting_get_elem(st->plot, (unsigned)j);
        fprintf(f, "%s\"%s\": ", j ? ", " : "", config_setting_name(e));
        if (config_setting_type(e) == CONFIG_TYPE_ARRAY) { /* strings: a JSON array */
            fputc('[', f);
            for (int i = 0; i < config_setting_length(e); ++i) {
                if (i) fputs(", ", f);
                write_scalar(f, NULL, e, config_setting_get_elem(e, (unsigned)i), i);
            }
            fputc(']', f);
        } else write_scalar(f, NULL, e, e, -1);
    }
    fputc('}', f);
    if (fclose(f)) snprintf(buf, n, "{}");
    else snprintf(buf, n, "%s", s);
    free(s);
}
