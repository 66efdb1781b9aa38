/* `peloid params`: the SRD fluid's derived parameters from PL Sec. II.B,
 * as text or as JSON (jansson; also the "derived" object of summary.json). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "peloid/real.h" /* PL_PI */
#include "json_build.h"
#include "peloid/collision_rule.h"
#include "peloid/colloid.h"
#include "peloid/observe_check.h"
#include "peloid/params.h"
#include "peloid/srd_theory.h"
#include "peloid/threads.h"


int pl_params_json(const pl_scene_t *sc, struct json_t **out, pl_err_t *err)
{
    const double kT = pl_scene_kT(sc);
    pl_srd_theory_t t;
    pl_srd_theory_of(sc, &t);
    pl_json_t b = {err, sc->path, "derived", 0};
    json_t *o = json_object();
    const struct { const char *key; double v; } v[] = {
        {"lambda", t.lambda}, {"f_kin", t.f_kin}, {"f_col", t.f_col}, {"nu_kin", t.nu_kin},
        {"nu_col", t.nu_col}, {"nu", t.nu},       {"eta", t.eta},     {"D_f", t.D_f},
        {"Sc", t.Sc},         {"tau_f", t.tau_f}, {"c_s", t.c_s},     {"kT", kT},
    };
    /* without fluid (density 0) the SRD transport coefficients are undefined: null */
    for (size_t i = 0; i < sizeof v / sizeof v[0]; ++i) {
        if (sc->fluid.density > 0) pl_json_real(&b, o, v[i].key, v[i].v);
        else pl_json_real_or_null(&b, o, v[i].key, v[i].v);
    }
    if (sc->box.walls_z == PL_WALLS_NOSLIP) { /* nominal shear rate (u_top - u_bottom) / Lz, Hecht Sec. VIII.C */
        double shear[2];
        for (int d = 0; d < 2; ++d)
            shear[d] = (sc->box.wall_velocity[1][d] - sc->box.wall_velocity[0][d]) / sc->box.cells[2];
        pl_json_reals(&b, o, "wall_shear_rate", shear, 2);
    }
    if (b.failed && err->code == PL_ERR_INPUT) { /* name the input that gives it */
        char what[sizeof err->msg];
        const char *p = strstr(err->msg, "'derived.");
        snprintf(what, sizeof what, "%s", p ? p + 1 : err->msg);
        char *q = strchr(what, '\'');
        if (q) *q = '\0';
        json_decref(o);
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, srd.dt), "srd.dt",
                             "%g with fluid.density = %g, kT = %g, alpha = %g deg gives a non-finite %s "
                             "(PL Eqs. 4-15); allowed: values with finite derived parameters",
                             sc->srd.dt, sc->fluid.density, kT, sc->srd.alpha_deg, what);
    }
    if (b.failed || !o) {
        json_decref(o);
        return b.failed ? err->code : pl_err_set(err, PL_ERR_NOMEM, "out of memory building JSON");
    }
    *out = o;
    return 0;
}

int pl_run_check(const pl_scene_t *sc, pl_err_t *err)
{
    json_t *derived = NULL, *mapping = NULL;
    int nthreads = 1;
    int rc = pl_threads_resolve(0, &nthreads, err); /* as a run without --threads */
    if (!rc) rc = pl_scene_memory_check(sc, nthreads, err);
    if (!rc) rc = pl_params_json(sc, &derived, err);
    if (!rc) rc = pl_mapping_report_json(sc, &mapping, err);
    json_decref(derived);
    json_decref(mapping);
    if (!rc && sc->colloids.count > 0) { /* placement: init file, overlaps */
        pl_colloid_t *c = NULL;
        rc = pl_colloid_create(sc, nthreads, &c, err);
        if (!rc) rc = pl_observe_check_colloids(sc, c, err);
        pl_colloid_free(c);
    }
    return rc;
}

int pl_params_write_json(const pl_scene_t *sc, FILE *out, int strict, pl_err_t *err)
{
    json_t *srd = NULL, *map = NULL, *doc;
    int rc = pl_params_json(sc, &srd, err);
    if (rc) return rc;
    if (!sc->mapping.enabled) {
        doc = srd;
    } else { /* a scene with physical{} adds the unit mapping report (mapping.h) */
        if ((rc = pl_mapping_report_json(sc, &map, err)) || (rc = pl_mapping_report_strict(sc, strict, err))) {
            json_decref(srd);
            json_decref(map);
            return rc;
        }
        doc = json_object();
        pl_json_t b = {err, sc->path, "", 0};
        pl_json_set(&b, doc, "srd", srd);
        pl_json_set(&b, doc, "mapping", map);
        json_t *cal = pl_mapping_calibration_json(&sc->mapping.map); /* as summary.json's */
        if (cal) pl_json_set(&b, doc, "calibration", cal);
        if (b.failed) {
            json_decref(doc);
            return err->code;
        }
    }
    rc = pl_json_dump(doc, out, "stdout", err);
    json_decref(doc);
    return rc;
}

void pl_params_print(const pl_scene_t *sc, FILE *out)
{
    const double kT = pl_scene_kT(sc);
    pl_srd_theory_t t;
    pl_srd_theory_of(sc, &t);
    const pl_collision_rule_t *rule = pl_collision_rule(sc->srd.rule);
    /* rot: a rotation by srd.alpha; srd: PL's or Hecht's equations (not a rotation rule with a theory of its own) */
    const int hecht = rule->srd_rotation == PL_RULE_HECHT_AXES, rot = rule->srd_rotation >= 0,
              srd = rot && !rule->angular;
    /* the equation of each line: PL's, Hecht's, or the row's own theory */
    const char *e_fk = hecht ? "Hecht Eq. 28" : srd ? "PL Eq. 11" : rule->theory_ref;
    const char *e_fc = hecht ? "Hecht Eq. 28" : srd ? "PL Eq. 12" : rule->theory_ref;
    const char *e_nk = hecht ? "Hecht Eq. 28" : srd ? "PL Eq. 9" : rule->theory_ref;
    const char *e_nc = hecht ? "Hecht Eq. 28" : srd ? "PL Eq. 10" : rule->theory_ref;
    /* moving no-slip walls: nominal shear rate (u_top - u_bottom) / Lz (Hecht Sec. VIII.C) */
    const int sheared = sc->box.walls_z == PL_WALLS_NOSLIP;
    double shear[2];
    for (int d = 0; d < 2; ++d)
        shear[d] = (sc->box.wall_velocity[1][d] - sc->box.wall_velocity[0][d]) / sc->box.cells[2];
    fprintf(out, "SRD fluid of scene %s (units: a0 = 1, m_f = 1, kT_ref = 1)\n", sc->path);
    if (rot)
        fprintf(out, "  gamma = %g particles/cell, dt = %g, alpha = %g deg (%s), kT = %g\n", sc->fluid.density,
                sc->srd.dt, hecht ? 90.0 : sc->srd.alpha_deg, rule->name, kT);
    else /* no rotation: srd.alpha unused */
        fprintf(out, "  gamma = %g particles/cell, dt = %g (%s), kT = %g\n", sc->fluid.density, sc->srd.dt,
                rule->name, kT);
    if (hecht)
        fprintf(out, "  note: hecht_axes rotates by 90 deg whatever srd.alpha says: viscosity from "
                     "Hecht Eq. 28, f_kin and f_col as PL Eqs. 9-10 would need them\n");
    if (!srd) fprintf(out, "  note: %s: %s\n", rule->name, rule->doc);
    fprintf(out, "  lambda   = %-12.6g mean free path / a0            (PL Eq. 4)\n", t.lambda);
    fprintf(out, "  f_kin    = %-12.6g                                 (%s)\n", t.f_kin, e_fk);
    fprintf(out, "  f_col    = %-12.6g                                 (%s)\n", t.f_col, e_fc);
    fprintf(out, "  nu_kin   = %-12.6g a0^2/t0 kinetic viscosity      (%s)\n", t.nu_kin, e_nk);
    fprintf(out, "  nu_col   = %-12.6g a0^2/t0 collisional viscosity  (%s)\n", t.nu_col, e_nc);
    fprintf(out, "  nu       = %-12.6g a0^2/t0 kinematic viscosity\n", t.nu);
    fprintf(out, "  eta      = %-12.6g sqrt(m kT)/a0^2 shear viscosity (PL Eqs. 14-15)\n", t.eta);
    fprintf(out, "  D_f      = %-12.6g a0^2/t0 fluid self-diffusion   (%s)\n", t.D_f, srd ? "PL Eq. 6" : rule->theory_ref);
    fprintf(out, "  Sc       = %-12.6g nu / D_f Schmidt number        (PL Eq. 26)\n", t.Sc);
    fprintf(out, "  tau_f    = %-12.6g t0  a0^2/nu, momentum diffusion over one cell\n", t.tau_f);
    fprintf(out, "  c_s      = %-12.6g a0/t0 speed of sound sqrt(5kT/3m)\n", t.c_s);
    if (sheared)
        fprintf(out, "  shear    = [%g, %g] t0^-1 (u_top - u_bottom) / Lz of the walls; in the bulk "
                     "somewhat more (wall slip)\n", shear[0], shear[1]);
}
