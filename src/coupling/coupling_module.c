/* The colloid-solvent coupling module (peloid/module.h): creates the
 * coupling the scene asks for (Hecht's I and II, PL's potential coupling:
 * each a row, peloid/coupling_row.h; pinned colloids, drift removal), adds
 * the method's stages and columns (its row) and the common ones (flow hold,
 * drift removal; the drag on pinned colloids) at their slots around the
 * fluid's.  Hecht Secs. IV-V, VIII.A; PL Secs. III, V. */
#include "checkpoint_h5.h"
#include "json_build.h"
#include "peloid/checkpoint.h"
#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/coupling_row.h"
#include "peloid/module.h"

static int coupling_create(pl_sim_t *sim, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    if (!sim->colloids || sim->fluid.n == 0 ||
        (sc->coupling.method == PL_COUPLE_NONE && sc->coupling.drift_interval <= 0))
        return 0;
    pl_coupling_t *cp = NULL;
    const int rc = pl_coupling_create(sim, &cp, err);
    pl_module_set_state(sim, &pl_coupling_module, cp);
    return rc;
}

static void coupling_destroy(pl_sim_t *sim)
{
    pl_coupling_free(pl_coupling_of(sim));
    pl_module_set_state(sim, &pl_coupling_module, NULL);
}

pl_coupling_t *pl_coupling_of(const pl_sim_t *sim) { return pl_module_state(sim, &pl_coupling_module); }

static int add(pl_sim_t *sim, const char *name, pl_stage_fn fn, long long interval, pl_stage_slot_t slot,
               pl_err_t *err)
{
    pl_stage_t s = {.name = name, .fn = fn, .ctx = pl_coupling_of(sim), .interval = interval, .slot = slot};
    return pl_sim_add_stage(sim, &s, err);
}

static int coupling_stages(pl_sim_t *sim, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const pl_coupling_t *cp = pl_coupling_of(sim);
    if (!cp) return 0;
    const pl_coupling_row_t *row = pl_coupling_row(cp->method);
    int rc = row ? row->add_stages(sim, err) : 0;
    if (rc) return rc;
    const double *fv = sc->coupling.flow_velocity;
    if (cp->pinned && pl_vec3_nonzero(fv) &&
        (rc = add(sim, "flow-hold", pl_coupling_stage_flow, 1, PL_SLOT_CONSTRAIN, err)))
        return rc;
    /* momentum is not conserved with walls: nothing to remove */
    if (sc->coupling.drift_interval > 0 && !sim->grid.any_walls)
        rc = add(sim, "drift-removal", pl_coupling_stage_drift, sc->coupling.drift_interval, PL_SLOT_CONSTRAIN, err);
    return rc;
}

/* ---- thermo columns ------------------------------------------------------ */
static double v_drag(const pl_thermo_sample_t *s, int d) /* mean force (torque: d 3..5) per pinned colloid so far */
{
    const pl_coupling_t *cp = pl_coupling_of(s->sim);
    double k = cp->pinned_time > 0 ? 1.0 / (cp->pinned_time * (double)s->sim->colloids->n) : 0.0;
    return cp->impulse[d] * k;
}
static const pl_thermo_column_t pinned_cols[] = {
    {.name = "cpl_drag_x", .unit = "kT/a0", .value = v_drag, .arg = 0},
    {.name = "cpl_drag_y", .unit = "kT/a0", .value = v_drag, .arg = 1},
    {.name = "cpl_drag_z", .unit = "kT/a0", .value = v_drag, .arg = 2},
    /* with a held spin (coupling.pinned_spin): the mean torque per colloid so far */
    {.name = "cpl_torque_x", .unit = "kT", .value = v_drag, .arg = 3},
    {.name = "cpl_torque_y", .unit = "kT", .value = v_drag, .arg = 4},
    {.name = "cpl_torque_z", .unit = "kT", .value = v_drag, .arg = 5},
};

static int spins(const pl_coupling_t *cp) { return pl_vec3_nonzero(cp->spin); }

static void coupling_columns(const pl_sim_t *sim, pl_thermo_table_t *t)
{
    const pl_coupling_t *cp = pl_coupling_of(sim);
    if (!cp) return;
    const pl_coupling_row_t *row = pl_coupling_row(cp->method);
    if (row && row->ncolumns) pl_thermo_add(t, row->columns, row->ncolumns);
    if (cp->pinned) pl_thermo_add(t, pinned_cols, spins(cp) ? 6 : 3);
}

/* /wall_impulse (walls) and group /coupling: the run counters
 * (src/coupling/checkpoint_coupling.c); written for any scene with walls. */
static int coupling_ckpt_write(int64_t f, const pl_sim_t *sim) { return pl_ckpt_coupling_write((hid_t)f, sim, pl_coupling_of(sim)); }

static int coupling_ckpt_read(int64_t f, pl_sim_t *sim, const char *path, pl_err_t *err)
{
    /* the colloid set-up the reader redoes knows nothing of the coupling:
     * coupled colloids exchange energy with the fluid, no NVE drift guard
     * (as pl_coupling_create decided) */
    pl_coupling_t *cp = pl_coupling_of(sim);
    if (sim->colloids && cp && cp->method != PL_COUPLE_NONE) pl_colloid_exchange_energy(sim->colloids);
    return pl_ckpt_coupling_read((hid_t)f, sim, cp, path, err);
}

/* The method's summary.json entries (its row). */
static int coupling_finish(pl_sim_t *sim, const char *dir, json_t *doc, pl_err_t *err)
{
    (void)dir;
    pl_coupling_t *cp = pl_coupling_of(sim);
    const pl_coupling_row_t *row = cp ? pl_coupling_row(cp->method) : NULL;
    return row && row->finish ? row->finish(cp, sim, doc, err) : 0;
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
