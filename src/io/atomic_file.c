/* The one atomic-write helper (DESIGN.md "Output files are written
 * atomically"): every output is written to "<path>.tmp", which is then
 * fsync'ed, renamed to <path>, and the directory fsync'ed, so a crash never
 * leaves a half-written file under the final name and the rename survives
 * with the data it names.  Used by the checkpoint, the trajectory, the
 * fields and the text outputs (scene echo, summary). */
#include <errno.h>
#include <fcntl.h>
#include <libgen.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "peloid/io.h"

void pl_atomic_tmp(const char *path, char *tmp, size_t n) { snprintf(tmp, n, "%s.tmp", path); }

int pl_fsync_path(const char *path, int dir)
{
    char buf[PATH_MAX + 8];
    snprintf(buf, sizeof buf, "%s", path);
    const char *p = dir ? dirname(buf) : buf;
    int fd = open(p, O_RDONLY | (dir ? O_DIRECTORY : 0));
    if (fd < 0) return -1;
    int rc = fsync(fd);
    int e = errno;
    close(fd);
    errno = e;
    return rc;
}

int pl_atomic_commit(const char *tmp, const char *path, pl_err_t *err)
{
    if (pl_fsync_path(tmp, 0)) {
        int e = errno;
        unlink(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: fsync failed: %s", tmp, strerror(e));
    }
    if (rename(tmp, path)) {
        int e = errno;
        unlink(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot rename to %s: %s", tmp, path, strerror(e));
    }
    if (pl_fsync_path(path, 1))
        return pl_err_set(err, PL_ERR_IO, "%s: fsync of the directory failed: %s", path, strerror(errno));
    return 0;
}

FILE *pl_file_begin(const char *path, char *tmp, size_t ntmp, pl_err_t *err)
{
    pl_atomic_tmp(path, tmp, ntmp);
    FILE *f = fopen(tmp, "w");
    if (!f) pl_err_set(err, PL_ERR_IO, "%s: cannot write: %s", tmp, strerror(errno));
    return f;
}

int pl_file_commit(FILE *f, const char *tmp, const char *path, pl_err_t *err)
{
    errno = 0;
    int bad = fflush(f) != 0 || ferror(f);
    int e = errno;
    if (fclose(f) || bad) {
        unlink(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: write failed: %s", tmp, e ? strerror(e) : "stream error");
    }
    return pl_atomic_commit(tmp, path, err);
}

int pl_file_copy(const char *src, const char *path, pl_err_t *err)
{
    FILE *in = fopen(src, "rb");
    if (!in) return pl_err_set(err, PL_ERR_IO, "%s: cannot read: %s", src, strerror(errno));
    char tmp[PATH_MAX + 8], buf[65536];
    FILE *f = pl_file_begin(path, tmp, sizeof tmp, err);
    if (!f) {
        fclose(in);
        return PL_ERR_IO;
    }
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, in)) > 0)
        if (fwrite(buf, 1, n, f) != n) break;
    int bad = ferror(in);
    fclose(in);
    if (bad) {
        fclose(f);
        unlink(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: read failed", src);
    }
    return pl_file_commit(f, tmp, path, err);
}
