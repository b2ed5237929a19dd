/*
 * tests/test_geom_primitives.c -- the geometry room's primitives: spheres, triangles and
 * quads, alone and in small geometries, against closed forms and geometric truths.
 *
 * Truths: exact arithmetic for the triangle's edge function; closed forms for a single
 * primitive of each kind and for primitives without area; the smallpt wall, small and
 * grazing spheres, uv and normals at known points; watertight closed meshes, which every
 * ray from inside meets. The BVH over many primitives is test_geom.c's. Randomness:
 * STREAM_TEST, keyed by case and index (geom_helpers.h).
 */
#include <math.h>
#include <stdint.h>

#include "../src/base/alloc.h"
#include "../src/base/rng.h"
#include "../src/geom/geometry.h"
#include "../src/geom/quad.h"
#include "../src/geom/sphere.h"
#include "../src/geom/triangle.h"
#include "geom_helpers.h"
#include "tests.h"

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

void test_geom_primitives(struct check *t)
{
    RUN_TEST(t, test_edge_function_exact_sign);
    RUN_TEST(t, test_empty_and_single_primitives);
    RUN_TEST(t, test_degenerate_primitives);
    RUN_TEST(t, test_sphere_far_wall);
    RUN_TEST(t, test_sphere_small);
    RUN_TEST(t, test_sphere_grazing);
    RUN_TEST(t, test_sphere_uv_and_normal);
    RUN_TEST(t, test_quad_uv);
    RUN_TEST(t, test_triangle_normals);
    RUN_TEST(t, test_watertight_meshes);
}
