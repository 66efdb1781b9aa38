/* The thermostats' one list, X(row, name) in thermostat.type order: the rows
 * are the fluid's (src/fluid/thermostats.c; none there, the others each in
 * its own file), the names the key schema's (src/scene/scene_keys.c: the
 * thermostat.type choice).  A new thermostat is its own file plus one line
 * here. */
#ifndef PELOID_THERMOSTAT_LIST_H
#define PELOID_THERMOSTAT_LIST_H

#define PL_THERMOSTATS(X)                                                                                          \
    X(none, "none")                                                                                                \
    X(pl_thermostat_heyes, "heyes")                                                                                \
    X(pl_thermostat_rescale, "rescale")

#endif
