/*
 * image/exr_write.c -- writing a struct image as a scanline OpenEXR file (exr.h).
 *
 * A file every OpenEXR reader takes: FLOAT channels B, G, R (a channel list is sorted by
 * name), ZIP compression, the data and display windows both (0, 0) - (width - 1,
 * height - 1), INCREASING_Y, and the other attributes the format requires
 * (pixelAspectRatio 1, screenWindowCenter (0, 0), screenWindowWidth 1): the header
 * OpenEXR's library writes for such an image, byte for byte. Each double is rounded to the
 * nearest float as pfm.c rounds it, so a PFM and an OpenEXR written from one image hold
 * the same floats, and exr_read() gives them back exactly.
 *
 * A ZIP chunk ("OpenEXR File Layout": ZIP_COMPRESSION, 16 scanlines) is its rows' raw bytes
 * (each row its B values, then G, then R, as an uncompressed file holds them), interleaved
 * and predicted (exr_decompress.c), in one zlib stream (base/deflate.h). A chunk that
 * deflate does not shorten is stored raw: every reader takes a chunk whose data is as long
 * as its raw rows as raw, so compression never costs a byte. The chunks' offsets are
 * known only once they are written: the offset table is written as zeros first and
 * filled in at the end, as OpenEXR's library does too.
 *
 * There is no uncompressed choice: ZIP is lossless, it is the OpenEXR library's own
 * default (so every reader reads it), and a chunk it does not shrink is raw anyway.
 */
#include "exr.h"

#include <assert.h>
#include <stdint.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/deflate.h"
#include "../base/output.h"

#define ROW_CHANNELS 3 /* B, G, R */

static void put_u32(uint32_t v, FILE *f)
{
    for (int i = 0; i < 4; i++)
        putc((int)(v >> (8 * i) & 0xFF), f);
}

static void put_u64(uint64_t v, FILE *f)
{
    put_u32((uint32_t)(v & 0xFFFFFFFFu), f);
    put_u32((uint32_t)(v >> 32), f);
}

static uint32_t float_bits(double value)
{
    float f = (float)pfm_stored_value(value); /* exact: already a float's value */
    uint32_t bits;
    memcpy(&bits, &f, sizeof bits);
    return bits;
}

/* An attribute's name, type name and size; its value follows. */
static void put_attribute(FILE *f, const char *name, const char *type, uint32_t size)
{
    fwrite(name, 1, strlen(name) + 1, f);
    fwrite(type, 1, strlen(type) + 1, f);
    put_u32(size, f);
}

static void put_float(FILE *f, float value)
{
    uint32_t bits;
    memcpy(&bits, &value, sizeof bits);
    put_u32(bits, f);
}

/* The header (attributes in alphabetical order, as OpenEXR's own writer puts them). */
static void put_header(FILE *f, const struct image *img)
{
    static const char *const channels[ROW_CHANNELS] = {"B", "G", "R"};
    put_u32((uint32_t)EXR_MAGIC, f);
    put_u32(EXR_VERSION, f); /* no flags: a single-part scanline file, short names */
    put_attribute(f, "channels", "chlist", ROW_CHANNELS * (2 + 16) + 1);
    for (int c = 0; c < ROW_CHANNELS; c++) {
        fwrite(channels[c], 1, 2, f); /* the name and its '\0' */
        put_u32(EXR_FLOAT, f);
        put_u32(0, f); /* pLinear 0 and three reserved bytes */
        put_u32(1, f); /* xSampling */
        put_u32(1, f); /* ySampling */
    }
    putc(0, f);
    put_attribute(f, "compression", "compression", 1);
    putc(EXR_ZIP_COMPRESSION, f);
    for (int w = 0; w < 2; w++) {
        put_attribute(f, w == 0 ? "dataWindow" : "displayWindow", "box2i", 16);
        put_u32(0, f);
        put_u32(0, f);
        put_u32((uint32_t)(img->width - 1), f);
        put_u32((uint32_t)(img->height - 1), f);
    }
    put_attribute(f, "lineOrder", "lineOrder", 1);
    putc(0, f); /* INCREASING_Y */
    put_attribute(f, "pixelAspectRatio", "float", 4);
    put_float(f, 1.0f);
    put_attribute(f, "screenWindowCenter", "v2f", 8);
    put_float(f, 0.0f);
    put_float(f, 0.0f);
    put_attribute(f, "screenWindowWidth", "float", 4);
    put_float(f, 1.0f);
    putc(0, f); /* the header's end */
}

/* The header's length in bytes, for the offset table: put_header()'s bytes counted. */
static uint64_t header_bytes(void)
{
    uint64_t n = 8;
    n += sizeof "channels" + sizeof "chlist" + 4 + ROW_CHANNELS * (2 + 16) + 1;
    n += sizeof "compression" + sizeof "compression" + 4 + 1;
    n += sizeof "dataWindow" + sizeof "box2i" + 4 + 16;
    n += sizeof "displayWindow" + sizeof "box2i" + 4 + 16;
    n += sizeof "lineOrder" + sizeof "lineOrder" + 4 + 1;
    n += sizeof "pixelAspectRatio" + sizeof "float" + 4 + 4;
    n += sizeof "screenWindowCenter" + sizeof "v2f" + 4 + 8;
    n += sizeof "screenWindowWidth" + sizeof "float" + 4 + 4;
    return n + 1;
}

/* v's 4 bytes at p, lowest first. */
static void u32_to(unsigned char *p, uint32_t v)
{
    for (int i = 0; i < 4; i++)
        p[i] = (unsigned char)(v >> (8 * i) & 0xFF);
}

/* The raw bytes of rows y0 .. y0 + n_rows - 1 into raw: each row's B, G, R values in turn. */
static void fill_rows(const struct image *img, int y0, int n_rows, unsigned char *raw)
{
    for (int y = y0; y < y0 + n_rows; y++)
        for (int c = ROW_CHANNELS - 1; c >= 0; c--) /* B, G, R: vec3's z, y, x */
            for (int x = 0; x < img->width; x++) {
                struct vec3 v = image_get(img, x, y);
                u32_to(raw, float_bits(c == 0 ? v.x : c == 1 ? v.y : v.z));
                raw += 4;
            }
}

static void put_table(FILE *f, const uint64_t *offsets, size_t n_chunks)
{
    for (size_t i = 0; i < n_chunks; i++)
        put_u64(offsets[i], f);
}

/* Every chunk, the first at file position first: its first row's y, its data's size, its
 * data, compressed or raw (above). Sets offsets[i] to chunk i's position. */
static void put_chunks(FILE *f, const struct image *img, uint64_t first, uint64_t *offsets)
{
    int lines = exr_lines_per_block(EXR_ZIP_COMPRESSION);
    size_t row_bytes = (size_t)img->width * ROW_CHANNELS * 4;
    size_t most = (size_t)(img->height < lines ? img->height : lines) * row_bytes;
    unsigned char *raw = xmalloc(3, most, "an OpenEXR chunk"); /* and the two below */
    unsigned char *predicted = raw + most, *packed = raw + 2 * most;
    for (int i = 0, y = 0; y < img->height; i++, y += lines) {
        int n_rows = img->height - y < lines ? img->height - y : lines;
        size_t n = (size_t)n_rows * row_bytes;
        fill_rows(img, y, n_rows, raw);
        exr_interleave_and_predict(raw, n, predicted);
        size_t packed_size = zlib_deflate(predicted, n, packed, n - 1); /* 0: not shorter */
        size_t size = packed_size > 0 ? packed_size : n;
        offsets[i] = first;
        put_u32((uint32_t)y, f);
        put_u32((uint32_t)size, f);
        fwrite(packed_size > 0 ? packed : raw, 1, size, f);
        first += 8 + size;
    }
    xfree(raw);
}

int exr_write(const char *name, const struct image *img, struct error *err)
{
    if (image_check_float_range(name, img, "an OpenEXR FLOAT's", err) < 0)
        return -1;
    FILE *f = output_open(name, err);
    if (f == NULL)
        return -1;
    int lines = exr_lines_per_block(EXR_ZIP_COMPRESSION);
    size_t n_chunks = (size_t)((img->height + lines - 1) / lines);
    uint64_t *offsets = xcalloc(n_chunks, sizeof *offsets, "an OpenEXR offset table");
    put_header(f, img);
    put_table(f, offsets, n_chunks); /* zeros, until the chunks are written */
    put_chunks(f, img, header_bytes() + 8 * (uint64_t)n_chunks, offsets);
    /* Going back flushes the chunks' last bytes, so a full disk fails the seek, and C99
     * then sets the stream's error (7.19.9.2): the table is not written, and the commit
     * reports the failure with its reason. Nothing else fails a seek to a small offset of
     * our temporary, a regular file. */
    int back = fseek(f, (long)header_bytes(), SEEK_SET) == 0;
    assert(back || ferror(f));
    if (back)
        put_table(f, offsets, n_chunks);
    xfree(offsets);
    return output_commit(f, err); /* a failed write shows in ferror(), checked there */
}
