/* Initial fluid state from the scene (uniform positions; uniform or
 * Gaussian velocities with zero total momentum and exactly the set
 * temperature): unpacks the scene for the kernel pl_srd_init
 * (kernels/srd_init.c). */
#include "peloid/sim.h"

void pl_fluid_init(pl_fluid_t *f, const pl_scene_t *sc, int nthreads)
{
    const pl_srd_init_params_t p = {
        .seed = (uint64_t)sc->run.seed,
        .kT = sc->fluid.temperature,
        .uniform = sc->fluid.init_velocity == PL_VEL_UNIFORM,
        .L = {sc->box.cells[0], sc->box.cells[1], sc->box.cells[2]},
    };
    pl_srd_init(f, &p, nthreads);
}
