/* The table pair term (colloids.pairs "table", a row of the pair-term table
 * PL_PAIR_TERMS): a colloid-colloid potential U(r) of the centre distance
 * read from colloids.table_file, as LAMMPS pair_style table.  The file's
 * rows are interpolated (GSL gsl_interp: linear or natural cubic spline,
 * colloids.table_interpolation) onto PL_PAIR_TABLE_N equal intervals from
 * its first r to its last, the cut-off; the force kernel interpolates U and
 * F linearly between those nodes (pl_pair_term_TAB).  Interpolation error
 * for a smooth U sampled at spacing D (internal spacing h):
 *   |dU| <= D^2/8 max|U''| + h^2/8 max|U''|,  |dF| <= D^2/8 max|F''| + h^2/8 max|F''|
 * with linear rows; with the spline the first term falls to O(D^4) away
 * from the ends (natural end conditions: O(D^2) within a few rows of them).
 * Tested against the analytic terms in tests/test_pair_table.c.
 *
 * The file (model units: r in a0, U in kT_ref, F in kT_ref/a0):
 *   - rows "r U F" or "r U" (F then -dU/dr of the spline of U), or
 *   - one LAMMPS table section: a keyword line, a line "N n" (no R, RSQ or
 *     BITMAP: the rows carry their own r), rows "i r U F";
 * '#' starts a comment, blank lines are skipped.  Refused, naming the file
 * and line: a missing or unreadable file, fewer than 3 rows, a malformed or
 * non-finite number, r <= 0, r not strictly increasing, a second LAMMPS
 * section, N not the row count, and an F column that disagrees with the
 * change of U between neighbouring rows (check_force) by more than
 * colloids.table_force_tolerance times max|F| (inconsistent U and F break
 * energy conservation). */
#include <errno.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/colloid.h"

#define OFF(m) offsetof(pl_scene_t, m)
#define KEY "colloids.table_file"

typedef struct {
    size_t n, cap;
    double *r, *u, *f;
    long *ln; /* the file line of each row */
    int ncol; /* 2 or 3 (r U [F]) */
} rows_t;

static void rows_free(rows_t *t)
{
    free(t->r);
    free(t->u);
    free(t->f);
    free(t->ln);
}

static int rows_push(rows_t *t, double r, double u, double f, long line)
{
    if (t->n == t->cap) {
        size_t c = t->cap ? 2 * t->cap : 256;
        double *a = realloc(t->r, c * sizeof *a);
        if (a) t->r = a;
        double *b = realloc(t->u, c * sizeof *b);
        if (b) t->u = b;
        double *e = realloc(t->f, c * sizeof *e);
        if (e) t->f = e;
        long *l = realloc(t->ln, c * sizeof *l);
        if (l) t->ln = l;
        if (!a || !b || !e || !l) return -1;
        t->cap = c;
    }
    t->r[t->n] = r;
    t->u[t->n] = u;
    t->f[t->n] = f;
    t->ln[t->n] = line;
    ++t->n;
    return 0;
}

/* The numbers of a line (up to 5); -1 on a token that is not a finite number
 * (copied into bad). */
static int numbers(char *s, double *v, char *bad, size_t nbad)
{
    int k = 0;
    for (char *tok = strtok(s, " \t\r\n"); tok; tok = strtok(NULL, " \t\r\n")) {
        char *end;
        errno = 0;
        double x = strtod(tok, &end);
        if (*end || end == tok || errno == ERANGE || !isfinite(x) || k == 5) {
            snprintf(bad, nbad, "%.60s", tok);
            return -1;
        }
        v[k++] = x;
    }
    return k;
}

/* Reads the file's rows; errors name path:line. */
static int read_rows(const pl_scene_t *scene, const char *path, rows_t *t, pl_err_t *err)
{
    FILE *fp = fopen(path, "r");
    if (!fp)
        return pl_scene_fail(scene, err, OFF(colloids.table_file), KEY, "cannot open \"%s\": %s", path,
                             strerror(errno));
    char buf[1024], bad[64];
    long line = 0, nline = -1, sections = 0, n_decl = -1;
    int lammps = 0, rc = 0;
    while (!rc && fgets(buf, sizeof buf, fp)) {
        ++line;
        char *hash = strchr(buf, '#');
        if (hash) *hash = '\0';
        size_t len = strlen(buf);
        while (len && strchr(" \t\r\n", buf[len - 1])) buf[--len] = '\0';
        char *s = buf + strspn(buf, " \t\r\n");
        if (!*s) continue;
        char *numend;
        (void)strtod(s, &numend);
        if (numend == s) { /* not a number (nan and inf are, and are refused below): LAMMPS keyword or N line */
            if (s[0] == 'N' && (s[1] == ' ' || s[1] == '\t')) {
                char *e;
                n_decl = strtol(s + 1, &e, 10);
                nline = line;
                if (strstr(e, "R") || n_decl < 2)
                    rc = pl_scene_fail(scene, err, OFF(colloids.table_file), KEY,
                                       "\"%s\":%ld: \"%.60s\": allowed: \"N n\" (n >= 2, optionally FPRIME; "
                                       "no R, RSQ or BITMAP: the rows carry their own r)", path, line, s);
                continue;
            }
            if (++sections > 1 || t->n)
                rc = pl_scene_fail(scene, err, OFF(colloids.table_file), KEY,
                                   "\"%s\":%ld: a second table section \"%.60s\"; allowed: one section "
                                   "per file", path, line, strtok(s, " \t\r\n"));
            lammps = 1;
            continue;
        }
        double v[5];
        int k = numbers(s, v, bad, sizeof bad);
        int want = lammps ? 4 : (t->n ? t->ncol : (k == 2 || k == 3 ? k : 3));
        if (k < 0) {
            rc = pl_scene_fail(scene, err, OFF(colloids.table_file), KEY,
                               "\"%s\":%ld: \"%s\" is not a finite number", path, line, bad);
        } else if (k != want) {
            rc = pl_scene_fail(scene, err, OFF(colloids.table_file), KEY,
                               "\"%s\":%ld: %d columns; allowed: %s", path, line, k,
                               lammps ? "4 (i r U F) in a LAMMPS section"
                                      : (t->n ? "the column count of the first row" : "2 (r U) or 3 (r U F)"));
        } else {
            const double *x = lammps ? v + 1 : v;
            t->ncol = lammps ? 3 : k;
            if (!(x[0] > 0.0))
                rc = pl_scene_fail(scene, err, OFF(colloids.table_file), KEY,
                                   "\"%s\":%ld: r = %g; allowed: r > 0", path, line, x[0]);
            else if (t->n && !(x[0] > t->r[t->n - 1]))
                rc = pl_scene_fail(scene, err, OFF(colloids.table_file), KEY,
                                   "\"%s\":%ld: r = %.17g is not above the previous row's %.17g; allowed: r "
                                   "strictly increasing", path, line, x[0], t->r[t->n - 1]);
            else if (rows_push(t, x[0], x[1], t->ncol == 3 ? x[2] : 0.0, line))
                rc = pl_err_set(err, PL_ERR_NOMEM, "colloids: out of memory (table)");
        }
    }
    fclose(fp);
    if (rc) return rc;
    if (t->n < 3)
        return pl_scene_fail(scene, err, OFF(colloids.table_file), KEY,
                             "\"%s\":%ld: %zu rows; allowed: at least 3", path, line, t->n);
    if (n_decl >= 0 && (size_t)n_decl != t->n)
        return pl_scene_fail(scene, err, OFF(colloids.table_file), KEY,
                             "\"%s\":%ld: N %ld but %zu rows follow; allowed: N = the row count", path, nline,
                             n_decl, t->n);
    return 0;
}

/* Two columns: F = -dU/dr of the spline of U at the rows.  Three: each
 * pair of neighbouring rows must have
 *   |U_i - U_{i+1} - (r_{i+1} - r_i) (F_i + F_{i+1}) / 2| <= tol (r_{i+1} - r_i) max|F|
 * (the trapezoid rule for the work of F; consistent rows miss it by
 * (r_{i+1} - r_i)^2 |F''| / 12 relative, a resolution the interpolation needs
 * anyway). */
static int check_force(const pl_scene_t *scene, const char *path, rows_t *t, pl_err_t *err)
{
    if (t->ncol == 2) {
        gsl_interp *sp = gsl_interp_alloc(gsl_interp_cspline, t->n);
        if (!sp) return pl_err_set(err, PL_ERR_NOMEM, "colloids: out of memory (table spline)");
        int rc = 0;
        if (gsl_interp_init(sp, t->r, t->u, t->n))
            rc = pl_scene_fail(scene, err, OFF(colloids.table_file), KEY, "\"%s\": GSL cannot fit a spline to U", path);
        for (size_t i = 0; i < t->n && !rc; ++i) t->f[i] = -gsl_interp_eval_deriv(sp, t->r, t->u, t->r[i], NULL);
        gsl_interp_free(sp);
        return rc;
    }
    double fmax = 0.0, worst = -1.0;
    size_t at = 0;
    for (size_t i = 0; i < t->n; ++i) fmax = fmax > fabs(t->f[i]) ? fmax : fabs(t->f[i]);
    for (size_t i = 0; i + 1 < t->n; ++i) {
        double dr = t->r[i + 1] - t->r[i];
        double miss = fabs(t->u[i] - t->u[i + 1] - dr * 0.5 * (t->f[i] + t->f[i + 1])) / dr;
        if (miss > worst) {
            worst = miss;
            at = i;
        }
    }
    const double tol = scene->colloids.table_force_tolerance;
    if (worst > tol * fmax)
        return pl_scene_fail(scene, err, OFF(colloids.table_file), KEY,
                             "\"%s\":%ld: from r = %.6g to %.6g U falls by %.6g but the mean of F times "
                             "the step is %.6g: the mean force misses by %.3g of max|F| = %.3g; allowed: <= "
                             "colloids.table_force_tolerance = %g (F = -dU/dr, or a finer table)",
                             path, t->ln[at], t->r[at], t->r[at + 1], t->u[at] - t->u[at + 1],
                             (t->r[at + 1] - t->r[at]) * 0.5 * (t->f[at] + t->f[at + 1]), worst / fmax, fmax, tol);
    return 0;
}

int pl_colloid_term_setup_tab(const pl_scene_t *scene, pl_colloid_pair_params_t *p,
                              pl_colloid_dlvo_info_t *info, pl_err_t *err)
{
    (void)info;
    const pl_scene_colloids_t *cs = &scene->colloids;
    if (!(p->terms & PL_CT_TAB)) {
        if (cs->table_file[0])
            return pl_scene_fail(scene, err, OFF(colloids.table_file), KEY,
                                 "\"%s\" is given but colloids.pairs has no table; allowed: add table to "
                                 "colloids.pairs, or leave the key out", cs->table_file);
        return 0;
    }
    if (scene->mapping.enabled)
        return pl_scene_fail(scene, err, OFF(colloids.pairs), "colloids.pairs",
                             "the table pair term reads U(r) in model units (a0, kT_ref), and a physical{} "
                             "scene derives its model units; allowed: table in a model-unit scene");
    if (!cs->table_file[0])
        return pl_scene_fail(scene, err, OFF(colloids.pairs), "colloids.pairs",
                             "the table pair term needs colloids.table_file");
    char path[640];
    const char *slash = strrchr(scene->path, '/');
    int dl = cs->table_file[0] != '/' && slash ? (int)(slash - scene->path) + 1 : 0;
    snprintf(path, sizeof path, "%.*s%s", dl, scene->path, cs->table_file);
    rows_t t = {0};
    int rc = read_rows(scene, path, &t, err);
    if (!rc) rc = check_force(scene, path, &t, err);
    gsl_interp *iu = NULL, *ifo = NULL;
    if (!rc) {
        const gsl_interp_type *type =
            cs->table_interpolation == PL_TABLE_LINEAR ? gsl_interp_linear : gsl_interp_cspline;
        iu = gsl_interp_alloc(type, t.n);
        ifo = gsl_interp_alloc(type, t.n);
        if (!iu || !ifo) rc = pl_err_set(err, PL_ERR_NOMEM, "colloids: out of memory (table)");
        else if (gsl_interp_init(iu, t.r, t.u, t.n) || gsl_interp_init(ifo, t.r, t.f, t.n))
            rc = pl_scene_fail(scene, err, OFF(colloids.table_file), KEY, "\"%s\": GSL cannot interpolate the rows", path);
    }
    if (!rc) {
        const int N = PL_PAIR_TABLE_N;
        const double r0 = t.r[0], rc_ = t.r[t.n - 1], h = (rc_ - r0) / N;
        p->tab_r0 = r0;
        p->tab_rc = rc_;
        p->tab_inv_h = N / (rc_ - r0);
        for (int k = 0; k <= N && !rc; ++k) {
            double r = k == N ? rc_ : fmin(r0 + k * h, rc_), u = 0.0, f = 0.0;
            if (gsl_interp_eval_e(iu, t.r, t.u, r, NULL, &u) || gsl_interp_eval_e(ifo, t.r, t.f, r, NULL, &f)) {
                rc = pl_scene_fail(scene, err, OFF(colloids.table_file), KEY,
                                   "\"%s\": GSL cannot evaluate the table at r = %g", path, r);
                break;
            }
            p->tab_uf[2 * k] = u;
            p->tab_uf[2 * k + 1] = f;
        }
        p->tab_uf[2 * (N + 1)] = p->tab_uf[2 * N];
        p->tab_uf[2 * (N + 1) + 1] = p->tab_uf[2 * N + 1];
    }
    gsl_interp_free(iu);
    gsl_interp_free(ifo);
    rows_free(&t);
    return rc;
}
