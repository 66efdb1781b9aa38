/* The mapping report: units, derived SRD/MD parameters, time-scale tables
 * (Hecht Tables II-IV; PL Table III) for reality and model in seconds and in
 * steps, dimensionless numbers (PL Table II) side by side, and the audit
 * warnings - as readable text and as one JSON object.  NaN (undefined, e.g.
 * no gravity) prints as "-" / null. */
#include <math.h>
#include <stdio.h>

#include "peloid/mapping.h"

static const char *coupling_name(int c) { return c == PL_COUPLING_I ? "I" : "II"; }
static const char *match_name(int m) { return m == PL_MATCH_DIFFUSION ? "diffusion" : "kinematic"; }
static const char *visc_name(int v) { return v == PL_VISC_HECHT28 ? "Hecht Eq. 28" : "PL Eqs. 9-12"; }

static void num(FILE *f, double v)
{
    if (isfinite(v)) fprintf(f, " %12.4g", v);
    else fprintf(f, " %12s", "-");
}

static void jnum(FILE *f, const char *key, double v, int comma)
{
    if (isfinite(v)) fprintf(f, "\"%s\": %.10g%s", key, v, comma ? ", " : "");
    else fprintf(f, "\"%s\": null%s", key, comma ? ", " : "");
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
            coupling_name(cg->coupling), match_name(cg->match), visc_name(cg->viscosity),
            cg->srd_dt > 0 ? ", SRD step given" : "");
    fprintf(f, "  units: a0 = %.4g m, t0 = %.4g s, m_f = %.4g kg, kT_model = %.4g J\n", m->a0, m->t0, m->m_f,
            m->kT_model);
    fprintf(f, "  energy scale kT_real/kT_model = %.4g (Lambda = rho_m/kT: real %.4g, model %.4g s^2/m^5)\n",
            m->energy_scale, m->lambda_real, m->lambda_model);
    fprintf(f, "  SRD: gamma = %g, lambda = %g a0, dt = %.4g s = %g t0, nu = %.4g a0^2/t0 (nu dt/a0^2 = %.4f)"
               " = %.4g m^2/s (real %.4g)\n",
            cg->gamma, cg->lambda, m->dt, cg->lambda, m->nu_sim, m->nu_coeff, m->model.nu, m->real.nu);
    fprintf(f, "  colloid: R = %.4g a0, mass = %.4g m_f, gravity %.4g m/s^2 = %.4g a0/t0^2 (Hecht Eq. 31), "
               "A_H = %.4g J in the model\n",
            m->sigma, m->mass_sim, m->model.g, m->g_sim, m->model.hamaker);
    if (c)
        fprintf(f, "           A_H = %.4g kT, Coulomb prefactor (Hecht Eq. 1) = %.4g kT/a0, kappa = %.4g /a0, "
                   "l = %.4g a0, colloids = %lld\n",
                c->hamaker, c->coulomb, c->kappa, c->primary_minimum, c->n_colloids);
    fprintf(f, "  MD: dt_MD = %.4g s = %.4g t0, %lld MD steps per SRD step\n", m->md_dt, m->md_dt / m->t0,
            m->md_substeps);
    row_t rows[8];
    const char *title[2] = {"time scales (Hecht Tables II-IV)", "time scales (PL Table III)"};
    for (int k = 0; k < 2; ++k) {
        int n = k == 0 ? hecht_rows(m, rows) : pl_rows(m, rows);
        fprintf(f, "  %-34s %12s %12s %12s %12s\n", title[k], "real [s]", "model [s]", "SRD steps", "MD steps");
        for (int i = 0; i < n; ++i) {
            fprintf(f, "    %-8s %-23s", rows[i].name, rows[i].src);
            num(f, rows[i].real);
            num(f, rows[i].model);
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

static void jstr(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; ++s) {
        if (*s == '"' || *s == '\\') fputc('\\', f);
        fputc(*s, f);
    }
    fputc('"', f);
}

static void jrows(FILE *f, const char *key, const row_t *r, int n, double dt, double md_dt)
{
    fprintf(f, "  \"%s\": {", key);
    for (int i = 0; i < n; ++i) {
        fprintf(f, "%s\"%s\": {", i ? ", " : "", r[i].name);
        jnum(f, "real_s", r[i].real, 1);
        jnum(f, "model_s", r[i].model, dt > 0);
        if (dt > 0) {
            jnum(f, "srd_steps", r[i].model / dt, 1);
            jnum(f, "md_steps", r[i].model / md_dt, 0);
        }
        fprintf(f, "}");
    }
    fprintf(f, "},\n");
}

void pl_mapping_print_json(const pl_mapping_t *m, const pl_mapping_colloid_t *c, FILE *f)
{
    const pl_mapping_cg_t *cg = &m->cg;
    fprintf(f, "{\n  \"coupling\": \"%s\", \"time_match\": \"%s\", \"viscosity_formula\": \"%s\",\n",
            coupling_name(cg->coupling), match_name(cg->match), visc_name(cg->viscosity));
    fprintf(f, "  \"units\": {");
    jnum(f, "a0_m", m->a0, 1);
    jnum(f, "t0_s", m->t0, 1);
    jnum(f, "m_f_kg", m->m_f, 1);
    jnum(f, "kT_model_J", m->kT_model, 1);
    jnum(f, "energy_scale", m->energy_scale, 0);
    fprintf(f, "},\n  \"srd\": {");
    jnum(f, "gamma", cg->gamma, 1);
    jnum(f, "lambda", cg->lambda, 1);
    jnum(f, "dt_s", m->dt, 1);
    jnum(f, "dt_t0", cg->lambda, 1);
    jnum(f, "nu_nu0", m->nu_sim, 1);
    jnum(f, "nu_dt_over_a2", m->nu_coeff, 1);
    jnum(f, "nu_model_m2_s", m->model.nu, 1);
    jnum(f, "D_fluid_D0", m->d_fluid_sim, 0);
    fprintf(f, "},\n  \"colloid\": {");
    jnum(f, "radius_a0", m->sigma, 1);
    jnum(f, "mass_m_f", m->mass_sim, 1);
    jnum(f, "gravity_model_m_s2", m->model.g, 1);
    jnum(f, "gravity_a0_t0_2", m->g_sim, 1);
    jnum(f, "hamaker_model_J", m->model.hamaker, 1);
    jnum(f, "D_col_a0_2_t0", m->d_col_sim, 1);
    if (c) {
        jnum(f, "hamaker_kT", c->hamaker, 1);
        jnum(f, "coulomb_kT_a0", c->coulomb, 1);
        jnum(f, "kappa_a0", c->kappa, 1);
        jnum(f, "primary_minimum_a0", c->primary_minimum, 1);
        fprintf(f, "\"n_colloids\": %lld, ", c->n_colloids);
    }
    jnum(f, "md_dt_s", m->md_dt, 1);
    jnum(f, "md_dt_t0", m->md_dt / m->t0, 1);
    fprintf(f, "\"md_substeps\": %lld},\n", m->md_substeps);
    row_t rows[8];
    jrows(f, "hecht_times", rows, hecht_rows(m, rows), m->dt, m->md_dt);
    jrows(f, "pl_times", rows, pl_rows(m, rows), m->dt, m->md_dt);
    int n = number_rows(m, rows);
    fprintf(f, "  \"numbers\": {");
    for (int i = 0; i < n; ++i) {
        fprintf(f, "%s\"%s\": {", i ? ", " : "", rows[i].name);
        jnum(f, "real", rows[i].real, 1);
        jnum(f, "model", rows[i].model, 1);
        fprintf(f, "\"recommended\": ");
        jstr(f, rows[i].src);
        fprintf(f, "}");
    }
    fprintf(f, "},\n  \"warnings\": [");
    for (int i = 0; i < m->nwarn; ++i) {
        fprintf(f, "%s{\"name\": \"%s\", \"severity\": \"%s\", ", i ? ", " : "", m->warn[i].name,
                m->warn[i].severity == PL_SEV_WARNING ? "warning" : "note");
        jnum(f, "value", m->warn[i].value, 1);
        fprintf(f, "\"text\": ");
        jstr(f, m->warn[i].text);
        fprintf(f, "}");
    }
    fprintf(f, "]\n}\n");
}
