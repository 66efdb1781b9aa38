/* The list of output files (peloid/outputs.h): the only place that names
 * them. */
#include <stddef.h>

#include "peloid/outputs.h"

const pl_output_t pl_outputs[] = {
    [PL_OUT_SCENE] = {"scene.cfg", 1},
    [PL_OUT_INIT_COPY] = {"colloids_init.txt", 1},
    [PL_OUT_THERMO] = {"thermo.tsv", 1},
    [PL_OUT_COLLOIDS] = {"colloids.h5", 1},
    [PL_OUT_COLLOIDS_XYZ] = {"colloids.xyz", 1},
    [PL_OUT_FIELDS] = {"fields.h5", 1},
    [PL_OUT_FIELDS_XDMF] = {"fields.xdmf", 1},
    [PL_OUT_OBSERVABLES] = {"observables.h5", 1},
    [PL_OUT_CHECKPOINT] = {"checkpoint.h5", 1},
    [PL_OUT_SUMMARY] = {"summary.json", 1},
    [PL_OUT_TABLE_COPY] = {"pair_table.txt", 0},
    /* `peloid report` */
    {"report.md", 0},
    {"rdf.png", 0},
    {"rdf_classes.png", 0},
    {"sq.png", 0},
    {"cff.png", 0},
    {"bonds.png", 0},
    {"msd.png", 0},
    {"clusters.png", 0},
    {"vdist.png", 0},
    {"sediment_phi.png", 0},
    {"viscosity.png", 0},
    {"thermo.png", 0},
    {"sediment.png", 0},
    {NULL, 0},
};
