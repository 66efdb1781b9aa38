/* Output directory creation and atomic file writes (DESIGN.md "Errors"). */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "peloid/io.h"

void pl_path_join(char *buf, size_t n, const char *dir, const char *name)
{
    snprintf(buf, n, "%s/%s", dir, name);
}

static int mkdir_p(const char *dir)
{
    char tmp[1024];
    snprintf(tmp, sizeof tmp, "%s", dir);
    for (char *p = tmp + 1; *p; ++p) {
        if (*p != '/') continue;
        *p = '\0';
        if (mkdir(tmp, 0777) && errno != EEXIST) return -1;
        *p = '/';
    }
    if (mkdir(tmp, 0777) && errno != EEXIST) return -1;
    return 0;
}

int pl_outdir_prepare(const char *dir, int force, pl_err_t *err)
{
    struct stat st;
    if (stat(dir, &st) == 0) {
        if (!S_ISDIR(st.st_mode))
            return pl_err_set(err, PL_ERR_INPUT, "%s: output path exists and is not a directory", dir);
        if (!force)
            return pl_err_set(err, PL_ERR_INPUT,
                              "%s: output directory exists; use --force to write into it or --out DIR", dir);
        return 0;
    }
    if (mkdir_p(dir))
        return pl_err_set(err, PL_ERR_IO, "%s: cannot create output directory: %s", dir, strerror(errno));
    return 0;
}

FILE *pl_file_begin(const char *path, char *tmp, size_t ntmp, pl_err_t *err)
{
    snprintf(tmp, ntmp, "%s.tmp", path);
    FILE *f = fopen(tmp, "w");
    if (!f) pl_err_set(err, PL_ERR_IO, "%s: cannot write: %s", tmp, strerror(errno));
    return f;
}

int pl_file_commit(FILE *f, const char *tmp, const char *path, pl_err_t *err)
{
    int bad = ferror(f);
    if (fclose(f) || bad) return pl_err_set(err, PL_ERR_IO, "%s: write failed", tmp);
    if (rename(tmp, path))
        return pl_err_set(err, PL_ERR_IO, "%s: cannot rename to %s: %s", tmp, path, strerror(errno));
    return 0;
}
