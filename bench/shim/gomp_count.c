/* LD_PRELOAD shim that counts the calls into libgomp's entry points which
 * fork/join a team or synchronise it (bench/omp_counts.sh): per entry point
 * and per call site (for GOMP_parallel the outlined function it runs, for
 * the others the caller's return address), written at exit to the file
 * named by GOMP_COUNT_OUT as lines "entry object offset count" (offset
 * relative to the object's load base, for addr2line).  Counts are per call
 * by any thread: a barrier reached by a team of t threads counts t.
 *   gcc -O2 -shared -fPIC -o gomp_count.so gomp_count.c -ldl -lpthread
 * Not part of the library or the bench binaries (the Makefile builds only the
 * top-level bench sources). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <pthread.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

enum { NSLOT = 8192 };

typedef struct {
    const char *entry;
    void *site;
    unsigned long long count;
} slot_t;

static slot_t slots[NSLOT];
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;

static void count(const char *entry, void *site)
{
    uintptr_t h = ((uintptr_t)site * 0x9E3779B97F4A7C15ull) ^ (uintptr_t)entry;
    pthread_mutex_lock(&lock);
    for (size_t k = 0; k < NSLOT; ++k) {
        slot_t *s = &slots[(h + k) % NSLOT];
        if (!s->entry) {
            s->entry = entry;
            s->site = site;
        }
        if (s->entry == entry && s->site == site) {
            s->count++;
            break;
        }
    }
    pthread_mutex_unlock(&lock);
}

__attribute__((destructor)) static void dump(void)
{
    const char *path = getenv("GOMP_COUNT_OUT");
    FILE *f = path ? fopen(path, "w") : stderr;
    if (!f) return;
    for (size_t k = 0; k < NSLOT; ++k) {
        if (!slots[k].entry) continue;
        Dl_info in;
        const char *obj = "?";
        uintptr_t off = (uintptr_t)slots[k].site;
        if (dladdr(slots[k].site, &in) && in.dli_fname) {
            obj = in.dli_fname;
            off -= (uintptr_t)in.dli_fbase;
        }
        fprintf(f, "%s %s 0x%lx %llu\n", slots[k].entry, obj, (unsigned long)off, slots[k].count);
    }
    if (f != stderr) fclose(f);
}

#define NEXT(name) static __typeof__(name) *next; if (!next) next = (__typeof__(name) *)dlsym(RTLD_NEXT, #name)
#define SITE ((char *)__builtin_return_address(0) - 1)

void GOMP_parallel(void (*fn)(void *), void *data, unsigned nthreads, unsigned flags);
void GOMP_parallel(void (*fn)(void *), void *data, unsigned nthreads, unsigned flags)
{
    NEXT(GOMP_parallel);
    count("GOMP_parallel", (void *)fn);
    next(fn, data, nthreads, flags);
}

void GOMP_barrier(void);
void GOMP_barrier(void)
{
    NEXT(GOMP_barrier);
    count("GOMP_barrier", SITE);
    next();
}

bool GOMP_barrier_cancel(void);
bool GOMP_barrier_cancel(void)
{
    NEXT(GOMP_barrier_cancel);
    count("GOMP_barrier_cancel", SITE);
    return next();
}

bool GOMP_single_start(void);
bool GOMP_single_start(void)
{
    NEXT(GOMP_single_start);
    count("GOMP_single_start", SITE);
    return next();
}

void GOMP_critical_start(void);
void GOMP_critical_start(void)
{
    NEXT(GOMP_critical_start);
    count("GOMP_critical_start", SITE);
    next();
}

void GOMP_atomic_start(void);
void GOMP_atomic_start(void)
{
    NEXT(GOMP_atomic_start);
    count("GOMP_atomic_start", SITE);
    next();
}

void GOMP_loop_end(void);
void GOMP_loop_end(void)
{
    NEXT(GOMP_loop_end);
    count("GOMP_loop_end", SITE);
    next();
}

bool GOMP_loop_end_cancel(void);
bool GOMP_loop_end_cancel(void)
{
    NEXT(GOMP_loop_end_cancel);
    count("GOMP_loop_end_cancel", SITE);
    return next();
}

void GOMP_loop_end_nowait(void);
void GOMP_loop_end_nowait(void)
{
    NEXT(GOMP_loop_end_nowait);
    count("GOMP_loop_end_nowait", SITE);
    next();
}
