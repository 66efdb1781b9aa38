/* Scene text (src/scene/scene_text.c): a scene file with its @include files
 * expanded into one buffer for libconfig, a map from each line of that buffer
 * back to (file, line), and the literal text of a value as written.
 * Internal to the scene loader. */
#ifndef PELOID_SCENE_TEXT_H
#define PELOID_SCENE_TEXT_H

#include <stddef.h>

#include "peloid/error.h"

enum { PL_SCENE_TEXT_MAX_FILES = 8 }; /* the scene and up to 7 @include files */

typedef struct {
    char *text;            /* expanded text, NUL-terminated */
    size_t len, cap;
    int *file_of, *line_of; /* per expanded line (0-based): file index, line in it (1-based) */
    size_t nlines, cap_lines;
    char *files[PL_SCENE_TEXT_MAX_FILES]; /* file names as messages show them */
    int nfiles;
    char root[4096];       /* realpath of the scene's directory (include boundary) */
    int anywhere;          /* --allow-include-anywhere */
} pl_scene_text_t;

/* Reads `path` and every @include it names (relative to the including
 * file's directory; inside the scene's directory tree unless `anywhere`).
 * Errors: PL_ERR_INPUT, "FILE:LINE: what; allowed: ...". */
int pl_scene_text_read(pl_scene_text_t *t, const char *path, int anywhere, pl_err_t *err);

/* The same for a scene given as a string (tests): `label` names it; @include
 * is resolved relative to the working directory. */
int pl_scene_text_string(pl_scene_text_t *t, const char *text, const char *label, pl_err_t *err);

void pl_scene_text_free(pl_scene_text_t *t);

/* File index and line (in that file) of expanded line `line` (1-based);
 * index 0 is the scene itself. */
int pl_scene_text_where(const pl_scene_text_t *t, int line, int *file_line);

/* Text of expanded line `line` (leading blanks dropped), cut to n - 1. */
void pl_scene_text_line(const pl_scene_text_t *t, int line, char *buf, size_t n);

/* The literal of setting `name` (element `elem`, -1: a scalar) on expanded
 * line `line` as written (first occurrence); 0, or -1 when not found. */
int pl_scene_text_token(const pl_scene_text_t *t, int line, const char *name, int elem, char *lit, size_t nlit);

/* Integer value of setting `name` (element `elem` of an array; -1: a scalar)
 * given on expanded line `line`, read from the text as written.  `libval` is
 * libconfig's (possibly wrapped) value, used to pick the right occurrence.
 * Returns 0 with *out set, 1 when the literal does not fit in 64 bits, -1
 * when it cannot be found; `lit` receives the literal text in both first
 * cases. */
int pl_scene_text_integer(const pl_scene_text_t *t, int line, const char *name, int elem, long long libval,
                          long long *out, char *lit, size_t nlit);

#endif
