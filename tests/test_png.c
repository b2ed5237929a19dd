/*
 * tests/test_png.c -- the PNG room: the display image png.c writes, read back by readers
 * that share none of its code.
 *
 * Two readers. This file's own (read_png): the chunks with a bit-by-bit CRC-32, and the
 * zlib stream as photon writes it, stored deflate blocks only, with its Adler-32 summed by
 * another formula than png.c's. And, outside, Python's zlib through tests/png_check.py,
 * with pngcheck and ImageMagick where they are installed; a reader that is not installed
 * is named on a "skipped" line, never passed over in silence.
 *
 * Files go to /tmp under names unique to the run (temp_name, files.c) and are removed by
 * the test that made them. The -o naming rule is tested on the binary in test_outputs.c.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/rng.h"
#include "../src/image/image.h"
#include "../src/image/png.h"
#include "check.h"
#include "files.h"
#include "tests.h"

#define NAME_MAX_BYTES 256
#define COMMAND_MAX 1024
#define STORED_BLOCK_MAX 65535 /* RFC 1951 Sec. 3.2.4: a stored block's LEN is 16 bits */

/* The whole of a file (malloc'd, caller frees) and its length in *n; NULL if unreadable. */
static unsigned char *read_whole_file(const char *name, size_t *n)
{
    FILE *f = fopen(name, "rb");
    long length = f != NULL && fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    unsigned char *bytes = length >= 0 ? malloc((size_t)length + 1) : NULL;
    *n = 0;
    if (bytes != NULL && fseek(f, 0, SEEK_SET) == 0)
        *n = fread(bytes, 1, (size_t)length, f);
    if (f != NULL)
        fclose(f);
    if (bytes != NULL && *n != (size_t)length) {
        free(bytes);
        bytes = NULL;
    }
    return bytes;
}

static uint32_t big_endian_32(const unsigned char *p)
{
    return ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | p[3];
}

/* PNG's CRC-32 (ISO/IEC 15948 Sec. 5.5) one bit at a time, as the definition reads: the
 * register starts all ones, each bit shifts out and, when it is 1, the reflected
 * polynomial 0xEDB88320 is added; the result is complemented. No table, unlike png.c. */
static uint32_t crc32_bitwise(const unsigned char *bytes, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= bytes[i];
        for (int k = 0; k < 8; k++)
            c = (c >> 1) ^ (c & 1 ? 0xEDB88320u : 0);
    }
    return c ^ 0xFFFFFFFFu;
}

/* Adler-32 (RFC 1950 Sec. 2.2) from its sums in closed form: s1 = 1 + sum b_i and
 * s2 = sum over j of (1 + b_0 + ... + b_j) = n + sum (n - i) b_i, each reduced modulo
 * 65521 once at the end (exact in 64 bits for the few MB here); png.c reduces per byte. */
static uint32_t adler32_closed_form(const unsigned char *bytes, size_t n)
{
    uint64_t s1 = 1, s2 = n;
    for (size_t i = 0; i < n; i++) {
        s1 += bytes[i];
        s2 += (uint64_t)(n - i) * bytes[i];
    }
    return ((uint32_t)(s2 % 65521) << 16) | (uint32_t)(s1 % 65521);
}

/* What read_png() found. */
struct png_read {
    int width, height;  /* IHDR's                                           */
    unsigned char *idat; /* owned: the IDATs' data joined, the zlib stream   */
    size_t n_idat;
    unsigned char *raw; /* owned: the stream inflated, the scanlines         */
    size_t n_raw;
    int n_blocks;       /* stored blocks in the stream                       */
    const char *why;    /* what was wrong, or NULL                           */
};

static int refuse(struct png_read *pr, const char *why)
{
    pr->why = why;
    return -1;
}

/* IHDR's 13 bytes (Sec. 11.2.2): width, height, then depth 8, colour type 2, methods 0. */
static int read_ihdr(const unsigned char *data, uint32_t length, struct png_read *pr)
{
    static const unsigned char rest[5] = {8, 2, 0, 0, 0};
    if (length != 13 || memcmp(data + 8, rest, 5) != 0)
        return refuse(pr, "IHDR is not 13 bytes of 8-bit RGB, methods 0");
    pr->width = (int)big_endian_32(data);
    pr->height = (int)big_endian_32(data + 4);
    return pr->width >= 1 && pr->height >= 1 ? 0 : refuse(pr, "IHDR: an empty image");
}

/* The signature, then chunks (Sec. 5.3), each CRC checked: IHDR, IDATs, IEND, nothing
 * after it and nothing else (photon writes no other chunk). */
static int read_chunks(const unsigned char *file, size_t n, struct png_read *pr)
{
    static const unsigned char signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    if (n < 8 || memcmp(file, signature, 8) != 0)
        return refuse(pr, "no PNG signature");
    pr->idat = malloc(n); /* the IDATs' data is less than the file */
    size_t at = 8;
    for (int ended = 0; !ended;) {
        uint32_t length = at + 12 <= n ? big_endian_32(file + at) : 0;
        if (pr->idat == NULL || at + 12 > n || length > n - at - 12)
            return refuse(pr, "a chunk runs past the end of the file");
        const unsigned char *type = file + at + 4, *data = file + at + 8;
        if (crc32_bitwise(type, 4 + (size_t)length) != big_endian_32(data + length))
            return refuse(pr, "a chunk's CRC is wrong");
        int ihdr = memcmp(type, "IHDR", 4) == 0, idat = memcmp(type, "IDAT", 4) == 0;
        ended = memcmp(type, "IEND", 4) == 0;
        if ((at == 8) != ihdr || !(ihdr || idat || ended) || (ended && length != 0))
            return refuse(pr, "IHDR not first, a non-empty IEND, or an unknown chunk");
        if (ihdr && read_ihdr(data, length, pr) < 0)
            return -1;
        if (idat) {
            memcpy(pr->idat + pr->n_idat, data, length);
            pr->n_idat += length;
        }
        at += 12 + (size_t)length;
    }
    return at == n ? 0 : refuse(pr, "bytes after IEND");
}

/* The zlib stream (RFC 1950 Sec. 2.2) of stored deflate blocks (RFC 1951 Sec. 3.2.4):
 * header CM 8 with FCHECK right and no dictionary; blocks of BTYPE 00, each LEN with NLEN
 * its complement, up to the one marked BFINAL; then the Adler-32 and the end of the data. */
static int inflate_stored(struct png_read *pr)
{
    const unsigned char *z = pr->idat;
    size_t n = pr->n_idat, at = 2;
    if (n < 6 || (z[0] & 0x0F) != 8 || (z[0] * 256 + z[1]) % 31 != 0 || (z[1] & 0x20) != 0)
        return refuse(pr, "not a zlib header of deflate without a dictionary");
    pr->raw = malloc(n); /* stored blocks hold fewer bytes than the stream */
    for (int final = 0; !final; pr->n_blocks++) {
        if (at + 5 > n || ((z[at] >> 1) & 3) != 0)
            return refuse(pr, "a block cut short, or not a stored one");
        final = z[at] & 1;
        unsigned len = z[at + 1] | ((unsigned)z[at + 2] << 8);
        unsigned nlen = z[at + 3] | ((unsigned)z[at + 4] << 8);
        if ((len ^ nlen) != 0xFFFF || len > n - at - 5)
            return refuse(pr, "a stored block's LEN and NLEN disagree, or it runs past");
        if (pr->raw != NULL)
            memcpy(pr->raw + pr->n_raw, z + at + 5, len);
        pr->n_raw += len;
        at += 5 + len;
    }
    if (at + 4 != n || big_endian_32(z + at) != adler32_closed_form(pr->raw, pr->n_raw))
        return refuse(pr, "the Adler-32 is wrong, or bytes follow it");
    return 0;
}

/* The PNG file's pixels, R G B from the top left (malloc'd, caller frees): its chunks
 * read, its stream inflated, each scanline's filter byte 0 (Sec. 9.2) dropped. NULL with
 * pr->why set when the file breaks any rule above; pr's buffers are freed either way. */
static unsigned char *read_png(const char *name, struct png_read *pr)
{
    memset(pr, 0, sizeof *pr);
    size_t n = 0;
    unsigned char *file = read_whole_file(name, &n);
    unsigned char *rgb = NULL;
    if (file == NULL)
        refuse(pr, "cannot read the file");
    else if (read_chunks(file, n, pr) == 0 && inflate_stored(pr) == 0) {
        size_t row = 1 + 3 * (size_t)pr->width;
        rgb = pr->n_raw == row * (size_t)pr->height ? malloc(pr->n_raw) : NULL;
        for (int y = 0; rgb != NULL && y < pr->height; y++) {
            const unsigned char *scanline = pr->raw + (size_t)y * row;
            if (scanline[0] == 0) {
                memcpy(rgb + (size_t)y * (row - 1), scanline + 1, row - 1);
            } else {
                free(rgb);
                rgb = NULL;
            }
        }
        if (rgb == NULL)
            refuse(pr, "scanlines of the wrong length, or a filter type other than 0");
    }
    free(file);
    free(pr->idat);
    free(pr->raw);
    pr->idat = pr->raw = NULL;
    return rgb;
}

/* The stored blocks that hold n raw bytes: ceil(n / 65535), since only the last is short. */
static int blocks_for(size_t n)
{
    return (int)((n + STORED_BLOCK_MAX - 1) / STORED_BLOCK_MAX);
}

/* truth: the file worked by hand from ISO/IEC 15948 and RFC 1950/1951 for one pixel
 *   (1, 0, 0.5), whose sRGB bytes are 255 0 188 (test_image.c works them out):
 *   IHDR 1 x 1, depth 8, colour type 2, with CRC 907753DE; IDAT 78 01 (zlib header),
 *   01 04 00 FB FF (final stored block, LEN 4, NLEN ~4), 00 FF 00 BC (filter 0, the
 *   pixel), Adler-32 03BD01BC (s1 = 1 + 443 = 444, s2 = 1 + 256 + 256 + 444 = 957); its
 *   CRC 56B9F844 and IHDR's from Python's zlib.crc32; IEND's CRC AE426082, printed in
 *   every PNG that exists.
 * tolerance: none; bytes.
 * catches: little-endian lengths, a CRC over the length or without the type, a wrong zlib
 *   header or FCHECK, BFINAL unset, NLEN not complemented, no filter byte, BGR order. */
static void test_png_bytes_by_hand(struct check *t)
{
    static const unsigned char expected[72] = {
        0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n',
        0, 0, 0, 13, 'I', 'H', 'D', 'R', 0, 0, 0, 1, 0, 0, 0, 1, 8, 2, 0, 0, 0,
        0x90, 0x77, 0x53, 0xDE,
        0, 0, 0, 15, 'I', 'D', 'A', 'T', 0x78, 0x01, 0x01, 0x04, 0x00, 0xFB, 0xFF,
        0x00, 0xFF, 0x00, 0xBC, 0x03, 0xBD, 0x01, 0xBC, 0x56, 0xB9, 0xF8, 0x44,
        0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82,
    };
    char name[NAME_MAX_BYTES];
    temp_name(name, sizeof name, "png", "hand.png");
    struct image *img = image_create(1, 1);
    image_set(img, 0, 0, vec3(1, 0, 0.5));
    struct error err;
    CHECK(t, png_write(name, img, 1.0, &err) == 0);
    size_t n = 0;
    unsigned char *bytes = read_whole_file(name, &n);
    CHECK(t, bytes != NULL && n == sizeof expected && memcmp(bytes, expected, n) == 0);
    free(bytes);
    remove(name);
    image_free(img);
}

/* The cases both round trips write. The raw (filtered) data is height * (1 + 3 width). */
static const struct png_case {
    int width, height;
    double exposure;
} png_cases[] = {
    {1, 1, 1.0},    /* 4 bytes: the smallest file                                 */
    {3, 2, 0.37},   /* 20 bytes: odd sizes, an exposure below 1                     */
    {28, 771, 1.0}, /* 85 x 771 = 65535: one block, exactly full, and final         */
    {28, 1542, 4.0}, /* 131070: two full blocks, the last full one final           */
    {101, 257, 1.0}, /* 304 x 257 = 78128: two blocks, a scanline across the boundary */
};
#define N_PNG_CASES (sizeof png_cases / sizeof png_cases[0])

/* An image of case c: values spread over [-0.1, 1.4), so some clamp at either end. */
static struct image *random_image(size_t c)
{
    const struct png_case *pc = &png_cases[c];
    struct image *img = image_create(pc->width, pc->height);
    struct rng r = rng_stream(7, STREAM_TEST, c, 0);
    for (int y = 0; y < pc->height; y++)
        for (int x = 0; x < pc->width; x++) {
            double v[3];
            for (int k = 0; k < 3; k++)
                v[k] = -0.1 + 1.5 * rng_uniform(&r);
            image_set(img, x, y, vec3(v[0], v[1], v[2]));
        }
    return img;
}

/* truth: a round trip through an independent reader (read_png above: its own CRC, its
 *   own Adler-32, its own stored-block parser), whose pixels must equal the PPM's bytes for
 *   the same image and exposure (test_image.c checks those by hand), in as many stored
 *   blocks as the raw size needs.
 * tolerance: none; bytes.
 * catches: a block boundary losing or repeating a byte, a full last block not marked
 *   final or followed by an empty one, the Adler-32 of the wrong bytes, exposure ignored,
 *   rows in the wrong order. */
static void test_png_matches_ppm(struct check *t)
{
    char png[NAME_MAX_BYTES], ppm[NAME_MAX_BYTES];
    temp_name(png, sizeof png, "png", "round.png");
    temp_name(ppm, sizeof ppm, "png", "round.ppm");
    for (size_t c = 0; c < N_PNG_CASES; c++) {
        struct image *img = random_image(c);
        double exposure = png_cases[c].exposure;
        struct error err;
        CHECK(t, png_write(png, img, exposure, &err) == 0);
        CHECK(t, ppm_write(ppm, img, exposure, &err) == 0);
        struct png_read pr;
        unsigned char *rgb = read_png(png, &pr);
        size_t n_ppm = 0;
        unsigned char *ppm_bytes = read_whole_file(ppm, &n_ppm);
        size_t n_rgb = 3 * (size_t)img->width * (size_t)img->height;
        CHECK(t, rgb != NULL && pr.width == img->width && pr.height == img->height);
        CHECK(t, pr.n_blocks == blocks_for(pr.n_raw) && pr.n_raw == n_rgb + img->height);
        CHECK(t, rgb != NULL && ppm_bytes != NULL && n_ppm > n_rgb &&
                 memcmp(rgb, ppm_bytes + n_ppm - n_rgb, n_rgb) == 0);
        if (pr.why != NULL)
            fprintf(stderr, "test_png: %dx%d: %s\n", img->width, img->height, pr.why);
        free(rgb);
        free(ppm_bytes);
        image_free(img);
    }
    remove(png);
    remove(ppm);
}

/* The byte pattern of the outside-reader test: every value 0..255 appears, neighbours in
 * x, y and channel differ. */
static unsigned char pattern_byte(int x, int y, int k)
{
    return (unsigned char)((x * 7 + y * 13 + k * 101) % 256);
}

/* The linear value whose display byte at exposure is b: the centre of level b, b / 255,
 * through the sRGB curve inverted by hand (IEC 61966-2-1), over the exposure. The float
 * the PFM keeps of it, times the exposure, is a few ulps from that centre, half a level
 * from either boundary, so it encodes to b. */
static double linear_of_byte(int b, double exposure)
{
    double e = b / 255.0;
    return (e <= 0.04045 ? e / 12.92 : pow((e + 0.055) / 1.055, 2.4)) / exposure;
}

/* Writes case c's pattern image as the PNG png, and the pixel bytes it must hold, from
 * pattern_byte() alone, as the raw file rgb. Returns png_write's status. */
static int write_pattern_case(size_t c, const char *png, const char *rgb)
{
    const struct png_case *pc = &png_cases[c];
    struct image *img = image_create(pc->width, pc->height);
    unsigned char *bytes = malloc(3 * (size_t)pc->width * (size_t)pc->height);
    for (int y = 0; bytes != NULL && y < pc->height; y++)
        for (int x = 0; x < pc->width; x++) {
            double v[3];
            for (int k = 0; k < 3; k++) {
                int b = pattern_byte(x, y, k);
                bytes[3 * ((size_t)y * (size_t)pc->width + (size_t)x) + (size_t)k] =
                    (unsigned char)b;
                v[k] = linear_of_byte(b, pc->exposure);
            }
            image_set(img, x, y, vec3(v[0], v[1], v[2]));
        }
    if (bytes != NULL)
        write_bytes_file(rgb, bytes, 3 * (size_t)pc->width * (size_t)pc->height);
    struct error err;
    int status = png_write(png, img, pc->exposure, &err);
    free(bytes);
    image_free(img);
    return status;
}

/* Whether the program is on the PATH; when not, says on stdout that what needs it is
 * skipped. */
static int installed(const char *program, const char *needed_for)
{
    char command[COMMAND_MAX];
    snprintf(command, sizeof command, "command -v %s > /dev/null 2>&1", program);
    int found = run_command(command) == 0;
    if (!found)
        printf("  png: %s skipped: %s not found\n", needed_for, program);
    return found;
}

/* Whether the shell command exits 0; its output goes to log and, when it fails, to
 * stderr, so the reader's complaint is seen. */
static int reader_accepts(const char *command, const char *log)
{
    char full[2 * COMMAND_MAX];
    snprintf(full, sizeof full, "%s > %s 2>&1", command, log);
    int accepted = run_command(full) == 0;
    if (!accepted) {
        char *said = read_text_file(log);
        fprintf(stderr, "test_png: '%s' failed: %s", command, said != NULL ? said : "\n");
        free(said);
    }
    return accepted;
}

/* truth: outside readers. tests/png_check.py decodes with Python's zlib (its own CRC-32,
 *   inflate and Adler-32) and checks the chunks, IHDR and filter bytes; its pixels must
 *   equal the pattern's bytes, made without the encoder. Where installed, pngcheck must
 *   find no error and ImageMagick (libpng) must decode the same bytes.
 * tolerance: none; bytes.
 * catches: any byte of the format another reader takes otherwise than png.c meant, at
 *   the sizes that reach the block boundaries (png_cases[]). */
static void test_png_outside_readers(struct check *t)
{
    int python = installed("python3", "outside reader tests/png_check.py");
    int pngcheck = installed("pngcheck", "outside reader pngcheck");
    int magick = installed("identify", "outside reader ImageMagick") &&
                 installed("stream", "outside reader ImageMagick");
    char png[NAME_MAX_BYTES], rgb[NAME_MAX_BYTES], decoded[NAME_MAX_BYTES], log[NAME_MAX_BYTES];
    temp_name(png, sizeof png, "png", "outside.png");
    temp_name(rgb, sizeof rgb, "png", "outside.rgb");
    temp_name(decoded, sizeof decoded, "png", "decoded.rgb");
    temp_name(log, sizeof log, "png", "outside.log");
    char command[COMMAND_MAX];
    for (size_t c = 0; c < N_PNG_CASES; c++) {
        CHECK(t, write_pattern_case(c, png, rgb) == 0);
        snprintf(command, sizeof command, "python3 tests/png_check.py %s %s", png, rgb);
        CHECK(t, !python || reader_accepts(command, log));
        snprintf(command, sizeof command, "pngcheck -q %s", png);
        CHECK(t, !pngcheck || reader_accepts(command, log));
        snprintf(command, sizeof command, "stream -map rgb -storage-type char %s %s", png,
                 decoded);
        CHECK(t, !magick || (reader_accepts(command, log) && files_equal(decoded, rgb)));
        remove(decoded);
    }
    remove(png);
    remove(rgb);
    remove(log);
}

/* truth: outputs are whole or absent (README): a PNG written into a directory that
 *   does not exist fails with an error naming the file and leaves neither it nor its
 *   temporary (test_cli.c checks a failure after the bytes were written).
 * catches: a crash on a NULL stream, a success status for a failed write, a stray file. */
static void test_png_write_fails_cleanly(struct check *t)
{
    char dir[NAME_MAX_BYTES], name[2 * NAME_MAX_BYTES];
    temp_name(dir, sizeof dir, "png", "no_such_dir");
    snprintf(name, sizeof name, "%s/out.png", dir);
    struct image *img = image_create(3, 2);
    struct error err;
    CHECK(t, png_write(name, img, 1.0, &err) == -1 && strcmp(err.file, name) == 0);
    CHECK(t, !file_exists(name) && no_temporaries(name));
    image_free(img);
}

void test_png(struct check *t)
{
    RUN_TEST(t, test_png_bytes_by_hand);
    RUN_TEST(t, test_png_matches_ppm);
    RUN_TEST(t, test_png_outside_readers);
    RUN_TEST(t, test_png_write_fails_cleanly);
}
