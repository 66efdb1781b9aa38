/* The serial decisions of the velocity-Verlet MD steps of one collision
 * step, taken inside the one parallel region that runs them
 * (kernels/colloid_md_region.c, by one thread between barriers): after
 * each MD step its counter, the adaptive substeps' record of the closest
 * call, the guards (src/colloid/colloid_guard.c) and, with adaptive
 * substeps, the switch to the finest MD step for the rest of the collision
 * step (the rule: src/colloid/colloid_step.c); before each, the time step
 * and the slow kicks of multiple time stepping; and the neighbour list's
 * slot reservation at a rebuild. */
#include <math.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/colloid.h"

typedef struct {
    pl_colloid_t *c;
    pl_err_t *err;
    int n;      /* the MD steps the run started with (the refinement's base) */
    int todo;   /* MD steps still to run */
    int refine; /* may still switch to the finest MD step */
} md_run_t;

/* The next MD step's time step and slow kicks: the slow kicks of k dt / 2
 * open the first and close the last MD step of each outer step of k;
 * slow_phase counts the MD steps of the outer step, reset by
 * pl_colloid_advance at each collision step (k divides the substeps, so
 * outer steps end with it). */
static void step_params(pl_colloid_t *c, pl_colloid_md_sub_t *sub)
{
    const int k = c->slow_interval;
    const int phase = k > 1 ? c->slow_phase : 0;
    if (k > 1) c->slow_phase = (phase + 1) % k;
    const double slow_h = 0.5 * (double)k * c->dt;
    sub->dt = c->dt;
    sub->open_h = k > 1 && phase == 0 ? slow_h : 0.0;
    sub->close_h = k > 1 && phase == k - 1 ? slow_h : 0.0;
}

static int step_end(md_run_t *m, const pl_colloid_guard_max_t *g)
{
    pl_colloid_t *c = m->c;
    c->md_step++;
    if (c->adaptive) { /* this step's and the run's closest call */
        const double steps = g->omega2 > 0.0 ? PL_PI / sqrt(g->omega2) / c->dt : INFINITY;
        c->adapt_last = steps;
        if (!(steps >= c->adapt_worst)) c->adapt_worst = steps;
    }
    const int check_e = c->nve && c->max_energy_drift > 0.0 && c->md_step % c->guard_interval == 0;
    if (pl_colloid_guard_max(c, g, check_e, m->err)) return -1;
    m->todo--;
    if (m->refine && m->todo > 0 && c->adapt_last < PL_ADAPT_REFINE * c->min_contact_steps) {
        const int left = m->todo, n = m->n;
        const int steps = (int)(((long long)left * c->substeps + n - 1) / n);
        c->dt = c->dt_coll * ((double)left / (double)n) / (double)steps;
        c->adapt_refined++;
        c->adapt_md += steps - left;
        m->todo = steps;
        m->refine = 0;
    }
    return 0;
}

static int next(void *ctx, const pl_colloid_guard_max_t *g, pl_colloid_md_sub_t *sub)
{
    md_run_t *m = ctx;
    if (g && step_end(m, g)) return -1;
    if (m->todo <= 0) return 0;
    step_params(m->c, sub);
    return 1;
}

static int reserve(void *ctx, pl_colloid_nlist_t *nl, size_t need)
{
    md_run_t *m = ctx;
    return pl_colloid_nlist_reserve(nl, need, m->err) ? -1 : 0;
}

int pl_colloid_verlet_run(pl_colloid_t *c, int n, int refine, pl_err_t *err)
{
    md_run_t m = {c, err, n, n, refine};
    pl_colloid_md_region_t r;
    pl_colloid_view_t v;
    pl_colloid_md_region_of(c, &r, &v);
    const pl_colloid_md_hooks_t hk = {&m, next, reserve};
    return pl_colloid_md_region(&r, &hk) ? err->code : 0;
}
