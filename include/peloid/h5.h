/* Small HDF5 helpers shared by the writers (checkpoint, fields, colloid
 * trajectory).  Objects are created without time stamps, so that equal
 * content gives equal bytes (bitwise-comparable outputs). */
#ifndef PELOID_H5_H
#define PELOID_H5_H

#include <hdf5.h>
#include <stddef.h>

hid_t pl_h5_group(hid_t parent, const char *name);
/* 0 or -1. */
int pl_h5_attr_str(hid_t obj, const char *name, const char *value);
/* Scalar variable-length UTF-8 string attribute: what h5py reads back as
 * str (MDAnalysis' H5MD reader looks `unit` strings up as str; a
 * fixed-length string reads back as bytes and is not recognised). */
int pl_h5_attr_vlstr(hid_t obj, const char *name, const char *value);
/* Double attribute: scalar (n = 1) or n values; 0 or -1. */
int pl_h5_attr_doubles(hid_t obj, const char *name, const double *v, hsize_t n);
/* Dataset of `rank` dims (rank 0: scalar) written in one go; 0 or -1. */
int pl_h5_write(hid_t parent, const char *name, hid_t type, int rank, const hsize_t *dims,
                const void *data);
/* Silences HDF5's automatic error-stack printing (our one-line messages
 * instead). */
void pl_h5_quiet(void);
/* Once at program start, before any other HDF5 call (src/app/main.c): no HDF5
 * exit handler (it crashes after a failed H5Fclose), no automatic error
 * printing. */
void pl_h5_init_process(void);
/* One line describing the HDF5 failure on the current error stack: the
 * system error text of a failed low-level write (e.g. "No space left on
 * device") when there is one, else the innermost HDF5 description, else
 * strerror(errno).  Call right after the failing HDF5 call. */
void pl_h5_error_text(char *buf, size_t n);
/* The H5MD 1.1 header group /h5md (version, author, creator); 0 or -1. */
int pl_h5_h5md_header(hid_t file);
/* The H5MD units module /h5md/modules/units (version 1.0, system: "SI"),
 * after pl_h5_h5md_header; 0 or -1. */
int pl_h5_h5md_units(hid_t file, const char *system);

#endif
