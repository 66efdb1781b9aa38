/* Opening a file that a scene names as input (colloids.table_file,
 * colloids.init_file): only a regular file of bounded size, so that a name
 * linked to a device (/dev/zero), a pipe or a directory is refused before
 * anything is read (src/io/input_file.c). */
#ifndef PELOID_INPUT_FILE_H
#define PELOID_INPUT_FILE_H

#include <stddef.h>
#include <stdio.h>

/* Opens path for reading when it is a regular file of at most max_bytes
 * (max_bytes <= 0: no bound).  Otherwise NULL, and why (n bytes) says what
 * it is instead, e.g. "is a directory", "is a character device, not a
 * regular file", "has 5000000000 bytes, more than 16777216", or the
 * system error of open.  A pipe is opened without waiting for a writer. */
FILE *pl_input_open(const char *path, long long max_bytes, char *why, size_t n);

#endif
