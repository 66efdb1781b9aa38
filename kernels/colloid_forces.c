/* Colloid pair forces, torques and energies over the Verlet neighbour list
 * (kernels/colloid_neighbors.c).
 *
 * Terms (each switched on by a bit of p->terms, one row each of the
 * pair-term table PL_PAIR_TERMS, formulas in colloid_pair.h and
 * colloid_pair_terms.h):
 *   DLVO: Hecht Eqs. 1-2 with the parabolic primary minimum (Hecht Sec. II)
 *   Hertz: Hecht Eq. 3, normal damping Hecht Eq. 6, tangential viscous
 *          friction on the relative surface velocity (Hecht Sec. II), torques
 *   lubrication: Hecht Eqs. 4-5, limited at a minimum gap, with its random
 *          partner when p->lub_noise > 0 (lubrication.thermal)
 *   WCA: PL Eq. 16 with exponent n
 *   depletion_comp: Phi_comp = -Phi_depl (PL Sec. III.C.1, Eqs. 22-23),
 *          cubic Hermite interpolation of the table built by src/colloid/depletion.c
 *
 * Race-free accumulation with Newton's third law: a half list, each pair
 * evaluated once by its owner.  Pass 1 (parallel over owners, static blocks)
 * evaluates the owner's pairs in ascending partner index, sums them into the
 * owner's force and torque and stores each pair's force (and the partner's
 * torque) for the partner.  Pass 2 (parallel over colloids) adds to each
 * colloid its reverse entries, the results of its pairs with other owners,
 * in ascending owner index.  Where the results lie (by slot or by reverse
 * entry) is the list's layout, chosen by the thread count
 * (pl_colloid_nlist_t); the values and the order of the sums are the same.
 * Every result is written by the thread of the pair's owner and read after
 * the barrier, so there are no races and no atomics; each sum is formed in an order fixed
 * by the indices alone, so the forces are bitwise identical for any thread
 * count and for any valid list (see colloid_neighbors.c).  Chosen over
 * per-thread force buffers because their reduction order would follow the
 * thread count (and their size grows with it); the slots cost 24 bytes per
 * pair (48 with torques).  One thread stores by slot and reads through
 * rslot: scattered stores that miss L1 slowed its owner pass more than
 * pass 2's scattered loads cost; with more threads, loads of lines another
 * core wrote cost more than stores (bench/RESULTS_colloid.md).
 *
 * Multiple time stepping (p->mts, colloids.slow_interval > 1): the pass over
 * the near list gives each pair's DLVO force times 1 - w (pl_pair_slow_share;
 * the rest, w times it, is kernels/colloid_slow.c's); every other term whole.
 *
 * The term mask is a compile-time constant inside each specialised loop
 * (owner_pairs is force-inlined into one case per mask), so a term that is off
 * costs nothing in the inner loop (DESIGN.md "Scene -> plan").  Energies are
 * computed only by the energy pass (pl_colloid_pair_energies), when asked for;
 * the force pass computes none (this file is built with -fno-math-errno so
 * the compiler drops the logarithm of the unused van der Waals energy). */
#include <math.h>

#include "colloid_block.h"
#include "peloid/colloid_kernels.h"
#include "peloid/colloid_pair_terms.h"
#include "peloid/rng.h"

/* The standard normal number of pair (i, j) for the force pass at MD step
 * p->noise_step: Philox with the counter (step, lower index, higher index),
 * so the same for either order, any thread count and after a restart. */
static inline double pair_gauss(const pl_colloid_pair_params_t *p, size_t i, size_t j)
{
    const size_t lo = i < j ? i : j, hi = i < j ? j : i;
    const pl_rand4_t u = pl_rng_uniform4(p->noise_seed, PL_RNG_LUB_NOISE, p->noise_step, lo, hi);
    return sqrt(-2.0 * log(u.u[0])) * cos(6.283185307179586476925 * u.u[1]); /* Box-Muller */
}

typedef struct {
    double f[3], t[3], e[PL_CE_NTERMS];
    double ov, om2, damp;
    int32_t jov, jom, jdamp;
} acc_t;

/* One pair, i the owner: adds i's torque (and, when E, the pair's whole
 * energy) to a, its guard maxima to a's, and returns in tj the torque on j
 * and in fo the force on i (zero beyond the cut-off), which the caller adds
 * to a->f in slot order.  T: term mask; E: energies wanted. */
static inline __attribute__((always_inline)) void pair_eval(
    const pl_colloid_pair_params_t *p, const pl_colloid_view_t *v, size_t i, size_t j, double dx,
    double dy, double dz, double r2, const unsigned T, const int E, const int M, acc_t *a,
    double fo[3], double tj[3])
{
    fo[0] = fo[1] = fo[2] = 0.0;
    tj[0] = tj[1] = tj[2] = 0.0;
    double ri = v->rad[i], rj = v->rad[j], d = ri + rj;
    const double rc = pl_colloid_pair_rc(p, T, d);
    if (r2 >= rc * rc) return;
    double r = sqrt(r2), inv = 1.0 / r;
    double ex = dx * inv, ey = dy * inv, ez = dz * inv;
    double h = r - d, delta = -h;
    double fr = 0.0, k2 = 0.0, zeta = 0.0;
    if (T & PL_CT_DLVO) {
        if (h < p->dlvo_hcut) {
            pl_pair_val_t s;
            if (h >= p->coul_hcut) { /* Eq. 1 below 1e-15 there: its exp skipped */
                s = pl_pair_vdw(r, d, p->hamaker);
                s.u -= p->dlvo_shift;
            } else if (h < p->prim_hm && d == p->prim_d) { /* the match point kept */
                s = pl_pair_parabola(h, p->prim_hm, p->prim_mu, p->prim_vp, p->prim_c, p->dlvo_shift);
            } else {
                s = pl_pair_dlvo(r, d, p->coul_C, p->kappa, p->hamaker, p->prim_hm, p->prim_h0,
                                 p->dlvo_shift);
            }
            if (M) { /* the fast share (multiple time stepping) */
                const double keep = 1.0 - pl_pair_slow_share(r2, d, p->mts_hin, p->mts_hout);
                fr += keep * s.f;
                k2 += keep * s.k2;
            } else {
                fr += s.f;
                k2 += s.k2;
            }
            if (E) a->e[PL_CE_DLVO] += s.u;
        }
    }
    /* the RADIAL rows of the pair-term table, in row order */
#define RADIAL_OWN(ID, slot)
#define RADIAL_RADIAL(ID, slot)                                   \
    if ((T & PL_CT_##ID) && r < pl_pair_rc_##ID(p, d)) {          \
        pl_pair_val_t s = pl_pair_term_##ID(p, r, d);             \
        fr += s.f;                                                \
        k2 += s.k2;                                               \
        if (E) a->e[slot] += s.u;                                 \
    }
#define RADIAL_ROW(ID, id, name, slot, kind) RADIAL_##kind(ID, slot)
    PL_PAIR_TERMS(RADIAL_ROW)
#undef RADIAL_ROW
#undef RADIAL_RADIAL
#undef RADIAL_OWN
    /* relative velocity: only the dissipative terms read it */
    double vrx = 0.0, vry = 0.0, vrz = 0.0, vn = 0.0;
    if (((T & PL_CT_HERTZ) && delta > 0.0) || ((T & PL_CT_LUB) && h < p->lub_hcut)) {
        vrx = v->vx[i] - v->vx[j];
        vry = v->vy[i] - v->vy[j];
        vrz = v->vz[i] - v->vz[j];
        vn = vrx * ex + vry * ey + vrz * ez;
    }
    if ((T & PL_CT_HERTZ) && delta > 0.0) {
        pl_pair_val_t s = pl_pair_hertz(delta, p->hertz_K);
        fr += s.f;
        k2 += s.k2;
        if (E) a->e[PL_CE_HERTZ] += s.u;
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
            fo[0] = ftx;
            fo[1] = fty;
            fo[2] = ftz;
            /* torques (-a_i e) x F_t on i and (a_j e) x (-F_t) on j */
            double cx = ey * ftz - ez * fty, cy = ez * ftx - ex * ftz, cz = ex * fty - ey * ftx;
            a->t[0] -= ai * cx;
            a->t[1] -= ai * cy;
            a->t[2] -= ai * cz;
            tj[0] = -(aj * cx);
            tj[1] = -(aj * cy);
            tj[2] = -(aj * cz);
            zeta += gt;
        }
    }
    if ((T & PL_CT_LUB) && h < p->lub_hcut) {
        double zl = pl_pair_lub_zeta(h, ri, rj, p->lub_eta, p->lub_hmin, p->lub_hcut);
        zeta += zl;
        fr -= zl * vn; /* Hecht Eq. 4 */
        /* its random partner (fluctuation-dissipation, as DPD's: Espanol &
         * Warren 1995), sigma = sqrt(2 kT zeta / dt); the draw is the
         * pair's own, symmetric in i and j, so either owner gives F_i =
         * sigma g e_ij and F_j = -F_i; the guard's zeta is the friction's */
        if (!E && p->lub_noise != 0.0) fr += p->lub_noise * sqrt(zl) * pair_gauss(p, i, j);
    }
    fo[0] += fr * ex;
    fo[1] += fr * ey;
    fo[2] += fr * ez;
    if (delta > 0.0) { /* the maximum starts at 0: only overlaps can raise it */
        double ov = delta / d;
        if (ov > a->ov) { a->ov = ov; a->jov = (int32_t)j; }
    }
    /* k2 / m_red > max as k2 (m_i + m_j) > max m_i m_j: the division only
     * when the maximum grows */
    double msum = v->mass[i] + v->mass[j], mprod = v->mass[i] * v->mass[j];
    if (k2 * msum > a->om2 * mprod) { a->om2 = k2 * msum / mprod; a->jom = (int32_t)j; }
    if (zeta * msum > a->damp * mprod) { a->damp = zeta * msum / mprod; a->jdamp = (int32_t)j; }
}

/* The pairs colloid i owns: pass 1 (E = 0: forces, torques, guard maxima,
 * pair slots) or the energy pass (E = 1: only the owner's pair energies).
 * M: only the fast share of the DLVO force (multiple time stepping). */
static inline __attribute__((always_inline)) void owner_pairs(const pl_colloid_pair_params_t *p,
                                                              const pl_colloid_nlist_t *nl,
                                                              const pl_colloid_view_t *v, size_t i,
                                                              const unsigned T, const int E,
                                                              const int M)
{
    acc_t a = {{0}, {0}, {0}, 0.0, 0.0, 0.0, -1, -1, -1};
    const double L[3] = {p->box[0], p->box[1], p->box[2]};
    const double iL[3] = {1.0 / L[0], 1.0 / L[1], 1.0 / L[2]};
    const int per[3] = {p->periodic[0], p->periodic[1], p->periodic[2]};
    const double pL[3] = {per[0] ? L[0] : 0.0, per[1] ? L[1] : 0.0, per[2] ? L[2] : 0.0};
    const double xi = v->x[i], yi = v->y[i], zi = v->z[i];
    /* far pairs, vectorised: beyond every term but the van der Waals tail of
     * Eq. 2 (gap >= far_gap, outside the ranges of the RADIAL terms) the force
     * is F/r = -A d^6 / (6 r^4 (r^2 - d^2)^2), no square root; the pairs of
     * a block are classified and these forces computed in SIMD lanes, then
     * added in slot order with the others (so the sums keep their order) */
    enum { BLK = 32 };
    const int FAR = !E && (T & PL_CT_DLVO);
    double bfx[BLK], bfy[BLK], bfz[BLK], bcls[BLK]; /* bcls: 0 out of range, 1 far, 2 other */
    const int TQ = (T & PL_CT_HERTZ) && p->hertz_gamma_t > 0.0; /* torques on the partners */
    double btx[BLK], bty[BLK], btz[BLK];
    const double far_gap = (T & PL_CT_LUB) && p->lub_hcut > p->coul_hcut ? p->lub_hcut : p->coul_hcut;
    /* fast share (M): from the gap mts_hout on the DLVO force is all slow,
     * so only lubrication keeps those pairs off the van der Waals path */
    const double far_gap_m = fmax(fmin(p->mts_hout, p->coul_hcut), (T & PL_CT_LUB) ? p->lub_hcut : 0.0);
    const double ri = v->rad[i];
    for (int32_t s0 = nl->start[i]; s0 < nl->start[i + 1]; s0 += BLK) {
        const int m = nl->start[i + 1] - s0 < BLK ? nl->start[i + 1] - s0 : BLK;
        if (FAR) {
            /* the partners' coordinates first copied into contiguous block
             * arrays, which the SIMD loop reads with plain vector loads */
            double gx[BLK], gy[BLK], gz[BLK], gr[BLK];
            pl_colloid_gather_block(nl, s0, m, v->x, v->y, v->z, v->rad, gx, gy, gz, gr);
#pragma omp simd
            for (int k = 0; k < m; ++k) {
                double dx = xi - gx[k], dy = yi - gy[k], dz = zi - gz[k];
                /* minimum image without a branch: on a closed axis pL = 0
                 * and dx - 0 is dx exactly */
                dx -= pL[0] * rint(dx * iL[0]);
                dy -= pL[1] * rint(dy * iL[1]);
                dz -= pL[2] * rint(dz * iL[2]);
                double r2 = dx * dx + dy * dy + dz * dz;
                /* rf: beyond the far gap and every RADIAL term's range */
                const double d = ri + gr[k], rc = pl_colloid_pair_rc(p, T, d);
                const double rf = pl_colloid_pair_rc_from(p, T & PL_CT_RADIAL, d, d + (M ? far_gap_m : far_gap));
                double rd = d + p->dlvo_hcut;
                int in = r2 < rc * rc, far = in & (r2 >= rf * rf) & (r2 < rd * rd);
                /* lanes that are not far compute on harmless operands and
                 * are zeroed (selects of values, no branch) */
                double d2 = d * d, r2f = far ? r2 : 2.0, sf = far ? r2 - d2 : 1.0;
                double ir2 = 1.0 / r2f, is = 1.0 / sf;
                double fc = -(p->hamaker * d2 * d2 * d2 / 6.0) * (ir2 * ir2) * (is * is);
                double fm = far ? 1.0 : 0.0;
                if (M) fm *= 1.0 - pl_pair_slow_share(r2, d, p->mts_hin, p->mts_hout);
                bfx[k] = fm * (fc * dx);
                bfy[k] = fm * (fc * dy);
                bfz[k] = fm * (fc * dz);
                bcls[k] = in ? (far ? 1.0 : 2.0) : 0.0;
            }
        }
        if (FAR) {
            /* the other pairs (class 2) one by one in slot order, their
             * forces into the block arrays; then the sums in slot order and
             * the pair slots, each in a loop of its own (the same sums
             * in the same order as one loop over the slots, in registers);
             * the van der Waals tail and out of range: no torque */
            if (TQ)
                for (int k = 0; k < m; ++k) btx[k] = bty[k] = btz[k] = 0.0;
            for (int k = 0; k < m; ++k) {
                if (bcls[k] != 2.0) continue;
                const size_t j = (size_t)nl->nbr[s0 + k];
                double dx = xi - v->x[j], dy = yi - v->y[j], dz = zi - v->z[j];
                pl_colloid_min_image(per, L, iL, &dx, &dy, &dz);
                double fo[3], tj[3];
                pair_eval(p, v, i, j, dx, dy, dz, dx * dx + dy * dy + dz * dz, T, E, M, &a, fo, tj);
                bfx[k] = fo[0];
                bfy[k] = fo[1];
                bfz[k] = fo[2];
                if (TQ) {
                    btx[k] = tj[0];
                    bty[k] = tj[1];
                    btz[k] = tj[2];
                }
            }
            double sx = a.f[0], sy = a.f[1], sz = a.f[2];
            for (int k = 0; k < m; ++k) {
                sx += bfx[k];
                sy += bfy[k];
                sz += bfz[k];
            }
            a.f[0] = sx;
            a.f[1] = sy;
            a.f[2] = sz;
            for (int k = 0; k < m; ++k) pl_colloid_pair_store(nl, nl->pf, s0 + k, bfx[k], bfy[k], bfz[k]);
            if (TQ)
                for (int k = 0; k < m; ++k) pl_colloid_pair_store(nl, nl->pt, s0 + k, btx[k], bty[k], btz[k]);
            continue;
        }
        for (int k = 0; k < m; ++k) {
            const int32_t s = s0 + k;
            double fo[3], tj[3];
            size_t j = (size_t)nl->nbr[s];
            double dx = xi - v->x[j], dy = yi - v->y[j], dz = zi - v->z[j];
            pl_colloid_min_image(per, L, iL, &dx, &dy, &dz);
            pair_eval(p, v, i, j, dx, dy, dz, dx * dx + dy * dy + dz * dz, T, E, M, &a, fo, tj);
            a.f[0] += fo[0];
            a.f[1] += fo[1];
            a.f[2] += fo[2];
            if (!E) {
                pl_colloid_pair_store(nl, nl->pf, s, fo[0], fo[1], fo[2]);
                if (TQ) pl_colloid_pair_store(nl, nl->pt, s, tj[0], tj[1], tj[2]);
            }
        }
    }
    if (E) {
        /* every energy slot but the external ones (pl_colloid_ext_forces writes those) */
        for (int k = 0; k < PL_CE_NTERMS; ++k)
            if (k != PL_CE_WALL && k != PL_CE_GRAVITY) v->epot[(size_t)k * v->n + i] = a.e[k];
        return;
    }
    v->fx[i] = a.f[0];
    v->fy[i] = a.f[1];
    v->fz[i] = a.f[2];
    v->tx[i] = a.t[0];
    v->ty[i] = a.t[1];
    v->tz[i] = a.t[2];
    v->g_overlap[i] = a.ov;
    v->g_omega2[i] = a.om2;
    v->g_damp[i] = a.damp;
    v->g_partner[i] = a.jov;
    v->g_partner[v->n + i] = a.jom;
    v->g_partner[2 * v->n + i] = a.jdamp;
}

/* One worksharing loop per term mask inside one parallel region: the switch
 * runs in the outlined region, so each case calls owner_pairs with a literal
 * mask and the compiler specialises it (a mask passed into the region as a
 * variable would not be constant there).  Static schedule: equal blocks of
 * owners; the owner rule spreads the pairs evenly over indices. */
#define CASE(m)                                                                            \
    case m:                                                                                \
        if (((m) & PL_CT_DLVO) && !E && p->mts) {                                          \
            _Pragma("omp for schedule(static)") for (size_t i = 0; i < v->n; ++i)          \
                owner_pairs(p, nl, v, i, m, E, 1);                                         \
        } else {                                                                           \
            _Pragma("omp for schedule(static)") for (size_t i = 0; i < v->n; ++i)          \
                owner_pairs(p, nl, v, i, m, E, 0);                                         \
        }                                                                                  \
        break;
/* Every mask 0..PL_CT_ALL, by doubling: level k lists the 2^k masks from
 * b; the table's row count PL_PAIR_NTERMS picks the level. */
#define CASES_0(b) CASE((b))
#define CASES_1(b) CASES_0(b) CASES_0((b) + 1)
#define CASES_2(b) CASES_1(b) CASES_1((b) + 2)
#define CASES_3(b) CASES_2(b) CASES_2((b) + 4)
#define CASES_4(b) CASES_3(b) CASES_3((b) + 8)
#define CASES_5(b) CASES_4(b) CASES_4((b) + 16)
#define CASES_6(b) CASES_5(b) CASES_5((b) + 32)
#define CASES_7(b) CASES_6(b) CASES_6((b) + 64)
#define CASES_AT_(n) CASES_##n(0)
#define CASES_AT(n) CASES_AT_(n)
_Static_assert(PL_PAIR_NTERMS <= 7, "add a CASES level");
#define ALL_CASES CASES_AT(PL_PAIR_NTERMS)

/* Pass 1 as an orphaned worksharing loop (call it from every thread of a
 * parallel region, or outside one): the implicit barrier of its loop ends it. */
void pl_colloid_pair_owner_pass(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                                const pl_colloid_view_t *v)
{
    enum { E = 0 };
    const unsigned mask = p->terms & PL_CT_ALL;
    switch (mask) { ALL_CASES }
}

void pl_colloid_pair_forces(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                            const pl_colloid_view_t *v, int nthreads)
{
    const int torques = pl_colloid_pair_torques(p);
    /* one parallel region: pass 1, the barrier of its loop, pass 2 */
#pragma omp parallel num_threads(nthreads) if (v->n >= PL_COLLOID_OMP_MIN)
    {
        pl_colloid_pair_owner_pass(p, nl, v);
#pragma omp for schedule(static)
        for (size_t i = 0; i < v->n; ++i) pl_colloid_pair_reverse_one(nl, v, i, torques);
    }
}

void pl_colloid_pair_energies(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                              const pl_colloid_view_t *v, int nthreads)
{
    enum { E = 1 };
    const unsigned mask = p->terms & PL_CT_ALL;
#pragma omp parallel num_threads(nthreads) if (v->n >= PL_COLLOID_OMP_MIN)
    switch (mask) { ALL_CASES }
}

/* One pair's conservative energy by the kernel's own pair evaluation (the
 * energy pass's formula): a two-colloid view at rest, colloid 1 at distance r
 * along x from colloid 0. */
double pl_colloid_pair_energy(const pl_colloid_pair_params_t *p, double r, double ri, double rj)
{
    const double rad[2] = {ri, rj}, one[2] = {1.0, 1.0}, zero[2] = {0.0, 0.0};
    const pl_colloid_view_t v = {.n = 2, .x = zero, .y = zero, .z = zero, .vx = zero, .vy = zero,
                                 .vz = zero, .wx = zero, .wy = zero, .wz = zero, .rad = rad, .mass = one};
    acc_t a = {{0}, {0}, {0}, 0.0, 0.0, 0.0, -1, -1, -1};
    double fo[3], tj[3];
    pair_eval(p, &v, 0, 1, r, 0.0, 0.0, r * r, p->terms & PL_CT_ALL, 1, 0, &a, fo, tj);
    double u = 0.0; /* the energies of the table's rows, in row order */
#define SUM_ROW(ID, id, name, slot, kind) \
    if ((slot) != PL_CE_NONE) u += a.e[(slot) < 0 ? 0 : (slot)];
    PL_PAIR_TERMS(SUM_ROW)
#undef SUM_ROW
    return u;
}
