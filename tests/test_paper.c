/*
 * tests/test_paper.c -- `--paper` (app/presets.h) and the switches it stands for: the
 * option parser gives each mode exactly the words of its row, each word follows the rule
 * of a departure's switch (--no-NAME beside a default --NAME), the user's own options still
 * win, a render with --paper is the same bytes as one with the words spelled out, and the
 * one switch shared by three modes, --no-exclude-rim-photon, computes the paper's sums (the
 * other switches' effects: test_switches.c).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/app/options.h"
#include "../src/app/presets.h"
#include "../src/base/alloc.h"
#include "../src/photon/estimate.h"
#include "files.h"
#include "option_words.h"
#include "tests.h"
#include "truths.h"

#define OUT "build/test_paper"

static const char *const modes[] = {"direct", "pt", "photons", "1994", "1996", "2008",
                                    "2009"};
#define N_MODES (sizeof modes / sizeof modes[0])

/* truth: the contract of --paper (presets.h, options.h): for every mode, the options
 *   of its row in the table, spelled out, with the specular pixels at --spp samples,
 *   give the same options_hash (so the same pixels and tiles); a mode with a row differs
 *   from its defaults; --help all prints each row's words (a long row wrapped).
 * tolerance: none (hashes of the parsed values).
 * catches: --paper applied by another path than the parser, a row the mode refuses,
 *   --paper that leaves the specular pixels at 64 x --spp, a row missing from --help all. */
static void test_paper_is_its_words(struct check *t)
{
    CHECK(t, photon_logged("", "--help all", OUT ".log") == 0);
    char *help = read_text_file(OUT ".log");
    CHECK(t, help != NULL);
    if (help != NULL)
        join_option_rows(help);
    for (size_t m = 0; m < N_MODES; m++) {
        char words[512], spelled[512];
        struct options o;
        snprintf(words, sizeof words, "--mode %s --paper", modes[m]);
        REQUIRE(t, options_of(words, &o) == 0);
        CHECK(t, o.paper == 1 && o.specular_spp == o.spp);
        struct preset_words p;
        paper_words(o.mode, 1, &p);
        int n = snprintf(spelled, sizeof spelled, "--mode %s", modes[m]);
        for (int i = 0; i < p.n_words; i++)
            n += snprintf(spelled + n, sizeof spelled - (size_t)n, " %s", p.word[i]);
        char row[512]; /* the words alone, as --help prints them */
        snprintf(row, sizeof row, "%s", spelled + strlen("--mode ") + strlen(modes[m]));
        if (o.mode != MODE_PPM2008 && o.mode != MODE_SPPM2009) /* no specular pixels: refused */
            snprintf(spelled + n, sizeof spelled - (size_t)n, " --specular-spp %d", o.spp);
        CHECK(t, hash_of(words) == hash_of(spelled));
        snprintf(words, sizeof words, "--mode %s", modes[m]);
        int has_row = p.n_words > 0;
        int specular = o.mode == MODE_JENSEN1994 || o.mode == MODE_JENSEN1996;
        CHECK(t, (hash_of(spelled) != hash_of(words)) == (has_row || specular));
        CHECK(t, !has_row || (help != NULL && strstr(help, row + 1) != NULL));
    }
    struct preset_words none;
    paper_words(MODE_JENSEN1996, 0, &none);
    CHECK(t, none.n_words == 0);
    free(help);
    remove(OUT ".log");
}

/* Whether the words "--mode MODE WORDS" parse; their options' hash in *hash if so. */
static int parses(const char *mode, const char *words, uint64_t *hash)
{
    char text[512];
    struct options o;
    snprintf(text, sizeof text, "--mode %s %s", mode, words);
    *hash = hash_of(text);
    return options_of(text, &o) == 0;
}

/* truth: the rule of a departure's switch (the top of app/options.c): every word --paper
 *   stands for, in every mode, is --no-NAME where --help all lists --NAME, or an option with
 *   the paper's value, not 0. Such a --NAME is the mode's default: given alone it leaves
 *   the options as they are (a switch), or it takes a value, of which 0 is none (a
 *   departure with a value, whose paper's side is --no-NAME alone); and --no-NAME changes
 *   them. No --no-NAME that --help all lists is any mode's default.
 * tolerance: none (hashes of the parsed options).
 * catches: a paper's side spelled as a flag of its own (--rim-photon), a --no-NAME that
 *   is the default (--no-shadow-photons, the paper's being --shadow-photons), 0 for the
 *   paper's way (--precomputed-irradiance 0, in --paper's words or in a range), a
 *   --no-NAME without its --NAME. */
static void test_paper_words_follow_the_rule(struct check *t)
{
    CHECK(t, photon_logged("", "--help all", OUT ".log") == 0);
    char *help = read_text_file(OUT ".log");
    REQUIRE(t, help != NULL);
    for (size_t m = 0; m < N_MODES; m++) {
        uint64_t defaults, hash;
        REQUIRE(t, parses(modes[m], "", &defaults));
        struct options o;
        char words[256], on[64], listed[80];
        snprintf(words, sizeof words, "--mode %s", modes[m]);
        REQUIRE(t, options_of(words, &o) == 0);
        struct preset_words p;
        paper_words(o.mode, 1, &p);
        for (int i = 0; i < p.n_words; i++) {
            const char *word = p.word[i];
            if (i + 1 < p.n_words && strncmp(p.word[i + 1], "--", 2) != 0) {
                /* an option with the paper's value, which is not 0: a value that turns
                 * a departure off is its --no-NAME */
                snprintf(words, sizeof words, "%s %s", word, p.word[i + 1]);
                int ok = parses(modes[m], words, &hash) && atof(p.word[i + 1]) != 0;
                CHECK(t, ok);
                if (!ok)
                    fprintf(stderr, "test_paper: --mode %s --paper: %s breaks the rule\n",
                            modes[m], words);
                i++;
                continue;
            }
            int paired = strncmp(word, "--no-", 5) == 0;
            snprintf(on, sizeof on, "--%s", paired ? word + 5 : word);
            snprintf(listed, sizeof listed, "\n  %s ", on);
            int ok = paired && strstr(help, listed) != NULL && parses(modes[m], word, &hash) &&
                     hash != defaults;
            if (parses(modes[m], on, &hash)) { /* a switch: --NAME is the default */
                ok = ok && hash == defaults;
            } else { /* a departure with a value: 0 is none of them, --no-NAME is off */
                snprintf(words, sizeof words, "%s 0", on);
                ok = ok && !parses(modes[m], words, &hash);
            }
            CHECK(t, ok);
            if (!ok)
                fprintf(stderr, "test_paper: --mode %s --paper: %s breaks the rule\n",
                        modes[m], word);
        }
    }
    /* --no-progress changes no pixel, so no hash sees it; its default asks the
     * environment. */
    const char *row = "\n  --no-";
    for (const char *at = strstr(help, row); at != NULL; at = strstr(at + 1, row)) {
        char name[64];
        if (sscanf(at, " %63s", name) != 1 || strcmp(name, "--no-progress") == 0)
            continue;
        for (size_t m = 0; m < N_MODES; m++) {
            uint64_t defaults, hash;
            int default_side = parses(modes[m], "", &defaults) &&
                               parses(modes[m], name, &hash) && hash == defaults;
            CHECK(t, !default_side);
            if (default_side)
                fprintf(stderr, "test_paper: %s is --mode %s's default\n", name, modes[m]);
        }
    }
    free(help);
    remove(OUT ".log");
}

/* truth: parse_options()'s order (options.h): defaults, preset, --paper, the user's words.
 * catches: --paper applied after the user's words, or only when it comes first; a
 *   preset's words applied after --paper's. */
static void test_user_options_win_over_paper(struct check *t)
{
    struct options o;
    CHECK(t, options_of("--precomputed-irradiance 4 --mode 1996 --paper", &o) == 0);
    CHECK(t, o.precomputed_irradiance == 4 && o.shadow_rays == 0 && o.exclude_rim == 0);
    CHECK(t, options_of("--mode 1996 --paper --shadow-rays --specular-spp 256", &o) == 0);
    CHECK(t, o.shadow_rays == 1 && o.precomputed_irradiance == 0 && o.specular_spp == 256);
    CHECK(t, options_of("--mode 1996 --quality preview --paper", &o) == 0);
    CHECK(t, o.precomputed_irradiance == 0 && o.spp == 8 && o.gather_rays == 32);
    CHECK(t, options_of("--mode 1996", &o) == 0);
    CHECK(t, o.paper == 0 && o.exclude_rim == 1 && o.specular_spp == 64 * o.spp);
    CHECK(t, options_of("--mode 1996 --paper --glossy-corner --caustic-radius-fraction 0.5", &o)
                 == 0);
    CHECK(t, o.glossy_corner == 1 && o.caustic_radius_fraction == 0.5 && o.both_lobes == 0 &&
             o.bounded_reach == 0 && o.gradient_limit == 0);
}

/* truth: --paper and its words spelled out are the same render: compared as files, on the
 *   binary as a user runs it, for each mode with a row.
 * catches: a switch that options_hash() sees but the mode does not read, or the reverse. */
static void test_paper_renders_as_its_words(struct check *t)
{
    static const char *const runs[][2] = {
        {"--mode photons --photons 20000", "--no-exclude-rim-photon --no-max-radius"},
        {"--mode 1994 --photons 20000 --gather-rays 16 --spp 2",
         "--no-exclude-rim-photon --no-max-radius --no-both-lobes "
         "--no-bounded-reach --no-gradient-limit --no-precomputed-irradiance --specular-spp 2"},
        {"--mode 1996 --photons 20000 --caustic-photons 5000 --gather-rays 16 --spp 2",
         "--no-exclude-rim-photon --no-max-radius --no-shadow-rays "
         "--no-precomputed-irradiance --no-disc-coverage --no-both-lobes --no-glossy-corner "
         "--no-corner-photons --no-bounded-reach --no-gradient-limit --specular-spp 2"},
        {"--mode 2008 --passes 3 --photons-per-pass 5000 --spp 2",
         "--no-direct-light-samples --footprints 1 --no-caustic-footprints --no-fit-radius "
         "--no-merge-hit-points --no-resample-emission --no-facing-test "
         "--no-turn-photon-directions"},
    };
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        char args[512];
        const char *size = "--width 24 --height 16 scenes/cornell-specular.scene";
        snprintf(args, sizeof args, "%s --paper %s -o %s_paper.pfm", runs[i][0], size, OUT);
        CHECK(t, photon_logged("", args, OUT ".log") == 0);
        snprintf(args, sizeof args, "%s %s %s -o %s_words.pfm", runs[i][0], runs[i][1], size, OUT);
        CHECK(t, photon_logged("", args, OUT ".log") == 0);
        snprintf(args, sizeof args, "%s %s -o %s_ours.pfm", runs[i][0], size, OUT);
        CHECK(t, photon_logged("", args, OUT ".log") == 0);
        CHECK(t, files_equal(OUT "_paper.pfm", OUT "_words.pfm"));
        CHECK(t, !files_equal(OUT "_paper.pfm", OUT "_ours.pfm"));
    }
    const char *names[] = {OUT "_paper.pfm", OUT "_paper.png", OUT "_words.pfm",
                           OUT "_words.png", OUT "_ours.pfm",  OUT "_ours.png", OUT ".log"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        remove(names[i]);
}

/* Photons i = 1..8 on the x axis at distance i from the origin, power 1 each, arriving
 * along +z (and holding the normal +z, as 1994's records do). */
static struct kdtree *line_of_photons(void)
{
    struct photon *photons = xmalloc(8, sizeof *photons, "test photons");
    for (int i = 0; i < 8; i++)
        photons[i] = photon_pack(vec3(i + 1, 0, 0), vec3(1, 1, 1), vec3(0, 0, 1),
                                 PHOTON_DIRECT);
    return balance_kdtree(photons, 8);
}

/* truth: the sums by hand. Eight photons of power 1 at distances 1..8, k = 8: Eq. 3 as
 *   printed is f_r 8 / (pi 8^2), ours f_r 7 / (pi 8^2); the 1994 irradiance without
 *   differential checking 8 / (pi 8^2) against 7 / (pi 8^2).
 * tolerance: 1e-12 relative (a few roundings).
 * catches: exclude_rim ignored by either estimate, or the rim photon counted twice. */
static void test_rim_photon_switch(struct check *t)
{
    struct scene *scene = scene_create();
    add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    struct vec3 up = vec3(0, 0, 1), o = vec3(0, 0, 0);
    struct shading_frame frame = shading_frame_from_normal(up, 1, TRANSPORT_RADIANCE);
    struct estimate_point at = {o, up, up, &scene->materials[0], &frame, 0};
    struct kdtree *map = line_of_photons();
    struct nearest *nn = nearest_create(8);
    double fr = 0.5 / PI, area = PI * 64;
    struct estimate_settings es = {8, HUGE_VAL, 0, 0, 1};
    CHECK_CLOSE(t, radiance_estimate(map, &at, &es, nn).y, fr * 7 / area, 1e-12 * fr / area);
    es.exclude_rim = 0;
    CHECK_CLOSE(t, radiance_estimate(map, &at, &es, nn).y, fr * 8 / area, 1e-12 * fr / area);
    struct irradiance_settings is = {8, HUGE_VAL, 0, 0, 1};
    CHECK_CLOSE(t, irradiance_estimate(map, o, up, &is, nn).y, 7 / area, 1e-12 / area);
    is.exclude_rim = 0;
    CHECK_CLOSE(t, irradiance_estimate(map, o, up, &is, nn).y, 8 / area, 1e-12 / area);
    nearest_free(nn);
    kdtree_free(map);
    scene_free(scene);
}

void test_paper(struct check *t)
{
    RUN_TEST(t, test_paper_is_its_words);
    RUN_TEST(t, test_paper_words_follow_the_rule);
    RUN_TEST(t, test_user_options_win_over_paper);
    RUN_TEST(t, test_paper_renders_as_its_words);
    RUN_TEST(t, test_rim_photon_switch);
}
