/* The list of output files (peloid/outputs.h, src/io/outputs.c) and the
 * writer rows (peloid/writer.h, src/app/writers.c): every name once, the
 * files the run's closing list names in order first (list_outputs of
 * src/app/run.c walks that prefix); the writers a fluid scene wants add
 * their stages after the thermo rows' and write their files at the end,
 * and a writer not wanted writes nothing. */
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "peloid/checkpoint.h"
#include "peloid/io.h"
#include "peloid/writer.h"
#include "support.h"

Test(writer_rows, outputs_listed_once)
{
    size_t n = 0;
    while (pl_outputs[n].name) ++n;
    cr_assert_gt(n, (size_t)PL_OUT_TABLE_COPY);
    for (size_t i = 0; i < n; ++i) {
        cr_expect(pl_outputs[i].name[0], "entry %zu has a name", i);
        for (size_t j = i + 1; j < n; ++j) cr_expect_str_neq(pl_outputs[i].name, pl_outputs[j].name);
        if (i > 0 && pl_outputs[i].listed)
            cr_expect(pl_outputs[i - 1].listed, "%s: listed ones first", pl_outputs[i].name);
    }
    cr_expect_str_eq(pl_outputs[PL_OUT_CHECKPOINT].name, "checkpoint.h5");
    cr_expect_str_eq(pl_outputs[PL_OUT_COLLOIDS].name, "colloids.h5");
    cr_expect_str_eq(pl_outputs[PL_OUT_FIELDS].name, "fields.h5");
}

static int exists(const char *dir, pl_output_id_t id)
{
    char path[PATH_MAX];
    pl_path_join(path, sizeof path, dir, pl_outputs[id].name);
    return access(path, F_OK) == 0;
}

Test(writer_rows, fluid_scene_writers)
{
    pl_sim_t *sim = pl_test_sim("seed = 2;\nbox: { cells = [6, 6, 6]; };\nfluid: { density = 4.0; };\n"
                                "output: { checkpoint_interval = 2; fields_interval = 1; };\n", 1);
    char dir[] = "/tmp/peloid-writers.XXXXXX";
    cr_assert(mkdtemp(dir));
    pl_writers_t ws;
    memset(&ws, 0, sizeof ws);
    pl_writer_out_t out = {.dir = dir};
    pl_err_t err = {0, ""};
    cr_assert_eq(pl_writers_open(sim, &out, &ws, &err), 0, "%s", err.msg);
    int ck = -1, traj = -1;
    for (int k = 0; k < sim->nstages; ++k) {
        if (!strcmp(sim->stages[k].name, "checkpoint")) ck = k;
        if (!strcmp(sim->stages[k].name, "colloid-trajectory")) traj = k;
    }
    cr_assert_geq(ck, 0, "the checkpoint stage");
    cr_expect(sim->stages[ck].interval == 2 && sim->stages[ck].slot == PL_SLOT_WRITE && sim->stages[ck].writes);
    cr_expect_eq(traj, -1, "no colloids: no trajectory");
    cr_assert_eq(pl_sim_begin(sim, 3, &err), 0, "%s", err.msg);
    pl_test_steps(sim, 3);
    cr_expect(exists(dir, PL_OUT_CHECKPOINT), "the stage wrote the checkpoint of step 2");
    cr_expect(!exists(dir, PL_OUT_FIELDS), "fields only at the end");
    cr_assert_eq(pl_writers_finish(sim, &ws, &out, &err), 0, "%s", err.msg);
    pl_writers_close(&ws);
    cr_expect(exists(dir, PL_OUT_FIELDS) && exists(dir, PL_OUT_FIELDS_XDMF));
    cr_expect(!exists(dir, PL_OUT_COLLOIDS));
    long long step = -1;
    char path[PATH_MAX];
    pl_path_join(path, sizeof path, dir, pl_outputs[PL_OUT_CHECKPOINT].name);
    cr_expect(pl_checkpoint_step(path, &step) == 0 && step == 3, "the last state's checkpoint (step %lld)", step);
    for (int id = 0; pl_outputs[id].name; ++id) { /* the files it wrote */
        pl_path_join(path, sizeof path, dir, pl_outputs[id].name);
        unlink(path);
    }
    cr_expect_eq(rmdir(dir), 0, "no other file");
    pl_sim_free(sim);
}
