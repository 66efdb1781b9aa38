/* Energy drift of undamped colloid MD against the time step (the
 * error-against-run-time view): 27 colloids with DLVO (Hecht Fig. 1 set A) +
 * Hertz, kT = 1, run for 2500 t0 at several dt_MD.  One line per case:
 *   kernel dt steps max_drift_per_colloid seconds */
#include <math.h>
#include <omp.h>
#include <stdio.h>

#include "peloid/colloid.h"

int main(void)
{
    int subs[] = {2, 4, 8, 16};
    for (int k = 0; k < 4; ++k) {
        char sc[1024];
        snprintf(sc, sizeof sc,
                 "box: { cells = [24, 24, 24]; }; fluid: { density = 0.0; }; srd: { dt = 0.1; };\n"
                 "colloids: { count = 27; radius = 2.0; substeps = %d; pairs = \"dlvo, hertz\";\n"
                 "  max_energy_drift = 0.0; min_contact_steps = 0.0; };\n"
                 "dlvo: { psi0 = 20.0; kappa = 1.4e8; hamaker = 4.76e-20; length_unit = 1.25e-7; };\nhertz: { K = 1000.0; };\n",
                 subs[k]);
        pl_scene_t s;
        pl_err_t err;
        pl_colloid_t *c;
        if (pl_scene_load_string(sc, "bench", &s, &err) || pl_colloid_create(&s, 1, &c, &err) /* 27 colloids: serial */) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
        pl_colloid_energy_t e;
        double e0 = c->e0, worst = 0;
        long steps = (long)llround(2500.0 / c->dt);
        double t0 = omp_get_wtime();
        for (long i = 0; i < steps; ++i) {
            if (pl_colloid_md_step(c, &err)) {
                fprintf(stderr, "%s\n", err.msg);
                return 1;
            }
            if (i % 10 == 0) {
                pl_colloid_energy(c, &e);
                worst = fmax(worst, fabs(e.total - e0) / (double)c->n);
            }
        }
        printf("kernel=colloid_nve_drift dt=%.6g steps=%ld max_drift_kT_per_colloid=%.3g seconds=%.3f\n",
               c->dt, steps, worst, omp_get_wtime() - t0);
        pl_colloid_free(c);
    }
    return 0;
}
