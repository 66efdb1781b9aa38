/* The decisions of the velocity-Verlet MD steps of one collision step,
 * taken inside the one parallel region that runs them
 * (kernels/colloid_md_region.c).  end and next, by every thread on its own
 * copy of the control state (so it reads of c only what stays fixed during the
 * region): after each MD step its counter, the adaptive substeps' record of
 * the closest call, whether a guard's bound is exceeded or the energy drift
 * is due, and, with adaptive substeps, the switch to the finest MD step for
 * the rest of the collision step (the rule: src/colloid/colloid_step.c);
 * before each, the time step and the slow kicks of multiple time stepping.
 * check, by one thread: the guards' report (src/colloid/colloid_guard.c).
 * reserve, by one thread: the neighbour list's slots at a rebuild. */
#include <math.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/colloid.h"
#include "peloid/colloid_reach.h"

typedef struct {
    pl_colloid_t *c;
    pl_err_t *err;
    int choose; /* adaptive substeps: the MD steps chosen in the region */
} md_run_t;

/* The next MD step's time step and slow kicks: the slow kicks of len dt / 2
 * open the first and close the last MD step of each outer step of len =
 * slow_interval MD steps, or of the MD steps left when fewer are (with
 * adaptive substeps the collision step's count need not be a multiple of
 * slow_interval: its last outer step is cut to what is left, so outer steps
 * end with the collision step); slow_phase counts the MD steps of the
 * outer step, reset by pl_colloid_advance at each collision step. */
static void step_params(const pl_colloid_t *c, pl_colloid_md_ctl_t *k, pl_colloid_md_sub_t *sub)
{
    const int si = c->slow_interval;
    if (si > 1 && k->slow_phase == 0) k->slow_len = k->todo < si ? k->todo : si;
    const int len = si > 1 ? k->slow_len : 1, phase = si > 1 ? k->slow_phase : 0;
    if (si > 1) k->slow_phase = (phase + 1) % len;
    const double slow_h = 0.5 * (double)len * k->dt;
    sub->dt = k->dt;
    sub->open_h = si > 1 && phase == 0 ? slow_h : 0.0;
    sub->close_h = si > 1 && phase == len - 1 ? slow_h : 0.0;
}

/* The end of an MD step: PL_MD_CHECK when the guards are to report or the
 * energy drift is due. */
static int end(const void *ctx, pl_colloid_md_ctl_t *k, const pl_colloid_guard_max_t *g)
{
    const pl_colloid_t *c = ((const md_run_t *)ctx)->c;
    k->md_step++;
    if (c->adaptive) { /* this step's and the run's closest call */
        const double steps = g->omega2 > 0.0 ? PL_PI / sqrt(g->omega2) / k->dt : INFINITY;
        k->adapt_last = steps;
        if (!(steps >= k->adapt_worst)) k->adapt_worst = steps;
    }
    k->check_e = c->nve && c->max_energy_drift > 0.0 && k->md_step % c->guard_interval == 0;
    k->todo--;
    return k->check_e || pl_colloid_guard_trips(c, k->dt, g) ? PL_MD_CHECK : 0;
}

/* The next MD step, after the end of one (done: 1) when the guards passed:
 * with adaptive substeps the switch to the finest MD step; PL_MD_RUN with
 * its parameters, or 0 when the steps are done. */
static int next(const void *ctx, pl_colloid_md_ctl_t *k, int done, pl_colloid_md_sub_t *sub)
{
    const md_run_t *m = ctx;
    const pl_colloid_t *c = m->c;
    if (!done && m->choose) { /* adaptive substeps: this collision step's MD steps */
        const int n = pl_colloid_adaptive_choose(c, k->reach_e, k->reach_v2);
        k->adapt_steps++;
        k->adapt_md += n;
        if (n < k->adapt_lo) k->adapt_lo = n;
        if (n > k->adapt_hi) k->adapt_hi = n;
        k->dt = c->dt_coll / (double)n;
        k->n = k->todo = n;
        /* one time step: the rest may run at the finest MD step (under
         * multiple time stepping the outer steps keep their length) */
        k->refine = c->slow_interval <= 1 && n < c->substeps;
    }
    if (done && k->refine && k->todo > 0 && k->adapt_last < PL_ADAPT_REFINE * c->min_contact_steps) {
        const int left = k->todo, n = k->n;
        const int steps = (int)(((long long)left * c->substeps + n - 1) / n);
        k->dt = c->dt_coll * ((double)left / (double)n) / (double)steps;
        k->adapt_refined++;
        k->adapt_md += steps - left;
        k->todo = steps;
        k->refine = 0;
    }
    if (k->todo <= 0) return 0;
    step_params(c, k, sub);
    return PL_MD_RUN;
}

/* The guards on the state of the step just done (c->md_step theirs, as
 * the messages name it). */
static int check(void *ctx, const pl_colloid_md_ctl_t *k, const pl_colloid_guard_max_t *g)
{
    md_run_t *m = ctx;
    m->c->md_step = k->md_step;
    return pl_colloid_guard_max(m->c, g, k->check_e, m->err) ? -1 : 0;
}

static int reserve(void *ctx, pl_colloid_nlist_t *nl, size_t need)
{
    md_run_t *m = ctx;
    return pl_colloid_nlist_reserve(nl, need, m->err) ? -1 : 0;
}

/* The velocity-Verlet (or, brownian, the Brownian) steps of one call: n,
 * or with adaptive substeps (n = 0) the count chosen in the region. */
static int run_region(pl_colloid_t *c, int n, int brownian, pl_err_t *err)
{
    md_run_t m = {c, err, n == 0};
    pl_colloid_md_ctl_t k = {.md_step = c->md_step, .adapt_md = c->adapt_md,
                             .adapt_refined = c->adapt_refined, .adapt_steps = c->adapt_steps,
                             .adapt_lo = c->adapt_lo, .adapt_hi = c->adapt_hi, .dt = c->dt,
                             .adapt_last = c->adapt_last, .adapt_worst = c->adapt_worst,
                             .slow_phase = c->slow_phase, .n = n, .todo = n, .refine = 0};
    pl_colloid_md_region_t r;
    pl_colloid_view_t v;
    pl_colloid_md_region_of(c, &r, &v);
    if (m.choose) {
        r.reach = &c->reach;
        r.reach_margin = c->adapt_margin;
    }
    const pl_colloid_md_hooks_t hk = {&m, end, next, check, reserve};
    const pl_colloid_bd_params_t bd = {c->dt, c->kT, c->bd_eta, c->seed, 0};
    const int rc = brownian ? pl_colloid_bd_region(&r, &hk, &bd, &k) : pl_colloid_md_region(&r, &hk, &k);
    c->md_step = k.md_step;
    c->adapt_md = k.adapt_md;
    c->adapt_refined = k.adapt_refined;
    c->adapt_steps = k.adapt_steps;
    c->adapt_lo = k.adapt_lo;
    c->adapt_hi = k.adapt_hi;
    c->dt = k.dt;
    c->adapt_last = k.adapt_last;
    c->adapt_worst = k.adapt_worst;
    c->slow_phase = k.slow_phase;
    return rc ? err->code : 0;
}

int pl_colloid_verlet_run(pl_colloid_t *c, int n, pl_err_t *err) { return run_region(c, n, 0, err); }

int pl_colloid_bd_run(pl_colloid_t *c, int n, pl_err_t *err) { return run_region(c, n, 1, err); }

