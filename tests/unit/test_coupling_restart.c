/* Coupling checkpoint/restart: for each coupling, 2N steps == N steps +
 * checkpoint + restart + N steps, bitwise, in the state (fluid, colloids)
 * AND in the run counters thermo.tsv reports as sums since step 0: coupling I
 * reflections and truncations, the potential coupling's selected
 * particle-steps, the pinned colloids' impulse and time (drag), the walls'
 * impulse (wall stress), kT_cell of the last collision.  Before reading, the
 * resumed sim's counters are poisoned, so a counter the checkpoint leaves out
 * fails the comparison even where it would be 0.  Scenes: hecht1 between
 * moving no-slip walls with N_max = 1 (truncations, particles pushed through
 * a wall), hecht2 with Heyes and drift removal, potential between moving
 * walls, pinned colloids under a held flow (hecht1, turning at a held
 * spin, and potential),
 * potential with lubrication (its random partner on). */
#include <criterion/criterion.h>
#include <stdio.h>
#include <unistd.h>

#include "peloid/checkpoint.h"
#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/io.h"
#include "support.h"

#define BOX "box: { cells = [12, 12, 12]%s; };\nfluid: { density = 5.0; };\nsrd: { dt = 0.1; };\n"
#define COLLR(n, init, R) "colloids: { count = " #n "; radius = " #R "; mass_density = 6.0; init = \"" #init "\"; " \
                         "pairs = \"hertz\"; substeps = 4; };\n"
#define COLL(n, init) COLLR(n, init, 1.8)
#define BASE BOX COLL(8, random)
#define WALLS "; walls_z = \"noslip\"; wall_velocity_bottom = [-0.2, 0.1, 0.0]; wall_velocity_top = [0.2, 0.0, 0.0]"

static const char *scenes[] = {
    /* a lattice with gaps of 0.2 a0: reflections land in neighbours, N_max = 1 truncates */
    "seed = 31;\n" BOX COLLR(27, lattice, 1.9) "coupling: { method = \"hecht1\"; max_reflections = 1; };\n"
    "thermostat: { type = \"rescale\"; };\n",
    "seed = 32;\n" BASE "coupling: { method = \"hecht2\"; drift_interval = 3; };\n"
    "thermostat: { type = \"heyes\"; };\n",
    "seed = 33;\n" BASE "coupling: { method = \"potential\"; sigma_cf = 1.8; };\n",
    "seed = 34;\n" BASE "coupling: { method = \"hecht1\"; pinned = true; flow_velocity = [0.1, 0.0, 0.0];\n"
    "  pinned_spin = [0.0, 0.02, 0.05]; };\n",
    "seed = 35;\n" BASE "coupling: { method = \"potential\"; pinned = true; flow_velocity = [0.0, 0.1, 0.0]; };\n",
    /* potential with lubrication and its random partner (keyed by the MD
     * step: the step's forces recomputed at its start draw the same
     * numbers); lattice gaps of 0.2 a0, inside the cut-off gap */
    "seed = 36;\n" BOX "colloids: { count = 27; radius = 1.9; mass_density = 6.0; init = \"lattice\"; "
    "pairs = \"hertz, lubrication\"; substeps = 4; };\ncoupling: { method = \"potential\"; sigma_cf = 1.8; };\n",
};
/* which scenes have the moving walls */
static const int walled[] = {1, 0, 1, 0, 1, 0};
enum { NSCENES = sizeof scenes / sizeof *scenes };

static pl_sim_t *make(size_t s, int threads)
{
    char text[2048];
    snprintf(text, sizeof text, scenes[s], walled[s] ? WALLS : "");
    return pl_test_sim(text, threads);
}

#define SAME(a, b, bytes, ...) cr_assert_eq(memcmp((a), (b), (bytes)), 0, __VA_ARGS__)

static void assert_same(const pl_sim_t *a, const pl_sim_t *b, size_t s)
{
    char what[32];
    snprintf(what, sizeof what, "scene %zu", s);
    pl_test_assert_same_fluid(a, b, what);
    const pl_colloid_t *ca = a->colloids, *cb = b->colloids;
    size_t m = ca->n * sizeof(double);
    const double *xa[] = {ca->x, ca->y, ca->z, ca->vx, ca->vy, ca->vz, ca->wx, ca->wy, ca->wz,
                          ca->q0, ca->q1, ca->q2, ca->q3, ca->fx, ca->fy, ca->fz};
    const double *xb[] = {cb->x, cb->y, cb->z, cb->vx, cb->vy, cb->vz, cb->wx, cb->wy, cb->wz,
                          cb->q0, cb->q1, cb->q2, cb->q3, cb->fx, cb->fy, cb->fz};
    for (size_t k = 0; k < sizeof xa / sizeof *xa; ++k) SAME(xa[k], xb[k], m, "scene %zu: colloid array %zu", s, k);
    const pl_coupling_t *pa = pl_coupling_of(a), *pb = pl_coupling_of(b);
    cr_assert_eq(pa->method, pb->method, "scene %zu: method", s);
    if (pa->c1) {
        cr_assert_eq(pa->c1->events, pb->c1->events, "scene %zu: events %llu / %llu", s, pa->c1->events,
                     pb->c1->events);
        cr_assert_eq(pa->c1->truncations, pb->c1->truncations, "scene %zu: truncations %llu / %llu", s,
                     pa->c1->truncations, pb->c1->truncations);
    }
    if (pa->pot)
        cr_assert_eq(pa->pot->near_total, pb->pot->near_total, "scene %zu: near_total %llu / %llu", s,
                     pa->pot->near_total, pb->pot->near_total);
    SAME(pa->impulse, pb->impulse, sizeof pa->impulse, "scene %zu: pinned impulse", s);
    SAME(&pa->pinned_time, &pb->pinned_time, sizeof pa->pinned_time, "scene %zu: pinned_time", s);
    SAME(pl_srd_kept(a->srd).kT_cell, pl_srd_kept(b->srd).kT_cell, sizeof(double), "scene %zu: kT_cell", s);
}

/* The scenes really exercise what they are meant to (else the test proves little). */
static void assert_exercised(const pl_sim_t *sim, size_t s)
{
    const pl_coupling_t *cp = pl_coupling_of(sim);
    if (cp->method == PL_COUPLE_HECHT1) cr_assert_gt(cp->c1->events, 0, "scene %zu: no reflections", s);
    if (s == 0) cr_assert_gt(cp->c1->truncations, 0, "scene %zu: no truncations", s);
    if (cp->method == PL_COUPLE_POTENTIAL) cr_assert_gt(cp->pot->near_total, 0, "scene %zu: nothing selected", s);
    if (cp->pinned) cr_assert(cp->pinned_time > 0 && cp->impulse[0] != 0.0, "scene %zu: no drag", s);
    if (cp->spin[2] != 0.0) cr_assert(cp->impulse[5] * cp->spin[2] < 0.0, "scene %zu: no torque against the spin", s);
    if (walled[s]) cr_assert(sim->wall_impulse[1][0] != 0.0, "scene %zu: no wall impulse", s);
}

static void poison(pl_sim_t *sim)
{
    pl_coupling_t *cp = pl_coupling_of(sim);
    if (cp->c1) cp->c1->events = cp->c1->truncations = 12345;
    if (cp->pot) cp->pot->near_total = 12345;
    for (int k = 0; k < 6; ++k) cp->impulse[k] = -7.0;
    cp->pinned_time = -7.0;
    if (pl_srd_walls_measured(sim->srd)) /* only scenes with walls have (and store) wall impulses */
        for (int k = 0; k < 6; ++k) sim->wall_impulse[k / 3][k % 3] = -7.0;
    *pl_srd_kept(sim->srd).kT_cell = -7.0;
}

Test(coupling_restart, restart_continues_bitwise_with_counters, .timeout = 300)
{
    long long N = 10; /* enough for truncations in scene 0; seconds even under the sanitizers */
    char path[] = "/tmp/peloid_test_cplckpt_XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    close(fd);
    for (size_t s = 0; s < NSCENES; ++s) {
        pl_err_t err = {0, ""};
        pl_sim_t *full = make(s, 2);
        pl_test_steps(full, 2 * N);
        assert_exercised(full, s);
        pl_sim_t *half = make(s, 1);
        pl_test_steps(half, N);
        cr_assert_eq(pl_checkpoint_write(half, path, &err), 0, "%s", err.msg);
        pl_sim_t *resumed = make(s, 2);
        poison(resumed);
        cr_assert_eq(pl_checkpoint_read(resumed, path, &err), 0, "scene %zu: %s", s, err.msg);
        /* at the restart step (its thermo row repeats the last one written) ... */
        assert_same(half, resumed, s);
        pl_sim_free(half);
        /* ... and N steps on */
        pl_test_steps(resumed, N);
        assert_same(full, resumed, s);
        pl_sim_free(full);
        pl_sim_free(resumed);
    }
    unlink(path);
}
