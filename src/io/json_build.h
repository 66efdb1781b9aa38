/* Building JSON documents with jansson (src/io/json_build.c): summary.json and
 * `params --json`.  Escaping is jansson's; a non-finite number never reaches
 * a document: it is an error naming the key.  Internal to src/. */
#ifndef PELOID_JSON_BUILD_H
#define PELOID_JSON_BUILD_H

#include <jansson.h>
#include <stdio.h>

#include "peloid/error.h"

/* The first failure while building is kept: err gets one line naming
 * `where` (the scene file) and the key path `prefix.key`. */
typedef struct pl_json {
    pl_err_t *err;
    const char *where;  /* e.g. the scene path */
    const char *prefix; /* key path of the object being filled, e.g. "derived" */
    int failed;
} pl_json_t;

/* obj[key] = v (v is stolen; NULL means out of memory). */
void pl_json_set(pl_json_t *b, json_t *obj, const char *key, json_t *v);
/* A finite number, else an error naming the key. */
void pl_json_real(pl_json_t *b, json_t *obj, const char *key, double v);
/* A finite number, null for NaN (undefined), an error for +-inf. */
void pl_json_real_or_null(pl_json_t *b, json_t *obj, const char *key, double v);
void pl_json_int(pl_json_t *b, json_t *obj, const char *key, long long v);
/* A string (must be valid UTF-8). */
void pl_json_str(pl_json_t *b, json_t *obj, const char *key, const char *s);
/* [v0, v1, ...] of n finite numbers. */
void pl_json_reals(pl_json_t *b, json_t *obj, const char *key, const double *v, int n);

/* Writes doc (2-space indent, key order kept) and a newline to f. */
int pl_json_dump(const json_t *doc, FILE *f, const char *name, pl_err_t *err);

#endif
