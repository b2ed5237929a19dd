/*
 * tests/test_trace.c -- photon emission, photon tracing, the radiance estimates and
 * `--mode photons`, against closed forms and against each other.
 *
 * Statistical checks use fixed seeds and standard errors estimated from the same
 * photons. Photon powers after Russian roulette are not identically distributed
 * photon by photon, but the paths are independent and identically distributed: a path's
 * contribution (the sum of the powers it stored) is the unit whose variance is
 * estimated. Where a path can store at most one photon of the class summed (first hits,
 * caustics ending a caustic map's path), the stored photons in path order are those
 * contributions; elsewhere each path is traced alone (n_emit = 1, pass = path index).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/image/image.h"
#include "../src/modes/photons.h"
#include "../src/photon/estimate.h"
#include "../src/photon/illumination_map.h"
#include "../src/photon/trace.h"
#include "../src/scene/emit.h"
#include "check.h"
#include "files.h"
#include "tests.h"
#include "truths.h"

#define SEED 11            /* every trace in this file */
#define TEST_MAX_DEPTH 1000 /* bounces: roulette ends paths long before */
#define RGBE_REL (1.0 / 255.5) /* photon.h: each channel within max(R, G, B) / 255.5 */

/* ---- helpers ---- */

/* The square |x - cx|, |z - cz| <= half in the plane y, its front facing +y (up) or -y. */
static void add_square(struct scene *scene, struct vec3 centre, double half, int up, int m)
{
    struct vec3 p0 = vec3(centre.x - half, centre.y, centre.z - half);
    struct vec3 ex = vec3(2 * half, 0, 0), ez = vec3(0, 0, 2 * half);
    if (up)
        scene_add_quad(scene, p0, ez, ex, m); /* ez x ex = +y */
    else
        scene_add_quad(scene, p0, ex, ez, m); /* ex x ez = -y */
}

static struct photon_trace trace(const struct scene *scene, size_t n, unsigned store,
                                 uint64_t pass, const struct emission_targets *targets)
{
    struct trace_settings ts;
    ts.seed = SEED;
    ts.pass = pass;
    ts.n_emit = n;
    ts.max_stored = MAX_PHOTONS;
    ts.store = store;
    ts.max_depth = TEST_MAX_DEPTH;
    ts.targets = targets;
    ts.projection = NULL;
    struct photon_trace out;
    struct error err;
    if (trace_photons(scene, &ts, &out, &err) < 0)
        error_print(&err);
    return out;
}

static struct rng test_rng(uint64_t index, uint64_t sub)
{
    return rng_stream(SEED, STREAM_TEST, index, sub);
}

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

/* ---- tracing ---- */

/* Per-channel totals of n paths traced one at a time (photon i alone, pass i), each
 * path's stored power summed: the iid contributions. first: the same for first hits;
 * *direct_exact: whether every path stored exactly one direct photon of power Phi. */
static void trace_paths(const struct scene *scene, size_t n, struct tally total[3],
                        struct tally first[3], int *direct_exact)
{
    struct vec3 phi = light_power(&scene->lights[0]);
    *direct_exact = 1;
    for (int a = 0; a < 3; a++) {
        total[a].sum = total[a].sum2 = first[a].sum = first[a].sum2 = 0;
        total[a].n = first[a].n = (double)n;
    }
    for (size_t i = 0; i < n; i++) {
        struct photon_trace tr = trace(scene, 1, PHOTON_MAP_GLOBAL, i, NULL);
        struct vec3 path = vec3_zero(), direct = vec3_zero();
        for (size_t p = 0; p < tr.n_photons; p++) {
            struct vec3 power = photon_power(&tr.photons[p]);
            path = vec3_add(path, power);
            if (tr.photons[p].flags & PHOTON_DIRECT)
                direct = vec3_add(direct, power);
        }
        *direct_exact &= tr.n_direct == 1 && vec3_length2(vec3_sub(direct, phi)) == 0;
        for (int a = 0; a < 3; a++) {
            tally_add(&total[a], vec3_get(path, a));
            tally_add(&first[a], vec3_get(direct, a));
        }
        photon_trace_free(&tr);
    }
}

/* truth: scenes/analytic/closed-box.scene, a point light of Phi = 1 W inside a closed
 *   Lambertian box: the flux stored at first hits is Phi, and over all bounces
 *   Phi (1 + rho + rho^2 + ...) = Phi / (1 - rho), per channel. Grey rho = 0.5 (total
 *   2 W); then the walls recoloured to rho = (0.8, 0.4, 0.2) (totals 5, 5/3, 5/4 W).
 * tolerance: first hits exactly Phi (1 W is exact in the record and a grey first hit
 *   has had no roulette); totals within 3 standard errors of 20000 independent paths,
 *   plus the record's rounding for the coloured box (a power that has taken the walls'
 *   colour is no longer exact: at most the largest channel / 255.5 per stored photon).
 * catches: roulette without dividing by q (the grey total would be 4/3), storing after
 *   instead of before the roulette (total 1 instead of 2), photons lost through the
 *   box's seams, first hits not classed as direct, a depth limit cutting paths, a
 *   channel scaled by another's albedo. (Any q in (0, 1] keeps the sums unbiased, so
 *   the choice of q is not what this tests.) */
static void test_closed_box_flux(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/closed-box.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    CHECK(t, scene->n_lights == 1 && scene->n_materials == 1);
    struct tally total[3], first[3];
    int direct_exact = 0;
    trace_paths(scene, 20000, total, first, &direct_exact);
    CHECK(t, direct_exact);
    for (int a = 0; a < 3; a++) {
        CHECK(t, first[a].sum == 20000);
        CHECK_CLOSE(t, total[a].sum / 20000, 2.0, 3 * tally_se(&total[a]) / 20000);
    }
    scene->materials[0].rho = vec3(0.8, 0.4, 0.2);
    trace_paths(scene, 20000, total, first, &direct_exact);
    CHECK(t, direct_exact);
    double rounding = total[0].sum * RGBE_REL; /* channel 0 is the largest throughout */
    for (int a = 0; a < 3; a++) {
        double rho = vec3_get(scene->materials[0].rho, a);
        CHECK_CLOSE(t, total[a].sum / 20000, 1 / (1 - rho),
                    (3 * tally_se(&total[a]) + rounding) / 20000);
    }
    scene_free(scene);
}

/* A point light of 1000 W at (0, 1, 0) over a 200 x 200 Lambertian floor (rho = 0.5)
 * and, if `mirror`, a 1 x 1 mirror of reflectance 0.8 at height 2 facing down. */
static struct scene *mirror_scene(int mirror)
{
    struct scene *scene = scene_create();
    int floor = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    int chrome = add_test_material(scene, MATERIAL_MIRROR, vec3(0.8, 0.8, 0.8), vec3_zero());
    add_square(scene, vec3(0, 0, 0), 100, 1, floor);
    if (mirror)
        add_square(scene, vec3(0, 2, 0), 0.5, 0, chrome);
    scene_add_point_light(scene, vec3(0, 1, 0), vec3(1000, 1000, 1000));
    finish_test_scene(scene);
    return scene;
}

/* truth: a mirror in front of a wall makes a caustic; without it there is none. The
 *   point light sees the 1 x 1 mirror at distance 1 in the solid angle
 *   Omega = 4 asin(a b / sqrt((a^2 + 4 d^2)(b^2 + 4 d^2))) = 4 asin(1/5) (a rectangle
 *   seen from its axis), so the caustic flux is rho_m Phi Omega / (4 pi), and it lands
 *   where the image source (0, 3, 0) sees the mirror: |x|, |z| <= 1.5.
 * tolerance: the flux within 3 binomial standard errors (100000 photons, about 5000 of
 *   them caustic) plus the record's rounding; the footprint to 1e-6.
 * catches: mirror bounces counted as diffuse (the caustic classed indirect), a caustic
 *   map storing the first (direct) hit, roulette at a mirror not divided by q, classes
 *   leaking into a scene without specular surfaces. */
static void test_mirror_caustic_classes(struct check *t)
{
    size_t n = 100000;
    struct scene *plain = mirror_scene(0);
    struct photon_trace tr = trace(plain, n, PHOTON_MAP_GLOBAL, 0, NULL);
    CHECK(t, tr.n_direct > 0 && tr.n_caustic == 0 && tr.n_indirect == 0);
    photon_trace_free(&tr);
    scene_free(plain);
    struct scene *scene = mirror_scene(1);
    tr = trace(scene, n, PHOTON_MAP_GLOBAL, 0, NULL);
    CHECK(t, tr.n_caustic > 0 && tr.n_indirect > 0 && tr.n_shadow == 0);
    struct tally f = {0, 0, (double)n};
    for (size_t i = 0; i < tr.n_photons; i++) {
        if (!(tr.photons[i].flags & PHOTON_CAUSTIC))
            continue;
        struct vec3 x = photon_position(&tr.photons[i]);
        CHECK(t, fabs(x.y) < 1e-6 && fabs(x.x) <= 1.5 + 1e-6 && fabs(x.z) <= 1.5 + 1e-6);
        tally_add(&f, photon_power(&tr.photons[i]).y);
    }
    double expected = 0.8 * 1000 * 4 * asin(0.2) / (4 * PI);
    CHECK_CLOSE(t, f.sum, expected, 3 * tally_se(&f) + expected * RGBE_REL);
    photon_trace_free(&tr);
    tr = trace(scene, n, PHOTON_MAP_CAUSTIC, 0, NULL);
    CHECK(t, tr.n_photons == tr.n_caustic && tr.n_direct == 0 && tr.n_indirect == 0);
    photon_trace_free(&tr);
    scene_free(scene);
}

/* truth: Jensen and Christensen 1995: a light ray followed through the occluder (a
 *   0.5 x 0.5 square at height 1 under a point light at height 2) stores one shadow
 *   photon on the floor behind it, so there are exactly as many shadow photons as
 *   direct photons on the occluder; all of them lie in the occluder's shadow
 *   (|x|, |z| <= 0.5), no direct floor photon does, and each carries zero power and the
 *   direction back towards the light. Without the option there are none.
 * tolerance: positions to 1e-6 (floats of values near 1); directions to the record's
 *   1.06 degrees.
 * catches: shadow photons stored at the first hit, or with power (they would brighten
 *   estimates), the continued ray re-hitting the occluder, direct photons leaking into
 *   the shadow, the direction pointing away from the light. */
static void test_shadow_photons(struct check *t)
{
    struct scene *scene = scene_create();
    int grey = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    add_square(scene, vec3(0, 0, 0), 100, 1, grey);
    add_square(scene, vec3(0, 1, 0), 0.25, 1, grey);
    struct vec3 light = vec3(0, 2, 0);
    scene_add_point_light(scene, light, vec3(10, 10, 10));
    finish_test_scene(scene);
    struct photon_trace tr = trace(scene, 50000, PHOTON_MAP_GLOBAL | PHOTON_SHADOW, 0, NULL);
    size_t on_occluder = 0;
    CHECK(t, tr.n_shadow > 100);
    for (size_t i = 0; i < tr.n_photons; i++) {
        const struct photon *p = &tr.photons[i];
        struct vec3 x = photon_position(p);
        int in_shadow = fabs(x.x) <= 0.5 + 1e-6 && fabs(x.z) <= 0.5 + 1e-6;
        int on_floor = fabs(x.y) < 1e-6;
        on_occluder += (p->flags & PHOTON_DIRECT) && !on_floor;
        if (p->flags & PHOTON_DIRECT)
            CHECK(t, !(on_floor && fabs(x.x) < 0.5 - 1e-6 && fabs(x.z) < 0.5 - 1e-6));
        if (!(p->flags & PHOTON_SHADOW))
            continue;
        struct vec3 to_light = vec3_normalize(vec3_sub(light, x));
        CHECK(t, on_floor && in_shadow && vec3_length2(photon_power(p)) == 0);
        CHECK(t, vec3_dot(photon_direction(p), to_light) >= cos(PI / 510 + PI / 256));
    }
    CHECK(t, on_occluder == tr.n_shadow);
    photon_trace_free(&tr);
    tr = trace(scene, 10000, PHOTON_MAP_GLOBAL, 0, NULL);
    CHECK(t, tr.n_shadow == 0);
    photon_trace_free(&tr);
    scene_free(scene);
}

/* truth: none; both sides are the same computation. Photon i's path depends only on its
 *   stream, so the same seed gives the same bytes, and a trace of 2N photons begins with
 *   the N-photon trace's photons at the same places, each with exactly twice the power
 *   (Phi / N against Phi / (2N): doubling is exact in binary).
 * tolerance: none (bytes and exact doubles).
 * catches: random numbers shared between photons, state carried from one photon to the
 *   next, powers depending on anything but N. */
static void test_trace_determinism(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/cornell.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct photon_trace a = trace(scene, 2000, PHOTON_MAP_GLOBAL, 3, NULL);
    struct photon_trace b = trace(scene, 2000, PHOTON_MAP_GLOBAL, 3, NULL);
    struct photon_trace half = trace(scene, 1000, PHOTON_MAP_GLOBAL, 3, NULL);
    CHECK(t, a.n_photons == b.n_photons && a.n_photons > 2000);
    CHECK(t, memcmp(a.photons, b.photons, a.n_photons * sizeof *a.photons) == 0);
    CHECK(t, half.n_photons < a.n_photons);
    for (size_t i = 0; i < half.n_photons && i < a.n_photons; i++) {
        const struct photon *p = &half.photons[i], *q = &a.photons[i];
        CHECK(t, memcmp(p->pos, q->pos, sizeof p->pos) == 0 && p->flags == q->flags);
        CHECK(t, p->theta == q->theta && p->phi == q->phi);
        struct vec3 doubled = vec3_scale(photon_power(q), 2.0);
        CHECK(t, vec3_length2(vec3_sub(photon_power(p), doubled)) == 0);
    }
    photon_trace_free(&half);
    photon_trace_free(&b);
    photon_trace_free(&a);
    scene_free(scene);
}

/* truth: the contract: more stored photons than max_stored fail with a message and
 *   leave nothing allocated; exactly max_stored succeed.
 * tolerance: none.
 * catches: a map silently truncated (Jensen's store() drops photons when full), a
 *   failure that leaks the array. */
static void test_trace_refuses_overflow(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/closed-box.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct photon_trace full = trace(scene, 100, PHOTON_MAP_GLOBAL, 0, NULL);
    struct trace_settings ts = {SEED, 0, 100, 0, PHOTON_MAP_GLOBAL, TEST_MAX_DEPTH, NULL, NULL};
    struct photon_trace out;
    struct error err;
    ts.max_stored = full.n_photons;
    CHECK(t, trace_photons(scene, &ts, &out, &err) == 0 && out.n_photons == full.n_photons);
    photon_trace_free(&out);
    ts.max_stored = full.n_photons - 1;
    err.message[0] = '\0';
    CHECK(t, trace_photons(scene, &ts, &out, &err) == -1);
    CHECK(t, out.photons == NULL && out.n_photons == 0 && strstr(err.message, "more than"));
    photon_trace_free(&full);
    scene_free(scene);
}

/* truth: photon.h's contract: photon_pack() takes powers below PHOTON_POWER_MAX (2^127 W)
 *   only, and trace.c promises no photon outside that range is stored. A light's power is
 *   set past the scene's limit by hand here (the parser refuses it: test_scene.c), so
 *   that photons leave at just under 2^127 W and a Ward lobe of rho_s = 1 between two
 *   facing planes scatters them with weights up to 2, out of range.
 * tolerance: none.
 * catches: a photon whose power grew past the record's range packed (an assertion, or
 *   a wrapped exponent byte), a light of non-representable power emitting at all. */
static void test_trace_keeps_powers_in_range(struct check *t)
{
    char path[256];
    temp_name(path, sizeof path, "trace", "slab.scene");
    write_text_file(path, "camera 0 0.5 -5 0 0.5 0 0 1 0 40\n"
                          "material w ward 0 0 0 1 1 1 0.3 0.3\n"
                          "quad -50 0 -50 -50 0 50 50 0 50 50 0 -50 w\n"
                          "quad -50 1 -50 50 1 -50 50 1 50 -50 1 50 w\n"
                          "light point 0 0.5 0 1 1 1\n");
    struct scene *scene = load_test_scene(path, 8, 8);
    remove(path);
    CHECK(t, scene != NULL && scene->n_lights == 1);
    if (scene == NULL)
        return;
    const size_t n = 200;
    scene->lights[0].power = vec3_scale(vec3(1, 0.5, 0.25), 0.99 * PHOTON_POWER_MAX * n);
    struct photon_trace tr = trace(scene, n, PHOTON_MAP_GLOBAL, 0, NULL);
    CHECK(t, tr.n_photons > n); /* the first hits, and later ones that stayed in range */
    size_t lost = 0;
    for (size_t i = 0; i < tr.n_photons; i++) {
        struct vec3 power = photon_power(&tr.photons[i]);
        CHECK(t, vec3_is_finite(power) && vec3_max_component(power) <= PHOTON_POWER_MAX);
        lost += !(vec3_max_component(power) > 0);
    }
    CHECK(t, lost == 0);
    photon_trace_free(&tr);
    scene->lights[0].power = vec3(1e300, 1e300, 1e300);
    tr = trace(scene, n, PHOTON_MAP_GLOBAL, 0, NULL);
    CHECK(t, tr.n_photons == 0);
    photon_trace_free(&tr);
    scene_free(scene);
}

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
    struct estimate_settings es = {k, HUGE_VAL, 0, 0, 0};
    double sum = 0;
    for (int i = 0; i < 17 * 17; i++) {
        struct vec3 x = vec3(-2 + 0.25 * (i % 17), 0, -2 + 0.25 * (i / 17));
        struct estimate_point at = {x, up, up, &scene->materials[0], &frame};
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
        struct estimate_settings es = {k, HUGE_VAL, cone ? 1.0 : 0.0, 0, 0};
        struct tally m = {0, 0, 441};
        for (int i = 0; i < 441; i++) {
            struct vec3 x = vec3(0.1 + 0.04 * (i % 21), 0.1 + 0.04 * (i / 21), 0);
            struct estimate_point at = {x, up, vec3(0, 0.6, 0.8), &scene->materials[0], &frame};
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
    struct estimate_point at = {vec3(0, 0, 0), up, up, &scene->materials[0], &frame};
    struct estimate_settings es = {10, HUGE_VAL, 1.0, 0, 0};
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
    struct irradiance_settings is = {k, HUGE_VAL, 0, 0, 0};
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
    struct irradiance_settings is = {8, HUGE_VAL, 0, 2, 0};
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
 *   times that without (measured: 0.62 against 0.78, 0.79 times). Far from the edge
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
            struct irradiance_settings is = {k, HUGE_VAL, 0, checking ? DIFFERENTIAL_RUN : 0, 0};
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

/* ---- --mode photons ---- */

/* truth: reference/cornell-pt.pfm, the converged path-traced Cornell box. A 32 x 32
 *   render's pixel is the mean radiance over its square, so it estimates the mean of
 *   the reference's 8 x 8 block of 256 x 256 pixels.
 * tolerance: the whole image's mean within 3% (the photon map's noise at 100000 photons
 *   and k = 100 averages out over 1024 pixels; its bias, corners darkened and edges
 *   blurred, is about 1% of the mean); every 4 x 4 group of render pixels within 20%
 *   (one group sees about 16 estimates' blotches). Groups that show the light are left
 *   out: its emission is not the map's, and 4 jittered samples of its edge per pixel
 *   are noise of order one. The stats: every photon emitted,
 *   20 bytes per photon and a map that holds something.
 * catches: black walls (photons on the wrong side of a surface), the light's emission
 *   missing, a pi or 1/N error, estimates from the far side of a wall, light leaking
 *   into corners. */
#define LIGHT_SEEN 2.0 /* a reference pixel this bright shows the light (green Le = 12) */

static void test_photons_mode_cornell(struct check *t)
{
    struct error err;
    struct scene *scene = load_test_scene("scenes/cornell.scene", 32, 32);
    struct image *ref = pfm_read("reference/cornell-pt.pfm", &err);
    CHECK(t, scene != NULL && ref != NULL && ref->width == 256);
    if (scene == NULL || ref == NULL || ref->width != 256) {
        scene_free(scene);
        image_free(ref);
        return;
    }
    struct render_settings rs = render_settings_whole(scene, 3, 16, TEST_MAX_DEPTH);
    struct photon_settings ps = {100000, 100, 0, 0, 0, NULL};
    struct render_counters counters = {0, 0, 0, 0, 0};
    struct photon_stats stats;
    struct render_result r = render_photons(scene, &rs, &ps, 0, NULL, &counters, &stats, &err);
    CHECK(t, r.image != NULL && counters.nonfinite_samples == 0);
    CHECK(t, stats.photons_emitted == 100000 && stats.photons_stored > 100000);
    CHECK(t, stats.bytes_per_photon >= 20 && stats.bytes_per_photon < 20.01);
    double sum = 0, sum_ref = 0, light = 0, light_ref = 0;
    for (int g = 0; r.image != NULL && g < 64; g++) { /* 4 x 4 of ours, 32 x 32 of theirs */
        int gx = g % 8, gy = g / 8;
        double mine = 0, theirs = 0, brightest = 0;
        for (int p = 0; p < 16; p++)
            mine += image_get(r.image, 4 * gx + p % 4, 4 * gy + p / 4).y / 16;
        for (int p = 0; p < 1024; p++) {
            double v = image_get(ref, 32 * gx + p % 32, 32 * gy + p / 32).y;
            theirs += v / 1024;
            brightest = fmax(brightest, v);
        }
        if (brightest > LIGHT_SEEN) {
            light += mine;
            light_ref += theirs;
            continue;
        }
        CHECK(t, fabs(mine - theirs) <= 0.2 * theirs);
        sum += mine;
        sum_ref += theirs;
    }
    CHECK(t, light_ref > 0 && fabs(light - light_ref) <= 0.1 * light_ref);
    CHECK(t, fabs(sum - sum_ref) <= 0.03 * sum_ref);
    render_result_free(&r);
    image_free(ref);
    scene_free(scene);
}

/* The mirror-view scene: a point light of Phi = 1000 W at (2.5, 1, 0) over a dark
 * Lambertian plane (rho = 0.01, so light that bounces twice is under 1% of the picture)
 * and, 0.5 beyond it, a 4 x 2 mirror of reflectance 0.9 standing on the plane at x = 3,
 * facing -x. Near the mirror the caustic is as bright as the direct light. */
#define MV_PHI 1000.0
#define MV_RHO 0.01
#define MV_MIRROR 0.9
#define MV_LIGHT_X 2.5

static struct scene *mirror_view_scene(void)
{
    struct scene *scene = scene_create();
    int plane = add_test_material(scene, MATERIAL_LAMBERT, vec3(MV_RHO, MV_RHO, MV_RHO),
                                  vec3_zero());
    int chrome = add_test_material(scene, MATERIAL_MIRROR, vec3(MV_MIRROR, MV_MIRROR, MV_MIRROR),
                              vec3_zero());
    add_square(scene, vec3(0, 0, 0), 100, 1, plane);
    scene_add_quad(scene, vec3(3, 0, -2), vec3(0, 0, 4), vec3(0, 2, 0), chrome); /* -x */
    scene_add_point_light(scene, vec3(MV_LIGHT_X, 1, 0), vec3(MV_PHI, MV_PHI, MV_PHI));
    finish_with_camera(scene, vec3(1, 1.5, 0), vec3(3, 0.5, 0), 40, 24, 24);
    return scene;
}

/* Closed-form radiance of the plane at p (x < 3): E = Phi h / (4 pi d^3) from the light
 * and, where the mirror's image of the light (3.5, 1, 0) sees p through the mirror, the
 * caustic MV_MIRROR Phi h / (4 pi d'^3) from that image source; L = rho E / pi. *inside
 * is set to 0 when p is within `margin` of the caustic's edge (the estimate blurs it). */
static double mirror_view_plane_radiance(struct vec3 p, double margin, int *inside)
{
    struct vec3 light = vec3(MV_LIGHT_X, 1, 0), image = vec3(6 - MV_LIGHT_X, 1, 0);
    double d = vec3_length(vec3_sub(p, light));
    double e = MV_PHI / (4 * PI * d * d * d);
    double t = (image.x - 3) / (image.x - p.x); /* where image -> p crosses x = 3 */
    double y = 1 - t, z = t * p.z;
    *inside = y > margin && y < 2 - margin && fabs(z) < 2 - margin;
    double dc = vec3_length(vec3_sub(p, image));
    if (y > 0 && y < 2 && fabs(z) < 2)
        e += MV_MIRROR * MV_PHI / (4 * PI * dc * dc * dc);
    return MV_RHO * e / PI;
}

/* The closed form seen at image-plane point (px, py): through the mirror when the ray
 * meets the mirror at least 0.2 inside its edges, then the plane within about 2 of the
 * light's foot; 0 (excluded) anywhere else. */
static double mirror_view_truth_at(const struct scene *scene, double px, double py)
{
    struct ray r = camera_ray(&scene->camera, px, py);
    if (!(r.dir.x > 0))
        return 0;
    double s = (3 - r.origin.x) / r.dir.x; /* the mirror's plane x = 3 */
    struct vec3 m = ray_at(r, s);
    if (!(m.y > 0.2 && m.y < 1.8 && fabs(m.z) < 1.8))
        return 0;
    struct vec3 dir = vec3(-r.dir.x, r.dir.y, r.dir.z); /* reflected about x */
    if (!(dir.y < 0))
        return 0;
    struct vec3 p = vec3_madd(m, dir, -m.y / dir.y); /* down to y = 0 */
    if (!(p.x > 0.5 && p.x < 2.95 && fabs(p.z) < 2))
        return 0; /* far out a pixel spans a wide stretch of a sparse map */
    int inside = 0;
    double l = MV_MIRROR * mirror_view_plane_radiance(p, 0.1, &inside);
    return inside ? l : 0;
}

/* The pixel's mean of the closed form over an 8 x 8 grid of its square (a render's pixel
 * is the mean over its square, and the radiance curves across it); 0 when any point of
 * the grid is excluded. */
static double mirror_view_truth(const struct scene *scene, int x, int y)
{
    double sum = 0;
    for (int i = 0; i < 64; i++) {
        double l = mirror_view_truth_at(scene, x + (i % 8 + 0.5) / 8, y + (i / 8 + 0.5) / 8);
        if (!(l > 0))
            return 0;
        sum += l / 64;
    }
    return sum;
}

/* truth: the image-source solution (Jensen 1994, Fig. 7-8): the plane seen in the mirror
 *   has radiance rho_m rho / pi (E_light + E_caustic), E_caustic the irradiance from the
 *   light's mirror image, present only where the image sees the plane through the mirror.
 *   The photon map must hold the caustic (photons reflected by the mirror) and the camera
 *   ray must follow the mirror to the plane.
 * tolerance: the mean over the pixels that see well inside the mirror and the caustic of
 *   render / closed form within 4% of 1 (the neighbouring estimates share photons, so
 *   the mean's noise is about 1.5%; the k/(k-1) bias 0.5%; twice-bounced light, which the
 *   closed form leaves out, under 1%).
 * catches: a mode that estimates at the mirror instead of following it, the mirror's
 *   reflectance left out of the throughput, caustic photons not in the global map. */
static void test_photons_mode_mirror(struct check *t)
{
    struct scene *scene = mirror_view_scene();
    struct render_settings rs = render_settings_whole(scene, 5, 4, TEST_MAX_DEPTH);
    struct photon_settings ps = {400000, 200, 0, 0, 0, NULL};
    struct render_counters counters = {0, 0, 0, 0, 0};
    struct photon_stats stats;
    struct error err;
    struct render_result r = render_photons(scene, &rs, &ps, 0, NULL, &counters, &stats, &err);
    CHECK(t, r.image != NULL);
    double sum = 0;
    int n = 0;
    for (int y = 0; r.image != NULL && y < 24; y++)
        for (int x = 0; x < 24; x++) {
            double truth = mirror_view_truth(scene, x, y);
            if (truth > 0) {
                sum += image_get(r.image, x, y).y / truth;
                n++;
            }
        }
    CHECK(t, n > 100);
    CHECK(t, n > 0 && fabs(sum / n - 1) < 0.04);
    render_result_free(&r);
    scene_free(scene);
}

void test_trace(struct check *t)
{
    RUN_TEST(t, test_emission_densities);
    RUN_TEST(t, test_emission_flux_per_channel);
    RUN_TEST(t, test_directed_emission_flux);
    RUN_TEST(t, test_directed_caustic_irradiance);
    RUN_TEST(t, test_closed_box_flux);
    RUN_TEST(t, test_mirror_caustic_classes);
    RUN_TEST(t, test_shadow_photons);
    RUN_TEST(t, test_trace_determinism);
    RUN_TEST(t, test_trace_refuses_overflow);
    RUN_TEST(t, test_trace_keeps_powers_in_range);
    RUN_TEST(t, test_point_over_plane_estimate);
    RUN_TEST(t, test_cone_filter_uniform);
    RUN_TEST(t, test_estimate_boundaries);
    RUN_TEST(t, test_irradiance_uniform);
    RUN_TEST(t, test_irradiance_rules);
    RUN_TEST(t, test_differential_checking_edge);
    RUN_TEST(t, test_illumination_maps);
    RUN_TEST(t, test_photons_mode_cornell);
    RUN_TEST(t, test_photons_mode_mirror);
}
