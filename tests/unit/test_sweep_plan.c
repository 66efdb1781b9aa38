/* The throughput plan of `peloid sweep` (pl_sweep_plan, src/app/sweep_plan.c):
 * jobs x threads, the cores of each job and the memory bound for several
 * (points, cores, topology) combinations; the points' cost from their
 * scenes; the memory estimate's bytes per fluid particle against the fluid's
 * own arrays.  Pure functions: no process is started. */
#include <criterion/criterion.h>
#include <string.h>

#include "peloid/fluid.h"
#include "peloid/scene.h"
#include "peloid/sweep.h"

/* A machine of `nd` domains of `per` cores each, `smt` PUs per core. */
static pl_sweep_machine_t machine(int nd, int per, int smt, double mem)
{
    pl_sweep_machine_t m;
    memset(&m, 0, sizeof m);
    m.cores = nd * per;
    m.pus = m.cores * smt;
    m.ndomains = nd;
    for (int d = 0; d < nd; ++d) m.domain_cores[d] = per;
    strcpy(m.domain_kind, "L3");
    m.mem_bytes = mem;
    return m;
}

static pl_sweep_plan_t plan;

static void run(const pl_sweep_machine_t *m, int todo, int jobs, int threads, int max_threads, double mem)
{
    pl_sweep_request_t r = {.todo = todo, .jobs_given = jobs, .threads_given = threads,
                            .cost = {.mem_bytes = mem, .mem_per_thread = 0, .max_threads = max_threads}};
    pl_sweep_plan(m, &r, &plan);
}

/* Every bound plan: each job's cores distinct from every other's, inside
 * the machine; returns how many jobs lie in one domain. */
static int check_disjoint(const pl_sweep_machine_t *m)
{
    cr_assert(plan.bound);
    int used[PL_SWEEP_MAX_CORES] = {0}, inside = 0;
    for (int j = 0; j < plan.jobs; ++j) {
        int d0 = -1, same = 1;
        for (int i = 0; i < plan.threads; ++i) {
            int c = plan.core[j * plan.threads + i], d = 0, at = m->domain_cores[0];
            cr_assert(c >= 0 && c < m->cores, "job %d core %d outside 0..%d", j, c, m->cores - 1);
            cr_assert_eq(used[c]++, 0, "core %d given to two jobs", c);
            while (c >= at) at += m->domain_cores[++d];
            if (d0 >= 0 && d != d0) same = 0;
            d0 = d;
        }
        inside += same;
    }
    cr_assert_eq(plan.idle, m->cores - plan.jobs * plan.threads);
    return inside;
}

Test(sweep_plan, points_at_least_cores_one_single_thread_job_per_core)
{
    pl_sweep_machine_t m = machine(1, 16, 1, 0);
    run(&m, 16, 0, 0, 8, 0);
    cr_assert_eq(plan.jobs, 16);
    cr_assert_eq(plan.threads, 1);
    check_disjoint(&m);
    run(&m, 100, 0, 0, 8, 0); /* more points than cores: a pool of 16 */
    cr_assert_eq(plan.jobs, 16);
    cr_assert_eq(plan.threads, 1);
    cr_assert(strstr(plan.why, "100 point(s) >= 16 cores: one single-thread job per core"), "%s", plan.why);
    pl_sweep_machine_t two = machine(1, 2, 1, 0); /* this 2-core machine, 4 points */
    run(&two, 4, 0, 0, 1, 0);
    cr_assert_eq(plan.jobs, 2);
    cr_assert_eq(plan.threads, 1);
    cr_assert_eq(plan.core[0], 0);
    cr_assert_eq(plan.core[1], 1);
}

Test(sweep_plan, fewer_points_than_cores_get_the_spare_cores_as_threads)
{
    pl_sweep_machine_t m = machine(1, 16, 1, 0);
    run(&m, 2, 0, 0, 100, 0);
    cr_assert_eq(plan.jobs, 2);
    cr_assert_eq(plan.threads, 8);
    check_disjoint(&m);
    run(&m, 3, 0, 0, 100, 0); /* floor(16 / 3) = 5: one core idle */
    cr_assert_eq(plan.jobs, 3);
    cr_assert_eq(plan.threads, 5);
    check_disjoint(&m);
    cr_assert_eq(plan.idle, 1);
    run(&m, 1, 0, 0, 100, 0);
    cr_assert_eq(plan.jobs, 1);
    cr_assert_eq(plan.threads, 16);
    /* bounded by what the points scale to: the rest stays idle, and the line says why */
    run(&m, 2, 0, 0, 3, 0);
    cr_assert_eq(plan.jobs, 2);
    cr_assert_eq(plan.threads, 3);
    cr_assert_eq(plan.idle, 10);
    cr_assert(strstr(plan.why, "at most 3: the points' scaling bound") && strstr(plan.why, "10 core(s) idle"), "%s",
              plan.why);
    run(&m, 4, 0, 0, 1, 0); /* points that do not scale: one thread each */
    cr_assert_eq(plan.threads, 1);
    cr_assert_eq(plan.jobs, 4);
}

Test(sweep_plan, jobs_spread_over_l3_domains_and_stay_inside_one)
{
    pl_sweep_machine_t m = machine(2, 8, 1, 0);
    run(&m, 2, 0, 0, 100, 0); /* 2 x 8: one job per L3 */
    cr_assert_eq(plan.threads, 8);
    cr_assert_eq(check_disjoint(&m), 2);
    cr_assert_eq(plan.core[0], 0);
    cr_assert_eq(plan.core[8], 8);
    run(&m, 4, 0, 0, 100, 0); /* 4 x 4: two per L3, none split */
    cr_assert_eq(plan.threads, 4);
    cr_assert_eq(check_disjoint(&m), 4);
    cr_assert_eq(plan.split, 0);
    run(&m, 2, 0, 0, 4, 0); /* 2 x 4 on 16 cores: one job in each L3, not both in the first */
    cr_assert_eq(check_disjoint(&m), 2);
    cr_assert_eq(plan.core[0], 0);
    cr_assert_eq(plan.core[4], 8);
    cr_assert(strstr(plan.why, "in one L3 domain"), "%s", plan.why);
    run(&m, 3, 0, 0, 100, 0); /* 3 x 5: two fit an L3, the third takes what is left of both */
    cr_assert_eq(plan.threads, 5);
    cr_assert_eq(check_disjoint(&m), 2);
    cr_assert_eq(plan.split, 1);
    cr_assert(strstr(plan.why, "1 job(s) across two L3 domains"), "%s", plan.why);
    pl_sweep_machine_t odd = machine(4, 6, 2, 0); /* 4 L3 x 6 cores, SMT 2: 24 single-thread jobs */
    run(&odd, 30, 0, 0, 8, 0);
    cr_assert_eq(plan.jobs, 24);
    cr_assert_eq(plan.threads, 1);
    cr_assert_eq(check_disjoint(&odd), 24);
    cr_assert(strstr(plan.why, "48 PUs on 24 cores: one thread per core"), "%s", plan.why);
}

Test(sweep_plan, given_jobs_and_threads_win)
{
    pl_sweep_machine_t m = machine(1, 2, 1, 0);
    run(&m, 4, 1, 2, 1, 0);
    cr_assert_eq(plan.jobs, 1);
    cr_assert_eq(plan.threads, 2);
    check_disjoint(&m);
    cr_assert(strstr(plan.why, "--jobs 1 --threads 2 as given"), "%s", plan.why);
    run(&m, 4, 4, 2, 1, 0); /* oversubscribed as asked: not bound */
    cr_assert_eq(plan.jobs, 4);
    cr_assert_eq(plan.threads, 2);
    cr_assert(!plan.bound);
    cr_assert(strstr(plan.why, "not bound: 4 job(s) x 2 thread(s) > 2 cores"), "%s", plan.why);
    run(&m, 3, 8, 0, 1, 0); /* never more jobs than points */
    cr_assert_eq(plan.jobs, 3);
    pl_sweep_machine_t big = machine(1, 16, 1, 0);
    run(&big, 100, 0, 2, 1, 0); /* only --threads: 16 / 2 jobs */
    cr_assert_eq(plan.jobs, 8);
    cr_assert_eq(plan.threads, 2);
    check_disjoint(&big);
    run(&big, 100, 2, 0, 100, 0); /* only --jobs: the spare cores as threads */
    cr_assert_eq(plan.jobs, 2);
    cr_assert_eq(plan.threads, 8);
    run(&big, 0, 0, 0, 1, 0); /* nothing to run */
    cr_assert_eq(plan.jobs, 1);
    cr_assert_eq(plan.threads, 1);
    cr_assert_str_eq(plan.why, "no point to run");
}

Test(sweep_plan, memory_bounds_the_jobs)
{
    const double GB = 1e9, over = PL_SWEEP_JOB_OVERHEAD_BYTES;
    pl_sweep_machine_t m = machine(1, 16, 1, 10 * GB);
    /* 2 GB points: 0.8 x 10 GB holds 3 jobs of 2 GB + the overhead */
    run(&m, 16, 0, 0, 1, 2 * GB);
    cr_assert_eq(plan.jobs, 3);
    cr_assert_eq(plan.threads, 1);
    cr_assert(plan.jobs * (2 * GB + over) <= PL_SWEEP_MEMORY_SHARE * 10 * GB);
    cr_assert(strstr(plan.why, "memory: 16 job(s) would need"), "%s", plan.why);
    /* ... and when the points scale, the freed cores become threads */
    run(&m, 16, 0, 0, 8, 2 * GB);
    cr_assert_eq(plan.jobs, 3);
    cr_assert_eq(plan.threads, 5);
    /* small points: no limit */
    run(&m, 16, 0, 0, 1, 1e6);
    cr_assert_eq(plan.jobs, 16);
    /* a given --jobs is kept, and the line says it does not fit */
    run(&m, 16, 16, 0, 1, 2 * GB);
    cr_assert_eq(plan.jobs, 16);
    cr_assert(strstr(plan.why, "more than fits: --jobs as given"), "%s", plan.why);
    /* larger than the share even alone: one job, said so */
    run(&m, 4, 0, 0, 1, 9 * GB);
    cr_assert_eq(plan.jobs, 1);
    cr_assert(strstr(plan.why, "even one job exceeds it"), "%s", plan.why);
    /* memory unknown: no bound */
    pl_sweep_machine_t u = machine(1, 16, 1, 0);
    run(&u, 16, 0, 0, 1, 2 * GB);
    cr_assert_eq(plan.jobs, 16);
}

static pl_scene_t scene;

static void load(const char *text)
{
    pl_err_t err;
    cr_assert_eq(pl_scene_load_string(text, "s.cfg", &scene, &err), 0, "%s", err.msg);
}

Test(sweep_plan, point_cost_from_the_scene)
{
    pl_sweep_cost_t c;
    load("box: { cells = [64, 64, 64]; }; fluid: { density = 10.0; };"); /* 2.6 M particles */
    pl_sweep_point_cost(&scene, &c);
    cr_assert_eq(c.max_threads, 20);
    load("box: { cells = [16, 16, 16]; }; fluid: { density = 10.0; };"); /* 41 k: one thread */
    pl_sweep_point_cost(&scene, &c);
    cr_assert_eq(c.max_threads, 1);
    load("box: { cells = [15, 15, 15]; }; fluid: { density = 10.0; };");
    scene.colloids.count = 462; /* the Fig. 9 model: colloids / 64 */
    pl_sweep_point_cost(&scene, &c);
    cr_assert_eq(c.max_threads, 7);
    scene.colloids.count = 1155; /* the Fig. 14 model: at most 8 with colloids */
    pl_sweep_point_cost(&scene, &c);
    cr_assert_eq(c.max_threads, 8);
    cr_assert_float_eq(c.mem_bytes, pl_scene_memory_bytes(&scene, 1), 0.5);
    cr_assert_float_eq(c.mem_per_thread, 4.0 * 15 * 15 * 15, 0.5); /* one histogram entry per cell */
}

/* The estimate's bytes per fluid particle are those of the fluid's arrays
 * (pl_fluid_bytes: positions, velocities, their sort twins, the cell index;
 * with output.track_fluid ids and displacements and their twins). */
Test(sweep_plan, memory_estimate_per_particle_is_the_fluid_arrays)
{
    for (int tracked = 0; tracked < 2; ++tracked) {
        load(tracked ? "box: { cells = [8, 8, 8]; }; fluid: { density = 5.0; }; output: { track_fluid = true; };"
                     : "box: { cells = [8, 8, 8]; }; fluid: { density = 5.0; };");
        double a = pl_scene_memory_bytes(&scene, 1);
        scene.fluid.density = 10.0;
        double per = (pl_scene_memory_bytes(&scene, 1) - a) / (5.0 * 8 * 8 * 8);
        pl_fluid_t f;
        pl_err_t err;
        cr_assert_eq(pl_fluid_create(64, tracked, 1, &f, &err), 0);
        cr_assert_float_eq(per, (double)pl_fluid_bytes(&f), 1e-9, "tracked %d: %g B vs %zu B", tracked, per,
                           pl_fluid_bytes(&f));
        pl_fluid_free(&f);
    }
}
