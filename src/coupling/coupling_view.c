/* What the couplings see of the colloids and where: the view of the colloid
 * arrays the coupling kernels take, and the colloid lookup on unit cells
 * built from such a view.  The bottom of the coupling modules (coupling.c,
 * coupling_potential.c, coupling_stages.c use it; it uses none of them). */
#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/sim.h"

pl_coupling_colloids_t pl_coupling_view(const pl_colloid_t *c)
{
    pl_coupling_colloids_t v = {.n = c->n, .x = c->x, .y = c->y, .z = c->z, .vx = c->vx, .vy = c->vy,
                                .vz = c->vz, .wx = c->wx, .wy = c->wy, .wz = c->wz, .rad = c->rad,
                                .mass = c->mass, .inertia = c->inertia};
    return v;
}

/* Builds the colloid lookup for the colloids seen through `v`, growing the
 * list until it holds every entry; 0 or PL_ERR_NOMEM. */
int pl_coupling_lookup_fill(pl_coupling_t *cp, const pl_sim_t *sim, const pl_coupling_colloids_t *v,
                            pl_err_t *err)
{
    for (;;) {
        size_t need = pl_coupling_lookup_build(v, sim->grid.L, sim->grid.walls, cp->lk_start,
                                               cp->lk_list, cp->lk_cap);
        if (need <= cp->lk_cap) return 0;
        pl_free(cp->lk_list);
        cp->lk_cap = need + need / 2 + 64;
        if (!(cp->lk_list = pl_alloc(cp->lk_cap * sizeof(int32_t), cp->nthreads)))
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the colloid lookup");
    }
}
