/* colloids.init_file: the strict reader of initial colloid positions (and
 * radii).  One colloid per line, "x y z" or "x y z R" (the same column count
 * on every line), numbers separated by blanks; a line whose first non-blank
 * character is '#' is a comment (any length), blank lines are skipped.
 * Every line is read whole (getline) and every token must be one whole
 * finite number (strtod, full-token check).  The file lists exactly
 * colloids.count colloids.  Positions lie in the box: [0, L] on a periodic
 * axis (L is the same point as 0), [R, L - R] between walls (the colloid
 * inside).  A radius lies within the spread colloids.polydispersity can give
 * at its largest (R0 (1 +- sqrt(3) 0.25), R0 = colloids.radius) and its pair
 * cut-off within half a periodic edge (minimum image).  Any other content is
 * one error line "FILE:LINE: column N (name): value 'TOKEN': allowed: ...".
 * Anything but a regular file (a directory, a device such as /dev/zero, a
 * pipe) is refused before it is read, naming the key and the path. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/colloid.h"
#include "peloid/input_file.h"
#include "peloid/io.h"

#define OFF(m) offsetof(pl_scene_t, m)

/* the largest colloids.polydispersity (its key's range): the radius spread a file may use */
#define PL_INIT_POLY_MAX 0.25

static const char *const col_name[4] = {"x", "y", "z", "R"};

double pl_colloid_radius_min(const pl_scene_t *scene)
{
    const pl_scene_colloids_t *cs = &scene->colloids;
    return cs->radius * (1.0 - sqrt(3.0) * (cs->init == PL_CINIT_FILE ? PL_INIT_POLY_MAX : cs->polydispersity));
}

typedef struct {
    const char *path;
    long line;
    pl_err_t *err;
} reader_t;

/* "FILE:LINE: column N (name): value 'TOKEN': " + what; PL_ERR_INPUT. */
static int bad_value(const reader_t *r, int col, const char *tok, const char *what)
{
    size_t n = strlen(tok);
    return pl_err_set(r->err, PL_ERR_INPUT, "%s:%ld: column %d (%s): value '%.40s%s': %s", r->path, r->line,
                      col + 1, col < 4 ? col_name[col] : "extra", tok, n > 40 ? "..." : "", what);
}

/* The blank-separated tokens of `s` (cut in place); up to max, the count
 * (max + 1 when there are more). */
static int split(char *s, char **tok, int max)
{
    int n = 0;
    for (;;) {
        s += strspn(s, " \t\r\v\f");
        if (!*s) return n;
        if (n == max) return max + 1;
        tok[n++] = s;
        s += strcspn(s, " \t\r\v\f");
        if (*s) *s++ = '\0';
    }
}

/* Value v of token tok of column col in [lo, hi], or PL_ERR_INPUT naming
 * the column and what is allowed. */
static int in_range(const reader_t *r, int col, const char *tok, double v, double lo, double hi, const char *allowed)
{
    if (v >= lo && v <= hi) return 0;
    char what[400];
    snprintf(what, sizeof what, "%s; allowed: %s", isfinite(v) ? "out of range" : "not finite", allowed);
    return bad_value(r, col, tok, what);
}

/* One colloid line (tokens tok[0..nt-1]): x, y, z and R into colloid i.
 * *ncol: the column count of the first colloid line (0 before it); the
 * fourth token, when there is one, into rtok. */
static int colloid_line(const reader_t *r, const pl_scene_t *scene, pl_colloid_t *c, size_t i, char **tok,
                        int nt, int *ncol, char *rtok, size_t rtok_n)
{
    const double R0 = scene->colloids.radius;
    const double rlo = R0 * (1.0 - sqrt(3.0) * PL_INIT_POLY_MAX), rhi = R0 * (1.0 + sqrt(3.0) * PL_INIT_POLY_MAX);
    char allowed[320];
    if (nt > 4 || (*ncol && nt > *ncol))
        return bad_value(r, nt > 4 ? 4 : *ncol, tok[nt > 4 ? 4 : *ncol],
                         *ncol == 3 ? "an extra column; allowed: 3 columns (x y z), as on the first colloid line"
                                    : "an extra column; allowed: 3 columns (x y z) or 4 (x y z R), the same on "
                                      "every line");
    double v[4];
    for (int k = 0; k < nt; ++k) { /* each token one whole number */
        char *end;
        v[k] = strtod(tok[k], &end);
        if (end == tok[k] || *end)
            return bad_value(r, k, tok[k], "not a number; allowed: x y z [R], blank-separated numbers");
    }
    if (nt < 3 || (*ncol && nt < *ncol))
        return pl_err_set(r->err, PL_ERR_INPUT, "%s:%ld: column %d (%s): missing; allowed: %s", r->path, r->line,
                          nt + 1, col_name[nt],
                          *ncol == 4 ? "4 columns (x y z R), as on the first colloid line"
                                     : "3 columns (x y z) or 4 (x y z R) on every line");
    if (!*ncol) *ncol = nt;
    if (nt == 4) {
        snprintf(allowed, sizeof allowed,
                 "a radius in [%.6g, %.6g] (colloids.radius = %g within the spread of colloids.polydispersity "
                 "<= %g: R (1 +- sqrt(3) %g))",
                 rlo, rhi, R0, PL_INIT_POLY_MAX, PL_INIT_POLY_MAX);
        if (in_range(r, 3, tok[3], v[3], rlo, rhi, allowed)) return r->err->code;
        c->rad[i] = v[3];
        snprintf(rtok, rtok_n, "%s", tok[3]);
    }
    const double R = c->rad[i];
    for (int k = 0; k < 3; ++k) {
        const double L = c->box[k];
        if (c->periodic[k])
            snprintf(allowed, sizeof allowed, "a position in [0, %g] (periodic %c axis, L%c = %g)", L, "xyz"[k],
                     "xyz"[k], L);
        else
            snprintf(allowed, sizeof allowed,
                     "a position in [%.6g, %.6g] (R = %g from the walls at 0 and L%c = %g: the colloid inside)", R,
                     L - R, R, "xyz"[k], L);
        if (in_range(r, k, tok[k], v[k], c->periodic[k] ? 0.0 : R, c->periodic[k] ? L : L - R, allowed))
            return r->err->code;
        if (c->periodic[k]) v[k] -= floor(v[k] / L) * L; /* L is 0 */
    }
    c->x[i] = v[0];
    c->y[i] = v[1];
    c->z[i] = v[2];
    return 0;
}

/* Radii from the file: the largest one's pair cut-off within half of every
 * periodic edge (what pl_colloid_validate_scene checks for the scene's own
 * radii). */
static int check_cutoff(const reader_t *r, const pl_scene_t *scene, const pl_colloid_t *c, const char *rtok)
{
    const pl_scene_colloids_t *cs = &scene->colloids;
    double rmax = 0.0;
    for (size_t i = 0; i < c->n; ++i) rmax = fmax(rmax, c->rad[i]);
    if (rmax <= cs->radius * (1.0 + sqrt(3.0) * cs->polydispersity)) return 0; /* validated with the scene */
    pl_colloid_pair_params_t p;
    pl_colloid_dlvo_info_t info;
    if (pl_colloid_pair_params(scene, &p, &info, r->err)) return r->err->code;
    const double rc = pl_colloid_pair_cutoff(&p, rmax);
    for (int k = 0; k < 3; ++k)
        if (p.periodic[k] && rc > 0.5 * c->box[k]) {
            char what[320];
            snprintf(what, sizeof what,
                     "the largest radius; its pair cut-off %.4g a0 exceeds half the periodic edge L%c = %g "
                     "(minimum image); allowed: radii whose cut-off is <= %g",
                     rc, "xyz"[k], c->box[k], 0.5 * c->box[k]);
            return bad_value(r, 3, rtok, what);
        }
    return 0;
}

int pl_colloid_read_init_file(const pl_scene_t *scene, pl_colloid_t *c, pl_err_t *err)
{
    char path[PATH_MAX];
    pl_scene_init_file_path(scene, path, sizeof path);
    char why[160];
    FILE *f = pl_input_open(path, 0, why, sizeof why);
    if (!f)
        return pl_scene_fail(scene, err, OFF(colloids.init_file), "colloids.init_file",
                             "\"%s\": %s; allowed: a regular file, one colloid per line", path, why);
    reader_t r = {.path = path, .line = 0, .err = err};
    char *line = NULL, *tok[5] = {NULL}, rtok[64] = "";
    size_t cap = 0, i = 0;
    long rline = 0;
    int ncol = 0, rc = 0;
    ssize_t len;
    double rmax = -1.0;
    while ((len = getline(&line, &cap, f)) >= 0) {
        ++r.line;
        if (memchr(line, '\0', (size_t)len)) {
            rc = pl_err_set(err, PL_ERR_INPUT, "%s:%ld: a NUL byte; allowed: text, one colloid per line", path,
                            r.line);
            break;
        }
        const char *s = line + strspn(line, " \t\r\v\f\n");
        if (*s == '#' || *s == '\0') continue;
        line[strcspn(line, "\n")] = '\0';
        if (i == c->n) {
            rc = pl_err_set(err, PL_ERR_INPUT,
                            "%s:%ld: colloid %zu of a file for colloids.count = %zu; allowed: exactly %zu colloid "
                            "lines",
                            path, r.line, i + 1, c->n, c->n);
            break;
        }
        int nt = split(line, tok, 5);
        char rt[64] = "";
        if ((rc = colloid_line(&r, scene, c, i, tok, nt, &ncol, rt, sizeof rt))) break;
        if (ncol == 4 && c->rad[i] > rmax) {
            rmax = c->rad[i];
            rline = r.line;
            snprintf(rtok, sizeof rtok, "%s", rt);
        }
        ++i;
    }
    if (!rc && ferror(f)) rc = pl_err_set(err, PL_ERR_IO, "%s:%ld: read failed", path, r.line + 1);
    free(line);
    fclose(f);
    if (!rc && i < c->n)
        rc = pl_err_set(err, PL_ERR_INPUT,
                        "%s:%ld: the file ends after %zu colloid lines; allowed: exactly colloids.count = %zu "
                        "colloid lines",
                        path, r.line > 0 ? r.line : 1, i, c->n);
    if (!rc && ncol == 4) {
        r.line = rline;
        rc = check_cutoff(&r, scene, c, rtok);
    }
    return rc;
}
