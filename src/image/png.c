/*
 * image/png.c -- PNG (ISO/IEC 15948, the W3C PNG Second Edition; RFC 2083 is PNG 1.0, the
 * same bytes for all used here), the display image written beside the PFM by default.
 *
 * The file, with section numbers of ISO/IEC 15948:
 *   signature  137 80 78 71 13 10 26 10                                      (Sec. 5.2)
 *   IHDR       width, height; bit depth 8, colour type 2 (RGB), compression 0,
 *              filter method 0, interlace 0                                  (Sec. 11.2.2)
 *   IDAT ...   the zlib stream of the scanlines, one stored block per chunk  (Sec. 11.2.4)
 *   IEND       no data                                                       (Sec. 11.2.5)
 * A chunk is its data's length, its 4-letter type, the data, and the CRC-32 of type and
 * data (Sec. 5.3); every multi-byte integer is big-endian (Sec. 7.1), put_u32() alone.
 * The scanlines, top row first, are each filter-type byte 0 ("None", Sec. 9.2) followed
 * by R G B of each pixel left to right: display_encode()'s bytes, the PPM's (or a
 * picture's bytes made beforehand, png_write_bytes()).
 *
 * The zlib stream (RFC 1950) is uncompressed deflate (RFC 1951, Sec. 3.2.4: stored
 * blocks): compressing is a program of its own, and the display image is a convenience
 * beside the PFM of record. Stored blocks cost 5 bytes per 65535, and the zlib header and
 * trailer 6 in all. The writer keeps one block in memory and sends it as one IDAT chunk,
 * so an image of any size is written in constant memory and no chunk nears PNG's limit
 * of 2^31 - 1 bytes. Written atomically through output_open()/output_commit().
 */
#include "png.h"

#include <stdint.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/inflate.h"
#include "../base/output.h"

#define STORED_BLOCK_MAX 65535 /* RFC 1951 Sec. 3.2.4: LEN is 16 bits                */
#define FILTER_NONE 0          /* ISO/IEC 15948 Sec. 9.2: filter type 0, bytes as they are */

/* One PNG being written: the CRC table, the running Adler-32 and the block of raw
 * (filtered) scanline bytes not yet sent. */
struct png_stream {
    FILE *f;                 /* borrowed: output_open()'s stream                 */
    uint32_t crc_table[256]; /* the CRC of each byte value (make_crc_table)      */
    uint32_t crc;            /* the CRC register of the chunk being written      */
    uint32_t adler;          /* Adler-32 of every raw byte so far                */
    int header_sent;         /* whether the zlib header went out                 */
    size_t n;                /* raw bytes waiting in block[], <= STORED_BLOCK_MAX */
    unsigned char block[STORED_BLOCK_MAX]; /* the next stored block's bytes      */
};

/* The big-endian 32-bit integer of Sec. 7.1, into out[0..3]. */
static void put_u32(unsigned char *out, uint32_t v)
{
    out[0] = (unsigned char)(v >> 24);
    out[1] = (unsigned char)((v >> 16) & 0xFF);
    out[2] = (unsigned char)((v >> 8) & 0xFF);
    out[3] = (unsigned char)(v & 0xFF);
}

/* Sec. 5.5 and Annex D: the CRC-32 of ISO 3309 and ITU-T V.42, polynomial
 * x^32+x^26+x^23+x^22+x^16+x^12+x^11+x^10+x^8+x^7+x^5+x^4+x^2+x+1 with bits taken
 * least significant first, hence its reflection 0xEDB88320; table[n] is byte n's CRC. */
static void make_crc_table(uint32_t table[256])
{
    for (uint32_t n = 0; n < 256; n++) {
        uint32_t c = n;
        for (int k = 0; k < 8; k++)
            c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        table[n] = c;
    }
}

/* Writes bytes into the open chunk, folding them into its CRC (Annex D's update_crc). */
static void chunk_put(struct png_stream *s, const unsigned char *bytes, size_t n)
{
    for (size_t i = 0; i < n; i++)
        s->crc = s->crc_table[(s->crc ^ bytes[i]) & 0xFF] ^ (s->crc >> 8);
    fwrite(bytes, 1, n, s->f);
}

/* Sec. 5.3: length (not in the CRC), then the type, the first bytes the CRC covers; the
 * register starts as all ones (Sec. 5.5). */
static void chunk_begin(struct png_stream *s, const char *type, uint32_t length)
{
    unsigned char bytes[4];
    put_u32(bytes, length);
    fwrite(bytes, 1, 4, s->f);
    s->crc = 0xFFFFFFFFu;
    chunk_put(s, (const unsigned char *)type, 4);
}

/* Sec. 5.5: the CRC is the register complemented, after the chunk's data. */
static void chunk_end(struct png_stream *s)
{
    unsigned char bytes[4];
    put_u32(bytes, s->crc ^ 0xFFFFFFFFu);
    fwrite(bytes, 1, 4, s->f);
}

/* Sends block[] as one IDAT chunk holding one stored block (RFC 1951 Sec. 3.2.4): a
 * header byte of BFINAL (bit 0) and BTYPE 00 (bits 1-2, Sec. 3.2.3), then LEN and its
 * one's complement NLEN, 16 bits each with the least significant byte first (Sec. 3.1.1),
 * then the LEN bytes. The first chunk opens the zlib stream with its header, the final
 * one closes it with the Adler-32 of all the raw bytes (RFC 1950 Sec. 2.2). */
static void send_block(struct png_stream *s, int final)
{
    /* RFC 1950 Sec. 2.2: CMF 0x78 is CM 8 (deflate) with CINFO 7 (a 32 KiB window, the
     * most Sec. 10.1 of ISO/IEC 15948 allows); FLG 0x01 is FLEVEL 0, no preset dictionary,
     * and FCHECK 1, which makes CMF * 256 + FLG = 30721 a multiple of 31. */
    static const unsigned char zlib_header[2] = {0x78, 0x01};
    unsigned len = (unsigned)s->n, nlen = 0xFFFFu ^ len;
    unsigned char stored_header[5] = {(unsigned char)(final ? 1 : 0),
                                      (unsigned char)(len & 0xFF), (unsigned char)(len >> 8),
                                      (unsigned char)(nlen & 0xFF), (unsigned char)(nlen >> 8)};
    unsigned char adler[4];
    put_u32(adler, s->adler);
    int first = !s->header_sent;
    chunk_begin(s, "IDAT", (uint32_t)((first ? 2 : 0) + 5 + s->n + (final ? 4 : 0)));
    if (first)
        chunk_put(s, zlib_header, 2);
    chunk_put(s, stored_header, 5);
    chunk_put(s, s->block, s->n);
    if (final)
        chunk_put(s, adler, 4);
    chunk_end(s);
    s->header_sent = 1;
    s->n = 0;
}

/* Adds raw bytes to the zlib stream. A full block is sent only when more bytes follow,
 * so the block png_write() sends last, marked final, is never empty. */
static void put_raw(struct png_stream *s, const unsigned char *bytes, size_t n)
{
    s->adler = (uint32_t)adler32_update(s->adler, bytes, n);
    while (n > 0) {
        if (s->n == STORED_BLOCK_MAX)
            send_block(s, 0);
        size_t take = n < STORED_BLOCK_MAX - s->n ? n : STORED_BLOCK_MAX - s->n;
        memcpy(s->block + s->n, bytes, take);
        s->n += take;
        bytes += take;
        n -= take;
    }
}

/* Sec. 11.2.2: 13 bytes; width and height are at most MAX_IMAGE_SIDE, far below 2^31. */
static void write_ihdr(struct png_stream *s, int width, int height)
{
    unsigned char data[13];
    put_u32(data, (uint32_t)width);
    put_u32(data + 4, (uint32_t)height);
    data[8] = 8;   /* bit depth: 8 bits per channel                       */
    data[9] = 2;   /* colour type 2: truecolour, R G B per pixel          */
    data[10] = 0;  /* compression method 0: zlib's deflate (Sec. 10)      */
    data[11] = 0;  /* filter method 0: the filter types of Sec. 9.2      */
    data[12] = 0;  /* interlace method 0: none, rows in order             */
    chunk_begin(s, "IHDR", sizeof data);
    chunk_put(s, data, sizeof data);
    chunk_end(s);
}

/* The file of Sec. 5.2 onwards. */
int png_write_bytes(const char *name, int width, int height, const unsigned char *rgb,
                    struct error *err)
{
    static const unsigned char signature[8] = {137, 80, 78, 71, 13, 10, 26, 10}; /* 5.2 */
    FILE *f = output_open(name, err);
    if (f == NULL)
        return -1;
    struct png_stream *s = xmalloc(1, sizeof *s, "PNG stream");
    s->f = f;
    make_crc_table(s->crc_table);
    s->adler = 1; /* RFC 1950 Sec. 2.2: s1 = 1, s2 = 0 before any byte */
    s->header_sent = 0;
    s->n = 0;
    fwrite(signature, 1, sizeof signature, f);
    write_ihdr(s, width, height);
    size_t scanline_bytes = 1 + 3 * (size_t)width;
    unsigned char *scanline = xmalloc(scanline_bytes, 1, "PNG scanline");
    scanline[0] = FILTER_NONE;
    for (int y = 0; y < height; y++) {
        memcpy(scanline + 1, rgb + (size_t)y * (scanline_bytes - 1), scanline_bytes - 1);
        put_raw(s, scanline, scanline_bytes);
    }
    send_block(s, 1);
    chunk_begin(s, "IEND", 0);
    chunk_end(s);
    xfree(scanline);
    xfree(s);
    return output_commit(f, err); /* a failed write shows in ferror(), checked there */
}

int png_write(const char *name, const struct image *img, double exposure, struct error *err)
{
    unsigned char *rgb = display_encode(img, exposure);
    int status = png_write_bytes(name, img->width, img->height, rgb, err);
    xfree(rgb);
    return status;
}
