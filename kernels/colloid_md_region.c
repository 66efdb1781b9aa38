/* The MD substeps of one collision step in one parallel region (issue 38):
 * the team is forked once and the MD steps run inside it, their passes
 * separated by barriers instead of a fork/join each (kernels/colloid_verlet.h
 * has the passes and their formulas).  Per MD step:
 *
 *   open    static loop over blocks: half kick, drift, rotations, max
 *           displacement (reduction; its barrier)
 *   list    every thread takes the same decision from the reduced maximum;
 *           a rebuild runs its serial parts (cells, prefix sums, the slot
 *           reservation of the caller, reverse entries) in single and its
 *           scans as static loops
 *   close   pair pass 1 (barrier), under multiple time stepping the slow
 *           pass 1 (barrier), then per colloid pass 2, external forces,
 *           half kick and the guard maxima (reduction; its barrier)
 *   next    single: the caller's serial step end (guards, counters, the next
 *           step's time step and slow kicks, or the end; barrier)
 *
 * so 4 barriers per MD step (5 at the end of an outer step of multiple time
 * stepping), and one fork/join per call.  The serial decisions are the
 * caller's (pl_colloid_md_hooks_t: src/colloid/colloid_md.c), taken by one
 * thread while the others wait; shared values they write are read by the
 * team only after the barrier that follows.
 *
 * Determinism: every colloid's operations are those of the separate passes
 * in the same order; the only reductions are maxima (exact); the list is
 * built by the same loops as pl_colloid_nlist_count / _fill.  So the state
 * is bitwise that of the per-pass regions, for any thread count. */
#include <math.h>

#include "colloid_verlet.h"

/* The neighbour list rebuilt inside the region (every thread calls it):
 * cells, counts, prefix sum and reservation, fill, reverse entries; under
 * multiple time stepping then the near list the same way.  Returns the
 * reservation's status (the same in every thread). */
static int rebuild(const pl_colloid_md_region_t *r, const pl_colloid_md_hooks_t *hk, int *rc)
{
    const pl_colloid_dyn_t *s = &r->s;
    pl_colloid_nlist_t *const lists[2] = {r->full, r->near};
    for (int k = 0; k < (r->near ? 2 : 1); ++k) {
        pl_colloid_nlist_t *nl = lists[k];
        if (k == 0) {
#pragma omp single
            pl_colloid_cells_build(r->cells, s->n, s->x, s->y, s->z);
            pl_colloid_nlist_count_loop(nl, r->cells, s->box, s->periodic, s->x, s->y, s->z);
        } else {
            pl_colloid_nlist_near_count_loop(nl, r->full, r->p, s->x, s->y, s->z, s->rad);
        }
#pragma omp single
        {
            for (size_t i = 0; i < s->n; ++i) nl->start[i + 1] += nl->start[i];
            *rc = hk->reserve(hk->ctx, nl, (size_t)nl->start[s->n]);
        }
        if (*rc) return *rc;
        if (k == 0) pl_colloid_nlist_fill_loop(nl, r->cells, s->box, s->periodic, s->x, s->y, s->z);
        else pl_colloid_nlist_near_fill_loop(nl, r->full, r->p, s->x, s->y, s->z, s->rad);
#pragma omp single
        {
            if (k == 1) nl->skin = r->full->skin;
            pl_colloid_nlist_finish(nl, r->nthreads);
        }
    }
    return 0;
}

int pl_colloid_md_region(const pl_colloid_md_region_t *r, const pl_colloid_md_hooks_t *hk)
{
    const size_t n = r->s.n, nblk = (n + PL_COLLOID_ROT_BLOCK - 1) / PL_COLLOID_ROT_BLOCK;
    /* shared by the team: the step's parameters and the reductions (reset
     * by the single that ends the step before), the status */
    pl_colloid_md_sub_t sub;
    double dmax = 0.0;
    pl_colloid_guard_max_t gm = {0.0, 0.0, 0.0, 0};
    int go = hk->next(hk->ctx, NULL, &sub), rc = 0;
    if (go <= 0) return go;
#pragma omp parallel num_threads(r->nthreads) if (n >= PL_COLLOID_OMP_MIN)
    {
        /* each thread's own copies of the arrays and parameters (kept in
         * registers across the loops' stores; read through the shared
         * descriptor they were reloaded per colloid) */
        const pl_colloid_dyn_t s = r->s;
        const pl_colloid_view_t v = *r->v, vs = pl_colloid_slow_view(n, s.fsx, s.fsy, s.fsz);
        const pl_colloid_ext_params_t ext = *r->ext;
        const pl_colloid_pair_params_t *const p = r->p;
        pl_colloid_nlist_t *const full = r->full;
        const pl_colloid_nlist_t *const pairs = r->near ? r->near : full;
        double *const epot = r->epot;
        const double rf = pow(2.0, 1.0 / ext.wall_n);
        const int torques = pl_colloid_pair_torques(p);
        for (;;) {
            const double dt = sub.dt, open_h = sub.open_h, close_h = sub.close_h;
#pragma omp for schedule(static) reduction(max : dmax)
            for (size_t bk = 0; bk < nblk; ++bk) pl_colloid_verlet_open_block(&s, bk, dt, open_h, full, &dmax);
            if (pl_colloid_nlist_stale(full, dmax) && rebuild(r, hk, &rc)) break;
            pl_colloid_pair_owner_pass(p, pairs, &v);
            if (close_h != 0.0)
                pl_colloid_slow_owner_pass(p, full, s.x, s.y, s.z, s.rad, s.fsx, s.fsy, s.fsz);
#pragma omp for schedule(static) reduction(pl_guard_max : gm)
            for (size_t i = 0; i < n; ++i)
                pl_colloid_verlet_close_one(&s, i, dt, close_h, pairs, full, &v, &vs, torques, &ext, rf, epot,
                                            &gm);
#pragma omp single
            {
                go = hk->next(hk->ctx, &gm, &sub);
                dmax = 0.0;
                gm = (pl_colloid_guard_max_t){0.0, 0.0, 0.0, 0};
            }
            if (go <= 0) break;
        }
    }
    return rc ? rc : go;
}
