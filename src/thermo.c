/* thermo.tsv columns (include/peloid/thermo.h).  Each module's columns are
 * one table below, with a predicate saying whether the simulation has that
 * module; pl_thermo_table_build concatenates the tables that apply. */
#include <string.h>

#include "peloid/coupling.h"
#include "peloid/mapping.h"
#include "peloid/thermo.h"

typedef struct {
    int (*present)(const pl_sim_t *sim);
    const pl_thermo_column_t *col;
    int n;
} group_t;

#define NCOL(a) ((int)(sizeof(a) / sizeof(a[0])))

/* ---- fluid ------------------------------------------------------------ */
static long long v_step(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->sim->step;
}
static double v_time(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return (double)s->sim->step * s->sim->scene.srd.dt;
}
static double v_kT(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->kT;
}
static double v_kT_cell(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->sim->last_kT_meas;
}
static double v_momentum(const pl_thermo_sample_t *s, int d) { return s->fluid.momentum[d]; }
static double v_kinetic(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->fluid.kinetic;
}
static double v_msd(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->fluid.msd;
}
static int always(const pl_sim_t *sim)
{
    (void)sim;
    return 1;
}
static int tracked(const pl_sim_t *sim) { return sim->fluid.tracked; }

static const pl_thermo_column_t step_time[] = {
    {.name = "step", .unit = "1", .format = PL_THERMO_INT, .ivalue = v_step},
    {.name = "time", .unit = "t0", .value = v_time},
};
static const pl_thermo_column_t fluid_cols[] = {
    {.name = "temperature", .unit = "kT", .value = v_kT},
    {.name = "kT_cell", .unit = "kT", .value = v_kT_cell}, /* PL Eq. A1, last collision */
    {.name = "px", .unit = "m_f a0/t0", .value = v_momentum, .arg = 0},
    {.name = "py", .unit = "m_f a0/t0", .value = v_momentum, .arg = 1},
    {.name = "pz", .unit = "m_f a0/t0", .value = v_momentum, .arg = 2},
    {.name = "kinetic_energy", .unit = "kT", .value = v_kinetic},
};
static const pl_thermo_column_t tracked_cols[] = {
    {.name = "msd", .unit = "a0^2", .value = v_msd},
};

/* ---- physical units (Hecht Sec. VII): kT = 1 is the model temperature ---- */
static int mapped(const pl_sim_t *sim) { return sim->scene.mapping.enabled; }
static double v_time_s(const pl_thermo_sample_t *s, int a)
{
    return v_time(s, a) * s->sim->scene.mapping.map.t0;
}
static double v_temperature_K(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->kT * s->sim->scene.mapping.map.kT_model / PL_KB;
}
static const pl_thermo_column_t mapped_cols[] = {
    {.name = "time_s", .unit = "s", .value = v_time_s},
    {.name = "temperature_K", .unit = "K", .value = v_temperature_K},
};

/* ---- walls: PL Eq. 13 stress from each wall's momentum, mean since step 0 */
static int noslip_walls(const pl_sim_t *sim)
{
    return sim->scene.box.walls_z == PL_WALLS_NOSLIP && sim->fluid.n > 0;
}
static int noslip_side_walls(const pl_sim_t *sim)
{
    return sim->scene.box.walls_xy == PL_WALLS_NOSLIP && sim->fluid.n > 0;
}
/* arg = 3 wall + d */
static double v_wall_stress(const pl_thermo_sample_t *s, int a) { return pl_sim_wall_stress(s->sim, a / 3, a % 3); }
static const pl_thermo_column_t wall_cols[] = {
    {.name = "sxz_bottom", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 0},
    {.name = "sxz_top", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 3},
    {.name = "syz_bottom", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 1},
    {.name = "syz_top", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 4},
};
static const pl_thermo_column_t side_wall_cols[] = { /* force per area on the x/y walls */
    {.name = "s_side_x", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 6},
    {.name = "s_side_y", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 7},
    {.name = "s_side_z", .unit = "kT/a0^3", .value = v_wall_stress, .arg = 8},
};

/* ---- colloids (energies: src/colloid_state.c) ------------------------- */
static int colloids(const pl_sim_t *sim) { return sim->colloids != NULL; }
static double v_ekin(const pl_thermo_sample_t *s, int rot) { return rot ? s->ce.kin_rot : s->ce.kin_trans; }
static double v_epot(const pl_thermo_sample_t *s, int k) { return s->ce.pot[k]; }
static double v_etotal(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->ce.total;
}
/* centre-of-mass height of the colloids (unwrapped z): sedimentation */
static double v_zcm(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    const pl_colloid_t *c = s->sim->colloids;
    double mz = 0.0, m = 0.0;
    for (size_t k = 0; k < c->n; ++k) { /* fixed order */
        mz += c->mass[k] * (c->z[k] + (double)c->iz[k] * c->box[2]);
        m += c->mass[k];
    }
    return m > 0.0 ? mz / m : 0.0;
}
static const pl_thermo_column_t colloid_kin_cols[] = {
    {.name = "c_kin_trans", .unit = "kT", .value = v_ekin, .arg = 0},
    {.name = "c_kin_rot", .unit = "kT", .value = v_ekin, .arg = 1},
};
static const pl_thermo_column_t colloid_tail_cols[] = {
    {.name = "c_total", .unit = "kT", .value = v_etotal},
    {.name = "c_zcm", .unit = "a0", .value = v_zcm},
};

/* ---- couplings -------------------------------------------------------- */
static int reflecting(const pl_sim_t *sim) /* coupling I (Hecht Sec. IV) */
{
    return sim->coupling && sim->coupling->method == PL_COUPLE_HECHT1;
}
static long long v_events(const pl_thermo_sample_t *s, int trunc)
{
    const pl_coupling_t *cp = s->sim->coupling;
    return (long long)(trunc ? cp->truncations : cp->events);
}
static const pl_thermo_column_t reflect_cols[] = {
    {.name = "cpl_events", .unit = "1", .format = PL_THERMO_INT, .ivalue = v_events, .arg = 0},
    {.name = "cpl_truncations", .unit = "1", .format = PL_THERMO_INT, .ivalue = v_events, .arg = 1},
};
static int pinned(const pl_sim_t *sim) { return sim->coupling && sim->coupling->pinned; }
static double v_drag(const pl_thermo_sample_t *s, int d) /* mean force per pinned colloid so far */
{
    const pl_coupling_t *cp = s->sim->coupling;
    double k = cp->pinned_time > 0 ? 1.0 / (cp->pinned_time * (double)s->sim->colloids->n) : 0.0;
    return cp->impulse[d] * k;
}
static const pl_thermo_column_t pinned_cols[] = {
    {.name = "cpl_drag_x", .unit = "kT/a0", .value = v_drag, .arg = 0},
    {.name = "cpl_drag_y", .unit = "kT/a0", .value = v_drag, .arg = 1},
    {.name = "cpl_drag_z", .unit = "kT/a0", .value = v_drag, .arg = 2},
};

static double v_rate(const pl_thermo_sample_t *s, int a)
{
    (void)a;
    return s->rate;
}
static const pl_thermo_column_t rate_cols[] = { /* wall clock: last, apart from the state */
    {.name = "mupdates_per_s", .unit = "1e6/s", .format = PL_THERMO_RATE, .value = v_rate},
};

static void add(pl_thermo_table_t *t, const pl_thermo_column_t *c, int n)
{
    for (int k = 0; k < n && t->n < PL_THERMO_MAX_COLUMNS; ++k) t->col[t->n++] = c[k];
}

void pl_thermo_table_build(const pl_sim_t *sim, pl_thermo_table_t *t)
{
    t->n = 0;
    add(t, step_time, NCOL(step_time));
    if (mapped(sim)) add(t, mapped_cols, NCOL(mapped_cols));
    const group_t groups[] = {
        {always, fluid_cols, NCOL(fluid_cols)},
        {tracked, tracked_cols, NCOL(tracked_cols)},
        {noslip_walls, wall_cols, NCOL(wall_cols)},
        {noslip_side_walls, side_wall_cols, NCOL(side_wall_cols)},
    };
    for (int g = 0; g < NCOL(groups); ++g)
        if (groups[g].present(sim)) add(t, groups[g].col, groups[g].n);
    if (colloids(sim)) {
        add(t, colloid_kin_cols, NCOL(colloid_kin_cols));
        for (int k = 0; k < PL_CE_NTERMS; ++k) { /* one column per energy term, named by its table */
            pl_thermo_column_t c = {.name = pl_colloid_energy_names[k], .unit = "kT", .value = v_epot, .arg = k};
            add(t, &c, 1);
        }
        add(t, colloid_tail_cols, NCOL(colloid_tail_cols));
    }
    if (reflecting(sim)) add(t, reflect_cols, NCOL(reflect_cols));
    if (pinned(sim)) add(t, pinned_cols, NCOL(pinned_cols));
    add(t, rate_cols, NCOL(rate_cols));
}

void pl_thermo_header(const pl_thermo_table_t *t, FILE *f)
{
    for (int k = 0; k < t->n; ++k) fprintf(f, "%s%c", t->col[k].name, k + 1 < t->n ? '\t' : '\n');
}

void pl_thermo_sample(const pl_sim_t *sim, double rate, pl_thermo_sample_t *s)
{
    memset(s, 0, sizeof *s);
    s->sim = sim;
    s->rate = rate;
    pl_sim_observe(sim, &s->fluid, &s->kT);
    if (sim->colloids) pl_colloid_energy(sim->colloids, &s->ce);
}

int pl_thermo_row(const pl_thermo_table_t *t, const pl_thermo_sample_t *s, FILE *f)
{
    int r = 0;
    for (int k = 0; k < t->n && r >= 0; ++k) {
        const pl_thermo_column_t *c = &t->col[k];
        const char sep = k + 1 < t->n ? '\t' : '\n';
        if (c->format == PL_THERMO_INT) r = fprintf(f, "%lld%c", c->ivalue(s, c->arg), sep);
        else if (c->format == PL_THERMO_RATE) r = fprintf(f, "%.4g%c", c->value(s, c->arg), sep);
        else r = fprintf(f, "%.10g%c", c->value(s, c->arg), sep);
    }
    return r;
}
