/*
 * tests/test_deflate.c -- the deflate room: zlib streams written by base/deflate.c must
 * inflate back to their input, byte for byte, through base/inflate.c (which the exr room
 * tests against Python's zlib and OpenEXR's own files), on the inputs where a compressor
 * goes wrong: nothing, one byte, runs longer than a block, copies of every length and from
 * the farthest distance, data that does not compress, a buffer too small.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/base/deflate.h"
#include "../src/base/inflate.h"
#include "../src/base/rng.h"
#include "check.h"
#include "tests.h"

/* Compresses in[0 .. n - 1] with room for the worst case and inflates the stream back: its
 * size, or 0 (saying why) when it does not give the input back. *type: the first block's
 * BTYPE (RFC 1951 3.2.3: 0 stored, 1 fixed codes, 2 dynamic codes). */
static size_t round_trip(const unsigned char *in, size_t n, int *type)
{
    size_t capacity = zlib_deflate_bound(n);
    unsigned char *z = xmalloc(capacity, 1, "a test's stream");
    unsigned char *out = xmalloc(n + 1, 1, "a test's inflated bytes");
    size_t size = zlib_deflate(in, n, z, capacity);
    const char *message = "the bytes differ";
    int same = size > 0 && zlib_inflate(z, size, out, n, &message) == 0 &&
               (n == 0 || memcmp(in, out, n) == 0);
    if (!same)
        printf("    %zu bytes: %s\n", n, size == 0 ? "the stream did not fit" : message);
    *type = size > 2 ? z[2] >> 1 & 3 : -1; /* the bits after BFINAL, lowest first */
    xfree(out);
    xfree(z);
    return same ? size : 0;
}

/* n bytes of the test stream index, each uniform in 0..255. */
static void random_bytes(unsigned char *b, size_t n, uint64_t index)
{
    struct rng r = rng_stream(1, STREAM_TEST, index, 0);
    for (size_t i = 0; i < n; i++)
        b[i] = (unsigned char)(rng_next(&r) >> 56);
}

/* truth: RFC 1950 and 1951, through our inflate: an empty stream holds one block with its
 * end symbol, and a run of one value is one literal and copies of 258 bytes from distance
 * 1, overlapping themselves. catches: a stream with no block, or no end of block, for empty
 * input; a copy that reads bytes not yet written; a run cut wrongly at the block's end
 * (70,000 bytes are two blocks); a stream that grows a run instead of shrinking it. */
static void test_deflate_edges(struct check *t)
{
    static unsigned char run[70000];
    unsigned char one = 0x2a;
    int type;
    size_t size = round_trip(NULL, 0, &type);
    CHECK(t, size > 0 && type == 1); /* the end symbol alone: fixed codes are shortest */
    CHECK(t, round_trip(&one, 1, &type) > 0);
    memset(run, 0x2a, sizeof run);
    size = round_trip(run, sizeof run, &type);
    CHECK(t, size > 0 && size < 300);
    run[sizeof run - 1] = 0x2b; /* the last copy cut short by a different byte */
    CHECK(t, round_trip(run, sizeof run, &type) > 0);
}

/* truth: RFC 1951 3.2.4: a stored block costs 5 bytes besides its own, at most 65535 of
 * them, and the zlib wrapper 6; random bytes do not compress, so the stream is exactly
 * that (zlib_deflate_bound()). With one byte less room, the stream is abandoned and no
 * byte past the room is written. catches: compressed blocks chosen where they are longer,
 * a stored block over 65535 bytes, a bound too small, a write past the caller's buffer. */
static void test_deflate_incompressible(struct check *t)
{
    enum { N = 100000, GUARD = 16 };
    static unsigned char in[N], z[N + GUARD];
    random_bytes(in, N, 1);
    int type;
    size_t size = round_trip(in, N, &type);
    CHECK(t, size == N + 2 * 5 + 6 && size == zlib_deflate_bound(N) && type == 0);
    memset(z, 0xEE, sizeof z);
    CHECK(t, zlib_deflate(in, N, z, N - 1) == 0);
    int untouched = 1;
    for (size_t i = N - 1; i < sizeof z; i++)
        untouched &= z[i] == 0xEE;
    CHECK(t, untouched);
}

/* truth: RFC 1951 3.2.5: a copy reaches back at most 32768 bytes (distance symbol 29 with
 * all 13 extra bits set). 32768 random bytes twice: the second half is copies from exactly
 * 32768 back; 32769 random bytes and then the first 2000 again: out of reach, so stored.
 * catches: the window's edge off by one either way (a copy not taken, or a distance that
 * deflate cannot code, which inflates to other bytes or fails). */
static void test_deflate_farthest_copies(struct check *t)
{
    enum { W = 32768 };
    static unsigned char in[2 * W + 1];
    int type;
    random_bytes(in, W, 2);
    memcpy(in + W, in, W);
    size_t size = round_trip(in, 2 * W, &type);
    CHECK(t, size > W && size < W + W / 16);
    random_bytes(in, W + 1, 3);
    memcpy(in + W + 1, in, 2000);
    size = round_trip(in, W + 1 + 2000, &type);
    CHECK(t, size == zlib_deflate_bound(W + 1 + 2000));
}

/* truth: RFC 1951 3.2.5's length and distance symbols, through our inflate. Runs of every
 * length 1..300 (a literal, then a copy of length - 1 from distance 1: every length symbol
 * and every value of its extra bits, 258 and its neighbours); stretches of 48 bytes copied
 * from distances around each distance symbol's base; "ABC" and a new byte, 200 times: the
 * shortest copies, 3 bytes from 4 back, which must shrink the data. catches: a length or
 * distance put under the wrong symbol or with wrong extra bits, a length of 258 coded as
 * 284 + 31, a 3-byte copy not taken. */
static void test_deflate_every_length_and_distance(struct check *t)
{
    static unsigned char in[200000];
    size_t n = 0;
    for (int length = 1; length <= 300; length++) {
        memset(in + n, length % 2 == 0 ? 'a' + length % 26 : 'A' + length % 26, (size_t)length);
        n += (size_t)length;
    }
    int type;
    size_t size = round_trip(in, n, &type);
    CHECK(t, size > 0 && size < n / 20);
    static const int bases[] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193,
                                257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145,
                                8193, 12289, 16385, 24577, 32768};
    random_bytes(in, 32768, 4);
    n = 32768;
    for (size_t i = 0; i < sizeof bases / sizeof bases[0]; i++)
        for (int more = 0; more < 3; more++) { /* the base, one beyond, one before the next */
            size_t d = (size_t)bases[i] + (more == 1 ? 1u : 0u);
            if (more == 2)
                d = i + 1 < sizeof bases / sizeof bases[0] ? (size_t)bases[i + 1] - 1 : d;
            for (size_t k = 0; k < 48; k++, n++)
                in[n] = in[n - d];
            random_bytes(in + n, 5, 5 + n); /* so that the next stretch starts a new copy */
            n += 5;
        }
    CHECK(t, round_trip(in, n, &type) > 0);
    n = 0;
    for (int k = 0; k < 200; k++) { /* the new byte: 0x44 + k modulo 256, never A, B, C */
        memcpy(in + n, "ABC", 3);
        in[n + 3] = (unsigned char)((0x44 + k) % 256);
        n += 4;
    }
    size = round_trip(in, n, &type);
    CHECK(t, size > 0 && size < n * 3 / 4);
}

/* truth: a float image's bytes (base/deflate.h's purpose): the floats 1 + i / 10000, whose
 * high bytes repeat and whose low bytes change slowly: skewed symbol counts, which codes of
 * the block's own (3.2.7) take in fewer bits than the fixed ones (zlib -6 keeps 62 % of
 * these bytes). catches: a dynamic block's header written wrongly (HLIT, HDIST, HCLEN, the
 * code-length code's runs), codes longer than 15 bits, an incomplete code. */
static void test_deflate_dynamic_codes(struct check *t)
{
    enum { N = 30000 };
    static unsigned char in[4 * N];
    for (int i = 0; i < N; i++) {
        float f = 1.0f + (float)i / 10000.0f;
        memcpy(in + 4 * i, &f, 4);
    }
    int type;
    size_t size = round_trip(in, sizeof in, &type);
    CHECK(t, size > 0 && size < sizeof in * 3 / 4 && type == 2);
}

void test_deflate(struct check *t)
{
    RUN_TEST(t, test_deflate_edges);
    RUN_TEST(t, test_deflate_incompressible);
    RUN_TEST(t, test_deflate_farthest_copies);
    RUN_TEST(t, test_deflate_every_length_and_distance);
    RUN_TEST(t, test_deflate_dynamic_codes);
}
