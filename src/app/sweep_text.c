/* The sweep's shared files (points.json, the point scenes, the Slurm
 * scripts, plan.json) written whole or not at all, read back whole, and
 * points.json itself (what the collect step, tools/sweep_collect.py, knows
 * of the study). */
#include <errno.h>
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "peloid/io.h"
#include "sweep_priv.h"

/* Atomic write through a temporary file of this process's own
 * ("<path>.tmp.<pid>"): the array tasks of a Slurm sweep write the shared
 * files (points.json, the point scenes) concurrently, and with one shared
 * temporary name one task's rename took the file from under another's. */
int pl_sweep_write_text(const char *path, const char *text, pl_err_t *err)
{
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "w");
    if (!f) return pl_err_set(err, PL_ERR_IO, "%s: cannot create: %s", tmp, strerror(errno));
    fputs(text, f);
    return pl_file_commit(f, tmp, path, err);
}

char *pl_sweep_read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *s = NULL;
    size_t cap = 0, n = 0, r;
    char b[8192];
    while ((r = fread(b, 1, sizeof b, f)) > 0) {
        if (n + r + 1 > cap) {
            cap = 2 * (n + r + 1);
            char *q = realloc(s, cap);
            if (!q) break;
            s = q;
        }
        memcpy(s + n, b, r);
        n += r;
    }
    fclose(f);
    if (s) s[n] = '\0';
    return s ? s : calloc(1, 1);
}

int pl_sweep_write_changed(const char *path, const char *text, pl_err_t *err)
{
    char *old = pl_sweep_read_text(path);
    int same = old && !strcmp(old, text);
    free(old);
    return same ? 0 : pl_sweep_write_text(path, text, err);
}

/* points.json: the study's name, file, swept keys and plot{}, and each run's
 * index, id and values; with replicas > 1 also "replicas" and each run's
 * point, replica and seed (the collect step pools a point's replicas). */
int pl_sweep_write_points(const sweep_t *s, pl_err_t *err)
{
    json_t *doc = json_object(), *keys = json_array(), *pts = json_array();
    char plot[2048], path[4096];
    const int replicas = pl_study_replicas(s->st);
    json_object_set_new(doc, "study", json_string(pl_study_name(s->st)));
    json_object_set_new(doc, "study_file", json_string(pl_study_path(s->st)));
    for (int a = 0; a < pl_study_naxes(s->st); ++a) json_array_append_new(keys, json_string(pl_study_axis_key(s->st, a)));
    json_object_set_new(doc, "keys", keys);
    pl_study_plot_json(s->st, plot, sizeof plot);
    json_t *pj = json_loads(plot, 0, NULL);
    json_object_set_new(doc, "plot", pj ? pj : json_object());
    if (replicas > 1) json_object_set_new(doc, "replicas", json_integer(replicas));
    for (int k = 0; k < s->n; ++k) {
        json_t *p = json_object(), *params = json_object();
        char id[32], v[256];
        pl_study_point_id(s->st, k, id, sizeof id);
        json_object_set_new(p, "index", json_integer(k));
        json_object_set_new(p, "id", json_string(id));
        if (replicas > 1) {
            json_object_set_new(p, "point", json_integer(k / replicas));
            json_object_set_new(p, "replica", json_integer(k % replicas));
            json_object_set_new(p, "seed", json_integer(pl_study_seed(s->st, k)));
        }
        for (int a = 0; a < pl_study_naxes(s->st); ++a) {
            pl_study_point_value(s->st, k, a, v, sizeof v);
            json_t *jv = json_loads(v, JSON_DECODE_ANY, NULL);
            json_object_set_new(params, pl_study_axis_key(s->st, a), jv ? jv : json_string(v));
        }
        json_object_set_new(p, "params", params);
        json_array_append_new(pts, p);
    }
    json_object_set_new(doc, "points", pts);
    char *text = json_dumps(doc, JSON_INDENT(1));
    json_decref(doc);
    if (!text) return pl_err_set(err, PL_ERR_NOMEM, "out of memory writing points.json");
    snprintf(path, sizeof path, "%s/points.json", s->out);
    size_t len = strlen(text);
    char *t2 = realloc(text, len + 2);
    if (t2) {
        t2[len] = '\n';
        t2[len + 1] = '\0';
        text = t2;
    }
    int rc = pl_sweep_write_changed(path, text, err);
    free(text);
    return rc;
}
