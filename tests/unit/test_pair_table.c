/* The table pair term (src/colloid/colloid_pair_table.c) against the
 * analytic DLVO term it was sampled from: values and forces within the
 * interpolation error derived below, the continuation below the first row,
 * and a short MD run equal to the analytic one within the deviation its
 * force error allows.
 *
 * Error of the two interpolation stages (rows at spacing D, internal nodes at
 * h = (r_c - r_0) / PL_PAIR_TABLE_N, kernel linear between the nodes), for a
 * function g (U, or F) with local bounds M2 = max|g''|, M4 = max|g''''| on
 * the row interval:
 *   linear rows: |dg| <= D^2/8 M2 (linear interpolation) + D h/4 M2 (a row's
 *                kink inside an internal interval; the nodes lie on the
 *                piecewise-linear interpolant, so nowhere else an error);
 *   spline rows: |dg| <= 5/384 D^4 M4 (complete cubic spline, Hall 1968)
 *                + D^2/8 |g''(end)| (2 - sqrt 3)^j (the natural end
 *                condition g'' = 0 is off by g''(end); the error of the
 *                second derivatives it causes decays by 2 - sqrt 3 per row,
 *                j rows from that end) + h^2/8 M2 (internal stage). */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "colloid_test_util.h"
#include "peloid/colloid_pair_terms.h"

#define DLVO_KEYS "dlvo: { psi0 = 20.0; kappa = 1.4e8; hamaker = 4.76e-20; length_unit = 1.25e-7; };\n"
#define D_REF 4.0 /* contact distance 2R of every pair (monodisperse) */

/* The analytic DLVO term (with its primary minimum and cut-off shift). */
static pl_pair_val_t dlvo_at(const pl_colloid_pair_params_t *p, double r)
{
    return pl_pair_dlvo(r, D_REF, p->coul_C, p->kappa, p->hamaker, p->prim_hm, p->prim_h0, p->dlvo_shift);
}

static void dlvo_params(pl_colloid_pair_params_t *p)
{
    pl_scene_t s;
    scene_from("box: { cells = [24, 24, 24]; }; fluid: { density = 0.0; };\n"
               "colloids: { count = 8; radius = 2.0; pairs = \"dlvo\"; };\n" DLVO_KEYS, &s);
    pl_colloid_dlvo_info_t info;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_colloid_pair_params(&s, p, &info, &err), 0, "%s", err.msg);
}

/* Writes rows r U F of the DLVO term at n steps, r0 + (r1 - r0) (k/(n-1))^2, to
 * table.txt in a fresh directory (the scene's, see table_scene); the
 * directory into dir. */
static void write_table(const pl_colloid_pair_params_t *p, double r0, double r1, int n, char *dir)
{
    strcpy(dir, "/tmp/peloid_table_XXXXXX");
    cr_assert(mkdtemp(dir));
    char path[96];
    snprintf(path, sizeof path, "%s/table.txt", dir);
    FILE *f = fopen(path, "w");
    cr_assert(f);
    fprintf(f, "# DLVO (Hecht Eqs. 1-2 + primary minimum), R = 2 a0\n");
    for (int k = 0; k < n; ++k) { /* denser where the force is steep, near r0 */
        double x = (double)k / (n - 1), r = k == n - 1 ? r1 : r0 + (r1 - r0) * x * x;
        pl_pair_val_t v = dlvo_at(p, r);
        fprintf(f, "%.17g %.17g %.17g\n", r, v.u, v.f);
    }
    fclose(f);
}

static void remove_table(const char *dir)
{
    char path[96];
    snprintf(path, sizeof path, "%s/table.txt", dir);
    unlink(path);
    rmdir(dir);
}

/* The scene, as if read from dir/test.cfg (no dir: ./test.cfg, no table). */
static void table_scene(const char *dir, const char *interp, const char *pairs, pl_scene_t *s)
{
    char body[1024], tab[256] = "", cfg[96];
    if (dir) snprintf(tab, sizeof tab, "table_file = \"table.txt\"; table_interpolation = \"%s\";", interp);
    snprintf(cfg, sizeof cfg, "%s%stest.cfg", dir ? dir : "", dir ? "/" : "");
    snprintf(body, sizeof body,
             "box: { cells = [24, 24, 24]; }; fluid: { density = 0.0; }; srd: { dt = 0.1; };\n"
             "colloids: { count = 27; radius = 2.0; temperature = 1.0; substeps = 12;\n"
             "  pairs = \"%s\"; %s max_energy_drift = 0.0; };\n"
             "hertz: { K = 1000.0; };\n" DLVO_KEYS,
             pairs, tab);
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_scene_load_string(body, cfg, s, &err), 0, "scene refused: %s", err.msg);
}

/* max over [a, b] of |g''| and |g''''| for g = U (k2 and its second
 * difference) or g = F (= -U': the differences of k2 give F'' = -U'''). */
static void bounds(const pl_colloid_pair_params_t *p, double a, double b, int force, double *m2, double *m4)
{
    const double e = 1e-4;
    *m2 = *m4 = 0.0;
    for (int q = 0; q <= 16; ++q) {
        double r = a + (b - a) * q / 16.0;
        double k0 = dlvo_at(p, r).k2, kp = dlvo_at(p, r + e).k2, km = dlvo_at(p, r - e).k2;
        double kpp = dlvo_at(p, r + 2 * e).k2, kmm = dlvo_at(p, r - 2 * e).k2;
        double d1 = (kp - km) / (2 * e), d2 = (kp - 2 * k0 + km) / (e * e);
        double d3 = (kpp - 2 * kp + 2 * km - kmm) / (2 * e * e * e);
        *m2 = fmax(*m2, fabs(force ? d1 : k0));
        *m4 = fmax(*m4, fabs(force ? d3 : d2));
    }
}

typedef struct {
    const pl_colloid_pair_params_t *p;
    double r0, L;
    int n, spline, force;
    double end2[2]; /* |g''| at the two ends */
} rows_t;

/* the row k of the table written by write_table */
static double row_r(const rows_t *t, int k)
{
    double x = (double)k / (t->n - 1);
    return k >= t->n - 1 ? t->r0 + t->L : t->r0 + t->L * x * x;
}

/* The error bound of the rows' interpolant (stage 1) at x. */
static double stage1_bound(const rows_t *t, double x)
{
    int i = (int)floor((t->n - 1) * sqrt(fmax(0.0, (x - t->r0) / t->L)));
    i = i < 0 ? 0 : (i > t->n - 2 ? t->n - 2 : i);
    double m2, m4;
    if (!t->spline) {
        double D = row_r(t, i + 1) - row_r(t, i);
        bounds(t->p, row_r(t, i), row_r(t, i + 1), t->force, &m2, &m4);
        return D * D / 8.0 * m2;
    }
    int lo = i > 0 ? i - 1 : 0, hi = i + 2 < t->n - 1 ? i + 2 : t->n - 1;
    double D = 0.0;
    for (int k = lo; k < hi; ++k) D = fmax(D, row_r(t, k + 1) - row_r(t, k));
    bounds(t->p, row_r(t, lo), row_r(t, hi), t->force, &m2, &m4);
    int j0 = i, j1 = t->n - 2 - i; /* rows to each end */
    return 5.0 / 384.0 * pow(D, 4) * m4 +
           D * D / 8.0 * (t->end2[0] * pow(2.0 - sqrt(3.0), j0) + t->end2[1] * pow(2.0 - sqrt(3.0), j1));
}

/* The bound at r: stage 1 at the two internal nodes around r, plus the
 * internal linear stage h^2/8 max|g''| (|L_h g1 - g| <= max_nodes |g1 - g|
 * + |L_h g - g|). */
static double table_bound(const rows_t *t, double r, double h)
{
    double n0 = t->r0 + floor((r - t->r0) / h) * h, n1 = fmin(n0 + h, t->r0 + t->L), m2, m4;
    bounds(t->p, n0, n1, t->force, &m2, &m4);
    return fmax(stage1_bound(t, n0), stage1_bound(t, n1)) + h * h / 8.0 * m2;
}

/* The DLVO tail from the match gap to the cut-off (smooth: Eqs. 1-2). */
static void check_accuracy(const char *interp)
{
    pl_colloid_pair_params_t pd, pt;
    dlvo_params(&pd);
    const int n = 200;
    const double r0 = D_REF + pd.prim_hm, r1 = D_REF + pd.dlvo_hcut;
    char path[64];
    write_table(&pd, r0, r1, n, path);
    pl_scene_t s;
    table_scene(path, interp, "table", &s);
    pl_colloid_dlvo_info_t info;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_colloid_pair_params(&s, &pt, &info, &err), 0, "%s", err.msg);
    remove_table(path);
    cr_expect_eq(pl_colloid_pair_rc(&pt, pt.terms, D_REF), r1, "cut-off %.17g, want the last r %.17g",
                 pl_colloid_pair_rc(&pt, pt.terms, D_REF), r1);
    const double h = (r1 - r0) / PL_PAIR_TABLE_N;
    rows_t tu = {&pd, r0, r1 - r0, n, !strcmp(interp, "spline"), 0, {0, 0}}, tf = tu;
    tf.force = 1;
    double dummy;
    bounds(&pd, r0, r0, 0, &tu.end2[0], &dummy);
    bounds(&pd, r1, r1, 0, &tu.end2[1], &dummy);
    bounds(&pd, r0, r0, 1, &tf.end2[0], &dummy);
    bounds(&pd, r1, r1, 1, &tf.end2[1], &dummy);
    double worst_u = 0.0, worst_f = 0.0; /* error / bound */
    for (int q = 0; q < 3000; ++q) {
        double r = r0 + (r1 - r0) * (q + 0.37) / 3000.0;
        double bu = table_bound(&tu, r, h), bf = table_bound(&tf, r, h);
        pl_pair_val_t x = dlvo_at(&pd, r), y = pl_pair_term_TAB(&pt, r, D_REF);
        double eu = fabs(y.u - x.u), ef = fabs(y.f - x.f), tiny = 1e-12 * (fabs(x.u) + fabs(x.f));
        cr_expect(eu <= bu + tiny, "%s r=%.6g: U %.12g vs %.12g, error %.3g > bound %.3g", interp, r, y.u, x.u,
                  eu, bu);
        cr_expect(ef <= bf + tiny, "%s r=%.6g: F %.12g vs %.12g, error %.3g > bound %.3g", interp, r, y.f, x.f,
                  ef, bf);
        worst_u = fmax(worst_u, eu / (bu + tiny));
        worst_f = fmax(worst_f, ef / (bf + tiny));
    }
    cr_log_info("%s: largest error / bound: U %.3g, F %.3g", interp, worst_u, worst_f);
    /* below the first row: U continues with the first row's force */
    pl_pair_val_t v0 = pl_pair_term_TAB(&pt, r0, D_REF), vb = pl_pair_term_TAB(&pt, r0 - 0.1, D_REF);
    cr_expect(vb.f == v0.f && fabs(vb.u - (v0.u + 0.1 * v0.f)) < 1e-12 * (1 + fabs(v0.u)),
              "below r0: U %.12g F %.12g (first row U %.12g F %.12g)", vb.u, vb.f, v0.u, v0.f);
}

Test(pair_table, linear_rows_within_bound) { check_accuracy("linear"); }
Test(pair_table, spline_rows_within_bound) { check_accuracy("spline"); }

/* The smallest surface gap of monodisperse colloids in the periodic 24^3 box. */
static double min_gap(const pl_colloid_t *c)
{
    double gap = INFINITY;
    for (size_t i = 0; i < c->n; ++i)
        for (size_t j = i + 1; j < c->n; ++j) {
            double ex = pl_min_image(c->x[i] - c->x[j], 24, 1), ey = pl_min_image(c->y[i] - c->y[j], 24, 1);
            double ez = pl_min_image(c->z[i] - c->z[j], 24, 1);
            gap = fmin(gap, sqrt(ex * ex + ey * ey + ez * ez) - D_REF);
        }
    return gap;
}

/* MD: the NVE scene of test_colloid_md (27 colloids, DLVO + Hertz) with the
 * DLVO term from a table (3000 spline rows from 12.5 % overlap to the
 * cut-off, across the primary minimum) against the analytic term. */
Test(pair_table, md_matches_analytic, .timeout = 60)
{
    pl_colloid_pair_params_t pd;
    dlvo_params(&pd);
    char path[64];
    const double r0 = D_REF - 0.5, r1 = D_REF + pd.dlvo_hcut;
    write_table(&pd, r0, r1, 3000, path);
    pl_scene_t sa, sb;
    table_scene(NULL, "spline", "dlvo, hertz", &sa);
    table_scene(path, "spline", "table, hertz", &sb);
    pl_colloid_t *a, *b;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_colloid_create(&sa, 1, &a, &err), 0, "%s", err.msg);
    cr_assert_eq(pl_colloid_create(&sb, 1, &b, &err), 0, "%s", err.msg);
    remove_table(path);
    pl_colloid_energy_t ea, eb, eb0;
    pl_colloid_energy(a, &ea);
    pl_colloid_energy(b, &eb0);
    cr_expect(fabs(ea.pot[PL_CE_DLVO] - eb0.pot[PL_CE_TAB]) < 1e-6, "U at start: dlvo %.12g, table %.12g",
              ea.pot[PL_CE_DLVO], eb0.pot[PL_CE_TAB]);
    const long steps = 1200;
    double drift = 0.0, gmin = min_gap(a);
    for (long k = 0; k < steps; ++k) {
        cr_assert_eq(pl_colloid_md_step(a, &err), 0, "%s", err.msg);
        cr_assert_eq(pl_colloid_md_step(b, &err), 0, "%s", err.msg);
        if (k % 100 == 99) {
            gmin = fmin(gmin, min_gap(a));
            pl_colloid_energy(b, &eb);
            drift = fmax(drift, fabs(eb.total - eb0.total) / (double)b->n);
        }
    }
    double dx = 0.0;
    for (size_t i = 0; i < a->n; ++i)
        dx = fmax(dx, fmax(fabs(a->x[i] - b->x[i]), fmax(fabs(a->y[i] - b->y[i]), fabs(a->z[i] - b->z[i]))));
    cr_log_info("MD: max |x_table - x_dlvo| = %.3g a0 after %ld MD steps; table NVE drift %.3g kT/colloid", dx,
                steps, drift);
    /* the deviation the force error allows: each colloid feels at most its 6
     * lattice neighbours (spacing 8 a0 < r_c < 8 sqrt 2), each pair force
     * off by at most dF over the gaps the run visited (the smallest seen
     * every 100 MD steps, less 0.2 a0: 100 steps move a colloid ~0.07 a0 at
     * kT = 1; dF the derived bound, table_bound, not the measured error):
     * the deviation obeys |dx''| <= a + w^2 |dx| with a = 6 dF / m
     * and w^2 = 6 max|U''| / m (its own feedback through the force
     * gradient), so |dx(t)| <= a / w^2 (cosh(w t) - 1) (linearised; the
     * 1.25 covers the next order) */
    double dF = 0.0, k2 = 0.0, measured = 0.0;
    const double g0 = gmin - 0.2;
    cr_assert(g0 > pd.prim_hm, "pairs came within %.3g a0", gmin);
    rows_t tf = {&pd, r0, r1 - r0, 3000, 1, 1, {0, 0}};
    double dummy;
    bounds(&pd, r0, r0, 1, &tf.end2[0], &dummy);
    bounds(&pd, r1, r1, 1, &tf.end2[1], &dummy);
    for (int q = 0; q < 4000; ++q) {
        double r = D_REF + g0 + (r1 - D_REF - g0) * (q + 0.5) / 4000.0;
        dF = fmax(dF, table_bound(&tf, r, (r1 - r0) / PL_PAIR_TABLE_N));
        measured = fmax(measured, fabs(pl_pair_term_TAB(&b->pair, r, D_REF).f - dlvo_at(&pd, r).f));
        k2 = fmax(k2, fabs(dlvo_at(&pd, r).k2));
    }
    const double t = (double)steps * a->dt, w = sqrt(6.0 * k2 / a->mass[0]);
    const double est = 6.0 * dF / a->mass[0] / (w * w) * (cosh(w * t) - 1.0);
    cr_log_info("MD: gaps >= %.3g a0, force error there <= %.3g kT/a0 (measured %.3g), deviation allowed %.3g a0, "
                "found %.3g", gmin, dF, measured, 1.25 * est, dx);
    cr_expect(dx <= 1.25 * est, "positions differ by %.3g a0, more than 1.25 x %.3g", dx, est);
    pl_colloid_free(a);
    pl_colloid_free(b);
}

/* ---- the reader (read_rows, check_force) ---- */

/* Writes text to dir/table.txt in a fresh directory (into dir). */
static void write_text(const char *text, char *dir)
{
    strcpy(dir, "/tmp/peloid_table_XXXXXX");
    cr_assert(mkdtemp(dir));
    char path[96];
    snprintf(path, sizeof path, "%s/table.txt", dir);
    FILE *f = fopen(path, "w");
    cr_assert(f);
    fputs(text, f);
    fclose(f);
}

/* The table term of dir/table.txt (the scene's load reads it too): 0, or
 * the error (in err). */
static int read_table(const char *dir, pl_colloid_pair_params_t *p, pl_err_t *err)
{
    char body[512], cfg[96];
    snprintf(cfg, sizeof cfg, "%s/test.cfg", dir);
    snprintf(body, sizeof body,
             "box: { cells = [24, 24, 24]; }; fluid: { density = 0.0; };\n"
             "colloids: { count = 8; radius = 2.0; pairs = \"table\"; table_file = \"table.txt\"; };\n");
    pl_scene_t *s = malloc(sizeof *s);
    cr_assert(s);
    int rc = pl_scene_load_string(body, cfg, s, err);
    pl_colloid_dlvo_info_t info;
    if (!rc) rc = pl_colloid_pair_params(s, p, &info, err);
    free(s);
    return rc;
}

/* The LAMMPS words N, R, RSQ, FPRIME as words: FPRIME read and unused, R and
 * RSQ give the rows' r (a row 1e-7 off lands on the spacing); a keyword
 * that starts like "inf" is a word; a comment of any length is one line. */
Test(pair_table, lammps_words)
{
    static const char *const ok[] = {
        "TAB\nN 3 FPRIME 0.0 0.0\n\n1 4.0 0.33333333 0.16666667\n2 5.0 0.16666667 0.16666667\n3 6.0 0.0 0.16666667\n",
        "TAB\nN 3 R 4.0 6.0 FPRIME -1 1\n1 4.0000004 0.33333333 0.16666667\n2 5.0 0.16666667 0.16666667\n"
        "3 6.0 0.0 0.16666667\n",
        "TAB\nN 3 RSQ 4.0 6.0\n1 4.0 0.33333333 0.16666667\n2 5.0990195 0.15016341 0.16666667\n3 6.0 0.0 0.16666667\n",
        "INFLUENCE\nN 3\n1 4.0 0.33333333 0.16666667\n2 5.0 0.16666667 0.16666667\n3 6.0 0.0 0.16666667\n",
        NULL};
    for (int k = 0; ok[k]; ++k) {
        char dir[64];
        write_text(ok[k], dir);
        pl_colloid_pair_params_t p;
        pl_err_t err = {0, ""};
        int rc = read_table(dir, &p, &err);
        remove_table(dir);
        cr_expect_eq(rc, 0, "table %d refused: %s", k, err.msg);
        if (!rc) cr_expect(p.tab_r0 == 4.0 && p.tab_rc == 6.0, "table %d: r from %.17g to %.17g", k, p.tab_r0, p.tab_rc);
    }
    char *text = malloc(20000);
    cr_assert(text);
    strcpy(text, "# ");
    for (int k = 0; k < 1000; ++k) strcat(text, "comment ");
    strcat(text, "\n4.0 0.3333333333 0.1666666667\n5.0 0.1666666667 0.1666666667  # and another\n"
                 "6.0 0.0 0.1666666667\n");
    char dir[64];
    write_text(text, dir);
    free(text);
    pl_colloid_pair_params_t p;
    pl_err_t err = {0, ""};
    cr_expect_eq(read_table(dir, &p, &err), 0, "a long comment: %s", err.msg);
    remove_table(dir);
}

/* What the reader refuses, each naming the key and what is allowed: a pipe
 * (without waiting for a writer), a file over 16 MiB (sparse), BITMAP, an R
 * spacing the rows do not follow, a force that alternates around -dU/dr. */
Test(pair_table, reader_refuses, .timeout = 20)
{
    char dir[64], path[96];
    pl_colloid_pair_params_t p;
    strcpy(dir, "/tmp/peloid_table_XXXXXX");
    cr_assert(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/table.txt", dir);
    cr_assert_eq(mkfifo(path, 0600), 0);
    pl_err_t err = {0, ""};
    cr_expect(read_table(dir, &p, &err) == PL_ERR_INPUT && strstr(err.msg, "colloids.table_file") &&
                  strstr(err.msg, "pipe") && strstr(err.msg, "allowed: a regular file"),
              "a pipe: %s", err.msg);
    unlink(path);
    FILE *f = fopen(path, "w");
    cr_assert(f);
    fputs("4.0 0.3333333333 0.1666666667\n5.0 0.1666666667 0.1666666667\n6.0 0.0 0.1666666667\n", f);
    fclose(f);
    cr_assert_eq(truncate(path, (16 << 20) + 1), 0);
    cr_expect(read_table(dir, &p, &err) == PL_ERR_INPUT && strstr(err.msg, "has 16777217 bytes") &&
                  strstr(err.msg, "at most 16777216"),
              "16 MiB + 1: %s", err.msg);
    remove_table(dir);
    static const struct {
        const char *text, *want;
    } bad[] = {
        {"TAB\nN 3 BITMAP 2 4\n1 4 0.3 0.1\n2 5 0.2 0.1\n3 6 0 0.1\n", "BITMAP"},
        {"TAB\nN 3 R 4.0 7.0\n1 4 0.3 0.1\n2 5 0.2 0.1\n3 6 0 0.1\n", "R 4 7 puts row 2 at 5.5"},
        {"TAB\nN 3 R 4.0\n1 4 0.3 0.1\n2 5 0.2 0.1\n3 6 0 0.1\n", "R needs two numbers"},
        {"N 3\n4 0.3 0.1\n5 0.2 0.1\n6 0 0.1\n", "without a keyword line"},
        {"TAB\n1 4 0.3 0.1\n2 5 0.2 0.1\n3 6 0 0.1\n", "right after the keyword line"},
        {"TAB\nN 3\n1 4 0.3 0.1\n3 5 0.2 0.1\n3 6 0 0.1\n", "index 3; allowed: 2"},
        {"4.0 0 -50\n4.05 0 50\n4.1 0 -50\n4.15 0 50\n4.2 0 -50\n", "F misses by 1 of max|F| = 50"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        write_text(bad[k].text, dir);
        pl_err_clear(&err);
        int rc = read_table(dir, &p, &err);
        remove_table(dir);
        cr_expect(rc == PL_ERR_INPUT && strstr(err.msg, bad[k].want) && strstr(err.msg, "allowed"),
                  "table %zu: want \"%s\", got rc %d: %s", k, bad[k].want, rc, err.msg);
    }
}
