/*
 * tests/test_convert.c -- the convert room: `photon convert` (by exposure and in false
 * colour, with its scale), the font of the scale's labels, and `photon compare --diff`'s
 * false-colour picture of the error.
 *
 * Every input is a PFM written here byte by byte (not by pfm_write), so that the values
 * are known exactly; every picture is read back as a PPM by this file's own reader, and
 * the PNG of the same picture by tests/png_check.py (Python's zlib, none of photon's
 * code) against the PPM's pixels. The colours expected are viridis' entries as
 * matplotlib publishes them (_viridis_data in lib/matplotlib/_cm_listed.py), typed here
 * from that table, not from colour_map.c; the sRGB bytes from IEC 61966-2-1's formula.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/image/font.h"
#include "check.h"
#include "files.h"
#include "tests.h"

#define NAME_BYTES 256
#define ARGS_BYTES 1024

/* _viridis_data[15 k], k = 0 .. 17: the colours at t = k / 17, as published. */
static const double published[18][3] = {
    {0.267004, 0.004874, 0.329415}, {0.281924, 0.089666, 0.412415},
    {0.280255, 0.165693, 0.476498}, {0.263663, 0.237631, 0.518762},
    {0.237441, 0.305202, 0.541921}, {0.208623, 0.367752, 0.552675},
    {0.182256, 0.426184, 0.557120}, {0.159194, 0.482237, 0.558073},
    {0.137770, 0.537492, 0.554906}, {0.121148, 0.592739, 0.544641},
    {0.128087, 0.647749, 0.523491}, {0.180653, 0.701402, 0.488189},
    {0.274149, 0.751988, 0.436601}, {0.395174, 0.797475, 0.367757},
    {0.535621, 0.835785, 0.281908}, {0.688944, 0.865448, 0.182725},
    {0.845561, 0.887322, 0.099702}, {0.993248, 0.906157, 0.143936},
};

/* The byte of a published value: the nearest of 256 levels. */
static int level(double v)
{
    return (int)floor(255.0 * v + 0.5);
}

/* Writes a little-endian colour PFM of width x height pixels, rgb[3 (y width + x) + c]
 * with row 0 at the top, by hand: "PF", the size, scale -1, rows bottom to top. */
static void write_pfm(const char *name, int width, int height, const float *rgb)
{
    FILE *f = fopen(name, "wb");
    if (f == NULL)
        return;
    fprintf(f, "PF\n%d %d\n-1.0\n", width, height);
    for (int y = height - 1; y >= 0; y--)
        for (int i = 0; i < 3 * width; i++) {
            uint32_t u;
            memcpy(&u, &rgb[3 * (size_t)y * (size_t)width + (size_t)i], 4);
            unsigned char b[4] = {(unsigned char)(u & 0xFF), (unsigned char)(u >> 8 & 0xFF),
                                  (unsigned char)(u >> 16 & 0xFF), (unsigned char)(u >> 24)};
            fwrite(b, 1, 4, f);
        }
    fclose(f);
}

/* A binary PPM as photon writes it ("P6\nW H\n255\n", then R G B bytes from the top). */
struct ppm {
    int width, height;
    unsigned char *rgb; /* malloc'd; NULL when the file was not such a PPM */
};

static struct ppm read_ppm(const char *name)
{
    struct ppm p = {0, 0, NULL};
    FILE *f = fopen(name, "rb");
    if (f == NULL)
        return p;
    if (fscanf(f, "P6\n%d %d\n255", &p.width, &p.height) == 2 && fgetc(f) == '\n' &&
        p.width > 0 && p.height > 0) {
        size_t n = 3 * (size_t)p.width * (size_t)p.height;
        p.rgb = malloc(n);
        if (p.rgb != NULL && fread(p.rgb, 1, n, f) != n) {
            free(p.rgb);
            p.rgb = NULL;
        }
    }
    fclose(f);
    return p;
}

static const unsigned char *pixel(const struct ppm *p, int x, int y)
{
    return p->rgb + 3 * ((size_t)y * (size_t)p->width + (size_t)x);
}

/* Whether pixel (x, y) is the published colour k, to the byte. */
static int is_control_point(const struct ppm *p, int x, int y, int k)
{
    const unsigned char *q = pixel(p, x, y);
    return q[0] == level(published[k][0]) && q[1] == level(published[k][1]) &&
           q[2] == level(published[k][2]);
}

/* Whether text is written white on black at (x, y) at scale s: every glyph pixel
 * (font.h) inked white, every other pixel of its cells, and the column after each, black. */
static int label_at(const struct ppm *p, int x, int y, int s, const char *text)
{
    int n = (int)strlen(text);
    for (int gy = 0; gy < FONT_HEIGHT * s; gy++)
        for (int gx = 0; gx < n * FONT_ADVANCE * s; gx++) {
            int px = x + gx, py = y + gy;
            if (px < 0 || py < 0 || px >= p->width || py >= p->height)
                return 0;
            int c = gx / s / FONT_ADVANCE, cx = gx / s % FONT_ADVANCE, cy = gy / s;
            int ink = cx < FONT_WIDTH && font_pixel(text[c], cx, cy);
            const unsigned char *q = pixel(p, px, py);
            if (q[0] != (ink ? 255 : 0) || q[1] != q[0] || q[2] != q[0])
                return 0;
        }
    return 1;
}

/* Runs photon SUBCOMMAND ARGS with output in log; its exit status. */
static int run(const char *subcommand, const char *args, const char *log)
{
    return photon_logged(subcommand, args, log);
}

/* The files a test uses, named for it under /tmp. */
struct files {
    char pfm[NAME_BYTES], ppm[NAME_BYTES], png[NAME_BYTES], rgb[NAME_BYTES], log[NAME_BYTES];
};

static void name_files(struct files *f, const char *what)
{
    char name[NAME_BYTES];
    snprintf(name, sizeof name, "%s.pfm", what);
    temp_name(f->pfm, sizeof f->pfm, "convert", name);
    snprintf(name, sizeof name, "%s.ppm", what);
    temp_name(f->ppm, sizeof f->ppm, "convert", name);
    snprintf(name, sizeof name, "%s.png", what);
    temp_name(f->png, sizeof f->png, "convert", name);
    snprintf(name, sizeof name, "%s.rgb", what);
    temp_name(f->rgb, sizeof f->rgb, "convert", name);
    snprintf(name, sizeof name, "%s.log", what);
    temp_name(f->log, sizeof f->log, "convert", name);
}

static void remove_files(const struct files *f)
{
    remove(f->pfm);
    remove(f->ppm);
    remove(f->png);
    remove(f->rgb);
    remove(f->log);
}

/* Converts f->pfm with options to f->ppm and to f->png, and reads the PPM; the PNG must
 * hold the PPM's pixels by an outside reader (python3 tests/png_check.py), when there is
 * one. */
static struct ppm convert_both(struct check *t, const struct files *f, const char *options)
{
    char args[ARGS_BYTES];
    snprintf(args, sizeof args, "%s -o %s %s", f->pfm, f->ppm, options);
    CHECK(t, run("convert", args, f->log) == 0);
    snprintf(args, sizeof args, "%s -o %s %s", f->pfm, f->png, options);
    CHECK(t, run("convert", args, f->log) == 0);
    struct ppm p = read_ppm(f->ppm);
    if (p.rgb != NULL && run_command("command -v python3 > /dev/null 2>&1") == 0) {
        write_bytes_file(f->rgb, p.rgb, 3 * (size_t)p.width * (size_t)p.height);
        snprintf(args, sizeof args, "python3 tests/png_check.py %s %s > %s 2>&1", f->png,
                 f->rgb, f->log);
        CHECK(t, run_command(args) == 0);
    } else if (p.rgb != NULL) {
        printf("  convert: the PNG's outside reader skipped: python3 not found\n");
    }
    return p;
}

/* truth: viridis as published: a pixel of value k with --min 0 --max 17 is entry 15 k of
 *   matplotlib's 256, to the byte (the map's 18 control points, t = k / 17); a value
 *   below --min is the first colour, above --max the last; a pixel's number is its
 *   largest channel; halfway between two control points, the mean of their bytes (+-1).
 *   The PNG holds the PPM's pixels, by Python's zlib.
 * catches: a wrong entry or a typo in the table, points at t = k / 16 or k / 18, the map
 *   reversed, no clamping at the ends, the mean or luminance of the channels for the
 *   largest, nearest-point lookup instead of interpolation, the bar drawn over the image. */
static void test_convert_control_points(struct check *t)
{
    struct files f;
    name_files(&f, "points");
    float values[3 * 22];
    for (int k = 0; k < 18; k++)
        values[3 * k] = values[3 * k + 1] = values[3 * k + 2] = (float)k;
    float rest[4][3] = {{-1, -1, -1}, {100, 100, 100}, {3, 9, 1}, {0.5f, 0.5f, 0.5f}};
    memcpy(values + 3 * 18, rest, sizeof rest);
    write_pfm(f.pfm, 22, 1, values);
    struct ppm p = convert_both(t, &f, "--false-colour --min 0 --max 17");
    REQUIRE(t, p.rgb != NULL && p.width > 22 && p.height >= 1);
    for (int k = 0; k < 18; k++)
        CHECK(t, is_control_point(&p, k, 0, k));
    CHECK(t, is_control_point(&p, 18, 0, 0));  /* -1: below --min */
    CHECK(t, is_control_point(&p, 19, 0, 17)); /* 100: above --max */
    CHECK(t, is_control_point(&p, 20, 0, 9));  /* (3, 9, 1): its largest channel, 9 */
    for (int c = 0; c < 3; c++) {              /* 0.5: halfway from point 0 to point 1 */
        double mean = 0.5 * (255.0 * published[0][c] + 255.0 * published[1][c]);
        CHECK(t, fabs(pixel(&p, 21, 0)[c] - mean) <= 1.0);
    }
    free(p.rgb);
    remove_files(&f);
}

/* The sRGB byte of linear value v (IEC 61966-2-1): 12.92 v up to 0.0031308, else
 * 1.055 v^(1/2.4) - 0.055; clamped to [0, 1], rounded to the nearest of 256 levels. */
static int srgb(double v)
{
    v = v < 0 ? 0 : v > 1 ? 1 : v;
    return level(v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1 / 2.4) - 0.055);
}

/* truth: by exposure, the picture is the image's size and each byte the sRGB formula of
 *   value x E (values exact in binary, so the float the PFM holds is the value), R G B in
 *   order; without --exposure, E = 1.
 * catches: exposure ignored or applied twice, gamma 2.2 for sRGB's curve, channels
 *   swapped, a bar added to an exposure picture, rows upside down. */
static void test_convert_exposure(struct check *t)
{
    struct files f;
    name_files(&f, "exposure");
    const float values[2][3][3] = {{{0, 0.0009765625f, 0.125f}, {0.25f, 0.5f, 0.75f},
                                    {1, 2, 0.001953125f}},
                                   {{0.375f, 0.0625f, 0.03125f}, {0.4375f, 0, 0.5625f},
                                    {0.015625f, 0.3125f, 0.6875f}}};
    write_pfm(f.pfm, 3, 2, &values[0][0][0]);
    const double exposures[2] = {2.0, 1.0};
    for (int e = 0; e < 2; e++) {
        struct ppm p = convert_both(t, &f, e == 0 ? "--exposure 2" : "");
        REQUIRE(t, p.rgb != NULL);
        CHECK(t, p.width == 3 && p.height == 2);
        for (int y = 0; y < 2 && p.width == 3 && p.height == 2; y++)
            for (int x = 0; x < 3; x++)
                for (int c = 0; c < 3; c++)
                    CHECK(t, pixel(&p, x, y)[c] == srgb(values[y][x][c] * exposures[e]));
        free(p.rgb);
    }
    remove_files(&f);
}

/* A w x h image of zeros but for the values given per pixel in row order (n of them). */
static void write_gray(const char *name, int w, int h, const float *v, size_t n, int red)
{
    float *rgb = calloc(3 * (size_t)w * (size_t)h, sizeof *rgb);
    if (rgb == NULL)
        return;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            rgb[3 * i + (size_t)c] = red && c > 0 ? 0 : v[i];
    write_pfm(name, w, h, rgb);
    free(rgb);
}

/* truth: README's layout (false_colour.c): s = height / 256 (1 to 4); the picture is
 *   s (27 + 6 n) wider than the image, n the longest label's characters, and at least
 *   60 s tall; the bar from row 6 s to 6 s above the bottom (an odd number of rows), its
 *   top max's colour and its bottom min's; the labels white at column width + 24 s, each
 *   centred on its row: --max at the bar's top, the middle value at its middle row,
 *   --min at its bottom; glyphs as font.h draws them, at s x s pixels each.
 * catches: labels missing, swapped (min at the top), misplaced or of the wrong scale,
 *   the middle value wrong (not the mean of the ends), a size other than documented, a
 *   bar upside down. */
static void test_convert_labels(struct check *t)
{
    struct files f;
    name_files(&f, "labels");
    write_gray(f.pfm, 64, 64, NULL, 0, 0);
    struct ppm p = convert_both(t, &f, "--false-colour --min 0 --max 2.5");
    /* s = 1; labels "2.5", "1.25", "0": n = 4; 64 rows, so the bar is rows 6 .. 56 */
    REQUIRE(t, p.rgb != NULL);
    CHECK(t, p.width == 64 + 27 + 6 * 4 && p.height == 64);
    CHECK(t, label_at(&p, 64 + 24, 6 - 3, 1, "2.5"));
    CHECK(t, label_at(&p, 64 + 24, 31 - 3, 1, "1.25"));
    CHECK(t, label_at(&p, 64 + 24, 56 - 3, 1, "0"));
    CHECK(t, is_control_point(&p, 64 + 6, 6, 17) && is_control_point(&p, 64 + 17, 56, 0));
    CHECK(t, is_control_point(&p, 0, 0, 0)); /* the image: zeros, min's colour */
    free(p.rgb);
    /* a 520-row image: s = 2 */
    write_gray(f.pfm, 8, 520, NULL, 0, 0);
    p = convert_both(t, &f, "--false-colour --min=-1 --max=1");
    /* s = 2; labels "1", "0", "-1": n = 2; bar rows 12 .. 507 (496 rows: 12 .. 506) */
    REQUIRE(t, p.rgb != NULL);
    CHECK(t, p.width == 8 + 2 * (27 + 6 * 2) && p.height == 520);
    CHECK(t, label_at(&p, 8 + 48, 12 - 6, 2, "1"));
    CHECK(t, label_at(&p, 8 + 48, 259 - 6, 2, "0"));
    CHECK(t, label_at(&p, 8 + 48, 506 - 6, 2, "-1"));
    for (int c = 0; c < 3; c++) { /* 0: the middle of -1 .. 1, between points 8 and 9 */
        double mean = 0.5 * (255.0 * published[8][c] + 255.0 * published[9][c]);
        CHECK(t, fabs(pixel(&p, 3, 3)[c] - mean) <= 1.0);
    }
    free(p.rgb);
    /* a short image: 10 rows, the picture 60 tall, black under the image */
    write_gray(f.pfm, 5, 10, NULL, 0, 0);
    p = convert_both(t, &f, "--false-colour --min 0 --max 1");
    REQUIRE(t, p.rgb != NULL);
    CHECK(t, p.height == 60 && p.width == 5 + 27 + 6 * 3);
    CHECK(t, pixel(&p, 2, 30)[0] == 0 && pixel(&p, 2, 30)[1] == 0);
    free(p.rgb);
    remove_files(&f);
}

/* truth: the default range (false_colour.c): 0 to the 99th percentile by nearest rank,
 *   the ceil(0.99 n)-th smallest, rounded to two digits and labelled " p99": of the 100
 *   values 0.00, 0.01, ..., 0.99 that is 0.98; 0.98 is the top colour and 0.49 halfway.
 *   An image of 99 zeros and one 0.5 has a p99 of 0, so its top is its largest value,
 *   0.5, with no "p99". --log: from --max / 1000; sqrt(1e-3 x 1) is the middle. The
 *   number is the largest channel, so a red-only image is mapped as its red.
 * catches: the 99th percentile off by one rank, the largest value for the default
 *   top, no fallback for a mostly black image (a range 0 to 0), "p99" claimed for a
 *   top that is no percentile, --log's bottom or middle wrong. */
static void test_convert_default_range(struct check *t)
{
    struct files f;
    name_files(&f, "range");
    float v[100];
    for (int i = 0; i < 100; i++)
        v[i] = (float)i / 100.0f;
    write_gray(f.pfm, 10, 10, v, 100, 1);
    struct ppm p = convert_both(t, &f, "--false-colour");
    REQUIRE(t, p.rgb != NULL);
    CHECK(t, p.height == 60 && p.width == 10 + 27 + 6 * 8); /* "0.98 p99" */
    CHECK(t, label_at(&p, 10 + 24, 6 - 3, 1, "0.98 p99"));
    CHECK(t, label_at(&p, 10 + 24, 29 - 3, 1, "0.49"));
    CHECK(t, label_at(&p, 10 + 24, 52 - 3, 1, "0"));
    CHECK(t, is_control_point(&p, 8, 9, 17) && is_control_point(&p, 9, 9, 17)); /* .98 .99 */
    CHECK(t, is_control_point(&p, 0, 0, 0));
    for (int c = 0; c < 3; c++) { /* 0.49: halfway, between points 8 and 9 */
        double mean = 0.5 * (255.0 * published[8][c] + 255.0 * published[9][c]);
        CHECK(t, fabs(pixel(&p, 9, 4)[c] - mean) <= 1.0);
    }
    free(p.rgb);
    float one = 0.5f;
    write_gray(f.pfm, 10, 10, &one, 1, 0);
    p = convert_both(t, &f, "--false-colour");
    REQUIRE(t, p.rgb != NULL);
    CHECK(t, label_at(&p, 10 + 24, 6 - 3, 1, "0.5") && !label_at(&p, 10 + 24, 6 - 3, 1,
                                                                  "0.5 p99"));
    CHECK(t, is_control_point(&p, 0, 0, 17) && is_control_point(&p, 1, 0, 0));
    free(p.rgb);
    float logs[3] = {1.0f, (float)sqrt(1e-3), 1e-6f};
    write_gray(f.pfm, 3, 1, logs, 3, 0);
    p = convert_both(t, &f, "--false-colour --log --max 1");
    REQUIRE(t, p.rgb != NULL);
    CHECK(t, label_at(&p, 3 + 24, 6 - 3, 1, "1") && label_at(&p, 3 + 24, 29 - 3, 1, "0.0316") &&
             label_at(&p, 3 + 24, 52 - 3, 1, "0.001"));
    CHECK(t, is_control_point(&p, 0, 0, 17) && is_control_point(&p, 2, 0, 0));
    for (int c = 0; c < 3; c++) {
        double mean = 0.5 * (255.0 * published[8][c] + 255.0 * published[9][c]);
        CHECK(t, fabs(pixel(&p, 1, 0)[c] - mean) <= 1.0);
    }
    free(p.rgb);
    remove_files(&f);
}

/* truth: the glyphs of the labels: every character a label can hold has one, each digit
 *   differs from every other, and each is inked (but the space).
 * catches: a digit left blank or drawn as another (a '6' copied as an '8'), a character
 *   the labels write without a glyph (shown as a box). */
static void test_font_glyphs(struct check *t)
{
    const char *all = FONT_CHARACTERS;
    for (const char *c = all; *c != '\0'; c++) {
        int ink = 0;
        for (int y = 0; y < FONT_HEIGHT; y++)
            for (int x = 0; x < FONT_WIDTH; x++)
                ink += font_pixel(*c, x, y);
        CHECK(t, font_has(*c) && (ink > 0) == (*c != ' ') && ink < FONT_WIDTH * FONT_HEIGHT);
        for (const char *d = c + 1; *d != '\0'; d++) {
            int differ = 0;
            for (int y = 0; y < FONT_HEIGHT; y++)
                for (int x = 0; x < FONT_WIDTH; x++)
                    differ += font_pixel(*c, x, y) != font_pixel(*d, x, y);
            CHECK(t, differ > 0);
        }
    }
    CHECK(t, !font_has('x') && font_pixel('x', 0, 0));
    CHECK(t, font_text_width("0.5", 1) == 17 && font_text_width("", 3) == 0);
}

/* truth: compare --diff's relative error |a - b| / max(b, floor), floor 1% of b's mean:
 *   of 200 pixels of b = 0.5 but one black, 10 with a 10% error, 10 with 17% and the black
 *   one with a = 10% of the floor, the 99th percentile is 17%, so a 10% error is at t =
 *   10 / 17, control point 10, and so is the black pixel; the top label reads "17% p99".
 *   --diff-absolute: |a - b|, top 0.085 (17% of 0.5), the 10% pixels at point 10 again,
 *   the black pixel's tiny error near point 0. The metrics line is printed as before.
 * catches: an absolute error for the relative one, a floor of another size (or none: the
 *   black pixel would be +Inf, the top colour), the relative error of the wrong side
 *   (|a - b| / a), the mean of the channels for the worst, labels not in percent. */
static void test_compare_diff(struct check *t)
{
    struct files f, r;
    name_files(&f, "test");
    name_files(&r, "reference");
    float a[3 * 200], b[3 * 200];
    for (int i = 0; i < 200; i++)
        for (int c = 0; c < 3; c++)
            a[3 * i + c] = b[3 * i + c] = 0.5f;
    double mean = 0.5 * 199.0 / 200.0, floor_value = 0.01 * mean;
    for (int i = 0; i < 10; i++)
        for (int c = 0; c < 3; c++) {
            a[3 * (20 + i) + c] = 0.55f;  /* 10% */
            a[3 * (40 + i) + c] = 0.585f; /* 17% */
        }
    a[3 * 0 + 1] = 0.7f * 0.5f + 0.5f; /* pixel 0: 70% in green alone: shows as 70% */
    for (int c = 0; c < 3; c++) {
        b[3 * 199 + c] = 0;
        a[3 * 199 + c] = c == 2 ? (float)(0.1 * floor_value) : 0;
    }
    write_pfm(f.pfm, 20, 10, a);
    write_pfm(r.pfm, 20, 10, b);
    char args[ARGS_BYTES];
    snprintf(args, sizeof args, "%s %s --diff %s", f.pfm, r.pfm, f.ppm);
    CHECK(t, run("compare", args, f.log) == 0 && file_contains(f.log, "rmse=") &&
             file_contains(f.log, " maxerr="));
    struct ppm p = read_ppm(f.ppm);
    REQUIRE(t, p.rgb != NULL);
    CHECK(t, p.width == 20 + 27 + 6 * 7 && p.height == 60); /* "17% p99" */
    CHECK(t, label_at(&p, 20 + 24, 6 - 3, 1, "17% p99") &&
             label_at(&p, 20 + 24, 29 - 3, 1, "8.5%") &&
             label_at(&p, 20 + 24, 52 - 3, 1, "0%"));
    CHECK(t, is_control_point(&p, 0, 1, 10) && is_control_point(&p, 9, 1, 10)); /* 10% */
    CHECK(t, is_control_point(&p, 19, 9, 10));  /* the black pixel: 10% of the floor */
    CHECK(t, is_control_point(&p, 0, 2, 17) && is_control_point(&p, 1, 0, 0));
    CHECK(t, is_control_point(&p, 0, 0, 17));   /* 70% in green: above the top */
    free(p.rgb);
    snprintf(args, sizeof args, "%s %s --diff %s --diff-absolute", f.pfm, r.pfm, f.ppm);
    CHECK(t, run("compare", args, f.log) == 0);
    p = read_ppm(f.ppm);
    REQUIRE(t, p.rgb != NULL);
    CHECK(t, label_at(&p, 20 + 24, 6 - 3, 1, "0.085 p99"));
    CHECK(t, is_control_point(&p, 0, 1, 10));
    CHECK(t, !is_control_point(&p, 19, 9, 10) && pixel(&p, 19, 9)[1] < 30);
    free(p.rgb);
    remove_files(&f);
    remove_files(&r);
}

/* truth: the command-line contract (README: Errors): --help exits 0 with the usage; bad
 *   options and bad input exit 2 with a message naming the problem (a near miss named),
 *   leaving no output and no temporary; an output that is the input is refused and the
 *   input left as it was; photon convrt suggests photon convert.
 * catches: a missing check, a wrong status, an output written before the refusal, an
 *   input overwritten. */
static void test_convert_refusals(struct check *t)
{
    struct files f;
    name_files(&f, "refuse");
    float one[3] = {1, 1, 1};
    write_pfm(f.pfm, 1, 1, one);
    CHECK(t, run("convert", "--help", f.log) == 0 &&
             file_contains(f.log, "usage: photon convert"));
    static const struct {
        const char *options, *said;
    } cases[] = {
        {"--false-colur", "did you mean '--false-colour'"},
        {"--min 0", "--min needs --false-colour"},
        {"--false-colour --min 2 --max 1", "must be below --max"},
        {"--false-colour --log --min 0", "--log needs --min and --max above 0"},
        {"--false-colour --max x", "--max: expected a number"},
        {"--exposure -1", "--exposure: expected"},
        {"--exposure 2 --false-colour", "--exposure"},
        {"--log=1 --false-colour", "--log takes no value"},
    };
    char args[ARGS_BYTES];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        snprintf(args, sizeof args, "%s -o %s %s", f.pfm, f.png, cases[i].options);
        CHECK(t, run("convert", args, f.log) == 2 && file_contains(f.log, cases[i].said) &&
                 !file_exists(f.png) && no_temporaries(f.png));
    }
    snprintf(args, sizeof args, "%s -o %s.jpg", f.pfm, f.pfm);
    CHECK(t, run("convert", args, f.log) == 2 && file_contains(f.log, "ending in .png"));
    snprintf(args, sizeof args, "%s", f.pfm);
    CHECK(t, run("convert", args, f.log) == 2 && file_contains(f.log, "no output"));
    /* the input as the output: IN.ppm is refused before anything is written */
    write_pfm(f.ppm, 1, 1, one);
    write_pfm(f.rgb, 1, 1, one); /* its copy */
    snprintf(args, sizeof args, "%s -o %s", f.ppm, f.ppm);
    CHECK(t, run("convert", args, f.log) == 2 && file_contains(f.log, "input") &&
             files_equal(f.ppm, f.rgb) && no_temporaries(f.ppm));
    write_text_file(f.rgb, "not a PFM\n");
    snprintf(args, sizeof args, "%s -o %s", f.rgb, f.png);
    CHECK(t, run("convert", args, f.log) == 2 && file_contains(f.log, f.rgb) &&
             !file_exists(f.png));
    CHECK(t, run("", "convrt x -o y.png", f.log) == 2 &&
             file_contains(f.log, "did you mean 'photon convert'"));
    remove_files(&f);
}

void test_convert(struct check *t)
{
    RUN_TEST(t, test_convert_control_points);
    RUN_TEST(t, test_convert_exposure);
    RUN_TEST(t, test_convert_labels);
    RUN_TEST(t, test_convert_default_range);
    RUN_TEST(t, test_font_glyphs);
    RUN_TEST(t, test_compare_diff);
    RUN_TEST(t, test_convert_refusals);
}
