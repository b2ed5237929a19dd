/*
 * tests/test_shapes_heightfield.c -- the fractal heightfield (geom/heightfield.c) and the
 * gradient noise it is made of (geom/noise.c): the noise against its definition and
 * recorded values; the heightfield's layout, normals and parameters, a flat closed form,
 * watertightness, and its own triangles. The sphere flake is test_shapes.c's.
 *
 * The truths are the expansion: the same triangles as plain primitives, tested one by one
 * (brute force) or through geometry's BVH. Both sides run the shared triangle.c test on the
 * same doubles, so the procedural walk is what is under test: a pruned node, a wrong bound,
 * a cell skipped.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/base/rng.h"
#include "../src/geom/heightfield.h"
#include "../src/geom/noise.h"
#include "../src/geom/triangle.h"
#include "geom_helpers.h"
#include "shape_hits.h"
#include "tests.h"

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

void test_shapes_heightfield(struct check *t)
{
    RUN_TEST(t, test_noise);
    RUN_TEST(t, test_heightfield_structure);
    RUN_TEST(t, test_heightfield_shading_normals);
    RUN_TEST(t, test_heightfield_refuses_bad_parameters);
    RUN_TEST(t, test_heightfield_flat_closed_form);
    RUN_TEST(t, test_heightfield_is_watertight);
    RUN_TEST(t, test_heightfield_matches_brute_force);
    RUN_TEST(t, test_heightfield_matches_expansion);
}
