/* Error reporting: fallible functions return int (0 = ok) and write one line
 * into a pl_err_t; only src/app/main.c prints it and picks the exit code
 * (STYLE.md 8, DESIGN.md "Errors"). */
#ifndef PELOID_ERROR_H
#define PELOID_ERROR_H

#include <stddef.h>

enum {
    PL_OK = 0,
    PL_ERR_INPUT = 2,  /* bad scene / command line: nothing was run or written */
    PL_ERR_GUARD = 3,  /* a stability guard tripped during the run             */
    PL_ERR_IO = 4,     /* file system / HDF5 failure                           */
    PL_ERR_NOMEM = 5,
    PL_ERR_INTERNAL = 6, /* a program limit or invariant (a bug to report)     */
    /* a signal ended the run early: its outputs and checkpoint are complete
     * at the step reached; the driver exits with 128 + the signal number */
    PL_ERR_INTERRUPTED = 7,
};

typedef struct pl_err {
    int code;
    char msg[1024];
} pl_err_t;

/* Sets code and a printf-formatted one-line message; returns code. */
int pl_err_set(pl_err_t *err, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

void pl_err_clear(pl_err_t *err);

#endif
