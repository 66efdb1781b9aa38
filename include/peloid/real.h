/* Storage precision of particle positions and velocities.  Double by default;
 * `make DEFS=-DPL_SINGLE` stores them in float (issue: single-precision mode).
 * Accumulations (cell sums, reductions) are always done in double. */
#ifndef PELOID_REAL_H
#define PELOID_REAL_H

#ifdef PL_SINGLE
typedef float pl_real;
#define PL_REAL_NAME "float"
#else
typedef double pl_real;
#define PL_REAL_NAME "double"
#endif

#define PL_ALIGN 64

/* The one spelling of pi. */
#define PL_PI 3.14159265358979323846

/* A 3-vector key (a flow velocity, a spin, a wall velocity) that is set: any
 * component non-zero. */
static inline int pl_vec3_nonzero(const double v[3]) { return v[0] != 0.0 || v[1] != 0.0 || v[2] != 0.0; }

/* For a function whose products gcc's SLP vectoriser fuses into vfmaddsub
 * (pairs a b - c, a b + c, as in a quaternion product) despite
 * -ffp-contract=off, one rounding fewer than the source: without SLP the
 * function rounds as written.  (Functions outlined by OpenMP do not inherit
 * it, and the loop vectoriser's fusions are not affected.) */
#if defined(__GNUC__) && !defined(__clang__)
#define PL_ROUND_AS_WRITTEN __attribute__((optimize("no-tree-slp-vectorize")))
#else
#define PL_ROUND_AS_WRITTEN
#endif

#endif
