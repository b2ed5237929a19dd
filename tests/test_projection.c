/*
 * tests/test_projection.c -- projection maps (Jensen and Christensen 1994, Sec. 3.1) and
 * photon emission through them, against closed forms, brute force and plain emission: the
 * flux photons bring, the cells the maps mark, the origins they leave from. How photons
 * spread over a map's cells, and the maps at their edges, are test_projection_cells.c's.
 *
 * Photons are counted through a sink that sees each stored photon in full precision
 * (trace.h), so no record rounding enters the sums. Where a trace stores at most one
 * photon per path (first hits and caustics, whose paths end at their first diffuse
 * bounce), the stored photons are the paths' contributions. With projection maps the
 * paths are stratified rather than independent; the standard error of independent
 * paths, used for them too, then over-states their error, which keeps tolerances safe.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "../src/base/rng.h"
#include "../src/geom/sphereflake.h"
#include "../src/photon/projection_map.h"
#include "../src/photon/trace.h"
#include "check.h"
#include "projection_fixtures.h"
#include "tests.h"
#include "truths.h"

/* ---- flux on a wall ---- */

#define WALL_Z 3.0 /* the wall: the square |x|, |y| <= 1 in the plane z = 3, facing -z */

/* Direct and caustic flux the photons of each light leave on the wall, per channel. */
struct wall_flux {
    struct tally direct[4][3], caustic[4][3]; /* [light][channel] */
};

static int count_on_wall(void *context, const struct photon_event *e)
{
    struct wall_flux *w = context;
    if (!(fabs(e->position.z - WALL_Z) < 1e-6 && fabs(e->position.x) <= 1 &&
          fabs(e->position.y) <= 1))
        return 0;
    struct tally *t = e->kind == PHOTON_DIRECT ? w->direct[e->light] : w->caustic[e->light];
    for (int a = 0; a < 3; a++)
        tally_add(&t[a], vec3_get(e->power, a));
    return 0;
}

/* The wall's flux from n photons traced through pm (NULL: plain emission). */
static struct wall_flux wall_flux(const struct scene *scene, const struct projection_maps *pm,
                                  size_t n)
{
    struct wall_flux w;
    memset(&w, 0, sizeof w);
    for (int l = 0; l < 4; l++)
        for (int a = 0; a < 3; a++)
            w.direct[l][a].n = w.caustic[l][a].n = (double)n;
    struct photon_sink sink = {count_on_wall, &w};
    trace_into(scene, pm, n, pm != NULL, PHOTON_DIRECT | PHOTON_CAUSTIC, &sink);
    return w;
}

/* A point light of power (1, 2, 3) W at the origin (light 0), the diffuse wall, and a
 * 1 x 1 mirror (rho = 0.8) in the plane z = -1 behind the light, which reflects onto the
 * whole wall the light of the light's image at z = -2. With area_lights, three more
 * lights facing the wall beside the light's cones to the wall: a quad (light 1), a
 * sphere (2) and a triangle (3). */
static struct scene *wall_scene(int area_lights)
{
    struct scene *scene = scene_create();
    int wall = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    int chrome = add_test_material(scene, MATERIAL_MIRROR, vec3(0.8, 0.8, 0.8), vec3_zero());
    scene_add_point_light(scene, vec3_zero(), vec3(1, 2, 3));
    scene_add_quad(scene, vec3(-1, -1, WALL_Z), vec3(0, 2, 0), vec3(2, 0, 0), wall);
    scene_add_quad(scene, vec3(-0.5, -0.5, -1), vec3(1, 0, 0), vec3(0, 1, 0), chrome);
    if (area_lights) {
        int quad = add_test_material(scene, MATERIAL_LAMBERT, vec3_zero(), vec3(3, 2, 1));
        int ball = add_test_material(scene, MATERIAL_LAMBERT, vec3_zero(), vec3(1, 2, 3));
        int tri = add_test_material(scene, MATERIAL_LAMBERT, vec3_zero(), vec3(8, 8, 4));
        scene_add_quad(scene, vec3(-0.3, -1.8, 0), vec3(0.6, 0, 0), vec3(0, 0.6, 0), quad);
        scene_add_sphere(scene, vec3(0, 1.5, 0.5), 0.2, ball);
        struct vec3 v[3] = {{-1.5, 0, 0.5}, {-1.0, 0, 0.5}, {-1.5, 0.5, 0.5}};
        scene_add_triangle(scene, v, NULL, tri);
    }
    finish_test_scene(scene);
    return scene;
}

/* The solid angle of the wall (a 2 x 2 square) seen on its axis from distance d:
 * 4 asin(a b / sqrt((a^2 + 4 d^2) (b^2 + 4 d^2))) with a = b = 2. */
static double wall_solid_angle(double d)
{
    return 4 * asin(1 / (1 + d * d));
}

/* Whether a's and b's direct (or caustic) flux agree within 4 combined standard errors for
 * every light and channel; for direct flux also whether a's is known to 5% (every light
 * lights the wall directly, but not every one reaches the mirror). */
static int fluxes_agree(const struct wall_flux *a, const struct wall_flux *b, int n_lights,
                        int caustic)
{
    int agree = 1;
    for (int l = 0; l < n_lights; l++)
        for (int c = 0; c < 3; c++) {
            const struct tally *x = caustic ? &a->caustic[l][c] : &a->direct[l][c];
            const struct tally *y = caustic ? &b->caustic[l][c] : &b->direct[l][c];
            double se = sqrt(tally_se(x) * tally_se(x) + tally_se(y) * tally_se(y));
            agree &= caustic || (x->sum > 0 && tally_se(x) < 0.05 * x->sum);
            agree &= fabs(x->sum - y->sum) <= 4 * se;
        }
    return agree;
}

/* Whether the point light's (light 0's) direct flux on the wall, Phi Omega(3) / (4 pi),
 * and its caustic flux through the mirror, rho Phi Omega(5) / (4 pi) (its image is 5 from
 * the wall), are in w within 3 standard errors, channel by channel. */
static int point_light_closed_forms(const struct wall_flux *w)
{
    int close = 1;
    for (int c = 0; c < 3; c++) {
        double phi = c + 1.0; /* the point light's (1, 2, 3) W */
        double direct = phi * wall_solid_angle(WALL_Z) / (4 * PI);
        double caustic = 0.8 * phi * wall_solid_angle(WALL_Z + 2) / (4 * PI);
        close &= fabs(w->direct[0][c].sum - direct) <= 3 * tally_se(&w->direct[0][c]);
        close &= fabs(w->caustic[0][c].sum - caustic) <= 3 * tally_se(&w->caustic[0][c]);
    }
    return close;
}

/* truth: the point light's direct flux on the wall, Phi Omega(3) / (4 pi), and its
 *   caustic flux through the mirror, rho Phi Omega(5) / (4 pi) (the image light is 5
 *   from the wall); for the area lights, plain emission (light_emit()): both ways must
 *   leave the same direct and caustic flux, light by light and channel by channel.
 *   Maps of the default resolution and of coarse ones (1 x 1 and 2 x 3 cells over the
 *   hemisphere), where a cell's own density carries the whole emission profile.
 * tolerance: 3 standard errors of the closed forms; 4 combined standard errors where plain
 *   and mapped emission are compared (4 rather than 3: some 60 comparisons are made, a
 *   light's channels moving together); 100000 photons each way.
 * catches: a cell's flux F_c or its density wrong for one kind of light (uniform taken
 *   for cosine), a patch's share of the light's area (a_k) missing from the weight, a
 *   light's share of the power counted twice (p_pick with the maps' own choice), the
 *   specular raise (1 + boost s) not divided out of the weight (the caustic would be 1.3x
 *   too bright), directions drawn uniformly within an area light's cell. */
static void test_wall_flux_with_and_without_maps(struct check *t)
{
    static const int resolutions[3][2] = {
        {PROJECTION_N_THETA_DEFAULT, PROJECTION_N_PHI_DEFAULT}, {1, 1}, {2, 3}};
    for (int area_lights = 0; area_lights < 2; area_lights++) {
        struct scene *scene = wall_scene(area_lights);
        int n_lights = (int)scene->n_lights;
        struct wall_flux plain = wall_flux(scene, NULL, 100000);
        CHECK(t, point_light_closed_forms(&plain));
        for (int r = 0; r < 3; r++) {
            struct projection_settings ps = settings(PROJECTION_BOOST_DEFAULT);
            ps.n_theta = resolutions[r][0];
            ps.n_phi = resolutions[r][1];
            struct projection_maps *pm = projection_maps_build(scene, &ps);
            struct wall_flux mapped = wall_flux(scene, pm, 100000);
            CHECK(t, fluxes_agree(&plain, &mapped, n_lights, 0));
            CHECK(t, fluxes_agree(&plain, &mapped, n_lights, 1));
            CHECK(t, point_light_closed_forms(&mapped));
            projection_maps_free(pm);
        }
        scene_free(scene);
    }
}

/* ---- conservativeness ---- */

/* Objects the brute force aims at: the balls holding each of the scene's small objects. */
struct aim {
    struct vec3 centre;
    double radius;
};

/* Specularity of the materials of map_scene(), by index: diffuse, mirror 0.7, glass,
 * the lights' black. */
static const double map_scene_specularity[] = {0.0, 0.7, 1.0, 0.0};

/* A 10 x 10 diffuse floor at y = 0 of 4 x 4 tiles (one quad's bounding sphere would hold
 * the lights and mark every cell) under four lights facing down: a 2 x 2 quad at y = 3, a
 * sphere of radius 0.5, a triangle and a point light; with objects close to the lights
 * (closer than their patches are wide), a sphere far smaller than a cell, a sphere
 * flake (one procedural primitive) and a mirror triangle. aims[] receives the balls
 * around the small objects (7 of them). */
static struct scene *map_scene(struct aim aims[7])
{
    struct scene *scene = scene_create();
    int diffuse = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    int mirror = add_test_material(scene, MATERIAL_MIRROR, vec3(0.7, 0.6, 0.5), vec3_zero());
    int glass = add_test_material(scene, MATERIAL_GLASS, vec3_zero(), vec3_zero());
    int glow = add_test_material(scene, MATERIAL_LAMBERT, vec3_zero(), vec3(5, 5, 5));
    for (int tile = 0; tile < 16; tile++)
        scene_add_quad(scene, vec3(-5 + 2.5 * (tile % 4), 0, -5 + 2.5 * (tile / 4)),
                       vec3(0, 0, 2.5), vec3(2.5, 0, 0), diffuse);
    scene_add_quad(scene, vec3(-1, 3, -1), vec3(2, 0, 0), vec3(0, 0, 2), glow);
    scene_add_sphere(scene, vec3(3, 2.5, 0), 0.5, glow);
    struct vec3 tri[3] = {{-4, 3, -1}, {-2, 3, -1}, {-4, 3, 1}};
    scene_add_triangle(scene, tri, NULL, glow);
    scene_add_point_light(scene, vec3(0, 2, 2), vec3(10, 10, 10));
    struct aim balls[7] = {{{0.2, 2.75, 0.1}, 0.15}, {{3, 1.75, 0}, 0.2}, {{0.5, 1, 0.3}, 0.01},
                           {{-3.2, 2.7, 0.3}, 0.1}, {{0.3, 1.9, 2.2}, 0.05},
                           {{-1.5, 0.6, -1}, 0.3 * 5.0 / 3.0}, {{1.5, 0.5, 1}, 0.3}};
    int materials[5] = {mirror, glass, diffuse, glass, mirror};
    for (int i = 0; i < 5; i++)
        scene_add_sphere(scene, balls[i].centre, balls[i].radius, materials[i]);
    struct sphereflake_params fp = {{-1.5, 0.6, -1}, 0.3, 2, {0, 1, 0}, {0}};
    struct error err;
    scene_add_shape(scene, &sphereflake_ops, sphereflake_create(&fp, &err), diffuse);
    struct vec3 shard[3] = {{1.3, 0.3, 1}, {1.7, 0.5, 1.1}, {1.4, 0.7, 0.9}};
    scene_add_triangle(scene, shard, NULL, mirror);
    memcpy(aims, balls, sizeof balls);
    finish_test_scene(scene);
    return scene;
}

/* A direction for the brute force: k < 200 uniform over the sphere, then aimed at a
 * uniform point of one of the aims' balls in turn. */
static struct vec3 brute_direction(struct rng *r, struct vec3 origin, const struct aim aims[7],
                                   int k)
{
    double u1 = rng_uniform(r), u2 = rng_uniform(r), u3 = rng_uniform(r);
    double z = 1 - 2 * u1, s = sqrt(fmax(0.0, 1 - z * z)), phi = 2 * PI * u2;
    struct vec3 w = vec3(s * cos(phi), s * sin(phi), z);
    if (k < 200)
        return w;
    const struct aim *a = &aims[k % 7];
    struct vec3 target = vec3_madd(a->centre, w, a->radius * cbrt(u3));
    return vec3_normalize(vec3_sub(target, origin));
}

/* Of the rays from n_origins origins of map k in 480 directions each: those that hit
 * something, and of them those whose material is more specular than the map's cell says
 * (-1: unmarked), added to brute[0] and brute[1]. */
static void brute_force_map(const struct scene *scene, const struct projection_maps *pm,
                            size_t k, const struct aim aims[7], long brute[2])
{
    for (int o = 0; o < 16; o++) {
        struct rng r = rng_stream(SEED, STREAM_TEST, k, (uint64_t)o);
        double u[2] = {rng_uniform(&r), rng_uniform(&r)};
        struct emission e;
        projection_origin(pm, scene, k, u, &e);
        int area = vec3_length2(e.normal) > 0;
        struct vec3 start = area ? offset_origin(e.origin, e.normal) : e.origin; /* trace.c */
        for (int d = 0; d < 480; d++) {
            e.dir = brute_direction(&r, e.origin, aims, d);
            struct hit hit;
            if ((area && !(vec3_dot(e.dir, e.normal) > 0)) ||
                !scene_intersect(scene, make_ray(start, e.dir), INFINITY, &hit))
                continue;
            brute[0]++;
            brute[1] += projection_specularity(pm, k, &e) < map_scene_specularity[hit.material];
        }
    }
}

/* Of n photons emitted through pm, those that leave from off their light, or not into
 * the front of an area light's surface at their origin, or not along a unit direction, or
 * with no power. */
static long badly_emitted(const struct scene *scene, const struct projection_maps *pm,
                          size_t n)
{
    long bad = 0;
    for (size_t i = 0; i < n; i++) {
        struct rng r = rng_stream(SEED, STREAM_TEST, 300, i);
        double u[5];
        for (int k = 0; k < 5; k++)
            u[k] = rng_uniform(&r);
        struct emission e;
        int index = projection_emit(pm, scene, u, &e);
        const struct light *l = &scene->lights[index < 0 ? 0 : index];
        double distance = vec3_length(vec3_sub(e.origin, l->position));
        struct vec3 corner = vec3_sub(e.origin, l->position); /* quad, triangle: s e1 + t e2 */
        int on_light = l->kind == LIGHT_POINT    ? distance == 0
                       : l->kind == LIGHT_SPHERE ? fabs(distance - l->radius) <= 1e-12
                                                 : corner.y == 0 && corner.x >= 0 &&
                                                       corner.x <= 2 && corner.z >= 0 &&
                                                       corner.z <= 2;
        int front = l->kind == LIGHT_POINT || vec3_dot(e.dir, e.normal) > 0;
        bad += index < 0 || !on_light || !front || !(e.weight > 0) ||
               fabs(vec3_length(e.dir) - 1) > 1e-12;
    }
    return bad;
}

/* truth: brute force. From random origins of every patch, directions uniform over the
 *   sphere and directions aimed into the balls around the small objects are traced
 *   through the scene (scene_intersect); every one that leaves the light's front and
 *   hits something must lie in a marked cell of that patch's map, whose specularity is
 *   at least that of the material hit (Sec. 3.1: "nothing is missed"). Emitted photons
 *   leave their light (the quad's and the triangle's corners are their v0, from which
 *   both reach at most 2 along +x and +z) into the front of its surface at their origin.
 * tolerance: none: not one ray may be missed (of about 200000 that hit).
 * catches: bounding spheres not widened by the patch's radius rho (objects close to
 *   the quad light), a sphere light's normals turning over its patch not allowed for
 *   (beta), cells marked by their centre alone without their half-diagonal (the sphere
 *   of radius 0.01 is smaller than a cell), a cone's columns wrapped wrongly at phi = pi,
 *   a specularity taken as the last object's rather than the largest, a shape's box
 *   ignored, origins off their patch, a sphere light's directions drawn about its patch's
 *   normal and not turned to its origin's (some would leave below its surface). */
static void test_maps_miss_nothing(struct check *t)
{
    struct aim aims[7];
    struct scene *scene = map_scene(aims);
    struct projection_settings ps = settings(PROJECTION_BOOST_DEFAULT);
    struct projection_maps *pm = projection_maps_build(scene, &ps);
    struct projection_stats s = projection_maps_stats(pm);
    CHECK(t, s.n_maps >= 4 + 32 && s.n_marked > 0 && s.n_marked < s.n_cells);
    long brute[2] = {0, 0}; /* rays that hit, rays missed by the maps */
    for (size_t k = 0; k < s.n_maps; k++)
        brute_force_map(scene, pm, k, aims, brute);
    CHECK(t, brute[0] > 100000 && brute[1] == 0);
    CHECK(t, badly_emitted(scene, pm, 20000) == 0);
    printf("  projection: %zu maps, %zu of %zu cells marked (%.1f%% of the power), %zu bytes; "
           "%ld rays hit, %ld missed\n", s.n_maps, s.n_marked, s.n_cells,
           100 * s.marked_fraction, s.bytes, brute[0], brute[1]);
    projection_maps_free(pm);
    scene_free(scene);
}

/* ---- emission positions ---- */

/* A scene of one area light (0: a 4 x 2 quad, 1: a triangle, 2: a sphere of radius 1,
 * each as large as the scene: the most patches) and a small diffuse sphere to light. */
static struct scene *lone_light_scene(int kind)
{
    struct scene *scene = scene_create();
    int diffuse = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    int glow = add_test_material(scene, MATERIAL_LAMBERT, vec3_zero(), vec3(1, 1, 1));
    struct vec3 tri[3] = {{0, 0, 0}, {4, 0, 0}, {1, 3, 0}};
    if (kind == 0)
        scene_add_quad(scene, vec3_zero(), vec3(4, 0, 0), vec3(0, 2, 0), glow);
    else if (kind == 1)
        scene_add_triangle(scene, tri, NULL, glow);
    else
        scene_add_sphere(scene, vec3(1, 1, 0), 1, glow);
    scene_add_sphere(scene, vec3(1, 1, 3), 0.1, diffuse);
    finish_test_scene(scene);
    return scene;
}

/* n origins from each patch of the lone light's maps: how many lie off the light, and
 * the mean of (x, y, z) and of the origin's normal's z^2 (with their standard errors in
 * mean[4 + a]). */
static long patch_origins(const struct scene *scene, const struct projection_maps *pm, int n,
                          double mean[8])
{
    const struct light *l = &scene->lights[0];
    struct tally m[4];
    memset(m, 0, sizeof m);
    long off = 0;
    size_t n_maps = projection_maps_stats(pm).n_maps;
    for (size_t k = 0; k < n_maps; k++)
        for (int i = 0; i < n; i++) {
            struct rng r = rng_stream(SEED, STREAM_TEST, 400 + k, (uint64_t)i);
            double u[2] = {rng_uniform(&r), rng_uniform(&r)};
            struct emission e;
            projection_origin(pm, scene, k, u, &e);
            struct vec3 d = vec3_sub(e.origin, l->position);
            if (l->kind == LIGHT_SPHERE)
                off += fabs(vec3_length(d) - 1) > 1e-12 ||
                       vec3_length(vec3_sub(d, e.normal)) > 1e-12; /* R = 1: d is n */
            else if (l->kind == LIGHT_QUAD) /* [0, 4] x [0, 2] in the plane z = 0 */
                off += d.z != 0 || e.normal.z != 1 || d.x < 0 || d.x > 4 || d.y < 0 || d.y > 2;
            else /* the triangle (0, 0) (4, 0) (1, 3): y >= 0, x >= y / 3, x + y <= 4 */
                off += d.z != 0 || e.normal.z != 1 || d.y < 0 || d.x < d.y / 3 - 1e-12 ||
                       d.x + d.y > 4 + 1e-12;
            tally_add(&m[0], e.origin.x);
            tally_add(&m[1], e.origin.y);
            tally_add(&m[2], e.origin.z);
            tally_add(&m[3], e.normal.z * e.normal.z);
        }
    for (int a = 0; a < 4; a++) {
        m[a].n = (double)n * (double)n_maps;
        mean[a] = m[a].sum / m[a].n;
        mean[4 + a] = tally_se(&m[a]) / m[a].n;
    }
    return off;
}

/* truth: the patches of an area light are equal in area and tile it, so origins drawn
 *   equally from every patch are uniform over the light: they lie on it, their mean is
 *   its centroid (the quad's (2, 1, 0), the triangle's (5/3, 1, 0), the sphere's centre)
 *   and, on the sphere, the normals' z^2 averages 1/3 (Archimedes); a light as large as
 *   the scene is cut into the most patches (8 x 8, 8^2 triangles, 8 x 16 zones); its own
 *   surface is left out of its maps, so they mark little more than the small sphere
 *   (under 20% of the power; its bounding sphere, holding every patch, would mark all).
 * tolerance: 4 standard errors of each mean (2000 origins per patch; 4 rather than 3:
 *   eleven means), 1e-12 for lying on the light.
 * catches: patches that overlap or leave gaps (an upside-down triangle at the wrong
 *   lattice point, sphere bands of unequal height), origins off their patch or with the
 *   wrong normal, patch counts not capped, a light's own primitive in its maps. */
static void test_patches_tile_lights(struct check *t)
{
    static const size_t n_maps[3] = {64, 64, 128};
    static const double centroid[3][3] = {{2, 1, 0}, {5.0 / 3, 1, 0}, {1, 1, 0}};
    for (int kind = 0; kind < 3; kind++) {
        struct scene *scene = lone_light_scene(kind);
        struct projection_settings ps = settings(PROJECTION_BOOST_DEFAULT);
        struct projection_maps *pm = projection_maps_build(scene, &ps);
        struct projection_stats s = projection_maps_stats(pm);
        CHECK(t, s.n_maps == n_maps[kind] && s.marked_fraction > 0 && s.marked_fraction < 0.2);
        double mean[8];
        CHECK(t, patch_origins(scene, pm, 2000, mean) == 0);
        for (int a = 0; a < 3; a++)
            CHECK_CLOSE(t, mean[a], centroid[kind][a], 4 * mean[4 + a] + 1e-12);
        if (kind == 2)
            CHECK_CLOSE(t, mean[3], 1.0 / 3, 4 * mean[7]);
        projection_maps_free(pm);
        scene_free(scene);
    }
}

/* ---- one sphere in the open ---- */

static int sum_direct(void *context, const struct photon_event *e)
{
    *(double *)context += e->power.y;
    return 0;
}

/* A point light of 1 W at the origin and a diffuse sphere of radius 0.5 at distance 3,
 * nothing else. */
static struct scene *lone_sphere_scene(void)
{
    struct scene *scene = scene_create();
    int diffuse = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    scene_add_point_light(scene, vec3_zero(), vec3(1, 1, 1));
    scene_add_sphere(scene, vec3(2.4, 0, 1.8), 0.5, diffuse);
    finish_test_scene(scene);
    return scene;
}

/* The direct flux on the sphere from `passes` independent traces of n photons each:
 * their mean and the variance of one trace's total. */
static void lone_sphere_flux(const struct scene *scene, const struct projection_maps *pm,
                             size_t n, int passes, double mean_var[2])
{
    struct tally totals = {0, 0, (double)passes};
    for (int p = 0; p < passes; p++) {
        double flux = 0;
        struct photon_sink sink = {sum_direct, &flux};
        trace_into(scene, pm, n, (uint64_t)p, PHOTON_DIRECT, &sink);
        tally_add(&totals, flux);
    }
    mean_var[0] = totals.sum / passes;
    mean_var[1] = (totals.sum2 - totals.sum * totals.sum / passes) / (passes - 1);
}

/* truth: a point light of power Phi sends Phi (1 - cos alpha) / 2 into a sphere seen at
 *   angular radius alpha = asin(r / d); with the maps every photon carries the marked
 *   share of the power, which is at least that and, at the default resolution, within
 *   a few times of it; the flux they bring is the same, with far less variance: plain
 *   emission sends 99.3% of its photons into the void.
 * tolerance: 3 standard errors of the mean of 40 traces of 2000 photons each; weights to
 *   1e-12 relative; the variance ratio at least 20.
 * catches: photons carrying Phi / N whatever the marked share (flux 1 / marked share too
 *   high), unmarked directions emitted, a marked share computed from the marked cells'
 *   count instead of their flux. */
static void test_lone_sphere(struct check *t)
{
    struct scene *scene = lone_sphere_scene();
    struct projection_settings ps = settings(PROJECTION_BOOST_DEFAULT);
    struct projection_maps *pm = projection_maps_build(scene, &ps);
    struct projection_stats s = projection_maps_stats(pm);
    double truth = (1 - sqrt(1 - 0.25 / 9)) / 2;
    CHECK(t, s.n_maps == 1 && s.marked_fraction > truth && s.marked_fraction < 5 * truth);
    int same_weight = 1;
    for (int i = 0; i < 1000; i++) {
        struct rng r = rng_stream(SEED, STREAM_TEST, 100, (uint64_t)i);
        double u[5];
        for (int k = 0; k < 5; k++)
            u[k] = rng_uniform(&r);
        struct emission e;
        same_weight &= projection_emit(pm, scene, u, &e) == 0 &&
                       fabs(e.weight - s.marked_fraction) <= 1e-12 * s.marked_fraction;
    }
    CHECK(t, same_weight);
    double plain[2], mapped[2];
    lone_sphere_flux(scene, NULL, 2000, 40, plain);
    lone_sphere_flux(scene, pm, 2000, 40, mapped);
    CHECK_CLOSE(t, plain[0], truth, 3 * sqrt(plain[1] / 40));
    CHECK_CLOSE(t, mapped[0], truth, 3 * sqrt(mapped[1] / 40));
    CHECK(t, mapped[1] * 20 < plain[1]);
    printf("  projection: one sphere, flux %.6f (plain) %.6f (maps), truth %.6f; marked %.4f; "
           "variance ratio %.0f\n", plain[0], mapped[0], truth, s.marked_fraction,
           plain[1] / mapped[1]);
    projection_maps_free(pm);
    scene_free(scene);
}

void test_projection(struct check *t)
{
    RUN_TEST(t, test_patches_tile_lights);
    RUN_TEST(t, test_maps_miss_nothing);
    RUN_TEST(t, test_lone_sphere);
    RUN_TEST(t, test_wall_flux_with_and_without_maps);
}
