/*
 * image/pfm.c -- Portable Float Map files, the format of photon's reference images.
 *
 * A colour PFM is a short text header followed by raw IEEE-754 binary32 floats:
 *
 *   "PF" ws WIDTH ws HEIGHT ws SCALE one-ws-byte DATA
 *
 * ws is one or more whitespace bytes. DATA is WIDTH * HEIGHT RGB triples, rows from the
 * BOTTOM of the picture to the top, each row left to right; image.h keeps row 0 at the top,
 * and this file alone does the flip. SCALE < 0 means little-endian floats, > 0 big-endian,
 * and |SCALE| multiplies every value (as pbrt reads it); we always write -1.0.
 *
 * The reader also skips '#' comment lines between header fields, which some writers put
 * there; the writer writes none, since other readers refuse them (netpbm's pfmtopam does,
 * so a crop's window goes in a file of its own: app/tile.h). Greyscale "Pf" files are
 * refused: a reference is colour. Every size is checked, and the data's length compared
 * with it, before the image is allocated.
 *
 * Byte order is assembled by hand from the float's bits, so the file is the same on hosts
 * of either endianness; the one assumption is that float is IEEE binary32 (checked below)
 * with the same byte order as uint32_t. double <-> float happens in exactly two functions,
 * float_bits() and float_value().
 */
#include "image.h"

#include "../base/input.h"
#include "../base/number.h"
#include "../base/output.h"

#include <assert.h>
#include <errno.h>
#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define PFM_TOKEN_MAX 64   /* longest header field: any sensible spelling of a number */
#define PFM_PIXEL_BYTES 12 /* three binary32 channels */

extern char pfm_float_is_binary32[sizeof(float) == 4 && FLT_MANT_DIG == 24 ? 1 : -1];

struct pfm_header {
    int width, height; /* 1..MAX_IMAGE_SIDE each        */
    double scale;      /* finite, non-zero; < 0: little-endian */
};

/* The one place a double becomes a file float: rounded to nearest (C99 6.3.1.5, default
 * rounding mode). A finite double beyond the float range would be undefined to convert
 * (and Inf under IEEE), so it saturates to +-FLT_MAX; pfm_write() refuses such an image
 * first (check_float_range), so only the display image, clamped anyway, sees it. */
static uint32_t float_bits(double value)
{
    assert(isfinite(value)); /* the renderer lets no NaN or Inf reach an image */
    float f = (float)fmax(-FLT_MAX, fmin(FLT_MAX, value));
    uint32_t bits;
    memcpy(&bits, &f, sizeof bits);
    return bits;
}

/* The one place a file float becomes a double: exact, as every float is a double. */
static double float_value(uint32_t bits)
{
    float f;
    memcpy(&f, &bits, sizeof f);
    return (double)f;
}

double pfm_stored_value(double v)
{
    return float_value(float_bits(v));
}

static void put_little_endian(uint32_t bits, FILE *f)
{
    for (int i = 0; i < 4; i++)
        putc((int)((bits >> (8 * i)) & 0xFF), f);
}

int image_check_float_range(const char *name, const struct image *img, const char *format,
                            struct error *err)
{
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            struct vec3 v = image_get(img, x, y);
            double m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
            if (m > FLT_MAX) {
                error_set(err, name, 0, "pixel (%d, %d) from the top left holds %g, beyond "
                          "%s float range (%g): the scene's units give more radiance than a "
                          "float holds (scale the scene up or its lights down)", x, y, m,
                          format, FLT_MAX);
                if (err != NULL)
                    err->failed_write = 1;
                return -1;
            }
        }
    return 0;
}

int pfm_write(const char *name, const struct image *img, struct error *err)
{
    if (image_check_float_range(name, img, "a PFM's", err) < 0)
        return -1;
    FILE *f = output_open(name, err);
    if (f == NULL)
        return -1;
    fprintf(f, "PF\n%d %d\n-1.0\n", img->width, img->height);
    for (int y = img->height - 1; y >= 0; y--) { /* the file's rows run bottom to top */
        for (int x = 0; x < img->width; x++) {
            struct vec3 v = image_get(img, x, y);
            put_little_endian(float_bits(v.x), f);
            put_little_endian(float_bits(v.y), f);
            put_little_endian(float_bits(v.z), f);
        }
    }
    return output_commit(f, err); /* a failed write shows in ferror(), checked there */
}

/* The bytes C's isspace() accepts in the "C" locale, independent of the locale in force. */
static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/* "PF" and one whitespace byte. */
static int read_magic(FILE *f, const char *name, struct error *err)
{
    errno = 0;
    int c0 = getc(f);
    int c1 = getc(f);
    int c2 = getc(f);
    if (ferror(f))
        return error_set(err, name, 0, "cannot be read: %s", input_failure());
    if (c0 == EOF)
        return error_set(err, name, 0, "empty file, expected a PFM image");
    if (c0 == 'P' && c1 == 'f')
        return error_set(err, name, 0, "greyscale PFM (\"Pf\") is not supported: "
                                       "a reference image must be colour (\"PF\")");
    if (c0 != 'P' || c1 != 'F' || !is_space(c2))
        return error_set(err, name, 0, "not a colour PFM file: it must start with \"PF\" "
                                       "and a line break");
    return 0;
}

/* Skips whitespace and '#' comment lines; returns the byte after them, or EOF. */
static int skip_separators(FILE *f)
{
    int c;
    do {
        c = getc(f);
        if (c == '#')
            while (c != '\n' && c != EOF)
                c = getc(f);
    } while (is_space(c));
    return c;
}

/* Reads one header field (the non-space bytes after the separators) into
 * token[PFM_TOKEN_MAX] and consumes exactly one whitespace byte after it, so that after
 * the scale the stream stands at the first data byte, whatever its value. */
static int read_token(FILE *f, const char *name, const char *field, char *token,
                      struct error *err)
{
    size_t n = 0;
    int c = skip_separators(f);
    while (c != EOF && !is_space(c)) {
        if (n + 1 == PFM_TOKEN_MAX)
            return error_set(err, name, 0, "header: the %s is too long", field);
        token[n++] = (char)c;
        c = getc(f);
    }
    token[n] = '\0';
    if (c == EOF)
        return error_set(err, name, 0, "truncated header: the file ends at the %s", field);
    return 0;
}

/* WIDTH or HEIGHT: a whole number in 1..MAX_IMAGE_SIDE. */
static int parse_side(const char *token, const char *name, const char *field, int *side,
                      struct error *err)
{
    double value;
    if (!number_parse(token, 1, &value))
        return error_set(err, name, 0, "header: %s '%s' is not a whole number", field, token);
    if (value < 1 || value > MAX_IMAGE_SIDE)
        return error_set(err, name, 0, "header: %s %s is outside 1..%d", field, token,
                         MAX_IMAGE_SIDE);
    *side = (int)value;
    return 0;
}

static int parse_scale(const char *token, const char *name, double *scale, struct error *err)
{
    if (!number_parse(token, 0, scale) || *scale == 0)
        return error_set(err, name, 0, "header: scale '%s' must be a finite non-zero number "
                                       "(negative for little-endian data)", token);
    return 0;
}

static int read_header(FILE *f, const char *name, struct pfm_header *h, struct error *err)
{
    char token[PFM_TOKEN_MAX];
    if (read_magic(f, name, err) != 0
        || read_token(f, name, "width", token, err) != 0
        || parse_side(token, name, "width", &h->width, err) != 0
        || read_token(f, name, "height", token, err) != 0
        || parse_side(token, name, "height", &h->height, err) != 0
        || read_token(f, name, "scale", token, err) != 0)
        return -1;
    return parse_scale(token, name, &h->scale, err);
}

/* Refuses data that is not exactly width * height pixels long, before anything is
 * allocated for it; leaves the stream at the first data byte. */
static int check_data_size(FILE *f, const char *name, const struct pfm_header *h,
                           struct error *err)
{
    long start = ftell(f);
    if (start < 0 || fseek(f, 0, SEEK_END) != 0)
        return error_set(err, name, 0, "cannot measure the file (not a regular file?)");
    long end = ftell(f);
    if (end < 0 || fseek(f, start, SEEK_SET) != 0)
        return error_set(err, name, 0, "cannot measure the file (not a regular file?)");
    long long have = (long long)end - start;
    long long need = (long long)PFM_PIXEL_BYTES * h->width * h->height;
    if (have != need)
        return error_set(err, name, 0, "pixel data is %lld bytes, but %dx%d RGB floats need "
                                       "%lld", have, h->width, h->height, need);
    return 0;
}

/* The float whose four bytes start at b, in the file's byte order. */
static double decode_float(const unsigned char *b, int little_endian)
{
    uint32_t bits = little_endian
        ? (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24
        : (uint32_t)b[3] | (uint32_t)b[2] << 8 | (uint32_t)b[1] << 16 | (uint32_t)b[0] << 24;
    return float_value(bits);
}

/* The pixels after the header; a value that is NaN or infinite is refused, but for +Inf
 * when plus_infinity is set. */
static int read_pixels(FILE *f, const char *name, const struct pfm_header *h,
                       struct image *img, int plus_infinity, struct error *err)
{
    int little_endian = h->scale < 0;
    double magnitude = fabs(h->scale);
    for (int y = img->height - 1; y >= 0; y--) { /* the file's rows run bottom to top */
        for (int x = 0; x < img->width; x++) {
            unsigned char b[PFM_PIXEL_BYTES];
            if (fread(b, 1, sizeof b, f) != sizeof b)
                return error_set(err, name, 0, "truncated pixel data");
            struct vec3 v = vec3_scale(vec3(decode_float(b, little_endian),
                                            decode_float(b + 4, little_endian),
                                            decode_float(b + 8, little_endian)), magnitude);
            int allowed = vec3_is_finite(v) ||
                          (plus_infinity && !isnan(v.x + v.y + v.z) &&
                           v.x != -HUGE_VAL && v.y != -HUGE_VAL && v.z != -HUGE_VAL);
            if (!allowed)
                return error_set(err, name, 0, "pixel (%d, %d) from the top left is NaN or "
                                 "infinite: photon reads only finite images%s", x, y,
                                 plus_infinity ? " and +Inf bounds" : "");
            image_set(img, x, y, v);
        }
    }
    return 0;
}

static struct image *read_pfm(const char *name, int plus_infinity, struct error *err)
{
    struct pfm_header h;
    struct image *img = NULL;
    struct input in;
    if (input_open(&in, name, err) < 0)
        return NULL;
    if (read_header(in.f, name, &h, err) != 0 || check_data_size(in.f, name, &h, err) != 0)
        goto fail;
    img = image_create(h.width, h.height);
    if (read_pixels(in.f, name, &h, img, plus_infinity, err) != 0)
        goto fail;
    input_close(&in);
    return img;
fail:
    image_free(img);
    input_close(&in);
    return NULL;
}

struct image *pfm_read(const char *name, struct error *err)
{
    return read_pfm(name, 0, err);
}

struct image *pfm_read_bounds(const char *name, struct error *err)
{
    return read_pfm(name, 1, err);
}
