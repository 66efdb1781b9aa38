/* Coupling at the system level: bitwise determinism across thread counts (1,
 * 2, 3) for each coupling, and gravity in a periodic box (Hecht Sec. VIII.A iii): the
 * fluid carries the opposite of the colloids' weight, so the total momentum
 * (centre of mass) stays at rest while the colloids sediment through the
 * fluid; without compensation the drift removal brings it back to rest. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/coupling_kernels.h"
#include "support.h"

static const char *BASE =
    "seed = 9;\n"
    "box: { cells = [12, 12, 12]; };\n"
    "fluid: { density = 5.0; temperature = 1.0; };\n"
    "srd: { dt = 0.1; };\n"
    "colloids: { count = 8; radius = 2.0; mass_density = 10.0; temperature = 1.0;\n"
    "  init = \"random\"; pairs = \"hertz\"; substeps = 4; %s };\n"
    "coupling: { %s };\n%s";

static pl_sim_t *make(const char *colloid_extra, const char *coupling, const char *extra, int threads)
{
    char text[2048];
    snprintf(text, sizeof text, BASE, colloid_extra, coupling, extra);
    return pl_test_sim(text, threads);
}

static int same(const void *a, const void *b, size_t bytes) { return memcmp(a, b, bytes) == 0; }

static void check_threads(const char *coupling)
{
    long long steps = pl_test_quick() ? 10 : 60;
    pl_sim_t *a = make("", coupling, "thermostat: { type = \"heyes\"; };\n", 1);
    pl_test_steps(a, steps);
    if (pl_coupling_of(a)->method == PL_COUPLE_POTENTIAL) /* the blocked force sum is exercised */
        cr_expect_geq(pl_coupling_wca_blocks(pl_coupling_of(a)->pot->nnear, a->colloids->n), 2,
                      "%zu selected particles", pl_coupling_of(a)->pot->nnear);
    for (int t = 2; t <= 3; ++t) {
        pl_sim_t *b = make("", coupling, "thermostat: { type = \"heyes\"; };\n", t);
        pl_test_steps(b, steps);
        size_t n = a->fluid.n * sizeof(pl_real);
        for (int d = 0; d < 3; ++d) {
            cr_expect(same(a->fluid.r[d], b->fluid.r[d], n), "%s, %d threads: fluid r[%d] differs", coupling, t, d);
            cr_expect(same(a->fluid.v[d], b->fluid.v[d], n), "%s, %d threads: fluid v[%d] differs", coupling, t, d);
        }
        const pl_colloid_t *ca = a->colloids, *cb = b->colloids;
        size_t m = ca->n * sizeof(double);
        cr_expect(same(ca->x, cb->x, m) && same(ca->y, cb->y, m) && same(ca->z, cb->z, m),
                  "%s, %d threads: colloid positions differ", coupling, t);
        cr_expect(same(ca->vx, cb->vx, m) && same(ca->vy, cb->vy, m) && same(ca->vz, cb->vz, m),
                  "%s, %d threads: colloid velocities differ", coupling, t);
        cr_expect(same(ca->wx, cb->wx, m) && same(ca->wy, cb->wy, m) && same(ca->wz, cb->wz, m),
                  "%s, %d threads: colloid angular velocities differ", coupling, t);
        if (pl_coupling_of(a)->method == PL_COUPLE_HECHT1)
            cr_expect_eq(pl_coupling_of(a)->c1->events, pl_coupling_of(b)->c1->events, "event counts differ");
        pl_sim_free(b);
    }
    pl_sim_free(a);
}

Test(coupling_system, bitwise_threads_hecht1, .timeout = 120)
{
    check_threads("method = \"hecht1\"; boundary = \"stick_stochastic\";");
    check_threads("method = \"hecht1\"; boundary = \"slip\"; placement = \"nearest\";");
}

Test(coupling_system, bitwise_threads_hecht2, .timeout = 120)
{
    check_threads("method = \"hecht2\";");
}

/* sigma_cf 2.8 (> the radius 2): enough particles within reach of the
 * colloids for more than one block of the force sums */
Test(coupling_system, bitwise_threads_potential, .timeout = 120)
{
    check_threads("method = \"potential\"; sigma_cf = 2.8;");
}

/* |P| / sqrt(M kT) after each step; the colloids' weight per step is
 * sum M g dt = 8 * 335 * 0.02 * 0.1 ~ 5.4 in these units, i.e. ~0.1 of the
 * scale per step: a missing compensation fails at once. */
static void gravity_run(const char *coupling, const char *extra, double *worst, double *vrel)
{
    long long steps = pl_test_quick() ? 20 : 300;
    pl_sim_t *sim = make("gravity = [0.0, 0.0, -0.02];", coupling, extra, 2);
    double P[3], M;
    *worst = 0.0;
    double vc = 0.0;
    for (long long s = 0; s < steps; ++s) {
        pl_test_steps(sim, 1);
        pl_coupling_total_momentum(sim, P, &M);
        for (int d = 0; d < 3; ++d) *worst = fmax(*worst, fabs(P[d]) / sqrt(M));
        if (s >= steps / 2) {
            const pl_colloid_t *c = sim->colloids;
            for (size_t k = 0; k < c->n; ++k) vc += c->vz[k] / (double)c->n;
        }
    }
    /* colloid velocity relative to the fluid's (which moves up) */
    pl_fluid_obs_t o;
    double kT;
    pl_sim_observe(sim, &o, &kT);
    *vrel = vc / (double)(steps - steps / 2) - o.momentum[2] / (double)sim->fluid.n;
    pl_sim_free(sim);
}

Test(coupling_system, gravity_compensated_centre_of_mass_at_rest, .timeout = 120)
{
    /* strong gravity on purpose (momentum test, not a thermal one): the
     * coupling II settling bound is off */
    const char *cases[] = {"method = \"hecht2\"; max_settling_energy = 0;", "method = \"hecht1\";"};
    for (int k = 0; k < 2; ++k) {
        double worst, vrel;
        gravity_run(cases[k], "thermostat: { type = \"heyes\"; };\n", &worst, &vrel);
        cr_log_info("%s gravity: max |P|/sqrt(M) = %.3g, colloid v_z - fluid v_z = %.4g", cases[k],
                    worst, vrel);
        cr_expect_lt(worst, 1e-9, "%s: centre of mass moves: |P|/sqrt(M) = %.3g", cases[k], worst);
        /* quick (sanitizer) runs: 20 steps, the mean of 8 colloids' thermal v_z (~0.02) hides the settling */
        if (!pl_test_quick())
            cr_expect_lt(vrel, -1e-3, "%s: colloids do not sediment (v_rel = %.3g)", cases[k], vrel);
    }
}

/* Drift removal without gravity compensation, every 10 steps: the colloids'
 * weight W = sum M g dt per step is the only external impulse, so k steps
 * after a removal the total momentum is exactly -k W along z (the removal
 * runs at the end of its step, the colloid MD at the start of the next).
 * Measured after every step, not only right after a removal: P_z = -k W
 * within round-off (1e-9 sqrt(M)) for k = 0..9, so a removal that leaves
 * momentum, or one that does not run, fails. */
Test(coupling_system, drift_removal_without_compensation, .timeout = 120)
{
    const long long every = 10, steps = pl_test_quick() ? 30 : 300;
    pl_sim_t *sim = make("gravity = [0.0, 0.0, -0.02];",
                         "method = \"hecht2\"; compensate_gravity = false; drift_interval = 10; "
                         "max_settling_energy = 0;",
                         "thermostat: { type = \"heyes\"; };\n", 2);
    double W = 0.0;
    for (size_t k = 0; k < sim->colloids->n; ++k) W += sim->colloids->mass[k] * 0.02 * sim->scene.srd.dt;
    double worst = 0.0, largest = 0.0, P[3], M;
    for (long long s = 0; s < steps; ++s) {
        pl_test_steps(sim, 1);
        pl_coupling_total_momentum(sim, P, &M);
        const double k = (double)((sim->step - 1) % every), expect = -k * W;
        worst = fmax(worst, fmax(fmax(fabs(P[0]), fabs(P[1])), fabs(P[2] - expect)) / sqrt(M));
        largest = fmax(largest, fabs(P[2]) / sqrt(M));
    }
    cr_log_info("drift removal every %lld steps: weight %.4g per step; |P - (0, 0, -k W)| / sqrt(M) <= %.3g; "
                "largest |P_z| / sqrt(M) %.3g", every, W, worst, largest);
    cr_expect_lt(worst, 1e-9, "momentum off -k W by %.3g sqrt(M)", worst);
    const double top = (double)(every - 1) * W / sqrt(M); /* just before a removal */
    cr_expect_gt(largest, 0.999 * top, "the weight did not build momentum between removals (%.3g, expected %.3g)",
                 largest, top);
    pl_sim_free(sim);
}

/* The potential coupling's selection from the sorted cells
 * (pl_coupling_find_sorted, used while the fluid is as the last sort left
 * it) lists exactly the particles of the full scan, in the same order and
 * thread chunks: periodic, z-wall and capillary boxes, selection radii from
 * PL's (cut-off + margin) up to more than the box, with and without each
 * particle's own reach, 1 and 3 threads, after every step of a run. */
Test(coupling_system, sorted_selection_equals_full_scan, .timeout = 120)
{
    const char *walls[3] = {"", "walls_z = \"noslip\";", "walls_xy = \"noslip\";"};
    const double radii[3] = {2.0 * pow(2.0, 1.0 / 6.0) + 0.9, 4.7, 7.0};
    long long steps = pl_test_quick() ? 3 : 12;
    for (int b = 0; b < 3; ++b) {
        char text[1024];
        snprintf(text, sizeof text,
                 "seed = 9;\nbox: { cells = [12, 12, 12]; %s };\nfluid: { density = 5.0; temperature = 1.0; };\n"
                 "srd: { dt = 0.1; };\ncolloids: { count = 8; radius = 2.0; mass_density = 10.0; temperature = 1.0;\n"
                 "  init = \"random\"; pairs = \"hertz\"; substeps = 4; };\n"
                 "coupling: { method = \"potential\"; sigma_cf = 2.0; };\n",
                 walls[b]);
        pl_sim_t *sim = pl_test_sim(text, 2);
        const pl_fluid_t *f = &sim->fluid;
        const size_t L3 = 12 * 12 * 12;
        int32_t *start = malloc((L3 + 1) * sizeof *start);
        size_t cap = 8 * L3;
        int32_t *list = malloc(cap * sizeof *list);
        uint32_t *fa = malloc(f->n * sizeof *fa), *fb = malloc(f->n * sizeof *fb);
        uint32_t *ga = malloc(f->n * sizeof *ga), *gb = malloc(f->n * sizeof *gb);
        uint32_t *fc = malloc(f->n * sizeof *fc), *gc = malloc(f->n * sizeof *gc);
        double *sbuf = malloc(6 * f->n * sizeof *sbuf);
        cr_assert(fc && gc && sbuf);
        uint64_t ca[3 * 8], cb[3 * 8];
        uint32_t *cstart = malloc((sim->grid.ncells + 2) * sizeof *cstart);
        const size_t ccap = 8 * sim->grid.ncells; /* every colloid in every cell */
        int32_t *clist = malloc(ccap * sizeof *clist);
        int axis[256]; /* 3 threads x (n0 + n1 + n2) */
        double gap[256];
        uint32_t *cstart2 = malloc((sim->grid.ncells + 2) * sizeof *cstart2);
        int32_t *clist2 = malloc(ccap * sizeof *clist2);
        cr_assert(cstart2 && clist2);
        double rad[8];
        cr_assert(start && list && fa && fb && ga && gb && cstart && clist);
        size_t listed = 0;
        for (long long s = 0; s < steps; ++s) {
            pl_test_steps(sim, 1);
            const uint32_t *cells = pl_srd_cells(sim->srd);
            cr_assert(cells, "the sort is the last stage that moves particles");
            for (int r = 0; r < 3; ++r) {
                pl_coupling_colloids_t v = pl_coupling_view(sim->colloids);
                for (size_t k = 0; k < v.n; ++k) rad[k] = radii[r];
                v.rad = rad;
                size_t need = pl_coupling_lookup_build(&v, sim->grid.L, sim->grid.walls, start, list, cap);
                cr_assert_leq(need, cap);
                need = pl_coupling_cell_candidates(&sim->grid, &v, axis, gap, cstart, clist, ccap, 1);
                cr_assert_leq(need, ccap);
                for (int nt = 2; nt <= 3; ++nt) { /* the same lists for any thread count */
                    const size_t need2 = pl_coupling_cell_candidates(&sim->grid, &v, axis, gap, cstart2, clist2, ccap, nt);
                    cr_assert_eq(need2, need, "box %d, R %g, %d threads: %zu vs %zu entries", b, radii[r], nt, need2,
                                 need);
                    cr_assert(same(cstart, cstart2, (sim->grid.ncells + 1) * sizeof *cstart) &&
                                  same(clist, clist2, need * sizeof *clist),
                              "box %d, R %g, %d threads: candidate lists differ", b, radii[r], nt);
                }
                /* the radii alone, and each particle's own reach (the
                 * potential coupling's: rc 2^{1/6} sigma_cf) */
                const pl_coupling_reach_t reach = {2.0 * pow(2.0, 1.0 / 6.0), 0.1, 1e-3, 0.1};
                for (int run = 0; run < 4; ++run) { /* 1 and 3 threads, without and with */
                    const int nt = run < 2 ? 1 : 3;
                    const pl_coupling_reach_t *rp = run % 2 ? &reach : NULL;
                    pl_coupling_find(f, &sim->grid, &v, rp, start, list, nt, fa, ga, ca);
                    pl_coupling_find_sorted(f, &sim->grid, &v, rp, cstart, clist, cells, nt, fb, gb, cb);
                    for (int t = 0; t < nt; ++t) {
                        size_t lo, hi;
                        pl_chunk(f->n, t, nt, &lo, &hi);
                        cr_assert_eq(ca[t * 8 + 2], cb[t * 8 + 2], "box %d, R %g, %d threads: chunk %d lists %llu vs %llu",
                                     b, radii[r], nt, t, (unsigned long long)ca[t * 8 + 2],
                                     (unsigned long long)cb[t * 8 + 2]);
                        cr_assert(same(fa + lo, fb + lo, ca[t * 8 + 2] * sizeof *fa), "box %d, R %g: lists differ", b,
                                  radii[r]);
                        cr_assert_eq(ca[t * 8 + 3], cb[t * 8 + 3], "box %d, R %g, %d threads: chunk %d pairs %llu vs %llu",
                                     b, radii[r], nt, t, (unsigned long long)ca[t * 8 + 3],
                                     (unsigned long long)cb[t * 8 + 3]);
                        listed += ca[t * 8 + 2];
                    }
                    /* the same lists from inside the streaming
                     * (pl_coupling_select_block on each block of each
                     * chunk, in order), for blocks of the streaming's size
                     * and of odd sizes that cut runs of cells, with the
                     * state of each listed particle saved */
                    if (!rp) continue;
                    const size_t blocks[3] = {256, 37, 1}; /* 256: PL_DRIFT_BLOCK */
                    for (int bs = 0; bs < 3; ++bs) {
                        uint64_t cc[3 * 8] = {0};
                        pl_coupling_stage_t stage[3];
                        for (int t = 0; t < nt; ++t) {
                            size_t lo, hi;
                            pl_chunk(f->n, t, nt, &lo, &hi);
                            stage[t] = (pl_coupling_stage_t){.buf = sbuf + 6 * lo, .cap = hi - lo, .width = 6};
                        }
                        pl_coupling_select_ctx_t x = {.f = f, .g = &sim->grid, .c = v, .reach = reach, .cstart = cstart,
                                                      .clist = clist, .cell_start = cells, .nthreads = nt,
                                                      .found = fc, .found_cell = gc, .counts = cc, .stage = stage};
                        for (int t = 0; t < nt; ++t) {
                            size_t lo, hi;
                            pl_chunk(f->n, t, nt, &lo, &hi);
                            for (size_t i = lo; i < hi; i += blocks[bs])
                                pl_coupling_select_block(&x, t, i, hi - i < blocks[bs] ? hi : i + blocks[bs]);
                            cr_assert_eq(cc[t * 8 + 2], ca[t * 8 + 2], "box %d, R %g, %d threads, blocks of %zu: lists %llu vs %llu",
                                         b, radii[r], nt, blocks[bs], (unsigned long long)cc[t * 8 + 2],
                                         (unsigned long long)ca[t * 8 + 2]);
                            cr_assert_eq(cc[t * 8 + 3], ca[t * 8 + 3], "box %d, R %g, blocks of %zu: pairs differ", b,
                                         radii[r], blocks[bs]);
                            cr_assert_eq(cc[t * 8 + 5], 0, "no room for %llu", (unsigned long long)cc[t * 8 + 5]);
                            cr_assert(same(fa + lo, fc + lo, ca[t * 8 + 2] * sizeof *fa),
                                      "box %d, R %g, blocks of %zu: lists differ", b, radii[r], blocks[bs]);
                            for (size_t j = 0; j < cc[t * 8 + 2]; ++j) {
                                const size_t i = fc[lo + j];
                                const double *w = stage[t].buf + 6 * j;
                                const double want[6] = {f->r[0][i], f->r[1][i], f->r[2][i],
                                                        f->v[0][i], f->v[1][i], f->v[2][i]};
                                cr_assert(same(w, want, sizeof want), "particle %zu: saved state differs", i);
                                /* the cell named has the particle's candidates */
                                const uint32_t own = gb[lo + j], got = gc[lo + j];
                                cr_assert(cstart[own + 1] - cstart[own] == cstart[got + 1] - cstart[got] &&
                                              same(clist + cstart[own], clist + cstart[got],
                                                   (cstart[own + 1] - cstart[own]) * sizeof *clist),
                                          "particle %zu: cell %u named, candidates differ from cell %u", i, got, own);
                            }
                        }
                    }
                }
            }
        }
        cr_expect_gt(listed, 0);
        free(start);
        free(list);
        free(fa);
        free(fb);
        free(ga);
        free(gb);
        free(fc);
        free(gc);
        free(sbuf);
        free(cstart);
        free(clist);
        free(cstart2);
        free(clist2);
        pl_sim_free(sim);
    }
}

/* A potential coupling whose first selections find no fluid particle near
 * the colloid (a sparse fluid: 5 particles in 512 cells) runs: the selection
 * buffers exist even when empty (the gather writes their first offset). */
Test(coupling_system, potential_with_no_particle_selected, .timeout = 60)
{
    pl_sim_t *s = pl_test_sim("seed = 1;\nbox: { cells = [8, 8, 8]; };\n"
                              "fluid: { density = 0.01; temperature = 1.0; };\nsrd: { dt = 0.1; };\n"
                              "colloids: { count = 1; radius = 0.5; mass_density = 5.0; temperature = 1.0;\n"
                              "  init = \"lattice\"; pairs = \"wca\"; substeps = 4; };\n"
                              "wca: { epsilon = 2.5; sigma = 1.0; n = 24.0; };\n"
                              "coupling: { method = \"potential\"; sigma_cf = 0.5; epsilon_cf = 2.5; };\n",
                              1);
    pl_test_steps(s, 20);
    cr_expect_eq(pl_coupling_of(s)->pot->nnear, 0, "the test wants an empty selection, got %zu particles",
                 pl_coupling_of(s)->pot->nnear);
    cr_expect(isfinite(s->colloids->x[0]) && isfinite(s->fluid.v[0][0]), "state not finite");
    pl_sim_free(s);
}

/* The potential coupling counts its force evaluations (substeps + 1 per
 * collision step) and those at which the selection margin was used up: none
 * in an ordinary run; every one when the margin is zero (each then takes the
 * lookup path). */
Test(coupling_system, potential_counts_margin_exceeded, .timeout = 120)
{
    const char *cpl = "method = \"potential\"; sigma_cf = 2.0; epsilon_cf = 2.5;";
    pl_sim_t *a = make("", cpl, "", 1);
    pl_test_steps(a, 6);
    cr_expect_eq(pl_coupling_of(a)->pot->force_calls, 6 * 5, "force evaluations %llu", pl_coupling_of(a)->pot->force_calls);
    cr_expect_eq(pl_coupling_of(a)->pot->margin_exceeded, 0, "margin exceeded %llu times in an ordinary run",
                 pl_coupling_of(a)->pot->margin_exceeded);
    pl_sim_free(a);
    pl_sim_t *b = make("", cpl, "", 1);
    pl_coupling_of(b)->pot->margin = 0.0;
    pl_test_steps(b, 6);
    cr_expect_eq(pl_coupling_of(b)->pot->margin_exceeded, pl_coupling_of(b)->pot->force_calls,
                 "zero margin: %llu of %llu evaluations counted", pl_coupling_of(b)->pot->margin_exceeded,
                 pl_coupling_of(b)->pot->force_calls);
    cr_expect_gt(pl_coupling_of(b)->pot->force_calls, 0);
    pl_sim_free(b);
}

/* Coupling I's events in parallel over blocks of colloids (more than one
 * thread, periodic box) give the serial loop's bits: fluid and colloids
 * after 8 steps at 1, 2 and 3 threads, on a lattice (the parallel pass runs
 * every step after the first) and on a dense random suspension (particles
 * reflected into a second colloid: the pass may give up and the serial loop
 * runs; either way the same bits). */
Test(coupling_system, reflect_events_parallel_equal_serial, .timeout = 120)
{
    const char *tails[2] = {
        "colloids: { count = 8; radius = 2.0; mass_density = 5.0; temperature = 1.0; init = \"lattice\";\n"
        "  pairs = \"hertz\"; substeps = 4; };\n",
        "colloids: { count = 14; radius = 2.0; mass_density = 5.0; temperature = 1.0; init = \"random\";\n"
        "  pairs = \"hertz\"; substeps = 4; };\n"};
    for (int s = 0; s < 2; ++s) {
        char text[1024];
        snprintf(text, sizeof text,
                 "seed = 5;\nbox: { cells = [12, 12, 12]; };\nfluid: { density = 5.0; temperature = 1.0; };\n"
                 "srd: { dt = 0.1; };\n%scoupling: { method = \"hecht1\"; boundary = \"stick_stochastic\";\n"
                 "  placement = \"entry\"; max_reflections = 4; };\n",
                 tails[s]);
        pl_sim_t *sim[3];
        for (int t = 0; t < 3; ++t) {
            sim[t] = pl_test_sim(text, t + 1);
            pl_test_steps(sim[t], 8);
        }
        const pl_coupling1_scratch_t *sc = &pl_coupling_of(sim[1])->c1->events_scratch;
        if (s == 0) cr_expect_geq(sc->parallel, 7, "parallel event passes: %llu of 8 steps", sc->parallel);
        cr_expect_gt(pl_coupling_of(sim[0])->c1->events, 0, "scene %d: no reflection", s);
        for (int t = 1; t < 3; ++t) {
            const pl_fluid_t *a = &sim[0]->fluid, *b = &sim[t]->fluid;
            for (int d = 0; d < 3; ++d) {
                cr_assert(same(a->r[d], b->r[d], a->n * sizeof *a->r[d]), "scene %d, %d threads: positions differ", s,
                          t + 1);
                cr_assert(same(a->v[d], b->v[d], a->n * sizeof *a->v[d]), "scene %d, %d threads: velocities differ", s,
                          t + 1);
            }
            const pl_colloid_t *ca = sim[0]->colloids, *cb = sim[t]->colloids;
            cr_assert(same(ca->vx, cb->vx, ca->n * sizeof *ca->vx) && same(ca->wz, cb->wz, ca->n * sizeof *ca->wz) &&
                          same(ca->x, cb->x, ca->n * sizeof *ca->x),
                      "scene %d, %d threads: colloids differ", s, t + 1);
            cr_assert_eq(pl_coupling_of(sim[0])->c1->events, pl_coupling_of(sim[t])->c1->events);
            cr_assert_eq(pl_coupling_of(sim[0])->c1->truncations, pl_coupling_of(sim[t])->c1->truncations);
        }
        fprintf(stderr, "reflect_events_parallel: scene %d: %llu events, 2 threads: %llu parallel passes, %llu given up\n",
                s, pl_coupling_of(sim[0])->c1->events, sc->parallel, sc->gave_up);
        for (int t = 0; t < 3; ++t) pl_sim_free(sim[t]);
    }
}
