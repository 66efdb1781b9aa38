/* Adaptive MD substeps (colloids.adaptive_substeps; the rule in
 * peloid/colloid_reach.h): the reach table, built once, and the choice
 * of each collision step's MD steps from the state at its start.
 *
 * The contact guard asks pi sqrt(m_red / U'') >= min_contact_steps dt_MD for
 * every pair at every MD step (Hecht Sec. II: ~20 MD steps per collision).
 * The fixed substeps of a physical{} scene meet it for the stiffest gap any
 * pair could reach with coarse_graining.reach_energy (40 kT); this meets it
 * for the stiffest gap the pairs present can reach in this collision step:
 *   - a pair within the cut-off: its energy U(h) + m_red v_n^2 / 2 (closing)
 *     + colloids.adaptive_margin, through the reach table;
 *   - a pair beyond it: within one collision step its gap shrinks by at most
 *     2 v_max srd.dt (the forces beyond the cut-off are nil, the colloids'
 *     accelerations small over dt), so it meets the curvature outward of
 *     gap_cut - 2 v_max srd.dt at most.
 * Between the collision steps the fluid changes the velocities (coupling);
 * within one the MD is the colloids' own, conservative in the pair terms.
 * A contact that comes within 25 % of the guard's bound anyway (energy from
 * a third colloid or a wall beyond the margin) finishes the collision step
 * at the finest MD step (src/colloid/colloid_step.c); the guard still checks
 * every MD step, so a choice that fell short stops the run (exit 3), never
 * passes silently.
 * The choice is a function of the positions and velocities at the step's
 * start (exact maxima, pairs within the cut-off), so it is the same at any
 * thread count and recomputed bitwise after a restart (no state of its own). */
#include <math.h>
#include <stdlib.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/colloid.h"
#include "peloid/colloid_reach.h"
#include "peloid/colloid_integrator.h"

#define OFF(member) offsetof(pl_scene_t, colloids.member)

enum { REACH_NODES = 100000 };

static int build_table(pl_colloid_reach_t *t, const pl_colloid_pair_params_t *p, double d, double max_overlap)
{
    double hlo = -max_overlap * d, hhi = fmax(p->gap_cut, 0.0);
    t->d = d;
    t->hcut = hhi;
    t->nk = REACH_NODES;
    t->dh = (hhi - hlo) / (double)REACH_NODES;
    t->ereq = malloc((REACH_NODES + 1) * sizeof(double));
    t->k2 = malloc((REACH_NODES + 1) * sizeof(double));
    t->u = malloc((REACH_NODES + 2) * sizeof(double));
    if (!t->ereq || !t->k2 || !t->u) return -1;
    double em = -INFINITY, km = 0.0;
    for (int k = 0; k <= REACH_NODES; ++k) {
        pl_pair_val_t v = pl_colloid_contact_val(p, d, hhi - (double)k * t->dh);
        if (v.u > em) em = v.u;
        if (v.k2 > km) km = v.k2;
        t->ereq[k] = em;
        t->k2[k] = km;
        t->u[k] = v.u;
    }
    t->u[REACH_NODES + 1] = t->u[REACH_NODES];
    return 0;
}

void pl_colloid_adaptive_free(pl_colloid_t *c)
{
    free(c->reach.ereq);
    free(c->reach.k2);
    free(c->reach.u);
    c->reach.ereq = c->reach.k2 = c->reach.u = NULL;
}

int pl_colloid_adaptive_setup(pl_colloid_t *c, const pl_scene_t *scene, pl_err_t *err)
{
    const pl_scene_colloids_t *cs = &scene->colloids;
    pl_colloid_adaptive_free(c); /* a set-up again (restart) builds the table anew */
    c->adaptive = 0;
    c->dt_coll = scene->srd.dt;
    c->sub_min = (int)cs->substeps;
    if (!cs->adaptive_substeps) return 0;
    const size_t K = OFF(adaptive_substeps);
    if (!pl_colloid_integrator(c->integrator)->inertial)
        return pl_scene_fail(scene, err, K, "colloids.adaptive_substeps",
                             "true needs colloids.integrator = \"verlet\" (the contact guard's MD); allowed here: false");
    if (cs->polydispersity != 0.0)
        return pl_scene_fail(scene, err, K, "colloids.adaptive_substeps",
                             "true needs equal colloids (the reach table is one pair diameter); "
                             "colloids.polydispersity = %g; allowed here: false", cs->polydispersity);
    if (cs->min_substeps > cs->substeps)
        return pl_scene_fail(scene, err, OFF(min_substeps), "colloids.min_substeps",
                             "%lld is more than colloids.substeps = %lld; allowed: 1 .. %lld",
                             cs->min_substeps, cs->substeps, cs->substeps);
    /* under multiple time stepping a count that is not a multiple of
     * slow_interval cuts the last outer step (src/colloid/colloid_md.c) */
    const long long lo = cs->min_substeps;
    c->sub_min = (int)(lo < cs->substeps ? lo : cs->substeps);
    c->adapt_margin = cs->adaptive_margin;
    if (build_table(&c->reach, &c->pair, 2.0 * cs->radius, cs->max_overlap))
        return pl_err_set(err, PL_ERR_NOMEM, "colloids: out of memory for the adaptive substeps' reach table");
    double mmin = INFINITY;
    for (size_t i = 0; i < c->n; ++i) mmin = fmin(mmin, c->mass[i]);
    c->adapt_mred = 0.5 * mmin;
    c->adapt_lo = c->substeps;
    c->adapt_worst = c->adapt_last = INFINITY;
    c->adaptive = 1;
    return 0;
}

/* The curvature met by a pair of total energy e: k2 at the first node whose
 * ereq exceeds e (the most of the table when none does). */
static double k2_of_energy(const pl_colloid_reach_t *t, double e)
{
    if (!(e < t->ereq[t->nk])) return t->k2[t->nk];
    int lo = 0, hi = t->nk; /* ereq[hi] > e */
    if (t->ereq[0] > e) return t->k2[0];
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (t->ereq[mid] > e) hi = mid;
        else lo = mid;
    }
    return t->k2[hi];
}

int pl_colloid_adaptive_choose(const pl_colloid_t *c, double em, double v2)
{
    const pl_colloid_reach_t *t = &c->reach;
    double k2 = k2_of_energy(t, em);
    double hfar = t->hcut - 2.0 * sqrt(v2) * c->dt_coll, qf = (t->hcut - hfar) / t->dh;
    double kf = !(qf < (double)t->nk) ? t->k2[t->nk] : t->k2[(int)qf + 1];
    if (kf > k2) k2 = kf;
    long long n = c->sub_min;
    if (c->min_contact_steps > 0.0 && k2 > 0.0) {
        double need = ceil(1.05 * c->min_contact_steps * c->dt_coll * sqrt(k2 / c->adapt_mred) / PL_PI);
        if (!(need <= (double)c->substeps)) need = (double)c->substeps;
        if ((long long)need > n) n = (long long)need;
    }
    if (n > c->substeps) n = c->substeps;
    return (int)n;
}

int pl_colloid_adaptive_substeps(pl_colloid_t *c)
{
    double em, v2;
    pl_colloid_reach_energy(&c->pair, &c->nlist, &c->reach, c->adapt_margin, c->x, c->y, c->z, c->vx, c->vy,
                            c->vz, c->mass, &em, &v2, c->nthreads);
    const int n = pl_colloid_adaptive_choose(c, em, v2);
    c->adapt_steps++;
    c->adapt_md += n;
    if (n < c->adapt_lo) c->adapt_lo = n;
    if (n > c->adapt_hi) c->adapt_hi = n;
    return n;
}
