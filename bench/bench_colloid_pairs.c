/* Colloid pair-force throughput of one force evaluation (the neighbour list
 * already built: the colloids do not move): ordered pairs within the cut-off
 * per second (each unordered pair is evaluated once, Newton's third law, and
 * counted twice, as the figures of the former full lists were), for 1 and 2
 * threads (or PL_BENCH_THREADS), DLVO + Hertz + WCA, polydisperse colloids
 * at volume fraction ~0.27 (simple cubic lattice).  The whole MD step on a
 * dense suspension: bench_colloid_md.  One line per case:
 *   kernel threads n pairs ns_per_pair pairs_per_s */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#include "peloid/colloid.h"

int main(void)
{
    const char *sc = "box: { cells = [80, 80, 80]; }; fluid: { density = 0.0; };\n"
                     "colloids: { count = 4096; init = \"lattice\"; radius = 2.0; polydispersity = 0.05;\n"
                     "  pairs = \"dlvo, hertz, wca\"; min_contact_steps = 0.0; };\n"
                     "dlvo: { psi0 = 20.0; kappa = 1.4e8; hamaker = 4.76e-20; length_unit = 1.25e-7; cutoff_energy = 0.01; };\n";
    pl_scene_t s;
    pl_err_t err;
    if (pl_scene_load_string(sc, "bench", &s, &err) || 0) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    int maxt = omp_get_num_procs() < 2 ? 1 : 2;
    for (int t = 1; t <= maxt; ++t) {
        pl_colloid_t *c;
        if (pl_colloid_create(&s, t, &c, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
        /* ordered pairs inside the per-pair cut-off, counted once */
        long long pairs = 0;
        double L = c->box[0];
        for (size_t i = 0; i < c->n; ++i)
            for (size_t j = 0; j < c->n; ++j) {
                if (i == j) continue;
                double dx = c->x[i] - c->x[j], dy = c->y[i] - c->y[j], dz = c->z[i] - c->z[j];
                dx -= L * rint(dx / L), dy -= L * rint(dy / L), dz -= L * rint(dz / L);
                double rc = fmax(c->rad[i] + c->rad[j] + c->pair.gap_cut, (c->rad[i] + c->rad[j]) * c->pair.wca_rfac);
                pairs += dx * dx + dy * dy + dz * dz < rc * rc;
            }
        int reps = 50;
        pl_colloid_forces(c, &err);
        double t0 = omp_get_wtime();
        for (int r = 0; r < reps; ++r) pl_colloid_forces(c, &err);
        double el = (omp_get_wtime() - t0) / reps;
        printf("kernel=colloid_pairs threads=%d n=%zu pairs=%lld ns_per_pair=%.3f pairs_per_s=%.4g\n", t,
               c->n, pairs, el * 1e9 / (double)pairs, (double)pairs / el);
        pl_colloid_free(c);
    }
    return 0;
}
