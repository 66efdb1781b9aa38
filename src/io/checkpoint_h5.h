/* HDF5 helpers of the checkpoint writer and reader (src/core/checkpoint.c)
 * and of the components' checkpoint items (peloid/checkpoint.h): checksummed
 * 1-d datasets, attributes, groups.  Every object is created without time
 * stamps, so the same state gives the same bytes. */
#ifndef PELOID_CHECKPOINT_H5_H
#define PELOID_CHECKPOINT_H5_H

#include <hdf5.h>
#include <stdint.h>

#include "peloid/error.h"

/* Format of the files pl_checkpoint_write writes (root attribute
 * "format_version"); the reader refuses any other.  2: per-dataset
 * checksums and the scene fingerprint. */
enum { PL_CKPT_FORMAT = 2 };

/* 64-bit FNV-1a hash of n bytes (the per-dataset checksum). */
uint64_t pl_ckpt_fnv1a(const void *data, size_t n);
/* The same continued over more bytes: pl_ckpt_fnv1a(a b) =
 * pl_ckpt_fnv1a_more(pl_ckpt_fnv1a(a), b). */
uint64_t pl_ckpt_fnv1a_more(uint64_t h, const void *data, size_t n);

/* 1-d dataset `name` of n elements under g, with the attribute "fnv1a64":
 * the FNV-1a hash of its n elements' bytes in memory; 0 or -1.  type must be
 * a native type (file and memory bytes are then the same). */
int pl_ckpt_write_1d(hid_t g, const char *name, hid_t type, const void *data, size_t n);
/* Reads dataset `name` and verifies its checksum; on failure sets err
 * (PL_ERR_INPUT, naming path and dataset: missing, not 1-d, not of length n,
 * unreadable, or checksum mismatch) and returns its code. */
int pl_ckpt_read_1d(hid_t g, const char *name, hid_t type, void *data, size_t n, const char *path,
                    pl_err_t *err);
/* String attribute (write: 0 or -1; read: malloc'ed text or NULL). */
char *pl_ckpt_attr_str_read(hid_t obj, const char *name);

/* Writes (write != 0) or reads an n-element int64 attribute; a read of an
 * attribute with another element count fails (-1). */
int pl_ckpt_attr_i64(hid_t obj, const char *name, long long *v, int n, int write);
/* Group without time stamps; < 0 on failure. */
hid_t pl_ckpt_group_create(hid_t f, const char *name);

#endif
