/* The stress observer's state (src/observe/stress_module.c: checks, stages,
 * checkpoint; stress_output.c: its estimates, observables.h5 groups and
 * summary entries).  Private to src/observe. */
#ifndef PELOID_STRESS_PRIV_H
#define PELOID_STRESS_PRIV_H

#include <jansson.h>
#include <stdint.h>

#include "observables_out.h"
#include "peloid/blocking.h"
#include "peloid/error.h"
#include "peloid/module.h"
#include "peloid/sim.h"
#include "peloid/srd_kernels.h"

enum { NOFF = 6, NFRAC = PL_OBS_NFRAC };

typedef struct pl_stress {
    int K;              /* Green-Kubo lags */
    double V, kT, dt, N;
    double *scratch;
    double pre[PL_STRESS_NSUMS]; /* sums before this step's collision */
    int have_pre;
    double *ring;       /* K x NOFF: g of the last K steps, newest at ring_head */
    int ring_head;
    long long ring_n;
    double *cacc;       /* (K + 1): sum over steps and (a, b) of g(n) g(n - k) */
    uint64_t ncorr;     /* steps in cacc */
    pl_blocking_t eta;  /* per-step Green-Kubo estimator */
    pl_blocking_t pressure;
    double win[9];      /* P_ab summed over the present output window */
    long long win_n;
    long long *ts_step;
    double *ts_val;     /* 9 per sample */
    size_t ts_n, ts_cap;
    long long first, last;
    double t_start, wall;
    pl_obs_point_t ept[NFRAC];
    int next_frac;
    /* Couette */
    int couette;
    double e[3], A, du, imp_prev[2];
    int nlayers;
    double *lay_sum, *lay_cnt;
    pl_blocking_t sigma, rate;
    double *ts_sigma, *ts_rate; /* per sample: mean stress since the last, slope */
    double *ts_prof;            /* per sample: nlayers layer means of v . e, then nlayers densities */
    /* restart (stress_ckpt_read): the checkpoint's step (-1: none) */
    long long resume_step;
    int begun, have_first, nept_saved;
    pl_obs_point_t ept_saved[NFRAC];
} pl_stress_t;

/* The run's stress observer (NULL without): the stress module's state. */
static inline pl_stress_t *pl_stress_of(const pl_sim_t *sim) { return pl_module_state(sim, &pl_stress_module); }

/* The Green-Kubo estimate and SE of eta after what was sampled (res: the
 * blocking result); 0 when there is none. */
int pl_stress_eta_estimate(const pl_stress_t *o, double *v, double *se, pl_blocking_result_t *res);
/* Couette: eta = <sigma> / <rate> and its SE; 0 when there is none. */
int pl_stress_couette_estimate(const pl_stress_t *o, double *v, double *se, pl_blocking_result_t *rs,
                               pl_blocking_result_t *rr);
/* The module's finish (peloid/module.h): the stress groups of observables.h5
 * and the summary.json entries. */
int pl_stress_finish(pl_sim_t *sim, const char *dir, json_t *doc, pl_err_t *err);

#endif
