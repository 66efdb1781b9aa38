/* SRD fluid particle state: structure of arrays, 64-byte aligned, each array
 * with a twin that the counting sort scatters into before the two are swapped
 * (STYLE.md 4).  Checkpointable state is exactly what this struct owns. */
#ifndef PELOID_FLUID_H
#define PELOID_FLUID_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/error.h"
#include "peloid/real.h"

enum { PL_FLUID_NARR = 6, PL_FLUID_NTRACK = 3 };

typedef struct pl_fluid {
    size_t n;          /* number of particles */
    int tracked;       /* id + unwrapped displacement carried */
    /* r[0..2] = x, y, z; v[0..2] = vx, vy, vz; *_alt are the sort twins */
    pl_real *r[3], *v[3];
    pl_real *r_alt[3], *v_alt[3];
    /* tracked only: particle id and displacement since the start (unwrapped) */
    uint32_t *id, *id_alt;
    double *disp[3], *disp_alt[3];
    uint32_t *cell; /* per particle: collision cell of the current step */
} pl_fluid_t;

/* The arrays first touched on nthreads threads (pl_alloc). */
int pl_fluid_create(size_t n, int tracked, int nthreads, pl_fluid_t *fluid, pl_err_t *err);
void pl_fluid_free(pl_fluid_t *fluid);
/* Swaps every array with its twin (after the scatter of the counting sort). */
void pl_fluid_swap(pl_fluid_t *fluid);
/* Bytes held per particle (state + twins + cell index): for the benchmarks. */
size_t pl_fluid_bytes(const pl_fluid_t *fluid);

/* 64-byte aligned, zeroed allocation; first touch is done in parallel on
 * nthreads threads (those of the kernels that will use it) with the same
 * static schedule the kernels use, so pages land near their threads. */
void *pl_alloc(size_t bytes, int nthreads);
/* Zeroes bytes at mem page by page on nthreads threads, with the kernels'
 * static schedule (kernels/first_touch.c). */
void pl_first_touch(void *mem, size_t bytes, int nthreads);
void pl_free(void *p);

#endif
