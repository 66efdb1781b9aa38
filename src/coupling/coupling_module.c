/* The colloid-solvent coupling module (peloid/module.h): creates the
 * coupling the scene asks for (Hecht's I and II, PL's potential coupling,
 * pinned colloids, drift removal), adds its stages at their slots around
 * the fluid's, and its thermo columns (coupling I event counters, the drag
 * on pinned colloids).  Hecht Secs. IV-V, VIII.A; PL Secs. III, V. */
#include "checkpoint_h5.h"
#include "json_build.h"
#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/module.h"

static int coupling_create(pl_sim_t *sim, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    if (!sim->colloids || sim->fluid.n == 0 ||
        (sc->coupling.method == PL_COUPLE_NONE && sc->coupling.drift_interval <= 0))
        return 0;
    return pl_coupling_create(sim, &sim->coupling, err);
}

static void coupling_destroy(pl_sim_t *sim)
{
    pl_coupling_free(sim->coupling);
    sim->coupling = NULL;
}

static int add(pl_sim_t *sim, const char *name, pl_stage_fn fn, long long interval, pl_stage_slot_t slot,
               pl_err_t *err)
{
    pl_stage_t s = {.name = name, .fn = fn, .interval = interval, .slot = slot};
    return pl_sim_add_stage(sim, &s, err);
}

static int coupling_stages(pl_sim_t *sim, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    if (!sim->coupling) return 0;
    const int m = sim->coupling->method;
    int rc = 0;
    if (m == PL_COUPLE_POTENTIAL) {
        pl_stage_t md = {.name = "potential-md", .fn = pl_coupling_stage_potential_md, .slot = PL_SLOT_POST_STREAM,
                         .colloid_md = 1}; /* the colloids' MD, with the fluid near them (PL Sec. III) */
        if ((rc = add(sim, "potential-select", pl_coupling_stage_select, 1, PL_SLOT_PRE_STREAM, err)) ||
            (rc = pl_sim_add_stage(sim, &md, err)))
            return rc;
    }
    if (m == PL_COUPLE_HECHT1) {
        if ((rc = add(sim, "coupling1-cells", pl_coupling_stage_reflect_cells, 1, PL_SLOT_PRE_STREAM, err)) ||
            (rc = add(sim, "coupling1-reflect", pl_coupling_stage_reflect, 1, PL_SLOT_POST_STREAM, err)))
            return rc;
    }
    if (m == PL_COUPLE_HECHT2) { /* the variant of the fluid's collision */
        pl_stage_t plain = {.name = "coupling2-collide", .fn = pl_coupling_stage_collide,
                            .slot = PL_SLOT_POST_COLLIDE};
        pl_stage_t heyes = {.name = "coupling2-collide+heyes", .fn = pl_coupling_stage_collide_heyes,
                            .slot = PL_SLOT_POST_COLLIDE};
        if ((rc = add(sim, "coupling2-save", pl_coupling_stage_save, 1, PL_SLOT_PRE_COLLIDE, err)) ||
            (rc = pl_sim_add_collide_stage(sim, &plain, &heyes, err)))
            return rc;
    }
    const double *fv = sc->coupling.flow_velocity;
    if (sim->coupling->pinned && (fv[0] != 0.0 || fv[1] != 0.0 || fv[2] != 0.0) &&
        (rc = add(sim, "flow-hold", pl_coupling_stage_flow, 1, PL_SLOT_CONSTRAIN, err)))
        return rc;
    /* momentum is not conserved with walls: nothing to remove */
    if (sc->coupling.drift_interval > 0 && !sim->grid.any_walls)
        rc = add(sim, "drift-removal", pl_coupling_stage_drift, sc->coupling.drift_interval, PL_SLOT_CONSTRAIN, err);
    return rc;
}

/* ---- thermo columns ------------------------------------------------------ */
static long long v_events(const pl_thermo_sample_t *s, int trunc)
{
    const pl_coupling1_state_t *c1 = s->sim->coupling->c1; /* a column of coupling I only */
    return (long long)(trunc ? c1->truncations : c1->events);
}
static double v_drag(const pl_thermo_sample_t *s, int d) /* mean force per pinned colloid so far */
{
    const pl_coupling_t *cp = s->sim->coupling;
    double k = cp->pinned_time > 0 ? 1.0 / (cp->pinned_time * (double)s->sim->colloids->n) : 0.0;
    return cp->impulse[d] * k;
}
static const pl_thermo_column_t reflect_cols[] = { /* coupling I (Hecht Sec. IV) */
    {.name = "cpl_events", .unit = "1", .format = PL_THERMO_INT, .ivalue = v_events, .arg = 0},
    {.name = "cpl_truncations", .unit = "1", .format = PL_THERMO_INT, .ivalue = v_events, .arg = 1},
};
static const pl_thermo_column_t pinned_cols[] = {
    {.name = "cpl_drag_x", .unit = "kT/a0", .value = v_drag, .arg = 0},
    {.name = "cpl_drag_y", .unit = "kT/a0", .value = v_drag, .arg = 1},
    {.name = "cpl_drag_z", .unit = "kT/a0", .value = v_drag, .arg = 2},
};

static void coupling_columns(const pl_sim_t *sim, pl_thermo_table_t *t)
{
    if (!sim->coupling) return;
    if (sim->coupling->method == PL_COUPLE_HECHT1) pl_thermo_add(t, reflect_cols, 2);
    if (sim->coupling->pinned) pl_thermo_add(t, pinned_cols, 3);
}

/* /wall_impulse (walls) and group /coupling: the run counters
 * (src/io/checkpoint_coupling.c); written for any scene with walls. */
static int coupling_ckpt_write(int64_t f, const pl_sim_t *sim) { return pl_ckpt_coupling_write((hid_t)f, sim); }

static int coupling_ckpt_read(int64_t f, pl_sim_t *sim, const char *path, pl_err_t *err)
{
    /* the colloid set-up the reader redoes knows nothing of the coupling:
     * coupled colloids exchange energy with the fluid, no NVE drift guard
     * (as pl_coupling_create decided) */
    if (sim->colloids && sim->coupling && sim->coupling->method != PL_COUPLE_NONE) sim->colloids->nve = 0;
    return pl_ckpt_coupling_read((hid_t)f, sim, path, err);
}

/* summary.json "coupling" (potential coupling): how often the selection
 * margin was used up in this run (not checkpointed: counts of this run). */
static int coupling_finish(pl_sim_t *sim, const char *dir, json_t *doc, pl_err_t *err)
{
    (void)dir;
    if (!sim->coupling || sim->coupling->method != PL_COUPLE_POTENTIAL || !sim->coupling->pot) return 0;
    const pl_coupling_potential_state_t *ps = sim->coupling->pot;
    pl_json_t b = {err, sim->scene.path, "coupling", 0};
    json_t *o = json_object();
    pl_json_int(&b, o, "potential_force_evaluations", (long long)ps->force_calls);
    pl_json_int(&b, o, "selection_margin_exceeded", (long long)ps->margin_exceeded);
    pl_json_int(&b, o, "selected_particle_steps", (long long)ps->near_total); /* the cost */
    pl_json_set(&b, doc, "coupling", o);
    return b.failed ? err->code : 0;
}

const pl_module_t pl_coupling_module = {
    .name = "coupling",
    .validate_scene = pl_coupling_validate_scene,
    .create = coupling_create,
    .destroy = coupling_destroy,
    .add_stages = coupling_stages,
    .thermo_columns = coupling_columns,
    .checkpoint_write = coupling_ckpt_write,
    .checkpoint_read = coupling_ckpt_read,
    .finish = coupling_finish,
};
