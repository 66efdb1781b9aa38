/* The collision rules of the fluid, one row each (peloid/collision_rule.h).
 * Their one list is include/peloid/collision_rule_list.h: a new rule is its
 * own files (kernel, theory, row) plus one line there.  The scene stores a
 * rule as its index in this list (srd.rule); the two SRD rotations keep
 * their old indices PL_RULE_RANDOM_AXIS = 0 and PL_RULE_HECHT_AXES = 1, so
 * scenes and checkpoints read as before. */
#include <stddef.h>

#include "peloid/collision_rule.h"
#include "peloid/collision_rule_list.h"

#define DECL(row, name) extern const pl_collision_rule_t row; /* in the rule's own file */
PL_COLLISION_RULES(DECL)
#define ROW(row, name) &row,
static const pl_collision_rule_t *const rows[] = {PL_COLLISION_RULES(ROW)};

_Static_assert(PL_RULE_RANDOM_AXIS == 0 && PL_RULE_HECHT_AXES == 1, "the SRD rows keep their indices");

const pl_collision_rule_t *pl_collision_rule(int rule)
{
    const int n = (int)(sizeof rows / sizeof rows[0]);
    return rule >= 0 && rule < n ? rows[rule] : NULL;
}
