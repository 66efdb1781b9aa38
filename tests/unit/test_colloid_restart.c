/* Colloid checkpoint/restart: for colloid scenes, 2N steps == N steps +
 * checkpoint + restart + N steps, bitwise, and 1 thread == 2 threads,
 * bitwise.  The scenes switch on every piece of colloid state: velocity
 * Verlet with rotation (Hertz tangential friction gives torques), Hertz
 * damping, DLVO, WCA, walls + gravity (images, unwrapped heights), the
 * drift guard's reference energy (NVE scene), the Brownian integrator (noise
 * keyed by the MD step), polydisperse radii, multiple time stepping (slow
 * forces recomputed from the restored positions), adaptive substeps (each
 * collision step's MD steps chosen from the state), lubrication with its
 * random partner (keyed by the MD step and the pair); with and without
 * fluid.  Five scenes have >= PL_COLLOID_OMP_MIN colloids so the kernels
 * really thread. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <unistd.h>

#include "peloid/checkpoint.h"
#include "peloid/colloid.h"
#include "peloid/io.h"
#include "support.h"

#define DLVO "dlvo: { psi0 = 20.0; kappa = 1.4e8; hamaker = 4.76e-20; length_unit = 1.25e-7; };\n"

static const char *scenes[] = {
    /* Verlet + rotation, Hertz with damping and tangential friction, DLVO, fluid */
    "seed = 11;\nbox: { cells = [32, 32, 32]; };\nfluid: { density = 1.0; };\nsrd: { dt = 0.1; };\n"
    "colloids: { count = 300; init = \"random\"; radius = 1.8; polydispersity = 0.1;\n"
    "  temperature = 3.0; substeps = 4; pairs = \"dlvo, hertz\"; min_contact_steps = 0.0; };\n"
    "hertz: { K = 1000.0; beta = 2.0; gamma_t = 3.0; };\n" DLVO,
    /* NVE (drift guard with its reference energy), walls + gravity, WCA, no fluid */
    "seed = 12;\nbox: { cells = [24, 24, 24]; walls_z = \"noslip\"; };\nfluid: { density = 0.0; };\n"
    "srd: { dt = 0.1; };\n"
    "colloids: { count = 27; radius = 2.0; temperature = 1.0; substeps = 4; gravity = [0.0, 0.0, -0.02];\n"
    "  pairs = \"dlvo, hertz, wca\"; max_energy_drift = 10.0; guard_interval = 3; };\n"
    "hertz: { K = 1000.0; };\n" DLVO,
    /* Brownian, Hertz + friction + DLVO, fluid with walls */
    "seed = 13;\nbox: { cells = [32, 32, 24]; walls_z = \"slip\"; };\nfluid: { density = 1.0; };\n"
    "srd: { dt = 0.1; };\n"
    "colloids: { count = 260; init = \"random\"; radius = 1.5; polydispersity = 0.1;\n"
    "  integrator = \"brownian\"; temperature = 1.0; substeps = 10; pairs = \"dlvo, hertz\";\n"
    "  min_contact_steps = 0.0; };\n"
    "hertz: { K = 1000.0; beta = 2.0; gamma_t = 3.0; };\n" DLVO,
    /* Brownian, walls + gravity, DLVO + Hertz + WCA, no fluid */
    "seed = 14;\nbox: { cells = [24, 24, 24]; walls_z = \"noslip\"; };\nfluid: { density = 0.0; };\n"
    "srd: { dt = 0.1; };\n"
    "colloids: { count = 80; init = \"random\"; radius = 1.5; integrator = \"brownian\";\n"
    "  gravity = [0.0, 0.0, -0.05]; temperature = 1.0; substeps = 10; pairs = \"dlvo, hertz, wca\";\n"
    "  min_contact_steps = 0.0; };\n" DLVO,
    /* multiple time stepping (outer steps of 5 MD steps), Hecht Fig. 14 DLVO, coupling II */
    "seed = 15;\nbox: { cells = [10, 10, 10]; };\nfluid: { density = 5.0; };\nsrd: { dt = 0.1; };\n"
    "colloids: { count = 300; radius = 0.62; mass_density = 39.0; temperature = 1.0; substeps = 10;\n"
    "  slow_interval = 5; pairs = \"dlvo, hertz\"; min_contact_steps = 0.0; };\n"
    "coupling: { method = \"hecht2\"; };\nhertz: { K = 1000.0; };\n"
    "dlvo: { psi0 = 50.0; kappa = 3.0e8; hamaker = 4.76e-20; length_unit = 4.03e-7; };\n",
    /* adaptive substeps (10 .. 200 per collision step, multiples of the outer
     * step of 2), the contact guard on, Hecht Fig. 14 DLVO, coupling II: the
     * choice is made from the state at each collision step's start */
    "seed = 16;\nbox: { cells = [10, 10, 10]; };\nfluid: { density = 5.0; };\nsrd: { dt = 0.1; };\n"
    "colloids: { count = 300; radius = 0.62; mass_density = 39.0; temperature = 1.0; substeps = 200;\n"
    "  min_substeps = 10; adaptive_substeps = true; slow_interval = 2; pairs = \"dlvo, hertz\"; };\n"
    "coupling: { method = \"hecht2\"; };\nhertz: { K = 1000.0; };\n"
    "dlvo: { psi0 = 50.0; kappa = 3.0e8; hamaker = 4.76e-20; length_unit = 4.03e-7; };\n",
    /* lubrication with its random partner (lubrication.thermal, on by
     * default: Philox keyed by the MD step and the pair), Hecht Fig. 14
     * DLVO, coupling II; lattice gaps of 0.19 a0, inside the cut-off gap */
    "seed = 17;\nbox: { cells = [10, 10, 10]; };\nfluid: { density = 5.0; };\nsrd: { dt = 0.1; };\n"
    "colloids: { count = 300; radius = 0.62; mass_density = 39.0; temperature = 1.0; substeps = 10;\n"
    "  pairs = \"dlvo, hertz, lubrication\"; min_contact_steps = 0.0; };\n"
    "coupling: { method = \"hecht2\"; };\nhertz: { K = 1000.0; };\n"
    "lubrication: { viscosity = 5.0; cutoff_gap = 0.5; };\n"
    "dlvo: { psi0 = 50.0; kappa = 3.0e8; hamaker = 4.76e-20; length_unit = 4.03e-7; };\n",
};
enum { NSCENES = sizeof scenes / sizeof *scenes };

#define SAME(field, len, what)                                                                     \
    cr_assert_eq(memcmp(a->field, b->field, (len) * sizeof *a->field), 0, "%s: colloid %s differs", \
                 what, #field)

/* Every colloid array (state and scratch), the MD step, the reference energy,
 * and the fluid arrays. */
static void assert_same(const pl_sim_t *sa, const pl_sim_t *sb, const char *what)
{
    pl_test_assert_same_fluid(sa, sb, what);
    const pl_colloid_t *a = sa->colloids, *b = sb->colloids;
    cr_assert(a && b);
    size_t n = a->n;
    cr_assert_eq(n, b->n);
    cr_assert_eq(a->md_step, b->md_step, "%s: md_step %lld / %lld", what, a->md_step, b->md_step);
    cr_assert_eq(memcmp(&a->e0, &b->e0, sizeof a->e0), 0, "%s: e0 %.17g / %.17g", what, a->e0, b->e0);
    SAME(x, n, what); SAME(y, n, what); SAME(z, n, what);
    SAME(vx, n, what); SAME(vy, n, what); SAME(vz, n, what);
    SAME(wx, n, what); SAME(wy, n, what); SAME(wz, n, what);
    SAME(q0, n, what); SAME(q1, n, what); SAME(q2, n, what); SAME(q3, n, what);
    SAME(ix, n, what); SAME(iy, n, what); SAME(iz, n, what);
    SAME(rad, n, what); SAME(mass, n, what); SAME(inertia, n, what);
    SAME(fx, n, what); SAME(fy, n, what); SAME(fz, n, what);
    SAME(tx, n, what); SAME(ty, n, what); SAME(tz, n, what);
    SAME(zu, n, what);
    cr_assert_eq(!a->fsx, !b->fsx, "%s: slow forces in one run only", what);
    if (a->fsx) { /* multiple time stepping: recomputed at a restart, not stored */
        SAME(fsx, n, what); SAME(fsy, n, what); SAME(fsz, n, what);
    }
    /* epot: the rows the force evaluation writes (the pair rows are filled
     * on demand by pl_colloid_energy, whose result e0 is compared above) */
    for (int k = 0; k < PL_CE_NTERMS; ++k)
        if (k == PL_CE_WALL || k == PL_CE_GRAVITY)
            cr_assert_eq(memcmp(a->epot + (size_t)k * n, b->epot + (size_t)k * n, n * sizeof *a->epot), 0,
                         "%s: colloid epot row %d differs", what, k);
    SAME(g_overlap, n, what); SAME(g_omega2, n, what); SAME(g_damp, n, what);
    SAME(g_partner, 3 * n, what);
    /* the linked cells and the neighbour list are not compared: a restart
     * rebuilds them from the restored positions, and the forces above (every
     * one of them compared) do not depend on when the list was built */
}

/* The scenes really move every piece of state (else the test proves little);
 * spins change only where torques act (tangential friction or Brownian). */
static void assert_state_moves(const pl_sim_t *s0, const pl_sim_t *s1, size_t k)
{
    int torques = s0->scene.colloids.hertz.gamma_t > 0.0 || s0->scene.colloids.integrator == PL_CINT_BROWNIAN;
    const pl_colloid_t *a = s0->colloids, *b = s1->colloids;
    size_t n = a->n;
    cr_assert_neq(memcmp(a->x, b->x, n * sizeof(double)), 0, "scene %zu: x frozen", k);
    cr_assert_neq(memcmp(a->q1, b->q1, n * sizeof(double)), 0, "scene %zu: quaternions frozen", k);
    if (torques) cr_assert_neq(memcmp(a->wz, b->wz, n * sizeof(double)), 0, "scene %zu: spins frozen", k);
    cr_assert_neq(memcmp(a->fx, b->fx, n * sizeof(double)), 0, "scene %zu: forces frozen", k);
    cr_assert_gt(b->md_step, a->md_step);
}

Test(colloid_restart, thread_count_does_not_change_results)
{
    long long steps = pl_test_quick() ? 6 : 20;
    for (size_t s = 0; s < NSCENES; ++s) {
        pl_sim_t *ref = pl_test_sim(scenes[s], 1);
        pl_sim_t *other = pl_test_sim(scenes[s], 2);
        pl_test_steps(ref, steps);
        pl_test_steps(other, steps);
        assert_same(ref, other, "threads");
        if (ref->colloids->adaptive) /* the choice really varies */
            cr_assert_lt(ref->colloids->adapt_lo, ref->colloids->adapt_hi, "scene %zu: MD steps %lld .. %lld", s,
                         ref->colloids->adapt_lo, ref->colloids->adapt_hi);
        pl_sim_free(ref);
        pl_sim_free(other);
    }
}

/* Overwrites every array the checkpoint restores, so a piece the reader
 * forgets shows up even where the scene would re-derive it (radii, masses). */
static void poison(pl_sim_t *sim)
{
    pl_colloid_t *c = sim->colloids;
    size_t n = c->n;
    double *d[] = {c->x,  c->y,  c->z,  c->vx, c->vy,  c->vz,   c->wx,      c->wy, c->wz, c->q0, c->q1,
                   c->q2, c->q3, c->rad, c->mass, c->inertia, c->fx, c->fy, c->fz, c->tx, c->ty, c->tz};
    for (size_t k = 0; k < sizeof d / sizeof *d; ++k) memset(d[k], 0xA5, n * sizeof(double));
    double *fs[] = {c->fsx, c->fsy, c->fsz};
    for (int k = 0; k < 3; ++k)
        if (fs[k]) memset(fs[k], 0xA5, n * sizeof(double));
    int32_t *img[] = {c->ix, c->iy, c->iz};
    for (int k = 0; k < 3; ++k) memset(img[k], 0xA5, n * sizeof(int32_t));
    c->md_step = -1;
    c->e0 = -1.0;
    for (int k = 0; k < 3; ++k) {
        memset(sim->fluid.r[k], 0xA5, sim->fluid.n * sizeof(pl_real));
        memset(sim->fluid.v[k], 0xA5, sim->fluid.n * sizeof(pl_real));
    }
}

static int same_bytes(const char *p, const char *q)
{
    FILE *f = fopen(p, "rb"), *g = fopen(q, "rb");
    int same = f && g;
    while (same) {
        int a = fgetc(f), b = fgetc(g);
        if (a != b) same = 0;
        if (a == EOF || b == EOF) break;
    }
    if (f) fclose(f);
    if (g) fclose(g);
    return same;
}

Test(colloid_restart, restart_continues_bitwise)
{
    long long N = pl_test_quick() ? 4 : 12;
    char path[] = "/tmp/peloid_test_cckpt_XXXXXX", p2[] = "/tmp/peloid_test_cckpt_XXXXXX",
         p3[] = "/tmp/peloid_test_cckpt_XXXXXX";
    char *paths[3] = {path, p2, p3};
    for (int k = 0; k < 3; ++k) {
        int fd = mkstemp(paths[k]);
        cr_assert_geq(fd, 0);
        close(fd);
    }
    for (size_t s = 0; s < NSCENES; ++s) {
        pl_err_t err = {0, ""};
        pl_sim_t *start = pl_test_sim(scenes[s], 1);
        pl_sim_t *full = pl_test_sim(scenes[s], 2);
        pl_test_steps(full, 2 * N);
        assert_state_moves(start, full, s);
        pl_sim_free(start);
        pl_sim_t *half = pl_test_sim(scenes[s], 1);
        pl_test_steps(half, N);
        cr_assert_eq(pl_checkpoint_write(half, path, &err), 0, "%s", err.msg);
        pl_sim_free(half);
        pl_sim_t *resumed = pl_test_sim(scenes[s], 2);
        poison(resumed);
        cr_assert_eq(pl_checkpoint_read(resumed, path, &err), 0, "%s", err.msg);
        cr_assert_eq(resumed->step, N);
        pl_test_steps(resumed, N);
        assert_same(full, resumed, "restart");
        /* same state => same checkpoint bytes (no time stamps anywhere) */
        cr_assert_eq(pl_checkpoint_write(full, p2, &err), 0, "%s", err.msg);
        cr_assert_eq(pl_checkpoint_write(resumed, p3, &err), 0, "%s", err.msg);
        cr_assert(same_bytes(p2, p3), "scene %zu: checkpoints of the same state differ in bytes", s);
        pl_sim_free(full);
        pl_sim_free(resumed);
    }
    for (int k = 0; k < 3; ++k) unlink(paths[k]);
}

Test(colloid_restart, checkpoint_with_another_colloid_count_is_refused)
{
    static const char *base = "seed = 5;\nbox: { cells = [16, 16, 16]; };\nfluid: { density = 0.0; };\n"
                              "srd: { dt = 0.1; };\n";
    char a_txt[512], b_txt[512];
    snprintf(a_txt, sizeof a_txt, "%scolloids: { count = 27; radius = 2.0; };\n", base);
    snprintf(b_txt, sizeof b_txt, "%scolloids: { count = 26; radius = 2.0; };\n", base);
    char path[] = "/tmp/peloid_test_cckpt_XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    close(fd);
    pl_err_t err = {0, ""};
    const char *pairs[3][2] = {{a_txt, b_txt}, {base, a_txt}, {a_txt, base}};
    for (int k = 0; k < 3; ++k) {
        pl_sim_t *a = pl_test_sim(pairs[k][0], 1);
        cr_assert_eq(pl_checkpoint_write(a, path, &err), 0, "%s", err.msg);
        pl_sim_t *b = pl_test_sim(pairs[k][1], 1);
        cr_assert_eq(pl_checkpoint_read(b, path, &err), PL_ERR_INPUT, "case %d accepted", k);
        cr_assert(strstr(err.msg, "colloids"), "case %d: %s", k, err.msg);
        pl_sim_free(a);
        pl_sim_free(b);
    }
    unlink(path);
}
