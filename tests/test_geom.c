/*
 * tests/test_geom.c -- the geometry room: spheres, triangles, quads, shapes and the BVH.
 *
 * The BVH is checked against brute force: a second copy of every primitive, made with the
 * same *_make() calls, intersected one by one with the same functions, so BVH and brute
 * force must agree exactly (they compute the same doubles); any difference is a primitive
 * the traversal lost or a record geometry.c mixed up. The primitives are checked against
 * closed forms and geometric truths: watertight closed meshes, the smallpt wall, grazing
 * rays, uv and normals at known points. Randomness: STREAM_TEST, keyed by case and index.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/base/rng.h"
#include "../src/geom/bvh.h"
#include "../src/geom/geometry.h"
#include "../src/geom/quad.h"
#include "../src/geom/sphere.h"
#include "../src/geom/triangle.h"
#include "tests.h"

#define TEST_SEED 2024

/* ---- random numbers, points, directions ---- */

static double uniform(struct rng *r, double lo, double hi)
{
    return lo + (hi - lo) * rng_uniform(r);
}

/* Uniform on the unit sphere (Archimedes: z uniform in [-1, 1]). */
static struct vec3 random_unit(struct rng *r)
{
    double z = uniform(r, -1.0, 1.0), phi = uniform(r, 0.0, 2.0 * PI);
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    return vec3(s * cos(phi), s * sin(phi), z);
}

static struct vec3 random_point(struct rng *r, double half_size)
{
    return vec3(uniform(r, -half_size, half_size), uniform(r, -half_size, half_size),
                uniform(r, -half_size, half_size));
}

static int relative_close(double a, double b, double rel)
{
    return fabs(a - b) <= rel * fmax(fabs(a), fabs(b));
}

static int hit_is_finite(const struct hit *h)
{
    return isfinite(h->t) && vec3_is_finite(h->p) && vec3_is_finite(h->ng)
           && vec3_is_finite(h->ns) && isfinite(h->u) && isfinite(h->v);
}

/* ---- a procedural test shape: a ball behind struct shape_ops ---- */

struct ball {
    struct sphere sphere;
    int *n_freed;   /* borrowed from the test: counts ball_free() calls */
};

static struct aabb ball_bounds(const void *shape)
{
    return sphere_bounds(&((const struct ball *)shape)->sphere);
}

static int ball_intersect(const void *shape, struct ray ray, double tmax, struct hit *hit)
{
    const struct sphere *s = &((const struct ball *)shape)->sphere;
    if (!sphere_intersect(s, ray, tmax, hit))
        return 0;
    sphere_shade(s, ray, hit);
    hit->prim = -7;   /* geometry must overwrite this */
    return 1;
}

static int ball_occluded(const void *shape, struct ray ray, double tmax)
{
    struct hit hit;
    return sphere_intersect(&((const struct ball *)shape)->sphere, ray, tmax, &hit);
}

static size_t ball_bytes(const void *shape)
{
    (void)shape;
    return sizeof(struct ball);
}

static void ball_free(void *shape)
{
    struct ball *b = shape;
    if (b == NULL)
        return;
    (*b->n_freed)++;
    xfree(b);
}

static const struct shape_ops ball_ops = {"ball", ball_bounds, ball_intersect, ball_occluded,
                                          ball_bytes, ball_free, NULL, NULL};

/* ---- brute force: every primitive twice, once in a geometry, once in a plain list ---- */

enum brute_kind { BRUTE_SPHERE, BRUTE_TRIANGLE, BRUTE_QUAD, BRUTE_BALL };

struct brute_prim {
    enum brute_kind kind;
    struct sphere sphere;        /* BRUTE_SPHERE, and BRUTE_BALL's sphere */
    struct triangle triangle;
    struct vec3 normals[3];      /* the triangle's vertex normals when it has them */
    int has_normals;
    struct quad quad;
};

struct brute {
    struct geometry *g;          /* owned */
    struct brute_prim *prims;    /* owned; prims[id] is primitive id of g */
    size_t n, cap;
    int n_balls;                 /* balls handed to the geometry */
    int n_freed;                 /* balls freed by geometry_free */
};

static void brute_init(struct brute *b)
{
    b->g = geometry_create();
    b->prims = NULL;
    b->n = 0;
    b->cap = 0;
    b->n_balls = 0;
    b->n_freed = 0;
}

static void brute_free(struct brute *b)
{
    geometry_free(b->g);
    xfree(b->prims);
}

static struct brute_prim *brute_next(struct brute *b, enum brute_kind kind)
{
    if (b->n == b->cap) {
        b->cap = b->cap < 16 ? 16 : 2 * b->cap;
        b->prims = xrealloc(b->prims, b->cap, sizeof *b->prims, "test primitives");
    }
    b->prims[b->n].kind = kind;
    b->prims[b->n].has_normals = 0;
    return &b->prims[b->n];
}

/* Each add checks that geometry hands out ids 0, 1, 2, ... in order. */
static int brute_sphere(struct brute *b, struct vec3 c, double r, int material)
{
    struct brute_prim *p = brute_next(b, BRUTE_SPHERE);
    p->sphere = sphere_make(c, r, material, (int)b->n);
    return geometry_add_sphere(b->g, c, r, material) == (int)b->n++;
}

static int brute_triangle(struct brute *b, const struct vec3 v[3], const struct vec3 *normals,
                          int material)
{
    struct brute_prim *p = brute_next(b, BRUTE_TRIANGLE);
    p->triangle = triangle_make(v, normals != NULL ? 0 : -1, material, (int)b->n);
    p->has_normals = normals != NULL;
    for (int i = 0; i < 3 && normals != NULL; i++)
        p->normals[i] = normals[i];
    return geometry_add_triangle(b->g, v, normals, material) == (int)b->n++;
}

static int brute_quad(struct brute *b, struct vec3 p0, struct vec3 e1, struct vec3 e2,
                      int material)
{
    struct brute_prim *p = brute_next(b, BRUTE_QUAD);
    p->quad = quad_make(p0, e1, e2, material, (int)b->n);
    return geometry_add_quad(b->g, p0, e1, e2, material) == (int)b->n++;
}

static int brute_ball(struct brute *b, struct vec3 c, double r, int material)
{
    struct brute_prim *p = brute_next(b, BRUTE_BALL);
    struct ball *ball = xmalloc(1, sizeof *ball, "test ball");
    ball->sphere = sphere_make(c, r, material, -1);
    ball->n_freed = &b->n_freed;
    p->sphere = ball->sphere;
    b->n_balls++;
    return geometry_add_shape(b->g, &ball_ops, ball, material) == (int)b->n++;
}

/* Primitive p's test as geometry.c does it: degenerate ones are never hit. */
static int brute_test(const struct brute_prim *p, struct ray ray, const struct sheared_ray *sr,
                      double tmax, struct hit *hit)
{
    switch (p->kind) {
    case BRUTE_SPHERE:
    case BRUTE_BALL:
        return sphere_intersect(&p->sphere, ray, tmax, hit);
    case BRUTE_TRIANGLE:
        return !triangle_is_degenerate(&p->triangle)
               && triangle_intersect(&p->triangle, sr, tmax, hit);
    default:
        return !quad_is_degenerate(&p->quad) && quad_intersect(&p->quad, sr, tmax, hit);
    }
}

static void brute_shade(const struct brute_prim *p, struct ray ray, struct hit *hit)
{
    switch (p->kind) {
    case BRUTE_SPHERE:
    case BRUTE_BALL:
        sphere_shade(&p->sphere, ray, hit);
        break;
    case BRUTE_TRIANGLE:
        triangle_shade(&p->triangle, p->has_normals ? p->normals : NULL, hit);
        break;
    default:
        quad_shade(&p->quad, hit);
    }
}

/* The closest hit over every primitive, by linear scan. */
static int brute_intersect(const struct brute *b, struct ray ray, double tmax, struct hit *hit)
{
    if (!(vec3_length2(ray.dir) > 0))
        return 0;
    struct sheared_ray sr = shear_ray(ray);
    size_t closest = b->n;
    for (size_t i = 0; i < b->n; i++) {
        if (brute_test(&b->prims[i], ray, &sr, tmax, hit)) {
            tmax = hit->t;
            closest = i;
        }
    }
    if (closest == b->n)
        return 0;
    brute_shade(&b->prims[closest], ray, hit);   /* the last hit written is the closest */
    hit->prim = (int)closest;
    return 1;
}

/* One ray through the BVH and by brute force. Ties (equal t) may pick either primitive;
 * otherwise the whole record must match. Returns 1 when they agree. */
static int same_as_brute_force(const struct brute *b, struct ray ray, double tmax)
{
    struct hit h_bvh, h_brute;
    int found = geometry_intersect(b->g, ray, tmax, &h_bvh);
    int expected = brute_intersect(b, ray, tmax, &h_brute);
    if (geometry_occluded(b->g, ray, tmax) != expected || found != expected)
        return 0;
    if (!found)
        return 1;
    if (!relative_close(h_bvh.t, h_brute.t, 1e-12) || !hit_is_finite(&h_bvh))
        return 0;
    if (h_bvh.prim != h_brute.prim)
        return h_bvh.t == h_brute.t;   /* a tie */
    return h_bvh.material == h_brute.material && h_bvh.u == h_brute.u && h_bvh.v == h_brute.v
           && vec3_length2(vec3_sub(h_bvh.p, h_brute.p)) == 0
           && vec3_length2(vec3_sub(h_bvh.ng, h_brute.ng)) == 0
           && vec3_length2(vec3_sub(h_bvh.ns, h_brute.ns)) == 0;
}

/* ---- random scenes ---- */

/* A size drawn log-uniformly from 1e-3 to 10: several magnitudes in one scene. */
static double random_size(struct rng *r)
{
    return pow(10.0, uniform(r, -3.0, 1.0));
}

static int add_random_primitive(struct brute *b, struct rng *r)
{
    struct vec3 c = random_point(r, 20.0);
    double s = random_size(r);
    int material = (int)(rng_next(r) % 5);
    switch (rng_next(r) % 8) {
    case 0:
    case 1:
        return brute_sphere(b, c, s, material);
    case 2:
        return brute_ball(b, c, s, material);
    case 3:
    case 4: {
        struct vec3 v[3] = {vec3_madd(c, random_unit(r), s), vec3_madd(c, random_unit(r), s),
                            vec3_madd(c, random_unit(r), s)};
        struct vec3 n[3] = {random_unit(r), random_unit(r), random_unit(r)};
        return brute_triangle(b, v, rng_next(r) % 2 ? n : NULL, material);
    }
    default:
        return brute_quad(b, c, vec3_scale(random_unit(r), s),
                          vec3_scale(random_unit(r), s * uniform(r, 0.1, 1.0)), material);
    }
}

/* A ray for the brute-force comparison: origins in and around the scene; directions of any
 * length, a fifth of them along axes with +-0 components; tmax finite for a third. */
static struct ray random_ray(struct rng *r, double *tmax)
{
    struct vec3 o = random_point(r, 30.0);
    struct vec3 d = vec3_scale(random_unit(r), pow(10.0, uniform(r, -2.0, 2.0)));
    if (rng_next(r) % 5 == 0) {
        double sign = rng_next(r) % 2 ? 1.0 : -1.0;
        double zero = rng_next(r) % 2 ? 0.0 : -0.0;
        int axis = (int)(rng_next(r) % 3);
        d = vec3(axis == 0 ? sign : zero, axis == 1 ? sign : zero, axis == 2 ? sign : zero);
    }
    *tmax = rng_next(r) % 3 == 0 ? uniform(r, 0.0, 60.0) : INFINITY;
    return make_ray(o, d);
}

/* Builds a BVH over the boxes geometry_build() would use (hittable primitives) and checks
 * it; bvh_build is deterministic, so this is the tree inside b->g. */
static int brute_bvh_check(const struct brute *b)
{
    struct aabb *bounds = xmalloc(b->n, sizeof *bounds, "test bounds");
    size_t n = 0;
    for (size_t i = 0; i < b->n; i++) {
        const struct brute_prim *p = &b->prims[i];
        if (p->kind == BRUTE_SPHERE || p->kind == BRUTE_BALL)
            bounds[n++] = sphere_bounds(&p->sphere);
        else if (p->kind == BRUTE_TRIANGLE && !triangle_is_degenerate(&p->triangle))
            bounds[n++] = triangle_bounds(&p->triangle);
        else if (p->kind == BRUTE_QUAD && !quad_is_degenerate(&p->quad))
            bounds[n++] = quad_bounds(&p->quad);
    }
    struct bvh *bvh = bvh_build(bounds, n);
    int ok = bvh_check(bvh, bounds, n);
    bvh_free(bvh);
    xfree(bounds);
    return ok;
}

/* truth: brute force over all primitives (same functions, so exact agreement).
 * tolerance: t to 1e-12 relative (it is in fact bitwise); at a tie either primitive.
 * catches: a subtree never visited, a stale tmax pruning a closer hit, nearer-first order
 *   stopping early, slabs mishandling zero direction components, refs or records permuted
 *   inconsistently, shapes' prim not set, occluded() disagreeing with intersect(). */
static void test_bvh_matches_brute_force(struct check *t)
{
    static const size_t sizes[] = {0, 1, 2, 3, 5, 17, 200, 2000};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 1, s);
        struct brute b;
        brute_init(&b);
        for (size_t i = 0; i < sizes[s]; i++)
            CHECK(t, add_random_primitive(&b, &r));
        geometry_build(b.g);
        CHECK(t, geometry_primitive_count(b.g) == sizes[s]);
        CHECK(t, brute_bvh_check(&b));
        int agree = 1;
        for (int k = 0; k < 1000; k++) {
            double tmax;
            struct ray ray = random_ray(&r, &tmax);
            agree &= same_as_brute_force(&b, ray, tmax);
        }
        CHECK(t, agree);
        size_t bytes = geometry_bytes(b.g);
        CHECK(t, bytes >= sizes[s] * sizeof(struct sphere));
        brute_free(&b);
        CHECK(t, b.n_freed == b.n_balls);   /* geometry_free released every shape once */
    }
}

/* Whether geometry reports every primitive's box and material as the plain list has them
 * (a ball's box is its sphere's; its material the one it was added with). */
static int brute_records_agree(const struct brute *b)
{
    int agree = 1;
    for (size_t i = 0; i < b->n; i++) {
        const struct brute_prim *p = &b->prims[i];
        struct aabb box = p->kind == BRUTE_TRIANGLE ? triangle_bounds(&p->triangle)
                          : p->kind == BRUTE_QUAD   ? quad_bounds(&p->quad)
                                                    : sphere_bounds(&p->sphere);
        int material = p->kind == BRUTE_TRIANGLE ? p->triangle.material
                       : p->kind == BRUTE_QUAD   ? p->quad.material
                                                 : p->sphere.material;
        struct aabb got = geometry_primitive_bounds(b->g, (int)i);
        agree &= memcmp(&got, &box, sizeof box) == 0;
        agree &= geometry_primitive_material(b->g, (int)i) == material;
    }
    return agree;
}

/* truth: brute force, the plain list's own records.
 * tolerance: none (the same functions on the same numbers).
 * catches: an id naming another primitive's record after geometry_build() permutes the
 *   arrays into leaf order (or after more adds and a rebuild), degenerate primitives
 *   (left out of the BVH) losing their place, a shape's box or material not its own. */
static void test_primitive_bounds_and_material(struct check *t)
{
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 5, 0);
    struct brute b;
    brute_init(&b);
    struct vec3 flat[3] = {{1, 1, 1}, {2, 2, 2}, {3, 3, 3}}; /* degenerate: no area */
    CHECK(t, brute_triangle(&b, flat, NULL, 3));
    for (int i = 0; i < 300; i++)
        CHECK(t, add_random_primitive(&b, &r));
    CHECK(t, brute_records_agree(&b)); /* before any build */
    geometry_build(b.g);
    CHECK(t, brute_records_agree(&b));
    for (int i = 0; i < 100; i++)
        CHECK(t, add_random_primitive(&b, &r));
    CHECK(t, brute_records_agree(&b)); /* adds after a build */
    geometry_build(b.g);
    CHECK(t, brute_records_agree(&b));
    brute_free(&b);
}

/* truth: brute force again, on scenes built to corner the builder and the slab test: every
 *   box identical (no centroid spread), centres at powers of 2 up to 2^299 (equal bins peel
 *   a few items per level, so the SAH alone would pass BVH_MAX_DEPTH), and axis-aligned unit
 *   cubes of quads hit by axis-parallel rays lying exactly in their faces' planes.
 * tolerance: as above.
 * catches: a build that loops or overflows its depth on coincident centres, a leaf over
 *   BVH_MAX_LEAF (8 nearly coincident balls tempt the SAH), a traversal stack overrun, a
 *   slab whose 0 * inf = NaN rejects the box. */
static void test_bvh_hard_cases(struct check *t)
{
    struct brute same, deep, cubes;
    brute_init(&same);
    brute_init(&deep);
    brute_init(&cubes);
    struct vec3 v[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 300; i++) {
        CHECK(t, brute_triangle(&same, v, NULL, i % 3));
        if (i < 8)   /* nearly coincident balls: the SAH would rather keep all 8 in one leaf */
            CHECK(t, brute_sphere(&same, vec3(1e-6 * i, 0.5, 0.0), 1.0, 0));
        CHECK(t, brute_sphere(&deep, vec3(ldexp(1.0, i), 0.0, 0.0), ldexp(0.1, i), 0));
    }
    for (int i = 0; i < 64; i++) {
        struct vec3 o = vec3(i % 4, (i / 4) % 4, i / 16);
        struct vec3 x = vec3(1, 0, 0), y = vec3(0, 1, 0), z = vec3(0, 0, 1);
        CHECK(t, brute_quad(&cubes, o, y, x, 0) && brute_quad(&cubes, vec3_add(o, z), x, y, 0));
        CHECK(t, brute_quad(&cubes, o, z, y, 0) && brute_quad(&cubes, vec3_add(o, x), y, z, 0));
        CHECK(t, brute_quad(&cubes, o, x, z, 0) && brute_quad(&cubes, vec3_add(o, y), z, x, 0));
    }
    geometry_build(same.g);
    geometry_build(deep.g);
    geometry_build(cubes.g);
    CHECK(t, brute_bvh_check(&same) && brute_bvh_check(&deep) && brute_bvh_check(&cubes));
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 2, 0);
    int agree = 1;
    for (int k = 0; k < 500; k++) {
        struct vec3 d = random_unit(&r);
        agree &= same_as_brute_force(&same, make_ray(vec3(0.2, 0.3, 5.0), vec3(0, 0, -1)), 9);
        agree &= same_as_brute_force(&same, make_ray(vec3_scale(d, 3.0), vec3_neg(d)), INFINITY);
        agree &= same_as_brute_force(&deep, make_ray(vec3(-1.0, 0.0, 0.0), vec3(1, 0, 0)),
                                     ldexp(1.0, k % 300));
        agree &= same_as_brute_force(&deep, make_ray(vec3_scale(d, ldexp(1.0, k % 300)),
                                                     vec3_neg(d)), INFINITY);
        /* In the plane y = j of a cube face, along x from outside: d.y = 0, origin.y = j. */
        double y = (double)(k % 5), z = uniform(&r, 0.0, 4.0);
        agree &= same_as_brute_force(&cubes, make_ray(vec3(-1.0, y, z), vec3(1, 0, 0)), INFINITY);
        agree &= same_as_brute_force(&cubes, make_ray(vec3(z, y, 9.0), vec3(-0.0, 0, -1)), 20);
    }
    CHECK(t, agree);
    brute_free(&same);
    brute_free(&deep);
    brute_free(&cubes);
}

/* truth: exact arithmetic. With a = 1 + 2^-52, e(P, Q) = qx py - qy px for P = (1, a),
 *   Q = (a, 1 + 2^-51) is a^2 - (1 + 2^-51) = 2^-104: both products round to 1 + 2^-51, so
 *   only the exact fallback sees the difference. Scaled by 2^40 per coordinate it is 2^-24;
 *   collinear points give exactly 0; and e(Q, P) = -e(P, Q) bit for bit on random inputs.
 * tolerance: none.
 * catches: the fallback missing (a false zero lets a ray through a vertex fan miss every
 *   triangle), a fallback with the wrong sign, an edge function that is not antisymmetric
 *   (neighbours would disagree about their shared edge). */
static void test_edge_function_exact_sign(struct check *t)
{
    double a = 1.0 + ldexp(1.0, -52), b = 1.0 + ldexp(1.0, -51), big = ldexp(1.0, 40);
    CHECK(t, edge_function(1.0, a, a, b) == ldexp(1.0, -104));
    CHECK(t, edge_function(a, b, 1.0, a) == -ldexp(1.0, -104));
    CHECK(t, edge_function(big, big * a, big * a, big * b) == ldexp(1.0, -24));
    CHECK(t, edge_function(2.0, 3.0, 4.0, 6.0) == 0.0);
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 11, 0);
    int antisymmetric = 1;
    for (int k = 0; k < 10000; k++) {
        double px = uniform(&r, -1, 1), py = uniform(&r, -1, 1);
        double qx = uniform(&r, -1, 1), qy = uniform(&r, -1, 1);
        if (k % 2) {   /* collinear with the origin: the value is 0 or nearly */
            qx = px * 3.0;
            qy = py * 3.0;
        }
        antisymmetric &= edge_function(px, py, qx, qy) == -edge_function(qx, qy, px, py);
    }
    CHECK(t, antisymmetric);
}

/* truth: closed forms for one primitive of each kind in front of a ray along +z from
 *   z = -10: sphere of radius 2 at the origin t = 8; triangle and quad in z = 0, t = 10 with
 *   ng = +z (their counter-clockwise side) although the ray comes from -z. An empty geometry
 *   hits nothing, before and after geometry_build(). tmax is open: a hit at t = tmax is none.
 * tolerance: exact (every number is a small integer or half).
 * catches: a build or traversal that fails for 0 or 1 items, ng flipped towards the ray,
 *   t <= tmax accepted, occluded() with the wrong interval. */
static void test_empty_and_single_primitives(struct check *t)
{
    struct ray ray = make_ray(vec3(0.0, 0.0, -10.0), vec3(0.0, 0.0, 1.0));
    struct hit hit;
    struct geometry *g = geometry_create();
    CHECK(t, !geometry_intersect(g, ray, INFINITY, &hit));
    geometry_build(g);
    CHECK(t, geometry_primitive_count(g) == 0 && geometry_bvh_nodes(g) == 0);
    CHECK(t, !geometry_intersect(g, ray, INFINITY, &hit) && !geometry_occluded(g, ray, 1e9));
    CHECK(t, geometry_bounds(g).lo.x > geometry_bounds(g).hi.x);
    geometry_free(g);
    geometry_free(NULL);
    struct vec3 tri[3] = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    static const double expected_t[3] = {8.0, 10.0, 10.0};
    for (int kind = 0; kind < 3; kind++) {
        g = geometry_create();
        int id = kind == 0   ? geometry_add_sphere(g, vec3_zero(), 2.0, 4)
                 : kind == 1 ? geometry_add_triangle(g, tri, NULL, 4)
                             : geometry_add_quad(g, vec3(-1, -1, 0), vec3(2, 0, 0),
                                                 vec3(0, 2, 0), 4);
        geometry_build(g);
        CHECK(t, id == 0 && geometry_bvh_nodes(g) == 1);
        CHECK(t, geometry_intersect(g, ray, INFINITY, &hit) && hit.prim == 0 && hit.material == 4);
        CHECK(t, hit.t == expected_t[kind] && hit.ng.z == (kind == 0 ? -1.0 : 1.0));
        CHECK(t, hit.p.z == (kind == 0 ? -2.0 : 0.0) && hit.ns.z == hit.ng.z);
        CHECK(t, !geometry_intersect(g, ray, expected_t[kind], &hit));
        CHECK(t, geometry_occluded(g, ray, expected_t[kind] + 1e-9));
        CHECK(t, !geometry_occluded(g, ray, expected_t[kind]));
        geometry_free(g);
    }
}

/* truth: geometry.h's life cycle: adds after geometry_build() join the BVH when it is
 *   called again, ids keep counting, and the records permuted by the first build still
 *   answer with their own ids.
 * tolerance: exact (small integers).
 * catches: a rebuild that drops or duplicates permuted records, arrays shrunk by the build
 *   and not grown again, stale refs. */
static void test_rebuild_after_more_adds(struct check *t)
{
    struct geometry *g = geometry_create();
    for (int i = 0; i < 10; i++)
        CHECK(t, geometry_add_sphere(g, vec3(3.0 * i, 0.0, 0.0), 1.0, i) == i);
    geometry_build(g);
    for (int i = 0; i < 10; i++)
        CHECK(t, geometry_add_quad(g, vec3(3.0 * i - 1, -1, 5), vec3(2, 0, 0), vec3(0, 2, 0), 0)
                     == 10 + i);
    struct hit hit;
    struct ray before = make_ray(vec3(6.0, 0.0, 9.0), vec3(0, 0, -1));
    CHECK(t, geometry_intersect(g, before, INFINITY, &hit) && hit.prim == 2);   /* old BVH */
    geometry_build(g);
    CHECK(t, geometry_primitive_count(g) == 20);
    for (int i = 0; i < 10; i++) {
        struct ray down = make_ray(vec3(3.0 * i, 0.0, 9.0), vec3(0, 0, -1));
        struct ray below = make_ray(vec3(3.0 * i, 0.0, -9.0), vec3(0, 0, 1));
        CHECK(t, geometry_intersect(g, down, INFINITY, &hit) && hit.prim == 10 + i);
        CHECK(t, geometry_intersect(g, below, INFINITY, &hit) && hit.prim == i);
        CHECK(t, hit.material == i);
    }
    geometry_free(g);
}

/* truth: a primitive without area has no surface (triangle.h, quad.h, sphere.h): rays aimed
 *   exactly at one pass on to the backstop behind it. Geometry of only such primitives is
 *   empty to rays.
 * tolerance: none; every field of every hit must be finite.
 * catches: 0 / 0 barycentrics on a zero-area triangle, a zero normal normalised into NaN, a
 *   build that fails on point boxes, degenerate primitives reported as hits. */
static void test_degenerate_primitives(struct check *t)
{
    struct vec3 point[3] = {{1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
    struct vec3 line[3] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    struct geometry *empty = geometry_create();
    struct geometry *g = geometry_create();
    for (int k = 0; k < 2; k++) {
        struct geometry *h = k == 0 ? empty : g;
        geometry_add_triangle(h, point, NULL, 1);
        geometry_add_triangle(h, line, point, 1);
        geometry_add_quad(h, vec3(0, 1, 0), vec3(1, 1, 1), vec3(-2, -2, -2), 1);
        geometry_add_quad(h, vec3(0, 1, 0), vec3_zero(), vec3(1, 0, 0), 1);
        geometry_add_sphere(h, vec3(1, 2, 3), 0.0, 1);
        geometry_add_sphere(h, vec3(1, 1, 1), -1.0, 1);
    }
    int backstop = geometry_add_quad(g, vec3(-50, -50, -20), vec3(100, 0, 0), vec3(0, 100, 0), 2);
    geometry_build(empty);
    geometry_build(g);
    CHECK(t, geometry_primitive_count(empty) == 6 && geometry_bvh_nodes(empty) == 0);
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 3, 0);
    static const struct vec3 targets[] = {{1, 2, 3}, {1, 1, 1}, {0.5, 0.5, 0.5}, {0, 1, 0}};
    int ok = 1;
    for (int k = 0; k < 400; k++) {
        struct vec3 target = targets[k % 4];
        struct vec3 up = random_unit(&r);
        up.z = fabs(up.z) + 1.0;   /* from above, steeply enough to reach the backstop */
        struct vec3 o = vec3_madd(target, vec3_normalize(up), uniform(&r, 0.5, 5.0));
        struct ray ray = make_ray(o, vec3_sub(target, o));
        struct hit hit;
        ok &= !geometry_intersect(empty, ray, INFINITY, &hit);
        ok &= geometry_intersect(g, ray, INFINITY, &hit) && hit.prim == backstop;
        ok &= hit_is_finite(&hit);
    }
    CHECK(t, ok);
    geometry_free(empty);
    geometry_free(g);
}

/* A unit vector at angle theta from the unit vector a, in a random plane through a. */
static struct vec3 tilted(struct vec3 a, double theta, struct rng *r)
{
    struct vec3 e1, e2;
    vec3_frame(a, &e1, &e2);
    double phi = uniform(r, 0.0, 2.0 * PI);
    struct vec3 side = vec3_add(vec3_scale(e1, cos(phi)), vec3_scale(e2, sin(phi)));
    return vec3_add(vec3_scale(a, cos(theta)), vec3_scale(side, sin(theta)));
}

/* truth: the smallpt wall: a sphere of radius R = 1e5 whose centre is at distance R + 1
 *   from the ray origin (0). For a unit direction with b = d.c, the near root is
 *   t = C / (b + sqrt(b^2 - C)), C = |c|^2 - R^2 = (|c| - R)(|c| + R) = 2e5 + 1, a sum of
 *   positives (no cancellation), so it is good to ~1e-15 (c's rounding moves it ~1e-11).
 * tolerance: 1e-9 relative. (In double the textbook form also stays within ~1e-11 here;
 *   the small and grazing tests below are the ones it fails.)
 * catches: the far root for the near one, a lossy t or p on a wall a renderer relies on,
 *   p not on the sphere. */
static void test_sphere_far_wall(struct check *t)
{
    const double radius = 1e5, distance = 1e5 + 1.0;
    const double c_term = (distance - radius) * (distance + radius);
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 4, 0);
    int ok = 1;
    for (int k = 0; k < 2000; k++) {
        struct vec3 a = random_unit(&r);
        struct vec3 c = vec3_scale(a, distance);
        struct sphere s = sphere_make(c, radius, 0, 0);
        struct ray ray = make_ray(vec3_zero(), k == 0 ? a : tilted(a, uniform(&r, 0, 1.2), &r));
        double b = vec3_dot(ray.dir, c);
        double t_true = c_term / (b + sqrt(b * b - c_term));
        struct hit hit;
        ok &= sphere_intersect(&s, ray, INFINITY, &hit);
        sphere_shade(&s, ray, &hit);
        ok &= relative_close(hit.t, t_true, 1e-9);
        ok &= relative_close(vec3_length(hit.p), t_true, 1e-9);
        ok &= relative_close(vec3_length(vec3_sub(hit.p, c)), radius, 1e-9);
    }
    CHECK(t, ok);
}

/* truth: a hit point lies on its sphere: | |o + t d - c| - r | = 0, here for r = 1e-4 seen
 *   from 10 to 1e5 radii away; and the near root is the entry (the normal faces the ray).
 * tolerance: 1e-9 r for o + t d, which itself carries ~1e-16 |o| <= 2e-15 = 2e-11 r of
 *   rounding; 1e-11 r for the shading point p, which sphere_shade() projects onto the
 *   sphere (its error is then ~1e-16 |c| = 2e-12 r), beyond what o + t d can promise.
 * catches: b^2 - ac losing the 1e-8 r^2 a small sphere is made of; the far root returned
 *   instead of the near one; p taken from the ray equation without the projection. */
static void test_sphere_small(struct check *t)
{
    const double radius = 1e-4;
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 5, 0);
    int ok = 1;
    for (int k = 0; k < 2000; k++) {
        struct vec3 c = random_point(&r, 1.0);
        struct vec3 o = vec3_madd(c, random_unit(&r), radius * pow(10.0, uniform(&r, 1.0, 5.0)));
        struct vec3 aim = vec3_madd(c, random_unit(&r), radius * uniform(&r, 0.0, 0.999));
        struct ray ray = make_ray(o, vec3_normalize(vec3_sub(aim, o)));
        struct sphere s = sphere_make(c, radius, 0, 0);
        struct hit hit;
        ok &= sphere_intersect(&s, ray, INFINITY, &hit);
        struct vec3 p = ray_at(ray, hit.t);
        ok &= fabs(vec3_length(vec3_sub(p, c)) - radius) <= 1e-9 * radius;
        ok &= vec3_dot(vec3_sub(p, c), ray.dir) <= 0;
        sphere_shade(&s, ray, &hit);
        ok &= fabs(vec3_length(vec3_sub(hit.p, c)) - radius) <= 1e-11 * radius;
    }
    CHECK(t, ok);
}

/* truth: a line at distance f r from the centre meets the sphere iff f <= 1. Rays start 1e4 r
 *   away, at offsets f = 1 - 1e-9 ... 0 (must hit) and f = 1 + 1e-6 (must miss), for
 *   spheres of radius 1e-4, 1 and 1e5 (the last far from the origin).
 * tolerance: the offset is exact to ~1e-16 * 1e4 r = 1e-12 r, far below 1e-9 r.
 * catches: a discriminant b^2 - ac (error ~1e-16 * (1e4 r)^2 = 1e-8 r^2 > the 2e-9 r^2 that
 *   decides the grazing hit), sqrt of a negative discriminant, an inflated discriminant. */
static void test_sphere_grazing(struct check *t)
{
    static const double radii[] = {1e-4, 1.0, 1e5};
    static const double offsets[] = {0.0, 0.5, 0.99, 1 - 1e-3, 1 - 1e-6, 1 - 1e-9, 1 + 1e-6};
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 6, 0);
    int ok = 1;
    for (int k = 0; k < 3000; k++) {
        double radius = radii[k % 3], f = offsets[(k / 3) % 7];
        struct vec3 c = vec3_scale(random_point(&r, 1.0), radius < 1e3 ? 1.0 : 1e5);
        struct vec3 d = random_unit(&r), side, unused;
        vec3_frame(d, &side, &unused);
        struct vec3 o = vec3_madd(vec3_madd(c, side, f * radius), d, -1e4 * radius);
        struct sphere s = sphere_make(c, radius, 0, 0);
        struct hit hit;
        ok &= sphere_intersect(&s, make_ray(o, d), INFINITY, &hit) == (f <= 1.0);
    }
    CHECK(t, ok);
}

/* truth: the sphere's surface parameters at its six axis points (sphere.h: y up, u from
 *   atan2(z, x), v = theta / pi), its outward normal there, and the same outward normal
 *   when the ray starts inside.
 * tolerance: 1e-15; these points come out exact or within an ulp.
 * catches: u and v swapped, z-up parameters, phi not wrapped into [0, 2 pi), the normal
 *   flipped towards the ray from inside. */
static void test_sphere_uv_and_normal(struct check *t)
{
    static const struct {
        struct vec3 axis;
        double u, v;
    } points[] = {{{1, 0, 0}, 0.0, 0.5},  {{0, 0, 1}, 0.25, 0.5}, {{-1, 0, 0}, 0.5, 0.5},
                  {{0, 0, -1}, 0.75, 0.5}, {{0, 1, 0}, 0.0, 0.0},  {{0, -1, 0}, 0.0, 1.0}};
    struct geometry *g = geometry_create();
    geometry_add_sphere(g, vec3(1, 2, 3), 2.0, 0);
    geometry_build(g);
    for (int k = 0; k < 6; k++) {
        struct vec3 a = points[k].axis;
        struct hit hit;
        CHECK(t, geometry_intersect(g, make_ray(vec3_madd(vec3(1, 2, 3), a, 5), vec3_neg(a)),
                                    INFINITY, &hit));
        CHECK_CLOSE(t, hit.v, points[k].v, 1e-15);
        if (k < 4)   /* u is undefined at the poles */
            CHECK_CLOSE(t, hit.u, points[k].u, 1e-15);
        CHECK(t, vec3_length2(vec3_sub(hit.ng, a)) < 1e-30 && hit.t == 3.0);
        CHECK(t, geometry_intersect(g, make_ray(vec3(1, 2, 3), a), INFINITY, &hit));
        CHECK(t, vec3_length2(vec3_sub(hit.ng, a)) < 1e-30 && hit.t == 2.0);
    }
    geometry_free(g);
}

/* ---- closed meshes for the watertightness test ---- */

/* A closed triangle mesh; vertices are recomputed from integer indices wherever they recur,
 * so a vertex shared by several triangles is bitwise the same in each. */
struct mesh {
    struct vec3 (*tri)[3];   /* owned */
    size_t n_tri;
    struct vec3 centre;      /* inside, and every ray from it leaves through the mesh */
};

static void mesh_add(struct mesh *m, struct vec3 a, struct vec3 b, struct vec3 c)
{
    m->tri[m->n_tri][0] = a;
    m->tri[m->n_tri][1] = b;
    m->tri[m->n_tri][2] = c;
    m->n_tri++;
}

#define LAT_RINGS 16   /* latitude bands of the sphere mesh  */
#define LON_SEGMENTS 24 /* longitude segments                 */
#define CUBE_CELLS 4   /* cells per cube edge: steps of 1/2, so corner sums are exact */

/* Vertex (i, j) of a latitude-longitude sphere of radius 1: i = 0 and LAT_RINGS are the
 * poles, j wraps around. */
static struct vec3 sphere_vertex(struct vec3 centre, int i, int j)
{
    if (i == 0 || i == LAT_RINGS)
        return vec3_add(centre, vec3(0.0, i == 0 ? 1.0 : -1.0, 0.0));
    double theta = PI * i / LAT_RINGS, phi = 2.0 * PI * (j % LON_SEGMENTS) / LON_SEGMENTS;
    return vec3_add(centre, vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi)));
}

static struct mesh sphere_mesh(struct vec3 centre)
{
    struct mesh m = {NULL, 0, centre};
    m.tri = xmalloc(2 * LAT_RINGS * LON_SEGMENTS, sizeof *m.tri, "test mesh");
    for (int i = 0; i < LAT_RINGS; i++) {
        for (int j = 0; j < LON_SEGMENTS; j++) {
            struct vec3 a = sphere_vertex(centre, i, j), b = sphere_vertex(centre, i, j + 1);
            struct vec3 c = sphere_vertex(centre, i + 1, j);
            struct vec3 d = sphere_vertex(centre, i + 1, j + 1);
            if (i > 0)
                mesh_add(&m, a, b, c);
            if (i + 1 < LAT_RINGS)
                mesh_add(&m, b, d, c);
        }
    }
    return m;
}

/* Lattice point (i, j, k), 0..CUBE_CELLS each, of the cube [-1, 1]^3 + centre. */
static struct vec3 cube_vertex(struct vec3 centre, int i, int j, int k)
{
    struct vec3 p = vec3(i, j, k);
    return vec3_add(centre, vec3_sub(vec3_scale(p, 2.0 / CUBE_CELLS), vec3(1.0, 1.0, 1.0)));
}

/* Lattice point (u, v) of cube face f: axis f % 3 held at 0 (f < 3) or CUBE_CELLS. */
static struct vec3 face_vertex(struct vec3 centre, int f, int u, int v)
{
    int fixed = f < 3 ? 0 : CUBE_CELLS;
    switch (f % 3) {
    case 0:
        return cube_vertex(centre, fixed, u, v);
    case 1:
        return cube_vertex(centre, v, fixed, u);
    default:
        return cube_vertex(centre, u, v, fixed);
    }
}

static struct mesh cube_mesh(struct vec3 centre)
{
    struct mesh m = {NULL, 0, centre};
    m.tri = xmalloc(12 * CUBE_CELLS * CUBE_CELLS, sizeof *m.tri, "test mesh");
    for (int f = 0; f < 6; f++) {
        for (int u = 0; u < CUBE_CELLS; u++) {
            for (int v = 0; v < CUBE_CELLS; v++) {
                struct vec3 a = face_vertex(centre, f, u, v), b = face_vertex(centre, f, u + 1, v);
                struct vec3 c = face_vertex(centre, f, u, v + 1);
                struct vec3 d = face_vertex(centre, f, u + 1, v + 1);
                mesh_add(&m, a, b, d);
                mesh_add(&m, a, d, c);
            }
        }
    }
    return m;
}

/* A point of the mesh: a vertex, an edge's midpoint, a random point of an edge or of a
 * triangle (choice 0..3). */
static struct vec3 mesh_point(const struct mesh *m, struct rng *r, int choice)
{
    const struct vec3 *tri = m->tri[rng_next(r) % m->n_tri];
    int i = (int)(rng_next(r) % 3);
    struct vec3 a = tri[i], b = tri[(i + 1) % 3], c = tri[(i + 2) % 3];
    double u = uniform(r, 0.0, 1.0), v = uniform(r, 0.0, 1.0 - u);
    switch (choice) {
    case 0:
        return a;
    case 1:
        return vec3_scale(vec3_add(a, b), 0.5);
    case 2:
        return vec3_madd(a, vec3_sub(b, a), u);
    default:
        return vec3_madd(vec3_madd(a, vec3_sub(b, a), u), vec3_sub(c, a), v);
    }
}

/* Rays that must meet the closed mesh: from inside in any direction or aimed at a mesh
 * point; from outside aimed at a mesh point, along roughly the inward radial direction so
 * that the ray enters the (convex) body there. Returns the number that escaped. */
static long count_leaks(const struct geometry *g, const struct mesh *m, uint64_t key, long n)
{
    long leaks = 0;
    for (long k = 0; k < n; k++) {
        struct rng r = rng_stream(TEST_SEED, STREAM_TEST, key, (uint64_t)k);
        struct vec3 target = mesh_point(m, &r, (int)(k % 4));
        struct vec3 o;
        if (k % 2 == 0) {
            o = vec3_madd(m->centre, random_unit(&r), uniform(&r, 0.0, 0.5));
            if (k % 8 == 0)
                target = vec3_add(o, random_unit(&r));
        } else {
            struct vec3 out = vec3_normalize(vec3_sub(target, m->centre));
            o = vec3_madd(vec3_madd(target, out, uniform(&r, 0.1, 3.0)), random_unit(&r), 0.01);
        }
        struct hit hit;
        leaks += !geometry_intersect(g, make_ray(o, vec3_sub(target, o)), INFINITY, &hit);
    }
    return leaks;
}

/* truth: a closed mesh has no holes, so every ray from inside meets it, and so does every
 *   ray from outside aimed into the body through one of its points; rays aimed exactly at
 *   vertices and edges are the ones that find cracks. Three closed meshes off the origin
 *   (where the shear rounds coordinates): a lat-long sphere of 720 triangles, a cube of 192
 *   triangles, and the same cube as 96 quads (their fourth corners p0 + e1 + e2 exact).
 * tolerance: zero leaks in 1,000,002 rays.
 * catches: edge tests with strict inequalities (a ray on an edge hits neither triangle),
 *   edge functions computed per triangle in an order that differs between neighbours, a
 *   zero edge function taken as a miss, a BVH box test losing rays through box corners. */
static void test_watertight_meshes(struct check *t)
{
    struct mesh meshes[2];
    meshes[0] = sphere_mesh(vec3(10.3, -4.7, 2.9));
    meshes[1] = cube_mesh(vec3(-3.25, 7.5, 0.75));
    for (int k = 0; k < 3; k++) {
        const struct mesh *m = &meshes[k < 2 ? k : 1];
        struct geometry *g = geometry_create();
        for (size_t i = 0; i < m->n_tri; i++) {
            const struct vec3 *a = m->tri[i];
            if (k < 2)
                geometry_add_triangle(g, a, NULL, 0);
            else if (i % 2 == 0)   /* cube_mesh() made (a, b, d), (a, d, c) */
                geometry_add_quad(g, a[0], vec3_sub(a[1], a[0]), vec3_sub(m->tri[i + 1][2], a[0]),
                                  0);
        }
        geometry_build(g);
        CHECK(t, count_leaks(g, m, 100 + (uint64_t)k, 333334) == 0);
        geometry_free(g);
    }
    xfree(meshes[0].tri);
    xfree(meshes[1].tri);
}

/* truth: the quad's own parametrisation: a ray aimed at p0 + s e1 + t e2 reports uv = (s, t)
 *   and p there; ng = unit(e1 x e2) from either side; aims just outside [0, 1]^2 miss.
 *   (Aims exactly at an edge may go either way: the aim itself is rounded. Edges are the
 *   watertightness test's business, between neighbours.)
 * tolerance: 1e-10 on s, t (relative to the quad) and on p (relative to |p|): the sheared
 *   coordinates are differences of numbers up to ~40 for quads as small as 0.1, and rays
 *   meet them at down to ~10 degrees, so rounding reaches ~1e-13; 1e-10 leaves a margin.
 *   The misses are 1e-3 outside, far beyond it.
 * catches: s and t swapped, an edge function pair mismatched (wrong corner order), ng
 *   flipped towards the ray, the bilinear depth mixing corners. */
static void test_quad_uv(struct check *t)
{
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 7, 0);
    int ok = 1;
    for (int k = 0; k < 3000; k++) {
        struct vec3 p0 = random_point(&r, 20.0);
        struct vec3 e1 = vec3_scale(random_unit(&r), uniform(&r, 0.1, 10.0));
        struct vec3 e2 = vec3_scale(random_unit(&r), uniform(&r, 0.1, 10.0));
        struct vec3 n = unit_normal(vec3_cross(e1, e2));
        if (vec3_length(vec3_cross(vec3_normalize(e1), vec3_normalize(e2))) < 0.2)
            continue;   /* nearly parallel edges: a sliver, where s and t are ill-conditioned */
        struct quad q = quad_make(p0, e1, e2, 3, 0);
        double s = uniform(&r, 0.0, 1.0), u = uniform(&r, 0.0, 1.0);
        struct vec3 target = vec3_madd(vec3_madd(p0, e1, s), e2, u);
        struct vec3 from = tilted(vec3_scale(n, k % 2 ? 1.0 : -1.0), uniform(&r, 0.0, 1.4), &r);
        struct vec3 o = vec3_madd(target, from, uniform(&r, 0.5, 20.0));
        struct ray ray = make_ray(o, vec3_sub(target, o));
        struct sheared_ray sr = shear_ray(ray);
        struct hit hit;
        ok &= quad_intersect(&q, &sr, INFINITY, &hit);
        quad_shade(&q, &hit);
        ok &= fabs(hit.u - s) <= 1e-10 && fabs(hit.v - u) <= 1e-10 && hit.material == 3;
        ok &= vec3_length(vec3_sub(hit.p, target)) <= 1e-10 * fmax(1.0, vec3_length(target));
        ok &= vec3_length(vec3_sub(hit.ng, n)) <= 1e-15;
        ok &= vec3_length(vec3_sub(hit.ns, n)) <= 1e-15;
        double beyond = k % 2 ? 1.0 + 1e-3 : -1e-3;   /* just past one of the four edges */
        struct vec3 outside = k % 4 < 2 ? vec3_madd(vec3_madd(p0, e1, beyond), e2, u)
                                        : vec3_madd(vec3_madd(p0, e1, s), e2, beyond);
        struct sheared_ray miss = shear_ray(make_ray(o, vec3_sub(outside, o)));
        ok &= !quad_intersect(&q, &miss, INFINITY, &hit);
    }
    CHECK(t, ok);
}

/* truth: triangle_shade()'s contract (triangle.h): ns = normalize(b0 n0 + b1 n1 + b2 n2) turned to
 *   ng's side, ng = unit((v1 - v0) x (v2 - v0)) from either side; where the blend vanishes,
 *   ns = ng; without vertex normals ns = ng.
 * tolerance: 1e-9: the barycentrics carry ~1e-13 of rounding and the blend is kept at
 *   length >= 0.1, so ns moves by < 1e-12.
 * catches: barycentrics assigned to the wrong vertices, ns not renormalised, ns left on the
 *   back side, ng flipped towards the ray. */
static void test_triangle_normals(struct check *t)
{
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 8, 0);
    int ok = 1;
    for (int k = 0; k < 3000; k++) {
        struct vec3 v[3] = {random_point(&r, 5.0), random_point(&r, 5.0), random_point(&r, 5.0)};
        struct vec3 n[3] = {random_unit(&r), random_unit(&r), random_unit(&r)};
        struct triangle tri = triangle_make(v, 0, 0, 0);
        struct vec3 ng = unit_normal(vec3_cross(vec3_sub(v[1], v[0]), vec3_sub(v[2], v[0])));
        double b1 = uniform(&r, 0.05, 0.9), b2 = uniform(&r, 0.05, 0.95 - b1), b0 = 1 - b1 - b2;
        struct vec3 blend = vec3_madd(vec3_madd(vec3_scale(n[0], b0), n[1], b1), n[2], b2);
        if (vec3_length(blend) < 0.1 || triangle_is_degenerate(&tri))
            continue;
        struct vec3 ns = vec3_normalize(blend);
        ns = vec3_dot(ns, ng) < 0 ? vec3_neg(ns) : ns;
        struct vec3 target = vec3_madd(vec3_madd(vec3_scale(v[0], b0), v[1], b1), v[2], b2);
        struct vec3 o = vec3_madd(target, random_unit(&r), uniform(&r, 1.0, 10.0));
        struct ray ray = make_ray(o, vec3_sub(target, o));
        struct sheared_ray sr = shear_ray(ray);
        struct hit hit;
        if (!triangle_intersect(&tri, &sr, INFINITY, &hit))
            continue;   /* a ray nearly in the triangle's plane: not this test's business */
        triangle_shade(&tri, n, &hit);
        ok &= vec3_length(vec3_sub(hit.ns, ns)) <= 1e-9;
        ok &= vec3_length(vec3_sub(hit.ng, ng)) <= 1e-15;
        triangle_shade(&tri, NULL, &hit);
        ok &= vec3_length(vec3_sub(hit.ns, ng)) <= 1e-15;
    }
    struct vec3 v[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    struct vec3 cancel[3] = {{1, 0, 0}, {-1, 0, 0}, {0, 0, 1}};
    struct triangle tri = triangle_make(v, 0, 0, 0);
    struct hit hit;
    hit.u = 0.5;   /* b0 = b1 = 1/2: n0 and n1 cancel */
    hit.v = 0.0;
    triangle_shade(&tri, cancel, &hit);
    ok &= hit.ns.z == 1.0 && hit.ng.z == 1.0;
    CHECK(t, ok);
}

/* truth: bvh_check() (bvh.h invariants (1)-(4)) holds for trees over 0, 1, 2, 4, 5 and 1000
 *   random boxes, and fails once the tree is damaged: an item listed twice, a child box
 *   poking out of its parent, an item outside its leaf, the wrong item count.
 * tolerance: none.
 * catches: a checker that cannot fail (then the build tests above prove nothing), and
 *   builds that break the invariants at the small sizes. */
static void test_bvh_check_detects_damage(struct check *t)
{
    static const size_t sizes[] = {0, 1, 2, 4, 5, 1000};
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 9, 0);
    struct aabb *bounds = xmalloc(1000, sizeof *bounds, "test bounds");
    for (size_t i = 0; i < 1000; i++) {
        bounds[i].lo = random_point(&r, 10.0);
        bounds[i].hi = vec3_madd(bounds[i].lo, vec3(1, 1, 1), random_size(&r));
    }
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        struct bvh *bvh = bvh_build(bounds, sizes[s]);
        CHECK(t, bvh_check(bvh, bounds, sizes[s]));
        CHECK(t, sizes[s] == 0 || !bvh_check(bvh, bounds, sizes[s] - 1));
        bvh_free(bvh);
    }
    struct bvh *bvh = bvh_build(bounds, 1000);
    struct bvh_node *root = &bvh->nodes[0], *child = &bvh->nodes[root->offset];
    uint32_t item = bvh->items[1];
    bvh->items[1] = bvh->items[0];
    CHECK(t, !bvh_check(bvh, bounds, 1000));
    bvh->items[1] = item;
    float lo = child->box[0];
    child->box[0] = root->box[0] - 1.0f;
    CHECK(t, !bvh_check(bvh, bounds, 1000));
    child->box[0] = lo;
    struct aabb moved = bounds[bvh->items[0]];
    bounds[bvh->items[0]].hi.x = 1e6;
    CHECK(t, !bvh_check(bvh, bounds, 1000));
    bounds[bvh->items[0]] = moved;
    CHECK(t, bvh_check(bvh, bounds, 1000));
    bvh_free(bvh);
    bvh_free(NULL);
    xfree(bounds);
}

/* truth: pbrt's geometric test: a ray leaving a surface point, offset by offset_origin() to
 *   the side it leaves on, never meets that primitive again, since a plane, and a sphere
 *   left outward, cannot be met twice. Scenes span sizes 1e-3 .. 10 at distances to 30.
 * tolerance: none: any re-hit fails.
 * catches: hit points off the surface by more than RAY_OFFSET_REL allows (p from a lossy
 *   t, no projection onto the sphere), ng on the wrong side. */
static void test_spawned_rays_leave_their_surface(struct check *t)
{
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 10, 0);
    struct brute b;
    brute_init(&b);
    for (int i = 0; i < 3000; i++)
        CHECK(t, add_random_primitive(&b, &r));
    geometry_build(b.g);
    int ok = 1, n_spawned = 0;
    for (int k = 0; k < 20000; k++) {
        double tmax;
        struct ray ray = random_ray(&r, &tmax);
        struct hit hit;
        if (!geometry_intersect(b.g, ray, INFINITY, &hit))
            continue;
        struct vec3 n = vec3_dot(hit.ng, ray.dir) > 0 ? vec3_neg(hit.ng) : hit.ng;
        int kind = b.prims[hit.prim].kind;
        if ((kind == BRUTE_SPHERE || kind == BRUTE_BALL) && n.x != hit.ng.x)
            continue;   /* inside a sphere: it may be met again */
        struct vec3 d = random_unit(&r);
        d = vec3_dot(d, n) < 0 ? vec3_neg(d) : d;
        struct hit next;
        struct ray spawned = make_ray(offset_origin(hit.p, n), d);
        ok &= !geometry_intersect(b.g, spawned, INFINITY, &next) || next.prim != hit.prim;
        n_spawned++;
    }
    CHECK(t, ok && n_spawned > 1000);
    brute_free(&b);
}

void test_geom(struct check *t)
{
    RUN_TEST(t, test_edge_function_exact_sign);
    RUN_TEST(t, test_empty_and_single_primitives);
    RUN_TEST(t, test_rebuild_after_more_adds);
    RUN_TEST(t, test_bvh_matches_brute_force);
    RUN_TEST(t, test_primitive_bounds_and_material);
    RUN_TEST(t, test_bvh_hard_cases);
    RUN_TEST(t, test_bvh_check_detects_damage);
    RUN_TEST(t, test_degenerate_primitives);
    RUN_TEST(t, test_sphere_far_wall);
    RUN_TEST(t, test_sphere_small);
    RUN_TEST(t, test_sphere_grazing);
    RUN_TEST(t, test_sphere_uv_and_normal);
    RUN_TEST(t, test_quad_uv);
    RUN_TEST(t, test_triangle_normals);
    RUN_TEST(t, test_watertight_meshes);
    RUN_TEST(t, test_spawned_rays_leave_their_surface);
}
