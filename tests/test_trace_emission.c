/*
 * tests/test_trace_emission.c -- photon emission (scene/emit.h): the densities every kind
 * of light emits by, the flux each channel carries when lights are picked by power, and
 * emission directed towards target spheres, against closed forms and plain emission.
 * Tracing itself is test_trace.c's.
 *
 * Statistical checks use fixed seeds and standard errors estimated from the same samples.
 * A caustic map's path stores at most one photon (it ends at the first diffuse bounce),
 * and so does a path whose first hits alone are kept: there the stored photons are the
 * paths' independent contributions.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "../src/photon/trace.h"
#include "../src/scene/emit.h"
#include "check.h"
#include "tests.h"
#include "trace_fixtures.h"
#include "truths.h"

/* ---- emission ---- */

/* Emits n photons from l with light_emit() and checks what emit.h promises. Returns the
 * number of checks failed (so the caller can CHECK it and still report which light). */
static int check_emission(const struct light *l, size_t n, uint64_t index)
{
    struct tally cos_tally = {0, 0, 0}, centroid[3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    int failed = 0;
    for (size_t i = 0; i < n; i++) {
        struct rng r = test_rng(index, i);
        double u[4];
        for (int k = 0; k < 4; k++)
            u[k] = rng_uniform(&r);
        struct emission e;
        if (!light_emit(l, u, &e) || e.weight != 1.0 || fabs(vec3_length(e.dir) - 1) > 1e-12)
            return failed + 1;
        /* the point light's "cos" is the direction's z, whose mean is 0 and z^2's 1/3 */
        double c = l->kind == LIGHT_POINT ? e.dir.z : vec3_dot(e.dir, e.normal);
        failed += l->kind != LIGHT_POINT && !(c > 0); /* only the front emits */
        tally_add(&cos_tally, l->kind == LIGHT_POINT ? c * c : c);
        tally_add(&centroid[0], e.origin.x);
        tally_add(&centroid[1], e.origin.y);
        tally_add(&centroid[2], e.origin.z);
        if (l->kind == LIGHT_SPHERE)
            failed += fabs(vec3_length(vec3_sub(e.origin, l->position)) - l->radius) > 1e-12;
    }
    cos_tally.n = (double)n;
    double expected = l->kind == LIGHT_POINT ? 1.0 / 3.0 : 2.0 / 3.0; /* E[cos] for cos/pi */
    failed += fabs(cos_tally.sum / n - expected) > 4 * tally_se(&cos_tally) / n;
    struct vec3 mean_origin = l->position; /* point, sphere: the centre */
    if (l->kind == LIGHT_QUAD)
        mean_origin = vec3_madd(l->position, vec3_add(l->e1, l->e2), 0.5);
    if (l->kind == LIGHT_TRIANGLE)
        mean_origin = vec3_madd(l->position, vec3_add(l->e1, l->e2), 1.0 / 3.0);
    for (int a = 0; a < 3; a++) {
        centroid[a].n = (double)n;
        double se = tally_se(&centroid[a]) / n;
        failed += fabs(centroid[a].sum / n - vec3_get(mean_origin, a)) > 4 * se + 1e-12;
    }
    return failed;
}

/* truth: the densities emit.h states: directions cosine-distributed about the front
 *   normal (E[cos] = 2/3) for area lights, uniform over the sphere (E[z^2] = 1/3) for a
 *   point light; origins uniform by area (their mean is the centroid: the quad's and
 *   triangle's centres, the sphere's centre) and on the surface; weight exactly 1.
 * tolerance: 4 standard errors of each mean from the same 40000 samples (4 rather than
 *   3: sixteen means are tested at once).
 * catches: a uniform instead of a cosine hemisphere (E[cos] = 1/2), emission from the
 *   back, a triangle sampled without the square root (centroid moves towards v0), a
 *   sphere sampled in angle instead of by area, the point light's directions bunched
 *   at the poles. */
static void test_emission_densities(struct check *t)
{
    struct light l;
    memset(&l, 0, sizeof l);
    l.radiance = vec3(1, 1, 1);
    l.power = vec3(1, 1, 1);
    l.kind = LIGHT_POINT;
    l.position = vec3(0.5, -2, 3);
    CHECK(t, check_emission(&l, 40000, 1) == 0);
    l.kind = LIGHT_SPHERE;
    l.radius = 0.7;
    CHECK(t, check_emission(&l, 40000, 2) == 0);
    l.kind = LIGHT_QUAD;
    l.e1 = vec3(2, 0, 0.5);
    l.e2 = vec3(0, 0.3, 1);
    CHECK(t, check_emission(&l, 40000, 3) == 0);
    l.kind = LIGHT_TRIANGLE;
    CHECK(t, check_emission(&l, 40000, 4) == 0);
    l.e2 = vec3_scale(l.e1, 2); /* no area: no photon */
    double u[4] = {0.5, 0.5, 0.5, 0.5};
    struct emission e;
    CHECK(t, light_emit(&l, u, &e) == 0);
}

/* The closed unit box with the given floor material (exactly [0, 1]^2, so an emitting
 * floor emits only inside) and walls of albedo 0.5 reaching 0.1 beyond the cube. */
static void add_closed_box(struct scene *scene, int floor, int wall)
{
    add_square(scene, vec3(0.5, 0, 0.5), 0.5, 1, floor);
    add_square(scene, vec3(0.5, 1, 0.5), 0.6, 0, wall);
    scene_add_quad(scene, vec3(0, -0.1, -0.1), vec3(0, 1.2, 0), vec3(0, 0, 1.2), wall);
    scene_add_quad(scene, vec3(1, -0.1, -0.1), vec3(0, 0, 1.2), vec3(0, 1.2, 0), wall);
    scene_add_quad(scene, vec3(-0.1, -0.1, 0), vec3(1.2, 0, 0), vec3(0, 1.2, 0), wall);
    scene_add_quad(scene, vec3(-0.1, -0.1, 1), vec3(0, 1.2, 0), vec3(1.2, 0, 0), wall);
}

/* truth: every photon leaves some light and, in a closed box whose every surface holds
 *   photons, is stored exactly once as PHOTON_DIRECT. Lights are picked by luminance
 *   with probability p_l and each carries Phi_l / (p_l N), so (a) every photon's
 *   luminance is the same, lum(Phi_total) / N, and (b) per channel the direct flux sums
 *   to Phi_total in expectation (it is random through how many photons each light got).
 * tolerance: (a) the record's rounding, max channel / 255.5; (b) 3 standard errors of
 *   the sum of 50000 iid first-hit powers, plus the rounding bound.
 * catches: picking lights uniformly but weighting by power (or the reverse), a missing
 *   1/p_pick, a light kind whose power or emission density disagree, photons stored twice
 *   or lost at a first hit, a channel taken from the wrong light. */
static void test_emission_flux_per_channel(struct check *t)
{
    struct scene *scene = scene_create();
    int floor = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5),
                                  vec3(0.3, 0.1, 0.05));
    int wall = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3(0, 0, 0));
    int glow = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3(0.1, 2, 0.4));
    add_closed_box(scene, floor, wall);
    scene_add_sphere(scene, vec3(0.5, 0.6, 0.5), 0.1, glow);
    struct vec3 tri[3] = {vec3(0.2, 0.2, 0.2), vec3(0.4, 0.2, 0.2), vec3(0.2, 0.4, 0.3)};
    scene_add_triangle(scene, tri, NULL, glow);
    scene_add_point_light(scene, vec3(0.7, 0.3, 0.6), vec3(1, 0.5, 3));
    finish_test_scene(scene);
    struct vec3 phi = vec3_zero();
    for (size_t l = 0; l < scene->n_lights; l++)
        phi = vec3_add(phi, light_power(&scene->lights[l]));
    size_t n = 50000;
    struct photon_trace tr = trace(scene, n, PHOTON_DIRECT, 0, NULL);
    CHECK(t, tr.n_photons == n && tr.n_direct == n);
    struct tally c[3] = {{0, 0, (double)n}, {0, 0, (double)n}, {0, 0, (double)n}};
    double rounding = 0, lum = vec3_luminance(phi) / n;
    for (size_t i = 0; i < tr.n_photons; i++) {
        struct vec3 p = photon_power(&tr.photons[i]);
        double bound = vec3_max_component(p) * RGBE_REL * (1 + 1e-9);
        CHECK(t, fabs(vec3_luminance(p) - lum) <= bound);
        rounding += bound;
        for (int a = 0; a < 3; a++)
            tally_add(&c[a], vec3_get(p, a));
    }
    for (int a = 0; a < 3; a++)
        CHECK_CLOSE(t, c[a].sum, vec3_get(phi, a), 3 * tally_se(&c[a]) + rounding);
    photon_trace_free(&tr);
    scene_free(scene);
}

/* Whether the ray from o along unit d meets sphere s (the test's own ray-sphere test). */
static int ray_meets_sphere(struct vec3 o, struct vec3 d, const struct bounding_sphere *s)
{
    struct vec3 oc = vec3_sub(o, s->centre);
    double b = vec3_dot(oc, d), c = vec3_length2(oc) - s->radius * s->radius;
    return c < 0 || (b < 0 && b * b - c >= 0);
}

/* Flux (in units of Phi_l) that n photons from l carry into the targets: undirected
 * photons counted when they meet a sphere, directed ones by their weights. */
static struct tally flux_into(const struct light *l, const struct emission_targets *targets,
                              int directed, size_t n, uint64_t index)
{
    struct tally f = {0, 0, (double)n};
    for (size_t i = 0; i < n; i++) {
        struct rng r = test_rng(index, i);
        double u[5];
        for (int k = 0; k < 5; k++)
            u[k] = rng_uniform(&r);
        struct emission e;
        if (directed ? !light_emit_towards(l, targets, u, &e) : !light_emit(l, u, &e))
            continue;
        int meets = 0;
        for (size_t s = 0; s < targets->n_spheres; s++)
            meets |= ray_meets_sphere(e.origin, e.dir, &targets->spheres[s]);
        if (directed || meets)
            tally_add(&f, e.weight / n);
    }
    return f;
}

/* truth: directed and undirected emission estimate the same flux into the targets; from
 *   a point light into one sphere of radius r at distance d every directed photon has
 *   weight Omega / (4 pi) = (1 - sqrt(1 - r^2/d^2)) / 2 exactly; a target around the
 *   light makes directed emission the whole emission (flux 1); the sky's photons into
 *   one sphere of radius r inside the sky's of radius R each carry r^2 / R^2 (its share
 *   of the sky's power Le pi R^2 4 pi), and start outside the sky's sphere.
 * tolerance: 3 combined standard errors of the two estimates (20000 photons each); the
 *   single-sphere weight to 1e-12.
 * catches: the union's density taken as the sum of cone densities without the count of
 *   overlapping cones (overlap counted twice), cones picked uniformly instead of by
 *   solid angle, the area light's cosine missing from the weight, directions behind an
 *   area light given power, a cone half-angle from tan instead of sin; the sky's targets
 *   picked uniformly instead of by r^2, overlapping discs counted twice. */
static void test_directed_emission_flux(struct check *t)
{
    struct bounding_sphere spheres[3] = {{{0.2, 3, 0}, 1}, {{0.9, 3.2, 0.3}, 0.8},
                                         {{0, 0, 0}, 5}};
    struct bounding_sphere sky_sphere = {{0, 2, 0}, 6};
    struct emission_targets two = {spheres, 2}, around = {spheres + 2, 1};
    struct light l;
    memset(&l, 0, sizeof l);
    l.kind = LIGHT_POINT;
    l.power = vec3(1, 1, 1);
    for (int kind = 0; kind < 3; kind++) {
        if (kind == 1) {
            l.kind = LIGHT_QUAD; /* a 1 x 1 square at y = 0 facing up: e1 x e2 = +y */
            l.position = vec3(-0.5, 0, 0.5);
            l.e1 = vec3(1, 0, 0);
            l.e2 = vec3(0, 0, -1);
        } else if (kind == 2) { /* the sky around both targets; its own sphere is all of it */
            l.kind = LIGHT_SKY;
            l.position = sky_sphere.centre;
            l.radius = sky_sphere.radius;
            around.spheres = &sky_sphere;
        }
        struct tally a = flux_into(&l, &two, 0, 20000, 10 + kind);
        struct tally b = flux_into(&l, &two, 1, 20000, 20 + kind);
        double se = sqrt(tally_se(&a) * tally_se(&a) + tally_se(&b) * tally_se(&b));
        CHECK(t, a.sum > 0.01 && se < 0.1 * a.sum);
        CHECK_CLOSE(t, b.sum, a.sum, 3 * se);
        struct tally whole = flux_into(&l, &around, 1, 20000, 30 + kind);
        CHECK_CLOSE(t, whole.sum, 1.0, 3 * tally_se(&whole) + 1e-12);
    }
    l.kind = LIGHT_POINT;
    l.position = vec3(0, 0, 0);
    struct emission_targets one = {spheres, 1};
    double d2 = vec3_length2(spheres[0].centre);
    double u[5] = {0.1, 0.2, 0.3, 0.4, 0.5};
    struct emission e;
    CHECK(t, light_emit_towards(&l, &one, u, &e) == 1);
    CHECK_CLOSE(t, e.weight, (1 - sqrt(1 - 1 / d2)) / 2, 1e-12);
    CHECK(t, ray_meets_sphere(e.origin, e.dir, &spheres[0]));
    /* the sky sends r^2 / R^2 of its power into a sphere of radius r inside its own */
    l.kind = LIGHT_SKY;
    l.position = sky_sphere.centre;
    l.radius = sky_sphere.radius;
    CHECK(t, light_emit_towards(&l, &one, u, &e) == 1);
    CHECK_CLOSE(t, e.weight, 1.0 / 36.0, 1e-12);
    CHECK(t, ray_meets_sphere(e.origin, e.dir, &spheres[0]));
    CHECK(t, vec3_length(vec3_sub(e.origin, sky_sphere.centre)) >= sky_sphere.radius);
}

/* A glass ball of radius 0.5 at (0, 1, 0) over a large diffuse floor, lit by a point
 * light (area = 0) or a 0.4 x 0.4 quad light facing down (area = 1) above it. */
static struct scene *glass_ball_scene(int area)
{
    struct scene *scene = scene_create();
    int floor = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    int glass = add_test_material(scene, MATERIAL_GLASS, vec3_zero(), vec3_zero());
    int light = add_test_material(scene, MATERIAL_LAMBERT, vec3_zero(), vec3(50, 50, 50));
    add_square(scene, vec3(0, 0, 0), 50, 1, floor);
    scene_add_sphere(scene, vec3(0, 1, 0), 0.5, glass);
    if (area)
        add_square(scene, vec3(0.3, 3, 0.1), 0.2, 0, light);
    else
        scene_add_point_light(scene, vec3(0.3, 3, 0.1), vec3(100, 100, 100));
    finish_test_scene(scene);
    return scene;
}

/* The caustic flux stored on the floor within `radius` of the ball's foot, with its
 * standard error: a caustic map's path stores at most one photon (its path ends at the
 * first diffuse bounce), so the stored photons are the nonzero path contributions. */
static struct tally caustic_flux(const struct photon_trace *tr, double radius)
{
    struct tally f = {0, 0, (double)tr->n_emitted};
    for (size_t i = 0; i < tr->n_photons; i++) {
        struct vec3 x = photon_position(&tr->photons[i]);
        if (x.x * x.x + x.z * x.z <= radius * radius)
            tally_add(&f, photon_power(&tr->photons[i]).y);
    }
    return f;
}

/* truth: the caustic a glass ball focuses on a diffuse floor is the same light whether
 *   photons are emitted everywhere or only towards the ball's bounding sphere (here the
 *   ball itself); compared as the flux (irradiance times area) in a disc under the ball
 *   and on the whole floor, for a point light and for a quad light.
 * tolerance: 3 combined standard errors (200000 undirected photons, 20000 directed) plus
 *   the record's rounding (1/255.5 of the flux).
 * catches: directed photons carrying Phi / N instead of the solid-angle fraction, a
 *   directed cone aimed from the light's corner or centre rather than from each origin,
 *   caustic photons classed as direct or indirect. (Refraction's 1/eta^2, wrongly
 *   applied to power, would cancel between entering and leaving the ball: not tested
 *   here.) */
static void test_directed_caustic_irradiance(struct check *t)
{
    for (int area = 0; area < 2; area++) {
        struct scene *scene = glass_ball_scene(area);
        struct bounding_sphere ball = {{0, 1, 0}, 0.5};
        struct emission_targets targets = {&ball, 1};
        struct photon_trace all = trace(scene, 200000, PHOTON_MAP_CAUSTIC, 0, NULL);
        struct photon_trace aimed = trace(scene, 20000, PHOTON_MAP_CAUSTIC, 1, &targets);
        CHECK(t, all.n_caustic == all.n_photons && aimed.n_caustic == aimed.n_photons);
        CHECK(t, all.n_photons > 1000 && aimed.n_photons > 1000);
        for (int whole = 0; whole < 2; whole++) {
            double radius = whole ? 1e9 : 0.3;
            struct tally a = caustic_flux(&all, radius), b = caustic_flux(&aimed, radius);
            double se = sqrt(tally_se(&a) * tally_se(&a) + tally_se(&b) * tally_se(&b));
            CHECK(t, a.sum > 0 && se < 0.1 * a.sum);
            CHECK_CLOSE(t, b.sum, a.sum, 3 * se + a.sum * RGBE_REL);
        }
        photon_trace_free(&aimed);
        photon_trace_free(&all);
        scene_free(scene);
    }
}

void test_trace_emission(struct check *t)
{
    RUN_TEST(t, test_emission_densities);
    RUN_TEST(t, test_emission_flux_per_channel);
    RUN_TEST(t, test_directed_emission_flux);
    RUN_TEST(t, test_directed_caustic_irradiance);
}
