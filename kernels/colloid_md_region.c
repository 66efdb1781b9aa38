/* The MD substeps of one collision step in one parallel region (issue 38):
 * the team is forked once and the MD steps run inside it, their passes
 * separated by barriers instead of a fork/join each (kernels/colloid_verlet.h
 * has the passes and their formulas).  Per MD step:
 *
 *   open    static loop over blocks: half kick, drift, rotations, max
 *           displacement (reduction; barrier B1)
 *   list    every thread takes the same decision from the reduced maximum;
 *           a rebuild runs its serial parts (cells, prefix sums, the slot
 *           reservation of the caller, reverse entries) in single and its
 *           scans as static loops
 *   close   pair pass 1 (barrier B2), under multiple time stepping at the end
 *           of an outer step the slow pass 1 (a barrier), then per colloid
 *           pass 2, external forces, half kick and the guard maxima
 *           (reduction; barrier B3)
 *   end, next  every thread on its own copy of the caller's control
 *           state: the step's counters, then the next step's time step and
 *           slow kicks, or the end; between them a single only when the
 *           caller asks for a serial check (a guard's bound exceeded, the
 *           energy drift due)
 *
 * so 3 barriers per MD step (4 at the end of an outer step of multiple time
 * stepping) and one fork/join per call.  With adaptive substeps the region
 * first computes the maxima of their choice (pl_colloid_reach_owner, a
 * reduction and its barrier), from which every thread chooses the MD steps.
 * The reductions' shared targets are reset by the master between barriers
 * that every reader has passed: the guard maxima after B1 (all threads
 * ended the step before from them), the displacement after B2 (all decided
 * from it before it).
 *
 * Determinism: every colloid's operations are those of the separate passes
 * in the same order; the only reductions are maxima (exact); the list is
 * built by the same loops as pl_colloid_nlist_count / _fill; every thread
 * decides from the same values.  So the state is bitwise that of the per-pass
 * regions, for any thread count. */
#include <math.h>

#include "colloid_bd.h"
#include "colloid_verlet.h"
#include "peloid/colloid_reach.h"

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

/* The end of a step in every thread: its counters; when the guards are to
 * report or the energy drift is due, the check by one thread (its single's
 * barrier ends it for all).  1: stop with *rc (shared), which is not 0. */
static int step_end(const pl_colloid_md_hooks_t *hk, pl_colloid_md_ctl_t *k, const pl_colloid_guard_max_t *gm,
                    int *rc)
{
    if (!(hk->end(hk->ctx, k, gm) & PL_MD_CHECK)) return 0;
#pragma omp single
    *rc = hk->check(hk->ctx, k, gm);
    return *rc != 0;
}

int pl_colloid_md_region(const pl_colloid_md_region_t *r, const pl_colloid_md_hooks_t *hk,
                         pl_colloid_md_ctl_t *ctl)
{
    const size_t n = r->s.n, nblk = (n + PL_COLLOID_ROT_BLOCK - 1) / PL_COLLOID_ROT_BLOCK;
    /* shared by the team: the reductions' targets, the status, the control
     * state going out */
    double dmax = 0.0, em = -INFINITY, vm = 0.0;
    pl_colloid_guard_max_t gm = {0.0, 0.0, 0.0, 0};
    int rc = 0;
    pl_colloid_md_ctl_t out = *ctl;
#pragma omp parallel num_threads(r->nthreads) if (n >= PL_COLLOID_OMP_MIN)
    {
        /* each thread's own copies of the arrays and parameters (kept in
         * registers across the loops' stores; read through the shared
         * descriptor they were reloaded per colloid) and of the control */
        const pl_colloid_dyn_t s = r->s;
        const pl_colloid_view_t v = *r->v, vs = pl_colloid_slow_view(n, s.fsx, s.fsy, s.fsz);
        const pl_colloid_ext_params_t ext = *r->ext;
        /* the pair parameters: each thread's copy, whose lubrication noise
         * (lubrication.thermal) the MD step sets: one random force per time
         * level, drawn at the positions after the step (counter md_step + 1)
         * with the amplitude sqrt(2 kT / dt) of its dt (src/colloid/
         * colloid_state.c, lub_noise_set: the same for the forces of a
         * restart or a collision step's start) */
        pl_colloid_pair_params_t pp = *r->p;
        const pl_colloid_pair_params_t *const p = &pp;
        const int noisy = pp.lub_thermal && (pp.terms & PL_CT_LUB);
        pl_colloid_nlist_t *const full = r->full;
        const pl_colloid_nlist_t *const pairs = r->near ? r->near : full;
        double *const epot = r->epot;
        const double rf = pow(2.0, 1.0 / ext.wall_n);
        const int torques = pl_colloid_pair_torques(p);
        pl_colloid_md_ctl_t k = *ctl;
        pl_colloid_md_sub_t sub;
        if (r->reach) { /* adaptive substeps: the maxima their choice needs */
#pragma omp for schedule(static) reduction(max : em, vm)
            for (size_t i = 0; i < n; ++i)
                pl_colloid_reach_owner(p, full, r->reach, r->reach_margin, s.x, s.y, s.z, s.vx, s.vy, s.vz,
                                       s.mass, i, &em, &vm);
            k.reach_e = em;
            k.reach_v2 = vm;
        }
        int run = hk->next(hk->ctx, &k, 0, &sub);
        while (run & PL_MD_RUN) {
#pragma omp for schedule(static) reduction(max : dmax)
            for (size_t bk = 0; bk < nblk; ++bk)
                pl_colloid_verlet_open_block(&s, bk, sub.dt, sub.open_h, full, &dmax);
            if (pl_colloid_nlist_stale(full, dmax) && rebuild(r, hk, &rc)) break;
#pragma omp master
            gm = (pl_colloid_guard_max_t){0.0, 0.0, 0.0, 0};
            if (noisy) {
                pp.noise_step = (uint64_t)(k.md_step + 1);
                pp.lub_noise = sqrt(2.0 * pp.lub_kT / sub.dt);
            }
            pl_colloid_pair_owner_pass(p, pairs, &v);
#pragma omp master
            dmax = 0.0;
            if (sub.close_h != 0.0)
                pl_colloid_slow_owner_pass(p, full, s.x, s.y, s.z, s.rad, s.fsx, s.fsy, s.fsz);
#pragma omp for schedule(static) reduction(pl_guard_max : gm)
            for (size_t i = 0; i < n; ++i)
                pl_colloid_verlet_close_one(&s, i, sub.dt, sub.close_h, pairs, full, &v, &vs, torques,
                                            &ext, rf, epot, &gm);
            if (step_end(hk, &k, &gm, &rc)) break;
            run = hk->next(hk->ctx, &k, 1, &sub);
        }
#pragma omp master
        out = k;
    }
    *ctl = out;
    return rc;
}

/* The Brownian steps of one collision step in one parallel region, as the
 * velocity-Verlet ones above and with the same hooks: per step the move of
 * every colloid (pl_colloid_bd_one: with the forces of the step's start,
 * noise counter md_step) and its displacement since the list build
 * (barrier), the list rebuilt when that asks, pair pass 1 (barrier), then per
 * colloid pass 2, unwrapped z, external forces and the guard's tests and
 * maxima (barrier): the operations of the separate passes it replaced (the
 * Brownian step, pl_colloid_forces, the guard's scan; bitwise their state,
 * the regression hashes of 4c626c3 unchanged), colloid by colloid in the same order (lubrication's
 * noise at the step's counter md_step, as pl_colloid_forces draws it before
 * the step's count goes up), so the state is bitwise theirs, for any thread
 * count.  bd: kT, eta, seed (its dt and step are set per step). */
int pl_colloid_bd_region(const pl_colloid_md_region_t *r, const pl_colloid_md_hooks_t *hk,
                         const pl_colloid_bd_params_t *bd, pl_colloid_md_ctl_t *ctl)
{
    const size_t n = r->s.n;
    double dmax = 0.0;
    pl_colloid_guard_max_t gm = {0.0, 0.0, 0.0, 0};
    int rc = 0;
    pl_colloid_md_ctl_t out = *ctl;
#pragma omp parallel num_threads(r->nthreads) if (n >= PL_COLLOID_OMP_MIN)
    {
        const pl_colloid_dyn_t s = r->s;
        const pl_colloid_view_t v = *r->v;
        const pl_colloid_ext_params_t ext = *r->ext;
        pl_colloid_pair_params_t pp = *r->p;
        const pl_colloid_pair_params_t *const p = &pp;
        const int noisy = pp.lub_thermal && (pp.terms & PL_CT_LUB);
        pl_colloid_nlist_t *const full = r->full;
        double *const epot = r->epot;
        const double rf = pow(2.0, 1.0 / ext.wall_n);
        const int torques = pl_colloid_pair_torques(p);
        pl_colloid_md_ctl_t k = *ctl;
        pl_colloid_md_sub_t sub;
        int run = hk->next(hk->ctx, &k, 0, &sub);
        while (run & PL_MD_RUN) {
            pl_colloid_bd_params_t b = *bd;
            b.dt = sub.dt;
            b.step = (uint64_t)k.md_step;
#pragma omp for schedule(static) reduction(max : dmax)
            for (size_t i = 0; i < n; ++i) {
                pl_colloid_bd_one(&b, i, s.box, s.periodic, s.rad, s.x, s.y, s.z, s.ix, s.iy, s.iz, s.fx, s.fy,
                                  s.fz, s.tx, s.ty, s.tz, s.vx, s.vy, s.vz, s.wx, s.wy, s.wz, s.q0, s.q1, s.q2,
                                  s.q3);
                double d2 = pl_colloid_nlist_disp2(full, s.box, s.periodic, s.x, s.y, s.z, i);
                if (!(d2 <= dmax)) dmax = isnan(d2) ? INFINITY : d2;
            }
            if (pl_colloid_nlist_stale(full, dmax) && rebuild(r, hk, &rc)) break;
#pragma omp master
            gm = (pl_colloid_guard_max_t){0.0, 0.0, 0.0, 0};
            if (noisy) {
                pp.noise_step = (uint64_t)k.md_step;
                pp.lub_noise = sqrt(2.0 * pp.lub_kT / sub.dt);
            }
            pl_colloid_pair_owner_pass(p, full, &v);
#pragma omp master
            dmax = 0.0;
#pragma omp for schedule(static) reduction(pl_guard_max : gm)
            for (size_t i = 0; i < n; ++i) {
                pl_colloid_forces_close_one(&s, i, full, &v, torques, &ext, rf, epot);
                pl_colloid_guard_one(&s, i, &v, &gm);
            }
            if (step_end(hk, &k, &gm, &rc)) break;
            run = hk->next(hk->ctx, &k, 1, &sub);
        }
#pragma omp master
        out = k;
    }
    *ctl = out;
    return rc;
}

