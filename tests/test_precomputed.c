/*
 * tests/test_precomputed.c -- irradiance precomputed at photon positions (Christensen
 * 1999; photon/precomputed_irradiance.h): the value at every record against a linear scan
 * of the map, and each lookup against a linear scan of the records.
 *
 * The map is a box's corner: photons on a floor (z = 0) and a wall (x = 0) of 1 x 1 m,
 * crowded towards the corner's line so that some estimates find their k photons within
 * the maximum radius and others do not, arriving from all directions so that about half
 * of them face away from the surface and must be left out. Every fourth photon is a
 * record, with its surface's normal.
 */
#include <math.h>
#include <stdlib.h>

#include "../src/base/alloc.h"
#include "../src/base/rng.h"
#include "../src/photon/disc_coverage.h"
#include "../src/photon/precomputed_irradiance.h"
#include "check.h"
#include "tests.h"
#include "truths.h"

#define N_PHOTONS 4000
#define RECORD_STEP 4
#define K 30
#define MAX_R2 (0.07 * 0.07) /* about 15 photons in the sparsest part, 50 near the line */

/* Photon i of the corner: on the floor or the wall, each half the time; u = w^2 crowds
 * the photons towards the corner's line (density 1 / (2 sqrt(u))). */
static struct photon corner_photon(size_t i, int as_record)
{
    struct rng r = rng_stream(1, STREAM_TEST, 320, i);
    int floor = rng_uniform(&r) < 0.5;
    double u = rng_uniform(&r), v = rng_uniform(&r);
    u *= u;
    struct vec3 x = floor ? vec3(u, v, 0) : vec3(0, v, u);
    struct vec3 normal = floor ? vec3(0, 0, 1) : vec3(1, 0, 0);
    if (as_record)
        return photon_pack(x, vec3_zero(), normal, PHOTON_DIRECT);
    double z = 2 * rng_uniform(&r) - 1, phi = 2 * PI * rng_uniform(&r);
    struct vec3 wi = vec3(sqrt(1 - z * z) * cos(phi), sqrt(1 - z * z) * sin(phi), z);
    struct vec3 power = vec3(rng_uniform(&r), rng_uniform(&r), 0.5 * rng_uniform(&r));
    return photon_pack(x, vec3_scale(power, 1e-3), wi, PHOTON_INDIRECT);
}

static struct photon *corner_photons(int as_records)
{
    size_t n = as_records ? N_PHOTONS / RECORD_STEP : N_PHOTONS;
    struct photon *photons = xmalloc(n, sizeof *photons, "test photons");
    for (size_t i = 0; i < n; i++)
        photons[i] = corner_photon(as_records ? i * RECORD_STEP : i, as_records);
    return photons;
}

/* kdtree.c's squared distance: from the record's floats, in double, axis by axis. */
static double squared_distance(const struct photon *p, struct vec3 x)
{
    double d[3] = {(double)p->pos[0] - x.x, (double)p->pos[1] - x.y, (double)p->pos[2] - x.z};
    return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

/* The k nearest and E by a linear scan over photons[0..n-1] (estimate.h's rules). */
struct scan {
    double d2;
    size_t index;
};

static int nearer(const void *a, const void *b)
{
    const struct scan *p = a, *q = b;
    if (p->d2 != q->d2)
        return p->d2 < q->d2 ? -1 : 1;
    return p->index < q->index ? -1 : p->index > q->index;
}

/* E at x with normal n from the K nearest photons within MAX_R2, the one on the rim left
 * out (or all of them over MAX_R2's disc when fewer are within it); *r2 its disc. */
static struct vec3 scanned_irradiance(const struct photon *photons, struct scan *order,
                                      struct vec3 x, struct vec3 n, double *r2)
{
    size_t within = 0;
    for (size_t i = 0; i < N_PHOTONS; i++) {
        order[i].d2 = squared_distance(&photons[i], x);
        order[i].index = i;
        within += order[i].d2 <= MAX_R2;
    }
    qsort(order, N_PHOTONS, sizeof *order, nearer);
    size_t summed = within >= K ? K - 1 : within;
    *r2 = within >= K ? order[K - 1].d2 : MAX_R2;
    struct vec3 sum = vec3_zero();
    for (size_t j = 0; j < summed; j++) {
        const struct photon *p = &photons[order[j].index];
        if (vec3_dot(photon_direction(p), n) > 0)
            sum = vec3_add(sum, photon_power(p));
    }
    return vec3_scale(sum, 1.0 / (PI * *r2));
}

static int same_float(float a, double b)
{
    return fabs((double)a - b) <= 1e-6 * fabs(b) + 1e-300;
}

/* truth: brute force, a linear scan of all the photons for each record's K nearest (the
 *   same squared distances from the same floats as the tree), with estimate.h's rules.
 * tolerance: float rounding of the stored value (1e-6 relative); r^2 exactly.
 * catches: the record's normal not used for the facing test (photons from behind
 *   counted), the rim photon counted, the wrong disc where fewer than K are within the
 *   maximum radius, values kept at the wrong node (the tree's order against the
 *   photons'), a node skipped. Checked to reach both kinds of disc. */
static void test_values_match_linear_scan(struct check *t)
{
    struct photon *photons = corner_photons(0);
    struct kdtree *map = balance_kdtree(corner_photons(0), N_PHOTONS);
    struct kdtree *records = balance_kdtree(corner_photons(1), N_PHOTONS / RECORD_STEP);
    struct irradiance_settings is = {K, MAX_R2, 0, 0, 1};
    struct precomputed_irradiance *pi = precompute_irradiance(map, records, &is, NULL, NULL);
    struct scan *order = xmalloc(N_PHOTONS, sizeof *order, "test scan");
    size_t full = 0, sparse = 0, bad = 0;
    for (size_t i = 1; i <= records->n_photons; i++) {
        const struct photon *rec = &records->photons[i];
        double r2;
        struct vec3 e = scanned_irradiance(photons, order, photon_position(rec),
                                           photon_normal(rec), &r2);
        const struct irradiance_value *v = &pi->value[i];
        bad += !(same_float(v->e[0], e.x) && same_float(v->e[1], e.y) &&
                 same_float(v->e[2], e.z) && v->r2 == (float)r2);
        full += r2 < MAX_R2;
        sparse += r2 == MAX_R2;
    }
    CHECK(t, bad == 0);
    CHECK(t, full > 100 && sparse > 20);
    CHECK(t, precomputed_irradiance_bytes(pi) >= records->n_photons * sizeof *pi->value);
    xfree(order);
    precomputed_irradiance_free(pi);
    kdtree_free(records);
    kdtree_free(map);
    xfree(photons);
}

/* The node of records that should serve x with normal n, by a linear scan: of the
 * PRECOMPUTED_CANDIDATES nearest within MAX_R2, the nearest with a similar normal whose
 * disc reaches x; 0 for none. */
static size_t scanned_record(const struct precomputed_irradiance *pi, struct scan *order,
                             struct vec3 x, struct vec3 n)
{
    const struct kdtree *records = pi->records;
    for (size_t i = 1; i <= records->n_photons; i++) {
        order[i - 1].d2 = squared_distance(&records->photons[i], x);
        order[i - 1].index = i;
    }
    qsort(order, records->n_photons, sizeof *order, nearer);
    for (size_t j = 0; j < PRECOMPUTED_CANDIDATES && j < records->n_photons; j++) {
        size_t i = order[j].index;
        if (!(order[j].d2 <= MAX_R2))
            break;
        if (vec3_dot(n, photon_normal(&records->photons[i])) >= PRECOMPUTED_MIN_COS &&
            order[j].d2 <= pi->value[i].r2)
            return i;
    }
    return 0;
}

/* Query q: a point on the floor or the wall (some within a centimetre of the corner's
 * line), with its surface's normal, tilted 30 degrees for every fifth (no record's normal
 * is then similar), or 1 m off the walls for another of every 25 (no record in reach). */
static void corner_query(size_t q, struct vec3 *x, struct vec3 *n)
{
    struct rng r = rng_stream(1, STREAM_TEST, 321, q);
    double u = q % 3 == 0 ? 0.01 * rng_uniform(&r) : rng_uniform(&r), v = rng_uniform(&r);
    int floor = q % 2 == 0;
    *x = floor ? vec3(u, v, 0) : vec3(0, v, u);
    *n = floor ? vec3(0, 0, 1) : vec3(1, 0, 0);
    if (q % 5 == 4)
        *n = floor ? vec3(0.5, 0, sqrt(0.75)) : vec3(sqrt(0.75), 0, 0.5);
    if (q % 25 == 23)
        *x = vec3_add(*x, *n);
}

/* truth: brute force, a linear scan over the records in order of distance (then node),
 *   with the rule of precomputed_irradiance_at().
 * tolerance: none; the value is the record's own, copied.
 * catches: a record that is not the nearest usable one, the normal or disc test left out
 *   or turned round, candidates beyond the maximum radius, a record served from the
 *   other wall at the corner, a lookup that never declines (checked to decline some and
 *   serve most), an empty set of records. */
static void test_lookup_matches_linear_scan(struct check *t)
{
    struct kdtree *map = balance_kdtree(corner_photons(0), N_PHOTONS);
    struct kdtree *records = balance_kdtree(corner_photons(1), N_PHOTONS / RECORD_STEP);
    struct kdtree *none = balance_kdtree(NULL, 0);
    struct irradiance_settings is = {K, MAX_R2, 0, 0, 1};
    struct precomputed_irradiance *pi = precompute_irradiance(map, records, &is, NULL, NULL);
    struct precomputed_irradiance *empty = precompute_irradiance(map, none, &is, NULL, NULL);
    struct nearest *nn = nearest_create(K);
    struct scan *order = xmalloc(records->n_photons, sizeof *order, "test scan");
    size_t served = 0, declined = 0, bad = 0;
    for (size_t q = 0; q < 500; q++) {
        struct vec3 x, n, e = vec3(-1, -1, -1);
        double r2 = -1;
        corner_query(q, &x, &n);
        size_t expected = scanned_record(pi, order, x, n);
        int found = precomputed_irradiance_at(pi, x, n, nn, &e, &r2);
        const struct irradiance_value *v = &pi->value[expected];
        bad += found != (expected != 0);
        bad += found && !(e.x == v->e[0] && e.y == v->e[1] && e.z == v->e[2] && r2 == v->r2);
        bad += precomputed_irradiance_at(empty, x, n, nn, &e, &r2) != 0;
        served += found;
        declined += !found;
    }
    CHECK(t, bad == 0);
    CHECK(t, served > 300 && declined >= 120); /* 100 tilted, 20 far, and a few at the line */
    xfree(order);
    nearest_free(nn);
    precomputed_irradiance_free(empty);
    precomputed_irradiance_free(pi);
    kdtree_free(none);
    kdtree_free(records);
    kdtree_free(map);
}

/* The share of a disc of radius r whose centre is h >= 0 inside a straight edge that
 * lies on the edge's near side: the disc less the circular segment beyond. */
static double disc_short_of_edge(double h, double r)
{
    double c = h >= r ? 1.0 : h / r;
    return 1.0 - (acos(c) - c * sqrt(1.0 - c * c)) / PI;
}

/* truth: the Cornell box's geometry in closed form: a disc on the floor's middle or on a
 *   ball is covered; one h from the floor's open front edge (z = 0), or on the green
 *   wall (x = 0) h above the floor, loses the circular segment beyond; under the light
 *   (a black emitter, which holds no photons) nothing is covered, which the floor clamps;
 *   in the specular box the floor under the glass ball, where photons land through the
 *   glass, is covered.
 * tolerance: 0.07 of the disc: the probes stand for 1/32 of it each, and an edge cuts
 *   a ring of 8 between probes.
 * catches: probes on the wrong side of the plane or too shallow to find a surface, the
 *   turned-surface test reversed (the wall counted as floor), the black emitter counted,
 *   rings not of equal area (a half-disc far from 1/2), the floor left out, a probe that
 *   stops at glass. */
static void test_disc_coverage_of_the_cornell_box(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/cornell.scene", 0, 0);
    if (scene == NULL) {
        CHECK(t, 0);
        return;
    }
    struct vec3 up = vec3(0, 1, 0), right = vec3(1, 0, 0);
    double r = 20;
    CHECK(t, disc_coverage(scene, vec3(300, 0, 300), up, r) == 1.0);
    CHECK(t, disc_coverage(scene, vec3(185, 180, 169), up, r) == 1.0); /* a ball's top */
    double worst = 0;
    for (int i = 0; i <= 8; i++) {
        double h = 2.5 * i, truth = disc_short_of_edge(h, r);
        worst = fmax(worst, fabs(disc_coverage(scene, vec3(300, 0, h), up, r) - truth));
        worst = fmax(worst, fabs(disc_coverage(scene, vec3(0, h, 300), right, r) - truth));
    }
    CHECK(t, worst <= 0.07);
    CHECK(t, disc_coverage(scene, vec3(278, 548.8, 280), vec3(0, -1, 0), r) ==
                 DISC_COVERAGE_FLOOR);
    scene_free(scene);
    scene = load_test_scene("scenes/cornell-specular.scene", 0, 0);
    CHECK(t, scene != NULL && disc_coverage(scene, vec3(185, 0, 169), up, r) == 1.0);
    if (scene != NULL)
        scene_free(scene);
}

/* truth: photons spread evenly over the Cornell box's floor, 0 to 549.6 in x and 0 to
 *   559.2 in z, each of power P: irradiance N P / A everywhere on it, up to the open
 *   front edge; the plain estimate there is dark by the share of its disc beyond it.
 * tolerance: 5%, for the mean over 20 points 2 mm from the edge with 400 photons each
 *   (Poisson noise about 1.3%, the probes' coverage within 1/32).
 * catches: the coverage not applied or applied twice, photons off the disc's plane
 *   counted, the rim photon counted; and (the plain estimate checked to be at least 20%
 *   dark there) a test that could not tell. */
static void test_covered_estimate_at_an_open_edge(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/cornell.scene", 0, 0);
    if (scene == NULL) {
        CHECK(t, 0);
        return;
    }
    size_t n = 200000;
    double power = 1e-3, width = 549.6, depth = 559.2;
    struct photon *photons = xmalloc(n, sizeof *photons, "test photons");
    for (size_t i = 0; i < n; i++) {
        struct rng r = rng_stream(1, STREAM_TEST, 321, i);
        double x = width * rng_uniform(&r), z = depth * rng_uniform(&r);
        photons[i] = photon_pack(vec3(x, 0, z), vec3(power, power, power), vec3(0, 1, 0),
                                 PHOTON_DIRECT);
    }
    struct kdtree *map = balance_kdtree(photons, n);
    struct irradiance_settings is = {400, HUGE_VAL, 0, 0, 1};
    struct nearest *nn = nearest_create(is.n);
    double truth = n * power / (width * depth), covered = 0, plain = 0;
    for (int i = 0; i < 20; i++) {
        struct vec3 x = vec3(150 + 12.5 * i, 0, 2), up = vec3(0, 1, 0);
        covered += covered_irradiance_estimate(map, scene, x, up, &is, nn).y / 20;
        plain += irradiance_estimate(map, x, up, &is, nn).y / 20;
    }
    CHECK(t, fabs(covered / truth - 1) <= 0.05);
    CHECK(t, plain / truth < 0.8);
    nearest_free(nn);
    kdtree_free(map);
    scene_free(scene);
}

void test_precomputed(struct check *t)
{
    RUN_TEST(t, test_disc_coverage_of_the_cornell_box);
    RUN_TEST(t, test_covered_estimate_at_an_open_edge);
    RUN_TEST(t, test_values_match_linear_scan);
    RUN_TEST(t, test_lookup_matches_linear_scan);
}
