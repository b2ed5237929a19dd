/*
 * tests/test_import_geom.c -- the shapes the importers make: NFF's open cone (geom/cone.c)
 * and the ear clipping that cuts NFF and OBJ polygons into triangles (geom/polygon.c). The
 * readers themselves are test_import.c's.
 *
 * Truths: the cone's implicit equation sampled along each ray (brute force) and closed
 * forms for special rays; the shoelace area and point-in-polygon for triangulations of
 * hand-made, random and real polygons (a gear face of gears-s3, kept in tests/data/spd/).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/base/rng.h"
#include "../src/geom/cone.h"
#include "../src/geom/polygon.h"
#include "spd.h"
#include "tests.h"

/* ---- the cone ---------------------------------------------------------------------- */

/* The cone's implicit function g(P) = |q(P)| - r(s(P)) and P's axial coordinate s. */
struct cone_truth {
    struct vec3 base, axis; /* axis unit */
    double height, r_base, slope;
};

static struct cone_truth cone_truth(struct vec3 base, double r_base, struct vec3 apex,
                                    double r_apex)
{
    struct cone_truth c;
    c.base = base;
    c.height = vec3_length(vec3_sub(apex, base));
    c.axis = vec3_scale(vec3_sub(apex, base), 1.0 / c.height);
    c.r_base = fabs(r_base);
    c.slope = (fabs(r_apex) - fabs(r_base)) / c.height;
    return c;
}

static double axial(const struct cone_truth *c, struct vec3 p)
{
    return vec3_dot(vec3_sub(p, c->base), c->axis);
}

static double implicit(const struct cone_truth *c, struct vec3 p)
{
    double s = axial(c, p);
    struct vec3 q = vec3_madd(vec3_sub(p, c->base), c->axis, -s);
    return vec3_length(q) - (c->r_base + c->slope * s);
}

/* Whether the point at t on the ray is on the frustum's length, away from its rims by a
 * relative margin (near a rim a sample and a root may fall on different sides). */
static int well_inside(const struct cone_truth *c, struct ray ray, double t)
{
    double s = axial(c, ray_at(ray, t));
    return s > 1e-6 * c->height && s < (1 - 1e-6) * c->height;
}

/* The first sign change of g along the ray within [0, t_end] in N_STEPS samples, both ends
 * well inside the length: its left end, or INFINITY when there is none. */
#define N_STEPS 3000
static double first_crossing(const struct cone_truth *c, struct ray ray, double t_end)
{
    double step = t_end / N_STEPS, g0 = implicit(c, ray.origin);
    for (int i = 1; i <= N_STEPS; i++) {
        double g1 = implicit(c, ray_at(ray, i * step));
        if ((g0 < 0) != (g1 < 0) && well_inside(c, ray, (i - 1) * step) &&
            well_inside(c, ray, i * step))
            return (i - 1) * step;
        g0 = g1;
    }
    return INFINITY;
}

static double random_in(struct rng *rng, double lo, double hi)
{
    return lo + (hi - lo) * rng_uniform(rng);
}

static struct vec3 random_point(struct rng *rng, double extent)
{
    double x = random_in(rng, -extent, extent), y = random_in(rng, -extent, extent);
    return vec3(x, y, random_in(rng, -extent, extent));
}

/* Checks one reported hit: on the surface, within the length, normal perpendicular to the
 * surface's two tangents and on the front side, inside the bounds. */
static void check_cone_hit(struct check *t, const struct cone_truth *c, const struct hit *h,
                           struct aabb box, int inside)
{
    double scale = fmax(1.0, vec3_max_abs(h->p));
    CHECK(t, fabs(implicit(c, h->p)) <= 1e-9 * scale);
    double s = axial(c, h->p);
    CHECK(t, s >= -1e-9 * scale && s <= c->height + 1e-9 * scale);
    struct vec3 e = vec3_normalize(vec3_madd(vec3_sub(h->p, c->base), c->axis, -s));
    struct vec3 around = vec3_cross(c->axis, e), along = vec3_madd(c->axis, e, c->slope);
    CHECK(t, fabs(vec3_length(h->ng) - 1) <= 1e-12);
    CHECK(t, fabs(vec3_dot(h->ng, around)) <= 1e-9 && fabs(vec3_dot(h->ng, along)) <= 1e-9);
    CHECK(t, inside ? vec3_dot(h->ng, e) < 0 : vec3_dot(h->ng, e) > 0);
    CHECK(t, h->u >= 0 && h->u < 1 && h->v >= 0 && h->v <= 1);
    CHECK(t, h->p.x >= box.lo.x && h->p.y >= box.lo.y && h->p.z >= box.lo.z &&
                 h->p.x <= box.hi.x && h->p.y <= box.hi.y && h->p.z <= box.hi.z);
}

/* truth: brute force, the implicit function |q| - r(s) sampled at 3000 points along each
 *   ray: a reported hit must lie on the surface, no sign change may come before it, and a
 *   sign change well inside the length must be reported (at or before it).
 * tolerance: 1e-9 of the coordinates' size on the surface equation (the hit carries a few
 *   ulps times the conditioning, 1e-15 to 1e-12 here); the sampled root is bracketed by a
 *   step, so "before" means before the bracket's right end. Grazing pairs of roots closer
 *   than a step escape the sampling; those rays are not judged (the checks are one-sided).
 * catches: a dropped term in A, B or C, the wrong root taken, hits beyond the rims or on
 *   the mirrored nappe accepted, a normal off the gradient, negative radii not flipped. */
static void test_cone_against_brute_force(struct check *t)
{
    int n_hits = 0;
    for (uint64_t k = 0; k < 64; k++) {
        struct rng rng = rng_stream(11, STREAM_TEST, k, 0);
        struct vec3 base = random_point(&rng, 2.0);
        struct vec3 apex = vec3_add(base, random_point(&rng, 1.5));
        double r_base = random_in(&rng, 0.05, 1.2), r_apex = random_in(&rng, 0.05, 1.2);
        if (k % 4 == 0)
            r_apex = r_base; /* cylinder */
        else if (k % 4 == 1)
            r_apex = 0;      /* true cone */
        int inside = k % 8 == 5;
        struct error err;
        struct cone *cone = cone_create(base, inside ? -r_base : r_base, apex,
                                        inside ? -r_apex : r_apex, 7, &err);
        REQUIRE(t, cone != NULL);
        struct cone_truth c = cone_truth(base, r_base, apex, r_apex);
        struct aabb box = cone_ops.bounds(cone);
        for (int i = 0; i < 40; i++) {
            struct vec3 o = random_point(&rng, 5.0);
            struct vec3 aim = vec3_add(vec3_madd(base, c.axis, c.height * rng_uniform(&rng)),
                                       random_point(&rng, 1.0));
            struct ray ray = make_ray(o, vec3_scale(vec3_sub(aim, o), random_in(&rng, 0.3, 3)));
            double t_end = 20.0 / vec3_length(ray.dir); /* beyond every cone from any o */
            struct hit h;
            int hit = cone_ops.intersect(cone, ray, INFINITY, &h);
            double crossing = first_crossing(&c, ray, hit ? h.t : t_end);
            CHECK(t, hit == cone_ops.occluded(cone, ray, INFINITY));
            if (!hit) {
                CHECK(t, crossing == INFINITY);
                continue;
            }
            n_hits++;
            CHECK(t, h.material == 7);
            check_cone_hit(t, &c, &h, box, inside);
            CHECK(t, crossing == INFINITY || crossing + h.t / N_STEPS >= h.t * (1 - 1e-9));
            CHECK(t, !cone_ops.occluded(cone, ray, h.t * (1 - 1e-9)));
        }
        cone_ops.free(cone);
    }
    CHECK(t, n_hits > 800); /* most of the 2560 rays are aimed at the cone */
}

/* A unit-radius shape along +z from the origin, of height 1 or 2. */
static struct cone *z_cone(double r_base, double r_apex, double height)
{
    struct error err;
    return cone_create(vec3(0, 0, 0), r_base, vec3(0, 0, height), r_apex, 0, &err);
}

/* truth: closed forms. A cylinder's axis ray, and rays parallel to its axis inside it,
 *   meet nothing (open ends); a ray parallel to a generator of the cone r = 1 - s
 *   (A = 0, the linear case) hits at t = 1.3; a ray tangent to the cylinder x^2 + y^2 = 1
 *   touches it at t = 5; one 1e-6 inside, 1e4 away, enters at t = 1e4 - sqrt(1 - x^2).
 * tolerance: 1e-12 for the first three (a few roundings of numbers near 1); 1e-9 for the
 *   far grazing ray, whose half chord 1.4e-3 the textbook discriminant (1e8 - 1e8) would
 *   get wrong by 5e-6, which is what this catches.
 * catches: A = 0 divided by, open ends capped, cancellation in the discriminant. */
static void test_cone_special_rays(struct check *t)
{
    struct cone *cylinder = z_cone(1, 1, 2), *cone = z_cone(1, 0, 1);
    struct hit h;
    CHECK(t, !cone_ops.intersect(cylinder, make_ray(vec3(0, 0, 1), vec3(0, 0, 1)), INFINITY, &h));
    CHECK(t, !cone_ops.intersect(cylinder, make_ray(vec3(0, 0, -1), vec3(0, 0, 1)), INFINITY,
                                 &h));
    CHECK(t, !cone_ops.intersect(cylinder, make_ray(vec3(0.5, 0.2, 1), vec3(0, 0, -3)),
                                 INFINITY, &h));
    for (double scale = 1; scale <= 3; scale += 2) {
        struct ray ray = make_ray(vec3(1.1, 0, -0.5), vec3(-scale, 0, scale));
        CHECK(t, cone_ops.intersect(cone, ray, INFINITY, &h));
        CHECK_CLOSE(t, h.t, 1.3 / scale, 1e-12);
        CHECK_CLOSE(t, h.p.x, -0.2, 1e-12);
        CHECK_CLOSE(t, h.p.z, 0.8, 1e-12);
    }
    CHECK(t, cone_ops.intersect(cylinder, make_ray(vec3(1, -5, 0.5), vec3(0, 1, 0)), INFINITY,
                                &h));
    CHECK_CLOSE(t, h.t, 5.0, 1e-12);
    CHECK(t, !cone_ops.intersect(cylinder, make_ray(vec3(1 + 1e-9, -5, 0.5), vec3(0, 1, 0)),
                                 INFINITY, &h));
    double x = 1 - 1e-6;
    CHECK(t, cone_ops.intersect(cylinder, make_ray(vec3(x, -1e4, 0.5), vec3(0, 1, 0)),
                                INFINITY, &h));
    CHECK_CLOSE(t, h.t, 1e4 - sqrt((1 - x) * (1 + x)), 1e-9);
    /* from inside the cylinder, the far wall; bounded by tmax */
    CHECK(t, cone_ops.intersect(cylinder, make_ray(vec3(0, 0, 1), vec3(1, 0, 0)), INFINITY, &h));
    CHECK_CLOSE(t, h.t, 1.0, 1e-15);
    CHECK(t, !cone_ops.intersect(cylinder, make_ray(vec3(0, 0, 1), vec3(1, 0, 0)), 1.0, &h));
    cone_ops.free(cylinder);
    cone_ops.free(cone);
}

/* truth: NFF's rules (nff.c): coincident ends, radii of opposite signs or both zero are
 *   refused; anything else is made. catches: a zero height divided by. */
static void test_cone_refusals(struct check *t)
{
    struct error err;
    struct vec3 o = vec3(0, 0, 0), z = vec3(0, 0, 1);
    CHECK(t, cone_create(o, 1, o, 1, 0, &err) == NULL && strstr(err.message, "coincide"));
    CHECK(t, cone_create(o, 1, z, -1, 0, &err) == NULL && strstr(err.message, "opposite"));
    CHECK(t, cone_create(o, 0, z, 0, 0, &err) == NULL && strstr(err.message, "both zero"));
    CHECK(t, cone_create(o, NAN, z, 1, 0, &err) == NULL && strstr(err.message, "finite"));
    CHECK(t, cone_create(o, 1e300, vec3(0, 0, 1e-300), 0, 0, &err) == NULL);
    struct cone *c = cone_create(o, -1, z, 0, 0, &err);
    CHECK(t, c != NULL);
    cone_free(c);
    cone_free(NULL);
}

/* ---- ear clipping --------------------------------------------------------------------- */

/* Twice the signed area of the 2-D polygon (x, y) by the shoelace formula. */
static double shoelace(const double *x, const double *y, const int *index, int n)
{
    double sum = 0;
    for (int i = 0; i < n; i++) {
        int a = index != NULL ? index[i] : i, b = index != NULL ? index[(i + 1) % n] : (i + 1) % n;
        sum += x[a] * y[b] - x[b] * y[a];
    }
    return sum;
}

/* Whether (px, py) is inside the polygon (even-odd rule). */
static int point_in_polygon(const double *x, const double *y, int n, double px, double py)
{
    int inside = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((y[i] > py) != (y[j] > py) &&
            px < x[j] + (x[i] - x[j]) * (py - y[j]) / (y[i] - y[j])) /* y[i] != y[j] here */
            inside = !inside;
    return inside;
}

/* Triangulates the 2-D polygon embedded in 3-D by `frame` (a rotation and a shift) and checks
 * the triangles in 2-D: n - 2 of them with distinct corners, each turning the polygon's way,
 * centroid inside, areas summing to the polygon's. Returns the number of failed checks. */
static int check_triangulation(struct check *t, const double *x, const double *y, int n,
                               const struct vec3 frame[4])
{
    struct vec3 *v = xmalloc((size_t)n, sizeof *v, "test polygon");
    int *tri = xmalloc(3 * (size_t)(n - 2), sizeof *tri, "test triangles");
    for (int i = 0; i < n; i++)
        v[i] = vec3_add(frame[3], vec3_add(vec3_scale(frame[0], x[i]), vec3_scale(frame[1], y[i])));
    polygon_triangulate(v, n, tri);
    int before = t->failures_in_test;
    double polygon = shoelace(x, y, NULL, n), sum = 0;
    for (int k = 0; k < n - 2; k++) {
        const int *c = tri + 3 * k;
        CHECK(t, c[0] >= 0 && c[0] < n && c[1] >= 0 && c[1] < n && c[2] >= 0 && c[2] < n);
        CHECK(t, c[0] != c[1] && c[1] != c[2] && c[2] != c[0]);
        double area = shoelace(x, y, c, 3);
        CHECK(t, area * polygon >= 0);
        sum += fabs(area);
        if (area != 0)
            CHECK(t, point_in_polygon(x, y, n, (x[c[0]] + x[c[1]] + x[c[2]]) / 3,
                                      (y[c[0]] + y[c[1]] + y[c[2]]) / 3));
    }
    CHECK_CLOSE(t, sum, fabs(polygon), 1e-12 * fabs(polygon));
    xfree(tri);
    xfree(v);
    return t->failures_in_test - before;
}

/* A star-shaped polygon of n vertices: increasing angles, random radii; so simple, and
 * concave wherever a radius dips. */
static void random_star(struct rng *rng, int n, double *x, double *y)
{
    for (int i = 0; i < n; i++) {
        double angle = 2 * PI * (i + 0.8 * rng_uniform(rng)) / n;
        double radius = random_in(rng, 0.05, 1.0);
        x[i] = radius * cos(angle);
        y[i] = radius * sin(angle);
    }
}

/* A comb: a bar along the bottom with `teeth` thin teeth upwards (2 + 4 teeth vertices). */
static int comb(int teeth, double *x, double *y)
{
    int n = 0;
    x[n] = 0, y[n++] = 0;
    x[n] = teeth, y[n++] = 0;
    for (int i = teeth - 1; i >= 0; i--) {
        x[n] = i + 0.8, y[n++] = 3;
        x[n] = i + 0.6, y[n++] = 0.5;
        x[n] = i + 0.4, y[n++] = 0.5;
        x[n] = i + 0.2, y[n++] = 3;
    }
    x[n - 1] = 0; /* the first tooth's left edge is the bar's */
    return n;
}

/* A random orthonormal pair and a shift: the polygon's plane in space. */
static void random_frame(struct rng *rng, struct vec3 frame[4])
{
    struct vec3 n = vec3_normalize(random_point(rng, 1.0));
    vec3_frame(n, &frame[0], &frame[1]);
    frame[2] = n;
    frame[3] = random_point(rng, 100.0);
}

/* Reads the first 144-vertex polygon of gears-s3.nff (a gear's concave outline) into x, y
 * (it lies in a plane z = constant); returns its vertex count, 0 if not found. */
static int gear_outline(double *x, double *y)
{
    FILE *f = fopen(SPD_DATA "/gears-s3-head.nff", "r");
    if (f == NULL)
        return 0;
    char line[256];
    while (fgets(line, sizeof line, f) != NULL && strcmp(line, "p 144\n") != 0)
        continue;
    int n = 0;
    double z;
    while (n < 144 && fgets(line, sizeof line, f) != NULL &&
           sscanf(line, "%lf %lf %lf", &x[n], &y[n], &z) == 3)
        n++;
    fclose(f);
    return n;
}

/* truth: the shoelace area and an even-odd point-in-polygon test, in the polygon's own 2-D
 *   coordinates, of triangles found in 3-D (randomly rotated and shifted planes).
 * tolerance: 1e-12 relative on the area: the 3-D embedding rounds the coordinates (1e-16
 *   of 100), which may tip a triangle of collinear points, nothing more.
 * catches: a fan (wrong on every concave polygon here), reflex vertices not checked,
 *   clockwise polygons (the reversed copies) clipped on the wrong side, a wrong count. */
static void test_ear_clipping(struct check *t)
{
    static double x[200], y[200], rx[200], ry[200];
    struct rng rng = rng_stream(12, STREAM_TEST, 0, 0);
    struct vec3 frame[4];
    for (int k = 0; k < 120; k++) {
        int n;
        if (k == 0) {
            static const double lx[] = {0, 2, 2, 0.7, 0.7, 0}, ly[] = {0, 0, 0.7, 0.7, 2, 2};
            n = 6;
            memcpy(x, lx, sizeof lx);
            memcpy(y, ly, sizeof ly);
        } else if (k == 1) {
            n = comb(20, x, y);
        } else if (k == 2) {
            static const double sx[] = {0, 1, 2, 2, 2, 1, 0, 0}, sy[] = {0, 0, 0, 1, 2, 2, 2, 1};
            n = 8; /* a square with collinear midpoints */
            memcpy(x, sx, sizeof sx);
            memcpy(y, sy, sizeof sy);
        } else if (k == 3) {
            n = gear_outline(x, y);
            REQUIRE(t, n == 144); /* else n - 2 triangles is no size */
        } else {
            n = 3 + (int)(rng_uniform(&rng) * 120);
            random_star(&rng, n, x, y);
        }
        random_frame(&rng, frame);
        for (int i = 0; i < n; i++) {
            rx[i] = x[n - 1 - i];
            ry[i] = y[n - 1 - i];
        }
        if (check_triangulation(t, x, y, n, frame) + check_triangulation(t, rx, ry, n, frame))
            fprintf(stderr, "ear clipping: polygon %d (%d vertices) failed\n", k, n);
    }
}

void test_import_geom(struct check *t)
{
    RUN_TEST(t, test_cone_against_brute_force);
    RUN_TEST(t, test_cone_special_rays);
    RUN_TEST(t, test_cone_refusals);
    RUN_TEST(t, test_ear_clipping);
}
