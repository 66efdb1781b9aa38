/* pl_input_open (peloid/input_file.h): open, then fstat the descriptor
 * (the file checked is the file read, whatever a name or link points to),
 * then a stream.  O_NONBLOCK keeps open from waiting on a pipe without a
 * writer; it is cleared again for the read. */
#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "peloid/input_file.h"

static const char *kind(mode_t m)
{
    if (S_ISDIR(m)) return "is a directory";
    if (S_ISCHR(m)) return "is a character device, not a regular file";
    if (S_ISBLK(m)) return "is a block device, not a regular file";
    if (S_ISFIFO(m)) return "is a pipe (FIFO), not a regular file";
    if (S_ISSOCK(m)) return "is a socket, not a regular file";
    return "is not a regular file";
}

FILE *pl_input_open(const char *path, long long max_bytes, char *why, size_t n)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        snprintf(why, n, "cannot open: %s", strerror(errno));
        return NULL;
    }
    struct stat st;
    FILE *f = NULL;
    if (fstat(fd, &st)) snprintf(why, n, "cannot stat: %s", strerror(errno));
    else if (!S_ISREG(st.st_mode)) snprintf(why, n, "%s", kind(st.st_mode));
    else if (max_bytes > 0 && (long long)st.st_size > max_bytes)
        snprintf(why, n, "has %lld bytes, more than %lld", (long long)st.st_size, max_bytes);
    else if (fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK) || !(f = fdopen(fd, "r")))
        snprintf(why, n, "cannot open: %s", strerror(errno));
    if (!f) close(fd);
    return f;
}
