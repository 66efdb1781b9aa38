/* The colloids' pair terms that the scene sets up on a colloid state (parts
 * of pl_colloid_setup, src/colloid/colloid_state.c): sigma_cc and the
 * spurious depletion it leaves, with the table of the depletion
 * compensation (PL Sec. III.C.1), and the force split of multiple time
 * stepping (r-RESPA) with the stiffness its slow share may have. */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/colloid.h"
#include "peloid/colloid_pair.h"
#include "peloid/colloid_integrator.h"

#define OFF(m) offsetof(pl_scene_t, m)

/* sigma_cc and the spurious depletion it leaves (PL Sec. III.C.1); with
 * depletion_comp the table of Phi_comp = -Phi_depl for the force kernel. */
int pl_colloid_depletion_setup(pl_colloid_t *c, const pl_scene_t *scene, pl_err_t *err)
{
    const pl_scene_wca_t *w = &scene->colloids.wca;
    pl_colloid_depl_info_t *in = &c->depl;
    pl_depletion_params_t dp;
    pl_colloid_depletion_params(scene, &dp);
    memset(in, 0, sizeof *in);
    in->rule = w->sigma_rule;
    in->sigma_cc = c->pair.wca_sigma;
    in->d_match = 2.0 * pl_depletion_cf_cutoff(&dp);
    double sg = in->sigma_cc > 0 ? in->sigma_cc : 2.0 * scene->colloids.radius;
    in->phi_match = in->d_match < sg * c->pair.wca_rfac ? pl_pair_wca(in->d_match, sg, w->epsilon, w->n).u : 0.0;
    double dphi;
    if (scene->coupling.method == PL_COUPLE_POTENTIAL && dp.density > 0.0 &&
        pl_depletion_potential(&dp, sg, &in->phi_sigma, &dphi, err))
        return err->code;
    free(c->dep_table);
    c->dep_table = NULL;
    if (!(c->pair.terms & PL_CT_DEPL)) return 0;
    int m = PL_COLLOID_DEPL_TABLE;
    /* m + 2 nodes: the last, zero, is read when r rounds to the cut-off */
    if (!(c->dep_table = calloc(2 * (size_t)(m + 2), sizeof(double))))
        return pl_err_set(err, PL_ERR_NOMEM, "colloids: out of memory (depletion table)");
    if (pl_depletion_table(&dp, m, c->dep_table, c->dep_table + m + 2, err)) return err->code;
    in->table_n = m;
    c->pair.dep_u = c->dep_table;
    c->pair.dep_du = c->dep_table + m + 2;
    c->pair.dep_inv_h = m / in->d_match;
    return 0;
}

double pl_colloid_slow_stiffness(const pl_colloid_pair_params_t *p, double d, double hin, double *h_at)
{
    enum { NS = 4000 };
    const double hc = p->dlvo_hcut, hout = pl_pair_slow_hout(hin);
    double kmax = 0.0;
    for (int q = 0; q <= NS && hc > hin; ++q) {
        /* denser near hin, where the force is largest */
        double t = (double)q / NS, h = hin + (hc - hin) * t * t, eps = 1e-6 * (hout - hin);
        double f[2];
        for (int b = 0; b < 2; ++b) {
            double r = d + h + (b ? eps : -eps);
            f[b] = pl_pair_slow_share(r * r, d, hin, hout) * pl_pair_dlvo_raw(r, d, p->coul_C, p->kappa, p->hamaker).f;
        }
        double kk = fabs(f[1] - f[0]) / (2.0 * eps);
        if (kk > kmax) {
            kmax = kk;
            *h_at = h;
        }
    }
    return kmax;
}

/* Multiple time stepping (colloids.slow_interval = k > 1, r-RESPA): checks
 * what it needs, sets the force split of the pair parameters.  Refused where the slow share itself is too
 * stiff for the outer step: its largest |dF_slow/dr| over the pair diameters
 * of the run gives a collision time pi sqrt(m_red / k) that must span
 * colloids.min_contact_steps outer steps (the contact guard's rule applied
 * to the outer step).  The near list and the slow forces are allocated by
 * pl_colloid_setup. */
int pl_colloid_mts_setup(pl_colloid_t *c, const pl_scene_t *scene, pl_err_t *err)
{
    const pl_scene_colloids_t *cs = &scene->colloids;
    const long long k = cs->slow_interval;
    c->slow_interval = (int)k;
    c->pair.mts = 0;
    if (k <= 1) return 0;
    const size_t K = OFF(colloids.slow_interval);
    if (!pl_colloid_integrator(c->integrator)->inertial)
        return pl_scene_fail(scene, err, K, "colloids.slow_interval",
                             "%lld: multiple time stepping needs colloids.integrator = \"verlet\"; allowed here: 1 (off)", k);
    if (scene->coupling.method == PL_COUPLE_POTENTIAL)
        return pl_scene_fail(scene, err, K, "colloids.slow_interval",
                             "%lld: the potential coupling integrates the colloids with the fluid forces "
                             "itself; multiple time stepping needs coupling.method none, hecht1 or hecht2; "
                             "allowed here: 1 (off)", k);
    if (!(c->pair.terms & PL_CT_DLVO))
        return pl_scene_fail(scene, err, K, "colloids.slow_interval",
                             "%lld: the slow share is the DLVO force, and colloids.pairs has no dlvo; allowed here: 1 (off)", k);
    if (cs->substeps % k != 0)
        return pl_scene_fail(scene, err, K, "colloids.slow_interval",
                             "%lld does not divide colloids.substeps = %lld (an outer step must end with "
                             "the collision step); allowed: 1 or a divisor of the substeps", k, cs->substeps);
    const double hin = cs->slow_gap, hout = pl_pair_slow_hout(hin);
    if (!(hin > c->pair.prim_hm))
        return pl_scene_fail(scene, err, OFF(colloids.slow_gap), "colloids.slow_gap",
                             "%g a0 is not beyond the primary minimum's match gap %.4g a0 (the slow share "
                             "is Hecht Eqs. 1-2 alone); allowed: > %.4g", hin, c->pair.prim_hm, c->pair.prim_hm);
    c->pair.mts = 1;
    c->pair.mts_hin = hin;
    c->pair.mts_hout = hout;
    double rmin = INFINITY, rmax = 0.0, mmin = INFINITY;
    for (size_t i = 0; i < c->n; ++i) {
        rmin = fmin(rmin, c->rad[i]);
        rmax = fmax(rmax, c->rad[i]);
        mmin = fmin(mmin, c->mass[i]);
    }
    double kmax = 0.0, h_at = hin;
    const double ds[3] = {2.0 * rmin, rmin + rmax, 2.0 * rmax};
    for (int a = 0; a < (c->n ? 3 : 0); ++a) {
        double h = hin, kk = pl_colloid_slow_stiffness(&c->pair, ds[a], hin, &h);
        if (kk > kmax) {
            kmax = kk;
            h_at = h;
        }
    }
    const double outer = (double)k * c->dt;
    if (c->min_contact_steps > 0.0 && kmax > 0.0 && mmin > 0.0) {
        double tc = PL_PI * sqrt(0.5 * mmin / kmax), steps = tc / outer;
        if (steps < c->min_contact_steps) {
            long long kok = (long long)floor(tc / (c->min_contact_steps * c->dt));
            return pl_scene_fail(scene, err, K, "colloids.slow_interval",
                                 "%lld: the slow DLVO share (stiffness up to %.4g kT/a0^2 at gap %.4g a0) "
                                 "would last %.3g outer steps of %lld MD steps, fewer than "
                                 "colloids.min_contact_steps = %g; allowed: <= %lld here (or raise "
                                 "colloids.slow_gap)", k, kmax, h_at, steps, k, c->min_contact_steps,
                                 kok < 1 ? 1 : kok);
        }
    }
    return 0;
}
