/*
 * tests/bench/bench_knn.c -- bench/README.md, knn: k-nearest photons on Cornell-box walls.
 *
 * Points on the five inner walls of the unit box, made by SplitMix64 exactly as bench/README.md
 * spells it (not our keyed rng.h streams: the points must be the ones any outside
 * library, e.g. nanoflann, is given), seed 1 for the photons and seed 2 for the
 * queries. For N = 100k and 1M: the map's build (balance_kdtree) timed, then 100,000
 * exact k-nearest queries with no maximum radius for k = 50 and k = 500, each figure the
 * median of BENCH_REPEATS runs, with the checksums bench/README.md documents.
 */
#include "bench.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "../../src/base/alloc.h"
#include "../../src/photon/kdtree.h"

#define N_QUERIES 100000   /* bench/README.md, knn */
#define PHOTON_SEED 1u     /* bench/README.md, knn: seed 1 for photons, 2 for query points */
#define QUERY_SEED 2u

/* One SplitMix64 step, bench/README.md's definition (wrapping unsigned 64-bit arithmetic). */
static uint64_t splitmix_next(uint64_t *s)
{
    *s += 0x9E3779B97F4A7C15u;
    uint64_t z = *s;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

static double unit_double(uint64_t *s)
{
    return (double)(splitmix_next(s) >> 11) * (1.0 / 9007199254740992.0); /* 2^-53 */
}

/* The next point: wall 0 floor (a, 0, b), 1 ceiling (a, 1, b), 2 back (a, b, 0),
 * 3 left (0, a, b), 4 right (1, a, b); each coordinate rounded to float. */
static struct vec3 next_wall_point(uint64_t *s)
{
    uint64_t wall = ((splitmix_next(s) >> 32) * 5) >> 32;
    double a = (float)unit_double(s);
    double b = (float)unit_double(s);
    switch (wall) {
    case 0: return vec3(a, 0, b);
    case 1: return vec3(a, 1, b);
    case 2: return vec3(a, b, 0);
    case 3: return vec3(0, a, b);
    default: return vec3(1, a, b);
    }
}

static struct vec3 *wall_points(uint64_t seed, size_t n)
{
    struct vec3 *points = xmalloc(n, sizeof *points, "bench points");
    uint64_t s = seed;
    for (size_t i = 0; i < n; i++)
        points[i] = next_wall_point(&s);
    return points;
}

/* bench/README.md: sum over i of (i + 1) (x_i + 2 y_i + 3 z_i), in double. */
static double points_checksum(const struct vec3 *points, size_t n)
{
    double sum = 0;
    for (size_t i = 0; i < n; i++)
        sum += (double)(i + 1) * (points[i].x + 2 * points[i].y + 3 * points[i].z);
    return sum;
}

/* Photons at the points; power and direction are any constant (bench/README.md). */
static struct photon *photons_at(const struct vec3 *points, size_t n)
{
    struct photon *photons = xmalloc(n, sizeof *photons, "bench photons");
    for (size_t i = 0; i < n; i++)
        photons[i] = photon_pack(points[i], vec3(1, 1, 1), vec3(0, 1, 0), PHOTON_DIRECT);
    return photons;
}

/* Median build seconds; *map receives the last map built. */
static double time_build(const struct photon *photons, size_t n, struct kdtree **map)
{
    double seconds[BENCH_REPEATS];
    *map = NULL;
    for (int r = 0; r < BENCH_REPEATS; r++) {
        struct photon *copy = xmalloc(n, sizeof *copy, "bench photons");
        memcpy(copy, photons, n * sizeof *copy);
        kdtree_free(*map);
        double start = bench_seconds();
        *map = balance_kdtree(copy, n);
        seconds[r] = bench_seconds() - start;
    }
    return bench_median(seconds, BENCH_REPEATS);
}

struct knn_figures {
    double qps;          /* median queries per second       */
    double sum_kth_d2;   /* sum of the k-th nearest d2       */
    double sum_nearest_d2; /* sum of the nearest d2          */
};

/* All queries for one k, BENCH_REPEATS times; sums from the last run (all runs agree). */
static struct knn_figures time_queries(const struct kdtree *map, const struct vec3 *queries,
                                       size_t k, struct nearest *nn)
{
    struct knn_figures f = {0, 0, 0};
    double qps[BENCH_REPEATS];
    for (int r = 0; r < BENCH_REPEATS; r++) {
        f.sum_kth_d2 = 0;
        f.sum_nearest_d2 = 0;
        double start = bench_seconds();
        for (size_t q = 0; q < N_QUERIES; q++) {
            locate_photons(map, queries[q], HUGE_VAL, k, nn);
            f.sum_kth_d2 += nn->r2;
            double nearest = nn->r2;
            for (size_t i = 0; i < nn->found; i++)
                nearest = nn->d2[i] < nearest ? nn->d2[i] : nearest;
            f.sum_nearest_d2 += nearest;
        }
        double seconds = bench_seconds() - start;
        qps[r] = seconds > 0 ? N_QUERIES / seconds : 0; /* 0: clock too coarse to say */
    }
    f.qps = bench_median(qps, BENCH_REPEATS);
    return f;
}

static void bench_one_size(const char *name, const struct vec3 *points, size_t n,
                           const struct vec3 *queries, struct nearest *nn)
{
    struct photon *photons = photons_at(points, n);
    printf("knn.%s.photons_checksum=%.17g\n", name, points_checksum(points, n));
    struct kdtree *map = NULL;
    printf("knn.%s.build_s=%.4f\n", name, time_build(photons, n, &map));
    xfree(photons);
    struct knn_figures k50 = time_queries(map, queries, 50, nn);
    printf("knn.%s.k50_qps=%.0f\n", name, k50.qps);
    struct knn_figures k500 = time_queries(map, queries, 500, nn);
    printf("knn.%s.k500_qps=%.0f\n", name, k500.qps);
    printf("knn.%s.k50_sum_kth_d2=%.10g\n", name, k50.sum_kth_d2);
    printf("knn.%s.k500_sum_kth_d2=%.10g\n", name, k500.sum_kth_d2);
    printf("knn.%s.sum_nearest_d2=%.10g\n", name, k50.sum_nearest_d2);
    fflush(stdout);
    kdtree_free(map);
}

void bench_knn(void)
{
    size_t n_max = 1000000;  /* bench/README.md: the 100k set is the prefix of the 1M set */
    struct vec3 *points = wall_points(PHOTON_SEED, n_max);
    struct vec3 *queries = wall_points(QUERY_SEED, N_QUERIES);
    struct nearest *nn = nearest_create(500);
    printf("knn.queries_checksum=%.17g\n", points_checksum(queries, N_QUERIES));
    printf("knn.bytes_per_photon=%zu\n", sizeof(struct photon));
    bench_one_size("100k", points, 100000, queries, nn);
    bench_one_size("1m", points, n_max, queries, nn);
    nearest_free(nn);
    xfree(queries);
    xfree(points);
}
