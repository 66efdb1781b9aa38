/* The sweep's shared files (points.json, the point scenes, the Slurm
 * scripts, plan.json) written whole or not at all. */
#include <errno.h>
#include <stdio.h>
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
