/* Coupling and wall part of the checkpoint: the run counters that thermo.tsv
 * reports as sums since step 0, so that a restarted run writes the same rows
 * as an uninterrupted one:
 *   - /wall_impulse (walls): momentum each z wall gave the fluid (wall
 *     stress), bottom xyz, top xyz; /side_wall_impulse: the x/y walls';
 *   - /coupling/counters: coupling I reflections and truncations, the
 *     potential coupling's selected particle-steps (each in its method's
 *     state; 0 in the file, and not read back, for the other methods);
 *   - /coupling/pinned: impulse (momentum, angular momentum) the pinned
 *     colloids received, and the time it was summed over (drag).
 * Not stored, because every step rebuilds it before use: the colloid lookups,
 * coupling II's colloid binning and saved velocities, the potential
 * coupling's near list, its forces and epot_cf (recomputed at the start of
 * each MD stage), and fluid_accel (from the scene's masses). */
#include <math.h>

#include "checkpoint_h5.h"
#include "peloid/checkpoint.h"
#include "peloid/coupling.h"
#include "peloid/sim.h"

int pl_ckpt_coupling_write(hid_t f, const pl_sim_t *sim, const pl_coupling_t *cp)
{
    int bad = 0;
    if (pl_srd_walls_measured(sim->srd)) {
        bad |= pl_ckpt_write_1d(f, "wall_impulse", H5T_NATIVE_DOUBLE, &sim->wall_impulse[0][0], 6);
        bad |= pl_ckpt_write_1d(f, "side_wall_impulse", H5T_NATIVE_DOUBLE, &sim->wall_impulse[2][0], 3);
    }
    if (!cp) return bad ? -1 : 0;
    hid_t g = pl_ckpt_group_create(f, "coupling");
    if (g < 0) return -1;
    const unsigned long long cnt[3] = {cp->c1 ? cp->c1->events : 0, cp->c1 ? cp->c1->truncations : 0,
                                       cp->pot ? cp->pot->near_total : 0};
    double pin[7];
    for (int k = 0; k < 6; ++k) pin[k] = cp->impulse[k];
    pin[6] = cp->pinned_time;
    bad |= pl_ckpt_write_1d(g, "counters", H5T_NATIVE_ULLONG, cnt, 3);
    bad |= pl_ckpt_write_1d(g, "pinned", H5T_NATIVE_DOUBLE, pin, 7);
    if (H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
}

int pl_ckpt_coupling_read(hid_t f, pl_sim_t *sim, pl_coupling_t *cp, const char *path, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    if (sc->box.walls_z != PL_WALLS_NONE && H5Lexists(f, "wall_impulse", H5P_DEFAULT) <= 0)
        return pl_err_set(err, PL_ERR_INPUT, "%s: checkpoint has no wall_impulse (the scene has z walls)", path);
    if (sc->box.walls_z != PL_WALLS_NONE &&
        pl_ckpt_read_1d(f, "wall_impulse", H5T_NATIVE_DOUBLE, &sim->wall_impulse[0][0], 6, path, err))
        return err->code;
    if (sc->box.walls_xy != PL_WALLS_NONE && H5Lexists(f, "side_wall_impulse", H5P_DEFAULT) <= 0)
        return pl_err_set(err, PL_ERR_INPUT,
                          "%s: checkpoint has no side_wall_impulse (the scene has x/y walls; a checkpoint from "
                          "before peloid counted their momentum cannot continue it)",
                          path);
    if (sc->box.walls_xy != PL_WALLS_NONE &&
        pl_ckpt_read_1d(f, "side_wall_impulse", H5T_NATIVE_DOUBLE, &sim->wall_impulse[2][0], 3, path, err))
        return err->code;
    for (int k = 0; k < 9; ++k)
        if (!isfinite(sim->wall_impulse[k / 3][k % 3]))
            return pl_err_set(err, PL_ERR_INPUT, "%s: wall impulse %d is not finite (corrupt checkpoint)", path, k);
    if (!cp) return 0;
    hid_t g = H5Lexists(f, "coupling", H5P_DEFAULT) > 0 ? H5Gopen2(f, "coupling", H5P_DEFAULT) : -1;
    if (g < 0) return pl_err_set(err, PL_ERR_INPUT, "%s: checkpoint has no /coupling group (the scene has a coupling)", path);
    unsigned long long cnt[3];
    double pin[7];
    int rc = pl_ckpt_read_1d(g, "counters", H5T_NATIVE_ULLONG, cnt, 3, path, err);
    if (!rc) rc = pl_ckpt_read_1d(g, "pinned", H5T_NATIVE_DOUBLE, pin, 7, path, err);
    H5Gclose(g);
    if (rc) return rc;
    for (int k = 0; k < 7; ++k)
        if (!isfinite(pin[k]) || (k == 6 && pin[k] < 0.0))
            return pl_err_set(err, PL_ERR_INPUT, "%s: /coupling/pinned[%d] = %g is out of range (corrupt checkpoint)",
                              path, k, pin[k]);
    if (cp->c1) {
        cp->c1->events = cnt[0];
        cp->c1->truncations = cnt[1];
    }
    if (cp->pot) cp->pot->near_total = cnt[2];
    for (int k = 0; k < 6; ++k) cp->impulse[k] = pin[k];
    cp->pinned_time = pin[6];
    return 0;
}
