/* The study's representation, shared by the files of src/app/ that read
 * and check it (study.c, study_check.c); nothing outside src/app/ sees it. */
#ifndef PELOID_SWEEP_STUDY_PRIV_H
#define PELOID_SWEEP_STUDY_PRIV_H

#include <libconfig.h>
#include <stdio.h>

#include "peloid/scene.h"
#include "peloid/sweep.h"
#include "scene_text.h"

typedef struct {
    char key[128];           /* section.key, or key for the top level */
    char sec[64], leaf[64];
    config_setting_t *values; /* grid: this axis's values */
    int n, line;
} axis_t;

struct pl_study {
    char path[512], name[128], out[512], base[1024];
    pl_scene_text_t stext, btext;
    config_t scfg, bcfg;
    int have_s, have_b;
    axis_t ax[PL_STUDY_MAX_AXES];
    int naxes, npoints;      /* npoints: distinct points (grid or rows) */
    int replicas;            /* runs of each point, seeds seed0 + r (>= 1) */
    long long seed0;         /* the base scene's seed (its default when unset) */
    config_setting_t *rows; /* points{}: one row per point, NULL for a grid */
    config_setting_t *plot;
};

/* "FILE:LINE: key 'KEY': WHAT" at setting s (NULL: line 1); returns PL_ERR_INPUT. */
int pl_study_fail_at(const pl_study_t *st, const config_setting_t *s, pl_err_t *err, const char *key,
                     const char *what);

/* Value setting of axis a at point k (a distinct point: run k / replicas). */
const config_setting_t *pl_study_value_of(const pl_study_t *st, int k, int a);
/* The same as scene text (study_text.c; pl_study_point_value takes a run). */
int pl_study_value_text(const pl_study_t *st, int k, int a, char *buf, size_t n);

/* Refuses a study that would run a point twice: a grid value given twice
 * on one axis, or two equal rows of points{}. */
int pl_study_check_unique(const pl_study_t *st, pl_err_t *err);

/* Refuses a plot.y that names no observable (scene NULL, at load) or one
 * that point k's scene does not measure, naming the study's line of the
 * name, plot.y and the names allowed. */
int pl_study_check_plot(const pl_study_t *st, const pl_scene_t *scene, int k, pl_err_t *err);

/* Writes the settings of group g as libconfig text, indented by depth
 * (study_text.c; text: where integer literals were read, or NULL). */
void pl_study_write_group(FILE *f, const pl_scene_text_t *text, const config_setting_t *g, int depth);

#endif
