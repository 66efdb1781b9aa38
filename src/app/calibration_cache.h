/* The calibration cache (src/app/calibration_cache.c): where the
 * coupling-true-time calibrations of src/app/calibrate.c are kept, how an
 * entry is read and checked, written, and locked against a second process
 * measuring the same.  Nothing here may cost a run: every failure comes back
 * as a reason (one line, in why) that the caller turns into a warning, except
 * a bad PELOID_CACHE_LOCK_TIMEOUT (input) and a corrupt shipped calibration
 * (a bug), which the caller refuses. */
#ifndef PELOID_PLAN_CALIBRATION_CACHE_H
#define PELOID_PLAN_CALIBRATION_CACHE_H

#include <stdio.h>

#include "peloid/error.h"
#include "peloid/mapping.h"

enum { PL_CALCACHE_VERSION = 1 }; /* the "version" of an entry, hashed into its name */

/* What an entry of one parameter set must hold: the plan its key hashes
 * (box, steps, colloids), the numbers the code derives without measuring
 * (phi, the periodic images' D, 1 - c phi, kT) and the theory's D. */
typedef struct {
    double kT, d_theory, hasimoto, phi, concentration;
    double nu, rho, t1, t2; /* the fluid's kinematic viscosity and mass density, the lags of the slope (t0) */
    int box, n_colloids;
    long long steps;
} pl_calcache_expect_t;

/* The hydrodynamic tail the slope over the lags [t1, t2] misses in the
 * calibration box (pl_srd_tail_missed with a = nu + d_box / kT): cal_run adds
 * it, the reader checks it. */
double pl_calcache_tail(const pl_calcache_expect_t *e, double d_box);

/* Results of pl_calcache_read and pl_calcache_lock. */
enum { PL_CALCACHE_OK = 0, PL_CALCACHE_ABSENT = 1, PL_CALCACHE_BAD = 2 };
enum { PL_CALCACHE_LOCKED = 0, PL_CALCACHE_GAVE_UP = 1, PL_CALCACHE_NO_LOCK = 2 };

/* The cache folder: PELOID_CACHE, else $XDG_CACHE_HOME/peloid, else
 * ~/.cache/peloid (/tmp/.cache/peloid without HOME). */
void pl_calcache_dir(char *dir, size_t n);

/* Creates dir (mkdir -p) and checks that it is a folder this process may
 * write: 0, or -1 with the reason in why. */
int pl_calcache_dir_prepare(const char *dir, char *why, size_t nwhy);

/* Reads the entry at path into *cal (the measured fields; cal->cache and
 * d_theory untouched): PL_CALCACHE_OK when it passes every check against *e,
 * PL_CALCACHE_ABSENT when there is no file, PL_CALCACHE_BAD with the reason
 * (naming the key and value at fault) otherwise. */
int pl_calcache_read(const char *path, const pl_calcache_expect_t *e, pl_mapping_calibration_t *cal, char *why,
                     size_t nwhy);

/* Writes *cal to path atomically ("<path>.tmp", then rename; a stale .tmp
 * left by a crashed writer is removed first: call it under the lock).  The
 * bytes are those of every earlier version (JSON, indent 2, 17 digits).
 * 0, or -1 with the reason in why (nothing left under either name). */
int pl_calcache_write(const char *path, const pl_mapping_calibration_t *cal, const char *about, char *why,
                      size_t nwhy);

/* PELOID_CACHE_LOCK_TIMEOUT (seconds >= 0) into *t, default 1800 s;
 * PL_ERR_INPUT naming the variable and its value when it is not a number. */
int pl_calcache_lock_timeout(double *t, pl_err_t *err);

/* The exclusive lock of path's entry ("<path>.lock"): PL_CALCACHE_LOCKED with
 * *fd held (pl_calcache_unlock), PL_CALCACHE_GAVE_UP after timeout_s of
 * waiting (or after a holder on this host stayed stopped for a minute), or
 * PL_CALCACHE_NO_LOCK when the lock file cannot be made; why says which
 * holder or which error.  While it waits it writes to log (may be NULL) who
 * holds the lock, once and then every 30 s. */
int pl_calcache_lock(const char *path, double timeout_s, FILE *log, int *fd, char *why, size_t nwhy);
void pl_calcache_unlock(int fd);

#endif
