/* Scene front end, second half: physical{} + coarse_graining{} -> the colloid
 * sections in model units (a0, m_f, t0, kT_real = 1), so that a scene in
 * physical units is the whole truth (DESIGN.md "Units and mapping"):
 *   colloids.count        phi V_box / (4/3 pi R^3), V of the box used
 *   colloids.radius       R / a0
 *   colloids.mass_density gamma rho_p / rho_f (rho_f = gamma m_f / a0^3, Hecht Sec. VII.B)
 *   colloids.gravity      g_model t0^2 / a0 (Hecht Eq. 31, weight minus buoyancy)
 *   colloids.temperature  1 (kT_model is the energy unit)
 *   dlvo.*                Psi0, kappa, A_H, eps_r, z, T, a0 (Hecht Eqs. 1-2; energies
 *                         in kT: A_H / kT kept, Hecht Sec. VII.B)
 *   hertz.K               K a0^2.5 / kT (Hecht Eq. 3; K from E, nu_P by Hertz theory)
 *   lubrication.viscosity eta_model = gamma nu_model (Hecht Eq. 4 with the model fluid)
 *   coupling.method       hecht1 (coupling I) / hecht2 (coupling II)
 *   colloids.substeps     the largest of: the mapping's MD step (Hecht Sec. VII: min(tau_V,
 *                         tau_P) / md_resolution, or md_dt), the min_contact_steps guard for the
 *                         stiffest contact the pair terms can produce (Hertz at the largest allowed
 *                         overlap, the primary minimum, WCA), the damping guard (Hecht Eqs. 4, 6).
 * A derived key given in the file is refused, naming it and the physical keys it comes from;
 * a pair term without its material constants is refused, naming the missing keys. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/colloid.h"
#include "peloid/colloid_pair.h"
#include "peloid/colloid_integrator.h"

#include "mapping_refuse.h"

#define OFF(m) offsetof(pl_scene_t, m)

typedef struct {
    size_t off;
    const char *key, *from;
    double derived, given;
    const char *shown; /* the derived value as a word (choices); NULL: the number */
} derived_t;

/* Largest U'' (kT/a0^2) over the gaps a pair of reference diameter d can
 * reach: scanned inward from the pair cut-off, down to the largest overlap
 * the overlap guard allows, and stopping where the pair energy rises more
 * than e_reach above the lowest energy met further out (a barrier the pair
 * cannot cross, or the Hertz wall).  U'' is the sum of curvatures the force
 * kernel hands the min_contact_steps guard (kernels/colloid_forces.c). */
static double stiffest(const pl_colloid_pair_params_t *p, double d, double max_overlap, double e_reach,
                       double *h_at, double *h_reach)
{
    double hlo = -max_overlap * d, hhi = fmax(p->gap_cut, 0.0), best = 0.0, umin = INFINITY;
    if (p->terms & PL_CT_WCA) /* from the WCA cut-off, which lies beyond contact when sigma_cc > d */
        hhi = fmax(hhi, (p->wca_sigma > 0.0 ? p->wca_sigma : d) * p->wca_rfac - d);
    *h_at = *h_reach = hlo;
    const int ng = 200000;
    for (int k = ng; k >= 0; --k) {
        double h = hlo + (hhi - hlo) * (double)k / ng;
        pl_pair_val_t v = pl_colloid_contact_val(p, d, h);
        double k2 = v.k2, u = v.u;
        if (u < umin) umin = u;
        if (u - umin > e_reach) {
            *h_reach = h;
            break;
        }
        if (k2 > best) {
            best = k2;
            *h_at = h;
        }
    }
    return best;
}

/* The pair cut-off against the periodic box edges (minimum image), checked
 * here, where the physical key that set the range is known: the Debye
 * length (physical.kappa or ionic_strength) for a screened Coulomb term,
 * else physical.box. */
static int pair_range(const pl_scene_t *s, const pl_colloid_pair_params_t *p, pl_err_t *err)
{
    const pl_scene_physical_t *ph = &s->mapping.physical;
    const pl_scene_colloids_t *cs = &s->colloids;
    double a0 = s->mapping.map.a0;
    double rc = pl_colloid_pair_cutoff(p, cs->radius * (1.0 + sqrt(3.0) * cs->polydispersity));
    for (int k = 0; k < 3; ++k) {
        if (!p->periodic[k] || rc <= 0.5 * s->box.cells[k]) continue;
        int debye = (p->terms & PL_CT_DLVO) && ph->surface_potential != 0;
        int box_given = pl_mapping_given(s, OFF(mapping.physical.box)) || !pl_mapping_given(s, OFF(box.cells));
        size_t off = box_given ? OFF(mapping.physical.box) : OFF(box.cells);
        const char *key = box_given ? "physical.box" : "box.cells";
        if (debye && pl_mapping_given(s, OFF(mapping.physical.kappa))) {
            off = OFF(mapping.physical.kappa);
            key = "physical.kappa";
        } else if (debye && pl_mapping_given(s, OFF(mapping.physical.ionic_strength))) {
            off = OFF(mapping.physical.ionic_strength);
            key = "physical.ionic_strength";
        }
        char why[96] = "";
        if (debye) snprintf(why, sizeof why, "the Debye length 1/kappa = %.4g m (%.4g a0) is too long: ",
                            1.0 / s->mapping.kappa, 1.0 / (s->mapping.kappa * a0));
        return pl_scene_fail(s, err, off, key,
                             "%sthe colloid pair cut-off is %.4g a0 = %.4g m, more than half the periodic box "
                             "edge %d (%d a0 = %.4g m, minimum image); allowed: a shorter range (a Debye "
                             "length 1/kappa well below the box: larger physical.kappa or ionic_strength) "
                             "or physical.box edges >= %.4g m",
                             why, rc, rc * a0, k, s->box.cells[k], s->box.cells[k] * a0,
                             2.0 * rc * a0);
    }
    return 0;
}

/* coarse_graining.multiple_time_stepping: colloids.slow_gap and
 * slow_interval derived (r-RESPA, kernels/colloid_slow.c).  The split gap is
 * the outer edge of the DLVO secondary minimum's well, its inflection point
 * beyond the minimum: inside it a pair feels the well's positive curvature
 * and the steep screened-Coulomb wall (the stiff near field, on every MD
 * step; a pair bound in the well oscillates there), beyond it the smooth
 * attractive tail of negative curvature (the slow share, on outer steps).
 * (Split at the minimum itself, the slow share ramps across the bound pairs'
 * oscillation: twice the NVE energy drift for the same cost,
 * bench/RESULTS_colloid.md.)  The interval is
 * the largest k whose outer step, at the longest MD step the run will take
 * (that of the floor nfl), still lasts at least
 * colloids.min_contact_steps outer steps per collision time pi sqrt(m_red /
 * K) of the slow share's stiffness K (the contact guard's rule, which
 * pl_colloid_mts_setup checks again on the colloids), and at most nfl / 4
 * (at least four outer steps per collision step). */
static int mts_derive(pl_scene_t *s, const pl_colloid_pair_params_t *p, const pl_colloid_dlvo_info_t *info,
                      double mass, long long nfl, pl_err_t *err)
{
    pl_scene_colloids_t *cs = &s->colloids;
    pl_mapping_colloid_t *c = &s->mapping.colloid;
    const size_t K = OFF(mapping.cg.multiple_time_stepping);
    const char *key = "coarse_graining.multiple_time_stepping";
    if (!(p->terms & PL_CT_DLVO))
        return pl_scene_fail(s, err, K, key, "true needs the dlvo pair term (its slow share is the DLVO "
                                            "tail); colloids.pairs has none; allowed here: false");
    if (!pl_colloid_integrator(cs->integrator)->inertial || s->coupling.method == PL_COUPLE_POTENTIAL)
        return pl_scene_fail(s, err, K, key, "true needs colloids.integrator = \"verlet\" and coupling I or II "
                                            "(the potential coupling integrates the fluid forces with the "
                                            "colloids); allowed here: false");
    if (!isfinite(info->secmin_u) || !(info->secmin_h > p->prim_hm))
        return pl_scene_fail(s, err, K, key, "true: the DLVO potential has no secondary minimum beyond the "
                                            "primary one (the gap that separates the stiff near field from the "
                                            "smooth tail); allowed here: false, or colloids.slow_gap and "
                                            "colloids.slow_interval chosen by hand");
    /* the well's outer edge: its curvature U'' > 0 ends at the inflection
     * point beyond the minimum (scanned in steps of 1e-3 of the gap) */
    const double d0 = 2.0 * cs->radius, hm = info->secmin_h, step = 1e-3 * hm;
    double hin = hm;
    while (hin < p->dlvo_hcut && pl_pair_dlvo_raw(d0 + hin, d0, p->coul_C, p->kappa, p->hamaker).k2 > 0.0) hin += step;
    const double spread = sqrt(3.0) * cs->polydispersity;
    const double ds[3] = {2.0 * cs->radius * (1.0 - spread), 2.0 * cs->radius, 2.0 * cs->radius * (1.0 + spread)};
    double kmax = 0.0, h_at = hin;
    for (int a = 0; a < 3; ++a) {
        double h = hin, kk = pl_colloid_slow_stiffness(p, ds[a], hin, &h);
        if (kk > kmax) {
            kmax = kk;
            h_at = h;
        }
    }
    const double dt = s->srd.dt, tc = kmax > 0.0 ? PL_PI * sqrt(0.5 * mass / kmax) : INFINITY;
    long long k = 1;
    for (long long q = nfl / 4; q >= 2; --q)
        if (!(cs->min_contact_steps > 0.0) || tc / ((double)q * (dt / (double)nfl)) >= cs->min_contact_steps) {
            k = q;
            break;
        }
    if (pl_mapping_refuse_derived(s, err, OFF(colloids.slow_gap), "colloids.slow_gap",
                                  "coarse_graining.multiple_time_stepping (the outer edge of the DLVO secondary "
                                  "minimum's well)",
                                  cs->slow_gap, hin, NULL) ||
        pl_mapping_refuse_derived(s, err, OFF(colloids.slow_interval), "colloids.slow_interval",
                                  "coarse_graining.multiple_time_stepping (the longest outer step the slow share allows)",
                                  (double)cs->slow_interval, (double)k, NULL))
        return PL_ERR_INPUT;
    if (k < 2) {
        pl_mapping_warn(&s->mapping.map, PL_SEV_NOTE, "MTS_NOT_USED", kmax,
                        "coarse_graining.multiple_time_stepping: the slow DLVO share beyond the secondary "
                        "minimum's well (gap %.4g a0) is too stiff (%.4g kT/a0^2 at gap %.4g a0) for an outer step "
                        "of 2 or more MD steps at the fewest MD steps per SRD step (%lld); the MD runs with "
                        "one time step", hin, kmax, h_at, nfl);
        return 0;
    }
    cs->slow_gap = hin;
    cs->slow_interval = k;
    pl_mapping_prov(c, "colloids.slow_gap = %.6g (derived: coarse_graining.multiple_time_stepping, the outer edge of the "
            "well of the DLVO secondary minimum at gap %.4g a0 (its inflection point); the DLVO force beyond it moves "
            "to the outer step up to the gap %.6g a0)",
         hin, hm, pl_pair_slow_hout(hin));
    pl_mapping_prov(c, "colloids.slow_interval = %lld (derived: coarse_graining.multiple_time_stepping; the slow share's "
            "stiffness %.4g kT/a0^2 at gap %.4g a0 lasts %.3g outer steps per collision time at %lld MD "
            "steps per SRD step (>= colloids.min_contact_steps = %g); at most a quarter of %lld)",
         k, kmax, h_at, tc / ((double)k * dt / (double)nfl), nfl, cs->min_contact_steps, nfl);
    return 0;
}

static int substeps(pl_scene_t *s, pl_err_t *err)
{
    pl_scene_mapping_t *mp = &s->mapping;
    pl_mapping_colloid_t *c = &mp->colloid;
    pl_scene_colloids_t *cs = &s->colloids;
    pl_colloid_pair_params_t p;
    pl_colloid_dlvo_info_t info;
    pl_err_t e = {0, ""};
    if (pl_colloid_pair_params(s, &p, &info, &e)) {
        /* an implausible physical input first; then a dlvo{} model choice the user wrote
         * (cutoff_energy, primary_depth) where the failure names it; else the surface potential */
        const size_t dl[] = {OFF(mapping.physical.hamaker), OFF(mapping.physical.surface_potential),
                             OFF(mapping.physical.kappa), OFF(mapping.physical.ionic_strength),
                             OFF(mapping.physical.primary_minimum), OFF(mapping.physical.radius),
                             OFF(mapping.physical.temperature)};
        size_t off;
        char why[160];
        const char *key =
            info.fail_key ? pl_mapping_blame(s, dl, sizeof dl / sizeof dl[0], &off, why, sizeof why) : NULL;
        if (key) return pl_scene_fail(s, err, off, key, "%sthe derived DLVO potential: %s", why, e.msg);
        if (info.fail_key && pl_mapping_given(s, info.fail_off))
            return pl_scene_fail(s, err, info.fail_off, info.fail_key, "%s", e.msg);
        if (!info.fail_key) /* not the DLVO set-up: another term's own message */
            return pl_err_set(err, e.code, "%s", e.msg);
        return pl_scene_fail(s, err, OFF(mapping.physical.surface_potential), "physical.surface_potential",
                             "the derived DLVO potential: %s", e.msg);
    }
    if (pair_range(s, &p, err)) return PL_ERR_INPUT;
    if (p.terms & PL_CT_DLVO) {
        char bar[64] = "none", sec[64] = "none"; /* the potential need not have them */
        if (isfinite(info.barrier_u)) snprintf(bar, sizeof bar, "%.4g kT at gap %.4g a0", info.barrier_u, info.barrier_h);
        if (isfinite(info.secmin_u)) snprintf(sec, sizeof sec, "%.4g kT at gap %.4g a0", info.secmin_u, info.secmin_h);
        pl_mapping_prov(c, "DLVO potential (Hecht Eqs. 1-2, parabolic primary minimum of Sec. II): primary minimum -%g kT "
                "at gap %.4g a0 (matched at %.4g a0, curvature %.4g kT/a0^2); barrier %s; secondary minimum %s; "
                "cut-off gap %.4g a0",
             cs->dlvo.primary_depth, info.h0, info.hm, info.curvature, bar, sec, info.hcut);
    }
    double d = 2.0 * cs->radius, dt = s->srd.dt;
    double shrink = 1.0 - sqrt(3.0) * cs->polydispersity; /* smallest colloid of the distribution */
    double mass = cs->mass_density * 4.0 / 3.0 * PL_PI * pow(cs->radius * shrink, 3.0);
    double m_red = 0.5 * mass;
    double e_reach = mp->cg.reach_energy, h_at = 0.0, h_reach = 0.0;
    double k2 = stiffest(&p, d, cs->max_overlap, e_reach, &h_at, &h_reach);
    long long n_map = mp->map.md_substeps, n_contact = 0, n_damp = 0;
    c->contact_time = k2 > 0.0 ? PL_PI * sqrt(m_red / k2) : INFINITY;
    if (cs->min_contact_steps > 0.0 && k2 > 0.0)
        n_contact = (long long)ceil(1.05 * cs->min_contact_steps * dt / c->contact_time);
    /* dissipative rate zeta / m_red <= 0.5 / dt_MD (the damping guard) */
    double zeta = 0.0;
    if (p.terms & PL_CT_HERTZ) zeta += p.hertz_beta * sqrt(cs->max_overlap * d) + p.hertz_gamma_t;
    if (p.terms & PL_CT_LUB)
        zeta += pl_pair_lub_zeta(0.0, cs->radius, cs->radius, p.lub_eta, p.lub_hmin, p.lub_hcut);
    if (zeta > 0.0) n_damp = (long long)ceil(1.05 * dt * zeta / (0.5 * m_red));
    long long n = n_map, n_cf = 0;
    const char *why = mp->cg.md_dt > 0 ? "coarse_graining.md_dt" : "min(tau_V, tau_P) / md_resolution (Hecht Sec. VII)";
    if (s->coupling.method == PL_COUPLE_POTENTIAL) { /* PL Sec. III.A: the fluid-colloid WCA sets dt_MD */
        const double res = mp->cg.md_resolution > 0 ? mp->cg.md_resolution : 20.0;
        n_cf = pl_mapping_cf_substeps(s->coupling.sigma_cf, s->coupling.epsilon_cf, mass, dt, res);
        if (n_cf > n) {
            n = n_cf;
            why = "fluid-colloid contact (PL Eq. 17 at kT / md_resolution)";
        }
    }
    if (n_contact > n) {
        n = n_contact;
        why = "contact guard";
    }
    if (n_damp > n) {
        n = n_damp;
        why = "damping guard";
    }
    if (n > 1000000) {
        /* at fault: an implausible physical input; else the MD step the file asks for where it
         * sets the count; else a given coarse_graining.cell_size (R / a0: mass, curvature); else R */
        const size_t from[] = {OFF(mapping.physical.viscosity), OFF(mapping.physical.radius),
                               OFF(mapping.physical.particle_density), OFF(mapping.physical.solvent_density),
                               OFF(mapping.physical.temperature)};
        size_t off = OFF(mapping.physical.radius);
        char bl[160];
        const char *key = pl_mapping_blame(s, from, sizeof from / sizeof from[0], &off, bl, sizeof bl);
        const size_t md = mp->cg.md_dt > 0 ? OFF(mapping.cg.md_dt) : OFF(mapping.cg.md_resolution);
        if (!key && n == n_map && pl_mapping_given(s, md)) {
            off = md;
            key = mp->cg.md_dt > 0 ? "coarse_graining.md_dt" : "coarse_graining.md_resolution";
        } else if (!key && pl_mapping_given(s, OFF(mapping.cg.cell_size))) {
            off = OFF(mapping.cg.cell_size);
            key = "coarse_graining.cell_size";
        }
        return pl_scene_fail(s, err, off, key ? key : "physical.radius",
                             "%sR = %.4g m, a0/R = %.6g give R = %.4g a0; the %s (stiffest contact U'' = %.4g "
                             "kT/a0^2, collision time %.4g t0; coarse_graining.md_dt = %g s, md_resolution = %g) needs "
                             "%lld MD steps per SRD step (more than 1e6); soften it: coarse_graining.hertz_K, "
                             "dlvo.primary_depth, or a smaller coarse_graining.cell_size or md_resolution",
                             bl, mp->physical.radius, mp->map.a0 / mp->physical.radius, cs->radius, why, k2,
                             c->contact_time, mp->cg.md_dt, mp->cg.md_resolution, n);
    }
    snprintf(c->substeps_reason, sizeof c->substeps_reason,
             "%lld MD steps per SRD step from the %s; mapping %lld, contact %lld (U''max = %.4g kT/a0^2 at gap "
             "%.3g a0, collision %.4g t0, >= %g steps: colloids.min_contact_steps; gaps down to %.4g a0 "
             "reachable with %g kT: coarse_graining.reach_energy), damping %lld, fluid-colloid %lld",
             n, why, n_map, n_contact, k2, h_at, c->contact_time, cs->min_contact_steps, h_reach, e_reach,
             n_damp, n_cf);
    c->reach_gap = h_reach;
    if (mp->cg.md_dt > 0 && n > n_map) /* the user's MD step made finer: said, not silent */
        pl_mapping_warn(&mp->map, PL_SEV_NOTE, "MD_DT_REFINED", mp->map.dt / (double)n,
                        "coarse_graining.md_dt = %g s (%lld MD steps per SRD step) is refined to %.4g s (%lld "
                        "steps) by the %s (its criterion: colloids.substeps in peloid params)",
                        mp->cg.md_dt, n_map, mp->map.dt / (double)n, n, why);
    if (h_reach > 0.0 && (p.terms & PL_CT_DLVO))
        pl_mapping_warn(&mp->map, PL_SEV_NOTE, "CONTACT_SHIELDED", h_reach,
                        "the DLVO barrier keeps pairs out of gaps below %.4g a0 (more than "
                        "coarse_graining.reach_energy = %g kT above the outer minimum): the primary minimum "
                        "and the Hertz contact are not resolved by the MD step; a pair started or pushed "
                        "there trips the contact guard (raise reach_energy to resolve them)",
                        h_reach, e_reach);
    /* adaptive substeps by default where the contact guard sets the MD step
     * (velocity Verlet, equal colloids: what the reach table covers) */
    if (!pl_mapping_given(s, OFF(colloids.adaptive_substeps)))
        cs->adaptive_substeps = strcmp(why, "contact guard") == 0 && pl_colloid_integrator(cs->integrator)->inertial &&
                                cs->polydispersity == 0.0;
    if (mp->cg.multiple_time_stepping &&
        mts_derive(s, &p, &info, mass, cs->adaptive_substeps ? (n_map < n ? n_map : n) : n, err))
        return PL_ERR_INPUT;
    if (cs->slow_interval > 1 && n % cs->slow_interval) { /* an outer step ends with the collision step */
        n = (n / cs->slow_interval + 1) * cs->slow_interval;
        snprintf(c->substeps_reason + strlen(c->substeps_reason), sizeof c->substeps_reason - strlen(c->substeps_reason),
                 "; rounded up to %lld, a multiple of colloids.slow_interval", n);
    }
    if (pl_mapping_refuse_derived(s, err, OFF(colloids.substeps), "colloids.substeps",
                                  "physical{} and coarse_graining{} (MD step, stiffest contact)", (double)cs->substeps,
                                  (double)n, NULL))
        return PL_ERR_INPUT;
    cs->substeps = n;
    mp->map.md_substeps = n;
    mp->map.md_dt = mp->map.dt / (double)n;
    c->md_substeps = n;
    c->md_dt = dt / (double)n;
    pl_mapping_prov(c, "colloids.substeps = %lld (derived: %s)", n, c->substeps_reason);
    /* adaptive substeps: the mapping's own MD step is the floor */
    long long nmin = n_map < n ? n_map : n;
    if (pl_mapping_refuse_derived(s, err, OFF(colloids.min_substeps), "colloids.min_substeps",
                                  "physical{} and coarse_graining{} (the mapping's MD step)", (double)cs->min_substeps,
                                  (double)nmin, NULL))
        return PL_ERR_INPUT;
    cs->min_substeps = nmin;
    if (cs->adaptive_substeps)
        pl_mapping_prov(c, "colloids.min_substeps = %lld (derived: the mapping's MD step; adaptive substeps run %lld .. %lld "
                "per collision step, the stiffest contact the pairs present can reach with their energy + "
                "colloids.adaptive_margin = %g kT)", nmin, nmin, n, cs->adaptive_margin);
    return 0;
}

/* PL Sec. VII's choices for the potential coupling, in model units: the
 * colloid-fluid WCA of PL Eq. 17 at sigma_cf = R (the hydrodynamic radius,
 * PL Table VI: a ~ sigma_cf) and epsilon_cf = 2.5 kT (PL Sec. III.C), the
 * colloid-colloid WCA of PL Eq. 16 with n = 24, epsilon_cc = 2.5 kT and
 * sigma_cc from PL's rule against spurious depletion (Sec. III.C.1).  A
 * hand-given value that differs is refused. */
static const double PL_EPS_CF = 2.5, PL_EPS_CC = 2.5, PL_N_CC = 24.0;

static int potential_keys(pl_scene_t *s, unsigned mask, pl_err_t *err)
{
    pl_scene_colloids_t *cs = &s->colloids;
    const int wca = (mask & PL_CT_WCA) != 0;
    const double sigma = s->mapping.map.sigma;
    const char *pl = "coarse_graining.coupling = \"potential\" (PL Sec. VII)";
    derived_t dk[] = {
        {OFF(coupling.sigma_cf), "coupling.sigma_cf", "physical.radius and coarse_graining.cell_size (sigma_cf = R)",
         sigma, s->coupling.sigma_cf, NULL},
        {OFF(coupling.epsilon_cf), "coupling.epsilon_cf", pl, PL_EPS_CF, s->coupling.epsilon_cf, NULL},
        {OFF(colloids.wca.epsilon), "wca.epsilon", pl, PL_EPS_CC, cs->wca.epsilon, NULL},
        {OFF(colloids.wca.n), "wca.n", pl, PL_N_CC, cs->wca.n, NULL},
        {OFF(colloids.wca.sigma_rule), "wca.sigma_rule", pl, (double)PL_SIGMA_PL, (double)cs->wca.sigma_rule, "pl"},
        {OFF(colloids.wca.sigma), "wca.sigma", "wca.sigma_rule = \"pl\" of the potential coupling (PL Sec. III.C.1)",
         0.0, cs->wca.sigma, "0: sigma_cc from PL's rule"},
    };
    /* the wca{} keys only where colloids.pairs switches the term on */
    for (size_t i = 0; i < (wca ? sizeof dk / sizeof dk[0] : 2); ++i)
        if (pl_mapping_refuse_derived(s, err, dk[i].off, dk[i].key, dk[i].from, dk[i].given, dk[i].derived,
                                      dk[i].shown))
            return PL_ERR_INPUT;
    s->coupling.sigma_cf = sigma;
    s->coupling.epsilon_cf = PL_EPS_CF;
    if (wca) cs->wca = (pl_scene_wca_t){.epsilon = PL_EPS_CC, .n = PL_N_CC, .sigma_rule = PL_SIGMA_PL, .sigma = 0.0};
    return pl_mapping_potential_core(s, mask, err); /* its hard core, and DLVO beside it refused */
}

int pl_mapping_colloids_apply(pl_scene_t *s, pl_err_t *err)
{
    pl_scene_mapping_t *mp = &s->mapping;
    const pl_scene_physical_t *ph = &mp->physical;
    const pl_mapping_t *m = &mp->map;
    pl_mapping_colloid_t *c = &mp->colloid;
    pl_scene_colloids_t *cs = &s->colloids;
    c->nprov = 0;
    int have = c->n_colloids > 0; /* a volume fraction without one is refused by the box (mapping_scene.c) */
    if (have && mp->cg.fluid_gravity && ph->gravity > 0)
        return pl_scene_fail(s, err, OFF(mapping.cg.fluid_gravity), "coarse_graining.fluid_gravity",
                             "with colloids is not supported: the fluid would need the body force and the "
                             "colloids the full weight, with buoyancy from the fluid's pressure, which "
                             "coupling II point colloids do not feel; allowed: false (Hecht Eq. 31: "
                             "weight minus buoyancy on the colloids alone)");
    const char *pairs_src = "given";
    if (have && !pl_mapping_given(s, OFF(colloids.pairs))) {
        int dlvo = pl_mapping_given(s, OFF(mapping.physical.surface_potential)) ||
                   pl_mapping_given(s, OFF(mapping.physical.hamaker));
        const int pot = mp->cg.coupling == PL_COUPLE_POTENTIAL; /* PL Eq. 16 as the contact repulsion */
        /* potential + DLVO: contact at 2R, depletion compensated (mapping_potential.c) */
        snprintf(cs->pairs, sizeof cs->pairs, "%s",
                 dlvo ? (pot ? "dlvo, hertz, depletion_comp" : "dlvo, hertz") : pot ? "wca" : "hertz");
        pairs_src = dlvo && pot ? "derived: DLVO given; contact at 2R, PL's depletion compensation (Sec. III.C.1)"
                    : dlvo      ? "derived: physical.surface_potential / hamaker given"
                    : pot       ? "derived: PL Eq. 16 WCA repulsion of the potential coupling (PL Sec. III.A)"
                                : "derived: contact repulsion only";
    }
    unsigned mask = 0;
    char bad[128];
    if (pl_colloid_parse_pairs(cs->pairs, &mask, bad, sizeof bad) || !have) mask = 0; /* bad: the colloid checks */
    double rho_ratio = ph->particle_density / ph->solvent_density;
    double eta = mp->cg.particles_per_cell * m->nu_sim; /* rho_f nu, m_f / (a0 t0) */
    double kT = PL_KB * ph->temperature;
    double K = 0.0; /* hertz.K, from K_src */
    const char *K_src = "";
    const int pairs_given = pl_mapping_given(s, OFF(colloids.pairs));
    size_t pairs_off = pairs_given ? OFF(colloids.pairs) : OFF(mapping.physical.volume_fraction);
    const char *pairs_key = pairs_given ? "colloids.pairs" : "physical.volume_fraction";
    if (!pairs_given && mp->cg.coupling == PL_COUPLE_POTENTIAL && (mask & PL_CT_DLVO)) { /* Hertz */
        const int sp = pl_mapping_given(s, OFF(mapping.physical.surface_potential));
        pairs_off = sp ? OFF(mapping.physical.surface_potential) : OFF(mapping.physical.hamaker);
        pairs_key = sp ? "physical.surface_potential" : "physical.hamaker";
    }
    if (mask & PL_CT_DLVO) { /* colloids.pairs derived: blamed on the key that switched the term on */
        const int ham = pl_mapping_given(s, OFF(mapping.physical.hamaker)), own = pairs_given;
        char miss[256] = "";
        if (!ham) strcat(miss, "physical.hamaker, ");
        if (!pl_mapping_given(s, OFF(mapping.physical.surface_potential))) strcat(miss, "physical.surface_potential, ");
        if (!(mp->kappa > 0)) strcat(miss, "physical.kappa or physical.ionic_strength, ");
        if (miss[0]) miss[strlen(miss) - 2] = '\0';
        const size_t on = own ? pairs_off : ham ? OFF(mapping.physical.hamaker) : OFF(mapping.physical.surface_potential);
        if (pl_mapping_refuse_missing(s, err, on,
                                      own ? pairs_key : ham ? "physical.hamaker" : "physical.surface_potential", "dlvo",
                                      "physical.hamaker, physical.surface_potential and physical.kappa (or "
                                      "physical.ionic_strength)", miss))
            return PL_ERR_INPUT;
    }
    if (mask & PL_CT_HERTZ) {
        if (mp->cg.hertz_K > 0) {
            K = mp->cg.hertz_K;
            K_src = "given: coarse_graining.hertz_K (softer than the material, Hecht Sec. II)";
            c->hertz_off = OFF(mapping.cg.hertz_K), c->hertz_key = "coarse_graining.hertz_K";
        } else if (ph->hertz_constant > 0) {
            K = ph->hertz_constant * pow(m->a0, 2.5) / kT;
            K_src = "derived: physical.hertz_constant a0^2.5 / kT (Hecht Eq. 3)";
            c->hertz_off = OFF(mapping.physical.hertz_constant), c->hertz_key = "physical.hertz_constant";
        } else if (ph->young_modulus > 0 && pl_mapping_given(s, OFF(mapping.physical.poisson_ratio))) {
            K = pl_mapping_hertz_K(ph->young_modulus, ph->poisson_ratio, ph->radius) * pow(m->a0, 2.5) / kT;
            K_src = "derived: Hertz theory from physical.young_modulus, poisson_ratio (Hecht Eq. 3)";
            c->hertz_off = OFF(mapping.physical.young_modulus), c->hertz_key = "physical.young_modulus";
        } else {
            char miss[200];
            snprintf(miss, sizeof miss, "%s",
                     ph->young_modulus > 0 ? "physical.poisson_ratio"
                     : pl_mapping_given(s, OFF(mapping.physical.poisson_ratio))
                         ? "physical.young_modulus"
                         : "physical.young_modulus + physical.poisson_ratio, or physical.hertz_constant, or "
                           "coarse_graining.hertz_K");
            if (pl_mapping_refuse_missing(s, err, pairs_off, pairs_key, "hertz",
                                          "physical.young_modulus + physical.poisson_ratio (or physical.hertz_constant, "
                                          "or the model choice coarse_graining.hertz_K)", miss))
                return PL_ERR_INPUT;
        }
    }
    int method = !have ? s->coupling.method : mp->cg.coupling;
    double g = have && m->g_sim > 0.0 ? -m->g_sim : 0.0;
    double temp = have ? 1.0 : cs->temperature;
    /* the derived keys: refused when given with another value */
    const char *phi_from = "physical.volume_fraction, physical.box and physical.radius";
    derived_t dk[] = {
        {OFF(colloids.count), "colloids.count", phi_from, (double)c->n_colloids, (double)cs->count, NULL},
        {OFF(colloids.radius), "colloids.radius", "physical.radius and coarse_graining.cell_size", m->sigma,
         cs->radius, NULL},
        {OFF(colloids.mass_density), "colloids.mass_density",
         "physical.particle_density, solvent_density and coarse_graining.particles_per_cell",
         mp->cg.particles_per_cell * rho_ratio, cs->mass_density, NULL},
        {OFF(colloids.temperature), "colloids.temperature", "physical.temperature (kT_model = 1)", temp,
         cs->temperature, NULL},
        {OFF(colloids.gravity), "colloids.gravity", "physical.gravity and the densities (Hecht Eq. 31)", g,
         cs->gravity[2], NULL},
        {OFF(colloids.bd_viscosity), "colloids.bd_viscosity", "physical.viscosity (model eta)", eta,
         cs->bd_viscosity, NULL},
        {OFF(colloids.dlvo.eps_r), "dlvo.eps_r", "physical.permittivity", ph->permittivity, cs->dlvo.eps_r, NULL},
        {OFF(colloids.dlvo.psi0_mV), "dlvo.psi0", "physical.surface_potential", 1e3 * ph->surface_potential,
         cs->dlvo.psi0_mV, NULL},
        {OFF(colloids.dlvo.z), "dlvo.z", "physical.valence", (double)ph->valence, cs->dlvo.z, NULL},
        {OFF(colloids.dlvo.temperature_K), "dlvo.temperature", "physical.temperature", ph->temperature,
         cs->dlvo.temperature_K, NULL},
        {OFF(colloids.dlvo.kappa_per_m), "dlvo.kappa", "physical.kappa or physical.ionic_strength", mp->kappa,
         cs->dlvo.kappa_per_m, NULL},
        {OFF(colloids.dlvo.hamaker_J), "dlvo.hamaker", "physical.hamaker", ph->hamaker, cs->dlvo.hamaker_J, NULL},
        {OFF(colloids.dlvo.length_unit_m), "dlvo.length_unit", "physical.radius and coarse_graining.cell_size (a0)",
         m->a0, cs->dlvo.length_unit_m, NULL},
        {OFF(colloids.hertz.K), "hertz.K",
         "physical.young_modulus + poisson_ratio, physical.hertz_constant or coarse_graining.hertz_K",
         (mask & PL_CT_HERTZ) ? K : cs->hertz.K, cs->hertz.K, NULL}, /* unused without Hertz */
        {OFF(colloids.lub.viscosity), "lubrication.viscosity", "physical.viscosity (model eta = gamma nu)", eta,
         cs->lub.viscosity, NULL},
        {OFF(coupling.method), "coupling.method", "coarse_graining.coupling", (double)method,
         (double)s->coupling.method, pl_couple_model_name(method)},
    };
    /* without colloids (no volume fraction) only a hand-given count matters:
     * the other colloid keys act on nothing (an echoed scene prints them) */
    for (size_t i = 0; i < (have ? sizeof dk / sizeof dk[0] : 1); ++i)
        if (pl_mapping_refuse_derived(s, err, dk[i].off, dk[i].key, dk[i].from, dk[i].given, dk[i].derived,
                                      dk[i].shown))
            return PL_ERR_INPUT;
    if (have && method == PL_COUPLE_POTENTIAL && potential_keys(s, mask, err)) return PL_ERR_INPUT;
    if (have && pl_mapping_given(s, OFF(colloids.gravity)) && (cs->gravity[0] != 0.0 || cs->gravity[1] != 0.0))
        return pl_scene_fail(s, err, OFF(colloids.gravity), "colloids.gravity",
                             "is derived from physical.gravity (along -z); remove it");
    if (!have) return 0;

    cs->count = c->n_colloids;
    cs->radius = m->sigma;
    cs->mass_density = mp->cg.particles_per_cell * rho_ratio;
    cs->temperature = 1.0;
    cs->gravity[0] = cs->gravity[1] = 0.0;
    cs->gravity[2] = g;
    cs->bd_viscosity = eta;
    cs->lub.viscosity = eta;
    cs->dlvo.eps_r = ph->permittivity;
    cs->dlvo.psi0_mV = 1e3 * ph->surface_potential;
    cs->dlvo.z = (double)ph->valence;
    cs->dlvo.temperature_K = ph->temperature;
    cs->dlvo.kappa_per_m = mp->kappa;
    cs->dlvo.hamaker_J = ph->hamaker;
    cs->dlvo.length_unit_m = m->a0;
    if (mask & PL_CT_HERTZ) cs->hertz.K = K;
    s->coupling.method = method;
    double M = cs->mass_density * 4.0 / 3.0 * PL_PI * pow(cs->radius, 3.0);
    c->mass_density = cs->mass_density;
    c->inertia = 0.4 * M * cs->radius * cs->radius;
    c->hertz_K = cs->hertz.K;
    c->lub_viscosity = eta;

    pl_mapping_prov(c, "colloids.count = %lld (derived: phi V / (4/3 pi R^3) in the box used, %d x %d x %d a0; phi "
            "given %g, realised %.5g)",
         c->n_colloids, s->box.cells[0], s->box.cells[1], s->box.cells[2], c->phi_given, c->phi_realised);
    pl_mapping_prov(c, "colloids.radius = %.6g a0 (derived: R / a0, a0 = %s R)", cs->radius,
         pl_mapping_given(s, OFF(mapping.cg.cell_size)) ? "coarse_graining.cell_size" : "the coupling's default");
    pl_mapping_prov(c, "colloids.mass_density = %.6g m_f/a0^3 (derived: gamma rho_p / rho_f, Hecht Sec. VII.B): M = %.6g "
            "m_f, I = 2/5 M R^2 = %.6g m_f a0^2",
         cs->mass_density, M, c->inertia);
    pl_mapping_prov(c, "colloids.gravity = [0, 0, %.6g] a0/t0^2 (derived: Hecht Eq. 31, weight minus buoyancy)", g);
    pl_mapping_prov(c, "colloids.temperature = 1 kT_model (derived: the model energy unit)");
    pl_mapping_prov(c, "colloids.pairs = \"%s\" (%s)", cs->pairs, pairs_src);
    if (mask & PL_CT_DLVO)
        pl_mapping_prov(c, "dlvo: psi0 = %.6g mV, kappa = %.6g /m (%s), hamaker = %.6g J, eps_r = %.6g (%s), z = %g, "
                "T = %g K, length_unit = a0 = %.6g m (derived: Hecht Eqs. 1-2)",
             cs->dlvo.psi0_mV, mp->kappa, pl_mapping_given(s, OFF(mapping.physical.kappa)) ? "given" : "Debye-Hueckel",
             ph->hamaker, ph->permittivity,
             pl_mapping_given(s, OFF(mapping.physical.permittivity)) ? "given" : "water at T, Malmberg & Maryott",
             cs->dlvo.z, ph->temperature, m->a0);
    if (mask & PL_CT_HERTZ) pl_mapping_prov(c, "hertz.K = %.6g kT/a0^2.5 (%s)", K, K_src);
    pl_mapping_prov(c, "lubrication.viscosity = %.6g m_f/(a0 t0) (derived: eta = gamma nu_model, Hecht Eq. 4%s)", eta,
         (mask & PL_CT_LUB) ? "" : "; lubrication not in colloids.pairs");
    pl_mapping_prov(c, "coupling.method = \"%s\" (derived: coarse_graining.coupling = \"%s\")",
                    pl_couple_model_name(method), pl_couple_physical_name(mp->cg.coupling));
    if (method == PL_COUPLE_POTENTIAL)
        pl_mapping_prov(c, "coupling.sigma_cf = %.6g a0 = R, epsilon_cf = %g kT (derived: PL Eq. 17 with PL Sec. VII's choices: "
                "the hydrodynamic radius a ~ sigma_cf, PL Table VI; 2.5 kT, PL Sec. III.C); wca: epsilon = %g kT, n = "
                "%g, sigma_rule = \"pl\" (PL Eq. 16, sigma_cc against spurious depletion, PL Sec. III.C.1; where "
                "colloids.pairs has wca)",
             s->coupling.sigma_cf, s->coupling.epsilon_cf, cs->wca.epsilon, cs->wca.n);
    return substeps(s, err);
}
