/* The step a checkpoint holds, read without a simulation: `peloid sweep`
 * resumes a point whose run was killed (no summary.json) from its last
 * checkpoint for the steps it has left (src/app/sweep.c). */
#include "checkpoint_h5.h"
#include "peloid/checkpoint.h"
#include "peloid/io.h"

int pl_checkpoint_step(const char *path, long long *step)
{
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0) return -1;
    long long meta[8]; /* "peloid_checkpoint": step first (src/core/checkpoint.c) */
    int rc = pl_ckpt_attr_i64(f, "peloid_checkpoint", meta, 8, 0);
    H5Fclose(f);
    if (rc || meta[0] < 0) return -1;
    *step = meta[0];
    return 0;
}
