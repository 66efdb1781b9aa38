/* Streaming + collision conserve total momentum (no thermostat, periodic,
 * no force) to 1e-12 relative over 10^4 steps; kinetic energy likewise
 * (issue 2).  The fluid is given a mean flow so that the relative bound is
 * taken against a non-zero total momentum. */
#include <math.h>

#include "support.h"

Test(conservation, momentum_and_energy_over_1e4_steps, .timeout = 120)
{
    pl_sim_t *sim = pl_test_sim("seed = 5;\nbox: { cells = [8, 8, 8]; };\nfluid: { density = 5.0; };\n"
                                "srd: { dt = 0.5; alpha = 130.0; };\n",
                                2);
    const double flow[3] = {0.3, -0.2, 0.1};
    for (size_t i = 0; i < sim->fluid.n; ++i)
        for (int d = 0; d < 3; ++d) sim->fluid.v[d][i] += flow[d];
    pl_fluid_obs_t o0, o1;
    double kT;
    pl_sim_observe(sim, &o0, &kT);
    double P0 = sqrt(o0.momentum[0] * o0.momentum[0] + o0.momentum[1] * o0.momentum[1] +
                     o0.momentum[2] * o0.momentum[2]);
    long long steps = pl_test_quick() ? 500 : 10000;
    pl_test_steps(sim, steps);
    pl_sim_observe(sim, &o1, &kT);
    for (int d = 0; d < 3; ++d)
        cr_assert(fabs(o1.momentum[d] - o0.momentum[d]) <= 1e-12 * P0, "P_%d: %.17g -> %.17g (|P| = %g)", d,
                  o0.momentum[d], o1.momentum[d], P0);
    cr_assert(fabs(o1.kinetic - o0.kinetic) <= 1e-12 * o0.kinetic, "E: %.17g -> %.17g", o0.kinetic, o1.kinetic);
    pl_sim_free(sim);
}
