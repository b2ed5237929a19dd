/*
 * tests/test_geom.c -- the geometry room: the BVH over spheres, triangles, quads and
 * shapes, against brute force.
 *
 * The BVH is checked against brute force: a second copy of every primitive, made with the
 * same *_make() calls, intersected one by one with the same functions, so BVH and brute
 * force must agree exactly (they compute the same doubles); any difference is a primitive
 * the traversal lost or a record geometry.c mixed up. Also the BVH's checker, rebuilds
 * after more adds, and rays spawned off the surfaces found. The primitives themselves are
 * checked against closed forms in test_geom_primitives.c. Randomness: STREAM_TEST, keyed
 * by case and index (geom_helpers.h).
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
#include "geom_helpers.h"
#include "tests.h"

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
    RUN_TEST(t, test_rebuild_after_more_adds);
    RUN_TEST(t, test_bvh_matches_brute_force);
    RUN_TEST(t, test_primitive_bounds_and_material);
    RUN_TEST(t, test_bvh_hard_cases);
    RUN_TEST(t, test_bvh_check_detects_damage);
    RUN_TEST(t, test_spawned_rays_leave_their_surface);
}
