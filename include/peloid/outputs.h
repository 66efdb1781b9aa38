/* Every file peloid writes into an output directory, listed once
 * (src/io/outputs.c): `peloid run` (its thermo.tsv, scene.cfg and
 * summary.json, the writer rows of src/app/writers.c, the observers'
 * observables.h5) and `peloid report` (tools/report.py,
 * tools/plot_sediment.py).  --force removes every one (pl_outdir_clean); the
 * run's closing list names those it wrote in this order. */
#ifndef PELOID_OUTPUTS_H
#define PELOID_OUTPUTS_H

/* The files code names, by their index in pl_outputs. */
typedef enum {
    PL_OUT_SCENE,          /* scene.cfg: the effective scene */
    PL_OUT_INIT_COPY,      /* colloids_init.txt: colloids.init_file, copied */
    PL_OUT_THERMO,         /* thermo.tsv */
    PL_OUT_COLLOIDS,       /* colloids.h5: the colloid trajectory (H5MD) */
    PL_OUT_COLLOIDS_XYZ,   /* colloids.xyz: the same as extended XYZ */
    PL_OUT_FIELDS,         /* fields.h5: time-averaged fields (H5MD) */
    PL_OUT_FIELDS_XDMF,    /* fields.xdmf: their mesh for ParaView */
    PL_OUT_OBSERVABLES,    /* observables.h5: the observers' series and estimates */
    PL_OUT_CHECKPOINT,     /* checkpoint.h5 */
    PL_OUT_SUMMARY,        /* summary.json */
    PL_OUT_TABLE_COPY,     /* pair_table.txt: colloids.table_file, copied */
} pl_output_id_t;

typedef struct {
    const char *name;
    /* the run's closing list names it in list order (else among the other
     * files, by name) */
    int listed;
} pl_output_t;

/* Terminated by a NULL name; the first rows in pl_output_id_t order, then
 * the files of `peloid report`. */
extern const pl_output_t pl_outputs[];

#endif
