/* A scene in physical units is the whole truth (issue 13): every model value
 * of the colloids is derived from physical{} + coarse_graining{}.
 *
 * Property test over 240 random physical inputs in these ranges (uniform,
 * log-uniform where marked):
 *   R 0.1-2 um (log), rho_f 900-1100 kg/m^3, rho_p/rho_f 1.2-5, T 280-360 K,
 *   nu 0.5e-6-2e-6 m^2/s, g 0 (coupling II: its settling guard refuses fast
 *   colloids) or for half the coupling I cases 0.1-10 m/s^2, A_H 1e-21-2e-20 J (log),
 *   Psi0 +-(10-60) mV, kappa R 10-150, Hertz from E 1e9-1e11 Pa (log) and
 *   nu_P 0.1-0.4 or coarse_graining.hertz_K 300-3000 kT/a0^2.5, phi 0.01-0.3,
 *   gamma 3-10, lambda 0.1-1, coupling I (a0 = R/2, 24-30 cells an edge) or
 *   II (8-14 cells), box edges given off the whole cell by up to 0.3 a0.
 * For each: SI -> model -> SI round trips to 1e-12 relative and each derived
 * value against its equation evaluated here (Hecht Eqs. 1-3, 18, 28, 30, 31;
 * Hertz theory; water permittivity of Malmberg & Maryott), and the substeps
 * against the contact guard's criterion on the reachable gaps.  Changing the
 * radius changes its dependents consistently.  hecht_table1 runs with its
 * colloids at the realised phi. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mapping_testutil.h"
#include "support.h"

#include "peloid/colloid.h"
#include "peloid/colloid_pair.h"
#include "peloid/scene.h"
#include "peloid/sim.h"

#define REL(a, b) (fabs((a) - (b)) <= 1e-12 * fabs(b))
#define CHECK_REL(a, b, what)                                                                            \
    cr_expect(REL((a), (b)), "case %d: %s: %.17g, expected %.17g", id, what, (double)(a), (double)(b))

typedef struct {
    int coupling; /* 0: I, 1: II */
    double R, rho_f, rho_p, T, nu, g, A, psi, kappa, E, nu_p, hertz_K, phi, gamma, lambda;
    int cells[3];
    double box[3];
} input_t;

static uint64_t rng_state;
static double uni(double a, double b)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return a + (b - a) * (double)(rng_state >> 11) / 9007199254740992.0;
}
static double logu(double a, double b) { return exp(uni(log(a), log(b))); }

static void draw(input_t *in)
{
    in->coupling = uni(0, 1) < 0.5;
    in->R = logu(1e-7, 2e-6);
    in->rho_f = uni(900, 1100);
    in->rho_p = in->rho_f * uni(1.2, 5.0);
    in->T = uni(280, 360);
    in->nu = uni(0.5e-6, 2e-6);
    in->g = uni(0, 1) < 0.5 || in->coupling ? 0.0 : uni(0.1, 10);
    in->A = logu(1e-21, 2e-20);
    in->psi = (uni(0, 1) < 0.5 ? -1.0 : 1.0) * uni(0.01, 0.06);
    in->kappa = uni(10, 150) / in->R;
    int mat = uni(0, 1) < 0.5;
    in->E = mat ? logu(1e9, 1e11) : 0.0;
    in->nu_p = uni(0.1, 0.4);
    in->hertz_K = mat ? 0.0 : uni(300, 3000);
    in->phi = uni(0.01, 0.3);
    in->gamma = uni(3, 10);
    in->lambda = uni(0.1, 1.0);
    double a0 = (in->coupling ? cbrt(4.0 * M_PI / 3.0) : 0.5) * in->R;
    for (int d = 0; d < 3; ++d) {
        in->cells[d] = in->coupling ? (int)uni(8, 15) : (int)uni(24, 31);
        in->box[d] = (in->cells[d] + uni(-0.3, 0.3)) * a0;
    }
}

static int load(const input_t *in, pl_scene_t *s, pl_err_t *err)
{
    char hertz[160] = "", cgk[80] = "", text[2048];
    if (in->E > 0)
        snprintf(hertz, sizeof hertz, "young_modulus = %.17g; poisson_ratio = %.17g;", in->E, in->nu_p);
    else
        snprintf(cgk, sizeof cgk, "hertz_K = %.17g;", in->hertz_K);
    snprintf(text, sizeof text,
             "srd: { rule = \"hecht_axes\"; };\n"
             "physical: { radius = %.17g; solvent_density = %.17g; particle_density = %.17g; temperature = %.17g;\n"
             "  viscosity = %.17g; gravity = %.17g; hamaker = %.17g; surface_potential = %.17g; kappa = %.17g;\n"
             "  %s volume_fraction = %.17g; box = [%.17g, %.17g, %.17g]; };\n"
             "coarse_graining: { coupling = \"%s\"; particles_per_cell = %.17g; mean_free_path = %.17g; %s };\n"
             "colloids: { pairs = \"dlvo, hertz\"; };\n",
             in->R, in->rho_f, in->rho_p, in->T, in->nu, in->g, in->A, in->psi, in->kappa, hertz, in->phi,
             in->box[0], in->box[1], in->box[2], in->coupling ? "II" : "I", in->gamma, in->lambda, cgk);
    return pl_scene_load_string(text, "prop.cfg", s, err);
}

/* Every derived value against its equation, and the SI round trips. */
static void check_case(int id, const input_t *in, const pl_scene_t *s)
{
    const pl_mapping_t *m = &s->mapping.map;
    const pl_scene_colloids_t *cs = &s->colloids;
    double kT = PL_KB * in->T;
    double a0 = (in->coupling ? cbrt(4.0 * M_PI / 3.0) : 0.5) * in->R; /* Hecht Sec. VII.B / VII.C */
    CHECK_REL(m->a0, a0, "a0");
    double m_f = in->rho_f * a0 * a0 * a0 / in->gamma; /* rho_f = gamma m_f / a0^3 */
    CHECK_REL(m->m_f, m_f, "m_f");
    /* Hecht Eq. 28 (+-90 deg about the axes), a0 = m_f = kT = 1, dt = lambda */
    double M = in->gamma, L = in->lambda;
    double nu_sim = (1.0 - (1.0 - exp(-M)) / M) / (18.0 * L) + L * (M + 2.0) / (4.0 * (M - 1.0));
    CHECK_REL(m->nu_sim, nu_sim, "nu (Hecht Eq. 28)");
    double t0 = m->t0, nu_model = nu_sim * a0 * a0 / t0;
    /* Hecht Eq. 30: the colloid diffusion coefficient (Eq. 18) as in reality */
    double D_real = kT / (6.0 * M_PI * in->nu * in->rho_f * in->R);
    double D_model = m->kT_model / (6.0 * M_PI * nu_model * in->rho_f * in->R);
    CHECK_REL(D_model, D_real, "D (Hecht Eqs. 18, 30)");
    CHECK_REL(m->kT_model, m_f * a0 * a0 / (t0 * t0), "kT_model");
    for (int d = 0; d < 3; ++d) cr_expect_eq(s->box.cells[d], in->cells[d], "case %d: cells[%d]", id, d);
    /* count from phi in the box used */
    double V = (double)in->cells[0] * in->cells[1] * in->cells[2] * a0 * a0 * a0;
    double vc = 4.0 / 3.0 * M_PI * pow(in->R, 3);
    cr_expect_eq(cs->count, (long long)floor(in->phi * V / vc + 0.5), "case %d: count", id);
    double phi_r = (double)cs->count * vc / V;
    CHECK_REL(s->mapping.colloid.phi_realised, phi_r, "realised phi");
    cr_expect(fabs(phi_r - in->phi) <= 0.5 * vc / V * (1 + 1e-12), "case %d: phi %g vs %g", id, phi_r, in->phi);
    /* radius, mass: model -> SI */
    CHECK_REL(cs->radius * a0, in->R, "R round trip");
    double mass_sim = cs->mass_density * 4.0 / 3.0 * M_PI * pow(cs->radius, 3);
    CHECK_REL(mass_sim * m_f, vc * in->rho_p, "mass round trip");
    CHECK_REL(s->mapping.colloid.inertia, 0.4 * mass_sim * cs->radius * cs->radius, "inertia");
    /* Hecht Eq. 31: g_model = g nu_model / nu (1 - rho_f / rho_p); and back */
    double g_model = -cs->gravity[2] * a0 / (t0 * t0);
    double g_eq = in->g * nu_model / in->nu * (1.0 - in->rho_f / in->rho_p);
    if (in->g > 0) {
        CHECK_REL(g_model, g_eq, "gravity (Hecht Eq. 31)");
        CHECK_REL(g_model * in->nu / nu_model / (1.0 - in->rho_f / in->rho_p), in->g, "gravity round trip");
    } else {
        cr_expect_eq(cs->gravity[2], 0.0, "case %d: no gravity", id);
    }
    cr_expect_eq(cs->temperature, 1.0);
    /* DLVO arguments and Hecht Eqs. 1-2 in kT and a0 */
    double eps = 87.740 - 0.40008 * (in->T - 273.15) + 9.398e-4 * pow(in->T - 273.15, 2) -
                 1.410e-6 * pow(in->T - 273.15, 3);
    CHECK_REL(cs->dlvo.eps_r, eps, "eps_r (water at T)");
    CHECK_REL(cs->dlvo.psi0_mV, 1e3 * in->psi, "psi0");
    CHECK_REL(cs->dlvo.kappa_per_m, in->kappa, "kappa");
    CHECK_REL(cs->dlvo.hamaker_J, in->A, "hamaker");
    CHECK_REL(cs->dlvo.length_unit_m, a0, "length_unit = a0");
    CHECK_REL(cs->dlvo.temperature_K, in->T, "dlvo T");
    pl_colloid_pair_params_t p;
    pl_colloid_dlvo_info_t info;
    pl_err_t e = {0, ""};
    cr_assert_eq(pl_colloid_pair_params(s, &p, &info, &e), 0, "case %d: %s", id, e.msg);
    double b = 4.0 * kT / PL_E_CHARGE * tanh(PL_E_CHARGE * in->psi / (4.0 * kT));
    double C = M_PI * eps * PL_EPS0 * b * b; /* J/m, Hecht Eq. 1 */
    CHECK_REL(p.coul_C * kT / a0, C, "Coulomb prefactor (Hecht Eq. 1) round trip");
    CHECK_REL(p.kappa / a0, in->kappa, "kappa a0 round trip");
    CHECK_REL(p.hamaker * kT, in->A, "A_H / kT round trip (Hecht Sec. VII.B)");
    /* Hertz (Hecht Eq. 3): K = 4 E sqrt(R/2) / (15 (1 - nu_P^2)) */
    if (in->E > 0) {
        double K = 4.0 * in->E * sqrt(in->R / 2.0) / (15.0 * (1.0 - in->nu_p * in->nu_p));
        CHECK_REL(cs->hertz.K * kT / pow(a0, 2.5), K, "Hertz K round trip");
    } else {
        CHECK_REL(cs->hertz.K, in->hertz_K, "hertz_K");
    }
    /* lubrication (Hecht Eq. 4): eta = rho_f nu_model */
    CHECK_REL(cs->lub.viscosity * m_f / (a0 * t0), in->rho_f * nu_model, "eta round trip");
    cr_expect_eq(s->coupling.method, in->coupling ? PL_COUPLE_HECHT2 : PL_COUPLE_HECHT1, "case %d: method", id);
    /* substeps: the mapping's MD step, and the contact guard's criterion
     * pi sqrt(m_red / U'') >= min_contact_steps dt_MD on every reachable gap */
    long long n = cs->substeps;
    cr_expect_geq(n, 1);
    cr_expect_eq(s->mapping.map.md_substeps, n);
    double dt_md = s->srd.dt / (double)n, d = 2.0 * cs->radius, m_red = 0.5 * mass_sim;
    double h_lo = s->mapping.colloid.reach_gap;
    for (int k = 0; k <= 400; ++k) {
        double h = h_lo + (p.gap_cut - h_lo) * k / 400.0, k2 = 0.0;
        if (h < p.dlvo_hcut)
            k2 += pl_pair_dlvo(d + h, d, p.coul_C, p.kappa, p.hamaker, p.prim_hm, p.prim_h0, p.dlvo_shift).k2;
        if (h < 0) k2 += pl_pair_hertz(-h, p.hertz_K).k2;
        if (k2 > 0)
            cr_expect(M_PI * sqrt(m_red / k2) / dt_md >= cs->min_contact_steps,
                      "case %d: gap %g: %g MD steps per collision < %g", id, h, M_PI * sqrt(m_red / k2) / dt_md,
                      cs->min_contact_steps);
    }
}

Test(mapping_colloids, property_random_physical_inputs, .timeout = 600)
{
    static pl_scene_t s;
    rng_state = 20261201;
    int ncase = pl_test_quick() ? 20 : 240, nwarn = 0;
    for (int id = 0; id < ncase; ++id) {
        input_t in;
        draw(&in);
        pl_err_t err = {0, ""};
        cr_assert_eq(load(&in, &s, &err), 0, "case %d: %s", id, err.msg);
        check_case(id, &in, &s);
        nwarn += s.mapping.map.nwarn > 0;
    }
    cr_log_info("%d random physical scenes derived and checked", ncase);
}

/* One input changed: its dependents follow (radius -> count, length unit,
 * Hertz K, gravity, substeps), everything else stays. */
Test(mapping_colloids, radius_changes_its_dependents, .timeout = 300)
{
    static pl_scene_t a, b;
    rng_state = 77;
    for (int id = 0; id < (pl_test_quick() ? 5 : 40); ++id) {
        input_t in, in2;
        draw(&in);
        in2 = in;
        in2.R = in.R * 1.25;
        for (int k = 0; k < 3; ++k) { /* same box in metres: cells follow a0 */
            double a02 = (in.coupling ? cbrt(4.0 * M_PI / 3.0) : 0.5) * in2.R;
            in2.cells[k] = (int)fmax(1.0, floor(in.box[k] / a02 + 0.5));
        }
        pl_err_t err = {0, ""};
        cr_assert_eq(load(&in, &a, &err), 0, "case %d: %s", id, err.msg);
        if (load(&in2, &b, &err)) continue; /* a box too small for the larger colloids: refused, fine */
        check_case(id, &in2, &b);
        CHECK_REL(b.colloids.dlvo.length_unit_m, 1.25 * a.colloids.dlvo.length_unit_m, "length unit x 1.25");
        CHECK_REL(b.colloids.radius, a.colloids.radius, "R / a0 unchanged");
        CHECK_REL(b.colloids.mass_density, a.colloids.mass_density, "mass density unchanged");
        CHECK_REL(b.colloids.dlvo.kappa_per_m, a.colloids.dlvo.kappa_per_m, "kappa unchanged");
        if (in.E > 0) CHECK_REL(b.colloids.hertz.K, a.colloids.hertz.K * pow(1.25, 3.0), "K a0^2.5 sqrt(R) ~ R^3");
        if (in.g > 0) cr_expect(b.colloids.gravity[2] != a.colloids.gravity[2], "case %d: gravity follows R", id);
    }
}

/* scenes/hecht_table1.cfg: 196 colloids at phi = 0.1 within 0.5 %, coupling I,
 * and it runs. */
Test(mapping_colloids, hecht_table1_runs_with_its_colloids, .timeout = 300)
{
    static pl_scene_t scene;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_scene_load("scenes/hecht_table1.cfg", &scene, &err), 0, "%s", err.msg);
    cr_expect_eq(scene.colloids.count, 196);
    cr_expect_lt(fabs(scene.mapping.colloid.phi_realised / 0.1 - 1.0), 0.005, "phi %g",
                 scene.mapping.colloid.phi_realised);
    cr_expect_eq(scene.coupling.method, PL_COUPLE_HECHT1);
    pl_sim_t *sim = NULL;
    cr_assert_eq(pl_sim_create(&scene, 1, &sim, &err), 0, "%s", err.msg);
    cr_assert_not_null(sim->colloids);
    cr_expect_eq(sim->colloids->n, 196);
    pl_test_steps(sim, pl_test_quick() ? 1 : 3);
    pl_sim_free(sim);
}

/* The shipped physical scenes: colloids derived, nothing hand-typed. */
Test(mapping_colloids, shipped_physical_scenes)
{
    static pl_scene_t scene;
    static const struct {
        const char *path;
        long long count;
    } sc[] = {{"scenes/quickstart.cfg", 173},  {"scenes/sediment.cfg", 64},    {"scenes/capillary.cfg", 96},
              {"scenes/hecht_fig9.cfg", 472},  {"scenes/hecht_fig14.cfg", 1181}};
    for (size_t i = 0; i < sizeof sc / sizeof sc[0]; ++i) {
        pl_err_t err = {0, ""};
        cr_assert_eq(pl_scene_load(sc[i].path, &scene, &err), 0, "%s", err.msg);
        cr_expect(scene.mapping.enabled);
        cr_expect_eq(scene.colloids.count, sc[i].count, "%s: %lld colloids", sc[i].path, scene.colloids.count);
        cr_expect_eq(scene.coupling.method, PL_COUPLE_HECHT2, "%s", sc[i].path);
        cr_expect_lt(fabs(scene.mapping.colloid.phi_realised / scene.mapping.physical.volume_fraction - 1.0), 0.005,
                     "%s", sc[i].path);
    }
}

/* PL Eq. 17 energy (kT) and its second derivative by central differences:
 * independent of the closed form in pl_mapping_cf_contact_time. */
static double wca_cf(double r, double s, double e) { return 4.0 * e * (pow(s / r, 12) - pow(s / r, 6) + 0.25); }

/* The potential coupling's front end (issue 35): scenes/pl_potential_physical.cfg
 * gets PL Sec. VII's choices: sigma_cf = R / a0 = 2, epsilon_cf = 2.5 kT, the
 * colloid-colloid WCA n = 24, 2.5 kT, PL's sigma_cc rule, mass from the
 * density (neutrally buoyant: mass_density = gamma), a slip surface with the
 * Enskog friction as the theory, and the MD step resolving the fluid-colloid
 * contact at kT by 20 steps (pi sqrt(m_red / U'') at U = kT, checked here by
 * bisection and finite differences). */
Test(mapping_colloids, potential_front_end)
{
    static pl_scene_t scene;
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_scene_load("scenes/pl_potential_physical.cfg", &scene, &err), 0, "%s", err.msg);
    const pl_mapping_t *m = &scene.mapping.map;
    cr_expect_eq(scene.coupling.method, PL_COUPLE_POTENTIAL);
    cr_expect_eq(scene.colloids.count, 41); /* 0.1 (12 um)^3 / (4/3 pi (1 um)^3) = 41.3 */
    cr_expect(fabs(scene.colloids.radius - 2.0) < 1e-12, "R = %g a0", scene.colloids.radius);
    cr_expect(fabs(m->a0 - 0.5e-6) < 1e-18, "a0 = %g", m->a0);
    cr_expect_eq(scene.coupling.sigma_cf, scene.colloids.radius);
    cr_expect_eq(scene.coupling.epsilon_cf, 2.5);
    cr_expect_str_eq(scene.colloids.pairs, "wca");
    cr_expect_eq(scene.colloids.wca.n, 24.0);
    cr_expect_eq(scene.colloids.wca.epsilon, 2.5);
    cr_expect_eq(scene.colloids.wca.sigma_rule, PL_SIGMA_PL);
    cr_expect_eq(scene.colloids.wca.sigma, 0.0);
    cr_expect(fabs(scene.colloids.mass_density - 5.0) < 1e-12, "neutrally buoyant: %g", scene.colloids.mass_density);
    cr_expect_eq(m->cg.boundary, PL_BOUNDARY_SLIP);
    cr_expect(m->cg.enskog);
    const double xi = 1.0 / (1.0 / m->xi_stokes_sim + 1.0 / m->xi_enskog_sim);
    cr_expect(fabs(m->d_col_theory * xi - 1.0) < 1e-12, "PL Eq. 41");
    cr_expect(fabs(m->xi_stokes_sim / (4.0 * PL_PI * scene.fluid.density * m->nu_sim * 2.0) - 1.0) < 1e-12, "slip");
    /* the contact time at kT, independently */
    double lo = 1.5, hi = 2.0 * pow(2.0, 1.0 / 6.0);
    for (int k = 0; k < 200; ++k) {
        double mid = 0.5 * (lo + hi);
        if (wca_cf(mid, 2.0, 2.5) > 1.0) lo = mid;
        else hi = mid;
    }
    const double r1 = 0.5 * (lo + hi), h = 1e-4;
    const double u2 = (wca_cf(r1 + h, 2.0, 2.5) - 2.0 * wca_cf(r1, 2.0, 2.5) + wca_cf(r1 - h, 2.0, 2.5)) / (h * h);
    const double M = 5.0 * 4.0 / 3.0 * PL_PI * 8.0, tc = PL_PI * sqrt(M / (M + 1.0) / u2);
    cr_expect(fabs(pl_mapping_cf_contact_time(2.0, 2.5, M) / tc - 1.0) < 1e-6, "contact time %.8g vs %.8g",
              pl_mapping_cf_contact_time(2.0, 2.5, M), tc);
    cr_expect_eq(scene.colloids.substeps, (long long)ceil(20.0 * 0.1 / tc), "substeps %lld, contact %g t0: %s",
                 scene.colloids.substeps, tc, scene.mapping.colloid.substeps_reason);
}

/* coarse_graining.multiple_time_stepping (issue 38) on the stiff suspension
 * bench/scenes/silica_10mM.cfg: colloids.slow_gap is the outer edge of the
 * DLVO secondary minimum's well (its inflection point, found here by a scan
 * of Hecht Eqs. 1-2 and finite differences of its own), and
 * colloids.slow_interval k the largest the colloids' own check
 * (pl_colloid_mts_setup, the contact guard's rule on the slow share) accepts:
 * the colloids set up with k, and refuse k + 1 given by hand with the same
 * gap, unless k is already the cap of a quarter of the fewest MD steps. */
static char *silica_text(const char *extra_cg, const char *extra_colloids)
{
    FILE *f = fopen("bench/scenes/silica_10mM.cfg", "r");
    cr_assert(f != NULL);
    static char base[8192];
    size_t n = fread(base, 1, sizeof base - 1, f);
    fclose(f);
    base[n] = 0;
    char *out = malloc(n + 1024);
    cr_assert(out != NULL);
    const char *cg = strstr(base, "coarse_graining: {"), *co = strstr(base, "colloids: {");
    cr_assert(cg && co && cg < co);
    size_t a = (size_t)(cg - base) + strlen("coarse_graining: {"), b = (size_t)(co - base) + strlen("colloids: {");
    snprintf(out, n + 1024, "%.*s %s%.*s %s%s", (int)a, base, extra_cg, (int)(b - a), base + a, extra_colloids,
             base + b);
    return out;
}

/* the checks on the silica scene with extra colloids{} keys; returns k */
static long long check_mts(const char *extra_colloids)
{
    static pl_scene_t scene, hand;
    pl_err_t err = {0, ""};
    char *text = silica_text("multiple_time_stepping = true;", extra_colloids);
    cr_assert_eq(pl_scene_load_string(text, "silica_mts.cfg", &scene, &err), 0, "%s", err.msg);
    free(text);
    const pl_scene_colloids_t *cs = &scene.colloids;
    cr_assert(cs->adaptive_substeps, "the stiff scene runs adaptive substeps");
    const long long k = cs->slow_interval;
    cr_expect_geq(k, 2, "slow_interval = %lld", k);
    cr_expect_eq(cs->substeps % k, 0, "substeps %lld a multiple of %lld", cs->substeps, k);
    cr_expect_leq(k, cs->min_substeps / 4, "k = %lld at most a quarter of %lld", k, cs->min_substeps);

    /* the secondary minimum by a scan of the DLVO energy beyond the barrier */
    pl_colloid_pair_params_t p;
    pl_colloid_dlvo_info_t info;
    cr_assert_eq(pl_colloid_pair_params(&scene, &p, &info, &err), 0, "%s", err.msg);
    const double d = 2.0 * cs->radius;
    double hbest = NAN, ubest = INFINITY, umax = -INFINITY;
    int past_barrier = 0;
    for (int q = 1; q <= 200000; ++q) {
        double h = p.dlvo_hcut * q / 200000.0;
        double u = pl_pair_dlvo_raw(d + h, d, p.coul_C, p.kappa, p.hamaker).u;
        if (u > umax) umax = u;
        if (u < umax - 1.0) past_barrier = 1;
        if (past_barrier && u < ubest) {
            ubest = u;
            hbest = h;
        }
    }
    /* the well's outer edge: the inflection point beyond the minimum, where
     * U'' (central differences of U) changes sign */
    const double dh = p.dlvo_hcut / 200000.0;
    double hinf = NAN;
    for (double h = hbest; h < p.dlvo_hcut; h += dh) {
        double um = pl_pair_dlvo_raw(d + h - dh, d, p.coul_C, p.kappa, p.hamaker).u,
               u0 = pl_pair_dlvo_raw(d + h, d, p.coul_C, p.kappa, p.hamaker).u,
               up = pl_pair_dlvo_raw(d + h + dh, d, p.coul_C, p.kappa, p.hamaker).u;
        if (um - 2.0 * u0 + up <= 0.0) {
            hinf = h;
            break;
        }
    }
    cr_expect(fabs(cs->slow_gap - hinf) <= 2e-3 * hbest + 2.0 * dh,
              "slow_gap %.6g, the inflection point beyond the minimum %.6g (minimum %.6g)", cs->slow_gap, hinf, hbest);
    cr_expect_gt(cs->slow_gap, hbest);

    /* the colloids accept k and refuse k + 1 */
    pl_colloid_t *c = NULL;
    cr_assert_eq(pl_colloid_create(&scene, 1, &c, &err), 0, "k = %lld refused: %s", k, err.msg);
    pl_colloid_free(c);
    if (k + 1 <= cs->min_substeps / 4) {
        char extra[256];
        snprintf(extra, sizeof extra, "%s slow_interval = %lld; slow_gap = %.17g;", extra_colloids, k + 1,
                 cs->slow_gap);
        text = silica_text("", extra);
        int rc = pl_scene_load_string(text, "silica_hand.cfg", &hand, &err);
        free(text);
        if (rc == 0) {
            c = NULL;
            rc = pl_colloid_create(&hand, 1, &c, &err);
            pl_colloid_free(c);
        }
        cr_expect_neq(rc, 0, "k + 1 = %lld accepted", k + 1);
        cr_expect(strstr(err.msg, "colloids.slow_interval") != NULL, "%s", err.msg);
    }
    return k;
}

/* As the scene is, k is the cap (a quarter of the fewest MD steps); with
 * min_contact_steps = 40 the slow share's resolution sets it below the cap,
 * so k + 1 is refused by the colloids' own check. */
Test(mapping_colloids, multiple_time_stepping_derived, .timeout = 300)
{
    const long long k20 = check_mts(""), k40 = check_mts("min_contact_steps = 40.0;");
    cr_expect_eq(k20, 94 / 4, "the cap: %lld", k20);
    cr_expect_lt(k40, 94 / 4, "below the cap: %lld", k40);
}
