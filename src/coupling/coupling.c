/* Coupling object: its common part (method, threads, seed, the compensating
 * fluid acceleration of Hecht Sec. VIII.A iii, the pinned colloids' impulse),
 * the state of the method in use (built and freed by that method's file:
 * coupling_stages.c for I and II, coupling_potential.c), the initial removal
 * of fluid from colloid interiors (couplings I and potential), and the
 * cross-key checks of the coupling section.  The pinned impulse is common
 * because every method's stages add to it and the thermo columns and the
 * checkpoint read it whatever the method; the colloid lookup is not: each of
 * the two methods that use one keeps its own, with its own radii. */
#include <math.h>
#include <stdlib.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/sim.h"



#define OFF(m) offsetof(pl_scene_t, m)

/* Coupling II friction of a colloid of mass M in a cell of gamma fluid
 * particles (m_f = 1): one collision changes its momentum on average by
 * -(1 - <R>) mu (v_c - v_fluid), mu = M gamma / (M + gamma), <R> = (1 + 2 cos
 * alpha) / 3 (hecht_axes: 1/3), so xi_II = 2/3 (1 - cos alpha) mu / dt.  The
 * cell's fluid is dragged along, so the true friction is smaller. */
double pl_coupling2_friction(const pl_scene_t *scene, double mass)
{
    double gamma = scene->fluid.density;
    double cos_a = scene->srd.rule == PL_RULE_HECHT_AXES ? 0.0 : cos(scene->srd.alpha_deg * PL_PI / 180.0);
    double mu = mass * gamma / (mass + gamma);
    return 2.0 / 3.0 * (1.0 - cos_a) * mu / scene->srd.dt;
}

/* Hecht Sec. VI asks tau_P << tau_S: a colloid must relax before it settles
 * far.  With Pe = M g R / kT this is M v_s^2 / kT = 2 Pe tau_P / tau_S << 1
 * (Hecht's Table IV: 0.011).  Coupling II gives the colloid only the friction
 * of its own cell (pl_coupling2_friction); a colloid much heavier than the
 * fluid of its cell (Hecht Sec. VII.C avoids it: cell volume = colloid
 * volume) settles nearly as fast as it moves thermally, and the kinetic
 * energy of the settling flow then passes for heat: the colloids run hot.
 * v_s = M g / xi_II is a lower bound of the settling speed. */
static int check_settling(const pl_scene_t *scene, pl_err_t *err)
{
    const pl_scene_colloids_t *cs = &scene->colloids;
    double bound = scene->coupling.max_settling_energy;
    const double *g = cs->gravity;
    double gn = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (scene->coupling.method != PL_COUPLE_HECHT2 || bound <= 0.0 || gn == 0.0 ||
        scene->coupling.pinned)
        return 0;
    double rmax = cs->radius * (1.0 + sqrt(3.0) * cs->polydispersity);
    double mass = cs->mass_density * 4.0 / 3.0 * PL_PI * rmax * rmax * rmax;
    double kT = pl_scene_kT(scene);
    double xi = pl_coupling2_friction(scene, mass);
    double vs = mass * gn / xi, e = mass * vs * vs / kT;
    if (e <= bound) return 0;
    /* a physical scene: the model gravity g t0^2 / a0 comes from the SRD
     * step in seconds the user wrote, else from physical.gravity */
    size_t off = OFF(colloids.gravity);
    const char *key = "colloids.gravity";
    char why[160] = "";
    if (scene->mapping.enabled && pl_scene_line_of(scene, off) <= 0) {
        /* at fault: an implausible physical input of M g, then a mean free
         * path above one cell (xi_II ~ 1/srd.dt, Hecht Sec. V), else
         * physical.gravity */
        const size_t from[] = {OFF(mapping.physical.particle_density), OFF(mapping.physical.solvent_density),
                               OFF(mapping.physical.gravity), OFF(mapping.physical.radius),
                               OFF(mapping.physical.viscosity)};
        int dt_given = pl_scene_line_of(scene, OFF(mapping.cg.srd_dt)) > 0;
        int lambda = pl_scene_line_of(scene, OFF(mapping.cg.mean_free_path)) > 0 &&
                     scene->mapping.cg.mean_free_path > 1.0;
        off = dt_given ? OFF(mapping.cg.srd_dt)
              : lambda ? OFF(mapping.cg.mean_free_path)
                       : OFF(mapping.physical.gravity);
        key = dt_given ? "coarse_graining.srd_dt" : lambda ? "coarse_graining.mean_free_path" : "physical.gravity";
        const char *k = pl_mapping_blame(scene, from, sizeof from / sizeof from[0], &off, why, sizeof why);
        if (k) key = k;
    }
    if (off == OFF(mapping.cg.srd_dt))
        return pl_scene_fail(scene, err, off, key,
                             "%g s makes t0 = %.4g s and the model gravity %.4g a0/t0^2: coupling II "
                             "colloids settle too fast (M v_s^2 >= %.3g kT > coupling.max_settling_energy = "
                             "%g, Hecht Sec. VI: tau_P << tau_S); allowed: a shorter SRD step, or 0 "
                             "(derived from coarse_graining.time_match)",
                             scene->mapping.cg.srd_dt, scene->mapping.map.t0, gn, e, bound);
    const int phys = scene->mapping.enabled;
    return pl_scene_fail(scene, err, off, key,
                         "%scoupling II settling too fast: M = %.4g m_f in cells of %.3g fluid "
                         "particles, xi_II = %.4g, v_s >= M g / xi_II = %.3g a0/t0, M v_s^2 = "
                         "%.3g kT > coupling.max_settling_energy = %g (Hecht Sec. VI: tau_P << "
                         "tau_S); lower the gravity, or the colloid mass per cell (radius ~ 0.62 "
                         "a0: cell volume = colloid volume, Hecht Sec. VII.C), or raise %s, or lower %s",
                         why, mass, scene->fluid.density, xi, vs, e, bound,
                         phys ? "coarse_graining.particles_per_cell" : "fluid.density",
                         phys ? "coarse_graining.mean_free_path" : "srd.dt");
}

int pl_coupling_validate_scene(const pl_scene_t *scene, pl_err_t *err)
{
    const pl_scene_coupling_t *cs = &scene->coupling;
    if (cs->method == PL_COUPLE_NONE) return 0;
    if (scene->colloids.count == 0 || scene->fluid.density <= 0.0)
        return pl_scene_fail(scene, err, OFF(coupling.method), "coupling.method",
                             "a coupling needs colloids (colloids.count > 0) and fluid "
                             "(fluid.density > 0); allowed without them: \"none\"");
    if (!cs->pinned && (cs->flow_velocity[0] != 0.0 || cs->flow_velocity[1] != 0.0 ||
                        cs->flow_velocity[2] != 0.0))
        return pl_scene_fail(scene, err, OFF(coupling.flow_velocity), "coupling.flow_velocity",
                             "a held flow velocity needs coupling.pinned = true");
    if (scene->colloids.integrator != PL_CINT_VERLET)
        return pl_scene_fail(scene, err, OFF(coupling.method), "coupling.method",
                             "colloids.integrator = \"brownian\" already stands for the solvent; "
                             "a coupling needs \"verlet\"");
    return check_settling(scene, err);
}

/* Couplings I and potential start without fluid inside colloids (radius R,
 * or sigma_cf when rad is given): such particles get a new uniform position
 * (draws keyed by particle index: thread independent). */
static void clear_interiors(const pl_coupling_t *cp, pl_sim_t *sim, const pl_coupling_lookup_t *lk,
                            const double *rad)
{
    pl_coupling_colloids_t v = pl_coupling_view(sim->colloids);
    if (rad) v.rad = rad;
    pl_coupling_clear_interiors(&sim->fluid, &v, sim->grid.L, sim->grid.walls, lk->start, lk->list, cp->seed,
                                cp->nthreads);
}

int pl_coupling_moves_colloids(const pl_scene_t *scene, size_t n_fluid)
{
    const pl_scene_coupling_t *c = &scene->coupling;
    return n_fluid > 0 && c->method != PL_COUPLE_NONE && (c->pinned || c->method == PL_COUPLE_POTENTIAL);
}

int pl_coupling_create(pl_sim_t *sim, pl_coupling_t **out, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    pl_colloid_t *col = sim->colloids;
    *out = NULL;
    pl_coupling_t *cp = calloc(1, sizeof *cp);
    if (!cp) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    cp->method = sc->coupling.method;
    cp->nthreads = sim->nthreads;
    cp->seed = (uint64_t)sc->run.seed;
    size_t nc = col ? col->n : 0;
    /* Hecht Sec. VIII.A (iii): the fluid carries minus the colloids' weight;
     * only in a periodic box (walls take up momentum: options i and ii) */
    if (col && cp->method != PL_COUPLE_NONE && sc->coupling.compensate_gravity && !sim->grid.any_walls && sim->fluid.n > 0) {
        double M = 0.0;
        for (size_t k = 0; k < nc; ++k) M += col->mass[k];
        for (int d = 0; d < 3; ++d) cp->fluid_accel[d] = -sc->colloids.gravity[d] * M / (double)sim->fluid.n;
    }
    /* coupled colloids exchange energy with the fluid: no NVE drift guard */
    if (cp->method != PL_COUPLE_NONE) sim->colloids->nve = 0;
    cp->pinned = cp->method != PL_COUPLE_NONE && sc->coupling.pinned;
    if (cp->pinned) /* held fixed from the start */
        for (size_t k = 0; k < nc; ++k)
            col->vx[k] = col->vy[k] = col->vz[k] = col->wx[k] = col->wy[k] = col->wz[k] = 0.0;
    int rc = 0;
    if (cp->method == PL_COUPLE_HECHT1) {
        if (!(rc = pl_coupling1_create(cp, sim, &cp->c1, err)) &&
            !(rc = pl_coupling_lookup_update(&cp->c1->lk, sim, err)))
            clear_interiors(cp, sim, &cp->c1->lk, NULL);
    } else if (cp->method == PL_COUPLE_HECHT2) {
        rc = pl_coupling2_create(cp, sim, &cp->c2, err);
    } else if (cp->method == PL_COUPLE_POTENTIAL && !(rc = pl_coupling_potential_create(cp, sim, &cp->pot, err))) {
        /* the interiors of the spheres of radius sigma_cf */
        pl_coupling_potential_state_t *ps = cp->pot;
        for (size_t k = 0; k < nc; ++k) ps->rad_big[k] = ps->wca.sigma;
        pl_coupling_colloids_t v = pl_coupling_view(col);
        v.rad = ps->rad_big;
        if (!(rc = pl_coupling_lookup_fill(&ps->lk, sim, &v, err))) clear_interiors(cp, sim, &ps->lk, ps->rad_big);
    }
    if (rc) {
        pl_coupling_free(cp);
        if (rc == PL_ERR_NOMEM && !err->code) return pl_err_set(err, rc, "out of memory for the coupling");
        return rc;
    }
    *out = cp;
    return 0;
}

void pl_coupling_free(pl_coupling_t *cp)
{
    if (!cp) return;
    pl_coupling1_free(cp->c1);
    pl_coupling2_free(cp->c2);
    pl_coupling_potential_free(cp->pot);
    free(cp);
}
