/*
 * tests/test_shapes.c -- the sphere flake (geom/sphereflake.c), the first procedural
 * shape: against Haines' balls-s3.nff, figures of balls-s4.nff, and its own spheres. The
 * fractal heightfield is test_shapes_heightfield.c's.
 *
 * The truths are the expansions: the same spheres as plain primitives, tested one by one
 * (brute force) or through geometry's BVH. Both sides run the shared sphere.c tests on the
 * same doubles, so the procedural walk is what is under test: a pruned subtree, a wrong
 * bound or child placement. Visiting order (near first) only saves work and cannot be seen
 * in results; bench_shapes.c shows it.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/base/rng.h"
#include "../src/geom/sphere.h"
#include "../src/geom/sphereflake.h"
#include "geom_helpers.h"
#include "shape_hits.h"
#include "spd.h"
#include "tests.h"

/* ---- helpers: sphere lists ----------------------------------------------------------- */

struct sphere_list {
    struct sphere *spheres; /* owned */
    int *depth;             /* owned; depth of sphere k, from its material (see flake_make) */
    size_t n, cap;
};

static void collect_sphere(void *context, struct vec3 centre, double radius, int material)
{
    struct sphere_list *list = context;
    if (list->n == list->cap) {
        list->cap = list->cap == 0 ? 64 : 2 * list->cap;
        list->spheres = xrealloc(list->spheres, list->cap, sizeof *list->spheres, "spheres");
        list->depth = xrealloc(list->depth, list->cap, sizeof *list->depth, "depths");
    }
    list->spheres[list->n] = sphere_make(centre, radius, material, (int)list->n);
    list->depth[list->n++] = material - 100;
}

static struct sphere_list flake_spheres(const struct sphereflake *flake)
{
    struct sphere_list list = {NULL, NULL, 0, 0};
    sphereflake_spheres(flake, collect_sphere, &list);
    return list;
}

static void sphere_list_free(struct sphere_list *list)
{
    xfree(list->spheres);
    xfree(list->depth);
}

/* Materials 100 + depth, so a hit's material names the depth of the sphere hit. */
static struct sphereflake *flake_make(struct vec3 centre, double radius, int levels,
                                      struct vec3 orientation)
{
    struct sphereflake_params p;
    p.centre = centre;
    p.radius = radius;
    p.levels = levels;
    p.orientation = orientation;
    for (int k = 0; k <= SPHEREFLAKE_MAX_LEVELS; k++)
        p.materials[k] = 100 + k;
    struct error err;
    return sphereflake_create(&p, &err);
}

/* ---- the sphere flake against Haines' balls.c ---------------------------------------- */

/* truth: Haines' own output, balls-s3.nff (SPD 3.14 balls.c at size factor 3, kept in
 *   tests/data/spd/): 820 spheres, centres and radii printed with %g.
 * tolerance: the printing's, 5e-6 relative per number (spd.c). Matched as a set: each
 *   printed sphere to one of ours within tolerance (spheres are >= 0.012 apart, far more
 *   than it, so at most one can match), each of ours matched exactly once.
 * catches: a wrong child direction, frame, scale or radius ratio; the +-z special cases of
 *   balls.c's frame (axes exactly -z occur from depth 2, so their children, at depth 3, are
 *   the first spheres they place: balls-s2 could not see them); a missing or extra level. */
static void test_sphereflake_is_balls_s3(struct check *t)
{
    size_t n_printed, n_ours;
    double *printed = nff_spheres(SPD_DATA "/balls-s3.nff", &n_printed);
    REQUIRE(t, printed != NULL);
    double *ours = balls_spheres(3, &n_ours);
    CHECK(t, n_printed == 820);
    check_same_spheres(t, ours, n_ours, printed, n_printed);
    xfree(ours);
    xfree(printed);
}

/* truth: balls-s4.nff (balls.c at size factor 4, the SPD benchmark size; not in the
 *   repository), kept as figures in spd.h: its 7381 spheres and the digest of their
 *   printed text. Our spheres printed the same way give the same digest only if every
 *   one prints as one of the file's (test_spd.c compares them one by one, and checks the
 *   figures against the file).
 * tolerance: none: the digest compares printed text. Our doubles differ from balls.c's by
 *   rounding only (~1e-16 relative), so they print as the file does unless one lies that
 *   close to a rounding boundary of the 6th digit (odds ~1e-10 a number; none of the
 *   29,524 does); the noise balls.c prints for zero is written as 0 on both sides.
 * catches: what the balls-s3 test catches, in the deepest level's 6561 spheres. */
static void test_sphereflake_prints_as_balls_s4(struct check *t)
{
    size_t n;
    double *ours = balls_spheres(4, &n);
    CHECK(t, n == BALLS_S4_SPHERES);
    CHECK(t, spheres_digest(ours, n) == BALLS_S4_SPHERE_DIGEST);
    xfree(ours);
}

/* ---- the sphere flake's structure ---------------------------------------------------- */

/* Pre-order: the parent of a depth-k sphere is the last depth-(k-1) sphere before it. */
static int children_touch_parents(const struct sphere_list *list)
{
    int last[SPHEREFLAKE_MAX_LEVELS + 1];
    for (size_t k = 0; k < list->n; k++) {
        int d = list->depth[k];
        last[d] = (int)k;
        if (d == 0)
            continue;
        const struct sphere *child = &list->spheres[k], *parent = &list->spheres[last[d - 1]];
        double distance = vec3_length(vec3_sub(child->centre, parent->centre));
        if (!(fabs(distance - 4.0 / 3.0 * parent->radius) <= 1e-12 * parent->radius &&
              fabs(child->radius - parent->radius / 3.0) <= 1e-15 * parent->radius))
            return 0;
    }
    return 1;
}

static int spheres_inside(const struct sphere_list *list, struct aabb box)
{
    for (size_t k = 0; k < list->n; k++) {
        struct aabb b = sphere_bounds(&list->spheres[k]);
        if (b.lo.x < box.lo.x || b.lo.y < box.lo.y || b.lo.z < box.lo.z ||
            b.hi.x > box.hi.x || b.hi.y > box.hi.y || b.hi.z > box.hi.z)
            return 0;
    }
    return 1;
}

/* truth: the definition (sphereflake.h): (9^(k+1) - 1)/8 spheres at level k, 9^d of them
 *   at depth d; each child of radius r/3 at distance r + r/3 from its parent (tangent);
 *   the three upper children of the top sphere at polar angle acos(sqrt(2/3)) from the
 *   orientation, the six others on its equator; everything inside bounds().
 * tolerance: 1e-12 relative for distances (a few roundings per level), exact counts.
 * catches: a wrong count or depth, children not touching, orientation ignored or inverted,
 *   bounds that clip the deepest spheres, bytes() growing with the level. */
static void test_sphereflake_structure(struct check *t)
{
    const struct vec3 axes[] = {{0, 0, 1}, {0, 1, 0}, {0, 0, -3}, {1, -2, 0.5}};
    for (int level = 0; level <= 4; level++) {
        struct vec3 axis = axes[level % 4], unit = vec3_normalize(axis);
        struct sphereflake *flake = flake_make(vec3(1, -2, 3), 0.7, level, axis);
        struct sphere_list list = flake_spheres(flake);
        CHECK(t, (double)list.n == sphereflake_sphere_count(level));
        CHECK(t, (double)list.n == (pow(9, level + 1) - 1) / 8);
        size_t per_depth[5] = {0, 0, 0, 0, 0};
        for (size_t k = 0; k < list.n; k++)
            per_depth[list.depth[k]]++;
        for (int d = 0; d <= level; d++)
            CHECK(t, (double)per_depth[d] == pow(9, d));
        CHECK(t, children_touch_parents(&list));
        CHECK(t, spheres_inside(&list, sphereflake_ops.bounds(flake)));
        CHECK(t, sphereflake_ops.bytes(flake) < 1024);
        int n_upper = 0, n_equator = 0;
        for (size_t k = 1; level > 0 && k < list.n; k++) {
            if (list.depth[k] != 1)
                continue;
            double c = vec3_dot(vec3_sub(list.spheres[k].centre, vec3(1, -2, 3)), unit) /
                       (4.0 / 3.0 * 0.7);
            n_upper += fabs(c - sqrt(2.0 / 3.0)) < 1e-12;
            n_equator += fabs(c) < 1e-12;
        }
        CHECK(t, level == 0 || (n_upper == 3 && n_equator == 6));
        sphere_list_free(&list);
        sphereflake_free(flake);
    }
}

/* truth: the contract of sphereflake_create(): out-of-range parameters give NULL and a
 *   message, never a crash; the boundaries 0 and SPHEREFLAKE_MAX_LEVELS are accepted.
 * catches: an off-by-one limit, NaN slipping through a "< 0" test, a zero orientation
 *   normalised to NaN. */
static void test_sphereflake_refuses_bad_parameters(struct check *t)
{
    struct sphereflake_params p;
    memset(&p, 0, sizeof p);
    p.radius = 1;
    p.orientation = vec3(0, 1, 0);
    struct error err;
    struct sphereflake_params bad[7];
    for (int k = 0; k < 7; k++)
        bad[k] = p;
    bad[0].radius = 0;
    bad[1].radius = NAN;
    bad[2].levels = -1;
    bad[3].levels = SPHEREFLAKE_MAX_LEVELS + 1;
    bad[4].orientation = vec3(0, 0, 0);
    bad[5].orientation = vec3(NAN, 1, 0);
    bad[6].centre = vec3(INFINITY, 0, 0);
    for (int k = 0; k < 7; k++) {
        err.message[0] = '\0';
        CHECK(t, sphereflake_create(&bad[k], &err) == NULL);
        CHECK(t, strncmp(err.message, "sphereflake:", 12) == 0);
    }
    p.levels = SPHEREFLAKE_MAX_LEVELS;
    struct sphereflake *deepest = sphereflake_create(&p, &err);
    REQUIRE(t, deepest != NULL);
    CHECK(t, sphereflake_expand(deepest, NULL) == -1); /* 3.9e9 > MAX_PRIMITIVES */
    sphereflake_free(deepest);
    sphereflake_free(NULL);
}

/* ---- rays ----------------------------------------------------------------------------- */

/* Ray q of a mix for a shape within the ball (centre, bound), with spheres to graze:
 * 1/2 from outside towards a random point of the ball; 1/4 from a random point in the
 * ball's cube in a random direction (often inside spheres, or between them); 1/4 from
 * outside tangent to a random sphere, its silhouette missed or hit by up to 1e-6 of its
 * radius. Directions are not unit: length in [0.5, 2), so t's unit is tested too. */
static struct ray flake_test_ray(const struct sphere_list *list, struct vec3 centre,
                                 double bound, uint64_t q)
{
    struct rng r = rng_stream(1, STREAM_TEST, q, 0);
    double kind = rng_uniform(&r);
    struct vec3 o = vec3_madd(centre, random_unit(&r), 2 * bound);
    struct vec3 target = vec3_madd(centre, random_unit(&r), bound * rng_uniform(&r));
    if (kind >= 0.5 && kind < 0.75) {
        o = vec3_add(centre, vec3_scale(vec3(2 * rng_uniform(&r) - 1, 2 * rng_uniform(&r) - 1,
                                             2 * rng_uniform(&r) - 1), bound));
        target = vec3_add(o, random_unit(&r));
    } else if (kind >= 0.75) {
        const struct sphere *s = &list->spheres[(size_t)(rng_uniform(&r) * list->n)];
        struct vec3 w = vec3_normalize(vec3_sub(s->centre, o)), u, v;
        vec3_frame(w, &u, &v);
        double graze = 1.0 + (2 * rng_uniform(&r) - 1) * 1e-6;
        target = vec3_madd(s->centre, u, s->radius * graze);
    }
    struct vec3 d = vec3_normalize(vec3_sub(target, o));
    return make_ray(o, vec3_scale(d, 0.5 + 1.5 * rng_uniform(&r)));
}

/* Closest hit over every sphere of the list, shaded as geometry shades a sphere. */
static int brute_force_spheres(const struct sphere_list *list, struct ray ray, struct hit *hit)
{
    double tmax = INFINITY;
    size_t best = 0;
    for (size_t k = 0; k < list->n; k++) {
        if (sphere_intersect(&list->spheres[k], ray, tmax, hit)) {
            tmax = hit->t;
            best = k;
        }
    }
    if (tmax == INFINITY)
        return 0;
    hit->t = tmax;
    sphere_shade(&list->spheres[best], ray, hit);
    return 1;
}

/* How many of n_rays rays find the same closest hit procedurally as by brute force, and
 * whether occluded() agrees with the hit on both sides of its distance. */
static size_t flake_agreements(const struct sphereflake *flake, const struct sphere_list *list,
                               size_t n_rays, uint64_t first)
{
    struct sphere top = list->spheres[0];
    double bound = 2 * top.radius;
    size_t n_same = 0;
    for (uint64_t q = first; q < first + n_rays; q++) {
        struct ray ray = flake_test_ray(list, top.centre, bound, q);
        struct hit a, b;
        int found_a = sphereflake_ops.intersect(flake, ray, INFINITY, &a);
        int found_b = brute_force_spheres(list, ray, &b);
        int same = found_a == found_b && (!found_a || same_hit(&a, &b, ray, 1e-12, 1));
        if (found_a)
            same &= sphereflake_ops.occluded(flake, ray, a.t * (1 + 1e-9)) &&
                    !sphereflake_ops.occluded(flake, ray, a.t * (1 - 1e-9));
        else
            same &= !sphereflake_ops.occluded(flake, ray, INFINITY);
        n_same += same;
    }
    return n_same;
}

/* truth: brute force, every sphere of the expansion tested with sphere.c; the same doubles
 *   on both sides, so the procedural walk must find exactly the same closest sphere.
 * tolerance: 1e-12 relative on t and p (a tie between touching spheres could differ by
 *   rounding; none occurs in these rays), 1e-12 on normals; exact material (= depth).
 * placements: balls.c's; far from the origin and small (bounds padded for rounding of far
 *   coordinates); axes +y, -z (balls.c's half-turn frame) and oblique; levels 0..3.
 * catches: a bounding ball too small (grazing rays on the deepest spheres miss), a child
 *   pruned by a stale or wrong entry distance, leaf children skipped, origins inside
 *   spheres, t in units of a non-unit direction, occluded() ignoring tmax, a stack
 *   overflow at the deepest level (level 10 axis ray below). */
static void test_sphereflake_matches_brute_force(struct check *t)
{
    const struct vec3 centres[] = {{0, 0, 0}, {1e3, -2e3, 5e2}, {0.3, 0.1, -0.2},
                                   {-1, 2, 3}};
    const double radii[] = {0.5, 1e-2, 2.0, 0.25};
    const struct vec3 axes[] = {{0, 0, 1}, {0, 1, 0}, {0, 0, -1}, {0.3, -1, 0.7}};
    for (int level = 0; level <= 3; level++) {
        for (int p = 0; p < 4; p++) {
            struct sphereflake *flake = flake_make(centres[p], radii[p], level, axes[p]);
            struct sphere_list list = flake_spheres(flake);
            size_t n_rays = level == 3 ? 3000 : 2000;
            CHECK(t, flake_agreements(flake, &list, n_rays, 1000 * (uint64_t)(4 * level + p))
                         == n_rays);
            sphere_list_free(&list);
            sphereflake_free(flake);
        }
    }
    struct sphereflake *deepest = flake_make(vec3(0, 0, 0), 1, SPHEREFLAKE_MAX_LEVELS,
                                             vec3(0, 1, 0));
    REQUIRE(t, deepest != NULL);
    struct hit h;
    CHECK(t, sphereflake_ops.intersect(deepest, make_ray(vec3(0, 5, 0), vec3(0, -1, 0)),
                                       INFINITY, &h));
    CHECK(t, h.t == 4 && h.material == 100);  /* no child lies on the axis */
    sphereflake_free(deepest);
}

static struct ray flake_ray_of(const void *context, uint64_t q)
{
    const struct sphere_list *list = context;
    return flake_test_ray(list, list->spheres[0].centre, 2 * list->spheres[0].radius,
                          q + 100000);
}

/* truth: the expansion, sphereflake_expand() into a geometry (BVH over 820 and 7381 plain
 *   spheres), against the shape alone in another geometry: geometry_intersect() both ways.
 * tolerance: 1e-12 relative on t and p, as in the brute-force test; normals through ns
 *   (ng = ns on spheres) to 1e-9; same material.
 * catches: what a million rays find and thousands do not; the shape's plumbing (bounds
 *   given to the BVH, the hit record through geometry, prim = the shape's id). */
static void test_sphereflake_matches_expansion(struct check *t)
{
    for (int level = 3; level <= 4; level++) {
        struct sphereflake *flake = flake_make(vec3(0, 0, 0), 0.5, level, vec3(0, 0, 1));
        struct sphereflake *copy = flake_make(vec3(0, 0, 0), 0.5, level, vec3(0, 0, 1));
        struct geometry *procedural = geometry_create(), *expanded = geometry_create();
        CHECK(t, geometry_add_shape(procedural, &sphereflake_ops, flake, 7) == 0);
        CHECK(t, sphereflake_expand(copy, expanded) == 0);
        CHECK(t, (double)geometry_primitive_count(expanded) == sphereflake_sphere_count(level));
        geometry_build(procedural);
        geometry_build(expanded);
        struct sphere_list list = flake_spheres(copy);
        CHECK(t, geometry_agreements(procedural, expanded, flake_ray_of, &list,
                                     EXPANSION_RAYS, 1e-12) == EXPANSION_RAYS);
        struct hit h;
        CHECK(t, geometry_intersect(procedural, make_ray(vec3(0, 0, 3), vec3(0, 0, -1)),
                                    INFINITY, &h) && h.prim == 0 && h.t == 2.5);
        sphere_list_free(&list);
        sphereflake_free(copy);
        geometry_free(expanded);
        geometry_free(procedural); /* frees flake */
    }
}

void test_shapes(struct check *t)
{
    RUN_TEST(t, test_sphereflake_is_balls_s3);
    RUN_TEST(t, test_sphereflake_prints_as_balls_s4);
    RUN_TEST(t, test_sphereflake_structure);
    RUN_TEST(t, test_sphereflake_refuses_bad_parameters);
    RUN_TEST(t, test_sphereflake_matches_brute_force);
    RUN_TEST(t, test_sphereflake_matches_expansion);
}
