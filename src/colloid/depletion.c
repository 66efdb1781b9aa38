/* Depletion potential of the ideal SRD fluid between two colloids (PL
 * Eqs. 22-23), its hard-sphere closed form (PL Eq. 24), PL's rule for
 * sigma_cc and the table of the compensating potential (PL Sec. III.C.1).
 *
 * Quadrature: for radial Mayer functions the overlap integral reduces, in
 * bipolar coordinates (r1, r2 = distances to the two centres,
 * d^3r = 2 pi r1 r2 dr1 dr2 / d on |r1 - r2| <= d <= r1 + r2), to
 *   I(d) = Int f(r1) f(r2) d^3r = (2 pi / d) J(d),
 *   J(d) = Int_0^rc r1 f(r1) [F(min(d + r1, rc)) - F(|d - r1|)] dr1,
 *   F(x) = Int_0^x r f(r) dr,
 * and its derivative to a single integral (the integrand of J vanishes at
 * the moving bound, so Leibniz adds nothing):
 *   J'(d) = Int_0^rc r1 f(r1) [(d + r1) f(d + r1) - (d - r1) f(|d - r1|)] dr1.
 * Both are GSL adaptive Gauss-Kronrod integrals with breakpoints at the
 * kinks r1 = d and r1 = rc - d.  Phi_depl = -n_f kT I (PL Eqs. 22-23 with
 * V_excl(d) - V_excl(inf) = -I(d)). */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <math.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/depletion.h"

enum { WS = 1000 };

typedef struct {
    const pl_depletion_params_t *p;
    double rc, d;
    gsl_integration_workspace *w_in;
    int status;
} ctx_t;

double pl_depletion_cf_cutoff(const pl_depletion_params_t *p)
{
    return p->hard_sphere ? p->sigma_cf : pow(2.0, 1.0 / p->n) * p->sigma_cf;
}

/* Mayer function of phi_cf (PL Eq. 17 with exponent n), or of hard spheres. */
static double mayer(const pl_depletion_params_t *p, double rc, double r)
{
    if (r >= rc) return 0.0;
    if (p->hard_sphere) return -1.0;
    double s = pow(p->sigma_cf / r, p->n);
    if (!(s < 1e100)) return -1.0; /* deep inside: exp(-beta phi) underflows */
    return expm1(-4.0 * p->epsilon_cf * (s * s - s + 0.25) / p->kT);
}

static double rf(double r, void *vp)
{
    const ctx_t *c = vp;
    return r * mayer(c->p, c->rc, r);
}

/* F(x) = Int_0^min(x, rc) r f(r) dr. */
static double big_f(ctx_t *c, double x)
{
    x = fmin(x, c->rc);
    if (x <= 0.0) return 0.0;
    gsl_function g = {rf, c};
    double v, e;
    int s = gsl_integration_qag(&g, 0.0, x, 1e-14 * c->rc * c->rc, 1e-12, WS, GSL_INTEG_GAUSS61,
                                c->w_in, &v, &e);
    if (s) c->status = s;
    return v;
}

static double j_integrand(double r1, void *vp)
{
    ctx_t *c = vp;
    double f1 = mayer(c->p, c->rc, r1);
    if (f1 == 0.0) return 0.0;
    return r1 * f1 * (big_f(c, c->d + r1) - big_f(c, fabs(c->d - r1)));
}

static double dj_integrand(double r1, void *vp)
{
    ctx_t *c = vp;
    double f1 = mayer(c->p, c->rc, r1), d = c->d;
    return r1 * f1 * ((d + r1) * mayer(c->p, c->rc, d + r1) - (d - r1) * mayer(c->p, c->rc, fabs(d - r1)));
}

/* d -> 0: I = 4 pi Int r^2 f^2 dr. */
static double r2f2(double r, void *vp)
{
    const ctx_t *c = vp;
    double f = mayer(c->p, c->rc, r);
    return r * r * f * f;
}

static int integrate(ctx_t *c, gsl_function *g, double lo, double hi, double d,
                     gsl_integration_workspace *w, double *out)
{
    double pts[4];
    size_t np = 0;
    pts[np++] = lo;
    double k1 = fmin(d, c->rc - d), k2 = fmax(d, c->rc - d); /* kinks, in order */
    if (k1 > lo && k1 < hi) pts[np++] = k1;
    if (k2 > lo && k2 < hi && k2 > pts[np - 1]) pts[np++] = k2;
    pts[np++] = hi;
    double err;
    double scale = c->rc * c->rc * c->rc * c->rc;
    return gsl_integration_qagp(g, pts, np, 1e-13 * scale, 1e-10, WS, w, out, &err);
}

int pl_depletion_potential(const pl_depletion_params_t *p, double d, double *phi, double *dphi,
                           pl_err_t *err)
{
    ctx_t c = {p, pl_depletion_cf_cutoff(p), d, NULL, 0};
    *phi = *dphi = 0.0;
    if (d >= 2.0 * c.rc) return 0;
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(WS);
    c.w_in = gsl_integration_workspace_alloc(WS);
    int s = 0;
    double pre = -p->density * p->kT; /* PL Eq. 22 */
    if (!w || !c.w_in) {
        s = GSL_ENOMEM;
    } else if (d < 1e-9 * c.rc) {
        gsl_function g = {r2f2, &c};
        double v, e;
        s = gsl_integration_qag(&g, 0.0, c.rc, 1e-14 * c.rc * c.rc * c.rc, 1e-12, WS,
                                GSL_INTEG_GAUSS61, w, &v, &e);
        *phi = pre * 4.0 * PL_PI * v;
    } else {
        double lo = fmax(0.0, d - c.rc), J = 0.0, dJ = 0.0; /* read only when both integrals succeeded */
        gsl_function gj = {j_integrand, &c}, gd = {dj_integrand, &c};
        s = integrate(&c, &gj, lo, c.rc, d, w, &J);
        if (!s) s = integrate(&c, &gd, lo, c.rc, d, w, &dJ);
        if (!s) s = c.status;
        *phi = pre * 2.0 * PL_PI / d * J;
        *dphi = pre * 2.0 * PL_PI / d * (dJ - J / d);
    }
    gsl_integration_workspace_free(w);
    gsl_integration_workspace_free(c.w_in);
    gsl_set_error_handler(old);
    if (s)
        return pl_err_set(err, PL_ERR_INPUT,
                          "depletion potential at d = %g (sigma_cf %g, epsilon_cf %g): GSL "
                          "quadrature failed: %s", d, p->sigma_cf, p->epsilon_cf, gsl_strerror(s));
    return 0;
}

double pl_depletion_hs(double sigma_cf, double density, double kT, double d)
{
    if (d >= 2.0 * sigma_cf) return 0.0;
    double x = d / sigma_cf; /* PL Eq. 24 */
    return -density * kT * 4.0 / 3.0 * PL_PI * sigma_cf * sigma_cf * sigma_cf *
           (1.0 - 0.75 * x + x * x * x / 16.0);
}

double pl_depletion_sigma_cc(double d_match, double eps_cc, double n, double energy)
{
    return d_match * pow(0.5 + sqrt(energy / (4.0 * eps_cc)), 1.0 / n);
}

int pl_depletion_table(const pl_depletion_params_t *p, int m, double *u, double *du,
                       pl_err_t *err)
{
    double h = 2.0 * pl_depletion_cf_cutoff(p) / m;
    for (int k = 0; k < m; ++k) {
        double phi, dphi;
        if (pl_depletion_potential(p, k * h, &phi, &dphi, err)) return err->code;
        u[k] = -phi; /* Phi_comp = -Phi_depl (PL Sec. III.C.1) */
        du[k] = -dphi;
    }
    u[m] = du[m] = 0.0;
    return 0;
}
