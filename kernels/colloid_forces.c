/* Colloid pair forces and torques over linked cells.
 *
 * Terms (each switched on by a bit of p->terms, formulas in colloid_pair.h):
 *   DLVO: Hecht Eqs. 1-2 with the parabolic primary minimum (Hecht Sec. II)
 *   Hertz: Hecht Eq. 3, normal damping Hecht Eq. 6, tangential viscous
 *          friction on the relative surface velocity (Hecht Sec. II), torques
 *   lubrication: Hecht Eqs. 4-5, limited at a minimum gap
 *   WCA: PL Eq. 16 with exponent n
 *   depletion_comp: Phi_comp = -Phi_depl (PL Sec. III.C.1, Eqs. 22-23),
 *          cubic Hermite interpolation of the table built by src/depletion.c
 *
 * Race-free accumulation: full neighbour lists without Newton's third law.
 * Thread t owns a static block of particles i and writes only f[i], t[i],
 * epot[., i] and the guard slots of i; each pair is evaluated twice (once
 * from each side).  The partners of i are visited in a fixed order (neighbour
 * cells in fixed offset order, particles within a cell in index order), so
 * each sum is formed in the same order for any thread count: the forces are
 * bitwise identical for 1, 2, ... threads.
 *
 * The term mask is a compile-time constant inside each specialised loop
 * (pair_loop is force-inlined into one case per mask), so a term that is off
 * costs nothing in the inner loop (DESIGN.md "Scene -> plan"). */
#include <math.h>

#include "peloid/colloid_kernels.h"
#include "peloid/colloid_pair.h"
#include "peloid/depletion.h"

typedef struct {
    double f[3], t[3], e[PL_CE_NTERMS];
    double ov, om2, damp;
    int32_t jov, jom, jdamp;
} acc_t;

static inline __attribute__((always_inline)) void pair_eval(
    const pl_colloid_pair_params_t *p, const pl_colloid_view_t *v, size_t i, size_t j, double dx,
    double dy, double dz, double r2, const unsigned T, acc_t *a)
{
    double ri = v->rad[i], rj = v->rad[j], d = ri + rj;
    double rc = d + p->gap_cut;
    double wsig = 0.0, wrc = 0.0;
    if (T & PL_CT_WCA) {
        wsig = p->wca_sigma > 0.0 ? p->wca_sigma : d;
        wrc = wsig * p->wca_rfac;
        if (wrc > rc) rc = wrc;
    }
    if ((T & PL_CT_DEPL) && p->dep_rc > rc) rc = p->dep_rc;
    if (r2 >= rc * rc) return;
    double r = sqrt(r2), inv = 1.0 / r;
    double ex = dx * inv, ey = dy * inv, ez = dz * inv;
    double h = r - d, delta = -h;
    double fr = 0.0, k2 = 0.0, zeta = 0.0;
    double mred = v->mass[i] * v->mass[j] / (v->mass[i] + v->mass[j]);
    if (T & PL_CT_DLVO) {
        if (h < p->dlvo_hcut) {
            pl_pair_val_t s = pl_pair_dlvo(r, d, p->coul_C, p->kappa, p->hamaker, p->prim_hm,
                                           p->prim_h0, p->dlvo_shift);
            fr += s.f;
            k2 += s.k2;
            a->e[PL_CE_DLVO] += 0.5 * s.u;
        }
    }
    if (T & PL_CT_WCA) {
        if (r < wrc) {
            pl_pair_val_t s = pl_pair_wca(r, wsig, p->wca_eps, p->wca_n);
            fr += s.f;
            k2 += s.k2;
            a->e[PL_CE_WCA] += 0.5 * s.u;
        }
    }
    if ((T & PL_CT_DEPL) && r < p->dep_rc) {
        double u, f, kk;
        pl_depletion_table_eval(p->dep_u, p->dep_du, p->dep_inv_h, r, &u, &f, &kk);
        fr += f;
        k2 += kk;
        a->e[PL_CE_DEPL] += 0.5 * u;
    }
    double vrx = v->vx[i] - v->vx[j], vry = v->vy[i] - v->vy[j], vrz = v->vz[i] - v->vz[j];
    double vn = vrx * ex + vry * ey + vrz * ez;
    if ((T & PL_CT_HERTZ) && delta > 0.0) {
        pl_pair_val_t s = pl_pair_hertz(delta, p->hertz_K);
        fr += s.f;
        k2 += s.k2;
        a->e[PL_CE_HERTZ] += 0.5 * s.u;
        double zd = p->hertz_beta * sqrt(delta); /* Hecht Eq. 6 */
        zeta += zd;
        fr -= zd * vn;
        if (p->hertz_gamma_t > 0.0) {
            /* tangential friction at the middle of the overlap lens: lever
             * arms a_i + a_j = r, so the force couple carries no moment and
             * total angular momentum is conserved */
            double ai = ri - 0.5 * delta, aj = rj - 0.5 * delta;
            double wx = ai * v->wx[i] + aj * v->wx[j];
            double wy = ai * v->wy[i] + aj * v->wy[j];
            double wz = ai * v->wz[i] + aj * v->wz[j];
            double sx = vrx - (wy * ez - wz * ey);
            double sy = vry - (wz * ex - wx * ez);
            double sz = vrz - (wx * ey - wy * ex);
            double sn = sx * ex + sy * ey + sz * ez;
            double gt = p->hertz_gamma_t;
            double ftx = -gt * (sx - sn * ex), fty = -gt * (sy - sn * ey), ftz = -gt * (sz - sn * ez);
            a->f[0] += ftx;
            a->f[1] += fty;
            a->f[2] += ftz;
            /* torque (-a_i e) x F_t */
            a->t[0] -= ai * (ey * ftz - ez * fty);
            a->t[1] -= ai * (ez * ftx - ex * ftz);
            a->t[2] -= ai * (ex * fty - ey * ftx);
            zeta += gt;
        }
    }
    if ((T & PL_CT_LUB) && h < p->lub_hcut) {
        double zl = pl_pair_lub_zeta(h, ri, rj, p->lub_eta, p->lub_hmin, p->lub_hcut);
        zeta += zl;
        fr -= zl * vn; /* Hecht Eq. 4 */
    }
    a->f[0] += fr * ex;
    a->f[1] += fr * ey;
    a->f[2] += fr * ez;
    double ov = delta / d;
    if (ov > a->ov) { a->ov = ov; a->jov = (int32_t)j; }
    double om2 = k2 / mred;
    if (om2 > a->om2) { a->om2 = om2; a->jom = (int32_t)j; }
    double dr = zeta / mred;
    if (dr > a->damp) { a->damp = dr; a->jdamp = (int32_t)j; }
}

static inline __attribute__((always_inline)) void pair_loop(const pl_colloid_pair_params_t *p,
                                                            const pl_colloid_cells_t *c,
                                                            const pl_colloid_view_t *v,
                                                            const unsigned T)
{
    const int *nc = c->nc;
    int lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {
        lo[d] = nc[d] == 1 ? 0 : -1;
        hi[d] = nc[d] == 1 ? 0 : 1;
    }
    double L[3] = {p->box[0], p->box[1], p->box[2]};
    double iL[3] = {1.0 / L[0], 1.0 / L[1], 1.0 / L[2]};
    /* static schedule: equal blocks of particles; the cost per particle is
     * nearly uniform at the densities of interest */
#pragma omp parallel for schedule(static) if (v->n >= PL_COLLOID_OMP_MIN)
    for (size_t i = 0; i < v->n; ++i) {
        acc_t a = {{0}, {0}, {0}, 0.0, 0.0, 0.0, -1, -1, -1};
        int32_t ci = c->cell[i];
        int cx = ci % nc[0], cy = (ci / nc[0]) % nc[1], cz = ci / (nc[0] * nc[1]);
        for (int oz = lo[2]; oz <= hi[2]; ++oz) {
            int zz = cz + oz;
            if (zz < 0 || zz >= nc[2]) {
                if (!p->periodic[2]) continue;
                zz = (zz + nc[2]) % nc[2];
            }
            for (int oy = lo[1]; oy <= hi[1]; ++oy) {
                int yy = cy + oy;
                if (yy < 0 || yy >= nc[1]) {
                    if (!p->periodic[1]) continue;
                    yy = (yy + nc[1]) % nc[1];
                }
                for (int ox = lo[0]; ox <= hi[0]; ++ox) {
                    int xx = cx + ox;
                    if (xx < 0 || xx >= nc[0]) {
                        if (!p->periodic[0]) continue;
                        xx = (xx + nc[0]) % nc[0];
                    }
                    int32_t cc = (zz * nc[1] + yy) * nc[0] + xx;
                    for (int32_t k = c->start[cc]; k < c->start[cc + 1]; ++k) {
                        size_t j = (size_t)c->list[k];
                        if (j == i) continue;
                        double dx = v->x[i] - v->x[j], dy = v->y[i] - v->y[j], dz = v->z[i] - v->z[j];
                        if (p->periodic[0]) dx -= L[0] * rint(dx * iL[0]);
                        if (p->periodic[1]) dy -= L[1] * rint(dy * iL[1]);
                        if (p->periodic[2]) dz -= L[2] * rint(dz * iL[2]);
                        pair_eval(p, v, i, j, dx, dy, dz, dx * dx + dy * dy + dz * dz, T, &a);
                    }
                }
            }
        }
        v->fx[i] = a.f[0];
        v->fy[i] = a.f[1];
        v->fz[i] = a.f[2];
        v->tx[i] = a.t[0];
        v->ty[i] = a.t[1];
        v->tz[i] = a.t[2];
        if (v->epot)
            for (int e = 0; e < PL_CE_NTERMS; ++e) v->epot[(size_t)e * v->n + i] = a.e[e];
        v->g_overlap[i] = a.ov;
        v->g_omega2[i] = a.om2;
        v->g_damp[i] = a.damp;
        v->g_partner[i] = a.jov;
        v->g_partner[v->n + i] = a.jom;
        v->g_partner[2 * v->n + i] = a.jdamp;
    }
}

#define CASE(m) \
    case m: pair_loop(p, cells, v, m); break;

void pl_colloid_pair_forces(const pl_colloid_pair_params_t *p, const pl_colloid_cells_t *cells,
                            const pl_colloid_view_t *v)
{
    switch (p->terms & PL_CT_ALL) {
        CASE(0) CASE(1) CASE(2) CASE(3) CASE(4) CASE(5) CASE(6) CASE(7)
        CASE(8) CASE(9) CASE(10) CASE(11) CASE(12) CASE(13) CASE(14) CASE(15)
        CASE(16) CASE(17) CASE(18) CASE(19) CASE(20) CASE(21) CASE(22) CASE(23)
        CASE(24) CASE(25) CASE(26) CASE(27) CASE(28) CASE(29) CASE(30) CASE(31)
    }
}
