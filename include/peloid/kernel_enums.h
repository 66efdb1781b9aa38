/* The option values the kernels switch on (wall type of an axis, collision
 * rule, coupling I's surface rule and placement): plain enums, without the
 * scene they come from.  scene.h and coupling_scene.h include this header,
 * so the scene structs and the kernels share one definition of each value;
 * kernels include it (through srd_kernels.h, coupling_kernels.h, grid.h)
 * instead of scene.h (DESIGN.md "Layers"). */
#ifndef PELOID_KERNEL_ENUMS_H
#define PELOID_KERNEL_ENUMS_H

/* Boundary of a box axis (pl_grid_t.walls, scene box.walls_z / walls_xy). */
enum { PL_WALLS_NONE = 0, PL_WALLS_NOSLIP = 1, PL_WALLS_SLIP = 2 };
/* SRD collision rule (scene srd.rule). */
enum { PL_RULE_RANDOM_AXIS = 0, PL_RULE_HECHT_AXES = 1 };
/* Surface rule of coupling I (frame of the colloid surface). */
enum { PL_BOUND_SLIP = 0, PL_BOUND_STICK_STOCHASTIC = 1, PL_BOUND_STICK_BOUNCE = 2 };
/* Where a reflected particle restarts: Hecht Sec. IV methods (i) and (ii). */
enum { PL_PLACE_NEAREST = 0, PL_PLACE_ENTRY = 1 };

#endif
