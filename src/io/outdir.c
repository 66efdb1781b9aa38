/* Output directory: creation, the one-run lock, clearing what an earlier
 * run wrote (DESIGN.md "Errors"). */
#include <errno.h>
#include <fcntl.h>
#include <sys/file.h>
#include <limits.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "peloid/io.h"
#include "peloid/outputs.h"

void pl_path_join(char *buf, size_t n, const char *dir, const char *name)
{
    snprintf(buf, n, "%s/%s", dir, name);
}

void pl_path_beside(char *buf, size_t n, const char *file, const char *name)
{
    const char *slash = strrchr(file, '/');
    const int dl = name[0] != '/' && slash ? (int)(slash - file) + 1 : 0;
    snprintf(buf, n, "%.*s%s", dl, file, name);
}

/* dir is an ancestor of (or the same as) path; both resolved. */
static int contains(const char *dir, const char *path)
{
    size_t n = strlen(dir);
    if (n == 1 && dir[0] == '/') return 1;
    return strncmp(dir, path, n) == 0 && (path[n] == '/' || path[n] == '\0');
}

/* The output directory is resolved before anything is created: the longest
 * prefix that exists goes through realpath(), the rest must be plain names
 * (no "." or ".."), so no spelling of the path reaches an existing directory
 * that the existence check did not see (`victim/newdir/..` is `victim`). */
int pl_outdir_prepare(const char *dir, int force, const char *scene_path, char *resolved, size_t n,
                      pl_err_t *err)
{
    size_t len = strlen(dir);
    if (len == 0) return pl_err_set(err, PL_ERR_INPUT, "--out \"\": empty output directory");
    if (len + 32 >= PATH_MAX) /* room for "/checkpoint.h5.tmp" */
        return pl_err_set(err, PL_ERR_INPUT, "%.80s...: output directory is %zu characters; allowed: < %d",
                          dir, len, PATH_MAX - 32);
    /* head = longest existing prefix, tail = the components still to create */
    char head[PATH_MAX], tail[PATH_MAX] = "";
    snprintf(head, sizeof head, "%s", dir);
    struct stat st;
    for (;;) {
        size_t hl = strlen(head);
        while (hl > 1 && head[hl - 1] == '/') head[--hl] = '\0';
        if (lstat(head, &st) == 0) break;
        char *slash = strrchr(head, '/');
        const char *seg = slash ? slash + 1 : head; /* prepend "seg/" to tail (both parts of dir) */
        size_t sl = strlen(seg), tl = strlen(tail);
        memmove(tail + sl + (tl ? 1 : 0), tail, tl + 1);
        memcpy(tail, seg, sl);
        if (tl) tail[sl] = '/';
        if (!slash) {
            snprintf(head, sizeof head, ".");
            break;
        }
        if (slash == head) {
            snprintf(head, sizeof head, "/");
            break;
        }
        *slash = '\0';
    }
    char real[PATH_MAX];
    if (!realpath(head, real))
        return pl_err_set(err, PL_ERR_INPUT, "%s: cannot resolve %s: %s", dir, head, strerror(errno));
    if (stat(real, &st) || !S_ISDIR(st.st_mode)) {
        if (!*tail) return pl_err_set(err, PL_ERR_INPUT, "%s: output path exists and is not a directory", dir);
        return pl_err_set(err, PL_ERR_INPUT, "%s: %s is not a directory", dir, head);
    }
    size_t rl = strlen(real), base_len = rl;
    char tmp[PATH_MAX], exist[PATH_MAX];
    memcpy(exist, real, rl + 1);
    snprintf(tmp, sizeof tmp, "%s", tail);
    for (char *save = NULL, *c = strtok_r(tmp, "/", &save); c; c = strtok_r(NULL, "/", &save)) {
        if (!strcmp(c, ".") || !strcmp(c, ".."))
            return pl_err_set(err, PL_ERR_INPUT, "%s: '%s' after the part of the path that exists (%s); "
                              "allowed: plain directory names there", dir, c, exist);
        size_t cl = strlen(c);
        if (cl > NAME_MAX)
            return pl_err_set(err, PL_ERR_INPUT, "%.80s...: a directory name of %zu characters; allowed: <= %d",
                              dir, cl, NAME_MAX);
        if (rl + 1 + cl + 32 >= PATH_MAX || rl + 1 + cl >= n)
            return pl_err_set(err, PL_ERR_INPUT, "%.80s...: output directory path is longer than %d characters",
                              dir, PATH_MAX - 32);
        if (rl > 1) real[rl++] = '/';
        memcpy(real + rl, c, cl + 1);
        rl += cl;
    }
    if (rl + 32 >= PATH_MAX || rl >= n)
        return pl_err_set(err, PL_ERR_INPUT, "%.80s...: output directory path is longer than %d characters", dir,
                          PATH_MAX - 32);
    if (!*tail) { /* it exists */
        if (!force)
            return pl_err_set(err, PL_ERR_INPUT,
                              "%s: output directory exists; use --force to write into it or --out DIR%s%s%s",
                              dir, strcmp(real, dir) ? " (" : "", strcmp(real, dir) ? real : "",
                              strcmp(real, dir) ? ")" : "");
        char cwd[PATH_MAX], sd[PATH_MAX], scene_dir[PATH_MAX];
        if (getcwd(cwd, sizeof cwd) && contains(real, cwd))
            return pl_err_set(err, PL_ERR_INPUT, "%s: output directory %s holds the working directory; "
                              "refused even with --force", dir, real);
        const char *slash = scene_path ? strrchr(scene_path, '/') : NULL;
        snprintf(sd, sizeof sd, "%.*s", slash ? (int)(slash - scene_path) + (slash == scene_path) : 1,
                 slash ? scene_path : ".");
        if (scene_path && realpath(sd, scene_dir) && contains(real, scene_dir))
            return pl_err_set(err, PL_ERR_INPUT, "%s: output directory %s holds the scene file; refused even "
                              "with --force", dir, real);
    }
    memcpy(resolved, real, rl + 1);
    /* create the missing components, one at a time */
    for (size_t i = base_len + 1; i <= rl; ++i) {
        if (resolved[i] != '/' && resolved[i] != '\0') continue;
        char keep = resolved[i];
        resolved[i] = '\0';
        int bad = mkdir(resolved, 0777) && errno != EEXIST;
        int e = errno;
        resolved[i] = keep;
        if (bad) return pl_err_set(err, PL_ERR_IO, "%s: cannot create output directory: %s", resolved, strerror(e));
    }
    return 0;
}

int pl_outdir_lock(const char *dir, int *fd, pl_err_t *err)
{
    char path[PATH_MAX + 16];
    snprintf(path, sizeof path, "%s/.peloid.lock", dir);
    int f = open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (f < 0) return pl_err_set(err, PL_ERR_IO, "%s: cannot create the lock file: %s", path, strerror(errno));
    if (flock(f, LOCK_EX | LOCK_NB)) {
        int e = errno;
        close(f);
        if (e == EWOULDBLOCK)
            return pl_err_set(err, PL_ERR_INPUT, "%s: another peloid run is writing into this output directory "
                              "(%s is locked); refused even with --force: wait for it or use another --out",
                              dir, path);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot lock: %s", path, strerror(e));
    }
    *fd = f;
    return 0;
}

int pl_outdir_clean(const char *dir, pl_err_t *err)
{
    char path[PATH_MAX + 32];
    struct stat st;
    for (size_t k = 0; pl_outputs[k].name; ++k) /* every file peloid writes there (peloid/outputs.h) */
        for (int tmp = 0; tmp < 2; ++tmp) {
            snprintf(path, sizeof path, "%s/%s%s", dir, pl_outputs[k].name, tmp ? ".tmp" : "");
            /* a run writes regular files; a link or device placed under such
             * a name is not an earlier run's */
            if (lstat(path, &st) || !S_ISREG(st.st_mode)) continue;
            if (unlink(path) && errno != ENOENT)
                return pl_err_set(err, PL_ERR_IO, "%s: cannot remove the earlier run's file (--force): %s", path,
                                  strerror(errno));
        }
    return 0;
}

/* `key = value;` of section `sec` in an echoed scene.cfg (our own format:
 * "sec: {", two-space keys, "};"); 0 when absent. */
static long long echo_value(FILE *f, const char *sec, const char *key)
{
    char line[512], head[128], want[128];
    snprintf(head, sizeof head, "%s: {\n", sec);
    snprintf(want, sizeof want, "  %s = ", key);
    int in = 0;
    rewind(f);
    while (fgets(line, sizeof line, f)) {
        if (!strcmp(line, head)) in = 1;
        else if (in && !strcmp(line, "};\n")) in = 0;
        else if (in && !strncmp(line, want, strlen(want))) {
            const char *v = line + strlen(want);
            return !strncmp(v, "true", 4) ? 1 : strtoll(v, NULL, 10);
        }
    }
    return 0;
}

int pl_outdir_resume_check(const char *dir, long long first, pl_err_t *err)
{
    char path[PATH_MAX + 32], tmp[PATH_MAX + 40];
    snprintf(path, sizeof path, "%s/%s", dir, pl_outputs[PL_OUT_SCENE].name);
    FILE *f = fopen(path, "r");
    long long traj = 0, xyz = 0, count = 0;
    if (f) {
        count = echo_value(f, "colloids", "count");
        traj = echo_value(f, "colloids", "trajectory_interval");
        xyz = echo_value(f, "output", "colloids_xyz");
        fclose(f);
    }
    const struct {
        const char *name;
        int wanted;
        const char *why;
    } out[] = {
        {pl_outputs[PL_OUT_THERMO].name, 1, "its rows"},
        {pl_outputs[PL_OUT_COLLOIDS].name, count > 0 && traj > 0,
         "its frames (scene.cfg: colloids.trajectory_interval > 0)"},
        {pl_outputs[PL_OUT_COLLOIDS_XYZ].name, count > 0 && traj > 0 && xyz,
         "its frames (scene.cfg: output.colloids_xyz = true)"},
    };
    for (size_t k = 0; k < sizeof out / sizeof out[0]; ++k) {
        if (!out[k].wanted) continue;
        snprintf(path, sizeof path, "%s/%s", dir, out[k].name);
        snprintf(tmp, sizeof tmp, "%s.tmp", path);
        if (access(path, F_OK) && access(tmp, F_OK))
            return pl_err_set(err, PL_ERR_INPUT,
                              "%s: missing; the run resumed in place at step %lld wrote %s before it there; "
                              "allowed: put the file back, or resume into another --out",
                              path, first, out[k].why);
    }
    return 0;
}
