/* Coupling II as a component row (peloid/coupling_row.h): the colloids join
 * the SRD collision of their cell (Hecht Sec. V), as a variant of the
 * fluid's collision stage; its friction and the settling bound of Hecht
 * Sec. VI that scenes must keep.  Its state and stages:
 * src/coupling/coupling_stages.c. */
#include <math.h>

#include "peloid/coupling_row.h"
#include "peloid/collision_rule.h"
#include "peloid/mapping.h"
#include "peloid/real.h" /* PL_PI */
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
    double cos_a = pl_collision_rule(scene->srd.rule)->srd_rotation == PL_RULE_HECHT_AXES ? 0.0 : cos(scene->srd.alpha_deg * PL_PI / 180.0);
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
static int validate(const pl_scene_t *scene, pl_err_t *err)
{
    const pl_scene_colloids_t *cs = &scene->colloids;
    double bound = scene->coupling.max_settling_energy;
    const double *g = cs->gravity;
    double gn = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (bound <= 0.0 || gn == 0.0 || scene->coupling.pinned)
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


static int create(pl_coupling_t *cp, pl_sim_t *sim, pl_err_t *err)
{
    return pl_coupling2_create(cp, sim, &cp->c2, err);
}

static void free_state(pl_coupling_t *cp)
{
    pl_coupling2_free(cp->c2);
    cp->c2 = NULL;
}

static int add_stages(pl_sim_t *sim, pl_err_t *err)
{
    pl_stage_t save = {.name = "coupling2-save", .fn = pl_coupling_stage_save, .ctx = pl_coupling_of(sim),
                       .interval = 1, .slot = PL_SLOT_PRE_COLLIDE};
    pl_stage_t plain = {.name = "coupling2-collide", .fn = pl_coupling_stage_collide, .ctx = pl_coupling_of(sim),
                        .slot = PL_SLOT_POST_COLLIDE};
    pl_stage_t heyes = {.name = "coupling2-collide+heyes", .fn = pl_coupling_stage_collide_heyes, .ctx = pl_coupling_of(sim),
                        .slot = PL_SLOT_POST_COLLIDE};
    int rc = pl_sim_add_stage(sim, &save, err);
    return rc ? rc : pl_sim_add_collide_stage(sim, &plain, &heyes, err);
}

const pl_coupling_row_t pl_coupling2_row = {
    .method = PL_COUPLE_HECHT2,
    .validate = validate,
    .create = create,
    .free = free_state,
    .add_stages = add_stages,
};
