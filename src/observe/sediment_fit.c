/* The settling velocities a user of the sedimentation observer means
 * (issue 35): the initial velocity of the homogeneous fall, over the window
 * the data show to be homogeneous, and the comparison with Stokes (Hecht
 * Eq. 16, with the friction the mapping matched) and Richardson-Zaki (Hecht
 * Eq. 37) at the scene's volume fraction.
 *
 * The samples are the velocities of the colloids' mean height between
 * consecutive observer samples, v_k = (h_k - h_{k-1}) / dt_k (less the
 * fluid's mean velocity); over samples a few colloid relaxation times apart
 * they are independent (the mean height is a random walk with drift).  The
 * fall is homogeneous while the drift does not change: the window is the
 * longest prefix of the series whose first and second halves agree within 2
 * combined standard errors (a z test; a settling layer slows the second
 * half); prefixes of 16, 24, 32, ... samples are tried and the longest that
 * passes is kept, so its SE shrinks as the data allow and never mixes the
 * settled state in.  The SE is from blocking over the window (which also
 * covers correlated samples). */
#include <math.h>
#include <stddef.h>

#include "peloid/blocking.h"
#include "sediment_fit.h"

/* mean and SE (blocking) of v[a, b) */
static void mean_se(const double *v, size_t a, size_t b, double *mean, double *se)
{
    pl_blocking_t bl;
    pl_blocking_init(&bl);
    for (size_t k = a; k < b; ++k) pl_blocking_add(&bl, v[k]);
    pl_blocking_result_t r = pl_blocking_result(&bl);
    *mean = r.mean;
    *se = r.se;
}

/* |first half - second half| / combined SE of v[0, n) */
static double drift_z(const double *v, size_t n)
{
    double m1, s1, m2, s2;
    mean_se(v, 0, n / 2, &m1, &s1);
    mean_se(v, n / 2, n, &m2, &s2);
    const double s = sqrt(s1 * s1 + s2 * s2);
    return s > 0 ? fabs(m1 - m2) / s : (m1 == m2 ? 0.0 : INFINITY);
}

int pl_sediment_initial(const double *v, size_t n, pl_sediment_fit_t *out)
{
    enum { MIN_WINDOW = 16, STEP = 8 };
    *out = (pl_sediment_fit_t){.window = 0, .z_whole = n >= 4 ? drift_z(v, n) : NAN};
    if (n < MIN_WINDOW) return -1;
    size_t best = 0;
    double zbest = NAN;
    for (size_t w = MIN_WINDOW; w <= n; w += STEP) {
        const double z = drift_z(v, w);
        if (z < 2.0) {
            best = w;
            zbest = z;
        }
    }
    if (!best) return -1;
    out->window = best;
    out->z_window = zbest;
    mean_se(v, 0, best, &out->value, &out->se);
    return 0;
}
