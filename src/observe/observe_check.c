/* What the observers check beyond one key's range, where it needs the
 * colloids themselves or an estimate of the work: the cluster search's bond
 * range against the largest radius and the box (at `check` and when a run
 * creates its observers, before any output), and the terms of one S(q)
 * sample (at load, O(1)). */
#include <math.h>
#include <stdio.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/observe_check.h"

#define OFFO(m) offsetof(pl_scene_t, observe.m)

/* The most terms (wave vector x colloid) one S(q) sample may sum: about 10 s
 * of one core. */
#define PL_SQ_MAX_TERMS 1e10

pl_cluster_params_t pl_observe_cluster_params(const pl_scene_t *sc, const pl_colloid_t *c)
{
    pl_cluster_params_t p = {.gap = sc->observe.clusters_gap, .nmax = c->n};
    for (int d = 0; d < 3; ++d) {
        p.box[d] = c->box[d];
        p.periodic[d] = c->periodic[d];
    }
    for (size_t i = 0; i < c->n; ++i) p.rad_max = fmax(p.rad_max, c->rad[i]);
    if (sc->observe.clusters_bond == PL_BOND_ENERGY) /* candidates: every pair within the pair cut-off */
        p.gap = pl_colloid_pair_cutoff(&c->pair, p.rad_max) - 2.0 * p.rad_max;
    return p;
}

int pl_observe_check_colloids(const pl_scene_t *sc, const pl_colloid_t *c, pl_err_t *err)
{
    if (sc->observe.clusters_interval <= 0 || !c) return 0;
    pl_cluster_params_t p = pl_observe_cluster_params(sc, c);
    pl_cluster_t *cl = NULL;
    int rc = pl_cluster_create(&p, &cl, err);
    pl_cluster_free(cl);
    if (rc != PL_ERR_INPUT) return rc;
    char why[sizeof err->msg];
    snprintf(why, sizeof why, "%s", err->msg);
    if (sc->observe.clusters_bond == PL_BOND_ENERGY)
        return pl_scene_fail(sc, err, OFFO(clusters_bond), "observe.clusters_bond",
                             "\"energy\": bonds within the pair cut-off: %s; allowed: \"gap\", or a box whose "
                             "periodic edges exceed twice the cut-off", why);
    return pl_scene_fail(sc, err, OFFO(clusters_gap), "observe.clusters_gap",
                         "%g: %s; allowed: -2 R_max < clusters_gap <= L/2 - 2 R_max on every periodic axis "
                         "(R_max = %g, the largest colloid radius)",
                         sc->observe.clusters_gap, why, p.rad_max);
}

int pl_observe_sq_cost_check(const pl_scene_t *sc, pl_err_t *err)
{
    const pl_scene_observe_t *o = &sc->observe;
    const double qmax = o->sq_qmax > 0 ? o->sq_qmax : 4.0 * PL_PI / sc->colloids.radius;
    double nvec = 2.0 * PL_PI / 3.0; /* the half ball |q| < qmax: (1/2) (4 pi / 3) prod_d (qmax L_d / 2 pi) */
    for (int d = 0; d < 3; ++d) nvec *= qmax * sc->box.cells[d] / (2.0 * PL_PI);
    const double terms = nvec * (double)sc->colloids.count;
    if (terms <= PL_SQ_MAX_TERMS) return 0;
    return pl_scene_fail(sc, err, OFFO(sq_qmax), "observe.sq_qmax",
                         "%g%s: S(q) sums over %.3g wave vectors x %lld colloids = %.3g terms per sample; "
                         "allowed: <= %.0e terms per sample (a smaller sq_qmax, box or colloid count)",
                         qmax, o->sq_qmax > 0 ? "" : " (the default 4 pi / colloids.radius)", nvec,
                         sc->colloids.count, terms, PL_SQ_MAX_TERMS);
}
