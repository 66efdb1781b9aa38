/* Pair parameters from the scene: unit conversion of Hecht Eqs. 1-2, the fit
 * of the parabolic primary minimum (Hecht Sec. II), and the DLVO cut-off
 * chosen from the potential's own decay with the truncation error reported. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/colloid.h"
#include "peloid/colloid_pair_terms.h"
#include "peloid/depletion.h"
#include "peloid/colloid_integrator.h"

static const double E_CHARGE = 1.602176634e-19, K_B = 1.380649e-23, EPS0 = 8.8541878128e-12;

/* the name and bit of each row of the pair-term table (colloid_kernels.h) */
static const struct { const char *name; unsigned bit; } names[] = {
#define NAME_(ID, id, name, slot, kind) {name, PL_CT_##ID},
    PL_PAIR_TERMS(NAME_)
#undef NAME_
};

void pl_colloid_pair_names(char *buf, size_t n)
{
    size_t used = 0;
    buf[0] = '\0';
    for (size_t k = 0; k < sizeof names / sizeof names[0] && used < n; ++k)
        used += (size_t)snprintf(buf + used, n - used, "%s%s", k ? ", " : "", names[k].name);
}

int pl_colloid_parse_pairs(const char *list, unsigned *mask, char *bad, size_t nbad)
{
    *mask = 0;
    const char *s = list;
    while (*s) {
        while (*s == ' ' || *s == ',' || *s == '\t') ++s;
        if (!*s) break;
        size_t len = strcspn(s, ", \t");
        int found = 0;
        for (size_t k = 0; k < sizeof names / sizeof names[0]; ++k)
            if (strlen(names[k].name) == len && !strncmp(s, names[k].name, len)) {
                *mask |= names[k].bit;
                found = 1;
            }
        if (!found) {
            snprintf(bad, nbad, "%.*s", (int)(len < 100 ? len : 100), s);
            return PL_ERR_INPUT;
        }
        s += len;
    }
    return 0;
}

/* Raw DLVO (Eqs. 1-2) as a function of the gap, and the matching function of
 * the parabola: f(h) = V(h) + D - V'(h) (h - h0) / 2, zero where the parabola
 * with minimum -D at h0 touches V with equal slope. */
static double v_of(const pl_colloid_pair_params_t *p, double d, double h)
{
    return pl_pair_dlvo_raw(d + h, d, p->coul_C, p->kappa, p->hamaker).u;
}

static double match_f(const pl_colloid_pair_params_t *p, double d, double h, double D, double h0)
{
    pl_pair_val_t v = pl_pair_dlvo_raw(d + h, d, p->coul_C, p->kappa, p->hamaker);
    return v.u + D + v.f * (h - h0) / 2.0;
}

int pl_colloid_dlvo_setup(const pl_scene_dlvo_t *s, double d, pl_colloid_pair_params_t *p,
                          pl_colloid_dlvo_info_t *info, pl_err_t *err)
{
    double kT = K_B * s->temperature_K, a0 = s->length_unit_m;
    double ze = s->z * E_CHARGE;
    double psi = 4.0 * kT / ze * tanh(ze * s->psi0_mV * 1e-3 / (4.0 * kT));
    p->coul_C = PL_PI * s->eps_r * EPS0 * psi * psi * a0 / kT; /* Hecht Eq. 1, kT per a0 */
    p->kappa = s->kappa_per_m * a0;
    p->hamaker = s->hamaker_J / kT; /* Hecht Eq. 2, kT */
    double D = s->primary_depth, h0 = s->primary_gap;
    memset(info, 0, sizeof *info);
    info->C = p->coul_C;
    info->kappa = p->kappa;
    info->A = p->hamaker;
    info->d_ref = d;
    info->h0 = h0;
    info->fail_off = offsetof(pl_scene_t, colloids.dlvo.primary_depth);
    info->fail_key = "dlvo.primary_depth";
    /* match gap: first sign change of f from - to + on a fine grid above h0 */
    double hmax = fmax(60.0 / p->kappa, 5.0 * d);
    int ng = 200000;
    double hprev = h0 + 1e-9 * d, fprev = match_f(p, d, hprev, D, h0), hm = NAN;
    if (!(fprev < 0.0))
        return pl_err_set(err, PL_ERR_INPUT,
                          "dlvo: the DLVO potential at primary_gap %g a0 is %.3g kT, not below "
                          "-primary_depth = %g kT; no parabolic primary minimum can join it; "
                          "lower dlvo.primary_gap or dlvo.primary_depth",
                          h0, v_of(p, d, hprev), -D);
    for (int k = 1; k <= ng && isnan(hm); ++k) {
        double h = h0 + hmax * pow((double)k / ng, 3.0);
        double f = match_f(p, d, h, D, h0);
        if (f >= 0.0) {
            double lo = hprev, hi = h;
            for (int it = 0; it < 200; ++it) {
                double mid = 0.5 * (lo + hi);
                if (match_f(p, d, mid, D, h0) < 0.0) lo = mid;
                else hi = mid;
            }
            hm = 0.5 * (lo + hi);
        }
        hprev = h;
    }
    if (isnan(hm))
        return pl_err_set(err, PL_ERR_INPUT, "dlvo: no match gap for the primary minimum found "
                                             "below %g a0; check dlvo.kappa and dlvo.primary_depth", hmax);
    pl_pair_val_t vm = pl_pair_dlvo_raw(d + hm, d, p->coul_C, p->kappa, p->hamaker);
    p->prim_hm = hm;
    p->prim_h0 = h0;
    p->prim_d = d;
    p->prim_mu = vm.u;
    p->prim_vp = -vm.f;
    p->prim_c = pl_pair_parabola_curvature(p->prim_vp, hm, h0);
    info->hm = hm;
    info->curvature = p->prim_c;
    /* cut-off: beyond the last gap where |V| >= cutoff_energy */
    double tol = s->cutoff_energy, hc = NAN;
    for (int k = ng; k >= 0; --k) {
        double h = hm + (hmax - hm) * (double)k / ng;
        if (fabs(v_of(p, d, h)) >= tol) {
            if (k == ng) {
                info->fail_off = offsetof(pl_scene_t, colloids.dlvo.cutoff_energy);
                info->fail_key = "dlvo.cutoff_energy";
                return pl_err_set(err, PL_ERR_INPUT,
                                  "dlvo: |V| is still %.3g kT at gap %g a0 (the largest gap scanned) "
                                  "with dlvo.cutoff_energy = %g kT; allowed: a "
                                  "cutoff_energy above %.3g kT",
                                  fabs(v_of(p, d, h)), h, tol, fabs(v_of(p, d, h)));
            }
            double lo = h, hi = hm + (hmax - hm) * (double)(k + 1) / ng;
            for (int it = 0; it < 200; ++it) {
                double mid = 0.5 * (lo + hi);
                if (fabs(v_of(p, d, mid)) >= tol) lo = mid;
                else hi = mid;
            }
            hc = hi;
            break;
        }
    }
    if (isnan(hc)) hc = hm; /* |V| < tol everywhere outside the primary minimum */
    pl_pair_val_t vc = pl_pair_dlvo_raw(d + hc, d, p->coul_C, p->kappa, p->hamaker);
    p->dlvo_hcut = hc;
    /* Eq. 1 is below eps in energy and force for gaps beyond coul_hcut:
     * |U| <= C d e^{-kappa h}, |F| <= C d (1/d + kappa) e^{-kappa h} for
     * r >= d, taken at twice the reference diameter (polydisperse pairs) */
    const double eps = 1e-15, dh = 2.0 * d;
    double cb = p->coul_C * dh * fmax(1.0, 1.0 / dh + p->kappa);
    p->coul_hcut = fmax(hm, cb > eps ? log(cb / eps) / p->kappa : 0.0);
    p->dlvo_shift = vc.u;
    info->hcut = hc;
    info->trunc_u = fabs(vc.u);
    info->trunc_f = fabs(vc.f);
    /* barrier and secondary minimum between hm and hc (sign changes of F) */
    info->barrier_h = info->barrier_u = info->secmin_h = info->secmin_u = NAN;
    double fl = pl_pair_dlvo_raw(d + hm, d, p->coul_C, p->kappa, p->hamaker).f, hl = hm;
    for (int k = 1; k <= ng; ++k) {
        double h = hm + (hc - hm) * (double)k / ng;
        double f = pl_pair_dlvo_raw(d + h, d, p->coul_C, p->kappa, p->hamaker).f;
        if ((fl < 0.0) != (f < 0.0)) {
            double lo = hl, hi = h;
            for (int it = 0; it < 200; ++it) {
                double mid = 0.5 * (lo + hi);
                double fm = pl_pair_dlvo_raw(d + mid, d, p->coul_C, p->kappa, p->hamaker).f;
                if ((fm < 0.0) == (fl < 0.0)) lo = mid;
                else hi = mid;
            }
            double hx = 0.5 * (lo + hi), ux = v_of(p, d, hx);
            if (fl < 0.0 && isnan(info->barrier_h)) { /* F: attractive -> repulsive going in */
                info->barrier_h = hx;
                info->barrier_u = ux;
            } else if (fl >= 0.0 && isnan(info->secmin_h)) {
                info->secmin_h = hx;
                info->secmin_u = ux;
            }
        }
        fl = f;
        hl = h;
    }
    return 0;
}

int pl_colloid_pair_params(const pl_scene_t *scene, pl_colloid_pair_params_t *p,
                           pl_colloid_dlvo_info_t *info, pl_err_t *err)
{
    const pl_scene_colloids_t *cs = &scene->colloids;
    memset(p, 0, sizeof *p);
    memset(info, 0, sizeof *info);
    char bad[128], all[256];
    if (pl_colloid_parse_pairs(cs->pairs, &p->terms, bad, sizeof bad)) {
        pl_colloid_pair_names(all, sizeof all);
        return pl_scene_fail(scene, err, offsetof(pl_scene_t, colloids.pairs), "colloids.pairs",
                             "unknown pair term \"%s\"; allowed: %s", bad, all);
    }
    for (int k = 0; k < 3; ++k) p->box[k] = scene->box.cells[k];
    int walls[3];
    pl_scene_box_walls(&scene->box, walls);
    for (int k = 0; k < 3; ++k) p->periodic[k] = walls[k] == PL_WALLS_NONE;
    p->gap_cut = 0.0;
#define SETUP_(ID, id, name, slot, kind) \
    if (pl_colloid_term_setup_##id(scene, p, info, err)) return err->code;
    PL_PAIR_TERMS(SETUP_)
#undef SETUP_
    return 0;
}

/* The rows' set-ups (pl_colloid_term_setup_*, colloid.h). */
int pl_colloid_term_setup_dlvo(const pl_scene_t *scene, pl_colloid_pair_params_t *p,
                               pl_colloid_dlvo_info_t *info, pl_err_t *err)
{
    if (!(p->terms & PL_CT_DLVO)) return 0;
    if (pl_colloid_dlvo_setup(&scene->colloids.dlvo, 2.0 * scene->colloids.radius, p, info, err)) return err->code;
    info->fail_key = NULL; /* set: a later row's failure is not the DLVO set-up's */
    p->gap_cut = fmax(p->gap_cut, p->dlvo_hcut);
    return 0;
}

int pl_colloid_term_setup_hertz(const pl_scene_t *scene, pl_colloid_pair_params_t *p,
                                pl_colloid_dlvo_info_t *info, pl_err_t *err)
{
    (void)info;
    (void)err;
    p->hertz_K = scene->colloids.hertz.K;
    p->hertz_beta = scene->colloids.hertz.beta;
    p->hertz_gamma_t = scene->colloids.hertz.gamma_t;
    return 0;
}

int pl_colloid_term_setup_lub(const pl_scene_t *scene, pl_colloid_pair_params_t *p,
                              pl_colloid_dlvo_info_t *info, pl_err_t *err)
{
    (void)info;
    (void)err;
    if (!(p->terms & PL_CT_LUB)) return 0;
    p->lub_eta = scene->colloids.lub.viscosity;
    p->lub_hmin = scene->colloids.lub.min_gap;
    p->lub_hcut = scene->colloids.lub.cutoff_gap;
    /* the random partner: only where velocities are integrated (the
     * Brownian integrator has its own noise); lub_noise is set per force
     * pass (pl_colloid_lub_noise) */
    p->lub_thermal = scene->colloids.lub.thermal && pl_colloid_integrator(scene->colloids.integrator)->inertial;
    p->lub_kT = scene->colloids.temperature;
    p->gap_cut = fmax(p->gap_cut, p->lub_hcut);
    return 0;
}

/* sigma_cc also without the wca term: the depletion report reads it */
int pl_colloid_term_setup_wca(const pl_scene_t *scene, pl_colloid_pair_params_t *p,
                              pl_colloid_dlvo_info_t *info, pl_err_t *err)
{
    (void)info;
    (void)err;
    const pl_scene_colloids_t *cs = &scene->colloids;
    p->wca_eps = cs->wca.epsilon;
    p->wca_sigma = cs->wca.sigma;
    p->wca_n = cs->wca.n;
    p->wca_rfac = pow(2.0, 1.0 / cs->wca.n);
    if (cs->wca.sigma_rule == PL_SIGMA_PL) { /* PL Sec. III.C.1 */
        pl_depletion_params_t dp;
        pl_colloid_depletion_params(scene, &dp);
        p->wca_sigma = pl_depletion_sigma_cc(2.0 * pl_depletion_cf_cutoff(&dp), cs->wca.epsilon, cs->wca.n,
                                             PL_DEPLETION_RULE_ENERGY * dp.kT);
    }
    return 0;
}

/* the range only: the table is built by pl_colloid_setup (colloid_pair_setup.c) */
int pl_colloid_term_setup_depl(const pl_scene_t *scene, pl_colloid_pair_params_t *p,
                               pl_colloid_dlvo_info_t *info, pl_err_t *err)
{
    (void)info;
    (void)err;
    if (!(p->terms & PL_CT_DEPL)) return 0;
    pl_depletion_params_t dp;
    pl_colloid_depletion_params(scene, &dp);
    p->dep_rc = 2.0 * pl_depletion_cf_cutoff(&dp); /* where Phi_depl vanishes */
    return 0;
}

void pl_colloid_depletion_params(const pl_scene_t *scene, pl_depletion_params_t *dp)
{
    const pl_scene_coupling_t *cp = &scene->coupling;
    dp->sigma_cf = cp->sigma_cf > 0.0 ? cp->sigma_cf : scene->colloids.radius;
    dp->epsilon_cf = cp->epsilon_cf;
    dp->n = 6.0; /* PL Eq. 17 */
    dp->hard_sphere = 0;
    dp->density = scene->fluid.density;
    dp->kT = pl_scene_kT(scene);
}

double pl_colloid_pair_cutoff(const pl_colloid_pair_params_t *p, double rmax)
{
    return pl_colloid_pair_rc(p, p->terms, 2.0 * rmax);
}
