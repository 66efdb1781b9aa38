/* Colloid trajectory as extended XYZ (colloids.xyz), the text format OVITO,
 * VMD, ASE and ParaView read: per frame a count line and a comment line of
 * key=value pairs,
 *   Lattice="Lx 0 0 0 Ly 0 0 0 Lz" Origin="0 0 0"
 *   Properties=species:S:1:pos:R:3:radius:R:1:vel:R:3 pbc="T T F"
 *   Time=<t> step=<n> units="..."
 * (with the cluster observer: ...:vel:R:3:cluster_id:I:1, the smallest member
 * index of the colloid's cluster, -1 where the frame has none)
 * then one line per colloid.  Species is "X" (ASE's dummy element: every
 * reader accepts it; colloids have no chemical identity).  Positions are
 * wrapped into the box, in the same units as colloids.h5.  Written to
 * PATH.tmp, renamed to PATH on close; a run resumed in place continues the
 * file (pl_xyz_open_keep). */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "colloid_traj.h"
#include "peloid/io.h"

struct pl_xyz {
    FILE *f;
    char path[PATH_MAX], tmp[PATH_MAX + 8];
};

int pl_xyz_open(const char *path, pl_xyz_t **out, pl_err_t *err)
{
    pl_xyz_t *x = calloc(1, sizeof *x);
    if (!x) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    snprintf(x->path, sizeof x->path, "%s", path);
    if (!(x->f = pl_file_begin(path, x->tmp, sizeof x->tmp, err))) {
        free(x);
        return PL_ERR_IO;
    }
    *out = x;
    return 0;
}

/* Byte offset in f of the first frame of a step >= keep (the end when none);
 * -1 when f is not an extended XYZ file of frames. */
static long frames_end(FILE *f, long long keep)
{
    char *line = NULL;
    size_t cap = 0;
    long at = 0;
    unsigned long long n;
    for (;;) {
        at = ftell(f);
        if (getline(&line, &cap, f) < 0) break; /* the end */
        const char *st = NULL;
        int ok = sscanf(line, "%llu", &n) == 1 && getline(&line, &cap, f) >= 0 && (st = strstr(line, " step="));
        long long step = ok ? strtoll(st + 6, NULL, 10) : -1;
        if (!ok) at = -1;
        if (!ok || step >= keep) break;
        for (unsigned long long i = 0; i < n; ++i)
            if (getline(&line, &cap, f) < 0) break; /* a frame cut short: its step is >= keep */
    }
    free(line);
    return at;
}

int pl_xyz_open_keep(const char *path, long long keep, pl_xyz_t **out, pl_err_t *err)
{
    char tmp[PATH_MAX + 8];
    pl_atomic_tmp(path, tmp, sizeof tmp);
    int from_tmp = access(tmp, F_OK) == 0; /* a killed run's file: the newest */
    if (!from_tmp && access(path, F_OK) != 0) return pl_xyz_open(path, out, err);
    pl_xyz_t *x = calloc(1, sizeof *x);
    if (!x) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    snprintf(x->path, sizeof x->path, "%s", path);
    snprintf(x->tmp, sizeof x->tmp, "%s", tmp);
    const char *src = from_tmp ? tmp : path;
    errno = 0;
    FILE *in = fopen(src, from_tmp ? "r+" : "r");
    int e = errno, opened = in != NULL;
    long end = in ? frames_end(in, keep) : -1;
    int bad = end < 0;
    if (!bad && from_tmp) { /* cut it there and append */
        bad = fflush(in) || ftruncate(fileno(in), end) || fseek(in, 0, SEEK_END);
        e = errno;
        x->f = in;
        in = NULL;
    } else if (!bad) { /* the frames to keep into PATH.tmp */
        x->f = fopen(tmp, "w");
        bad = !x->f || fseek(in, 0, SEEK_SET);
        char buf[1 << 16];
        for (long left = end; !bad && left > 0;) {
            size_t want = (size_t)(left < (long)sizeof buf ? left : (long)sizeof buf);
            size_t got = fread(buf, 1, want, in);
            bad = got != want || fwrite(buf, 1, got, x->f) != got;
            left -= (long)got;
        }
        bad |= !x->f || fflush(x->f) != 0;
        e = errno;
    }
    if (in) fclose(in);
    if (bad) {
        if (x->f) fclose(x->f);
        free(x);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot continue the frames before step %lld: %s", src, keep,
                          !opened ? strerror(e) : end < 0 ? "not an extended XYZ file of frames"
                          : e ? strerror(e) : "stream error");
    }
    *out = x;
    return 0;
}

int pl_xyz_frame(pl_xyz_t *x, const pl_traj_frame_t *f, pl_err_t *err)
{
    FILE *o = x->f;
    const double L = f->len, V = f->len / f->tim;
    errno = 0;
    int bad = fprintf(o, "%zu\n", f->n) < 0;
    bad |= fprintf(o, "Lattice=\"%.10g 0 0 0 %.10g 0 0 0 %.10g\" Origin=\"0 0 0\" "
                      "Properties=species:S:1:pos:R:3:radius:R:1:vel:R:3%s pbc=\"%c %c %c\" "
                      "Time=%.17g step=%lld units=\"length %s, time %s, velocity %s/%s\"\n",
                   f->box[0] * L, f->box[1] * L, f->box[2] * L, f->has_cluster_id ? ":cluster_id:I:1" : "",
                   f->periodic[0] ? 'T' : 'F',
                   f->periodic[1] ? 'T' : 'F', f->periodic[2] ? 'T' : 'F', f->time * f->tim, f->step,
                   f->len_unit, f->time_unit, f->len_unit, f->time_unit) < 0;
    for (size_t i = 0; i < f->n && !bad; ++i) {
        bad |= fprintf(o, "X %.10g %.10g %.10g %.10g %.10g %.10g %.10g", f->x[i] * L, f->y[i] * L, f->z[i] * L,
                       f->rad[i] * L, f->vx[i] * V, f->vy[i] * V, f->vz[i] * V) < 0;
        if (f->has_cluster_id) bad |= fprintf(o, " %d", f->cluster_id ? (int)f->cluster_id[i] : -1) < 0;
        bad |= fputc('\n', o) == EOF;
    }
    bad |= fflush(o) != 0;
    bad |= ferror(o) != 0;
    if (bad)
        return pl_err_set(err, PL_ERR_IO, "%s: writing the frame of step %lld failed: %s", x->tmp, f->step,
                          errno ? strerror(errno) : "stream error");
    return 0;
}

int pl_xyz_close(pl_xyz_t *x, pl_err_t *err)
{
    if (!x) return 0;
    int rc = pl_file_commit(x->f, x->tmp, x->path, err);
    free(x);
    return rc;
}
