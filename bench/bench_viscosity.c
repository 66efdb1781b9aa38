/* Accuracy cost of the storage precision: kinematic viscosity from the decay
 * of a transverse shear wave, against SRD theory (PL Eqs. 9-12,
 * src/fluid/srd_theory.c).  Built as usual it measures double; built with
 * `make BUILD=build-single DEFS=-DPL_SINGLE` it measures float.
 *
 * Scene: periodic box Lx x Ly x Lz, 10 particles per cell, alpha = 130 deg,
 * dt = 0.1, grid shift on, no thermostat (the bench_srd scene).  At t = 0,
 * v_x += A sin(k z), k = 2 pi / Lz.  The amplitude
 *   a(t) = (2 / N) sum_i v_x,i sin(k z_i)
 * decays as exp(-nu k^2 t) (transverse momentum diffusion); nu is the slope of
 * ln <a(t)> over the first e-fold, <.> the mean over seeds.  The statistical
 * error is the spread of the per-seed fits / sqrt(seeds).
 *
 * Output: one TSV line on stdout and in bench/out/viscosity_<real>.tsv.
 * Usage: bench_viscosity [--quick] [--seeds N]   (PL_BENCH_QUICK=1 = --quick) */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "peloid/sim.h"
#include "peloid/srd_theory.h"

static const double PI = 3.14159265358979323846;

static double amplitude(const pl_fluid_t *f, double k)
{
    double s = 0.0;
    for (size_t i = 0; i < f->n; ++i) s += (double)f->v[0][i] * sin(k * (double)f->r[2][i]);
    return 2.0 * s / (double)f->n;
}

/* Least-squares slope of y against x over [0, m). */
static double slope(const double *x, const double *y, int m)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int i = 0; i < m; ++i) {
        sx += x[i]; sy += y[i]; sxx += x[i] * x[i]; sxy += x[i] * y[i];
    }
    return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

int main(int argc, char **argv)
{
    int quick = getenv("PL_BENCH_QUICK") && atoi(getenv("PL_BENCH_QUICK"));
    for (int i = 1; i < argc; ++i)
        if (!strcmp(argv[i], "--quick")) quick = 1;
    int seeds = quick ? 4 : 16;
    for (int i = 1; i + 1 < argc; ++i)
        if (!strcmp(argv[i], "--seeds")) seeds = atoi(argv[i + 1]) > 1 ? atoi(argv[i + 1]) : 2;
    const int Lxy = quick ? 8 : 16, Lz = 32;
    const double A = 0.2, dt = 0.1, alpha = 130.0, gamma = 10.0;
    pl_srd_theory_t th;
    pl_srd_theory(gamma, PL_RULE_RANDOM_AXIS, alpha * PI / 180.0, dt, 1.0, &th);
    const double k = 2.0 * PI / Lz;
    /* fit window: the first e-fold of the theoretical decay */
    const int steps = (int)ceil(1.0 / (th.nu * k * k * dt));
    double *mean = calloc((size_t)steps + 1, sizeof *mean), *t = calloc((size_t)steps + 1, sizeof *t);
    double *a = calloc((size_t)steps + 1, sizeof *a), *la = calloc((size_t)steps + 1, sizeof *la);
    double *nus = calloc((size_t)seeds, sizeof *nus);
    if (!mean || !t || !a || !la || !nus) return 1;
    double t0 = omp_get_wtime();
    for (int s = 0; s < seeds; ++s) {
        pl_scene_t sc;
        pl_scene_defaults(&sc);
        snprintf(sc.run.name, sizeof sc.run.name, "viscosity");
        sc.run.seed = 1000 + s;
        sc.box.cells[0] = sc.box.cells[1] = Lxy;
        sc.box.cells[2] = Lz;
        sc.fluid.density = gamma;
        sc.fluid.temperature = 1.0;
        sc.srd.dt = dt;
        sc.srd.alpha_deg = alpha;
        sc.srd.grid_shift = 1;
        sc.thermostat.type = PL_THERMO_NONE;
        pl_err_t err;
        memset(&err, 0, sizeof err);
        pl_sim_t *sim;
        if (pl_sim_create(&sc, 0, &sim, &err)) {
            fprintf(stderr, "bench_viscosity: %s\n", err.msg);
            return 1;
        }
        pl_fluid_t *f = &sim->fluid;
        for (size_t i = 0; i < f->n; ++i)
            f->v[0][i] = (pl_real)((double)f->v[0][i] + A * sin(k * (double)f->r[2][i]));
        for (int n = 0; n <= steps; ++n) {
            t[n] = n * dt;
            a[n] = amplitude(f, k);
            mean[n] += a[n] / seeds;
            la[n] = log(fabs(a[n]));
            if (n < steps && pl_sim_step(sim, &err)) {
                fprintf(stderr, "bench_viscosity: %s\n", err.msg);
                return 1;
            }
        }
        nus[s] = -slope(t, la, steps + 1) / (k * k);
        pl_sim_free(sim);
    }
    for (int n = 0; n <= steps; ++n) la[n] = log(mean[n]);
    const double nu = -slope(t, la, steps + 1) / (k * k);
    double m = 0, v = 0;
    for (int s = 0; s < seeds; ++s) m += nus[s] / seeds;
    for (int s = 0; s < seeds; ++s) v += (nus[s] - m) * (nus[s] - m) / (seeds - 1);
    const double err_nu = sqrt(v / seeds);
    mkdir("bench/out", 0777);
    char path[256];
    snprintf(path, sizeof path, "bench/out/viscosity_%s.tsv", PL_REAL_NAME);
    FILE *out = fopen(path, "w");
    const char *hdr = "real\tbox\tseeds\tsteps\tnu_measured\tnu_stat_err\tnu_theory\trel_error\twall_s\n";
    char line[256];
    snprintf(line, sizeof line, "%s\t%dx%dx%d\t%d\t%d\t%.9f\t%.5f\t%.5f\t%+.4f\t%.1f\n", PL_REAL_NAME,
             Lxy, Lxy, Lz, seeds, steps, nu, err_nu, th.nu, nu / th.nu - 1.0, omp_get_wtime() - t0);
    fputs(hdr, stdout);
    fputs(line, stdout);
    if (out) {
        fputs(hdr, out);
        fputs(line, out);
        fclose(out);
    }
    free(mean); free(t); free(a); free(la); free(nus);
    return 0;
}
