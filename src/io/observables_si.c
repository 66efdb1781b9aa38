/* SI twins of the observers' outputs for a physical scene (observables_si.h). */
#include "observables_si.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/h5.h"

/* Every model unit the observers write, as powers of a0, t0 and m_f (the
 * model energy kT is m_f a0^2 / t0^2), with its SI name. */
static const struct {
    const char *model, *si;
    int pa, pt, pm;
} units[] = {
    {"a0", "m", 1, 0, 0},          {"1/a0", "1/m", -1, 0, 0},          {"a0^2", "m^2", 2, 0, 0},
    {"1/a0^3", "1/m^3", -3, 0, 0}, {"t0", "s", 0, 1, 0},               {"1/t0", "1/s", 0, -1, 0},
    {"a0/t0", "m/s", 1, -1, 0},    {"a0^2/t0", "m^2/s", 2, -1, 0},     {"a0^2/t0^2", "m^2/s^2", 2, -2, 0},
    {"kT/a0^3", "Pa", -1, -2, 1},  {"m_f/(a0 t0)", "Pa s", -1, -1, 1}, {"m_f/t0", "kg/s", 0, -1, 1},
    {"(kT/a0)^2", "N^2", 2, -4, 2}, {"kT", "J", 2, -2, 1},             {"m_f", "kg", 0, 0, 1},
};
/* Ratios that are already dimensionless. */
static const char *const dimensionless[] = {"1", "R", "1/R"};

/* The power of t0 in model unit `model` (0 when not in the table). */
static int time_power(const char *model)
{
    for (size_t k = 0; k < sizeof units / sizeof *units; ++k)
        if (!strcmp(model, units[k].model)) return units[k].pt;
    return 0;
}

const char *pl_obs_si_unit(const char *model, const pl_mapping_t *m, double *to_si)
{
    for (size_t k = 0; k < sizeof dimensionless / sizeof *dimensionless; ++k)
        if (!strcmp(model, dimensionless[k])) {
            *to_si = 1.0;
            return "1";
        }
    for (size_t k = 0; k < sizeof units / sizeof *units; ++k)
        if (!strcmp(model, units[k].model)) {
            *to_si = pow(m->a0, units[k].pa) * pow(m->t0, units[k].pt) * pow(m->m_f, units[k].pm);
            return units[k].si;
        }
    return NULL;
}

/* ---- observables.h5 ---------------------------------------------------- */

typedef struct {
    char **name;
    size_t n, cap;
    int bad;
} names_t;

static herr_t collect(hid_t g, const char *name, const H5L_info_t *info, void *op)
{
    names_t *l = op;
    if (info->type != H5L_TYPE_HARD) return 0;
    hid_t obj = H5Oopen(g, name, H5P_DEFAULT);
    if (obj < 0) return -1;
    int ds = H5Iget_type(obj) == H5I_DATASET;
    if (H5Oclose(obj) < 0) return -1;
    if (!ds) return 0;
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 64;
        char **p = realloc(l->name, cap * sizeof *p);
        if (!p) return -1;
        l->name = p;
        l->cap = cap;
    }
    if (!(l->name[l->n] = strdup(name))) return -1;
    l->n++;
    return 0;
}

/* The `unit` attribute of ds (fixed or variable length) into buf; 1 when
 * ds has one, 0 when not, -1 on error. */
static int read_unit(hid_t ds, char *buf, size_t n)
{
    htri_t has = H5Aexists(ds, "unit");
    if (has <= 0) return has < 0 ? -1 : 0;
    hid_t a = H5Aopen(ds, "unit", H5P_DEFAULT);
    if (a < 0) return -1;
    hid_t ft = H5Aget_type(a);
    int rc = ft < 0 ? -1 : 1;
    if (rc > 0 && H5Tis_variable_str(ft) > 0) {
        hid_t mt = H5Tcopy(H5T_C_S1);
        char *s = NULL;
        if (mt < 0 || H5Tset_size(mt, H5T_VARIABLE) < 0 || H5Aread(a, mt, &s) < 0 || !s) rc = -1;
        if (s) {
            snprintf(buf, n, "%s", s);
            H5free_memory(s);
        }
        if (mt >= 0) H5Tclose(mt);
    } else if (rc > 0) {
        size_t len = H5Tget_size(ft);
        hid_t mt = H5Tcopy(H5T_C_S1);
        if (len + 1 > n || mt < 0 || H5Tset_size(mt, len + 1) < 0 || H5Aread(a, mt, buf) < 0) rc = -1;
        if (mt >= 0) H5Tclose(mt);
    }
    if (ft >= 0) H5Tclose(ft);
    if (H5Aclose(a) < 0) rc = -1;
    return rc;
}

static int has_suffix(const char *s, const char *suf)
{
    size_t n = strlen(s), k = strlen(suf);
    return n >= k && !strcmp(s + n - k, suf);
}

/* X_si beside dataset `name` of obs in model unit `unit`. */
static int write_twin(hid_t obs, const char *name, const char *unit, const pl_mapping_t *m)
{
    double f;
    const char *si = pl_obs_si_unit(unit, m, &f);
    if (!si || !strcmp(si, "1")) return 0; /* dimensionless or already SI */
    char twin[1024];
    if ((size_t)snprintf(twin, sizeof twin, "%s_si", name) >= sizeof twin) return -1;
    htri_t ex = H5Lexists(obs, twin, H5P_DEFAULT);
    if (ex != 0) return ex < 0 ? -1 : 0;
    hid_t ds = H5Dopen2(obs, name, H5P_DEFAULT);
    if (ds < 0) return -1;
    hid_t sp = H5Dget_space(ds);
    int rank = sp < 0 ? -1 : H5Sget_simple_extent_ndims(sp);
    hsize_t dims[H5S_MAX_RANK];
    hssize_t np = sp < 0 ? -1 : H5Sget_simple_extent_npoints(sp);
    int bad = rank < 0 || np < 0 || H5Sget_simple_extent_dims(sp, dims, NULL) < 0;
    double *v = bad ? NULL : malloc((np > 0 ? (size_t)np : 1) * sizeof *v);
    bad |= !v || (np > 0 && H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0);
    for (hssize_t k = 0; !bad && k < np; ++k) v[k] *= f;
    if (!bad) bad = pl_h5_write(obs, twin, H5T_NATIVE_DOUBLE, rank, dims, v) != 0;
    free(v);
    if (sp >= 0 && H5Sclose(sp) < 0) bad = 1;
    if (H5Dclose(ds) < 0) bad = 1;
    if (bad) return -1;
    hid_t t = H5Dopen2(obs, twin, H5P_DEFAULT);
    if (t < 0) return -1;
    bad = pl_h5_attr_vlstr(t, "unit", si) || pl_h5_attr_doubles(t, "to_si", &f, 1) ||
          pl_h5_attr_vlstr(t, "model_unit", unit);
    if (H5Dclose(t) < 0) bad = 1;
    return bad ? -1 : 0;
}

/* /parameters: the mapping's units in SI, read to convert any model value. */
static int parameters(hid_t file, const pl_mapping_t *m, double t0_rel)
{
    htri_t ex = H5Lexists(file, "parameters", H5P_DEFAULT);
    if (ex != 0) return ex < 0 ? -1 : 0;
    hid_t g = pl_h5_group(file, "parameters");
    if (g < 0) return -1;
    int bad = pl_h5_attr_doubles(g, "a0_m", &m->a0, 1) || pl_h5_attr_doubles(g, "t0_s", &m->t0, 1) ||
              (isfinite(t0_rel) && pl_h5_attr_doubles(g, "t0_relative_error", &t0_rel, 1)) ||
              pl_h5_attr_doubles(g, "m_f_kg", &m->m_f, 1) || pl_h5_attr_doubles(g, "kT_J", &m->kT_model, 1) ||
              pl_h5_attr_vlstr(g, "meaning", "model units in SI (kT_J = m_f a0^2/t0^2, the model energy); "
                                             "a dataset X in a model unit has X_si = X * to_si");
    if (H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
}

int pl_obs_si_h5(hid_t file, const pl_mapping_t *m, double t0_rel)
{
    hid_t obs = H5Gopen2(file, "observables", H5P_DEFAULT);
    if (obs < 0) return -1;
    names_t l = {NULL, 0, 0, 0};
    int bad = H5Lvisit(obs, H5_INDEX_NAME, H5_ITER_INC, collect, &l) < 0;
    for (size_t k = 0; k < l.n; ++k) {
        if (!bad && !has_suffix(l.name[k], "_si")) {
            char unit[256];
            hid_t ds = H5Dopen2(obs, l.name[k], H5P_DEFAULT);
            int has = ds < 0 ? -1 : read_unit(ds, unit, sizeof unit);
            if (ds >= 0 && H5Dclose(ds) < 0) has = -1;
            bad = has < 0 || (has > 0 && write_twin(obs, l.name[k], unit, m) != 0);
        }
        free(l.name[k]);
    }
    free(l.name);
    if (H5Gclose(obs) < 0) bad = 1;
    return bad || parameters(file, m, t0_rel) ? -1 : 0;
}

/* ---- summary.json ------------------------------------------------------ */

/* The keys of an entry that are in the entry's unit. */
static const char *const in_unit[] = {"value", "stderr", "theory", "ideal_gas", "nominal", "apparent_value"};

/* key_si = key * f for each key of in_unit present as a number in e; with
 * a value and its stderr, the mapping's share of the SI value's error
 * (stderr_mapping_si = |p| x t0's relative error x |value_si|, p the power
 * of t0 in the unit: t0 rests on the calibrated colloid D) and both combined
 * (stderr_total_si, in quadrature: independent). */
static void convert(pl_json_t *b, json_t *e, double f, int pt, double t0_rel)
{
    for (size_t k = 0; k < sizeof in_unit / sizeof *in_unit; ++k) {
        json_t *v = json_object_get(e, in_unit[k]);
        if (!json_is_number(v)) continue;
        char key[64];
        snprintf(key, sizeof key, "%s_si", in_unit[k]);
        pl_json_real(b, e, key, json_number_value(v) * f);
    }
    json_t *v = json_object_get(e, "value"), *se = json_object_get(e, "stderr");
    if (pt == 0 || !(t0_rel > 0.0) || !isfinite(t0_rel) || !json_is_number(v) || !json_is_number(se)) return;
    const double map = fabs((double)pt) * t0_rel * fabs(json_number_value(v) * f), run = json_number_value(se) * f;
    pl_json_real(b, e, "stderr_mapping_si", map);
    pl_json_real(b, e, "stderr_total_si", sqrt(run * run + map * map));
}

/* A number or array of numbers under key `stem`_t0 (`stem`_a0) gets its
 * twin `stem`_s (`stem`_m), e.g. fit_window_t0, integrated_to_t0. */
static void suffixed(pl_json_t *b, json_t *e, const pl_mapping_t *m)
{
    static const struct {
        const char *model, *si;
    } sfx[] = {{"_t0", "_s"}, {"_a0", "_m"}};
    const char *key;
    json_t *v;
    json_t *add = json_object(); /* collected first: e is not changed while iterated */
    if (!add) {
        pl_json_set(b, e, "_si", NULL); /* reports out of memory */
        return;
    }
    json_object_foreach(e, key, v) for (size_t k = 0; k < 2; ++k) {
        size_t n = strlen(key);
        if (n < 4 || strcmp(key + n - 3, sfx[k].model)) continue;
        const double f = k ? m->a0 : m->t0;
        char out[128];
        snprintf(out, sizeof out, "%.*s%s", (int)(n - 3), key, sfx[k].si);
        if (json_object_get(e, out)) continue;
        if (json_is_number(v)) {
            pl_json_real(b, add, out, json_number_value(v) * f);
        } else if (json_is_array(v)) {
            json_t *a = json_array();
            size_t i;
            json_t *x;
            json_array_foreach(v, i, x) json_array_append_new(a, json_real(json_number_value(x) * f));
            pl_json_set(b, add, out, a);
        }
    }
    if (json_object_update(e, add)) pl_json_set(b, e, "_si", NULL);
    json_decref(add);
}

void pl_obs_si_json(pl_json_t *b, json_t *all, const pl_mapping_t *m, double t0_rel)
{
    if (json_is_array(all)) {
        size_t i;
        json_t *v;
        json_array_foreach(all, i, v) pl_obs_si_json(b, v, m, t0_rel);
        return;
    }
    if (!json_is_object(all)) return;
    const char *unit = json_string_value(json_object_get(all, "unit"));
    double f;
    const char *si = unit ? pl_obs_si_unit(unit, m, &f) : NULL;
    if (si && !json_object_get(all, "unit_si")) {
        pl_json_str(b, all, "unit_si", si);
        const int pt = time_power(unit);
        convert(b, all, f, pt, t0_rel);
        size_t i;
        json_t *p;
        if (strcmp(si, "1")) /* a dimensionless series is its own SI one */
            json_array_foreach(json_object_get(all, "se_vs_time"), i, p) convert(b, p, f, 0, 0.0);
    }
    suffixed(b, all, m);
    const char *key;
    json_t *v;
    json_object_foreach(all, key, v) if (strcmp(key, "se_vs_time")) pl_obs_si_json(b, v, m, t0_rel);
}
