/* pl_err_t: the one-line error buffer shared by all modules. */
#include "peloid/error.h"

#include <stdarg.h>
#include <stdio.h>

int pl_err_set(pl_err_t *err, int code, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
        err->code = code;
    }
    return code;
}

void pl_err_clear(pl_err_t *err)
{
    if (err) {
        err->code = 0;
        err->msg[0] = '\0';
    }
}
