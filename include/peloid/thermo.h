/* thermo.tsv columns: each module (peloid/module.h) adds its own, each a
 * name, unit and value function.  The header and every row are written from
 * the same table, so a column cannot shift against its name; a module adds
 * a column by adding a row to its table. */
#ifndef PELOID_THERMO_H
#define PELOID_THERMO_H

#include <stdio.h>

#include "peloid/colloid.h"
#include "peloid/error.h"
#include "peloid/fluid.h"
#include "peloid/sim.h"

/* What one row samples once, shared by the value functions. */
typedef struct {
    const pl_sim_t *sim;
    pl_fluid_obs_t fluid; /* pl_sim_observe */
    double kT;            /* fluid temperature, centre-of-mass frame */
    pl_colloid_energy_t ce; /* colloids only */
    double rate;          /* fluid updates per second since the last row (1e6) */
} pl_thermo_sample_t;

typedef enum { PL_THERMO_REAL, PL_THERMO_INT, PL_THERMO_RATE } pl_thermo_format_t;

typedef struct {
    const char *name;
    const char *unit;           /* model units (a0, t0, m_f, kT) or SI */
    pl_thermo_format_t format;  /* %.10g, %lld, %.4g */
    double (*value)(const pl_thermo_sample_t *s, int arg);
    long long (*ivalue)(const pl_thermo_sample_t *s, int arg); /* PL_THERMO_INT */
    int arg;                    /* passed to value (a component, a term) */
    double to_si;               /* an SI twin: the value times this (0: the value itself) */
} pl_thermo_column_t;

/* The columns of this simulation, in order (at most PL_THERMO_MAX_COLUMNS;
 * more is refused by pl_thermo_table_build, never dropped). */
enum { PL_THERMO_MAX_COLUMNS = 128, PL_THERMO_NAME = 48 };
typedef struct {
    pl_thermo_column_t col[PL_THERMO_MAX_COLUMNS];
    char si_name[PL_THERMO_MAX_COLUMNS][PL_THERMO_NAME]; /* the names of the SI twins */
    int n;
    int wanted; /* columns asked for, > n when the table overflowed */
} pl_thermo_table_t;

/* The columns of sim: step and time, each module's, for a scene with
 * physical{} an SI twin of each column in a model length, area, velocity,
 * diffusivity or stress unit (name_<SI unit>, DESIGN.md "Units and
 * mapping"), then the wall-clock rate.  PL_ERR_INTERNAL past the cap. */
int pl_thermo_table_build(const pl_sim_t *sim, pl_thermo_table_t *t, pl_err_t *err);
/* Appends n columns (a module's thermo_columns); those past the cap are
 * counted in t->wanted and refused by pl_thermo_table_build. */
void pl_thermo_add(pl_thermo_table_t *t, const pl_thermo_column_t *c, int n);
void pl_thermo_header(const pl_thermo_table_t *t, FILE *f);
/* Opens thermo.tsv for the rows of a run.  keep < 0: a new file with the
 * header.  keep >= 0 (resume in place): the existing file's rows of steps
 * < keep stay and the rows go after them (a file that is not there is made
 * new); a header other than t's is PL_ERR_INPUT.  PL_ERR_IO naming the file. */
int pl_thermo_open(const pl_thermo_table_t *t, const char *path, long long keep, FILE **out, pl_err_t *err);
/* Samples the state (fluid observables, colloid energies) into s. */
void pl_thermo_sample(const pl_sim_t *sim, double rate, pl_thermo_sample_t *s);
/* One row; returns what fprintf returned last (< 0 on a write error). */
int pl_thermo_row(const pl_thermo_table_t *t, const pl_thermo_sample_t *s, FILE *f);

#endif
