/* Transport coefficients of an SRD fluid (PL Sec. II.B, Eqs. 4-15), in the
 * simulation units a0 = 1, m_f = 1 (kT as given). */
#ifndef PELOID_SRD_THEORY_H
#define PELOID_SRD_THEORY_H

typedef struct {
    double lambda;   /* mean free path / a0 (PL Eq. 4) */
    double f_kin, f_col; /* PL Eqs. 11-12 */
    double nu_kin, nu_col, nu; /* kinematic viscosity (PL Eqs. 9-10) */
    double eta;      /* shear viscosity rho nu (PL Eqs. 14-15) */
    double D_f;      /* fluid self-diffusion (PL Eq. 6) */
    double Sc;       /* Schmidt number nu / D_f (PL Eq. 26) */
    double tau_f;    /* fluid momentum-diffusion time over a cell, a0^2 / nu */
    double c_s;      /* ideal-gas speed of sound sqrt(5 kT / 3 m) */
} pl_srd_theory_t;

/* gamma: particles per cell, alpha in radians, dt: collision step, kT. */
void pl_srd_theory(double gamma, double alpha, double dt, double kT, pl_srd_theory_t *out);

double pl_srd_f_kin(double gamma, double alpha);
double pl_srd_f_col(double gamma, double alpha);

#endif
