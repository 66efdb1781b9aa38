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
