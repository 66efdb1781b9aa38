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

#endif
