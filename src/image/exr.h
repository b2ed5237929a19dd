/*
 * image/exr.h -- OpenEXR files: the scanline images Blender, pbrt-v4 and Mitsuba 3 write,
 * read (exr_read.c, exr_decompress.c, exr_piz.c) and written (exr_write.c), by hand from
 * the format's public description ("OpenEXR File Layout"); the names below are the spec's.
 *
 * An OpenEXR file is: the magic number 20000630 and a version field (4 bytes each, little
 * endian like every number in the file); a header of attributes (name, type name, size,
 * value) ended by an empty name; a table of one 8-byte file offset per chunk; the chunks.
 * A scanline chunk holds `lines per block` rows of the data window (1, 16 or 32 by the
 * compression): its first row's y (4 bytes), its data's size (4 bytes) and its data: for
 * each row, top to bottom, each channel's values in the channels' (alphabetical) order.
 * Rows run downward: y = yMin is the top row, struct image's row 0.
 */
#ifndef PHOTON_EXR_H
#define PHOTON_EXR_H

#include <stddef.h>

#include "image.h"

#define EXR_MAGIC 20000630L /* the bytes 0x76 0x2f 0x31 0x01 */
#define EXR_VERSION 2        /* the low byte of the version field */
/* Flags of the version field. */
#define EXR_FLAG_TILED 0x200
#define EXR_FLAG_LONG_NAMES 0x400
#define EXR_FLAG_DEEP 0x800 /* "non-image": deep data */
#define EXR_FLAG_MULTIPART 0x1000

enum exr_pixel_type { EXR_UINT = 0, EXR_HALF = 1, EXR_FLOAT = 2 };

enum exr_compression {
    EXR_NO_COMPRESSION = 0,
    EXR_RLE_COMPRESSION = 1,
    EXR_ZIPS_COMPRESSION = 2, /* zlib, one row a block   */
    EXR_ZIP_COMPRESSION = 3,  /* zlib, 16 rows a block   */
    EXR_PIZ_COMPRESSION = 4,  /* wavelet and Huffman, 32 rows: exr_piz.c */
    EXR_N_COMPRESSIONS = 10   /* PXR24, B44, B44A, DWAA, DWAB: not read */
};

/* Reads a scanline OpenEXR file (exr_read.c): its R, G, B channels, or Y alone as grey
 * (R = G = B = Y), of any pixel type; A and other channels are skipped. NULL with *err
 * filled for anything it does not read (named: "tiled OpenEXR files are not read") and
 * for a value that is NaN or infinite; +Inf is allowed when plus_infinity is set. */
struct image *exr_read(const char *name, int plus_infinity, struct error *err);

/* Writes img as a scanline OpenEXR of FLOAT channels B, G, R, ZIP-compressed (a chunk that
 * deflate does not shorten stored raw), its data and display windows (0, 0) - (width - 1,
 * height - 1), atomically through output_open() and output_commit(). A value beyond the
 * float range is refused as pfm_write() refuses it. */
int exr_write(const char *name, const struct image *img, struct error *err);

/* The shape of a chunk's rows, which PIZ needs: its width and rows, and each channel's
 * bytes per value (2 for HALF, 4 for FLOAT and UINT) in the file's order. */
struct exr_block {
    int width, rows, n_channels;
    const unsigned char *channel_bytes;
};

/* Undoes a chunk's compression (exr_decompress.c): in[0 .. in_size - 1] into exactly
 * out_size bytes at out, the block's raw rows. 0, or -1 with *message a constant text
 * saying what was wrong. */
int exr_decompress(enum exr_compression compression, const struct exr_block *block,
                   const unsigned char *in, size_t in_size, unsigned char *out,
                   size_t out_size, const char **message);

/* PIZ's part of exr_decompress() (exr_piz.c). */
int exr_piz_decompress(const struct exr_block *block, const unsigned char *in, size_t in_size,
                       unsigned char *out, size_t out_size, const char **message);

/* How many rows a chunk holds under compression (1 for NO, RLE and ZIPS). */
int exr_lines_per_block(enum exr_compression compression);

/* What RLE and ZIP do to a chunk's n raw bytes before compressing them, which
 * exr_decompress() undoes (exr_decompress.c): raw into out (n bytes, not raw). */
void exr_interleave_and_predict(const unsigned char *raw, size_t n, unsigned char *out);

#endif
