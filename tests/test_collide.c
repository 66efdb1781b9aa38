/* Collision kernel: per-cell momentum and kinetic energy conserved to
 * round-off (PL Eq. 3), the Heyes thermostat keeps the cell momentum
 * (Hecht Eq. 33), and the rotation statistics match the rule. */
#include <criterion/criterion.h>
#include <math.h>

#include "peloid/rng.h"
#include "peloid/scene.h"
#include "peloid/srd_kernels.h"
#include "peloid/srd_rules.h"

typedef struct {
    pl_fluid_t f;
    pl_grid_t g;
    uint32_t *hist, *start;
    double *block;
    int nthreads;
} box_t;

static void make_box(box_t *b, int L, double gamma, int nthreads)
{
    pl_err_t err;
    int Ls[3] = {L, L, L};
    pl_grid_init(&b->g, Ls, (const int[3]){PL_WALLS_NONE, PL_WALLS_NONE, PL_WALLS_NONE});
    size_t n = (size_t)(gamma * L * L * L);
    b->nthreads = nthreads;
    cr_assert_eq(pl_fluid_create(n, 0, nthreads, &b->f, &err), 0);
    for (size_t i = 0; i < n; ++i) {
        pl_rand4_t r = pl_rng_uniform4(99, 1, 0, i, 0), q = pl_rng_uniform4(99, 2, 0, i, 0);
        for (int d = 0; d < 3; ++d) {
            b->f.r[d][i] = (pl_real)(r.u[d] * L);
            b->f.v[d][i] = (pl_real)(2.0 * q.u[d] - 1.0 + 0.3 * d); /* a mean flow too */
        }
    }
    b->hist = pl_alloc((size_t)nthreads * b->g.ncells * sizeof(uint32_t), nthreads);
    b->start = pl_alloc((b->g.ncells + 1) * sizeof(uint32_t), nthreads);
    b->block = pl_alloc(2 * (b->g.ncells / PL_CELL_BLOCK + 1) * sizeof(double), nthreads);
    pl_grid_draw_shift(&b->g, 5, 0, 1);
    pl_srd_bin(&b->f, &b->g, b->hist, nthreads);
    pl_srd_sort(&b->f, b->hist, b->start, b->g.ncells, nthreads);
}

static void free_box(box_t *b)
{
    pl_fluid_free(&b->f);
    pl_free(b->hist);
    pl_free(b->start);
    pl_free(b->block);
}

static void cell_sums(const box_t *b, size_t c, double P[3], double *K, double *scale)
{
    P[0] = P[1] = P[2] = *K = *scale = 0.0;
    for (size_t i = b->start[c]; i < b->start[c + 1]; ++i)
        for (int d = 0; d < 3; ++d) {
            double v = b->f.v[d][i];
            P[d] += v;
            *K += 0.5 * v * v;
            *scale += fabs(v);
        }
}

static void check_conservation(int rule, int heyes)
{
    box_t b;
    make_box(&b, 6, 5.0, 2);
    size_t nc = b.g.ncells;
    double (*P0)[3] = malloc(nc * sizeof *P0), *K0 = malloc(nc * sizeof *K0);
    for (size_t c = 0; c < nc; ++c) {
        double s;
        cell_sums(&b, c, P0[c], &K0[c], &s);
    }
    pl_collide_params_t p = {0};
    p.rule = rule;
    p.cos_a = cos(130.0 * M_PI / 180.0);
    p.sin_a = sin(130.0 * M_PI / 180.0);
    p.seed = 11;
    p.step = 3;
    p.kT_target = 0.5;
    p.heyes_eps = 0.3;
    if (heyes) pl_srd_collide_heyes(&b.f, &b.g, b.start, &p, b.block, b.nthreads);
    else pl_srd_collide(&b.f, &b.g, b.start, &p, b.block, b.nthreads);
    int changed_K = 0;
    for (size_t c = 0; c < nc; ++c) {
        double P[3], K, s;
        cell_sums(&b, c, P, &K, &s);
        for (int d = 0; d < 3; ++d)
            cr_assert(fabs(P[d] - P0[c][d]) <= 1e-14 * s, "cell %zu momentum %d: %.17g vs %.17g", c, d, P[d],
                      P0[c][d]);
        if (!heyes)
            cr_assert(fabs(K - K0[c]) <= 1e-14 * K0[c], "cell %zu energy %.17g vs %.17g", c, K, K0[c]);
        else if (fabs(K - K0[c]) > 1e-12 * K0[c])
            changed_K++;
    }
    if (heyes) cr_assert_gt(changed_K, (int)nc / 10, "the thermostat should change many cells' energy");
    free(P0);
    free(K0);
    free_box(&b);
}

Test(collide, random_axis_conserves_cell_momentum_and_energy) { check_conservation(PL_RULE_RANDOM_AXIS, 0); }
Test(collide, hecht_axes_conserve_cell_momentum_and_energy) { check_conservation(PL_RULE_HECHT_AXES, 0); }
Test(collide, heyes_keeps_cell_momentum) { check_conservation(PL_RULE_RANDOM_AXIS, 1); }
Test(collide, heyes_keeps_cell_momentum_hecht) { check_conservation(PL_RULE_HECHT_AXES, 1); }

/* Relative velocity w rotated by alpha about a random axis n:
 * cos(w, w') = cos a + (1 - cos a)(n.w^)^2, and <(n.w^)^2> = 1/3 for an
 * isotropic axis (also for the 3 coordinate axes with random choice), so
 * <cos> = cos a + (1 - cos a)/3.  Tolerance: 5 standard errors of the mean. */
static void check_angle(int rule, double alpha_deg)
{
    box_t b;
    make_box(&b, 8, 2.0, 1);
    double ca = cos(alpha_deg * M_PI / 180.0);
    size_t nc = b.g.ncells;
    double sum = 0, sum2 = 0;
    long cnt = 0;
    for (int rep = 0; rep < 20; ++rep) {
        double (*w)[3] = malloc(b.f.n * sizeof *w);
        double (*u)[3] = malloc(nc * sizeof *u);
        for (size_t c = 0; c < nc; ++c) {
            double P[3], K, s;
            cell_sums(&b, c, P, &K, &s);
            size_t M = b.start[c + 1] - b.start[c];
            for (int d = 0; d < 3; ++d) u[c][d] = M ? P[d] / (double)M : 0.0;
            for (size_t i = b.start[c]; i < b.start[c + 1]; ++i)
                for (int d = 0; d < 3; ++d) w[i][d] = b.f.v[d][i] - u[c][d];
        }
        pl_collide_params_t p = {0};
        p.rule = rule;
        p.cos_a = ca;
        p.sin_a = sin(alpha_deg * M_PI / 180.0);
        p.seed = 3;
        p.step = (uint64_t)rep;
        pl_srd_collide(&b.f, &b.g, b.start, &p, b.block, b.nthreads);
        for (size_t c = 0; c < nc; ++c) {
            if (b.start[c + 1] - b.start[c] < 2) continue;
            size_t i = b.start[c]; /* one particle per cell: independent samples */
            double dot = 0, n0 = 0, n1 = 0;
            for (int d = 0; d < 3; ++d) {
                double w1 = b.f.v[d][i] - u[c][d];
                dot += w[i][d] * w1;
                n0 += w[i][d] * w[i][d];
                n1 += w1 * w1;
            }
            double cs = dot / sqrt(n0 * n1);
            sum += cs;
            sum2 += cs * cs;
            cnt++;
        }
        free(w);
        free(u);
    }
    double mean = sum / (double)cnt, sem = sqrt((sum2 / (double)cnt - mean * mean) / (double)cnt);
    double expect = ca + (1.0 - ca) / 3.0;
    cr_assert(fabs(mean - expect) < 5.0 * sem, "<cos> = %.5f +- %.5f, expected %.5f", mean, sem, expect);
    free_box(&b);
}

Test(collide, random_axis_angle_statistics) { check_angle(PL_RULE_RANDOM_AXIS, 130.0); }
Test(collide, hecht_axes_angle_statistics) { check_angle(PL_RULE_HECHT_AXES, 90.0); }

/* The random axis of PL Eq. 3 must be uniform on the sphere (Archimedes:
 * n_z uniform in [-1, 1], azimuth uniform in [0, 2 pi)).  The axis is read
 * back from the antisymmetric part of R (= 2 sin(alpha) [n]_x).  chi^2 of 20
 * bins of n_z and of the azimuth over 2e5 cells, 19 degrees of freedom each:
 * bound 50 (p ~ 1e-4).  Also |n| = 1 to round-off, and the cells whose axis
 * comes from the rejection path (both pairs of the first Philox draw
 * outside the unit disc, ~4.6 % = ~9200 cells) have a uniform n_z on their
 * own: chi^2 of 10 bins (9 degrees of freedom) below 33 (p ~ 1e-4), so a
 * redraw that reused a rejected pair or skipped the draw would fail. */
Test(collide, random_axis_uniform_on_sphere)
{
    enum { NCELL = 200000, NBIN = 20 };
    const double alpha = 130.0 * M_PI / 180.0, sa = sin(alpha);
    enum { NBIN_R = 10 };
    long hz[NBIN] = {0}, hp[NBIN] = {0}, hr[NBIN_R] = {0}, redraw = 0;
    for (uint64_t c = 0; c < NCELL; ++c) {
        double R[3][3];
        pl_srd_rotation(PL_RULE_RANDOM_AXIS, cos(alpha), sa, 17, PL_RNG_COLLIDE, 5, c, R);
        double n[3] = {(R[2][1] - R[1][2]) / (2 * sa), (R[0][2] - R[2][0]) / (2 * sa),
                       (R[1][0] - R[0][1]) / (2 * sa)};
        cr_assert(fabs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0) < 1e-12);
        int iz = (int)((n[2] + 1.0) * 0.5 * NBIN), ip = (int)((atan2(n[1], n[0]) + M_PI) / (2 * M_PI) * NBIN);
        hz[iz < NBIN ? iz : NBIN - 1]++;
        hp[ip < NBIN ? ip : NBIN - 1]++;
        pl_rand4_t r = pl_rng_uniform4(17, PL_RNG_COLLIDE, 5, c, 0);
        double s0 = pow(2 * r.u[0] - 1, 2) + pow(2 * r.u[1] - 1, 2), s1 = pow(2 * r.u[2] - 1, 2) + pow(2 * r.u[3] - 1, 2);
        if (s0 >= 1.0 && s1 >= 1.0) { /* the code took its rejection path for this cell */
            int ir = (int)((n[2] + 1.0) * 0.5 * NBIN_R);
            hr[ir < NBIN_R ? ir : NBIN_R - 1]++;
            redraw++;
        }
    }
    double chi_z = 0, chi_p = 0, e = (double)NCELL / NBIN;
    for (int k = 0; k < NBIN; ++k) {
        chi_z += ((double)hz[k] - e) * ((double)hz[k] - e) / e;
        chi_p += ((double)hp[k] - e) * ((double)hp[k] - e) / e;
    }
    cr_assert(chi_z < 50.0, "chi2(n_z) = %.1f", chi_z);
    cr_assert(chi_p < 50.0, "chi2(azimuth) = %.1f", chi_p);
    double chi_r = 0, er = (double)redraw / NBIN_R;
    for (int k = 0; k < NBIN_R; ++k) chi_r += ((double)hr[k] - er) * ((double)hr[k] - er) / er;
    cr_assert_gt(redraw, 5000, "only %ld cells on the rejection path", redraw);
    cr_assert(chi_r < 33.0, "chi2(n_z) of the %ld redrawn axes = %.1f", redraw, chi_r);
}
