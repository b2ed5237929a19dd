/*
 * tests/test_merge.c -- tiles: the hash of what made a render's pixels (options_hash), the
 * record beside a crop (app/tile.h), `photon merge` run as a user runs it, and the file of
 * global work that tiles share (--save-photons, --load-photons) as renders write and read
 * it. That file's bytes, worked out by hand, are test_merge_work_file.c's.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/app/options.h"
#include "../src/app/tile.h"
#include "../src/image/image.h"
#include "files.h"
#include "option_words.h"
#include "tests.h"
#include "truths.h"

#define OUT "build/test_merge"
#define ARGS_MAX 2048

/* Runs "PHOTON " + the printf-formatted arguments, output in OUT.log; the exit status. */
static int photon(const char *format, ...)
{
    char args[ARGS_MAX];
    va_list list;
    va_start(list, format);
    int n = vsnprintf(args, sizeof args, format, list);
    va_end(list);
    return n < (int)sizeof args ? photon_logged("", args, OUT ".log") : -1;
}

static int log_contains(const char *text)
{
    return file_contains(OUT ".log", text);
}

/* hash_of() (option_words.h) of "--mode photons WORDS": a mode with global work, so
 * --save-photons parses. */
static uint64_t photons_hash_of(const char *words)
{
    char text[256]; /* --mode photons unless words give theirs: an option is given once */
    snprintf(text, sizeof text, "%s%s", strncmp(words, "--mode ", 7) == 0 ? "" :
             "--mode photons ", words);
    return hash_of(text);
}

/* Options that change no pixel (checked for the pixels themselves by
 * test_merged_tiles_equal_whole_render and README's measurements), and one changed value of
 * each option that does; an option for other modes than photons comes after its mode,
 * and is compared with that mode's hash (base_of). */
static const char *const same_pixels_options[] = {
    "-o build/x.pfm", "--crop 0 0 4 4", "--time-limit 5", "--reference r.pfm --report r.csv",
    "--variance v.pfm", "--mode pt --error e.pfm", "--mode pt --error e.pfm --block-error b.pfm",
    "--mode 2008 --checkpoint 3", "--exposure 2", "--stats", "--progress",
    "--no-progress", "--save-photons w.work", "--load-photons w.work", "--quality default",
    "--mode pt --paper", "--exclude-rim-photon" /* the default */,
    "--mode 1996 --shadow-rays" /* the default */,
    "--mode 1996 --disc-coverage" /* the default */, "--mode 1994 --both-lobes" /* the default */,
    "--mode 1994 --glossy-photons" /* the default */,
    "--mode 1994 --lobe-lights" /* the default */,
    "--mode 1996 --glossy-corner" /* the default */, "--mode 1994 --bounded-reach" /* the default */,
    "--mode 1996 --corner-photons" /* the default */,
    "--mode 1996 --gradient-limit" /* the default */,
    "--mode 2008 --fit-radius --merge-hit-points --resample-emission" /* the defaults */,
    "--mode 2008 --facing-test --turn-photon-directions" /* the defaults */,
    "--mode 2009 --direct-light-samples --follow-glossy-lobes" /* the defaults */,
};
static const char *const other_pixels_options[] = {
    "--mode pt", "--seed 2", "--spp 3", "--specular-spp 40", "--width 100", "--height 100",
    "--adaptive 0.1", "--max-depth 3", "--photons 7", "--gather 9", "--max-radius 2", "--cone 2",
    "--no-max-radius", "--no-exclude-rim-photon", "--mode 1994 --caustic-radius-fraction 1",
    "--mode 1996 --caustic-photons 5", "--mode 1996 --caustic-gather 5",
    "--mode 1996 --gather-rays 9", "--mode 1996 --glossy-rays 2",
    "--mode 1996 --cache-accuracy 0.2", "--mode 1996 --accurate-distance 2",
    "--mode 1996 --accurate-weight 0.2", "--mode 1996 --no-shadow-rays",
    "--mode 1996 --one-map", "--mode 1996 --precomputed-irradiance 4",
    "--mode 1996 --no-precomputed-irradiance",
    "--mode 1996 --no-disc-coverage", "--mode 1996 --no-both-lobes",
    "--mode 1996 --no-glossy-corner", "--mode 1996 --no-corner-photons",
    "--mode 1994 --no-bounded-reach",
    "--mode 1996 --no-bounded-reach", "--mode 1994 --no-gradient-limit",
    "--mode 1994 --no-glossy-photons",
    "--mode 1994 --no-lobe-lights",
    "--mode 1994 --differential 3", "--mode 1994 --light-samples 9",
    "--mode 1994 --irradiance-store illumination", "--mode 1994 --no-projection-maps",
    "--mode 2008 --passes 3", "--mode 2008 --photons-per-pass 7", "--mode 2008 --alpha 0.5",
    "--mode 2008 --radius 2", "--mode 2008 --no-direct-light-samples",
    "--mode 2008 --footprints 2",
    "--mode 2008 --no-fit-radius", "--mode 2008 --no-merge-hit-points",
    "--mode 2008 --no-resample-emission", "--mode 2008 --no-facing-test",
    "--mode 2008 --no-turn-photon-directions",
    "--mode 2009 --no-follow-glossy-lobes",
    "--mode 2008 --caustic-footprints 2", "--mode 2008 --no-caustic-footprints",
    "--mode pt --target-error 0.1", "--mode pt --target-error 0.1 --confidence 0.9",
};

/* The hash words are compared with: that of their leading "--mode M" alone when more
 * words follow it, else that of no words (--mode photons). */
static uint64_t base_of(const char *words)
{
    char mode[32];
    int n = 0;
    if (sscanf(words, "--mode %31s %n", mode, &n) == 1 && n > 0 && words[n] != '\0') {
        char alone[64];
        snprintf(alone, sizeof alone, "--mode %s", mode);
        return photons_hash_of(alone);
    }
    return photons_hash_of("");
}

#define N_SAME (sizeof same_pixels_options / sizeof same_pixels_options[0])
#define N_OTHER (sizeof other_pixels_options / sizeof other_pixels_options[0])

/* Whether option (as --help prints it) is a word of one of the n entries of list. */
static int listed(const char *option, const char *const *list, size_t n)
{
    size_t length = strlen(option);
    for (size_t i = 0; i < n; i++) {
        const char *w = list[i];
        while (w != NULL) {
            if (strncmp(w, option, length) == 0 && (w[length] == ' ' || w[length] == '\0'))
                return 1;
            w = strchr(w, ' ');
            w = w != NULL ? w + 1 : NULL;
        }
    }
    return 0;
}

/* Whether every option --help all lists is in one of the two lists above (or is --help or
 * --version), so that an option added later must be put on one side here. */
static int every_option_classified(void)
{
    if (photon("--help all") != 0)
        return 0;
    char *help = read_text_file(OUT ".log");
    int all = help != NULL;
    for (char *line = help != NULL ? strtok(help, "\n") : NULL; line != NULL;
         line = strtok(NULL, "\n")) {
        char option[64];
        if (strncmp(line, "  -", 3) != 0 || sscanf(line, "%63s", option) != 1 ||
            strcmp(option, "--help") == 0 || strcmp(option, "--version") == 0 ||
            strcmp(option, "--manual") == 0)
            continue;
        if (!listed(option, same_pixels_options, N_SAME) &&
            !listed(option, other_pixels_options, N_OTHER)) {
            fprintf(stderr, "test_merge: %s is in neither list of options\n", option);
            all = 0;
        }
    }
    free(help);
    return all;
}

/* truth: what determines a render's pixels (README): the scene, the mode,
 *   the seed and the settings; not where the files go, what is printed, the PPM's
 *   exposure or the window. The hash is of values, so spelling and order do not count.
 * tolerance: none.
 * catches: an option left out of the hash (tiles of different settings would merge), an
 *   output option hashed (tiles of one image refused), argv text hashed instead of
 *   values, a new option nobody classified. */
static void test_options_hash_covers_pixel_options(struct check *t)
{
    uint64_t base = photons_hash_of("");
    CHECK(t, base != 0);
    CHECK(t, photons_hash_of("--seed 1 --spp 16") == base
                 && photons_hash_of("--spp 016 --seed 01") == base);
    for (size_t i = 0; i < N_SAME; i++)
        CHECK(t, photons_hash_of(same_pixels_options[i]) == base_of(same_pixels_options[i]));
    for (size_t i = 0; i < N_OTHER; i++) {
        uint64_t h = photons_hash_of(other_pixels_options[i]);
        base = base_of(other_pixels_options[i]);
        CHECK(t, h != 0 && base != 0 && h != base);
        if (h == 0 || h == base)
            fprintf(stderr, "test_merge: '%s' does not change the hash\n",
                    other_pixels_options[i]);
    }
    CHECK(t, every_option_classified());
}

/* truth: tile.h's format, written out by hand: the six lines in order, the hashes as 16
 *   lower-case hex digits; reading it back gives the record written. The pixels' hash of a
 *   1 x 1 image (1, 0.5, -2) is FNV-1a 64 of the floats' bits lowest byte first,
 *   00 00 80 3f, 00 00 00 3f, 00 00 00 c0, worked out apart from photon (Python:
 *   h = 0xcbf29ce484222325; for b in bytes: h = ((h ^ b) * 0x100000001b3) % 2**64).
 * tolerance: none.
 * catches: a field left out or swapped (x1 for y0), a hash printed short or in decimal,
 *   the pixels hashed as doubles or in the machine's byte order. */
static void test_tile_record_round_trip(struct check *t)
{
    struct tile_record r = {1, 2, 30, 4, 32, 6, UINT64_C(0x0123456789abcdef),
                            UINT64_C(0xfedcba9876543210), 0.0}, back;
    struct error err;
    CHECK(t, tile_record_write(OUT "_record.pfm", &r, &err) == 0);
    CHECK(t, file_equals_text(OUT "_record.pfm.window", "photon-window 2\nwindow 1 2 30 4\n"
                              "image 32 6\nhash fnv1a64 0123456789abcdef\n"
                              "pixels fnv1a64 fedcba9876543210\ntime-limit 0\n"));
    CHECK(t, tile_record_read(OUT "_record.pfm", &back, &err) == 0);
    CHECK(t, back.x0 == 1 && back.y0 == 2 && back.x1 == 30 && back.y1 == 4 &&
             back.width == 32 && back.height == 6 && back.hash == r.hash &&
             back.pixels == r.pixels && back.time_limit == 0);
    remove(OUT "_record.pfm.window");
    struct image *one = image_create(1, 1);
    image_set(one, 0, 0, vec3(1, 0.5, -2));
    CHECK(t, tile_pixels_hash(one) == UINT64_C(0x456cf7b72e202e05));
    image_free(one);
}

/* truth: tile.h's format read strictly: each malformed record is refused at its line
 *   with a message saying what was expected.
 * catches: a window outside its image accepted (merge would write out of bounds), a
 *   short or foreign hash read as some number, another version read as this one,
 *   trailing text ignored, a missing record not reported. */
static void test_bad_tile_records_are_refused(struct check *t)
{
    static const struct {
        const char *text;
        int line;
        const char *message;
    } bad[] = {
        {"", 1, "expected 'photon-window 2'"},
        {"photon-window 3\n", 1, "version 3"},
        {"photon-window 1\nwindow 0 0 8 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n"
         "time-limit 0\n", 1, "version 1 of the record; this photon reads version 2"},
        {"photon-window 2\nwindow 0 0 8\n", 2, "expected 'window X0 Y0 X1 Y1'"},
        {"photon-window 2\nwindow 0 0 -8 6\n", 2, "not a whole number"},
        {"photon-window 2\nwindow 0 0 9 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n"
         "pixels fnv1a64 0000000000000000\ntime-limit 0\n", 2, "not a window of the 8x6 image"},
        {"photon-window 2\nwindow 4 0 4 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n"
         "pixels fnv1a64 0000000000000000\ntime-limit 0\n", 2, "not a window"},
        {"photon-window 2\nwindow 0 0 8 6\nimage 8 6\nhash fnv1a64 0123456789abcde\n", 4,
         "16 hex digits"},
        {"photon-window 2\nwindow 0 0 8 6\nimage 8 6\nhash md5 0123456789abcdef\n", 4,
         "fnv1a64"},
        {"photon-window 2\nwindow 0 0 8 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n", 5,
         "expected 'pixels fnv1a64 HHHHHHHHHHHHHHHH', found the end of the file"},
        {"photon-window 2\nwindow 0 0 8 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n"
         "time-limit 0\n", 5, "expected 'pixels fnv1a64"},
        {"photon-window 2\nwindow 0 0 8 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n"
         "pixels fnv1a64 0123\n", 5, "pixels: expected 'fnv1a64' and 16 hex digits"},
        {"photon-window 2\nwindow 0 0 8 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n"
         "pixels fnv1a64 0000000000000000\n", 6, "found the end of the file"},
        {"photon-window 2\nwindow 0 0 8 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n"
         "pixels fnv1a64 0000000000000000\ntime-limit nan\n", 6, "time-limit"},
        {"photon-window 2\nwindow 0 0 8 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n"
         "pixels fnv1a64 0000000000000000\ntime-limit 0\nwindow 0 0 8 6\n", 7, "unexpected text"},
    };
    struct tile_record r;
    struct error err;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        write_text_file(OUT "_bad.pfm.window", bad[i].text);
        int refused = tile_record_read(OUT "_bad.pfm", &r, &err) < 0 &&
                      err.line == bad[i].line && strstr(err.message, bad[i].message) != NULL;
        CHECK(t, refused);
        if (!refused)
            fprintf(stderr, "test_merge: bad record %zu: line %d: %s\n", i, err.line,
                    err.message);
    }
    remove(OUT "_bad.pfm.window");
    CHECK(t, tile_record_read(OUT "_bad.pfm", &r, &err) < 0 &&
             strstr(err.message, "cannot open") != NULL);
}

/* The options of a small render of the mode that render (a mode, then anything) starts
 * with (truths.h). A static string, for one call. */
static const char *tile_options(const char *render)
{
    static char text[128];
    snprintf(text, sizeof text, "--no-progress --width 32 --height 24 --spp 2 %s",
             mode_work_options(render));
    return text;
}

/* The scene of the small renders unless a test says otherwise. */
#define BOX "scenes/cornell-specular.scene"

/* Four tiles of the 32 x 24 image with edges at odd places (13, 7, 5), so an off-by-one in
 * a window's placement shows. */
static const int tiles[4][4] = {{0, 0, 13, 7}, {13, 0, 32, 7}, {0, 7, 5, 24}, {5, 7, 32, 24}};

/* Renders tile k of tiles[] to OUT_tileK.pfm: render is the mode and the scene, with any
 * options between ("1994 --irradiance-store illumination " BOX), extra options last (so
 * they win); the exit status. */
static int render_tile(const char *render, int k, const char *extra)
{
    return photon("--mode %s %s %s --crop %d %d %d %d -o " OUT "_tile%d.pfm", render,
                  tile_options(render), extra, tiles[k][0], tiles[k][1], tiles[k][2],
                  tiles[k][3], k);
}

/* Merges the four tiles of tiles[], in another order, into OUT_full.pfm; the status. */
static int merge_four_tiles(void)
{
    remove(OUT "_full.pfm");
    return photon("merge -o " OUT "_full.pfm " OUT "_tile2.pfm " OUT "_tile0.pfm " OUT
                  "_tile3.pfm " OUT "_tile1.pfm");
}

/* truth: README's promise that a crop renders bit-identically to the same window of
 *   the whole image, in every mode, so the merged tiles are byte for byte the whole
 *   render's PFM and PPM; a whole render writes no record (its files are as before).
 *   Tile 3 is made with options that change no pixel (--stats, --exposure, --progress,
 *   and --checkpoint for 2008), which must not stop it merging.
 * tolerance: none.
 * catches: a tile pasted one pixel off, rows flipped, a mode whose crop differs from its
 *   window (global work that depends on the window), floats not kept exactly, a
 *   pixel-neutral option in the hash. */
static void test_merged_tiles_equal_whole_render(struct check *t)
{
    static const char *const modes[] = {"direct", "pt", "photons", "1994", "1996", "2008"};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        const char *mode = modes[m];
        char render[64];
        snprintf(render, sizeof render, "%s " BOX, mode);
        remove(OUT "_whole.pfm.window");
        CHECK(t, photon("--mode %s %s " BOX " -o " OUT "_whole.pfm", mode,
                        tile_options(mode)) == 0);
        CHECK(t, !file_exists(OUT "_whole.pfm.window"));
        for (int k = 0; k < 3; k++)
            CHECK(t, render_tile(render, k, "") == 0);
        CHECK(t, render_tile(render, 3, strcmp(mode, "2008") == 0
                                            ? "--stats --exposure 4 --progress --checkpoint 1"
                                            : "--stats --exposure 4 --progress") == 0);
        CHECK(t, merge_four_tiles() == 0);
        int same = files_equal(OUT "_full.pfm", OUT "_whole.pfm") &&
                   files_equal(OUT "_full.png", OUT "_whole.png");
        CHECK(t, same);
        if (!same)
            fprintf(stderr, "test_merge: mode %s: merged tiles differ from the whole\n", mode);
    }
}

/* Renders the window w (x0 y0 x1 y1) in mode direct, extra options last, to name. */
static int render_window(const char *name, const int *w, const char *extra)
{
    return photon("--mode direct %s " BOX " %s --crop %d %d %d %d -o %s",
                  tile_options("direct"), extra, w[0], w[1], w[2], w[3], name);
}

/* Whether "photon merge -o OUT_full.pfm TILES" exits 2 with message in its output and
 * leaves no OUT_full.pfm, OUT_full.png or temporary behind. */
static int merge_refused(const char *tile_names, const char *message)
{
    remove(OUT "_full.pfm");
    remove(OUT "_full.png");
    int refused = photon("merge -o " OUT "_full.pfm %s", tile_names) == 2 &&
                  log_contains(message) && !file_exists(OUT "_full.pfm") &&
                  !file_exists(OUT "_full.png") && no_temporaries(OUT "_full.pfm");
    if (!refused)
        fprintf(stderr, "test_merge: 'merge %s' was not refused with '%s'\n", tile_names,
                message);
    return refused;
}

#define THREE_TILES OUT "_tile0.pfm " OUT "_tile1.pfm " OUT "_tile2.pfm "

/* truth: merge.h's contract: a set of tiles that is not exactly one image's windows is
 *   refused with exit status 2, a message naming the file (or, for a gap, the window to
 *   render; for a tile given twice, both arguments), and no output; the same tiles with
 *   the right fourth one merge.
 * catches: a gap filled with black, an overlap resolved silently, a PFM pasted into a
 *   window of another size, tiles of another seed, image size or time limit mixed in, a
 *   tile given twice (by one name or two) reported as overlapping itself. */
static void test_merge_refuses_bad_tile_sets(struct check *t)
{
    for (int k = 0; k < 4; k++)
        CHECK(t, render_tile("direct " BOX, k, "") == 0);
    static const int overlapping[4] = {10, 5, 20, 10};
    CHECK(t, render_window(OUT "_foreign.pfm", tiles[3], "--seed 2") == 0);
    CHECK(t, render_window(OUT "_timed.pfm", tiles[3], "--time-limit 1000") == 0);
    CHECK(t, photon("--mode direct --no-progress --width 40 --height 24 --spp 2 %s " BOX
                    " --crop 5 7 32 24 -o " OUT "_wide.pfm", mode_work_options("direct")) == 0);
    CHECK(t, render_window(OUT "_over.pfm", overlapping, "") == 0);
    CHECK(t, photon("--mode direct %s " BOX " -o " OUT "_plain.pfm",
                    tile_options("direct")) == 0);
    CHECK(t, run_command("cp " OUT "_tile2.pfm " OUT "_wrong.pfm && cp " OUT "_tile3.pfm.window "
                         OUT "_wrong.pfm.window") == 0);
    CHECK(t, merge_refused(THREE_TILES, "uncovered: --crop 5 7 32 24"));
    CHECK(t, merge_refused(THREE_TILES OUT "_tile3.pfm " OUT "_over.pfm",
                           OUT "_over.pfm: overlaps " OUT "_tile0.pfm in the window 10 5 13 7"));
    CHECK(t, merge_refused(THREE_TILES OUT "_wrong.pfm",
                           OUT "_wrong.pfm: 5x17 pixels, but its record's window 5 7 32 24 "
                           "is 27x17"));
    CHECK(t, merge_refused(THREE_TILES OUT "_wide.pfm",
                           OUT "_wide.pfm: a window of a 40x24 image"));
    CHECK(t, merge_refused(THREE_TILES OUT "_foreign.pfm",
                           OUT "_foreign.pfm: made from other scene files, mode, seed"));
    CHECK(t, merge_refused(THREE_TILES OUT "_timed.pfm", OUT "_timed.pfm: rendered with "
                           "--time-limit 1000"));
    CHECK(t, merge_refused(THREE_TILES OUT "_plain.pfm", OUT "_plain.pfm.window: cannot open"));
    CHECK(t, merge_refused(THREE_TILES OUT "_tile3.pfm " OUT "_tile1.pfm", "merge: one tile "
                           "given twice: tile 2 (" OUT "_tile1.pfm) and tile 5 (" OUT
                           "_tile1.pfm) are both the window 13 0 32 7"));
    CHECK(t, run_command("cp " OUT "_tile3.pfm " OUT "_again.pfm && cp " OUT "_tile3.pfm.window "
                         OUT "_again.pfm.window") == 0);
    CHECK(t, merge_refused(THREE_TILES OUT "_tile3.pfm " OUT "_again.pfm", "tile 4 (" OUT
                           "_tile3.pfm) and tile 5 (" OUT "_again.pfm) are both the window"));
    CHECK(t, merge_refused("", "at least one tile"));
    CHECK(t, merge_refused("--frobnicate " THREE_TILES, "unknown option '--frobnicate'"));
    CHECK(t, photon("merge -o " OUT "_full.jpg " THREE_TILES) == 2 && log_contains(".png or"));
    CHECK(t, photon("merge -o " OUT "_full.pfm " THREE_TILES OUT "_tile3.pfm") == 0);
    CHECK(t, photon("merge --help") == 0 && log_contains("usage: photon merge"));
}

/* truth: tile.h: a record describes the one PFM it was written with (its pixels' hash), so
 *   merge refuses a tile whose PFM was written again without its record: the top half's
 *   PFM replaced by the bottom half's, of the same size (as a --checkpoint of a render of
 *   the bottom half to the top's name leaves it when that render is stopped), or with one
 *   byte of its last pixel changed. The true tiles merge. merge -o NAME.pfm then removes
 *   the record NAME.pfm.window an earlier crop to NAME.pfm left, as a whole render does.
 * tolerance: none.
 * catches: a bottom tile pasted into the top half with exit 0 (the record's window and
 *   hash alone checked); a stale record beside the merged image, by which merge would
 *   take the whole image for that crop. */
static void test_merge_refuses_pixels_the_record_does_not_describe(struct check *t)
{
    static const int top[4] = {0, 0, 32, 12}, bottom[4] = {0, 12, 32, 24};
    const char *both = OUT "_top.pfm " OUT "_bottom.pfm";
    CHECK(t, render_window(OUT "_top.pfm", top, "") == 0);
    CHECK(t, render_window(OUT "_bottom.pfm", bottom, "") == 0);
    CHECK(t, run_command("cp " OUT "_top.pfm " OUT "_kept.pfm && cp " OUT "_bottom.pfm "
                         OUT "_top.pfm") == 0);
    CHECK(t, merge_refused(both, OUT "_top.pfm: not the pixels its record " OUT
                           "_top.pfm.window describes"));
    CHECK(t, run_command("cp " OUT "_kept.pfm " OUT "_top.pfm && printf '\\001' | dd of="
                         OUT "_top.pfm bs=1 seek=$(($(wc -c < " OUT "_top.pfm) - 1)) "
                         "conv=notrunc 2>/dev/null && ! cmp -s " OUT "_top.pfm " OUT
                         "_kept.pfm") == 0);
    CHECK(t, merge_refused(both, OUT "_top.pfm: not the pixels its record"));
    CHECK(t, run_command("cp " OUT "_kept.pfm " OUT "_top.pfm") == 0);
    CHECK(t, render_window(OUT "_full.pfm", bottom, "") == 0 &&
             file_exists(OUT "_full.pfm.window"));
    CHECK(t, photon("merge -o " OUT "_full.pfm %s", both) == 0 &&
             !file_exists(OUT "_full.pfm.window"));
}

/* truth: tile.h's contract: a whole render removes the record an earlier crop left under
 *   its name once its own image is written, so that merge cannot take the whole image for
 *   that crop; a render that fails writes nothing and removes nothing. The crop here is
 *   of the whole window with another seed, whose record merge would otherwise accept
 *   with the new image (it is the window's size).
 * tolerance: none.
 * catches: a stale record left beside a whole render (merge then passes off the new image
 *   as the old crop), a record removed by a render that wrote no image. */
static void test_whole_render_removes_stale_record(struct check *t)
{
    static const int whole[4] = {0, 0, 32, 24};
    CHECK(t, render_window(OUT "_stale.pfm", whole, "--seed 2") == 0);
    CHECK(t, photon("--mode photons %s " BOX " --load-photons " OUT "_none.work -o " OUT
                    "_stale.pfm", tile_options("photons")) == 2);
    CHECK(t, file_exists(OUT "_stale.pfm.window"));
    CHECK(t, photon("--mode direct %s " BOX " -o " OUT "_stale.pfm",
                    tile_options("direct")) == 0);
    CHECK(t, !file_exists(OUT "_stale.pfm.window"));
    CHECK(t, merge_refused(OUT "_stale.pfm", OUT "_stale.pfm.window: cannot open"));
}

/* ---- The file of global work (app/work_file.h) ---- */

/* What the work-file tests render: each mode with global work on the specular box, and
 * 1994 with illumination maps on the PPM box, whose shrouds (quads) catch its lenses'
 * caustics, so that CI sub-maps are made (268 at tile_options()'s), saved and loaded. */
#define ILLUMINATION_RENDER "1994 --irradiance-store illumination scenes/ppm-box.scene"
static const char *const work_renders[] = {
    "photons " BOX, "1994 " BOX, "1996 " BOX, ILLUMINATION_RENDER,
};

/* Renders render (mode, options, scene) with tile_options(), extra options last, to
 * OUT_NAME.pfm; the status. */
static int render_work(const char *render, const char *name, const char *extra)
{
    return photon("--mode %s %s %s -o " OUT "_%s.pfm", render, tile_options(render), extra,
                  name);
}

/* The number --stats printed for key in the last command's output; -1 when it did not. */
static double logged_stat(const char *key)
{
    return file_stat(OUT ".log", key);
}

/* truth: the global work is the same whatever window is rendered (README: a crop
 *   equals its window of the whole image), so a render that loads it instead of doing it
 *   writes the bytes of the plain render, whole and as tiles merged, and a crop saves the
 *   same file as the whole render. The render that loads 1994's illumination maps must
 *   find CI sub-maps in them (--stats), or the CI path went untried.
 * tolerance: none.
 * catches: a map re-balanced or reordered on loading, photons or doubles not kept
 *   exactly, cache records re-added in another order (other sums), the cache's pre-pass,
 *   a map or the illumination maps left out of the file, CI sub-maps dropped or misplaced,
 *   work that depends on the window (the CI resolution's pretrace over the crop alone). */
static void test_loaded_work_renders_same_bytes(struct check *t)
{
    for (size_t m = 0; m < sizeof work_renders / sizeof work_renders[0]; m++) {
        const char *render = work_renders[m];
        CHECK(t, render_work(render, "plain", "") == 0);
        CHECK(t, render_work(render, "made", "--save-photons " OUT "_made.work") == 0);
        CHECK(t, render_work(render, "loaded", "--stats --load-photons " OUT "_made.work") == 0);
        CHECK(t, strcmp(render, ILLUMINATION_RENDER) != 0 ||
                 logged_stat("illumination_ci_maps") > 0);
        CHECK(t, render_work(render, "crop_saved", "--crop 5 7 30 20 --save-photons "
                             OUT "_crop.work") == 0);
        for (int k = 0; k < 4; k++)
            CHECK(t, render_tile(render, k, "--load-photons " OUT "_made.work") == 0);
        CHECK(t, merge_four_tiles() == 0);
        int same = files_equal(OUT "_made.pfm", OUT "_plain.pfm") &&
                   files_equal(OUT "_loaded.pfm", OUT "_plain.pfm") &&
                   files_equal(OUT "_full.pfm", OUT "_plain.pfm") &&
                   files_equal(OUT "_full.png", OUT "_plain.png") &&
                   files_equal(OUT "_made.work", OUT "_crop.work");
        CHECK(t, same);
        if (!same)
            fprintf(stderr, "test_merge: --mode %s: --load-photons changed the image\n",
                    render);
    }
}

/* The length of the file name in bytes, or -1 when it cannot be read. */
static long file_length(const char *name)
{
    FILE *f = fopen(name, "rb");
    long length = f != NULL && fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (f != NULL)
        fclose(f);
    return length;
}

/* OUT_made.work changed into OUT_bad.work: its first keep bytes (all when keep < 0), byte
 * flip (when >= 0) with its bits inverted, and extra bytes of zeros after. */
static void write_changed_work(long keep, long flip, size_t extra)
{
    static unsigned char bytes[4 << 20];
    FILE *f = fopen(OUT "_made.work", "rb");
    size_t n = f != NULL ? fread(bytes, 1, sizeof bytes - extra, f) : 0;
    if (f != NULL)
        fclose(f);
    if (keep >= 0 && (size_t)keep < n)
        n = (size_t)keep;
    if (flip >= 0 && (size_t)flip < n)
        bytes[flip] ^= 0xff;
    memset(bytes + n, 0, extra);
    write_bytes_file(OUT "_bad.work", bytes, n + extra);
}

/* Whether "photon --mode RENDER tile_options() EXTRA -o OUT_refused.pfm" exits 2 with
 * message in its output and leaves no image. */
static int render_refused(const char *render, const char *extra, const char *message)
{
    remove(OUT "_refused.pfm");
    remove(OUT "_refused.png");
    int refused = render_work(render, "refused", extra) == 2 && log_contains(message) &&
                  !file_exists(OUT "_refused.pfm") && !file_exists(OUT "_refused.png");
    if (!refused)
        fprintf(stderr, "test_merge: '%s' with --mode %s not refused with '%s'\n", extra,
                render, message);
    return refused;
}

#define LOAD_BAD "--load-photons " OUT "_bad.work"

/* truth: work_file.h's promise that a file of global work is used only when it is whole,
 *   undamaged and made for this render, and the modes that have none refuse the options.
 *   The 1996 file of tile_options() is some 0.48 MB, the cache's 276 records (62 kB) at
 *   its end: the cuts fall in the header, in the first map's photons, in the cache's
 *   records and in the checksum. The illumination
 *   maps end a 1994 file that holds them (the PPM box's, over 50 kB: 2,036 DI elements
 *   of 24 bytes): cuts and flipped bytes from the last byte before the checksum to 9 kB
 *   before it fall in their flags and in their DI and CI irradiances. A flipped byte may
 *   be refused by a range check before the checksum is reached, so any refusal of the
 *   file will do there.
 * tolerance: none.
 * catches: a missing length or checksum check (a truncated or damaged file read as
 *   good), trailing bytes accepted, the hash not compared (another seed's maps used),
 *   the illumination maps outside the checksum, a mode without global work silently
 *   ignoring the options. */
static void test_bad_work_files_are_refused(struct check *t)
{
    CHECK(t, render_work("1996 " BOX, "made", "--save-photons " OUT "_made.work") == 0);
    static const struct {
        long keep, flip;
        size_t extra;
        const char *message;
    } bad[] = {
        {-1, 0, 0, "not a file of photon's saved global work"},
        {-1, 8, 0, "version 252 of the saved work; this photon reads version 3"},
        {6, -1, 0, "not a file of photon's saved global work"},
        {10, -1, 0, "truncated: the file ends inside the header"},
        {16, -1, 0, "truncated: the file ends inside the header"},
        {1000, -1, 0, "truncated: "},
        {450000, -1, 0, "truncated: "},
        {-1, 40, 0, "damaged: its checksum is"},
        {-1, -1, 1, "unexpected bytes after the checksum"},
        {-1, 13, 0, "saved from other scene files, mode, seed or options"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        write_changed_work(bad[i].keep, bad[i].flip, bad[i].extra);
        CHECK(t, render_refused("1996 " BOX, LOAD_BAD, bad[i].message));
    }
    write_changed_work(-1, -1, 0);
    CHECK(t, render_work("1996 " BOX, "loaded", LOAD_BAD) == 0);
    CHECK(t, render_refused("1996 " BOX, LOAD_BAD " --seed 2", "saved from other scene files"));
    CHECK(t, render_refused("photons " BOX, LOAD_BAD, "saved from other scene files"));
    CHECK(t, render_refused("1996 " BOX, "--load-photons " OUT "_none.work", "cannot open"));
    CHECK(t, render_refused("pt " BOX, LOAD_BAD, "mode pt has no global work"));
    CHECK(t, render_refused("direct " BOX, "--save-photons " OUT "_x.work",
                            "mode direct has no"));
    CHECK(t, render_refused("2008 " BOX, LOAD_BAD, "mode 2008 traces new photons in every "
                            "pass"));
    CHECK(t, render_refused("1996 " BOX, LOAD_BAD " --save-photons " OUT "_x.work",
                            "give one or the other"));
    CHECK(t, !file_exists(OUT "_x.work"));
    CHECK(t, render_work(ILLUMINATION_RENDER, "made", "--save-photons " OUT "_made.work") == 0);
    long length = file_length(OUT "_made.work");
    CHECK(t, length > 60000);
    for (long back = 9; back <= 9 * 1024; back *= 4) {
        write_changed_work(length - back, -1, 0);
        CHECK(t, render_refused(ILLUMINATION_RENDER, LOAD_BAD, "truncated: "));
        write_changed_work(-1, length - back, 0);
        CHECK(t, render_refused(ILLUMINATION_RENDER, LOAD_BAD, OUT "_bad.work: "));
    }
}

void test_merge(struct check *t)
{
    RUN_TEST(t, test_options_hash_covers_pixel_options);
    RUN_TEST(t, test_tile_record_round_trip);
    RUN_TEST(t, test_bad_tile_records_are_refused);
    RUN_TEST(t, test_merged_tiles_equal_whole_render);
    RUN_TEST(t, test_merge_refuses_bad_tile_sets);
    RUN_TEST(t, test_whole_render_removes_stale_record);
    RUN_TEST(t, test_merge_refuses_pixels_the_record_does_not_describe);
    RUN_TEST(t, test_loaded_work_renders_same_bytes);
    RUN_TEST(t, test_bad_work_files_are_refused);
}
