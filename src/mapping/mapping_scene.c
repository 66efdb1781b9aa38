/* Scene front end of the mapping: physical{} + coarse_graining{} -> the
 * mapping inputs -> derived simulation parameters written into the scene
 * (srd.dt, fluid.density, fluid.temperature, box.cells) and the colloid
 * parameters in simulation units; the entry point of the report.
 *
 * Hecht Eq. 1 (screened Coulomb prefactor), Debye-Hueckel kappa; the rest
 * is in mapping_hecht.c / mapping_pl.c. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "peloid/real.h" /* PL_PI */
#include "json_build.h"
#include "peloid/scene.h"

#define OFF(m) offsetof(pl_scene_t, m)
#define DLVO_KAPPA_R_MIN 5.0

double pl_mapping_water_permittivity(double T)
{
    double t = T - 273.15;
    if (!(t >= 0.0 && t <= 100.0)) return NAN;
    /* Malmberg & Maryott, J. Res. NBS 56, 1 (1956), Eq. 5 */
    return 87.740 - 0.40008 * t + 9.398e-4 * t * t - 1.410e-6 * t * t * t;
}

/* The physical front end is on when any key of physical{} is in the file. */
/* 1 + the offset of the first key of `sec` given in the file; 0: none. */
static size_t section_given(const pl_scene_t *s, const pl_section_t *sec)
{
    for (size_t i = 0; i < sec->nkeys; ++i)
        if (pl_scene_line_of(s, sec->keys[i].offset) > 0) return sec->keys[i].offset + 1;
    return 0;
}

/* Keys the mapping derives must not be set in the file as well - unless
 * with the derived value itself (an echoed effective scene reloads). */
static int forbid(const pl_scene_t *s, pl_err_t *err, size_t off, const char *key, double derived,
                  double given)
{
    if (pl_scene_line_of(s, off) <= 0 || fabs(given - derived) <= 1e-12 * fabs(derived)) return 0;
    return pl_scene_fail(s, err, off, key,
                         "is derived from physical{} by the unit mapping (value %g); remove it here "
                         "or remove the physical section",
                         derived);
}

static void fill_inputs(const pl_scene_t *s, pl_mapping_system_t *r, pl_mapping_solvent_t *sv,
                        pl_mapping_cg_t *cg)
{
    const pl_scene_physical_t *p = &s->mapping.physical;
    const pl_scene_cg_t *c = &s->mapping.cg;
    *r = (pl_mapping_system_t){0};
    r->radius = p->radius;
    r->rho_p = p->particle_density;
    r->rho_f = p->solvent_density;
    r->nu = p->viscosity;
    r->kT = PL_KB * p->temperature;
    r->g = p->gravity;
    r->buoyancy = 1;
    r->hamaker = p->hamaker;
    r->l_min = p->primary_minimum;
    sv->flow_velocity = p->flow_velocity;
    sv->sound_speed = p->sound_speed;
    sv->mean_free_path = p->mean_free_path;
    sv->self_diffusion = p->self_diffusion;
    *cg = (pl_mapping_cg_t){0};
    cg->coupling = c->coupling;
    cg->d_col_calibrated = s->mapping.calib.d_inf;
    cg->d_col_calibrated_se = s->mapping.calib.d_inf_se;
    cg->match = c->time_match;
    cg->boundary = c->boundary;
    cg->enskog = c->enskog;
    cg->fluid_gravity = c->fluid_gravity;
    cg->cell_over_R = c->cell_size > 0 ? c->cell_size
                      : c->coupling == PL_COUPLE_HECHT2 ? cbrt(4.0 * PL_PI / 3.0)
                                                      : 0.5; /* I: Hecht a = R/2; potential: PL sigma_cf = 2 a0 */
    if (c->coupling == PL_COUPLE_POTENTIAL) {
        /* PL Sec. III.B: the radial forces of PL Eq. 17 transfer no angular
         * momentum (slip); PL Table VI adds the Enskog friction in parallel
         * (PL Eq. 41) unless the file switches it off */
        cg->boundary = PL_BOUNDARY_SLIP;
        cg->enskog = pl_scene_line_of(s, OFF(mapping.cg.enskog)) > 0 ? c->enskog : 1;
    }
    cg->gamma = c->particles_per_cell;
    cg->lambda = c->mean_free_path;
    /* The collision rule of srd{} picks the viscosity formula: its row's theory. */
    cg->viscosity = s->srd.rule;
    cg->alpha = s->srd.rule == PL_RULE_HECHT_AXES ? 0.5 * PL_PI : s->srd.alpha_deg * PL_PI / 180.0;
    cg->srd_dt = c->srd_dt;
    cg->md_dt = c->md_dt;
    cg->md_resolution = c->md_resolution;
}

static int electrostatics(pl_scene_t *s, pl_err_t *err)
{
    pl_scene_mapping_t *mp = &s->mapping;
    pl_scene_physical_t *p = &mp->physical;
    double kT = PL_KB * p->temperature;
    if (pl_scene_line_of(s, OFF(mapping.physical.permittivity)) <= 0) {
        /* not given: water at the scene's temperature, stated in the report */
        p->permittivity = pl_mapping_water_permittivity(p->temperature);
        if (!isfinite(p->permittivity))
            return pl_scene_fail(s, err, OFF(mapping.physical.temperature), "physical.temperature",
                                 "%g K is outside 273.15-373.15 K where the water permittivity fit "
                                 "(Malmberg & Maryott 1956) holds; give physical.permittivity",
                                 p->temperature);
    }
    if (p->kappa > 0 && p->ionic_strength > 0)
        return pl_scene_fail(s, err, OFF(mapping.physical.kappa), "physical.kappa",
                             "given together with physical.ionic_strength; give one of them");
    mp->kappa = p->kappa > 0 ? p->kappa
                : p->ionic_strength > 0 ? pl_mapping_debye_kappa(p->ionic_strength, p->permittivity, kT)
                                        : 0.0;
    if (p->surface_potential != 0 && !(mp->kappa > 0))
        return pl_scene_fail(s, err, OFF(mapping.physical.surface_potential), "physical.surface_potential",
                             "needs physical.kappa or physical.ionic_strength (Hecht Eq. 1 is screened)");
    double kR = mp->kappa * p->radius;
    if (p->surface_potential != 0 && kR < DLVO_KAPPA_R_MIN)
        pl_mapping_warn(&mp->map, PL_SEV_WARNING, "DLVO_RANGE", kR,
                        "kappa R = %.3g < %.0f: Hecht Eq. 1 (screened Coulomb of thin double layers) and "
                        "Eq. 2 assume kappa R >> 1; raise physical.ionic_strength or kappa",
                        kR, DLVO_KAPPA_R_MIN);
    /* Hecht Eq. 1 prefactor pi eps_r eps0 [4kT/(ze) tanh(z e Psi0/(4kT))]^2 in J/m. */
    double ze = (double)p->valence * PL_E_CHARGE;
    double b = 4.0 * kT / ze * tanh(ze * p->surface_potential / (4.0 * kT));
    double pref = PL_PI * p->permittivity * PL_EPS0 * b * b;
    mp->colloid.coulomb = pref * mp->map.a0 / kT;
    mp->colloid.kappa = mp->kappa * mp->map.a0;
    return 0;
}

/* physical.box edge d gives n cells of a0 outside 1..4096 (or none): the
 * key at fault is an implausible physical.radius (a0 follows R), else a
 * coarse_graining.cell_size the file gives outside 0.1..2 (a colloid of
 * more than 20 cells across or a cell wider than a colloid: beyond the
 * couplings' 0.5 to 1.6 of Hecht and PL), else the box. */
static int box_fail(const pl_scene_t *s, pl_err_t *err, int d, double n, double a0)
{
    const pl_scene_physical_t *p = &s->mapping.physical;
    const size_t radius = OFF(mapping.physical.radius), cell = OFF(mapping.cg.cell_size);
    size_t off = OFF(mapping.physical.box);
    char why[160];
    const char *key = pl_mapping_blame(s, &radius, 1, &off, why, sizeof why);
    if (!key && pl_scene_line_of(s, cell) > 0 && !(s->mapping.cg.cell_size >= 0.1 && s->mapping.cg.cell_size <= 2.0)) {
        off = cell;
        key = "coarse_graining.cell_size";
    }
    return pl_scene_fail(s, err, off, key ? key : "physical.box",
                         "%sphysical.box edge %d = %g m gives %g cells of a0 = %g m (a0 = %g x physical.radius = %g "
                         "m); allowed: 1..4096 cells (a0/2 < edge <= 4096.5 a0)",
                         why, d, p->box[d], n, a0, a0 / p->radius, p->radius);
}

/* Hecht Sec. VII (phi kept): the colloid count is phi V / (4/3 pi R^3) of
 * the box actually used (whole cells), so the realised phi differs from the
 * given one only by rounding the count; rounding the box is reported. */
static int apply_box(pl_scene_t *s, pl_err_t *err)
{
    const pl_scene_physical_t *p = &s->mapping.physical;
    double a0 = s->mapping.map.a0;
    int given = p->box[0] > 0 || p->box[1] > 0 || p->box[2] > 0;
    if (given) {
        for (int d = 0; d < 3; ++d) {
            double n = floor(p->box[d] / a0 + 0.5); /* nearest whole number of cells */
            if (forbid(s, err, OFF(box.cells), "box.cells", fmax(1.0, n), s->box.cells[d])) return PL_ERR_INPUT;
            if (!(p->box[d] > 0) || !(n >= 1.0 && n <= 4096)) return box_fail(s, err, d, n, a0);
            s->box.cells[d] = (int)n;
        }
    }
    double V = 1.0;
    for (int d = 0; d < 3; ++d) V *= s->box.cells[d] * a0;
    double vc = 4.0 / 3.0 * PL_PI * pow(p->radius, 3);
    pl_mapping_colloid_t *c = &s->mapping.colloid;
    c->n_colloids = (long long)floor(p->volume_fraction * V / vc + 0.5);
    c->phi_given = p->volume_fraction;
    c->phi_realised = (double)c->n_colloids * vc / V;
    if (p->volume_fraction > 0 && c->n_colloids == 0) { /* at fault: a box narrower than a colloid, else phi */
        const size_t radius = OFF(mapping.physical.radius);
        size_t off = OFF(mapping.physical.volume_fraction);
        char why[160];
        const char *key = pl_mapping_blame(s, &radius, 1, &off, why, sizeof why);
        int narrow = 0;
        for (int d = 0; d < 3; ++d) narrow |= s->box.cells[d] * a0 < 2.0 * p->radius;
        if (!key && narrow) {
            off = given ? OFF(mapping.physical.box) : OFF(box.cells);
            key = given ? "physical.box" : "box.cells";
        }
        return pl_scene_fail(s, err, off, key ? key : "physical.volume_fraction",
                             "%sphysical.volume_fraction = %g gives no colloid of radius %g m in the box (%d x %d x "
                             "%d cells of %.4g m)%s; allowed: a larger box or volume fraction",
                             why, p->volume_fraction, p->radius, s->box.cells[0], s->box.cells[1], s->box.cells[2],
                             a0, narrow ? ", an edge shorter than the colloid diameter" : "");
    }
    if (given && p->volume_fraction > 0) {
        double Vg = p->box[0] * p->box[1] * p->box[2];
        if (fabs(V / Vg - 1.0) > 0.005)
            pl_mapping_warn(&s->mapping.map, PL_SEV_NOTE, "BOX_ROUNDED", V / Vg,
                            "physical.box %.4g x %.4g x %.4g um rounded up to %d x %d x %d cells of a0 = "
                            "%.4g um (volume x %.4f): the count phi V / (4/3 pi R^3) of the given box "
                            "(%.0f) would give phi = %.4g in the box used; the colloid count is taken "
                            "from the box used instead: %lld colloids, phi = %.5g",
                            p->box[0] * 1e6, p->box[1] * 1e6, p->box[2] * 1e6, s->box.cells[0],
                            s->box.cells[1], s->box.cells[2], a0 * 1e6, V / Vg,
                            floor(p->volume_fraction * Vg / vc + 0.5),
                            floor(p->volume_fraction * Vg / vc + 0.5) * vc / V, c->n_colloids,
                            c->phi_realised);
    }
    if (p->volume_fraction > 0 && fabs(c->phi_realised / p->volume_fraction - 1.0) > 0.005)
        pl_mapping_warn(&s->mapping.map, PL_SEV_WARNING, "PHI_ROUNDED", c->phi_realised,
                        "%lld colloids in the box realise phi = %.5g, %.2g%% off physical.volume_fraction "
                        "= %g (too few colloids to round finely); enlarge physical.box",
                        c->n_colloids, c->phi_realised, 100.0 * (c->phi_realised / p->volume_fraction - 1.0),
                        p->volume_fraction);
    return 0;
}

/* A coarse_graining.md_dt longer than the SRD step cannot be used (one MD
 * step per SRD step at most): refused, not replaced.  Checked once the SRD
 * step in seconds is final: given (srd_dt), kinematic matching, calibrated,
 * the theory's D by choice (--calibrate never), or without colloids (no
 * calibration run follows). */
static int check_md_dt(const pl_scene_t *s, pl_err_t *err)
{
    const pl_scene_mapping_t *mp = &s->mapping;
    const pl_mapping_t *m = &mp->map;
    int final = mp->cg.srd_dt > 0 || mp->cg.time_match == PL_MATCH_KINEMATIC || mp->calib.d_inf > 0 ||
                mp->calib.source == PL_CALSRC_THEORY || mp->colloid.n_colloids == 0;
    if (!final || !(mp->cg.md_dt > 0) || mp->cg.md_dt <= m->dt * (1.0 + 1e-9)) return 0;
    /* the SRD step in seconds (t0) follows the physical inputs: an implausible one is at fault */
    const size_t from[] = {OFF(mapping.physical.viscosity), OFF(mapping.physical.radius),
                           OFF(mapping.physical.temperature), OFF(mapping.physical.solvent_density)};
    size_t off = OFF(mapping.cg.md_dt);
    char why[160];
    const char *key = pl_mapping_blame(s, from, sizeof from / sizeof from[0], &off, why, sizeof why);
    return pl_scene_fail(s, err, off, key ? key : "coarse_graining.md_dt",
                         "%scoarse_graining.md_dt = %g s is longer than the SRD step %.6g s (lambda t0, coarse_graining.mean_free_path = "
                         "%g); allowed: 0 < md_dt <= %.6g s (rounded to divide the SRD step), or 0 (derived "
                         "from min(tau_V, tau_P) / md_resolution)",
                         why, mp->cg.md_dt, m->dt, mp->cg.mean_free_path, m->dt);
}

int pl_mapping_scene_apply(pl_scene_t *s, pl_err_t *err)
{
    pl_scene_mapping_t *mp = &s->mapping;
    mp->enabled = section_given(s, &pl_scene_section_physical) != 0;
    if (!mp->enabled) {
        size_t cg_key = section_given(s, &pl_scene_section_coarse_graining);
        if (cg_key)
            return pl_scene_fail(s, err, cg_key - 1, "coarse_graining",
                                 "has no effect without a physical{} section (give at least physical.radius)");
        return 0;
    }
    if (pl_scene_line_of(s, OFF(mapping.physical.radius)) <= 0)
        return pl_scene_fail(s, err, OFF(mapping.physical.radius), "physical.radius",
                             "is required when physical{} is given");
    pl_mapping_system_t r;
    pl_mapping_solvent_t sv;
    pl_mapping_cg_t cg;
    if (mp->cg.coupling == PL_COUPLE_POTENTIAL && pl_scene_line_of(s, OFF(mapping.cg.boundary)) > 0 &&
        mp->cg.boundary != PL_BOUNDARY_SLIP)
        return pl_scene_fail(s, err, OFF(mapping.cg.boundary), "coarse_graining.boundary",
                             "\"stick\" contradicts coarse_graining.coupling = \"potential\": the radial forces of "
                             "PL Eq. 17 transfer no angular momentum (PL Sec. III.B); allowed: \"slip\" or not given");
    fill_inputs(s, &r, &sv, &cg);
    pl_err_t e = {0};
    if (pl_mapping_derive(&r, &sv, &cg, &mp->map, &e)) { /* the inputs' own checks (mapping_hecht.c) */
        const size_t dens[] = {OFF(mapping.physical.solvent_density), OFF(mapping.physical.particle_density)};
        const int density = strstr(e.msg, "dens") != NULL;
        size_t off = density ? dens[1] : OFF(mapping.physical.radius);
        char why[160];
        const char *key = density ? pl_mapping_blame(s, dens, 2, &off, why, sizeof why) : NULL;
        if (!key) key = density ? "physical.particle_density" : "physical.radius";
        return pl_scene_fail(s, err, off, key, "%s%s", density ? why : "", e.msg);
    }
    const pl_mapping_t *m = &mp->map;
    if (forbid(s, err, OFF(srd.dt), "srd.dt", cg.lambda, s->srd.dt) ||
        forbid(s, err, OFF(fluid.density), "fluid.density", cg.gamma, s->fluid.density) ||
        forbid(s, err, OFF(fluid.temperature), "fluid.temperature", 1.0, s->fluid.temperature))
        return PL_ERR_INPUT;
    s->srd.dt = cg.lambda;              /* PL Eq. 4: dt = lambda t0 */
    s->fluid.density = cg.gamma;
    s->fluid.temperature = 1.0;         /* kT_model is the energy unit */
    if (electrostatics(s, err) || apply_box(s, err) || check_md_dt(s, err)) return PL_ERR_INPUT;
    pl_mapping_diffusion_box(s);

    pl_mapping_colloid_t *c = &mp->colloid;
    c->radius = m->sigma;
    c->mass = m->mass_sim;
    c->gravity = m->g_sim;
    c->hamaker = r.hamaker / r.kT;
    c->primary_minimum = r.l_min / m->a0;
    c->md_dt = m->md_dt / m->t0;
    c->md_substeps = m->md_substeps;
    if (pl_mapping_colloids_apply(s, err) || pl_mapping_observe_apply(s, err)) return PL_ERR_INPUT;
    pl_mapping_plausible(s, &mp->map);
    pl_mapping_sediment_audit(s, &mp->map);
    if (mp->cg.strict && pl_mapping_nwarnings(m) > 0) {
        for (int i = 0; i < m->nwarn; ++i)
            if (m->warn[i].severity == PL_SEV_WARNING)
                return pl_scene_fail(s, err, OFF(mapping.cg.strict), "coarse_graining.strict", "%s: %s",
                                     m->warn[i].name, m->warn[i].text);
    }
    return 0;
}

int pl_mapping_report_json(const struct pl_scene *scene, struct json_t **out, pl_err_t *err)
{
    const pl_scene_mapping_t *mp = &scene->mapping;
    if (!mp->enabled) {
        *out = json_null();
        return 0;
    }
    return pl_mapping_json(&mp->map, &mp->colloid, scene->path, out, err);
}

static int ident_char(char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.'; }

/* The first "section.key" a warning's text names (its remedy, e.g. "lower
 * coarse_graining.mean_free_path") that the scene file gives: the key a
 * --strict refusal blames, with its file and line.  0: none given. */
static int named_given_key(const pl_scene_t *s, const char *text, size_t *off, char *key, size_t nkey)
{
    size_t nsec;
    const pl_section_t *const *secs = pl_scene_sections(&nsec);
    const char *best = NULL;
    for (size_t i = 0; i < nsec; ++i)
        for (size_t k = 0; secs[i]->name[0] && k < secs[i]->nkeys; ++k) {
            char full[128];
            snprintf(full, sizeof full, "%s.%s", secs[i]->name, secs[i]->keys[k].name);
            for (const char *p = strstr(text, full); p; p = strstr(p + 1, full))
                if ((p == text || !ident_char(p[-1])) && !ident_char(p[strlen(full)]) &&
                    pl_scene_line_of(s, secs[i]->keys[k].offset) > 0 && (!best || p < best)) {
                    best = p;
                    *off = secs[i]->keys[k].offset;
                    snprintf(key, nkey, "%s", full);
                }
        }
    return best != NULL;
}

int pl_mapping_report_strict(const struct pl_scene *scene, int strict, pl_err_t *err)
{
    const pl_scene_mapping_t *mp = &scene->mapping;
    if (mp->enabled && (strict || mp->cg.strict)) {
        /* an implausible input first (its file, line and key): it is most
         * likely the cause of the other warnings */
        for (int pass = 0; pass < 2; ++pass)
            for (int i = 0; i < mp->map.nwarn; ++i) {
                const pl_mapping_warning_t *w = &mp->map.warn[i];
                if (w->severity != PL_SEV_WARNING || (pass == 0) != (w->key[0] != '\0')) continue;
                if (pass == 0)
                    return pl_scene_fail(scene, err, w->key_off, w->key, "strict mapping audit: %s: %s", w->name,
                                         w->text);
                size_t off; /* else the key its remedy names, where the file gives it */
                char key[128];
                if (named_given_key(scene, w->text, &off, key, sizeof key))
                    return pl_scene_fail(scene, err, off, key, "strict mapping audit: %s: %s", w->name, w->text);
                return pl_err_set(err, PL_ERR_INPUT, "%s: strict mapping audit: %s: %s", scene->path, w->name,
                                  w->text);
            }
    }
    return 0;
}

void pl_mapping_warnings_print(const struct pl_scene *scene, FILE *out)
{
    const pl_scene_mapping_t *mp = &scene->mapping;
    if (!mp->enabled) return;
    for (int i = 0; i < mp->map.nwarn; ++i)
        if (mp->map.warn[i].severity == PL_SEV_WARNING)
            fprintf(out, "peloid: warning: %s: %s: %s\n", scene->path, mp->map.warn[i].name, mp->map.warn[i].text);
}

/* The physical{} and coarse_graining{} inputs, each marked given (with its
 * line), derived (from which relation) or default. */
static void print_inputs(const pl_scene_t *s, FILE *f)
{
    const pl_section_t *secs[2] = {&pl_scene_section_physical, &pl_scene_section_coarse_graining};
    fprintf(f, "Inputs of the mapping (given: in the file; default: the schema's; derived: computed here):\n");
    for (int k = 0; k < 2; ++k) {
        for (size_t i = 0; i < secs[k]->nkeys; ++i) {
            const pl_key_t *key = &secs[k]->keys[i];
            const char *base = (const char *)s + key->offset;
            char v[96];
            switch (key->type) {
            case PL_KEY_REAL: snprintf(v, sizeof v, "%.6g", *(const double *)base); break;
            case PL_KEY_REAL3: {
                const double *x = (const double *)base;
                snprintf(v, sizeof v, "[%.6g, %.6g, %.6g]", x[0], x[1], x[2]);
                break;
            }
            case PL_KEY_INT: snprintf(v, sizeof v, "%lld", *(const long long *)base); break;
            case PL_KEY_BOOL: snprintf(v, sizeof v, "%s", *(const int *)base ? "true" : "false"); break;
            case PL_KEY_CHOICE: snprintf(v, sizeof v, "\"%s\"", pl_key_choice_name(key, *(const int *)base)); break;
            default: snprintf(v, sizeof v, "-"); break;
            }
            int line = pl_scene_line_of(s, key->offset);
            char how[160];
            if (line > 0) snprintf(how, sizeof how, "given, line %d", line);
            else if (key->offset == OFF(mapping.physical.permittivity))
                snprintf(how, sizeof how, "derived: water at %g K (Malmberg & Maryott 1956)",
                         s->mapping.physical.temperature);
            else if (key->offset == OFF(mapping.physical.kappa) && s->mapping.physical.ionic_strength > 0)
                snprintf(how, sizeof how, "derived: Debye-Hueckel from ionic_strength = %.4g /m",
                         s->mapping.kappa);
            else if (s->mapping.cg.coupling == PL_COUPLE_POTENTIAL &&
                     (key->offset == OFF(mapping.cg.boundary) || key->offset == OFF(mapping.cg.enskog)))
                snprintf(how, sizeof how, "derived: the potential coupling's theory is slip + Enskog (PL Sec. "
                                          "III.B, Eq. 41), not this value");
            else if (key->offset == OFF(mapping.cg.cell_size))
                snprintf(how, sizeof how, "default: a0/R = %.6g of the coupling (Hecht Sec. VII.B/C)",
                         s->mapping.map.cg.cell_over_R);
            else snprintf(how, sizeof how, "default");
            fprintf(f, "  %s.%-20s = %-28s (%s)\n", secs[k]->name, key->name, v, how);
        }
    }
}

int pl_mapping_report(const struct pl_scene *scene, FILE *out, int json, int strict, pl_err_t *err)
{
    const pl_scene_mapping_t *mp = &scene->mapping;
    if (json) {
        json_t *doc = NULL;
        int rc = pl_mapping_report_json(scene, &doc, err);
        if (!rc) rc = pl_json_dump(doc, out, "stdout", err);
        json_decref(doc);
        if (rc) return rc;
    } else if (mp->enabled) {
        print_inputs(scene, out);
        pl_mapping_print_text(&mp->map, &mp->colloid, out);
    }
    return pl_mapping_report_strict(scene, strict, err);
}
