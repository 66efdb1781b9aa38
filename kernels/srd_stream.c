/* Streaming fused with cell binning (one pass over the particle arrays), and
 * the count-only pass of the stream-in-scatter step.  With z walls the
 * streaming also sums the impulse of their bounces (the wall stress).
 *
 * The drift itself (Hecht Eq. 11 / PL Eqs. 1-2, walls, grid shift) is
 * pl_drift_one in srd_drift.h.  The cell of each particle is counted in the
 * owning thread's histogram row (no atomics; STYLE.md 6).  An optional hook
 * (pl_stream_params_t.hook) sees each block right after it was stored:
 * coupling I finds the particles inside colloids there, while the block is
 * in L1, instead of in a pass of its own.  A pre-hook sees each block after
 * it was read and before it is stored: the potential coupling selects its
 * particles there from the state before the streaming. */
#include <omp.h>
#include <string.h>

#include "omp_parts.h"
#include "srd_drift.h"

/* The cells thread t may count into (pl_fluid_bands_t): its band of its row. */
typedef struct {
    uint32_t lo, len, ncells;
} band_t;

/* Drift + store + bin of particles [lo, hi) one by one (walls, tracking);
 * wall_acc: NULL, or this thread's wall impulses (PL_WALL_ACC_N slots). */
static inline __attribute__((always_inline)) uint32_t moved_range(pl_fluid_t *f, const pl_drift_t *c,
                                                                  const int closed[3], uint32_t *restrict h,
                                                                  size_t lo, size_t hi, int tracked,
                                                                  int64_t *wall_acc, const band_t *b)
{
    uint32_t out = 0;
    pl_real *restrict x = f->r[0], *restrict y = f->r[1], *restrict z = f->r[2];
    pl_real *restrict vx = f->v[0], *restrict vy = f->v[1], *restrict vz = f->v[2];
    uint32_t *restrict cell = f->cell;
    for (size_t i = lo; i < hi; ++i) {
        double r[3] = {x[i], y[i], z[i]}, v[3] = {vx[i], vy[i], vz[i]}, dr[3];
        const uint32_t cl = pl_drift_one_closed(c, closed, r, v, dr, wall_acc);
        if (tracked) {
            f->disp[0][i] += dr[0];
            f->disp[1][i] += dr[1];
            f->disp[2][i] += dr[2];
        }
        x[i] = (pl_real)r[0]; y[i] = (pl_real)r[1]; z[i] = (pl_real)r[2];
        vx[i] = (pl_real)v[0]; vy[i] = (pl_real)v[1]; vz[i] = (pl_real)v[2];
        cell[i] = cl;
        h[cl]++;
        out |= pl_fluid_band_out(cl, b->lo, b->len, b->ncells);
    }
    return out;
}

/* Whether a and b have the same bits (-0.0 and +0.0 differ). */
static inline int same_bits(pl_real a, pl_real b) { return !memcmp(&a, &b, sizeof a); }

/* The periodic box without tracking, in blocks: drift, store, bin.
 * kick_free (a literal at each call): store a velocity only where its bits
 * changed (see the caller). */
static inline __attribute__((always_inline)) uint32_t periodic_blocks(
    const pl_drift_t *c, pl_real *restrict x, pl_real *restrict y, pl_real *restrict z,
    pl_real *restrict vx, pl_real *restrict vy, pl_real *restrict vz, uint32_t *restrict cell,
    uint32_t *restrict h, size_t lo, size_t hi, const int kick_free, const pl_stream_params_t *p, int t,
    const band_t *b, const int check)
{
    uint32_t out = 0;
    const pl_stream_hook_fn hook = p->hook, pre_hook = p->pre_hook;
    double rb[3][PL_DRIFT_BLOCK], vb[3][PL_DRIFT_BLOCK];
    uint32_t cb[PL_DRIFT_BLOCK];
    pl_real *const v[3] = {vx, vy, vz};
    for (size_t i = lo; i < hi; i += PL_DRIFT_BLOCK) {
        const size_t m = hi - i < PL_DRIFT_BLOCK ? hi - i : PL_DRIFT_BLOCK;
        pl_drift_block_periodic(c, x + i, y + i, z + i, vx + i, vy + i, vz + i, m, rb, vb, cb);
        if (pre_hook) pre_hook(p->pre_hook_ctx, t, i, i + m); /* the block as it was, still in L1 */
        for (size_t k = 0; k < m; ++k) {
            x[i + k] = (pl_real)rb[0][k]; y[i + k] = (pl_real)rb[1][k]; z[i + k] = (pl_real)rb[2][k];
            for (int d = 0; d < 3; ++d)
                if (!kick_free || !same_bits((pl_real)vb[d][k], v[d][i + k])) v[d][i + k] = (pl_real)vb[d][k];
            cell[i + k] = cb[k];
            h[cb[k]]++;
            if (check) out |= pl_fluid_band_out(cb[k], b->lo, b->len, b->ncells);
        }
        if (hook) hook(p->hook_ctx, t, i, i + m); /* the block still in L1 */
    }
    return out;
}

/* mode: 0 = bin only, 1 = drift + store + bin, 2 = count the drifted cell
 * without storing anything but the histogram. */
static uint32_t stream_range(pl_fluid_t *f, const pl_drift_t *c, uint32_t *restrict h, size_t lo,
                             size_t hi, int mode, int64_t *wall_acc, const pl_stream_params_t *p, int t,
                             const band_t *b)
{
    uint32_t out = 0;
    pl_real *restrict x = f->r[0], *restrict y = f->r[1], *restrict z = f->r[2];
    pl_real *restrict vx = f->v[0], *restrict vy = f->v[1], *restrict vz = f->v[2];
    uint32_t *restrict cell = f->cell;
    if (mode == 2 && !c->walls) {
        double rb[3][PL_DRIFT_BLOCK], vb[3][PL_DRIFT_BLOCK];
        uint32_t cb[PL_DRIFT_BLOCK];
        for (size_t i = lo; i < hi; i += PL_DRIFT_BLOCK) {
            const size_t m = hi - i < PL_DRIFT_BLOCK ? hi - i : PL_DRIFT_BLOCK;
            pl_drift_block_periodic(c, x + i, y + i, z + i, vx + i, vy + i, vz + i, m, rb, vb, cb);
            for (size_t k = 0; k < m; ++k) {
                h[cb[k]]++;
                out |= pl_fluid_band_out(cb[k], b->lo, b->len, b->ncells);
            }
        }
        return out;
    }
    if (mode == 2) {
        for (size_t i = lo; i < hi; ++i) {
            double r[3] = {x[i], y[i], z[i]}, v[3] = {vx[i], vy[i], vz[i]}, dr[3];
            const uint32_t cl = pl_drift_one(c, r, v, dr, NULL);
            h[cl]++;
            out |= pl_fluid_band_out(cl, b->lo, b->len, b->ncells);
        }
        return out;
    }
    const int tracked = f->tracked && mode == 1;
    pl_stream_params_t hooks = *p; /* the hooks run only where the particles are stored */
    if (mode != 1) hooks.hook = hooks.pre_hook = NULL;
    if (!tracked && !c->walls) {
        /* No body force: the kick v + 0 leaves every velocity as it is
         * except -0.0 (which becomes +0.0), so v is stored only where its
         * bits change: the velocity arrays are read, not written back
         * (24 B per particle less, and no dirty lines to write back). */
        /* the band test only where the band is not the whole row (kick_free
         * and check as literals: four specialisations) */
        const int kf = c->a[0] == 0.0 && c->a[1] == 0.0 && c->a[2] == 0.0, ck = b->len < b->ncells;
        if (kf && ck) return periodic_blocks(c, x, y, z, vx, vy, vz, cell, h, lo, hi, 1, &hooks, t, b, 1);
        if (kf) return periodic_blocks(c, x, y, z, vx, vy, vz, cell, h, lo, hi, 1, &hooks, t, b, 0);
        if (ck) return periodic_blocks(c, x, y, z, vx, vy, vz, cell, h, lo, hi, 0, &hooks, t, b, 1);
        return periodic_blocks(c, x, y, z, vx, vy, vz, cell, h, lo, hi, 0, &hooks, t, b, 0);
    }
    /* the common wall layouts with their closed axes as constants */
    const int *w = c->wall;
    /* with a pre-hook, in blocks: each block seen before it is stored */
    const size_t step = hooks.pre_hook ? PL_DRIFT_BLOCK : (hi > lo ? hi - lo : 1);
    for (size_t i = lo; i < hi; i += step) {
        const size_t e = hi - i < step ? hi : i + step;
        if (hooks.pre_hook) hooks.pre_hook(hooks.pre_hook_ctx, t, i, e);
        if (!w[0] && !w[1] && w[2]) out |= moved_range(f, c, (const int[3]){0, 0, 1}, h, i, e, tracked, wall_acc, b);
        else if (w[0] && w[1] && !w[2]) out |= moved_range(f, c, (const int[3]){1, 1, 0}, h, i, e, tracked, wall_acc, b);
        else out |= moved_range(f, c, w, h, i, e, tracked, wall_acc, b);
    }
    if (hooks.hook) hooks.hook(hooks.hook_ctx, t, lo, hi);
    return out;
}

static void run(pl_fluid_t *f, const pl_grid_t *g, const pl_stream_params_t *p, uint32_t *hist,
                int nthreads, int mode)
{
    pl_drift_t c;
    pl_drift_init(&c, g, p, mode != 0);
    /* the grid's planes, for the bands the sort sets for the next step */
    f->bands.plane = (uint32_t)g->n[0] * (uint32_t)g->n[1];
    f->bands.nz = (uint32_t)g->n[2];
    f->bands.z_periodic = g->walls[2] == PL_WALLS_NONE;
    /* One parallel region; thread t owns the static chunk pl_chunk(t) here and
     * in the scatter of the sort, so its histogram row matches its chunk.  It
     * zeroes and counts only its band of the row (pl_fluid_bands_t).  Part t
     * rather than thread t where the team is smaller (omp_parts.h). */
#pragma omp parallel num_threads(nthreads)
    PL_FOR_PART(t, nthreads) {
        size_t lo, hi;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        uint32_t *h = hist + (size_t)t * g->ncells;
        band_t b = {0, 0, (uint32_t)g->ncells};
        pl_fluid_band(f, t, nthreads, b.ncells, &b.lo, &b.len);
        const size_t first = b.lo + b.len < b.ncells ? b.len : b.ncells - b.lo;
        memset(h + b.lo, 0, first * sizeof *h);
        memset(h, 0, (b.len - first) * sizeof *h); /* the part wrapped to plane 0 */
        /* the wall impulses of this thread's chunk, in its own cache line */
        int64_t *acc = mode == 1 && c.walls && p->wall_acc ? p->wall_acc + (size_t)t * PL_WALL_ACC_STRIDE : NULL;
        if (acc) memset(acc, 0, PL_WALL_ACC_STRIDE * sizeof *acc);
        if (stream_range(f, &c, h, lo, hi, mode, acc, p, t, &b)) pl_fluid_band_overflow(f);
    }
}

void pl_srd_stream_bin(pl_fluid_t *f, const pl_grid_t *g, const pl_stream_params_t *p,
                       uint32_t *hist, int nthreads)
{
    run(f, g, p, hist, nthreads, 1);
}

void pl_srd_stream_count(pl_fluid_t *f, const pl_grid_t *g, const pl_stream_params_t *p,
                         uint32_t *hist, int nthreads)
{
    run(f, g, p, hist, nthreads, 2); /* mode 2 writes no particle state, only f->bands */
}

void pl_srd_stream_wall_impulse(const pl_grid_t *g, const pl_stream_params_t *p, const double r0[3],
                                const double v0[3], int64_t acc[PL_WALL_ACC_N])
{
    pl_drift_t c;
    pl_drift_init(&c, g, p, 1);
    if (!c.walls) return;
    /* the first steps of pl_drift_one_closed: no wall crossed, no impulse */
    int out = 0;
    for (int d = 0; d < 3; ++d) {
        const double x = r0[d] + (v0[d] + c.a[d]) * c.dt;
        out |= c.wall[d] && (x < 0.0 || x > c.L[d]);
    }
    if (!out) return;
    double r[3] = {r0[0], r0[1], r0[2]}, v[3] = {v0[0], v0[1], v0[2]}, dr[3];
    (void)pl_drift_one(&c, r, v, dr, acc);
}

int pl_srd_wall_bounce(const pl_grid_t *g, const double wall_u[2][3], double dt, const double r0[3],
                       double r[3], double v[3], int64_t acc[PL_WALL_ACC_N])
{
    pl_drift_t c;
    memset(&c, 0, sizeof c);
    c.dt = dt;
    for (int d = 0; d < 3; ++d) {
        c.L[d] = g->L[d];
        c.wall[d] = g->walls[d];
    }
    c.walls = g->any_walls;
    memcpy(c.wall_u, wall_u, sizeof c.wall_u);
    if (!c.walls || !pl_drift_outside(&c, r)) return 0;
    pl_drift_reflect(&c, r, v, r0, acc);
    return 1;
}

void pl_srd_bin(pl_fluid_t *f, const pl_grid_t *g, uint32_t *hist, int nthreads)
{
    pl_stream_params_t none;
    memset(&none, 0, sizeof none);
    run(f, g, &none, hist, nthreads, 0);
}
