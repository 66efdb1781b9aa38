/* JSON documents through jansson: helpers that keep the first error (a
 * non-finite number, invalid UTF-8, out of memory) with the key it belongs
 * to, so that a writer builds the whole object and checks once. */
#include "json_build.h"

#include <math.h>

static void fail(pl_json_t *b, const char *key, const char *what)
{
    if (b->failed) return;
    b->failed = 1;
    pl_err_set(b->err, PL_ERR_INPUT, "%s: '%s%s%s' %s", b->where, b->prefix ? b->prefix : "",
               b->prefix && *b->prefix ? "." : "", key, what);
}

void pl_json_set(pl_json_t *b, json_t *obj, const char *key, json_t *v)
{
    if (!v) {
        if (!b->failed) {
            b->failed = 1;
            pl_err_set(b->err, PL_ERR_NOMEM, "%s: out of memory building JSON ('%s')", b->where, key);
        }
        return;
    }
    if (!obj || json_object_set_new(obj, key, v)) {
        if (obj) fail(b, key, "cannot be stored (invalid UTF-8 in the key?)");
        else json_decref(v);
    }
}

static void not_finite(pl_json_t *b, const char *key, double v)
{
    char what[128];
    snprintf(what, sizeof what, "= %g is not a finite number; allowed: inputs that give finite values", v);
    fail(b, key, what);
}

void pl_json_real(pl_json_t *b, json_t *obj, const char *key, double v)
{
    if (!isfinite(v)) not_finite(b, key, v);
    else pl_json_set(b, obj, key, json_real(v));
}

void pl_json_real_or_null(pl_json_t *b, json_t *obj, const char *key, double v)
{
    if (isnan(v)) pl_json_set(b, obj, key, json_null());
    else pl_json_real(b, obj, key, v);
}

void pl_json_int(pl_json_t *b, json_t *obj, const char *key, long long v)
{
    pl_json_set(b, obj, key, json_integer((json_int_t)v));
}

void pl_json_str(pl_json_t *b, json_t *obj, const char *key, const char *s)
{
    json_t *v = json_string(s);
    if (!v) fail(b, key, "is not valid UTF-8");
    else pl_json_set(b, obj, key, v);
}

void pl_json_reals(pl_json_t *b, json_t *obj, const char *key, const double *v, int n)
{
    json_t *a = json_array();
    for (int i = 0; a && i < n; ++i) {
        if (!isfinite(v[i])) {
            not_finite(b, key, v[i]);
            json_decref(a);
            return;
        }
        if (json_array_append_new(a, json_real(v[i]))) {
            json_decref(a);
            a = NULL;
        }
    }
    pl_json_set(b, obj, key, a);
}

int pl_json_dump(const json_t *doc, FILE *f, const char *name, pl_err_t *err)
{
    if (json_dumpf(doc, f, JSON_INDENT(2) | JSON_PRESERVE_ORDER | JSON_REAL_PRECISION(17)) || fputc('\n', f) == EOF)
        return pl_err_set(err, PL_ERR_IO, "%s: cannot write JSON", name);
    return 0;
}
