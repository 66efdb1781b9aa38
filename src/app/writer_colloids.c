/* The colloid trajectory as a writer row (peloid/writer.h): colloids.h5
 * (H5MD) and, with output.colloids_xyz, colloids.xyz beside it
 * (src/io/colloid_h5md.c, colloid_xyz.c), a frame every
 * colloids.trajectory_interval steps, on the start state and on the last.
 * Before every step it holds the state, so that a guard stop inside the
 * step writes the last good frame.  Per-colloid columns another component
 * offers (pl_sim_t.frame_ids: the clusters observer's cluster ids) join
 * every frame. */
#include <limits.h>
#include <stdlib.h>

#include "peloid/colloid.h"
#include "peloid/io.h"
#include "peloid/mapping.h"
#include "peloid/writer.h"

typedef struct {
    pl_colloid_traj_t *t; /* NULL once closed */
} traj_w_t;

static int wanted(const pl_sim_t *sim) { return sim->colloids && sim->scene.colloids.trajectory_interval > 0; }

static int open_traj(pl_sim_t *sim, const pl_writer_out_t *out, void **ctx, pl_err_t *err)
{
    const pl_scene_t *scene = &sim->scene;
    traj_w_t *w = calloc(1, sizeof *w);
    if (!w) return pl_err_set(err, PL_ERR_NOMEM, "out of memory");
    *ctx = w;
    const pl_mapping_t *m = &scene->mapping.map;
    char path[PATH_MAX], xyz[PATH_MAX];
    pl_path_join(path, sizeof path, out->dir, pl_outputs[PL_OUT_COLLOIDS].name);
    pl_path_join(xyz, sizeof xyz, out->dir, pl_outputs[PL_OUT_COLLOIDS_XYZ].name);
    pl_colloid_traj_params_t tp = {.a0_m = scene->mapping.enabled ? m->a0 : 0.0,
                                   .t0_s = scene->mapping.enabled ? m->t0 : 0.0,
                                   .m_f_kg = scene->mapping.enabled ? m->m_f : 0.0,
                                   .mass_kg = scene->mapping.enabled
                                                  ? m->real.kT / (pl_scene_kT(scene) * m->a0 * m->a0 / (m->t0 * m->t0))
                                                  : 0.0,
                                   .frame_dt = (double)scene->colloids.trajectory_interval * scene->srd.dt,
                                   .xyz_path = scene->output.colloids_xyz ? xyz : NULL, .overwrite = 1,
                                   .resume = out->in_place, .keep_before = out->first};
    int rc = pl_colloid_traj_open(path, sim->colloids, &tp, &w->t, err);
    if (!rc && sim->frame_ids) rc = pl_colloid_traj_cluster_ids(w->t, sim->frame_ids, sim->frame_ids_ctx, err);
    return rc;
}

static int stage_frame(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    const traj_w_t *w = ctx;
    return pl_colloid_traj_write(w->t, sim->colloids, sim->step, (double)sim->step * sim->scene.srd.dt, err);
}

/* in the slot of frames, before the run's other writers (thermo.tsv,
 * checkpoint.h5), after the observers (whose cluster ids the frames carry) */
static int add_stages(pl_sim_t *sim, void *ctx, pl_err_t *err)
{
    pl_stage_t t = {.name = "colloid-trajectory", .fn = stage_frame, .ctx = ctx,
                    .interval = sim->scene.colloids.trajectory_interval, .phase = PL_PHASE_AFTER,
                    .at_start = 1, .at_end = 1, .writes = 1, .slot = PL_SLOT_FRAMES};
    return pl_sim_add_stage(sim, &t, err);
}

static void hold(const pl_sim_t *sim, void *ctx)
{
    const traj_w_t *w = ctx;
    pl_colloid_traj_hold(w->t, sim->colloids, sim->step, (double)sim->step * sim->scene.srd.dt);
}

static void guard_stop(const pl_sim_t *sim, void *ctx)
{
    const traj_w_t *w = ctx;
    pl_colloid_traj_write_held(w->t, sim->colloids, NULL);
}

/* the final state is the last frame (the stage's at_end) */
static int finish(pl_sim_t *sim, void *ctx, const pl_writer_out_t *out, pl_err_t *err)
{
    (void)sim;
    (void)out;
    traj_w_t *w = ctx;
    const int rc = pl_colloid_traj_close(w->t, err);
    w->t = NULL;
    return rc;
}

/* a trajectory the run left open (an error): its frames so far */
static void close_traj(void *ctx)
{
    traj_w_t *w = ctx;
    if (!w) return;
    pl_colloid_traj_close(w->t, NULL);
    free(w);
}

const pl_writer_t pl_writer_colloids = {
    .file = PL_OUT_COLLOIDS,
    .wanted = wanted,
    .open = open_traj,
    .add_stages = add_stages,
    .hold = hold,
    .guard_stop = guard_stop,
    .finish = finish,
    .close = close_traj,
};
