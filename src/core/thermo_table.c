/* thermo.tsv's columns (include/peloid/thermo.h), core's registry: step and
 * time, then each module's columns (its thermo_columns, peloid/module.h), the
 * SI twins of a physical scene's model columns, then the wall-clock rate; a
 * row's text.  The state a row shows is sampled, and the file kept, by the
 * run (src/app/thermo_log.c). */
#include <stdio.h>
#include <string.h>

#include "observables_si.h"
#include "peloid/module.h"
#include "peloid/thermo.h"

#define NCOL(a) ((int)(sizeof(a) / sizeof(a[0])))

static long long v_step(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->sim->step;
}
static double v_time(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return (double)s->sim->step * s->sim->scene.srd.dt;
}
static const pl_thermo_column_t step_time[] = {
    {.name = "step", .unit = "1", .format = PL_THERMO_INT, .ivalue = v_step},
    {.name = "time", .unit = "t0", .value = v_time},
};

static double v_rate(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->rate;
}
static const pl_thermo_column_t rate_cols[] = { /* wall clock: last, apart from the state */
    {.name = "mupdates_per_s", .unit = "1e6/s", .format = PL_THERMO_RATE, .value = v_rate},
};

void pl_thermo_add(pl_thermo_table_t *t, const pl_thermo_column_t *c, int n)
{
    for (int k = 0; k < n; ++k, ++t->wanted)
        if (t->n < PL_THERMO_MAX_COLUMNS) t->col[t->n++] = c[k];
}

/* The model units whose columns get an SI twin: lengths, areas, velocities,
 * diffusivities and stresses.  Not t0 (time_s is there), not kT (an energy
 * in kT is the real one in units of the scene's k_B T). */
static const char *const twin_units[] = {"a0", "a0^2", "a0/t0", "a0^2/t0", "kT/a0^3"};

/* "m^2" -> "m2", "m/s" -> "m_per_s": a column-name suffix */
static void unit_suffix(const char *si, char *out, size_t cap)
{
    size_t o = 0;
    for (const char *p = si; *p && o + 5 < cap; ++p) {
        if (*p == '^') continue;
        if (*p == '/') o += (size_t)snprintf(out + o, cap - o, "_per_");
        else if (*p == ' ') out[o++] = '_';
        else out[o++] = *p;
    }
    out[o] = 0;
}

static void add_si_twins(const pl_mapping_t *m, pl_thermo_table_t *t)
{
    const int n_model = t->n;
    for (int k = 0; k < n_model; ++k) {
        const pl_thermo_column_t *c = &t->col[k];
        int twin = 0;
        for (size_t u = 0; u < sizeof twin_units / sizeof twin_units[0]; ++u) twin |= !strcmp(c->unit, twin_units[u]);
        double to_si = 0.0;
        const char *si = twin ? pl_obs_si_unit(c->unit, m, &to_si) : NULL;
        if (!si || t->n >= PL_THERMO_MAX_COLUMNS) {
            t->wanted += si != NULL;
            continue;
        }
        char suffix[24];
        unit_suffix(si, suffix, sizeof suffix);
        char *name = t->si_name[t->n];
        snprintf(name, PL_THERMO_NAME, "%s_%s", c->name, suffix);
        pl_thermo_column_t s = *c;
        s.name = name;
        s.unit = si;
        s.to_si = to_si;
        pl_thermo_add(t, &s, 1);
    }
}

int pl_thermo_table_build(const pl_sim_t *sim, pl_thermo_table_t *t, pl_err_t *err)
{
    t->n = t->wanted = 0;
    pl_thermo_add(t, step_time, NCOL(step_time));
    for (int m = 0; pl_modules[m]; ++m)
        if (pl_modules[m]->thermo_columns) pl_modules[m]->thermo_columns(sim, t);
    if (sim->scene.mapping.enabled) add_si_twins(&sim->scene.mapping.map, t);
    pl_thermo_add(t, rate_cols, NCOL(rate_cols));
    if (t->wanted > t->n)
        return pl_err_set(err, PL_ERR_INTERNAL, "thermo.tsv: this scene asks for %d columns, more than the %d "
                          "this build holds (PL_THERMO_MAX_COLUMNS)", t->wanted, PL_THERMO_MAX_COLUMNS);
    return 0;
}

void pl_thermo_header(const pl_thermo_table_t *t, FILE *f)
{
    for (int k = 0; k < t->n; ++k) fprintf(f, "%s%c", t->col[k].name, k + 1 < t->n ? '\t' : '\n');
}

int pl_thermo_row(const pl_thermo_table_t *t, const pl_thermo_sample_t *s, FILE *f)
{
    int r = 0;
    for (int k = 0; k < t->n && r >= 0; ++k) {
        const pl_thermo_column_t *c = &t->col[k];
        const char sep = k + 1 < t->n ? '\t' : '\n';
        if (c->format == PL_THERMO_INT) r = fprintf(f, "%lld%c", c->ivalue(s, c->arg), sep);
        else if (c->format == PL_THERMO_RATE) r = fprintf(f, "%.4g%c", c->value(s, c->arg), sep);
        else r = fprintf(f, "%.10g%c", c->value(s, c->arg) * (c->to_si != 0.0 ? c->to_si : 1.0), sep);
    }
    return r;
}
