/*
 * image/exr_read.c -- reading a scanline OpenEXR file (exr.h) into a struct image.
 *
 * The whole file is read into memory first, so that every offset and length the file
 * states can be checked against its size before it is used. Then:
 *   - the magic number and version field: version 2, and no flag of a tiled, deep or
 *     multi-part file (each refused by name), nor an unknown one;
 *   - the header's attributes: channels, compression, dataWindow and lineOrder are used,
 *     the others (displayWindow, pixelAspectRatio, a writer's own) are skipped by their
 *     stated size. The data window is the image (the display window only frames it);
 *   - the offset table, one entry per chunk in the order of y, whichever the line order
 *     (DECREASING_Y changes where chunks stand in the file, not the table's order);
 *   - each chunk, checked to hold the rows the table says, decompressed (exr_decompress.c)
 *     unless its data is as long as the raw rows: a writer stores a chunk raw when
 *     compression would not make it shorter.
 * Values are checked once all are read: NaN and infinities refused (the pfm.c rules).
 */
#include "exr.h"

#include <errno.h>
#include <float.h>
#include <stdint.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/input.h"

#define EXR_MAX_CHANNELS 1024 /* far more than any renderer's output layers */
#define EXR_MAX_NAME 256      /* a long name (255 bytes) and its '\0'          */

/* Where a channel's values go in a pixel. */
enum channel_role { ROLE_SKIPPED = -1, ROLE_R, ROLE_G, ROLE_B, ROLE_Y };

struct channel {
    char name[EXR_MAX_NAME];
    enum exr_pixel_type type;
    enum channel_role role;
};

struct exr_header {
    struct channel channels[EXR_MAX_CHANNELS]; /* in the file's order: by name   */
    int n_channels;
    int compression;                  /* enum exr_compression; -1 before the attribute */
    long long x_min, y_min, x_max, y_max; /* the data window, inclusive             */
    int has_window;
    size_t pixel_bytes; /* one pixel's bytes over every channel                         */
    unsigned char channel_bytes[EXR_MAX_CHANNELS]; /* 2 or 4 each, for PIZ             */
    int grey;           /* Y alone: R = G = B = Y                                       */
};

/* The file's bytes and where the reader stands, for the messages too. */
struct reader {
    const unsigned char *bytes;
    size_t size, at;
    const char *name;
    struct error *err;
};

static int refuse(struct reader *r, const char *message)
{
    return error_set(r->err, r->name, 0, "%s", message);
}

static int need(struct reader *r, size_t n, const char *what)
{
    if (r->size - r->at < n)
        return error_set(r->err, r->name, 0, "the file ends inside %s", what);
    return 0;
}

static uint32_t u32_at(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

/* A 4-byte two's complement number (int in the spec). */
static long long i32_at(const unsigned char *b)
{
    uint32_t u = u32_at(b);
    return u < 0x80000000u ? (long long)u : (long long)u - 4294967296LL;
}

static int get_i32(struct reader *r, const char *what, long long *v)
{
    if (need(r, 4, what) < 0)
        return -1;
    *v = i32_at(r->bytes + r->at);
    r->at += 4;
    return 0;
}

/* A '\0'-ended name of at most max_len bytes into text[EXR_MAX_NAME]. */
static int get_name(struct reader *r, size_t max_len, const char *what, char *text)
{
    size_t n = 0;
    for (;;) {
        if (r->at == r->size)
            return error_set(r->err, r->name, 0, "the file ends inside %s", what);
        unsigned char c = r->bytes[r->at++];
        if (c == '\0')
            break;
        if (n == max_len)
            return error_set(r->err, r->name, 0, "%s is longer than %zu bytes", what, max_len);
        text[n++] = (char)c;
    }
    text[n] = '\0';
    return 0;
}

static int read_version(struct reader *r, size_t *max_name)
{
    if (r->size < 8 || i32_at(r->bytes) != EXR_MAGIC)
        return refuse(r, "not an OpenEXR file (its first 4 bytes are not 76 2f 31 01)");
    uint32_t version = u32_at(r->bytes + 4);
    r->at = 8;
    if (version & EXR_FLAG_TILED)
        return refuse(r, "tiled OpenEXR files are not read (only scanline files are)");
    if (version & EXR_FLAG_DEEP)
        return refuse(r, "deep OpenEXR files are not read (only scanline images are)");
    if (version & EXR_FLAG_MULTIPART)
        return refuse(r, "multi-part OpenEXR files are not read (only single-part ones are)");
    if ((version & 0xFF) != EXR_VERSION || (version & ~(0xFFu | EXR_FLAG_LONG_NAMES)) != 0)
        return error_set(r->err, r->name, 0, "OpenEXR version field 0x%08lx is not read "
                         "(version 2, scanline)", (unsigned long)version);
    *max_name = version & EXR_FLAG_LONG_NAMES ? 255 : 31;
    return 0;
}

/* The channel list: for each channel its name, pixel type (4 bytes), pLinear (1), three
 * reserved bytes, xSampling and ySampling (4 each); an empty name ends it. */
static int read_channels(struct reader *r, size_t end, size_t max_name, struct exr_header *h)
{
    struct reader list = *r;
    list.size = end; /* the attribute's value alone */
    for (;;) {
        char name[EXR_MAX_NAME];
        if (get_name(&list, max_name, "a channel's name", name) < 0)
            return -1;
        if (name[0] == '\0')
            break;
        if (h->n_channels == EXR_MAX_CHANNELS)
            return error_set(r->err, r->name, 0, "more than %d channels", EXR_MAX_CHANNELS);
        long long type, x_sampling, y_sampling;
        if (get_i32(&list, "the channel list", &type) < 0 || need(&list, 4, "the channel list") < 0)
            return -1;
        list.at += 4; /* pLinear and the reserved bytes */
        if (get_i32(&list, "the channel list", &x_sampling) < 0 ||
            get_i32(&list, "the channel list", &y_sampling) < 0)
            return -1;
        if (type < EXR_UINT || type > EXR_FLOAT)
            return error_set(r->err, r->name, 0, "channel %s: pixel type %lld is not UINT (0), "
                             "HALF (1) or FLOAT (2)", name, type);
        if (x_sampling != 1 || y_sampling != 1)
            return error_set(r->err, r->name, 0, "channel %s is subsampled (%lld x %lld): "
                             "not read", name, x_sampling, y_sampling);
        struct channel *c = &h->channels[h->n_channels++];
        strcpy(c->name, name);
        c->type = (enum exr_pixel_type)type;
        c->role = strcmp(name, "R") == 0 ? ROLE_R : strcmp(name, "G") == 0 ? ROLE_G
                : strcmp(name, "B") == 0 ? ROLE_B : strcmp(name, "Y") == 0 ? ROLE_Y
                : ROLE_SKIPPED;
        h->channel_bytes[h->n_channels - 1] = type == EXR_HALF ? 2 : 4;
        h->pixel_bytes += h->channel_bytes[h->n_channels - 1];
    }
    if (list.at != end)
        return refuse(r, "bytes follow the channel list inside its attribute");
    return 0;
}

/* The channels that make the image: R, G and B, else Y alone; any other is skipped. */
static int choose_channels(struct reader *r, struct exr_header *h)
{
    int has[4] = {0, 0, 0, 0};
    int chroma = 0;
    for (int i = 0; i < h->n_channels; i++) {
        if (h->channels[i].role != ROLE_SKIPPED)
            has[h->channels[i].role] = 1;
        chroma |= strcmp(h->channels[i].name, "RY") == 0 || strcmp(h->channels[i].name, "BY") == 0;
    }
    if (has[ROLE_R] && has[ROLE_G] && has[ROLE_B]) {
        for (int i = 0; i < h->n_channels; i++)
            if (h->channels[i].role == ROLE_Y)
                h->channels[i].role = ROLE_SKIPPED;
        return 0;
    }
    if (has[ROLE_Y] && chroma)
        return refuse(r, "luminance-chroma files (channels Y, RY, BY) are not read");
    if (has[ROLE_Y] && !has[ROLE_R] && !has[ROLE_G] && !has[ROLE_B]) {
        h->grey = 1;
        return 0;
    }
    return refuse(r, "no image channels: photon reads the channels R, G and B, or Y alone "
                     "(layer names such as \"view.R\" are not read)");
}

/* One attribute's value, for the attributes used; the others are skipped. */
static int read_attribute(struct reader *r, const char *name, const char *type, size_t size,
                          size_t max_name, struct exr_header *h)
{
    const unsigned char *v = r->bytes + r->at;
    if (strcmp(name, "tiles") == 0)
        return refuse(r, "tiled OpenEXR files are not read (only scanline files are)");
    if (strcmp(name, "type") == 0 && strcmp(type, "string") == 0) {
        if (size >= 4 && memcmp(v, "deep", 4) == 0)
            return refuse(r, "deep OpenEXR files are not read (only scanline images are)");
        if (size >= 5 && memcmp(v, "tiled", 5) == 0)
            return refuse(r, "tiled OpenEXR files are not read (only scanline files are)");
    }
    if (strcmp(name, "channels") == 0 && strcmp(type, "chlist") == 0)
        return read_channels(r, r->at + size, max_name, h);
    if (strcmp(name, "compression") == 0 && strcmp(type, "compression") == 0 && size == 1) {
        h->compression = v[0];
        return 0;
    }
    if (strcmp(name, "dataWindow") == 0 && strcmp(type, "box2i") == 0 && size == 16) {
        h->x_min = i32_at(v);
        h->y_min = i32_at(v + 4);
        h->x_max = i32_at(v + 8);
        h->y_max = i32_at(v + 12);
        h->has_window = 1;
        return 0;
    }
    if (strcmp(name, "lineOrder") == 0 && strcmp(type, "lineOrder") == 0 && size == 1 &&
        v[0] > 2)
        return error_set(r->err, r->name, 0, "line order %d is not INCREASING_Y (0), "
                         "DECREASING_Y (1) or RANDOM_Y (2)", v[0]);
    return 0;
}

static const char *const compression_names[EXR_N_COMPRESSIONS] = {
    "NO", "RLE", "ZIPS", "ZIP", "PIZ", "PXR24", "B44", "B44A", "DWAA", "DWAB"};

static int check_header(struct reader *r, struct exr_header *h)
{
    if (h->n_channels == 0 || !h->has_window || h->compression < 0)
        return refuse(r, "the header lacks channels, compression or dataWindow");
    if (h->compression >= EXR_N_COMPRESSIONS)
        return error_set(r->err, r->name, 0, "compression %d is unknown", h->compression);
    if (h->compression > EXR_PIZ_COMPRESSION)
        return error_set(r->err, r->name, 0, "%s compression is not read (NO, RLE, ZIPS, "
                         "ZIP and PIZ are)", compression_names[h->compression]);
    long long width = h->x_max - h->x_min + 1, height = h->y_max - h->y_min + 1;
    if (width < 1 || width > MAX_IMAGE_SIDE || height < 1 || height > MAX_IMAGE_SIDE)
        return error_set(r->err, r->name, 0, "data window (%lld, %lld) - (%lld, %lld) is "
                         "not 1..%d pixels on each side", h->x_min, h->y_min, h->x_max,
                         h->y_max, MAX_IMAGE_SIDE);
    return choose_channels(r, h);
}

static int read_header(struct reader *r, struct exr_header *h)
{
    size_t max_name = 31;
    if (read_version(r, &max_name) < 0)
        return -1;
    h->n_channels = 0;
    h->compression = -1;
    h->has_window = 0;
    h->pixel_bytes = 0;
    h->grey = 0;
    for (;;) {
        char name[EXR_MAX_NAME], type[EXR_MAX_NAME];
        long long size;
        if (get_name(r, max_name, "an attribute's name", name) < 0)
            return -1;
        if (name[0] == '\0')
            break;
        if (get_name(r, max_name, "an attribute's type", type) < 0 ||
            get_i32(r, "the header", &size) < 0)
            return -1;
        if (size < 0 || (unsigned long long)size > r->size - r->at)
            return error_set(r->err, r->name, 0, "attribute %s: its size %lld runs past the "
                             "end of the file", name, size);
        if (read_attribute(r, name, type, (size_t)size, max_name, h) < 0)
            return -1;
        r->at += (size_t)size;
    }
    return check_header(r, h);
}

/* The value of a HALF: sign, 5 bits of exponent (bias 15), 10 of fraction. */
static double half_value(uint32_t bits)
{
    int exponent = (int)(bits >> 10 & 0x1F), fraction = (int)(bits & 0x3FF);
    double v = exponent == 0    ? ldexp(fraction, -24) /* subnormal: fraction * 2^-24 */
               : exponent == 31 ? (fraction == 0 ? HUGE_VAL : NAN)
                                : ldexp(fraction + 1024, exponent - 25);
    return bits & 0x8000 ? -v : v;
}

static double float_value(uint32_t bits)
{
    float f;
    memcpy(&f, &bits, sizeof f); /* float is binary32 with uint32_t's byte order: pfm.c */
    return (double)f;
}

/* Rows y0 .. y0 + n_rows - 1 of the image from the raw rows at p. */
static void decode_rows(const struct exr_header *h, const unsigned char *p, int y0,
                        int n_rows, struct image *img)
{
    for (int row = y0; row < y0 + n_rows; row++)
        for (int c = 0; c < h->n_channels; c++) {
            const struct channel *ch = &h->channels[c];
            for (int x = 0; x < img->width; x++) {
                double v = ch->type == EXR_HALF  ? half_value((uint32_t)p[0] | (uint32_t)p[1] << 8)
                           : ch->type == EXR_FLOAT ? float_value(u32_at(p))
                                                   : (double)u32_at(p);
                p += ch->type == EXR_HALF ? 2 : 4;
                struct vec3 *px = &img->pixels[(size_t)row * (size_t)img->width + (size_t)x];
                if (ch->role == ROLE_R || ch->role == ROLE_Y)
                    px->x = v;
                if (ch->role == ROLE_G || ch->role == ROLE_Y)
                    px->y = v;
                if (ch->role == ROLE_B || ch->role == ROLE_Y)
                    px->z = v;
            }
        }
}

/* Chunk i of n_chunks, whose table entry stands at table: checked, decompressed into raw
 * (room for a whole block of rows), decoded into img. */
static int read_chunk(struct reader *r, const struct exr_header *h, size_t table, long long i,
                      unsigned char *raw, struct image *img)
{
    int lines = exr_lines_per_block((enum exr_compression)h->compression);
    const unsigned char *entry = r->bytes + table + 8 * (size_t)i;
    uint64_t offset = (uint64_t)u32_at(entry) | (uint64_t)u32_at(entry + 4) << 32;
    if (offset < table || offset > r->size || r->size - offset < 8)
        return error_set(r->err, r->name, 0, "chunk %lld: its offset %llu is outside the "
                         "file's chunks", i, (unsigned long long)offset);
    const unsigned char *chunk = r->bytes + offset;
    long long y = i32_at(chunk), data_size = i32_at(chunk + 4);
    if (y != h->y_min + i * lines)
        return error_set(r->err, r->name, 0, "chunk %lld starts at y = %lld, not at %lld",
                         i, y, h->y_min + i * lines);
    if (data_size <= 0 || (uint64_t)data_size > r->size - offset - 8)
        return error_set(r->err, r->name, 0, "chunk %lld: its data size %lld runs past the "
                         "end of the file", i, data_size);
    int y0 = (int)(y - h->y_min);
    int n_rows = img->height - y0 < lines ? img->height - y0 : lines;
    size_t raw_size = (size_t)n_rows * (size_t)img->width * h->pixel_bytes;
    const unsigned char *data = chunk + 8;
    if ((uint64_t)data_size > raw_size ||
        (h->compression == EXR_NO_COMPRESSION && (size_t)data_size != raw_size))
        return error_set(r->err, r->name, 0, "chunk %lld holds %lld bytes, but its %d rows "
                         "are %zu bytes raw", i, data_size, n_rows, raw_size);
    const char *message = NULL;
    struct exr_block block = {img->width, n_rows, h->n_channels, h->channel_bytes};
    if ((size_t)data_size == raw_size) /* stored raw: compression would not shorten it */
        memcpy(raw, data, raw_size);
    else if (exr_decompress((enum exr_compression)h->compression, &block, data,
                            (size_t)data_size, raw, raw_size, &message) < 0)
        return error_set(r->err, r->name, 0, "chunk %lld (%s compression): %s", i,
                         compression_names[h->compression], message);
    decode_rows(h, raw, y0, n_rows, img);
    return 0;
}

/* The rules of pfm.c: finite values only, +Inf too for an error image's bounds. */
static int check_values(struct reader *r, const struct image *img, int plus_infinity)
{
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            struct vec3 v = image_get(img, x, y);
            int allowed = vec3_is_finite(v) ||
                          (plus_infinity && !isnan(v.x + v.y + v.z) &&
                           v.x != -HUGE_VAL && v.y != -HUGE_VAL && v.z != -HUGE_VAL);
            if (!allowed)
                return error_set(r->err, r->name, 0, "pixel (%d, %d) from the top left is NaN "
                                 "or infinite: photon reads only finite images%s", x, y,
                                 plus_infinity ? " and +Inf bounds" : "");
        }
    return 0;
}

/* The header, the table and every chunk, into a new image; NULL with r->err filled. */
static struct image *read_image(struct reader *r, int plus_infinity)
{
    struct exr_header *h = xmalloc(1, sizeof *h, "an OpenEXR header");
    struct image *img = NULL;
    unsigned char *raw = NULL;
    if (read_header(r, h) < 0)
        goto fail;
    int width = (int)(h->x_max - h->x_min + 1), height = (int)(h->y_max - h->y_min + 1);
    int lines = exr_lines_per_block((enum exr_compression)h->compression);
    long long n_chunks = (height + lines - 1) / lines;
    size_t table = r->at;
    if ((uint64_t)n_chunks > (r->size - table) / 8) {
        refuse(r, "the file ends inside its table of chunk offsets");
        goto fail;
    }
    /* Before the image is allocated: no compression read here makes data more than 1032
     * times shorter (deflate's limit; PIZ's runs reach about 450, RLE's 64), so a file too
     * short for its window is refused, not allocated for. */
    double raw_total = (double)width * height * (double)h->pixel_bytes;
    double ratio = h->compression == EXR_NO_COMPRESSION    ? 1
                   : h->compression == EXR_RLE_COMPRESSION ? 64
                                                           : 1032;
    if (raw_total > ratio * (double)(r->size - table)) {
        error_set(r->err, r->name, 0, "the file is too short for its %d x %d pixels of %zu "
                  "bytes (%s compression)", width, height, h->pixel_bytes,
                  compression_names[h->compression]);
        goto fail;
    }
    img = image_create(width, height);
    raw = xmalloc((size_t)(lines < height ? lines : height) * (size_t)width, h->pixel_bytes,
                  "an OpenEXR chunk");
    for (long long i = 0; i < n_chunks; i++)
        if (read_chunk(r, h, table, i, raw, img) < 0)
            goto fail;
    if (check_values(r, img, plus_infinity) < 0)
        goto fail;
    xfree(raw);
    xfree(h);
    return img;
fail:
    xfree(raw);
    xfree(h);
    image_free(img);
    return NULL;
}

struct image *exr_read(const char *name, int plus_infinity, struct error *err)
{
    struct input in;
    if (input_open(&in, name, err) < 0)
        return NULL;
    unsigned char *bytes = xmalloc(in.size > 0 ? (size_t)in.size : 1, 1, "an OpenEXR file");
    struct image *img = NULL;
    errno = 0;
    size_t got = fread(bytes, 1, (size_t)in.size, in.f);
    if (ferror(in.f))
        error_set(err, name, 0, "cannot read the file's %ld bytes: %s", in.size,
                  input_failure());
    else if (got != (size_t)in.size) /* shorter than input_open() measured */
        error_set(err, name, 0, "the file ends after %zu of the %ld bytes it had when "
                  "opened (not a regular file?)", got, in.size);
    else {
        struct reader r = {bytes, (size_t)in.size, 0, name, err};
        img = read_image(&r, plus_infinity);
    }
    xfree(bytes);
    input_close(&in);
    return img;
}
