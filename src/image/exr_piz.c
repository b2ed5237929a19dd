/*
 * image/exr_piz.c -- undoing OpenEXR's PIZ compression (exr.h), from the format's
 * description and the behaviour of OpenEXR's library (its source read for facts only).
 *
 * PIZ treats a block's data as 16-bit words (a HALF is one, a FLOAT or UINT two, low word
 * first), laid out channel by channel: all of the block's rows of the first channel, then
 * of the next. The writer
 *   1. maps the words that occur to 0, 1, 2, ... (a bitmap of the values present is stored),
 *      so that small data stays small;
 *   2. applies a 2D Haar-like wavelet to each channel (and to each word of a FLOAT apart);
 *   3. Huffman-codes the words, with a code of its own whose table is stored as code
 *      lengths, and one extra symbol that repeats the previous word.
 * The reader undoes them in reverse: Huffman, wavelet, the value map, then the rows are
 * put back in the order of an uncompressed block (row by row, channels in turn).
 *
 * The stored data: minNonZero and maxNonZero (2 bytes each), the bitmap's bytes from
 * minNonZero to maxNonZero (none when min > max), the Huffman data's length (4 bytes), the
 * Huffman data. All numbers are little-endian.
 */
#include "exr.h"

#include <stdint.h>
#include <string.h>

#include "../base/alloc.h"

#define USHORT_RANGE 65536
#define BITMAP_SIZE (USHORT_RANGE / 8)
#define HUF_SYMBOLS (USHORT_RANGE + 1) /* every word, and the run symbol above them */
#define HUF_MAX_LENGTH 58              /* the longest code the format allows        */
#define SHORT_ZEROCODE_RUN 59          /* table lengths 59..62: 2..5 unused symbols  */
#define LONG_ZEROCODE_RUN 63           /* 63 and 8 bits n: n + 6 unused symbols      */
#define SHORTEST_LONG_RUN 6

/* The bits of a Huffman stream, read from the high end of each byte first. */
struct bit_reader {
    const unsigned char *p;
    uint64_t n_bits, at; /* bits available, bits read */
};

static int read_bits(struct bit_reader *b, int n, uint32_t *value)
{
    if (b->n_bits - b->at < (uint64_t)n)
        return -1;
    uint32_t v = 0;
    for (int i = 0; i < n; i++, b->at++)
        v = v << 1 | (uint32_t)(b->p[b->at / 8] >> (7 - b->at % 8) & 1);
    *value = v;
    return 0;
}

static uint32_t u32_at(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* The canonical Huffman code of the format: from the code length of each symbol, codes
 * of each length are consecutive numbers, given to the symbols in increasing order; the
 * longest codes take the smallest numbers, and each shorter length starts where the one
 * above ends, halved. first[len] is the smallest code of length len, and the symbols of
 * that length are sorted[start[len] ..]. */
struct huffman {
    uint64_t first[HUF_MAX_LENGTH + 1];
    uint32_t count[HUF_MAX_LENGTH + 1], start[HUF_MAX_LENGTH + 1];
    uint32_t *sorted; /* HUF_SYMBOLS entries */
};

static void build_code(struct huffman *h, const unsigned char *length, uint32_t lo,
                       uint32_t hi)
{
    memset(h->count, 0, sizeof h->count);
    for (uint32_t s = lo; s <= hi; s++)
        h->count[length[s]]++;
    uint64_t c = 0;
    for (int len = HUF_MAX_LENGTH; len > 0; len--) {
        h->first[len] = c;
        c = (c + h->count[len]) >> 1;
    }
    uint32_t at = 0;
    for (int len = 1; len <= HUF_MAX_LENGTH; len++) {
        h->start[len] = at;
        at += h->count[len];
    }
    uint32_t fill[HUF_MAX_LENGTH + 1];
    memcpy(fill, h->start, sizeof fill);
    for (uint32_t s = lo; s <= hi; s++)
        if (length[s] != 0)
            h->sorted[fill[length[s]]++] = s;
}

/* The code lengths of symbols lo..hi, 6 bits each, with runs of unused symbols. */
static int read_table(struct bit_reader *b, uint32_t lo, uint32_t hi, unsigned char *length)
{
    memset(length, 0, HUF_SYMBOLS);
    for (uint32_t s = lo; s <= hi;) {
        uint32_t l, run = 1;
        if (read_bits(b, 6, &l) < 0)
            return -1;
        if (l == LONG_ZEROCODE_RUN) {
            if (read_bits(b, 8, &run) < 0)
                return -1;
            run += SHORTEST_LONG_RUN;
            l = 0;
        } else if (l >= SHORT_ZEROCODE_RUN) {
            run = l - SHORT_ZEROCODE_RUN + 2;
            l = 0;
        }
        if (run > hi - s + 1)
            return -1;
        for (uint32_t i = 0; i < run; i++)
            length[s++] = (unsigned char)l;
    }
    return 0;
}

/* The next symbol: bits are added one at a time until the code read so far is one of
 * its length. */
static int decode_symbol(struct bit_reader *b, const struct huffman *h, uint32_t *symbol)
{
    uint64_t code = 0;
    for (int len = 1; len <= HUF_MAX_LENGTH; len++) {
        uint32_t bit;
        if (read_bits(b, 1, &bit) < 0)
            return -1;
        code = code << 1 | bit;
        if (code >= h->first[len] && code - h->first[len] < h->count[len]) {
            *symbol = h->sorted[h->start[len] + (uint32_t)(code - h->first[len])];
            return 0;
        }
    }
    return -1;
}

/* The Huffman data (a 20-byte header: the lowest and highest symbol, the table's length,
 * the data's length in bits, a reserved word; then the table and the data) into n words.
 * The highest symbol is the run symbol: 8 bits follow, how often the previous word
 * repeats. */
static int huffman_decode(const unsigned char *in, size_t in_size, uint16_t *out, size_t n,
                          const char **message)
{
    *message = "its Huffman data is damaged";
    if (in_size < 20)
        return -1;
    uint32_t lo = u32_at(in), hi = u32_at(in + 4), n_bits = u32_at(in + 12);
    if (lo > hi || hi >= HUF_SYMBOLS)
        return -1;
    struct bit_reader b = {in + 20, 8 * (uint64_t)(in_size - 20), 0};
    unsigned char *length = xmalloc(HUF_SYMBOLS, 1, "a PIZ code table");
    struct huffman h;
    h.sorted = xmalloc(HUF_SYMBOLS, sizeof *h.sorted, "a PIZ code table");
    int status = read_table(&b, lo, hi, length);
    if (status == 0) {
        build_code(&h, length, lo, hi);
        uint64_t table_end = (b.at + 7) / 8 * 8; /* the data starts on a whole byte */
        if (n_bits > b.n_bits - table_end)
            status = -1;
        b.p += table_end / 8;
        b.n_bits = n_bits;
        b.at = 0;
    }
    for (size_t i = 0; status == 0 && i < n;) {
        uint32_t s, repeat;
        status = decode_symbol(&b, &h, &s);
        if (status == 0 && s == hi) {
            status = i == 0 || read_bits(&b, 8, &repeat) < 0 || repeat > n - i ? -1 : 0;
            for (uint32_t k = 0; status == 0 && k < repeat; k++, i++)
                out[i] = out[i - 1];
        } else if (status == 0)
            out[i++] = (uint16_t)s;
    }
    xfree(h.sorted);
    xfree(length);
    return status;
}

/* Two's complement views of a 16-bit word, without implementation-defined conversions. */
static int signed16(unsigned v)
{
    return v >= 0x8000 ? (int)v - 0x10000 : (int)v;
}

static uint16_t word(long v)
{
    return (uint16_t)((unsigned long)v & 0xFFFFu);
}

/* One inverse wavelet step on the pair (l, h) -> (a, b). With wide 0: the 14-bit form
 * (l the mean, h the difference, as signed numbers); wide 1: the 16-bit form, modulo
 * 2^16. */
static void unwavelet(int wide, uint16_t *a, uint16_t *b)
{
    uint16_t l = *a, h = *b;
    if (!wide) {
        int hs = signed16(h);
        int floor_half = hs >= 0 ? hs / 2 : -((1 - hs) / 2);
        long ai = signed16(l) + (hs % 2 != 0) + floor_half;
        *a = word(ai);
        *b = word(ai - hs);
    } else {
        long bb = ((long)l - (long)(h >> 1)) & 0xFFFF;
        *a = word((long)h + bb - 0x8000);
        *b = word(bb);
    }
}

/* The 2D wavelet undone in place on an nx x ny grid of words at data, x steps ox words
 * and y steps oy words apart: levels from the coarsest down, each undoing 2 x 2 squares,
 * then a lone column or row that a side of odd length leaves over. */
static void unwavelet_2d(uint16_t *data, int nx, int ox, int ny, int oy, int wide)
{
    int n = nx < ny ? nx : ny, p = 1;
    while (p <= n)
        p <<= 1;
    int p2 = p >> 1; /* the largest power of 2 <= n: the coarsest level's square */
    for (p = p2 >> 1; p >= 1; p2 = p, p >>= 1) {
        int y = 0;
        for (; y <= ny - p2; y += p2) {
            int x = 0;
            for (; x <= nx - p2; x += p2) {
                uint16_t *q00 = data + (size_t)y * oy + (size_t)x * ox;
                uint16_t *q01 = q00 + (size_t)p * ox, *q10 = q00 + (size_t)p * oy;
                uint16_t *q11 = q10 + (size_t)p * ox;
                unwavelet(wide, q00, q10); /* the columns first, then the rows */
                unwavelet(wide, q01, q11);
                unwavelet(wide, q00, q01);
                unwavelet(wide, q10, q11);
            }
            if (nx & p) { /* a lone column at x */
                uint16_t *q = data + (size_t)y * oy + (size_t)x * ox;
                unwavelet(wide, q, q + (size_t)p * oy);
            }
        }
        if (ny & p) /* a lone row at y */
            for (int x = 0; x <= nx - p2; x += p2) {
                uint16_t *q = data + (size_t)y * oy + (size_t)x * ox;
                unwavelet(wide, q, q + (size_t)p * ox);
            }
    }
}

int exr_piz_decompress(const struct exr_block *block, const unsigned char *in, size_t in_size,
                       unsigned char *out, size_t out_size, const char **message)
{
    static const char damaged[] = "its value map or lengths are damaged";
    *message = damaged;
    if (in_size < 4)
        return -1;
    unsigned lo = in[0] | (unsigned)in[1] << 8, hi = in[2] | (unsigned)in[3] << 8;
    size_t at = 4;
    unsigned char bitmap[BITMAP_SIZE];
    memset(bitmap, 0, sizeof bitmap);
    if (hi >= BITMAP_SIZE)
        return -1;
    if (lo <= hi) {
        if (in_size - at < hi - lo + 1)
            return -1;
        memcpy(bitmap + lo, in + at, hi - lo + 1);
        at += hi - lo + 1;
    }
    /* The value map: word k stands for the k-th value present (0 always is). */
    uint16_t *value = xmalloc(USHORT_RANGE, sizeof *value, "a PIZ value map");
    unsigned n_values = 0;
    for (unsigned v = 0; v < USHORT_RANGE; v++)
        if (v == 0 || (bitmap[v >> 3] >> (v & 7) & 1))
            value[n_values++] = (uint16_t)v;
    for (unsigned k = n_values; k < USHORT_RANGE; k++)
        value[k] = 0;
    size_t n_words = out_size / 2;
    uint16_t *words = xmalloc(n_words, sizeof *words, "a PIZ block");
    int status = -1;
    if (in_size - at >= 4 && u32_at(in + at) <= in_size - at - 4 &&
        huffman_decode(in + at + 4, u32_at(in + at), words, n_words, message) == 0) {
        int wide = n_values - 1 >= (1u << 14); /* the writer's choice, by the largest word */
        uint16_t *w = words;
        for (int c = 0; c < block->n_channels; c++) {
            int per_value = block->channel_bytes[c] / 2;
            for (int j = 0; j < per_value; j++)
                unwavelet_2d(w + j, block->width, per_value, block->rows,
                             per_value * block->width, wide);
            w += (size_t)block->width * (size_t)block->rows * (size_t)per_value;
        }
        /* Channel by channel into row by row, each word through the value map and out
         * little-endian. */
        size_t out_row = out_size / (size_t)block->rows; /* bytes of a raw row */
        size_t channel_start = 0, row_offset = 0; /* in words; in a raw row's bytes */
        for (int c = 0; c < block->n_channels; c++) {
            size_t row_words = (size_t)block->width * (size_t)(block->channel_bytes[c] / 2);
            for (int y = 0; y < block->rows; y++)
                for (size_t i = 0; i < row_words; i++) {
                    uint16_t v = value[words[channel_start + (size_t)y * row_words + i]];
                    unsigned char *put = out + (size_t)y * out_row + row_offset + 2 * i;
                    put[0] = (unsigned char)(v & 0xFF);
                    put[1] = (unsigned char)(v >> 8);
                }
            channel_start += row_words * (size_t)block->rows;
            row_offset += 2 * row_words;
        }
        status = 0;
    }
    xfree(words);
    xfree(value);
    return status;
}
