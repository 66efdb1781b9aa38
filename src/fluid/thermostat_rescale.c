/* The rescaling thermostat as a thermostat row (peloid/thermostat.h): every
 * thermostat.interval steps, after the collision, each particle's velocity
 * relative to its cell's mean scaled by sqrt(kT* / kT_cell), kT_cell the
 * PL Eq. A1 temperature of the last collision (PL Appendix A, Eqs. A1-A2;
 * kernel pl_srd_rescale, kernels/srd_collide.c). */
#include <math.h>
#include <stddef.h>

#include "peloid/sim.h"
#include "peloid/thermostat.h"

#include "srd_state.h"

/* ctx: the fluid's state (peloid/srd.h) */
static int stage_rescale(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    (void)err;
    pl_srd_t *fs = ctx;
    if (fs->last_kT_meas <= 0.0) return 0;
    double factor = sqrt(sim->scene.thermostat.temperature / fs->last_kT_meas); /* PL App. A */
    pl_srd_rescale(&sim->fluid, fs->cell_start, sim->grid.ncells, factor, sim->nthreads);
    fs->last_kT_meas = sim->scene.thermostat.temperature;
    return 0;
}

/* The rescaling reads each cell's particles as one range of the arrays: not
 * between the full sorts of srd.sort_interval (the index sort's steps). */
static int validate(const pl_scene_t *sc, pl_err_t *err)
{
    if (sc->srd.sort_interval > 1)
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, srd.sort_interval), "srd.sort_interval",
                             "%lld: thermostat.type = \"rescale\" reads each cell's particles contiguous; allowed "
                             "here: 1", sc->srd.sort_interval);
    return 0;
}

static int add_stages(pl_sim_t *sim, pl_srd_t *fs, pl_err_t *err)
{
    pl_stage_t r = {.name = "thermostat-rescale", .fn = stage_rescale, .ctx = fs,
                    .interval = sim->scene.thermostat.interval, .slot = PL_SLOT_THERMOSTAT};
    return pl_sim_add_stage(sim, &r, err);
}

const pl_thermostat_t pl_thermostat_rescale = {
    .name = "rescale",
    .doc = "cell-relative rescaling to the global T (PL Appendix A, Eqs. A1-A2)",
    .keys = "thermostat.temperature, thermostat.interval",
    .validate = validate,
    .add_stages = add_stages,
};
