/* Colloid state: allocation (64-byte aligned structure of arrays), set-up of
 * radii, masses, positions and velocities from the scene (its depletion and
 * multiple-time-stepping parts: colloid_pair_setup.c), force evaluation,
 * energies and momenta (fixed-order serial sums: bitwise reproducible). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/real.h" /* PL_PI */
#include "peloid/colloid.h"
#include "peloid/rng.h"
#include "peloid/colloid_integrator.h"

#define ENERGY_NAME_(ID, col, bit, always) [PL_CE_##ID] = col,
const char *const pl_colloid_energy_names[PL_CE_NTERMS] = {PL_COLLOID_ENERGY_SLOTS(ENERGY_NAME_)};
#undef ENERGY_NAME_

#define OFF(m) offsetof(pl_scene_t, m)

static void *zalloc(size_t bytes)
{
    size_t b = (bytes + 63) / 64 * 64;
    void *p = aligned_alloc(64, b ? b : 64);
    if (p) memset(p, 0, b ? b : 64);
    return p;
}

enum { NDBL = 27, NI32 = 6 };

static pl_colloid_view_t colloid_view(pl_colloid_t *c)
{
    pl_colloid_view_t v = {.n = c->n, .x = c->x, .y = c->y, .z = c->z, .vx = c->vx, .vy = c->vy,
                           .vz = c->vz, .wx = c->wx, .wy = c->wy, .wz = c->wz, .rad = c->rad,
                           .mass = c->mass, .fx = c->fx, .fy = c->fy, .fz = c->fz, .tx = c->tx,
                           .ty = c->ty, .tz = c->tz, .epot = c->epot, .g_overlap = c->g_overlap,
                           .g_omega2 = c->g_omega2, .g_damp = c->g_damp, .g_partner = c->g_partner};
    return v;
}

static void nlist_free(pl_colloid_nlist_t *nl)
{
    void *a[] = {nl->start, nl->nbr, nl->rstart, nl->rslot, nl->spos, nl->pf, nl->pt, nl->x0, nl->y0, nl->z0};
    for (size_t k = 0; k < sizeof a / sizeof *a; ++k) free(a[k]);
    memset(nl, 0, sizeof *nl);
}

int pl_colloid_alloc(size_t n, int nthreads, pl_colloid_t **out, pl_err_t *err)
{
    pl_colloid_t *c = calloc(1, sizeof *c);
    if (!c) return pl_err_set(err, PL_ERR_NOMEM, "colloids: out of memory");
    c->n = n;
    c->nthreads = nthreads > 0 ? nthreads : 1;
    double **d[NDBL] = {&c->x, &c->y, &c->z, &c->vx, &c->vy, &c->vz, &c->wx, &c->wy, &c->wz,
                        &c->q0, &c->q1, &c->q2, &c->q3, &c->rad, &c->mass, &c->inertia,
                        &c->fx, &c->fy, &c->fz, &c->tx, &c->ty, &c->tz, &c->zu,
                        &c->g_overlap, &c->g_omega2, &c->g_damp, &c->epot};
    int fail = 0;
    for (int k = 0; k < NDBL; ++k) {
        size_t len = k == NDBL - 1 ? (size_t)PL_CE_NTERMS * n : n;
        *d[k] = zalloc(len * sizeof(double));
        fail |= !*d[k];
    }
    c->ix = zalloc(n * sizeof(int32_t));
    c->iy = zalloc(n * sizeof(int32_t));
    c->iz = zalloc(n * sizeof(int32_t));
    c->g_partner = zalloc(3 * n * sizeof(int32_t));
    c->cells.list = zalloc(n * sizeof(int32_t));
    c->cells.cell = zalloc(n * sizeof(int32_t));
    fail |= !c->ix || !c->iy || !c->iz || !c->g_partner || !c->cells.list || !c->cells.cell;
    pl_colloid_nlist_t *nl = &c->nlist;
    nl->n = n;
    nl->start = zalloc((n + 1) * sizeof(int32_t));
    nl->rstart = zalloc((n + 1) * sizeof(int32_t));
    nl->x0 = zalloc(n * sizeof(double));
    nl->y0 = zalloc(n * sizeof(double));
    nl->z0 = zalloc(n * sizeof(double));
    fail |= !nl->start || !nl->rstart || !nl->x0 || !nl->y0 || !nl->z0;
    if (fail) {
        pl_colloid_free(c);
        return pl_err_set(err, PL_ERR_NOMEM, "colloids: out of memory for %zu colloids", n);
    }
    for (size_t i = 0; i < n; ++i) c->q0[i] = 1.0;
    *out = c;
    return 0;
}

void pl_colloid_free(pl_colloid_t *c)
{
    if (!c) return;
    double *d[NDBL] = {c->x, c->y, c->z, c->vx, c->vy, c->vz, c->wx, c->wy, c->wz,
                       c->q0, c->q1, c->q2, c->q3, c->rad, c->mass, c->inertia,
                       c->fx, c->fy, c->fz, c->tx, c->ty, c->tz, c->zu,
                       c->g_overlap, c->g_omega2, c->g_damp, c->epot};
    for (int k = 0; k < NDBL; ++k) free(d[k]);
    free(c->ix);
    free(c->iy);
    free(c->iz);
    free(c->g_partner);
    free(c->cells.list);
    free(c->cells.cell);
    free(c->cells.start);
    nlist_free(&c->nlist);
    nlist_free(&c->near);
    pl_colloid_adaptive_free(c);
    free(c->fsx);
    free(c->fsy);
    free(c->fsz);
    free(c->dep_table);
    free(c);
}

/* The near list and the slow forces of multiple time stepping (once). */
static int mts_alloc(pl_colloid_t *c, pl_err_t *err)
{
    const size_t n = c->n;
    if (!c->fsx) {
        c->fsx = zalloc(n * sizeof(double));
        c->fsy = zalloc(n * sizeof(double));
        c->fsz = zalloc(n * sizeof(double));
        c->near.n = n;
        c->near.start = zalloc((n + 1) * sizeof(int32_t));
        c->near.rstart = zalloc((n + 1) * sizeof(int32_t));
        if (!c->fsx || !c->fsy || !c->fsz || !c->near.start || !c->near.rstart)
            return pl_err_set(err, PL_ERR_NOMEM, "colloids: out of memory (multiple time stepping)");
    }
    return 0;
}

/* Slot arrays of the neighbour list for at least `need` pairs (grown by a
 * quarter beyond the need, so rebuilds rarely allocate). */
int pl_colloid_nlist_reserve(pl_colloid_nlist_t *nl, size_t need, pl_err_t *err)
{
    if (need <= nl->cap) return 0;
    size_t cap = need + need / 4 + 64;
    free(nl->nbr);
    free(nl->rslot);
    free(nl->spos);
    free(nl->pf);
    free(nl->pt);
    nl->nbr = zalloc(cap * sizeof(int32_t));
    nl->rslot = zalloc(cap * sizeof(int32_t));
    nl->spos = zalloc(cap * sizeof(int32_t));
    nl->pf = zalloc(3 * cap * sizeof(double));
    nl->pt = zalloc(3 * cap * sizeof(double));
    int fail = !nl->nbr || !nl->rslot || !nl->spos || !nl->pf || !nl->pt;
    nl->cap = fail ? 0 : cap;
    if (fail)
        return pl_err_set(err, PL_ERR_NOMEM, "colloids: out of memory for a neighbour list of %zu pairs",
                          need);
    return 0;
}

/* Cells and neighbour list for the present positions. */
static int nlist_build(pl_colloid_t *c, pl_err_t *err)
{
    pl_colloid_nlist_t *nl = &c->nlist;
    pl_colloid_cells_build(&c->cells, c->n, c->x, c->y, c->z);
    pl_colloid_nlist_count(nl, &c->cells, c->box, c->periodic, c->x, c->y, c->z, c->nthreads);
    for (size_t i = 0; i < c->n; ++i) nl->start[i + 1] += nl->start[i];
    if (pl_colloid_nlist_reserve(nl, (size_t)nl->start[c->n], err)) return err->code;
    pl_colloid_nlist_fill(nl, &c->cells, c->box, c->periodic, c->x, c->y, c->z, c->nthreads);
    if (c->slow_interval <= 1) return 0;
    pl_colloid_nlist_t *nr = &c->near;
    pl_colloid_nlist_near_count(nr, nl, &c->pair, c->x, c->y, c->z, c->rad, c->nthreads);
    for (size_t i = 0; i < c->n; ++i) nr->start[i + 1] += nr->start[i];
    if (pl_colloid_nlist_reserve(nr, (size_t)nr->start[c->n], err)) return err->code;
    pl_colloid_nlist_near_fill(nr, nl, &c->pair, c->x, c->y, c->z, c->rad, c->nthreads);
    return 0;
}

int pl_colloid_neighbors_init(pl_colloid_t *c, double rc, double skin_fraction, pl_err_t *err)
{
    double skin = skin_fraction * rc;
    for (int k = 0; k < 3; ++k)
        if (c->periodic[k]) skin = fmin(skin, fmax(0.0, 0.5 * c->box[k] - rc));
    c->nlist.skin = skin;
    c->nlist.rlist = rc + skin;
    c->nlist.builds = 0; /* the next force evaluation builds the list */
    pl_colloid_cells_dims(c->box, c->periodic, c->nlist.rlist, c->cells.nc);
    c->cells.ncells = (size_t)c->cells.nc[0] * (size_t)c->cells.nc[1] * (size_t)c->cells.nc[2];
    for (int k = 0; k < 3; ++k) c->cells.inv_cl[k] = c->cells.nc[k] / c->box[k];
    free(c->cells.start);
    c->cells.start = zalloc((c->cells.ncells + 1) * sizeof(int32_t));
    if (!c->cells.start) return pl_err_set(err, PL_ERR_NOMEM, "colloids: out of memory (cells)");
    return 0;
}

/* Rebuilds the list when a colloid may have moved a pair from beyond the
 * list radius to inside the cut-off: disp2, the largest squared displacement
 * since the build, beyond (skin/2)^2 (a function of the state alone). */
static int nlist_ensure(pl_colloid_t *c, double disp2, pl_err_t *err)
{
    return pl_colloid_nlist_stale(&c->nlist, disp2) ? nlist_build(c, err) : 0;
}

static pl_colloid_dyn_t colloid_dyn(pl_colloid_t *c)
{
    pl_colloid_dyn_t s = {.n = c->n, .box = {c->box[0], c->box[1], c->box[2]},
                          .periodic = {c->periodic[0], c->periodic[1], c->periodic[2]},
                          .mass = c->mass, .inertia = c->inertia, .rad = c->rad, .x = c->x,
                          .y = c->y, .z = c->z, .zu = c->zu, .ix = c->ix, .iy = c->iy, .iz = c->iz,
                          .vx = c->vx, .vy = c->vy, .vz = c->vz, .wx = c->wx, .wy = c->wy,
                          .wz = c->wz, .q0 = c->q0, .q1 = c->q1, .q2 = c->q2, .q3 = c->q3,
                          .fx = c->fx, .fy = c->fy, .fz = c->fz, .tx = c->tx, .ty = c->ty,
                          .tz = c->tz, .fsx = c->fsx, .fsy = c->fsy, .fsz = c->fsz};
    return s;
}

/* The list of the pair pass: the near list under multiple time stepping
 * (the slow share runs over the full list), else the full list. */
static const pl_colloid_nlist_t *pair_list(const pl_colloid_t *c)
{
    return c->slow_interval > 1 ? &c->near : &c->nlist;
}

/* The lubrication noise of a force pass at the positions of MD step
 * `step` (the MD steps done to reach them): its amplitude sqrt(2 kT / dt)
 * for this MD step and the counter of its draws (pl_colloid_pair_params_t).
 * Both evaluations of one time level (restart: read from the checkpoint
 * instead; coupling III: the step's forces recomputed at its start) draw
 * the same numbers, so each time level has one random force, which its two
 * half kicks share (DPD velocity Verlet). */
static void lub_noise_set(pl_colloid_t *c, long long step)
{
    pl_colloid_pair_params_t *p = &c->pair;
    p->noise_seed = c->seed;
    p->noise_step = (uint64_t)step;
    p->lub_noise = p->lub_thermal && (p->terms & PL_CT_LUB) ? sqrt(2.0 * p->lub_kT / c->dt) : 0.0;
}

void pl_colloid_md_region_of(pl_colloid_t *c, pl_colloid_md_region_t *r, pl_colloid_view_t *v)
{
    *v = colloid_view(c);
    c->pair.noise_seed = c->seed; /* the region sets each MD step's noise_step and lub_noise (lub_noise_set) */
    const pl_colloid_md_region_t rr = {.s = colloid_dyn(c), .p = &c->pair, .full = &c->nlist,
                                       .near = c->slow_interval > 1 ? &c->near : NULL,
                                       .cells = &c->cells, .v = v, .ext = &c->ext, .epot = c->epot,
                                       .reach = NULL, .reach_margin = 0.0, .nthreads = c->nthreads};
    *r = rr;
}

int pl_colloid_forces(pl_colloid_t *c, pl_err_t *err)
{
    pl_colloid_nlist_t *nl = &c->nlist;
    double disp2 = nl->builds ? pl_colloid_nlist_max_disp2(nl, c->box, c->periodic, c->x, c->y, c->z, c->nthreads)
                              : INFINITY;
    if (nlist_ensure(c, disp2, err)) return err->code;
    pl_colloid_view_t v = colloid_view(c);
    lub_noise_set(c, c->md_step);
    pl_colloid_pair_forces(&c->pair, pair_list(c), &v, c->nthreads);
    if (c->slow_interval > 1)
        pl_colloid_slow_forces(&c->pair, nl, c->x, c->y, c->z, c->rad, c->fsx, c->fsy, c->fsz, c->nthreads);
    for (size_t i = 0; i < c->n; ++i) c->zu[i] = c->z[i] + (double)c->iz[i] * c->box[2];
    pl_colloid_ext_forces(&c->ext, c->n, c->x, c->y, c->z, c->zu, c->rad, c->mass, c->fx, c->fy, c->fz, c->epot, c->nthreads);
    return 0;
}

int pl_colloid_setup(pl_colloid_t *c, const pl_scene_t *scene, pl_err_t *err)
{
    const pl_scene_colloids_t *cs = &scene->colloids;
    if (pl_colloid_pair_params(scene, &c->pair, &c->dlvo, err)) return err->code;
    if (pl_colloid_depletion_setup(c, scene, err)) return err->code;
    for (int k = 0; k < 3; ++k) {
        c->box[k] = c->pair.box[k];
        c->periodic[k] = c->pair.periodic[k];
    }
    for (int k = 0; k < 3; ++k) c->ext.g[k] = cs->gravity[k];
    for (int k = 0; k < 3; ++k) {
        c->ext.walls[k] = !c->periodic[k];
        c->ext.L[k] = c->box[k];
    }
    c->ext.wall_eps = cs->wall_epsilon;
    c->ext.wall_n = cs->wall_n;
    c->integrator = cs->integrator;
    c->substeps = (int)cs->substeps;
    c->dt = scene->srd.dt / (double)cs->substeps;
    c->min_contact_steps = cs->min_contact_steps;
    if (pl_colloid_adaptive_setup(c, scene, err)) return err->code;
    /* multiple time stepping is checked at the longest MD step it will meet */
    c->dt = scene->srd.dt / (double)c->sub_min;
    if (pl_colloid_mts_setup(c, scene, err)) return err->code;
    c->dt = scene->srd.dt / (double)cs->substeps;
    if (c->slow_interval > 1 && mts_alloc(c, err)) return err->code;
    c->kT = cs->temperature;
    c->bd_eta = cs->bd_viscosity;
    c->seed = (uint64_t)scene->run.seed;
    c->max_overlap = cs->max_overlap;
    c->max_energy_drift = cs->max_energy_drift;
    c->guard_interval = cs->guard_interval;
    unsigned t = c->pair.terms;
    c->nve = pl_colloid_integrator(c->integrator)->inertial && !(t & PL_CT_LUB) &&
             !((t & PL_CT_HERTZ) && (cs->hertz.beta > 0.0 || cs->hertz.gamma_t > 0.0));
    /* neighbour list radius: the largest pair cut-off plus the skin (the
     * skin capped so the list keeps to the minimum image); cells sized by it */
    double rmax = 0.0;
    for (size_t i = 0; i < c->n; ++i) rmax = fmax(rmax, c->rad[i]);
    const double rc = pl_colloid_pair_cutoff(&c->pair, rmax);
    if (pl_colloid_neighbors_init(c, rc, cs->neighbor_skin, err)) return err->code;
    if (pl_colloid_forces(c, err)) return err->code;
    pl_colloid_energy_t e;
    pl_colloid_energy(c, &e);
    c->e0 = e.total;
    return 0;
}

static void place_lattice(pl_colloid_t *c, const double L[3], int walls)
{
    double a = cbrt(L[0] * L[1] * L[2] / (double)c->n);
    long m[3];
    for (int k = 0; k < 3; ++k) m[k] = lround(fmax(1.0, floor(L[k] / a)));
    while (m[0] * m[1] * m[2] < (long)c->n) {
        int k = 0; /* refine the axis with the widest spacing */
        for (int j = 1; j < 3; ++j)
            if (L[j] / (double)m[j] > L[k] / (double)m[k]) k = j;
        m[k]++;
    }
    (void)walls;
    for (size_t i = 0; i < c->n; ++i) {
        long ii = (long)i;
        c->x[i] = ((double)(ii % m[0]) + 0.5) * L[0] / (double)m[0];
        c->y[i] = ((double)((ii / m[0]) % m[1]) + 0.5) * L[1] / (double)m[1];
        c->z[i] = ((double)(ii / (m[0] * m[1])) + 0.5) * L[2] / (double)m[2];
    }
}


static int place_random(pl_colloid_t *c, const pl_scene_t *scene, pl_err_t *err)
{
    const double *L = c->box;
    for (size_t i = 0; i < c->n; ++i) {
        int ok = 0;
        for (uint64_t att = 0; att < 100000 && !ok; ++att) {
            pl_rand4_t u = pl_rng_uniform4(c->seed, PL_RNG_COLLOID_PLACE, att, i, 0);
            double R = c->rad[i];
            double *const x[3] = {&c->x[i], &c->y[i], &c->z[i]};
            for (int k = 0; k < 3; ++k) { /* closed axes: the colloid clear of the walls */
                double lo = c->periodic[k] ? 0.0 : R, hi = c->periodic[k] ? L[k] : L[k] - R;
                *x[k] = c->periodic[k] ? u.u[k] * L[k] : lo + u.u[k] * (hi - lo);
            }
            ok = 1;
            for (size_t j = 0; j < i && ok; ++j) {
                double dx = pl_min_image(c->x[i] - c->x[j], L[0], c->periodic[0]);
                double dy = pl_min_image(c->y[i] - c->y[j], L[1], c->periodic[1]);
                double dz = pl_min_image(c->z[i] - c->z[j], L[2], c->periodic[2]);
                double d = c->rad[i] + c->rad[j];
                if (dx * dx + dy * dy + dz * dz < d * d) ok = 0;
            }
        }
        if (!ok)
            return pl_scene_fail(scene, err, OFF(colloids.count), "colloids.count",
                                 "random placement found no free site for colloid %zu of %zu "
                                 "after 100000 tries; lower colloids.count or use init = \"lattice\"",
                                 i, c->n);
    }
    return 0;
}

int pl_colloid_create(const pl_scene_t *scene, int nthreads, pl_colloid_t **out, pl_err_t *err)
{
    const pl_scene_colloids_t *cs = &scene->colloids;
    pl_colloid_t *c;
    if (pl_colloid_alloc((size_t)cs->count, nthreads, &c, err)) return err->code;
    c->seed = (uint64_t)scene->run.seed;
    for (int k = 0; k < 3; ++k) c->box[k] = scene->box.cells[k];
    int walls[3];
    pl_scene_box_walls(&scene->box, walls);
    for (int k = 0; k < 3; ++k) c->periodic[k] = walls[k] == PL_WALLS_NONE;
    for (size_t i = 0; i < c->n; ++i) {
        pl_rand4_t u = pl_rng_uniform4(c->seed, PL_RNG_COLLOID_RADIUS, 0, i, 0);
        c->rad[i] = cs->radius * (1.0 + sqrt(3.0) * cs->polydispersity * (2.0 * u.u[0] - 1.0));
    }
    int rc = 0;
    if (cs->init == PL_CINIT_LATTICE) place_lattice(c, c->box, !c->periodic[2]);
    else if (cs->init == PL_CINIT_RANDOM) rc = place_random(c, scene, err);
    else rc = pl_colloid_read_init_file(scene, c, err);
    if (rc) {
        pl_colloid_free(c);
        return rc;
    }
    double ptot[3] = {0, 0, 0}, mtot = 0.0;
    for (size_t i = 0; i < c->n; ++i) {
        double R = c->rad[i];
        c->mass[i] = cs->mass_density * 4.0 / 3.0 * PL_PI * R * R * R;
        c->inertia[i] = 0.4 * c->mass[i] * R * R;
        pl_rand4_t a = pl_rng_uniform4(c->seed, PL_RNG_COLLOID_VEL, 0, i, 0);
        pl_rand4_t b = pl_rng_uniform4(c->seed, PL_RNG_COLLOID_VEL, 0, i, 1);
        pl_rand4_t q = pl_rng_uniform4(c->seed, PL_RNG_COLLOID_VEL, 0, i, 2);
        double g[6], sv = sqrt(cs->temperature / c->mass[i]), sw = sqrt(cs->temperature / c->inertia[i]);
        pl_rng_gauss2(a.u[0], a.u[1], &g[0], &g[1]);
        pl_rng_gauss2(a.u[2], a.u[3], &g[2], &g[3]);
        pl_rng_gauss2(b.u[0], b.u[1], &g[4], &g[5]);
        c->vx[i] = sv * g[0];
        c->vy[i] = sv * g[1];
        c->vz[i] = sv * g[2];
        c->wx[i] = sw * g[3];
        c->wy[i] = sw * g[4];
        c->wz[i] = sw * g[5];
        /* random orientation: normalised 4-d Gaussian */
        double h[4];
        pl_rng_gauss2(q.u[0], q.u[1], &h[0], &h[1]);
        pl_rng_gauss2(q.u[2], q.u[3], &h[2], &h[3]);
        double nq = 1.0 / sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2] + h[3] * h[3]);
        c->q0[i] = h[0] * nq;
        c->q1[i] = h[1] * nq;
        c->q2[i] = h[2] * nq;
        c->q3[i] = h[3] * nq;
        ptot[0] += c->mass[i] * c->vx[i];
        ptot[1] += c->mass[i] * c->vy[i];
        ptot[2] += c->mass[i] * c->vz[i];
        mtot += c->mass[i];
    }
    for (size_t i = 0; i < c->n; ++i) { /* zero total momentum */
        c->vx[i] -= ptot[0] / mtot;
        c->vy[i] -= ptot[1] / mtot;
        c->vz[i] -= ptot[2] / mtot;
    }
    if ((rc = pl_colloid_overlap_screen(c, scene, err)) || (rc = pl_colloid_setup(c, scene, err))) {
        pl_colloid_free(c);
        return rc;
    }
    size_t worst = 0;
    for (size_t i = 1; i < c->n; ++i)
        if (c->g_overlap[i] > c->g_overlap[worst]) worst = i;
    if (c->n && c->g_overlap[worst] > c->max_overlap) {
        char what[160];
        snprintf(what, sizeof what, "initial colloids %zu and %d overlap by %.4g", worst, c->g_partner[worst],
                 c->g_overlap[worst]);
        rc = pl_colloid_overlap_fail(scene, err, what);
        pl_colloid_free(c);
        return rc;
    }
    /* the contact guard's criterion on the initial configuration: a pair
     * that starts unresolved is an input error, not a guard trip at MD step 1 */
    size_t stiff = 0;
    for (size_t i = 1; i < c->n; ++i)
        if (c->g_omega2[i] > c->g_omega2[stiff]) stiff = i;
    if (c->n && c->min_contact_steps > 0.0 && c->g_omega2[stiff] > 0.0 &&
        PL_PI / sqrt(c->g_omega2[stiff]) / c->dt < c->min_contact_steps) {
        double tc = PL_PI / sqrt(c->g_omega2[stiff]);
        rc = pl_scene_fail(scene, err, OFF(colloids.init), "colloids.init",
                           "initial colloids %zu and %d: the collision time pi sqrt(m_red/U'') = %.4g t0 "
                           "is resolved by %.3g MD steps < colloids.min_contact_steps = %g (the contact "
                           "guard would stop the run at its first MD step); %s",
                           stiff, c->g_partner[c->n + stiff], tc, tc / c->dt, c->min_contact_steps,
                           scene->mapping.enabled
                               ? "start without touching pairs (colloids.init = \"lattice\"), or resolve the contact: "
                                 "raise coarse_graining.reach_energy (the MD step is derived from it)"
                               : "raise colloids.substeps or start elsewhere (colloids.init = \"lattice\")");
        pl_colloid_free(c);
        return rc;
    }
    *out = c;
    return 0;
}

void pl_colloid_energy(pl_colloid_t *c, pl_colloid_energy_t *e)
{
    memset(e, 0, sizeof *e);
    /* the pair energies of the positions the last force evaluation saw (its
     * list is valid for them) */
    pl_colloid_view_t v = colloid_view(c);
    pl_colloid_pair_energies(&c->pair, &c->nlist, &v, c->nthreads);
    for (size_t i = 0; i < c->n; ++i) {
        e->kin_trans += 0.5 * c->mass[i] * (c->vx[i] * c->vx[i] + c->vy[i] * c->vy[i] + c->vz[i] * c->vz[i]);
        e->kin_rot += 0.5 * c->inertia[i] * (c->wx[i] * c->wx[i] + c->wy[i] * c->wy[i] + c->wz[i] * c->wz[i]);
        for (int k = 0; k < PL_CE_NTERMS; ++k) e->pot[k] += c->epot[(size_t)k * c->n + i];
    }
    e->total = e->kin_trans + e->kin_rot;
    for (int k = 0; k < PL_CE_NTERMS; ++k) e->total += e->pot[k];
}

void pl_colloid_momentum(const pl_colloid_t *c, double p[3], double l[3])
{
    for (int k = 0; k < 3; ++k) p[k] = l[k] = 0.0;
    for (size_t i = 0; i < c->n; ++i) {
        double m = c->mass[i];
        double x = c->x[i] + c->ix[i] * c->box[0], y = c->y[i] + c->iy[i] * c->box[1];
        double z = c->z[i] + c->iz[i] * c->box[2];
        double px = m * c->vx[i], py = m * c->vy[i], pz = m * c->vz[i];
        p[0] += px;
        p[1] += py;
        p[2] += pz;
        l[0] += y * pz - z * py + c->inertia[i] * c->wx[i];
        l[1] += z * px - x * pz + c->inertia[i] * c->wy[i];
        l[2] += x * py - y * px + c->inertia[i] * c->wz[i];
    }
}

void pl_colloid_exchange_energy(pl_colloid_t *c) { c->nve = 0; }
