/* `peloid sweep --slurm`: the job-array scripts of a study (sweep.c
 * prepares the points' scenes first). */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sweep_priv.h"

/* The Slurm job array: task K runs point K; collect.sbatch the table. */
int pl_sweep_write_slurm(const sweep_t *s, pl_err_t *err)
{
    char path[4096], study[4096], out[4096], self[4096], b[16384];
    if (!realpath(pl_study_path(s->st), study) || !realpath(s->out, out) || !realpath(s->o->self, self))
        return pl_err_set(err, PL_ERR_IO, "%s: cannot resolve the study, OUT or peloid path: %s",
                          pl_study_path(s->st), strerror(errno));
    int threads = s->o->threads > 0 ? s->o->threads : 1;
    int len = snprintf(b, sizeof b,
             "#!/bin/bash\n"
             "# peloid sweep %s: one Slurm array task per point (written by peloid sweep --slurm).\n"
             "#   submit: bash %s/submit.sh   (or: sbatch %s/sweep.sbatch, then sbatch %s/collect.sbatch)\n"
             "# Task K runs point K; a finished point is skipped, so resubmitting reruns only the rest.\n"
             "#SBATCH --job-name=%s\n#SBATCH --array=0-%d\n#SBATCH --cpus-per-task=%d\n#SBATCH --ntasks=1\n"
             "#SBATCH --output=%s/logs/slurm-%%A_%%a.out\n"
             "exec %s sweep %s --out %s --point \"$SLURM_ARRAY_TASK_ID\" --threads \"${SLURM_CPUS_PER_TASK:-%d}\"%s%s\n",
             pl_study_name(s->st), out, out, out, pl_study_name(s->st), s->n - 1, threads, out, self, study, out,
             threads, s->o->calibrate ? " --calibrate " : "", s->o->calibrate ? s->o->calibrate : "");
    snprintf(path, sizeof path, "%s/sweep.sbatch", s->out);
    int rc = len < 0 || (size_t)len >= sizeof b ? pl_err_set(err, PL_ERR_INPUT, "%s: paths too long", s->out)
                                                 : pl_sweep_write_text(path, b, err);
    len = snprintf(b, sizeof b,
             "#!/bin/bash\n# peloid sweep %s: the table and plot of every point (after the array).\n"
             "#SBATCH --job-name=%s-collect\n#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n"
             "#SBATCH --output=%s/logs/slurm-collect-%%j.out\n"
             "exec %s sweep %s --out %s --collect\n", pl_study_name(s->st), pl_study_name(s->st), out, self, study, out);
    snprintf(path, sizeof path, "%s/collect.sbatch", s->out);
    if (!rc && (len < 0 || (size_t)len >= sizeof b)) rc = pl_err_set(err, PL_ERR_INPUT, "%s: paths too long", s->out);
    if (!rc) rc = pl_sweep_write_text(path, b, err);
    len = snprintf(b, sizeof b,
             "#!/bin/bash\n# Submits the array, then the collect step after it (whatever the tasks' exit codes).\n"
             "set -euo pipefail\njid=$(sbatch --parsable %s/sweep.sbatch)\njid=${jid%%%%;*}\n"
             "sbatch --parsable --dependency=afterany:$jid %s/collect.sbatch\n", out, out);
    snprintf(path, sizeof path, "%s/submit.sh", s->out);
    if (!rc && (len < 0 || (size_t)len >= sizeof b)) rc = pl_err_set(err, PL_ERR_INPUT, "%s: paths too long", s->out);
    if (!rc) rc = pl_sweep_write_text(path, b, err);
    if (!rc)
        fprintf(s->o->log, "peloid sweep %s: wrote %s/{sweep.sbatch,collect.sbatch,submit.sh}: %d array tasks x %d "
                "thread(s); submit with: bash %s/submit.sh\n", pl_study_name(s->st), s->out, s->n, threads, s->out);
    return rc;
}
