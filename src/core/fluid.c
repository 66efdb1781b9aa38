/* Fluid state allocation: SoA arrays + sort twins, 64-byte aligned. */
#include "peloid/fluid.h"

#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

void *pl_alloc(size_t bytes, int nthreads)
{
    size_t rounded = (bytes + PL_ALIGN - 1) / PL_ALIGN * PL_ALIGN;
    if (rounded == 0) rounded = PL_ALIGN;
    /* Arrays of 4 MiB and more start on a 2 MiB boundary and their whole
     * 2 MiB pages are marked for transparent huge pages (the kernel's THP
     * mode "madvise"): fewer TLB misses in the streaming and scatter passes
     * (bench/RESULTS.md: step -8% at 1 thread).  Nothing is touched beyond
     * `rounded`, so the resident size is unchanged. */
    const size_t huge = (size_t)2 << 20;
    void *q = NULL;
    if (posix_memalign(&q, bytes >= 2 * huge ? huge : PL_ALIGN, rounded)) return NULL;
    char *p = q;
#ifdef MADV_HUGEPAGE
    if (bytes >= 2 * huge) (void)madvise(p, rounded / huge * huge, MADV_HUGEPAGE); /* advice: errors ignored */
#endif
    /* First touch with the kernels' static partition (pages near threads). */
    pl_first_touch(p, rounded, nthreads);
    return p;
}

void pl_free(void *p) { free(p); }

void pl_fluid_free(pl_fluid_t *f)
{
    for (int d = 0; d < 3; ++d) {
        pl_free(f->r[d]); pl_free(f->v[d]); pl_free(f->r_alt[d]); pl_free(f->v_alt[d]);
        pl_free(f->disp[d]); pl_free(f->disp_alt[d]);
    }
    pl_free(f->id); pl_free(f->id_alt); pl_free(f->cell); pl_free(f->order);
    memset(f, 0, sizeof *f);
}

int pl_fluid_create(size_t n, int tracked, int nthreads, pl_fluid_t *f, pl_err_t *err)
{
    memset(f, 0, sizeof *f);
    f->n = n;
    f->tracked = tracked;
    int ok = 1;
    for (int d = 0; d < 3; ++d) {
        ok &= (f->r[d] = pl_alloc(n * sizeof(pl_real), nthreads)) != NULL;
        ok &= (f->v[d] = pl_alloc(n * sizeof(pl_real), nthreads)) != NULL;
        ok &= (f->r_alt[d] = pl_alloc(n * sizeof(pl_real), nthreads)) != NULL;
        ok &= (f->v_alt[d] = pl_alloc(n * sizeof(pl_real), nthreads)) != NULL;
        if (tracked) {
            ok &= (f->disp[d] = pl_alloc(n * sizeof(double), nthreads)) != NULL;
            ok &= (f->disp_alt[d] = pl_alloc(n * sizeof(double), nthreads)) != NULL;
        }
    }
    if (tracked) {
        ok &= (f->id = pl_alloc(n * sizeof(uint32_t), nthreads)) != NULL;
        ok &= (f->id_alt = pl_alloc(n * sizeof(uint32_t), nthreads)) != NULL;
    }
    ok &= (f->cell = pl_alloc(n * sizeof(uint32_t), nthreads)) != NULL;
    if (!ok) {
        pl_fluid_free(f);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory allocating %zu fluid particles", n);
    }
    return 0;
}


void pl_fluid_swap(pl_fluid_t *f)
{
    for (int d = 0; d < 3; ++d) {
        pl_real *t = f->r[d]; f->r[d] = f->r_alt[d]; f->r_alt[d] = t;
        t = f->v[d]; f->v[d] = f->v_alt[d]; f->v_alt[d] = t;
        double *q = f->disp[d]; f->disp[d] = f->disp_alt[d]; f->disp_alt[d] = q;
    }
    uint32_t *u = f->id; f->id = f->id_alt; f->id_alt = u;
}

size_t pl_fluid_bytes(const pl_fluid_t *f)
{
    size_t b = 2 * 6 * sizeof(pl_real) + sizeof(uint32_t) + (f->order ? sizeof(uint32_t) : 0);
    if (f->tracked) b += 2 * (3 * sizeof(double) + sizeof(uint32_t));
    return b;
}
