/* Scene fingerprint of a checkpoint: the root attribute "scene_keys" holds
 * every physics-relevant effective key of the scene that wrote it, one
 * "key = value" line each (reals in the shortest of 15..17 digits that
 * reads back exactly), enumerated from the schema (src/scene_keys*.c), and
 * "scene_fingerprint" the 64-bit FNV-1a hash of that text.  A restart
 * compares every key with the scene it continues in and refuses any
 * difference that `--restart-changed KEY[,KEY...]` does not name.  A key
 * the checkpoint lacks (one added to the schema after it was written) is no
 * difference while the scene leaves it at its default: the checkpoint's
 * binary had that physics.
 *
 * Not physics, so free to change on restart: the run's name and length, the
 * output intervals, the colloid trajectory interval, the guard bounds
 * (they stop a run, they do not change its trajectory) and the neighbour-list
 * skin (the forces are bitwise the same for any valid list).
 *
 * Not state either: colloids.init_file (the checkpoint holds the colloids'
 * positions and radii, and a run directory's scene.cfg names its own copy
 * of the file, colloids_init.txt): its line keeps its place with the value
 * "" and is not compared on restart (older checkpoints hold a path there).
 * colloids.table_file is compared by the table's content (its name may
 * differ: a run directory holds a copy, pair_table.txt). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint_h5.h"
#include "peloid/checkpoint.h"
#include "peloid/scene.h"
#include "peloid/h5.h"
#include "peloid/io.h"

static const char *const not_physics[] = {
    "name",
    "steps",
    "output.thermo_interval",
    "output.checkpoint_interval",
    "output.fields_interval",
    "output.fields_start",
    "output.colloids_xyz",
    "output.progress_s",
    "colloids.trajectory_interval",
    "colloids.max_overlap",
    "colloids.min_contact_steps",
    "colloids.max_energy_drift",
    "colloids.guard_interval",
    "colloids.neighbor_skin", /* the forces do not depend on the list's skin */
    "coarse_graining.strict",
};

static int not_compared(const char *name) { return !strcmp(name, "colloids.init_file"); }

/* colloids.table_file by its content, "fnv1a:HASH" of the file's bytes: a
 * run directory's scene.cfg names its own copy (pair_table.txt), and a
 * restart must see the same table, not the same name. */
static void table_text(const pl_scene_t *scene, char *buf, size_t n)
{
    char path[4096];
    pl_scene_table_file_path(scene, path, sizeof path);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(buf, n, "\"(unreadable)\"");
        return;
    }
    char chunk[1 << 14];
    size_t got;
    uint64_t h = pl_ckpt_fnv1a(NULL, 0);
    while ((got = fread(chunk, 1, sizeof chunk, f)) > 0) h = pl_ckpt_fnv1a_more(h, chunk, got);
    const int bad = ferror(f);
    fclose(f);
    if (bad) snprintf(buf, n, "\"(unreadable)\"");
    else snprintf(buf, n, "\"fnv1a:%016llx\"", (unsigned long long)h);
}

static void full_name(const pl_section_t *sec, const pl_key_t *k, char *buf, size_t n)
{
    if (*sec->name) snprintf(buf, n, "%s.%s", sec->name, k->name);
    else snprintf(buf, n, "%s", k->name);
}

static int is_physics(const char *name)
{
    if (!strncmp(name, "observe.", 8)) return 0; /* observers only read the state */
    if (!strncmp(name, "stop.", 5)) return 0;    /* it ends a run, as steps does */
    for (size_t i = 0; i < sizeof not_physics / sizeof not_physics[0]; ++i)
        if (!strcmp(name, not_physics[i])) return 0;
    return 1;
}

/* Shortest of %.15g .. %.17g that reads back as v. */
static void real_text(char *buf, size_t n, double v)
{
    for (int prec = 15; prec <= 17; ++prec) {
        snprintf(buf, n, "%.*g", prec, v);
        if (strtod(buf, NULL) == v) return;
    }
}

static void value_text(const pl_key_t *k, const pl_scene_t *scene, char *buf, size_t n)
{
    const char *base = (const char *)scene + k->offset;
    switch (k->type) {
    case PL_KEY_INT: snprintf(buf, n, "%lld", *(const long long *)base); break;
    case PL_KEY_REAL: real_text(buf, n, *(const double *)base); break;
    case PL_KEY_BOOL: snprintf(buf, n, "%s", *(const int *)base ? "true" : "false"); break;
    case PL_KEY_STRING: snprintf(buf, n, "\"%.127s\"", base); break;
    case PL_KEY_CHOICE: snprintf(buf, n, "\"%s\"", pl_key_choice_name(k, *(const int *)base)); break;
    case PL_KEY_INT3: {
        const int *v = (const int *)base;
        snprintf(buf, n, "[%d, %d, %d]", v[0], v[1], v[2]);
        break;
    }
    case PL_KEY_REAL3: {
        const double *v = (const double *)base;
        char a[3][32];
        for (int d = 0; d < 3; ++d) real_text(a[d], sizeof a[d], v[d]);
        snprintf(buf, n, "[%s, %s, %s]", a[0], a[1], a[2]);
        break;
    }
    }
}

/* Whether key k of the scene holds its default. */
static int at_default(const pl_key_t *k, const pl_scene_t *scene)
{
    const char *base = (const char *)scene + k->offset;
    switch (k->type) {
    case PL_KEY_INT: return *(const long long *)base == (long long)k->def;
    case PL_KEY_REAL: return *(const double *)base == k->def;
    case PL_KEY_BOOL:
    case PL_KEY_CHOICE: return *(const int *)base == (int)k->def;
    case PL_KEY_STRING: return !strcmp(base, k->def_str ? k->def_str : "");
    case PL_KEY_REAL3: {
        const double *v = (const double *)base;
        return v[0] == k->def && v[1] == k->def && v[2] == k->def;
    }
    default: return 0;
    }
}

/* "name = value" lines of the scene's keys that `keep` selects, in schema
 * order, a PL_KEY_FP_SET key only when it is set (malloc'ed, NULL when out
 * of memory). */
static char *keys_text(const pl_scene_t *scene, int (*keep)(const char *name))
{
    size_t ns, cap = 4096, len = 0;
    const pl_section_t *const *all = pl_scene_sections(&ns);
    char *s = malloc(cap);
    if (!s) return NULL;
    s[0] = '\0';
    for (size_t j = 0; j < ns; ++j)
        for (size_t i = 0; i < all[j]->nkeys; ++i) {
            char name[128], val[256];
            full_name(all[j], &all[j]->keys[i], name, sizeof name);
            if (!keep(name) || ((all[j]->keys[i].flags & PL_KEY_FP_SET) && at_default(&all[j]->keys[i], scene)))
                continue;
            if (not_compared(name)) snprintf(val, sizeof val, "\"\"");
            else if (!strcmp(name, "colloids.table_file")) table_text(scene, val, sizeof val);
            else value_text(&all[j]->keys[i], scene, val, sizeof val);
            size_t need = strlen(name) + strlen(val) + 5;
            if (len + need >= cap) {
                char *t = realloc(s, cap = 2 * cap + need);
                if (!t) {
                    free(s);
                    return NULL;
                }
                s = t;
            }
            len += (size_t)snprintf(s + len, cap - len, "%s = %s\n", name, val);
        }
    return s;
}

/* The fingerprint text of `scene` (malloc'ed, NULL when out of memory). */
static char *scene_text(const pl_scene_t *scene) { return keys_text(scene, is_physics); }

/* The observe keys that shape the observers' state (all but the report's
 * target and the averaging window, which are applied to the stored state
 * at the end of the run). */
static int is_observer_shape(const char *name)
{
    return !strncmp(name, "observe.", 8) && strcmp(name, "observe.target_rel_error") &&
           strcmp(name, "observe.average_from");
}

char *pl_ckpt_observe_text(const pl_scene_t *scene) { return keys_text(scene, is_observer_shape); }

int pl_ckpt_scene_write(hid_t f, const pl_scene_t *scene)
{
    char *text = scene_text(scene);
    if (!text) return -1;
    int bad = pl_h5_attr_str(f, "scene_keys", text);
    long long h = (long long)pl_ckpt_fnv1a(text, strlen(text));
    bad |= pl_ckpt_attr_i64(f, "scene_fingerprint", &h, 1, 1);
    free(text);
    return bad ? -1 : 0;
}

/* 1 when `name` is one of the comma-separated keys in `list`. */
static int listed(const char *list, const char *name)
{
    size_t n = strlen(name);
    for (const char *p = list; p && *p;) {
        const char *e = strchr(p, ',');
        size_t m = e ? (size_t)(e - p) : strlen(p);
        if (m == n && !strncmp(p, name, n)) return 1;
        p = e ? e + 1 : NULL;
    }
    return 0;
}

/* Value of key `name` in fingerprint text `t` into buf; 0 if absent. */
static int lookup(const char *t, const char *name, char *buf, size_t n)
{
    size_t m = strlen(name);
    for (const char *p = t; p && *p;) {
        const char *e = strchr(p, '\n');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len > m + 3 && !strncmp(p, name, m) && !strncmp(p + m, " = ", 3)) {
            size_t v = len - m - 3;
            if (v >= n) v = n - 1;
            memcpy(buf, p + m + 3, v);
            buf[v] = '\0';
            return 1;
        }
        p = e ? e + 1 : NULL;
    }
    return 0;
}

int pl_ckpt_scene_check(hid_t f, const pl_scene_t *scene, const char *changed, const char *path,
                        pl_err_t *err)
{
    char *old = pl_ckpt_attr_str_read(f, "scene_keys");
    if (!old) return pl_err_set(err, PL_ERR_INPUT, "%s: checkpoint has no scene_keys (scene fingerprint)", path);
    long long h = 0;
    if (pl_ckpt_attr_i64(f, "scene_fingerprint", &h, 1, 0) || (uint64_t)h != pl_ckpt_fnv1a(old, strlen(old))) {
        free(old);
        return pl_err_set(err, PL_ERR_INPUT, "%s: scene_keys do not match scene_fingerprint (corrupt checkpoint)",
                          path);
    }
    char *now = scene_text(scene), *defaults = NULL;
    pl_scene_t *def = malloc(sizeof *def);
    if (def) {
        pl_scene_defaults(def);
        defaults = scene_text(def);
        free(def);
    }
    if (!now || !defaults) {
        free(old);
        free(now);
        free(defaults);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    }
    char diff[900];
    size_t len = 0;
    int ndiff = 0;
    /* keys of this scene, then keys only the checkpoint has */
    for (int pass = 0; pass < 2; ++pass) {
        const char *src = pass ? old : now, *other = pass ? now : old;
        for (const char *p = src; *p;) {
            const char *e = strchr(p, '\n'), *eq = strstr(p, " = ");
            if (!e || !eq || eq > e) break;
            char name[128], a[256], b[256];
            snprintf(name, sizeof name, "%.*s", (int)(eq - p), p);
            snprintf(a, sizeof a, "%.*s", (int)(e - eq - 3), eq + 3);
            int has = lookup(other, name, b, sizeof b);
            p = e + 1;
            if (pass && has) continue; /* compared in the first pass */
            if (not_compared(name)) continue;
            if (has && !strcmp(a, b)) continue;
            char c[256];
            if (!pass && !has && lookup(defaults, name, c, sizeof c) && !strcmp(a, c)) continue; /* newer key, default */
            if (listed(changed, name)) continue;
            const char *vck = pass ? a : has ? b : "(absent)", *vsc = pass ? "(absent)" : a;
            if (len < sizeof diff)
                len += (size_t)snprintf(diff + len, sizeof diff - len, "%s%s %s -> %s", ndiff ? "; " : "", name,
                                        vck, vsc);
            ndiff++;
        }
    }
    free(old);
    free(now);
    free(defaults);
    if (ndiff)
        return pl_err_set(err, PL_ERR_INPUT,
                          "%s: checkpoint was written by another scene: %d physics key(s) differ "
                          "(checkpoint -> scene): %s; name deliberate changes with --restart-changed KEY[,KEY...]",
                          path, ndiff, diff);
    return 0;
}

int pl_checkpoint_changed_keys_valid(const char *list, pl_err_t *err)
{
    size_t ns;
    const pl_section_t *const *all = pl_scene_sections(&ns);
    for (const char *p = list; p && *p;) {
        const char *e = strchr(p, ',');
        size_t m = e ? (size_t)(e - p) : strlen(p);
        int found = 0;
        for (size_t j = 0; j < ns && !found; ++j)
            for (size_t i = 0; i < all[j]->nkeys && !found; ++i) {
                char name[128];
                full_name(all[j], &all[j]->keys[i], name, sizeof name);
                found = strlen(name) == m && !strncmp(name, p, m);
            }
        if (!found)
            return pl_err_set(err, PL_ERR_INPUT,
                              "--restart-changed: '%.*s' is not a scene key (expected section.key, e.g. srd.dt; "
                              "see peloid keys)", (int)m, p);
        p = e ? e + 1 : NULL;
    }
    return 0;
}
