/*
 * base/inflate.c -- inflate: RFC 1951's deflate format undone, inside RFC 1950's zlib
 * wrapper (two header bytes, the deflate blocks, the Adler-32 of the output).
 *
 * A deflate stream is a run of blocks, each starting with a bit "last block?" and two bits
 * of type: 0 stored (a byte-aligned length, its complement, the bytes as they are), 1
 * compressed with the fixed Huffman codes of RFC 1951 3.2.6, 2 compressed with codes the
 * block describes first (3.2.7). A compressed block is a run of symbols of the
 * literal/length code: 0..255 a byte, 256 the block's end, 257..285 a length, followed by
 * a symbol of the distance code; the pair copies `length` bytes from `distance` back.
 *
 * Bits are read from the low end of each byte first; Huffman codes are packed from their
 * first bit on, so they are decoded one bit at a time (canonical codes: RFC 1951 3.2.2):
 * among the codes of each length in turn, the code read so far is a symbol when it is
 * below the first code of the next length. This is slower than table lookup and much
 * shorter; it is the way Mark Adler's puff (zlib's contrib/puff) teaches it too.
 */
#include "inflate.h"

#include <stdint.h>
#include <string.h>

/* Short names for inflate.h's numbers of RFC 1951. */
#define MAX_BITS DEFLATE_MAX_BITS
#define N_LITLEN DEFLATE_N_LITLEN
#define N_DIST DEFLATE_N_DIST
#define N_CODE_LENGTHS DEFLATE_N_CODE_LENGTHS

struct bits {
    const unsigned char *in;
    size_t in_size, in_at; /* the next byte to take a bit from       */
    unsigned buffer;        /* bits taken and not yet used, low first */
    int n_buffer;           /* how many                               */
    unsigned char *out;
    size_t out_size, out_at;
    const char *message;    /* set by the first failure               */
};

/* A canonical Huffman code: count[len] codes of each length, and the symbols in order of
 * their codes. */
struct huffman {
    short count[MAX_BITS + 1];
    short symbol[N_LITLEN];
};

static int fail(struct bits *s, const char *message)
{
    if (s->message == NULL)
        s->message = message;
    return -1;
}

/* The next n (0..16) bits as a number, the first read in its lowest bit; -1 past the end. */
static int get_bits(struct bits *s, int n)
{
    while (s->n_buffer < n) {
        if (s->in_at == s->in_size)
            return fail(s, "the compressed data ends early");
        s->buffer |= (unsigned)s->in[s->in_at++] << s->n_buffer;
        s->n_buffer += 8;
    }
    int value = (int)(s->buffer & ((1u << n) - 1));
    s->buffer >>= n;
    s->n_buffer -= n;
    return value;
}

/* Builds h from the code length of each of n symbols (0: the symbol is unused). -1 when
 * the lengths ask for more codes than exist (an over-subscribed code); an incomplete code
 * is allowed, as RFC 1951 allows one distance code, and decode() fails on its gaps. */
static int build(struct huffman *h, const unsigned char *length, int n)
{
    short offset[MAX_BITS + 1];
    memset(h->count, 0, sizeof h->count);
    for (int i = 0; i < n; i++)
        h->count[length[i]]++;
    int left = 1; /* codes of the current length not yet taken */
    for (int len = 1; len <= MAX_BITS; len++) {
        left = 2 * left - h->count[len];
        if (left < 0)
            return -1;
    }
    offset[1] = 0;
    for (int len = 1; len < MAX_BITS; len++)
        offset[len + 1] = (short)(offset[len] + h->count[len]);
    for (int i = 0; i < n; i++)
        if (length[i] != 0)
            h->symbol[offset[length[i]]++] = (short)i;
    return 0;
}

/* The next symbol of code h, one bit at a time: code is the bits read so far, first the
 * codes of length 1, then 2, ...; first the smallest code of this length, index the
 * position of that code's symbol in h->symbol. */
static int decode(struct bits *s, const struct huffman *h)
{
    int code = 0, first = 0, index = 0;
    for (int len = 1; len <= MAX_BITS; len++) {
        int bit = get_bits(s, 1);
        if (bit < 0)
            return -1;
        code |= bit;
        int count = h->count[len];
        if (code - first < count)
            return h->symbol[index + (code - first)];
        index += count;
        first = (first + count) << 1;
        code <<= 1;
    }
    return fail(s, "a Huffman code that the block's codes do not hold");
}

static int put_byte(struct bits *s, int byte)
{
    if (s->out_at == s->out_size)
        return fail(s, "the data inflates to more bytes than the block states");
    s->out[s->out_at++] = (unsigned char)byte;
    return 0;
}

/* A stored block: the rest of the current byte skipped, LEN and its ones' complement NLEN
 * (16 bits each, low byte first), then LEN bytes as they are. */
static int stored(struct bits *s)
{
    s->buffer = 0;
    s->n_buffer = 0;
    if (s->in_size - s->in_at < 4)
        return fail(s, "the compressed data ends early");
    const unsigned char *p = s->in + s->in_at;
    unsigned len = p[0] | (unsigned)p[1] << 8, nlen = p[2] | (unsigned)p[3] << 8;
    s->in_at += 4;
    if (len != (~nlen & 0xFFFFu))
        return fail(s, "a stored block's length does not match its complement");
    if (s->in_size - s->in_at < len)
        return fail(s, "the compressed data ends early");
    if (s->out_size - s->out_at < len)
        return fail(s, "the data inflates to more bytes than the block states");
    memcpy(s->out + s->out_at, s->in + s->in_at, len);
    s->in_at += len;
    s->out_at += len;
    return 0;
}

/* RFC 1951 3.2.5: each length symbol 257..285 and distance symbol 0..29 stands for a base
 * value plus that many extra bits read after it (inflate.h: deflate.c codes with them). */
const short deflate_length_base[DEFLATE_N_LENGTHS] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15,
                                                      17, 19, 23, 27, 31, 35, 43, 51, 59, 67,
                                                      83, 99, 115, 131, 163, 195, 227, 258};
const short deflate_length_extra[DEFLATE_N_LENGTHS] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2,
                                                       2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5,
                                                       5, 5, 0};
const short deflate_dist_base[DEFLATE_N_DIST] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65,
                                                 97, 129, 193, 257, 385, 513, 769, 1025, 1537,
                                                 2049, 3073, 4097, 6145, 8193, 12289, 16385,
                                                 24577};
const short deflate_dist_extra[DEFLATE_N_DIST] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6,
                                                  6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12,
                                                  13, 13};

/* RFC 1951 3.2.7: the order in which a dynamic block states the code-length code's
 * lengths, the ones most often used first, so that HCLEN can leave off the rarest. */
const unsigned char deflate_code_length_order[DEFLATE_N_CODE_LENGTHS] = {
    16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};

/* RFC 1951 3.2.6: the fixed codes' lengths. */
void deflate_fixed_lengths(unsigned char litlen[DEFLATE_N_LITLEN],
                           unsigned char dist[DEFLATE_N_DIST])
{
    for (int i = 0; i < DEFLATE_N_LITLEN; i++)
        litlen[i] = i < 144 ? 8 : i < 256 ? 9 : i < 280 ? 7 : 8;
    for (int i = 0; i < DEFLATE_N_DIST; i++)
        dist[i] = 5;
}

/* The symbols of a compressed block, up to its end symbol 256. */
static int codes(struct bits *s, const struct huffman *litlen, const struct huffman *dist)
{
    for (;;) {
        int symbol = decode(s, litlen);
        if (symbol < 0)
            return -1;
        if (symbol < 256) {
            if (put_byte(s, symbol) < 0)
                return -1;
            continue;
        }
        if (symbol == 256)
            return 0;
        symbol -= 257;
        if (symbol >= DEFLATE_N_LENGTHS)
            return fail(s, "a length symbol beyond 285");
        int extra = get_bits(s, deflate_length_extra[symbol]);
        int d = decode(s, dist);
        if (extra < 0 || d < 0)
            return -1;
        if (d >= N_DIST)
            return fail(s, "a distance symbol beyond 29");
        int dextra = get_bits(s, deflate_dist_extra[d]);
        if (dextra < 0)
            return -1;
        size_t length = (size_t)(deflate_length_base[symbol] + extra);
        size_t distance = (size_t)(deflate_dist_base[d] + dextra);
        if (distance > s->out_at)
            return fail(s, "a distance back before the start of the data");
        if (s->out_size - s->out_at < length)
            return fail(s, "the data inflates to more bytes than the block states");
        for (size_t i = 0; i < length; i++) { /* byte by byte: the copy may overlap */
            s->out[s->out_at] = s->out[s->out_at - distance];
            s->out_at++;
        }
    }
}

/* A block with the fixed codes of RFC 1951 3.2.6. */
static int fixed(struct bits *s)
{
    unsigned char litlen_length[N_LITLEN], dist_length[N_DIST];
    struct huffman litlen, dist;
    deflate_fixed_lengths(litlen_length, dist_length);
    build(&litlen, litlen_length, N_LITLEN);
    build(&dist, dist_length, N_DIST);
    return codes(s, &litlen, &dist);
}

/* A block with its own codes (RFC 1951 3.2.7): HLIT, HDIST, HCLEN; the code-length code's
 * lengths in a fixed order; then the literal/length and distance codes' lengths, coded
 * with it (16: repeat the previous length 3..6 times, 17 and 18: 3..10 and 11..138 zeros). */
static int dynamic(struct bits *s)
{
    unsigned char length[N_LITLEN + N_DIST];
    struct huffman lencode, litlen, dist;
    int nlen = get_bits(s, 5), ndist = get_bits(s, 5), ncode = get_bits(s, 4);
    if (nlen < 0 || ndist < 0 || ncode < 0)
        return -1;
    nlen += 257;
    ndist += 1;
    ncode += 4;
    if (nlen > 286 || ndist > N_DIST)
        return fail(s, "a block states more codes than deflate has");
    memset(length, 0, sizeof length);
    for (int i = 0; i < ncode; i++) {
        int len = get_bits(s, 3);
        if (len < 0)
            return -1;
        length[deflate_code_length_order[i]] = (unsigned char)len;
    }
    if (build(&lencode, length, N_CODE_LENGTHS) < 0)
        return fail(s, "a block's code-length code is over-subscribed");
    int i = 0;
    while (i < nlen + ndist) {
        int symbol = decode(s, &lencode);
        if (symbol < 0)
            return -1;
        if (symbol < 16) {
            length[i++] = (unsigned char)symbol;
            continue;
        }
        int len = 0, repeat;
        if (symbol == 16) {
            if (i == 0)
                return fail(s, "a block repeats a code length before the first");
            len = length[i - 1];
            repeat = get_bits(s, 2);
            repeat = repeat < 0 ? -1 : 3 + repeat;
        } else if (symbol == 17) {
            repeat = get_bits(s, 3);
            repeat = repeat < 0 ? -1 : 3 + repeat;
        } else {
            repeat = get_bits(s, 7);
            repeat = repeat < 0 ? -1 : 11 + repeat;
        }
        if (repeat < 0)
            return -1;
        if (i + repeat > nlen + ndist)
            return fail(s, "a block's code lengths run past their count");
        while (repeat-- > 0)
            length[i++] = (unsigned char)len;
    }
    if (length[256] == 0)
        return fail(s, "a block's codes have no end-of-block symbol");
    if (build(&litlen, length, nlen) < 0 || build(&dist, length + nlen, ndist) < 0)
        return fail(s, "a block's Huffman code is over-subscribed");
    return codes(s, &litlen, &dist);
}

/* RFC 1950 Sec. 2.2 (ADLER32) and Sec. 9: s1 = 1 + the sum of the bytes, s2 = the sum of
 * the s1 after each byte, both modulo 65521, the largest prime below 65536; the checksum
 * is s2 * 65536 + s1. */
unsigned long adler32_update(unsigned long adler, const unsigned char *bytes, size_t n)
{
    uint32_t a = (uint32_t)(adler & 0xFFFF), b = (uint32_t)(adler >> 16 & 0xFFFF);
    for (size_t i = 0; i < n; i++) {
        a = (a + bytes[i]) % 65521u;
        b = (b + a) % 65521u;
    }
    return (unsigned long)b << 16 | a;
}

unsigned long adler32(const unsigned char *bytes, size_t n)
{
    return adler32_update(1, bytes, n);
}

int zlib_inflate(const unsigned char *in, size_t in_size, unsigned char *out,
                 size_t out_size, const char **message)
{
    struct bits s = {in, in_size, 0, 0, 0, out, out_size, 0, NULL};
    /* RFC 1950: CMF (method 8, deflate; window up to 32 KiB), FLG (no preset dictionary),
     * the two read as a 16-bit number a multiple of 31. */
    if (in_size < 6 || (in[0] & 0x0F) != 8 || (in[0] >> 4) > 7 || (in[1] & 0x20) != 0 ||
        (in[0] * 256 + in[1]) % 31 != 0) {
        *message = "not a zlib stream (its two header bytes are wrong)";
        return -1;
    }
    s.in_at = 2;
    int last = 0;
    while (!last) {
        last = get_bits(&s, 1);
        int type = get_bits(&s, 2);
        int status = last < 0 || type < 0 ? -1
                     : type == 0          ? stored(&s)
                     : type == 1          ? fixed(&s)
                     : type == 2          ? dynamic(&s)
                                          : fail(&s, "a block of the reserved type 3");
        if (status < 0) {
            *message = s.message;
            return -1;
        }
    }
    if (s.out_at != out_size) {
        *message = "the data inflates to fewer bytes than the block states";
        return -1;
    }
    /* The checksum stands in the 4 bytes after the last block's byte, high byte first. */
    if (in_size - s.in_at < 4) {
        *message = "the zlib stream ends before its checksum";
        return -1;
    }
    const unsigned char *c = in + s.in_at;
    unsigned long stated = (unsigned long)c[0] << 24 | (unsigned long)c[1] << 16 |
                           (unsigned long)c[2] << 8 | c[3];
    if (stated != adler32(out, out_size)) {
        *message = "the inflated data's Adler-32 checksum is wrong";
        return -1;
    }
    return 0;
}
