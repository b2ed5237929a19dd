/*
 * tests/test_hit_points.c -- the hit points' room: the tree of progressive photon
 * mapping's hit points (photon/hit_points.h) and the hash grid of stochastic progressive
 * photon mapping's (photon/hit_point_grid.h) against brute force.
 */
#include <stdlib.h>
#include <string.h>

#include "../src/base/rng.h"
#include "../src/photon/hit_point_grid.h"
#include "../src/photon/hit_points.h"
#include "check.h"
#include "tests.h"

struct visited {
    char *hit; /* one flag per hit point */
    int twice; /* whether any was visited more than once */
};

static void mark_visited(void *context, size_t i)
{
    struct visited *v = context;
    v->twice = v->twice || v->hit[i];
    v->hit[i] = 1;
}

/* A search over hit points: the tree's or the grid's visit, on index. */
typedef void (*search_fn)(const void *index, struct vec3 p,
                          void (*visit)(void *context, size_t i), void *context);

static void tree_search(const void *index, struct vec3 p, void (*visit)(void *, size_t),
                        void *context)
{
    hit_point_tree_visit(index, p, visit, context);
}

static void grid_search(const void *index, struct vec3 p, void (*visit)(void *, size_t),
                        void *context)
{
    hit_point_grid_visit(index, p, visit, context);
}

/* Whether search visits exactly the hit points a linear scan finds for 2000 queries,
 * each once. */
static int matches_scan(search_fn search, const void *index, const struct hit_point *points,
                        size_t n, struct rng *rng)
{
    struct visited v = {calloc(n > 0 ? n : 1, 1), 0};
    int same = 1;
    for (int q = 0; q < 2000; q++) {
        struct vec3 p = vec3(rng_uniform(rng), rng_uniform(rng), rng_uniform(rng) * 0.1);
        memset(v.hit, 0, n);
        search(index, p, mark_visited, &v);
        for (size_t i = 0; i < n; i++) {
            double d2 = vec3_length2(vec3_sub(p, points[i].x));
            same = same && v.hit[i] == (d2 <= points[i].global.radius * points[i].global.radius);
        }
    }
    free(v.hit);
    return same && !v.twice;
}

/* truth: brute force: a photon belongs to every hit point within that hit point's own
 *   radius. Sets: random points in a thin slab with radii from 0 to 0.1; many identical
 *   points; one point; none. Then the radii shrink at random (some to 0) and the tree is
 *   refitted.
 * catches: a subtree pruned by its split plane alone (radii reach across it), boxes not
 *   covering the discs, a hit point visited twice, duplicates lost by the median split,
 *   a refit that leaves a node's copy of R^2 as it was. */
static void test_hit_point_tree(struct check *t)
{
    struct rng rng = rng_stream(1, STREAM_TEST, 2008, 0);
    static const size_t sizes[] = {0, 1, 2, 7, 1000, 3000};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        size_t n = sizes[s];
        struct hit_point *points = calloc(n > 0 ? n : 1, sizeof *points);
        for (size_t i = 0; i < n; i++) {
            int duplicate = n == 3000 && i % 3 == 0; /* a third share one position */
            points[i].x = duplicate ? vec3(0.5, 0.5, 0.05)
                                    : vec3(rng_uniform(&rng), rng_uniform(&rng),
                                           rng_uniform(&rng) * 0.1);
            points[i].global.radius = 0.1 * rng_uniform(&rng);
        }
        struct hit_point_tree tree;
        hit_point_tree_build(&tree, points, n);
        CHECK(t, matches_scan(tree_search, &tree, points, n, &rng));
        for (size_t i = 0; i < n; i++)
            points[i].global.radius *= i % 5 == 0 ? 0.0 : rng_uniform(&rng);
        hit_point_tree_refit(&tree);
        CHECK(t, matches_scan(tree_search, &tree, points, n, &rng));
        hit_point_tree_free(&tree);
        free(points);
    }
}

/* truth: brute force, as for the tree: random points in a thin slab with radii from 0 to
 *   0.1 (one at exactly the largest, so cells as wide as it), many identical points, one
 *   point, none, and all radii 0.
 * catches: a disc listed in too few cells (a box 2 reach wide can touch 3 cells a side),
 *   a hit point listed twice in one bucket (two of its cells hashed alike) and visited
 *   twice, a photon off the grid's corner (negative cells) lost. */
static void test_hit_point_grid(struct check *t)
{
    struct rng rng = rng_stream(1, STREAM_TEST, 2009, 0);
    static const size_t sizes[] = {0, 1, 2, 7, 1000, 3000};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        size_t n = sizes[s];
        struct hit_point *points = calloc(n > 0 ? n : 1, sizeof *points);
        for (size_t i = 0; i < n; i++) {
            int duplicate = n == 3000 && i % 3 == 0;
            points[i].x = duplicate ? vec3(0.5, 0.5, 0.05)
                                    : vec3(rng_uniform(&rng), rng_uniform(&rng),
                                           rng_uniform(&rng) * 0.1);
            points[i].global.radius = i == 0 ? 0.1 : 0.1 * rng_uniform(&rng);
        }
        struct hit_point_grid grid;
        hit_point_grid_build(&grid, points, n);
        CHECK(t, matches_scan(grid_search, &grid, points, n, &rng));
        hit_point_grid_free(&grid);
        for (size_t i = 0; i < n; i++)
            points[i].global.radius = 0;
        hit_point_grid_build(&grid, points, n);
        CHECK(t, matches_scan(grid_search, &grid, points, n, &rng));
        hit_point_grid_free(&grid);
        free(points);
    }
}

void test_hit_points(struct check *t)
{
    RUN_TEST(t, test_hit_point_tree);
    RUN_TEST(t, test_hit_point_grid);
}
