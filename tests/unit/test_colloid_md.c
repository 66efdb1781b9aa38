/* Colloid dynamics invariants: NVE energy conservation with damping off,
 * linear and angular momentum conservation, monotone energy decay with
 * damping (Hecht Sec. IX.A), the friction impulse of noncentral collisions of
 * eight Hertz spheres in a closed box (Hecht Sec. II end), bitwise
 * identical runs for 1 and 2 threads, and the fused MD step bitwise equal to
 * its separate passes. */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "colloid_test_util.h"

/* 27 colloids, DLVO (Fig. 1 set A scaled to R = 2 a0) + Hertz, kT = 1,
 * dt_MD = 0.1/12 t0: a pair that crosses the 11.9 kT barrier into contact
 * (this happens within the run) is resolved by the 20 MD steps the contact
 * guard asks for (at dt_MD = 0.025 t0 it would be 7). */
static const char *NVE_SCENE =
    "box: { cells = [24, 24, 24]; };\n"
    "fluid: { density = 0.0; };\n"
    "srd: { dt = 0.1; };\n"
    "colloids: { count = 27; radius = 2.0; temperature = 1.0; substeps = 12;\n"
    "  pairs = \"dlvo, hertz\"; max_energy_drift = 0.0; };\n"
    "dlvo: { psi0 = 20.0; kappa = 1.4e8; hamaker = 4.76e-20; length_unit = 1.25e-7; };\n"
    "hertz: { K = 1000.0; };\n";

/* Undamped: the total energy stays within the bound over 3 10^5 MD steps,
 * 2500 t0 (3 10^4 with PL_QUICK).  Velocity Verlet has no secular drift; the bound
 * covers the O(dt^2) shadow-energy fluctuation and the energy jump of pairs
 * crossing the DLVO cut-off (shifted: none).  Measured 1.0e-3 kT/colloid
 * (the run includes a barrier crossing into Hertz contact);
 * bound 2e-3 kT per colloid. */
Test(colloid_md, nve_energy_and_momentum, .timeout = 120)
{
    pl_scene_t s;
    scene_from(NVE_SCENE, &s);
    pl_colloid_t *c;
    pl_err_t err;
    cr_assert_eq(pl_colloid_create(&s, omp_get_max_threads(), &c, &err), 0, "%s", err.msg);
    pl_colloid_energy_t e0, e;
    pl_colloid_energy(c, &e0);
    double p0[3], l0[3], p[3], l[3];
    pl_colloid_momentum(c, p0, l0);
    long steps = quick() ? 30000 : 300000;
    double worst = 0.0;
    for (long k = 0; k < steps; ++k) {
        cr_assert_eq(pl_colloid_md_step(c, &err), 0, "%s", err.msg);
        if (k % 100 == 0) {
            pl_colloid_energy(c, &e);
            worst = fmax(worst, fabs(e.total - e0.total) / (double)c->n);
        }
    }
    cr_expect(worst < 2e-3, "energy drift %.3g kT/colloid over %ld steps", worst, steps);
    cr_log_info("NVE: max |E-E0|/N = %.3g kT over %ld MD steps", worst, steps);
    /* momentum: only round-off (1e-9 of the thermal momentum scale sqrt(N m kT)) */
    pl_colloid_momentum(c, p, l);
    double scale = sqrt((double)c->n * c->mass[0]);
    for (int k = 0; k < 3; ++k)
        cr_expect(fabs(p[k] - p0[k]) < 1e-9 * scale, "P[%d] %.3g -> %.3g", k, p0[k], p[k]);
    pl_colloid_free(c);
}

/* Angular momentum: a noncentral, frictional two-body collision in open space
 * (no periodic image involved) conserves L = sum m x x v + I w exactly up to
 * round-off (the tangential couple has no moment: lever arms a_i + a_j = r). */
Test(colloid_md, angular_momentum_frictional_collision)
{
    pl_scene_t s;
    scene_from("box: { cells = [40, 40, 40]; }; fluid: { density = 0.0; };\n"
               "colloids: { count = 2; pairs = \"hertz\"; substeps = 10; };\n"
               "hertz: { K = 1000.0; beta = 5.0; gamma_t = 20.0; };\n", &s);
    pl_colloid_t *c;
    pl_err_t err;
    cr_assert_eq(pl_colloid_create(&s, omp_get_max_threads(), &c, &err), 0, "%s", err.msg);
    double x0[2] = {15, 25}, y0[2] = {20, 21.5}, v0[2] = {0.3, -0.3};
    for (int i = 0; i < 2; ++i) {
        c->x[i] = x0[i], c->y[i] = y0[i], c->z[i] = 20, c->vx[i] = v0[i];
        c->vy[i] = c->vz[i] = 0, c->wx[i] = c->wy[i] = 0, c->wz[i] = 0.05 * (i + 1);
    }
    pl_colloid_forces(c, &err);
    double p0[3], l0[3], p[3], l[3];
    pl_colloid_momentum(c, p0, l0);
    for (int k = 0; k < 4000; ++k) cr_assert_eq(pl_colloid_md_step(c, &err), 0, "%s", err.msg);
    pl_colloid_momentum(c, p, l);
    double ls = c->mass[0] * 0.3 * 10.0; /* m v b scale */
    for (int k = 0; k < 3; ++k) {
        cr_expect(fabs(l[k] - l0[k]) < 1e-10 * ls, "L[%d] %.15g -> %.15g", k, l0[k], l[k]);
        cr_expect(fabs(p[k] - p0[k]) < 1e-10 * ls, "P[%d] %.15g -> %.15g", k, p0[k], p[k]);
    }
    cr_expect(fabs(c->wz[0] - 0.05) > 1e-3, "friction acted on the spin");
    pl_colloid_free(c);
}

/* Damping on (Hertz beta, friction, lubrication without its random
 * partner, lubrication.thermal = false): sampled every 50 MD steps the
 * total energy never increases by more than the undamped fluctuation level
 * (1e-6 kT per colloid) and ends well below the start.  (With the random
 * partner the energy fluctuates around equipartition instead:
 * tests/physics/test_colloid_lub_thermal.c.) */
Test(colloid_md, damped_energy_decreases)
{
    pl_scene_t s;
    scene_from("box: { cells = [16, 16, 16]; }; fluid: { density = 0.0; };\n"
               "colloids: { count = 27; temperature = 20.0; pairs = \"hertz, lubrication\"; substeps = 8; };\n"
               "hertz: { K = 1000.0; beta = 20.0; gamma_t = 5.0; };\n"
               "lubrication: { viscosity = 2.5; min_gap = 0.1; cutoff_gap = 1.0; thermal = false; };\n", &s);
    pl_colloid_t *c;
    pl_err_t err;
    cr_assert_eq(pl_colloid_create(&s, omp_get_max_threads(), &c, &err), 0, "%s", err.msg);
    pl_colloid_energy_t e;
    pl_colloid_energy(c, &e);
    double first = e.total, prev = e.total;
    int steps = quick() ? 4000 : 20000;
    for (int k = 1; k <= steps; ++k) {
        cr_assert_eq(pl_colloid_md_step(c, &err), 0, "%s", err.msg);
        if (k % 50 == 0) {
            pl_colloid_energy(c, &e);
            cr_expect(e.total <= prev + 1e-6 * (double)c->n, "step %d: E rose %.10g -> %.10g", k, prev, e.total);
            prev = e.total;
        }
    }
    cr_expect(prev < 0.9 * first, "energy %.6g -> %.6g: damping did not act", first, prev);
    pl_colloid_free(c);
}

/* Eight Hertz spheres with friction in a box closed in z (Phi ~ 20%).  For every
 * isolated two-body contact (no other contact, no wall force, during it) the
 * change of each spin matches the tangential impulse:
 *   I_i dw_i = -R_i e x (m_i dv_i)
 * with e the unit vector j->i at the deepest overlap.  Tolerance 3%: the lever
 * arm is R - delta/2 (delta <~ 2% of R) and e turns a little during contact. */
Test(colloid_md, eight_spheres_friction_impulse, .timeout = 60)
{
    pl_scene_t s;
    scene_from("box: { cells = [12, 12, 12]; walls_z = \"slip\"; }; fluid: { density = 0.0; };\n"
               "seed = 3;\n"
               "colloids: { count = 8; radius = 2.2; temperature = 5.0; init = \"lattice\";\n"
               "  pairs = \"hertz\"; substeps = 20; };\n"
               "hertz: { K = 3000.0; gamma_t = 30.0; };\n", &s);
    pl_colloid_t *c;
    pl_err_t err;
    cr_assert_eq(pl_colloid_create(&s, omp_get_max_threads(), &c, &err), 0, "%s", err.msg);
    int in = 0, a = -1, b = -1, checked = 0, spoiled = 0;
    double v0[2][3], w0[2][3], e[3] = {0, 0, 0}, maxov = 0;
    for (int step = 0; step < 40000 && checked < 6; ++step) {
        cr_assert_eq(pl_colloid_md_step(c, &err), 0, "%s", err.msg);
        int ncont = 0, ci = -1, cj = -1;
        for (int i = 0; i < 8; ++i)
            for (int j = i + 1; j < 8; ++j) {
                double dx = c->x[i] - c->x[j], dy = c->y[i] - c->y[j], dz = c->z[i] - c->z[j];
                dx -= 12 * rint(dx / 12), dy -= 12 * rint(dy / 12);
                double r = sqrt(dx * dx + dy * dy + dz * dz);
                if (r < c->rad[i] + c->rad[j]) {
                    ncont++, ci = i, cj = j;
                    double ov = c->rad[i] + c->rad[j] - r;
                    if (in && i == a && j == b && ov > maxov)
                        maxov = ov, e[0] = dx / r, e[1] = dy / r, e[2] = dz / r;
                }
            }
        int wall = 0;
        for (int i = 0; i < 8; ++i)
            if (c->z[i] < c->rad[i] * pow(2.0, 1.0 / 24) || 12 - c->z[i] < c->rad[i] * pow(2.0, 1.0 / 24)) wall = 1;
        if (!in && ncont == 1 && !wall) { /* contact starts: state before it is the previous step's */
            in = 1, a = ci, b = cj, spoiled = 0, maxov = 0;
            int id[2] = {a, b};
            for (int q = 0; q < 2; ++q) {
                double m = c->mass[id[q]], I = c->inertia[id[q]], h = c->dt;
                /* undo this step's contact kick approx.: take values now and compare at end */
                v0[q][0] = c->vx[id[q]], v0[q][1] = c->vy[id[q]], v0[q][2] = c->vz[id[q]];
                w0[q][0] = c->wx[id[q]], w0[q][1] = c->wy[id[q]], w0[q][2] = c->wz[id[q]];
                (void)m, (void)I, (void)h;
            }
        } else if (in) {
            if (ncont > 1 || wall) spoiled = 1;
            if (ncont == 0) {
                in = 0;
                if (spoiled) continue;
                int id[2] = {a, b};
                double sgn[2] = {1, -1};
                for (int q = 0; q < 2; ++q) {
                    int i = id[q];
                    double dv[3] = {c->vx[i] - v0[q][0], c->vy[i] - v0[q][1], c->vz[i] - v0[q][2]};
                    double dL[3] = {c->inertia[i] * (c->wx[i] - w0[q][0]), c->inertia[i] * (c->wy[i] - w0[q][1]),
                                    c->inertia[i] * (c->wz[i] - w0[q][2])};
                    double ee[3] = {sgn[q] * e[0], sgn[q] * e[1], sgn[q] * e[2]}, m = c->mass[i], R = c->rad[i];
                    double want[3] = {-R * m * (ee[1] * dv[2] - ee[2] * dv[1]), -R * m * (ee[2] * dv[0] - ee[0] * dv[2]),
                                      -R * m * (ee[0] * dv[1] - ee[1] * dv[0])};
                    double nw = sqrt(want[0] * want[0] + want[1] * want[1] + want[2] * want[2]);
                    double dd = sqrt(pow(dL[0] - want[0], 2) + pow(dL[1] - want[1], 2) + pow(dL[2] - want[2], 2));
                    cr_expect(dd <= 0.03 * nw + 1e-9, "contact %d-%d particle %d: I dw (%g %g %g) vs -R e x m dv (%g %g %g)",
                              a, b, i, dL[0], dL[1], dL[2], want[0], want[1], want[2]);
                }
                checked++;
            }
        }
    }
    cr_expect(checked >= 2, "only %d isolated contacts seen", checked);
    cr_log_info("eight spheres: %d isolated frictional contacts checked", checked);
    pl_colloid_free(c);
}

/* Forces, positions, spins of 400 colloids after 200 MD steps with every term on: bitwise
 * identical for 1 and 2 threads (full neighbour lists, fixed sum order). */
Test(colloid_md, bitwise_threads)
{
    const char *sc = "box: { cells = [40, 40, 40]; }; fluid: { density = 0.0; };\n"
                     "colloids: { count = 400; init = \"random\"; radius = 1.8; polydispersity = 0.1;\n"
                     "  pairs = \"dlvo, hertz, lubrication, wca\"; substeps = 10; temperature = 3.0;\n"
                     "  min_contact_steps = 0.0; };\n"
                     "dlvo: { psi0 = 20.0; kappa = 1.4e8; hamaker = 4.76e-20; length_unit = 1.25e-7; };\n"
                     "hertz: { K = 1000.0; beta = 2.0; gamma_t = 3.0; };\n";
    pl_scene_t s;
    scene_from(sc, &s);
    double *snap[2];
    size_t n = 400; /* >= PL_COLLOID_OMP_MIN: the kernels really run threaded */
    for (int t = 0; t < 2; ++t) {
        pl_colloid_t *c;
        pl_err_t err;
        cr_assert_eq(pl_colloid_create(&s, t + 1, &c, &err), 0, "%s", err.msg);
        for (int k = 0; k < 200; ++k) cr_assert_eq(pl_colloid_md_step(c, &err), 0, "%s", err.msg);
        snap[t] = malloc(9 * n * sizeof(double));
        const double *src[9] = {c->x, c->y, c->z, c->vx, c->vy, c->vz, c->wx, c->fx, c->q1};
        for (int a = 0; a < 9; ++a) memcpy(snap[t] + (size_t)a * n, src[a], n * sizeof(double));
        pl_colloid_free(c);
    }
    cr_expect(memcmp(snap[0], snap[1], 9 * n * sizeof(double)) == 0, "1 and 2 threads differ");
    free(snap[0]);
    free(snap[1]);
}

/* The fused velocity-Verlet step (kernels/colloid_verlet.h, what
 * pl_colloid_md_step runs) against the separate passes it replaces (kick,
 * drift, pl_colloid_forces, kick, pl_colloid_guard; the potential coupling's
 * MD loop still runs these): every state array bitwise equal after 200 MD
 * steps, 2 threads, every pair term with friction torques, walls on z and
 * gravity (the external forces), 400 colloids (threaded). */
Test(colloid_md, fused_step_equals_separate_passes)
{
    const char *sc = "box: { cells = [40, 40, 40]; walls_z = \"slip\"; }; fluid: { density = 0.0; };\n"
                     "colloids: { count = 400; init = \"random\"; radius = 1.8; polydispersity = 0.1;\n"
                     "  pairs = \"dlvo, hertz, lubrication, wca\"; substeps = 10; temperature = 3.0;\n"
                     "  gravity = [0.0, 0.0, -0.002]; min_contact_steps = 0.0; };\n"
                     "dlvo: { psi0 = 20.0; kappa = 1.4e8; hamaker = 4.76e-20; length_unit = 1.25e-7; };\n"
                     "hertz: { K = 1000.0; beta = 2.0; gamma_t = 3.0; };\n";
    pl_scene_t s;
    scene_from(sc, &s);
    pl_colloid_t *a, *b;
    pl_err_t err;
    cr_assert_eq(pl_colloid_create(&s, 2, &a, &err), 0, "%s", err.msg);
    cr_assert_eq(pl_colloid_create(&s, 2, &b, &err), 0, "%s", err.msg);
    const size_t n = a->n;
    long long builds = a->nlist.builds;
    for (int k = 0; k < 200; ++k) {
        cr_assert_eq(pl_colloid_md_step(a, &err), 0, "%s", err.msg);
        const double h = 0.5 * b->dt;
        pl_colloid_kick(n, h, b->mass, b->inertia, b->fx, b->fy, b->fz, b->tx, b->ty, b->tz, b->vx,
                        b->vy, b->vz, b->wx, b->wy, b->wz, b->nthreads);
        pl_colloid_drift(n, b->dt, b->box, b->periodic, b->x, b->y, b->z, b->ix, b->iy, b->iz, b->vx,
                         b->vy, b->vz, b->wx, b->wy, b->wz, b->q0, b->q1, b->q2, b->q3, b->nthreads);
        b->md_step++; /* first: the forces are those of the step's end (they key the lubrication noise) */
        cr_assert_eq(pl_colloid_forces(b, &err), 0, "%s", err.msg);
        pl_colloid_kick(n, h, b->mass, b->inertia, b->fx, b->fy, b->fz, b->tx, b->ty, b->tz, b->vx,
                        b->vy, b->vz, b->wx, b->wy, b->wz, b->nthreads);
        cr_assert_eq(pl_colloid_guard(b, 0, &err), 0, "%s", err.msg);
    }
    cr_expect_gt(a->nlist.builds, builds, "the run rebuilt no neighbour list");
    cr_expect_eq(a->nlist.builds, b->nlist.builds);
    const double *da[] = {a->x, a->y, a->z, a->vx, a->vy, a->vz, a->wx, a->wy, a->wz, a->fx, a->fy,
                          a->fz, a->tx, a->ty, a->tz, a->q0, a->q1, a->q2, a->q3, a->zu,
                          a->g_overlap, a->g_omega2, a->g_damp};
    const double *db[] = {b->x, b->y, b->z, b->vx, b->vy, b->vz, b->wx, b->wy, b->wz, b->fx, b->fy,
                          b->fz, b->tx, b->ty, b->tz, b->q0, b->q1, b->q2, b->q3, b->zu,
                          b->g_overlap, b->g_omega2, b->g_damp};
    for (size_t q = 0; q < sizeof da / sizeof da[0]; ++q)
        cr_expect(memcmp(da[q], db[q], n * sizeof(double)) == 0, "state array %zu differs", q);
    cr_expect(memcmp(a->epot, b->epot, (size_t)PL_CE_NTERMS * n * sizeof(double)) == 0, "epot differs");
    const int32_t *ia[] = {a->ix, a->iy, a->iz}, *ib[] = {b->ix, b->iy, b->iz};
    for (int q = 0; q < 3; ++q) cr_expect(memcmp(ia[q], ib[q], n * sizeof(int32_t)) == 0, "image %d differs", q);
    pl_colloid_free(a);
    pl_colloid_free(b);
}

/* The orientation update: the vector lanes of the drift (blocks of 64
 * colloids, small angles) and the scalar pl_colloid_quat_rotate (what BD
 * uses) round the same, bit for bit.  (gcc's SLP vectoriser had fused the
 * scalar function's product into vfmaddsub: one rounding fewer, other
 * bits.)  The large angles mixed into the blocks check that the drift
 * leaves them to the scalar function. */
Test(colloid_md, orientation_lanes_equal_scalar_rotation)
{
    enum { N = 200 };
    static double x[N], y[N], z[N], vx[N], vy[N], vz[N], wx[N], wy[N], wz[N];
    static double q0[N], q1[N], q2[N], q3[N], want[N][4];
    static int32_t ix[N], iy[N], iz[N];
    const double box[3] = {100.0, 100.0, 100.0}, dt = 0.01;
    const int periodic[3] = {1, 1, 1};
    srand(11);
    for (int i = 0; i < N; ++i) {
        x[i] = y[i] = z[i] = 50.0;
        /* |phi| = dt |w| mostly below 0.01 (the lanes), every seventh above */
        const double scale = i % 7 == 3 ? 3.0 : 0.3;
        wx[i] = scale * (2.0 * rand() / RAND_MAX - 1.0);
        wy[i] = scale * (2.0 * rand() / RAND_MAX - 1.0);
        wz[i] = scale * (2.0 * rand() / RAND_MAX - 1.0);
        double q[4], n2 = 0.0;
        for (int k = 0; k < 4; ++k) q[k] = 2.0 * rand() / RAND_MAX - 1.0, n2 += q[k] * q[k];
        for (int k = 0; k < 4; ++k) q[k] /= sqrt(n2);
        q0[i] = q[0], q1[i] = q[1], q2[i] = q[2], q3[i] = q[3];
        pl_colloid_quat_rotate(dt * wx[i], dt * wy[i], dt * wz[i], q);
        for (int k = 0; k < 4; ++k) want[i][k] = q[k];
    }
    pl_colloid_drift(N, dt, box, periodic, x, y, z, ix, iy, iz, vx, vy, vz, wx, wy, wz, q0, q1, q2, q3, 2);
    int large = 0;
    for (int i = 0; i < N; ++i) {
        const double got[4] = {q0[i], q1[i], q2[i], q3[i]};
        cr_expect(memcmp(got, want[i], sizeof got) == 0, "colloid %d: (%.17g %.17g %.17g %.17g) vs (%.17g %.17g %.17g %.17g)",
                  i, got[0], got[1], got[2], got[3], want[i][0], want[i][1], want[i][2], want[i][3]);
        large += dt * dt * (wx[i] * wx[i] + wy[i] * wy[i] + wz[i] * wz[i]) >= 1e-4;
    }
    cr_expect(large > 10 && large < N - 100, "%d large angles: the test wants both kinds", large);
}
