/* SRD fluid particle state: structure of arrays, 64-byte aligned, each array
 * with a twin that the counting sort scatters into before the two are swapped
 * (STYLE.md 4).  Checkpointable state is exactly what this struct owns, but
 * for `bands` (the counting sort's scratch, rebuilt every step). */
#ifndef PELOID_FLUID_H
#define PELOID_FLUID_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/error.h"
#include "peloid/real.h"

enum { PL_FLUID_NARR = 6, PL_FLUID_NTRACK = 3 };

/* The counting sort's narrow histogram rows (issue 38).  Each thread's
 * static chunk of particles, sorted by cell at the step before, covers a
 * narrow band of z planes, so thread t zeroes, counts into and scans only
 * the cells [lo[t], lo[t] + len[t]) (modulo the cell count: a band may wrap
 * around a periodic z axis) of its histogram row instead of the whole row,
 * whose traffic grows with the thread count (0.4 B per particle and thread
 * at 10 per cell, three times a step).  The sort sets the bands for the next
 * step (its chunks' planes and `margin` planes each side, PL_BAND_MARGIN at
 * first), for a team of `threads` (0: whole rows); the streaming records the
 * grid's planes.  A cell counted outside its thread's band (a particle that
 * moved further, a coupling's move, particles placed by hand) sets
 * `overflow`, and the sort then counts the whole rows again from the cells
 * and doubles the margin: the result is the stable sort by cell in every
 * case, for any thread count; only the traffic depends on the bands. */
enum { PL_BAND_MAX_THREADS = 256, PL_BAND_MARGIN = 2 };
typedef struct {
    int threads;           /* the team the bands are for; 0: whole rows */
    int overflow;          /* a count fell outside its band this step */
    uint32_t plane, nz;    /* cells per z plane and planes, from the streaming */
    uint32_t margin;       /* planes added each side of a chunk's (0: PL_BAND_MARGIN) */
    int z_periodic;
    uint64_t sorts, recounts; /* sorts with bands in use, and those that counted whole rows again */
    uint32_t lo[PL_BAND_MAX_THREADS], len[PL_BAND_MAX_THREADS];
} pl_fluid_bands_t;

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
    uint32_t *order; /* srd.sort_interval > 1 only (else NULL): the index sort's slot j is particle
                      * order[j]; scratch, rebuilt every step; the owner allocates it (pl_alloc),
                      * pl_fluid_free frees it */
    pl_fluid_bands_t bands; /* the counting sort's scratch, not state */
} pl_fluid_t;

/* The band of thread t of a team of nthreads for a sort over ncells cells:
 * *lo, *len (the whole row when the bands are not for this team). */
static inline void pl_fluid_band(const pl_fluid_t *f, int t, int nthreads, uint32_t ncells, uint32_t *lo,
                                 uint32_t *len)
{
    const int on = f->bands.threads == nthreads && f->bands.threads > 0;
    *lo = on ? f->bands.lo[t] : 0;
    *len = on ? f->bands.len[t] : ncells;
}

/* 1 when cell lies outside the band (lo, len) of ncells cells. */
static inline uint32_t pl_fluid_band_out(uint32_t cell, uint32_t lo, uint32_t len, uint32_t ncells)
{
    uint32_t rel = cell - lo;
    if (rel >= ncells) rel += ncells; /* cell < lo: the band wraps (or the cell lies before it) */
    return rel >= len;
}

/* Records a count outside a band (any thread; the next sort recounts). */
static inline void pl_fluid_band_overflow(pl_fluid_t *f) { __atomic_store_n(&f->bands.overflow, 1, __ATOMIC_RELAXED); }

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
 * static schedule (src/core/first_touch.c). */
void pl_first_touch(void *mem, size_t bytes, int nthreads);
void pl_free(void *p);

#endif
