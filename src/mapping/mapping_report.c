/* The mapping report: units, derived SRD/MD parameters, time-scale tables
 * (Hecht Tables II-IV; PL Table III) for reality and model in seconds and in
 * steps, dimensionless numbers (PL Table II) side by side, and the audit
 * warnings - as readable text and as one JSON object (jansson).  NaN
 * (undefined, e.g. no gravity) prints as "-" / null; an infinite value is an
 * error in JSON. */
#include <math.h>
#include <stdio.h>

#include "json_build.h"
#include "peloid/collision_rule.h"
#include "peloid/mapping.h"

static const char *match_name(int m) { return m == PL_MATCH_DIFFUSION ? "diffusion" : "kinematic"; }
static const char *visc_name(int rule) { return pl_collision_rule(rule)->theory_ref; }

static void num(FILE *f, double v)
{
    if (isfinite(v)) fprintf(f, " %12.4g", v);
    else fprintf(f, " %12s", "-");
}

typedef struct {
    const char *name, *src;
    double real, model;
} row_t;

static int hecht_rows(const pl_mapping_t *m, row_t *r)
{
    const pl_mapping_hecht_times_t *a = &m->hecht_real, *b = &m->hecht_model;
    row_t t[] = {{"tau_S", "Hecht Eq. 17", a->tau_S, b->tau_S}, {"tau_D", "Hecht Eq. 20", a->tau_D, b->tau_D},
                 {"tau_G", "Hecht Sec. VI", a->tau_G, b->tau_G}, {"tau_V", "Hecht Eq. 26", a->tau_V, b->tau_V},
                 {"tau_F", "Hecht Eq. 24", a->tau_F, b->tau_F}, {"tau_P", "Hecht Eq. 23", a->tau_P, b->tau_P}};
    for (int i = 0; i < 6; ++i) r[i] = t[i];
    return 6;
}

static int pl_rows(const pl_mapping_t *m, row_t *r)
{
    const pl_mapping_pl_times_t *a = &m->pl_real, *b = &m->pl_model;
    row_t t[] = {{"t_cs", "PL Eq. 46", a->t_cs, b->t_cs},   {"tau_nu", "PL Eq. 31", a->tau_nu, b->tau_nu},
                 {"tau_B", "PL Eq. 47", a->tau_B, b->tau_B}, {"tau_E", "PL Eq. 53", a->tau_E, b->tau_E},
                 {"tau_D", "PL Eq. 36", a->tau_D, b->tau_D}, {"t_S", "PL Eq. 30", a->t_S, b->t_S}};
    for (int i = 0; i < 6; ++i) r[i] = t[i];
    return 6;
}

static int number_rows(const pl_mapping_t *m, row_t *r)
{
    const pl_mapping_numbers_t *a = &m->num_real, *b = &m->num_model;
    row_t t[] = {{"Sc", ">= 3 (Sc >> 1, PL Eq. 26)", a->Sc, b->Sc}, {"Ma", "<= 0.1 (PL Eq. 28)", a->Ma, b->Ma},
                 {"Re", "<= 0.2 (PL Eq. 29)", a->Re, b->Re},         {"Kn", "<= 0.05 (PL Eq. 34)", a->Kn, b->Kn},
                 {"Pe", "= real (Hecht Sec. VII)", a->Pe, b->Pe}};
    for (int i = 0; i < 5; ++i) r[i] = t[i];
    return 5;
}

void pl_mapping_print_text(const pl_mapping_t *m, const pl_mapping_colloid_t *c, FILE *f)
{
    const pl_mapping_cg_t *cg = &m->cg;
    fprintf(f, "Unit mapping (Hecht Sec. VII, PL Sec. VII): coupling %s, time matched on %s, viscosity %s%s\n",
            pl_couple_physical_name(cg->coupling), match_name(cg->match), visc_name(cg->viscosity),
            cg->srd_dt > 0 ? ", SRD step given" : "");
    fprintf(f, "  units: a0 = %.4g m, t0 = %.4g s, m_f = %.4g kg, kT_model = %.4g J\n", m->a0, m->t0, m->m_f,
            m->kT_model);
    /* Model values in model units, real ones in SI; where they differ, their ratio (never a model value in SI) */
    fprintf(f, "  energy scale kT_real/kT_model = %.4g (Hecht Sec. VII.B: the model suspension is colder by this, "
               "its Lambda = rho_m/kT larger by it; real Lambda = %.4g s^2/m^5)\n",
            m->energy_scale, m->lambda_real);
    fprintf(f, "  SRD: gamma = %g, lambda = %g a0, dt = %.4g s = %g t0, nu = %.4g a0^2/t0 (nu dt/a0^2 = %.4f); "
               "real nu = %.4g m^2/s, model/real = %.4g\n",
            cg->gamma, cg->lambda, m->dt, cg->lambda, m->nu_sim, m->nu_coeff, m->real.nu, m->model.nu / m->real.nu);
    fprintf(f, "  colloid: R = %.4g a0, mass = %.4g m_f, gravity %.4g m/s^2 (real) = %.4g a0/t0^2 in the model "
               "(Hecht Eq. 31)\n",
            m->sigma, m->mass_sim, m->real.g, m->g_sim);
    if (c)
        fprintf(f, "           A_H = %.4g kT, Coulomb prefactor (Hecht Eq. 1) = %.4g kT/a0, kappa = %.4g /a0, "
                   "l = %.4g a0, colloids = %lld\n",
                c->hamaker, c->coulomb, c->kappa, c->primary_minimum, c->n_colloids);
    if (c) pl_mapping_core_print(c, f);
    pl_mapping_diffusion_print(m, f);
    fprintf(f, "  MD: dt_MD = %.4g s = %.4g t0, %lld MD steps per SRD step\n", m->md_dt, m->md_dt / m->t0,
            m->md_substeps);
    if (c && c->nprov > 0) {
        fprintf(f, "  model keys derived from physical{} + coarse_graining{}:\n");
        for (int i = 0; i < c->nprov; ++i) fprintf(f, "    %s\n", c->prov[i]);
    }
    row_t rows[8];
    const char *title[2] = {"time scales (Hecht Tables II-IV)", "time scales (PL Table III)"};
    for (int k = 0; k < 2; ++k) {
        int n = k == 0 ? hecht_rows(m, rows) : pl_rows(m, rows);
        fprintf(f, "  %-34s %12s %12s %12s %12s %12s\n", title[k], "real [s]", "model [t0]", "model/real",
                "SRD steps", "MD steps");
        for (int i = 0; i < n; ++i) {
            fprintf(f, "    %-8s %-23s", rows[i].name, rows[i].src);
            num(f, rows[i].real);
            num(f, rows[i].model / m->t0);
            num(f, rows[i].model / rows[i].real);
            num(f, rows[i].model / m->dt);
            num(f, rows[i].model / m->md_dt);
            fprintf(f, "\n");
        }
    }
    int n = number_rows(m, rows);
    fprintf(f, "  %-34s %12s %12s   %s\n", "dimensionless numbers (PL Table II)", "real", "model", "recommended");
    for (int i = 0; i < n; ++i) {
        fprintf(f, "    %-32s", rows[i].name);
        num(f, rows[i].real);
        num(f, rows[i].model);
        fprintf(f, "   %s\n", rows[i].src);
    }
    for (int i = 0; i < m->nwarn; ++i)
        fprintf(f, "  %s %s: %s\n", m->warn[i].severity == PL_SEV_WARNING ? "warning" : "note", m->warn[i].name,
                m->warn[i].text);
    if (m->nwarn == 0) fprintf(f, "  audit: all numbers in the recommended ranges\n");
}

static void jrows(pl_json_t *b, json_t *doc, const char *key, const row_t *r, int n, double dt, double md_dt)
{
    json_t *o = json_object();
    for (int i = 0; i < n; ++i) {
        json_t *row = json_object();
        pl_json_real_or_null(b, row, "real_s", r[i].real);
        pl_json_real_or_null(b, row, "model_s", r[i].model);
        if (dt > 0) {
            pl_json_real_or_null(b, row, "srd_steps", r[i].model / dt);
            pl_json_real_or_null(b, row, "md_steps", r[i].model / md_dt);
        }
        pl_json_set(b, o, r[i].name, row);
    }
    pl_json_set(b, doc, key, o);
}

int pl_mapping_json(const pl_mapping_t *m, const pl_mapping_colloid_t *c, const char *where, struct json_t **out,
                    pl_err_t *err)
{
    const pl_mapping_cg_t *cg = &m->cg;
    pl_json_t b = {err, where, "mapping", 0};
    json_t *doc = json_object(), *o;
    pl_json_str(&b, doc, "coupling", pl_couple_physical_name(cg->coupling));
    pl_json_str(&b, doc, "time_match", match_name(cg->match));
    pl_json_str(&b, doc, "viscosity_formula", visc_name(cg->viscosity));
    const struct { const char *key; double v; } units[] = {
        {"a0_m", m->a0}, {"t0_s", m->t0}, {"m_f_kg", m->m_f}, {"kT_model_J", m->kT_model},
        {"energy_scale", m->energy_scale}};
    o = json_object();
    for (size_t i = 0; i < sizeof units / sizeof units[0]; ++i) pl_json_real_or_null(&b, o, units[i].key, units[i].v);
    pl_json_set(&b, doc, "units", o);
    const struct { const char *key; double v; } srd[] = {
        {"gamma", cg->gamma}, {"lambda", cg->lambda}, {"dt_s", m->dt}, {"dt_t0", cg->lambda},
        {"nu_nu0", m->nu_sim}, {"nu_dt_over_a2", m->nu_coeff}, {"nu_model_m2_s", m->model.nu},
        {"D_fluid_D0", m->d_fluid_sim}};
    o = json_object();
    for (size_t i = 0; i < sizeof srd / sizeof srd[0]; ++i) pl_json_real_or_null(&b, o, srd[i].key, srd[i].v);
    pl_json_set(&b, doc, "srd", o);
    o = json_object();
    const struct { const char *key; double v; } col[] = {
        {"radius_a0", m->sigma}, {"mass_m_f", m->mass_sim}, {"gravity_model_m_s2", m->model.g},
        {"gravity_a0_t0_2", m->g_sim}, {"hamaker_model_J", m->model.hamaker}, {"D_col_a0_2_t0", m->d_col_sim}};
    for (size_t i = 0; i < sizeof col / sizeof col[0]; ++i) pl_json_real_or_null(&b, o, col[i].key, col[i].v);
    pl_mapping_hydro_json(m, o);
    if (c) {
        pl_json_real_or_null(&b, o, "hamaker_kT", c->hamaker);
        pl_json_real_or_null(&b, o, "coulomb_kT_a0", c->coulomb);
        pl_json_real_or_null(&b, o, "kappa_a0", c->kappa);
        pl_json_real_or_null(&b, o, "primary_minimum_a0", c->primary_minimum);
        pl_json_int(&b, o, "n_colloids", c->n_colloids);
        if (c->nprov > 0) {
            pl_json_real_or_null(&b, o, "volume_fraction_given", c->phi_given);
            pl_json_real_or_null(&b, o, "volume_fraction_realised", c->phi_realised);
            pl_mapping_core_json(c, o);
            json_t *a = json_array();
            for (int i = 0; i < c->nprov; ++i) json_array_append_new(a, json_string(c->prov[i]));
            pl_json_set(&b, o, "derived_keys", a);
        }
    }
    pl_json_real_or_null(&b, o, "md_dt_s", m->md_dt);
    pl_json_real_or_null(&b, o, "md_dt_t0", m->md_dt / m->t0);
    pl_json_int(&b, o, "md_substeps", m->md_substeps);
    pl_json_set(&b, doc, "colloid", o);
    pl_json_set(&b, doc, "colloid_diffusion", pl_mapping_diffusion_json(m));
    row_t rows[8];
    jrows(&b, doc, "hecht_times", rows, hecht_rows(m, rows), m->dt, m->md_dt);
    jrows(&b, doc, "pl_times", rows, pl_rows(m, rows), m->dt, m->md_dt);
    int n = number_rows(m, rows);
    o = json_object();
    for (int i = 0; i < n; ++i) {
        json_t *row = json_object();
        pl_json_real_or_null(&b, row, "real", rows[i].real);
        pl_json_real_or_null(&b, row, "model", rows[i].model);
        pl_json_str(&b, row, "recommended", rows[i].src);
        pl_json_set(&b, o, rows[i].name, row);
    }
    pl_json_set(&b, doc, "numbers", o);
    json_t *w = json_array();
    for (int i = 0; i < m->nwarn; ++i) {
        json_t *row = json_object();
        pl_json_str(&b, row, "name", m->warn[i].name);
        pl_json_str(&b, row, "severity", m->warn[i].severity == PL_SEV_WARNING ? "warning" : "note");
        pl_json_real_or_null(&b, row, "value", m->warn[i].value);
        pl_json_str(&b, row, "text", m->warn[i].text);
        if (!row || json_array_append_new(w, row)) b.failed = b.failed ? 1 : (pl_err_set(err, PL_ERR_NOMEM,
                                                                                      "out of memory"), 1);
    }
    pl_json_set(&b, doc, "warnings", w);
    if (b.failed || !doc) {
        json_decref(doc);
        return b.failed ? err->code : pl_err_set(err, PL_ERR_NOMEM, "out of memory building JSON");
    }
    *out = doc;
    return 0;
}
