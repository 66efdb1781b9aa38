/* The laws of coupling I's hydrodynamic radius against the resolution, for
 * `peloid plan` and the calibration's table (src/app/advise_match.c). */
#ifndef PELOID_ADVISE_MATCH_H
#define PELOID_ADVISE_MATCH_H

#include "peloid/scene.h"

enum { PL_MATCH_MAX_POINTS = 8 };

typedef struct {
    int found;                  /* a measured law for this scene's fluid */
    char study[64];             /* its study (the file's name after rh_resolution-) */
    int have_match;             /* the law reaches R_h/R = 0.95 */
    double R_match, R_match_se; /* R/a0 where R_h/R = 0.95, its SE */
    int npoints;                /* the measured points */
    double R[PL_MATCH_MAX_POINTS], rh[PL_MATCH_MAX_POINTS];
    double rho_ratio;           /* the study's colloid over fluid mass density */
    char reason[200];           /* without a match: why (the file's words) */
    int checked;                /* a run at the law's matched resolution (the file's "check", R8) */
    double check_R, check_rh, check_rh_se; /* its R/a0 and measured R_h/R with its SE */
    char check_verdict[24];     /* "matched" or "not matched" (R3), "(not settled)" added where R1/R2 fail */
    /* the law R/R_h - 1 = b + c a0/R (b = 0 for the one-parameter form) */
    int law_nparams;            /* 1: c a0/R, 2: b + c a0/R, 0: none read */
    double law_b, law_c;
    double law_cov[2][2];       /* of (b, c) for 2, of c alone in [0][0] for 1; not scaled by chi2/dof */
    double law_chi2;
    int law_dof;
    double rh_se[PL_MATCH_MAX_POINTS]; /* the points' SEs */
    double mass_density;        /* the study's colloid mass density (m_f/a0^3) */
    char path[1400];            /* the law's file */
} pl_advise_match_t;

/* Reads the laws in dir (calibration/rh_resolution-*.json) and fills *m for
 * the scene's fluid (m->found = 0: none measured for it). */
void pl_advise_match(const pl_scene_t *s, const char *dir, pl_advise_match_t *m);

#endif
