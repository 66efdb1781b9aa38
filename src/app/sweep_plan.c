/* The throughput plan of `peloid sweep` (include/peloid/sweep.h): how many
 * `peloid run` processes at once, with how many OpenMP threads each, and on
 * which cores.  Independent single-thread runs scale with the cores (each
 * has its own caches and its own share of the bandwidth), one run's threads
 * only as far as its stages do; so the plan fills the cores with points
 * first and gives only the cores left over to the points as threads.  The
 * choice changes no result: a run is bitwise the same at any thread count
 * (DESIGN.md), and a point's result does not depend on the others. */
#include <hwloc.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peloid/scene.h"
#include "peloid/sweep.h"
#include "sweep_priv.h"

/* The rule of thumb of README "Parameter sweeps" (the figures behind it:
 * bench/RESULTS.md, issue 38): a thread needs this much work of its own. */
#define FLUID_PER_THREAD 131072.0
#define COLLOIDS_PER_THREAD 64.0
#define COLLOID_MAX_THREADS 8

void pl_sweep_point_cost(const struct pl_scene *scene, pl_sweep_cost_t *cost)
{
    double vol = (double)scene->box.cells[0] * scene->box.cells[1] * scene->box.cells[2];
    double fluid = scene->fluid.density * vol, colloids = (double)scene->colloids.count;
    double t = fmax(fluid / FLUID_PER_THREAD, colloids / COLLOIDS_PER_THREAD);
    if (colloids > 0 && t > COLLOID_MAX_THREADS) t = COLLOID_MAX_THREADS;
    cost->max_threads = t >= PL_SWEEP_MAX_CORES ? PL_SWEEP_MAX_CORES : t < 1 ? 1 : (int)t;
    cost->mem_bytes = pl_scene_memory_bytes(scene, 1);
    cost->mem_per_thread = pl_scene_memory_bytes(scene, 2) - cost->mem_bytes;
}

static double job_bytes(const pl_sweep_request_t *r, int threads)
{
    return r->cost.mem_bytes + (threads - 1) * r->cost.mem_per_thread + PL_SWEEP_JOB_OVERHEAD_BYTES;
}

static int imin(int a, int b)
{
    return a < b ? a : b;
}

/* Threads of a job that is not given them: the spare cores, bounded. */
static int spare_threads(int cores, int jobs, int max_threads)
{
    int t = imin(cores / jobs, max_threads);
    return t < 1 ? 1 : t;
}

/* Appends to p->why (cut at its size; `len` counts what was asked). */
#define WHY(...)                                                                \
    (len += (size_t)snprintf(len < sizeof p->why ? p->why + len : NULL,         \
                             len < sizeof p->why ? sizeof p->why - len : 0, __VA_ARGS__))

/* Cores for each job: the domain with the most free cores that holds a
 * whole job; else what is free, in logical order (a split job). */
static void place(const pl_sweep_machine_t *m, pl_sweep_plan_t *p)
{
    int nd = m->ndomains > 0 ? imin(m->ndomains, PL_SWEEP_MAX_DOMAINS) : 1;
    int free_[PL_SWEEP_MAX_DOMAINS], next[PL_SWEEP_MAX_DOMAINS], at = 0;
    for (int d = 0; d < nd; ++d) {
        free_[d] = m->ndomains > 0 ? m->domain_cores[d] : m->cores;
        next[d] = at;
        at += free_[d];
    }
    for (int j = 0, k = 0; j < p->jobs; ++j) {
        int best = -1;
        for (int d = 0; d < nd; ++d)
            if (free_[d] >= p->threads && (best < 0 || free_[d] > free_[best])) best = d;
        if (best >= 0) {
            for (int i = 0; i < p->threads; ++i) p->core[k++] = next[best]++;
            free_[best] -= p->threads;
            continue;
        }
        int need = p->threads, used = 0;
        for (int d = 0; d < nd && need; ++d) {
            if (free_[d] > 0) ++used;
            for (; free_[d] > 0 && need; --free_[d], --need) p->core[k++] = next[d]++;
        }
        p->split += used > 1;
    }
}

void pl_sweep_plan(const pl_sweep_machine_t *m, const pl_sweep_request_t *r, pl_sweep_plan_t *p)
{
    memset(p, 0, sizeof *p);
    size_t len = 0;
    const int C = m->cores > 0 ? imin(m->cores, PL_SWEEP_MAX_CORES) : 1;
    const int P = r->todo > 0 ? r->todo : 1, tmax = r->cost.max_threads > 0 ? r->cost.max_threads : 1;
    int j, t;
    if (r->todo <= 0) {
        p->jobs = p->threads = 1;
        WHY("no point to run");
        return;
    } else if (r->jobs_given > 0) {
        j = imin(r->jobs_given, P);
        t = r->threads_given > 0 ? r->threads_given : spare_threads(C, j, tmax);
        if (r->threads_given > 0) WHY("--jobs %d --threads %d as given", r->jobs_given, r->threads_given);
        else WHY("--jobs %d as given, %d thread(s) each (%d cores / %d job(s), at most %d)", r->jobs_given, t, C, j,
                 tmax);
    } else if (r->threads_given > 0) {
        t = r->threads_given;
        j = C / t < 1 ? 1 : imin(C / t, P);
        WHY("--threads %d as given, %d job(s) (%d cores / %d thread(s), at most the %d point(s))", t, j, C, t, P);
    } else if (P >= C) {
        j = C;
        t = 1;
        WHY("%d point(s) >= %d cores: one single-thread job per core", P, C);
    } else {
        j = P;
        t = spare_threads(C, j, tmax);
        WHY("%d point(s) < %d cores: the spare cores go to the points as threads, %d each", P, C, t);
        if (t < C / j) WHY(" (at most %d: the points' scaling bound)", tmax);
    }
    if (j > P) j = P;
    if (m->mem_bytes > 0 && r->cost.mem_bytes > 0) {
        const double have = PL_SWEEP_MEMORY_SHARE * m->mem_bytes;
        p->mem_jobs = (int)fmin(have / job_bytes(r, t), (double)PL_SWEEP_MAX_CORES);
        if (r->jobs_given <= 0 && j * job_bytes(r, t) > have && j > 1) {
            const int j0 = j;
            const double need0 = j0 * job_bytes(r, t);
            while (j > 1 && j * job_bytes(r, t) > have) {
                --j;
                if (r->threads_given <= 0) t = spare_threads(C, j, tmax);
            }
            p->mem_jobs = (int)fmin(have / job_bytes(r, t), (double)PL_SWEEP_MAX_CORES);
            WHY("; memory: %d job(s) would need %.3g GB, more than %.0f %% of the %.3g GB available: "
                "%d job(s) x %d thread(s)", j0, need0 / 1e9, 100 * PL_SWEEP_MEMORY_SHARE, m->mem_bytes / 1e9, j, t);
        } else WHY("; memory: %d x %.3g GB (the largest point's estimate + %.0f MB a process) of %.3g GB available",
                   j, job_bytes(r, t) / 1e9, PL_SWEEP_JOB_OVERHEAD_BYTES / 1e6, m->mem_bytes / 1e9);
        if (j * job_bytes(r, t) > have)
            WHY(" (%s)", r->jobs_given > 0 ? "more than fits: --jobs as given" : "even one job exceeds it");
    }
    p->jobs = j;
    p->threads = t;
    if ((long long)j * t <= C) {
        p->bound = 1;
        p->idle = C - j * t;
        place(m, p);
        WHY("; each job bound to %d core(s) of its own", t);
        if (m->ndomains > 1) {
            if (p->split) WHY(", %d job(s) across two %s domains", p->split, m->domain_kind);
            else WHY(" in one %s domain", m->domain_kind);
        }
        if (p->idle) WHY("; %d core(s) idle", p->idle);
    } else WHY("; not bound: %d job(s) x %d thread(s) > %d cores", j, t, C);
    if (m->pus > m->cores) WHY("; %d PUs on %d cores: one thread per core", m->pus, m->cores);
}

/* The sweep's topology: hwloc's, restricted to the process's CPU binding. */
static int load_topology(hwloc_topology_t *topo)
{
    if (hwloc_topology_init(topo)) return -1;
    if (hwloc_topology_load(*topo)) {
        hwloc_topology_destroy(*topo);
        return -1;
    }
    hwloc_bitmap_t set = hwloc_bitmap_alloc();
    if (set && !hwloc_get_cpubind(*topo, set, HWLOC_CPUBIND_PROCESS) && !hwloc_bitmap_iszero(set))
        hwloc_topology_restrict(*topo, set, 0);
    hwloc_bitmap_free(set);
    return 0;
}

static double mem_available(void)
{
    FILE *f = fopen("/proc/meminfo", "r");
    char line[256];
    double kb = 0;
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "MemAvailable: %lf kB", &kb) == 1) break;
    if (f) fclose(f);
    return kb * 1024.0;
}

void pl_sweep_machine(pl_sweep_machine_t *m)
{
    memset(m, 0, sizeof *m);
    m->mem_bytes = mem_available();
    hwloc_topology_t topo;
    if (load_topology(&topo)) {
        m->cores = m->pus = m->ndomains = 1;
        m->domain_cores[0] = 1;
        snprintf(m->domain_kind, sizeof m->domain_kind, "machine");
        return;
    }
    int nc = hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_CORE);
    m->cores = nc > 0 ? imin(nc, PL_SWEEP_MAX_CORES) : 1;
    m->pus = hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_PU);
    hwloc_obj_type_t kind = hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_L3CACHE) > 0 ? HWLOC_OBJ_L3CACHE
                            : hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_NUMANODE) > 1 ? HWLOC_OBJ_NUMANODE
                                                                                      : HWLOC_OBJ_MACHINE;
    snprintf(m->domain_kind, sizeof m->domain_kind, "%s",
             kind == HWLOC_OBJ_L3CACHE ? "L3" : kind == HWLOC_OBJ_NUMANODE ? "NUMA" : "machine");
    /* consecutive cores (logical order follows the tree) with the same domain */
    const void *prev = NULL;
    for (int c = 0; c < m->cores && nc > 0; ++c) {
        hwloc_obj_t core = hwloc_get_obj_by_type(topo, HWLOC_OBJ_CORE, (unsigned)c), dom = NULL;
        if (kind == HWLOC_OBJ_NUMANODE) { /* memory children: the node whose cpuset holds the core */
            for (int i = 0; !dom && i < hwloc_get_nbobjs_by_type(topo, HWLOC_OBJ_NUMANODE); ++i) {
                hwloc_obj_t n = hwloc_get_obj_by_type(topo, HWLOC_OBJ_NUMANODE, (unsigned)i);
                if (hwloc_bitmap_isincluded(core->cpuset, n->cpuset)) dom = n;
            }
        } else dom = hwloc_get_ancestor_obj_by_type(topo, kind, core);
        if (c == 0 || dom != prev) {
            if (m->ndomains == PL_SWEEP_MAX_DOMAINS) break;
            ++m->ndomains;
        }
        ++m->domain_cores[m->ndomains - 1];
        prev = dom;
    }
    if (m->ndomains == 0) {
        m->ndomains = 1;
        m->domain_cores[0] = m->cores;
    }
    hwloc_topology_destroy(topo);
}

int pl_sweep_cpusets(const pl_sweep_plan_t *p, cpu_set_t *sets, char (*text)[64])
{
    hwloc_topology_t topo;
    if (!p->bound || load_topology(&topo)) return -1;
    int rc = 0;
    hwloc_bitmap_t set = hwloc_bitmap_alloc();
    for (int j = 0; !rc && j < p->jobs; ++j) {
        hwloc_bitmap_zero(set);
        for (int i = 0; i < p->threads; ++i) {
            hwloc_obj_t core = hwloc_get_obj_by_type(topo, HWLOC_OBJ_CORE, (unsigned)p->core[j * p->threads + i]);
            if (!core) rc = -1;
            else hwloc_bitmap_or(set, set, core->cpuset);
        }
        CPU_ZERO(&sets[j]);
        for (int pu = hwloc_bitmap_first(set); !rc && pu >= 0; pu = hwloc_bitmap_next(set, pu)) {
            if (pu >= CPU_SETSIZE) rc = -1;
            else CPU_SET((unsigned)pu, &sets[j]);
        }
        hwloc_bitmap_list_snprintf(text[j], 64, set);
    }
    hwloc_bitmap_free(set);
    hwloc_topology_destroy(topo);
    return rc;
}

/* OUT/plan.json: what the sweep chose and why (tools/sweep_collect.py copies
 * it into sweep.json). */
static int write_plan(const sweep_t *s, const pl_sweep_request_t *r, const sweep_plan_t *pl, char (*text)[64],
                      pl_err_t *err)
{
    const pl_sweep_machine_t *m = &pl->machine;
    const pl_sweep_plan_t *p = pl->plan;
    json_t *doc = json_object(), *dom = json_array(), *sets = json_array();
    for (int d = 0; d < m->ndomains; ++d) json_array_append_new(dom, json_integer(m->domain_cores[d]));
    for (int j = 0; pl->sets && j < p->jobs; ++j) json_array_append_new(sets, json_string(text[j]));
    json_object_set_new(doc, "jobs", json_integer(p->jobs));
    json_object_set_new(doc, "threads", json_integer(p->threads));
    json_object_set_new(doc, "points_to_run", json_integer(r->todo));
    json_object_set_new(doc, "jobs_given", json_integer(r->jobs_given));
    json_object_set_new(doc, "threads_given", json_integer(r->threads_given));
    json_object_set_new(doc, "why", json_string(p->why));
    json_object_set_new(doc, "cpusets", sets); /* each job's PUs (OS indices); [] when not bound */
    json_object_set_new(doc, "idle_cores", json_integer(p->idle));
    json_object_set_new(doc, "split_jobs", json_integer(p->split));
    json_object_set_new(doc, "machine", json_pack("{s:i, s:i, s:s, s:o, s:f}", "cores", m->cores, "pus", m->pus,
                                                  "domain", m->domain_kind, "domain_cores", dom,
                                                  "memory_available_bytes", m->mem_bytes));
    json_object_set_new(doc, "point", json_pack("{s:f, s:f, s:i}", "memory_bytes", r->cost.mem_bytes,
                                                "memory_per_thread_bytes", r->cost.mem_per_thread,
                                                "max_threads", r->cost.max_threads));
    char *j = json_dumps(doc, JSON_INDENT(1));
    json_decref(doc);
    if (!j) return pl_err_set(err, PL_ERR_NOMEM, "out of memory writing plan.json");
    char path[4096], *t = malloc(strlen(j) + 2);
    if (t) sprintf(t, "%s\n", j);
    free(j);
    if (!t) return pl_err_set(err, PL_ERR_NOMEM, "out of memory writing plan.json");
    snprintf(path, sizeof path, "%s/plan.json", s->out);
    int rc = pl_sweep_write_text(path, t, err);
    free(t);
    return rc;
}

int pl_sweep_plan_points(const sweep_t *s, int first, int n, const int *state, int todo, sweep_plan_t *pl,
                         pl_err_t *err)
{
    pl_sweep_request_t r = {.todo = todo, .jobs_given = s->o->jobs, .threads_given = s->o->threads};
    for (int i = 0; s->cost && i < n; ++i) { /* the largest of the points to run */
        const pl_sweep_cost_t *c = &s->cost[first + i];
        if (state[i]) continue;
        r.cost.mem_bytes = fmax(r.cost.mem_bytes, c->mem_bytes);
        r.cost.mem_per_thread = fmax(r.cost.mem_per_thread, c->mem_per_thread);
        if (c->max_threads > r.cost.max_threads) r.cost.max_threads = c->max_threads;
    }
    pl_sweep_machine(&pl->machine);
    pl->plan = malloc(sizeof *pl->plan);
    char(*text)[64] = NULL;
    if (pl->plan) {
        pl_sweep_plan(&pl->machine, &r, pl->plan);
        text = calloc((size_t)pl->plan->jobs, sizeof *text);
    }
    if (!pl->plan || !text) {
        free(text);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory planning the sweep");
    }
    pl_sweep_plan_t *p = pl->plan;
    size_t len = strlen(p->why);
    if (p->bound && getenv("PL_NO_BIND")) WHY(" (not applied: PL_NO_BIND)");
    else if (p->bound) {
        pl->sets = calloc((size_t)p->jobs, sizeof *pl->sets);
        if (!pl->sets || pl_sweep_cpusets(p, pl->sets, text)) {
            free(pl->sets);
            pl->sets = NULL;
            WHY(" (not applied: hwloc could not give the cores' CPU sets)");
        }
    }
    int rc = s->o->point < 0 && todo > 0 ? write_plan(s, &r, pl, text, err) : 0; /* else: the last plan stays */
    free(text);
    return rc;
}

void pl_sweep_plan_free(sweep_plan_t *pl)
{
    free(pl->plan);
    free(pl->sets);
    pl->plan = NULL;
    pl->sets = NULL;
}
