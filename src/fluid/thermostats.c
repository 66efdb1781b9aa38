/* The thermostats of the fluid, one row each (peloid/thermostat.h).  Their
 * one list is include/peloid/thermostat_list.h: a new thermostat is its own
 * file (row, stages; a kernel of its own under kernels/) plus one line
 * there.  The scene stores a thermostat as its index in this list
 * (thermostat.type): none 0, heyes 1, rescale 2, as before the rows, so
 * scenes and checkpoints read as before.  Also the collision stage in its
 * two variants, which the row of the scene's thermostat chooses. */
#include <stddef.h>

#include "peloid/scene.h"
#include "peloid/sim.h"
#include "peloid/thermostat.h"
#include "peloid/thermostat_list.h"

static const pl_thermostat_t none = {
    .name = "none",
    .doc = "no thermostat",
};

extern const pl_thermostat_t pl_thermostat_heyes;   /* src/fluid/thermostat_heyes.c */
extern const pl_thermostat_t pl_thermostat_rescale; /* src/fluid/thermostat_rescale.c */
#define ROW(row, name) &row,
static const pl_thermostat_t *const rows[] = {PL_THERMOSTATS(ROW)};

_Static_assert(PL_THERMO_NONE == 0, "row 0 is none");

const pl_thermostat_t *pl_thermostat(int type)
{
    const int n = (int)(sizeof rows / sizeof rows[0]);
    return type >= 0 && type < n ? rows[type] : NULL;
}

int pl_sim_add_collide_stage(pl_sim_t *sim, const pl_stage_t *plain, const pl_stage_t *in_collision, pl_err_t *err)
{
    if (!pl_thermostat(sim->scene.thermostat.type)->in_collision) return pl_sim_add_stage(sim, plain, err);
    const long long k = sim->scene.thermostat.interval;
    pl_stage_t p = *plain, h = *in_collision;
    p.interval = 1;
    p.except = k;
    h.interval = k;
    int rc = k > 1 ? pl_sim_add_stage(sim, &p, err) : 0;
    return rc ? rc : pl_sim_add_stage(sim, &h, err);
}
