/* The SRD hot kernels (kernels/srd_*.c): OpenMP loops over the fluid arrays.
 * They see raw arrays and small parameter structs only: no scene, no I/O, no
 * allocation (DESIGN.md "Layers").  nthreads is the size of each parallel
 * region (num_threads): no kernel relies on a process-wide thread count. */
#ifndef PELOID_SRD_KERNELS_H
#define PELOID_SRD_KERNELS_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "peloid/fluid.h"
#include "peloid/grid.h"
#include "peloid/kernel_enums.h" /* PL_RULE_*, PL_WALLS_* */

/* ---- streaming fused with cell binning (kernels/srd_stream.c) ---------- */
/* Wall impulse accumulators: PL_WALL_ACC_STRIDE int64 per thread (two cache
 * lines), the first PL_WALL_ACC_N the impulse in fixed point
 * 2^-PL_FIELD_FIXED_SHIFT given by three "slots": the bottom z wall (xyz),
 * the top z wall (xyz), and the x/y walls of a capillary together (xyz). */
enum { PL_WALL_ACC_N = 9, PL_WALL_ACC_STRIDE = 16 };

/* Slot of wall `top` (0: at 0, 1: at L) of axis `axis`. */
static inline int pl_wall_slot(int axis, int top) { return axis == 2 ? top : 2; }

/* A pass over particles just streamed and binned, run by pl_srd_stream_bin
 * inside its parallel region: thread t calls it on consecutive ranges [lo,
 * hi) of its static chunk (pl_chunk), in order, each right after the range
 * was stored (blocks of PL_DRIFT_BLOCK on the periodic path, so the range
 * is still in L1; the whole chunk on the others).  Coupling I's detection
 * (pl_coupling_find_block) saves its own pass over the particle arrays.
 * As a pre-hook, it sees each block before it is stored, in blocks of
 * PL_DRIFT_BLOCK on every path (the potential coupling's selection,
 * pl_coupling_select_block). */
typedef void (*pl_stream_hook_fn)(void *ctx, int t, size_t lo, size_t hi);

typedef struct {
    double dt;          /* collision time step */
    double accel[3];    /* body force per unit mass (kick before the drift) */
    double wall_u[2][3];/* wall velocities (bottom z = 0, top z = Lz) */
    int64_t *wall_acc;  /* NULL, or nthreads x PL_WALL_ACC_STRIDE: pl_srd_stream_bin
                         * writes the impulse the walls gave each thread's chunk */
    pl_stream_hook_fn hook; /* NULL, or run on what pl_srd_stream_bin streamed */
    void *hook_ctx;
    /* NULL, or run on each block of the same ranges before it is stored:
     * the state before the streaming (on the periodic path after the
     * block was read, so in L1); the potential coupling's selection */
    pl_stream_hook_fn pre_hook;
    void *pre_hook_ctx;
} pl_stream_params_t;

/* r += v dt (after v += accel dt) with periodic wrap or wall reflection,
 * then the particle's collision cell under grid->shift is stored in
 * fluid->cell and counted in hist[t * ncells + c] of the thread t that owns
 * the particle (static partition pl_chunk).  hist: nthreads x ncells. */
void pl_srd_stream_bin(pl_fluid_t *fluid, const pl_grid_t *grid, const pl_stream_params_t *p,
                       uint32_t *hist, int nthreads);

/* The one wall bounce (the streaming's, kernels/srd_drift.h pl_drift_reflect):
 * a particle that moved in a straight line from r0 to r with velocity v in
 * time dt and left the box through a closed axis of g is taken back to the
 * earliest wall it hit, bounced (no-slip: v -> 2U - v; slip: the normal
 * component reversed) and moved on for the rest of dt, repeatedly; the
 * impulses go to acc.  Returns 0 (r, v untouched) when r is inside. */
int pl_srd_wall_bounce(const pl_grid_t *g, const double wall_u[2][3], double dt, const double r0[3],
                       double r[3], double v[3], int64_t acc[PL_WALL_ACC_N]);

/* The impulse pl_srd_stream_bin's bounces give one particle that starts at
 * (r0, v0), added to acc (fixed point, PL_WALL_ACC_N slots) bitwise as the
 * streaming adds it: lets a caller take back the count of a particle whose
 * streaming it replaces (the potential coupling). */
void pl_srd_stream_wall_impulse(const pl_grid_t *g, const pl_stream_params_t *p, const double r0[3],
                                const double v0[3], int64_t acc[PL_WALL_ACC_N]);

/* Cell binning only (no motion): used after initialisation and restart. */
void pl_srd_bin(pl_fluid_t *fluid, const pl_grid_t *grid, uint32_t *hist, int nthreads);

/* First half of the stream-in-scatter step: counts in hist (as
 * pl_srd_stream_bin does) the cell each particle will occupy after the
 * drift, but stores nothing else: r, v and fluid->cell are left as they are
 * (fluid->bands is: the grid's planes and a count outside a band).
 * Reads r, v only (48 B per particle in double, against 100 B read+written
 * by pl_srd_stream_bin). */
void pl_srd_stream_count(pl_fluid_t *fluid, const pl_grid_t *grid,
                         const pl_stream_params_t *p, uint32_t *hist, int nthreads);

/* ---- counting sort (kernels/srd_sort.c) ------------------------------- */
/* Prefix sum over (cell, thread), stable scatter into the twin arrays; the
 * caller then swaps them in (pl_fluid_swap).  After the swap the particles
 * of cell c are [cell_start[c], cell_start[c+1]).  The result is the stable
 * sort by cell: independent of nthreads. */
void pl_srd_sort(pl_fluid_t *fluid, uint32_t *hist, uint32_t *cell_start, size_t ncells,
                 int nthreads);

/* The same stable sort by cell, of an index only: slot j is particle
 * fluid->order[j] and cell_start as after pl_srd_sort, but the particle
 * arrays keep their order (no swap follows).  srd.sort_interval: the steps
 * between two full sorts, whose collision reads through the index. */
void pl_srd_sort_index(pl_fluid_t *fluid, uint32_t *hist, uint32_t *cell_start, size_t ncells,
                       int nthreads);

/* Second half of the stream-in-scatter step: pl_srd_sort in which each
 * particle is drifted (bitwise as pl_srd_stream_bin would drift it) on its
 * way into the twin arrays.  hist: from pl_srd_stream_count with the same
 * grid (shift) and p.  pl_srd_stream_count + pl_srd_stream_sort leave the
 * same state as pl_srd_stream_bin + pl_srd_sort, with one pass less over the
 * particle arrays; fluid->cell is not written.  The caller swaps, as after
 * pl_srd_sort. */
void pl_srd_stream_sort(pl_fluid_t *fluid, const pl_grid_t *grid, const pl_stream_params_t *p,
                        uint32_t *hist, uint32_t *cell_start, int nthreads);

/* Static partition of [0, n) among nthreads: thread t owns [lo, hi). */
static inline void pl_chunk(size_t n, int t, int nthreads, size_t *lo, size_t *hi)
{
    *lo = n * (size_t)t / (size_t)nthreads;
    *hi = n * (size_t)(t + 1) / (size_t)nthreads;
}

/* ---- collision + local thermostat (kernels/srd_collide.c) ------------- */
typedef struct {
    int rule;            /* PL_RULE_* */
    double cos_a, sin_a; /* rotation angle (random_axis rule) */
    uint64_t seed, step;
    double kT_target;    /* Heyes thermostat target kT* (pl_srd_collide_heyes); the bath kT of a
                          * collision rule that is itself a thermostat (peloid/collision_rule.h) */
    double heyes_eps;
    /* walls: virtual particles fill cells cut by a no-slip wall */
    int wall_ghosts;
    double ghost_density; /* gamma */
    double kT_wall;
    double wall_u[2][3];
    double *wall_dp;      /* NULL, or PL_WALL_ACC_N x nblocks: momentum the virtual
                           * particles gave the cells of block b (slots as wall_acc) */
    unsigned char *guard_bad; /* NULL, or one flag per block: 0 only when no particle of
                               * the block's cells has !(v^2 <= guard_vmax2) after the
                               * collision (the fluid guard's speed test, fused) */
    double guard_vmax2;
    const uint32_t *order; /* NULL: cell c is particles [cell_start[c], cell_start[c+1]); else slots
                            * of them, slot j being particle order[j] (pl_srd_sort_index; read by
                            * the SRD rules' kernel only) */
} pl_collide_params_t;

/* Fixed-order reductions are done over blocks of this many cells. */
enum { PL_CELL_BLOCK = 2048 };

/* Rotates relative velocities in every cell with >= 2 particles
 * (PL Eq. 3 / Hecht Eq. 12).  For each block b of PL_CELL_BLOCK cells,
 * block_sum[2b] receives sum m (v-u)^2 after the collision and
 * block_sum[2b+1] the degrees of freedom 3(M-1) (PL Eqs. A1-A2). */
void pl_srd_collide(pl_fluid_t *fluid, const pl_grid_t *grid, const uint32_t *cell_start,
                    const pl_collide_params_t *p, double *block_sum, int nthreads);
/* The same with the Heyes Monte Carlo cell thermostat (Hecht Sec. VIII.B,
 * Eq. 33) in every cell without virtual wall particles. */
void pl_srd_collide_heyes(pl_fluid_t *fluid, const pl_grid_t *grid, const uint32_t *cell_start,
                          const pl_collide_params_t *p, double *block_sum, int nthreads);

/* PL Appendix A: scale v - u in every cell with >= 2 particles by `factor`. */
void pl_srd_rescale(pl_fluid_t *fluid, const uint32_t *cell_start, size_t ncells, double factor, int nthreads);

/* ---- initial state, uniform velocity shift (kernels/srd_init.c) ------- */
typedef struct {
    uint64_t seed;  /* scene seed (PL_RNG_INIT_POS, PL_RNG_INIT_VEL) */
    double kT;      /* initial temperature */
    int uniform;    /* uniform velocities (Hecht Fig. 2), else Gaussian */
    double L[3];    /* box sides: positions uniform in [0, L) */
} pl_srd_init_params_t;

/* Positions and velocities from counter-based draws keyed by the particle
 * index, then the mean velocity removed and v scaled to exactly
 * kT = sum v^2 / (3 (N - 1)); tracked fluids get id = index and zero
 * displacements.  Independent of nthreads. */
void pl_srd_init(pl_fluid_t *fluid, const pl_srd_init_params_t *p, int nthreads);

/* v += du for every particle (a Galilean shift: drift removal, flow hold). */
void pl_srd_velocity_add(pl_fluid_t *fluid, const double du[3], int nthreads);

/* ---- observables (kernels/srd_observe.c) ------------------------------ */
typedef struct {
    double momentum[3]; /* sum m v */
    double kinetic;     /* sum m v^2 / 2 */
    double msd;         /* mean |disp|^2 (tracked fluids; else 0) */
} pl_fluid_obs_t;

/* Fixed-order (blocked) reductions: bitwise independent of nthreads.
 * scratch: pl_srd_observe_scratch(n) doubles. */
size_t pl_srd_observe_scratch(size_t n);
void pl_srd_observe(const pl_fluid_t *fluid, double *scratch, pl_fluid_obs_t *obs, int nthreads);

/* Accumulates density and momentum on the unshifted cell grid in 64-bit
 * fixed point (integer sums are order independent: deterministic for any
 * thread count).  acc: 4 x ncells_unshifted int64 (count, px, py, pz). */
enum { PL_FIELD_FIXED_SHIFT = 32 };
void pl_srd_fields_accumulate(const pl_fluid_t *fluid, const int L[3], int64_t *acc, int nthreads);

/* ---- momentum-flux sums (kernels/srd_stress.c) ------------------------ */
/* The fluid's sums the stress observer needs (src/observe/stress.c), m = 1:
 *   out[0..2]   sum v_a
 *   out[3..8]   sum v_a v_b       (xx, yy, zz, xy, xz, yz)
 *   out[9..17]  sum v_a rho_b     (index 9 + 3 a + b), rho the position
 *               relative to the centre of its collision cell under the grid
 *               shift s: rho = (x - s) - floor(x - s) - 1/2 on every axis
 *               (the cell rule of peloid/grid.h; periodic axes).
 * Collision: the change of the last block across a collision is the
 * collisional momentum flux (cells conserve momentum, so the cell centre is
 * the natural origin).  Fixed-order blocked reductions: bitwise independent
 * of nthreads.  scratch: pl_srd_stress_scratch(n) doubles. */
enum { PL_STRESS_NSUMS = 18 };
size_t pl_srd_stress_scratch(size_t n);
void pl_srd_stress_sums(const pl_fluid_t *fluid, const double shift[3], double *scratch,
                        double out[PL_STRESS_NSUMS], int nthreads);
/* Velocity profile across z: per layer k (floor(z), clipped to 0..nlayers-1)
 * sum_v[k] = sum of v . e over its particles and count[k] their number.
 * Fixed-order: bitwise independent of nthreads.  scratch:
 * pl_srd_layer_scratch(n, nlayers) doubles. */
size_t pl_srd_layer_scratch(size_t n, int nlayers);
void pl_srd_layer_velocity(const pl_fluid_t *fluid, int nlayers, const double e[3], double *scratch,
                           double *sum_v, double *count, int nthreads);

/* ---- fluid guard scan (kernels/srd_guard.c) --------------------------- */
/* Lowest index i with a position outside [0, L_d] on some axis d (NaN and
 * Inf included; only when `positions`) or |v_i|^2 > vmax2 (or not finite);
 * f->n when there is none.  Independent of nthreads. */
size_t pl_srd_guard_scan(const pl_fluid_t *f, const int L[3], double vmax2, int positions, int nthreads);
/* The speed test of pl_srd_guard_scan on particles [lo, hi) only, serial:
 * the lowest failing index, hi if none (a block flagged by the collision). */
size_t pl_srd_guard_scan_speeds(const pl_fluid_t *f, size_t lo, size_t hi, double vmax2);

/* A wall impulse accumulator slot that overflowed (sticky): the fluid guard
 * reports it (src/fluid/fluid_guard.c). */
#define PL_WALL_ACC_OVERFLOW INT64_MIN

/* Impulse dp (m_f = 1) a wall gave a particle, added in fixed point
 * (PL_FIELD_FIXED_SHIFT) to acc[3 slot + d] (slot: pl_wall_slot): integer
 * sums do not depend on the order, hence not on the thread count.  A sum
 * that would leave +-2^62 (or a non-finite dp) leaves the slot at
 * PL_WALL_ACC_OVERFLOW instead of wrapping. */
static inline void pl_wall_acc_add(int64_t *acc, int slot, const double dp[3])
{
    for (int d = 0; d < 3; ++d) {
        int64_t *a = &acc[3 * slot + d];
        const double q = ldexp(dp[d], PL_FIELD_FIXED_SHIFT);
        int64_t s;
        if (*a == PL_WALL_ACC_OVERFLOW) continue;
        if (!(fabs(q) < 0x1p62) || __builtin_add_overflow(*a, llround(q), &s) || s < -(INT64_C(1) << 62) ||
            s > (INT64_C(1) << 62))
            *a = PL_WALL_ACC_OVERFLOW;
        else
            *a = s;
    }
}

#endif
