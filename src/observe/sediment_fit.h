/* The initial (homogeneous-fall) settling velocity of the sedimentation
 * observer (src/observe/sediment_fit.c). */
#ifndef PELOID_SEDIMENT_FIT_H
#define PELOID_SEDIMENT_FIT_H

#include <stddef.h>

#include "json_build.h"

typedef struct {
    double value, se;  /* mean settling sample over the window and its SE */
    size_t window;     /* samples from the first: the homogeneous fall (0: none found) */
    double z_window;   /* |first half - second half| / SE inside the window (< 2) */
    double z_whole;    /* the same over every sample: >= 2 says the run's mean mixes states */
} pl_sediment_fit_t;

/* v: the n settling samples in order (positive down); 0, or -1 when fewer than 16 samples
 * or no prefix of 16 or more is homogeneous (out->z_whole is set either way). */
int pl_sediment_initial(const double *v, size_t n, pl_sediment_fit_t *out);

/* summary.json: "initial_settling_velocity" in `all` (value, SE, window,
 * Stokes and Richardson-Zaki at the scene's phi, model units and m/s), and
 * the run's "settling_velocity" (already in `all`) marked for what it
 * averages (its plateau false when its halves differ by 2 SE or more).
 * v, step: the n settling samples (positive down) and their steps. */
struct pl_scene;
void pl_sediment_summary(pl_json_t *b, struct json_t *all, const struct pl_scene *sc, const double *v,
                         const long long *step, size_t n);
/* its name (the sedimentation row's entries, NULL-terminated) */
extern const char *const pl_sediment_entries[];

#endif
