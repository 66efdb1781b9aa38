/* The shipped resolution table of coupling I (issue 45: a new suspension in
 * seconds).  A resolution study measured, for one model fluid, the
 * hydrodynamic radius of a coupling I colloid at several resolutions R/a0
 * and fitted R/R_h - 1 = b + c a0/R (tools/rh_resolution.py, rules
 * validation/RULES_rh_resolution.md, calibration/rh_resolution-X.json; read
 * by advise_match.c).  A colloid's friction is xi = 6 pi eta R_h (Stokes,
 * stick: the law's own definition of R_h), so where a scene's fluid is a
 * table's and its R/a0 lies between the table's smallest and largest
 * measured resolution, its unbounded diffusion coefficient is
 *     D_inf = kT / (6 pi eta R_h),  R_h = R / (1 + b + c a0/R),
 * (kT = 1, eta = gamma nu of the mapping, PL Eq. 13) with no calibration run.
 * Its relative standard error is R_h's: the law's covariance propagated,
 * g^T C g with g = dR_h/d(b, c) = -R_h^2/R (1, a0/R), the covariance scaled
 * by chi2/dof where that exceeds 1.  Interpolation only: outside the
 * measured range, with another fluid, or a colloid lighter than
 * TABLE_MIN_MASS the table gives nothing and the calibration runs as before.
 * The measured R_h came from settling (friction F/u, Hasimoto's images
 * removed), the calibration's from the MSD; tests/cli/calibration_table.sh
 * compares the two where both exist (Hecht Table I's resolution). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "advise_match.h"
#include "peloid/real.h" /* PL_PI */
#include "peloid/run.h"

/* The friction of the collisions depends on the colloid's mass through the
 * reduced mass m_f M / (m_f + M) only (PL Eq. 40, Enskog): above 100 m_f it
 * is within 1 % of the heavy-colloid limit the studies measured (their
 * colloids: 300 m_f and more). */
static const double TABLE_MIN_MASS = 100.0;

int pl_calibration_table(const pl_scene_t *sc, const char *dir, pl_mapping_calibration_t *cal)
{
    if (!dir || sc->coupling.method != PL_COUPLE_HECHT1) return 0;
    pl_advise_match_t *m = malloc(sizeof *m);
    if (!m) return 0; /* the calibration runs instead */
    pl_advise_match(sc, dir, m);
    const double R = sc->colloids.radius, x = 1.0 / R;
    const double M = sc->colloids.mass_density * 4.0 / 3.0 * PL_PI * R * R * R;
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < m->npoints; ++k) {
        lo = fmin(lo, m->R[k]);
        hi = fmax(hi, m->R[k]);
    }
    const pl_mapping_t *mp = &sc->mapping.map;
    const double eta = mp->cg.gamma * mp->nu_sim;
    int hit = m->found && m->law_nparams > 0 && m->npoints >= 2 && R >= lo * (1.0 - 1e-9) &&
              R <= hi * (1.0 + 1e-9) && M >= TABLE_MIN_MASS && eta > 0;
    if (hit) {
        const double y = m->law_b + m->law_c * x, rh = R / (1.0 + y);
        const double g[2] = {-rh * rh / R, -rh * rh / R * x}; /* dR_h/db, dR_h/dc */
        double var = 0.0;
        if (m->law_nparams == 1) var = g[1] * g[1] * m->law_cov[0][0];
        else
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j) var += g[i] * g[j] * m->law_cov[i][j];
        if (m->law_dof > 0 && m->law_chi2 > m->law_dof) var *= m->law_chi2 / m->law_dof;
        const double d = 1.0 / (6.0 * PL_PI * eta * rh); /* kT = 1 */
        hit = rh > 0 && isfinite(d) && var >= 0.0;
        if (hit) {
            memset(cal, 0, sizeof *cal);
            cal->d_inf = d;
            cal->d_inf_se = d * sqrt(var) / rh;
            cal->concentration = 1.0;
            cal->source = PL_CALSRC_TABLE;
            cal->table_rh_over_R = rh / R;
            cal->table_R_lo = lo;
            cal->table_R_hi = hi;
            snprintf(cal->cache, sizeof cal->cache, "%.*s", (int)sizeof cal->cache - 1, m->path);
        }
    }
    free(m);
    return hit;
}
