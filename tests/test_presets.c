/*
 * tests/test_presets.c -- `--quality preview|default|reference` (app/presets.h): each mode's
 * presets parse, set what the table says, give way to the user's own options wherever they
 * stand, and `default` is the render without --quality; checked on parse_options() and on
 * the built binary as a user runs it.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/app/options.h"
#include "../src/app/presets.h"
#include "files.h"
#include "option_words.h"
#include "tests.h"

#define OUT "build/test_presets"

static const char *const modes[] = {"direct", "pt", "photons", "1994", "1996", "2008",
                                    "2009"};
static const char *const qualities[] = {"preview", "default", "reference"};

#define N_MODES (sizeof modes / sizeof modes[0])
#define N_QUALITIES (sizeof qualities / sizeof qualities[0])

/* Runs "PHOTON args" with its output in OUT.log; the exit status. */
static int photon(const char *args)
{
    return photon_logged("", args, OUT ".log");
}

static int log_contains(const char *text)
{
    return file_contains(OUT ".log", text);
}

/* truth: the table's contract (presets.h): every mode has the three presets, each is
 *   accepted by the option parser for its mode, preview and reference change the
 *   settings and default does not, a preset renders as its words spelled out on the
 *   command line do (the same options_hash, so the same tiles), and --help all lists each
 *   preset's words.
 * tolerance: none (hashes of the parsed values).
 * catches: a preset word the mode refuses or a value out of its limits, a mode without a
 *   row, words applied by another path than the parser, a preset missing from --help all. */
static void test_every_preset_parses_as_its_words(struct check *t)
{
    char *help = photon("--help all") == 0 ? read_text_file(OUT ".log") : NULL;
    CHECK(t, help != NULL);
    if (help != NULL)
        join_option_rows(help);
    for (size_t m = 0; m < N_MODES; m++) {
        char words[512];
        snprintf(words, sizeof words, "--mode %s", modes[m]);
        uint64_t plain = hash_of(words);
        CHECK(t, plain != 0);
        for (size_t q = 0; q < N_QUALITIES; q++) {
            struct options o;
            snprintf(words, sizeof words, "--mode %s --quality %s", modes[m], qualities[q]);
            CHECK(t, options_of(words, &o) == 0);
            uint64_t h = hash_of(words);
            CHECK(t, h != 0 && (h == plain) == (strcmp(qualities[q], "default") == 0));
            struct preset_words p;
            preset_words(o.mode, o.quality, &p);
            char spelled[512];
            int n = snprintf(spelled, sizeof spelled, "--mode %s", modes[m]);
            for (int i = 0; i < p.n_words; i++)
                n += snprintf(spelled + n, sizeof spelled - (size_t)n, " %s", p.word[i]);
            CHECK(t, hash_of(spelled) == h);
            snprintf(words, sizeof words, "%s", spelled + strlen("--mode ") + strlen(modes[m]));
            CHECK(t, help != NULL && (words[0] == '\0' || strstr(help, words + 1) != NULL));
        }
    }
    free(help);
}

/* truth: the preview rows of the table (presets.c), written out here.
 * catches: a preset that sets nothing, or another mode's preset. */
static void test_preview_sets_the_table_options(struct check *t)
{
    struct options o;
    CHECK(t, options_of("--mode 1996 --quality preview", &o) == 0);
    CHECK(t, o.photons == 200000 && o.caustic_photons == 50000 && o.gather_rays == 32 &&
             o.cache_accuracy == 0.3 && o.spp == 8 && o.specular_spp == 8);
    CHECK(t, options_of("--mode 2008 --quality preview", &o) == 0);
    CHECK(t, o.passes == 8 && o.spp == 4 && o.photons_per_pass == 100000);
    CHECK(t, options_of("--quality preview --mode pt", &o) == 0 && o.spp == 4);
    /* The same seen by a user, on a 16 x 16 render, in --stats. */
    CHECK(t, photon("--mode 1996 --quality preview --width 16 --height 16 --stats -o "
                    OUT ".pfm scenes/cornell-specular.scene") == 0);
    CHECK(t, log_contains("\nphotons_emitted=250000\n") && log_contains("\nspp=8\n"));
    CHECK(t, photon("--mode 2008 --quality preview --width 16 --height 16 --stats -o "
                    OUT ".pfm scenes/cornell.scene") == 0);
    CHECK(t, log_contains("\npasses=8\n") && log_contains("\nspp=4\n") &&
             log_contains("\nphotons_emitted=800000\n"));
    remove(OUT ".pfm");
    remove(OUT ".ppm");
}

/* truth: the contract of parse_options(): the preset stands before the command line, so
 *   an option given there wins before or after --quality; a preset's --specular-spp gives
 *   way to a larger --spp given by the user, but not to the user's own --specular-spp.
 * catches: the preset applied after the user's words, applied only when --quality comes
 *   first, a preview that refuses --spp 16 in modes 1994 and 1996. */
static void test_explicit_option_beats_preset(struct check *t)
{
    struct options o;
    CHECK(t, options_of("--passes 3 --spp 2 --quality preview --mode 2008", &o) == 0);
    CHECK(t, o.passes == 3 && o.spp == 2);
    CHECK(t, options_of("--mode 2008 --quality preview --passes 3 --spp 2", &o) == 0);
    CHECK(t, o.passes == 3 && o.spp == 2);
    CHECK(t, options_of("--photons 1000 --mode 1996 --quality preview", &o) == 0);
    CHECK(t, o.photons == 1000 && o.caustic_photons == 50000);
    CHECK(t, options_of("--mode 1994 --quality preview --spp 16", &o) == 0);
    CHECK(t, o.spp == 16 && o.specular_spp == 16);
    CHECK(t, options_of("--mode 1994 --quality preview --spp 2", &o) == 0);
    CHECK(t, o.spp == 2 && o.specular_spp == 8);
    CHECK(t, options_of("--mode 1994 --quality preview --spp 16 --specular-spp 9", &o) == -1);
    CHECK(t, photon("--spp 2 --passes 3 --quality preview --mode 2008 --width 16 --height 16 "
                    "--stats -o " OUT ".pfm scenes/cornell.scene") == 0);
    CHECK(t, log_contains("\npasses=3\n") && log_contains("\nspp=2\n"));
    remove(OUT ".pfm");
    remove(OUT ".ppm");
}

/* truth: the command-line contract (README): a bad value exits 2 with a message that
 *   says what is expected.
 * catches: an unknown quality taken as default, a message that does not list the three. */
static void test_unknown_quality_refused(struct check *t)
{
    CHECK(t, photon("--quality best scenes/cornell.scene") == 2 &&
             log_contains("--quality") && log_contains("'best'") &&
             log_contains("preview, default, reference"));
    CHECK(t, photon("scenes/cornell.scene --quality") == 2 &&
             log_contains("preview, default, reference"));
    CHECK(t, photon("--quality Preview scenes/cornell.scene") == 2);
}

/* truth: `default` is today's defaults exactly (presets.h): no words in any mode, so the
 *   defaults of options.c and the modes' headers alone; and a render with --quality
 *   default has the same bytes as one without --quality, in a mode whose defaults are set
 *   after parsing (1996) and in 2008, while preview's bytes differ (so the comparison can
 *   tell).
 * tolerance: none (files compared byte for byte).
 * catches: default given words (a render without --quality would change with them too,
 *   so only the word count can tell), --quality default read as another preset. */
static void test_default_is_no_quality(struct check *t)
{
    static const enum mode all[] = {MODE_DIRECT, MODE_PT, MODE_PHOTONS, MODE_JENSEN1994,
                                    MODE_JENSEN1996, MODE_PPM2008, MODE_SPPM2009};
    for (size_t m = 0; m < sizeof all / sizeof all[0]; m++) {
        struct preset_words p;
        preset_words(all[m], QUALITY_DEFAULT, &p);
        CHECK(t, p.n_words == 0);
    }
    static const char *const runs[] = {
        "--mode 1996 --photons 20000 --caustic-photons 5000 --gather-rays 16 --spp 2",
        "--mode 2008 --passes 2 --photons-per-pass 10000",
    };
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        char args[512];
        const char *size = "--width 24 --height 16 scenes/cornell-specular.scene";
        snprintf(args, sizeof args, "%s %s -o %s_none.pfm", runs[i], size, OUT);
        CHECK(t, photon(args) == 0);
        snprintf(args, sizeof args, "%s --quality default %s -o %s_default.pfm", runs[i], size,
                 OUT);
        CHECK(t, photon(args) == 0);
        CHECK(t, files_equal(OUT "_none.pfm", OUT "_default.pfm"));
        snprintf(args, sizeof args, "--quality preview %s %s -o %s_preview.pfm", runs[i], size,
                 OUT);
        CHECK(t, photon(args) == 0);
        CHECK(t, file_exists(OUT "_preview.pfm") &&
                 !files_equal(OUT "_none.pfm", OUT "_preview.pfm"));
    }
    const char *names[] = {"_none", "_default", "_preview"};
    for (size_t i = 0; i < 3; i++) {
        char name[64];
        snprintf(name, sizeof name, "%s%s.pfm", OUT, names[i]);
        remove(name);
        snprintf(name, sizeof name, "%s%s.ppm", OUT, names[i]);
        remove(name);
    }
}

void test_presets(struct check *t)
{
    RUN_TEST(t, test_every_preset_parses_as_its_words);
    RUN_TEST(t, test_preview_sets_the_table_options);
    RUN_TEST(t, test_explicit_option_beats_preset);
    RUN_TEST(t, test_unknown_quality_refused);
    RUN_TEST(t, test_default_is_no_quality);
}
