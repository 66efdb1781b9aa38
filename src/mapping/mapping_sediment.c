/* Whether a physical scene's run can resolve the colloids' settling
 * velocity (its sedimentation observer on, gravity on).
 *
 * Over the observed time t the colloids' mean height falls v_S t, with v_S
 * = M g D / kT the Stokes velocity the mapping matched (Hecht Eq. 16 with
 * the model colloid's D; a0/t0 at kT_model = 1), while the mean height of N
 * colloids diffusing independently spreads by sqrt(2 D t / N).  Their ratio
 *     Pe_run = v_S t / sqrt(2 D t / N) = v_S sqrt(N t / (2 D))
 * is the run's settling Peclet number: below 3 the fall is within three
 * standard deviations of the Brownian drift of the mean and no settling
 * velocity can be told from it (a warning: lengthen the run or add
 * colloids); the SE the observer reports shrinks as 1 / Pe_run. */
#include <math.h>

#include "peloid/mapping.h"
#include "peloid/scene.h"

#define PE_RUN_MIN 3.0

void pl_mapping_sediment_audit(const pl_scene_t *s, pl_mapping_t *m)
{
    const pl_scene_observe_t *o = &s->observe;
    if (o->sediment_interval <= 0 || !(m->g_sim > 0.0) || s->colloids.count < 1) return;
    const double t = (double)(s->run.steps - o->sediment_start) * s->srd.dt;
    const double D = m->d_col_box > 0.0 ? m->d_col_box : m->d_col_sim;
    if (!(t > 0.0) || !(D > 0.0)) return;
    const double v = m->mass_sim * m->g_sim * D, n = (double)s->colloids.count;
    const double pe = v * sqrt(n * t / (2.0 * D));
    if (pe < PE_RUN_MIN)
        pl_mapping_warn(m, PL_SEV_WARNING, "SETTLING_UNRESOLVED", pe,
                        "the run's settling Peclet number v_S sqrt(N t / 2D) = %.3g < %.0f: over the %.4g t0 the "
                        "sedimentation observer watches, %lld colloids fall %.3g a0, less than %.0f times the "
                        "Brownian spread of their mean height (%.3g a0); no settling velocity can be resolved: "
                        "raise the steps, physical.box or physical.volume_fraction",
                        pe, PE_RUN_MIN, t, s->colloids.count, v * t, PE_RUN_MIN, sqrt(2.0 * D * t / n));
}
