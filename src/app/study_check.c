/* Checks of a study that read it whole (src/app/study.c reads it): no
 * point twice.  A grid value given twice on one axis, or two equal rows of
 * points{}, would run the same scene twice under two ids (twice the cost,
 * and a table whose rows look like independent samples); the study is
 * refused at load instead, naming the file, line, key and values.  And
 * every plot.y an observable that each point measures: a name no observer
 * writes is refused at load, one whose observer a point leaves off when the
 * points are checked (the names from the observer table,
 * pl_observe_named), so that a plot is never silently empty. */
#include <stdlib.h>
#include <string.h>

#include "peloid/observer.h"
#include "study_priv.h"

typedef struct {
    char *text; /* the point's values as scene text, '\x1f' between them */
    int k;
} row_t;

static int row_cmp(const void *a, const void *b)
{
    const row_t *x = a, *y = b;
    int c = strcmp(x->text, y->text);
    return c ? c : (x->k > y->k) - (x->k < y->k);
}

/* A grid: each axis's values distinct (then so are the points). */
static int grid_unique(const pl_study_t *st, pl_err_t *err)
{
    int stride = st->npoints;
    for (int a = 0; a < st->naxes; ++a) {
        stride /= st->ax[a].n; /* points between two values of axis a */
        for (int i = 1; i < st->ax[a].n; ++i)
            for (int j = 0; j < i; ++j) {
                char vi[256], vj[256], label[32], what[800];
                pl_study_value_text(st, i * stride, a, vi, sizeof vi);
                pl_study_value_text(st, j * stride, a, vj, sizeof vj);
                if (strcmp(vi, vj)) continue;
                snprintf(label, sizeof label, "grid.[%d]", a);
                snprintf(what, sizeof what, "\"%s\": value %.200s is given twice (values %d and %d), so every "
                         "point with it would run twice; allowed: each value once", st->ax[a].key, vi, j, i);
                return pl_study_fail_at(st, st->ax[a].values, err, label, what);
            }
    }
    return 0;
}

/* points{}: rows sorted by their text, equal neighbours refused. */
static int rows_unique(const pl_study_t *st, pl_err_t *err)
{
    int n = st->npoints, rc = 0;
    row_t *r = calloc((size_t)n, sizeof *r);
    if (!r) return pl_err_set(err, PL_ERR_NOMEM, "out of memory checking the study's points");
    for (int k = 0; !rc && k < n; ++k) {
        size_t cap = 256 * (size_t)st->naxes + 1, len = 0;
        r[k].k = k;
        r[k].text = malloc(cap);
        if (!r[k].text) rc = pl_err_set(err, PL_ERR_NOMEM, "out of memory checking the study's points");
        for (int a = 0; !rc && a < st->naxes; ++a) {
            pl_study_value_text(st, k, a, r[k].text + len, 256);
            len += strlen(r[k].text + len);
            r[k].text[len++] = '\x1f';
            r[k].text[len] = '\0';
        }
    }
    if (!rc) qsort(r, (size_t)n, sizeof *r, row_cmp);
    for (int i = 1; !rc && i < n; ++i) {
        if (strcmp(r[i - 1].text, r[i].text)) continue;
        char vals[600] = "", what[900];
        size_t len = 0;
        for (int a = 0; a < st->naxes && len < sizeof vals; ++a) {
            char v[256];
            pl_study_value_text(st, r[i].k, a, v, sizeof v);
            len += (size_t)snprintf(vals + len, sizeof vals - len, "%s%s = %.100s", a ? ", " : "", st->ax[a].key, v);
        }
        snprintf(what, sizeof what, "points %d and %d are the same (%s); allowed: each point once", r[i - 1].k,
                 r[i].k, vals);
        rc = pl_study_fail_at(st, config_setting_get_elem(st->rows, (unsigned)r[i].k), err, "points.values", what);
    }
    for (int k = 0; k < n; ++k) free(r[k].text);
    free(r);
    return rc;
}

int pl_study_check_unique(const pl_study_t *st, pl_err_t *err)
{
    return st->rows ? rows_unique(st, err) : grid_unique(st, err);
}

int pl_study_check_plot(const pl_study_t *st, const pl_scene_t *scene, int k, pl_err_t *err)
{
    const config_setting_t *y = st->plot ? config_setting_get_member(st->plot, "y") : NULL;
    if (!y) return 0;
    const int array = config_setting_type(y) == CONFIG_TYPE_ARRAY;
    for (int i = 0; i < (array ? config_setting_length(y) : 1); ++i) {
        const config_setting_t *v = array ? config_setting_get_elem(y, (unsigned)i) : y;
        const char *name = config_setting_get_string(v);
        char why[800], what[900];
        if (!name) return pl_study_fail_at(st, v, err, "plot.y", "expected an observable name (a string)");
        if (!pl_observe_named(scene, name, why, sizeof why)) continue;
        if (k < 0) snprintf(what, sizeof what, "%s", why);
        else snprintf(what, sizeof what, "point %d: %s", k, why);
        return pl_study_fail_at(st, v, err, "plot.y", what);
    }
    return 0;
}
