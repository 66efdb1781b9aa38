/* Colloid-solvent coupling kernels (kernels/coupling_*.c): pure functions of
 * raw arrays, counts and small parameter structs; no scene, no I/O, no
 * allocation.  Fluid mass m_f = 1 (the mass unit).  nthreads is the size of
 * each parallel region (num_threads): no kernel relies on a process-wide
 * thread count. */
#ifndef PELOID_COUPLING_KERNELS_H
#define PELOID_COUPLING_KERNELS_H

#include <stddef.h>
#include <stdint.h>

#include "peloid/fluid.h"
#include "peloid/grid.h"
#include "peloid/kernel_enums.h" /* PL_WALLS_*, PL_RULE_*, PL_BOUND_*, PL_PLACE_* */
#include "peloid/srd_kernels.h"  /* pl_stream_params_t, PL_WALL_ACC_N */

/* Colloid arrays the coupling kernels read (length n). */
typedef struct {
    size_t n;
    const double *x, *y, *z, *vx, *vy, *vz, *wx, *wy, *wz, *rad, *mass, *inertia;
} pl_coupling_colloids_t;

/* Collision cell of a point under the grid's current shift: the same formula
 * as the fluid binning of kernels/srd_stream.c (inline: the scatters call it
 * per particle). */
static inline uint32_t pl_coupling_cell_of(const pl_grid_t *g, double x, double y, double z)
{
    const double r[3] = {x, y, z};
    int ic[3];
    for (int d = 0; d < 3; ++d) {
        if (g->walls[d] == PL_WALLS_NONE) {
            ic[d] = pl_grid_cell_periodic(r[d], g->shift[d], g->n[d]);
            continue;
        }
        ic[d] = pl_grid_cell_closed(r[d], g->shift[d]); /* clipped: a point just beyond a wall */
        if (ic[d] < 0) ic[d] = 0;
        if (ic[d] >= g->n[d]) ic[d] = g->n[d] - 1;
    }
    return (uint32_t)((ic[2] * g->n[1] + ic[1]) * g->n[0] + ic[0]);
}

/* ---- colloid lookup (kernels/coupling_lookup.c) ------------------------ */
/* Unshifted unit cells over the box (L0 x L1 x L2); start[ncells + 1] and
 * list[] (CSR) name, in index order, the colloids whose bounding cube touches
 * each cell.  Returns the number of list entries needed; fills start/list
 * only when that is <= cap (start is always filled). */
size_t pl_coupling_lookup_build(const pl_coupling_colloids_t *c, const int L[3], const int walls[3],
                                int32_t *start, int32_t *list, size_t cap);

/* Index of the first colloid (list order) that contains the point, or -1;
 * *p receives the vector point - centre (minimum image on periodic axes).
 * walls: PL_WALLS_* of each axis, as in pl_grid_t. */
int32_t pl_coupling_inside(const pl_coupling_colloids_t *c, const int L[3], const int walls[3],
                           const int32_t *start, const int32_t *list, const double r[3],
                           double p[3]);
/* The same from the colloids near the point's collision cell under g->shift
 * (cstart, clist of pl_coupling_cell_candidates with the radii of c): the
 * same colloid, since both lists hold every colloid that contains it. */
int32_t pl_coupling_inside_cells(const pl_coupling_colloids_t *c, const pl_grid_t *g, const uint32_t *cstart,
                                 const int32_t *clist, const double r[3], double p[3]);

/* Every fluid particle inside a colloid of c (lookup start/list built for
 * c) gets a new uniform position in the box of sides L, redrawn (up to 1000
 * draws of PL_RNG_FLUID_REPLACE keyed by (seed, particle index, draw)) until
 * it lies outside every colloid: the same for any thread count. */
void pl_coupling_clear_interiors(pl_fluid_t *f, const pl_coupling_colloids_t *c, const int L[3],
                                 const int walls[3], const int32_t *lk_start, const int32_t *lk_list,
                                 uint64_t seed, int nthreads);

/* ---- coupling I: reflection off colloid surfaces (coupling_reflect.c) -- */
typedef struct {
    double dt;        /* collision step (the streaming that just happened) */
    double kT;        /* temperature of the thermal surface, Hecht Eqs. 13-14 */
    int boundary;     /* PL_BOUND_* */
    int placement;    /* PL_PLACE_* */
    int max_refl;     /* N_max */
    uint64_t seed, step;
    double wall_u[2][3]; /* z wall velocities (bottom, top): a particle pushed through a
                          * no-slip wall (grid->walls) bounces back in the wall's frame */
    int64_t *wall_acc;   /* NULL, or the wall impulses (fixed point, PL_WALL_ACC_N slots) */
    int move;            /* the events move the colloids' end positions (0: pinned colloids) */
} pl_coupling1_params_t;

/* After stream+bin: every fluid particle found inside a colloid is moved out
 * and given a new velocity (Hecht Sec. IV), up to max_refl times; the colloid
 * velocities vel = {vx, vy, vz, wx, wy, wz} (the arrays c points to: each
 * event sees the velocity the ones before it left) receive the opposite
 * impulse and angular impulse, the events in the order of
 * coupling_reflect.c.  An event that changes a colloid's velocity by dv at
 * the time s before the end of the step moves the colloid's end position
 * by dv s (p->move; at most the margin cb->rad - c->rad); a particle is
 * inside when it is inside a colloid at its moved end position, so found
 * and cstart, clist come from cb: the positions the MD left, radii
 * enlarged by the margin.  sc->disp returns the displacements (3 x c->n,
 * x then y then z) for the caller to add to the colloid positions.  The
 * particle's cell index and the histogram row of the thread that streamed
 * it (static chunks pl_chunk, as in the streaming) are updated, so the
 * counting sort that follows stays consistent.  found, counts: the
 * particles found inside cb (pl_coupling_find_binned or
 * pl_coupling_find_block); counts[0] events (reflections), counts[1]
 * truncations (still inside after max_refl). */
typedef struct {
    size_t cap;       /* events that key, idx, owner, k, next, taken, done, state hold */
    size_t vcap;      /* doubles of vsave (6 x colloids) */
    uint64_t *key;    /* 2 x cap: the sort key and particle; cap each: the particle, its streaming thread, */
    uint32_t *idx;    /* its colloid in cb, whether it is done, and */
    int32_t *owner;
    int32_t *k;
    int64_t *next;    /* the next event of the same colloid k, -1 at the end */
    uint8_t *taken;   /* chosen by the colloid's event order (pass 0) */
    uint16_t *done;   /* reflections so far */
    double *state;    /* 7 x cap: its r, v and cell before them */
    double *vsave;    /* vcap: the colloid velocities before the events */
    double *pos, *disp; /* vcap / 2 each: the colloids' moved end positions and displacements */
    int64_t *head;    /* vcap / 6 + 1: each colloid's first event (scratch of the chains) */
    int64_t *cbeg;    /* vcap / 6 + 1: where each colloid's chain lies in chain and cq */
    double *chain;    /* 7 x cap: the chains' untaken particles' r, v and meet times, by colloid */
    int64_t *cq;      /* cap: their events, in chain order */
    unsigned long long parallel, gave_up; /* steps done in parallel; given up (a second colloid) */
} pl_coupling1_scratch_t;

/* The number of particles the detection found (counts of
 * pl_coupling_find_binned): sc must hold that many events and 6 values per
 * colloid.  With more than one thread, two or more colloids, no walls and
 * no displacement tracking the events run in parallel over blocks of
 * colloids; the result is the same bits either way. */
size_t pl_coupling1_found(const uint64_t *counts, int nthreads);
void pl_coupling1_reflect(pl_fluid_t *f, const pl_grid_t *g, const pl_coupling1_params_t *p,
                          const pl_coupling_colloids_t *c, const pl_coupling_colloids_t *cb, double *const vel[6],
                          const uint32_t *cstart, const int32_t *clist, uint32_t *hist, int nthreads,
                          const uint32_t *found, uint64_t *counts, pl_coupling1_scratch_t *sc);

/* ---- coupling II: colloids in the collision (coupling_collide.c) ------- */
typedef struct {
    int rule;            /* PL_RULE_* */
    double cos_a, sin_a; /* random_axis rotation angle */
    uint64_t seed, step;
    double kT_target, heyes_eps; /* pl_coupling2_collide_heyes (Hecht Sec. VIII.B) */
    /* virtual wall particles, as in the fluid collision (pl_collide_params_t) */
    int wall_ghosts;
    double ghost_density, kT_wall, wall_u[2][3];
    double *wall_fix;    /* NULL, or PL_WALL_ACC_N per occupied cell: the
                          * correction to the wall impulse the fluid kernel counted */
} pl_coupling2_params_t;

/* Cells holding colloids: occ_cell[j] (j < nocc) with the colloids
 * col_idx[occ_col[j] .. occ_col[j+1]) and the fluid particles
 * cell_start[c] .. cell_start[c+1] whose velocities were saved at
 * vsave[3 * (occ_save[j] + i) + d]. */
typedef struct {
    size_t nocc;
    const uint32_t *occ_cell;
    const size_t *occ_save;
    const int32_t *occ_col, *col_idx;
} pl_coupling2_cells_t;

/* Copies the pre-collision velocities of the fluid in the occupied cells. */
void pl_coupling2_save(const pl_fluid_t *f, const uint32_t *cell_start,
                       const pl_coupling2_cells_t *oc, double *vsave, int nthreads);

/* Redoes the collision of every occupied cell from the saved fluid
 * velocities and the colloid velocities with the mass-weighted mean velocity
 * (Hecht Eq. 15) and writes both (the fluid kernel's result for these cells
 * is overwritten).  One rotation per cell from its own random stream. */
void pl_coupling2_collide(const pl_coupling2_params_t *p, const pl_coupling2_cells_t *oc, const pl_grid_t *g,
                          const uint32_t *cell_start, const double *vsave, pl_fluid_t *f,
                          const double *cmass, double *cvx, double *cvy, double *cvz, int nthreads);
/* The same with the mass-weighted Heyes thermostat in cells without
 * virtual wall particles. */
void pl_coupling2_collide_heyes(const pl_coupling2_params_t *p, const pl_coupling2_cells_t *oc, const pl_grid_t *g,
                          const uint32_t *cell_start, const double *vsave, pl_fluid_t *f,
                          const double *cmass, double *cvx, double *cvy, double *cvz, int nthreads);

/* ---- potential coupling: the selection (kernels/coupling_select.c) ---- */
/* How far a fluid particle can get from where it is within one collision
 * step: T |v| + tail (T the step, tail >= T^2 |g| + 2 T |wall speed|: the
 * streaming's kick and the walls' bounce-back), so it can come within rc of
 * a colloid that moves less than `budget` only if it is within rc + budget
 * + tail + T |v| of it now. */
typedef struct {
    double rc, budget, tail, T;
} pl_coupling_reach_t;

/* Lists in found[lo .. lo + counts[t * 8 + 2]) the particles of thread t's
 * static chunk (as in the streaming) that lie inside a colloid of c (whose
 * rad may be enlarged radii) and, unless reach is NULL, also within their
 * reach of it (rc + budget + tail + T |v|), with (found_cell, unless NULL)
 * the lookup cell whose list was tested; counts[t * 8 + 3]: the number of
 * (particle, colloid) pairs of the listed particles (every colloid of c
 * whose sphere holds the particle).  Parallel, no atomics. */
void pl_coupling_find(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling_colloids_t *c,
                      const pl_coupling_reach_t *reach, const int32_t *lk_start, const int32_t *lk_list,
                      int nthreads, uint32_t *found, uint32_t *found_cell, uint64_t *counts);
/* CSR lists (cstart[0 .. ncells], clist), in index order, of the colloids
 * whose sphere (radius c->rad + 1e-6 a0) can reach each collision cell
 * under g->shift.  cstart: g->ncells + 2 entries, axis_buf: nthreads x
 * (n[0] + n[1] + n[2]) ints, gap_buf as many doubles (scratch).  Returns
 * the number of list entries needed; fills clist only when that is <= cap.
 * Parallel over slabs of z planes: the same lists for any thread count. */
size_t pl_coupling_cell_candidates(const pl_grid_t *g, const pl_coupling_colloids_t *c, int *axis_buf,
                                   double *gap_buf, uint32_t *cstart, int32_t *clist, size_t cap, int nthreads);
/* The same list (and pair counts) from the particles of the collision cells
 * with candidates, when the fluid is still as the last sort left it: sorted
 * by collision cell under g->shift, cell c holding [cell_start[c],
 * cell_start[c + 1]); each particle tested against its cell's candidates
 * (found_cell: that cell, or an earlier one of the same run of cells with
 * the same candidates: the same list).  Cost ~ the particles near colloids
 * plus one offset per cell, instead of every particle. */
void pl_coupling_find_sorted(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling_colloids_t *c,
                             const pl_coupling_reach_t *reach, const uint32_t *cstart, const int32_t *clist,
                             const uint32_t *cell_start, int nthreads, uint32_t *found, uint32_t *found_cell,
                             uint64_t *counts);

/* The state before the streaming of the particles a thread listed
 * (pl_coupling_select_block), in list order: per particle `width` doubles,
 * r[3], v[3] and, for a tracked fluid (width 9), disp[3]; room for cap
 * particles. */
typedef struct {
    double *buf;
    size_t cap;
    int width;
} pl_coupling_stage_t;

/* pl_coupling_find_sorted from inside the streaming (a pl_stream_hook_fn
 * for pl_stream_params_t.pre_hook, ctx a pl_coupling_select_ctx_t): each
 * block of thread t's chunk, read by the streaming and not yet stored (in
 * L1), is tested as pl_coupling_find_sorted tests it, the selected
 * particles appended to found and found_cell from the chunk's start and
 * their state before the streaming to stage[t].  counts[t * 8 + 2 .. 5]
 * must be 0 before the streaming; after it, [2] and [3] hold what
 * pl_coupling_find_sorted leaves there (the same lists), [5] the particles
 * stage[t] had no room for (none when its cap is the chunk's size). */
typedef struct {
    const pl_fluid_t *f;
    const pl_grid_t *g; /* only L, walls and ncells are read: the streaming draws the shift */
    pl_coupling_colloids_t c;
    pl_coupling_reach_t reach;
    const uint32_t *cstart;
    const int32_t *clist;
    const uint32_t *cell_start;
    int nthreads;
    uint32_t *found, *found_cell;
    uint64_t *counts;
    pl_coupling_stage_t *stage; /* nthreads */
} pl_coupling_select_ctx_t;
void pl_coupling_select_block(void *ctx, int t, size_t lo, size_t hi);

/* The list of pl_coupling_find from the cells the binning left in f->cell
 * (under g->shift, after the streaming): the particles of the cells with
 * candidates (cstart, clist of pl_coupling_cell_candidates), then each
 * tested against its cell's.  Reads 4 B per particle where the full scan
 * reads the positions and finds their unit cells. */
void pl_coupling_find_binned(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling_colloids_t *c,
                             const uint32_t *cstart, const int32_t *clist, int nthreads, uint32_t *found,
                             uint64_t *counts);

/* The same list from inside the streaming (a pl_stream_hook_fn, ctx a
 * pl_coupling_find_ctx_t): each block of particles just streamed and binned,
 * still in L1, filtered and tested as pl_coupling_find_binned does, appended
 * to its thread's part of found; counts[t * 8 + 2], [t * 8 + 3] must be 0
 * before the streaming and hold what pl_coupling_find_binned leaves there
 * after it (the blocks of a chunk come in particle order). */
typedef struct {
    const pl_fluid_t *f;
    const pl_grid_t *g;
    pl_coupling_colloids_t c;
    const uint32_t *cstart;
    const int32_t *clist;
    const uint64_t *mask; /* pl_coupling_cell_mask of cstart */
    int nthreads;
    uint32_t *found;
    uint64_t *counts;
} pl_coupling_find_ctx_t;
void pl_coupling_find_block(void *ctx, int t, size_t lo, size_t hi);
/* Bit c % 64 of mask[c / 64]: cell c has candidates (cstart[c + 1] !=
 * cstart[c]); mask: (ncells + 63) / 64 words. */
void pl_coupling_cell_mask(const uint32_t *cstart, size_t ncells, uint64_t *mask);

/* ---- potential coupling: the WCA forces (kernels/coupling_wca.c) ------ */
typedef struct {
    double sigma, eps; /* PL Eq. 17 */
    int L[3], walls[3]; /* walls: PL_WALLS_* of each axis */
} pl_coupling_wca_t;

/* PL Eq. 17 forces between nn fluid particles (x, y, z) and the colloids
 * (positions in c; candidates from the lookup built with radii >= the
 * cut-off 2^{1/6} sigma): f overwritten, cf accumulated (+= the reaction).
 * Parallel over pl_coupling_wca_blocks(nn, c->n) fixed blocks, each with a
 * row of 3 c->n + 1 doubles in `partial` (scratch), added in block order:
 * the same bits for any thread count.  Returns the potential energy. */
size_t pl_coupling_wca_blocks(size_t nn, size_t ncolloids);
double pl_coupling_wca_forces(const pl_coupling_wca_t *w, size_t nn, const double *x, const double *y,
                              const double *z, double *fx, double *fy, double *fz,
                              const pl_coupling_colloids_t *c, const int32_t *lk_start,
                              const int32_t *lk_list, double *cfx, double *cfy, double *cfz,
                              int nthreads, double *partial);

/* The particles selected for the MD step (n of them), in particle order:
 * fluid index, the thread whose streaming chunk (pl_chunk) and histogram
 * row hold it (ascending), double copies of position, velocity, force and
 * displacement (disp[*] NULL: not kept, for a fluid that does not track
 * it) that the MD step integrates, the position at the selection
 * (r0); and their pairs: particle j's candidate colloids (those whose
 * selection sphere held it, in index order) are k0[j], then pk[pstart[j]
 * .. pstart[j + 1]), pj the particle of each of these further pairs. */
typedef struct {
    size_t n;
    uint32_t *idx;
    int32_t *owner;
    double *r[3], *v[3], *f[3], *disp[3], *r0[3];
    int32_t *k0;
    uint32_t *pstart, *pj;
    int32_t *pk;
} pl_coupling_near_t;

/* PL Eq. 17 forces as pl_coupling_wca_forces, over the pairs of nb instead
 * of a lookup: the same bits wherever every pair within the cut-off is one
 * of them (the caller checks that the particles and colloids have moved
 * less than the selection margin together).  pair_buf: 4 x pair_cap doubles
 * (scratch; pair_cap >= all the pairs). */
double pl_coupling_wca_pair_forces(const pl_coupling_wca_t *w, const pl_coupling_near_t *nb,
                                   const pl_coupling_colloids_t *c, double *cfx, double *cfy, double *cfz,
                                   int nthreads, double *partial, double *pair_buf, size_t pair_cap);

/* ---- potential coupling: the MD step (kernels/coupling_potential.c) --- */
/* One force evaluation of the MD step fused with the particle moves around
 * it: pl_coupling_wca_pair_forces, then per particle `kicks` half kicks
 * (pl_coupling_potential_kick: 1 at the last MD step, 2 when the next one
 * follows) and, for dt > 0, the drift (pl_coupling_potential_drift, its
 * largest |r - r0|^2 in *far2, else 0).  The same bits as the separate
 * kernels: each particle's operations in the same order; the particles
 * and colloids meet only through the forces. */
double pl_coupling_potential_force_step(const pl_coupling_wca_t *w, const pl_coupling_near_t *nb,
                                        const pl_coupling_colloids_t *c, const pl_grid_t *g,
                                        const double wall_u[2][3], double h, const double ga[3], int kicks,
                                        double dt, double *cfx, double *cfy, double *cfz, int nthreads,
                                        double *partial, double *pair_buf, size_t pair_cap,
                                        int64_t acc[PL_WALL_ACC_N], double *far2);

/* Fills nb (nb->n = the sum of counts[t * 8 + 2]) from the lists of
 * pl_coupling_find(_sorted) or pl_coupling_select_block: idx, owner, r, r0,
 * v, disp (0 when the fluid is not tracked) from f, or from stage (NULL:
 * from f) when the selection ran inside the streaming, and the pairs,
 * tested again against the candidates of the particle's found_cell in
 * (cstart, clist) (the lists the selection used); f is not touched. */
void pl_coupling_potential_gather(const pl_fluid_t *f, const pl_grid_t *g, const pl_coupling_colloids_t *c,
                                  const uint32_t *found, const uint32_t *found_cell, const uint64_t *counts,
                                  const uint32_t *cstart, const int32_t *clist,
                                  const pl_coupling_stage_t *stage, int nthreads, const pl_coupling_near_t *nb);
/* Takes back the free streaming of the selected particles (nb holding
 * their state before it): the saved displacements into f (tracked fluids),
 * and, when sp is not NULL, adds to acc the wall impulses the streaming
 * with sp counted for them (pl_srd_stream_wall_impulse, fixed point). */
void pl_coupling_potential_unstream(const pl_coupling_near_t *nb, pl_fluid_t *f, const pl_grid_t *g,
                                    const pl_stream_params_t *sp, int nthreads, int64_t acc[PL_WALL_ACC_N]);
/* Velocity Verlet half kick v += h (f + g) (PL Eq. 19, m_f = 1). */
void pl_coupling_potential_kick(const pl_coupling_near_t *nb, double h, const double g[3], int nthreads);
/* Drift r += v dt (PL Eq. 18), the displacement accumulated, with
 * reflection at the walls of every closed axis of g as the streaming does
 * (bounce-back in the frame of the wall for no-slip, the z walls moving
 * with wall_u (bottom, top) and the x/y walls at rest; specular for slip);
 * the walls' impulses added to acc (fixed point, PL_WALL_ACC_N slots).
 * Returns the largest |r - r0|^2. */
double pl_coupling_potential_drift(const pl_coupling_near_t *nb, const pl_grid_t *g, const double wall_u[2][3],
                                   double dt, int nthreads, int64_t acc[PL_WALL_ACC_N]);
/* Writes the selected particles back into f, wrapped on periodic axes,
 * with their new collision cell (under g->shift), moving each from its old
 * to its new cell in its owner's row of hist (nthreads x g->ncells). */
void pl_coupling_potential_scatter(const pl_coupling_near_t *nb, pl_fluid_t *f, const pl_grid_t *g,
                                   uint32_t *hist, int nthreads);

#endif
