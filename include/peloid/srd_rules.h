/* The SRD collision rule and the Heyes acceptance, shared by the fluid
 * collision (kernels/srd_collide.c) and coupling II (kernels/coupling_collide.c).
 * Pure functions of uniforms drawn by the caller (each caller keys its own
 * counter-based stream). */
#ifndef PELOID_SRD_RULES_H
#define PELOID_SRD_RULES_H

#include <math.h>

#include "peloid/scene.h"

/* Rotation matrix from two uniforms u0, u1 in (0, 1).
 * PL_RULE_RANDOM_AXIS: rotation by alpha (cos_a, sin_a) about an axis uniform
 * on the sphere (PL Eq. 3, Rodrigues' formula).  PL_RULE_HECHT_AXES: +-90 deg
 * about one of the three coordinate axes, each of the 6 with probability 1/6
 * (Hecht Sec. III); u1 unused. */
static inline void pl_srd_rotation(int rule, double cos_a, double sin_a, double u0, double u1,
                                   double R[3][3])
{
    if (rule == PL_RULE_HECHT_AXES) {
        int k = (int)(u0 * 6.0); /* 0..5: axis k/2, sign by parity */
        if (k > 5) k = 5;
        int a = k >> 1;
        double s = (k & 1) ? -1.0 : 1.0;
        int b = (a + 1) % 3, c = (a + 2) % 3;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) R[i][j] = 0.0;
        /* rotation by s*90 deg about axis a: e_b -> s e_c, e_c -> -s e_b */
        R[a][a] = 1.0;
        R[c][b] = s;
        R[b][c] = -s;
        return;
    }
    double cz = 2.0 * u0 - 1.0, sz = sqrt(1.0 - cz * cz);
    double phi = 6.283185307179586476925 * u1;
    double n[3] = {sz * cos(phi), sz * sin(phi), cz};
    double ca = cos_a, sa = sin_a, oc = 1.0 - ca;
    R[0][0] = ca + n[0] * n[0] * oc;
    R[0][1] = n[0] * n[1] * oc - n[2] * sa;
    R[0][2] = n[0] * n[2] * oc + n[1] * sa;
    R[1][0] = n[1] * n[0] * oc + n[2] * sa;
    R[1][1] = ca + n[1] * n[1] * oc;
    R[1][2] = n[1] * n[2] * oc - n[0] * sa;
    R[2][0] = n[2] * n[0] * oc - n[1] * sa;
    R[2][1] = n[2] * n[1] * oc + n[0] * sa;
    R[2][2] = ca + n[2] * n[2] * oc;
}

/* Heyes Monte Carlo scale factor (Hecht Sec. VIII.B, Eq. 33) for a cell of
 * nbody bodies with relative kinetic energy K = sum m (v-u)^2 / 2, from three
 * uniforms: eps = eps_max u0; zeta = 1+eps or 1/(1+eps) (u1 < 1/2), accepted
 * (u2) with probability min(1, zeta^{3(nbody-1)} exp(-(zeta^2-1) K/kT*)).
 * With Hecht's T = m sum (v-u)^2 / (2 (M-1) k_B) this is his Eq. 33 exactly.
 * Returns 1 when rejected. */
static inline double pl_heyes_zeta(double eps_max, double kT_target, double nbody, double K,
                                   double u0, double u1, double u2)
{
    double eps = eps_max * u0;
    double zeta = u1 < 0.5 ? 1.0 + eps : 1.0 / (1.0 + eps);
    double dof = 3.0 * (nbody - 1.0);
    double log_acc = dof * log(zeta) - (zeta * zeta - 1.0) * K / kT_target;
    return (log_acc >= 0.0 || log(u2) < log_acc) ? zeta : 1.0;
}

#endif
