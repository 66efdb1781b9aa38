/* Helpers shared by the mapping tests: compare with a number as the paper
 * prints it.  `unit` is one unit of the last printed digit; "within the
 * rounding of the printed digits" means |x - printed| <= unit/2. */
#ifndef PELOID_MAPPING_TESTUTIL_H
#define PELOID_MAPPING_TESTUTIL_H

#include <criterion/criterion.h>
#include <math.h>

#define EXPECT_PRINTED(x, printed, unit)                                                         \
    cr_expect(fabs((x) - (printed)) <= 0.5 * (unit) * (1 + 1e-9), "%s = %.6g, paper prints %g", \
              #x, (double)(x), (double)(printed))

/* For the papers' "approximately" entries and documented discrepancies. */
#define EXPECT_WITHIN(x, expected, tol)                                                              \
    cr_expect(fabs((x) - (expected)) <= (tol), "%s = %.6g, expected %g +- %g", #x, (double)(x), \
              (double)(expected), (double)(tol))

#define EXPECT_REL(x, expected, rel)                                                                   \
    cr_expect(fabs((x) / (expected) - 1.0) <= (rel), "%s = %.6g, expected %g within %g%%", #x, (double)(x), \
              (double)(expected), 100.0 * (rel))

#endif
