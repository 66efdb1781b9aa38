/* Coupling I as a component row (peloid/coupling_row.h): fluid particles
 * that stream into a colloid are reflected off its surface (Hecht Sec. IV).
 * Its state and stages: src/coupling/coupling_stages.c and
 * kernels/coupling_reflect.c; its checkpoint: none (the events are counters
 * of a run). */
#include "peloid/coupling_row.h"
#include "peloid/sim.h"

static int create(pl_coupling_t *cp, pl_sim_t *sim, pl_err_t *err)
{
    int rc = pl_coupling1_create(cp, sim, &cp->c1, err);
    if (!rc) rc = pl_coupling_lookup_update(&cp->c1->lk, sim, err);
    if (!rc) pl_coupling_clear_interiors_of(cp, sim, &cp->c1->lk, NULL);
    return rc;
}

static void free_state(pl_coupling_t *cp)
{
    pl_coupling1_free(cp->c1);
    cp->c1 = NULL;
}

static int add_stages(pl_sim_t *sim, pl_err_t *err)
{
    pl_stage_t cells = {.name = "coupling1-cells", .fn = pl_coupling_stage_reflect_cells, .ctx = pl_coupling_of(sim),
                        .interval = 1, .slot = PL_SLOT_PRE_STREAM};
    pl_stage_t reflect = {.name = "coupling1-reflect", .fn = pl_coupling_stage_reflect, .ctx = pl_coupling_of(sim),
                          .interval = 1, .slot = PL_SLOT_POST_STREAM};
    int rc = pl_sim_add_stage(sim, &cells, err);
    return rc ? rc : pl_sim_add_stage(sim, &reflect, err);
}

static long long v_events(const pl_thermo_sample_t *s, int trunc)
{
    const pl_coupling1_state_t *c1 = pl_coupling_of(s->sim)->c1;
    return (long long)(trunc ? c1->truncations : c1->events);
}
static const pl_thermo_column_t columns[] = {
    {.name = "cpl_events", .unit = "1", .format = PL_THERMO_INT, .ivalue = v_events, .arg = 0},
    {.name = "cpl_truncations", .unit = "1", .format = PL_THERMO_INT, .ivalue = v_events, .arg = 1},
};

const pl_coupling_row_t pl_coupling1_row = {
    .method = PL_COUPLE_HECHT1,
    .create = create,
    .free = free_state,
    .add_stages = add_stages,
    .columns = columns,
    .ncolumns = 2,
};
