/* Observer part of the checkpoint (the groups /observe and /stress that
 * src/observe/observe_module.c and stress_module.c write): each group carries
 * the observer fingerprint, attributes observe_keys (every observe.* key but
 * observe.target_rel_error, pl_ckpt_observe_text) and observe_fingerprint
 * (its FNV-1a hash).  The scene fingerprint leaves observe.* out, so a restart
 * may change the observers: with the same fingerprint they resume, with
 * another, or from a checkpoint without the group (written before peloid
 * saved observer state), or after --restart-changed (the physics changed:
 * src/core/checkpoint.c), they start afresh and the restart's record says
 * why (pl_sim_observers_afresh). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint_h5.h"
#include "peloid/checkpoint.h"
#include "peloid/h5.h"
#include "peloid/sim.h"

hid_t pl_ckpt_observe_group_write(hid_t f, const char *name, const pl_scene_t *sc)
{
    char *text = pl_ckpt_observe_text(sc);
    if (!text) return -1;
    hid_t g = pl_ckpt_group_create(f, name);
    long long h = (long long)pl_ckpt_fnv1a(text, strlen(text));
    if (g >= 0 && (pl_h5_attr_str(g, "observe_keys", text) || pl_ckpt_attr_i64(g, "observe_fingerprint", &h, 1, 1))) {
        H5Gclose(g);
        g = -1;
    }
    free(text);
    return g;
}

/* The first key whose line differs between fingerprint texts a and b. */
static void first_difference(const char *a, const char *b, char *key, size_t n)
{
    snprintf(key, n, "?");
    while (*a || *b) {
        const char *ea = strchr(a, '\n'), *eb = strchr(b, '\n');
        size_t la = ea ? (size_t)(ea - a) : strlen(a), lb = eb ? (size_t)(eb - b) : strlen(b);
        if (la != lb || strncmp(a, b, la)) {
            const char *line = la ? a : b;
            size_t k = strcspn(line, " \n");
            snprintf(key, n, "%.*s", (int)(k < 100 ? k : 100), line);
            return;
        }
        a += la + (ea != NULL);
        b += lb + (eb != NULL);
    }
}

hid_t pl_ckpt_observe_group_open(hid_t f, const char *name, pl_sim_t *sim)
{
    if (pl_sim_observers_resumed(sim, NULL) == 0) return -1; /* afresh already (--restart-changed, another group) */
    if (H5Lexists(f, name, H5P_DEFAULT) <= 0) {
        pl_sim_observers_afresh(sim, "the checkpoint holds no observer state (/%s; written before peloid saved it, "
                                     "or without observers): the observers start afresh at the restart step", name);
        return -1;
    }
    hid_t g = H5Gopen2(f, name, H5P_DEFAULT);
    if (g < 0) return -1;
    char *mine = pl_ckpt_observe_text(&sim->scene), *theirs = pl_ckpt_attr_str_read(g, "observe_keys");
    int same = mine && theirs && !strcmp(mine, theirs);
    if (!same) {
        char key[128];
        first_difference(mine ? mine : "", theirs ? theirs : "", key, sizeof key);
        pl_sim_observers_afresh(sim, "the observe section differs from the checkpoint's (first: %s): the observers "
                                     "start afresh at the restart step", key);
        H5Gclose(g);
        g = -1;
    } else {
        pl_sim_observers_resume(sim); /* unless one observer started afresh: the run says so */
    }
    free(mine);
    free(theirs);
    return g;
}
