/* Plausibility of the physical{} inputs of a liquid suspension: each key
 * has a range that covers the colloids and solvents peloid is for (water and
 * organic solvents, nm to 100 um particles, 1:1 to 4:4 salts); a value
 * outside it is most often a unit mistake, and the warning names the likely
 * one (a dynamic viscosity given for the kinematic one, millimolar for
 * molar, g/cm^3 for kg/m^3, micrometres for metres, mV for V, Celsius for
 * kelvin).  Warnings: `peloid check` and `run` print them, `--strict` and
 * coarse_graining.strict refuse the scene.  The ranges are listed in README
 * ("Physical units: plausible ranges").  The same ranges pick the key a
 * derived-value refusal blames (pl_mapping_blame). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>

#include "peloid/mapping.h"
#include "peloid/scene.h"

#define OFF(m) offsetof(pl_scene_t, m)

/* A physical key: the range [lo, hi] (|value| for the potential), and the
 * likely mistake below and above it (NULL: none to name). */
static const struct {
    size_t off;
    const char *key, *unit;
    double lo, hi;
    int absolute;   /* compare |value| (the surface potential's sign is free) */
    int zero_ok;    /* 0 means "not given" */
    const char *below, *above;
} ranges[] = {
    {OFF(mapping.physical.radius), "physical.radius", "m", 1e-9, 1e-4, 0, 0,
     "below 1 nm: a molecule, not a colloid", "looks like micrometres or millimetres; radius is in m (0.5 um: 0.5e-6)"},
    {OFF(mapping.physical.particle_density), "physical.particle_density", "kg/m^3", 100.0, 2.5e4, 0, 0,
     "looks like g/cm^3; densities are in kg/m^3 (Al2O3: 3.9e3)", "denser than any solid (osmium: 2.26e4)"},
    {OFF(mapping.physical.solvent_density), "physical.solvent_density", "kg/m^3", 500.0, 2500.0, 0, 0,
     "looks like g/cm^3; densities are in kg/m^3 (water: 1e3)", "denser than any common liquid solvent"},
    {OFF(mapping.physical.temperature), "physical.temperature", "K", 150.0, 650.0, 0, 0,
     "looks like degrees Celsius; temperature is in K (25 C: 298.15)", "above the critical point of water"},
    {OFF(mapping.physical.viscosity), "physical.viscosity", "m^2/s", 1e-7, 1e-4, 0, 0,
     "below any liquid's (acetone: 4e-7)",
     "looks like a dynamic viscosity in Pa s; viscosity is kinematic, m^2/s (water: 1e-6 = 0.89e-3 Pa s / 1e3 "
     "kg/m^3)"},
    {OFF(mapping.physical.gravity), "physical.gravity", "m/s^2", 0.01, 1e4, 0, 1,
     "below any planet's", "beyond a centrifuge's (Earth: 9.81)"},
    {OFF(mapping.physical.hamaker), "physical.hamaker", "J", 1e-22, 1e-18, 0, 1,
     "below any material pair's (~1e-21 for polymers in water)", "above any (metals: ~4e-19)"},
    {OFF(mapping.physical.surface_potential), "physical.surface_potential", "V", 1e-4, 0.3, 1, 1,
     "below 0.1 mV: no measurable charge (0 switches the term off)",
     "looks like millivolts; the potential is in V (20 mV: 0.02)"},
    {OFF(mapping.physical.ionic_strength), "physical.ionic_strength", "mol/L", 1e-7, 5.0, 0, 1,
     "below pure water's 1e-7 mol/L", "looks like millimolar; ionic_strength is in mol/L (10 mM: 0.01)"},
    {OFF(mapping.physical.kappa), "physical.kappa", "1/m", 1e6, 3e9, 0, 1,
     "a Debye length above 1 um: purer than pure water", "looks like 1/nm or a length; kappa is in 1/m "
     "(1/kappa = 3 nm: 3.3e8)"},
    {OFF(mapping.physical.primary_minimum), "physical.primary_minimum", "m", 1e-10, 1e-7, 0, 1,
     "below an atom's size", "looks like nanometres; the distance is in m (Hecht: 8e-9)"},
};

void pl_mapping_plausible(const struct pl_scene *s, pl_mapping_t *m)
{
    for (size_t k = 0; k < sizeof ranges / sizeof ranges[0]; ++k) {
        const double v = *(const double *)((const char *)s + ranges[k].off);
        const double a = ranges[k].absolute ? fabs(v) : v;
        if (ranges[k].zero_ok && v == 0.0) continue;
        if (a >= ranges[k].lo && a <= ranges[k].hi) continue;
        const int line = pl_scene_line_of(s, ranges[k].off);
        const char *why = a < ranges[k].lo ? ranges[k].below : ranges[k].above;
        char at[32] = "";
        if (line > 0) snprintf(at, sizeof at, " (line %d)", line);
        const int before = m->nwarn;
        pl_mapping_warn(m, PL_SEV_WARNING, "IMPLAUSIBLE", v,
                        "%s = %g %s%s is outside the plausible range %g..%g %s of a liquid suspension: %s",
                        ranges[k].key, v, ranges[k].unit, at, ranges[k].lo, ranges[k].hi, ranges[k].unit, why);
        if (m->nwarn > before) { /* not dropped at PL_MAP_MAX_WARN */
            pl_mapping_warning_t *w = &m->warn[m->nwarn - 1];
            snprintf(w->key, sizeof w->key, "%s", ranges[k].key);
            w->key_off = ranges[k].off;
        }
    }
}

/* The index in `ranges` of the key at `off` if the file gives it outside
 * its plausible range; -1: in range, not given, or a key without a range. */
static int implausible(const struct pl_scene *s, size_t off)
{
    for (size_t k = 0; k < sizeof ranges / sizeof ranges[0]; ++k) {
        if (ranges[k].off != off) continue;
        const double v = *(const double *)((const char *)s + off);
        const double a = ranges[k].absolute ? fabs(v) : v;
        const int bad = pl_scene_line_of(s, off) > 0 && !(ranges[k].zero_ok && v == 0.0) &&
                        !(a >= ranges[k].lo && a <= ranges[k].hi);
        return bad ? (int)k : -1;
    }
    return -1;
}

const char *pl_mapping_blame(const struct pl_scene *s, const size_t *offs, size_t n, size_t *off, char *why,
                             size_t nwhy)
{
    why[0] = '\0';
    for (size_t i = 0; i < n; ++i) {
        const int k = implausible(s, offs[i]);
        if (k < 0) continue;
        *off = offs[i];
        snprintf(why, nwhy, "%g %s, outside the plausible %g..%g %s, gives: ",
                 *(const double *)((const char *)s + offs[i]), ranges[k].unit, ranges[k].lo, ranges[k].hi,
                 ranges[k].unit);
        return ranges[k].key;
    }
    return NULL;
}
