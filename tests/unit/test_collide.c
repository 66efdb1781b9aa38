/* Collision kernel: per-cell momentum and kinetic energy conserved to
 * round-off (PL Eq. 3), the Heyes thermostat keeps the cell momentum
 * (Hecht Eq. 33), and the rotation statistics match the rule. */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "peloid/rng.h"
#include "peloid/scene.h"
#include "peloid/srd_kernels.h"
#include "peloid/srd_rules.h"

#include "srd_box.h"

static void cell_sums(const pl_test_box_t *b, size_t c, double P[3], double *K, double *scale)
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
    pl_test_box_t b;
    pl_test_box_make(&b, 6, 5.0, 2);
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
    pl_test_box_free(&b);
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
    pl_test_box_t b;
    pl_test_box_make(&b, 8, 2.0, 1);
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
    pl_test_box_free(&b);
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

/* The collision draws its rotations 32 cells at a time in vector lanes
 * (pl_srd_rotations, PL_RNG_VECTOR_LANES); the trajectories keep their bits
 * only if every lane equals the scalar draw.  Checked bitwise: the Philox
 * lanes (compiled in every build, used with AVX-512) against Random123's
 * philox4x64 over counters and keys with all-ones and carry-prone words;
 * pl_rng_uniform4_lanes against pl_rng_uniform4; and the lane rotations of
 * both rules against pl_srd_rotation, over 640 batches of 32 cells, in
 * which ~470 random-axis cells draw again (both disc points of the first
 * draw outside). */
Test(collide, lane_draws_equal_scalar_draws)
{
    const uint64_t words[] = {0, 1, 17, 0xffffffffull, 0x100000000ull, 0x9E3779B97F4A7C15ull,
                              0xffffffffffffffe0ull, 0xffffffffffffffffull};
    enum { NW = sizeof words / sizeof words[0] };
    long lanes = 0;
    for (int a = 0; a < NW; ++a)
        for (int b = 0; b < NW; b += 3)
            for (int d = 0; d < 2; ++d) {
                const uint64_t seed = words[a], purpose = words[(a + b) % NW], step = words[b];
                const uint64_t index0 = words[(a + 5 * b + d) % NW], draw = (uint64_t)d;
                uint64_t c[4][PL_RNG_LANES];
                double u[4][PL_RNG_LANES];
                pl_rng_philox_lanes(seed, purpose, step, index0, draw, c);
                pl_rng_uniform4_lanes(seed, purpose, step, index0, draw, u);
                for (uint64_t l = 0; l < PL_RNG_LANES; ++l, ++lanes) {
                    philox4x64_ctr_t ctr = {{step, index0 + l, draw, 0}};
                    philox4x64_key_t key = {{seed, purpose}};
                    philox4x64_ctr_t r = philox4x64(ctr, key);
                    pl_rand4_t q = pl_rng_uniform4(seed, purpose, step, index0 + l, draw);
                    for (int k = 0; k < 4; ++k) {
                        cr_assert_eq(c[k][l], r.v[k], "Philox lane %lu word %d: %016lx, scalar %016lx", (unsigned long)l,
                                     k, (unsigned long)c[k][l], (unsigned long)r.v[k]);
                        cr_assert(memcmp(&u[k][l], &q.u[k], sizeof(double)) == 0, "uniform lane %lu word %d",
                                  (unsigned long)l, k);
                    }
                }
            }
    cr_assert_eq(lanes, NW * 3 * 2 * PL_RNG_LANES);
}

Test(collide, lane_rotations_equal_scalar_rotations)
{
    const double alpha = 130.0 * M_PI / 180.0;
    long redrawn = 0;
    for (int rule = 0; rule < 2; ++rule)
        for (uint64_t step = 0; step < 20; ++step)
            for (uint64_t batch = 0; batch < 16; ++batch) {
                const int r = rule ? PL_RULE_HECHT_AXES : PL_RULE_RANDOM_AXIS;
                const uint64_t cell0 = batch * 1000 + step; /* not only multiples of 32 */
                double R[9][PL_RNG_LANES];
                pl_srd_rotations(r, cos(alpha), sin(alpha), 23, PL_RNG_COLLIDE, step, cell0, R);
                for (uint64_t l = 0; l < PL_RNG_LANES; ++l) {
                    double S[3][3];
                    pl_srd_rotation(r, cos(alpha), sin(alpha), 23, PL_RNG_COLLIDE, step, cell0 + l, S);
                    for (int e = 0; e < 9; ++e)
                        cr_assert(memcmp(&R[e][l], &S[e / 3][e % 3], sizeof(double)) == 0,
                                  "rule %d step %lu cell %lu element %d: %.17g, scalar %.17g", r, (unsigned long)step,
                                  (unsigned long)(cell0 + l), e, R[e][l], S[e / 3][e % 3]);
                    if (r == PL_RULE_RANDOM_AXIS) {
                        pl_rand4_t q = pl_rng_uniform4(23, PL_RNG_COLLIDE, step, cell0 + l, 0);
                        double a, b;
                        redrawn += !(pl_srd_disc_point(q.u[0], q.u[1], q.u[2], q.u[3], &a, &b) < 1.0);
                    }
                }
            }
    /* 20 x 16 x 32 = 10240 random-axis cells, 4.6 % of them: ~470, sd ~21 */
    cr_assert(redrawn > 350 && redrawn < 600, "%ld cells drew again", redrawn);
}

/* pl_heyes_zeta settles most decisions from intervals around the two
 * logarithms (pl_log1p_bracket, [1 - 1/u, u - 1]); its result must be that
 * of the logarithms themselves (the code before the intervals, below) bit
 * for bit.  Checked over 3e6 draws across eps_max, cell sizes,
 * temperatures and K from 0 to 4x its mean, and over draws whose u2 lies
 * within 4 ulp of the exact boundary exp(log_acc) (where the intervals
 * cannot decide), over K within 4 ulp of where log_acc crosses 0, and K =
 * NaN, +-Inf, eps_max = 0. */
static double heyes_zeta_logs(double eps_max, double kT, double nbody, double K, double u0, double u1, double u2)
{
    double eps = eps_max * u0;
    double zeta = u1 < 0.5 ? 1.0 + eps : 1.0 / (1.0 + eps);
    double dof = 3.0 * (nbody - 1.0);
    double log_acc = dof * log(zeta) - (zeta * zeta - 1.0) * K / kT;
    return (log_acc >= 0.0 || log(u2) < log_acc) ? zeta : 1.0;
}

Test(collide, heyes_decision_equals_the_logarithms)
{
    const double eps_max[] = {0.0, 0.01, 0.1, 0.3, 1.0, 2.0};
    const double kTs[] = {0.5, 1.0, 2.0};
    long n = 0, accepted = 0, boundary = 0;
    for (uint64_t i = 0; i < 3000000; ++i) {
        pl_rand4_t r = pl_rng_uniform4(5, 77, 0, i, 0), q = pl_rng_uniform4(5, 78, 0, i, 0);
        const double em = eps_max[i % 6], kT = kTs[(i / 6) % 3], nbody = (double)(2 + (i / 18) % 29);
        const double K = kT * 1.5 * (nbody - 1.0) * 4.0 * q.u[0];
        const double a = pl_heyes_zeta(em, kT, nbody, K, r.u[0], r.u[1], r.u[2]);
        const double b = heyes_zeta_logs(em, kT, nbody, K, r.u[0], r.u[1], r.u[2]);
        cr_assert(memcmp(&a, &b, sizeof a) == 0, "draw %lu: %.17g, with the logarithms %.17g", (unsigned long)i, a, b);
        accepted += a != 1.0;
        n++;
        /* K where log_acc crosses 0, and its neighbours */
        if (i % 10 == 5 && em > 0.0) {
            const double eps = em * r.u[0], zeta = r.u[1] < 0.5 ? 1.0 + eps : 1.0 / (1.0 + eps);
            if (zeta == 1.0) continue;
            double K0 = 3.0 * (nbody - 1.0) * log(zeta) * kT / (zeta * zeta - 1.0);
            for (int k = 0; k < 4; ++k) K0 = nextafter(K0, 0.0);
            for (int k = 0; k < 9; ++k, K0 = nextafter(K0, INFINITY)) {
                const double x = pl_heyes_zeta(em, kT, nbody, K0, r.u[0], r.u[1], r.u[2]);
                const double y = heyes_zeta_logs(em, kT, nbody, K0, r.u[0], r.u[1], r.u[2]);
                cr_assert(memcmp(&x, &y, sizeof x) == 0, "log_acc = 0 draw %lu step %d", (unsigned long)i, k);
                boundary++;
            }
        }
        /* u2 at the boundary: exp(log_acc) and its neighbours */
        if (i % 10 == 0 && em > 0.0) {
            double eps = em * r.u[0], zeta = r.u[1] < 0.5 ? 1.0 + eps : 1.0 / (1.0 + eps);
            double log_acc = 3.0 * (nbody - 1.0) * log(zeta) - (zeta * zeta - 1.0) * K / kT;
            if (log_acc >= 0.0) continue;
            double u2 = exp(log_acc);
            for (int k = 0; k < 4; ++k) u2 = nextafter(u2, 0.0);
            for (int k = 0; k < 9; ++k, u2 = nextafter(u2, 1.0)) {
                if (!(u2 > 0.0 && u2 < 1.0)) continue;
                const double x = pl_heyes_zeta(em, kT, nbody, K, r.u[0], r.u[1], u2);
                const double y = heyes_zeta_logs(em, kT, nbody, K, r.u[0], r.u[1], u2);
                cr_assert(memcmp(&x, &y, sizeof x) == 0, "boundary draw %lu step %d", (unsigned long)i, k);
                boundary++;
            }
        }
    }
    const double odd[] = {NAN, INFINITY, -INFINITY, 0.0, 1e300};
    for (int k = 0; k < 5; ++k)
        for (int s = 0; s < 2; ++s) {
            const double a = pl_heyes_zeta(0.1, 1.0, 10.0, odd[k], 0.5, s ? 0.7 : 0.2, 0.3);
            const double b = heyes_zeta_logs(0.1, 1.0, 10.0, odd[k], 0.5, s ? 0.7 : 0.2, 0.3);
            cr_assert(memcmp(&a, &b, sizeof a) == 0, "K = %g", odd[k]);
        }
    cr_assert(accepted > n / 10 && accepted < n, "%ld of %ld accepted", accepted, n);
    cr_assert(boundary > 100000, "%ld boundary draws", boundary);
}
