/*
 * tests/test_base.c -- the base room: keyed random streams, errors, atomic outputs, FNV-1a,
 * the allocation wrapper's bookkeeping; and the harness's REQUIRE (check.h).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/base/error.h"
#include "../src/base/hash.h"
#include "../src/base/output.h"
#include "../src/base/rng.h"
#include "../src/base/sequence02.h"
#include "files.h"
#include "tests.h"

/* truth: the definition of a keyed stream (rng.h): the same key gives the same numbers,
 *   any key field changed gives different ones.
 * tolerance: none.
 * catches: a key field left out of the hash (crops and photon passes would repeat noise),
 *   state shared between streams. */
static void test_streams_are_keyed(struct check *t)
{
    struct rng a = rng_stream(7, STREAM_CAMERA, 123, 4);
    struct rng b = rng_stream(7, STREAM_CAMERA, 123, 4);
    for (int i = 0; i < 100; i++)
        CHECK(t, rng_next(&a) == rng_next(&b));
    struct rng base = rng_stream(7, STREAM_CAMERA, 123, 4);
    uint64_t first = rng_next(&base);
    struct rng others[] = {
        rng_stream(8, STREAM_CAMERA, 123, 4), rng_stream(7, STREAM_PHOTON, 123, 4),
        rng_stream(7, STREAM_CAMERA, 124, 4), rng_stream(7, STREAM_CAMERA, 123, 5)};
    for (int k = 0; k < 4; k++)
        CHECK(t, rng_next(&others[k]) != first);
}

/* truth: a uniform variable on [0, 1) has mean 1/2 and variance 1/12; consecutive streams
 *   (index i, i + 1) are uncorrelated.
 * tolerance: 5 standard errors of the sample mean, sqrt(1/12 / n), and of the correlation,
 *   1 / sqrt(n): fixed seeds, so the test is deterministic; 5 SE makes a false alarm
 *   negligible.
 * catches: a biased conversion to double (e.g. dividing by 2^53 - 1), values reaching 1,
 *   a hash that maps neighbouring keys to correlated starts. */
static void test_uniform_numbers(struct check *t)
{
    const int n = 200000;
    double sum = 0, product = 0;
    int in_range = 1;
    for (int i = 0; i < n; i++) {
        struct rng r = rng_stream(1, STREAM_TEST, (uint64_t)i, 0);
        struct rng s = rng_stream(1, STREAM_TEST, (uint64_t)i + 1, 0);
        double u = rng_uniform(&r), v = rng_uniform(&s);
        in_range &= u >= 0 && u < 1;
        sum += u;
        product += (u - 0.5) * (v - 0.5);
    }
    CHECK(t, in_range);
    CHECK_CLOSE(t, sum / n, 0.5, 5 * sqrt(1.0 / 12 / n));
    CHECK_CLOSE(t, product / n * 12.0, 0.0, 5.0 / sqrt((double)n));
}

/* truth: the definition of a (0,k,2)-net in base 2: the first 2^k points put exactly one
 *   point in every elementary interval of area 2^-k, counted by brute force for every
 *   shape 2^j x 2^(k-j), k <= 10, under several random digital shifts, in the sequence's
 *   own order and in orders shuffled by sequence02_shuffled() (whose first 2^k must be an
 *   aligned block of the sequence, so a net too).
 * tolerance: none (counts).
 * catches: a wrong generator matrix (Sobol's second dimension is Pascal's triangle mod 2;
 *   the identity, or van der Corput twice, fails at k = 2), a shift applied to the index
 *   instead of the point, bits lost in the conversion to double, a shuffle that is a plain
 *   hash of the index (its first points are not a block) or not a permutation, or one
 *   that leaves the order as it was (most of the first 64 places must move). */
static void test_sequence02_is_a_net(struct check *t)
{
    static int count[1 << 10];
    for (int shift = 0; shift < 8; shift++) {
        struct rng r = rng_stream(3, STREAM_TEST, (uint64_t)shift, 0);
        uint64_t word = shift == 0 ? 0 : rng_next(&r);
        uint32_t order = (uint32_t)rng_next(&r); /* shifts 4 to 7: shuffled */
        int moved = 0; /* a shuffle must move points, or it pairs them as before */
        for (uint32_t i = 0; i < 64; i++)
            moved += sequence02_shuffled(i, order) != i;
        CHECK(t, shift < 4 || moved > 32);
        for (int k = 0; k <= 10; k++)
            for (int j = 0; j <= k; j++) {
                memset(count, 0, sizeof count);
                for (uint32_t i = 0; i < (1u << k); i++) {
                    double x, y;
                    uint32_t place = shift < 4 ? i : sequence02_shuffled(i, order);
                    sequence02_point(place, (uint32_t)word, (uint32_t)(word >> 32), &x, &y);
                    int cell_x = (int)(x * (1 << j)), cell_y = (int)(y * (1 << (k - j)));
                    count[(cell_y << j) + cell_x]++;
                }
                int once = 1;
                for (int c = 0; c < (1 << k); c++)
                    once &= count[c] == 1;
                CHECK(t, once);
            }
    }
}

/* truth: under a uniformly random digital shift, every point of the sequence is uniform on
 *   the unit square: mean 1/2 and variance 1/12 in each coordinate, coordinates
 *   uncorrelated (Owen 1995's argument for random shifts; this is what keeps pixel
 *   estimates unbiased).
 * tolerance: 5 standard errors over n shifts: sqrt(1/12 / n) for the mean, sqrt(1/180 / n)
 *   for the variance (the variance of (u - 1/2)^2 is 1/80 - 1/144 = 1/180), 1/sqrt(n)
 *   for the correlation; fixed seeds, so deterministic.
 * catches: a shift that leaves high bits fixed, a point scaled into [0, 1/2), the two
 *   coordinates shifted by the same word (they would be correlated for i = 0). */
static void test_sequence02_points_are_uniform(struct check *t)
{
    const int n = 100000;
    const uint32_t indices[] = {0, 1, 5, 12, 1000};
    for (int k = 0; k < 5; k++) {
        double sum_x = 0, sum_y = 0, square_x = 0, product = 0;
        for (int m = 0; m < n; m++) {
            struct rng r = rng_stream(5, STREAM_TEST, (uint64_t)m, 0);
            uint64_t word = rng_next(&r);
            double x, y;
            sequence02_point(indices[k], (uint32_t)word, (uint32_t)(word >> 32), &x, &y);
            sum_x += x;
            sum_y += y;
            square_x += (x - 0.5) * (x - 0.5);
            product += (x - 0.5) * (y - 0.5);
        }
        CHECK_CLOSE(t, sum_x / n, 0.5, 5 * sqrt(1.0 / 12 / n));
        CHECK_CLOSE(t, sum_y / n, 0.5, 5 * sqrt(1.0 / 12 / n));
        CHECK_CLOSE(t, square_x / n, 1.0 / 12, 5 * sqrt(1.0 / 180 / n));
        CHECK_CLOSE(t, product / n * 12.0, 0.0, 5.0 / sqrt((double)n));
    }
}

/* truth: error.h's contract: the message is formatted, file and line kept, -1 returned;
 *   bytes outside printable ASCII (0x20 to 0x7e) in the message and the file name come
 *   out as \xNN, in lower-case hex, and a message too long to quote whole is cut before
 *   an escape, never inside one. Quoting is idempotent (a quoted message passed on
 *   through "%s" stays as it is).
 * catches: a truncated or missing message, a lost line number, a file's raw bytes (a
 *   terminal escape) echoed, an escape cut in half, space or '~' quoted. */
static void test_error_set(struct check *t)
{
    struct error err, again;
    CHECK(t, error_set(&err, "a.scene", 12, "expected %d numbers", 4) == -1);
    CHECK(t, strcmp(err.file, "a.scene") == 0);
    CHECK(t, err.line == 12);
    CHECK(t, strcmp(err.message, "expected 4 numbers") == 0);
    CHECK(t, error_set(NULL, "x", 1, "no record") == -1);
    error_set(&err, "b\tc\x7f.scene", 3, "'%s' is not a number", "\x01\xff\x1b[31m ~\n");
    CHECK(t, strcmp(err.file, "b\\x09c\\x7f.scene") == 0);
    CHECK(t, strcmp(err.message, "'\\x01\\xff\\x1b[31m ~\\x0a' is not a number") == 0);
    error_set(&again, err.file, 3, "%s", err.message);
    CHECK(t, strcmp(again.message, err.message) == 0 && strcmp(again.file, err.file) == 0);
    char long_text[ERROR_MESSAGE_MAX];
    memset(long_text, '\x1b', sizeof long_text - 1);
    long_text[sizeof long_text - 1] = '\0';
    error_set(&err, "", 0, "ab%s", long_text);
    size_t n = strlen(err.message);
    CHECK(t, n < ERROR_MESSAGE_MAX && n >= ERROR_MESSAGE_MAX - 4 && (n - 2) % 4 == 0 &&
             strncmp(err.message + n - 4, "\\x1b", 4) == 0);
}

/* truth: outputs are whole or absent (README): before commit only a temporary exists
 *   (one NAME.XXXXXXXX.tmp, output.h); after commit only NAME; after abandon neither.
 * catches: writing the final name directly, leaving temporaries behind. */
static void test_outputs_are_atomic(struct check *t)
{
    const char *name = "build/test_base_output.txt";
    struct error err;
    remove(name);
    FILE *f = output_open(name, &err);
    CHECK(t, f != NULL);
    if (f == NULL)
        return;
    fputs("data\n", f);
    CHECK(t, !file_exists(name) && count_temporaries(name) == 1);
    CHECK(t, output_commit(f, &err) == 0);
    CHECK(t, file_exists(name) && no_temporaries(name));
    remove(name);
    f = output_open(name, &err);
    CHECK(t, f != NULL);
    output_abandon(f);
    CHECK(t, !file_exists(name) && no_temporaries(name));
    CHECK(t, output_open("build/no/such/directory/x.pfm", &err) == NULL);
}

/* truth: the FNV-1a 64-bit values published with the algorithm (the FNV page's test
 *   vectors: "" -> cbf29ce484222325, "a" -> af63dc4c8601ec8c, "foobar" ->
 *   85944171f73967e8), and hash.h's promise that a fold goes on from an earlier h.
 * tolerance: none.
 * catches: FNV-1 (multiply before XOR), a wrong prime or basis, a fold that restarts. */
static void test_fnv1a_vectors(struct check *t)
{
    CHECK(t, fnv1a(FNV1A_OFFSET_BASIS, "", 0) == UINT64_C(0xcbf29ce484222325));
    CHECK(t, fnv1a(FNV1A_OFFSET_BASIS, "a", 1) == UINT64_C(0xaf63dc4c8601ec8c));
    CHECK(t, fnv1a(FNV1A_OFFSET_BASIS, "foobar", 6) == UINT64_C(0x85944171f73967e8));
    CHECK(t, fnv1a(fnv1a(FNV1A_OFFSET_BASIS, "foo", 3), "bar", 3) ==
                 UINT64_C(0x85944171f73967e8));
}

/* Fills n bytes with a pattern keyed by the byte's index; whether they still hold it. */
static void fill_pattern(unsigned char *p, size_t n)
{
    for (size_t i = 0; i < n; i++)
        p[i] = (unsigned char)(i * 7 + 1);
}

static int holds_pattern(const unsigned char *p, size_t n)
{
    int same = 1;
    for (size_t i = 0; i < n; i++)
        same = same && p[i] == (unsigned char)(i * 7 + 1);
    return same;
}

/* truth: alloc.h's contract, summed by hand: bytes_now is the payload asked for by the
 *   blocks not yet freed (a zero-byte request counts 1), xrealloc's new size replaces the
 *   old, and bytes_peak is the largest running sum. Blocks are freed in another order than
 *   made. A long double and a function pointer are stored in blocks, so that a payload
 *   misaligned by the header fails under UBSan (make check).
 * tolerance: none, byte counts.
 * catches: xrealloc counting old + new or only the growth, xfree not subtracting, xcalloc
 *   or xstrdup uncounted, the peak not raised by a realloc, contents lost by xrealloc. */
static void test_alloc_counts_bytes(struct check *t)
{
    alloc_restart_peak();
    size_t base = alloc_bytes_now();
    CHECK(t, alloc_bytes_peak() == base);
    unsigned char *a = xmalloc(100, 3, "test a");
    fill_pattern(a, 300);
    unsigned char *b = xcalloc(7, 11, "test b");
    int zero = 1;
    for (size_t i = 0; i < 77; i++)
        zero = zero && b[i] == 0;
    CHECK(t, zero);
    char *c = xstrdup("photon");
    CHECK(t, strcmp(c, "photon") == 0);
    CHECK(t, alloc_bytes_now() == base + 300 + 77 + 7 && alloc_bytes_peak() == base + 384);
    a = xrealloc(a, 1000, 3, "test a");
    CHECK(t, holds_pattern(a, 300));
    CHECK(t, alloc_bytes_now() == base + 3000 + 84 && alloc_bytes_peak() == base + 3084);
    a = xrealloc(a, 10, 3, "test a");
    CHECK(t, holds_pattern(a, 30));
    CHECK(t, alloc_bytes_now() == base + 30 + 84 && alloc_bytes_peak() == base + 3084);
    xfree(b);
    long double *ld = xmalloc(0, 8, "test ld");
    CHECK(t, alloc_bytes_now() == base + 30 + 7 + 1);
    ld = xrealloc(ld, 1, sizeof *ld, "test ld");
    *ld = 1.5L;
    void (**f)(struct check *) = xrealloc(NULL, 2, sizeof *f, "test f");
    f[1] = test_alloc_counts_bytes;
    CHECK(t, *ld == 1.5L && f[1] == test_alloc_counts_bytes);
    CHECK(t, alloc_bytes_now() == base + 37 + sizeof *ld + 2 * sizeof *f);
    xfree(c);
    xfree(a);
    xfree(NULL);
    xfree(f);
    xfree(ld);
    CHECK(t, alloc_bytes_now() == base && alloc_bytes_peak() == base + 3084);
}

/* ---- the harness itself (check.h) ---------------------------------------------------- */

static int reached_after_require; /* set by the line after the failing REQUIRE */

static void passes_then_requires_false(struct check *t)
{
    REQUIRE(t, 1 + 1 == 2);
    CHECK(t, 1 + 1 == 3);
    REQUIRE(t, 1 + 1 == 3);
    reached_after_require = 1;
    CHECK(t, 1 + 1 == 3);
}

/* truth: check.h's contract: a REQUIRE that holds does nothing; one that fails counts one
 *   failed check and returns from the test function there. Run on a harness of its own
 *   whose report budget is spent, so the deliberate failures print nothing.
 * tolerance: none, counts.
 * catches: REQUIRE going on after a failure (what it guards would run on a NULL pointer or
 *   a wrong size), a failure not counted, one counted twice. */
static void test_require_stops_the_test(struct check *t)
{
    struct check inner = {0, 0, 0, CHECK_MAX_REPORTS, NULL};
    reached_after_require = 0;
    passes_then_requires_false(&inner);
    CHECK(t, inner.failures_in_test == 2);
    CHECK(t, !reached_after_require);
}

void test_base(struct check *t)
{
    RUN_TEST(t, test_require_stops_the_test);
    RUN_TEST(t, test_streams_are_keyed);
    RUN_TEST(t, test_uniform_numbers);
    RUN_TEST(t, test_sequence02_is_a_net);
    RUN_TEST(t, test_sequence02_points_are_uniform);
    RUN_TEST(t, test_error_set);
    RUN_TEST(t, test_outputs_are_atomic);
    RUN_TEST(t, test_fnv1a_vectors);
    RUN_TEST(t, test_alloc_counts_bytes);
}
