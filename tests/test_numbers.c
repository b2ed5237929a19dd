/*
 * tests/test_numbers.c -- every number on the command line has one syntax and a stated
 * range, values outside it are refused with that range, and the messages say where a
 * value came from and what to do.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "files.h"
#include "option_words.h"
#include "tests.h"

#define COMMAND_MAX 1024
#define OUT "build/test_numbers"

static int photon(const char *args)
{
    return photon_logged("", args, OUT ".log");
}

static int log_contains(const char *text)
{
    return file_contains(OUT ".log", text);
}

/* truth: base/number.h's syntax and options.c's ranges: a value outside its range is
 *   refused (status 2) with the range in words, integers printed as integers; 0 is no
 *   longer a silent default where it means nothing (--time-limit 0 was no limit, --radius
 *   0 and --max-radius 0 the default, --footprints 0 a radius of 0 that drops every
 *   photon, or 0.25 footprints when fitted); --alpha says the same of nan and of 0.
 * catches: "from 1 to 1.04858e+06", a 0 taken as "the default", nan read as a number. */
static void test_ranges_refused(struct check *t)
{
    static const char *const cases[][2] = {
        {"--spp 0", "--spp: expected a whole number from 1 to 1048576, got '0'"},
        {"--time-limit 0", "--time-limit: expected a number above 0, at most 1e+09, got '0'"},
        {"--mode 2008 --radius 0", "--radius: expected a number above 0"},
        {"--mode photons --max-radius 0", "--max-radius: expected a number above 0"},
        {"--mode 2009 --paper --footprints 0", "--footprints: expected a number above 0"},
        {"--mode 2009 --footprints 0", "--footprints: expected a number above 0"},
        {"--mode 2008 --alpha nan", "--alpha: expected a number strictly between 0 and 1, "
                                    "got 'nan'"},
        {"--mode 2008 --alpha 0", "--alpha: expected a number strictly between 0 and 1, "
                                  "got '0'"},
        {"--mode 2008 --alpha 1", "--alpha: expected a number strictly between 0 and 1"},
        {"--exposure -1", "--exposure: expected a number from 0 to 1e+30"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char command[COMMAND_MAX];
        snprintf(command, sizeof command, "%s build/no_such.scene", cases[i][0]);
        CHECK(t, photon(command) == 2 && log_contains(cases[i][1]));
    }
    struct options o;
    CHECK(t, options_of("--time-limit 0.5 --exposure 1e3", &o) == 0 && o.time_limit == 0.5 &&
             o.exposure == 1000);
}

/* truth: base/number.h: one syntax for every number of every command: a whole number is
 *   digits ("1e3" is refused as a count everywhere: --spp, --crop, --photons-per-pass,
 *   export --spp, compare --block, probe --samples), no white space on either side, no
 *   hexadecimal, no inf or nan; a real may have an exponent.
 * catches: " 5" taken and "5 " refused, 1e3 refused by one option and taken by another. */
static void test_one_number_syntax(struct check *t)
{
    static const char *const refused[] = {
        "--spp 1e3", "--spp ' 5'", "--spp '5 '", "--spp 0x10", "--spp +5", "--spp 5.0",
        "--crop 1e1 0 20 20", "--mode 2008 --photons-per-pass 1e3", "--exposure inf",
        "--exposure ' 1'", "--exposure 0x1p3", "--exposure 1e", "--exposure .",
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        char command[COMMAND_MAX];
        snprintf(command, sizeof command, "%s build/no_such.scene", refused[i]);
        CHECK(t, photon(command) == 2 && log_contains(": expected a"));
    }
    CHECK(t, photon("export --format pbrt --spp 1e3 scenes/cornell.scene -o " OUT ".pbrt") == 2
             && log_contains("export: --spp: expected a whole number from 1 to 16777216"));
    CHECK(t, photon("compare scenes/cornell.scene scenes/cornell.scene --block 1e1") == 2 &&
             log_contains("--block"));
    CHECK(t, photon("probe scenes/cornell.scene --line 0 0 0 1 1 1 --samples 1e1 -o "
                    OUT ".csv") == 2 && log_contains("--samples: expected a whole number"));
    struct options o;
    CHECK(t, options_of("--mode 2008 --alpha .5e0 --exposure +2.5E-1", &o) == 0 &&
             o.alpha == 0.5 && o.exposure == 0.25);
}

/* Whether the log holds text once every run of white space in it (a line wrapped onto
 * the next, its indent) is read as one space. */
static int log_contains_words(const char *text)
{
    char *log = read_text_file(OUT ".log");
    if (log == NULL)
        return 0;
    char *out = log;
    for (const char *c = log; *c != '\0'; c++)
        if (!(*c == ' ' || *c == '\n') || !(out > log && out[-1] == ' '))
            *out++ = *c == '\n' ? ' ' : *c;
    *out = '\0';
    int found = strstr(log, text) != NULL;
    free(log);
    return found;
}

/* truth: options.c's table: --help all prints the range of every option that takes a number,
 *   from the same limits the parser checks, and the --time-limit's clock (CPU seconds)
 *   and when it stops (the text layout may wrap a phrase onto the next line).
 * catches: a limit documented nowhere, a help text that disagrees with the parser. */
static void test_help_states_ranges(struct check *t)
{
    static const char *const lines[] = {
        "(N: a whole number from 1 to 1048576)", "(SECONDS: a number above 0, at most 1e+09)",
        "(A: a number strictly between 0 and 1)", "(each: a whole number from 0 to 32768)",
        "CPU seconds", "(R: a number above 0, at most 1e+30)",
    };
    CHECK(t, photon("--help all") == 0);
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++)
        CHECK(t, log_contains_words(lines[i]));
}

/* truth: the messages name where a value came from and advice that works: a preset's
 *   --spp is named as the preset's; merge's advice for a timed tile names --passes for
 *   2009 (which refuses --spp); compare names which image is not finite; a PSNR
 *   against a black reference is none (no peak), not -594 dB; after a --time-limit stop
 *   --stats' specular_spp is what was taken (at most the passes run), not the plan.
 * catches: "at least --spp (8)" for an 8 the user never gave, advice to use --spp with
 *   --mode 2009, "a reference must be finite" for the image tested. */
static void test_messages_say_the_truth(struct check *t)
{
    CHECK(t, photon("--quality preview --mode 1996 --specular-spp 4 build/no_such.scene") == 2
             && log_contains("--specular-spp 4: expected at least --spp (8, from --quality "
                             "preview)"));
    CHECK(t, photon("--no-progress --width 4 --height 4 --mode 2009 --passes 2 "
                    "--photons-per-pass 100 --time-limit 100 --crop 0 0 4 4 -o " OUT
                    "_t.pfm scenes/cornell.scene") == 0);
    CHECK(t, photon("merge -o " OUT "_m.pfm " OUT "_t.pfm") == 2 &&
             log_contains("--passes in 2008 and 2009"));
    static const unsigned char nan_pfm[] = "PF\n1 1\n-1.0\n\0\0\xc0\x7f\0\0\0\0\0\0\0\0";
    write_bytes_file(OUT "_nan.pfm", nan_pfm, sizeof nan_pfm - 1);
    static const unsigned char black_pfm[] = "PF\n1 1\n-1.0\n\0\0\0\0\0\0\0\0\0\0\0\0";
    write_bytes_file(OUT "_black.pfm", black_pfm, sizeof black_pfm - 1);
    CHECK(t, photon("compare " OUT "_nan.pfm " OUT "_black.pfm") == 2 &&
             log_contains("NaN or infinite") && log_contains("(A, the image tested)") &&
             !log_contains("a reference"));
    CHECK(t, photon("compare " OUT "_t.pfm " OUT "_t.pfm") == 0);
    CHECK(t, photon("--no-progress --width 1 --height 1 --mode pt --spp 1 -o " OUT "_one.pfm "
                    "scenes/cornell.scene") == 0);
    CHECK(t, photon("compare " OUT "_one.pfm " OUT "_black.pfm") == 0 &&
             log_contains("psnr=none"));
    CHECK(t, photon("--no-progress --stats --mode 1996 --spp 64 --width 8 --height 8 "
                    "--photons 2000 --caustic-photons 2000 --gather-rays 16 --time-limit "
                    "0.0001 -o " OUT "_s.pfm scenes/cornell-specular.scene") == 0);
    double spp = file_stat(OUT ".log", "spp"), specular = file_stat(OUT ".log", "specular_spp");
    CHECK(t, spp >= 1 && spp < 64 && specular == spp);
    run_command("rm -f " OUT "_*");
}

void test_numbers(struct check *t)
{
    RUN_TEST(t, test_ranges_refused);
    RUN_TEST(t, test_one_number_syntax);
    RUN_TEST(t, test_help_states_ranges);
    RUN_TEST(t, test_messages_say_the_truth);
}
