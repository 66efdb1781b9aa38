/* The run loop: step the plan, write thermo rows, checkpoints, fields and the
 * summary.  Order matters for "nothing written on bad input": the scene is
 * validated, the sim built and any restart checkpoint read before the output
 * directory is created. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "json_build.h"
#include "peloid/colloid.h"
#include "peloid/coupling.h"
#include "peloid/io.h"
#include "peloid/mapping.h"
#include "peloid/progress.h"
#include "peloid/run.h"
#include "peloid/srd_theory.h"

typedef struct {
    char dir[PATH_MAX]; /* resolved output directory (pl_outdir_prepare) */
    char thermo_path[PATH_MAX + 16];
    FILE *thermo;
    double t_start, t_last_row;
    long long step_last_row;
} writer_t;

static void thermo_header(FILE *f, int mapped, int tracked, int walls, int side_walls, int colloids, int reflect,
                          int pinned)
{
    fprintf(f, "step\ttime\t%stemperature\tkT_cell\tpx\tpy\tpz\tkinetic_energy\t%s%s%s%s%s%smupdates_per_s\n",
            mapped ? "time_s\ttemperature_K\t" : "", tracked ? "msd\t" : "",
            walls ? "sxz_bottom\tsxz_top\tsyz_bottom\tsyz_top\t" : "",
            side_walls ? "s_side_x\ts_side_y\ts_side_z\t" : "",
            colloids ? "c_kin_trans\tc_kin_rot\tc_dlvo\tc_hertz\tc_wca\tc_wall\tc_gravity\tc_depl\tc_total\tc_zcm\t" : "",
            reflect ? "cpl_events\tcpl_truncations\t" : "",
            pinned ? "cpl_drag_x\tcpl_drag_y\tcpl_drag_z\t" : "");
}

/* Wall shear stresses: no-slip walls (moving or not). */
static int noslip_walls(const pl_sim_t *sim)
{
    return sim->scene.box.walls_z == PL_WALLS_NOSLIP && sim->fluid.n > 0;
}

/* The x/y walls' stress: no-slip capillary walls. */
static int noslip_side_walls(const pl_sim_t *sim)
{
    return sim->scene.box.walls_xy == PL_WALLS_NOSLIP && sim->fluid.n > 0;
}

/* Coupling I counters (cumulative reflections and truncations, Hecht Sec. IV). */
static int reflecting(const pl_sim_t *sim)
{
    return sim->coupling && sim->coupling->method == PL_COUPLE_HECHT1;
}

/* The plan moves colloids by MD (not pinned): MD steps/s is worth showing. */
static int colloid_md_moves(const pl_sim_t *sim)
{
    for (int k = 0; k < sim->nstages; ++k)
        if (!strcmp(sim->stages[k].name, "colloid-md") || !strcmp(sim->stages[k].name, "potential-md")) return 1;
    return 0;
}

/* Appends one row and flushes it: PL_ERR_IO naming the file and the system
 * error when the row did not reach the file (a full disk must not lose rows
 * silently). */
static int thermo_row(writer_t *w, const pl_sim_t *sim, pl_err_t *err)
{
    pl_fluid_obs_t o;
    double kT;
    pl_sim_observe(sim, &o, &kT);
    double now = omp_get_wtime();
    double steps = (double)(sim->step - w->step_last_row);
    double rate = now > w->t_last_row && steps > 0 ? steps * (double)sim->fluid.n / (now - w->t_last_row) / 1e6 : 0.0;
    const double time = (double)sim->step * sim->scene.srd.dt;
    fprintf(w->thermo, "%lld\t%.10g\t", sim->step, time);
    const pl_scene_mapping_t *map = &sim->scene.mapping;
    if (map->enabled) /* physical units: kT = 1 is the model temperature kT_model (Hecht Sec. VII) */
        fprintf(w->thermo, "%.10g\t%.10g\t", time * map->map.t0, kT * map->map.kT_model / PL_KB);
    fprintf(w->thermo, "%.10g\t%.10g\t%.10g\t%.10g\t%.10g\t%.10g\t", kT, sim->last_kT_meas, o.momentum[0],
            o.momentum[1], o.momentum[2], o.kinetic);
    if (sim->fluid.tracked) fprintf(w->thermo, "%.10g\t", o.msd);
    if (noslip_walls(sim)) /* PL Eq. 13 stress from each wall's momentum, mean since step 0 */
        fprintf(w->thermo, "%.10g\t%.10g\t%.10g\t%.10g\t", pl_sim_wall_stress(sim, 0, 0),
                pl_sim_wall_stress(sim, 1, 0), pl_sim_wall_stress(sim, 0, 1), pl_sim_wall_stress(sim, 1, 1));
    if (noslip_side_walls(sim)) /* force per area on the x/y walls, mean since step 0 */
        fprintf(w->thermo, "%.10g\t%.10g\t%.10g\t", pl_sim_wall_stress(sim, 2, 0), pl_sim_wall_stress(sim, 2, 1),
                pl_sim_wall_stress(sim, 2, 2));
    if (sim->colloids) { /* colloid energy terms (src/colloid_state.c) */
        pl_colloid_energy_t ce;
        pl_colloid_energy(sim->colloids, &ce);
        fprintf(w->thermo, "%.10g\t%.10g\t", ce.kin_trans, ce.kin_rot);
        for (int k = 0; k < PL_CE_NTERMS; ++k) fprintf(w->thermo, "%.10g\t", ce.pot[k]);
        fprintf(w->thermo, "%.10g\t", ce.total);
        /* centre-of-mass height of the colloids (unwrapped z): sedimentation */
        const pl_colloid_t *c = sim->colloids;
        double mz = 0.0, m = 0.0;
        for (size_t k = 0; k < c->n; ++k) { /* fixed order */
            mz += c->mass[k] * (c->z[k] + (double)c->iz[k] * c->box[2]);
            m += c->mass[k];
        }
        fprintf(w->thermo, "%.10g\t", m > 0.0 ? mz / m : 0.0);
    }
    if (reflecting(sim))
        fprintf(w->thermo, "%llu\t%llu\t", sim->coupling->events, sim->coupling->truncations);
    if (sim->coupling && sim->coupling->pinned) { /* mean force per pinned colloid so far */
        const pl_coupling_t *cp = sim->coupling;
        double s = cp->pinned_time > 0 ? 1.0 / (cp->pinned_time * (double)sim->colloids->n) : 0.0;
        fprintf(w->thermo, "%.10g\t%.10g\t%.10g\t", cp->impulse[0] * s, cp->impulse[1] * s,
                cp->impulse[2] * s);
    }
    errno = 0;
    int bad = fprintf(w->thermo, "%.4g\n", rate) < 0;
    bad |= fflush(w->thermo) != 0;
    bad |= ferror(w->thermo) != 0;
    w->t_last_row = now;
    w->step_last_row = sim->step;
    if (bad)
        return pl_err_set(err, PL_ERR_IO, "%s: writing the row of step %lld failed: %s", w->thermo_path, sim->step,
                          errno ? strerror(errno) : "stream error");
    return 0;
}

/* The part of summary.json known before the run (build info, scene, derived
 * parameters, mapping, boundaries, colloid pair settings): built before the
 * output directory is created, so that a non-finite value is bad input with
 * nothing written. */
static int summary_head(const pl_sim_t *sim, json_t **out, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    pl_json_t b = {err, sc->path, "", 0};
    json_t *doc = json_object(), *o = json_object(), *v = NULL;
    pl_json_str(&b, o, "git_revision", PL_GIT_REV);
    pl_json_str(&b, o, "compiler", __VERSION__);
    pl_json_str(&b, o, "cflags", PL_CFLAGS);
    pl_json_str(&b, o, "real", PL_REAL_NAME);
    pl_json_set(&b, doc, "peloid", o);
    pl_json_str(&b, doc, "scene_file", sc->path);
    int rc = 0;
    if (!b.failed && !(rc = pl_scene_json(sc, &v, err))) pl_json_set(&b, doc, "scene", v);
    if (!b.failed && !rc && !(rc = pl_params_json(sc, &v, err))) pl_json_set(&b, doc, "derived", v);
    if (!b.failed && !rc && !(rc = pl_mapping_report_json(sc, &v, err))) pl_json_set(&b, doc, "mapping", v);
    if (!b.failed && !rc && sc->mapping.enabled) {
        const pl_mapping_t *m = &sc->mapping.map;
        b.prefix = "units_si";
        o = json_object();
        pl_json_real(&b, o, "a0_m", m->a0);
        pl_json_real(&b, o, "t0_s", m->t0);
        pl_json_real(&b, o, "m_f_kg", m->m_f);
        pl_json_real(&b, o, "kT_J", m->kT_model);
        pl_json_real(&b, o, "model_temperature_K", m->kT_model / PL_KB);
        pl_json_real(&b, o, "real_temperature_K", sc->mapping.physical.temperature);
        pl_json_set(&b, doc, "units_si", o);
    }
    int walls[3]; /* each axis: periodic, or noslip / slip walls at 0 and L */
    pl_scene_box_walls(&sc->box, walls);
    o = json_object();
    pl_json_str(&b, o, "x", pl_scene_boundary_name(walls[0]));
    pl_json_str(&b, o, "y", pl_scene_boundary_name(walls[1]));
    pl_json_str(&b, o, "z", pl_scene_boundary_name(walls[2]));
    pl_json_set(&b, doc, "boundaries", o);
    if (sim->colloids) {
        const pl_colloid_depl_info_t *d = &sim->colloids->depl;
        b.prefix = "colloid_pairs";
        o = json_object();
        pl_json_real(&b, o, "sigma_cc", d->sigma_cc);
        pl_json_str(&b, o, "sigma_rule", d->rule == PL_SIGMA_PL ? "pl" : "fixed");
        pl_json_real(&b, o, "d_match", d->d_match);
        pl_json_real(&b, o, "phi_cc_at_d_match", d->phi_match);
        pl_json_real(&b, o, "depletion_at_sigma_cc", d->phi_sigma);
        pl_json_set(&b, o, "depletion_comp", json_boolean(d->table_n));
        pl_json_set(&b, doc, "colloid_pairs", o);
    }
    if (rc || b.failed || !doc) {
        json_decref(doc);
        return rc ? rc : b.failed ? err->code : pl_err_set(err, PL_ERR_NOMEM, "out of memory building JSON");
    }
    *out = doc;
    return 0;
}

/* summary.json: the head and what the run measured. */
static int write_summary(const writer_t *w, json_t *doc, const pl_sim_t *sim, long long first, double wall,
                         pl_err_t *err)
{
    char path[PATH_MAX], tmp[PATH_MAX + 8], topo[256];
    pl_topology_summary(topo, sizeof topo);
    double updates = (double)(sim->step - first) * (double)sim->fluid.n;
    pl_json_t b = {err, path, "", 0};
    pl_path_join(path, sizeof path, w->dir, "summary.json");
    pl_json_int(&b, doc, "threads", sim->nthreads);
    pl_json_str(&b, doc, "topology", topo);
    pl_json_int(&b, doc, "fluid_particles", (long long)sim->fluid.n);
    pl_json_int(&b, doc, "first_step", first);
    pl_json_int(&b, doc, "last_step", sim->step);
    pl_json_real(&b, doc, "wall_seconds", wall);
    pl_json_real(&b, doc, "particle_updates_per_second", wall > 0 ? updates / wall : 0.0);
    if (sim->field_acc) /* 0: no sample was taken, no fields.h5 */
        pl_json_int(&b, doc, "field_samples", sim->field_samples);
    json_t *st = json_object();
    b.prefix = "stage_seconds";
    for (int k = 0; k < sim->nstages; ++k) pl_json_real(&b, st, sim->stages[k].name, sim->stages[k].seconds);
    pl_json_set(&b, doc, "stage_seconds", st);
    if (b.failed) return err->code;
    FILE *f = pl_file_begin(path, tmp, sizeof tmp, err);
    if (!f) return PL_ERR_IO;
    if (pl_json_dump(doc, f, tmp, err)) {
        fclose(f);
        remove(tmp);
        return PL_ERR_IO;
    }
    return pl_file_commit(f, tmp, path, err);
}

static int write_checkpoint(const writer_t *w, const pl_sim_t *sim, pl_err_t *err)
{
    char path[PATH_MAX];
    pl_path_join(path, sizeof path, w->dir, "checkpoint.h5");
    return pl_checkpoint_write(sim, path, err);
}

static int write_scene_echo(const writer_t *w, const pl_scene_t *sc, pl_err_t *err)
{
    char path[PATH_MAX], tmp[PATH_MAX + 8];
    pl_path_join(path, sizeof path, w->dir, "scene.cfg");
    FILE *f = pl_file_begin(path, tmp, sizeof tmp, err);
    if (!f) return PL_ERR_IO;
    fprintf(f, "# effective scene of %s (every key, defaults filled in)\n", sc->path);
    pl_scene_print(sc, f);
    errno = 0;
    if (fflush(f) || ferror(f) || fsync(fileno(f))) { /* name the system error */
        int e = errno;
        fclose(f);
        unlink(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: write failed: %s", tmp, e ? strerror(e) : "stream error");
    }
    return pl_file_commit(f, tmp, path, err);
}

static int loop(pl_sim_t *sim, writer_t *w, pl_progress_t *pg, long long last, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    long long first = sim->step;
    w->t_start = w->t_last_row = omp_get_wtime();
    w->step_last_row = first;
    int rc = 0;
    if ((first == 0 || first % sc->output.thermo_interval == 0) && (rc = thermo_row(w, sim, err))) return rc;
    while (sim->step < last) {
        /* the last good colloid frame, for a guard stop inside this step */
        if (sim->colloid_traj)
            pl_colloid_traj_hold(sim->colloid_traj, sim->colloids, sim->step, (double)sim->step * sc->srd.dt);
        rc = pl_sim_step(sim, err);
        if (rc == PL_ERR_GUARD && sim->colloid_traj) pl_colloid_traj_write_held(sim->colloid_traj, sim->colloids, NULL);
        if (rc) return rc;
        const int row = sim->step % sc->output.thermo_interval == 0 || sim->step == last;
        const int ckpt = sc->output.checkpoint_interval > 0 && sim->step % sc->output.checkpoint_interval == 0;
        /* the guard's particle scan before anything is written (the stage
         * scanned this state already on multiples of its interval) */
        if ((row || ckpt) && sim->fluid.n > 0 && sim->step % PL_FLUID_GUARD_SCAN_INTERVAL != 0 &&
            (rc = pl_fluid_guard_check(sim, sim->step, 1, err))) {
            if (sim->colloid_traj) pl_colloid_traj_write_held(sim->colloid_traj, sim->colloids, NULL);
            return rc;
        }
        if (row && (rc = thermo_row(w, sim, err))) return rc;
        if (ckpt && (rc = write_checkpoint(w, sim, err))) return rc;
        pl_progress_update(pg, sim->step);
    }
    return 0;
}

int pl_run(const pl_scene_t *scene, const pl_run_opts_t *o, pl_err_t *err)
{
    pl_sim_t *sim = NULL;
    json_t *summary = NULL;
    pl_progress_t *pg = NULL;
    int traj_written = 0;
    writer_t w;
    memset(&w, 0, sizeof w);
    int rc = pl_sim_create(scene, o->threads, &sim, err);
    if (rc) return rc;
    if (o->restart_changed && !o->restart) {
        rc = pl_err_set(err, PL_ERR_INPUT, "--restart-changed needs --restart CHECKPOINT");
        goto done;
    }
    if (o->restart_changed && (rc = pl_checkpoint_changed_keys_valid(o->restart_changed, err))) goto done;
    if (o->restart && (rc = pl_checkpoint_restart(sim, o->restart, o->restart_changed, err))) goto done;
    long long first = sim->step, nsteps = o->steps >= 0 ? o->steps : scene->run.steps, last;
    if (__builtin_add_overflow(first, nsteps, &last) || last > PL_RUN_MAX_STEP) {
        rc = pl_err_set(err, PL_ERR_INPUT,
                        "%s: checkpoint step %lld + %lld steps passes the largest step %lld; allowed: a step "
                        ">= 0 whose run ends by step %lld", o->restart ? o->restart : scene->path, first, nsteps,
                        (long long)PL_RUN_MAX_STEP, (long long)PL_RUN_MAX_STEP);
        goto done;
    }
    long long md_last; /* the colloid MD step counter: substeps per collision step */
    if (sim->colloids && (__builtin_mul_overflow(nsteps, (long long)scene->colloids.substeps, &md_last) ||
                          __builtin_add_overflow(md_last, sim->colloids->md_step, &md_last) ||
                          md_last > PL_RUN_MAX_STEP)) {
        rc = pl_err_set(err, PL_ERR_INPUT,
                        "%s: colloid MD step %lld + %lld steps x %lld substeps passes the largest step %lld",
                        o->restart ? o->restart : scene->path, sim->colloids->md_step, nsteps,
                        (long long)scene->colloids.substeps, (long long)PL_RUN_MAX_STEP);
        goto done;
    }
    /* a restarted state must pass the fluid guard before anything is written */
    if (o->restart && pl_fluid_guard_check(sim, first, 1, err)) {
        char why[sizeof err->msg];
        snprintf(why, sizeof why, "%s", err->msg);
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: the checkpointed state fails the fluid guard: %.700s", o->restart,
                        why);
        goto done;
    }
    if ((rc = summary_head(sim, &summary, err))) goto done;
    char given[PATH_MAX];
    if (o->out_dir && strlen(o->out_dir) >= sizeof given) {
        rc = pl_err_set(err, PL_ERR_INPUT, "--out %.80s...: %zu characters; allowed: < %d", o->out_dir,
                        strlen(o->out_dir), PATH_MAX - 32);
        goto done;
    }
    if (o->out_dir) snprintf(given, sizeof given, "%s", o->out_dir);
    else snprintf(given, sizeof given, "out/%s", scene->run.name);
    if ((rc = pl_outdir_prepare(given, o->force, scene->path, w.dir, sizeof w.dir, err))) goto done;
    if ((rc = write_scene_echo(&w, &sim->scene, err))) goto done;
    char path[PATH_MAX];
    pl_path_join(w.thermo_path, sizeof w.thermo_path, w.dir, "thermo.tsv");
    if (!(w.thermo = fopen(w.thermo_path, "w"))) {
        rc = pl_err_set(err, PL_ERR_IO, "%s: cannot write: %s", w.thermo_path, strerror(errno));
        goto done;
    }
    thermo_header(w.thermo, scene->mapping.enabled, sim->fluid.tracked, noslip_walls(sim), noslip_side_walls(sim),
                  sim->colloids != NULL, reflecting(sim), sim->coupling && sim->coupling->pinned);
    if (sim->colloids && scene->colloids.trajectory_interval > 0) {
        const pl_mapping_t *m = &scene->mapping.map;
        char xyz[PATH_MAX];
        pl_path_join(path, sizeof path, w.dir, "colloids.h5");
        pl_path_join(xyz, sizeof xyz, w.dir, "colloids.xyz");
        pl_colloid_traj_params_t tp = {.a0_m = scene->mapping.enabled ? m->a0 : 0.0,
                                       .t0_s = scene->mapping.enabled ? m->t0 : 0.0,
                                       .m_f_kg = scene->mapping.enabled ? m->m_f : 0.0,
                                       .xyz_path = scene->output.colloids_xyz ? xyz : NULL, .overwrite = 1};
        if ((rc = pl_colloid_traj_open(path, sim->colloids, &tp, &sim->colloid_traj, err))) goto done;
    }
    FILE *log = o->log; /* the driver's stream; NULL: quiet */
    if (log)
        fprintf(log, "peloid: %s: %zu fluid particles, %d thread(s), steps %lld..%lld -> %s/\n",
                scene->run.name, sim->fluid.n, sim->nthreads, first, last, w.dir);
    if (log && sim->colloids && (sim->colloids->pair.terms & PL_CT_DLVO)) {
        const pl_colloid_dlvo_info_t *d = &sim->colloids->dlvo;
        fprintf(log, "peloid: DLVO: primary minimum matched at gap %.4g a0 (curvature %.4g kT/a0^2); "
                        "barrier %.4g kT at %.4g a0; secondary minimum %.4g kT at %.4g a0; cut-off gap "
                        "%.4g a0, truncation error |V| = %.3g kT, |F| = %.3g kT/a0\n",
                d->hm, d->curvature, d->barrier_u, d->barrier_h, d->secmin_u, d->secmin_h, d->hcut,
                d->trunc_u, d->trunc_f);
    }
    if (log && sim->colloids && (sim->colloids->pair.terms & (PL_CT_WCA | PL_CT_DEPL))) {
        const pl_colloid_depl_info_t *d = &sim->colloids->depl;
        fprintf(log, "peloid: colloid-colloid sigma_cc = %.6g a0 (%s); phi_cc = %.4g kT at twice the "
                        "colloid-fluid cut-off %.6g a0; depletion potential at sigma_cc %.4g kT "
                        "(PL Eqs. 22-23)%s\n",
                d->sigma_cc, d->rule == PL_SIGMA_PL ? "wca.sigma_rule = pl, PL Sec. III.C.1" : "wca.sigma",
                d->phi_match, d->d_match, d->phi_sigma,
                d->table_n ? "; compensated by depletion_comp" : "");
    }
    pl_progress_params_t pp = {.out = o->log, .terminal = o->progress, .interval_s = scene->output.progress_s,
                               .first = first, .last = last, .dt = scene->srd.dt,
                               .t0_s = scene->mapping.enabled ? scene->mapping.map.t0 : 0.0,
                               .fluid_n = (double)sim->fluid.n,
                               .md_per_step = colloid_md_moves(sim) ? (double)scene->colloids.substeps : 0.0};
    pg = pl_progress_create(&pp);
    double t0 = omp_get_wtime();
    rc = loop(sim, &w, pg, last, err);
    double wall = omp_get_wtime() - t0;
    errno = 0;
    int thermo_bad = fflush(w.thermo) != 0 || fsync(fileno(w.thermo)) != 0;
    int thermo_errno = errno;
    thermo_bad |= fclose(w.thermo) != 0;
    w.thermo = NULL;
    if (rc) goto done; /* the last good checkpoint stays as it was */
    if (thermo_bad) {
        rc = pl_err_set(err, PL_ERR_IO, "%s: closing failed: %s", w.thermo_path,
                        strerror(thermo_errno ? thermo_errno : errno));
        goto done;
    }
    if (sim->colloid_traj) { /* the final state is always the last frame */
        rc = pl_colloid_traj_write(sim->colloid_traj, sim->colloids, sim->step, (double)sim->step * scene->srd.dt,
                                   err);
        if (!rc) rc = pl_colloid_traj_close(sim->colloid_traj, err);
        else pl_colloid_traj_close(sim->colloid_traj, NULL);
        traj_written = 1;
        sim->colloid_traj = NULL;
        if (rc) goto done;
    }
    if ((rc = write_checkpoint(&w, sim, err))) goto done;
    if (sim->field_acc && sim->field_samples == 0) {
        pl_progress_note(pg, "no field sample was taken (output.fields_start = %lld, last step %lld): "
                             "fields.h5 not written", scene->output.fields_start, sim->step);
    } else if (sim->field_acc) {
        pl_path_join(path, sizeof path, w.dir, "fields.h5");
        if ((rc = pl_fields_write(sim, path, err))) goto done;
    }
    rc = write_summary(&w, summary, sim, first, wall, err);
    if (!rc) {
        static const char *const names[] = {"scene.cfg", "thermo.tsv", "colloids.h5", "colloids.xyz",
                                            "fields.h5", "fields.xdmf", "checkpoint.h5", "summary.json"};
        const int wrote[] = {1, 1, traj_written, traj_written && scene->output.colloids_xyz,
                             sim->field_acc && sim->field_samples > 0, sim->field_acc && sim->field_samples > 0, 1, 1};
        for (size_t k = 0; k < sizeof names / sizeof *names; ++k)
            if (wrote[k]) pl_progress_file(pg, w.dir, names[k]);
        pl_progress_finish(pg, sim->step);
    }
done:
    pl_progress_free(pg);
    if (w.thermo) fclose(w.thermo);
    json_decref(summary);
    pl_sim_free(sim);
    return rc;
}
