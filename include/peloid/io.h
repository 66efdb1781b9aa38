/* Output files: directory handling, atomic writes and file copies (the
 * checkpoint: peloid/checkpoint.h).  All writers go through a temporary name and rename()
 * so a crash never leaves a half-written file under the final name. */
#ifndef PELOID_IO_H
#define PELOID_IO_H

#include <stdio.h>

#include "peloid/error.h"

/* Resolves `dir` (realpath of the part that exists; the rest must be plain
 * names, no "." or "..") into `resolved` (n bytes) and creates what is
 * missing.  If it exists and !force, or (even with force) it holds the
 * working directory or the directory of `scene_path` (may be NULL), or the
 * path is longer than PATH_MAX allows: PL_ERR_INPUT and nothing is created
 * or touched. */
int pl_outdir_prepare(const char *dir, int force, const char *scene_path, char *resolved, size_t n,
                      pl_err_t *err);

/* One run per output directory: an exclusive advisory lock (flock) on
 * "<dir>/.peloid.lock", held until *fd is closed (at the end of the run).
 * A directory another process holds locked is PL_ERR_INPUT naming it,
 * with or without --force; PL_ERR_IO when the lock file cannot be made. */
int pl_outdir_lock(const char *dir, int *fd, pl_err_t *err);

/* --force: removes from `dir` every file a peloid run (and `peloid report`)
 * writes there and their temporary "*.tmp" twins (regular files only), so
 * that a directory never mixes two runs; other files and the lock file stay.  PL_ERR_IO naming a
 * file that cannot be removed. */
int pl_outdir_clean(const char *dir, pl_err_t *err);
/* Before a resume in place at step `first`: every output the run being
 * continued wrote and this one appends to (thermo.tsv; colloids.h5 and
 * colloids.xyz where the directory's scene.cfg asked for them) is there,
 * else PL_ERR_INPUT naming the file (its earlier part would be lost). */
int pl_outdir_resume_check(const char *dir, long long first, pl_err_t *err);

/* "<dir>/<name>" into buf. */
void pl_path_join(char *buf, size_t n, const char *dir, const char *name);
/* name as read beside `file`: relative to file's directory, unless name is
 * absolute (how a scene names its init and table files, a study its base
 * scene). */
void pl_path_beside(char *buf, size_t n, const char *file, const char *name);

/* The one atomic-write helper (src/io/atomic_file.c).  pl_atomic_tmp: the
 * temporary name "<path>.tmp" to write first.  pl_atomic_commit: fsync it,
 * rename it to path, fsync the directory; on failure the temporary file is
 * removed and PL_ERR_IO names the file and the system error. */
void pl_atomic_tmp(const char *path, char *tmp, size_t n);
int pl_atomic_commit(const char *tmp, const char *path, pl_err_t *err);
/* Atomic text file: open "<path>.tmp"; pl_file_commit checks the stream,
 * closes it and commits it (pl_atomic_commit). */
FILE *pl_file_begin(const char *path, char *tmp, size_t ntmp, pl_err_t *err);
/* Copies the file src to dst (replaced); PL_ERR_IO naming the file, and no
 * dst left, when it fails. */
int pl_file_copy(const char *src, const char *dst, pl_err_t *err);
int pl_file_commit(FILE *f, const char *tmp, const char *path, pl_err_t *err);
/* A byte copy of file src written atomically to path. */
int pl_file_copy(const char *src, const char *path, pl_err_t *err);

/* fsync of `path` (dir = 0) or of the directory holding it (dir = 1);
 * 0, or -1 with errno. */
int pl_fsync_path(const char *path, int dir);


#endif
