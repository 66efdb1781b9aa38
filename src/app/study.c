/* Study files of `peloid sweep` (include/peloid/sweep.h): libconfig, read
 * through the scene loader's text layer (src/scene/scene_text.c: @include
 * relative to the study, every error with its file and line), so a study
 * reads like a scene:
 *
 *   name  = "kappa_psi";                 # default: the file name
 *   scene = "base.cfg";                  # base scene, relative to this file
 *   out   = "out/kappa_psi";             # default: out/<name>
 *   grid  = ( { key = "physical.kappa";            values = [1.4e8, 1.6e8]; },
 *             { key = "physical.surface_potential"; values = [0.02, 0.05]; } );
 *   # or an explicit list instead of grid:
 *   # points = { keys = ["physical.kappa", "seed"]; values = ( (1.4e8, 1), (1.6e8, 2) ); };
 *   plot  = { x = "physical.kappa"; y = ["rdf_peak"]; series = "physical.surface_potential"; };
 *   replicas = 3;                        # each point 3 times, seeds seed + 0, 1, 2
 *
 * A point's scene is the base scene's settings (its @include files
 * expanded) with the point's keys set, written back as libconfig text; the
 * scene loader then checks it like any scene.  Grid points run with the last
 * key fastest.
 *
 * Replicas: with replicas = N > 1 the sweep's runs are the points times N,
 * run k being replica r = k % N of point k / N, id pPPPrR, its scene the
 * point's with seed = S + r (S: the base scene's seed, its default when
 * unset); a swept seed is refused beside it (two sources of seeds).  The
 * runs go through the sweep's plan like any points; the collect step pools
 * the replicas of each point (tools/sweep_collect.py). */
#include <ctype.h>
#include <limits.h>
#include <libconfig.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/io.h"
#include "peloid/run.h"
#include "peloid/scene.h"
#include "peloid/sweep.h"
#include "scene_text.h"
#include "study_priv.h"

#define fail_at pl_study_fail_at
#define value_of pl_study_value_of

static int safe_name(const char *s)
{
    if (!*s || strlen(s) >= 100) return 0;
    for (; *s; ++s)
        if (!isalnum((unsigned char)*s) && !strchr("._-", *s)) return 0;
    return 1;
}

/* A scene key of the schema ("section.key", or "key" of the top level). */
static int scene_key(const char *path, axis_t *a)
{
    const char *dot = strchr(path, '.');
    size_t ls = dot ? (size_t)(dot - path) : 0;
    const char *leaf = dot ? dot + 1 : path;
    if (ls >= sizeof a->sec || strlen(leaf) >= sizeof a->leaf || strchr(leaf, '.')) return 0;
    size_t ns;
    const pl_section_t *const *all = pl_scene_sections(&ns);
    for (size_t j = 0; j < ns; ++j) {
        if (strlen(all[j]->name) != ls || strncmp(all[j]->name, path, ls)) continue;
        for (size_t i = 0; i < all[j]->nkeys; ++i)
            if (!strcmp(all[j]->keys[i].name, leaf)) {
                snprintf(a->sec, sizeof a->sec, "%.*s", (int)ls, path);
                snprintf(a->leaf, sizeof a->leaf, "%s", leaf);
                snprintf(a->key, sizeof a->key, "%s", path);
                return 1;
            }
    }
    return 0;
}

static int is_value(const config_setting_t *v)
{
    int t = config_setting_type(v);
    return t != CONFIG_TYPE_GROUP && t != CONFIG_TYPE_LIST;
}

static const char *string_of(const pl_study_t *st, const config_setting_t *root, const char *key, pl_err_t *err,
                             int *rc)
{
    config_setting_t *s = config_setting_get_member(root, key);
    if (!s) return NULL;
    if (config_setting_type(s) != CONFIG_TYPE_STRING) *rc = fail_at(st, s, err, key, "expected a string");
    return *rc ? NULL : config_setting_get_string(s);
}

static int add_axis(pl_study_t *st, const config_setting_t *where, const char *key, const char *label,
                    pl_err_t *err)
{
    char what[512];
    if (st->naxes >= PL_STUDY_MAX_AXES) {
        snprintf(what, sizeof what, "more than %d swept keys; allowed: at most %d", PL_STUDY_MAX_AXES,
                 PL_STUDY_MAX_AXES);
        return fail_at(st, where, err, label, what);
    }
    axis_t *a = &st->ax[st->naxes];
    memset(a, 0, sizeof *a);
    if (!scene_key(key, a)) {
        snprintf(what, sizeof what, "\"%.128s\" is not a scene key; allowed: a key of `peloid keys` as "
                 "section.key (e.g. physical.kappa) or a top-level key (seed, steps)", key);
        return fail_at(st, where, err, label, what);
    }
    if (!strcmp(a->key, "name")) { /* not physics: the sweep names each point STUDY-ID itself */
        snprintf(what, sizeof what, "\"name\" names the run, it is not swept (each point is named "
                 "<study>-<id>); allowed: a scene key of the physics or the run (seed, steps, section.key)");
        return fail_at(st, where, err, label, what);
    }
    for (int i = 0; i < st->naxes; ++i)
        if (!strcmp(st->ax[i].key, a->key)) {
            snprintf(what, sizeof what, "\"%s\" is swept twice; allowed: each key once", key);
            return fail_at(st, where, err, label, what);
        }
    a->line = (int)config_setting_source_line(where);
    st->naxes++;
    return 0;
}

static int read_grid(pl_study_t *st, config_setting_t *grid, pl_err_t *err)
{
    int n = config_setting_length(grid);
    if (config_setting_type(grid) != CONFIG_TYPE_LIST || n == 0)
        return fail_at(st, grid, err, "grid", "expected a non-empty list ( { key = \"...\"; values = [...]; }, ... )");
    long long points = 1;
    for (int i = 0; i < n; ++i) {
        config_setting_t *g = config_setting_get_elem(grid, (unsigned)i);
        char label[64];
        snprintf(label, sizeof label, "grid.[%d]", i);
        if (config_setting_type(g) != CONFIG_TYPE_GROUP)
            return fail_at(st, g, err, label, "expected a group { key = \"...\"; values = [...]; }");
        for (int j = 0; j < config_setting_length(g); ++j) {
            const char *m = config_setting_name(config_setting_get_elem(g, (unsigned)j));
            if (strcmp(m, "key") && strcmp(m, "values")) {
                char what[256];
                snprintf(what, sizeof what, "unknown key '%s'; allowed: key, values", m);
                return fail_at(st, config_setting_get_elem(g, (unsigned)j), err, label, what);
            }
        }
        config_setting_t *k = config_setting_get_member(g, "key"), *v = config_setting_get_member(g, "values");
        if (!k || config_setting_type(k) != CONFIG_TYPE_STRING)
            return fail_at(st, k ? k : g, err, label, "key: expected a string naming a scene key");
        int rc = add_axis(st, k, config_setting_get_string(k), label, err);
        if (rc) return rc;
        int t = v ? config_setting_type(v) : CONFIG_TYPE_NONE;
        int nv = v ? config_setting_length(v) : 0;
        if ((t != CONFIG_TYPE_ARRAY && t != CONFIG_TYPE_LIST) || nv == 0)
            return fail_at(st, v ? v : g, err, label, "values: expected a non-empty array [a, b, ...] or list "
                           "(a, b, ...); an empty grid runs nothing");
        for (int j = 0; j < nv; ++j)
            if (!is_value(config_setting_get_elem(v, (unsigned)j)))
                return fail_at(st, v, err, label, "values: expected numbers, strings, booleans or arrays");
        st->ax[st->naxes - 1].values = v;
        st->ax[st->naxes - 1].n = nv;
        st->ax[st->naxes - 1].line = (int)config_setting_source_line(v);
        points *= nv;
        if (points > PL_STUDY_MAX_POINTS) {
            char what[128];
            snprintf(what, sizeof what, "more than %d points; allowed: at most %d", PL_STUDY_MAX_POINTS,
                     PL_STUDY_MAX_POINTS);
            return fail_at(st, v, err, label, what);
        }
    }
    st->npoints = (int)points;
    return 0;
}

static int read_points(pl_study_t *st, config_setting_t *p, pl_err_t *err)
{
    config_setting_t *k = config_setting_get_member(p, "keys"), *v = config_setting_get_member(p, "values");
    if (config_setting_type(p) != CONFIG_TYPE_GROUP || !k || !v || config_setting_length(p) != 2 ||
        config_setting_type(k) != CONFIG_TYPE_ARRAY || config_setting_length(k) == 0 ||
        config_setting_type(v) != CONFIG_TYPE_LIST || config_setting_length(v) == 0)
        return fail_at(st, p, err, "points", "expected { keys = [\"a.b\", ...]; values = ( (va, ...), ... ); } "
                       "with at least one key and one point");
    for (int i = 0; i < config_setting_length(k); ++i) {
        const char *key = config_setting_get_string_elem(k, i);
        if (!key) return fail_at(st, k, err, "points.keys", "expected strings naming scene keys");
        int rc = add_axis(st, k, key, "points.keys", err);
        if (rc) return rc;
    }
    int n = config_setting_length(v);
    if (n > PL_STUDY_MAX_POINTS) return fail_at(st, v, err, "points.values", "too many points; allowed: 100000");
    for (int i = 0; i < n; ++i) {
        config_setting_t *row = config_setting_get_elem(v, (unsigned)i);
        int t = config_setting_type(row);
        if ((t != CONFIG_TYPE_LIST && t != CONFIG_TYPE_ARRAY) || config_setting_length(row) != st->naxes) {
            char what[256];
            snprintf(what, sizeof what, "point %d: expected a list of %d values (one per key)", i, st->naxes);
            return fail_at(st, row, err, "points.values", what);
        }
        for (int j = 0; j < st->naxes; ++j)
            if (!is_value(config_setting_get_elem(row, (unsigned)j)))
                return fail_at(st, row, err, "points.values", "expected numbers, strings, booleans or arrays");
    }
    for (int j = 0; j < st->naxes; ++j) st->ax[j].line = (int)config_setting_source_line(v);
    st->rows = v;
    st->npoints = n;
    return 0;
}

static int read_plot(pl_study_t *st, config_setting_t *p, pl_err_t *err)
{
    if (config_setting_type(p) != CONFIG_TYPE_GROUP) return fail_at(st, p, err, "plot", "expected a group");
    for (int j = 0; j < config_setting_length(p); ++j) {
        config_setting_t *s = config_setting_get_elem(p, (unsigned)j);
        const char *m = config_setting_name(s);
        char key[80], what[512];
        snprintf(key, sizeof key, "plot.%s", m);
        int t = config_setting_type(s);
        if (!strcmp(m, "x") || !strcmp(m, "series")) {
            const char *v = t == CONFIG_TYPE_STRING ? config_setting_get_string(s) : NULL;
            int found = 0;
            for (int i = 0; v && i < st->naxes; ++i) found |= !strcmp(v, st->ax[i].key);
            if (!found) {
                snprintf(what, sizeof what, "expected a string naming a swept key (%s%s)", st->ax[0].key,
                         st->naxes > 1 ? ", ..." : "");
                return fail_at(st, s, err, key, what);
            }
        } else if (!strcmp(m, "y")) {
            int ok = t == CONFIG_TYPE_STRING || (t == CONFIG_TYPE_ARRAY && config_setting_length(s) > 0 &&
                                                 config_setting_get_string_elem(s, 0));
            if (!ok) return fail_at(st, s, err, key, "expected an observable name or an array of them "
                                    "(summary.json \"observables\", e.g. \"colloid_D\")");
        } else if (!strcmp(m, "logx") || !strcmp(m, "logy")) {
            if (t != CONFIG_TYPE_BOOL) return fail_at(st, s, err, key, "expected true or false");
        } else {
            snprintf(what, sizeof what, "unknown key; allowed: x, y, series, logx, logy");
            return fail_at(st, s, err, key, what);
        }
    }
    st->plot = p;
    return 0;
}

/* replicas = N: an integer >= 1, the runs in all within PL_STUDY_MAX_POINTS,
 * and no swept seed (the replicas' seeds are the base scene's seed + r). */
static int read_replicas(pl_study_t *st, const config_setting_t *s, pl_err_t *err)
{
    char what[512], v[80];
    int t = config_setting_type(s);
    long long n = t == CONFIG_TYPE_INT || t == CONFIG_TYPE_INT64 ? config_setting_get_int64(s) : 0;
    long long most = PL_STUDY_MAX_POINTS / st->npoints;
    if (t == CONFIG_TYPE_INT || t == CONFIG_TYPE_INT64) snprintf(v, sizeof v, "%lld", n);
    else if (t == CONFIG_TYPE_FLOAT) snprintf(v, sizeof v, "%g", config_setting_get_float(s));
    else if (t == CONFIG_TYPE_STRING) snprintf(v, sizeof v, "\"%.64s\"", config_setting_get_string(s));
    else snprintf(v, sizeof v, "(not a number)");
    if (n < 1 || n > most) {
        snprintf(what, sizeof what, "value %s; allowed: an integer from 1 to %lld (each point run that many "
                 "times, at most %d runs in all)", v, most, PL_STUDY_MAX_POINTS);
        return fail_at(st, s, err, "replicas", what);
    }
    for (int a = 0; a < st->naxes; ++a)
        if (!strcmp(st->ax[a].key, "seed")) {
            int line = 0, fi = pl_scene_text_where(&st->stext, st->ax[a].line, &line);
            snprintf(what, sizeof what, "replicas = %lld with \"seed\" swept (%.200s:%d); allowed: one of them, "
                     "not both (replica r runs the base scene's seed + r)", n, st->stext.files[fi], line);
            return fail_at(st, s, err, "replicas", what);
        }
    st->replicas = (int)n;
    return 0;
}

static int read_study(pl_study_t *st, pl_err_t *err)
{
    config_setting_t *root = config_root_setting(&st->scfg);
    static const char *const known[] = {"name", "scene", "out", "grid", "points", "plot", "replicas", NULL};
    for (int j = 0; j < config_setting_length(root); ++j) {
        config_setting_t *s = config_setting_get_elem(root, (unsigned)j);
        int ok = 0;
        for (int i = 0; known[i]; ++i) ok |= !strcmp(known[i], config_setting_name(s));
        if (!ok)
            return fail_at(st, s, err, config_setting_name(s), "unknown study key; allowed: name, scene, out, "
                           "grid, points, plot, replicas");
    }
    int rc = 0;
    const char *name = string_of(st, root, "name", err, &rc), *scene = NULL, *out = NULL;
    if (!rc) scene = string_of(st, root, "scene", err, &rc);
    if (!rc) out = string_of(st, root, "out", err, &rc);
    if (rc) return rc;
    if (name && !safe_name(name))
        return fail_at(st, config_setting_get_member(root, "name"), err, "name", "expected letters, digits, "
                       "'.', '_', '-' (under 100 characters)");
    if (name) snprintf(st->name, sizeof st->name, "%s", name);
    else {
        const char *b = strrchr(st->path, '/');
        snprintf(st->name, sizeof st->name, "%.99s", b ? b + 1 : st->path);
        char *dot = strrchr(st->name, '.');
        if (dot && dot != st->name) *dot = '\0';
        if (!safe_name(st->name))
            return pl_err_set(err, PL_ERR_INPUT, "%s: key 'name' (default: the file name) \"%s\" is not a "
                              "name; allowed: letters, digits, '.', '_', '-'; set name = \"...\"", st->path, st->name);
    }
    if (!scene) return fail_at(st, NULL, err, "scene", "missing; allowed: scene = \"BASE.cfg\" (relative to the study)");
    pl_path_beside(st->base, sizeof st->base, st->path, scene);
    if (out && !*out) return fail_at(st, config_setting_get_member(root, "out"), err, "out", "empty; allowed: a directory");
    if (out) snprintf(st->out, sizeof st->out, "%s", out);
    else snprintf(st->out, sizeof st->out, "out/%s", st->name);
    config_setting_t *grid = config_setting_get_member(root, "grid"), *pts = config_setting_get_member(root, "points");
    config_setting_t *replicas = config_setting_get_member(root, "replicas");
    if (grid && pts) return fail_at(st, pts, err, "points", "given with grid; allowed: grid or points, not both");
    if (!grid && !pts && !replicas)
        return fail_at(st, NULL, err, "grid", "missing; allowed: grid = ( { key = \"...\"; values = [...]; } ), "
                       "points = { keys = [...]; values = ( (...), ... ); }, or replicas = N alone (the base scene "
                       "N times)");
    if (grid || pts) rc = grid ? read_grid(st, grid, err) : read_points(st, pts, err);
    else st->npoints = 1; /* the base scene alone: its replicas */
    if (!rc) rc = pl_study_check_unique(st, err);
    config_setting_t *plot = config_setting_get_member(root, "plot");
    if (!rc && plot) rc = read_plot(st, plot, err);
    if (!rc && plot) rc = pl_study_check_plot(st, NULL, -1, err);
    if (!rc && replicas) rc = read_replicas(st, replicas, err);
    if (!rc && !grid && !pts && st->replicas < 2)
        rc = fail_at(st, replicas, err, "replicas", "1 without grid or points runs the base scene once; allowed: "
                     "replicas = N > 1 alone, or a grid or points");
    return rc;
}

/* Reads the study at `path`, or, when `text` is given, the study `text`
 * labelled `path` (pl_study_of_scene). */
static int study_load(const char *path, const char *text, pl_study_t **out, pl_err_t *err)
{
    *out = NULL;
    pl_study_t *st = calloc(1, sizeof *st);
    if (!st) return pl_err_set(err, PL_ERR_NOMEM, "out of memory reading the study");
    snprintf(st->path, sizeof st->path, "%s", path);
    st->replicas = 1;
    int rc = text ? pl_scene_text_string(&st->stext, text, path, err) : pl_scene_text_read(&st->stext, path, 0, err);
    if (!rc) {
        config_init(&st->scfg);
        st->have_s = 1;
        if (config_read_string(&st->scfg, st->stext.text) != CONFIG_TRUE) {
            int line;
            int fi = pl_scene_text_where(&st->stext, config_error_line(&st->scfg), &line);
            rc = pl_err_set(err, PL_ERR_INPUT, "%s:%d: syntax error: %s; allowed: settings `key = value;`",
                            st->stext.files[fi], line, config_error_text(&st->scfg));
        }
    }
    if (!rc) rc = read_study(st, err);
    pl_scene_t *scene = rc ? NULL : malloc(sizeof *scene);
    if (!rc && !scene) rc = pl_err_set(err, PL_ERR_NOMEM, "out of memory reading the study");
    if (!rc) rc = pl_scene_load(st->base, scene, err); /* the base scene alone: the loader's message */
    if (!rc) st->seed0 = scene->run.seed;
    if (!rc && text && safe_name(scene->run.name)) { /* a scene's replicas: named, and written, as its run */
        snprintf(st->name, sizeof st->name, "%s", scene->run.name);
        if (!config_setting_get_member(config_root_setting(&st->scfg), "out"))
            snprintf(st->out, sizeof st->out, "out/%s", st->name);
    }
    free(scene);
    if (!rc) rc = pl_scene_text_read(&st->btext, st->base, 0, err);
    if (!rc) {
        config_init(&st->bcfg);
        st->have_b = 1;
        if (config_read_string(&st->bcfg, st->btext.text) != CONFIG_TRUE)
            rc = pl_err_set(err, PL_ERR_INPUT, "%s: base scene does not parse", st->base);
    }
    if (rc) {
        pl_study_free(st);
        return rc;
    }
    *out = st;
    return 0;
}

int pl_study_load(const char *path, pl_study_t **out, pl_err_t *err) { return study_load(path, NULL, out, err); }

int pl_study_of_scene(const char *scene, int replicas, const char *out_dir, pl_study_t **out, pl_err_t *err)
{
    const char *base = strrchr(scene, '/');
    char text[5 * PATH_MAX], q[2][2 * PATH_MAX + 1];
    const char *raw[2] = {base ? base + 1 : scene, out_dir ? out_dir : ""};
    for (int i = 0; i < 2; ++i) { /* libconfig strings: \ and \" escaped */
        size_t n = 0;
        for (const char *c = raw[i]; *c && n + 2 < sizeof q[i]; ++c) {
            if (*c == '"' || *c == '\\') q[i][n++] = '\\';
            q[i][n++] = *c;
        }
        q[i][n] = '\0';
    }
    snprintf(text, sizeof text, "scene = \"%s\";\n%s%s%sreplicas = %d;\n", q[0], out_dir ? "out = \"" : "",
             out_dir ? q[1] : "", out_dir ? "\";\n" : "", replicas);
    return study_load(scene, text, out, err);
}

int pl_study_scene_with(const char *scene, int n, const char *const *keys, const char *const *values, char **text,
                        pl_err_t *err)
{
    const char *base = strrchr(scene, '/');
    char study[2048], k[640] = "", v[640] = "";
    for (int i = 0; i < n; ++i) {
        size_t lk = strlen(k), lv = strlen(v);
        snprintf(k + lk, sizeof k - lk, "%s\"%.100s\"", i ? ", " : "", keys[i]);
        snprintf(v + lv, sizeof v - lv, "%s%.200s", i ? ", " : "", values[i]);
    }
    snprintf(study, sizeof study, "scene = \"%.400s\";\npoints = { keys = [%s]; values = ( (%s) ); };\n",
             base ? base + 1 : scene, k, v);
    pl_study_t *st = NULL;
    int rc = study_load(scene, study, &st, err);
    if (!rc) rc = pl_study_point_scene(st, 0, NULL, text, err);
    pl_study_free(st);
    return rc;
}

void pl_study_free(pl_study_t *st)
{
    if (!st) return;
    if (st->have_s) config_destroy(&st->scfg);
    if (st->have_b) config_destroy(&st->bcfg);
    pl_scene_text_free(&st->stext);
    pl_scene_text_free(&st->btext);
    free(st);
}

int pl_study_npoints(const pl_study_t *st) { return st->npoints * st->replicas; }
int pl_study_replicas(const pl_study_t *st) { return st->replicas; }
long long pl_study_seed(const pl_study_t *st, int k) { return st->seed0 + k % st->replicas; }

void pl_study_point_id(const pl_study_t *st, int k, char *buf, size_t n)
{
    int w = 3;
    for (int m = st->npoints - 1; m >= 1000; m /= 10) ++w;
    int len = st->replicas > 1 ? snprintf(buf, n, "p%0*dr%d", w, k / st->replicas, k % st->replicas)
                               : snprintf(buf, n, "p%0*d", w, k);
    if (len >= (int)n) buf[0] = '\0'; /* n >= 32 in every caller */
}
int pl_study_naxes(const pl_study_t *st) { return st->naxes; }
const char *pl_study_name(const pl_study_t *st) { return st->name; }
const char *pl_study_out(const pl_study_t *st) { return st->out; }
const char *pl_study_path(const pl_study_t *st) { return st->path; }
const char *pl_study_axis_key(const pl_study_t *st, int a) { return st->ax[a].key; }

/* Copies value setting `v` into `parent` as `name` (NULL: an element). */
static int copy_value(config_setting_t *parent, const char *name, const config_setting_t *v)
{
    int t = config_setting_type(v);
    config_setting_t *c = config_setting_add(parent, name, t);
    if (!c) return -1;
    switch (t) {
    case CONFIG_TYPE_INT: case CONFIG_TYPE_INT64: return config_setting_set_int64(c, config_setting_get_int64(v)) ? 0 : -1;
    case CONFIG_TYPE_FLOAT: return config_setting_set_float(c, config_setting_get_float(v)) ? 0 : -1;
    case CONFIG_TYPE_BOOL: return config_setting_set_bool(c, config_setting_get_bool(v)) ? 0 : -1;
    case CONFIG_TYPE_STRING: return config_setting_set_string(c, config_setting_get_string(v)) ? 0 : -1;
    case CONFIG_TYPE_ARRAY: case CONFIG_TYPE_LIST:
        for (int i = 0; i < config_setting_length(v); ++i)
            if (copy_value(c, NULL, config_setting_get_elem(v, (unsigned)i))) return -1;
        return 0;
    default: return -1;
    }
}

/* Sets key sec.leaf (sec "" for the top level) of the base tree to `v`. */
static int set_key(config_setting_t *root, const char *sec, const char *leaf, const config_setting_t *v)
{
    config_setting_t *g = root;
    if (*sec) {
        g = config_setting_get_member(root, sec);
        if (g && config_setting_type(g) != CONFIG_TYPE_GROUP) return -1;
        if (!g && !(g = config_setting_add(root, sec, CONFIG_TYPE_GROUP))) return -1;
    }
    if (config_setting_get_member(g, leaf) && config_setting_remove(g, leaf) != CONFIG_TRUE) return -1;
    return copy_value(g, leaf, v);
}

/* The files a scene reads, named relative to its folder (their keys allow
 * no '/'): a point's scene lives in OUT/scenes/, where the sweep copies
 * them from the base scene's folder (pl_study_point_files). */
static const char *const file_keys[] = {"init_file", "table_file"};

/* The point's value of colloids.<file_keys[i]> in the base tree as set for
 * the present point ("" when unset or not a string). */
static const char *file_key(const pl_study_t *st, size_t i)
{
    config_setting_t *c = config_setting_get_member(config_root_setting(&st->bcfg), "colloids");
    config_setting_t *f = c && config_setting_type(c) == CONFIG_TYPE_GROUP ? config_setting_get_member(c, file_keys[i])
                                                                            : NULL;
    const char *v = f && config_setting_type(f) == CONFIG_TYPE_STRING ? config_setting_get_string(f) : NULL;
    return v ? v : "";
}

static int point_reads_files(const pl_study_t *st)
{
    for (size_t i = 0; i < sizeof file_keys / sizeof file_keys[0]; ++i)
        if (*file_key(st, i)) return 1;
    return 0;
}

/* Where a point's scene is checked before anything is written: OUT/scenes/
 * ID.cfg, or, when it reads files, beside the base scene (where they are). */
static void check_label(const pl_study_t *st, const char *out_dir, const char *id, char *buf, size_t n)
{
    char name[64];
    snprintf(name, sizeof name, "%s.cfg", id);
    if (point_reads_files(st)) pl_path_beside(buf, n, st->base, name);
    else snprintf(buf, n, "%s/scenes/%s", out_dir, name);
}

int pl_study_point_files(const pl_study_t *st, const char *scenes_dir, pl_err_t *err)
{
    for (size_t i = 0; i < sizeof file_keys / sizeof file_keys[0]; ++i) {
        const char *v = file_key(st, i);
        if (!*v || strchr(v, '/')) continue; /* (a '/' is refused by the scene check) */
        char src[PATH_MAX], dst[PATH_MAX];
        pl_path_beside(src, sizeof src, st->base, v);
        snprintf(dst, sizeof dst, "%s/%s", scenes_dir, v);
        if (pl_file_copy(src, dst, err)) return err->code;
    }
    return 0;
}

/* Sets the top-level seed of the base tree (a replica's; a new setting,
 * so that the writer does not read the base's literal back). */
static int set_seed(config_setting_t *root, long long seed)
{
    if (config_setting_get_member(root, "seed") && config_setting_remove(root, "seed") != CONFIG_TRUE) return -1;
    config_setting_t *s = config_setting_add(root, "seed", CONFIG_TYPE_INT64);
    return s && config_setting_set_int64(s, seed) ? 0 : -1;
}

int pl_study_point_scene(pl_study_t *st, int k, const char *name, char **text, pl_err_t *err)
{
    config_setting_t *root = config_root_setting(&st->bcfg);
    const int p = k / st->replicas, r = k % st->replicas;
    for (int a = 0; a < st->naxes; ++a) {
        if (set_key(root, st->ax[a].sec, st->ax[a].leaf, value_of(st, p, a)))
            return pl_err_set(err, PL_ERR_INPUT, "%s: point %d: cannot set '%s' in the base scene %s (is '%s' "
                              "a group there?)", st->path, p, st->ax[a].key, st->base, st->ax[a].sec);
    }
    if (st->replicas > 1 && set_seed(root, pl_study_seed(st, k)))
        return pl_err_set(err, PL_ERR_INPUT, "%s: point %d replica %d: cannot set the seed", st->path, p, r);
    if (name) { /* name is never swept (add_axis) */
        config_setting_t *n = config_setting_get_member(root, "name");
        if (!n) n = config_setting_add(root, "name", CONFIG_TYPE_STRING);
        if (!n || config_setting_type(n) != CONFIG_TYPE_STRING || !config_setting_set_string(n, name))
            return pl_err_set(err, PL_ERR_INPUT, "%s: point %d: cannot set the scene name", st->path, k);
    }
    size_t len;
    FILE *f = open_memstream(text, &len);
    if (!f) return pl_err_set(err, PL_ERR_NOMEM, "out of memory writing a point's scene");
    fprintf(f, "# peloid sweep: study %s, point %d of %d: the base scene %s with\n", st->path, p, st->npoints,
            st->base);
    if (st->replicas > 1)
        fprintf(f, "#   replica %d of %d: seed = %lld (the base scene's + %d)\n", r, st->replicas, pl_study_seed(st, k), r);
    for (int a = 0; a < st->naxes; ++a) {
        char v[256];
        pl_study_point_value(st, k, a, v, sizeof v);
        fprintf(f, "#   %s = %s\n", st->ax[a].key, v);
    }
    pl_study_write_group(f, &st->btext, root, 0);
    if (fclose(f)) {
        free(*text);
        *text = NULL;
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory writing a point's scene");
    }
    return 0;
}

int pl_study_check_points(pl_study_t *st, const char *out_dir, pl_sweep_cost_t *cost, pl_err_t *err)
{
    pl_scene_t *scene = malloc(sizeof *scene);
    if (!scene) return pl_err_set(err, PL_ERR_NOMEM, "out of memory checking the study's points");
    int rc = 0;
    for (int k = 0; !rc && k < pl_study_npoints(st); ++k) {
        char *text = NULL, label[1024], name[160], id[32];
        pl_study_point_id(st, k, id, sizeof id);
        snprintf(name, sizeof name, "%s-%s", st->name, id);
        if ((rc = pl_study_point_scene(st, k, name, &text, err))) break;
        check_label(st, out_dir, id, label, sizeof label);
        rc = pl_scene_load_string(text, label, scene, err);
        if (!rc) rc = pl_run_check(scene, err);
        if (!rc && cost) pl_sweep_point_cost(scene, &cost[k]);
        free(text);
        if (!rc && (rc = pl_study_check_plot(st, scene, k / st->replicas, err))) break; /* names its own line */
        if (rc && st->naxes == 0) break; /* a scene's replicas: the loader's line names the scene */
        if (rc) { /* name the study line of the values, the point, then the loader's line */
            char vals[512] = "", v[128], inner[1024];
            int line = st->ax[0].line, fl;
            for (int a = 0; a < st->naxes; ++a) {
                pl_study_point_value(st, k, a, v, sizeof v);
                size_t l = strlen(vals);
                snprintf(vals + l, sizeof vals - l, "%s%s = %s", a ? ", " : "", st->ax[a].key, v);
                char quoted[160];
                snprintf(quoted, sizeof quoted, "'%s'", st->ax[a].key);
                if (strstr(err->msg, quoted)) line = st->ax[a].line;
            }
            int fi = pl_scene_text_where(&st->stext, line, &fl);
            snprintf(inner, sizeof inner, "%s", err->msg);
            rc = pl_err_set(err, PL_ERR_INPUT, "%s:%d: point %d (%s) is not a valid scene, nothing was run: %s",
                            st->stext.files[fi], fl, k / st->replicas, vals, inner);
        }
    }
    free(scene);
    return rc;
}
