/* Colloid kernels (kernels/colloid_*.c): linked cells, pair forces, external
 * forces, integrators.  Pure functions of raw arrays, counts and small
 * parameter structs: no scene, no I/O, no allocation.  nthreads is the size
 * of each parallel region (num_threads; serial below PL_COLLOID_OMP_MIN
 * colloids): no kernel relies on a process-wide thread count. */
#ifndef PELOID_COLLOID_KERNELS_H
#define PELOID_COLLOID_KERNELS_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

/* Below this many colloids the kernels run serially: a parallel region costs
 * more than the work (results are identical either way). */
#define PL_COLLOID_OMP_MIN 256
/* Largest |image counter| (ix, iy, iz: int32): the drift saturates a counter
 * that would pass it (no int32 overflow) and the colloid guard stops the run. */
#define PL_COLLOID_IMAGE_MAX (1 << 30)

/* The one minimum-image separation of the colloid code: d on an axis of
 * length L, wrapped to [-L/2, L/2] when the axis is periodic. */
static inline double pl_min_image(double d, double L, int periodic)
{
    return periodic ? d - L * rint(d / L) : d;
}

/* The pair-term table: one row per colloid-colloid term, in this order
 *   X(ID, id, name, energy slot, kind)
 * ID/id: the term's tag (PL_CT_ID is its bit, 1 << row index); name: its word
 * in colloids.pairs; energy slot: its row PL_CE_* of the energy array (and so
 * its thermo column, PL_COLLOID_ENERGY_SLOTS), PL_CE_NONE for a dissipative
 * term; kind: RADIAL for a conservative term U(r) of the centre distance
 * alone, OWN for one the force kernel evaluates by its own code.  Each row
 * has, by its id:
 *   pl_pair_rc_ID(p, d)           its cut-off (centre distance) for contact
 *                                 distance d (include/peloid/colloid_pair_terms.h);
 *   pl_pair_term_ID(p, r, d)      RADIAL: U, F = -dU/dr, d2U/dr2 at r < the
 *                                 cut-off (same header);
 *   pl_colloid_term_setup_id(...) its parameters from the scene
 *                                 (include/peloid/colloid.h).
 * Adding a term: its row here (and its slot below), its parameters in
 * pl_colloid_pair_params_t, its two inline functions, its set-up and its
 * scene keys.  The force kernel specialises one loop per subset of the rows
 * (kernels/colloid_forces.c), the cut-offs of the neighbour lists and of the
 * kernels are the largest row cut-off of the scene's subset
 * (pl_colloid_pair_rc), colloids.pairs and the thermo columns read the
 * names.  RADIAL rows are summed in row order after DLVO and before Hertz
 * and lubrication. */
#define PL_PAIR_TERMS(X)                                        \
    X(DLVO, dlvo, "dlvo", PL_CE_DLVO, OWN)                      \
    X(HERTZ, hertz, "hertz", PL_CE_HERTZ, OWN)                  \
    X(LUB, lub, "lubrication", PL_CE_NONE, OWN)                 \
    X(WCA, wca, "wca", PL_CE_WCA, RADIAL)                       \
    X(DEPL, depl, "depletion_comp", PL_CE_DEPL, RADIAL)         \
    X(TAB, tab, "table", PL_CE_TAB, RADIAL)
/* Rows of PL_PAIR_TERMS, as a literal for the preprocessor (the kernel
 * specialisations, 2^rows, are generated from it; checked below). */
#define PL_PAIR_NTERMS 6

/* Energy slots, one row of n per slot in the energy scratch array, in this
 * order (the order of the thermo columns):
 *   X(ID, thermo column, pair-term bit or 0, always)
 * always: the column is in every colloid run's thermo.tsv; otherwise only
 * when the scene switches its pair term on. */
#define PL_COLLOID_ENERGY_SLOTS(X)             \
    X(DLVO, "c_dlvo", PL_CT_DLVO, 1)           \
    X(HERTZ, "c_hertz", PL_CT_HERTZ, 1)        \
    X(WCA, "c_wca", PL_CT_WCA, 1)              \
    X(WALL, "c_wall", 0u, 1)                   \
    X(GRAVITY, "c_gravity", 0u, 1)             \
    X(DEPL, "c_depl", PL_CT_DEPL, 1)           \
    X(TAB, "c_table", PL_CT_TAB, 0)

#define PL_CE_ENUM_(ID, col, bit, always) PL_CE_##ID,
enum { PL_COLLOID_ENERGY_SLOTS(PL_CE_ENUM_) PL_CE_NTERMS, PL_CE_NONE = -1 };
#undef PL_CE_ENUM_

#define PL_CT_INDEX_(ID, id, name, slot, kind) PL_CT_INDEX_##ID,
enum { PL_PAIR_TERMS(PL_CT_INDEX_) PL_CT_COUNT };
#undef PL_CT_INDEX_
#define PL_CT_BIT_(ID, id, name, slot, kind) PL_CT_##ID = 1u << PL_CT_INDEX_##ID,
/* Pair terms a scene switches on (bit mask). */
enum { PL_PAIR_TERMS(PL_CT_BIT_) PL_CT_ALL = (1u << PL_CT_COUNT) - 1u };
#undef PL_CT_BIT_
_Static_assert(PL_CT_COUNT == PL_PAIR_NTERMS, "PL_PAIR_NTERMS must count the rows of PL_PAIR_TERMS");
/* The RADIAL rows' bits. */
#define PL_CT_KIND_OWN 0u
#define PL_CT_KIND_RADIAL 1u
#define PL_CT_RADIAL_(ID, id, name, slot, kind) | (PL_CT_KIND_##kind ? PL_CT_##ID : 0u)
#define PL_CT_RADIAL (0u PL_PAIR_TERMS(PL_CT_RADIAL_))

/* Intervals of the table term's internal table (tab_uf). */
#define PL_PAIR_TABLE_N 2048

typedef struct {
    unsigned terms;  /* PL_CT_* */
    double box[3];   /* edge lengths */
    int periodic[3]; /* minimum image along this axis */
    /* DLVO, Hecht Eqs. 1-2 + parabolic primary minimum (see colloid_pair.h) */
    double coul_C, kappa, hamaker, prim_hm, prim_h0, dlvo_shift, dlvo_hcut;
    /* the parabola's match point for the pairs of diameter prim_d (the
     * reference diameter): value, slope dU/dr and curvature, as
     * pl_pair_dlvo computes them (a pair of another diameter computes its
     * own); set with prim_hm by pl_colloid_dlvo_setup, from the constants
     * above: a change of any of them must set these again */
    double prim_d, prim_mu, prim_vp, prim_c;
    /* gap beyond which the screened Coulomb term of Eq. 1 is below 1e-15 kT
     * and kT/a0 (the kernel skips its exponential there) */
    double coul_hcut;
    /* Hertz, Hecht Eqs. 3 and 6 + tangential viscous friction */
    double hertz_K, hertz_beta, hertz_gamma_t;
    /* lubrication, Hecht Eqs. 4-5 */
    double lub_eta, lub_hmin, lub_hcut;
    /* its random partner (lubrication.thermal, velocity Verlet only): a
     * pair within lub_hcut gets the radial force lub_noise sqrt(zeta) g,
     * lub_noise = sqrt(2 kT / dt_MD), g a standard normal number of Philox
     * (key: noise_seed, PL_RNG_LUB_NOISE; counter: noise_step, the lower
     * and the higher colloid index); noise_step is the MD step count of the
     * positions the forces are evaluated at, set by the caller of each
     * force pass (src/colloid/colloid_state.c); off when lub_noise is 0 */
    double lub_noise, lub_kT;
    int lub_thermal;
    uint64_t noise_seed, noise_step;
    /* WCA, PL Eq. 16: sigma > 0 fixed, else R_i + R_j */
    double wca_eps, wca_sigma, wca_n, wca_rfac; /* rfac = 2^{1/n} */
    /* depletion compensation Phi_comp = -Phi_depl (PL Sec. III.C.1): cubic
     * Hermite table of value dep_u[k] and slope dep_du[k] at r = k / dep_inv_h,
     * zero from dep_rc on (twice the colloid-fluid cut-off) */
    const double *dep_u, *dep_du;
    double dep_inv_h, dep_rc;
    /* table (src/colloid/colloid_pair_table.c): U and F = -dU/dr at
     * r_k = tab_r0 + k / tab_inv_h, k = 0..PL_PAIR_TABLE_N, interleaved
     * (tab_uf[2k] = U, tab_uf[2k+1] = F; node N+1 repeats node N), each
     * interpolated linearly between the nodes; cut-off tab_rc (the file's
     * last r); below tab_r0 the force of tab_r0 */
    double tab_r0, tab_rc, tab_inv_h;
    double tab_uf[2 * (PL_PAIR_TABLE_N + 2)];
    double gap_cut; /* largest surface-gap cut-off of the DLVO/Hertz/lub terms */
    /* multiple time stepping (colloids.slow_interval > 1): the force pass
     * over the near list gives each pair's DLVO force times 1 - w, w =
     * pl_pair_slow_share(r^2, d, mts_hin, mts_hout); the slow pass
     * (kernels/colloid_slow.c) gives the rest, w times it */
    int mts;
    double mts_hin, mts_hout;
} pl_colloid_pair_params_t;

/* Raw arrays the force kernel reads and writes (all length n). */
typedef struct {
    size_t n;
    const double *x, *y, *z, *vx, *vy, *vz, *wx, *wy, *wz, *rad, *mass;
    double *fx, *fy, *fz, *tx, *ty, *tz;
    double *epot;         /* PL_CE_NTERMS x n per-particle energies */
    double *g_overlap;    /* n: largest overlap (R_i+R_j-r)/(R_i+R_j)        */
    double *g_omega2;     /* n: largest positive curvature / reduced mass    */
    double *g_damp;       /* n: largest dissipative rate zeta / reduced mass */
    int32_t *g_partner;   /* 3 x n: partner j of the three maxima            */
} pl_colloid_view_t;

/* Linked cells: particles counting-sorted by cell (stable, so a cell lists its
 * particles in index order). */
typedef struct {
    int nc[3];         /* cells per axis (1 when the box holds fewer than 3) */
    double inv_cl[3];  /* cells per unit length */
    size_t ncells;
    int32_t *start;    /* ncells + 1 */
    int32_t *list;     /* n: particle indices grouped by cell */
    int32_t *cell;     /* n: cell of each particle */
} pl_colloid_cells_t;

/* Cells per axis for cut-off rc in box L (0 cells => too small, see .c). */
void pl_colloid_cells_dims(const double box[3], const int periodic[3], double rc, int nc[3]);
/* Counting sort of the particles into cells (serial, O(n + ncells)). */
void pl_colloid_cells_build(pl_colloid_cells_t *cells, size_t n, const double *x, const double *y,
                            const double *z);

/* Verlet neighbour list (half list: each pair once) built from the linked
 * cells, kernels/colloid_neighbors.c.  Pair (i, j), i < j, belongs to i when
 * i + j is odd and to j when it is even, so every colloid owns about half of
 * its pairs whatever its index (a plain i < j rule would give the first
 * thread three quarters of the work).  A colloid's own partners are listed in
 * ascending index; the reverse entries of a colloid are the pairs other
 * colloids own with it, in ascending owner index.  The force kernel stores
 * each pair's result for the partner in one of two layouts, the same values
 * summed in the same order in both (pl_colloid_pair_store,
 * pl_colloid_pair_reverse_one):
 *   - by slot (the kernels' regions on one thread): in the pair's own slot,
 *     in slot order, so the owner pass stores sequentially; each colloid
 *     then reads its reverse entries' slots (rslot), scattered loads from
 *     L1/L2;
 *   - by reverse entry (a list built for two or more threads and at least
 *     PL_COLLOID_OMP_MIN colloids, so its regions run parallel): at the pair's
 *     reverse entry (spos), scattered stores; each colloid then reads its
 *     own entries in sequence.  About half of a thread's partners belong to
 *     another thread in a small box, and a scattered load of a line another
 *     core wrote stalls for the round trip between the cores (the pingpong
 *     of bench/bench_omp_overhead.c; bench/RESULTS_colloid.md), where a
 *     store does not stall the core. */
typedef struct {
    size_t n, cap;       /* colloids; capacity of the slot arrays */
    size_t npairs;       /* listed pairs (slots in use) */
    double rlist;        /* list radius: largest pair cut-off + skin */
    double skin;
    int32_t *start;      /* n + 1: the own slots of i are start[i] .. start[i+1]-1 */
    int32_t *nbr;        /* cap: partner of each slot */
    int32_t *rstart;     /* n + 1: the reverse entries of i are rstart[i] .. rstart[i+1]-1 */
    int32_t *rslot;      /* cap: the owner's slot of each reverse entry */
    int32_t *spos;       /* cap: the reverse entry of each slot */
    int by_entry;        /* layout of pf, pt: 0 by slot, 1 by reverse entry */
    double *pf;          /* 3 cap: per pair (slot or reverse entry), the force on the owner from its partner */
    double *pt;          /* 3 cap: per pair, the torque on the partner (tangential friction) */
    double *x0, *y0, *z0;    /* n: positions at the last build */
    long long builds;        /* list builds so far (diagnostic, not state) */
} pl_colloid_nlist_t;

/* Pair (i, j) is owned by i (see pl_colloid_nlist_t). */
static inline int pl_colloid_pair_owner(size_t i, size_t j)
{
    return ((i + j) & 1u) ? i < j : i > j;
}

/* Squared displacement of colloid i since the last build (minimum image on
 * periodic axes). */
static inline double pl_colloid_nlist_disp2(const pl_colloid_nlist_t *nl, const double box[3],
                                            const int periodic[3], const double *x,
                                            const double *y, const double *z, size_t i)
{
    double dx = pl_min_image(x[i] - nl->x0[i], box[0], periodic[0]);
    double dy = pl_min_image(y[i] - nl->y0[i], box[1], periodic[1]);
    double dz = pl_min_image(z[i] - nl->z0[i], box[2], periodic[2]);
    return dx * dx + dy * dy + dz * dz;
}

/* Largest squared displacement since the last build, with the minimum image
 * on periodic axes (a max: exact and the same for any thread count). */
double pl_colloid_nlist_max_disp2(const pl_colloid_nlist_t *nl, const double box[3],
                                  const int periodic[3], const double *x, const double *y,
                                  const double *z, int nthreads);
/* Counts the own partners of each colloid within rlist into start[1..n] (the
 * counts, not yet summed); the cells must be built for these positions. */
void pl_colloid_nlist_count(pl_colloid_nlist_t *nl, const pl_colloid_cells_t *cells,
                            const double box[3], const int periodic[3], const double *x,
                            const double *y, const double *z, int nthreads);
/* Fills the list after pl_colloid_nlist_count (start summed in place, the
 * slot arrays holding at least start[n] entries): partners, reverse slots,
 * reference positions. */
void pl_colloid_nlist_fill(pl_colloid_nlist_t *nl, const pl_colloid_cells_t *cells,
                           const double box[3], const int periodic[3], const double *x,
                           const double *y, const double *z, int nthreads);

/* The scans of pl_colloid_nlist_count / _fill (without the fill's reverse
 * entries) as orphaned worksharing loops for every thread of a caller's
 * team (static schedule, implicit barrier), and the reverse entries
 * (serial, one thread: pl_colloid_nlist_finish). */
void pl_colloid_nlist_count_loop(pl_colloid_nlist_t *nl, const pl_colloid_cells_t *cells,
                                 const double box[3], const int periodic[3], const double *x,
                                 const double *y, const double *z);
void pl_colloid_nlist_fill_loop(pl_colloid_nlist_t *nl, const pl_colloid_cells_t *cells,
                                const double box[3], const int periodic[3], const double *x,
                                const double *y, const double *z);
void pl_colloid_nlist_finish(pl_colloid_nlist_t *nl, int nthreads);
/* Is the list to be rebuilt before a force evaluation?  Never built, or a
 * colloid moved by more than half the skin since (disp2: the largest squared
 * displacement; a NaN asks for a rebuild). */
static inline int pl_colloid_nlist_stale(const pl_colloid_nlist_t *nl, double disp2)
{
    const double half = 0.5 * nl->skin;
    return nl->builds == 0 || !(disp2 <= half * half);
}

/* The near list of multiple time stepping (kernels/colloid_neighbors.c):
 * the pairs of the built full list that may feel a fast force before its
 * next build (count into start[1..n], not summed; then fill after the
 * prefix sum and the slot reservation). */
void pl_colloid_nlist_near_count(pl_colloid_nlist_t *near, const pl_colloid_nlist_t *full,
                                 const pl_colloid_pair_params_t *p, const double *x,
                                 const double *y, const double *z, const double *rad, int nthreads);
void pl_colloid_nlist_near_fill(pl_colloid_nlist_t *near, const pl_colloid_nlist_t *full,
                                const pl_colloid_pair_params_t *p, const double *x,
                                const double *y, const double *z, const double *rad, int nthreads);
/* Their scans as orphaned loops (near's skin and reverse entries then by
 * one thread: near->skin = full->skin, pl_colloid_nlist_finish). */
void pl_colloid_nlist_near_count_loop(pl_colloid_nlist_t *near, const pl_colloid_nlist_t *full,
                                      const pl_colloid_pair_params_t *p, const double *x,
                                      const double *y, const double *z, const double *rad);
void pl_colloid_nlist_near_fill_loop(pl_colloid_nlist_t *near, const pl_colloid_nlist_t *full,
                                     const pl_colloid_pair_params_t *p, const double *x,
                                     const double *y, const double *z, const double *rad);

/* The slow share of the DLVO forces (multiple time stepping,
 * kernels/colloid_slow.c) over the full list into fs (overwritten): the
 * owner pass as an orphaned worksharing loop, then per colloid after its
 * barrier the reverse entries (pl_colloid_pair_reverse_one over
 * pl_colloid_slow_view); or both in one call. */
void pl_colloid_slow_owner_pass(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                                const double *x, const double *y, const double *z,
                                const double *rad, double *fsx, double *fsy, double *fsz);
/* The view of the slow forces for pl_colloid_pair_reverse_one (no torques):
 * the reverse entries of the slow pass are added by the pair kernel's own
 * pass 2. */
static inline pl_colloid_view_t pl_colloid_slow_view(size_t n, double *fsx, double *fsy, double *fsz)
{
    pl_colloid_view_t v = {.n = n, .fx = fsx, .fy = fsy, .fz = fsz};
    return v;
}
void pl_colloid_slow_forces(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                            const double *x, const double *y, const double *z, const double *rad,
                            double *fsx, double *fsy, double *fsz, int nthreads);

/* Pair forces, torques and guard quantities over the neighbour list;
 * overwrites f, t.  `terms` of p must be a subset of PL_CT_ALL.  The guard
 * slots of i hold the maxima over the pairs i owns, so the maximum over all
 * colloids is the maximum over all pairs.  v->epot is not touched. */
void pl_colloid_pair_forces(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                            const pl_colloid_view_t *v, int nthreads);

/* The two passes of pl_colloid_pair_forces, for a caller that fuses more
 * per-colloid work into pass 2 (kernels/colloid_verlet.h).  Pass 1: each
 * colloid's own pairs, an orphaned worksharing loop (static schedule) to be
 * called by every thread of the caller's parallel region; its implicit
 * barrier ends it.  Pass 2, per colloid i after that barrier: the reverse
 * entries in ascending owner index (Newton's third law: the force on i is
 * minus the force on the owner), and the torques when the pair terms carry
 * them (pl_colloid_pair_torques). */
void pl_colloid_pair_owner_pass(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                                const pl_colloid_view_t *v);
static inline int pl_colloid_pair_torques(const pl_colloid_pair_params_t *p)
{
    return (p->terms & PL_CT_HERTZ) && p->hertz_gamma_t > 0.0;
}
/* Where pass 1 stores slot s's pair result (nl->by_entry: the layouts). */
static inline size_t pl_colloid_pair_at(const pl_colloid_nlist_t *nl, int32_t s)
{
    return 3 * (size_t)(nl->by_entry ? nl->spos[s] : s);
}
/* s minus (or plus, add) the results in a (nl->pf, nl->pt) of the reverse
 * entries r0 .. r1-1, in entry order; E: the list's layout (by_entry), a
 * constant at each call so that neither loop tests it per entry. */
static inline __attribute__((always_inline)) void pl_colloid_reverse_sum(const pl_colloid_nlist_t *nl,
                                                                         const double *a, int32_t r0,
                                                                         int32_t r1, const int E,
                                                                         const int add, double s[3])
{
    double x = s[0], y = s[1], z = s[2];
    for (int32_t r = r0; r < r1; ++r) {
        const size_t q = 3 * (size_t)(E ? r : nl->rslot[r]);
        if (add) {
            x += a[q];
            y += a[q + 1];
            z += a[q + 2];
        } else {
            x -= a[q];
            y -= a[q + 1];
            z -= a[q + 2];
        }
    }
    s[0] = x;
    s[1] = y;
    s[2] = z;
}
/* x, y, z[i] minus (plus: add) colloid i's reverse entries in a. */
static inline __attribute__((always_inline)) void pl_colloid_reverse_into(const pl_colloid_nlist_t *nl,
                                                                          const double *a, size_t i,
                                                                          const int add, double *x,
                                                                          double *y, double *z)
{
    const int32_t r0 = nl->rstart[i], r1 = nl->rstart[i + 1];
    double s[3] = {x[i], y[i], z[i]};
    if (nl->by_entry)
        pl_colloid_reverse_sum(nl, a, r0, r1, 1, add, s);
    else
        pl_colloid_reverse_sum(nl, a, r0, r1, 0, add, s);
    x[i] = s[0];
    y[i] = s[1];
    z[i] = s[2];
}
static inline void pl_colloid_pair_reverse_one(const pl_colloid_nlist_t *nl,
                                               const pl_colloid_view_t *v, size_t i, int torques)
{
    pl_colloid_reverse_into(nl, nl->pf, i, 0, v->fx, v->fy, v->fz);
    if (torques) pl_colloid_reverse_into(nl, nl->pt, i, 1, v->tx, v->ty, v->tz);
}

/* Pair energies of the present positions: rows PL_CE_DLVO, _HERTZ, _WCA,
 * _DEPL of v->epot get, for each colloid, the energies of the pairs it owns
 * (other rows and the forces are not touched). */
void pl_colloid_pair_energies(const pl_colloid_pair_params_t *p, const pl_colloid_nlist_t *nl,
                              const pl_colloid_view_t *v, int nthreads);

/* The conservative energy (kT_ref) of one pair of radii ri, rj at centre
 * distance r: DLVO + Hertz + WCA + depletion_comp of the terms in p, by the
 * same pair evaluation as pl_colloid_pair_energies (lubrication and the Hertz
 * damping carry no energy).  Zero beyond the pair cut-off. */
double pl_colloid_pair_energy(const pl_colloid_pair_params_t *p, double r, double ri, double rj);

typedef struct {
    double g[3];      /* acceleration (gravity minus buoyancy) */
    int walls[3];     /* repulsive walls at 0 and L[d] on axis d (closed axes) */
    double L[3], wall_eps, wall_n;
} pl_colloid_ext_params_t;

/* Adds gravity and wall forces (walls: PL Eq. 16 form with sigma = R_i at the
 * wall distance, on every closed axis); energies into epot rows PL_CE_WALL /
 * PL_CE_GRAVITY when non-NULL (gravity energy needs unwrapped z: zu). */
void pl_colloid_ext_forces(const pl_colloid_ext_params_t *p, size_t n, const double *x,
                           const double *y, const double *z, const double *zu, const double *rad,
                           const double *mass, double *fx, double *fy, double *fz, double *epot, int nthreads);

/* The guard's tests on one colloid (src/colloid/colloid_guard.c): its state
 * finite (one sum of the 12 components, in this order), and the first axis
 * whose image counter is beyond PL_COLLOID_IMAGE_MAX (-1: none). */
static inline int pl_colloid_state_finite(double x, double y, double z, double vx, double vy,
                                          double vz, double fx, double fy, double fz, double wx,
                                          double wy, double wz)
{
    return isfinite(x + y + z + vx + vy + vz + fx + fy + fz + wx + wy + wz);
}
static inline int pl_colloid_image_axis_out(int32_t ix, int32_t iy, int32_t iz)
{
    const int32_t im[3] = {ix, iy, iz};
    for (int d = 0; d < 3; ++d)
        if (im[d] > PL_COLLOID_IMAGE_MAX || im[d] < -PL_COLLOID_IMAGE_MAX) return d;
    return -1;
}

/* The maxima over all colloids of the guard quantities of the pair kernel
 * (g_overlap, g_omega2, g_damp; exact, so independent of the thread count)
 * and whether some colloid failed a per-colloid test (or has a NaN guard
 * quantity). */
typedef struct {
    double overlap, omega2, damp;
    int bad;
} pl_colloid_guard_max_t;

/* Adds colloid i to g: state_ok (its per-colloid tests passed) and the pair
 * kernel's guard quantities ov, om, dp of i (a NaN one marks g bad). */
static inline void pl_colloid_guard_add(pl_colloid_guard_max_t *g, int state_ok, double ov,
                                        double om, double dp)
{
    g->bad |= !state_ok || isnan(ov) || isnan(om) || isnan(dp);
    g->overlap = ov > g->overlap ? ov : g->overlap;
    g->omega2 = om > g->omega2 ? om : g->omega2;
    g->damp = dp > g->damp ? dp : g->damp;
}
static inline void pl_colloid_guard_merge(pl_colloid_guard_max_t *out, const pl_colloid_guard_max_t *in)
{
    pl_colloid_guard_add(out, !in->bad, in->overlap, in->omega2, in->damp);
}
/* The OpenMP reduction of partial maxima (exact: any order, any thread count). */
#pragma omp declare reduction(pl_guard_max : pl_colloid_guard_max_t : pl_colloid_guard_merge(&omp_out, &omp_in)) \
    initializer(omp_priv = (pl_colloid_guard_max_t){0.0, 0.0, 0.0, 0})

/* What the guard's pass reads (all length n): the state it tests and the
 * pair kernel's guard quantities (pl_colloid_view_t). */
typedef struct {
    size_t n;
    const double *x, *y, *z, *vx, *vy, *vz, *fx, *fy, *fz, *wx, *wy, *wz;
    const int32_t *ix, *iy, *iz;
    const double *g_overlap, *g_omega2, *g_damp;
} pl_colloid_guard_view_t;

/* The guard's pass over all colloids (kernels/colloid_guard_scan.c): the
 * per-colloid tests and the maxima into g, exact, so independent of
 * nthreads. */
void pl_colloid_guard_scan(const pl_colloid_guard_view_t *v, pl_colloid_guard_max_t *g, int nthreads);

/* The arrays of the colloids' dynamical state one MD step updates (n each). */
typedef struct {
    size_t n;
    double box[3];
    int periodic[3];
    const double *mass, *inertia, *rad;
    double *x, *y, *z, *zu; /* zu: unwrapped z (gravity energy) */
    int32_t *ix, *iy, *iz;
    double *vx, *vy, *vz, *wx, *wy, *wz;
    double *q0, *q1, *q2, *q3;
    double *fx, *fy, *fz, *tx, *ty, *tz;
    double *fsx, *fsy, *fsz; /* slow forces (multiple time stepping), else NULL */
} pl_colloid_dyn_t;

/* The MD steps of one collision step in one parallel region
 * (kernels/colloid_md_region.c): velocity Verlet, bitwise the same as the
 * separate passes (pl_colloid_kick, pl_colloid_drift, pl_colloid_forces,
 * pl_colloid_ext_forces, pl_colloid_kick, then the guard's pass), with the
 * neighbour list rebuilt inside when a colloid has moved by more than half
 * the skin.  The caller's decisions come through hooks on its control
 * state ctl, of which every thread keeps its own copy:
 *   end(ctx, ctl, g) and next(ctx, ctl, done, sub): called by every thread
 *     on its copy, so pure functions of ctl, g and what no hook changes
 *     inside the region.  end: after an MD step, g its guard maxima;
 *     PL_MD_CHECK when check is to run.  next: before the first MD step
 *     (done = 0) and after each end (done = 1, the check passed);
 *     PL_MD_RUN with the next step's parameters in sub, or 0: the end;
 *   check(ctx, ctl, g): one thread, the team waiting (guard report, energy
 *     drift); 0, or -1 to stop (ctl then as end left it);
 *   reserve(ctx, nl, need): one thread: slot arrays of nl for need pairs
 *     (0, or -1 to stop).
 * ctl comes in with the state before the first step and goes out with the
 * state after the last (the same in every thread).  Returns 0, or -1 when a
 * hook did.
 * Multiple time stepping (near != NULL): the pair pass runs over near with
 * the fast share; open_h > 0 first kicks by open_h s.fs (the start of an
 * outer step); close_h > 0 (its end) also evaluates the slow forces over
 * full into s.fs and kicks by close_h with them after the fast kick. */
typedef struct {
    double dt, open_h, close_h;
} pl_colloid_md_sub_t;
struct pl_colloid_reach; /* peloid/colloid_reach.h */
/* The control state of the MD steps (the hooks' to interpret;
 * src/colloid/colloid_md.c). */
typedef struct {
    long long md_step, adapt_md, adapt_refined, adapt_steps, adapt_lo, adapt_hi;
    double dt, adapt_last, adapt_worst;
    double reach_e, reach_v2; /* with r->reach: its maxima, before the first next */
    int slow_phase, n, todo, refine, check_e;
    int slow_len; /* MD steps of the current outer step (multiple time stepping) */
} pl_colloid_md_ctl_t;
enum { PL_MD_RUN = 1, PL_MD_CHECK = 2 };
typedef struct {
    void *ctx;
    int (*end)(const void *ctx, pl_colloid_md_ctl_t *ctl, const pl_colloid_guard_max_t *g);
    int (*next)(const void *ctx, pl_colloid_md_ctl_t *ctl, int done, pl_colloid_md_sub_t *sub);
    int (*check)(void *ctx, const pl_colloid_md_ctl_t *ctl, const pl_colloid_guard_max_t *g);
    int (*reserve)(void *ctx, pl_colloid_nlist_t *nl, size_t need);
} pl_colloid_md_hooks_t;
typedef struct {
    pl_colloid_dyn_t s;
    const pl_colloid_pair_params_t *p;
    pl_colloid_nlist_t *full, *near; /* near: multiple time stepping, else NULL */
    pl_colloid_cells_t *cells;
    const pl_colloid_view_t *v;      /* the same arrays as s */
    const pl_colloid_ext_params_t *ext;
    double *epot;
    /* adaptive substeps: the reach table, whose maxima (pl_colloid_reach_energy)
     * the region computes first into ctl->reach_e, reach_v2; else NULL */
    const struct pl_colloid_reach *reach;
    double reach_margin;
    int nthreads;
} pl_colloid_md_region_t;
int pl_colloid_md_region(const pl_colloid_md_region_t *r, const pl_colloid_md_hooks_t *hk,
                         pl_colloid_md_ctl_t *ctl);

/* Velocity Verlet half kick (PL Eq. 19 / Hecht Eq. 8 and the rotational
 * analogue of Hecht Eq. 9): v += h F/m, w += h T/I. */
void pl_colloid_kick(size_t n, double h, const double *mass, const double *inertia,
                     const double *fx, const double *fy, const double *fz, const double *tx,
                     const double *ty, const double *tz, double *vx, double *vy, double *vz,
                     double *wx, double *wy, double *wz, int nthreads);

/* x += dx (a move of the colloids' positions outside the MD: coupling I's
 * events), wrapped into the box with image counts; serial (few colloids). */
void pl_colloid_displace(size_t n, const double box[3], const int periodic[3], double *x, double *y, double *z,
                         int32_t *ix, int32_t *iy, int32_t *iz, const double *dx, const double *dy,
                         const double *dz);
/* Drift (PL Eq. 18 / Hecht Eq. 7 after the half kick) and quaternion update
 * (Hecht Eq. 10), positions wrapped into the box with image counts. */
void pl_colloid_drift(size_t n, double dt, const double box[3], const int periodic[3],
                      double *x, double *y, double *z, int32_t *ix, int32_t *iy, int32_t *iz,
                      const double *vx, const double *vy, const double *vz, const double *wx,
                      const double *wy, const double *wz, double *q0, double *q1, double *q2,
                      double *q3, int nthreads);

/* Rotates the unit quaternion q by the rotation vector phi (space frame) and
 * normalises it. */
void pl_colloid_quat_rotate(double phi_x, double phi_y, double phi_z, double q[4]);

typedef struct {
    double dt, kT, eta;  /* Stokes friction 6 pi eta R, 8 pi eta R^3 */
    uint64_t seed, step; /* counter-based noise (PL_RNG_BD_NOISE) */
} pl_colloid_bd_params_t;

/* The Brownian steps of one collision step in one parallel region
 * (kernels/colloid_md_region.c), with the hooks of pl_colloid_md_region (no
 * adaptive substeps and no multiple time stepping: r->reach and r->near
 * NULL); bd gives kT, eta and the seed, the control the steps and dt
 * (overdamped Langevin with Stokes friction, kernels/colloid_bd.h).  The
 * same state for any thread count. */
int pl_colloid_bd_region(const pl_colloid_md_region_t *r, const pl_colloid_md_hooks_t *hk,
                         const pl_colloid_bd_params_t *bd, pl_colloid_md_ctl_t *ctl);

#endif
