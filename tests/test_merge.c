/*
 * tests/test_merge.c -- tiles: the hash of what made a render's pixels (options_hash), the
 * record beside a crop (app/tile.h), `photon merge` run as a user runs it, and the file of
 * global work that tiles share (--save-photons, --load-photons: app/work_file.h).
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/app/options.h"
#include "../src/app/tile.h"
#include "../src/app/work_file.h"
#include "../src/base/hash.h"
#include "files.h"
#include "tests.h"

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

/* options_hash() of "photon --mode photons WORDS scenes/cornell.scene", WORDS split at
 * spaces; 0 (which
 * no test expects) when the options do not parse. */
static uint64_t hash_of(const char *words)
{
    char text[256], *argv[32];
    int argc = 0;
    argv[argc++] = "photon";
    argv[argc++] = "--mode"; /* a mode with global work, so --save-photons parses */
    argv[argc++] = "photons";
    snprintf(text, sizeof text, "%s", words);
    for (char *w = strtok(text, " "); w != NULL && argc < 30; w = strtok(NULL, " "))
        argv[argc++] = w;
    argv[argc++] = "scenes/cornell.scene";
    struct options o;
    struct error err;
    return parse_options(argc, argv, &o, &err) == 0 ? options_hash(&o, FNV1A_OFFSET_BASIS) : 0;
}

/* Options that change no pixel (checked for the pixels themselves by
 * test_merged_tiles_equal_whole_render and README's measurements), and one changed value of
 * each option that does. */
static const char *const same_pixels_options[] = {
    "-o build/x.pfm", "--crop 0 0 4 4", "--time-limit 5", "--reference r.pfm --report r.csv",
    "--variance v.pfm", "--checkpoint 3", "--exposure 2", "--stats", "--progress",
    "--no-progress", "--save-photons w.work", "--load-photons w.work",
};
static const char *const other_pixels_options[] = {
    "--mode pt", "--seed 2", "--spp 3", "--width 100", "--height 100", "--adaptive 0.1",
    "--max-depth 3", "--photons 7", "--gather 9", "--max-radius 2", "--cone 2",
    "--caustic-photons 5", "--caustic-gather 5", "--gather-rays 9", "--glossy-rays 2",
    "--cache-accuracy 0.2", "--accurate-distance 2", "--accurate-weight 0.2",
    "--no-shadow-photons", "--one-map", "--differential 3", "--light-samples 9",
    "--irradiance-store illumination", "--no-projection-maps", "--passes 3",
    "--photons-per-pass 7", "--alpha 0.5", "--radius 2",
};

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

/* Whether every option --help lists is in one of the two lists above (or is --help or
 * --version), so that an option added later must be put on one side here. */
static int every_option_classified(void)
{
    if (photon("--help") != 0)
        return 0;
    char *help = read_text_file(OUT ".log");
    int all = help != NULL;
    for (char *line = help != NULL ? strtok(help, "\n") : NULL; line != NULL;
         line = strtok(NULL, "\n")) {
        char option[64];
        if (strncmp(line, "  -", 3) != 0 || sscanf(line, "%63s", option) != 1 ||
            strcmp(option, "--help") == 0 || strcmp(option, "--version") == 0)
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

/* truth: what determines a render's pixels (DESIGN.md, Determinism): the scene, the mode,
 *   the seed and the settings; not where the files go, what is printed, the PPM's
 *   exposure or the window. The hash is of values, so spelling and order do not count.
 * tolerance: none.
 * catches: an option left out of the hash (tiles of different settings would merge), an
 *   output option hashed (tiles of one image refused), argv text hashed instead of
 *   values, a new option nobody classified. */
static void test_options_hash_covers_pixel_options(struct check *t)
{
    uint64_t base = hash_of("");
    CHECK(t, base != 0);
    CHECK(t, hash_of("--seed 1 --spp 16") == base && hash_of("--spp 016 --seed 01") == base);
    for (size_t i = 0; i < N_SAME; i++)
        CHECK(t, hash_of(same_pixels_options[i]) == base);
    for (size_t i = 0; i < N_OTHER; i++) {
        uint64_t h = hash_of(other_pixels_options[i]);
        CHECK(t, h != 0 && h != base);
        if (h == 0 || h == base)
            fprintf(stderr, "test_merge: '%s' does not change the hash\n",
                    other_pixels_options[i]);
    }
    CHECK(t, every_option_classified());
}

/* truth: tile.h's format, written out by hand: the five lines in order, the hash as 16
 *   lower-case hex digits; reading it back gives the record written.
 * tolerance: none.
 * catches: a field left out or swapped (x1 for y0), the hash printed short or in decimal. */
static void test_tile_record_round_trip(struct check *t)
{
    struct tile_record r = {1, 2, 30, 4, 32, 6, UINT64_C(0x0123456789abcdef), 0.0}, back;
    struct error err;
    CHECK(t, tile_record_write(OUT "_record.pfm", &r, &err) == 0);
    CHECK(t, file_equals_text(OUT "_record.pfm.window", "photon-window 1\nwindow 1 2 30 4\n"
                              "image 32 6\nhash fnv1a64 0123456789abcdef\ntime-limit 0\n"));
    CHECK(t, tile_record_read(OUT "_record.pfm", &back, &err) == 0);
    CHECK(t, back.x0 == 1 && back.y0 == 2 && back.x1 == 30 && back.y1 == 4 &&
             back.width == 32 && back.height == 6 && back.hash == r.hash &&
             back.time_limit == 0);
    remove(OUT "_record.pfm.window");
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
        {"", 1, "expected 'photon-window 1'"},
        {"photon-window 2\n", 1, "version 2"},
        {"photon-window 1\nwindow 0 0 8\n", 2, "expected 'window X0 Y0 X1 Y1'"},
        {"photon-window 1\nwindow 0 0 -8 6\n", 2, "not a whole number"},
        {"photon-window 1\nwindow 0 0 9 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n"
         "time-limit 0\n", 2, "not a window of the 8x6 image"},
        {"photon-window 1\nwindow 4 0 4 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n"
         "time-limit 0\n", 2, "not a window"},
        {"photon-window 1\nwindow 0 0 8 6\nimage 8 6\nhash fnv1a64 0123456789abcde\n", 4,
         "16 hex digits"},
        {"photon-window 1\nwindow 0 0 8 6\nimage 8 6\nhash md5 0123456789abcdef\n", 4,
         "fnv1a64"},
        {"photon-window 1\nwindow 0 0 8 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n", 5,
         "found the end of the file"},
        {"photon-window 1\nwindow 0 0 8 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n"
         "time-limit nan\n", 5, "time-limit"},
        {"photon-window 1\nwindow 0 0 8 6\nimage 8 6\nhash fnv1a64 0123456789abcdef\n"
         "time-limit 0\nwindow 0 0 8 6\n", 6, "unexpected text"},
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

/* A small render of the specular box with every mode's work cut to a fraction of a
 * second (the counts of `make check`'s determinism loop). */
#define TILE_SETTINGS "--no-progress --width 32 --height 24 --spp 2 --photons 20000 " \
                      "--passes 2 --photons-per-pass 20000 --caustic-photons 20000 "   \
                      "--gather-rays 32 scenes/cornell-specular.scene"

/* Four tiles of the 32 x 24 image with edges at odd places (13, 7, 5), so an off-by-one in
 * a window's placement shows. */
static const int tiles[4][4] = {{0, 0, 13, 7}, {13, 0, 32, 7}, {0, 7, 5, 24}, {5, 7, 32, 24}};

/* Renders tile k of tiles[] in mode to OUT_tileK.pfm, extra options last (so they win);
 * the exit status. */
static int render_tile(const char *mode, int k, const char *extra)
{
    return photon("--mode %s " TILE_SETTINGS " %s --crop %d %d %d %d -o " OUT "_tile%d.pfm",
                  mode, extra, tiles[k][0], tiles[k][1], tiles[k][2], tiles[k][3], k);
}

/* truth: DESIGN.md's promise that a crop renders bit-identically to the same window of
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
        remove(OUT "_whole.pfm.window");
        CHECK(t, photon("--mode %s %s -o " OUT "_whole.pfm", mode, TILE_SETTINGS) == 0);
        CHECK(t, !file_exists(OUT "_whole.pfm.window"));
        for (int k = 0; k < 3; k++)
            CHECK(t, render_tile(mode, k, "") == 0);
        CHECK(t, render_tile(mode, 3, strcmp(mode, "2008") == 0
                                          ? "--stats --exposure 4 --progress --checkpoint 1"
                                          : "--stats --exposure 4 --progress") == 0);
        remove(OUT "_full.pfm");
        CHECK(t, photon("merge -o " OUT "_full.pfm " OUT "_tile2.pfm " OUT "_tile0.pfm "
                        OUT "_tile3.pfm " OUT "_tile1.pfm") == 0);
        int same = files_equal(OUT "_full.pfm", OUT "_whole.pfm") &&
                   files_equal(OUT "_full.ppm", OUT "_whole.ppm");
        CHECK(t, same);
        if (!same)
            fprintf(stderr, "test_merge: mode %s: merged tiles differ from the whole\n", mode);
    }
}

/* Renders the window w (x0 y0 x1 y1) in mode direct, extra options last, to name. */
static int render_window(const char *name, const int *w, const char *extra)
{
    return photon("--mode direct " TILE_SETTINGS " %s --crop %d %d %d %d -o %s", extra, w[0],
                  w[1], w[2], w[3], name);
}

/* Whether "photon merge -o OUT_full.pfm TILES" exits 2 with message in its output and
 * leaves no OUT_full.pfm, OUT_full.ppm or temporary behind. */
static int merge_refused(const char *tile_names, const char *message)
{
    remove(OUT "_full.pfm");
    remove(OUT "_full.ppm");
    int refused = photon("merge -o " OUT "_full.pfm %s", tile_names) == 2 &&
                  log_contains(message) && !file_exists(OUT "_full.pfm") &&
                  !file_exists(OUT "_full.ppm") && !file_exists(OUT "_full.pfm.tmp");
    if (!refused)
        fprintf(stderr, "test_merge: 'merge %s' was not refused with '%s'\n", tile_names,
                message);
    return refused;
}

#define THREE_TILES OUT "_tile0.pfm " OUT "_tile1.pfm " OUT "_tile2.pfm "

/* truth: merge.h's contract: a set of tiles that is not exactly one image's windows is
 *   refused with exit status 2, a message naming the file (or, for a gap, the window to
 *   render), and no output; the same tiles with the right fourth one merge.
 * catches: a gap filled with black, an overlap resolved silently, a PFM pasted into a
 *   window of another size, tiles of another seed, image size or time limit mixed in. */
static void test_merge_refuses_bad_tile_sets(struct check *t)
{
    for (int k = 0; k < 4; k++)
        CHECK(t, render_tile("direct", k, "") == 0);
    static const int overlapping[4] = {10, 5, 20, 10};
    CHECK(t, render_window(OUT "_foreign.pfm", tiles[3], "--seed 2") == 0);
    CHECK(t, render_window(OUT "_timed.pfm", tiles[3], "--time-limit 1000") == 0);
    CHECK(t, render_window(OUT "_wide.pfm", tiles[3], "--width 40") == 0);
    CHECK(t, render_window(OUT "_over.pfm", overlapping, "") == 0);
    CHECK(t, photon("--mode direct %s -o " OUT "_plain.pfm", TILE_SETTINGS) == 0);
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
    CHECK(t, merge_refused("", "at least one tile"));
    CHECK(t, merge_refused("--frobnicate " THREE_TILES, "unknown option '--frobnicate'"));
    CHECK(t, photon("merge -o " OUT "_full.png " THREE_TILES) == 2 && log_contains(".pfm"));
    CHECK(t, photon("merge -o " OUT "_full.pfm " THREE_TILES OUT "_tile3.pfm") == 0);
    CHECK(t, photon("merge --help") == 0 && log_contains("usage: photon merge"));
}

/* ---- The file of global work (app/work_file.h) ---- */

/* The one photon of the hand-written file below (example_bytes). */
static struct photon example_photon(void)
{
    struct photon p = {{1.0f, -2.0f, 0.5f}, {1, 2, 3, 4}, 5, 6, 0, PHOTON_CAUSTIC};
    return p;
}

/* What work_file.h's table says the file of example_work() holds, written out by hand:
 * little-endian numbers, the floats' and doubles' IEEE 754 bits. Returns its length
 * without the last 8 bytes, the checksum, which are left for the caller. */
static size_t example_bytes(unsigned char *b)
{
    static const unsigned char head[] = {
        'p', 'h', 'o', 't', 'o', 'n', 'G', 'W', 1, 0, 0, 0,           /* magic, version  */
        0xef, 0xcd, 0xab, 0x89, 0x67, 0x45, 0x23, 0x01,               /* hash            */
        2, 0, 0, 0,                                                   /* two maps        */
        1, 1, 0, 0, 0, 0, 0, 0, 0,                                    /* one photon      */
        0, 0, 0x80, 0x3f, 0, 0, 0, 0xc0, 0, 0, 0, 0x3f,               /* 1, -2, 0.5      */
        1, 2, 3, 4, 5, 6, 0, PHOTON_CAUSTIC,                          /* power ... flags */
        0,                                                            /* no second map   */
        1, 0, 0, 0, 0, 0, 0, 0,                                       /* one record      */
    };
    size_t n = sizeof head;
    memcpy(b, head, n);
    memset(b + n, 0, 28 * 8); /* the record: all 0.0 but n.z = 1 and R = 2 */
    b[n + 5 * 8 + 6] = 0xf0;  /* 1.0 = 0x3ff0000000000000 */
    b[n + 5 * 8 + 7] = 0x3f;
    b[n + 9 * 8 + 7] = 0x40;  /* 2.0 = 0x4000000000000000 */
    return n + 28 * 8;
}

/* truth: work_file.h's byte table, written out by hand above (a photon's floats and a
 *   record's doubles as IEEE bits, numbers lowest byte first), and a round trip.
 * tolerance: none.
 * catches: a field in the wrong place or byte order, the unused heap[0] written, a
 *   missing map not marked, the checksum not over every byte before it. */
static void test_work_file_format(struct check *t)
{
    struct photon *heap = calloc(2, sizeof *heap);
    heap[1] = example_photon();
    struct global_work work = {NULL, 0, NULL, 0}, back = {NULL, 0, NULL, 0};
    global_work_add_maps(&work, 2);
    work.maps[0] = kdtree_from_heap(heap, 1);
    work.records = calloc(1, sizeof *work.records);
    work.n_records = 1;
    work.records[0].n = vec3(0, 0, 1);
    work.records[0].r = 2;
    struct error err;
    uint64_t hash = UINT64_C(0x0123456789abcdef);
    CHECK(t, work_file_write(OUT "_example.work", hash, &work, &err) == 0);
    unsigned char expected[512];
    size_t n = example_bytes(expected);
    uint64_t sum = fnv1a(FNV1A_OFFSET_BASIS, expected, n);
    for (int i = 0; i < 8; i++)
        expected[n + i] = (unsigned char)(sum >> (8 * i));
    write_bytes_file(OUT "_expected.work", expected, n + 8);
    CHECK(t, files_equal(OUT "_example.work", OUT "_expected.work"));
    CHECK(t, work_file_read(OUT "_example.work", hash, &back, &err) == 0);
    CHECK(t, back.n_maps == 2 && back.maps[0] != NULL && back.maps[1] == NULL &&
             back.maps[0]->n_photons == 1 && back.n_records == 1);
    if (back.n_maps == 2 && back.maps[0] != NULL && back.n_records == 1) {
        struct photon p = example_photon();
        CHECK(t, memcmp(&back.maps[0]->photons[1], &p, sizeof p) == 0);
        CHECK(t, memcmp(&back.records[0], &work.records[0], sizeof back.records[0]) == 0);
    }
    global_work_free(&back);
    global_work_free(&work);
}

/* Renders mode with TILE_SETTINGS, extra options last, to OUT_NAME.pfm; the status. */
static int render_work(const char *mode, const char *name, const char *extra)
{
    return photon("--mode %s " TILE_SETTINGS " %s -o " OUT "_%s.pfm", mode, extra, name);
}

/* truth: the global work is the same whatever window is rendered (DESIGN.md: a crop
 *   equals its window of the whole image), so a render that loads it instead of doing it
 *   must write the same bytes, whole and cropped, and a crop must save the same file as
 *   the whole render.
 * tolerance: none.
 * catches: a map re-balanced or reordered on loading, photons or doubles not kept
 *   exactly, cache records re-added in another order (other sums), the cache's pre-pass
 *   or a map left out of the file, work that depends on the window. */
static void test_loaded_work_renders_same_bytes(struct check *t)
{
    static const char *const modes[] = {"photons", "1994", "1996"};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        const char *mode = modes[m];
        CHECK(t, render_work(mode, "made", "--save-photons " OUT "_made.work") == 0);
        CHECK(t, render_work(mode, "loaded", "--load-photons " OUT "_made.work") == 0);
        CHECK(t, render_work(mode, "crop_made", "--crop 5 7 30 20") == 0);
        CHECK(t, render_work(mode, "crop_loaded", "--crop 5 7 30 20 --load-photons "
                             OUT "_made.work") == 0);
        CHECK(t, render_work(mode, "crop_saved", "--crop 5 7 30 20 --save-photons "
                             OUT "_crop.work") == 0);
        int same = files_equal(OUT "_made.pfm", OUT "_loaded.pfm") &&
                   files_equal(OUT "_crop_made.pfm", OUT "_crop_loaded.pfm") &&
                   files_equal(OUT "_crop_made.pfm", OUT "_crop_saved.pfm") &&
                   files_equal(OUT "_made.work", OUT "_crop.work");
        CHECK(t, same);
        if (!same)
            fprintf(stderr, "test_merge: mode %s: --load-photons changed the image\n", mode);
    }
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

/* Whether "photon --mode MODE TILE_SETTINGS EXTRA -o OUT_refused.pfm" exits 2 with message
 * in its output and leaves no image. */
static int render_refused(const char *mode, const char *extra, const char *message)
{
    remove(OUT "_refused.pfm");
    remove(OUT "_refused.ppm");
    int refused = render_work(mode, "refused", extra) == 2 && log_contains(message) &&
                  !file_exists(OUT "_refused.pfm") && !file_exists(OUT "_refused.ppm");
    if (!refused)
        fprintf(stderr, "test_merge: '%s' with --mode %s not refused with '%s'\n", extra,
                mode, message);
    return refused;
}

#define LOAD_BAD "--load-photons " OUT "_bad.work"

/* truth: work_file.h's promise that a file of global work is used only when it is whole,
 *   undamaged and made for this render, and the modes that have none refuse the options.
 *   The 1996 file of TILE_SETTINGS is some 1.2 MB: the cuts fall in the header, in the
 *   first map's photons, in the cache's records and in the checksum.
 * tolerance: none.
 * catches: a missing length or checksum check (a truncated or damaged file read as
 *   good), trailing bytes accepted, the hash not compared (another seed's maps used),
 *   a mode without global work silently ignoring the options. */
static void test_bad_work_files_are_refused(struct check *t)
{
    CHECK(t, render_work("1996", "made", "--save-photons " OUT "_made.work") == 0);
    static const struct {
        long keep, flip;
        size_t extra;
        const char *message;
    } bad[] = {
        {-1, 0, 0, "not a file of photon's saved global work"},
        {-1, 8, 0, "version 254 of the saved work; this photon reads version 1"},
        {6, -1, 0, "not a file of photon's saved global work"},
        {10, -1, 0, "truncated: the file ends inside the header"},
        {16, -1, 0, "truncated: the file ends inside the header"},
        {1000, -1, 0, "truncated: "},
        {1170000, -1, 0, "truncated: "},
        {-1, 40, 0, "damaged: its checksum is"},
        {-1, -1, 1, "unexpected bytes after the checksum"},
        {-1, 13, 0, "saved from other scene files, mode, seed or options"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        write_changed_work(bad[i].keep, bad[i].flip, bad[i].extra);
        CHECK(t, render_refused("1996", LOAD_BAD, bad[i].message));
    }
    write_changed_work(-1, -1, 0);
    CHECK(t, render_work("1996", "loaded", LOAD_BAD) == 0);
    CHECK(t, render_refused("1996", LOAD_BAD " --seed 2", "saved from other scene files"));
    CHECK(t, render_refused("photons", LOAD_BAD, "saved from other scene files"));
    CHECK(t, render_refused("1996", "--load-photons " OUT "_none.work", "cannot open"));
    CHECK(t, render_refused("pt", LOAD_BAD, "mode pt has no global work"));
    CHECK(t, render_refused("direct", "--save-photons " OUT "_x.work", "mode direct has no"));
    CHECK(t, render_refused("2008", LOAD_BAD, "mode 2008 traces new photons in every pass"));
    CHECK(t, render_refused("1994", "--irradiance-store illumination --save-photons " OUT
                            "_x.work", "not with --irradiance-store illumination"));
    CHECK(t, render_refused("1996", LOAD_BAD " --save-photons " OUT "_x.work",
                            "give one or the other"));
    CHECK(t, !file_exists(OUT "_x.work"));
}

void test_merge(struct check *t)
{
    RUN_TEST(t, test_options_hash_covers_pixel_options);
    RUN_TEST(t, test_tile_record_round_trip);
    RUN_TEST(t, test_bad_tile_records_are_refused);
    RUN_TEST(t, test_merged_tiles_equal_whole_render);
    RUN_TEST(t, test_merge_refuses_bad_tile_sets);
    RUN_TEST(t, test_work_file_format);
    RUN_TEST(t, test_loaded_work_renders_same_bytes);
    RUN_TEST(t, test_bad_work_files_are_refused);
}
