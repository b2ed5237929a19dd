/*
 * tests/test_merge_work_file.c -- the file of global work that tiles share
 * (app/work_file.h), byte by byte: a file written out by hand from work_file.h's and
 * illumination_map.h's tables is read as what it says and written back as the same bytes,
 * and illumination maps with a damaged field are refused. Renders that save and load the
 * file are test_merge.c's.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "../src/app/work_file.h"
#include "../src/base/hash.h"
#include "files.h"
#include "tests.h"

#define OUT "build/test_merge_work_file" /* the scratch files' names start so */

/* The one photon of the hand-written file below (example_bytes). */
static struct photon example_photon(void)
{
    struct photon p = {{1.0f, -2.0f, 0.5f}, {1, 2, 3, 4}, 5, 6, 0, PHOTON_CAUSTIC};
    return p;
}

/* b[0..7] = bits, lowest byte first: how the file keeps a double's IEEE 754 bits and its
 * checksum. */
static void put_bits(unsigned char *b, uint64_t bits)
{
    for (int i = 0; i < 8; i++)
        b[i] = (unsigned char)(bits >> (8 * i));
}

#define BITS_ONE UINT64_C(0x3ff0000000000000)  /* 1.0 */
#define BITS_TWO UINT64_C(0x4000000000000000)  /* 2.0 */
#define BITS_HALF UINT64_C(0x3fe0000000000000) /* 0.5 */

/* Where the parts of example_bytes()'s illumination maps start, counted from the byte
 * that says they follow: P; primitive 0's flag; primitive 1's res_u, ci_side, DI
 * irradiances, its elements' CI flags and its one CI sub-map; and their length. */
enum {
    AT_P = 1, AT_FLAG_0 = 5, AT_RES_U = 7, AT_CI_SIDE = 11, AT_DI = 12, AT_CI_FLAGS = 60,
    AT_CI = 62, MAPS_BYTES = 158
};

/* Appends the FNV-1a checksum of b[0..n-1]; the new length. */
static size_t with_checksum(unsigned char *b, size_t n)
{
    put_bits(b + n, fnv1a(FNV1A_OFFSET_BASIS, b, n));
    return n + 8;
}

/* What work_file.h's and illumination_map.h's tables say this work is in the file, written
 * out by hand: little-endian numbers, the floats' and doubles' IEEE 754 bits, the
 * checksum. Two maps, the first of one photon, the second absent; one cache record;
 * illumination maps for two primitives, 0 without a map, 1 with 2 x 1 DI elements of
 * irradiance (1, 0, 0) and (0, 2, 0) and CI sub-maps of 2 x 2 elements, of which element
 * 1 has one, whose element 1 (u high, v low) is (0, 0, 0.5). Returns the length; *maps_at
 * is where the illumination maps start. */
static size_t example_bytes(unsigned char *b, size_t *maps_at)
{
    static const unsigned char head[] = {
        'p', 'h', 'o', 't', 'o', 'n', 'G', 'W', 3, 0, 0, 0,           /* magic, version  */
        0xef, 0xcd, 0xab, 0x89, 0x67, 0x45, 0x23, 0x01,               /* hash            */
        2, 0, 0, 0,                                                   /* two maps        */
        1, 1, 0, 0, 0, 0, 0, 0, 0,                                    /* one photon      */
        0, 0, 0x80, 0x3f, 0, 0, 0, 0xc0, 0, 0, 0, 0x3f,               /* 1, -2, 0.5      */
        1, 2, 3, 4, 5, 6, 0, PHOTON_CAUSTIC,                          /* power ... flags */
        0,                                                            /* no second map   */
        1, 0, 0, 0, 0, 0, 0, 0,                                       /* one record      */
    };
    static const unsigned char maps_head[] = {
        1, 2, 0, 0, 0,        /* maps follow, for P = 2 primitives                   */
        0,                    /* primitive 0: no map                                 */
        1, 2, 0, 1, 0, 2,     /* primitive 1: res_u 2, res_v 1, ci_side 2            */
    };
    size_t n = sizeof head;
    memcpy(b, head, n);
    memset(b + n, 0, 28 * 8); /* the record: all 0.0 but n.z = 1 and R = 2 */
    put_bits(b + n + 5 * 8, BITS_ONE);
    put_bits(b + n + 9 * 8, BITS_TWO);
    n += 28 * 8;
    *maps_at = n;
    memset(b + n, 0, MAPS_BYTES);
    memcpy(b + n, maps_head, sizeof maps_head);
    put_bits(b + n + AT_DI, BITS_ONE);              /* DI element 0: R = 1                */
    put_bits(b + n + AT_DI + 4 * 8, BITS_TWO);      /* DI element 1: G = 2                */
    b[n + AT_CI_FLAGS + 1] = 1;                     /* DI element 1 has a CI sub-map      */
    put_bits(b + n + AT_CI + 5 * 8, BITS_HALF);     /* its CI element 1: B = 0.5          */
    return with_checksum(b, n + MAPS_BYTES);
}

/* Whether primitive 1 of maps has irradiance e at (u, v), of caustics alone or of all. */
static int irradiance_is(const struct illumination_maps *maps, double u, double v,
                         int caustic_only, struct vec3 e)
{
    struct vec3 got = illumination_irradiance(maps, 1, u, v, caustic_only);
    return got.x == e.x && got.y == e.y && got.z == e.z;
}

/* Whether example work's illumination maps say what example_bytes() meant: DI elements
 * along u, CI elements row by row (v the row), a DI element without a sub-map. */
static int example_illumination_read(const struct illumination_maps *maps)
{
    return !illumination_covers(maps, 0) && illumination_covers(maps, 1) &&
           !illumination_covers(maps, 2) && irradiance_is(maps, 0.25, 0.5, 0, vec3(1, 0, 0)) &&
           irradiance_is(maps, 0.25, 0.5, 1, vec3(0, 0, 0)) &&
           irradiance_is(maps, 0.6, 0.9, 0, vec3(0, 2, 0)) &&
           irradiance_is(maps, 0.9, 0.2, 0, vec3(0, 2, 0.5)) &&
           irradiance_is(maps, 0.9, 0.2, 1, vec3(0, 0, 0.5));
}

/* truth: work_file.h's and illumination_map.h's byte tables, written out by hand above
 *   (a photon's floats and the doubles as IEEE bits, numbers lowest byte first, DI and CI
 *   elements row by row): what is read must be what the bytes were written to say, and
 *   writing it back must give the same bytes.
 * tolerance: none.
 * catches: a field in the wrong place or byte order, the unused heap[0] written, a
 *   missing map not marked, res_u and res_v swapped, elements in column order, a CI
 *   sub-map in the wrong element, the checksum not over every byte before it. */
static void test_work_file_format(struct check *t)
{
    unsigned char bytes[1024];
    size_t maps_at, n = example_bytes(bytes, &maps_at);
    write_bytes_file(OUT "_expected.work", bytes, n);
    struct global_work work = {NULL, 0, NULL, 0, NULL};
    struct error err;
    uint64_t hash = UINT64_C(0x0123456789abcdef);
    CHECK(t, work_file_read(OUT "_expected.work", hash, &work, &err) == 0);
    int whole = work.n_maps == 2 && work.maps[0] != NULL && work.maps[1] == NULL &&
                work.maps[0]->n_photons == 1 && work.n_records == 1 && work.illumination != NULL;
    CHECK(t, whole);
    if (whole) {
        struct photon p = example_photon();
        struct irradiance_record record;
        memset(&record, 0, sizeof record);
        record.n = vec3(0, 0, 1);
        record.r = 2;
        CHECK(t, memcmp(&work.maps[0]->photons[1], &p, sizeof p) == 0);
        CHECK(t, memcmp(&work.records[0], &record, sizeof record) == 0);
        CHECK(t, example_illumination_read(work.illumination));
        CHECK(t, work_file_write(OUT "_example.work", hash, &work, &err) == 0);
        CHECK(t, files_equal(OUT "_example.work", OUT "_expected.work"));
    }
    global_work_free(&work);
}

/* Whether the n bytes, as a file of global work, are refused with message, after the
 * words that say what was being done, "cannot load the saved work (--load-photons): "
 * (and leave nothing allocated: the work stays empty for global_work_free to find so). */
static int example_refused(const unsigned char *bytes, size_t n, const char *message)
{
    write_bytes_file(OUT "_planted.work", bytes, n);
    struct global_work work = {NULL, 0, NULL, 0, NULL};
    struct error err;
    static const char doing[] = "cannot load the saved work (--load-photons): ";
    int refused = work_file_read(OUT "_planted.work", UINT64_C(0x0123456789abcdef), &work,
                                 &err) < 0 && strncmp(err.message, doing, strlen(doing)) == 0 &&
                  strstr(err.message, message) != NULL;
    if (!refused)
        fprintf(stderr, "test_merge: planted file not refused with '%s'\n", message);
    global_work_free(&work);
    return refused;
}

/* truth: illumination_map.h's contract: maps are read only when every side is in range,
 *   every flag 0 or 1 and every irradiance finite, and a count is checked against the
 *   bytes left before anything is allocated for it; work_file.h's: a file of the older
 *   version is refused, saying so. Each change is planted in example_bytes()'s file and
 *   the checksum made again, so only the check meant for it can refuse it.
 * tolerance: none.
 * catches: a side of 0 or over its limit accepted (a map of no elements, or one as large
 *   as a damaged byte says), an infinite irradiance let through to the image, a count
 *   trusted before its bytes are there, an older version's file read as this one. */
static void test_bad_illumination_maps_are_refused(struct check *t)
{
    static const struct {
        size_t at; /* from the start of the illumination maps */
        unsigned char bytes[8];
        size_t n_bytes;
        const char *message;
    } planted[] = {
        {AT_P, {0xff, 0xff, 0xff, 0xff}, 4, "truncated: 4294967295 illumination maps need"},
        {AT_FLAG_0, {2}, 1, "illumination map of primitive 0: expected 0 or 1, got 2"},
        {AT_RES_U, {1, 4}, 2, "primitive 1: 1025 elements along a side, not 1 to 1024"},
        {AT_CI_SIDE, {0}, 1, "primitive 1: 0 elements along a side, not 1 to 16"},
        {AT_CI_SIDE, {17}, 1, "primitive 1: 17 elements along a side, not 1 to 16"},
        {AT_RES_U, {0, 4, 0, 4}, 4, "truncated: 3145728 DI irradiances need 25165824 bytes"},
        {AT_DI + 8, {0, 0, 0, 0, 0, 0, 0xf0, 0x7f}, 8, "primitive 1: a number is not finite"},
        {AT_CI_FLAGS, {3}, 1, "illumination map of primitive 1: expected 0 or 1, got 3"},
    };
    unsigned char bytes[1024];
    size_t maps_at, n;
    for (size_t i = 0; i < sizeof planted / sizeof planted[0]; i++) {
        n = example_bytes(bytes, &maps_at);
        memcpy(bytes + maps_at + planted[i].at, planted[i].bytes, planted[i].n_bytes);
        n = with_checksum(bytes, n - 8);
        CHECK(t, example_refused(bytes, n, planted[i].message));
    }
    n = example_bytes(bytes, &maps_at);
    CHECK(t, example_refused(bytes, n - 12, "truncated: 12 CI irradiances need 96 bytes, 92"));
    bytes[8] = 2;
    CHECK(t, example_refused(bytes, n, "version 2 of the saved work; this photon reads "
                             "version 3"));
}

/* Where example_bytes()'s values start: its photon's position, power and flags; its
 * record's normal's z and irradiance's R. */
enum { AT_POSITION = 33, AT_POWER = 45, AT_FLAGS = 52, AT_NORMAL_Z = 102, AT_E = 110 };

/* truth: work_file.h: every value is checked for its range, not only the checksum, which
 *   anyone can compute: each value planted in example_bytes()'s file, its checksum made
 *   again, is refused naming what is wrong: a photon of some 1e37 W (RGBE 240 240 240 250:
 *   240 x 2^(250 - 135), photon.h), above WORK_PHOTON_POWER_MAX; a photon at an infinite x;
 *   a flag that is no photon kind; a record's negative irradiance, or its normal of length
 *   2; a negative irradiance in an illumination map. The same planted at the largest
 *   power the file takes (2^110 W, RGBE 128 128 128 238) is read. Each refusal says
 *   "cannot load ... (--load-photons)"; the 1e37 W photon is not saved either, the
 *   message saying "cannot save ... (--save-photons)" (a failed write: the work is the
 *   render's own), and no file is left.
 * tolerance: none.
 * catches: the checksum taken for a proof of sense: a crafted file's 1e37 W photons or
 *   negative irradiance rendered (nonsense pixels, or a NaN from a square root); a
 *   message that does not say whether the file was being loaded or saved. */
static void test_values_out_of_range_are_refused(struct check *t)
{
    static const struct {
        size_t at; /* from the file's start, or from the illumination maps' with maps */
        int maps;
        unsigned char bytes[8];
        size_t n_bytes;
        const char *message;
    } planted[] = {
        {AT_POWER, 0, {240, 240, 240, 250}, 4, "map 0, photon 1: power 9.9"},
        {AT_POSITION, 0, {0, 0, 0x80, 0x7f}, 4, "map 0, photon 1: its position is not finite"},
        {AT_FLAGS, 0, {3}, 1, "map 0, photon 1: flags 3 are not one photon kind"},
        {AT_E, 0, {0, 0, 0, 0, 0, 0, 0xf0, 0xbf}, 8, "cache record 0: irradiance (-1, 0, 0)"},
        {AT_NORMAL_Z, 0, {0, 0, 0, 0, 0, 0, 0, 0x40}, 8, "cache record 0: its normal is not "
         "of unit length (2)"},
        {AT_DI, 1, {0, 0, 0, 0, 0, 0, 0xf0, 0xbf}, 8, "primitive 1: irradiance -1 is negative"},
    };
    unsigned char bytes[1024];
    size_t maps_at, n;
    for (size_t i = 0; i < sizeof planted / sizeof planted[0]; i++) {
        n = example_bytes(bytes, &maps_at);
        memcpy(bytes + (planted[i].maps ? maps_at : 0) + planted[i].at, planted[i].bytes,
               planted[i].n_bytes);
        n = with_checksum(bytes, n - 8);
        CHECK(t, example_refused(bytes, n, planted[i].message));
    }
    n = example_bytes(bytes, &maps_at);
    memcpy(bytes + AT_POWER, (const unsigned char[]){128, 128, 128, 238}, 4);
    n = with_checksum(bytes, n - 8);
    write_bytes_file(OUT "_planted.work", bytes, n);
    struct global_work work = {NULL, 0, NULL, 0, NULL};
    struct error err;
    CHECK(t, work_file_read(OUT "_planted.work", UINT64_C(0x0123456789abcdef), &work,
                            &err) == 0);
    if (work.n_maps > 0 && work.maps[0] != NULL) { /* the same photon at 1e37 W, saved */
        memcpy(work.maps[0]->photons[1].power, (const unsigned char[]){240, 240, 240, 250}, 4);
        remove(OUT "_saved.work");
        CHECK(t, work_file_write(OUT "_saved.work", 1, &work, &err) < 0 && err.failed_write &&
                 strstr(err.message, "cannot save the work (--save-photons): map 0, photon 1: "
                        "power 9.9") == err.message && !file_exists(OUT "_saved.work"));
    }
    global_work_free(&work);
}

void test_merge_work_file(struct check *t)
{
    RUN_TEST(t, test_work_file_format);
    RUN_TEST(t, test_bad_illumination_maps_are_refused);
    RUN_TEST(t, test_values_out_of_range_are_refused);
}
