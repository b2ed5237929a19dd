/*
 * tests/test_exr.c -- the exr room: OpenEXR files read (image/exr_read.c), written
 * (image/exr_write.c), and zlib streams inflated (base/inflate.c), against files and
 * streams written by outside writers: OpenEXR's own library (scripts/make_exr_samples.cpp,
 * README.md there) and Python's zlib.
 *
 * The sample files hold a formula (R = x + 0.25 y, G = -2.5, B = 0.001 x y at (x, y)
 * from the data window's top left), which the tests recompute here, rounded to a float
 * as the C++ writer computed it, and to a half by a rounding written here from the
 * format's definition (round to nearest, ties to even), not by the reader's code.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/inflate.h"
#include "../src/base/rng.h"
#include "../src/image/exr.h"
#include "../src/image/image.h"
#include "check.h"
#include "files.h"
#include "tests.h"

#define DATA "tests/data/exr/"
#define NAME_MAX_BYTES 256
#define SAMPLE_MAX_BYTES 32768 /* larger than any sample file */

/* The formula's channel c at (x, y), in float arithmetic as the C++ writer did it. */
static double formula(int c, int x, int y)
{
    volatile float v = c == 0 ? (float)x + 0.25f * (float)y : c == 1 ? -2.5f : 0.001f * (float)x;
    if (c == 2)
        v = v * (float)y;
    return v;
}

/* v rounded to the nearest half (ties to even), from the format: 10 fraction bits below
 * the leading one, subnormals in steps of 2^-24; finite v of half range only. */
static double half_rounded(double v)
{
    if (v == 0)
        return v;
    int e;
    frexp(fabs(v), &e); /* |v| in [2^(e-1), 2^e) */
    double step = ldexp(1.0, (e - 1 < -14 ? -14 : e - 1) - 10);
    double q = v / step, r = floor(q);
    double d = q - r;
    if (d > 0.5 || (d == 0.5 && fmod(r, 2.0) != 0))
        r += 1;
    return r * step;
}

/* Whether img is width x height and holds the formula, each value passed through round
 * (NULL: the float itself). */
static int holds_formula(const struct image *img, int width, int height,
                         double (*round)(double))
{
    if (img == NULL || img->width != width || img->height != height)
        return 0;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            struct vec3 p = image_get(img, x, y);
            double e[3];
            for (int c = 0; c < 3; c++)
                e[c] = round != NULL ? round(formula(c, x, y)) : formula(c, x, y);
            if (p.x != e[0] || p.y != e[1] || p.z != e[2]) {
                printf("    (%d, %d) is (%.9g, %.9g, %.9g), not (%.9g, %.9g, %.9g)\n", x, y,
                       p.x, p.y, p.z, e[0], e[1], e[2]);
                return 0;
            }
        }
    return 1;
}

static int reads_formula(const char *file, int width, int height, double (*round)(double))
{
    struct error err;
    struct image *img = image_read(file, &err);
    if (img == NULL)
        printf("    %s: %s\n", file, err.message);
    int ok = holds_formula(img, width, height, round);
    image_free(img);
    return ok;
}

/* truth: OpenEXR's library wrote the formula in HALF and FLOAT with each compression photon
 * reads. catches: a wrong half decoding (exponent bias, subnormals), a predictor or
 * interleave undone wrongly, an RLE run read off by one, an inflate bug, PIZ's code table,
 * wavelet or value map undone wrongly, channels taken in the wrong order, rows flipped. */
static void test_exr_reads_each_compression(struct check *t)
{
    static const char *const codecs[] = {"none", "rle", "zips", "zip", "piz"};
    for (size_t i = 0; i < sizeof codecs / sizeof codecs[0]; i++) {
        char name[NAME_MAX_BYTES];
        snprintf(name, sizeof name, DATA "float-%s.exr", codecs[i]);
        CHECK(t, reads_formula(name, 7, 5, NULL));
        snprintf(name, sizeof name, DATA "half-%s.exr", codecs[i]);
        CHECK(t, reads_formula(name, 7, 5, half_rounded));
        /* 61 x 37 with an alpha channel: many chunks, the last one short, long runs and
         * distances, and the compressed (not raw) path of every codec. */
        snprintf(name, sizeof name, DATA "large-half-%s.exr", codecs[i]);
        CHECK(t, reads_formula(name, 61, 37, half_rounded));
    }
}

/* truth: OpenEXR's library, as above, with a data window at (3, -2), DECREASING_Y line
 * order, RGBA, and Y alone (Y = 0.5 x + y). catches: the window's origin used as a pixel
 * offset, DECREASING_Y's chunks read in file order (rows reversed by block), alpha taken
 * for a colour, Y not copied to all three channels. */
static void test_exr_reads_windows_orders_channels(struct check *t)
{
    CHECK(t, reads_formula(DATA "window-half-rle.exr", 7, 5, half_rounded));
    CHECK(t, reads_formula(DATA "decreasing-float-zip.exr", 7, 37, NULL));
    CHECK(t, reads_formula(DATA "rgba-half-zip.exr", 7, 5, half_rounded));
    struct error err;
    struct image *y = image_read(DATA "y-half-zip.exr", &err);
    REQUIRE(t, y != NULL && y->width == 7 && y->height == 5);
    int grey = 1;
    for (int j = 0; j < 5; j++)
        for (int i = 0; i < 7; i++) {
            struct vec3 p = image_get(y, i, j);
            double e = half_rounded(0.5 * i + j);
            grey &= p.x == e && p.y == e && p.z == e;
        }
    CHECK(t, grey);
    image_free(y);
    struct image *u = image_read(DATA "uint-none.exr", &err);
    REQUIRE(t, u != NULL && u->width == 7 && u->height == 5);
    CHECK(t, image_get(u, 6, 4).x == 406 && image_get(u, 6, 4).z == 406);
    image_free(u);
}

/* truth: OpenEXR's library (Imath's half(float)) wrote the edges of the half range: the
 * smallest subnormals, the smallest normal, 65504, -0, values rounded on the way in; the
 * rows below are zero, which deflate codes with its longest copies (258 bytes).
 * catches: subnormals scaled wrongly, an exponent bias off by one, a lost sign of zero,
 * the length table's last entry wrong. */
static void test_exr_half_range_edges(struct check *t)
{
    static const float first[] = {5.9604645e-8f, -5.9604645e-8f, 1.7881393e-7f, 6.0975552e-5f,
                                  6.1035156e-5f, 65504.0f, -0.0f, 0.1f, 1e-3f, 3.14159f,
                                  -65519.0f};
    const int n = (int)(sizeof first / sizeof first[0]);
    struct error err;
    struct image *img = image_read(DATA "y-half-special-zip.exr", &err);
    REQUIRE(t, img != NULL && img->width == 41 && img->height == 16);
    int same = 1;
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 41; x++) {
            double e = y == 0 && x < n ? half_rounded(first[x]) : 0.0;
            struct vec3 p = image_get(img, x, y);
            same &= p.x == e && p.y == e && p.z == e && !signbit(p.x) == !signbit(e);
        }
    CHECK(t, same);
    CHECK(t, image_get(img, 0, 0).x == ldexp(1.0, -24) && image_get(img, 10, 0).x == -65504);
    image_free(img);
}

/* truth: OpenEXR's library wrote, with PIZ, FLOAT RGB whose channel c at (x, y) is
 * ((7919 x + 104729 y + 15485863 c) mod 1000003) / 1024, exact in a float; and a HALF ramp
 * whose half at (x, y) has the bits 29 x + y (its value from the format's definition),
 * about 30,000 distinct words in a block (PIZ's 16-bit wavelet), the last block 13 rows.
 * catches: the 16-bit wavelet undone wrongly or chosen wrongly, a FLOAT's two words
 * transformed together, a lone row or column of an odd side left undone, long codes. */
static void test_exr_piz_wide_values(struct check *t)
{
    struct error err;
    struct image *img = image_read(DATA "wide-float-piz.exr", &err);
    REQUIRE(t, img != NULL && img->width == 101 && img->height == 67);
    int same = 1;
    for (int y = 0; y < 67; y++)
        for (int x = 0; x < 101; x++) {
            struct vec3 p = image_get(img, x, y);
            double e[3];
            for (int c = 0; c < 3; c++)
                e[c] = (double)((x * 7919L + y * 104729L + c * 15485863L) % 1000003L) / 1024;
            same &= p.x == e[0] && p.y == e[1] && p.z == e[2];
        }
    CHECK(t, same);
    image_free(img);
    img = image_read(DATA "ramp-half-piz.exr", &err);
    REQUIRE(t, img != NULL && img->width == 1024 && img->height == 45);
    same = 1;
    for (int y = 0; y < 45; y++)
        for (int x = 0; x < 1024; x++) {
            int bits = 29 * x + y, e = bits >> 10, m = bits & 1023; /* below 0x7c00: finite */
            double v = e == 0 ? m / 16777216.0 : (1 + m / 1024.0) * pow(2.0, e - 15);
            same &= image_get(img, x, y).x == v && image_get(img, x, y).z == v;
        }
    CHECK(t, same);
    image_free(img);
}

/* Whether reading file fails with a "file:0: message" containing text. */
static int refused_with(const char *file, const char *text)
{
    struct error err;
    struct image *img = image_read(file, &err);
    int ok = img == NULL && strcmp(err.file, file) == 0 && err.line == 0 &&
             strstr(err.message, text) != NULL;
    if (!ok)
        printf("    %s: %s\n", file, img == NULL ? err.message : "read");
    image_free(img);
    return ok;
}

/* Copies file into the test's temporary name with byte at offset set to value (offset <
 * 0: none changed) and the file cut to size bytes (size 0: whole); returns the bytes. */
static size_t patched_copy(const char *file, const char *out, long offset,
                           const unsigned char *value, size_t n_value, size_t size)
{
    static unsigned char bytes[SAMPLE_MAX_BYTES];
    FILE *f = fopen(file, "rb");
    size_t n = f != NULL ? fread(bytes, 1, sizeof bytes, f) : 0;
    if (f != NULL)
        fclose(f);
    if (offset >= 0 && (size_t)offset + n_value <= n)
        memcpy(bytes + offset, value, n_value);
    write_bytes_file(out, bytes, size != 0 && size < n ? size : n);
    return n;
}

/* truth: OpenEXR's library wrote a tiled, a multi-part and a PXR24 file; the deep flag
 * (bit 11 of the version field) is set by hand in a copy of a scanline file, as the
 * format's layout describes it. catches: a tiled or multi-part file read as scanlines
 * (garbage or a crash), an unread compression taken for another, an error without the
 * file's name. */
static void test_exr_refuses_by_name(struct check *t)
{
    CHECK(t, refused_with(DATA "tiled.exr", "tiled OpenEXR files are not read"));
    CHECK(t, refused_with(DATA "multipart.exr", "multi-part OpenEXR files are not read"));
    CHECK(t, refused_with(DATA "pxr24.exr", "PXR24 compression is not read"));
    char name[NAME_MAX_BYTES];
    temp_name(name, sizeof name, "exr", "deep.exr");
    const unsigned char deep = 0x08; /* the version field's second byte: bit 11 */
    patched_copy(DATA "float-none.exr", name, 5, &deep, 1, 0);
    CHECK(t, refused_with(name, "deep OpenEXR files are not read"));
    remove(name);
}

/* An image of random float values (and the range's edges), as pfm tests make them. */
static struct image *random_image(int width, int height, uint64_t index)
{
    struct image *img = image_create(width, height);
    struct rng r = rng_stream(1, STREAM_TEST, index, 0);
    for (size_t i = 0; i < (size_t)width * (size_t)height; i++) {
        double v[3];
        for (int c = 0; c < 3; c++) {
            double m = pow(10.0, -40.0 + 78.0 * rng_uniform(&r));
            v[c] = rng_uniform(&r) < 0.5 ? -m : m;
        }
        img->pixels[i] = vec3(v[0], v[1], v[2]);
    }
    img->pixels[0] = vec3(FLT_MAX, -FLT_MAX, ldexp(1.0, -149));
    return img;
}

/* The file's bytes into bytes[SAMPLE_MAX_BYTES]: how many (0 when unreadable or larger). */
static size_t file_bytes(const char *file, unsigned char *bytes)
{
    FILE *f = fopen(file, "rb");
    size_t n = f != NULL ? fread(bytes, 1, SAMPLE_MAX_BYTES, f) : 0;
    if (f != NULL)
        fclose(f);
    return n < SAMPLE_MAX_BYTES ? n : 0;
}

static uint64_t u64_at(const unsigned char *b)
{
    uint64_t v = 0;
    for (int i = 7; i >= 0; i--)
        v = v << 8 | b[i];
    return v;
}

/* Whether file, a width x height image photon wrote, is laid out as the OpenEXR File Layout
 * says for ZIP: compression attribute 3; after the header one offset per chunk of 16 rows;
 * each chunk its first row's y, its data's size (compressed: less than its raw rows; else
 * exactly those) and the data, the first right after the table, each next right after the
 * one before, the last ending the file. */
static int zip_layout_holds(const char *file, int width, int height, int compressed)
{
    static unsigned char b[SAMPLE_MAX_BYTES];
    size_t n = file_bytes(file, b), at = 8;
    int compression = -1;
    while (at < n && b[at] != 0) { /* name, type, size, value */
        const char *name = (const char *)b + at;
        at += strlen(name) + 1;
        at += strlen((const char *)b + at) + 1;
        size_t size = (size_t)(b[at] | b[at + 1] << 8);
        if (strcmp(name, "compression") == 0 && size == 1)
            compression = b[at + 4];
        at += 4 + size;
    }
    size_t n_chunks = (size_t)(height + 15) / 16, next = at + 1 + 8 * n_chunks;
    int ok = compression == EXR_ZIP_COMPRESSION && next <= n;
    for (size_t i = 0; ok && i < n_chunks; i++) {
        size_t rows = (size_t)height - 16 * i < 16 ? (size_t)height - 16 * i : 16;
        size_t raw = rows * (size_t)width * 12, offset = (size_t)u64_at(b + at + 1 + 8 * i);
        ok = offset == next && offset + 8 <= n && b[offset] == 16 * i && b[offset + 1] == 0;
        size_t size = ok ? (size_t)(b[offset + 4] | b[offset + 5] << 8 | b[offset + 6] << 16) : 0;
        ok = ok && (compressed ? size < raw : size == raw);
        next = offset + 8 + size;
    }
    if (!ok || next != n)
        printf("    %s: compression %d, a chunk or its offset is wrong\n", file, compression);
    return ok && next == n;
}

/* Whether img read back from file holds exactly img's values rounded to floats. */
static int reads_back(const char *file, const struct image *img)
{
    struct error err;
    struct image *back = image_read(file, &err);
    int same = back != NULL && back->width == img->width && back->height == img->height;
    for (size_t i = 0; same && i < (size_t)img->width * (size_t)img->height; i++) {
        volatile float x = (float)img->pixels[i].x, y = (float)img->pixels[i].y,
                       z = (float)img->pixels[i].z;
        same = back->pixels[i].x == x && back->pixels[i].y == y && back->pixels[i].z == z;
    }
    image_free(back);
    return same;
}

/* truth: (1) float-zip.exr, the formula as OpenEXR's library writes it in FLOAT with ZIP:
 * photon's header (313 bytes), offset table and chunk's y must be its bytes (the same
 * attributes, in the same order, compression 3, the same table); the compressed bytes
 * differ, being another compressor's; (2) C's own double -> float rounding, for random
 * values read back, whose chunk deflate cannot shorten: stored raw. catches: a header,
 * channel order or offset table another reader would take differently, rows written
 * bottom up, a value not rounded to its float. */
static void test_exr_writes_what_openexr_writes(struct check *t)
{
    static unsigned char ours[SAMPLE_MAX_BYTES], theirs[SAMPLE_MAX_BYTES];
    char name[NAME_MAX_BYTES];
    struct error err;
    temp_name(name, sizeof name, "exr", "formula.exr");
    struct image *img = image_create(7, 5);
    for (int y = 0; y < 5; y++)
        for (int x = 0; x < 7; x++)
            image_set(img, x, y, vec3(formula(0, x, y), formula(1, x, y), formula(2, x, y)));
    CHECK(t, image_write(name, img, &err) == 0);
    CHECK(t, file_bytes(name, ours) > 313 + 12 && file_bytes(DATA "float-zip.exr", theirs) > 0 &&
             memcmp(ours, theirs, 313 + 8 + 4) == 0);
    CHECK(t, zip_layout_holds(name, 7, 5, 1) && reads_formula(name, 7, 5, NULL));
    CHECK(t, no_temporaries(name));
    image_free(img);
    remove(name);
    temp_name(name, sizeof name, "exr", "random.exr");
    img = random_image(13, 9, 0);
    CHECK(t, image_write(name, img, &err) == 0);
    CHECK(t, zip_layout_holds(name, 13, 9, 0) && reads_back(name, img));
    img->pixels[5].y = 1e39; /* beyond a float: refused, nothing left */
    remove(name);
    CHECK(t, image_write(name, img, &err) < 0 && err.failed_write && !file_exists(name));
    image_free(img);
}

/* truth: a render (direct light in the Cornell box, 48 x 37: three chunks, the last of 5
 * rows) read from photon's PFM; the OpenEXR file of it must hold the same floats, be laid
 * out as the File Layout says (zip_layout_holds), and be noticeably smaller than the same
 * file uncompressed would be (its header, 8 bytes of offset and 8 of y and size per row,
 * the rows raw); a smooth ramp too, whose 16-row chunks shrink far more. catches: ZIP
 * written but not read back bit for bit, compression that does not compress. */
static void test_exr_zip_of_a_render(struct check *t)
{
    char name[NAME_MAX_BYTES];
    struct error err;
    struct image *img = photon_render("exr", "--mode direct --width 48 --height 37 --spp 4",
                                      "scenes/cornell.scene");
    REQUIRE(t, img != NULL);
    temp_name(name, sizeof name, "exr", "render.exr");
    CHECK(t, image_write(name, img, &err) == 0);
    static unsigned char b[SAMPLE_MAX_BYTES];
    double size = (double)file_bytes(name, b), raw = 313 + 37 * (8 + 8 + 48 * 12);
    CHECK(t, size > 0 && size < 0.8 * raw);
    CHECK(t, zip_layout_holds(name, 48, 37, 1) && reads_back(name, img));
    image_free(img);
    img = image_create(64, 40);
    for (int y = 0; y < 40; y++)
        for (int x = 0; x < 64; x++)
            image_set(img, x, y, vec3(0.25 + x / 256.0, 0.5, 1.0 - y / 128.0));
    CHECK(t, image_write(name, img, &err) == 0);
    size = (double)file_bytes(name, b);
    CHECK(t, size > 0 && size < 0.1 * (313 + 40 * (8 + 8 + 64 * 12)));
    CHECK(t, zip_layout_holds(name, 64, 40, 1) && reads_back(name, img));
    image_free(img);
    remove(name);
}

/* truth: IEEE 754 binary32's NaN and infinities (0x7fc00000, 0x7f800000, 0xff800000),
 * set by hand in the last value of a file photon wrote (of random values, which deflate
 * cannot shorten: its one chunk is raw). catches: a NaN or infinity let into an image,
 * +Inf refused where an error image's bound may be +Inf, -Inf allowed. */
static void test_exr_refuses_nan_and_infinity(struct check *t)
{
    char name[NAME_MAX_BYTES], bad[NAME_MAX_BYTES];
    struct error err;
    temp_name(name, sizeof name, "exr", "finite.exr");
    temp_name(bad, sizeof bad, "exr", "bad.exr");
    struct image *img = random_image(3, 2, 1);
    CHECK(t, image_write(name, img, &err) == 0);
    image_free(img);
    static const unsigned char values[3][4] = {
        {0x00, 0x00, 0xc0, 0x7f}, {0x00, 0x00, 0x80, 0x7f}, {0x00, 0x00, 0x80, 0xff}};
    FILE *f = fopen(name, "rb");
    long size = 0;
    if (f != NULL && fseek(f, 0, SEEK_END) == 0)
        size = ftell(f);
    if (f != NULL)
        fclose(f);
    REQUIRE(t, size > 4);
    for (int v = 0; v < 3; v++) {
        patched_copy(name, bad, size - 4, values[v], 4, 0);
        CHECK(t, refused_with(bad, "NaN or infinite"));
        struct image *bounds = image_read_bounds(bad, &err);
        CHECK(t, (bounds != NULL) == (v == 1)); /* +Inf only */
        if (bounds != NULL)
            CHECK(t, image_get(bounds, 2, 1).x == HUGE_VAL);
        image_free(bounds);
    }
    remove(name);
    remove(bad);
}

/* truth: every file cut short or with one byte changed is damaged input, which must end in
 * a message or (for a changed value byte) an image, never a crash or a hang; the
 * sanitizer build turns an out-of-bounds read into a failure. catches: an offset, a
 * length or a count from the file used unchecked. */
static void test_exr_damaged_files(struct check *t)
{
    static const char *const files[] = {DATA "half-zip.exr", DATA "half-rle.exr",
                                        DATA "float-zips.exr", DATA "y-half-zip.exr",
                                        DATA "half-piz.exr"};
    char name[NAME_MAX_BYTES];
    temp_name(name, sizeof name, "exr", "damaged.exr");
    int cut_refused = 1, changed_ok = 1;
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
        size_t n = patched_copy(files[k], name, -1, NULL, 0, 0);
        for (size_t cut = 1; cut < n; cut++) {
            struct error err;
            patched_copy(files[k], name, -1, NULL, 0, cut);
            struct image *img = image_read(name, &err);
            cut_refused &= img == NULL && err.message[0] != '\0';
            image_free(img);
        }
        for (size_t at = 0; at < n; at++)
            for (int bit = 0; bit < 8; bit += 3) {
                struct error err;
                err.message[0] = '\0';
                unsigned char b = 0;
                FILE *f = fopen(files[k], "rb");
                if (f != NULL && fseek(f, (long)at, SEEK_SET) == 0)
                    b = (unsigned char)getc(f);
                if (f != NULL)
                    fclose(f);
                b ^= (unsigned char)(1u << bit);
                patched_copy(files[k], name, (long)at, &b, 1, 0);
                struct image *img = image_read(name, &err);
                changed_ok &= img != NULL || err.message[0] != '\0';
                image_free(img);
            }
    }
    CHECK(t, cut_refused);
    CHECK(t, changed_ok);
    remove(name);
}

/* truth: input.h measures a file once, when it opens; exr_read() then reads that many
 *   bytes, and a file that holds fewer by then says where it ends. A sysfs file tells 4096
 *   bytes and holds a few (/sys/devices/system/cpu/online: "0-1\n" here), as a file cut
 *   while photon opens it would. Skipped where there is no such file.
 * catches: "cannot read the file's 4096 bytes", without why. */
static void test_exr_read_ends_early(struct check *t)
{
    const char *name = "/sys/devices/system/cpu/online";
    if (run_command("{ test \"$(wc -c < /sys/devices/system/cpu/online)\" -lt \"$(stat -c "
                    "%s /sys/devices/system/cpu/online)\"; } 2>/dev/null") != 0) {
        printf("  (test_exr_read_ends_early: no short sysfs file, skipped)\n");
        return;
    }
    struct error err;
    struct image *img = exr_read(name, 0, &err);
    CHECK(t, img == NULL && strcmp(err.file, name) == 0 &&
             strstr(err.message, "the file ends after ") != NULL &&
             strstr(err.message, " bytes it had when opened") != NULL);
    image_free(img);
}

/* truth: Python's zlib.compress(b"photon", 0) (a stored block) and
 * zlib.compress(b"photon photon photon mapping", 9) (fixed codes, a back reference).
 * catches: a stored block's length misread, a fixed code table off by one, an overlapping
 * copy done as a memcpy, a checksum not checked. */
static void test_inflate_python_streams(struct check *t)
{
    static const unsigned char stored[] = {0x78, 0x01, 0x01, 0x06, 0x00, 0xf9, 0xff, 0x70,
                                           0x68, 0x6f, 0x74, 0x6f, 0x6e, 0x09, 0x12, 0x02,
                                           0x99};
    static const unsigned char fixed[] = {0x78, 0xda, 0x2b, 0xc8, 0xc8, 0x2f, 0xc9, 0xcf,
                                          0x53, 0x28, 0x40, 0xa1, 0x72, 0x13, 0x0b, 0x0a,
                                          0x32, 0xf3, 0xd2, 0x01, 0xa1, 0x47, 0x0b, 0x15};
    const char *text = "photon photon photon mapping";
    unsigned char out[64];
    const char *message = NULL;
    CHECK(t, zlib_inflate(stored, sizeof stored, out, 6, &message) == 0 &&
             memcmp(out, "photon", 6) == 0);
    CHECK(t, zlib_inflate(fixed, sizeof fixed, out, strlen(text), &message) == 0 &&
             memcmp(out, text, strlen(text)) == 0);
    CHECK(t, zlib_inflate(fixed, sizeof fixed, out, strlen(text) - 1, &message) < 0);
    CHECK(t, zlib_inflate(fixed, sizeof fixed, out, strlen(text) + 1, &message) < 0);
    unsigned char wrong[sizeof fixed];
    memcpy(wrong, fixed, sizeof fixed);
    wrong[sizeof wrong - 1] ^= 1; /* the checksum's last byte */
    CHECK(t, zlib_inflate(wrong, sizeof wrong, out, strlen(text), &message) < 0 &&
             strstr(message, "Adler-32") != NULL);
    /* Wikipedia's example of Adler-32 */
    CHECK(t, adler32((const unsigned char *)"Wikipedia", 9) == 0x11E60398ul);
}

/* Whether file starts with OpenEXR's magic number. */
static int is_exr_file(const char *file)
{
    unsigned char b[4] = {0, 0, 0, 0};
    FILE *f = fopen(file, "rb");
    if (f != NULL) {
        if (fread(b, 1, 4, f) != 4)
            b[0] = 0;
        fclose(f);
    }
    return b[0] == 0x76 && b[1] == 0x2f && b[2] == 0x31 && b[3] == 0x01;
}

#define RENDER "--mode direct --width 9 --height 7 --spp 2 --no-progress scenes/cornell.scene "

/* truth: the same render written as a PFM (pfm.c, tested against outside readers in the
 * image room): photon compare must find the OpenEXR image equal to it, and so must the
 * image photon merge makes from two OpenEXR crops. catches: -o FILE.exr writing a PFM or
 * no PNG beside it, --variance ignoring the ending, a command that still reads PFM only,
 * an error message without the file's name. */
static void test_exr_commands(struct check *t)
{
    char a[NAME_MAX_BYTES], b[NAME_MAX_BYTES], v[NAME_MAX_BYTES], log[NAME_MAX_BYTES];
    char t1[NAME_MAX_BYTES], t2[NAME_MAX_BYTES], m[NAME_MAX_BYTES], args[2048];
    temp_name(a, sizeof a, "exr", "a.exr");
    temp_name(b, sizeof b, "exr", "b.pfm");
    temp_name(v, sizeof v, "exr", "v.exr");
    temp_name(t1, sizeof t1, "exr", "t1.exr");
    temp_name(t2, sizeof t2, "exr", "t2.exr");
    temp_name(m, sizeof m, "exr", "m.exr");
    temp_name(log, sizeof log, "exr", "commands.log");
    snprintf(args, sizeof args, RENDER "-o %s --variance %s", a, v);
    CHECK(t, photon_logged("", args, log) == 0);
    snprintf(args, sizeof args, RENDER "-o %s", b);
    CHECK(t, photon_logged("", args, log) == 0);
    CHECK(t, is_exr_file(a) && is_exr_file(v));
    char png[NAME_MAX_BYTES], pfm[NAME_MAX_BYTES];
    snprintf(png, sizeof png, "%.*s.png", (int)strlen(a) - 4, a);
    snprintf(pfm, sizeof pfm, "%.*s.pfm", (int)strlen(a) - 4, a);
    CHECK(t, file_exists(png) && !file_exists(pfm));
    snprintf(args, sizeof args, "%s %s", a, b);
    CHECK(t, photon_logged("compare", args, log) == 0 && file_contains(log, "rmse=0 "));
    snprintf(args, sizeof args, RENDER "--crop 0 0 9 4 -o %s", t1);
    CHECK(t, photon_logged("", args, log) == 0);
    snprintf(args, sizeof args, RENDER "--crop 0 4 9 7 -o %s", t2);
    CHECK(t, photon_logged("", args, log) == 0);
    snprintf(args, sizeof args, "-o %s %s %s", m, t1, t2);
    CHECK(t, photon_logged("merge", args, log) == 0 && is_exr_file(m));
    snprintf(args, sizeof args, "%s %s", m, b);
    CHECK(t, photon_logged("compare", args, log) == 0 && file_contains(log, "rmse=0 "));
    snprintf(args, sizeof args, DATA "tiled.exr %s", b);
    CHECK(t, photon_logged("compare", args, log) == 2 &&
             file_contains(log, DATA "tiled.exr: tiled OpenEXR files are not read"));
    const char *made[] = {a, b, v, t1, t2, m, png, log};
    for (size_t i = 0; i < sizeof made / sizeof made[0]; i++)
        remove(made[i]);
    const char *pngs[] = {b, t1, t2, m};
    for (size_t i = 0; i < sizeof pngs / sizeof pngs[0]; i++) {
        snprintf(png, sizeof png, "%.*s.png", (int)strlen(pngs[i]) - 4, pngs[i]);
        remove(png);
    }
    char window[NAME_MAX_BYTES + 8];
    snprintf(window, sizeof window, "%s.window", t1);
    remove(window);
    snprintf(window, sizeof window, "%s.window", t2);
    remove(window);
}

void test_exr(struct check *t)
{
    RUN_TEST(t, test_inflate_python_streams);
    RUN_TEST(t, test_exr_reads_each_compression);
    RUN_TEST(t, test_exr_reads_windows_orders_channels);
    RUN_TEST(t, test_exr_half_range_edges);
    RUN_TEST(t, test_exr_piz_wide_values);
    RUN_TEST(t, test_exr_refuses_by_name);
    RUN_TEST(t, test_exr_writes_what_openexr_writes);
    RUN_TEST(t, test_exr_zip_of_a_render);
    RUN_TEST(t, test_exr_refuses_nan_and_infinity);
    RUN_TEST(t, test_exr_damaged_files);
    RUN_TEST(t, test_exr_read_ends_early);
    RUN_TEST(t, test_exr_commands);
}
