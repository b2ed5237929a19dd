/*
 * tests/test_progress.c -- the progress line (base/progress.h): its forecast, its two
 * forms and when each shows a line, what the photon/ code that keeps no clock tells its
 * watch (base/watch.h), and what photon writes with --progress to a log file and to a
 * pipe.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../src/base/alloc.h"
#include "../src/base/progress.h"
#include "../src/base/rng.h"
#include "../src/photon/precomputed_irradiance.h"
#include "files.h"
#include "tests.h"

#define OUT "build/test_progress"

/* The text written to f since it was opened (a tmpfile()), at most size - 1 bytes. */
static void written(FILE *f, char *text, size_t size)
{
    rewind(f);
    size_t n = fread(text, 1, size - 1, f);
    text[n] = '\0';
}

/* truth: arithmetic: a phase of 100 units begun at t0, 25 done at t0 + 10 s, has
 *   10 x (100 - 25) / 25 = 30 s left; nothing done yet or no total: no forecast (-1); at
 *   the end, 0. On a file (ftell works) a line is due after PROGRESS_FILE_EVERY = 10 s and
 *   not before, and each is a whole line; in place (a terminal or a pipe) one is due after
 *   1 s, starts with a carriage return, and the last ends with a newline. A last update
 *   that says what the last line shown said prints nothing more. The clock is the test's
 *   own (POSIX time_t counts seconds).
 * tolerance: none (whole seconds, exact quotients).
 * catches: a forecast from the whole run's rate or from CPU seconds, the forecast's
 *   fraction upside down, a log filled with carriage returns or a line a second, the line
 *   in place never ended, the same last line printed twice. */
static void test_forecast_and_forms(struct check *t)
{
    FILE *f = tmpfile();
    REQUIRE(t, f != NULL);
    CHECK(t, progress_lines_to(f));
    time_t t0 = (time_t)1000000;
    struct progress p;
    progress_begin(&p, f, "test", 100.0, t0);
    CHECK(t, p.lines && progress_seconds_left(&p) == -1.0);
    CHECK(t, !progress_update(&p, 20.0, t0 + 9));
    CHECK(t, progress_update(&p, 25.0, t0 + 10) && progress_seconds_left(&p) == 30.0);
    progress_print(&p, "%d of %d widgets", 25, 100);
    CHECK(t, !progress_update(&p, 50.0, t0 + 19) && progress_update(&p, 50.0, t0 + 20));
    CHECK(t, progress_seconds_left(&p) == 20.0);
    CHECK(t, progress_end(&p, 100.0, t0 + 40) && progress_seconds_left(&p) == 0.0);
    progress_print(&p, "%d of %d widgets", 100, 100);
    char text[512];
    written(f, text, sizeof text);
    CHECK(t, strcmp(text, "photon: test: 25 of 100 widgets, 10 s, about 30 s left\n"
                          "photon: test: 100 of 100 widgets, 40 s, about 0 s left\n") == 0);
    fclose(f);

    f = tmpfile();
    REQUIRE(t, f != NULL);
    progress_begin(&p, f, "test", 0.0, t0);
    p.lines = 0; /* the form of a terminal or a pipe, written where the test can read it */
    CHECK(t, !progress_update(&p, 3.0, t0) && progress_update(&p, 3.0, t0 + 1));
    CHECK(t, progress_seconds_left(&p) == -1.0);
    progress_print(&p, "pass %d", 3);
    CHECK(t, progress_end(&p, 4.0, t0 + 2));
    progress_print(&p, "pass %d", 4);
    CHECK(t, !progress_end(&p, 4.0, t0 + 2)); /* said already */
    written(f, text, sizeof text);
    CHECK(t, strcmp(text, "\rphoton: test: pass 3, 1 s\rphoton: test: pass 4, 2 s\n") == 0);
    fclose(f);

    progress_begin(&p, NULL, "off", 10.0, t0);
    CHECK(t, !progress_update(&p, 5.0, t0 + 100) && !progress_end(&p, 10.0, t0 + 100));
}

/* What a watch was told: how often, the last count, and whether each count was the next
 * multiple of every. */
struct told {
    size_t every, calls, last;
    int in_steps;
};

static void tell(void *context, size_t done)
{
    struct told *w = context;
    w->calls++;
    w->in_steps = w->in_steps && done == w->calls * w->every;
    w->last = done;
}

/* n photons spread over the unit square of the floor y = 0, facing up (their direction
 * bytes hold the normal, as a record's do), from the test stream seed. */
static struct photon *floor_photons(size_t n, uint64_t seed)
{
    struct photon *photons = xmalloc(n, sizeof *photons, "test photons");
    struct rng rng = rng_stream(seed, STREAM_TEST, 0, 0);
    for (size_t i = 0; i < n; i++) {
        double u[2];
        rng_uniforms(&rng, u, 2);
        photons[i] = photon_pack(vec3(u[0], 0, u[1]), vec3(1, 1, 1), vec3(0, 1, 0),
                                 PHOTON_DIRECT);
    }
    return photons;
}

/* truth: kdtree.h and precomputed_irradiance.h: balancing n photons takes 2n steps, and
 *   the watch is told each positive multiple of KDTREE_WATCH_EVERY up to 2n, in order
 *   (2047 photons: none; 2048: once, at the last step; 10000: 4096 to 16384); the
 *   precomputed irradiance tells the records estimated at each multiple of
 *   PRECOMPUTED_WATCH_EVERY (1000 records: 256, 512, 768). Watched or not, the map and
 *   the values are the same, byte for byte.
 * tolerance: none.
 * catches: a phase that tells its watch nothing (no progress line before its end), or
 *   counts past its total (a forecast beyond the end), or out of order; a watch that
 *   changes the map or the values. */
static void test_watched_work(struct check *t)
{
    static const size_t sizes[] = {1, 2047, 2048, 10000};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        size_t n = sizes[s];
        struct told w = {KDTREE_WATCH_EVERY, 0, 0, 1};
        struct work_watch watch = {tell, &w};
        struct kdtree *plain = balance_kdtree(floor_photons(n, 1), n);
        struct kdtree *watched = balance_kdtree_watched(floor_photons(n, 1), n, &watch);
        CHECK(t, w.in_steps && w.calls == 2 * n / KDTREE_WATCH_EVERY && w.last <= 2 * n);
        CHECK(t, memcmp(plain->photons, watched->photons, (n + 1) * sizeof *plain->photons)
                     == 0);
        kdtree_free(watched);
        kdtree_free(plain);
    }
    struct kdtree *map = balance_kdtree(floor_photons(4000, 2), 4000);
    struct kdtree *records = balance_kdtree(floor_photons(1000, 3), 1000);
    struct irradiance_settings is = {30, 0.01, 0, 0, 1};
    struct told w = {PRECOMPUTED_WATCH_EVERY, 0, 0, 1};
    struct work_watch watch = {tell, &w};
    struct precomputed_irradiance *plain = precompute_irradiance(map, records, &is, NULL, NULL);
    struct precomputed_irradiance *watched =
        precompute_irradiance(map, records, &is, NULL, &watch);
    CHECK(t, w.in_steps && w.calls == 3 && w.last == 768);
    CHECK(t, memcmp(plain->value, watched->value, 1001 * sizeof *plain->value) == 0);
    precomputed_irradiance_free(watched);
    precomputed_irradiance_free(plain);
    kdtree_free(records);
    kdtree_free(map);
}

/* Whether every line of text is a progress line ("photon: "), ends with a newline, holds
 * no carriage return, and says "left" unless it names the target error (whose passes
 * are not known beforehand); *n: the lines. */
static int whole_lines(const char *text, int *n)
{
    *n = 0;
    if (strchr(text, '\r') != NULL || (*text != '\0' && text[strlen(text) - 1] != '\n'))
        return 0;
    for (const char *line = text; *line != '\0'; line = strchr(line, '\n') + 1) {
        const char *end = strchr(line, '\n');
        size_t len = (size_t)(end - line);
        char copy[512];
        if (len >= sizeof copy || strncmp(line, "photon: ", 8) != 0)
            return 0;
        memcpy(copy, line, len);
        copy[len] = '\0';
        if (strstr(copy, "blocks within") == NULL && strstr(copy, " s left") == NULL)
            return 0;
        (*n)++;
    }
    return 1;
}

/* The total of the line "photon: PHASE: DONE of TOTAL UNITS, ..." in text when DONE is
 * TOTAL (the phase's work all done); 0 when it is not, or there is no such line. */
static unsigned long all_done(const char *text, const char *phase, const char *units)
{
    char start[96], format[160];
    snprintf(start, sizeof start, "photon: %s: ", phase);
    snprintf(format, sizeof format, "%%lu of %%lu %s,", units);
    const char *line = text != NULL ? strstr(text, start) : NULL;
    unsigned long done = 0, total = 0;
    if (line == NULL || sscanf(line + strlen(start), format, &done, &total) != 2)
        return 0;
    return done == total ? total : 0;
}

/* Runs photon with args and --progress, stderr to log (a file) or through a pipe (cat)
 * into it; its exit status (the pipe's: cat's). */
static int photon_progress(const char *args, const char *log, int pipe)
{
    char command[1024];
    snprintf(command, sizeof command, "%s --progress %s 2>%s", photon_binary(), args,
             pipe ? "&1 | cat > " OUT "_pipe.log" : log);
    return run_command(command);
}

#define TINY_1996 "--mode 1996 --width 16 --height 16 --spp 2 --specular-spp 2 --photons " \
                  "20000 --caustic-photons 20000 --gather-rays 16 -o " OUT ".pfm " \
                  "scenes/cornell-specular.scene"

/* truth: README, "Options": with stderr a file, --progress writes whole lines, each a
 *   phase's ("photon: PHASE: ...") with the time left where its work is known: 1996's
 *   two photon maps' traces and balancing, its precomputed irradiance, its irradiance
 *   cache and its sample passes, seven phases; 2009's passes; with --target-error the
 *   passes' line names the blocks instead. A phase's last line says all its work is done
 *   (a balancing's steps, 2 a photon, an even number). Through a pipe, the line is
 *   rewritten in place: carriage returns, each phase ended by a newline.
 * tolerance: none.
 * catches: carriage returns in a log, a phase with no line (the photon maps once had
 *   none, and their balancing and the precomputed irradiance), a forecast missing, the
 *   form chosen by TERM rather than by where stderr goes. */
static void test_render_progress(struct check *t)
{
    const char *file_log = OUT "_file.log";
    CHECK(t, photon_progress(TINY_1996, file_log, 0) == 0);
    char *text = read_text_file(file_log);
    int n = 0;
    CHECK(t, text != NULL && whole_lines(text, &n) && n == 7);
    CHECK(t, text != NULL && strstr(text, "photon: global photon map: 20000 of 20000 photons "
                                          "emitted, ") != NULL &&
             strstr(text, "photon: caustic photon map: ") != NULL &&
             strstr(text, "photon: irradiance cache: row 16 of 16, ") != NULL &&
             strstr(text, "photon: sample passes: ") != NULL);
    unsigned long global = all_done(text, "global photon map balancing", "steps"),
                  caustic = all_done(text, "caustic photon map balancing", "steps");
    CHECK(t, global > 0 && global % 2 == 0 && caustic > 0 && caustic % 2 == 0 &&
             all_done(text, "precomputed irradiance", "records estimated") > 0);
    free(text);
    CHECK(t, photon_progress("--mode 2009 --passes 4 --width 16 --height 16 -o " OUT ".pfm "
                             "scenes/cornell.scene", file_log, 0) == 0);
    text = read_text_file(file_log);
    CHECK(t, text != NULL && whole_lines(text, &n) && n == 1 &&
             strstr(text, "photon: passes: pass 4/4, ") != NULL);
    free(text);
    CHECK(t, photon_progress("--mode pt --spp 64 --target-error 0.5 --width 16 --height 16 "
                             "-o " OUT ".pfm scenes/cornell.scene", file_log, 0) == 0);
    text = read_text_file(file_log);
    CHECK(t, text != NULL && whole_lines(text, &n) && n == 1 &&
             strstr(text, "blocks within 0.5, ") != NULL && strstr(text, "left") == NULL);
    free(text);

    CHECK(t, photon_progress(TINY_1996, NULL, 1) == 0);
    text = read_text_file(OUT "_pipe.log");
    int returns = 0, newlines = 0;
    for (const char *c = text != NULL ? text : ""; *c != '\0'; c++) {
        returns += *c == '\r';
        newlines += *c == '\n';
    }
    CHECK(t, text != NULL && returns >= 7 && newlines == 7 &&
             strncmp(text, "\rphoton: global photon map: ", 28) == 0 &&
             text[strlen(text) - 1] == '\n');
    free(text);
    remove(file_log);
    remove(OUT "_pipe.log");
    remove(OUT ".pfm");
    remove(OUT ".png");
}

void test_progress(struct check *t)
{
    run_test(t, test_forecast_and_forms, "progress: forecast and forms");
    run_test(t, test_watched_work, "progress: what balancing and precomputing tell a watch");
    run_test(t, test_render_progress, "progress: photon --progress to a file and a pipe");
}
