/* The colloid module (peloid/module.h): creates the colloids of the scene,
 * adds their MD stage and trajectory writer, their thermo columns (kinetic
 * and potential energy terms, centre-of-mass height) and their pair
 * settings in summary.json. */
#include <jansson.h>
#include <math.h>
#include <stdio.h>

#include "checkpoint_h5.h"
#include "json_build.h"
#include "peloid/checkpoint.h"
#include "peloid/colloid.h"
#include "peloid/module.h"

static int colloid_create(pl_sim_t *sim, pl_err_t *err)
{
    return sim->scene.colloids.count > 0 ? pl_colloid_create(&sim->scene, sim->nthreads, &sim->colloids, err) : 0;
}

static void colloid_destroy(pl_sim_t *sim)
{
    pl_colloid_free(sim->colloids);
    sim->colloids = NULL;
}

/* Colloid MD: colloids.substeps MD steps of dt_MD = srd.dt / substeps.
 * ctx: the colloids. */
static int stage_colloid_md(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    pl_colloid_t *c = ctx;
    return pl_colloid_advance(c, sim->step, err);
}

static int colloid_stages(pl_sim_t *sim, pl_err_t *err)
{
    int rc;
    const pl_scene_t *sc = &sim->scene;
    if (!sim->colloids) return 0;
    /* pinned colloids do not move; the potential coupling runs the
     * colloid MD together with the fluid near them */
    if (!pl_coupling_moves_colloids(sc, sim->fluid.n)) {
        pl_stage_t md = {.name = "colloid-md", .fn = stage_colloid_md, .ctx = sim->colloids,
                         .slot = PL_SLOT_COLLOID_MD, .colloid_md = 1};
        if ((rc = pl_sim_add_stage(sim, &md, err))) return rc;
    }
    return 0;
}

/* ---- thermo columns (energies: src/colloid/colloid_state.c) ------------------- */
static double v_ekin(const pl_thermo_sample_t *s, int rot) { return rot ? s->ce.kin_rot : s->ce.kin_trans; }
static double v_epot(const pl_thermo_sample_t *s, int k) { return s->ce.pot[k]; }
static double v_etotal(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->ce.total;
}
/* centre-of-mass height of the colloids (unwrapped z): sedimentation */
static double v_zcm(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    const pl_colloid_t *c = s->sim->colloids;
    double mz = 0.0, m = 0.0;
    for (size_t k = 0; k < c->n; ++k) { /* fixed order */
        mz += c->mass[k] * (c->z[k] + (double)c->iz[k] * c->box[2]);
        m += c->mass[k];
    }
    return m > 0.0 ? mz / m : 0.0;
}
static const pl_thermo_column_t kin_cols[] = {
    {.name = "c_kin_trans", .unit = "kT", .value = v_ekin, .arg = 0},
    {.name = "c_kin_rot", .unit = "kT", .value = v_ekin, .arg = 1},
};
static const pl_thermo_column_t tail_cols[] = {
    {.name = "c_total", .unit = "kT", .value = v_etotal},
    {.name = "c_zcm", .unit = "a0", .value = v_zcm},
};

static void colloid_columns(const pl_sim_t *sim, pl_thermo_table_t *t)
{
    if (!sim->colloids) return;
    pl_thermo_add(t, kin_cols, 2);
    /* one column per energy slot (PL_COLLOID_ENERGY_SLOTS): always, or when
     * the scene switches its pair term on */
    static const struct { unsigned bit; int always; } slot[PL_CE_NTERMS] = {
#define SLOT_(ID, col, b, a) [PL_CE_##ID] = {(b), (a)},
        PL_COLLOID_ENERGY_SLOTS(SLOT_)
#undef SLOT_
    };
    for (int k = 0; k < PL_CE_NTERMS; ++k) {
        if (!slot[k].always && !(sim->colloids->pair.terms & slot[k].bit)) continue;
        pl_thermo_column_t c = {.name = pl_colloid_energy_names[k], .unit = "kT", .value = v_epot, .arg = k};
        pl_thermo_add(t, &c, 1);
    }
    pl_thermo_add(t, tail_cols, 2);
}

/* The start-of-run lines about the pair terms: where the DLVO potential was
 * matched and cut (Hecht Eqs. 1-2), the colloid-colloid WCA diameter and
 * the depletion it compensates (PL Eqs. 22-23). */
static void colloid_describe(const pl_sim_t *sim, FILE *log)
{
    if (!sim->colloids) return;
    if (sim->colloids->pair.terms & PL_CT_DLVO) {
        const pl_colloid_dlvo_info_t *d = &sim->colloids->dlvo;
        char bar[64] = "none", sec[64] = "none"; /* NaN: the potential has no barrier / secondary minimum */
        if (isfinite(d->barrier_u)) snprintf(bar, sizeof bar, "%.4g kT at %.4g a0", d->barrier_u, d->barrier_h);
        if (isfinite(d->secmin_u)) snprintf(sec, sizeof sec, "%.4g kT at %.4g a0", d->secmin_u, d->secmin_h);
        fprintf(log, "peloid: DLVO: primary minimum matched at gap %.4g a0 (curvature %.4g kT/a0^2); "
                     "barrier %s; secondary minimum %s; cut-off gap %.4g a0, truncation error |V| = %.3g kT, "
                     "|F| = %.3g kT/a0\n",
                d->hm, d->curvature, bar, sec, d->hcut, d->trunc_u, d->trunc_f);
    }
    if (sim->colloids->pair.terms & (PL_CT_WCA | PL_CT_DEPL)) {
        const pl_colloid_depl_info_t *d = &sim->colloids->depl;
        if (d->sigma_cc > 0)
            fprintf(log, "peloid: colloid-colloid sigma_cc = %.6g a0 (%s); phi_cc = %.4g kT at twice the "
                         "colloid-fluid cut-off %.6g a0; depletion potential at sigma_cc %.4g kT "
                         "(PL Eqs. 22-23)%s\n",
                    d->sigma_cc, d->rule == PL_SIGMA_PL ? "wca.sigma_rule = pl, PL Sec. III.C.1" : "wca.sigma",
                    d->phi_match, d->d_match, d->phi_sigma, d->table_n ? "; compensated by depletion_comp" : "");
        else /* no wca term: the colloids touch at 2R */
            fprintf(log, "peloid: colloid-colloid contact at 2R = %.6g a0 (no wca term); depletion potential "
                         "there %.4g kT, acting below twice the colloid-fluid cut-off %.6g a0 (PL Eqs. 22-23)%s\n",
                    2.0 * sim->scene.colloids.radius, d->phi_sigma, d->d_match,
                    d->table_n ? "; compensated by depletion_comp" : "");
    }
}

/* summary.json "colloid_pairs": the colloid-colloid diameter and the
 * spurious depletion (PL Sec. III.C.1). */
static int colloid_summary(const pl_sim_t *sim, json_t *doc, pl_err_t *err)
{
    if (!sim->colloids) return 0;
    const pl_colloid_depl_info_t *d = &sim->colloids->depl;
    pl_json_t b = {err, sim->scene.path, "colloid_pairs", 0};
    json_t *o = json_object();
    pl_json_real(&b, o, "sigma_cc", d->sigma_cc);
    pl_json_str(&b, o, "sigma_rule", d->rule == PL_SIGMA_PL ? "pl" : "fixed");
    pl_json_real(&b, o, "d_match", d->d_match);
    pl_json_real(&b, o, "phi_cc_at_d_match", d->phi_match);
    /* the depletion potential (kT) at sigma_cc, or at the contact 2R without a wca term (sigma_cc 0); where (a0) */
    pl_json_real(&b, o, "depletion_at_sigma_cc", d->phi_sigma);
    pl_json_real(&b, o, "depletion_evaluated_at", d->sigma_cc > 0 ? d->sigma_cc : 2.0 * sim->scene.colloids.radius);
    pl_json_set(&b, o, "depletion_comp", json_boolean(d->table_n));
    pl_json_set(&b, doc, "colloid_pairs", o);
    return b.failed ? err->code : 0;
}

/* Group /colloids of the checkpoint (src/colloid/checkpoint_colloid.c). */
static int colloid_ckpt_write(int64_t f, const pl_sim_t *sim)
{
    return sim->colloids ? pl_ckpt_colloid_write((hid_t)f, sim->colloids) : 0;
}

static int colloid_ckpt_read(int64_t f, pl_sim_t *sim, const char *path, pl_err_t *err)
{
    return sim->colloids ? pl_ckpt_colloid_read((hid_t)f, sim->colloids, &sim->scene, path, err) : 0;
}

const pl_module_t pl_colloid_module = {
    .name = "colloids",
    .validate_scene = pl_colloid_validate_scene,
    .create = colloid_create,
    .destroy = colloid_destroy,
    .add_stages = colloid_stages,
    .thermo_columns = colloid_columns,
    .summary = colloid_summary,
    .describe = colloid_describe,
    .checkpoint_write = colloid_ckpt_write,
    .checkpoint_read = colloid_ckpt_read,
};
