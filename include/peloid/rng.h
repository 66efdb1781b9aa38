/* Counter-based random numbers (DESIGN.md "Random numbers").
 *
 * Random123 Philox4x64-10, keyed by (scene seed, purpose); the counter is
 * (step, entity index, draw index, 0).  Any draw is a pure function of those
 * values, so results do not depend on the thread count or on the order in
 * which entities are visited, and a restart continues the same streams. */
#ifndef PELOID_RNG_H
#define PELOID_RNG_H

#include <stdint.h>
#include <math.h>
#include <Random123/philox.h>

/* One purpose per call site: two call sites never share a stream. */
typedef enum {
    PL_RNG_INIT_POS = 1,
    PL_RNG_INIT_VEL = 2,
    PL_RNG_GRID_SHIFT = 3,
    PL_RNG_COLLIDE = 4,
    PL_RNG_THERMOSTAT = 5,
    PL_RNG_WALL_GHOST = 6,
    PL_RNG_WALL_THERMAL = 7,
    /* colloids */
    PL_RNG_BD_NOISE = 17,         /* Brownian displacements (kernels/colloid_bd.c) */
    PL_RNG_COLLOID_PLACE = 18,    /* random placement attempts */
    PL_RNG_COLLOID_VEL = 19,      /* initial translational/rotational velocities */
    PL_RNG_COLLOID_RADIUS = 20,   /* polydisperse radii */
    /* colloid-solvent couplings */
    PL_RNG_COUPLE2_ROTATE = 32,   /* coupling II rotation of a cell with colloids */
    PL_RNG_COUPLE2_THERMOSTAT = 33, /* coupling II Heyes factor */
    PL_RNG_REFLECT = 34,          /* coupling I thermal wall velocities (Hecht Eq. 13) */
    PL_RNG_FLUID_REPLACE = 35,    /* fluid particles moved out of colloids at start */
} pl_rng_purpose_t;

typedef struct {
    double u[4];
} pl_rand4_t;

/* Four uniform doubles in (0, 1) (never exactly 0 or 1: safe for log). */
static inline pl_rand4_t pl_rng_uniform4(uint64_t seed, uint64_t purpose, uint64_t step,
                                         uint64_t index, uint64_t draw)
{
    philox4x64_ctr_t ctr = {{step, index, draw, 0}};
    philox4x64_key_t key = {{seed, purpose}};
    philox4x64_ctr_t r = philox4x64(ctr, key);
    pl_rand4_t out;
    for (int k = 0; k < 4; ++k)
        out.u[k] = ((double)(r.v[k] >> 11) + 0.5) * 0x1.0p-53;
    return out;
}

/* Two independent standard normal deviates from two uniforms (Box–Muller). */
static inline void pl_rng_gauss2(double u1, double u2, double *g1, double *g2)
{
    double rad = sqrt(-2.0 * log(u1));
    double ang = 6.283185307179586476925 * u2;
    *g1 = rad * cos(ang);
    *g2 = rad * sin(ang);
}

#endif
