/* The potential coupling as a component row (peloid/coupling_row.h): WCA
 * colloid-fluid forces integrated at the MD step for the fluid near the
 * colloids (PL Sec. III.A, Eq. 17); its MD stage moves the colloids.  Its
 * state and stages: src/coupling/coupling_potential.c. */
#include "json_build.h"
#include "peloid/coupling_row.h"
#include "peloid/sim.h"

static int create(pl_coupling_t *cp, pl_sim_t *sim, pl_err_t *err)
{
    int rc = pl_coupling_potential_create(cp, sim, &cp->pot, err);
    if (rc) return rc;
    /* the interiors of the spheres of radius sigma_cf */
    pl_coupling_potential_state_t *ps = cp->pot;
    for (size_t k = 0; k < sim->colloids->n; ++k) ps->rad_big[k] = ps->wca.sigma;
    pl_coupling_colloids_t v = pl_coupling_view(sim->colloids);
    v.rad = ps->rad_big;
    if (!(rc = pl_coupling_lookup_fill(&ps->lk, sim, &v, err))) pl_coupling_clear_interiors_of(cp, sim, &ps->lk, ps->rad_big);
    return rc;
}

static void free_state(pl_coupling_t *cp)
{
    pl_coupling_potential_free(cp->pot);
    cp->pot = NULL;
}

static int add_stages(pl_sim_t *sim, pl_err_t *err)
{
    pl_stage_t select = {.name = "potential-select", .fn = pl_coupling_stage_select, .ctx = pl_coupling_of(sim),
                         .interval = 1, .slot = PL_SLOT_PRE_STREAM};
    pl_stage_t md = {.name = "potential-md", .fn = pl_coupling_stage_potential_md, .ctx = pl_coupling_of(sim),
                     .slot = PL_SLOT_POST_STREAM,
                     .colloid_md = 1}; /* the colloids' MD, with the fluid near them (PL Sec. III) */
    int rc = pl_sim_add_stage(sim, &select, err);
    return rc ? rc : pl_sim_add_stage(sim, &md, err);
}

/* summary.json "coupling": how often the selection margin was used up in
 * this run (not checkpointed: counts of this run). */
static int finish(const pl_coupling_t *cp, const pl_sim_t *sim, json_t *doc, pl_err_t *err)
{
    const pl_coupling_potential_state_t *ps = cp->pot;
    if (!ps) return 0;
    pl_json_t b = {err, sim->scene.path, "coupling", 0};
    json_t *o = json_object();
    pl_json_int(&b, o, "potential_force_evaluations", (long long)ps->force_calls);
    pl_json_int(&b, o, "selection_margin_exceeded", (long long)ps->margin_exceeded);
    pl_json_int(&b, o, "selected_particle_steps", (long long)ps->near_total); /* the cost */
    pl_json_set(&b, doc, "coupling", o);
    return b.failed ? err->code : 0;
}

const pl_coupling_row_t pl_coupling_potential_row = {
    .method = PL_COUPLE_POTENTIAL,
    .moves_colloids = 1,
    .create = create,
    .free = free_state,
    .add_stages = add_stages,
    .finish = finish,
};
