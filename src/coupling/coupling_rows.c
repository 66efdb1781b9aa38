/* The coupling rows (peloid/coupling_row.h), indexed by PL_COUPLE_*: one
 * line a coupling. */
#include "peloid/coupling_row.h"

static const pl_coupling_row_t *const rows[] = {
    [PL_COUPLE_HECHT1] = &pl_coupling1_row,
    [PL_COUPLE_HECHT2] = &pl_coupling2_row,
    [PL_COUPLE_POTENTIAL] = &pl_coupling_potential_row,
};

const pl_coupling_row_t *pl_coupling_row(int m)
{
    return m > 0 && (size_t)m < sizeof rows / sizeof rows[0] ? rows[m] : NULL;
}
