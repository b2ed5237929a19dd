/*
 * tests/test_bvh.c -- the wide BVH's float box test, its checker, and the mesh of shared
 * points (test_geom.c holds the primitives and the brute-force comparisons of everyday
 * scenes).
 *
 * The box test runs in float on boxes rounded outward, with the ray's origin and 1/d
 * rounded in the directions that keep it conservative (bvh.c). Where float's spacing is
 * as large as the primitives, and rays start a hair off a surface, a test rounded to the
 * nearest float instead loses hits; the brute force here, every primitive's own test in
 * double, finds them. Randomness: STREAM_TEST, keyed by case and index.
 */
#include <math.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/base/rng.h"
#include "../src/geom/bvh.h"
#include "../src/geom/geometry.h"
#include "../src/geom/mesh.h"
#include "../src/geom/triangle.h"
#include "tests.h"

#define TEST_SEED 2025

static double uniform(struct rng *r, double lo, double hi)
{
    return lo + (hi - lo) * rng_uniform(r);
}

static struct vec3 random_unit(struct rng *r)
{
    double z = uniform(r, -1.0, 1.0), phi = uniform(r, 0.0, 2.0 * PI);
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    return vec3(s * cos(phi), s * sin(phi), z);
}

/* A sheet of n x n small triangle pairs, 2 cells wide each, around centre: cell (i, k)
 * spans `cell` along x and z, its corners lifted by random heights up to `cell`; corners
 * are recomputed from (i, k) wherever they recur, so neighbours share them bit for bit. */
struct sheet {
    struct vec3 centre;
    double cell;
    int n;
    double *lift;   /* owned: (n + 1)^2 heights */
};

static struct vec3 sheet_point(const struct sheet *s, int i, int k)
{
    return vec3_add(s->centre, vec3(s->cell * i, s->lift[k * (s->n + 1) + i], s->cell * k));
}

static void sheet_triangle(const struct sheet *s, int i, int k, int upper, struct vec3 v[3])
{
    struct vec3 a = sheet_point(s, i, k), b = sheet_point(s, i, k + 1);
    struct vec3 c = sheet_point(s, i + 1, k), d = sheet_point(s, i + 1, k + 1);
    v[0] = upper ? c : a;
    v[1] = b;
    v[2] = upper ? d : c;
}

/* The closest hit over the sheet's triangles one by one, with triangle.h's own test. */
static int sheet_brute(const struct sheet *s, struct ray ray, double tmax, struct hit *hit)
{
    struct sheared_ray sr = shear_ray(ray);
    int found = 0;
    for (int k = 0; k < s->n; k++)
        for (int i = 0; i < s->n; i++)
            for (int upper = 0; upper < 2; upper++) {
                struct vec3 v[3];
                sheet_triangle(s, i, k, upper, v);
                struct triangle tri = triangle_make(v, -1, 0, 0);
                if (triangle_intersect(&tri, &sr, tmax, hit)) {
                    tmax = hit->t;
                    found = 1;
                }
            }
    return found;
}

/* truth: brute force, every triangle's own test in double (same functions, so exact
 *   agreement on t).
 * cases: sheets of triangles 1e-3 .. 1 wide at 1e3 .. 1e7 from the origin, where float's
 *   spacing (up to 1) exceeds a triangle, and 1e-42 .. 1e-36 wide at the origin, where the
 *   box test's products underflow into float's subnormals; rays spawned from hit points by
 *   offset_origin() (a hair off the surface, inside boxes a few floats thick), in random
 *   directions and grazing ones; rays from afar aimed at corners and edges.
 * tolerance: none; t must be bitwise the brute force's, and geometry_occluded() must agree.
 * catches: the origin and 1/d rounded to the nearest float instead of outward (tried: it
 *   fails), or rounded the wrong way. (Boxes rounded to nearest are bvh_check()'s to find.)
 */
static void test_box_test_where_floats_are_coarse(struct check *t)
{
    static const double offsets[] = {1e3, 1e5, 3e6, 1e7, 0.0};
    static const double cells[] = {1e-3, 0.05, 1.0};
    static const double tiny_cells[] = {1e-42, 1e-39, 1e-36};
    int agree = 1, n_rays = 0, n_hits = 0;
    for (int c = 0; c < 15; c++) {
        struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 1, (uint64_t)c);
        struct sheet s;
        s.n = 12;
        s.cell = c < 12 ? cells[c % 3] : tiny_cells[c % 3];
        double far = offsets[c / 3];
        s.centre = vec3(far, -far * uniform(&r, 0.5, 1.0), far * uniform(&r, -1.0, 1.0));
        s.lift = xmalloc((size_t)(s.n + 1) * (s.n + 1), sizeof *s.lift, "test sheet");
        for (int i = 0; i < (s.n + 1) * (s.n + 1); i++)
            s.lift[i] = s.cell * uniform(&r, 0.0, 1.0);
        struct geometry *g = geometry_create();
        for (int k = 0; k < s.n; k++)
            for (int i = 0; i < s.n; i++)
                for (int upper = 0; upper < 2; upper++) {
                    struct vec3 v[3];
                    sheet_triangle(&s, i, k, upper, v);
                    geometry_add_triangle(g, v, NULL, 0);
                }
        geometry_build(g);
        struct vec3 middle = sheet_point(&s, s.n / 2, s.n / 2);
        for (int q = 0; q < 400; q++) {
            /* from above, aimed at a corner, an edge's midpoint or a cell */
            int i = (int)(rng_next(&r) % (uint64_t)s.n), k = (int)(rng_next(&r) % (uint64_t)s.n);
            struct vec3 aim = sheet_point(&s, i, k);
            if (q % 3 == 1)
                aim = vec3_scale(vec3_add(aim, sheet_point(&s, i + 1, k + 1)), 0.5);
            else if (q % 3 == 2)
                aim = vec3_add(aim, vec3(uniform(&r, 0, s.cell), 0, uniform(&r, 0, s.cell)));
            struct vec3 from = vec3_add(middle, vec3_scale(random_unit(&r), s.cell * s.n * 3));
            from.y = middle.y + fabs(from.y - middle.y) + s.cell;
            /* length 1000 (t is in units of it): the tiny sheets' distances tiny too */
            struct vec3 towards = vec3_sub(aim, from);
            struct ray ray = make_ray(from, vec3_scale(towards, 1e3 / vec3_length(towards)));
            struct hit h, b;
            int found = geometry_intersect(g, ray, INFINITY, &h);
            int expected = sheet_brute(&s, ray, INFINITY, &b);
            agree &= found == expected && (!found || h.t == b.t);
            n_rays++;
            if (!found)
                continue;
            n_hits++;
            /* spawned from the hit, off the side it came from, in a random or grazing
             * direction; finite tmax for some, as shadow rays have */
            struct vec3 n = vec3_dot(h.ng, ray.dir) > 0 ? vec3_neg(h.ng) : h.ng;
            struct vec3 d = random_unit(&r);
            d = vec3_dot(d, n) < 0 ? vec3_neg(d) : d;
            if (q % 4 == 0)
                d = vec3_normalize(vec3_add(d, vec3_scale(n, -0.999 * vec3_dot(d, n))));
            struct ray spawned = make_ray(offset_origin(h.p, n), d);
            double tmax = q % 2 ? INFINITY : s.cell * uniform(&r, 0.1, 5.0);
            found = geometry_intersect(g, spawned, tmax, &h);
            expected = sheet_brute(&s, spawned, tmax, &b);
            agree &= found == expected && (!found || h.t == b.t);
            agree &= geometry_occluded(g, spawned, tmax) == expected;
            n_rays++;
        }
        geometry_free(g);
        xfree(s.lift);
    }
    CHECK(t, agree);
    CHECK(t, n_rays > 6000 && n_hits > 2000);   /* the cases did what they meant to */
}

/* A BVH over n random boxes, for damaging. */
static struct aabb *random_boxes(size_t n, uint64_t key)
{
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, key, 0);
    struct aabb *bounds = xmalloc(n, sizeof *bounds, "test bounds");
    for (size_t i = 0; i < n; i++) {
        bounds[i].lo = vec3(uniform(&r, -10, 10), uniform(&r, -10, 10), uniform(&r, -10, 10));
        bounds[i].hi = vec3_add(bounds[i].lo, vec3_scale(vec3(1, 1, 1), uniform(&r, 0.01, 2)));
    }
    return bounds;
}

/* The first node with an empty slot, and one with a leaf slot (index into nodes[]). */
static size_t node_where(const struct bvh *bvh, int want_empty)
{
    for (size_t i = 0; i < bvh->n_nodes; i++) {
        const struct bvh_node *node = &bvh->nodes[i];
        if (want_empty ? node->n_slots < BVH_WIDTH : node->n_nodes < node->n_slots)
            return i;
    }
    return 0;
}

/* truth: bvh.h's invariants (1)-(4) of the wide node, which bvh_check() must find broken
 *   when a tree is damaged in one field: an empty slot given a box, an interior slot given
 *   an item count, a leaf's count set to 0, a leaf's range moved onto another leaf's, a
 *   node's child offset pointing at itself, a node's slot count dropped below two. Each
 *   damage is undone before the next, and the repaired tree passes again.
 * tolerance: none.
 * catches: a checker blind to the fields the wide walk reads (test_geom.c's damage test
 *   covers duplicated items, boxes poking out and item boxes outside their leaf). */
static void test_wide_node_damage(struct check *t)
{
    const size_t n = 3000;
    struct aabb *bounds = random_boxes(n, 2);
    struct bvh *bvh = bvh_build(bounds, n);
    REQUIRE(t, bvh_check(bvh, bounds, n) && bvh->n_nodes > 10);
    struct bvh_node *empty = &bvh->nodes[node_where(bvh, 1)];
    struct bvh_node *leafy = &bvh->nodes[node_where(bvh, 0)];
    struct bvh_node *root = &bvh->nodes[0];
    struct bvh_node saved;
    int e = empty->n_slots, l = leafy->n_nodes;
    REQUIRE(t, e < BVH_WIDTH && l < leafy->n_slots && root->n_nodes > 0);

    saved = *empty;   /* an empty slot that a ray could enter */
    empty->box[0 * BVH_WIDTH + e] = 0.0f;
    empty->box[3 * BVH_WIDTH + e] = 1.0f;
    CHECK(t, !bvh_check(bvh, bounds, n));
    *empty = saved;
    saved = *root;    /* an interior slot that claims items */
    root->count[0] = 1;
    CHECK(t, !bvh_check(bvh, bounds, n));
    *root = saved;
    saved = *leafy;   /* a leaf of no items */
    leafy->count[l] = 0;
    CHECK(t, !bvh_check(bvh, bounds, n));
    *leafy = saved;
    saved = *leafy;   /* a leaf's range moved: some items covered twice, others never */
    leafy->first[l] = leafy->first[l] > 0 ? leafy->first[l] - 1 : leafy->first[l] + 1;
    CHECK(t, !bvh_check(bvh, bounds, n));
    *leafy = saved;
    saved = *root;    /* a child offset pointing back at the node */
    root->offset = 0;
    CHECK(t, !bvh_check(bvh, bounds, n));
    *root = saved;
    struct bvh_node *child = &bvh->nodes[root->offset];
    saved = *child;   /* a node of a single slot below the root */
    child->n_slots = 1;
    child->n_nodes = child->n_nodes > 1 ? 1 : child->n_nodes;
    CHECK(t, !bvh_check(bvh, bounds, n));
    *child = saved;
    CHECK(t, bvh_check(bvh, bounds, n));
    bvh_free(bvh);
    xfree(bounds);
}

/* truth: counting by construction. A grid of g x g cells as two triangles each has
 *   (g + 1)^2 distinct points, which the mesh must store once each; every triangle's
 *   corners must come back bit for bit as given, before and after mesh_finish(); after it
 *   the first triangle's corners are points 0, 1, 2 (first use); +0 and -0 are different
 *   bit patterns and stay two points; adds after mesh_finish() find the old points again.
 * tolerance: none.
 * catches: a hash that misses equal points (more points than the grid has), one that
 *   merges different ones (a corner coming back changed), a renumbering that mixes points
 *   up, a table not rebuilt after mesh_finish() drops it. */
static void test_mesh_shares_points(struct check *t)
{
    const int g = 40;
    struct mesh m;
    mesh_init(&m);
    struct rng r = rng_stream(TEST_SEED, STREAM_TEST, 3, 0);
    double *h = xmalloc((size_t)(g + 1) * (g + 1), sizeof *h, "test heights");
    for (int i = 0; i < (g + 1) * (g + 1); i++)
        h[i] = uniform(&r, -1.0, 1.0);
    struct vec3 (*given)[3] = xmalloc((size_t)2 * g * g, sizeof *given, "test triangles");
    size_t n = 0;
    for (int k = 0; k < g; k++)
        for (int i = 0; i < g; i++) {
            struct vec3 a = vec3(i, h[k * (g + 1) + i], k);
            struct vec3 b = vec3(i, h[(k + 1) * (g + 1) + i], k + 1);
            struct vec3 c = vec3(i + 1, h[k * (g + 1) + i + 1], k);
            struct vec3 d = vec3(i + 1, h[(k + 1) * (g + 1) + i + 1], k + 1);
            struct vec3 lower[3] = {a, b, c}, upper[3] = {c, b, d};
            memcpy(given[n], lower, sizeof lower);
            CHECK(t, mesh_add(&m, lower, -1, 0, (int)n) == n);
            n++;
            memcpy(given[n], upper, sizeof upper);
            CHECK(t, mesh_add(&m, upper, -1, 0, (int)n) == n);
            n++;
        }
    CHECK(t, m.n_points == (size_t)(g + 1) * (g + 1) && m.n_triangles == n);
    int same = 1;
    for (int pass = 0; pass < 2; pass++) {
        for (size_t j = 0; j < n; j++) {
            struct vec3 v[3];
            mesh_corners(&m, &m.triangles[j], v);
            same &= memcmp(v, given[j], sizeof v) == 0 && m.triangles[j].id == (int)j;
        }
        mesh_finish(&m);
    }
    CHECK(t, same && m.table == NULL);
    CHECK(t, m.triangles[0].corner[0] == 0 && m.triangles[0].corner[1] == 1
                 && m.triangles[0].corner[2] == 2);
    struct vec3 zeros[3] = {{0.0, 0.5, 0.0}, {-0.0, 0.5, 0.0}, {0, 0, 0}};
    mesh_add(&m, given[0], -1, 0, (int)n);   /* old points only */
    CHECK(t, m.n_points == (size_t)(g + 1) * (g + 1));
    mesh_add(&m, zeros, -1, 0, (int)n + 1);  /* (0, .5, 0), (-0, .5, 0), and (0, 0, 0) */
    CHECK(t, m.n_points == (size_t)(g + 1) * (g + 1) + 3);
    struct vec3 back[3];
    mesh_corners(&m, &m.triangles[n + 1], back);
    CHECK(t, memcmp(back, zeros, sizeof back) == 0 && signbit(back[1].x) && !signbit(back[0].x));
    mesh_free(&m);
    xfree(given);
    xfree(h);
}

/* truth: arithmetic on the stored records: a height field of g x g cells holds its
 *   2 g^2 triangles in 24 bytes each and its (g + 1)^2 points in 24 bytes each, plus the
 *   BVH's nodes and the geometry's per-primitive references; the whole stays under 76
 *   bytes a triangle, which is terrain1m's 1,051,250 triangles in 80 MB.
 * tolerance: the bound itself; the grid is large enough (80,000 triangles) for the BVH's
 *   share to be terrain1m's.
 * catches: triangles stored with their own points again, capacities left doubled after the
 *   build, a BVH of many nodes with few slots used. */
static void test_mesh_memory_per_triangle(struct check *t)
{
    const int g = 200;
    struct geometry *geo = geometry_create();
    for (int k = 0; k < g; k++)
        for (int i = 0; i < g; i++) {
            double x = i, z = k;
            struct vec3 a = vec3(x, sin(x) * cos(z), z), b = vec3(x, sin(x) * cos(z + 1), z + 1);
            struct vec3 c = vec3(x + 1, sin(x + 1) * cos(z), z);
            struct vec3 d = vec3(x + 1, sin(x + 1) * cos(z + 1), z + 1);
            struct vec3 lower[3] = {a, b, c}, upper[3] = {c, b, d};
            geometry_add_triangle(geo, lower, NULL, 0);
            geometry_add_triangle(geo, upper, NULL, 0);
        }
    geometry_build(geo);
    double per_triangle = (double)geometry_bytes(geo) / (2.0 * g * g);
    CHECK(t, per_triangle < 76.0);
    CHECK(t, per_triangle > 24.0 + 12.0);   /* the records themselves: nothing left out */
    geometry_free(geo);
}

void test_bvh(struct check *t)
{
    RUN_TEST(t, test_box_test_where_floats_are_coarse);
    RUN_TEST(t, test_wide_node_damage);
    RUN_TEST(t, test_mesh_shares_points);
    RUN_TEST(t, test_mesh_memory_per_triangle);
}
