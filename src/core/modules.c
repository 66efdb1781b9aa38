/* The table of modules (peloid/module.h): one row per module. */
#include "peloid/module.h"

const pl_module_t *const pl_modules[] = {
    &pl_fluid_module,
    &pl_colloid_module,
    &pl_coupling_module,
    &pl_observe_module,
    &pl_stress_module,
    &pl_stop_module,
    NULL,
};
_Static_assert(sizeof pl_modules / sizeof *pl_modules - 1 <= PL_MAX_MODULES, "a slot of sim->module_state per module");

static int module_index(const pl_module_t *m)
{
    int k = 0;
    while (pl_modules[k] && pl_modules[k] != m) ++k;
    return pl_modules[k] ? k : -1;
}

void *pl_module_state(const pl_sim_t *sim, const pl_module_t *m)
{
    const int k = module_index(m);
    return k >= 0 ? sim->module_state[k] : NULL;
}

void pl_module_set_state(pl_sim_t *sim, const pl_module_t *m, void *state)
{
    const int k = module_index(m);
    if (k >= 0) sim->module_state[k] = state;
}
