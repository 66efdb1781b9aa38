/* What the couplings see of the colloids and where: the view of the colloid
 * arrays the coupling kernels take, and the colloid lookup on unit cells
 * built from such a view (pl_coupling_lookup_t: couplings I and potential
 * each hold one in their state, with their own radii).  The bottom of the
 * coupling modules (coupling.c, coupling_potential.c, coupling_stages.c use
 * it; it uses none of them). */
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

int pl_coupling_lookup_init(pl_coupling_lookup_t *lk, const int L[3], int nthreads, pl_err_t *err)
{
    size_t L3 = (size_t)L[0] * (size_t)L[1] * (size_t)L[2];
    *lk = (pl_coupling_lookup_t){.start = pl_alloc((L3 + 1) * sizeof(int32_t), nthreads)};
    if (!lk->start) return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the colloid lookup");
    return 0;
}

void pl_coupling_lookup_free(pl_coupling_lookup_t *lk)
{
    pl_free(lk->start);
    pl_free(lk->list);
    *lk = (pl_coupling_lookup_t){0};
}

/* Builds the colloid lookup for the colloids seen through `v`, growing the
 * list until it holds every entry; 0 or PL_ERR_NOMEM. */
int pl_coupling_lookup_fill(pl_coupling_lookup_t *lk, const pl_sim_t *sim, const pl_coupling_colloids_t *v,
                            pl_err_t *err)
{
    for (;;) {
        size_t need = pl_coupling_lookup_build(v, sim->grid.L, sim->grid.walls, lk->start, lk->list, lk->cap);
        if (need <= lk->cap) return 0;
        pl_free(lk->list);
        lk->cap = need + need / 2 + 64;
        if (!(lk->list = pl_alloc(lk->cap * sizeof(int32_t), sim->nthreads)))
            return pl_err_set(err, PL_ERR_NOMEM, "out of memory for the colloid lookup");
    }
}

/* Lookup of the colloids with their own radii. */
int pl_coupling_lookup_update(pl_coupling_lookup_t *lk, const pl_sim_t *sim, pl_err_t *err)
{
    pl_coupling_colloids_t v = pl_coupling_view(sim->colloids);
    return pl_coupling_lookup_fill(lk, sim, &v, err);
}
