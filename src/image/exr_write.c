/*
 * image/exr_write.c -- writing a struct image as a scanline OpenEXR file (exr.h).
 *
 * The simplest file every OpenEXR reader takes: FLOAT channels B, G, R (a channel list is
 * sorted by name), no compression (so one row a chunk), the data and display windows both
 * (0, 0) - (width - 1, height - 1), INCREASING_Y, and the other attributes the format
 * requires (pixelAspectRatio 1, screenWindowCenter (0, 0), screenWindowWidth 1). Each
 * double is rounded to the nearest float as pfm.c rounds it, so a PFM and an OpenEXR
 * written from one image hold the same floats, and exr_read() gives them back exactly.
 */
#include "exr.h"

#include <stdint.h>
#include <string.h>

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
    putc(EXR_NO_COMPRESSION, f);
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

int exr_write(const char *name, const struct image *img, struct error *err)
{
    if (image_check_float_range(name, img, "an OpenEXR FLOAT's", err) < 0)
        return -1;
    FILE *f = output_open(name, err);
    if (f == NULL)
        return -1;
    put_header(f, img);
    uint64_t row_bytes = (uint64_t)img->width * ROW_CHANNELS * 4;
    uint64_t first = header_bytes() + 8 * (uint64_t)img->height; /* after the table */
    for (int y = 0; y < img->height; y++)
        put_u64(first + (uint64_t)y * (8 + row_bytes), f);
    for (int y = 0; y < img->height; y++) {
        put_u32((uint32_t)y, f);
        put_u32((uint32_t)row_bytes, f);
        for (int c = ROW_CHANNELS - 1; c >= 0; c--) /* B, G, R: vec3's z, y, x */
            for (int x = 0; x < img->width; x++) {
                struct vec3 v = image_get(img, x, y);
                put_u32(float_bits(c == 0 ? v.x : c == 1 ? v.y : v.z), f);
            }
    }
    return output_commit(f, err); /* a failed write shows in ferror(), checked there */
}
