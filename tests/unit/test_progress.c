/* Progress reporting (src/app/progress.c): the library prints only to the stream
 * it is given; a log (non-terminal) gets plain lines at the interval and no
 * carriage return; the end names the files with their sizes; notes close the
 * terminal line first. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "peloid/progress.h"

static char *slurp(FILE *f)
{
    static char buf[1 << 16];
    fflush(f);
    rewind(f);
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    return buf;
}

Test(progress, silent_without_stream)
{
    pl_progress_params_t p = {.out = NULL, .terminal = 0, .interval_s = 1e-9, .first = 0, .last = 10, .dt = 0.1};
    pl_progress_t *g = pl_progress_create(&p);
    cr_assert_not_null(g);
    for (long long s = 1; s <= 10; ++s) pl_progress_update(g, s);
    pl_progress_note(g, "nothing %d", 1);
    pl_progress_finish(g, 10);
    pl_progress_free(g);
}

Test(progress, log_lines_and_end)
{
    FILE *f = tmpfile();
    cr_assert_not_null(f);
    FILE *data = fopen("test_progress.dat", "w");
    cr_assert_not_null(data);
    fputs("0123456789", data);
    fclose(data);
    pl_progress_params_t p = {.out = f, .terminal = 0, .interval_s = 1e-9, .first = 0, .last = 4, .dt = 0.5,
                              .t0_s = 2.0, .fluid_n = 1e6, .md_per_step = 10};
    pl_progress_t *g = pl_progress_create(&p);
    for (long long s = 1; s <= 4; ++s) {
        usleep(2000);
        pl_progress_update(g, s);
    }
    pl_progress_note(g, "a note %s", "here");
    pl_progress_file(g, ".", "test_progress.dat");
    pl_progress_finish(g, 4);
    pl_progress_free(g);
    char *out = slurp(f);
    cr_assert(strstr(out, "peloid: step 4/4 100.0%  t = 2 t0 (4 s)  ETA") != NULL, "%s", out);
    cr_assert(strstr(out, "Mupdates/s") && strstr(out, "MD steps/s"), "%s", out);
    cr_assert(strstr(out, "peloid: a note here\n") != NULL, "%s", out);
    cr_assert(strstr(out, "peloid: done: steps 0..4 in ") != NULL, "%s", out);
    cr_assert(strstr(out, "simulated time 2 t0 = 4 s\n") != NULL, "%s", out);
    cr_assert(strstr(out, "./test_progress.dat  10 B\n") != NULL, "%s", out);
    cr_assert(strchr(out, '\r') == NULL, "carriage return in a log: %s", out);
    fclose(f);
    unlink("test_progress.dat");
}

/* No fluid: no Mupdates/s; no physical time: no seconds. */
Test(progress, colloid_only_model_units)
{
    FILE *f = tmpfile();
    pl_progress_params_t p = {.out = f, .terminal = 0, .interval_s = 1e-9, .first = 0, .last = 2, .dt = 1.0,
                              .md_per_step = 5};
    pl_progress_t *g = pl_progress_create(&p);
    usleep(2000);
    pl_progress_update(g, 1);
    pl_progress_finish(g, 2);
    pl_progress_free(g);
    char *out = slurp(f);
    cr_assert(strstr(out, "MD steps/s") != NULL && strstr(out, "Mupdates") == NULL, "%s", out);
    cr_assert(strstr(out, " s)") == NULL && strstr(out, "t0 =") == NULL, "%s", out);
    fclose(f);
}

/* A terminal: the line is rewritten in place (\r ... erase to end of line),
 * and a note or the end starts on a fresh line. */
Test(progress, terminal_line)
{
    FILE *f = tmpfile();
    pl_progress_params_t p = {.out = f, .terminal = 1, .interval_s = 30, .first = 0, .last = 100, .dt = 1.0,
                              .fluid_n = 10};
    pl_progress_t *g = pl_progress_create(&p);
    usleep(300000); /* past the 0.25 s refresh */
    pl_progress_update(g, 50);
    pl_progress_note(g, "half");
    pl_progress_finish(g, 100);
    pl_progress_free(g);
    char *out = slurp(f);
    cr_assert(strstr(out, "\r  step 50/100  50.0%") != NULL, "%s", out);
    cr_assert(strstr(out, "\033[K\npeloid: half\n") != NULL, "%s", out);
    cr_assert(strstr(out, "\033[K\npeloid: done: steps 0..100") != NULL, "%s", out);
    fclose(f);
}
