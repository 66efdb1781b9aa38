/* Every collision-rule row (peloid/collision_rule.h), by its own kernel:
 *  - each cell's momentum is conserved to round-off;
 *  - each cell's angular momentum about its centre of mass (positions
 *    unwrapped in the shifted grid) is conserved to round-off by the rows
 *    that say so (.angular), and measurably not by the others: most cells
 *    with >= 3 particles change it by more than 1e-3 of its scale;
 *  - each cell's kinetic energy is conserved to round-off by the rows that
 *    are not thermostats (SRD's rotations, and SRD+a, which scales back
 *    the part of the relative velocities that is not the kept rigid
 *    rotation; before that it changed the energy and needed a thermostat);
 *  - the same bits at 1, 2 and 3 threads;
 *  - a rule that is a thermostat (.thermostat, MPC-AT) takes a box from
 *    kT = 1/3 to the bath's kT: after each collision (with a new grid shift
 *    and sort before it, as in a run) sum (v - u)^2 / (3 sum (M - 1)); the
 *    mean of K = 400 collisions after 40 must be within 4 standard errors
 *    (from 16 blocks of 25, which holds for +a too, whose kept rigid
 *    rotation correlates successive collisions) of kT (probability 6e-5 to
 *    fail by chance); for MPC-AT, where all 3 (M - 1) relative degrees of
 *    freedom are drawn anew, each collision's estimate is kT chi^2_n / n, so
 *    the variance of the K estimates must be 2 kT^2 / n within 4 of its
 *    standard errors sqrt(2 / (K - 1)) (relative): a rule that scaled to kT
 *    exactly (variance 0) or drew at 2 kT fails;
 *  - scenes pick each row by name, a physical scene maps with the row's
 *    viscosity, a thermostat rule refuses a second thermostat. */
#include <criterion/criterion.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/collision_rule.h"
#include "peloid/rng.h"
#include "peloid/scene.h"
#include "peloid/srd_kernels.h"

#include "srd_box.h"

/* round-off of a sum of a cell's terms in pl_real */
#define TOL (64.0 * (sizeof(pl_real) == sizeof(float) ? (double)FLT_EPSILON : DBL_EPSILON))

static void collide(pl_test_box_t *b, const pl_collision_rule_t *rule, uint64_t step)
{
    pl_collide_params_t p = {0};
    p.rule = rule->srd_rotation >= 0 ? rule->srd_rotation : 0;
    p.cos_a = cos(130.0 * M_PI / 180.0);
    p.sin_a = sin(130.0 * M_PI / 180.0);
    p.seed = 11;
    p.step = step;
    p.kT_target = 0.5;
    rule->collide(&b->f, &b->g, b->start, &p, b->block, b->nthreads);
}

/* Momentum P, angular momentum L about the centre of mass (positions
 * unwrapped to the cell's first particle), and the scales |v| and |r||v|
 * summed, of cell c. */
static void cell_moments(const pl_test_box_t *b, size_t c, double P[3], double L[3], double *sp, double *sl,
                         double *ke)
{
    const size_t s = b->start[c], e = b->start[c + 1];
    double R[3] = {0, 0, 0}, (*r)[3] = malloc((e - s + 1) * sizeof *r);
    P[0] = P[1] = P[2] = L[0] = L[1] = L[2] = *sp = *sl = *ke = 0.0;
    for (size_t i = s; i < e; ++i)
        for (int d = 0; d < 3; ++d) {
            double x = (double)b->f.r[d][i] - (double)b->f.r[d][s];
            x -= b->g.L[d] * round(x / b->g.L[d]);
            r[i - s][d] = x;
            R[d] += x / (double)(e - s);
        }
    for (size_t i = s; i < e; ++i) {
        const double x = r[i - s][0] - R[0], y = r[i - s][1] - R[1], z = r[i - s][2] - R[2];
        const double vx = b->f.v[0][i], vy = b->f.v[1][i], vz = b->f.v[2][i];
        P[0] += vx; P[1] += vy; P[2] += vz;
        L[0] += y * vz - z * vy;
        L[1] += z * vx - x * vz;
        L[2] += x * vy - y * vx;
        const double v = fabs(vx) + fabs(vy) + fabs(vz);
        *sp += v;
        *ke += vx * vx + vy * vy + vz * vz;
        *sl += (fabs(x) + fabs(y) + fabs(z)) * v;
    }
    free(r);
}

static void check_row(const pl_collision_rule_t *rule)
{
    pl_test_box_t b;
    pl_test_box_make(&b, 6, 5.0, 2);
    const size_t nc = b.g.ncells;
    double (*P0)[3] = malloc(nc * sizeof *P0), (*L0)[3] = malloc(nc * sizeof *L0), *E0 = malloc(nc * sizeof *E0);
    for (size_t c = 0; c < nc; ++c) {
        double sp, sl;
        cell_moments(&b, c, P0[c], L0[c], &sp, &sl, &E0[c]);
    }
    collide(&b, rule, 3);
    int big = 0, cells3 = 0;
    double worst = 0.0;
    for (size_t c = 0; c < nc; ++c) {
        double P[3], L[3], sp, sl, ke;
        cell_moments(&b, c, P, L, &sp, &sl, &ke);
        for (int d = 0; d < 3; ++d)
            cr_assert(fabs(P[d] - P0[c][d]) <= TOL * sp, "%s: cell %zu momentum %d: %.17g vs %.17g", rule->name, c,
                      d, P[d], P0[c][d]);
        if (!rule->thermostat)
            cr_assert(fabs(ke - E0[c]) <= TOL * E0[c], "%s: cell %zu kinetic energy %.17g, before %.17g", rule->name,
                      c, ke, E0[c]);
        if (b.start[c + 1] - b.start[c] < 3) continue;
        cells3++;
        double dl = 0.0;
        for (int d = 0; d < 3; ++d) dl = fmax(dl, fabs(L[d] - L0[c][d]) / sl);
        worst = fmax(worst, dl);
        if (rule->angular)
            cr_assert(dl <= TOL, "%s: cell %zu angular momentum changed by %.3g of its scale", rule->name, c, dl);
        big += dl > 1e-3;
    }
    cr_log_info("%s: %d of %d cells with >= 3 particles changed L by > 1e-3 of sum |r||v| (largest %.3g)\n",
                rule->name, big, cells3, worst);
    if (!rule->angular)
        cr_assert_gt(big, cells3 / 2, "%s says it does not keep L, yet only %d of %d cells changed it", rule->name,
                     big, cells3);
    free(P0);
    free(L0);
    free(E0);
    pl_test_box_free(&b);
}

Test(collision_rules, every_row_conserves_momentum_and_angular_momentum_as_it_says)
{
    int n = 0;
    for (const pl_collision_rule_t *r; (r = pl_collision_rule(n)); ++n) {
        cr_assert_str_eq(pl_collision_rule_names[n], r->name);
        check_row(r);
    }
    cr_assert_null(pl_collision_rule_names[n], "one name per row");
    cr_assert_geq(n, 3);
}

Test(collision_rules, same_bits_at_1_2_3_threads)
{
    for (int k = 0; pl_collision_rule(k); ++k) {
        pl_test_box_t b[3];
        for (int t = 0; t < 3; ++t) {
            pl_test_box_make(&b[t], 6, 5.0, t + 1);
            collide(&b[t], pl_collision_rule(k), 7);
        }
        for (int t = 1; t < 3; ++t)
            for (int d = 0; d < 3; ++d)
                cr_assert_eq(memcmp(b[t].f.v[d], b[0].f.v[d], b[0].f.n * sizeof(pl_real)), 0,
                             "%s: %d threads differ from 1", pl_collision_rule(k)->name, t + 1);
        for (int t = 0; t < 3; ++t) pl_test_box_free(&b[t]);
    }
}

/* A new grid shift and sort before collision s, as a run would (the rigid
 * rotation that +a keeps only relaxes when cells change members). */
static void reshuffle(pl_test_box_t *b, uint64_t s)
{
    pl_grid_draw_shift(&b->g, 5, s, 1);
    pl_srd_bin(&b->f, &b->g, b->hist, b->nthreads);
    pl_srd_sort(&b->f, b->hist, b->start, b->g.ncells, b->nthreads);
    pl_fluid_swap(&b->f);
}

Test(collision_rules, a_thermostat_rule_sets_the_temperature)
{
    enum { BURN = 40, K = 400, NB = 16 };
    const double kT = 0.5; /* the box starts at kT = 1/3 */
    for (int k = 0; pl_collision_rule(k); ++k) {
        const pl_collision_rule_t *rule = pl_collision_rule(k);
        if (!rule->thermostat) continue;
        pl_test_box_t b;
        pl_test_box_make(&b, 8, 5.0, 1); /* one thread: 4 parallel regions a collision cost more than they save here */
        double est[K], mean = 0.0, var = 0.0, dof_mean = 0.0, blk[NB] = {0};
        for (int s = 0; s < BURN + K; ++s) {
            reshuffle(&b, (uint64_t)s + 1);
            collide(&b, rule, (uint64_t)s);
            const size_t nb = (b.g.ncells + PL_CELL_BLOCK - 1) / PL_CELL_BLOCK;
            double s2 = 0.0, n = 0.0;
            for (size_t j = 0; j < nb; ++j) {
                s2 += b.block[2 * j];
                n += b.block[2 * j + 1];
            }
            if (s < BURN) continue;
            est[s - BURN] = s2 / n;
            mean += est[s - BURN] / K;
            dof_mean += n / K;
            blk[(s - BURN) / (K / NB)] += est[s - BURN] / (K / NB);
        }
        for (int s = 0; s < K; ++s) var += (est[s] - mean) * (est[s] - mean) / (K - 1);
        double bvar = 0.0;
        for (int j = 0; j < NB; ++j) bvar += (blk[j] - mean) * (blk[j] - mean) / (NB - 1);
        const double se = sqrt(bvar / NB), var_th = 2.0 * kT * kT / dof_mean;
        cr_log_info("%s: kT = %.5f +- %.5f (bath %g; chi^2 SE %.5f); variance of one collision's kT %.3g (chi^2: "
                    "%.3g)\n", rule->name, mean, se, kT, kT * sqrt(2.0 / (dof_mean * K)), var, var_th);
        cr_assert_lt(fabs(mean - kT), 4.0 * se, "%s: kT %.5f vs %g (SE %.2g)", rule->name, mean, kT, se);
        /* chi^2 per collision where every relative degree of freedom is drawn anew (not +a: the rigid
         * rotation keeps its energy from one collision to the next) */
        if (!rule->angular)
            cr_assert_lt(fabs(var / var_th - 1.0), 4.0 * sqrt(2.0 / (K - 1)), "%s: variance %.3g vs %.3g",
                         rule->name, var, var_th);
        pl_test_box_free(&b);
    }
}

/* The scene picks a rule by name; a physical scene maps with the rule's
 * viscosity (its row's theory, not PL's); a rule that is itself a
 * thermostat refuses another; SRD+a refuses to run without one. */
static int load(const char *rule, const char *extra, pl_scene_t *sc, pl_err_t *err)
{
    char text[2048];
    snprintf(text, sizeof text,
             "srd: { rule = \"%s\"; };\n%s"
             "physical: { radius = 0.4e-6; temperature = 300.0; viscosity = 1.0e-6; gravity = 9.81;"
             " hamaker = 4.76e-20; primary_minimum = 0.008e-6; particle_density = 3.9e3; solvent_density = 1.0e3;"
             " box = [6.4e-6, 6.4e-6, 12.8e-6]; };\n"
             "coarse_graining: { coupling = \"I\"; cell_size = 0.5; particles_per_cell = 5; mean_free_path = 0.1;"
             " md_dt = 2e-6; };\n",
             rule, extra);
    return pl_scene_load_string(text, "test.cfg", sc, err);
}

Test(collision_rules, scenes_pick_rows_by_name_and_map_with_their_viscosity)
{
    pl_scene_t *sc = malloc(sizeof *sc);
    pl_err_t err = {0, ""};
    double nu_srd = 0.0;
    for (int k = 0; pl_collision_rule(k); ++k) {
        const pl_collision_rule_t *rule = pl_collision_rule(k);
        /* every rule runs without a thermostat (SRD+a, which keeps the cells' energy now, too) */
        cr_assert_eq(load(rule->name, "", sc, &err), 0, "%s: %s", rule->name, err.msg);
        cr_assert_eq(sc->srd.rule, k);
        pl_srd_theory_t th;
        pl_srd_theory(sc->fluid.density, k, sc->srd.alpha_deg * M_PI / 180.0, sc->srd.dt, 1.0, &th);
        cr_assert_float_eq(sc->mapping.map.nu_sim, th.nu, 1e-12 * th.nu, "%s: mapped nu %.6g, row's %.6g",
                           rule->name, sc->mapping.map.nu_sim, th.nu);
        if (k == PL_RULE_RANDOM_AXIS) nu_srd = th.nu;
        else cr_assert(fabs(th.nu / nu_srd - 1.0) > 0.01, "%s maps like random_axis", rule->name);
        if (rule->thermostat) {
            cr_assert_eq(load(rule->name, "thermostat: { type = \"rescale\"; };\n", sc, &err), PL_ERR_INPUT);
            cr_assert(strstr(err.msg, "itself"), "%s", err.msg);
        }
    }
    free(sc);
}
