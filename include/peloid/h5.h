/* Small HDF5 helpers shared by the writers (checkpoint, fields, colloid
 * trajectory).  Objects are created without time stamps, so that equal
 * content gives equal bytes (bitwise-comparable outputs). */
#ifndef PELOID_H5_H
#define PELOID_H5_H

#include <hdf5.h>

hid_t pl_h5_group(hid_t parent, const char *name);
void pl_h5_attr_str(hid_t obj, const char *name, const char *value);
/* Dataset of `rank` dims (rank 0: scalar) written in one go; 0 or -1. */
int pl_h5_write(hid_t parent, const char *name, hid_t type, int rank, const hsize_t *dims,
                const void *data);
/* The H5MD 1.1 header group /h5md (version, author, creator). */
void pl_h5_h5md_header(hid_t file);

#endif
