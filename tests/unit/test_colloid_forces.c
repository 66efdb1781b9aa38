/* Colloid pair terms: force = -dU/dr by central finite differences, the
 * curvature U'' likewise, closed-form values at hand-computed points, the
 * DLVO secondary minimum of two Hecht Fig. 1 parameter sets, the parabolic
 * primary minimum, the cut-off, and the neighbour-list kernel against a
 * direct O(N^2) pair sum (fresh, while colloids move, with another skin). */
#include <criterion/criterion.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/colloid.h"
#include "peloid/colloid_pair.h"

/* Central difference with step h: truncation error ~ h^2 U'''/6, rounding
 * ~ eps U / h; with h = 1e-7 r both are < 1e-8 relative, so 1e-6 is safe. */
#define FD_TOL 1e-6

typedef pl_pair_val_t (*fn_t)(double r, const double *a);

static void check_fd(fn_t f, const double *a, double r, const char *what)
{
    double h = 1e-7 * r;
    pl_pair_val_t v = f(r, a), p = f(r + h, a), m = f(r - h, a);
    double fd = -(p.u - m.u) / (2 * h), k2 = -(p.f - m.f) / (2 * h);
    cr_expect(fabs(fd - v.f) <= FD_TOL * (fabs(v.f) + fabs(v.u) / r + 1e-12),
              "%s r=%g: F=%.12g, -dU/dr=%.12g", what, r, v.f, fd);
    cr_expect(fabs(k2 - v.k2) <= FD_TOL * (fabs(v.k2) + fabs(v.f) / r + 1e-12),
              "%s r=%g: U''=%.12g, FD=%.12g", what, r, v.k2, k2);
}

static pl_pair_val_t f_coul(double r, const double *a) { return pl_pair_coulomb(r, a[0], a[1], a[2]); }
static pl_pair_val_t f_vdw(double r, const double *a) { return pl_pair_vdw(r, a[0], a[1]); }
static pl_pair_val_t f_dlvo(double r, const double *a)
{
    return pl_pair_dlvo(r, a[0], a[1], a[2], a[3], a[4], a[5], a[6]);
}
static pl_pair_val_t f_hertz(double r, const double *a)
{
    pl_pair_val_t v = pl_pair_hertz(a[0] - r, a[1]); /* dU/dr = -dU/ddelta */
    return v;
}
static pl_pair_val_t f_wca(double r, const double *a) { return pl_pair_wca(r, a[0], a[1], a[2]); }

Test(colloid_forces, fd_each_term)
{
    double ac[] = {4.0, 37.0, 0.7};
    double av[] = {4.0, 11.5};
    double aw24[] = {4.0, 2.5, 24.0}, aw6[] = {4.0, 2.5, 6.0};
    double ah[] = {4.0, 1e3};
    for (double r = 4.01; r < 8.0; r += 0.37) {
        check_fd(f_coul, ac, r, "coulomb");
        check_fd(f_vdw, av, r, "vdw");
    }
    for (double r = 3.9; r < 4.0 * pow(2.0, 1.0 / 24.0); r += 0.01) check_fd(f_wca, aw24, r, "wca24");
    for (double r = 3.7; r < 4.0 * pow(2.0, 1.0 / 6.0); r += 0.05) check_fd(f_wca, aw6, r, "wca6");
    for (double r = 3.6; r < 3.999; r += 0.03) check_fd(f_hertz, ah, r, "hertz");
    /* DLVO with the primary parabola, on both sides of the match gap */
    pl_scene_dlvo_t s = {81, 20, 1, 300, 1.4e8, 4.76e-20, 1.25e-7, 6.0, 0.0, 1e-3};
    pl_colloid_pair_params_t p;
    pl_colloid_dlvo_info_t info;
    pl_err_t err;
    cr_assert_eq(pl_colloid_dlvo_setup(&s, 4.0, &p, &info, &err), 0, "%s", err.msg);
    double ad[] = {4.0, p.coul_C, p.kappa, p.hamaker, p.prim_hm, p.prim_h0, p.dlvo_shift};
    for (double h = 0.0005; h < info.hcut; h *= 1.3) check_fd(f_dlvo, ad, 4.0 + h, "dlvo");
    /* C^1 at the match gap: value and force agree from both sides to 1e-9 */
    double hm = p.prim_hm;
    pl_pair_val_t lo = f_dlvo(4.0 + hm * (1 - 1e-12), ad), hi = f_dlvo(4.0 + hm * (1 + 1e-12), ad);
    cr_expect(fabs(lo.u - hi.u) < 1e-9 && fabs(lo.f - hi.f) < 1e-9 * (1 + fabs(hi.f)),
              "match gap: U %.12g|%.12g F %.12g|%.12g", lo.u, hi.u, lo.f, hi.f);
    /* minimum of the parabola: -D (+ the cut-off shift) at h0 with zero force */
    pl_pair_val_t m = f_dlvo(4.0 + p.prim_h0, ad);
    cr_expect(fabs(m.u + p.dlvo_shift + 6.0) < 1e-9, "primary minimum %.12g, want -6", m.u + p.dlvo_shift);
    cr_expect(fabs(m.f) < 1e-9, "force at primary minimum %g", m.f);
}

Test(colloid_forces, closed_form_points)
{
    /* Hertz, K = 100, overlap 0.04: U = 100 * 0.04^2.5 = 0.032, F = 250 * 0.04^1.5 = 2 */
    pl_pair_val_t h = pl_pair_hertz(0.04, 100.0);
    cr_expect(fabs(h.u - 0.032) < 1e-15 && fabs(h.f - 2.0) < 1e-14, "hertz %.17g %.17g", h.u, h.f);
    /* WCA: r = sigma gives U = eps, F = 4 eps n / sigma; r = 2^{1/n} sigma gives 0, 0 */
    pl_pair_val_t w = pl_pair_wca(4.0, 4.0, 2.5, 24.0);
    cr_expect(fabs(w.u - 2.5) < 1e-14 && fabs(w.f - 4 * 2.5 * 24 / 4.0) < 1e-12, "wca %g %g", w.u, w.f);
    w = pl_pair_wca(4.0 * pow(2.0, 1.0 / 24.0), 4.0, 2.5, 24.0);
    cr_expect(fabs(w.u) < 1e-13 && fabs(w.f) < 1e-12, "wca at cut-off %g %g", w.u, w.f);
    /* Coulomb at contact: U = C d, F = C (1 + kappa d) */
    pl_pair_val_t c = pl_pair_coulomb(4.0, 4.0, 3.0, 0.5);
    cr_expect(fabs(c.u - 12.0) < 1e-13 && fabs(c.f - 9.0) < 1e-13, "coulomb %g %g", c.u, c.f);
    /* vdW at r = 2d: U = -A/12 (1/3 + 1/4 + 2 ln 3/4), F = -A / (432 d) */
    double A = 10.0, d = 4.0;
    pl_pair_val_t v = pl_pair_vdw(2 * d, d, A);
    double u = -A / 12 * (1.0 / 3 + 0.25 + 2 * log(0.75));
    cr_expect(fabs(v.u - u) < 1e-14 && fabs(v.f + A / (432 * d)) < 1e-15, "vdw %.17g %.17g", v.u, v.f);
    /* lubrication: at contact zeta = 6 pi eta r_red^2 (1/hmin - 1/(hcut+hmin)),
     * zero at the cut-off gap */
    double z0 = pl_pair_lub_zeta(0.0, 2.0, 2.0, 1.5, 0.1, 0.9);
    cr_expect(fabs(z0 - 6 * M_PI * 1.5 * 1.0 * (10.0 - 1.0)) < 1e-12, "lub zeta %g", z0);
    cr_expect(fabs(pl_pair_lub_zeta(0.9, 2.0, 2.0, 1.5, 0.1, 0.9)) < 1e-14);
    cr_expect(pl_pair_lub_zeta(-0.3, 2.0, 2.0, 1.5, 0.1, 0.9) == z0, "limited below contact");
}

/* Hecht Fig. 1: Al2O3 spheres of diameter 0.5 um in water at 300 K, eps_r =
 * 81, A_H = 4.76e-20 J, a0 = 0.125 um (d = 4 a0).  Reference values from an
 * independent numpy/scipy evaluation of Eqs. 1-2 (tools/dlvo_reference.py):
 *   A: Psi0 = 20 mV, kappa = 1.4e8/m: barrier 11.858 kT at 5.93 nm,
 *      secondary minimum -2.871598734 kT at gap 0.2413970541 a0 (30.17 nm)
 *   B: Psi0 = 50 mV, kappa = 2.0e8/m: barrier 284.09 kT at 1.67 nm,
 *      secondary minimum -3.065321820 kT at gap 0.2568733056 a0 (32.11 nm)
 * Tolerances: depth 1e-8 relative, position 1e-7 relative (both codes find the
 * root of dV/dh; 10-digit reference values), barrier 1e-3 relative. */
Test(colloid_forces, dlvo_fig1_secondary_minimum)
{
    struct { double psi, kappa, h, u, bu; } set[] = {
        {20, 1.4e8, 0.2413970541, -2.871598734, 11.858},
        {50, 2.0e8, 0.2568733056, -3.065321820, 284.09},
    };
    for (int k = 0; k < 2; ++k) {
        pl_scene_dlvo_t s = {81, set[k].psi, 1, 300, set[k].kappa, 4.76e-20, 1.25e-7, 6.0, 0.0, 1e-3};
        pl_colloid_pair_params_t p;
        pl_colloid_dlvo_info_t info;
        pl_err_t err;
        cr_assert_eq(pl_colloid_dlvo_setup(&s, 4.0, &p, &info, &err), 0, "%s", err.msg);
        cr_expect(fabs(info.secmin_u - set[k].u) < 1e-8 * fabs(set[k].u), "set %d depth %.10g want %.10g",
                  k, info.secmin_u, set[k].u);
        cr_expect(fabs(info.secmin_h - set[k].h) < 1e-7 * set[k].h, "set %d gap %.10g want %.10g", k,
                  info.secmin_h, set[k].h);
        /* shape: a barrier between primary and secondary minimum */
        cr_expect(info.barrier_h < info.secmin_h && fabs(info.barrier_u - set[k].bu) < 1e-3 * set[k].bu,
                  "set %d barrier %g at %g", k, info.barrier_u, info.barrier_h);
        /* truncation error reported and within the request */
        cr_expect(info.trunc_u <= 1e-3 * (1 + 1e-9) && info.hcut > info.secmin_h, "cut-off %g err %g",
                  info.hcut, info.trunc_u);
    }
}

/* The conservative pair forces of every colloid against a direct O(N^2) sum
 * over all pairs with the minimum image (DLVO + Hertz + WCA with sigma =
 * R_i + R_j, as set by the tests below); relative 1e-12: only the summation
 * order differs.  Returns the number of pairs inside their cut-off. */
static long direct_sum_check(const pl_colloid_t *c, const char *what)
{
    const pl_colloid_pair_params_t *p = &c->pair;
    long inside = 0;
    for (size_t i = 0; i < c->n; ++i) {
        double f[3] = {0, 0, 0};
        for (size_t j = 0; j < c->n; ++j) {
            if (j == i) continue;
            double dd[3] = {c->x[i] - c->x[j], c->y[i] - c->y[j], c->z[i] - c->z[j]};
            double r2 = 0;
            for (int k = 0; k < 3; ++k) dd[k] -= c->box[k] * rint(dd[k] / c->box[k]), r2 += dd[k] * dd[k];
            double r = sqrt(r2), d = c->rad[i] + c->rad[j], fr = 0;
            if (r - d < p->dlvo_hcut) {
                fr += pl_pair_dlvo(r, d, p->coul_C, p->kappa, p->hamaker, p->prim_hm, p->prim_h0, p->dlvo_shift).f;
                inside += j > i;
            }
            if (r < d) fr += pl_pair_hertz(d - r, p->hertz_K).f;
            if (r < d * p->wca_rfac) fr += pl_pair_wca(r, d, p->wca_eps, p->wca_n).f;
            for (int k = 0; k < 3; ++k) f[k] += fr * dd[k] / r;
        }
        double got[3] = {c->fx[i], c->fy[i], c->fz[i]};
        for (int k = 0; k < 3; ++k)
            if (!(fabs(got[k] - f[k]) <= 1e-12 * (1 + fabs(f[k]))))
                cr_assert_fail("%s: particle %zu axis %d: %.17g vs %.17g", what, i, k, got[k], f[k]);
    }
    return inside;
}

/* 300 polydisperse colloids with DLVO + Hertz + WCA in a periodic 40^3 box,
 * for nthreads threads. */
static pl_colloid_t *random_colloids_threads(size_t n, double skin_fraction, int nthreads)
{
    pl_colloid_t *c;
    pl_err_t err;
    cr_assert_eq(pl_colloid_alloc(n, nthreads, &c, &err), 0);
    pl_colloid_pair_params_t *p = &c->pair;
    pl_scene_dlvo_t s = {81, 20, 1, 300, 1.4e8, 4.76e-20, 1.25e-7, 6.0, 0.0, 1e-3};
    pl_colloid_dlvo_info_t info;
    cr_assert_eq(pl_colloid_dlvo_setup(&s, 4.0, p, &info, &err), 0);
    p->terms = PL_CT_DLVO | PL_CT_HERTZ | PL_CT_WCA;
    p->hertz_K = 1e3;
    p->wca_eps = 2.5, p->wca_n = 24, p->wca_sigma = 0, p->wca_rfac = pow(2.0, 1.0 / 24);
    p->gap_cut = p->dlvo_hcut;
    for (int k = 0; k < 3; ++k) p->box[k] = c->box[k] = 40.0, p->periodic[k] = c->periodic[k] = 1;
    srand(7);
    for (size_t i = 0; i < n; ++i) {
        c->x[i] = 40.0 * rand() / RAND_MAX, c->y[i] = 40.0 * rand() / RAND_MAX;
        c->z[i] = 40.0 * rand() / RAND_MAX;
        c->rad[i] = 1.8 + 0.4 * rand() / RAND_MAX, c->mass[i] = 100, c->inertia[i] = 100;
    }
    cr_assert_eq(pl_colloid_neighbors_init(c, 4.4 + p->gap_cut, skin_fraction, &err), 0);
    cr_assert(c->nlist.skin == skin_fraction * (4.4 + p->gap_cut), "skin not capped");
    return c;
}

static pl_colloid_t *random_colloids(size_t n, double skin_fraction)
{
    return random_colloids_threads(n, skin_fraction, omp_get_max_threads());
}

/* The neighbour-list kernel against the direct sum on a fresh list. */
Test(colloid_forces, kernel_matches_direct_sum)
{
    pl_colloid_t *c = random_colloids(300, 0.1);
    pl_err_t err;
    cr_assert(c->cells.nc[0] >= 3, "test wants real cells, got %d", c->cells.nc[0]);
    cr_assert_eq(pl_colloid_forces(c, &err), 0);
    cr_expect(direct_sum_check(c, "fresh list") > 100, "too few pairs for a test");
    pl_colloid_free(c);
}

/* The list stays right while colloids move: fast random displacements
 * (uniform in +-0.15 a0 per axis and step; the half-skin is ~0.37 a0, used
 * up by some colloid every few steps)
 * with a force evaluation after each, against the direct sum every step;
 * several rebuilds, and steps where the old list is kept. */
Test(colloid_forces, moving_colloids_keep_a_valid_list)
{
    pl_colloid_t *c = random_colloids(300, 0.1);
    pl_err_t err;
    cr_assert_eq(pl_colloid_forces(c, &err), 0);
    long long b0 = c->nlist.builds;
    for (int step = 0; step < 40; ++step) {
        for (size_t i = 0; i < c->n; ++i) {
            double *x[3] = {&c->x[i], &c->y[i], &c->z[i]};
            for (int k = 0; k < 3; ++k) {
                *x[k] += 0.3 * ((double)rand() / RAND_MAX - 0.5);
                *x[k] -= 40.0 * floor(*x[k] / 40.0);
            }
        }
        cr_assert_eq(pl_colloid_forces(c, &err), 0);
        char what[32];
        snprintf(what, sizeof what, "step %d", step);
        direct_sum_check(c, what);
    }
    long long builds = c->nlist.builds - b0;
    cr_expect(builds >= 3 && builds < 40, "%lld rebuilds in 40 steps: the test should see both", builds);
    pl_colloid_free(c);
}

/* A list with a larger skin (more listed pairs; here a single cell, so the
 * other scan path) gives the same forces bit for bit: the kernel's sums do
 * not depend on the list. */
Test(colloid_forces, forces_do_not_depend_on_the_list)
{
    pl_colloid_t *a = random_colloids(300, 0.1), *b = random_colloids(300, 0.3);
    pl_err_t err;
    cr_assert_eq(pl_colloid_forces(a, &err), 0);
    cr_assert_eq(pl_colloid_forces(b, &err), 0);
    cr_assert(b->nlist.npairs > a->nlist.npairs, "the wider list lists more pairs");
    cr_assert(a->cells.nc[0] >= 3 && b->cells.nc[0] == 1, "cells %d / %d", a->cells.nc[0], b->cells.nc[0]);
    size_t n = a->n;
    cr_expect_eq(memcmp(a->fx, b->fx, n * sizeof *a->fx), 0);
    cr_expect_eq(memcmp(a->fy, b->fy, n * sizeof *a->fy), 0);
    cr_expect_eq(memcmp(a->fz, b->fz, n * sizeof *a->fz), 0);
    pl_colloid_free(a);
    pl_colloid_free(b);
}

/* The two layouts of the pair results (pl_colloid_nlist_t): a list built for
 * one thread stores them by slot, one for two threads by reverse entry; the
 * forces and the partners' friction torques are the same bits.  Contacts,
 * Hertz tangential friction and spinning colloids, so that pass 2 carries
 * torques too. */
Test(colloid_forces, both_result_layouts_give_the_same_bits)
{
    pl_colloid_t *c[2] = {random_colloids_threads(300, 0.1, 1), random_colloids_threads(300, 0.1, 2)};
    pl_err_t err;
    for (int k = 0; k < 2; ++k) {
        c[k]->pair.hertz_beta = 2.0, c[k]->pair.hertz_gamma_t = 5.0;
        for (size_t i = 0; i < c[k]->n; ++i) {
            c[k]->vx[i] = 0.01 * (double)(i % 7), c[k]->vy[i] = -0.02 * (double)(i % 5);
            c[k]->wx[i] = 0.03 * (double)(i % 3), c[k]->wz[i] = -0.01 * (double)(i % 11);
        }
        cr_assert_eq(pl_colloid_forces(c[k], &err), 0, "%s", err.msg);
    }
    cr_assert(c[0]->nlist.by_entry == 0 && c[1]->nlist.by_entry == 1, "layouts %d and %d", c[0]->nlist.by_entry,
              c[1]->nlist.by_entry);
    size_t contacts = 0, n = c[0]->n;
    for (size_t i = 0; i < n; ++i) contacts += c[0]->tx[i] != 0.0 || c[0]->ty[i] != 0.0 || c[0]->tz[i] != 0.0;
    cr_expect(contacts >= 10, "only %zu colloids with a friction torque: the test wants contacts", contacts);
    const double *a[6] = {c[0]->fx, c[0]->fy, c[0]->fz, c[0]->tx, c[0]->ty, c[0]->tz};
    const double *b[6] = {c[1]->fx, c[1]->fy, c[1]->fz, c[1]->tx, c[1]->ty, c[1]->tz};
    for (int k = 0; k < 6; ++k) cr_expect_eq(memcmp(a[k], b[k], n * sizeof *a[k]), 0, "array %d differs", k);
    pl_colloid_free(c[0]);
    pl_colloid_free(c[1]);
}

/* The kernel drops Eq. 1 beyond coul_hcut: there its energy and force are
 * below 1e-15 (kT, kT/a0) for contact distances up to twice the reference,
 * for both Hecht Fig. 1 sets and Fig. 14's strongly screened one (kappa =
 * 3e8 /m, Psi0 = 50 mV at a0 = 0.403 um), and the skip is real (inside the
 * cut-off). */
Test(colloid_forces, coulomb_skip_below_round_off)
{
    struct { double psi, kappa, a0, d; } set[] = {
        {20, 1.4e8, 1.25e-7, 4.0}, {50, 2.0e8, 1.25e-7, 4.0}, {50, 3.0e8, 4.03e-7, 1.24}};
    for (int k = 0; k < 3; ++k) {
        pl_scene_dlvo_t s = {81, set[k].psi, 1, 300, set[k].kappa, 4.76e-20, set[k].a0, 6.0, 0.0, 1e-3};
        pl_colloid_pair_params_t p;
        pl_colloid_dlvo_info_t info;
        pl_err_t err;
        cr_assert_eq(pl_colloid_dlvo_setup(&s, set[k].d, &p, &info, &err), 0, "%s", err.msg);
        cr_expect(p.coul_hcut < p.dlvo_hcut, "set %d: coul_hcut %g >= cut-off %g", k, p.coul_hcut, p.dlvo_hcut);
        for (double d = set[k].d; d <= 2.0 * set[k].d; d += 0.25 * set[k].d) {
            pl_pair_val_t v = pl_pair_coulomb(d + p.coul_hcut, d, p.coul_C, p.kappa);
            cr_expect(v.u < 1e-15 && v.f < 1e-15, "set %d d %g: U %g F %g at the skip gap", k, d, v.u, v.f);
        }
    }
}

/* pl_colloid_pair_energy (the observer's energy bond) is the sum of the
 * closed forms of colloid_pair.h for the terms switched on: DLVO with the
 * primary parabola and its cut-off shift, Hertz inside contact; zero beyond
 * the DLVO cut-off.  1e-12 relative: the same formulas, only the order of
 * two additions may differ. */
Test(colloid_forces, pair_energy_is_the_sum_of_the_terms)
{
    pl_scene_dlvo_t s = {81, 20, 1, 300, 1.4e8, 4.76e-20, 1.25e-7, 6.0, 0.0, 1e-3};
    pl_colloid_pair_params_t p;
    memset(&p, 0, sizeof p);
    pl_colloid_dlvo_info_t info;
    pl_err_t err;
    cr_assert_eq(pl_colloid_dlvo_setup(&s, 4.0, &p, &info, &err), 0, "%s", err.msg);
    p.terms = PL_CT_DLVO | PL_CT_HERTZ;
    p.hertz_K = 1000.0;
    p.gap_cut = p.dlvo_hcut;
    for (double h = -0.02; h < info.hcut + 1.0; h += 0.0173) {
        double r = 4.0 + h, want = 0.0;
        if (h < p.dlvo_hcut)
            want += pl_pair_dlvo(r, 4.0, p.coul_C, p.kappa, p.hamaker, p.prim_hm, p.prim_h0, p.dlvo_shift).u;
        if (h < 0.0) want += pl_pair_hertz(-h, p.hertz_K).u;
        double got = pl_colloid_pair_energy(&p, r, 2.0, 2.0);
        cr_expect(fabs(got - want) <= 1e-12 * (fabs(want) + 1e-300) || (got == 0.0 && want == 0.0),
                  "gap %g: %.15g want %.15g", h, got, want);
    }
    /* the primary minimum -6 kT (less the shift) and the secondary of Hecht Fig. 1 */
    cr_expect(fabs(pl_colloid_pair_energy(&p, 4.0, 2.0, 2.0) + p.dlvo_shift + 6.0) < 1e-9);
    cr_expect(fabs(pl_colloid_pair_energy(&p, 4.0 + info.secmin_h, 2.0, 2.0) + p.dlvo_shift - info.secmin_u) <
              1e-12);
}

/* The kernel keeps the parabola's match point of the reference diameter
 * (prim_mu, prim_vp, prim_c) instead of evaluating Eqs. 1-2 there for every
 * pair in the primary minimum: for two colloids of the reference diameter
 * at gaps across the parabola (and beyond its match gap) the kernel's force
 * and energy equal pl_pair_dlvo's bit for bit; for a pair of another
 * diameter (no kept point) too. */
Test(colloid_forces, kept_match_point_gives_the_same_bits)
{
    pl_scene_dlvo_t s = {81, 50, 1, 300, 3.0e8, 4.76e-20, 4.03e-7, 6.0, 0.0, 1e-3};
    const double d_ref = 1.24;
    for (int other = 0; other < 2; ++other) {
        const double ri = 0.62, rj = other ? 0.7 : 0.62, d = ri + rj;
        long parabola = 0;
        /* 40 gaps from an overlap of 0.01 to twice the match gap (~0.014 a0
         * here), then 20 more out to 0.3 a0 */
        for (int g = 0; g < 60; ++g) {
            const double h = g < 40 ? -0.01 + 0.024 * g / 40.0 : 0.014 + 0.286 * (g - 40) / 20.0;
            pl_colloid_t *c;
            pl_err_t err;
            cr_assert_eq(pl_colloid_alloc(2, 1, &c, &err), 0);
            pl_colloid_pair_params_t *p = &c->pair;
            pl_colloid_dlvo_info_t info;
            cr_assert_eq(pl_colloid_dlvo_setup(&s, d_ref, p, &info, &err), 0, "%s", err.msg);
            cr_assert(p->prim_d == d_ref);
            p->terms = PL_CT_DLVO;
            p->gap_cut = p->dlvo_hcut;
            for (int k = 0; k < 3; ++k) p->box[k] = c->box[k] = 20.0, p->periodic[k] = c->periodic[k] = 1;
            const double r = d + h;
            c->x[0] = 5.0, c->x[1] = 5.0 + r;
            c->y[0] = c->y[1] = c->z[0] = c->z[1] = 5.0;
            c->rad[0] = ri, c->rad[1] = rj;
            c->mass[0] = c->mass[1] = c->inertia[0] = c->inertia[1] = 1.0;
            cr_assert_eq(pl_colloid_neighbors_init(c, d + p->gap_cut, 0.1, &err), 0);
            cr_assert_eq(pl_colloid_forces(c, &err), 0, "%s", err.msg);
            /* the kernel's own operations: r from the squared distance, the
             * unit vector by the reciprocal */
            const double dx = c->x[0] - c->x[1], rk = sqrt(dx * dx), ex = dx * (1.0 / rk);
            pl_pair_val_t v = pl_pair_dlvo(rk, d, p->coul_C, p->kappa, p->hamaker, p->prim_hm,
                                           p->prim_h0, p->dlvo_shift);
            const double want = 0.0 + v.f * ex;
            cr_expect(memcmp(&c->fx[0], &want, sizeof want) == 0, "d %g gap %g: force %.17g, want %.17g",
                      d, h, c->fx[0], want);
            const double e = pl_colloid_pair_energy(p, rk, ri, rj);
            cr_expect(memcmp(&e, &v.u, sizeof e) == 0, "d %g gap %g: energy %.17g, want %.17g", d, h, e, v.u);
            parabola += rk - d < p->prim_hm;
            pl_colloid_free(c);
        }
        cr_expect(parabola > 10, "only %ld gaps inside the parabola", parabola);
    }
}

/* The partner's friction torque (Hertz tangential friction with DLVO on, so
 * the kernel's block path): two equal colloids in contact, sliding and
 * spinning; each torque is -R e x F_t with the same lever arm, so the two
 * are equal bit for bit, and not zero (the partner's comes through its
 * reverse entry).  A third colloid in the van der Waals tail of both (a far
 * pair of the same blocks, spinning too) gets no torque at all. */
Test(colloid_forces, partner_friction_torque_with_dlvo)
{
    pl_scene_dlvo_t s = {81, 50, 1, 300, 3.0e8, 4.76e-20, 4.03e-7, 6.0, 0.0, 1e-3};
    pl_colloid_t *c;
    pl_err_t err;
    cr_assert_eq(pl_colloid_alloc(3, 1, &c, &err), 0);
    pl_colloid_pair_params_t *p = &c->pair;
    pl_colloid_dlvo_info_t info;
    cr_assert_eq(pl_colloid_dlvo_setup(&s, 1.24, p, &info, &err), 0, "%s", err.msg);
    p->terms = PL_CT_DLVO | PL_CT_HERTZ;
    p->hertz_K = 1000.0, p->hertz_beta = 2.0, p->hertz_gamma_t = 5.0;
    p->gap_cut = p->dlvo_hcut;
    for (int k = 0; k < 3; ++k) p->box[k] = c->box[k] = 20.0, p->periodic[k] = c->periodic[k] = 1;
    c->x[0] = 5.0, c->y[0] = 5.0, c->z[0] = 5.0;
    c->x[1] = 5.0 + 1.2, c->y[1] = 5.0 + 0.2, c->z[1] = 5.0 - 0.1; /* overlap ~0.02 */
    c->x[2] = 5.6, c->y[2] = 5.0 + 1.9, c->z[2] = 5.0; /* gap ~0.7 to both: the tail */
    c->vy[0] = 0.3, c->vz[1] = -0.2, c->wx[0] = 0.1, c->wz[1] = 0.4, c->wy[2] = -0.3, c->vx[2] = 0.2;
    for (int i = 0; i < 3; ++i) c->rad[i] = 0.62, c->mass[i] = c->inertia[i] = 1.0;
    cr_assert_eq(pl_colloid_neighbors_init(c, 1.24 + p->gap_cut, 0.1, &err), 0);
    cr_assert_eq(pl_colloid_forces(c, &err), 0, "%s", err.msg);
    const double t0[3] = {c->tx[0], c->ty[0], c->tz[0]}, t1[3] = {c->tx[1], c->ty[1], c->tz[1]};
    cr_expect(memcmp(t0, t1, sizeof t0) == 0, "torques (%g %g %g) and (%g %g %g)", t0[0], t0[1], t0[2], t1[0],
              t1[1], t1[2]);
    cr_expect(fabs(t0[0]) + fabs(t0[1]) + fabs(t0[2]) > 1e-3, "no friction torque: (%g %g %g)", t0[0], t0[1], t0[2]);
    cr_expect(c->tx[2] == 0.0 && c->ty[2] == 0.0 && c->tz[2] == 0.0, "torque on the far colloid: (%g %g %g)",
              c->tx[2], c->ty[2], c->tz[2]);
    cr_expect(c->fy[2] != 0.0, "the third colloid feels no van der Waals tail: put it nearer");
    pl_colloid_free(c);
}
