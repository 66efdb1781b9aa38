/* Cross-key scene checks of the scene's own sections (box, fluid, output):
 * what one key's range cannot express; the run's memory against the
 * machine's.  A scene is loaded (src/app/scene_open.c) by these after the
 * mapping and before each module's own checks. */
#include <math.h>
#include <stdio.h>
#include <sys/resource.h>
#include <unistd.h>

#include "peloid/real.h"
#include "peloid/scene.h"

#define OFF(m) offsetof(pl_scene_t, m)

/* Bytes a run allocates, by O(1) arithmetic on the scene (src/core/sim.c,
 * src/core/fluid.c, src/coupling/coupling_potential.c): per fluid particle
 * the positions and velocities with their sort twins (12 reals), the cell
 * index, with output.track_fluid ids and unwrapped displacements (twins),
 * with the potential coupling its two selection indices and its staging row;
 * per collision cell (closed axes add a layer each side) the per-thread
 * histograms of the counting sort, the cell starts, a coupling's cell starts
 * and mask and, with output.fields_interval, the field sums (4 x 8 B); per
 * colloid ~600 B (state, scratch, neighbour list). */
static double memory_bytes(const pl_scene_t *scene, int nthreads, double *np_out, double *per_p_out,
                           double *cells_out, double *per_c_out)
{
    const pl_scene_box_t *b = &scene->box;
    const int cpl = scene->coupling.method != PL_COUPLE_NONE && scene->colloids.count > 0;
    const int pot = cpl && scene->coupling.method == PL_COUPLE_POTENTIAL;
    double cells = 1.0, vol = 1.0;
    for (int d = 0; d < 3; ++d) {
        int closed = d == 2 ? b->walls_z != PL_WALLS_NONE : b->walls_xy != PL_WALLS_NONE;
        cells *= (double)b->cells[d] + (closed ? 2.0 : 0.0);
        vol *= (double)b->cells[d];
    }
    const double np = scene->fluid.density * vol;
    const double per_p = 12.0 * sizeof(pl_real) + 4.0 + (scene->output.track_fluid ? 56.0 : 0.0) +
                         (pot ? 8.0 + 8.0 * (scene->output.track_fluid ? 9.0 : 6.0) : 0.0);
    const double per_c = 4.0 * nthreads + 4.0 + (cpl ? 4.125 : 0.0) + (scene->output.fields_interval > 0 ? 32.0 : 0.0);
    if (np_out) *np_out = np;
    if (per_p_out) *per_p_out = per_p;
    if (cells_out) *cells_out = cells;
    if (per_c_out) *per_c_out = per_c;
    return per_p * np + per_c * cells + 600.0 * (double)scene->colloids.count;
}

double pl_scene_memory_bytes(const pl_scene_t *scene, int nthreads)
{
    return memory_bytes(scene, nthreads, NULL, NULL, NULL, NULL);
}

/* A limit in bytes read from a cgroup file ("max" or absent: none, 0). */
static double cgroup_limit(const char *path)
{
    FILE *f = fopen(path, "r");
    double v = 0.0;
    if (f) {
        if (fscanf(f, "%lf", &v) != 1) v = 0.0;
        fclose(f);
    }
    return v > 0.0 && v < 1e18 ? v : 0.0; /* cgroup v1 writes ~9.2e18 for "no limit" */
}

/* The memory this process may allocate: the least of physical memory, the
 * address-space and data-segment limits (ulimit -v, -d) and the memory
 * limit of its cgroup (v2, v1), so that check refuses what the run's
 * allocation would fail on; `what` names the one that binds. */
static double memory_have(const char **what)
{
    long pages = sysconf(_SC_PHYS_PAGES), psize = sysconf(_SC_PAGESIZE);
    double have = pages > 0 && psize > 0 ? (double)pages * (double)psize : 0.0;
    *what = "physical memory";
    /* (the resources named in the calls: glibc types them as an enum, clang
     * would see a sign change through an int table) */
    struct { struct rlimit rl; int ok; const char *name; } lims[2];
    lims[0].ok = getrlimit(RLIMIT_AS, &lims[0].rl) == 0;
    lims[0].name = "address-space limit, ulimit -v";
    lims[1].ok = getrlimit(RLIMIT_DATA, &lims[1].rl) == 0;
    lims[1].name = "data-segment limit, ulimit -d";
    for (size_t k = 0; k < sizeof lims / sizeof lims[0]; ++k) {
        const struct rlimit rl = lims[k].rl;
        if (lims[k].ok && rl.rlim_cur != RLIM_INFINITY && (have <= 0.0 || (double)rl.rlim_cur < have)) {
            have = (double)rl.rlim_cur;
            *what = lims[k].name;
        }
    }
    const char *cg[] = {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"};
    for (size_t k = 0; k < sizeof cg / sizeof cg[0]; ++k) {
        double v = cgroup_limit(cg[k]);
        if (v > 0.0 && (have <= 0.0 || v < have)) {
            have = v;
            *what = "cgroup memory limit";
        }
    }
    return have;
}

/* The key a refusal of box.cells (density 0) or fluid.density (1) names:
 * in a physical{} scene, where the mapping derived them, the input they
 * come from (physical.box, coarse_graining.particles_per_cell) where the
 * file gives it. */
static const char *size_key(const pl_scene_t *s, int density, size_t *off)
{
    *off = density ? OFF(fluid.density) : OFF(box.cells);
    const size_t src = density ? OFF(mapping.cg.particles_per_cell) : OFF(mapping.physical.box);
    if (s->mapping.enabled && pl_scene_line_of(s, *off) <= 0 && pl_scene_line_of(s, src) > 0) {
        *off = src;
        return density ? "coarse_graining.particles_per_cell" : "physical.box";
    }
    return density ? "fluid.density" : "box.cells";
}

int pl_scene_memory_check(const pl_scene_t *scene, int nthreads, pl_err_t *err)
{
    double np, per_p, cells, per_c;
    const double need = memory_bytes(scene, nthreads, &np, &per_p, &cells, &per_c);
    const char *what;
    const double have = memory_have(&what);
    if (!(have > 0.0 && need > have)) return 0;
    size_t off;
    const char *key = size_key(scene, per_p * np >= per_c * cells, &off);
    return pl_scene_fail(scene, err, off, key,
                         "the run needs about %.3g GB: %.3g fluid particles (box.cells x fluid.density) x %.0f B "
                         "+ %.3g cells x %.0f B (at %d thread(s)) + %lld colloids x 600 B; this process may use %.3g GB "
                         "(%s); allowed: a smaller box, density or thread count",
                         need / 1e9, np, per_p, cells, per_c, nthreads, scene->colloids.count, have / 1e9, what);
}

int pl_scene_check_keys(pl_scene_t *scene, pl_err_t *err)
{
    const pl_scene_box_t *b = &scene->box;
    double ncells = (double)b->cells[0] * b->cells[1] * b->cells[2];
    size_t soff;
    const char *skey = size_key(scene, 0, &soff);
    if (ncells > 1.0e9)
        return pl_scene_fail(scene, err, soff, skey, "%d x %d x %d = %g cells (box.cells) is more than the 1e9 supported",
                             b->cells[0], b->cells[1], b->cells[2], ncells);
    if (b->walls_z != PL_WALLS_NONE && b->cells[2] < 2)
        return pl_scene_fail(scene, err, soff, skey,
                             "Lz = %d with walls_z; allowed: Lz >= 2", b->cells[2]);
    if (b->walls_xy != PL_WALLS_NONE && (b->cells[0] < 2 || b->cells[1] < 2))
        return pl_scene_fail(scene, err, soff, skey,
                             "Lx = %d, Ly = %d with walls_xy; allowed: Lx >= 2 and Ly >= 2",
                             b->cells[0], b->cells[1]);
    for (int w = 0; w < 2; ++w) { /* moving walls (shear, Hecht Sec. VIII.C) */
        const double *u = b->wall_velocity[w];
        const char *key = w ? "box.wall_velocity_top" : "box.wall_velocity_bottom";
        size_t off = w ? OFF(box.wall_velocity[1]) : OFF(box.wall_velocity[0]);
        if (pl_vec3_nonzero(u) && b->walls_z != PL_WALLS_NOSLIP)
            return pl_scene_fail(scene, err, off, key,
                                 "[%g, %g, %g] needs box.walls_z = \"noslip\" (%s); allowed "
                                 "otherwise: [0, 0, 0]", u[0], u[1], u[2],
                                 b->walls_z == PL_WALLS_SLIP ? "a slip wall cannot drag the fluid"
                                                             : "walls_z = \"none\" has no wall to move");
        if (u[2] != 0.0)
            return pl_scene_fail(scene, err, off, key,
                                 "z component %g: a wall moves in its own plane only; allowed: "
                                 "[ux, uy, 0]", u[2]);
    }
    double np = ncells * scene->fluid.density;
    skey = size_key(scene, 1, &soff);
    if (np > 4.0e9)
        return pl_scene_fail(scene, err, soff, skey, "%.3g fluid particles (fluid.density %g x %g cells); allowed: < 4e9",
                             np, scene->fluid.density, ncells);
    if (pl_scene_memory_check(scene, 1, err)) return PL_ERR_INPUT; /* at 1 thread: the least a run needs */
    if (scene->fluid.density > 0 && np < 2.0)
        return pl_scene_fail(scene, err, soff, skey, "%.3g fluid particles in the box (fluid.density %g x %g cells); "
                             "allowed: at least 2", np, scene->fluid.density, ncells);
    if (scene->output.fields_interval > 0 && scene->output.fields_start >= scene->run.steps &&
        scene->run.steps > 0)
        return pl_scene_fail(scene, err, OFF(output.fields_start), "output.fields_start",
                             "%lld is not before the last step %lld; no field sample would be taken",
                             scene->output.fields_start, scene->run.steps);
    if (scene->output.colloids_xyz && (scene->colloids.count <= 0 || scene->colloids.trajectory_interval <= 0))
        return pl_scene_fail(scene, err, OFF(output.colloids_xyz), "output.colloids_xyz",
                             "true without colloid frames; allowed: with colloids.count > 0 and "
                             "colloids.trajectory_interval > 0");
    return 0;
}
