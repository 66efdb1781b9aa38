/* Walls normal to x and y (box.walls_xy: a capillary, Hecht Sec. VIII.A
 * option ii; with walls_z a closed box).
 *
 * - The drift reflects at the earliest wall crossing, several times near an
 *   edge: exact positions and velocities for a particle driven into an edge
 *   (bounce-back: back along its path; specular: mirrored twice).
 * - The stream-in-scatter pipeline (pl_srd_stream_count + pl_srd_stream_sort)
 *   leaves bitwise the state of pl_srd_stream_bin + pl_srd_sort with walls.
 * - Slip x/y walls leave P_z alone: with a body force along the channel it
 *   grows by exactly N g dt per step.
 * - Containment: in a box closed on all axes no fluid particle and no
 *   colloid centre is ever outside [0, L]^3, for every coupling, with body
 *   forces and gravity pushing towards an edge.
 * - Determinism: 1, 2 and 3 threads give bitwise the same fluid and colloid
 *   state, and N + checkpoint + restart + N steps equals 2N steps bitwise.
 * - Moving z walls (shear) in a closed box, for the fluid and every
 *   coupling: containment, the top wall drags the fluid, 1 vs 2 threads and
 *   restart bitwise (the wall impulses included).  With slip x/y walls
 *   (specular: they change only P_x, P_y) P_z of the fluid changes by
 *   exactly the z walls' counted impulse, so no z-wall bounce near an edge
 *   is lost or counted twice; with no-slip x/y walls their momentum
 *   exchange is not counted (the stress columns are the z walls'). 
 * - Clear errors: boxes too thin, colloids wider than the capillary, a
 *   checkpoint of another capillary. */
#include <math.h>
#include <stdio.h>
#include <unistd.h>

#include "peloid/checkpoint.h"
#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/io.h"
#include "peloid/rng.h"
#include "peloid/srd_kernels.h"
#include "support.h"

/* Round-off of the stored positions and velocities (double, or float with
 * make DEFS=-DPL_SINGLE). */
static const double EPS = sizeof(pl_real) == sizeof(float) ? 1e-6 : 1e-12;

/* One particle, one drift of dt = 0.2 into the edge x = y = 0. */
static void drift_one(int walls_xy, double r[3], double v[3], uint32_t *cell)
{
    pl_err_t err = {0, ""};
    pl_fluid_t f;
    pl_grid_t g;
    const int L[3] = {4, 4, 4}, walls[3] = {walls_xy, walls_xy, PL_WALLS_NONE};
    pl_grid_init(&g, L, walls);
    cr_assert_eq(pl_fluid_create(1, 0, 1, &f, &err), 0);
    const double r0[3] = {0.1, 0.1, 1.0}, v0[3] = {-1.0, -2.0, 0.3};
    for (int d = 0; d < 3; ++d) {
        f.r[d][0] = (pl_real)r0[d];
        f.v[d][0] = (pl_real)v0[d];
    }
    pl_stream_params_t p;
    memset(&p, 0, sizeof p);
    p.dt = 0.2;
    uint32_t *hist = pl_alloc(g.ncells * sizeof(uint32_t), 1);
    pl_srd_stream_bin(&f, &g, &p, hist, 1);
    for (int d = 0; d < 3; ++d) {
        r[d] = f.r[d][0];
        v[d] = f.v[d][0];
    }
    *cell = f.cell[0];
    pl_free(hist);
    pl_fluid_free(&f);
}

Test(capillary, drift_reflects_at_the_earliest_wall_of_an_edge)
{
    double r[3], v[3];
    uint32_t cell;
    /* no-slip: y wall first (t = 0.05), v -> -v, back along the path */
    drift_one(PL_WALLS_NOSLIP, r, v, &cell);
    const double rn[3] = {0.2, 0.3, 0.97}, vn[3] = {1.0, 2.0, -0.3};
    for (int d = 0; d < 3; ++d) {
        cr_assert_float_eq(r[d], rn[d], EPS, "noslip r[%d] = %.15g", d, r[d]);
        cr_assert_float_eq(v[d], vn[d], EPS, "noslip v[%d] = %.15g", d, v[d]);
    }
    /* closed axes have L + 2 cells, index floor(x) + 1 (no shift): (1, 1, 0) */
    cr_assert_eq(cell, (0u * 6u + 1u) * 6u + 1u, "cell %u", cell);
    /* slip: y wall at t = 0.05, then x wall at t = 0.1: both normals flipped */
    drift_one(PL_WALLS_SLIP, r, v, &cell);
    const double rs[3] = {0.1, 0.3, 1.06}, vs[3] = {1.0, 2.0, 0.3};
    for (int d = 0; d < 3; ++d) {
        cr_assert_float_eq(r[d], rs[d], EPS, "slip r[%d] = %.15g", d, r[d]);
        cr_assert_float_eq(v[d], vs[d], EPS, "slip v[%d] = %.15g", d, v[d]);
    }
}

/* n particles, uniform in the box, thermal-ish velocities with a kick. */
static void fill(pl_fluid_t *f, const pl_grid_t *g, size_t n)
{
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_fluid_create(n, 0, 2, f, &err), 0);
    for (size_t i = 0; i < n; ++i) {
        pl_rand4_t r = pl_rng_uniform4(9, 1, 0, i, 0), u = pl_rng_uniform4(9, 2, 0, i, 0);
        for (int d = 0; d < 3; ++d) {
            f->r[d][i] = (pl_real)(r.u[d] * g->L[d]);
            f->v[d][i] = (pl_real)(3.0 * (u.u[d] - 0.5));
        }
    }
}

Test(capillary, stream_in_scatter_matches_stream_then_sort)
{
    const int L[3] = {6, 5, 7};
    const int layouts[3][3] = {{PL_WALLS_NONE, PL_WALLS_NONE, PL_WALLS_NOSLIP},
                               {PL_WALLS_NOSLIP, PL_WALLS_NOSLIP, PL_WALLS_NONE},
                               {PL_WALLS_SLIP, PL_WALLS_SLIP, PL_WALLS_NOSLIP}};
    const size_t n = 2000;
    const int nt = 2;
    for (int k = 0; k < 3; ++k) {
        pl_grid_t g;
        pl_grid_init(&g, L, layouts[k]);
        pl_grid_draw_shift(&g, 3, (uint64_t)k, 1);
        pl_stream_params_t p;
        memset(&p, 0, sizeof p);
        p.dt = 0.7;
        p.accel[0] = 0.05;
        pl_fluid_t a, b;
        fill(&a, &g, n);
        fill(&b, &g, n);
        uint32_t *ha = pl_alloc((size_t)nt * g.ncells * sizeof(uint32_t), nt),
                 *hb = pl_alloc((size_t)nt * g.ncells * sizeof(uint32_t), nt);
        uint32_t *sa = pl_alloc((g.ncells + 1) * sizeof(uint32_t), nt), *sb = pl_alloc((g.ncells + 1) * sizeof(uint32_t), nt);
        pl_srd_stream_bin(&a, &g, &p, ha, nt);
        pl_srd_sort(&a, ha, sa, g.ncells, nt);
        pl_fluid_swap(&a);
        pl_srd_stream_count(&b, &g, &p, hb, nt);
        pl_srd_stream_sort(&b, &g, &p, hb, sb, nt);
        pl_fluid_swap(&b);
        cr_assert_eq(memcmp(sa, sb, (g.ncells + 1) * sizeof(uint32_t)), 0, "layout %d: cell_start", k);
        for (int d = 0; d < 3; ++d) {
            cr_assert_eq(memcmp(a.r[d], b.r[d], n * sizeof(pl_real)), 0, "layout %d: r[%d]", k, d);
            cr_assert_eq(memcmp(a.v[d], b.v[d], n * sizeof(pl_real)), 0, "layout %d: v[%d]", k, d);
            for (size_t i = 0; i < n; ++i)
                cr_assert(a.r[d][i] >= 0 && a.r[d][i] <= L[d], "layout %d: r[%d] = %g", k, d, (double)a.r[d][i]);
        }
        pl_free(ha); pl_free(hb); pl_free(sa); pl_free(sb);
        pl_fluid_free(&a);
        pl_fluid_free(&b);
    }
}

Test(capillary, slip_walls_leave_the_channel_momentum_alone)
{
    pl_sim_t *sim = pl_test_sim("seed = 5;\nbox: { cells = [5, 6, 7]; walls_xy = \"slip\"; };\n"
                                "fluid: { body_force = [0.0, 0.0, 0.01]; };\nsrd: { dt = 0.5; };\n",
                                2);
    pl_fluid_obs_t o0, o1;
    double kT;
    pl_sim_observe(sim, &o0, &kT);
    pl_test_steps(sim, 100);
    pl_sim_observe(sim, &o1, &kT);
    double expect = (double)sim->fluid.n * 0.01 * 0.5 * 100;
    cr_assert(fabs(o1.momentum[2] - o0.momentum[2] - expect) < 1e3 * EPS * expect, "P_z gained %.12g, expected %.12g",
              o1.momentum[2] - o0.momentum[2], expect);
    pl_sim_free(sim);
}

#define BOX "box: { cells = [10, 9, 8]; walls_xy = \"noslip\"; walls_z = \"%s\"; };\n"
#define FLUID "fluid: { density = 5.0; body_force = [-0.02, -0.015, -0.01]; };\nsrd: { dt = 0.1; };\n"
#define COLL(extra)                                                                                \
    "colloids: { count = 8; radius = 1.4; mass_density = 8.0; temperature = 1.0; init = \"random\";\n" \
    "  substeps = 8; pairs = \"hertz\"; gravity = [-0.02, -0.02, -0.02]; " extra " };\n"

/* Closed boxes (x/y no-slip walls, z no-slip or slip) with colloids under
 * gravity towards the edge at the origin, one per coupling. */
static const char *closed[] = {
    "seed = 21;\n" BOX FLUID COLL("") "coupling: { method = \"hecht1\"; placement = \"entry\"; };\n"
    "output: { track_fluid = true; };\n",
    "seed = 22;\n" BOX FLUID "thermostat: { type = \"heyes\"; };\n" COLL("")
    "coupling: { method = \"hecht2\"; };\noutput: { fields_interval = 2; };\n",
    "seed = 23;\n" BOX FLUID COLL("") "coupling: { method = \"potential\"; sigma_cf = 1.4; epsilon_cf = 2.5; };\n"
    "output: { track_fluid = true; };\n",
};
enum { NCLOSED = sizeof closed / sizeof *closed };

static pl_sim_t *closed_sim(size_t k, const char *walls_z, int nthreads)
{
    char txt[1024];
    snprintf(txt, sizeof txt, closed[k], walls_z);
    return pl_test_sim(txt, nthreads);
}

static void assert_inside(const pl_sim_t *sim, const char *what)
{
    const int *L = sim->grid.L;
    for (size_t i = 0; i < sim->fluid.n; ++i)
        for (int d = 0; d < 3; ++d) {
            double x = sim->fluid.r[d][i];
            if (!(x >= 0.0 && x <= L[d]))
                cr_assert_fail("%s, step %lld: fluid particle %zu has r[%d] = %.17g outside [0, %d]", what,
                               sim->step, i, d, x, L[d]);
        }
    const pl_colloid_t *c = sim->colloids;
    for (size_t i = 0; c && i < c->n; ++i) {
        const double r[3] = {c->x[i], c->y[i], c->z[i]};
        for (int d = 0; d < 3; ++d)
            if (!(r[d] >= 0.0 && r[d] <= L[d]))
                cr_assert_fail("%s, step %lld: colloid %zu has r[%d] = %.17g outside [0, %d]", what, sim->step,
                               i, d, r[d], L[d]);
    }
}

Test(capillary, closed_box_keeps_every_particle_inside, .timeout = 120)
{
    const long long steps = pl_test_quick() ? 20 : 200;
    const char *wz[2] = {"noslip", "slip"};
    pl_err_t err = {0, ""};
    for (size_t k = 0; k < NCLOSED; ++k)
        for (int w = 0; w < 2; ++w) {
            pl_sim_t *sim = closed_sim(k, wz[w], 2);
            char what[64];
            snprintf(what, sizeof what, "scene %zu, walls_z %s", k, wz[w]);
            double x0 = sim->colloids->x[0];
            for (long long s = 0; s < steps; ++s) {
                cr_assert_eq(pl_sim_step(sim, &err), 0, "%s: %s", what, err.msg);
                assert_inside(sim, what);
            }
            cr_assert_neq(x0, sim->colloids->x[0], "%s: colloids frozen", what);
            pl_sim_free(sim);
        }
}

static void assert_same(const pl_sim_t *a, const pl_sim_t *b, const char *what)
{
    pl_test_assert_same_fluid(a, b, what);
    const pl_colloid_t *p = a->colloids, *q = b->colloids;
    if (!p) return;
    const size_t nc = p->n;
    const double *pa[] = {p->x, p->y, p->z, p->vx, p->vy, p->vz, p->wx, p->wy, p->wz, p->fx, p->fy, p->fz};
    const double *qa[] = {q->x, q->y, q->z, q->vx, q->vy, q->vz, q->wx, q->wy, q->wz, q->fx, q->fy, q->fz};
    for (size_t k = 0; k < sizeof pa / sizeof *pa; ++k)
        cr_assert_eq(memcmp(pa[k], qa[k], nc * sizeof(double)), 0, "%s: colloid array %zu", what, k);
}

typedef pl_sim_t *(*scene_maker_t)(size_t k, const char *walls, int nthreads);

/* N steps on 2 threads, checkpoint to path, resume on `resumed_threads`,
 * N more steps: the state must equal ref's after 2N steps. */
static void assert_restart_matches(const pl_sim_t *ref, scene_maker_t make, size_t k, const char *walls,
                                   long long N, int resumed_threads, const char *path, const char *what)
{
    pl_err_t err = {0, ""};
    pl_sim_t *half = make(k, walls, 2);
    pl_test_steps(half, N);
    cr_assert_eq(pl_checkpoint_write(half, path, &err), 0, "%s", err.msg);
    pl_sim_free(half);
    pl_sim_t *resumed = make(k, walls, resumed_threads);
    cr_assert_eq(pl_checkpoint_read(resumed, path, &err), 0, "%s", err.msg);
    pl_test_steps(resumed, N);
    assert_same(ref, resumed, what);
    pl_sim_free(resumed);
}

Test(capillary, thread_count_and_restart_do_not_change_results, .timeout = 120)
{
    const long long N = pl_test_quick() ? 5 : 25;
    char path[] = "/tmp/peloid_test_capckpt_XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    close(fd);
    for (size_t k = 0; k < NCLOSED; ++k) {
        const char *wz = k == 1 ? "none" : "noslip"; /* scene 1: open capillary along z */
        pl_sim_t *ref = closed_sim(k, wz, 1);
        pl_test_steps(ref, 2 * N);
        for (int t = 2; t <= 3; ++t) {
            pl_sim_t *other = closed_sim(k, wz, t);
            pl_test_steps(other, 2 * N);
            assert_same(ref, other, "threads");
            pl_sim_free(other);
        }
        assert_restart_matches(ref, closed_sim, k, wz, N, 3, path, "restart");
        pl_sim_free(ref);
    }
    unlink(path);
}

/* Closed boxes with moving z walls: the fluid alone and one per coupling;
 * walls_xy noslip or slip.  No body force (the momentum balance). */
#define MOVING                                                                                     \
    "box: { cells = [10, 9, 8]; walls_xy = \"%s\"; walls_z = \"noslip\";\n"                         \
    "  wall_velocity_bottom = [-0.3, 0.2, 0.0]; wall_velocity_top = [0.3, -0.1, 0.0]; };\n"          \
    "fluid: { density = 5.0; };\nsrd: { dt = 0.1; };\n"
static const char *moving[] = {
    "seed = 31;\n" MOVING "thermostat: { type = \"heyes\"; };\n",
    "seed = 32;\n" MOVING COLL("") "coupling: { method = \"hecht1\"; };\noutput: { track_fluid = true; };\n",
    "seed = 33;\n" MOVING "thermostat: { type = \"heyes\"; };\n" COLL("") "coupling: { method = \"hecht2\"; };\n",
    "seed = 34;\n" MOVING COLL("") "coupling: { method = \"potential\"; sigma_cf = 1.4; epsilon_cf = 2.5; };\n",
};
enum { NMOVING = sizeof moving / sizeof *moving };

static pl_sim_t *moving_sim(size_t k, const char *walls_xy, int nthreads)
{
    char txt[1024];
    snprintf(txt, sizeof txt, moving[k], walls_xy);
    return pl_test_sim(txt, nthreads);
}

Test(capillary, moving_z_walls_in_a_closed_box, .timeout = 120)
{
    const long long N = pl_test_quick() ? 5 : 25;
    char path[] = "/tmp/peloid_test_capckpt_XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    close(fd);
    pl_err_t err = {0, ""};
    for (size_t k = 0; k < NMOVING; ++k) {
        char what[64];
        snprintf(what, sizeof what, "moving z walls, scene %zu", k);
        pl_sim_t *ref = moving_sim(k, "noslip", 1);
        for (long long s = 0; s < 2 * N; ++s) {
            cr_assert_eq(pl_sim_step(ref, &err), 0, "%s: %s", what, err.msg);
            assert_inside(ref, what);
        }
        cr_assert(ref->wall_impulse[1][0] > 1.0, "%s: the top wall (u_x = +0.3) gave P_x %g", what,
                  ref->wall_impulse[1][0]);
        pl_sim_t *other = moving_sim(k, "noslip", 2);
        pl_test_steps(other, 2 * N);
        assert_same(ref, other, what);
        pl_sim_free(other);
        assert_restart_matches(ref, moving_sim, k, "noslip", N, 1, path, what);
        pl_sim_free(ref);
    }
    unlink(path);
    /* slip x/y walls: P_z balance (tolerance as tests/physics/test_shear.c) */
    pl_sim_t *sim = moving_sim(0, "slip", 2);
    double P0[3], P1[3], M;
    pl_test_steps(sim, 5);
    pl_coupling_total_momentum(sim, P0, &M);
    const double W0 = sim->wall_impulse[0][2] + sim->wall_impulse[1][2];
    pl_test_steps(sim, pl_test_quick() ? 10 : 100);
    pl_coupling_total_momentum(sim, P1, &M);
    const double W = sim->wall_impulse[0][2] + sim->wall_impulse[1][2] - W0;
    cr_assert(fabs(sim->wall_impulse[0][2]) > 1.0, "the bottom wall gave no P_z (%g)", sim->wall_impulse[0][2]);
    cr_assert(fabs(P1[2] - P0[2] - W) < 1e-7, "P_z changed by %.12g, the z walls gave %.12g", P1[2] - P0[2], W);
    pl_sim_free(sim);
}

/* The x/y walls' count (sim->wall_impulse[2], thermo's s_side_*): in a
 * capillary periodic along z with a body force g on the fluid, the z
 * momentum of fluid + colloids changes by exactly N g t plus what the x/y
 * walls gave: streaming bounce-backs, virtual particles of cells they cut,
 * coupling I pushes through them, the potential coupling's own reflections,
 * and coupling II cells holding one of Hecht's R = 0.62 a0 colloids.
 * Tolerance as tests/physics/test_shear.c (1e-7 against sqrt(M kT) ~ 1e2). */
Test(capillary, side_walls_balance_the_momentum_for_every_coupling, .timeout = 120)
{
    static const char *cases[][2] = {
        {"", ""},
        {"colloids: { count = 8; radius = 2.0; init = \"random\"; pairs = \"hertz\"; };\n",
         "coupling: { method = \"hecht1\"; };\n"},
        {"colloids: { count = 8; radius = 2.0; init = \"random\"; pairs = \"hertz\"; };\n",
         "coupling: { method = \"hecht1\"; boundary = \"slip\"; placement = \"nearest\"; };\n"},
        {"colloids: { count = 8; radius = 2.0; init = \"random\"; pairs = \"hertz\"; };\n",
         "coupling: { method = \"hecht2\"; };\n"},
        {"colloids: { count = 8; radius = 2.0; init = \"random\"; pairs = \"hertz\"; };\n",
         "coupling: { method = \"potential\"; sigma_cf = 2.0; };\n"},
        {"colloids: { count = 30; radius = 0.62; init = \"random\"; pairs = \"hertz\"; substeps = 16; };\n",
         "coupling: { method = \"hecht2\"; };\n"},
    };
    const double g = 0.02, dt = 0.1;
    for (size_t k = 0; k < sizeof cases / sizeof *cases; ++k) {
        char scene[1024];
        snprintf(scene, sizeof scene,
                 "seed = 5;\nbox: { cells = [10, 10, 10]; walls_xy = \"noslip\"; };\n"
                 "fluid: { density = 5.0; body_force = [0.0, 0.0, %g]; };\nsrd: { dt = %g; };\n"
                 "thermostat: { type = \"heyes\"; };\n%s%s",
                 g, dt, cases[k][0], cases[k][1]);
        pl_sim_t *sim = pl_test_sim(scene, 2);
        double P0[3], P1[3], M;
        pl_test_steps(sim, 5);
        pl_coupling_total_momentum(sim, P0, &M);
        const double S0 = sim->wall_impulse[2][2];
        const long long n = pl_test_quick() ? 10 : 100;
        pl_test_steps(sim, n);
        pl_coupling_total_momentum(sim, P1, &M);
        const double S = sim->wall_impulse[2][2] - S0, body = (double)sim->fluid.n * g * dt * (double)n;
        cr_assert(fabs(S) > 1.0, "case %zu: the x/y walls exchanged no P_z (%g)", k, S);
        cr_assert(fabs(P1[2] - P0[2] - body - S) < 1e-7,
                  "case %zu: P_z changed by %.12g, body force %.12g + x/y walls %.12g", k, P1[2] - P0[2], body, S);
        pl_sim_free(sim);
    }
}

static void expect_error(const char *text, const char *needle)
{
    static pl_scene_t scene;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_scene_load_string(text, "s.cfg", &scene, &err), PL_ERR_INPUT, "accepted: %s", text);
    cr_assert(strstr(err.msg, needle), "message \"%s\" lacks \"%s\"", err.msg, needle);
}

Test(capillary, clear_errors)
{
    expect_error("box: { cells = [1, 8, 8]; walls_xy = \"noslip\"; };\n", "Lx >= 2 and Ly >= 2");
    expect_error("box: { cells = [8, 1, 8]; walls_xy = \"slip\"; };\n", "s.cfg:1: key 'box.cells'");
    expect_error("box: { cells = [8, 8, 8]; walls_xy = \"closed\"; };\n", "\"none\" \"noslip\" \"slip\"");
    expect_error("box: { cells = [4, 9, 24]; walls_xy = \"noslip\"; };\nfluid: { density = 0.0; };\n"
                 "colloids: { count = 1; radius = 2.0; };\n",
                 "does not fit between the x walls (Lx = 4)");
    /* restarting a capillary from a periodic checkpoint, and the reverse */
    char path[] = "/tmp/peloid_test_capckpt_XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    close(fd);
    const char *a = "seed = 3;\nbox: { cells = [6, 6, 6]; };\n";
    const char *b = "seed = 3;\nbox: { cells = [6, 6, 6]; walls_xy = \"noslip\"; };\n";
    const char *pairs[2][2] = {{a, b}, {b, a}};
    for (int k = 0; k < 2; ++k) {
        pl_err_t err = {0, ""};
        pl_sim_t *s = pl_test_sim(pairs[k][0], 1);
        cr_assert_eq(pl_checkpoint_write(s, path, &err), 0, "%s", err.msg);
        pl_sim_free(s);
        s = pl_test_sim(pairs[k][1], 1);
        cr_assert_eq(pl_checkpoint_read(s, path, &err), PL_ERR_INPUT, "case %d accepted", k);
        cr_assert(strstr(err.msg, "box.walls_xy"), "case %d: %s", k, err.msg);
        pl_sim_free(s);
    }
    unlink(path);
}
