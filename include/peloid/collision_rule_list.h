/* The collision rules' one list, X(row, name) in srd.rule order: the rows
 * are the fluid's (src/fluid/collision_rules.c, each row in its own file),
 * the names the key schema's (src/scene/scene_keys.c: the srd.rule choice).
 * A new rule is its own files plus one line here. */
#ifndef PELOID_COLLISION_RULE_LIST_H
#define PELOID_COLLISION_RULE_LIST_H

#define PL_COLLISION_RULES(X)                                                                                      \
    X(pl_rule_random_axis, "random_axis")                                                                          \
    X(pl_rule_hecht_axes, "hecht_axes")                                                                            \
    X(pl_rule_mpc_at, "mpc_at")                                                                                    \
    X(pl_rule_mpc_at_a, "mpc_at_a")                                                                                \
    X(pl_rule_srd_a, "srd_a")

#endif
