/*
 * tests/test_photon.c -- the photon room: the 20-byte record's round trips and the
 * balanced kd-tree's searches against a linear scan.
 *
 * The kd-tree tests run every search on point sets chosen to break trees (uniform, the
 * walls of a Cornell box, all identical, all on a line in sorted order, few distinct
 * points repeated many times) at the boundary sizes and a few larger ones, and compare
 * the distances found with a linear scan over the same photons. Both sides compute each
 * squared distance from the same floats in the same order, so they agree exactly.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/base/rng.h"
#include "../src/photon/kdtree.h"
#include "check.h"
#include "tests.h"

#define K_MAX 1100        /* more than the largest test map, so k > n is reachable */
#define N_QUERIES 40      /* per map: enough to reach every subtree of the small ones */

/* ---- the record ---- */

/* A power channel spread evenly over the decades 1e-30 .. 1e30; every fifth one is 0. */
static double random_channel(struct rng *r)
{
    if (rng_next(r) % 5 == 0)
        return 0;
    return pow(10.0, 60.0 * rng_uniform(r) - 30.0);
}

/* 1 when every channel of the decoded power is within the bound photon.c derives:
 * max / 255.5 for max >= 2^-128, 2^-136 below (a tiny relative slack for the bound's
 * own rounding). */
static int power_within_bound(struct vec3 power)
{
    struct photon p = photon_pack(vec3(0, 0, 0), power, vec3(0, 0, 1), 0);
    struct vec3 back = photon_power(&p);
    double v = vec3_max_component(power);
    double bound = v >= ldexp(1.0, -128) ? v / 255.5 * (1 + 1e-12) : ldexp(1.0, -136);
    return fabs(back.x - power.x) <= bound && fabs(back.y - power.y) <= bound
           && fabs(back.z - power.z) <= bound;
}

/* truth: round trip photon_pack -> photon_power.
 * tolerance: max(R, G, B) / 255.5 per channel, the bound rounded RGBE guarantees (Ward's
 *   truncation would err by up to max / 128; the brief asks for 1%).
 * catches: truncating instead of rounding, a largest mantissa of 256 wrapping to 0 (the
 *   values just below a power of two), a wrong bias, zero or tiny powers decoding as
 *   garbage, strongly coloured powers losing their small channels entirely. */
static void test_photon_power_round_trip(struct check *t)
{
    static const double fixed[][3] = {
        {0, 0, 0}, {1, 1e-4, 0}, {0, 5, 0}, {1, 1, 1}, {255.75, 1, 0},
        {0.99999999, 0.5, 0.25}, {1.5e38, 1e30, 0}, {1e-39, 3e-40, 0}, {1e-45, 0, 1e-44},
        {4.0 - 1e-9, 2.0 - 1e-9, 1.0 - 1e-9}, {0.001, 0.0015, 0.00075}};
    for (size_t i = 0; i < sizeof fixed / sizeof fixed[0]; i++)
        CHECK(t, power_within_bound(vec3(fixed[i][0], fixed[i][1], fixed[i][2])));
    struct photon zero = photon_pack(vec3(0, 0, 0), vec3(0, 0, 0), vec3(0, 0, 1), 0);
    CHECK(t, vec3_length2(photon_power(&zero)) == 0);
    for (uint64_t i = 0; i < 20000; i++) {
        struct rng r = rng_stream(1, STREAM_TEST, 100, i);
        double scale = pow(10.0, 40.0 * rng_uniform(&r) - 20.0); /* one colour, any size */
        struct vec3 coloured = vec3_scale(vec3(rng_uniform(&r), rng_uniform(&r), 1e-4), scale);
        CHECK(t, power_within_bound(coloured));
        CHECK(t, power_within_bound(vec3(random_channel(&r), random_channel(&r),
                                         random_channel(&r))));
    }
}

/* truth: photon.h: photon_power_fits() is exactly photon_pack()'s range, every channel in
 *   [0, 2^127); the largest double below 2^127 packs within the RGBE bound (it rounds up
 *   into the top exponent, 128).
 * tolerance: as test_photon_power_round_trip.
 * catches: a range one exponent too wide (2^127 would wrap the exponent byte) or too
 *   narrow, NaN or a negative channel let through, only the largest channel tested. */
static void test_photon_power_range(struct check *t)
{
    double below = nextafter(PHOTON_POWER_MAX, 0);
    CHECK(t, PHOTON_POWER_MAX == ldexp(1.0, 127));
    CHECK(t, photon_power_fits(vec3(below, 0, 0)) && photon_power_fits(vec3(0, 0, 0)));
    CHECK(t, power_within_bound(vec3(below, below / 3, 0)));
    CHECK(t, !photon_power_fits(vec3(0, PHOTON_POWER_MAX, 0)));
    CHECK(t, !photon_power_fits(vec3(1, 1, HUGE_VAL)) && !photon_power_fits(vec3(1, -1e-300, 1)));
    CHECK(t, !photon_power_fits(vec3(NAN, 1, 1)) && !photon_power_fits(vec3(1, 1, NAN)));
}

/* Angle in radians between a and b (any lengths), well conditioned at 0 and pi. */
static double angle_between(struct vec3 a, struct vec3 b)
{
    return atan2(vec3_length(vec3_cross(a, b)), vec3_dot(a, b));
}

static int direction_within_bound(struct vec3 wi)
{
    struct photon p = photon_pack(vec3(0, 0, 0), vec3(1, 1, 1), wi, 0);
    struct vec3 back = photon_direction(&p);
    struct vec3 scaled = vec3_scale(wi, 1.0 / vec3_max_abs(wi)); /* no overflow in the test */
    return angle_between(back, scaled) <= PI / 510 + PI / 256 + 1e-12
           && fabs(vec3_length(back) - 1) <= 1e-15;
}

/* truth: round trip photon_pack -> photon_direction.
 * tolerance: pi/510 (theta, 255 steps over [0, pi]) + pi/256 (phi, 256 steps) radians,
 *   1.06 degrees, the bound photon.c derives (the brief asks for 1.5 degrees); the
 *   decoded vector is unit to 1e-15.
 * catches: truncated angles (errors up to twice the bound), phi's wrap at 2 pi, the
 *   poles (theta = 0, pi), x and y swapped, non-unit input not normalised. */
static void test_photon_direction_round_trip(struct check *t)
{
    static const double fixed[][3] = {
        {0, 0, 1}, {0, 0, -1}, {1e-12, 0, 1}, {0, -1e-12, -1}, {1, 0, 0}, {0, 1, 0},
        {1, -1e-9, 0}, {1, -1e-9, 1e-3}, {-1, 0, 0}, {-1, -1e-12, 0}, {0, -1, 0},
        {3, 4, 12}, {-1e-300, 1e-300, 0}, {1e300, -1e300, 1e300}};
    for (size_t i = 0; i < sizeof fixed / sizeof fixed[0]; i++)
        CHECK(t, direction_within_bound(vec3(fixed[i][0], fixed[i][1], fixed[i][2])));
    for (uint64_t i = 0; i < 50000; i++) {
        struct rng r = rng_stream(1, STREAM_TEST, 101, i);
        double z = 2 * rng_uniform(&r) - 1, phi = 2 * PI * rng_uniform(&r);
        double s = sqrt(fmax(0.0, 1 - z * z));
        struct vec3 wi = vec3(s * cos(phi), s * sin(phi), z); /* uniform on the sphere */
        CHECK(t, direction_within_bound(vec3_scale(wi, 1 + 9 * rng_uniform(&r))));
    }
}

/* truth: the record's definition (positions are the nearest floats; flags are kept;
 *   the plane is 0 until balanced). The 20 bytes are asserted at compile time.
 * tolerance: none.
 * catches: a coordinate stored in the wrong slot, flags truncated, an uninitialised plane. */
static void test_photon_position_and_flags(struct check *t)
{
    struct vec3 x = vec3(0.1, -2.5e10, 1.0 / 3.0);
    unsigned flags = PHOTON_CAUSTIC | PHOTON_SHADOW;
    struct photon p = photon_pack(x, vec3(1, 2, 3), vec3(0, 1, 0), flags);
    struct vec3 back = photon_position(&p);
    CHECK(t, back.x == (float)x.x && back.y == (float)x.y && back.z == (float)x.z);
    CHECK(t, p.flags == flags && p.plane == 0);
}

/* ---- the kd-tree: point sets and the linear scan ---- */

enum point_set { UNIFORM, CORNELL_WALLS, IDENTICAL, LINE, DUPLICATES, N_POINT_SETS };

/* Point i of n of a set; random sets draw from their own STREAM_TEST stream. */
static struct vec3 set_point(enum point_set set, size_t n, size_t i)
{
    struct rng r = rng_stream(2, STREAM_TEST, 200 + (uint64_t)set, i);
    double a = rng_uniform(&r), b = rng_uniform(&r);
    switch (set) {
    case UNIFORM:
        return vec3(8 * a - 3, b, 0.5 * rng_uniform(&r));
    case CORNELL_WALLS: {
        static const struct vec3 corner[5] = {{0, 0, 0}, {0, 1, 0}, {0, 0, 0},
                                              {0, 0, 0}, {1, 0, 0}};
        uint64_t wall = rng_next(&r) % 5; /* floor, ceiling, back, left, right */
        if (wall < 2)
            return vec3_add(corner[wall], vec3(a, 0, b));
        return vec3_add(corner[wall], wall == 2 ? vec3(a, b, 0) : vec3(0, a, b));
    }
    case IDENTICAL:
        return vec3(0.25, 0.5, 0.75);
    case LINE: /* sorted along a diagonal: median-of-three's easy case, quickselect's test */
        return vec3_scale(vec3(1, 2, -3), (double)i / (double)(n > 0 ? n : 1));
    default: /* DUPLICATES: 7 distinct points, each repeated about n / 7 times */
        return set_point(UNIFORM, 7, rng_next(&r) % 7);
    }
}

static struct photon *set_photons(enum point_set set, size_t n)
{
    struct photon *photons = xmalloc(n, sizeof *photons, "test photons");
    for (size_t i = 0; i < n; i++) /* flags cycle through the kinds, for the kind filter */
        photons[i] = photon_pack(set_point(set, n, i), vec3(1, 1, 1), vec3(0, 0, 1),
                                 1u << (i % 4));
    return photons;
}

/* |p - x|^2 exactly as kdtree.c computes it: float to double, then in axis order. */
static double photon_d2(const struct photon *p, struct vec3 x)
{
    double delta[3];
    delta[0] = (double)p->pos[0] - x.x;
    delta[1] = (double)p->pos[1] - x.y;
    delta[2] = (double)p->pos[2] - x.z;
    return delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2];
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The kind filter as kdtree.h defines it; kinds 0 keeps all. */
static int in_filter(const struct photon_query *q, const struct photon *p)
{
    return q->kinds == 0 || (p->flags & q->kinds) != 0;
}

/* The linear scan: the squared distances of photons[] from q->x that pass q's kind
 * filter, ascending, into scan[]; returns how many. max_r2 and k are applied later. */
static size_t scan_d2(const struct photon *photons, size_t n, const struct photon_query *q,
                      double *scan)
{
    size_t count = 0;
    for (size_t i = 0; i < n; i++) {
        double d2 = photon_d2(&photons[i], q->x);
        if (in_filter(q, &photons[i]))
            scan[count++] = d2;
    }
    qsort(scan, count, sizeof *scan, compare_doubles);
    return count;
}

/* 1 when nn's photons are distinct photons of map, each at its reported d2 from x. */
static int found_photons_consistent(const struct kdtree *map, const struct nearest *nn,
                                    struct vec3 x, unsigned char *seen)
{
    int ok = 1;
    memset(seen, 0, map->n_photons + 1);
    for (size_t i = 0; i < nn->found; i++) {
        ptrdiff_t at = nn->photon[i] - map->photons;
        if (at < 1 || (size_t)at > map->n_photons || seen[at])
            return 0;
        seen[at] = 1;
        ok = ok && photon_d2(nn->photon[i], x) == nn->d2[i];
    }
    return ok;
}

/* 1 when nn holds what the scan says the search q must find: the same distances, and
 * r2 as struct nearest defines it. scan[0..n_scan-1]: ascending squared distances of the
 * photons that pass q's filter. sorted: scratch for K_MAX doubles. */
static int matches_scan(const struct nearest *nn, const struct photon_query *q,
                        const double *scan, size_t n_scan, double *sorted)
{
    size_t n_within = 0;
    while (n_within < n_scan && scan[n_within] <= q->max_r2)
        n_within++;
    size_t expected = n_within < q->k ? n_within : q->k;
    if (nn->found != expected)
        return 0;
    memcpy(sorted, nn->d2, expected * sizeof *sorted);
    qsort(sorted, expected, sizeof *sorted, compare_doubles);
    for (size_t i = 0; i < expected; i++) {
        if (sorted[i] != scan[i])
            return 0;
    }
    double r2 = q->max_r2;  /* fewer than k within a finite max_r2: the searched radius */
    if (expected == q->k || q->max_r2 == HUGE_VAL)
        r2 = expected > 0 ? scan[expected - 1] : 0;  /* the farthest found */
    return nn->r2 == r2;
}

/* Query j: far outside the data (j = 0), exactly on a photon (ties at distance 0 and
 * duplicates), or anywhere in and around the sets' boxes. */
static struct vec3 query_point(const struct photon *photons, size_t n, uint64_t j)
{
    struct rng r = rng_stream(3, STREAM_TEST, 300, j);
    if (j == 0)
        return vec3(1e6, -1e6, 1e6);
    if (j % 3 == 1 && n > 0)
        return photon_position(&photons[rng_next(&r) % n]);
    double a = rng_uniform(&r), b = rng_uniform(&r);
    return vec3(10 * a - 4, 2 * b - 0.5, 4 * rng_uniform(&r) - 2);
}

/* A built map with the scan's copy of its photons and the scratch the checks use. */
struct test_map {
    struct photon *scan;   /* the same photons, in input order, for the linear scan */
    size_t n;
    struct kdtree *map;
    struct nearest *nn;    /* k_max = K_MAX */
    double *scan_d2;       /* n */
    double *sorted;        /* K_MAX */
    unsigned char *seen;   /* n + 1 */
};

static struct test_map test_map_create(enum point_set set, size_t n)
{
    struct test_map m;
    m.scan = set_photons(set, n);
    m.n = n;
    m.map = balance_kdtree(set_photons(set, n), n);
    m.nn = nearest_create(K_MAX);
    m.scan_d2 = xmalloc(n, sizeof *m.scan_d2, "test scan");
    m.sorted = xmalloc(K_MAX, sizeof *m.sorted, "test scan");
    m.seen = xmalloc(n + 1, 1, "test scan");
    return m;
}

static void test_map_free(struct test_map *m)
{
    xfree(m->seen);
    xfree(m->sorted);
    xfree(m->scan_d2);
    nearest_free(m->nn);
    kdtree_free(m->map);
    xfree(m->scan);
}

/* Whether nn's photons are in order of distance, nearest first. */
static int nearest_first(const struct nearest *nn)
{
    for (size_t i = 1; i < nn->found; i++)
        if (nn->d2[i] < nn->d2[i - 1])
            return 0;
    return 1;
}

/* Runs q on m's map and checks it against the scan (already in m->scan_d2, n_scan);
 * then nearest_sort() must order the same photons, each still at its distance. */
static int search_matches_scan(struct test_map *m, const struct photon_query *q,
                               size_t n_scan)
{
    locate_photons_of_kinds(m->map, q, m->nn);
    int ok = matches_scan(m->nn, q, m->scan_d2, n_scan, m->sorted) &&
             found_photons_consistent(m->map, m->nn, q->x, m->seen);
    nearest_sort(m->nn);
    return ok && nearest_first(m->nn) && matches_scan(m->nn, q, m->scan_d2, n_scan, m->sorted) &&
           found_photons_consistent(m->map, m->nn, q->x, m->seen);
}

static const size_t test_sizes[] = {0, 1, 2, 3, 4, 5, 7, 8, 9, 100, 1000, 1025};
#define N_TEST_SIZES (sizeof test_sizes / sizeof test_sizes[0])

static int compare_positions(const void *a, const void *b)
{
    const struct photon *p = a, *q = b;
    for (int i = 0; i < 3; i++) {
        if (p->pos[i] != q->pos[i])
            return p->pos[i] < q->pos[i] ? -1 : 1;
    }
    return 0;
}

/* 1 when map holds exactly the photons of scan[0..n-1] (as a multiset of positions).
 * Sorts both copies: scan here, and a copy of the map's array. */
static int same_photons(const struct kdtree *map, struct photon *scan, size_t n)
{
    if (map->n_photons != n)
        return 0;
    struct photon *mine = xmalloc(n, sizeof *mine, "test photons");
    if (n > 0)
        memcpy(mine, map->photons + 1, n * sizeof *mine);
    qsort(mine, n, sizeof *mine, compare_positions);
    qsort(scan, n, sizeof *scan, compare_positions);
    int same = 1;
    for (size_t i = 0; i < n; i++)
        same = same && compare_positions(&mine[i], &scan[i]) == 0;
    xfree(mine);
    return same;
}

/* truth: the invariants of kdtree.c, by kdtree_check(), and the input itself: the map
 *   must hold the same photons (positions as a multiset).
 * tolerance: none.
 * catches: a photon lost or duplicated by the median selection (the LINE and IDENTICAL
 *   sets stress its equal keys), a wrong left-subtree size (nodes outside 1..n), a split
 *   that leaves a smaller key on the right, kdtree_free(NULL) crashing. */
static void test_balance_kdtree_keeps_photons_in_order(struct check *t)
{
    for (int set = 0; set < N_POINT_SETS; set++) {
        for (size_t s = 0; s < N_TEST_SIZES; s++) {
            size_t n = test_sizes[s];
            struct photon *scan = set_photons((enum point_set)set, n);
            struct kdtree *map = balance_kdtree(set_photons((enum point_set)set, n), n);
            CHECK(t, kdtree_check(map));
            CHECK(t, same_photons(map, scan, n));
            CHECK(t, kdtree_bytes(map) >= (n + 1) * 20);
            kdtree_free(map);
            xfree(scan);
        }
    }
    kdtree_free(NULL);
    nearest_free(NULL);
}

/* The first axis along which photons[0..m-1] spread most, as kdtree.c's spec says. */
static int spec_axis(const struct photon *photons, size_t m)
{
    double extent[3];
    for (int a = 0; a < 3; a++) {
        float lo = photons[0].pos[a], hi = lo;
        for (size_t i = 1; i < m; i++) {
            lo = photons[i].pos[a] < lo ? photons[i].pos[a] : lo;
            hi = photons[i].pos[a] > hi ? photons[i].pos[a] : hi;
        }
        extent[a] = (double)hi - lo;
    }
    int axis = 0;
    for (int a = 1; a < 3; a++)
        axis = extent[a] > extent[axis] ? a : axis;
    return axis;
}

static int sort_axis; /* qsort's comparator reads the axis here */

static int compare_on_axis(const void *a, const void *b)
{
    float x = ((const struct photon *)a)->pos[sort_axis];
    float y = ((const struct photon *)b)->pos[sort_axis];
    return (x > y) - (x < y);
}

/* Nodes of a complete tree of m nodes in the subtree of node 2, counted level by level
 * over the heap slots 1..m. */
static size_t spec_left_size(size_t m)
{
    size_t count = 0;
    for (size_t first = 2, width = 1; first <= m; first *= 2, width *= 2)
        count += m - first + 1 < width ? m - first + 1 : width;
    return count;
}

/* The tree kdtree.c specifies, by brute force: sort the subtree's photons on their
 * widest axis, the root is the one with as many before it as the left subtree holds. */
static void spec_tree(struct photon *photons, size_t m, struct photon *heap, size_t node)
{
    sort_axis = spec_axis(photons, m);
    qsort(photons, m, sizeof *photons, compare_on_axis);
    size_t n_left = spec_left_size(m);
    heap[node] = photons[n_left];
    heap[node].plane = (unsigned char)sort_axis;
    if (n_left > 0)
        spec_tree(photons, n_left, heap, 2 * node);
    if (m - n_left > 1)
        spec_tree(photons + n_left + 1, m - n_left - 1, heap, 2 * node + 1);
}

/* truth: the tree kdtree.c's header specifies, built by sorting (spec_tree), which is
 *   unique when no two photons share a coordinate (UNIFORM); and the bytes the records
 *   take, counted by base/alloc.c: the in-place build may hold n + 1 records and the
 *   map's header, no second array.
 * tolerance: none.
 * catches: a record sent to the wrong heap slot (an off-by-one in the in-order rank, a
 *   partly full last level counted wrong), a placed mark left in a plane byte, a cycle
 *   followed twice, a copy of the array made while balancing. */
static void test_balance_kdtree_in_place_is_the_specified_tree(struct check *t)
{
    static const size_t sizes[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 31, 32, 33, 100, 1000};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        size_t n = sizes[s];
        struct photon *scan = set_photons(UNIFORM, n);
        struct photon *expected = xmalloc(n + 1, sizeof *expected, "test photons");
        spec_tree(scan, n, expected, 1);
        alloc_restart_peak();
        size_t before = alloc_bytes_now();
        struct kdtree *map = balance_kdtree(set_photons(UNIFORM, n), n);
        CHECK(t, alloc_bytes_peak() - before <= (n + 1) * sizeof *expected + sizeof *map);
        int same = 1;
        for (size_t i = 1; i <= n; i++)
            same = same && memcmp(&map->photons[i], &expected[i], sizeof *expected) == 0;
        CHECK(t, same);
        kdtree_free(map);
        xfree(expected);
        xfree(scan);
    }
}

/* truth: trees broken by hand must fail kdtree_check().
 * tolerance: none.
 * catches: a checker that cannot fail, which would make every build test above vacuous. */
static void test_kdtree_check_detects_broken_trees(struct check *t)
{
    size_t n = 100;
    struct kdtree *map = balance_kdtree(set_photons(UNIFORM, n), n);
    CHECK(t, kdtree_check(map));
    struct photon root = map->photons[1];  /* swap the root with the leftmost leaf */
    map->photons[1] = map->photons[64];
    map->photons[64] = root;
    CHECK(t, !kdtree_check(map));
    map->photons[64] = map->photons[1];
    map->photons[1] = root;
    CHECK(t, kdtree_check(map));
    map->photons[n].plane = 3;
    CHECK(t, !kdtree_check(map));
    kdtree_free(map);
}

/* Every (k, max_r2) search at query j of m against the scan; 1 when all match. */
static int all_searches_match(struct test_map *m, uint64_t j)
{
    static const double max_r2s[] = {HUGE_VAL, 0, 0.01, 0.25};
    size_t ks[] = {1, 7, 50, m->n + 3};  /* the last: k > n */
    struct photon_query q;
    memset(&q, 0, sizeof q);  /* kind filter off */
    q.x = query_point(m->scan, m->n, j);
    size_t n_scan = scan_d2(m->scan, m->n, &q, m->scan_d2);
    int ok = 1;
    for (size_t ik = 0; ik < sizeof ks / sizeof ks[0]; ik++) {
        for (size_t ir = 0; ir < sizeof max_r2s / sizeof max_r2s[0]; ir++) {
            q.k = ks[ik];
            q.max_r2 = max_r2s[ir];
            ok = ok && search_matches_scan(m, &q, n_scan);
        }
    }
    locate_photons(m->map, q.x, q.max_r2, q.k, m->nn); /* the plain entry point agrees */
    return ok && matches_scan(m->nn, &q, m->scan_d2, n_scan, m->sorted);
}

/* truth: brute force, a linear scan over the same photons.
 * tolerance: none; both sides compute the same doubles from the same floats. Distances,
 *   not photon identities, are compared, so ties cannot fail a correct tree; the found
 *   photons must also be distinct photons of the map at their reported distances.
 * catches: pruning with < for <= (max_r2 = 0 with queries exactly on photons), a subtree
 *   never visited, nearest_sort() losing, duplicating or misordering photons, a
 *   missing right child entered, the heap losing its top, k > n, r2
 *   not as documented, a far query or duplicates defeating the search. */
static void test_locate_photons_matches_linear_scan(struct check *t)
{
    for (int set = 0; set < N_POINT_SETS; set++) {
        for (size_t s = 0; s < N_TEST_SIZES; s++) {
            struct test_map m = test_map_create((enum point_set)set, test_sizes[s]);
            for (uint64_t j = 0; j < N_QUERIES; j++)
                CHECK(t, all_searches_match(&m, j));
            test_map_free(&m);
        }
    }
}

/* Searches with the kind filter at query j of m; 1 when all match the scan with the same
 * filter. */
static int kind_searches_match(struct test_map *m, uint64_t j)
{
    struct photon_query q;
    q.x = query_point(m->scan, m->n, j);
    q.kinds = (unsigned)(j % 4) * 3u; /* 0 (all kinds), then three different pairs */
    size_t n_scan = scan_d2(m->scan, m->n, &q, m->scan_d2);
    int ok = 1;
    for (size_t k = 1; k <= 50; k += 49) {
        q.k = k;
        q.max_r2 = HUGE_VAL;
        ok = ok && search_matches_scan(m, &q, n_scan);
        q.max_r2 = 0.04;
        ok = ok && search_matches_scan(m, &q, n_scan);
    }
    return ok;
}

/* truth: brute force, a linear scan applying the same kind filter (flags & kinds).
 * tolerance: none (same doubles on both sides).
 * catches: the filter ignored, applied to pruning (which would lose photons), r2
 *   counted over rejected photons. */
static void test_locate_photons_of_kinds_matches_linear_scan(struct check *t)
{
    static const enum point_set sets[] = {UNIFORM, CORNELL_WALLS, DUPLICATES};
    static const size_t sizes[] = {0, 1, 3, 1000};
    for (size_t set = 0; set < sizeof sets / sizeof sets[0]; set++) {
        for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
            struct test_map m = test_map_create(sets[set], sizes[s]);
            for (uint64_t j = 0; j < N_QUERIES; j++)
                CHECK(t, kind_searches_match(&m, j));
            test_map_free(&m);
        }
    }
}

void test_photon(struct check *t)
{
    RUN_TEST(t, test_photon_power_round_trip);
    RUN_TEST(t, test_photon_power_range);
    RUN_TEST(t, test_photon_direction_round_trip);
    RUN_TEST(t, test_photon_position_and_flags);
    RUN_TEST(t, test_balance_kdtree_keeps_photons_in_order);
    RUN_TEST(t, test_balance_kdtree_in_place_is_the_specified_tree);
    RUN_TEST(t, test_kdtree_check_detects_broken_trees);
    RUN_TEST(t, test_locate_photons_matches_linear_scan);
    RUN_TEST(t, test_locate_photons_of_kinds_matches_linear_scan);
}
