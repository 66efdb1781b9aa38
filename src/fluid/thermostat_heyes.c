/* The Heyes thermostat as a thermostat row (peloid/thermostat.h): a Monte
 * Carlo move on each cell's relative kinetic energy inside the collision,
 * accepted with the Boltzmann weight at thermostat.temperature (Hecht Sec.
 * VIII.B, Eq. 33; peloid/srd_rules.h pl_heyes_zeta).  It has no stage of its
 * own: the collision rule's Heyes kernel (and coupling II's) runs on
 * multiples of thermostat.interval (pl_sim_add_collide_stage). */
#include <stddef.h>

#include "peloid/collision_rule.h"
#include "peloid/scene.h"
#include "peloid/thermostat.h"

/* only a rule with a Heyes kernel */
static int validate(const pl_scene_t *sc, pl_err_t *err)
{
    const pl_collision_rule_t *rule = pl_collision_rule(sc->srd.rule);
    if (!rule->collide_heyes)
        return pl_scene_fail(sc, err, offsetof(pl_scene_t, thermostat.type), "thermostat.type",
                             "\"heyes\" with srd.rule = \"%s\", which has no Heyes collision; allowed: "
                             "\"none\" or \"rescale\"", rule->name);
    return 0;
}

const pl_thermostat_t pl_thermostat_heyes = {
    .name = "heyes",
    .doc = "Monte Carlo cell thermostat (Hecht Eq. 33)",
    .keys = "thermostat.temperature, thermostat.heyes_epsilon, thermostat.interval",
    .in_collision = 1,
    .validate = validate,
};
