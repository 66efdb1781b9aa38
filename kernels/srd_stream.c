/* Streaming fused with cell binning (one pass over the particle arrays).
 *
 * Hecht Eq. 11 / PL Eqs. 1-2: r += v dt, after a velocity kick v += g dt for a
 * constant body force.  Periodic wrap, or reflection at planar walls z = 0
 * and z = Lz: bounce-back (no-slip, v -> 2U - v in the frame of a wall moving
 * with U) or specular (slip, v_z -> -v_z).  The collision cell under the
 * current grid shift (Hecht Sec. III) is computed in the same pass and counted
 * in the owning thread's histogram row (no atomics; STYLE.md 6). */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "peloid/scene.h"
#include "peloid/srd_kernels.h"

static inline double wrap(double x, double L, double invL)
{
    x -= L * floor(x * invL);
    return x >= L ? 0.0 : x; /* x slightly below 0 can round up to L */
}

static inline int cell_1d(double x, double s, int n)
{
    int i = (int)floor(x - s);
    if (i < 0) i += n;
    else if (i >= n) i -= n;
    return i;
}

/* Reflects one particle at the walls after a drift of dt from (r0, v).  Walls
 * are at z = 0 (index 0) and z = Lz (index 1). */
static inline void reflect_z(double r[3], double v[3], const double r0[3], double dt, double Lz,
                             int noslip, const double wall_u[2][3])
{
    double t_left = dt;
    double p[3] = {r0[0], r0[1], r0[2]};
    for (int bounce = 0; bounce < 8 && (r[2] < 0.0 || r[2] > Lz); ++bounce) {
        int top = r[2] > Lz;
        double zw = top ? Lz : 0.0;
        double tc = (zw - p[2]) / v[2]; /* time to reach the wall */
        if (!(tc >= 0.0)) tc = 0.0;
        if (tc > t_left) tc = t_left;
        for (int d = 0; d < 3; ++d) p[d] += v[d] * tc;
        p[2] = zw;
        t_left -= tc;
        if (noslip) {
            for (int d = 0; d < 3; ++d) v[d] = 2.0 * wall_u[top][d] - v[d];
        } else {
            v[2] = -v[2];
        }
        for (int d = 0; d < 3; ++d) r[d] = p[d] + v[d] * t_left;
    }
    if (r[2] < 0.0) r[2] = 0.0;     /* pathological velocities only */
    if (r[2] > Lz) r[2] = Lz;
}

static void stream_range(pl_fluid_t *f, const pl_grid_t *g, const pl_stream_params_t *p,
                         uint32_t *restrict h, size_t lo, size_t hi, int move)
{
    pl_real *restrict x = f->r[0], *restrict y = f->r[1], *restrict z = f->r[2];
    pl_real *restrict vx = f->v[0], *restrict vy = f->v[1], *restrict vz = f->v[2];
    uint32_t *restrict cell = f->cell;
    const double dt = move ? p->dt : 0.0;
    const double ax = move ? p->accel[0] * p->dt : 0.0, ay = move ? p->accel[1] * p->dt : 0.0,
                 az = move ? p->accel[2] * p->dt : 0.0;
    const double Lx = g->L[0], Ly = g->L[1], Lz = g->L[2];
    const double iLx = 1.0 / Lx, iLy = 1.0 / Ly, iLz = 1.0 / Lz;
    const double sx = g->shift[0], sy = g->shift[1], sz = g->shift[2];
    const int nx = g->n[0], ny = g->n[1], nz = g->n[2];
    const int walls = g->walls_z != PL_WALLS_NONE, noslip = g->walls_z == PL_WALLS_NOSLIP;
    const int tracked = f->tracked && move;
    for (size_t i = lo; i < hi; ++i) {
        double v[3] = {vx[i] + ax, vy[i] + ay, vz[i] + az};
        double r0[3] = {x[i], y[i], z[i]};
        double r[3] = {r0[0] + v[0] * dt, r0[1] + v[1] * dt, r0[2] + v[2] * dt};
        if (walls && (r[2] < 0.0 || r[2] > Lz)) reflect_z(r, v, r0, dt, Lz, noslip, p->wall_u);
        if (tracked) {
            f->disp[0][i] += r[0] - r0[0];
            f->disp[1][i] += r[1] - r0[1];
            f->disp[2][i] += r[2] - r0[2];
        }
        r[0] = wrap(r[0], Lx, iLx);
        r[1] = wrap(r[1], Ly, iLy);
        int iz;
        if (walls) {
            iz = (int)floor(r[2] - sz) + 1; /* layers 0 .. Lz+1 */
        } else {
            r[2] = wrap(r[2], Lz, iLz);
            iz = cell_1d(r[2], sz, nz);
        }
#ifdef PL_SINGLE
        /* the stored (rounded) position is the one binned */
        r[0] = (pl_real)r[0] >= (pl_real)Lx ? 0.0 : (double)(pl_real)r[0];
        r[1] = (pl_real)r[1] >= (pl_real)Ly ? 0.0 : (double)(pl_real)r[1];
        if (!walls) r[2] = (pl_real)r[2] >= (pl_real)Lz ? 0.0 : (double)(pl_real)r[2];
        if (walls) iz = (int)floor((double)(pl_real)r[2] - sz) + 1;
#endif
        x[i] = (pl_real)r[0]; y[i] = (pl_real)r[1]; z[i] = (pl_real)r[2];
        vx[i] = (pl_real)v[0]; vy[i] = (pl_real)v[1]; vz[i] = (pl_real)v[2];
        uint32_t c = (uint32_t)((iz * ny + cell_1d(r[1], sy, ny)) * nx + cell_1d(r[0], sx, nx));
        cell[i] = c;
        h[c]++;
    }
}

static void run(pl_fluid_t *f, const pl_grid_t *g, const pl_stream_params_t *p, uint32_t *hist,
                int nthreads, int move)
{
    /* One parallel region; thread t owns the static chunk pl_chunk(t) here and
     * in the scatter of the sort, so its histogram row matches its chunk. */
#pragma omp parallel num_threads(nthreads)
    {
        int t = omp_get_thread_num();
        size_t lo, hi;
        pl_chunk(f->n, t, nthreads, &lo, &hi);
        uint32_t *h = hist + (size_t)t * g->ncells;
        memset(h, 0, g->ncells * sizeof *h);
        stream_range(f, g, p, h, lo, hi, move);
    }
}

void pl_srd_stream_bin(pl_fluid_t *f, const pl_grid_t *g, const pl_stream_params_t *p,
                       uint32_t *hist, int nthreads)
{
    run(f, g, p, hist, nthreads, 1);
}

void pl_srd_bin(pl_fluid_t *f, const pl_grid_t *g, uint32_t *hist, int nthreads)
{
    pl_stream_params_t none;
    memset(&none, 0, sizeof none);
    run(f, g, &none, hist, nthreads, 0);
}
