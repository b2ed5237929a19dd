/*
 * tests/test_shapes.c -- the procedural shapes: the sphere flake (against Haines' balls-s3.nff,
 * figures of balls-s4.nff, and its own spheres) and the fractal heightfield (against its
 * own triangles).
 *
 * The truths are the expansions: the same spheres or triangles as plain primitives, tested
 * one by one (brute force) or through geometry's BVH. Both sides run the shared sphere.c and
 * triangle.c tests on the same doubles, so the procedural walk is what is under test: a
 * pruned subtree, a wrong bound or child placement, a cell skipped. Visiting order (near
 * first) only saves work and cannot be seen in results; bench_shapes.c shows it.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/base/rng.h"
#include "../src/geom/heightfield.h"
#include "../src/geom/noise.h"
#include "../src/geom/sphere.h"
#include "../src/geom/sphereflake.h"
#include "../src/geom/triangle.h"
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

static struct vec3 random_unit(struct rng *r)
{
    double z = 2 * rng_uniform(r) - 1, phi = 2 * PI * rng_uniform(r);
    double s = sqrt(fmax(0.0, 1 - z * z));
    return vec3(s * cos(phi), s * sin(phi), z);
}

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

/* Two shading records of one surface point: t to rel_t, p to rel_t of the ray's scale,
 * normals to 1e-12, same material. (Distinct primitives at equal t, e.g. a ray through a
 * shared edge, may give different ng: compare_ng 0 skips it there.) */
static int same_hit(const struct hit *a, const struct hit *b, struct ray ray, double rel_t,
                    int compare_ng)
{
    double scale = fmax(1.0, fmax(vec3_max_abs(ray.origin), b->t * vec3_length(ray.dir)));
    return fabs(a->t - b->t) <= rel_t * b->t &&
           vec3_max_abs(vec3_sub(a->p, b->p)) <= rel_t * scale &&
           (!compare_ng || vec3_dot(a->ng, b->ng) >= 1 - 1e-12) &&
           vec3_dot(a->ns, b->ns) >= 1 - 1e-9 && a->material == b->material;
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

/* Rays make(context, q), q < n_rays, through both geometries: how many find the same hit. */
static size_t geometry_agreements(const struct geometry *procedural,
                                  const struct geometry *expanded,
                                  struct ray (*make)(const void *context, uint64_t q),
                                  const void *context, size_t n_rays, double rel_t)
{
    size_t n_same = 0;
    for (uint64_t q = 0; q < n_rays; q++) {
        struct ray ray = make(context, q);
        struct hit a, b;
        int found_a = geometry_intersect(procedural, ray, INFINITY, &a);
        int found_b = geometry_intersect(expanded, ray, INFINITY, &b);
        n_same += found_a == found_b && (!found_a || same_hit(&a, &b, ray, rel_t, 0));
    }
    return n_same;
}

static struct ray flake_ray_of(const void *context, uint64_t q)
{
    const struct sphere_list *list = context;
    return flake_test_ray(list, list->spheres[0].centre, 2 * list->spheres[0].radius,
                          q + 100000);
}

#define EXPANSION_RAYS 500000 /* per level: a million in all */

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

/* ---- noise ---------------------------------------------------------------------------- */

/* truth: the definition of gradient noise (noise.h): zero at lattice points, continuous
 *   across lattice lines, within [-1, 1]; a key (seed) fixes every value, bit for bit, on
 *   any IEEE machine, so fbm2 at three points must give the values recorded here (printed
 *   %.17g when the function was written; a change of algorithm must update them knowingly).
 * tolerance: exact for the recorded values and zeros; continuity: |jump| <= 1e-7 across
 *   +-1e-9 of a lattice line (slopes are below 10).
 * catches: a platform-dependent hash (rand(), unsigned long width), a fade or corner offset
 *   error (discontinuous at cell borders), an amplitude normalisation error, octaves
 *   sharing one key. */
static void test_noise(struct check *t)
{
    struct fbm f = fbm_make(42, 8, 0.5);
    CHECK(t, fbm2(&f, 0.3, 0.7) == -0.17881138156619059);
    CHECK(t, fbm2(&f, 1.9, -2.25) == -0.063680480053227448);
    CHECK(t, fbm2(&f, 123.456, 78.9) == 0.14392770689271486);
    double max_abs = 0;
    int continuous = 1, zero_at_lattice = 1;
    for (uint64_t q = 0; q < 20000; q++) {
        struct rng r = rng_stream(2, STREAM_TEST, q, 0);
        double x = 200 * rng_uniform(&r) - 100, y = 200 * rng_uniform(&r) - 100;
        uint64_t key = rng_next(&r);
        max_abs = fmax(max_abs, fmax(fabs(noise2(x, y, key)), fabs(fbm2(&f, x, y))));
        zero_at_lattice &= noise2(floor(x), floor(y), key) == 0;
        double line = floor(x);
        continuous &= fabs(noise2(line - 1e-9, y, key) - noise2(line + 1e-9, y, key)) <= 1e-7;
        continuous &= fabs(noise2(x, line - 1e-9, key) - noise2(x, line + 1e-9, key)) <= 1e-7;
    }
    CHECK(t, max_abs <= 1 && max_abs > 0.5);
    CHECK(t, zero_at_lattice && continuous);
    struct fbm other = fbm_make(43, 8, 0.5);
    CHECK(t, fbm2(&other, 0.3, 0.7) != fbm2(&f, 0.3, 0.7));
    CHECK(t, f.key[0] != f.key[1]);
}

/* ---- heightfield helpers -------------------------------------------------------------- */

struct triangle_list {
    struct vec3 *v;       /* owned; 3 per triangle */
    struct vec3 *normals; /* owned; 3 per triangle */
    int material;
    size_t n, cap;
};

static void collect_triangle(void *context, const struct vec3 v[3],
                             const struct vec3 normals[3], int material)
{
    struct triangle_list *list = context;
    if (list->n == list->cap) {
        list->cap = list->cap == 0 ? 64 : 2 * list->cap;
        list->v = xrealloc(list->v, 3 * list->cap, sizeof *list->v, "vertices");
        list->normals = xrealloc(list->normals, 3 * list->cap, sizeof *list->normals, "normals");
    }
    for (int k = 0; k < 3; k++) {
        list->v[3 * list->n + k] = v[k];
        list->normals[3 * list->n + k] = normals[k];
    }
    list->material = material;
    list->n++;
}

static struct triangle_list heightfield_list(const struct heightfield *hf)
{
    struct triangle_list list = {NULL, NULL, 0, 0, 0};
    heightfield_triangles(hf, collect_triangle, &list);
    return list;
}

static void triangle_list_free(struct triangle_list *list)
{
    xfree(list->v);
    xfree(list->normals);
}

static struct heightfield_params landscape(int n, double height, uint64_t seed)
{
    struct heightfield_params p;
    p.origin = vec3(-3, 0.5, 2);
    p.size = 6;
    p.resolution = n;
    p.octaves = 6;
    p.roughness = 0.55;
    p.frequency = 3;
    p.height = height;
    p.seed = seed;
    p.material = 5;
    return p;
}

/* Closest hit over every triangle of the list, shaded as geometry shades a triangle. */
static int brute_force_triangles(const struct triangle_list *list, struct ray ray,
                                 struct hit *hit)
{
    struct sheared_ray sheared = shear_ray(ray);
    double tmax = INFINITY;
    size_t best = 0;
    struct hit h, best_hit;
    for (size_t k = 0; k < list->n; k++) {
        struct triangle tri = triangle_make(list->v + 3 * k, -1, list->material, 0);
        if (triangle_intersect(&tri, &sheared, tmax, &h)) {
            tmax = h.t;
            best = k;
            best_hit = h;
        }
    }
    if (tmax == INFINITY)
        return 0;
    *hit = best_hit;
    struct triangle tri = triangle_make(list->v + 3 * best, -1, list->material, 0);
    triangle_shade(&tri, list->normals + 3 * best, hit);
    return 1;
}

/* Ray q for a heightfield made from p, its triangles in list: 1/3 from above the square
 * down to a random surface point; 1/3 from random points of a box around it in random
 * directions; 1/3 grazing: from a surface point lifted by 1e-9..1e-3 of the height range,
 * backed off along a nearly horizontal direction (vertical part +-1e-6..1e-2) by up to the
 * square's size. Direction lengths in [0.5, 2). */
static struct ray terrain_test_ray(const struct heightfield_params *p,
                                   const struct triangle_list *list, uint64_t q)
{
    struct rng r = rng_stream(3, STREAM_TEST, q, 0);
    double kind = 3 * rng_uniform(&r), a = rng_uniform(&r), b = rng_uniform(&r);
    const struct vec3 *v = list->v + 3 * (size_t)(rng_uniform(&r) * list->n);
    if (a + b > 1) {
        a = 1 - a;
        b = 1 - b;
    }
    struct vec3 surface = vec3_madd(vec3_madd(vec3_scale(v[0], 1 - a - b), v[1], a), v[2], b);
    struct vec3 o, d;
    if (kind < 1) {
        o = vec3_add(p->origin, vec3(p->size * (1.4 * rng_uniform(&r) - 0.2), 3 * p->height + 1,
                                     p->size * (1.4 * rng_uniform(&r) - 0.2)));
        d = vec3_normalize(vec3_sub(surface, o));
    } else if (kind < 2) {
        o = vec3_add(p->origin, vec3(p->size * (1.4 * rng_uniform(&r) - 0.2),
                                     p->height * (4 * rng_uniform(&r) - 2),
                                     p->size * (1.4 * rng_uniform(&r) - 0.2)));
        d = random_unit(&r);
    } else {
        double phi = 2 * PI * rng_uniform(&r), lift = pow(10, -9 + 6 * rng_uniform(&r));
        double dy = pow(10, -6 + 4 * rng_uniform(&r)) * (rng_uniform(&r) < 0.5 ? -1 : 1);
        d = vec3_normalize(vec3(cos(phi), dy, sin(phi)));
        o = vec3_madd(surface, vec3(0, 1, 0), lift * (2 * p->height + 1e-3));
        o = vec3_madd(o, d, -p->size * rng_uniform(&r));
    }
    return make_ray(o, vec3_scale(d, 0.5 + 1.5 * rng_uniform(&r)));
}

/* Whether list holds cell (0, 0)'s two triangles first, at heightfield.h's coordinates,
 * every triangle facing up, every vertex inside box, heights within origin.y +- height. */
static int triangles_as_documented(const struct triangle_list *list,
                                   const struct heightfield_params *p, struct aabb box)
{
    double spacing = p->size / (p->resolution - 1);
    const struct vec3 *v = list->v;
    int ok = v[0].x == p->origin.x && v[0].z == p->origin.z && v[1].x == p->origin.x &&
             v[1].z == p->origin.z + spacing && v[2].x == p->origin.x + spacing &&
             v[2].z == v[1].z && v[4].x == v[2].x && v[4].z == v[2].z && v[5].z == v[0].z;
    for (size_t k = 0; k < list->n; k++) {
        const struct vec3 *w = list->v + 3 * k;
        ok &= vec3_cross(vec3_sub(w[1], w[0]), vec3_sub(w[2], w[0])).y > 0;
        for (int i = 0; i < 3; i++) {
            ok &= w[i].x >= box.lo.x && w[i].y >= box.lo.y && w[i].z >= box.lo.z;
            ok &= w[i].x <= box.hi.x && w[i].y <= box.hi.y && w[i].z <= box.hi.z;
            ok &= fabs(w[i].y - p->origin.y) <= p->height;
            ok &= list->normals[3 * k + i].y > 0;
        }
    }
    return ok;
}

/* truth: heightfield.h's layout (vertex positions, diagonal, winding), the definition of
 *   the pyramid (heightfield_check(): every stored min/max equals a scan of its samples)
 *   and the stated memory: samples plus a third of the cells' worth of (min, max) pairs.
 * tolerance: exact; the coordinates are the documented expressions.
 * catches: an odd-sized level losing its last row, a cell's range from three corners,
 *   triangles wound downwards, the diagonal flipped, bounds() missing the top sample. */
static void test_heightfield_structure(struct check *t)
{
    const int sizes[] = {2, 3, 4, 5, 6, 17, 100};
    for (int s = 0; s < 7; s++) {
        int n = sizes[s];
        struct heightfield_params p = landscape(n, 0.8, (uint64_t)s);
        struct error err;
        struct heightfield *hf = heightfield_create(&p, &err);
        REQUIRE(t, hf != NULL);
        CHECK(t, heightfield_check(hf));
        struct triangle_list list = heightfield_list(hf);
        CHECK(t, list.n == 2 * (size_t)(n - 1) * (size_t)(n - 1) && list.material == 5);
        struct aabb box = heightfield_ops.bounds(hf);
        CHECK(t, triangles_as_documented(&list, &p, box));
        size_t n_samples = (size_t)n * (size_t)n, cells = (size_t)(n - 1) * (size_t)(n - 1);
        size_t bytes = heightfield_ops.bytes(hf);
        CHECK(t, bytes >= n_samples * 8 && bytes <= n_samples * 8 + (cells / 3 + n) * 16 + 512);
        triangle_list_free(&list);
        heightfield_free(hf);
    }
}

/* truth: central differences of a smooth surface approximate its normal: on a gentle
 *   one-octave landscape each vertex normal is within a few degrees of the faces around it,
 *   and a hit's ns (their blend) is close to its ng.
 * tolerance: cos > 0.995 (about 6 degrees): the difference is first order in the spacing
 *   times the curvature, here under 2 degrees.
 * catches: a derivative with the wrong sign or axis, a missing 1/(2 spacing), normals not
 *   unit, a border sample's one-sided difference taken from the wrong side. */
static void test_heightfield_shading_normals(struct check *t)
{
    struct heightfield_params p = landscape(65, 1.0, 3);
    p.octaves = 1;
    p.frequency = 1.5;
    struct error err;
    struct heightfield *hf = heightfield_create(&p, &err);
    struct triangle_list list = heightfield_list(hf);
    int n_wrong = 0;
    for (size_t k = 0; k < list.n; k++) {
        const struct vec3 *v = list.v + 3 * k;
        struct vec3 ng = vec3_normalize(vec3_cross(vec3_sub(v[1], v[0]), vec3_sub(v[2], v[0])));
        for (int i = 0; i < 3; i++) {
            struct vec3 n = list.normals[3 * k + i];
            n_wrong += !(vec3_dot(n, ng) > 0.995 && fabs(vec3_length(n) - 1) < 1e-12);
        }
    }
    CHECK(t, n_wrong == 0);
    for (uint64_t q = 0; q < 1000; q++) {
        struct hit h;
        struct ray ray = terrain_test_ray(&p, &list, q);
        if (heightfield_ops.intersect(hf, ray, INFINITY, &h))
            n_wrong += !(vec3_dot(h.ns, h.ng) > 0.995 && h.ng.y > 0);
    }
    CHECK(t, n_wrong == 0);
    triangle_list_free(&list);
    heightfield_free(hf);
}

/* truth: heightfield_create()'s contract: bad parameters give NULL and a message; the
 *   limits themselves are accepted.
 * catches: off-by-one limits, NaN passing a range test, a spacing that rounding collapses. */
static void test_heightfield_refuses_bad_parameters(struct check *t)
{
    struct heightfield_params bad[12];
    for (int k = 0; k < 12; k++)
        bad[k] = landscape(3, 1, 0);
    bad[0].size = 0;
    bad[1].size = NAN;
    bad[2].resolution = 1;
    bad[3].resolution = HEIGHTFIELD_MAX_RESOLUTION + 1;
    bad[4].octaves = 0;
    bad[5].octaves = HEIGHTFIELD_MAX_OCTAVES + 1;
    bad[6].roughness = 0;
    bad[7].roughness = 1.5;
    bad[8].frequency = -1;
    bad[9].height = -1;
    bad[10].origin = vec3(1e20, 0, 0); /* cells of 3 at 1e20 */
    bad[11].height = INFINITY;
    struct error err;
    for (int k = 0; k < 12; k++) {
        err.message[0] = '\0';
        CHECK(t, heightfield_create(&bad[k], &err) == NULL);
        CHECK(t, strncmp(err.message, "heightfield:", 12) == 0);
    }
    struct heightfield_params edge = landscape(2, 0, 0);
    edge.octaves = HEIGHTFIELD_MAX_OCTAVES;
    edge.roughness = 1;
    edge.frequency = HEIGHTFIELD_MAX_FREQUENCY;
    struct heightfield *hf = heightfield_create(&edge, &err);
    CHECK(t, hf != NULL && heightfield_check(hf));
    heightfield_free(hf);
    heightfield_free(NULL);
}

/* truth: closed form: with height 0 the surface is the plane y = origin.y over the square,
 *   so a ray with d.y != 0 hits at t = (origin.y - o.y) / d.y when that point is inside the
 *   square, with ng = ns = +y and u, v the point's place on the square.
 * tolerance: 1e-12 relative on t (a few roundings; grazing rays down to d.y = 1e-6 |d| make
 *   t up to 1e6 long but its relative error stays a few ulps); points within 1e-9 of the
 *   square's border are skipped (rounding there may go either way).
 * catches: a zero-thickness y slab culled, a direction component 0 turned into NaN, hits
 *   outside the square, t in the wrong unit. */
static void test_heightfield_flat_closed_form(struct check *t)
{
    struct heightfield_params p = landscape(9, 0, 0);
    struct error err;
    struct heightfield *hf = heightfield_create(&p, &err);
    int n_wrong = 0;
    for (uint64_t q = 0; q < 20000; q++) {
        struct rng r = rng_stream(4, STREAM_TEST, q, 0);
        struct vec3 o = vec3_add(p.origin, vec3(8 * rng_uniform(&r) - 1, 2 * rng_uniform(&r) - 1,
                                                8 * rng_uniform(&r) - 1));
        struct vec3 d = random_unit(&r);
        if (q % 4 == 0)
            d.y = (o.y > p.origin.y ? -1 : 1) * pow(10, -6 - 2 * rng_uniform(&r)) * (q % 8 == 0);
        struct hit h;
        int found = heightfield_ops.intersect(hf, make_ray(o, d), INFINITY, &h);
        double t_plane = (p.origin.y - o.y) / d.y; /* +-inf or NaN when d.y = 0: no hit */
        struct vec3 x = vec3_madd(o, d, t_plane);
        double u = (x.x - p.origin.x) / p.size, v = (x.z - p.origin.z) / p.size;
        if (fmin(fmin(u, v), fmin(1 - u, 1 - v)) > -1e-9 &&
            fmin(fmin(u, v), fmin(1 - u, 1 - v)) < 1e-9)
            continue;
        int inside = t_plane > 0 && isfinite(t_plane) && u > 0 && u < 1 && v > 0 && v < 1;
        n_wrong += found != inside;
        if (found && inside)
            n_wrong += !(fabs(h.t - t_plane) <= 1e-12 * t_plane && h.ng.y == 1 && h.ns.y == 1 &&
                         fabs(h.u - u) <= 1e-12 && fabs(h.v - v) <= 1e-12 && h.material == 5);
    }
    CHECK(t, n_wrong == 0);
    heightfield_free(hf);
}

/* The points of cell (i, j) a leak would show at: its corner, the midpoints of its two
 * lower edges and of its diagonal (k = 0..3). */
static struct vec3 seam_point(const struct triangle_list *list, int n, int i, int j, int k)
{
    const struct vec3 *v = list->v + 6 * ((size_t)j * (size_t)(n - 1) + (size_t)i);
    /* v[0] = (i, j), v[1] = (i, j+1), v[2] = (i+1, j+1), v[5] = (i+1, j) */
    switch (k) {
    case 0: return v[0];
    case 1: return vec3_scale(vec3_add(v[0], v[1]), 0.5);
    case 2: return vec3_scale(vec3_add(v[0], v[5]), 0.5);
    default: return vec3_scale(vec3_add(v[0], v[2]), 0.5);
    }
}

/* truth: a ray that crosses a surface must hit it; the heightfield is a graph over the
 *   square, so a steep ray from above aimed at a surface point crosses it there.
 * tolerance: the hit may be nearer than the point (another fold first), never farther
 *   than it by more than 1e-9 relative (midpoints are rounded to within ulps of the edge).
 * rays: aimed at every interior vertex, edge midpoint and diagonal midpoint of a 12 x 12
 *   grid (where cells meet), from random points above, at least 45 degrees steep; also
 *   straight down and with d.x = 0 or d.z = 0, which run inside the planes between
 *   pyramid nodes when aimed at a vertex or an edge.
 * catches: a ray slipping between triangles or cells (non-watertight test, vertices
 *   recomputed differently by neighbours, an inconsistent diagonal), boxes that exclude
 *   their own border, a ray lying in a split plane sent to one side only. */
static void test_heightfield_is_watertight(struct check *t)
{
    const int n = 12;
    struct heightfield_params p = landscape(n, 1.5, 7);
    struct error err;
    struct heightfield *hf = heightfield_create(&p, &err);
    struct triangle_list list = heightfield_list(hf);
    int n_leaks = 0;
    for (int j = 1; j < n - 1; j++) {
        for (int i = 1; i < n - 1; i++) {
            for (int k = 0; k < 4; k++) {
                struct vec3 x = seam_point(&list, n, i, j, k);
                struct rng r = rng_stream(5, STREAM_TEST, (uint64_t)(j * n + i), (uint64_t)k);
                double phi = 2 * PI * rng_uniform(&r), slope = rng_uniform(&r);
                const struct vec3 d[4] = {vec3(slope * cos(phi), -1, slope * sin(phi)),
                                          vec3(0, -1, 0), vec3(0, -1, slope - 0.5),
                                          vec3(0.5 - slope, -1, 0)};
                for (int m = 0; m < 4; m++) {
                    struct vec3 o = vec3_madd(x, d[m], -(3 + 2 * rng_uniform(&r)));
                    struct hit h;
                    n_leaks += !heightfield_ops.intersect(hf, make_ray(o, d[m]), INFINITY, &h) ||
                               h.t > vec3_length(vec3_sub(x, o)) / vec3_length(d[m]) * (1 + 1e-9);
                }
            }
        }
    }
    CHECK(t, n_leaks == 0);
    triangle_list_free(&list);
    heightfield_free(hf);
}

/* truth: brute force, every triangle of the expansion tested with triangle.c (the same
 *   watertight test on the same vertex doubles), closest kept.
 * tolerance: t and p to 1e-9 relative, the workload's figure (both sides run the same doubles
 *   and in fact agree to the ulp; a ray through a shared edge may report either triangle);
 *   ns to 1e-9; ng not compared (two triangles meet at an edge with different ng).
 * catches: a pruned node holding the nearest hit (box too small, y range from too few
 *   samples), grazing rays lost between pyramid levels, the last row of an odd grid never
 *   visited, a wrong child index, occluded() disagreeing with intersect(). */
static void test_heightfield_matches_brute_force(struct check *t)
{
    const int sizes[] = {2, 3, 8, 17, 33};
    for (int s = 0; s < 5; s++) {
        struct heightfield_params p = landscape(sizes[s], 0.9, 11 + (uint64_t)s);
        struct error err;
        struct heightfield *hf = heightfield_create(&p, &err);
        struct triangle_list list = heightfield_list(hf);
        int n_wrong = 0;
        for (uint64_t q = 0; q < 3000; q++) {
            struct ray ray = terrain_test_ray(&p, &list, 10000 * (uint64_t)s + q);
            struct hit a, b;
            int found_a = heightfield_ops.intersect(hf, ray, INFINITY, &a);
            int found_b = brute_force_triangles(&list, ray, &b);
            n_wrong += found_a != found_b || (found_a && !same_hit(&a, &b, ray, 1e-9, 0));
            n_wrong += heightfield_ops.occluded(hf, ray, INFINITY) != found_b;
            if (found_b)
                n_wrong += heightfield_ops.occluded(hf, ray, b.t * (1 - 1e-9));
        }
        CHECK(t, n_wrong == 0);
        triangle_list_free(&list);
        heightfield_free(hf);
    }
}

struct terrain_rays {
    struct heightfield_params p;
    struct triangle_list list;
};

static struct ray terrain_ray_of(const void *context, uint64_t q)
{
    const struct terrain_rays *rays = context;
    return terrain_test_ray(&rays->p, &rays->list, q + 100000);
}

/* truth: the expansion, heightfield_expand() into a geometry (BVH over 2 * 128^2 plain
 *   triangles with their vertex normals), against the shape alone in another geometry.
 * tolerance: as in the brute-force test, 1e-9 relative on t and p, and no misses either way.
 * rays: a million, a third of them grazing (nearly horizontal, just above the surface).
 * catches: what a million rays find and thousands do not; the shape's plumbing (bounds
 *   given to the BVH, the hit record through geometry). */
static void test_heightfield_matches_expansion(struct check *t)
{
    struct terrain_rays rays;
    rays.p = landscape(129, 1.2, 99);
    struct error err;
    struct heightfield *hf = heightfield_create(&rays.p, &err);
    struct heightfield *copy = heightfield_create(&rays.p, &err);
    rays.list = heightfield_list(copy);
    struct geometry *procedural = geometry_create(), *expanded = geometry_create();
    CHECK(t, geometry_add_shape(procedural, &heightfield_ops, hf, 5) == 0);
    CHECK(t, heightfield_expand(copy, expanded) == 0);
    CHECK(t, geometry_primitive_count(expanded) == 2 * 128 * 128);
    geometry_build(procedural);
    geometry_build(expanded);
    CHECK(t, geometry_agreements(procedural, expanded, terrain_ray_of, &rays, 2 * EXPANSION_RAYS,
                                 1e-9) == 2 * EXPANSION_RAYS);
    triangle_list_free(&rays.list);
    heightfield_free(copy);
    geometry_free(expanded);
    geometry_free(procedural); /* frees hf */
}

void test_shapes(struct check *t)
{
    RUN_TEST(t, test_sphereflake_is_balls_s3);
    RUN_TEST(t, test_sphereflake_prints_as_balls_s4);
    RUN_TEST(t, test_sphereflake_structure);
    RUN_TEST(t, test_sphereflake_refuses_bad_parameters);
    RUN_TEST(t, test_sphereflake_matches_brute_force);
    RUN_TEST(t, test_sphereflake_matches_expansion);
    RUN_TEST(t, test_noise);
    RUN_TEST(t, test_heightfield_structure);
    RUN_TEST(t, test_heightfield_shading_normals);
    RUN_TEST(t, test_heightfield_refuses_bad_parameters);
    RUN_TEST(t, test_heightfield_flat_closed_form);
    RUN_TEST(t, test_heightfield_is_watertight);
    RUN_TEST(t, test_heightfield_matches_brute_force);
    RUN_TEST(t, test_heightfield_matches_expansion);
}
