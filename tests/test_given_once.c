/*
 * tests/test_given_once.c -- an option that takes one value is given once: a second one
 * is refused, not silently kept in place of the first, in the render command and in
 * every subcommand; a preset's words still give way to the user's.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/app/commands.h"
#include "../src/app/options.h"
#include "../src/base/error.h"
#include "files.h"
#include "tests.h"

#define OUT "build/test_given_once"
#define WORDS_MAX 32

/* parse_options() of "photon WORDS scenes/cornell.scene" (WORDS split at spaces); the
 * message in *err when it refuses them. */
static int parse_words(const char *words, struct options *o, struct error *err)
{
    char text[512], *argv[WORDS_MAX];
    int argc = 0;
    argv[argc++] = "photon";
    snprintf(text, sizeof text, "%s", words);
    for (char *w = strtok(text, " "); w != NULL && argc < WORDS_MAX - 1; w = strtok(NULL, " "))
        argv[argc++] = w;
    argv[argc++] = "scenes/cornell.scene";
    err->message[0] = '\0';
    return parse_options(argc, argv, o, err);
}

/* truth: the rule: an option with a value given twice by the user is refused,
 *   both words named as typed (--spp, -o, --mode, --quality, --crop). A switch is not
 *   refused: repeated it says one thing, and its --no- form undoes an earlier word (a
 *   script's), the last word stating the whole setting (--progress --no-progress: off;
 *   --precomputed-irradiance 16 --no-precomputed-irradiance: 0). A preset's (--quality)
 *   and --paper's words come before the user's, who still wins: --quality preview makes
 *   1996's --spp 8 (test_numbers.c), the user's --spp 3 stands.
 * catches: the last of two values kept silently; a preset's word counted as the user's
 *   first (which would refuse every --spp with --quality). */
static void test_render_command(struct check *t)
{
    static const char *const refused[][2] = {
        {"--spp 4 --spp 8", "--spp 8: given after --spp 4"},
        {"-o " OUT "_a.pfm -o " OUT "_b.pfm", "-o " OUT "_b.pfm: given after -o " OUT "_a.pfm"},
        {"--mode pt --mode 1996", "--mode 1996: given after --mode pt"},
        {"--quality preview --quality reference", "given after --quality preview"},
        {"--crop 0 0 4 4 --crop 4 0 8 4", "--crop 4 0 8 4: given after --crop 0 0 4 4"},
        {"--mode 1996 --precomputed-irradiance 16 --precomputed-irradiance 4",
         "--precomputed-irradiance 4: given after --precomputed-irradiance 16"},
        {"--mode 1996 --paper --paper --spp 2 --spp 2", "--spp 2: given after --spp 2"},
    };
    struct options o;
    struct error err;
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        int right = parse_words(refused[i][0], &o, &err) < 0 &&
                    strstr(err.message, refused[i][1]) != NULL &&
                    strstr(err.message, "give the option once") != NULL;
        CHECK(t, right);
        if (!right)
            fprintf(stderr, "test_given_once: '%s': %s\n", refused[i][0], err.message);
    }
    CHECK(t, parse_words("--stats --stats --no-progress --no-progress", &o, &err) == 0 &&
             o.stats && !o.progress);
    CHECK(t, parse_words("--progress --no-progress", &o, &err) == 0 && !o.progress);
    CHECK(t, parse_words("--mode 1996 --precomputed-irradiance 16 --no-precomputed-irradiance",
                         &o, &err) == 0 && o.precomputed_irradiance == 0);
    CHECK(t, parse_words("--mode 1996 --quality preview", &o, &err) == 0 && o.spp == 8);
    CHECK(t, parse_words("--mode 1996 --quality preview --spp 3", &o, &err) == 0 && o.spp == 3);
    CHECK(t, parse_words("--spp 3 --mode 1996 --paper --quality preview", &o, &err) == 0 &&
             o.spp == 3 && o.paper);
}

/* truth: the same rule in each subcommand, in the render command's words (one helper,
 *   base/option_once.h): compare's --diff (the case), merge's -o, export's --spp,
 *   plot's --x (single, though it has a default) and -o, probe's --samples and --line
 *   (its six values), convert's --min across its two spellings are refused the second
 *   time (status 2), "COMMAND: NOW: given after BEFORE; give the option once", both with
 *   their values (--NAME=VALUE as --NAME VALUE), before any file is read, so the
 *   missing inputs here are never reached; plot's --y may repeat (one line each).
 * catches: the second value silently replacing the first in any subcommand; a
 *   subcommand's own wording ("is given twice", "given twice", "needs one value, once"),
 *   which named neither value. */
static void test_subcommands(struct check *t)
{
    static const char *const refused[][3] = {
        {"compare", "a.pfm b.pfm --diff " OUT "_a.png --diff " OUT "_b.png",
         "--diff " OUT "_b.png: given after --diff " OUT "_a.png"},
        {"compare", "a.pfm b.pfm --ref-variance v.pfm --ref-variance w.pfm",
         "--ref-variance w.pfm: given after --ref-variance v.pfm"},
        {"merge", "-o " OUT "_a.pfm --exposure 1 --exposure 2 t.pfm",
         "--exposure 2: given after --exposure 1"},
        {"merge", "-o " OUT "_a.pfm -o " OUT "_b.pfm t.pfm",
         "-o " OUT "_b.pfm: given after -o " OUT "_a.pfm"},
        {"export", "--format pbrt --spp 4 --spp 8 s.scene -o " OUT ".pbrt",
         "--spp 8: given after --spp 4"},
        {"export", "--format pbrt --format mitsuba s.scene -o " OUT ".pbrt",
         "--format mitsuba: given after --format pbrt"},
        {"plot", "--linear --x a --x b a.csv -o " OUT ".svg", "--x b: given after --x a"},
        {"plot", "a.csv -o " OUT "_a.svg -o " OUT "_b.svg",
         "-o " OUT "_b.svg: given after -o " OUT "_a.svg"},
        {"probe", "s.scene --line 0 0 0 1 1 1 --samples 4 --samples 8 -o " OUT ".csv",
         "--samples 8: given after --samples 4"},
        {"probe", "s.scene --line 0 0 0 1 1 1 --line 0 0 0 1 1 2 --samples 4 -o " OUT ".csv",
         "--line 0 0 0 1 1 2: given after --line 0 0 0 1 1 1"},
        {"convert", "a.pfm --false-colour --min=1 --min 2 -o " OUT ".png",
         "--min 2: given after --min 1"},
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        char expected[256];
        snprintf(expected, sizeof expected, "photon: %s: %s; give the option once\n",
                 refused[i][0], refused[i][2]);
        int right = photon_logged(refused[i][0], refused[i][1], OUT ".log") == 2 &&
                    file_contains(OUT ".log", expected);
        CHECK(t, right);
        if (!right)
            fprintf(stderr, "test_given_once: no '%s'\n", expected);
    }
    CHECK(t, photon_logged("plot", "--linear --x a --y b --y c no_such.csv -o " OUT ".svg",
                           OUT ".log") == 2 && !file_contains(OUT ".log", "given after") &&
             file_contains(OUT ".log", "no_such.csv"));
    run_command("rm -f " OUT "*");
}

/* truth: getopt_long()'s spelling: --NAME=VALUE is --NAME VALUE for an option of one
 *   value, so the two spellings parse to the same options (the same options_hash(), the
 *   same scene, output and mode), the text after the first '=' the value (a file name
 *   may hold '='); a switch or --crop with '=' is refused, naming the option; a repeat
 *   across the spellings is refused as a repeat.
 * catches: '=' taken into the option's name (unknown option), the value cut at a second
 *   '=', --stats=0 read as --stats. */
static void test_equals_spelling(struct check *t)
{
    struct options a, b;
    struct error err;
    CHECK(t, parse_words("--mode=2009 --passes=16 --seed=7 -o " OUT "_a=b.pfm", &a, &err) == 0);
    CHECK(t, parse_words("--mode 2009 --passes 16 --seed 7 -o " OUT "_a=b.pfm", &b, &err) == 0);
    CHECK(t, a.mode == MODE_SPPM2009 && options_hash(&a, 0) == options_hash(&b, 0) &&
             strcmp(a.output, b.output) == 0);
    CHECK(t, parse_words("--error=" OUT "_e=1.pfm --mode pt", &a, &err) == 0 &&
             strcmp(a.error, OUT "_e=1.pfm") == 0);
    CHECK(t, parse_words("--stats=0", &a, &err) < 0 &&
             strstr(err.message, "--stats takes no value") != NULL);
    CHECK(t, parse_words("--crop=0", &a, &err) < 0 &&
             strstr(err.message, "--crop takes four values") != NULL);
    CHECK(t, parse_words("--spp=4 --spp 8", &a, &err) < 0 &&
             strstr(err.message, "given after --spp 4") != NULL);
}

/* The usage of `photon COMMAND --help`: its first line and the indented lines after it
 * (export's usage takes two), in text[size]; "" when there is none. */
static void usage_of(const char *command, char *text, size_t size)
{
    text[0] = '\0';
    char *help = photon_logged(command, "--help", OUT "_help.log") == 0
                     ? read_text_file(OUT "_help.log")
                     : NULL;
    size_t n = 0;
    for (const char *line = help; line != NULL && (line == help || *line == ' ');) {
        const char *end = strchr(line, '\n');
        size_t length = end != NULL ? (size_t)(end - line) : strlen(line);
        n += (size_t)snprintf(text + n, size - n, "%.*s ", (int)length, line);
        line = end != NULL && n < size ? end + 1 : NULL;
    }
    free(help);
}

/* Whether an option that `photon COMMAND --help`'s usage names is called unknown by
 * `photon COMMAND --NAME=1`; the first such is said on stderr. */
static int usage_option_unknown(const char *command)
{
    char usage[1024], args[96];
    usage_of(command, usage, sizeof usage);
    int unknown = strstr(usage, "usage: photon ") == NULL;
    for (char *w = strtok(usage, " []"); w != NULL && !unknown; w = strtok(NULL, " []")) {
        if (strncmp(w, "--", 2) != 0)
            continue; /* a value or a file */
        snprintf(args, sizeof args, "%s=1", w);
        photon_logged(command, args, OUT ".log");
        unknown = file_contains(OUT ".log", "unknown option");
        if (unknown)
            fprintf(stderr, "test_given_once: photon %s %s: unknown option\n", command, args);
    }
    return unknown;
}

/* truth: getopt_long()'s spelling, which the render command takes (above), in every
 *   subcommand of main.c's table (commands.h) too: no option its --help's usage line
 *   names is called unknown when written --NAME=VALUE (a switch's is refused as one that
 *   takes no value); export's (the case) and compare's options so spelt give the
 *   same file and the same line as --NAME VALUE.
 * catches: a subcommand that reads "--spp=4" as an unknown option (export, compare,
 *   merge, plot and probe did: only convert split it), one left out of the table of
 *   options main.c splits by. */
static void test_subcommand_equals(struct check *t)
{
    for (size_t i = 0; i < N_COMMANDS; i++)
        CHECK(t, !usage_option_unknown(commands[i].name));
    CHECK(t, photon_logged("export", "--format=pbrt --spp=4 --width=8 --height=6 --channel=G "
                           "scenes/cornell.scene -o " OUT ".pbrt", OUT ".log") == 0);
    char *split = read_text_file(OUT ".pbrt");
    CHECK(t, photon_logged("export", "--format pbrt --spp 4 --width 8 --height 6 --channel G "
                           "scenes/cornell.scene -o " OUT ".pbrt", OUT ".log") == 0);
    CHECK(t, split != NULL && file_equals_text(OUT ".pbrt", split) &&
             strstr(split, "\"integer xresolution\" [8]") != NULL);
    free(split);
    CHECK(t, photon_logged("", "--mode pt --spp 1 --width 8 --height 8 --no-progress -o " OUT
                           ".pfm scenes/cornell.scene", OUT ".log") == 0);
    CHECK(t, photon_logged("compare", OUT ".pfm " OUT ".pfm --block=4", OUT "_a.log") == 0 &&
             photon_logged("compare", OUT ".pfm " OUT ".pfm --block 4", OUT ".log") == 0 &&
             files_equal(OUT "_a.log", OUT ".log") && file_contains(OUT ".log", "blocks=4 "));
    CHECK(t, photon_logged("compare", OUT ".pfm " OUT ".pfm --exit-status=1", OUT ".log") ==
                 2 &&
             file_contains(OUT ".log", "--exit-status takes no value"));
    run_command("rm -f " OUT "*");
}

void test_given_once(struct check *t)
{
    RUN_TEST(t, test_render_command);
    RUN_TEST(t, test_subcommands);
    RUN_TEST(t, test_equals_spelling);
    RUN_TEST(t, test_subcommand_equals);
}
