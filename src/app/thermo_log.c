/* thermo.tsv as the run keeps it (include/peloid/thermo.h): a sample of the
 * state a row shows (the fluid's observables, the colloids' energies), and the
 * file, new or continued after a restart (its header checked, the rows from
 * the restart's step on cut).  The columns are core's (src/core/thermo_table.c). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "peloid/colloid.h"
#include "peloid/thermo.h"

void pl_thermo_sample(const pl_sim_t *sim, double rate, pl_thermo_sample_t *s)
{
    memset(s, 0, sizeof *s);
    s->sim = sim;
    s->rate = rate;
    pl_sim_observe(sim, &s->fluid, &s->kT);
    if (sim->colloids) pl_colloid_energy(sim->colloids, &s->ce);
}

int pl_thermo_open(const pl_thermo_table_t *t, const char *path, long long keep, FILE **out, pl_err_t *err)
{
    FILE *f = keep >= 0 ? fopen(path, "r+") : NULL;
    if (!f && keep >= 0 && errno != ENOENT)
        return pl_err_set(err, PL_ERR_IO, "%s: cannot open to continue: %s", path, strerror(errno));
    if (!f) { /* a new file */
        if (!(f = fopen(path, "w"))) return pl_err_set(err, PL_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
        pl_thermo_header(t, f);
        *out = f;
        return 0;
    }
    char *want = NULL, *line = NULL;
    size_t cap = 0, want_len = 0;
    FILE *header = open_memstream(&want, &want_len);
    if (!header) {
        fclose(f);
        return pl_err_set(err, PL_ERR_NOMEM, "%s: no memory for its header", path);
    }
    pl_thermo_header(t, header);
    int rc = 0;
    if (fclose(header)) rc = pl_err_set(err, PL_ERR_NOMEM, "%s: no memory for its header", path);
    else if (getline(&line, &cap, f) < 0 || strcmp(line, want) != 0) {
        rc = pl_err_set(err, PL_ERR_INPUT, "%s: its columns are not this run's (another scene or other output "
                        "options); resume with another --out", path);
    } else { /* the whole rows of steps < keep stay (a row cut short by a crash has no newline) */
        long at = ftell(f);
        ssize_t len;
        while ((len = getline(&line, &cap, f)) > 0 && line[len - 1] == '\n' && strtoll(line, NULL, 10) < keep)
            at = ftell(f);
        errno = 0;
        if (at < 0 || fflush(f) || ftruncate(fileno(f), at) || fseek(f, 0, SEEK_END))
            rc = pl_err_set(err, PL_ERR_IO, "%s: cannot cut it at step %lld: %s", path, keep,
                            errno ? strerror(errno) : "stream error");
    }
    free(line);
    free(want);
    if (rc) fclose(f);
    else *out = f;
    return rc;
}
