/*
 * tests/test_cache_lookup.c -- lookups in the irradiance cache (photon/irradiance_cache.h):
 * the octree against a brute-force sum over every record, records added between lookups
 * as a renderer's pre-pass adds them; the lookup's contract at its boundaries, worked by
 * hand; and caches over boxes that are not finite. Records themselves are test_cache.c's.
 */
#include <math.h>
#include <stdlib.h>

#include "../src/base/rng.h"
#include "../src/photon/irradiance_cache.h"
#include "close_to.h"
#include "tests.h"

/* ---- lookups ---- */

/* The lookup written out from its contract, over every record in order. Returns
 * how many records were usable; when any, *e is the clamped mean and *scale the
 * weighted mean of the terms' magnitudes (what rounding is relative to). */
static int brute_force_lookup(const struct irradiance_record *records, size_t n_records, double a,
                              struct vec3 p, struct vec3 n, struct vec3 *e, double *scale)
{
    struct vec3 sum = vec3_zero();
    double sum_w = 0, sum_abs = 0;
    int usable = 0;
    for (size_t i = 0; i < n_records; i++) {
        const struct irradiance_record *ri = &records[i];
        struct vec3 d = vec3_sub(p, ri->p);
        if (vec3_dot(d, vec3_scale(vec3_add(n, ri->n), 0.5)) < -CACHE_FRONT_TOLERANCE * ri->r)
            continue;
        double epsilon = vec3_length(d) / ri->r + sqrt(fmax(0, 1 - vec3_dot(n, ri->n)));
        if (epsilon >= a)
            continue;
        double w = 1 / fmax(epsilon, CACHE_EPSILON_MIN);
        struct vec3 turn = vec3_cross(ri->n, n), value;
        value.x = ri->e.x + vec3_dot(turn, ri->grad_r[0]) + vec3_dot(d, ri->grad_t[0]);
        value.y = ri->e.y + vec3_dot(turn, ri->grad_r[1]) + vec3_dot(d, ri->grad_t[1]);
        value.z = ri->e.z + vec3_dot(turn, ri->grad_r[2]) + vec3_dot(d, ri->grad_t[2]);
        sum = vec3_madd(sum, value, w);
        sum_abs += w * vec3_max_abs(value);
        sum_w += w;
        usable++;
    }
    if (usable == 0)
        return 0;
    *e = vec3_max(vec3_scale(sum, 1 / sum_w), vec3_zero());
    *scale = sum_abs / sum_w;
    return usable;
}

static struct vec3 random_vector(struct rng *rng, double size)
{
    return vec3(size * (2 * rng_uniform(rng) - 1), size * (2 * rng_uniform(rng) - 1),
                size * (2 * rng_uniform(rng) - 1));
}

/* A record at a random place (partly outside the unit box), facing one of the
 * six axis directions give or take 0.2, with R spread over 1e-3 .. 3 (and one
 * in 50 at 1e-9, for the depth limit), E in [0.5, 2] and gradients small enough
 * that E rarely clamps. */
static struct irradiance_record random_record(struct rng *rng)
{
    static const struct vec3 axes[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                        {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    struct irradiance_record r;
    r.p = vec3_add(vec3(0.5, 0.5, 0.5), random_vector(rng, 0.75));
    r.n = vec3_normalize(vec3_add(axes[rng_next(rng) % 6], random_vector(rng, 0.2)));
    r.r = rng_next(rng) % 50 == 0 ? 1e-9 : 1e-3 * pow(3000, rng_uniform(rng));
    r.e = vec3(0.5 + 1.5 * rng_uniform(rng), 0.5 + 1.5 * rng_uniform(rng),
               0.5 + 1.5 * rng_uniform(rng));
    for (int c = 0; c < 3; c++) {
        r.grad_r[c] = random_vector(rng, 0.5);
        r.grad_t[c] = random_vector(rng, 0.5 / r.r);
    }
    return r;
}

/* A query near a random record (within 1.2 a R_i, normal turned by up to ~0.3),
 * or anywhere in and around the box facing an axis. */
static void random_query(struct rng *rng, const struct irradiance_record *records, size_t n,
                         double a, struct vec3 *p, struct vec3 *normal)
{
    if (n > 0 && rng_next(rng) % 4 != 0) {
        const struct irradiance_record *ri = &records[rng_next(rng) % n];
        *p = vec3_add(ri->p, random_vector(rng, 0.7 * a * ri->r));
        *normal = vec3_normalize(vec3_add(ri->n, random_vector(rng, 0.3 * rng_uniform(rng))));
    } else {
        *p = vec3_add(vec3(0.5, 0.5, 0.5), random_vector(rng, 0.8));
        *normal = vec3_normalize(random_vector(rng, 1));
    }
}

/* truth: brute force (brute_force_lookup) over the same records, with records
 * added in ten batches between batches of lookups, as a renderer's pre-pass
 * does; a quarter of them outside the box the cache was made for, R from 1e-9
 * (deeper than the depth limit) to 3 (wider than the box). The octree's checker
 * runs after each batch. tolerance: 1e-12 of the terms' magnitude: the same
 * terms summed in another order. catches: a node pruned whose grown box holds
 * the query, a record in a node too small for its reach, records outside the
 * box lost, a child index broken by the node array growing, the front test or
 * the weight cap differing from the contract. */
static void test_lookup_matches_brute_force(struct check *t)
{
    enum { BATCHES = 10, PER_BATCH = 300, QUERIES = 400 };
    const double a = 0.3;
    struct irradiance_record *records = calloc(BATCHES * PER_BATCH, sizeof *records);
    struct aabb box = {{0, 0, 0}, {1, 1, 1}};
    struct irradiance_cache *cache = irradiance_cache_create(box, a);
    struct rng rng = rng_stream(2, STREAM_TEST, 0, 0);
    size_t n = 0;
    int same = 1, found = 0, several = 0;
    for (int batch = 0; batch <= BATCHES; batch++) {
        for (int q = 0; q < QUERIES; q++) {
            struct vec3 p, normal, e = vec3(-1, -1, -1), e_brute = vec3(-2, -2, -2);
            double scale = 0;
            random_query(&rng, records, n, a, &p, &normal);
            double strictness = q % 2 ? a : 0.5 * a; /* the cache's a, and a fill's */
            int found_cache = irradiance_cache_lookup(cache, p, normal, strictness, &e);
            int usable = brute_force_lookup(records, n, strictness, p, normal, &e_brute, &scale);
            same = same && found_cache == (usable > 0);
            if (found_cache && usable > 0)
                same = same && vec3_max_abs(vec3_sub(e, e_brute)) <= 1e-12 * scale;
            found += usable > 0;
            several += usable > 1;
        }
        for (int i = 0; batch < BATCHES && i < PER_BATCH; i++) {
            records[n] = random_record(&rng);
            irradiance_cache_add(cache, &records[n++]);
        }
        CHECK(t, irradiance_cache_check(cache) && irradiance_cache_records(cache) == n);
    }
    CHECK(t, same);
    CHECK(t, found > BATCHES * QUERIES / 4);    /* the queries do reach records, */
    CHECK(t, several > BATCHES * QUERIES / 20); /* often several at once      */
    CHECK(t, irradiance_cache_bytes(cache) >= n * sizeof(struct irradiance_record));
    irradiance_cache_free(cache);
    free(records);
}

static struct irradiance_record plain_record(struct vec3 p, struct vec3 n, struct vec3 e, double r)
{
    struct irradiance_record record;
    record.p = p;
    record.n = n;
    record.e = e;
    record.r = r;
    for (int c = 0; c < 3; c++)
        record.grad_r[c] = record.grad_t[c] = vec3_zero();
    return record;
}

/* truth: the contract's boundaries, worked by hand. One record at the origin
 * facing z, R = 1, a = 0.3: a query 0.1 below it (d = -0.1 < -0.05 R) is in
 * front and gets nothing; 0.04 below (within the tolerance) and 0.1 above get
 * E; 0.3 away along the surface is just out of reach (epsilon = a exactly), and
 * so is the same point with a normal turned by 60 degrees (sqrt(1 - cos 60) =
 * 0.71). A query at the record itself gives its E (weight capped, no NaN), also
 * beside a second record 0.01 away with another E, and with normals whose n . n
 * rounds below 1 (a weight of 1e8) or above 1 (1 - n . n < 0 under the root). A
 * gradient pulling E below 0 is clamped, in its channel only. Nothing at all: 0
 * and *e untouched. free(NULL) is a no-op. tolerance: rounding (1e-15), or 1e-9
 * beside the second record: its weight, 100 against 1e12, moves E by at most
 * 100 (5 - 1) / 1e12 = 4e-10. catches: d_i tested with < 0 (no tolerance) or on
 * the wrong side, <= a for < a, an infinite weight or a root of -2^-52 turning
 * into NaN, negative irradiance. */
static void test_lookup_boundaries(struct check *t)
{
    struct aabb box = {{-1, -1, -1}, {1, 1, 1}};
    struct irradiance_cache *cache = irradiance_cache_create(box, 0.3);
    struct vec3 z = vec3(0, 0, 1), e = vec3(-1, -1, -1);
    CHECK(t, irradiance_cache_lookup(cache, vec3(0, 0, 0), z, 0.3, &e) == 0 && e.x == -1);
    struct irradiance_record r = plain_record(vec3(0, 0, 0), z, vec3(1, 2, 3), 1);
    irradiance_cache_add(cache, &r);
    CHECK(t, irradiance_cache_lookup(cache, vec3(0, 0, -0.1), z, 0.3, &e) == 0 && e.x == -1);
    CHECK(t, irradiance_cache_lookup(cache, vec3(0, 0, -0.04), z, 0.3, &e) == 1 && e.y == 2);
    CHECK(t, irradiance_cache_lookup(cache, vec3(0, 0, 0.1), z, 0.3, &e) == 1 && e.z == 3);
    CHECK(t, irradiance_cache_lookup(cache, vec3(0.3, 0, 0), z, 0.3, &e) == 0);
    CHECK(t, irradiance_cache_lookup(cache, vec3(0, 0, 0), vec3(sqrt(0.75), 0, 0.5), 0.3, &e) == 0);
    CHECK(t, irradiance_cache_lookup(cache, vec3(0, 0, 0), z, 0.3, &e) == 1);
    CHECK(t, close_to(e.x, 1, 1e-15) && close_to(e.y, 2, 1e-15) && close_to(e.z, 3, 1e-15));
    struct irradiance_record beside = plain_record(vec3(0.01, 0, 0), z, vec3(5, 5, 5), 1);
    irradiance_cache_add(cache, &beside);
    CHECK(t, irradiance_cache_lookup(cache, vec3(0, 0, 0), z, 0.3, &e) == 1);
    CHECK(t, close_to(e.x, 1, 1e-9) && close_to(e.y, 2, 1e-9) && close_to(e.z, 3, 1e-9));
    /* n . n rounds to 1 - 2^-53 for the first normal and to 1 + 2^-52 for the
   * second. */
    struct vec3 below = vec3_normalize(vec3(0.3, 0.4, 1)), above = vec3_normalize(vec3(1, 1, 1));
    struct irradiance_record tilted = plain_record(vec3(0.5, 0.5, 0.5), below, vec3(7, 8, 9), 1);
    struct vec3 along = vec3_normalize(vec3_cross(below, vec3(0, 1, 0)));
    tilted.grad_t[0] = vec3_scale(along, -100); /* E_R = 7 - 100 x: below 0 at x = 0.1 */
    irradiance_cache_add(cache, &tilted);
    struct irradiance_record skewed = plain_record(vec3(-0.5, 0.5, 0.5), above, vec3(4, 5, 6), 1);
    irradiance_cache_add(cache, &skewed);
    CHECK(t, irradiance_cache_lookup(cache, vec3(0.5, 0.5, 0.5), below, 0.3, &e) == 1);
    CHECK(t, close_to(e.x, 7, 1e-15) && close_to(e.y, 8, 1e-15) && close_to(e.z, 9, 1e-15));
    CHECK(t, irradiance_cache_lookup(cache, vec3(-0.5, 0.5, 0.5), above, 0.3, &e) == 1);
    CHECK(t, close_to(e.x, 4, 1e-15) && close_to(e.y, 5, 1e-15) && close_to(e.z, 6, 1e-15));
    CHECK(t, irradiance_cache_lookup(cache, vec3_madd(vec3(0.5, 0.5, 0.5), along, 0.1), below, 0.3,
                                     &e) == 1);
    CHECK(t, e.x == 0 && close_to(e.y, 8, 1e-15) && close_to(e.z, 9, 1e-15));
    CHECK(t, irradiance_cache_check(cache) && irradiance_cache_records(cache) == 4);
    irradiance_cache_free(cache);
    irradiance_cache_free(NULL);
}

/* truth: irradiance_cache.h's contract: the box only places the octree, so a cache over
 *   a box that is not finite (a scene with an object reaching past DBL_MAX: hi = inf, or
 *   hi - lo overflowing) or empty (lo = inf, hi = -inf) still finds each record at its
 *   own point, near the origin and far out.
 * tolerance: rounding (1e-15).
 * catches: such a box refused by an assertion (reached from a scene file), an octree
 *   built over an infinite side (NaN corners), a record lost outside the cube. */
static void test_cache_over_unbounded_box(struct check *t)
{
    const double inf = HUGE_VAL;
    const struct aabb boxes[] = {{{0, 0, 0}, {inf, 1, 1}},
                                 {{-1.7e308, 0, 0}, {1.7e308, 1, 1}},
                                 {{inf, inf, inf}, {-inf, -inf, -inf}}};
    const struct vec3 z = vec3(0, 0, 1), at[2] = {{0.5, 0.5, 0.5}, {1e300, 0.5, 0.5}};
    for (size_t b = 0; b < sizeof boxes / sizeof boxes[0]; b++) {
        struct irradiance_cache *cache = irradiance_cache_create(boxes[b], 0.3);
        for (int i = 0; i < 2; i++) {
            struct irradiance_record r = plain_record(at[i], z, vec3(1, 2, i + 3.0), 0.1);
            irradiance_cache_add(cache, &r);
        }
        CHECK(t, irradiance_cache_check(cache) && irradiance_cache_records(cache) == 2);
        for (int i = 0; i < 2; i++) {
            struct vec3 e = vec3_zero();
            CHECK(t, irradiance_cache_lookup(cache, at[i], z, 0.3, &e) == 1);
            CHECK(t, close_to(e.y, 2, 1e-15) && close_to(e.z, i + 3.0, 1e-15));
        }
        irradiance_cache_free(cache);
    }
}

void test_cache_lookup(struct check *t)
{
    RUN_TEST(t, test_lookup_matches_brute_force);
    RUN_TEST(t, test_lookup_boundaries);
    RUN_TEST(t, test_cache_over_unbounded_box);
}
