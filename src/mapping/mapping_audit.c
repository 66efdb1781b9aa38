/* The audit: named warnings when a number of the model leaves the regime the
 * papers recommend, each with its value, the range, the source and the input
 * to change.
 *
 * PL Sec. IV: Ma <= 0.1 (Eq. 28), Re <= 0.2 (Eq. 29), Kn <= 0.05 (Eq. 34),
 * Sc >> 1 (Eq. 26/27); PL Eq. 57 time-scale hierarchy; Hecht Sec. VII:
 * Pe kept exactly, tau_P < tau_G, creeping condition Eq. 27. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/mapping.h"

void pl_mapping_warn(pl_mapping_t *m, int severity, const char *name, double value, const char *fmt, ...)
{
    if (m->nwarn >= PL_MAP_MAX_WARN) return;
    pl_mapping_warning_t *w = &m->warn[m->nwarn++];
    snprintf(w->name, sizeof w->name, "%s", name);
    w->severity = severity;
    w->value = value;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(w->text, sizeof w->text, fmt, ap);
    va_end(ap);
}

int pl_mapping_nwarnings(const pl_mapping_t *m)
{
    int n = 0;
    for (int i = 0; i < m->nwarn; ++i) n += m->warn[i].severity == PL_SEV_WARNING;
    return n;
}

/* Thresholds.  Sc: PL calls its lambda = 0.1, gamma = 5 choice sufficient;
 * with the full Eqs. 6 and 9-12 that choice gives Sc = 3.6 (about 5 only by
 * the approximate Eq. 27), so peloid warns below 3. */
#define MA_MAX 0.1
#define RE_MAX 0.2
#define KN_MAX 0.05
#define SC_MIN 3.0
#define PE_TOL 0.05    /* relative mismatch of Pe, model vs reality */
#define SEPARATION 10.0 /* PL Sec. VI.B: one order of magnitude suffices */

static void audit_numbers(pl_mapping_t *m)
{
    const pl_mapping_numbers_t *n = &m->num_model;
    if (n->Ma > MA_MAX)
        pl_mapping_warn(m, PL_SEV_WARNING, "MACH", n->Ma,
                        "Ma = %.3g > %.2g (PL Sec. IV.B, Eq. 28): compressibility errors; lower the flow "
                        "(physical.gravity or physical.flow_velocity) or t0 via coarse_graining.particles_per_cell",
                        n->Ma, MA_MAX);
    if (n->Re > RE_MAX)
        pl_mapping_warn(m, PL_SEV_WARNING, "REYNOLDS", n->Re,
                        "Re = %.3g > %.2g (PL Sec. IV.C, Eq. 29): inertial effects; reduce "
                        "coarse_graining.mean_free_path (raises nu, PL Eq. 33) or coarse_graining.cell_size",
                        n->Re, RE_MAX);
    /* Kn compares the mean free path with a resolved colloid surface
     * (couplings I and potential); a coupling II colloid is a point in its
     * cell, which resolves nothing smaller (Hecht Sec. VII.C): a note */
    if (n->Kn > KN_MAX && m->cg.coupling == PL_COUPLE_HECHT2)
        pl_mapping_warn(m, PL_SEV_NOTE, "KNUDSEN", n->Kn,
                        "Kn = %.3g > %.2g (PL Sec. IV.D, Eq. 34), as always with coupling II: the colloid is a "
                        "point in its cell, the flow around it is not resolved (Hecht Sec. VII.C)", n->Kn, KN_MAX);
    else if (n->Kn > KN_MAX)
        pl_mapping_warn(m, PL_SEV_WARNING, "KNUDSEN", n->Kn,
                        "Kn = %.3g > %.2g (PL Sec. IV.D, Eq. 34): rarefaction lowers the friction; reduce "
                        "coarse_graining.mean_free_path or coarse_graining.cell_size (more cells per radius)",
                        n->Kn, KN_MAX);
    if (n->Sc < SC_MIN)
        pl_mapping_warn(m, PL_SEV_WARNING, "SCHMIDT", n->Sc,
                        "Sc = %.3g < %.2g (PL Sec. IV.A, Eq. 26, Sc >> 1): gas-like solvent; reduce "
                        "coarse_graining.mean_free_path (PL Eq. 27: Sc ~ 1/3 + 1/(18 lambda^2))",
                        n->Sc, SC_MIN);
    double pe_r = m->num_real.Pe, pe_m = n->Pe;
    if (isfinite(pe_r) && pe_r > 0 && fabs(pe_m / pe_r - 1.0) > PE_TOL)
        pl_mapping_warn(m, PL_SEV_WARNING, "PECLET", pe_m,
                        "Pe = %.3g in the model vs %.3g in reality (Hecht Sec. VII.A: Pe must be kept); "
                        "use coarse_graining.time_match = \"diffusion\", enskog = false and srd_dt = 0",
                        pe_m, pe_r);
}

static void audit_hierarchy(pl_mapping_t *m)
{
    const pl_mapping_pl_times_t *p = &m->pl_model;
    if (p->tau_B >= p->tau_nu)
        pl_mapping_warn(m, PL_SEV_WARNING, "HIERARCHY_B_NU", p->tau_B / p->tau_nu,
                        "tau_B/tau_nu = %.3g >= 1 (PL Eq. 57 needs tau_B < tau_nu; Eq. 51: 2 rho_p/(9 rho_f)): "
                        "colloid too heavy for its solvent; check physical.particle_density",
                        p->tau_B / p->tau_nu);
    if (SEPARATION * p->tau_nu > p->tau_D)
        pl_mapping_warn(m, PL_SEV_WARNING, "HIERARCHY_NU_D", p->tau_D / p->tau_nu,
                        "tau_D/tau_nu = %.3g < %.0f (PL Eq. 57: tau_nu << tau_D; Eq. 56 ~ 0.06 gamma sigma/"
                        "lambda^2): raise coarse_graining.particles_per_cell or lower mean_free_path",
                        p->tau_D / p->tau_nu, SEPARATION);
    if (m->dt >= p->tau_B)
        pl_mapping_warn(m, PL_SEV_WARNING, "HIERARCHY_DT_B", p->tau_B / m->dt,
                        "tau_B/dt_SRD = %.3g <= 1 (PL Eq. 57: tau_f ~ dt << tau_B): Brownian relaxation "
                        "not resolved; lower coarse_graining.mean_free_path or cell_size",
                        p->tau_B / m->dt);
    if (isfinite(p->t_S) && p->tau_B >= p->t_S)
        pl_mapping_warn(m, PL_SEV_WARNING, "HIERARCHY_B_S", p->t_S / p->tau_B,
                        "t_S/tau_B = %.3g <= 1 (PL Eq. 57: tau_B << t_S): the colloid advects before it "
                        "relaxes; lower physical.gravity or flow_velocity",
                        p->t_S / p->tau_B);
}

static void audit_hecht(pl_mapping_t *m)
{
    const pl_mapping_hecht_times_t *h = &m->hecht_model;
    if (h->tau_P >= h->tau_G)
        pl_mapping_warn(m, PL_SEV_WARNING, "HECHT_TAU_P_G", h->tau_P / h->tau_G,
                        "tau_P/tau_G = %.3g >= 1 (Hecht Sec. VII.B: tau_P < tau_G so that particles relax "
                        "between Brownian encounters): lower coarse_graining.mean_free_path or cell_size",
                        h->tau_P / h->tau_G);
    if (isfinite(h->tau_V) && h->tau_P > h->tau_V / (4.0 * PL_PI)) {
        double r = h->tau_V / h->tau_P;
        int real_creeping = m->hecht_real.tau_P <= m->hecht_real.tau_V / (4.0 * PL_PI);
        pl_mapping_warn(m, PL_SEV_NOTE, "HECHT_CREEPING", r,
                        "tau_V/tau_P = %.3g < 4 pi (Hecht Eq. 27): contacts are not creeping in the model%s; "
                        "Hecht restores creeping with the lubrication force (Eq. 4) - keep it on",
                        r, real_creeping ? " although they are in reality" : "");
    }
    if (m->cg.md_dt > 0) {
        double shortest = h->tau_P;
        if (isfinite(h->tau_V) && h->tau_V < shortest) shortest = h->tau_V;
        double res = m->cg.md_resolution > 0 ? m->cg.md_resolution : 20.0;
        if (m->md_dt > shortest / res)
            pl_mapping_warn(m, PL_SEV_NOTE, "MD_STEP", shortest / m->md_dt,
                            "min(tau_V, tau_P) = %.3g MD steps < %.0f (Hecht Sec. II: ~20 steps per contact) "
                            "unless lubrication sets a smaller scale; check coarse_graining.md_dt",
                            shortest / m->md_dt, res);
    }
}

void pl_mapping_audit(pl_mapping_t *m)
{
    audit_numbers(m);
    audit_hierarchy(m);
    audit_hecht(m);
}
