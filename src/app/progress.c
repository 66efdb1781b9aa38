/* Progress of a run: percent, simulated time (t0, and s for a physical
 * scene), an ETA from the recent rate, fluid particle updates per second and
 * colloid MD steps per second.  The rate is an exponential moving average
 * over about PL_PROGRESS_WINDOW_S of wall time, so the ETA follows a run that
 * speeds up or slows down (a sedimenting layer, a neighbour list that grows)
 * instead of the average since the start. */
#include "peloid/progress.h"

#include <limits.h>
#include <math.h>
#include <omp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define PL_PROGRESS_WINDOW_S 10.0 /* memory of the rate average */
#define PL_PROGRESS_TTY_S 0.25    /* refresh of the terminal line */

struct pl_progress {
    pl_progress_params_t p;
    double t_start, t_last_sample, t_last_line;
    long long step_last_sample;
    double rate;       /* steps per wall second, moving average (0: none yet) */
    int line_open;     /* the terminal line is showing */
    char **files; /* the run's output files, in the order given */
    int nfiles;
};

pl_progress_t *pl_progress_create(const pl_progress_params_t *p)
{
    pl_progress_t *g = calloc(1, sizeof *g);
    if (!g) return NULL;
    g->p = *p;
    g->t_start = g->t_last_sample = g->t_last_line = omp_get_wtime();
    g->step_last_sample = p->first;
    return g;
}

/* "1h02m", "3m05s", "12.3 s" */
static void fmt_dur(char *b, size_t n, double s)
{
    if (!isfinite(s) || s < 0) snprintf(b, n, "?");
    else if (s >= 3600) snprintf(b, n, "%dh%02dm", (int)(s / 3600), (int)fmod(s / 60, 60));
    else if (s >= 60) snprintf(b, n, "%dm%02ds", (int)(s / 60), (int)fmod(s, 60));
    else snprintf(b, n, "%.1f s", s);
}

static void line(pl_progress_t *g, long long step, double now)
{
    const pl_progress_params_t *p = &g->p;
    double todo = (double)(p->last - p->first), done = (double)(step - p->first);
    double t = (double)step * p->dt, el = now - g->t_start;
    double rate = g->rate > 0 ? g->rate : (el > 0 ? done / el : 0.0);
    char eta[32], tsim[96] = "", rates[96] = "", name[64] = "";
    fmt_dur(eta, sizeof eta, rate > 0 ? (todo - done) / rate : NAN);
    if (p->label) { /* a stage before the run: its wall time, not a simulated one */
        char e[32];
        fmt_dur(e, sizeof e, el);
        snprintf(name, sizeof name, "%s: ", p->label);
        snprintf(tsim, sizeof tsim, "elapsed %s", e);
    } else {
        int k = snprintf(tsim, sizeof tsim, "t = %.6g t0", t);
        if (p->t0_s > 0 && k > 0 && (size_t)k < sizeof tsim)
            snprintf(tsim + k, sizeof tsim - (size_t)k, " (%.4g s)", t * p->t0_s);
    }
    int k = 0;
    if (p->fluid_n > 0) k += snprintf(rates + k, sizeof rates - (size_t)k, "  %.3g Mupdates/s", rate * p->fluid_n / 1e6);
    if (p->md_per_step > 0 && k >= 0 && (size_t)k < sizeof rates)
        snprintf(rates + k, sizeof rates - (size_t)k, "  %.3g MD steps/s", rate * p->md_per_step);
    fprintf(p->out, "%s%s%sstep %lld/%lld %5.1f%%  %s  ETA %s%s%s", p->terminal ? "\r" : "",
            p->terminal ? "  " : "peloid: ", name, step, p->last, todo > 0 ? 100.0 * done / todo : 100.0, tsim, eta,
            rates, p->terminal ? "\033[K" : "\n");
    fflush(p->out);
    g->line_open = p->terminal;
    g->t_last_line = now;
}

void pl_progress_update(pl_progress_t *g, long long step)
{
    if (!g || !g->p.out) return;
    double now = omp_get_wtime(), dw = now - g->t_last_sample;
    if (dw >= PL_PROGRESS_TTY_S && step > g->step_last_sample) {
        double r = (double)(step - g->step_last_sample) / dw;
        double a = 1.0 - exp(-dw / PL_PROGRESS_WINDOW_S);
        g->rate = g->rate > 0 ? g->rate + a * (r - g->rate) : r;
        g->t_last_sample = now;
        g->step_last_sample = step;
    }
    double every = g->p.terminal ? PL_PROGRESS_TTY_S : g->p.interval_s;
    if (now - g->t_last_line >= every) line(g, step, now);
}

static void close_line(pl_progress_t *g)
{
    if (g->line_open) fputc('\n', g->p.out);
    g->line_open = 0;
}

void pl_progress_note(pl_progress_t *g, const char *fmt, ...)
{
    if (!g || !g->p.out) return;
    close_line(g);
    va_list ap;
    va_start(ap, fmt);
    fputs("peloid: ", g->p.out);
    vfprintf(g->p.out, fmt, ap);
    fputc('\n', g->p.out);
    va_end(ap);
    fflush(g->p.out);
}

void pl_progress_file(pl_progress_t *g, const char *dir, const char *name)
{
    if (!g) return;
    char **grown = realloc(g->files, (size_t)(g->nfiles + 1) * sizeof *grown);
    if (!grown) return; /* out of memory: the list is a courtesy, the files are written */
    g->files = grown;
    if (asprintf(&g->files[g->nfiles], "%s/%s", dir, name) >= 0) g->nfiles++;
}

static void fmt_size(char *b, size_t n, double s)
{
    if (s >= 1e9) snprintf(b, n, "%.3g GB", s / 1e9);
    else if (s >= 1e6) snprintf(b, n, "%.3g MB", s / 1e6);
    else if (s >= 1e3) snprintf(b, n, "%.3g kB", s / 1e3);
    else snprintf(b, n, "%.0f B", s);
}

void pl_progress_finish(pl_progress_t *g, long long step)
{
    if (!g || !g->p.out) return;
    const pl_progress_params_t *p = &g->p;
    double now = omp_get_wtime();
    if (p->terminal) line(g, step, now);
    close_line(g);
    double el = now - g->t_start, done = (double)(step - p->first);
    char wall[32];
    fmt_dur(wall, sizeof wall, el);
    fprintf(p->out, "peloid: %s%sdone: steps %lld..%lld in %s", p->label ? p->label : "", p->label ? ": " : "",
            p->first, step, wall);
    if (p->fluid_n > 0 && el > 0) fprintf(p->out, ", %.4g Mupdates/s", done * p->fluid_n / el / 1e6);
    if (p->md_per_step > 0 && el > 0) fprintf(p->out, ", %.4g MD steps/s", done * p->md_per_step / el);
    double t = (double)step * p->dt;
    if (!p->label) fprintf(p->out, "; simulated time %.6g t0", t);
    if (!p->label && p->t0_s > 0) fprintf(p->out, " = %.4g s", t * p->t0_s);
    fputc('\n', p->out);
    for (int k = 0; k < g->nfiles; ++k) {
        struct stat st;
        char sz[32] = "?";
        if (stat(g->files[k], &st) == 0) fmt_size(sz, sizeof sz, (double)st.st_size);
        fprintf(p->out, "peloid:   %s  %s\n", g->files[k], sz);
    }
    fflush(p->out);
}

void pl_progress_free(pl_progress_t *g)
{
    if (g && g->p.out) close_line(g); /* a run that stopped early */
    for (int k = 0; g && k < g->nfiles; ++k) free(g->files[k]);
    if (g) free(g->files);
    free(g);
}
