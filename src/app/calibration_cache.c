/* The calibration cache of src/app/calibrate.c: one JSON file per
 * parameter set, "calibration-<key>.json", in the cache folder or in the
 * project's calibration/ directory (shipped, read-only).
 *
 * Reading: only a regular file of at most CACHE_MAX_BYTES is read (a FIFO,
 * a device or /dev/zero where an entry should be cannot hang or exhaust a
 * run), and an entry is used only when it is the measurement of this
 * parameter set: the plan its key hashes (box, steps, colloids), the
 * numbers the code derives (phi, the periodic images' D, the hydrodynamic
 * tail beyond the lags, 1 - c phi) to READ_RTOL, d_inf = (d_box + tail +
 * hasimoto) / concentration / kT (as cal_run computes it) to READ_RTOL, a
 * standard error below the value, and d_inf within THEORY_FACTOR of the
 * coupling's theory D either way.  An entry written before the tail was
 * added (no "tail": d_inf = (d_box + hasimoto) / concentration / kT) is
 * checked as written, then given the tail and its d_inf derived again: its
 * measurement, d_box, is the same.
 *
 * Locking: flock(2) on "<entry>.lock", which the kernel releases when its
 * holder exits, however it ends.  The holder records "pid P host H since T"
 * in the lock file, so that a waiter can say who holds it, for how long,
 * and whether that process still exists.  A lock still held while its
 * recorded holder no longer exists on this host (its file was inherited by
 * a child that outlives it) is taken over: the lock file is unlinked and a
 * fresh one locked.  Race-free because taking the lock (flock + record) and
 * taking it over (read record + unlink) both happen under a second flock,
 * on the cache folder itself, held for microseconds and only tried without
 * blocking: a taker always reads the record of the current holder, written
 * before the folder lock was released, or an empty one (released). */
#include <errno.h>
#include <fcntl.h>
#include <jansson.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "calibration_cache.h"
#include "peloid/io.h"
#include "peloid/srd_theory.h"

enum { CACHE_MAX_BYTES = 1 << 16 };
/* The measured D of valid scenes lies between 0.85 and ~800 times the
 * theory's 1/xi (shipped scenes 0.85-2.0; coupling II treats the colloid as
 * a point in the cell collision, so its D does not scale with R as 6 pi eta R
 * does, and cell_size up to 100 R takes it to ~800x at 50 R).  A factor 1e4
 * either way keeps every such scene and refuses values that are no
 * measurement of the model (1e-300, 1e300); a single edited field is caught
 * by the consistency checks, which hold to rounding. */
static const double THEORY_FACTOR = 1e4, READ_RTOL = 1e-9;
static const double LOCK_TIMEOUT_S = 1800.0; /* above the longest shipped calibration (minutes) */
static const double LOCK_REPORT_S = 30.0, LOCK_STOPPED_S = 60.0, LOCK_POLL_S = 0.1;

static const char *const FIELDS[] = {"d_inf", "d_inf_se", "d_box", "d_box_se", "hasimoto", "phi", "wall_s"};
static double *field(pl_mapping_calibration_t *c, int k)
{
    double *f[] = {&c->d_inf, &c->d_inf_se, &c->d_box, &c->d_box_se, &c->hasimoto, &c->phi, &c->wall_s};
    return f[k];
}
enum { NFIELDS = sizeof FIELDS / sizeof FIELDS[0] };

void pl_calcache_dir(char *dir, size_t n)
{
    const char *e = getenv("PELOID_CACHE"), *x = getenv("XDG_CACHE_HOME"), *h = getenv("HOME");
    if (e && *e) snprintf(dir, n, "%s", e);
    else if (x && *x) snprintf(dir, n, "%s/peloid", x);
    else snprintf(dir, n, "%s/.cache/peloid", h && *h ? h : "/tmp");
}

int pl_calcache_dir_prepare(const char *dir, char *why, size_t nwhy)
{
    char b[512];
    snprintf(b, sizeof b, "%s", dir);
    int bad = 0;
    for (char *s = b + 1; *s && !bad; ++s) /* mkdir -p */
        if (*s == '/') {
            *s = '\0';
            bad = mkdir(b, 0755) && errno != EEXIST;
            *s = '/';
        }
    if (bad || (mkdir(b, 0755) && errno != EEXIST)) {
        snprintf(why, nwhy, "cannot create it: %s", strerror(errno));
        return -1;
    }
    struct stat st;
    if (stat(dir, &st)) {
        snprintf(why, nwhy, "%s", strerror(errno));
        return -1;
    }
    if (!S_ISDIR(st.st_mode)) {
        snprintf(why, nwhy, "not a folder");
        return -1;
    }
    if (access(dir, W_OK | X_OK)) {
        snprintf(why, nwhy, "not writable: %s", strerror(errno));
        return -1;
    }
    return 0;
}

double pl_calcache_tail(const pl_calcache_expect_t *e, double d_box)
{
    return pl_srd_tail_missed(e->kT, e->rho, e->nu + d_box / e->kT, (double)e->box, e->t1, e->t2);
}

/* |a - b| <= READ_RTOL |b| */
static int near(double a, double b) { return fabs(a - b) <= READ_RTOL * fabs(b); }

/* The checks of the file header on a parsed entry; 0, or -1 with why. */
static int entry_check(json_t *j, const pl_calcache_expect_t *e, pl_mapping_calibration_t *c, char *why, size_t nwhy)
{
    json_t *v = json_object_get(j, "version");
    if (!json_is_integer(v) || json_integer_value(v) != PL_CALCACHE_VERSION) {
        snprintf(why, nwhy, "'version' is not %d", PL_CALCACHE_VERSION);
        return -1;
    }
    for (int k = 0; k < NFIELDS; ++k) {
        v = json_object_get(j, FIELDS[k]);
        if (!json_is_number(v) || !isfinite(json_number_value(v))) {
            snprintf(why, nwhy, "'%s' is missing or not a finite number", FIELDS[k]);
            return -1;
        }
        *field(c, k) = json_number_value(v);
    }
    const char *ints[] = {"n_colloids", "box", "steps"};
    const long long want[] = {e->n_colloids, e->box, e->steps};
    for (int k = 0; k < 3; ++k) {
        v = json_object_get(j, ints[k]);
        if (!json_is_integer(v) || json_integer_value(v) != want[k]) {
            snprintf(why, nwhy, "'%s' is not %lld, the calibration's plan", ints[k], want[k]);
            return -1;
        }
    }
    c->n_colloids = e->n_colloids;
    c->box = e->box;
    c->steps = e->steps;
    v = json_object_get(j, "concentration"); /* written only where it is not 1 (the potential coupling) */
    c->concentration = v ? (json_is_number(v) ? json_number_value(v) : NAN) : 1.0;
    const double dt = e->d_theory;
    if (!(c->d_inf > 0 && c->d_inf >= dt / THEORY_FACTOR && c->d_inf <= dt * THEORY_FACTOR)) {
        snprintf(why, nwhy, "'d_inf' = %.17g is not within a factor %g of the theory's %.17g", c->d_inf,
                 THEORY_FACTOR, dt);
        return -1;
    }
    if (!(c->d_inf_se >= 0 && c->d_inf_se < c->d_inf && c->d_box_se >= 0)) {
        snprintf(why, nwhy, "'d_inf_se' = %.17g is not in [0, d_inf)", c->d_inf_se);
        return -1;
    }
    const char *name[] = {"phi", "hasimoto", "concentration"};
    const double got[] = {c->phi, c->hasimoto, c->concentration}, ref[] = {e->phi, e->hasimoto, e->concentration};
    for (int k = 0; k < 3; ++k)
        if (!near(got[k], ref[k])) {
            snprintf(why, nwhy, "'%s' = %.17g is not the %.17g this parameter set gives", name[k], got[k], ref[k]);
            return -1;
        }
    const double tail = pl_calcache_tail(e, c->d_box);
    v = json_object_get(j, "tail"); /* absent: an entry from before the tail (checked as written, then derived) */
    if (v && !(json_is_number(v) && near(json_number_value(v), tail))) {
        snprintf(why, nwhy, "'tail' is not the %.17g this parameter set gives", tail);
        return -1;
    }
    const double d = (c->d_box + (v ? tail : 0.0) + c->hasimoto) / c->concentration / e->kT;
    if (!near(c->d_inf, d)) {
        snprintf(why, nwhy, "'d_inf' = %.17g is not (d_box%s + hasimoto) / concentration = %.17g", c->d_inf,
                 v ? " + tail" : "", d);
        return -1;
    }
    c->tail = tail;
    c->d_inf = (c->d_box + tail + c->hasimoto) / c->concentration / e->kT;
    return 0;
}

int pl_calcache_read(const char *path, const pl_calcache_expect_t *e, pl_mapping_calibration_t *cal, char *why,
                     size_t nwhy)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0 && errno == ENOENT) return PL_CALCACHE_ABSENT;
    if (fd < 0) {
        snprintf(why, nwhy, "cannot read: %s", strerror(errno));
        return PL_CALCACHE_BAD;
    }
    struct stat st;
    char *buf = NULL;
    ssize_t got = -1;
    if (fstat(fd, &st)) snprintf(why, nwhy, "cannot read: %s", strerror(errno));
    else if (!S_ISREG(st.st_mode)) snprintf(why, nwhy, "not a regular file");
    else if (st.st_size > CACHE_MAX_BYTES) snprintf(why, nwhy, "%lld bytes, more than an entry's %d",
                                                    (long long)st.st_size, CACHE_MAX_BYTES);
    else if (!(buf = malloc((size_t)st.st_size + 1))) snprintf(why, nwhy, "out of memory");
    else if ((got = read(fd, buf, (size_t)st.st_size)) != (ssize_t)st.st_size) {
        snprintf(why, nwhy, "cannot read: %s", got < 0 ? strerror(errno) : "short read");
        got = -1;
    }
    close(fd);
    if (got < 0) {
        free(buf);
        return PL_CALCACHE_BAD;
    }
    json_error_t je;
    json_t *j = json_loadb(buf, (size_t)got, 0, &je);
    free(buf);
    if (!j || !json_is_object(j)) {
        if (j) snprintf(why, nwhy, "not a JSON object");
        else snprintf(why, nwhy, "not JSON (line %d: %s)", je.line, je.text);
        json_decref(j);
        return PL_CALCACHE_BAD;
    }
    pl_mapping_calibration_t c = *cal;
    int rc = entry_check(j, e, &c, why, nwhy);
    json_decref(j);
    if (rc) return PL_CALCACHE_BAD;
    *cal = c;
    return PL_CALCACHE_OK;
}

int pl_calcache_write(const char *path, const pl_mapping_calibration_t *c, const char *about, char *why, size_t nwhy)
{
    json_t *j = json_object();
    int bad = !j || json_object_set_new(j, "version", json_integer(PL_CALCACHE_VERSION)) ||
              json_object_set_new(j, "about", json_string(about));
    pl_mapping_calibration_t cc = *c;
    for (int k = 0; !bad && k < NFIELDS; ++k) bad = json_object_set_new(j, FIELDS[k], json_real(*field(&cc, k)));
    bad = bad || json_object_set_new(j, "n_colloids", json_integer(c->n_colloids)) ||
          json_object_set_new(j, "box", json_integer(c->box)) || json_object_set_new(j, "steps", json_integer(c->steps));
    if (c->concentration != 1.0) bad = bad || json_object_set_new(j, "concentration", json_real(c->concentration));
    bad = bad || json_object_set_new(j, "tail", json_real(c->tail));
    char *text = bad ? NULL : json_dumps(j, JSON_INDENT(2) | JSON_REAL_PRECISION(17));
    json_decref(j);
    if (!text) {
        snprintf(why, nwhy, "out of memory");
        return -1;
    }
    char tmp[700];
    pl_atomic_tmp(path, tmp, sizeof tmp);
    const size_t len = strlen(text);
    int fd = -1;
    if (unlink(tmp) && errno != ENOENT) snprintf(why, nwhy, "%s: cannot remove: %s", tmp, strerror(errno));
    else if ((fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644)) < 0)
        snprintf(why, nwhy, "%s: %s", tmp, strerror(errno));
    else {
        size_t off = 0;
        ssize_t w = 0;
        while (off < len && (w = write(fd, text + off, len - off)) > 0) off += (size_t)w;
        if (off < len) snprintf(why, nwhy, "%s: %s", tmp, w < 0 ? strerror(errno) : "short write");
        if (close(fd) && off == len) {
            snprintf(why, nwhy, "%s: %s", tmp, strerror(errno));
            off = 0;
        }
        if (off < len) unlink(tmp);
        else fd = -2; /* written */
    }
    free(text);
    if (fd != -2) return -1;
    pl_err_t e;
    if (pl_atomic_commit(tmp, path, &e)) { /* tmp removed */
        snprintf(why, nwhy, "%s", e.msg);
        return -1;
    }
    return 0;
}

int pl_calcache_lock_timeout(double *t, pl_err_t *err)
{
    const char *s = getenv("PELOID_CACHE_LOCK_TIMEOUT");
    *t = LOCK_TIMEOUT_S;
    if (!s || !*s) return 0;
    char *end;
    errno = 0;
    *t = strtod(s, &end);
    if (*end || errno || !isfinite(*t) || *t < 0)
        return pl_err_set(err, PL_ERR_INPUT, "PELOID_CACHE_LOCK_TIMEOUT = '%s': allowed: seconds >= 0", s);
    return 0;
}

/* ---- the lock ---------------------------------------------------------- */

typedef struct {
    long pid;
    char host[256];
    long long since; /* time(NULL) when it took the lock */
} holder_t;

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void host_name(char *h, size_t n)
{
    if (gethostname(h, n)) snprintf(h, n, "?");
    h[n - 1] = '\0';
}

/* The holder recorded in the lock file; 0, or -1 when none is recorded. */
static int holder_read(int fd, holder_t *h)
{
    char b[400];
    ssize_t n = pread(fd, b, sizeof b - 1, 0);
    if (n <= 0) return -1;
    b[n] = '\0';
    return sscanf(b, "pid %ld host %255s since %lld", &h->pid, h->host, &h->since) == 3 && h->pid > 0 ? 0 : -1;
}

static void holder_write(int fd)
{
    char host[256], b[400];
    host_name(host, sizeof host);
    int n = snprintf(b, sizeof b, "pid %ld host %s since %lld\n", (long)getpid(), host, (long long)time(NULL));
    /* the record only informs waiters: a failure leaves it empty ("recorded no pid") */
    if (ftruncate(fd, 0) == 0 && pwrite(fd, b, (size_t)n, 0) != n) {
        const int rc = ftruncate(fd, 0);
        (void)rc;
    }
}

/* 1 when h's process is on this host and stopped (SIGSTOP, SIGTSTP, a tracer). */
static int holder_stopped(const holder_t *h)
{
    char p[64], b[512];
    snprintf(p, sizeof p, "/proc/%ld/stat", h->pid);
    FILE *f = fopen(p, "r");
    if (!f) return 0;
    size_t n = fread(b, 1, sizeof b - 1, f);
    fclose(f);
    b[n] = '\0';
    const char *s = strrchr(b, ')'); /* "pid (comm) S ..." */
    return s && (s[2] == 'T' || s[2] == 't');
}

static void holder_say(const holder_t *h, int known, char *s, size_t n)
{
    if (!known) snprintf(s, n, "held by a process that recorded no pid");
    else
        snprintf(s, n, "held by pid %ld on %s for %lld s%s", h->pid, h->host, (long long)time(NULL) - h->since,
                 holder_stopped(h) ? " (stopped)" : "");
}

int pl_calcache_lock(const char *path, double timeout_s, FILE *log, int *fd, char *why, size_t nwhy)
{
    char lp[720], dir[700], host[256];
    snprintf(lp, sizeof lp, "%s.lock", path);
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (slash) *slash = '\0';
    else snprintf(dir, sizeof dir, ".");
    host_name(host, sizeof host);
    int dfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd < 0) {
        snprintf(why, nwhy, "%s: %s", dir, strerror(errno));
        return PL_CALCACHE_NO_LOCK;
    }
    holder_t h = {0};
    int known = 0;
    const double t0 = now_s();
    double next_report = t0, stopped_since = -1.0;
    for (;;) {
        if (flock(dfd, LOCK_EX | LOCK_NB) == 0) { /* the folder lock: microseconds, never waited on */
            int f = open(lp, O_CREAT | O_RDWR | O_CLOEXEC | O_NOFOLLOW, 0644);
            if (f < 0) {
                snprintf(why, nwhy, "%s: %s", lp, strerror(errno));
                close(dfd);
                return PL_CALCACHE_NO_LOCK;
            }
            if (flock(f, LOCK_EX | LOCK_NB) == 0) {
                holder_write(f);
                close(dfd); /* releases the folder lock */
                *fd = f;
                return PL_CALCACHE_LOCKED;
            }
            known = holder_read(f, &h) == 0;
            const int stale = known && strcmp(h.host, host) == 0 && kill((pid_t)h.pid, 0) && errno == ESRCH;
            if (stale) { /* its holder is gone: a fresh lock file in its place */
                if (log)
                    fprintf(log, "peloid: warning: calibration cache lock %s: held, but its holder pid %ld on %s no "
                                 "longer exists: taking it over\n", lp, h.pid, h.host);
                if (unlink(lp)) {
                    snprintf(why, nwhy, "%s: cannot remove the stale lock: %s", lp, strerror(errno));
                    close(f);
                    close(dfd);
                    return PL_CALCACHE_NO_LOCK;
                }
            }
            close(f);
            flock(dfd, LOCK_UN);
            if (stale) continue;
        }
        const double t = now_s();
        if (known && holder_stopped(&h)) {
            if (stopped_since < 0) stopped_since = t;
        } else stopped_since = -1.0;
        char who[400];
        holder_say(&h, known, who, sizeof who);
        if (t - t0 >= timeout_s || (stopped_since >= 0 && t - stopped_since >= LOCK_STOPPED_S)) {
            snprintf(why, nwhy, "%s: gave up after %.0f s of waiting (PELOID_CACHE_LOCK_TIMEOUT = %g s; a stopped "
                     "holder: %g s)", who, t - t0, timeout_s, LOCK_STOPPED_S);
            close(dfd);
            return PL_CALCACHE_GAVE_UP;
        }
        if (log && t >= next_report && (known || t - t0 >= 1.0)) { /* a new holder records itself at once */
            fprintf(log, "peloid: waiting for the calibration cache lock %s: %s (gives up after %g s: "
                         "PELOID_CACHE_LOCK_TIMEOUT)\n", lp, who, timeout_s);
            fflush(log);
            next_report = t + LOCK_REPORT_S;
        }
        struct timespec ts = {0, (long)(LOCK_POLL_S * 1e9)};
        nanosleep(&ts, NULL);
    }
}

void pl_calcache_unlock(int fd)
{
    if (fd < 0) return;
    /* an empty record: a waiter never reads this holder's once it has exited; a failure only keeps the record */
    const int rc = ftruncate(fd, 0);
    (void)rc;
    close(fd);
}
