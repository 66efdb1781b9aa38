/* The hydrodynamically matched resolution of coupling I for `peloid plan`
 * and the resolution table of the calibration (calibration_table.c; issue
 * 45).  A coupling I colloid's friction is its Stokes friction in
 * series with the finite friction of the fluid's collisions with its surface
 * (PL Eqs. 40-41), so its hydrodynamic radius R_h falls short of R by a
 * share that shrinks with the resolution R/a0.  A resolution study measured
 * R/R_h - 1 = b + c a0/R for one fluid (tools/rh_resolution.py, rules
 * validation/RULES_rh_resolution.md, its section of validation/REPORT.md)
 * and wrote calibration/rh_resolution-X.json (X: the study's name after
 * rh_resolution_): the fluid, the points,
 * the law and the R/a0 at which R_h/R = 0.95 (or why none).  A scene's fluid
 * matches a file when its collision rule, rotation angle, grid shift,
 * particles per cell, mean free path and coupling I surface rule are the
 * file's; the colloid's mass density is reported beside it (the friction
 * depends on the colloid mass by a few per cent, the rules' pilot runs).
 * Where the law's resolution was run (tools/rh_matched.py, rule R8), the
 * file's "check" holds that run's R_h/R and verdict. */
#include "advise_match.h"

#include <dirent.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "peloid/collision_rule.h"

#define LAW_PREFIX "rh_resolution-" /* the law files: LAW_PREFIX X ".json" */
#define LAW_SUFFIX ".json"

static int near(double a, double b) { return fabs(a - b) <= 1e-9 * fmax(fabs(a), fabs(b)); }

static double num(json_t *o, const char *key)
{
    json_t *v = json_object_get(o, key);
    return json_is_number(v) ? json_number_value(v) : NAN;
}

static const char *str(json_t *o, const char *key)
{
    const char *v = json_string_value(json_object_get(o, key));
    return v ? v : "";
}

/* The scene's model fluid is the file's. */
static int same_fluid(const pl_scene_t *s, json_t *fl)
{
    const pl_collision_rule_t *rule = pl_collision_rule(s->srd.rule);
    const double lambda = s->srd.dt * sqrt(s->fluid.temperature); /* PL Eq. 4, m_f = 1 */
    return rule && !strcmp(str(fl, "rule"), rule->name) && near(num(fl, "alpha_deg"), s->srd.alpha_deg) &&
           json_is_boolean(json_object_get(fl, "grid_shift")) &&
           json_is_true(json_object_get(fl, "grid_shift")) == (s->srd.grid_shift != 0) &&
           near(num(fl, "particles_per_cell"), s->fluid.density) && near(num(fl, "mean_free_path"), lambda) &&
           !strcmp(str(fl, "boundary"), pl_coupling_boundary_names[s->coupling.boundary]);
}

/* The law's fit (tools/rh_resolution.py R4): form, (b, c), covariance. */
static void read_fit(json_t *law, pl_advise_match_t *m)
{
    const char *form = str(law, "form");
    const int np = !strcmp(form, "c a0/R") ? 1 : !strcmp(form, "b + c a0/R") ? 2 : 0;
    json_t *cov = json_object_get(law, "covariance");
    m->law_b = np == 2 ? num(law, "b") : 0.0;
    m->law_c = num(law, "c");
    m->law_chi2 = num(law, "chi2");
    m->law_dof = (int)json_integer_value(json_object_get(law, "dof"));
    int ok = np > 0 && json_array_size(cov) == (size_t)np && isfinite(m->law_b) && isfinite(m->law_c);
    for (int i = 0; ok && i < np; ++i) {
        json_t *row = json_array_get(cov, (size_t)i);
        ok = json_array_size(row) == (size_t)np;
        for (int j = 0; ok && j < np; ++j) {
            json_t *v = json_array_get(row, (size_t)j);
            m->law_cov[i][j] = json_is_number(v) ? json_number_value(v) : NAN;
            ok = isfinite(m->law_cov[i][j]);
        }
    }
    m->law_nparams = ok ? np : 0;
}

static void read_law(json_t *doc, const char *name, pl_advise_match_t *m)
{
    json_t *fl = json_object_get(doc, "fluid"), *pts = json_object_get(doc, "points");
    snprintf(m->study, sizeof m->study, "%.*s", (int)(strlen(name) - strlen(LAW_PREFIX) - strlen(LAW_SUFFIX)),
             name + strlen(LAW_PREFIX));
    m->found = 1;
    m->rho_ratio = num(fl, "mass_density") / num(fl, "particles_per_cell");
    size_t i;
    json_t *p;
    json_array_foreach(pts, i, p)
    {
        if (m->npoints >= PL_MATCH_MAX_POINTS) break;
        m->R[m->npoints] = num(p, "R_over_a0");
        m->rh_se[m->npoints] = num(p, "rh_over_R_se");
        m->rh[m->npoints++] = num(p, "rh_over_R");
    }
    m->mass_density = num(fl, "mass_density");
    read_fit(json_object_get(doc, "law"), m);
    m->R_match = num(doc, "matched_R_over_a0");
    m->R_match_se = num(doc, "matched_R_over_a0_se");
    m->have_match = isfinite(m->R_match) && m->R_match > 0;
    snprintf(m->reason, sizeof m->reason, "%s", str(doc, "reason"));
    json_t *chk = json_array_get(json_object_get(json_object_get(doc, "check"), "points"), 0);
    if (chk) {
        m->checked = 1;
        m->check_R = num(chk, "R_over_a0");
        m->check_rh = num(chk, "rh_over_R");
        m->check_rh_se = num(chk, "rh_over_R_se");
        snprintf(m->check_verdict, sizeof m->check_verdict, "%s%s", str(chk, "verdict"),
                 json_is_false(json_object_get(chk, "settled")) ? " (not settled)" : "");
    }
}

void pl_advise_match(const pl_scene_t *s, const char *dir, pl_advise_match_t *m)
{
    memset(m, 0, sizeof *m);
    DIR *d = s->coupling.method == PL_COUPLE_HECHT1 ? opendir(dir) : NULL;
    struct dirent *e;
    while (d && !m->found && (e = readdir(d))) {
        const size_t n = strlen(e->d_name);
        const size_t lp = strlen(LAW_PREFIX), ls = strlen(LAW_SUFFIX);
        if (n <= lp + ls || strncmp(e->d_name, LAW_PREFIX, lp) || strcmp(e->d_name + n - ls, LAW_SUFFIX)) continue;
        char path[1400];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        json_t *doc = json_load_file(path, 0, NULL);
        if (doc && same_fluid(s, json_object_get(doc, "fluid"))) {
            read_law(doc, e->d_name, m);
            snprintf(m->path, sizeof m->path, "%s", path);
        }
        json_decref(doc);
    }
    if (d) closedir(d);
}
