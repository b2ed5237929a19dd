/*
 * tests/test_image.c -- the image room: PFM and PPM files byte for byte, PFM input that
 * must be refused, and the compare metrics on images small enough to work by hand.
 *
 * Files go to /tmp under names unique to the run (temp_name, files.c) and are removed by
 * the test that made them. The `photon compare` command line itself is tested on the built binary
 * in test_cli.c.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "../src/base/rng.h"
#include "../src/image/compare.h"
#include "../src/image/image.h"
#include "check.h"
#include "files.h"
#include "tests.h"

#define NAME_MAX_BYTES 256
#define FILE_MAX_BYTES 4096 /* larger than any file these tests write by hand */

/* Reads up to FILE_MAX_BYTES of a file into bytes; returns the count, 0 if unreadable. */
static size_t read_file(const char *name, unsigned char *bytes)
{
    FILE *f = fopen(name, "rb");
    if (f == NULL)
        return 0;
    size_t n = fread(bytes, 1, FILE_MAX_BYTES, f);
    fclose(f);
    return n;
}

/* True when the writer left no temporary behind (files.h). */
static int no_temporary(const char *name)
{
    return no_temporaries(name);
}

/* A value in [1e-45, 1e38) spread evenly over the decades (floats' subnormals to near
 * FLT_MAX), with a random sign; every seventh value is exactly 0. */
static double random_magnitude_value(struct rng *r, size_t i)
{
    if (i % 7 == 0)
        return 0.0;
    double value = pow(10.0, -45.0 + 83.0 * rng_uniform(r));
    return rng_uniform(r) < 0.5 ? -value : value;
}

/* v rounded to the nearest float, by C's own conversion. volatile: gcc 12.2 at -O2 drops
 * the (float) when its SLP vectorizer pairs the x and y of a struct vec3 built from
 * (float) values (seen in development; -fno-tree-slp-vectorize also avoids it). */
static double float_rounded(double v)
{
    volatile float f = (float)v;
    return f;
}

static void check_round_trip(struct check *t, int width, int height, uint64_t index)
{
    char name[NAME_MAX_BYTES];
    temp_name(name, sizeof name, "image", "round_trip.pfm");
    struct image *img = image_create(width, height);
    struct image *expected = image_create(width, height);
    struct rng r = rng_stream(1, STREAM_TEST, index, 0);
    for (size_t i = 0; i < (size_t)width * (size_t)height; i++) {
        double v[3];
        for (int c = 0; c < 3; c++)
            v[c] = random_magnitude_value(&r, 3 * i + (size_t)c);
        img->pixels[i] = vec3(v[0], v[1], v[2]);
        expected->pixels[i] = vec3(float_rounded(v[0]), float_rounded(v[1]),
                                   float_rounded(v[2]));
    }
    if (width * height >= 3) { /* boundaries of the float range, and one past it */
        img->pixels[0] = vec3(1e30, FLT_MAX, ldexp(1.0, -149));
        expected->pixels[0] = vec3(float_rounded(1e30), FLT_MAX, ldexp(1.0, -149));
        img->pixels[1] = vec3(-FLT_MAX, 1e-46, 0.1);
        expected->pixels[1] = vec3(-FLT_MAX, 0.0, float_rounded(0.1));
        img->pixels[2] = vec3(-0.0, -1e-46, -ldexp(1.0, -149)); /* signed zeros */
        expected->pixels[2] = vec3(-0.0, -0.0, -ldexp(1.0, -149));
    }
    struct error err;
    CHECK(t, pfm_write(name, img, &err) == 0);
    CHECK(t, no_temporary(name));
    struct image *back = pfm_read(name, &err);
    CHECK(t, back != NULL);
    if (back != NULL) {
        CHECK(t, back->width == width && back->height == height);
        for (size_t i = 0; i < (size_t)width * (size_t)height; i++)
            CHECK(t, memcmp(&back->pixels[i], &expected->pixels[i], sizeof(struct vec3)) == 0);
    }
    remove(name);
    if (width * height >= 3) { /* past the float range: refused, nothing written */
        img->pixels[1] = vec3(0.1, -1e39, 0.1);
        CHECK(t, pfm_write(name, img, &err) < 0 && err.failed_write && !file_exists(name) &&
                 no_temporary(name) && strstr(err.message, "float range") != NULL);
    }
    image_free(back);
    image_free(expected);
    image_free(img);
}

/* truth: round trip; pfm_read(pfm_write(x)) is x rounded to the nearest float, which C's
 *   own (float) conversion computes apart from the file code; an image with a value
 *   beyond the float range is refused, a failed write, and nothing is written (image.h).
 * tolerance: none, compared bit for bit (memcmp, so -0.0 keeps its sign): a float is a
 *   double exactly and the file holds its 32 bits.
 * catches: a lost or swapped channel, a byte-order slip only large exponents or sign bits
 *   show, truncation for rounding, subnormals flushed to zero, -0 losing its sign, Inf
 *   or a clamped FLT_MAX written for 1e39, odd sizes (7x5, 1x1, 1x9) indexing past a row, a NAME.tmp left. */
static void test_pfm_round_trip(struct check *t)
{
    check_round_trip(t, 7, 5, 0);
    check_round_trip(t, 1, 1, 1);
    check_round_trip(t, 1, 9, 2);
}

/* truth: the format, written out by hand: the header text, then each float's IEEE bits
 *   (1.0f = 0x3F800000, 0.1f = 0x3DCCCCCD rounded up from ...CCCC.CC) least significant
 *   byte first, the BOTTOM row (y = 1) first.
 * tolerance: none; bytes.
 * catches: rows not flipped, big-endian output, a wrong scale or header layout, 0.1
 *   truncated to 0x3DCCCCCC, channels out of order; and on reading the same bytes back,
 *   a reader that flips differently from the writer. */
static void test_pfm_byte_layout(struct check *t)
{
    static const unsigned char expected[] = {
        'P', 'F', '\n', '2', ' ', '2', '\n', '-', '1', '.', '0', '\n',
        /* row y = 1 (bottom): (3, 4, 8), (0.1, 1.5, -2) */
        0x00, 0x00, 0x40, 0x40, 0x00, 0x00, 0x80, 0x40, 0x00, 0x00, 0x00, 0x41,
        0xCD, 0xCC, 0xCC, 0x3D, 0x00, 0x00, 0xC0, 0x3F, 0x00, 0x00, 0x00, 0xC0,
        /* row y = 0 (top): (1, 2, 0.5), (-1, 0, 0.25) */
        0x00, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x00, 0x40, 0x00, 0x00, 0x00, 0x3F,
        0x00, 0x00, 0x80, 0xBF, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x80, 0x3E,
    };
    char name[NAME_MAX_BYTES];
    temp_name(name, sizeof name, "image", "layout.pfm");
    struct image *img = image_create(2, 2);
    image_set(img, 0, 0, vec3(1, 2, 0.5));
    image_set(img, 1, 0, vec3(-1, 0, 0.25));
    image_set(img, 0, 1, vec3(3, 4, 8));
    image_set(img, 1, 1, vec3(0.1, 1.5, -2));
    struct error err;
    CHECK(t, pfm_write(name, img, &err) == 0);
    unsigned char bytes[FILE_MAX_BYTES];
    size_t n = read_file(name, bytes);
    CHECK(t, n == sizeof expected && memcmp(bytes, expected, sizeof expected) == 0);
    struct image *back = pfm_read(name, &err);
    CHECK(t, back != NULL);
    if (back != NULL) {
        CHECK(t, back->width == 2 && back->height == 2);
        CHECK(t, image_get(back, 0, 0).z == 0.5 && image_get(back, 1, 0).x == -1);
        CHECK(t, image_get(back, 0, 1).y == 4 && image_get(back, 1, 1).x == float_rounded(0.1));
    }
    remove(name);
    image_free(back);
    image_free(img);
}

/* Writes bytes to a temporary file, reads it as a PFM, removes the file. */
static struct image *read_bytes_as_pfm(const unsigned char *bytes, size_t n,
                                       struct error *err)
{
    char name[NAME_MAX_BYTES];
    temp_name(name, sizeof name, "image", "by_hand.pfm");
    write_bytes_file(name, bytes, n);
    struct image *img = pfm_read(name, err);
    remove(name);
    return img;
}

/* truth: files built by hand in the other byte order and header spellings the format
 *   allows: big-endian data (scale > 0); a '#' comment line, tabs, CR LF and a scale of
 *   magnitude 2 (every value doubled, as pbrt reads it); each time the first data byte is
 *   itself whitespace (0x20, 0x0A), which the reader must not skip.
 * tolerance: none; each value is exact in binary (2^-63, 1 + 10 * 2^-23, 0.1f).
 * catches: big-endian ignored, |scale| ignored, comments refused, more than one byte
 *   consumed after the scale, rows or columns mixed up in a 1x2 or 2x1 image. */
static void test_pfm_read_by_hand(struct check *t)
{
    static const unsigned char big_endian[] = {
        'P', 'F', '\n', '2', ' ', '1', '\n', '1', '.', '0', '\n',
        0x20, 0x00, 0x00, 0x00, 0x3F, 0x80, 0x00, 0x00, 0xC0, 0x00, 0x00, 0x00,
        0x3D, 0xCC, 0xCC, 0xCD, 0x00, 0x00, 0x00, 0x00, 0x41, 0x00, 0x00, 0x00,
    };
    static const unsigned char commented[] = {
        'P', 'F', '\n', '#', ' ', 'c', 'r', 'o', 'p', ' ', '1', ' ', '2', '\n',
        '1', '\t', '2', '\r', '\n', '-', '2', ' ',
        0x0A, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x80, 0xBF, /* y = 1 */
        0x00, 0x00, 0x00, 0x3F, 0x00, 0x00, 0x80, 0x40, 0x00, 0x00, 0x00, 0x41, /* y = 0 */
    };
    struct error err;
    struct image *img = read_bytes_as_pfm(big_endian, sizeof big_endian, &err);
    CHECK(t, img != NULL && img->width == 2 && img->height == 1);
    if (img != NULL) {
        struct vec3 p0 = image_get(img, 0, 0), p1 = image_get(img, 1, 0);
        CHECK(t, p0.x == ldexp(1.0, -63) && p0.y == 1 && p0.z == -2);
        CHECK(t, p1.x == float_rounded(0.1) && p1.y == 0 && p1.z == 8);
    }
    image_free(img);
    img = read_bytes_as_pfm(commented, sizeof commented, &err);
    CHECK(t, img != NULL && img->width == 1 && img->height == 2);
    if (img != NULL) {
        struct vec3 top = image_get(img, 0, 0), bottom = image_get(img, 0, 1);
        CHECK(t, bottom.x == 2 * (1 + 10 * ldexp(1.0, -23)) && bottom.y == 0);
        CHECK(t, bottom.z == -2);
        CHECK(t, top.x == 1 && top.y == 8 && top.z == 16);
    }
    image_free(img);
}

/* One malformed file: a header, then n_floats little-endian floats, the first with the
 * given bits and the rest 1.0f. */
struct bad_pfm {
    const char *header;
    int n_floats;
    uint32_t first_bits;
    const char *keyword; /* a word the error message must contain: refused for this reason */
};

static size_t build_bad_pfm(const struct bad_pfm *c, unsigned char *bytes)
{
    size_t n = strlen(c->header);
    memcpy(bytes, c->header, n);
    for (int i = 0; i < c->n_floats; i++) {
        uint32_t bits = i == 0 ? c->first_bits : 0x3F800000u;
        for (int k = 0; k < 4; k++)
            bytes[n++] = (unsigned char)(bits >> (8 * k));
    }
    return n;
}

/* Checks that name is refused with an error that names the file and contains keyword. */
static void check_refused(struct check *t, const char *name, const char *keyword)
{
    struct error err;
    err.message[0] = '\0';
    struct image *img = pfm_read(name, &err);
    int ok = img == NULL && strcmp(err.file, name) == 0 && strstr(err.message, keyword);
    CHECK(t, ok);
    if (!ok)
        fprintf(stderr, "  expected '%s' in the error, got: %s\n", keyword, err.message);
    image_free(img);
}

/* truth: the format's rules and photon's limits (image.h, pfm.c); each file breaks one.
 * tolerance: none; each must be refused, with a message naming the file and the reason.
 * catches: a crash or an allocation on a huge or negative size, strtol's silent
 *   acceptance of "2x" or of overflow, scale 0 or NaN taken as a byte order, truncated or
 *   overlong data read as zeros, NaN or Inf (also by an overflowing scale) let into a
 *   reference, greyscale read as colour, a directory read as an empty image. */
static void test_pfm_refuses_malformed(struct check *t)
{
    static const struct bad_pfm cases[] = {
        {"", 0, 0, "empty"},
        {"P6\n1 1\n255\n", 1, 0, "\"PF\""},
        {"PFX 1 1 -1.0\n", 3, 0x3F800000u, "\"PF\""},
        {"Pf\n1 1\n-1.0\n", 1, 0x3F800000u, "greyscale"},
        {"PF\n2", 0, 0, "truncated header"},
        {"PF\n1 1\n-1.0", 0, 0, "truncated header"},
        {"PF\n40000 1\n-1.0\n", 3, 0x3F800000u, "outside 1..32768"},
        {"PF\n0 4\n-1.0\n", 0, 0, "outside"},
        {"PF\n3 -4\n-1.0\n", 0, 0, "outside"},
        {"PF\n99999999999999999999 1\n-1.0\n", 3, 0x3F800000u, "outside"},
        {"PF\nabc 4\n-1.0\n", 12, 0x3F800000u, "not a whole number"},
        {"PF\n2x 1\n-1.0\n", 6, 0x3F800000u, "not a whole number"},
        {"PF\n000000000000000000000000000000000000000000000000000000000000000001 1\n"
         "-1.0\n", 3, 0x3F800000u, "too long"},
        {"PF\n1 1\n0\n", 3, 0x3F800000u, "scale"},
        {"PF\n1 1\nnan\n", 3, 0x3F800000u, "scale"},
        {"PF\n1 1\n-1.0x\n", 3, 0x3F800000u, "scale"},
        {"PF\n2 2\n-1.0\n", 11, 0x3F800000u, "pixel data is 44 bytes"},
        {"PF\n2 2\n-1.0\n", 13, 0x3F800000u, "pixel data is 52 bytes"},
        {"PF\n1 1\n-1.0\n", 3, 0x7FC00000u, "NaN"},
        {"PF\n1 1\n-1.0\n", 3, 0xFF800000u, "infinite"},
        {"PF\n1 1\n-1e300\n", 3, 0x7149F2CAu, "infinite"}, /* 1e30 * 1e300 overflows */
    };
    char name[NAME_MAX_BYTES];
    temp_name(name, sizeof name, "image", "bad.pfm");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        unsigned char bytes[FILE_MAX_BYTES];
        write_bytes_file(name, bytes, build_bad_pfm(&cases[i], bytes));
        check_refused(t, name, cases[i].keyword);
    }
    remove(name);
    check_refused(t, name, "cannot open"); /* now missing */
    check_refused(t, "/tmp", "");          /* a directory: refused, for whatever reason */
}

/* truth: the sRGB encoding (IEC 61966-2-1) worked out by hand to the nearest byte:
 *   0.5 -> 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354 -> 187.52 -> 188;
 *   0.002 (linear segment) -> 12.92 * 0.002 * 255 = 6.59 -> 7 (the power law gives 6);
 *   0.125 -> 99.09 -> 99; 0.25 -> 136.96 -> 137; 0.75 -> 224.61 -> 225;
 *   0.0031308 -> 10.31 -> 10; with exposure 4: 0.008 -> 21.96 -> 22,
 *   0.0125232 -> 29.34 -> 29; anything >= 1 -> 255, <= 0 -> 0.
 * tolerance: none; the nearest values sit >= 0.01 from a rounding boundary.
 * catches: gamma 2.2 or 1/2.4 for 2.4, no linear segment, truncation for rounding,
 *   exposure ignored, no clamp (wrap-around of 2.0 or -1.0), rows written bottom up. */
static void test_ppm_bytes(struct check *t)
{
    static const unsigned char expected_1[] = {
        'P', '6', '\n', '2', ' ', '2', '\n', '2', '5', '5', '\n',
        0, 255, 188, 7, 255, 0, 99, 137, 255, 10, 225, 0,
    };
    static const unsigned char expected_4[] = {
        'P', '6', '\n', '2', ' ', '2', '\n', '2', '5', '5', '\n',
        0, 255, 255, 22, 255, 0, 188, 255, 255, 29, 255, 0,
    };
    char name[NAME_MAX_BYTES];
    temp_name(name, sizeof name, "image", "bytes.ppm");
    struct image *img = image_create(2, 2);
    image_set(img, 0, 0, vec3(0, 1, 0.5));
    image_set(img, 1, 0, vec3(0.002, 2.0, -1.0));
    image_set(img, 0, 1, vec3(0.125, 0.25, 1e30));
    image_set(img, 1, 1, vec3(0.0031308, 0.75, 0.0));
    struct error err;
    unsigned char bytes[FILE_MAX_BYTES];
    CHECK(t, ppm_write(name, img, 1.0, &err) == 0);
    size_t n = read_file(name, bytes);
    CHECK(t, n == sizeof expected_1 && memcmp(bytes, expected_1, n) == 0);
    CHECK(t, ppm_write(name, img, 4.0, &err) == 0);
    n = read_file(name, bytes);
    CHECK(t, n == sizeof expected_4 && memcmp(bytes, expected_4, n) == 0);
    CHECK(t, no_temporary(name));
    remove(name);
    image_free(img);
}

/* truth: a round trip. The PPM written beside a PFM equals, byte for byte, the PPM made
 *   from that PFM read back (what photon merge does). The image holds, for every level k,
 *   the linear values 1e-13 above and below the boundary between levels k and k + 1
 *   (the sRGB curve inverted by hand at (k + 1/2) / 255), so the doubles sit on either
 *   side of each boundary while their floats coincide.
 * tolerance: none; bytes.
 * catches: a PPM encoded from the doubles while the PFM keeps floats (a level apart at
 *   a boundary; found when Slurm tiles were merged). */
static void test_ppm_matches_its_pfm(struct check *t)
{
    char pfm[NAME_MAX_BYTES], ppm[NAME_MAX_BYTES], again[NAME_MAX_BYTES];
    temp_name(pfm, sizeof pfm, "image", "pair.pfm");
    snprintf(ppm, sizeof ppm, "%.*s.ppm", (int)strlen(pfm) - 4, pfm);
    temp_name(again, sizeof again, "image", "again.ppm");
    struct image *img = image_create(255, 2);
    for (int k = 0; k < 255; k++) {
        double e = (k + 0.5) / 255.0;
        double c = e <= 0.04045 ? e / 12.92 : pow((e + 0.055) / 1.055, 2.4);
        image_set(img, k, 0, vec3(c + 1e-13, c + 1e-13, c + 1e-13));
        image_set(img, k, 1, vec3(c - 1e-13, c - 1e-13, c - 1e-13));
    }
    struct error err;
    CHECK(t, image_write_pair(pfm, DISPLAY_PPM, img, 1.0, &err) == 0);
    struct image *back = pfm_read(pfm, &err);
    CHECK(t, back != NULL && ppm_write(again, back, 1.0, &err) == 0);
    CHECK(t, files_equal(ppm, again));
    image_free(back);
    image_free(img);
    remove(pfm);
    remove(ppm);
    remove(again);
}

/* truth: the definitions in compare.h, worked by hand. a = {(1,0,0), (0,0,0)} against
 *   b = {(0,0,0), (0,0,2)}: differences 1 and -2 among six channels, so mse = 5/6,
 *   relmse = (1/0.01 + 4/4.01) / 6, peak = 2, psnr = 10 log10(4 / (5/6)) = 10 log10(4.8),
 *   maxerr = 2. An all-black reference has no peak: a = (1,0,0) against black has no
 *   psnr; identical images give mse 0 and psnr +Inf, black ones too.
 * tolerance: 1e-12 relative; the code sums and divides in another order than the closed
 *   forms, a few ulps apart.
 * catches: the test and reference swapped in relmse's denominator, a missing epsilon,
 *   mean over pixels instead of channels, peak from a instead of b, |d| lost in maxerr,
 *   a peak of 0 giving -Inf or a floor's -594 dB, a NaN psnr for identical images. */
static void test_compare_metrics(struct check *t)
{
    struct image *a = image_create(2, 1), *b = image_create(2, 1);
    image_set(a, 0, 0, vec3(1, 0, 0));
    image_set(b, 1, 0, vec3(0, 0, 2));
    struct image_error e = image_compare(a, b);
    CHECK_CLOSE(t, e.rmse, sqrt(5.0 / 6.0), 1e-12);
    CHECK_CLOSE(t, e.relmse, (100.0 + 4.0 / 4.01) / 6.0, 1e-12 * 17);
    CHECK_CLOSE(t, e.psnr, 10.0 * log10(4.8), 1e-12 * 7);
    CHECK(t, e.maxerr == 2);
    e = image_compare(a, a);
    CHECK(t, e.rmse == 0 && e.relmse == 0 && e.maxerr == 0);
    CHECK(t, isinf(e.psnr) && e.psnr > 0);
    image_free(b);
    b = image_create(1, 1);
    image_free(a);
    a = image_create(1, 1);
    image_set(a, 0, 0, vec3(1, 0, 0));
    e = image_compare(a, b);
    CHECK(t, !e.has_psnr);
    CHECK(t, image_compare(b, b).has_psnr && isinf(image_compare(b, b).psnr));
    CHECK_CLOSE(t, e.relmse, 100.0 / 3.0, 1e-12 * 34);
    image_free(b);
    image_free(a);
}

/* truth: outputs are whole or absent (README): a write into a directory that does not
 *   exist fails with an error naming the file, and leaves neither NAME nor NAME.tmp.
 * tolerance: none.
 * catches: a crash on a NULL stream, a success status for a failed write, an error
 *   without the file's name, a partial or temporary file left behind. */
static void test_write_fails_cleanly(struct check *t)
{
    char dir[NAME_MAX_BYTES], name[2 * NAME_MAX_BYTES];
    temp_name(dir, sizeof dir, "image", "no_such_dir");
    struct image *img = image_create(3, 2);
    struct error err;
    snprintf(name, sizeof name, "%s/out.pfm", dir);
    CHECK(t, pfm_write(name, img, &err) == -1 && strcmp(err.file, name) == 0);
    CHECK(t, !file_exists(name) && no_temporary(name));
    snprintf(name, sizeof name, "%s/out.ppm", dir);
    CHECK(t, ppm_write(name, img, 1.0, &err) == -1 && strcmp(err.file, name) == 0);
    CHECK(t, !file_exists(name) && no_temporary(name));
    image_free(img);
}

void test_image(struct check *t)
{
    RUN_TEST(t, test_pfm_round_trip);
    RUN_TEST(t, test_pfm_byte_layout);
    RUN_TEST(t, test_pfm_read_by_hand);
    RUN_TEST(t, test_pfm_refuses_malformed);
    RUN_TEST(t, test_ppm_bytes);
    RUN_TEST(t, test_ppm_matches_its_pfm);
    RUN_TEST(t, test_compare_metrics);
    RUN_TEST(t, test_write_fails_cleanly);
}
