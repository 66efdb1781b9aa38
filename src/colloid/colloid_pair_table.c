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
 * Tested against the analytic terms in tests/unit/test_pair_table.c.
 *
 * The file (model units: r in a0, U in kT_ref, F in kT_ref/a0), a regular
 * file of at most PL_TABLE_FILE_MAX bytes, lines of any length:
 *   - rows "r U F" or "r U" (F then -dU/dr of the spline of U), or
 *   - one LAMMPS pair_style table section: a keyword line (one word), the
 *     parameter line "N n [R lo hi | RSQ lo hi] [FPRIME fplo fphi]" (whole
 *     words, as in the LAMMPS doc), rows "i r U F" with i = 1..n.  R and RSQ
 *     put row i at lo + (hi - lo) (i-1)/(n-1), or at the square root of that
 *     in r^2: those r are used, and a row whose own r differs from them by
 *     more than PL_TABLE_R_REL (LAMMPS's EPSILONR) is refused.  FPRIME gives
 *     dF/dr at the ends for LAMMPS's spline of F; the natural spline here
 *     takes none, so it is read and not used.  BITMAP (r from the bits of a
 *     float) is refused;
 * '#' starts a comment, blank lines are skipped.  Refused, naming the file
 * and line: a missing, unreadable, special or too large file, a NUL byte,
 * fewer than 3 rows, a malformed or non-finite number, r <= 0, r not
 * strictly increasing, a second LAMMPS section, a malformed parameter line,
 * N not the row count, and an F column inconsistent with U (check_force:
 * between neighbouring rows and at every row; inconsistent U and F break
 * energy conservation). */
#include <errno.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/colloid.h"
#include "peloid/input_file.h"

#define OFF(m) offsetof(pl_scene_t, m)
#define KEY "colloids.table_file"

/* The largest table file: 16 MiB, about 250,000 rows of 64 characters; the
 * rows are sampled onto PL_PAIR_TABLE_N intervals, so more add nothing. */
#define PL_TABLE_FILE_MAX (16LL << 20)
/* R / RSQ: the largest relative difference of a row's r from the r the
 * parameter line gives (LAMMPS pair_table.cpp EPSILONR). */
#define PL_TABLE_R_REL 1e-6

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

/* A reader's place: the scene (for the key's line), the file, its line. */
typedef struct {
    const pl_scene_t *scene;
    const char *path;
    long line;
    pl_err_t *err;
} rd_t;

/* "SCENE:LINE: key 'colloids.table_file': "PATH":LINE: " + the message;
 * PL_ERR_INPUT. */
static int fail(const rd_t *rd, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int fail(const rd_t *rd, const char *fmt, ...)
{
    char what[800];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return pl_scene_fail(rd->scene, rd->err, OFF(colloids.table_file), KEY, "\"%s\":%ld: %s", rd->path, rd->line,
                         what);
}

/* The blank-separated tokens of s (cut in place); up to max, the count
 * (max + 1 when there are more). */
static int split(char *s, char **tok, int max)
{
    int n = 0;
    for (;;) {
        s += strspn(s, " \t\r\n\v\f");
        if (!*s) return n;
        if (n == max) return max + 1;
        tok[n++] = s;
        s += strcspn(s, " \t\r\n\v\f");
        if (*s) *s++ = '\0';
    }
}

/* Whether tok is one whole finite number (into *x). */
static int number(const char *tok, double *x)
{
    char *end;
    errno = 0;
    *x = strtod(tok, &end);
    return end != tok && !*end && errno != ERANGE && isfinite(*x);
}

/* The LAMMPS section, when the file has one. */
typedef struct {
    int state;   /* 0: none (plain rows), 1: keyword line read, 2: parameter line read */
    long n, nline; /* N and its line */
    int spacing; /* 0: the rows carry r, 1: R, 2: RSQ */
    double lo, hi;
    char keyword[64];
} lammps_t;

static const char *const spacing_word[3] = {"", "R", "RSQ"};
static const char *const param_allowed =
    "allowed: \"N n [R lo hi | RSQ lo hi] [FPRIME fplo fphi]\" (LAMMPS pair_style table), n >= 2";

/* The parameter line, tokens tok[0..nt-1] (tok[0] is "N"), into *lm. */
static int param_line(const rd_t *rd, char **tok, int nt, lammps_t *lm)
{
    char *end = NULL;
    errno = 0;
    long n = nt > 1 ? strtol(tok[1], &end, 10) : 0;
    if (nt < 2 || *end || end == tok[1] || errno || n < 2)
        return fail(rd, "N \"%.40s\": not a row count; %s", nt > 1 ? tok[1] : "", param_allowed);
    if (nt > 8) return fail(rd, "more than 8 words on the parameter line; %s", param_allowed);
    int fprime = 0;
    for (int k = 2; k < nt; k += 3) {
        const char *w = tok[k];
        if (!strcmp(w, "BITMAP"))
            return fail(rd, "BITMAP: a bitmapped table (r from the bits of a float, LAMMPS pair_modify table) "
                            "cannot be read here; %s", param_allowed);
        const int sp = !strcmp(w, "R") ? 1 : !strcmp(w, "RSQ") ? 2 : 0;
        if (!sp && strcmp(w, "FPRIME")) return fail(rd, "\"%.40s\": not a parameter word; %s", w, param_allowed);
        if (sp ? lm->spacing != 0 : fprime)
            return fail(rd, "%s after %s; %s", w, sp ? spacing_word[lm->spacing] : "FPRIME", param_allowed);
        double a, b;
        if (k + 2 >= nt) return fail(rd, "%s needs two numbers; %s", w, param_allowed);
        if (!number(tok[k + 1], &a) || !number(tok[k + 2], &b))
            return fail(rd, "%s \"%.40s %.40s\": not two finite numbers; %s", w, tok[k + 1], tok[k + 2],
                        param_allowed);
        if (sp && !(a > 0.0 && b > a))
            return fail(rd, "%s %g %g: allowed: 0 < lo < hi (the first and last r)", w, a, b);
        if (sp) {
            lm->spacing = sp;
            lm->lo = a;
            lm->hi = b;
        }
        fprime |= !sp; /* read; the natural spline of F takes no end slopes */
    }
    lm->n = n;
    lm->nline = rd->line;
    lm->state = 2;
    return 0;
}

/* A line whose first word is not a number: a keyword or parameter line. */
static int word_line(const rd_t *rd, char **tok, int nt, const rows_t *t, lammps_t *lm)
{
    const int param = !strcmp(tok[0], "N");
    if (lm->state == 1 && !param)
        return fail(rd, "\"%.40s\" after the keyword line %s; %s", tok[0], lm->keyword, param_allowed);
    if (lm->state == 1) return param_line(rd, tok, nt, lm);
    if (param || !strcmp(tok[0], "R") || !strcmp(tok[0], "RSQ") || !strcmp(tok[0], "BITMAP") ||
        !strcmp(tok[0], "FPRIME"))
        return fail(rd, "parameter line \"%.40s ...\" %s; allowed: one, right after the section's keyword line",
                    tok[0], lm->state ? "given twice" : "without a keyword line before it");
    if (lm->state || t->n)
        return fail(rd, "a second table section \"%.60s\"; allowed: one section per file", tok[0]);
    if (nt > 1)
        return fail(rd, "keyword line \"%.40s %.40s...\"; allowed: the section's keyword alone on its line", tok[0],
                    tok[1]);
    snprintf(lm->keyword, sizeof lm->keyword, "%.63s", tok[0]);
    lm->state = 1;
    return 0;
}

/* A row: "r U [F]", or "i r U F" in a LAMMPS section. */
static int row_line(const rd_t *rd, char **tok, int nt, rows_t *t, const lammps_t *lm)
{
    if (lm->state == 1)
        return fail(rd, "a row right after the keyword line %s; %s", lm->keyword, param_allowed);
    const int lammps = lm->state == 2;
    const int want = lammps ? 4 : (t->n ? t->ncol : (nt == 2 || nt == 3 ? nt : 3));
    double v[4];
    for (int k = 0; k < nt && k < 4; ++k)
        if (!number(tok[k], &v[k])) return fail(rd, "\"%.60s\" is not a finite number", tok[k]);
    if (nt != want)
        return fail(rd, "%d%s columns; allowed: %s", nt, nt > 8 ? " or more" : "",
                    lammps ? "4 (i r U F) in a LAMMPS section"
                           : (t->n ? "the column count of the first row" : "2 (r U) or 3 (r U F)"));
    if (lammps && v[0] != (double)(t->n + 1))
        return fail(rd, "index %.40s; allowed: %zu (the rows numbered 1..N in order)", tok[0], t->n + 1);
    const double *x = lammps ? v + 1 : v;
    if (!(x[0] > 0.0)) return fail(rd, "r = %g; allowed: r > 0", x[0]);
    if (t->n && !(x[0] > t->r[t->n - 1]))
        return fail(rd, "r = %.17g is not above the previous row's %.17g; allowed: r strictly increasing", x[0],
                    t->r[t->n - 1]);
    t->ncol = lammps ? 3 : nt;
    if (rows_push(t, x[0], x[1], t->ncol == 3 ? x[2] : 0.0, rd->line))
        return pl_err_set(rd->err, PL_ERR_NOMEM, "colloids: out of memory (table)");
    return 0;
}

/* R / RSQ: the rows moved to the r the parameter line gives, each within
 * PL_TABLE_R_REL of its own. */
static int lammps_spacing(rd_t *rd, rows_t *t, const lammps_t *lm)
{
    for (size_t i = 0; lm->spacing && i < t->n; ++i) {
        const double s = (double)i / (double)(t->n - 1);
        const double r = lm->spacing == 1 ? lm->lo + (lm->hi - lm->lo) * s
                                          : sqrt(lm->lo * lm->lo + (lm->hi * lm->hi - lm->lo * lm->lo) * s);
        if (fabs(t->r[i] - r) > PL_TABLE_R_REL * r) {
            rd->line = t->ln[i];
            return fail(rd, "r = %.17g but %s %g %g puts row %zu at %.17g; allowed: rows within %g (relative) of "
                            "that spacing, or a parameter line without %s",
                        t->r[i], spacing_word[lm->spacing], lm->lo, lm->hi, i + 1, r, PL_TABLE_R_REL,
                        spacing_word[lm->spacing]);
        }
        t->r[i] = r;
    }
    return 0;
}

/* Reads the file's rows; errors name path:line. */
static int read_rows(const pl_scene_t *scene, const char *path, rows_t *t, pl_err_t *err)
{
    char why[160];
    FILE *fp = pl_input_open(path, PL_TABLE_FILE_MAX, why, sizeof why);
    if (!fp)
        return pl_scene_fail(scene, err, OFF(colloids.table_file), KEY,
                             "\"%s\": %s; allowed: a regular file of at most %lld bytes", path, why,
                             PL_TABLE_FILE_MAX);
    rd_t rd = {.scene = scene, .path = path, .line = 0, .err = err};
    lammps_t lm = {0};
    char *buf = NULL, *tok[9];
    size_t cap = 0;
    long long bytes = 0;
    ssize_t len;
    int rc = 0;
    while (!rc && (len = getline(&buf, &cap, fp)) >= 0) {
        ++rd.line;
        if ((bytes += len) > PL_TABLE_FILE_MAX) /* a file that grew after it was opened */
            rc = fail(&rd, "the file passes %lld bytes; allowed: at most %lld", PL_TABLE_FILE_MAX, PL_TABLE_FILE_MAX);
        else if (memchr(buf, '\0', (size_t)len))
            rc = fail(&rd, "a NUL byte; allowed: a text file");
        if (rc) break;
        buf[strcspn(buf, "#")] = '\0';
        const int nt = split(buf, tok, 8); /* the longest line: N n R lo hi FPRIME a b */
        if (!nt) continue;
        /* a row starts like a number or is one (inf and nan too, refused as such); anything else is a word */
        char *end;
        (void)strtod(tok[0], &end);
        const int row = strchr("+-.0123456789", tok[0][0]) || (end != tok[0] && !*end);
        rc = row ? row_line(&rd, tok, nt, t, &lm) : word_line(&rd, tok, nt, t, &lm);
    }
    if (!rc && ferror(fp)) rc = fail(&rd, "read failed");
    free(buf);
    fclose(fp);
    if (rc) return rc;
    if (lm.state == 1) return fail(&rd, "the file ends after the keyword line %s; %s", lm.keyword, param_allowed);
    if (t->n < 3) return fail(&rd, "%zu rows; allowed: at least 3", t->n);
    rd.line = lm.nline;
    if (lm.state == 2 && (size_t)lm.n != t->n)
        return fail(&rd, "N %ld but %zu rows follow; allowed: N = the row count", lm.n, t->n);
    return lammps_spacing(&rd, t, &lm);
}

/* The slope at r[i] of the parabola through the rows a, a+1, a+2. */
static double parabola_slope(const rows_t *t, size_t a, size_t i)
{
    const double *r = t->r + a, *u = t->u + a, x = t->r[i];
    return u[0] * ((x - r[1]) + (x - r[2])) / ((r[0] - r[1]) * (r[0] - r[2])) +
           u[1] * ((x - r[0]) + (x - r[2])) / ((r[1] - r[0]) * (r[1] - r[2])) +
           u[2] * ((x - r[0]) + (x - r[1])) / ((r[2] - r[0]) * (r[2] - r[1]));
}

/* Two columns: F = -dU/dr of the spline of U at the rows.  Three: two tests
 * against tol = colloids.table_force_tolerance times max|F|:
 *  - between neighbouring rows, the trapezoid rule for the work of F,
 *      |U_i - U_{i+1} - (r_{i+1} - r_i) (F_i + F_{i+1}) / 2| <= tol (r_{i+1} - r_i) max|F|;
 *    consistent rows miss it by (r_{i+1} - r_i)^2 max|F''| / 12, a
 *    resolution the interpolation needs anyway (D^2/8 max|F''|);
 *  - at every row, F_i against -U'_i, the slope of the parabola through the
 *    row and its two neighbours (at the first and last row: the first or
 *    last three rows): |F_i + U'_i| <= 2 tol max|F| at an inner row, 4 tol
 *    max|F| at the first and last.  The discretisation error of that slope
 *    for a smooth U is h_- h_+ max|F''| / 6 at an inner row (h_-, h_+ the
 *    spacings beside it) and h_1 (h_1 + h_2) max|F''| / 6 at an end row
 *    (F'' = -U'''): at even spacing h, 2 and 4 times the trapezoid rule's
 *    h^2/12, hence the factors, so that rows fine enough for the first test
 *    pass the second.  An F that alternates by +-A around -dU/dr passes the
 *    trapezoid rule (neighbours cancel) and misses the second by A. */
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
    rd_t rd = {.scene = scene, .path = path, .line = t->ln[at], .err = err};
    if (worst > tol * fmax)
        return fail(&rd, "from r = %.6g to %.6g U falls by %.6g but the mean of F times the step is %.6g: the mean "
                         "force misses by %.3g of max|F| = %.3g; allowed: <= colloids.table_force_tolerance = %g "
                         "(F = -dU/dr, or a finer table)",
                    t->r[at], t->r[at + 1], t->u[at] - t->u[at + 1],
                    (t->r[at + 1] - t->r[at]) * 0.5 * (t->f[at] + t->f[at + 1]), worst / fmax, fmax, tol);
    double wrel = -1.0, wslope = 0.0, wk = 2.0;
    for (size_t i = 0; i < t->n; ++i) {
        const int end = i == 0 || i + 1 == t->n;
        const double slope = parabola_slope(t, i == 0 ? 0 : (i + 1 == t->n ? t->n - 3 : i - 1), i);
        const double k = end ? 4.0 : 2.0, rel = fabs(t->f[i] + slope) / k;
        if (rel > wrel) {
            wrel = rel;
            wslope = slope;
            wk = k;
            at = i;
        }
    }
    rd.line = t->ln[at];
    if (wrel > tol * fmax)
        return fail(&rd, "at r = %.6g F = %.6g but -dU/dr of the rows around it is %.6g: F misses by %.3g of max|F| "
                         "= %.3g; allowed: <= %g x colloids.table_force_tolerance = %g at %s row (F = -dU/dr at "
                         "every row, or a finer table)",
                    t->r[at], t->f[at], 0.0 - wslope, wk * wrel / fmax, fmax, wk, wk * tol,
                    wk > 2.0 ? "an end" : "an inner");
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
    pl_scene_table_file_path(scene, path, sizeof path);
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
