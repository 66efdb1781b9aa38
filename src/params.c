/* `peloid params`: the SRD fluid's derived parameters from PL Sec. II.B. */
#include <math.h>
#include <stdio.h>

#include "peloid/run.h"
#include "peloid/srd_theory.h"

void pl_params_print(const pl_scene_t *sc, FILE *out, int json)
{
    const double kT = sc->thermostat.type != PL_THERMO_NONE ? sc->thermostat.temperature
                                                            : sc->fluid.temperature;
    pl_srd_theory_t t;
    pl_srd_theory(sc->fluid.density, sc->srd.alpha_deg * M_PI / 180.0, sc->srd.dt, kT, &t);
    const int hecht = sc->srd.rule == PL_RULE_HECHT_AXES;
    /* moving no-slip walls: nominal shear rate (u_top - u_bottom) / Lz (Hecht Sec. VIII.C) */
    const int sheared = sc->box.walls_z == PL_WALLS_NOSLIP;
    double shear[2];
    for (int d = 0; d < 2; ++d)
        shear[d] = (sc->box.wall_velocity[1][d] - sc->box.wall_velocity[0][d]) / sc->box.cells[2];
    if (json) {
        fprintf(out,
                "{\"lambda\": %.10g, \"f_kin\": %.10g, \"f_col\": %.10g, \"nu_kin\": %.10g, "
                "\"nu_col\": %.10g, \"nu\": %.10g, \"eta\": %.10g, \"D_f\": %.10g, \"Sc\": %.10g, "
                "\"tau_f\": %.10g, \"c_s\": %.10g, \"kT\": %.10g",
                t.lambda, t.f_kin, t.f_col, t.nu_kin, t.nu_col, t.nu, t.eta, t.D_f, t.Sc, t.tau_f, t.c_s, kT);
        if (sheared) fprintf(out, ", \"wall_shear_rate\": [%.10g, %.10g]", shear[0], shear[1]);
        fprintf(out, "}\n");
        return;
    }
    fprintf(out, "SRD fluid of scene %s (units: a0 = 1, m_f = 1, kT_ref = 1)\n", sc->path);
    fprintf(out, "  gamma = %g particles/cell, dt = %g, alpha = %g deg (%s), kT = %g\n", sc->fluid.density,
            sc->srd.dt, sc->srd.alpha_deg, hecht ? "hecht_axes: 90 deg" : "random_axis", kT);
    if (hecht)
        fprintf(out, "  note: the formulas below are for a random rotation axis (PL Eqs. 6-15); "
                     "evaluated here at alpha = 90 deg\n");
    fprintf(out, "  lambda   = %-12.6g mean free path / a0            (PL Eq. 4)\n", t.lambda);
    fprintf(out, "  f_kin    = %-12.6g                                 (PL Eq. 11)\n", t.f_kin);
    fprintf(out, "  f_col    = %-12.6g                                 (PL Eq. 12)\n", t.f_col);
    fprintf(out, "  nu_kin   = %-12.6g a0^2/t0 kinetic viscosity      (PL Eq. 9)\n", t.nu_kin);
    fprintf(out, "  nu_col   = %-12.6g a0^2/t0 collisional viscosity  (PL Eq. 10)\n", t.nu_col);
    fprintf(out, "  nu       = %-12.6g a0^2/t0 kinematic viscosity\n", t.nu);
    fprintf(out, "  eta      = %-12.6g sqrt(m kT)/a0^2 shear viscosity (PL Eqs. 14-15)\n", t.eta);
    fprintf(out, "  D_f      = %-12.6g a0^2/t0 fluid self-diffusion   (PL Eq. 6)\n", t.D_f);
    fprintf(out, "  Sc       = %-12.6g nu / D_f Schmidt number        (PL Eq. 26)\n", t.Sc);
    fprintf(out, "  tau_f    = %-12.6g t0  a0^2/nu, momentum diffusion over one cell\n", t.tau_f);
    fprintf(out, "  c_s      = %-12.6g a0/t0 speed of sound sqrt(5kT/3m)\n", t.c_s);
    if (sheared)
        fprintf(out, "  shear    = [%g, %g] t0^-1 (u_top - u_bottom) / Lz of the walls; in the bulk "
                     "somewhat more (wall slip)\n", shear[0], shear[1]);
}
