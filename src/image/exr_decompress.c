/*
 * image/exr_decompress.c -- undoing an OpenEXR chunk's compression: RLE, ZIPS and ZIP
 * here, PIZ in exr_piz.c; and the steps ZIP takes before deflate, for the writer
 * (exr_write.c), beside their inverse so that both use one definition of the byte order.
 *
 * RLE and ZIP share two steps the writer takes before compressing, which make the bytes of
 * slowly changing values alike: the chunk's bytes are split into two halves, the bytes at
 * even positions first, then those at odd positions (the high and low bytes of most halfs
 * and floats end up apart); then each byte is replaced by its difference from the one
 * before, plus 128, modulo 256 (a predictor). The reader undoes them in reverse order:
 * sums first, then the interleave.
 *
 * RLE's runs: a signed count byte c; c < 0: -c bytes follow as they are; c >= 0: the next
 * byte stands c + 1 times. ZIPS (one row) and ZIP (16 rows) are a zlib stream each
 * (base/inflate.h).
 */
#include "exr.h"

#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/inflate.h"

int exr_lines_per_block(enum exr_compression compression)
{
    switch (compression) {
    case EXR_ZIP_COMPRESSION:
        return 16;
    case EXR_PIZ_COMPRESSION:
        return 32;
    default:
        return 1;
    }
}

static int rle_expand(const unsigned char *in, size_t in_size, unsigned char *out,
                      size_t out_size, const char **message)
{
    size_t at = 0, put = 0;
    while (at < in_size) {
        int count = in[at] < 128 ? in[at] : in[at] - 256; /* the byte as signed */
        at++;
        if (count < 0) {
            size_t n = (size_t)-count;
            if (in_size - at < n || out_size - put < n) {
                *message = in_size - at < n ? "RLE data ends inside a literal run"
                                            : "RLE data expands past the block's size";
                return -1;
            }
            memcpy(out + put, in + at, n);
            at += n;
            put += n;
        } else {
            size_t n = (size_t)count + 1;
            if (at == in_size || out_size - put < n) {
                *message = at == in_size ? "RLE data ends inside a run"
                                         : "RLE data expands past the block's size";
                return -1;
            }
            memset(out + put, in[at], n);
            at++;
            put += n;
        }
    }
    if (put != out_size) {
        *message = "RLE data expands to fewer bytes than the block holds";
        return -1;
    }
    return 0;
}

/* Where byte i of a chunk of n bytes stands once interleaved: the bytes at even positions
 * first, then those at odd positions. */
static size_t interleaved_at(size_t i, size_t n)
{
    return i % 2 == 0 ? i / 2 : (n + 1) / 2 + i / 2;
}

/* The writer's two steps (exr.h), in the order OpenEXR's compressor takes them: the
 * interleave, then each byte but the first replaced by its difference from the byte
 * before it, plus 128 (from the end backwards, so each difference uses the byte as it was). */
void exr_interleave_and_predict(const unsigned char *raw, size_t n, unsigned char *out)
{
    for (size_t i = 0; i < n; i++)
        out[interleaved_at(i, n)] = raw[i];
    for (size_t i = n; i-- > 1;)
        out[i] = (unsigned char)(out[i] - out[i - 1] + 128);
}

/* The predictor and the interleave undone: t (n bytes) into out. */
static void undo_predictor_and_interleave(unsigned char *t, size_t n, unsigned char *out)
{
    for (size_t i = 1; i < n; i++)
        t[i] = (unsigned char)(t[i - 1] + t[i] - 128);
    for (size_t i = 0; i < n; i++)
        out[i] = t[interleaved_at(i, n)];
}

int exr_decompress(enum exr_compression compression, const struct exr_block *block,
                   const unsigned char *in, size_t in_size, unsigned char *out,
                   size_t out_size, const char **message)
{
    if (compression == EXR_NO_COMPRESSION) { /* exr_read.c sent only whole raw chunks */
        memcpy(out, in, out_size);
        return 0;
    }
    if (compression == EXR_PIZ_COMPRESSION)
        return exr_piz_decompress(block, in, in_size, out, out_size, message);
    if (compression != EXR_RLE_COMPRESSION && compression != EXR_ZIPS_COMPRESSION &&
        compression != EXR_ZIP_COMPRESSION) {
        *message = "this compression is not read";
        return -1;
    }
    unsigned char *t = xmalloc(out_size, 1, "an OpenEXR chunk");
    int status = compression == EXR_RLE_COMPRESSION
                     ? rle_expand(in, in_size, t, out_size, message)
                     : zlib_inflate(in, in_size, t, out_size, message);
    if (status == 0)
        undo_predictor_and_interleave(t, out_size, out);
    xfree(t);
    return status;
}
