/* Coupling object: its common part (method, threads, seed, the compensating
 * fluid acceleration of Hecht Sec. VIII.A iii, the pinned colloids' impulse),
 * the state of the method in use (built and freed by that method's row,
 * peloid/coupling_row.h), the initial removal
 * of fluid from colloid interiors (couplings I and potential), and the
 * cross-key checks of the coupling section.  The pinned impulse is common
 * because every method's stages add to it and the thermo columns and the
 * checkpoint read it whatever the method; the colloid lookup is not: each of
 * the two methods that use one keeps its own, with its own radii. */
#include <stdlib.h>
#include <string.h>

#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/coupling_row.h"
#include "peloid/sim.h"
#include "peloid/colloid_integrator.h"



#define OFF(m) offsetof(pl_scene_t, m)

int pl_coupling_validate_scene(const pl_scene_t *scene, pl_err_t *err)
{
    const pl_scene_coupling_t *cs = &scene->coupling;
    if (cs->method == PL_COUPLE_NONE) return 0;
    if (scene->colloids.count == 0 || scene->fluid.density <= 0.0)
        return pl_scene_fail(scene, err, OFF(coupling.method), "coupling.method",
                             "a coupling needs colloids (colloids.count > 0) and fluid "
                             "(fluid.density > 0); allowed without them: \"none\"");
    if (!cs->pinned && pl_vec3_nonzero(cs->flow_velocity))
        return pl_scene_fail(scene, err, OFF(coupling.flow_velocity), "coupling.flow_velocity",
                             "a held flow velocity needs coupling.pinned = true");
    const double *sp = cs->pinned_spin;
    if (pl_vec3_nonzero(sp) && (!cs->pinned || cs->method != PL_COUPLE_HECHT1))
        return pl_scene_fail(scene, err, OFF(coupling.pinned_spin), "coupling.pinned_spin",
                             "[%g, %g, %g] needs coupling.pinned = true and coupling.method = \"hecht1\" "
                             "(the only coupling whose surface carries the colloid's rotation to the fluid); "
                             "allowed otherwise: [0, 0, 0]", sp[0], sp[1], sp[2]);
    if (!pl_colloid_integrator(scene->colloids.integrator)->inertial)
        return pl_scene_fail(scene, err, OFF(coupling.method), "coupling.method",
                             "colloids.integrator = \"brownian\" already stands for the solvent; "
                             "a coupling needs \"verlet\"");
    const pl_coupling_row_t *row = pl_coupling_row(cs->method);
    return row && row->validate ? row->validate(scene, err) : 0;
}

/* Couplings I and potential start without fluid inside colloids (radius R,
 * or sigma_cf when rad is given): such particles get a new uniform position
 * (draws keyed by particle index: thread independent). */
void pl_coupling_clear_interiors_of(const pl_coupling_t *cp, pl_sim_t *sim, const pl_coupling_lookup_t *lk,
                                    const double *rad)
{
    pl_coupling_colloids_t v = pl_coupling_view(sim->colloids);
    if (rad) v.rad = rad;
    pl_coupling_clear_interiors(&sim->fluid, &v, sim->grid.L, sim->grid.walls, lk->start, lk->list, cp->seed,
                                cp->nthreads);
}

int pl_coupling_moves_colloids(const pl_scene_t *scene, size_t n_fluid)
{
    const pl_scene_coupling_t *c = &scene->coupling;
    const pl_coupling_row_t *row = pl_coupling_row(c->method);
    return n_fluid > 0 && row && (c->pinned || row->moves_colloids);
}

int pl_coupling_create(pl_sim_t *sim, pl_coupling_t **out, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    pl_colloid_t *col = sim->colloids;
    *out = NULL;
    pl_coupling_t *cp = calloc(1, sizeof *cp);
    if (!cp) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    cp->method = sc->coupling.method;
    cp->nthreads = sim->nthreads;
    cp->seed = (uint64_t)sc->run.seed;
    size_t nc = col ? col->n : 0;
    /* Hecht Sec. VIII.A (iii): the fluid carries minus the colloids' weight;
     * only in a periodic box (walls take up momentum: options i and ii) */
    if (col && cp->method != PL_COUPLE_NONE && sc->coupling.compensate_gravity && !sim->grid.any_walls && sim->fluid.n > 0) {
        double M = 0.0;
        for (size_t k = 0; k < nc; ++k) M += col->mass[k];
        for (int d = 0; d < 3; ++d) cp->fluid_accel[d] = -sc->colloids.gravity[d] * M / (double)sim->fluid.n;
        memcpy(sim->fluid_accel, cp->fluid_accel, sizeof sim->fluid_accel); /* the streaming's */
    }
    /* coupled colloids exchange energy with the fluid: no NVE drift guard */
    if (cp->method != PL_COUPLE_NONE) pl_colloid_exchange_energy(sim->colloids);
    cp->pinned = cp->method != PL_COUPLE_NONE && sc->coupling.pinned;
    if (cp->pinned) { /* held fixed from the start, turning at the held spin */
        memcpy(cp->spin, sc->coupling.pinned_spin, sizeof cp->spin);
        for (size_t k = 0; k < nc; ++k) {
            col->vx[k] = col->vy[k] = col->vz[k] = 0.0;
            col->wx[k] = cp->spin[0];
            col->wy[k] = cp->spin[1];
            col->wz[k] = cp->spin[2];
        }
    }
    const pl_coupling_row_t *row = pl_coupling_row(cp->method);
    int rc = row ? row->create(cp, sim, err) : 0;
    if (rc) {
        pl_coupling_free(cp);
        if (rc == PL_ERR_NOMEM && !err->code) return pl_err_set(err, rc, "out of memory for the coupling");
        return rc;
    }
    *out = cp;
    return 0;
}

void pl_coupling_free(pl_coupling_t *cp)
{
    if (!cp) return;
    const pl_coupling_row_t *row = pl_coupling_row(cp->method);
    if (row) row->free(cp);
    free(cp);
}
