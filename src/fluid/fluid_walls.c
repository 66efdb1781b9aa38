/* Walls of the SRD fluid (Hecht Sec. VIII; PL Eq. 13): the virtual wall
 * particles' density and temperature, the impulse the walls exchange with
 * the fluid (and colloids) since step 0, and the wall stress from it.  Used
 * by the fluid's stages and by the couplings. */
#include <math.h>

#include "peloid/sim.h"

void pl_sim_wall_add(pl_sim_t *sim, const int64_t acc[PL_WALL_ACC_N])
{
    for (int k = 0; k < PL_WALL_ACC_N; ++k) {
        if (acc[k] == PL_WALL_ACC_OVERFLOW) { /* the fluid guard stops the run */
            sim->wall_acc_overflow = 1;
            continue;
        }
        sim->wall_impulse[k / 3][k % 3] += ldexp((double)acc[k], -PL_FIELD_FIXED_SHIFT);
    }
}

void pl_sim_wall_add_momentum(pl_sim_t *sim, const double dp[PL_WALL_ACC_N])
{
    for (int k = 0; k < PL_WALL_ACC_N; ++k) sim->wall_impulse[k / 3][k % 3] += dp[k];
}

int pl_sim_wall_ghosts(const pl_sim_t *sim, double *density, double *kT_wall)
{
    const pl_scene_t *sc = &sim->scene;
    *density = sc->fluid.density;
    *kT_wall = pl_scene_kT(sc);
    return sc->box.walls_z == PL_WALLS_NOSLIP || sc->box.walls_xy == PL_WALLS_NOSLIP;
}

double pl_sim_wall_stress(const pl_sim_t *sim, int wall, int d)
{
    const int *L = sim->grid.L;
    const double t = (double)sim->step * sim->scene.srd.dt;
    if (!(t > 0.0)) return 0.0;
    if (wall == 2) /* the x/y walls: force the fluid exerts on them per area */
        return -sim->wall_impulse[2][d] / (2.0 * ((double)L[0] + L[1]) * L[2] * t);
    return (wall ? 1.0 : -1.0) * sim->wall_impulse[wall][d] / ((double)L[0] * L[1] * t);
}
