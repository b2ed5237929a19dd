/*
 * tests/test_trace_estimates.c -- what photon maps estimate: radiance with the cone filter
 * (photon/estimate.h), irradiance with differential checking (Jensen and Christensen
 * 1994), and the illumination maps of that paper's Sec. 3.2 (photon/illumination_map.h),
 * against closed forms and sums worked by hand.
 *
 * The maps are traced (scenes/analytic/point-over-plane.scene) or made here: photons
 * spread uniformly over a square, or with a step like a caustic's edge, or on a line at
 * chosen distances, so that each truth is a density known exactly.
 */
#include <math.h>

#include "../src/base/alloc.h"
#include "../src/photon/estimate.h"
#include "../src/photon/illumination_map.h"
#include "../src/photon/trace.h"
#include "check.h"
#include "tests.h"
#include "trace_fixtures.h"
#include "truths.h"

/* ---- estimates ---- */

/* The mean over a 17 x 17 grid of points |x|, |z| <= 2 on the floor of
 * point-over-plane.scene of estimate / closed form, from a map of n photons and k per
 * estimate. The points are 0.25 apart, more than twice the gathering radius, so the
 * estimates are nearly independent. */
static double point_over_plane_ratio(const struct scene *scene, size_t n, size_t k)
{
    struct photon_trace tr = trace(scene, n, PHOTON_MAP_GLOBAL, 0, NULL);
    struct kdtree *map = balance_kdtree(tr.photons, tr.n_photons);
    struct nearest *nn = nearest_create(k);
    struct vec3 up = vec3(0, 1, 0);
    struct shading_frame frame = shading_frame_from_normal(up, 1, TRANSPORT_RADIANCE);
    struct estimate_settings es = {k, HUGE_VAL, 0, 0, 1};
    double sum = 0;
    for (int i = 0; i < 17 * 17; i++) {
        struct vec3 x = vec3(-2 + 0.25 * (i % 17), 0, -2 + 0.25 * (i / 17));
        struct estimate_point at = {x, up, up, &scene->materials[0], &frame, 0};
        double d = sqrt(1 + x.x * x.x + x.z * x.z);
        double truth = 0.5 * 1000 * 1 / (4 * PI * PI * d * d * d); /* rho Phi h/(4 pi^2 d^3) */
        sum += radiance_estimate(map, &at, &es, nn).y / truth;
    }
    nearest_free(nn);
    kdtree_free(map);
    return sum / (17 * 17);
}

/* truth: scenes/analytic/point-over-plane.scene's closed form L = rho Phi h / (4 pi^2 d^3)
 *   at points within 2 of the light's foot (the plane's edges are 100 away).
 * tolerance: with 1M photons and 200 per estimate the mean ratio over 289 points is
 *   within 2% of 1 (one estimate's noise is 1/sqrt(200) = 7%, the mean's 0.4%; the
 *   blur of the falling irradiance over r <= 0.1 is below 1%);
 *   with 10k photons the radius is ten times larger and the blur bias must be larger
 *   than at 1M: the error falls as N grows.
 * catches: a missing pi or 1/pi, the disc area from r instead of r^2, emission not
 *   uniform over directions (bias growing with d), photons stored with the wrong
 *   direction (rejected by the front test), k photons with the wrong radius. */
static void test_point_over_plane_estimate(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/point-over-plane.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    double coarse = point_over_plane_ratio(scene, 10000, 200);
    double fine = point_over_plane_ratio(scene, 1000000, 200);
    CHECK(t, fabs(fine - 1) < 0.02);
    CHECK(t, fabs(coarse - 1) > fabs(fine - 1) + 0.01);
    scene_free(scene);
}

/* n photons of equal power spread uniformly over the unit square z = 0, all arriving
 * from +z: an irradiance E = n power exactly uniform in expectation. */
static struct kdtree *uniform_square_map(size_t n, double power)
{
    struct photon *photons = xmalloc(n, sizeof *photons, "test photons");
    for (size_t i = 0; i < n; i++) {
        struct rng r = test_rng(40, i);
        double x = rng_uniform(&r), y = rng_uniform(&r);
        photons[i] = photon_pack(vec3(x, y, 0), vec3(power, power, power), vec3(0.3, 0, 1),
                                 PHOTON_DIRECT);
    }
    return balance_kdtree(photons, n);
}

/* truth: a uniform region of irradiance E on a Lambertian surface of albedo rho has
 *   L = rho E / pi. With r the k-th photon's distance, E[(k - 1) / (pi r^2)] is the
 *   density of a Poisson process, so both estimates are unbiased: the cone filter with
 *   k_cone = 1 (its rim photon weighs 0, the k - 1 inside have mean weight 1/3) and the
 *   plain one, which leaves the rim photon out (estimate.c); Eq. 3 as printed would
 *   have mean L k / (k - 1).
 * tolerance: 3 standard errors of the mean over 441 estimates on a grid 0.04 apart
 *   (more than twice r, so they are nearly independent); k = 20 makes the printed
 *   Eq. 3's bias 5%, about 4 standard errors, so counting the rim photon is caught.
 * catches: the cone normalisation 1 - 2/(3k) missing or inverted (a factor of 3), the
 *   weight computed from d^2 instead of d (a factor of 1.5), the radius of the (k-1)-th
 *   photon used for the area, the rim photon counted in the plain estimate. */
static void test_cone_filter_uniform(struct check *t)
{
    size_t n = 100000, k = 20;
    double power = 1e-3, rho = 0.6;
    struct kdtree *map = uniform_square_map(n, power);
    struct nearest *nn = nearest_create(k);
    struct scene *scene = scene_create();
    add_test_material(scene, MATERIAL_LAMBERT, vec3(rho, rho, rho), vec3_zero());
    struct vec3 up = vec3(0, 0, 1);
    struct shading_frame frame = shading_frame_from_normal(up, 1, TRANSPORT_RADIANCE);
    double truth = rho * (n * power) / PI;
    for (int cone = 0; cone < 2; cone++) {
        struct estimate_settings es = {k, HUGE_VAL, cone ? 1.0 : 0.0, 0, 1};
        struct tally m = {0, 0, 441};
        for (int i = 0; i < 441; i++) {
            struct vec3 x = vec3(0.1 + 0.04 * (i % 21), 0.1 + 0.04 * (i / 21), 0);
            struct estimate_point at = {x, up, vec3(0, 0.6, 0.8), &scene->materials[0], &frame, 0};
            tally_add(&m, radiance_estimate(map, &at, &es, nn).x / truth);
        }
        CHECK_CLOSE(t, m.sum / 441, 1.0, 3 * tally_se(&m) / 441);
    }
    scene_free(scene);
    nearest_free(nn);
    kdtree_free(map);
}

/* truth: the contract of radiance_estimate(): zero, never NaN, when no photon is found,
 *   when every photon sits exactly at x (r = 0), and when all arrived from behind the
 *   surface; with fewer than k photons within the maximum radius, the area is the
 *   maximum radius's disc (Jensen's photonmap.cc).
 * tolerance: 1e-12 relative for the one value computed.
 * catches: a division by r^2 = 0, photons from a thin wall's other side counted (also
 *   where a tilted shading normal would let the BRDF see them), the found photons' own
 *   radius used when the search radius was the limit. */
static void test_estimate_boundaries(struct check *t)
{
    struct scene *scene = scene_create();
    add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    struct vec3 up = vec3(0, 0, 1);
    struct shading_frame frame = shading_frame_from_normal(up, 1, TRANSPORT_RADIANCE);
    struct estimate_point at = {vec3(0, 0, 0), up, up, &scene->materials[0], &frame, 0};
    struct estimate_settings es = {10, HUGE_VAL, 1.0, 0, 1};
    struct nearest *nn = nearest_create(10);
    struct kdtree *empty = balance_kdtree(NULL, 0);
    CHECK(t, vec3_length2(radiance_estimate(empty, &at, &es, nn)) == 0);
    struct photon *photons = xmalloc(3, sizeof *photons, "test photons");
    for (int i = 0; i < 3; i++)
        photons[i] = photon_pack(vec3(0, 0, 0), vec3(1, 1, 1), up, PHOTON_DIRECT);
    struct kdtree *at_x = balance_kdtree(photons, 3);
    struct vec3 l = radiance_estimate(at_x, &at, &es, nn);
    CHECK(t, vec3_is_finite(l) && vec3_length2(l) == 0);
    photons = xmalloc(2, sizeof *photons, "test photons");
    photons[0] = photon_pack(vec3(0.1, 0, 0), vec3(2, 2, 2), up, PHOTON_DIRECT);
    photons[1] = photon_pack(vec3(0, 0.2, 0), vec3(3, 3, 3), vec3_neg(up), PHOTON_DIRECT);
    struct kdtree *two = balance_kdtree(photons, 2);
    es.cone_k = 0;
    es.max_r2 = 0.25; /* radius 0.5: both found, fewer than k */
    l = radiance_estimate(two, &at, &es, nn);
    CHECK_CLOSE(t, l.y, 0.5 / PI * 2 / (PI * 0.25), 1e-12 * l.y); /* only the front one */
    struct shading_frame below = shading_frame_from_normal(vec3_neg(up), 0, TRANSPORT_RADIANCE);
    at.ng = at.wo = vec3_neg(up); /* the other side: only the photon from below counts */
    at.frame = &below;
    l = radiance_estimate(two, &at, &es, nn);
    CHECK_CLOSE(t, l.y, 0.5 / PI * 3 / (PI * 0.25), 1e-12 * l.y);
    struct shading_frame tilted = shading_frame_from_normal(vec3_normalize(vec3(1, 0, 1)), 1,
                                                            TRANSPORT_RADIANCE);
    at.ng = up; /* a shading normal tilted 45 degrees: the photon from below the geometric */
    at.wo = tilted.n; /* plane is above the shading one, yet came from the other side     */
    at.frame = &tilted;
    photons = xmalloc(1, sizeof *photons, "test photons");
    photons[0] = photon_pack(vec3(0.1, 0, 0), vec3(2, 2, 2), vec3(1, 0, -0.2), PHOTON_DIRECT);
    struct kdtree *behind = balance_kdtree(photons, 1);
    CHECK(t, vec3_length2(radiance_estimate(behind, &at, &es, nn)) == 0);
    kdtree_free(behind);
    kdtree_free(two);
    kdtree_free(at_x);
    kdtree_free(empty);
    nearest_free(nn);
    scene_free(scene);
}

/* ---- irradiance with differential checking (Jensen and Christensen 1994) ---- */

/* n photons of equal energy on the square [0, 1]^2 of z = 0, each holding the surface
 * normal +z (the 1994 record), `ratio` times denser right of x = edge than left of it:
 * an irradiance step like a caustic's edge (ratio 1: uniform, E = n energy). */
static struct kdtree *step_square_map(size_t n, double energy, double edge, double ratio)
{
    double right = ratio * (1 - edge) / (edge + ratio * (1 - edge)); /* P(x > edge) */
    struct photon *photons = xmalloc(n, sizeof *photons, "test photons");
    for (size_t i = 0; i < n; i++) {
        struct rng r = test_rng(41, i);
        double side = rng_uniform(&r), u = rng_uniform(&r), y = rng_uniform(&r);
        double x = side < right ? edge + (1 - edge) * u : edge * u;
        photons[i] = photon_pack(vec3(x, y, 0), vec3(energy, energy, energy), vec3(0, 0, 1),
                                 PHOTON_DIRECT);
    }
    return balance_kdtree(photons, n);
}

/* truth: the n - 1 photons inside the n-th photon's distance r of a uniform Poisson
 *   density E have E[(n - 1) / (pi r^2)] = E exactly (estimate.c), E = photons times
 *   energy per unit area.
 * tolerance: 3 standard errors of the mean over 441 estimates on a grid 0.04 apart;
 *   with n = 20 the paper's sum to n would be 5% (about 4 standard errors) high.
 * catches: a missing pi, r instead of r^2, the radius of the (n-1)-th photon, the rim
 *   photon counted, photons whose normal faces the query rejected (they all do here). */
static void test_irradiance_uniform(struct check *t)
{
    size_t n = 100000, k = 20;
    double energy = 1e-3;
    struct kdtree *map = step_square_map(n, energy, 0.5, 1.0);
    struct nearest *nn = nearest_create(k);
    struct irradiance_settings is = {k, HUGE_VAL, 0, 0, 1};
    struct tally m = {0, 0, 441};
    for (int i = 0; i < 441; i++) {
        struct vec3 x = vec3(0.1 + 0.04 * (i % 21), 0.1 + 0.04 * (i / 21), 0);
        tally_add(&m, irradiance_estimate(map, x, vec3(0, 0, 1), &is, nn).y / (n * energy));
    }
    CHECK_CLOSE(t, m.sum / 441, 1.0, 3 * tally_se(&m) / 441);
    nearest_free(nn);
    kdtree_free(map);
}

/* Photons i = 1..8 on the x axis at distance d_i from the origin, energy 1 each, normal
 * +z: the estimates E_j = (j - 1) / (pi d_j^2) of the j nearest follow from d alone. */
static struct kdtree *line_map(const double d[8])
{
    struct photon *photons = xmalloc(8, sizeof *photons, "test photons");
    for (int i = 0; i < 8; i++)
        photons[i] = photon_pack(vec3(d[i], 0, 0), vec3(1, 1, 1), vec3(0, 0, 1), PHOTON_DIRECT);
    return balance_kdtree(photons, 8);
}

/* truth: hand-computed sequences. d_j = 1 + j / 64 makes E_j = (j - 1) / (pi d_j^2)
 *   rise at every photon, d_j = j makes it fall from the second on ((j - 1) / (pi j^2));
 *   with runs of R = 2, checking starts at the 2R = 4th photon, where both runs are
 *   already long enough, so the estimate is E_4; without checking it is E_8. Photons whose normal faces away add
 *   nothing but still widen the disc; no photon, or all at x, give zero; fewer than n
 *   within max_r2 divide by the disc of max_r2.
 * tolerance: 1e-12 relative (a few roundings).
 * catches: checking that starts before 2R or never stops, a run counted on one
 *   direction only, the estimate of the run's start used, rejected photons left out of
 *   the radius or counted in the sum, a division by r^2 = 0. */
static void test_irradiance_rules(struct check *t)
{
    double rising[8], falling[8];
    for (int i = 0; i < 8; i++) {
        rising[i] = 1 + (i + 1) / 64.0; /* exact in float, as photons store it */
        falling[i] = i + 1;
    }
    struct nearest *nn = nearest_create(8);
    struct vec3 o = vec3(0, 0, 0), up = vec3(0, 0, 1);
    struct irradiance_settings is = {8, HUGE_VAL, 0, 2, 1};
    struct kdtree *up_map = line_map(rising), *down_map = line_map(falling);
    CHECK_CLOSE(t, irradiance_estimate(up_map, o, up, &is, nn).x,
                3 / (PI * rising[3] * rising[3]), 1e-12);
    CHECK_CLOSE(t, irradiance_estimate(down_map, o, up, &is, nn).x, 3 / (PI * 16), 1e-12);
    is.run = 0;
    CHECK_CLOSE(t, irradiance_estimate(up_map, o, up, &is, nn).x,
                7 / (PI * rising[7] * rising[7]), 1e-12);
    CHECK(t, vec3_length2(irradiance_estimate(up_map, o, vec3_neg(up), &is, nn)) == 0);
    is.max_r2 = 2.5 * 2.5; /* photons at 1 and 2 only: their sum over the disc of 2.5 */
    CHECK_CLOSE(t, irradiance_estimate(down_map, o, up, &is, nn).x, 2 / (PI * 6.25), 1e-12);
    struct photon *photons = xmalloc(3, sizeof *photons, "test photons");
    photons[0] = photon_pack(o, vec3(1, 1, 1), up, PHOTON_DIRECT);
    photons[1] = photon_pack(o, vec3(1, 1, 1), up, PHOTON_DIRECT);
    photons[2] = photon_pack(vec3(0.5, 0, 0), vec3(5, 5, 5), vec3_neg(up), PHOTON_DIRECT);
    struct kdtree *mixed = balance_kdtree(photons, 3), *empty = balance_kdtree(NULL, 0);
    is.max_r2 = HUGE_VAL;
    is.n = 2; /* both exactly at x: no area */
    CHECK(t, vec3_length2(irradiance_estimate(mixed, o, up, &is, nn)) == 0);
    is.n = 3; /* the third widens the disc to 0.5 without adding its (back-facing) energy */
    CHECK_CLOSE(t, irradiance_estimate(mixed, o, up, &is, nn).x, 2 / (PI * 0.25), 1e-12);
    CHECK(t, vec3_length2(irradiance_estimate(empty, o, up, &is, nn)) == 0);
    kdtree_free(empty);
    kdtree_free(mixed);
    kdtree_free(up_map);
    kdtree_free(down_map);
    nearest_free(nn);
}

/* truth: the irradiance of step_square_map() with photons 6 times denser right of the
 *   edge than left of it, the step a caustic's edge makes (Sec. 3.3).
 * tolerance: over 400 estimates with 200 photons each at points within one gathering
 *   radius of the edge, the relative RMS error with checking (runs of 10) is below 0.9
 *   times that without (measured: 0.60 against 0.77, 0.78 times). Far from the edge
 *   checking costs noise, which the test allows.
 * catches: checking that never stops (equal errors), a run that stops on noise before
 *   the disc reaches the edge (no gain), the wrong sign of a run. */
static void test_differential_checking_edge(struct check *t)
{
    size_t n = 200000, k = 200;
    double energy = 1e-3, left = n / 3.5; /* photons per unit area left of the edge */
    struct kdtree *map = step_square_map(n, energy, 0.5, 6.0);
    struct nearest *nn = nearest_create(k);
    double r = sqrt(k / (PI * left)); /* the gathering radius left of the edge: 0.019 */
    double error2[2] = {0, 0};
    for (int i = 0; i < 400; i++) {
        double x = 0.5 + r * (-1 + 2 * (i % 20 + 0.5) / 20);
        struct vec3 p = vec3(x, 0.2 + 0.6 * (i / 20) / 19.0, 0);
        double truth = left * energy * (x > 0.5 ? 6.0 : 1.0);
        for (int checking = 0; checking < 2; checking++) {
            struct irradiance_settings is = {k, HUGE_VAL, 0, checking ? DIFFERENTIAL_RUN : 0, 1};
            double e = irradiance_estimate(map, p, vec3(0, 0, 1), &is, nn).y / truth - 1;
            error2[checking] += e * e;
        }
    }
    CHECK(t, sqrt(error2[1]) < 0.9 * sqrt(error2[0]));
    nearest_free(nn);
    kdtree_free(map);
}

/* ---- illumination maps (Jensen and Christensen 1994, Sec. 3.2) ---- */

/* A scene of a 2 x 0.5 quad, a sphere of radius 0.7 and a triangle (no parameters). */
static struct scene *illumination_scene(void)
{
    struct scene *scene = scene_create();
    int m = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    scene_add_quad(scene, vec3(0, 0, 0), vec3(2, 0, 0), vec3(0, 0, 0.5), m);
    scene_add_sphere(scene, vec3(0, 2, 0), 0.7, m);
    struct vec3 v[3] = {vec3(0, 0, 2), vec3(1, 0, 2), vec3(0, 1, 2)};
    scene_add_triangle(scene, v, NULL, m);
    finish_test_scene(scene);
    return scene;
}

/* truth: closed forms of the area of a (u, v) rectangle: a quad's |e1 x e2| du dv, a
 *   sphere's r^2 2 pi du (cos pi v0 - cos pi v1); cells of a 7 x 5 grid sum to the whole
 *   area (1 and 4 pi r^2); a triangle has no parameters (-1, no extent). Then a photon of
 *   energy equal to its element's area, deposited at each element's centre (DI) and at
 *   a CI element's centre, makes that element's irradiance exactly 1 after finishing,
 *   whatever the element's size (the sphere's shrink towards its poles); a caustic
 *   lookup is 0 where no caustic photon landed; the all-photon lookup is DI plus CI; a
 *   CI sub-map exists only where a caustic photon landed.
 * tolerance: 1e-12 relative (a few roundings).
 * catches: an element's area from the wrong cell, the sphere's area uniform in v, CI
 *   sub-maps made for every element, caustic photons added to DI, u and v swapped. */
static void test_illumination_maps(struct check *t)
{
    struct scene *scene = illumination_scene();
    const struct geometry *g = scene->geometry;
    double lu, lv, sum[2] = {0, 0};
    for (int k = 0; k < 35; k++)
        for (int prim = 0; prim < 2; prim++)
            sum[prim] += geometry_uv_area(g, prim, (k % 7) / 7.0, (k % 7 + 1) / 7.0,
                                          (k / 7) / 5.0, (k / 7 + 1) / 5.0);
    CHECK_CLOSE(t, sum[0], 1.0, 1e-12);
    CHECK_CLOSE(t, sum[1], 4 * PI * 0.49, 1e-12);
    CHECK_CLOSE(t, geometry_uv_area(g, 1, 0, 0.25, 0, 0.5), 0.49 * 2 * PI * 0.25, 1e-12);
    CHECK(t, geometry_uv_area(g, 2, 0, 1, 0, 1) == -1 && !geometry_uv_extent(g, 2, &lu, &lv));
    static const double footprint[3] = {1.0 / 256, 1.0 / 256, 0}; /* CI 8 x 8 per DI */
    struct illumination_maps *maps = illumination_maps_create(g, 2.0, footprint, NULL);
    CHECK(t, illumination_covers(maps, 0) && illumination_covers(maps, 1) &&
             !illumination_covers(maps, 2));
    static const unsigned char only_the_square[3] = {1, 0, 1};
    struct illumination_maps *square = illumination_maps_create(g, 2.0, footprint,
                                                                only_the_square);
    CHECK(t, illumination_covers(square, 0) && !illumination_covers(square, 1));
    illumination_maps_free(square);
    int n_u[2], n_v[2]; /* elements: about 2 / 64 across */
    for (int prim = 0; prim < 2; prim++) {
        geometry_uv_extent(g, prim, &lu, &lv);
        n_u[prim] = (int)ceil(lu * 32);
        n_v[prim] = (int)ceil(lv * 32);
        for (int j = 0; j < n_v[prim]; j++)
            for (int i = 0; i < n_u[prim]; i++) {
                double a = geometry_uv_area(g, prim, (double)i / n_u[prim],
                                            (i + 1.0) / n_u[prim], (double)j / n_v[prim],
                                            (j + 1.0) / n_v[prim]);
                illumination_deposit(maps, prim, (i + 0.5) / n_u[prim], (j + 0.5) / n_v[prim],
                                     vec3(a, 2 * a, 3 * a), 0);
            }
    }
    /* one caustic photon in the CI element (3, 5) of the sphere's DI element (10, 4) */
    double cu = (10 + 3.5 / 8) / n_u[1], cv = (4 + 5.5 / 8) / n_v[1];
    double ca = geometry_uv_area(g, 1, (10 + 3.0 / 8) / n_u[1], (10 + 4.0 / 8) / n_u[1],
                                 (4 + 5.0 / 8) / n_v[1], (4 + 6.0 / 8) / n_v[1]);
    illumination_deposit(maps, 1, cu, cv, vec3(ca, ca, ca), 1);
    illumination_maps_finish(maps, g);
    int exact = 1;
    for (int prim = 0; prim < 2; prim++)
        for (int j = 0; j < n_v[prim]; j++)
            for (int i = 0; i < n_u[prim]; i++) {
                struct vec3 e = illumination_irradiance(maps, prim, (i + 0.2) / n_u[prim],
                                                        (j + 0.9) / n_v[prim], 0);
                exact = exact && fabs(e.x - 1) < 1e-12 && fabs(e.z - 3) < 3e-12;
            }
    CHECK(t, exact);
    CHECK_CLOSE(t, illumination_irradiance(maps, 1, cu, cv, 1).y, 1.0, 1e-12);
    CHECK_CLOSE(t, illumination_irradiance(maps, 1, cu, cv, 0).y, 3.0, 1e-12);
    CHECK(t, illumination_irradiance(maps, 1, cu + 0.5 / 8 / n_u[1], cv, 1).y == 0);
    CHECK(t, illumination_irradiance(maps, 0, 0.5, 0.5, 1).y == 0);
    struct illumination_stats st = illumination_maps_stats(maps);
    CHECK(t, st.n_maps == 2 && st.ci_maps == 1 &&
             st.di_elements == (size_t)(n_u[0] * n_v[0] + n_u[1] * n_v[1]));
    illumination_maps_free(maps);
    scene_free(scene);
}

void test_trace_estimates(struct check *t)
{
    RUN_TEST(t, test_point_over_plane_estimate);
    RUN_TEST(t, test_cone_filter_uniform);
    RUN_TEST(t, test_estimate_boundaries);
    RUN_TEST(t, test_irradiance_uniform);
    RUN_TEST(t, test_irradiance_rules);
    RUN_TEST(t, test_differential_checking_edge);
    RUN_TEST(t, test_illumination_maps);
}
