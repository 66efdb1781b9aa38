/* The thermostat rows (peloid/thermostat.h, src/fluid/thermostats.c): one
 * row per value of thermostat.type, in the order the scene stores, and what
 * each adds to the plan: none nothing, heyes the collision's Heyes variant
 * every thermostat.interval steps (the plain collision on the others),
 * rescale its own stage after the collision, with the fluid's state as its
 * context.  A rule that is itself a thermostat refuses every row but none. */
#include <string.h>

#include "peloid/thermostat.h"
#include "support.h"

static const pl_stage_t *stage(const pl_sim_t *sim, const char *name)
{
    for (int k = 0; k < sim->nstages; ++k)
        if (!strcmp(sim->stages[k].name, name)) return &sim->stages[k];
    return NULL;
}

static pl_sim_t *sim_with(const char *thermostat)
{
    static char text[512];
    snprintf(text, sizeof text,
             "seed = 5;\nbox: { cells = [6, 6, 6]; };\nfluid: { density = 4.0; };\nthermostat: { %s };\n", thermostat);
    return pl_test_sim(text, 1);
}

Test(thermostat_rows, names_in_scene_order)
{
    int n = 0;
    while (pl_thermostat_names[n]) {
        cr_assert_not_null(pl_thermostat(n), "row %d", n);
        cr_expect_str_eq(pl_thermostat(n)->name, pl_thermostat_names[n]);
        ++n;
    }
    cr_expect_eq(n, 3, "none, heyes, rescale");
    cr_expect_str_eq(pl_thermostat(PL_THERMO_NONE)->name, "none");
    cr_expect_null(pl_thermostat(n));
    cr_expect_null(pl_thermostat(-1));
}

Test(thermostat_rows, none_adds_nothing)
{
    pl_sim_t *sim = sim_with("type = \"none\";");
    cr_expect_null(stage(sim, "collide+heyes"));
    cr_expect_null(stage(sim, "thermostat-rescale"));
    const pl_stage_t *c = stage(sim, "collide");
    cr_assert_not_null(c);
    cr_expect(c->interval == 1 && c->except == 0);
    pl_sim_free(sim);
}

Test(thermostat_rows, heyes_runs_in_the_collision)
{
    pl_sim_t *sim = sim_with("type = \"heyes\"; interval = 3;");
    const pl_stage_t *h = stage(sim, "collide+heyes"), *c = stage(sim, "collide");
    cr_assert(h && c);
    cr_expect_eq(h->interval, 3);
    cr_expect(c->interval == 1 && c->except == 3, "plain on the other steps");
    cr_expect(h->ctx == sim->srd && c->ctx == sim->srd);
    cr_expect_null(stage(sim, "thermostat-rescale"));
    pl_sim_free(sim);
}

Test(thermostat_rows, rescale_adds_its_stage)
{
    pl_sim_t *sim = sim_with("type = \"rescale\"; interval = 2;");
    const pl_stage_t *r = stage(sim, "thermostat-rescale");
    cr_assert_not_null(r);
    cr_expect(r->interval == 2 && r->slot == PL_SLOT_THERMOSTAT && r->ctx == sim->srd);
    cr_expect_null(stage(sim, "collide+heyes"));
    /* it sets kT_cell to the target where it runs (step 0 -> 1), the
     * collision alone measures it (step 1 -> 2) */
    pl_test_steps(sim, 1);
    cr_expect_eq(*pl_srd_kept(sim->srd).kT_cell, sim->scene.thermostat.temperature);
    pl_test_steps(sim, 1);
    cr_expect_neq(*pl_srd_kept(sim->srd).kT_cell, sim->scene.thermostat.temperature);
    pl_sim_free(sim);
}

Test(thermostat_rows, a_thermostat_rule_refuses_them)
{
    for (int t = 1; pl_thermostat_names[t]; ++t) {
        char text[512];
        snprintf(text, sizeof text,
                 "box: { cells = [6, 6, 6]; };\nsrd: { rule = \"mpc_at\"; };\nthermostat: { type = \"%s\"; };\n",
                 pl_thermostat_names[t]);
        pl_scene_t scene;
        pl_err_t err = {0, ""};
        cr_expect_eq(pl_scene_load_string(text, "test.cfg", &scene, &err), PL_ERR_INPUT, "%s",
                     pl_thermostat_names[t]);
        cr_expect(strstr(err.msg, "thermostat.type") && strstr(err.msg, "itself one"), "%s", err.msg);
    }
}
