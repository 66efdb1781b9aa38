/* Counter-based random numbers (DESIGN.md "Random numbers").
 *
 * Random123 Philox4x64-10, keyed by (scene seed, purpose); the counter is
 * (step, entity index, draw index, 0).  Any draw is a pure function of those
 * values, so results do not depend on the thread count or on the order in
 * which entities are visited, and a restart continues the same streams. */
#ifndef PELOID_RNG_H
#define PELOID_RNG_H

#include <stddef.h>
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
    PL_RNG_ANDERSEN = 8,          /* MPC-AT relative velocities (peloid/mpc_at.h); counter (step, cell,
                                     rank in the cell) */
    /* colloids */
    PL_RNG_BD_NOISE = 17,         /* Brownian displacements (kernels/colloid_bd.c) */
    PL_RNG_COLLOID_PLACE = 18,    /* random placement attempts */
    PL_RNG_COLLOID_VEL = 19,      /* initial translational/rotational velocities */
    PL_RNG_COLLOID_RADIUS = 20,   /* polydisperse radii */
    PL_RNG_LUB_NOISE = 21,        /* random pair force of the lubrication friction (kernels/colloid_forces.c);
                                     counter (MD step, lower, higher colloid index) */
    /* colloid-solvent couplings */
    PL_RNG_COUPLE2_ROTATE = 32,   /* coupling II rotation of a cell with colloids */
    PL_RNG_COUPLE2_THERMOSTAT = 33, /* coupling II Heyes factor */
    PL_RNG_REFLECT = 34,          /* coupling I thermal wall velocities (Hecht Eq. 13) */
    PL_RNG_FLUID_REPLACE = 35,    /* fluid particles moved out of colloids at start */
    PL_RNG_REFLECT_ORDER = 36,    /* coupling I order of a step's events; counter (step, particle) */
} pl_rng_purpose_t;

typedef struct {
    double u[4];
} pl_rand4_t;

/* A Philox word as a uniform double in (0, 1): its top 53 bits, centred
 * (never exactly 0 or 1: safe for log). */
static inline double pl_rng_u01(uint64_t word) { return ((double)(word >> 11) + 0.5) * 0x1.0p-53; }

/* Four uniform doubles in (0, 1) (pl_rng_u01 of the four words). */
static inline pl_rand4_t pl_rng_uniform4(uint64_t seed, uint64_t purpose, uint64_t step,
                                         uint64_t index, uint64_t draw)
{
    philox4x64_ctr_t ctr = {{step, index, draw, 0}};
    philox4x64_key_t key = {{seed, purpose}};
    philox4x64_ctr_t r = philox4x64(ctr, key);
    pl_rand4_t out;
    for (int k = 0; k < 4; ++k) out.u[k] = pl_rng_u01(r.v[k]);
    return out;
}

/* pl_rng_uniform4 for PL_RNG_LANES consecutive entities at once:
 * u[k][l] = pl_rng_uniform4(seed, purpose, step, index0 + l, draw).u[k],
 * bit for bit.  With AVX-512 (64-bit lanes that multiply and convert to
 * double in one instruction each) Philox4x64-10 runs written out over lanes
 * (Random123's round and key schedule, the 64 x 64 -> 128-bit products from
 * 32-bit halves) in vector registers, where the scalar pl_rng_uniform4 is
 * one dependency chain per draw.  Without AVX-512 the lanes cost more than
 * the scalar draws, so they are drawn one by one (bench/RESULTS.md, "the
 * collision's random draws in vector lanes"). */
enum { PL_RNG_LANES = 32 };
#if defined(__AVX512F__) && defined(__AVX512DQ__)
#define PL_RNG_VECTOR_LANES 1
#else
#define PL_RNG_VECTOR_LANES 0
#endif

/* a * b = hi 2^64 + lo (returns hi), from the four 32 x 32 -> 64-bit
 * products of the halves (vpmuludq in vector lanes):
 * lo = (aL bL mod 2^32) | w << 32. */
static inline uint64_t pl_rng_mulhilo64(uint64_t a, uint64_t b, uint64_t *lo)
{
    const uint32_t aL = (uint32_t)a, aH = (uint32_t)(a >> 32), bL = (uint32_t)b, bH = (uint32_t)(b >> 32);
    const uint64_t t = (uint64_t)aL * bL;
    const uint64_t u = (uint64_t)aH * bL + (t >> 32);   /* < 2^64 */
    const uint64_t w = (uint64_t)aL * bH + (uint32_t)u; /* < 2^64 */
    *lo = (uint64_t)(uint32_t)t | w << 32;
    return (uint64_t)aH * bH + (u >> 32) + (w >> 32);
}

/* The Philox4x64-10 outputs c0..c3 of the lanes' counters (step, index0 +
 * l, draw, 0) under the key (seed, purpose), in loops the compiler
 * vectorises. */
static inline void pl_rng_philox_lanes(uint64_t seed, uint64_t purpose, uint64_t step, uint64_t index0,
                                       uint64_t draw, uint64_t c[4][PL_RNG_LANES])
{
    uint64_t *restrict c0 = c[0], *restrict c1 = c[1], *restrict c2 = c[2], *restrict c3 = c[3];
    for (size_t l = 0; l < PL_RNG_LANES; ++l) {
        c0[l] = step;
        c1[l] = index0 + l;
        c2[l] = draw;
        c3[l] = 0;
    }
    uint64_t k0 = seed, k1 = purpose;
    for (int round = 0; round < 10; ++round) {
        if (round > 0) { /* Random123's key bump */
            k0 += PHILOX_W64_0;
            k1 += PHILOX_W64_1;
        }
#pragma omp simd
        for (size_t l = 0; l < PL_RNG_LANES; ++l) {
            const uint64_t a = c0[l], b = c2[l];
            uint64_t lo0, lo1;
            const uint64_t hi0 = pl_rng_mulhilo64(PHILOX_M4x64_0, a, &lo0);
            const uint64_t hi1 = pl_rng_mulhilo64(PHILOX_M4x64_1, b, &lo1);
            c0[l] = hi1 ^ c1[l] ^ k0;
            c1[l] = lo1;
            c2[l] = hi0 ^ c3[l] ^ k1;
            c3[l] = lo0;
        }
    }
}

static inline void pl_rng_uniform4_lanes(uint64_t seed, uint64_t purpose, uint64_t step, uint64_t index0,
                                         uint64_t draw, double u[4][PL_RNG_LANES])
{
#if PL_RNG_VECTOR_LANES
    uint64_t c[4][PL_RNG_LANES];
    pl_rng_philox_lanes(seed, purpose, step, index0, draw, c);
#pragma omp simd
    for (size_t l = 0; l < PL_RNG_LANES; ++l) /* as pl_rng_uniform4 */
        for (int k = 0; k < 4; ++k) u[k][l] = pl_rng_u01(c[k][l]);
#else
    for (size_t l = 0; l < PL_RNG_LANES; ++l) {
        const pl_rand4_t r = pl_rng_uniform4(seed, purpose, step, index0 + l, draw);
        for (int k = 0; k < 4; ++k) u[k][l] = r.u[k];
    }
#endif
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
