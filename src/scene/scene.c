/*
 * scene/scene.c -- building a scene: materials, primitives, the lights they make.
 *
 * Invariant: n_prims equals the number of primitives in geometry, and light_of_prim has
 * one entry per primitive (grown with them), so an emitter's id finds its light.
 */
#include "scene.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/hash.h"

/* Relative pull-in of a shadow ray's far end: rounding in a hit distance is a few ulps
 * (1e-15) times the conditioning of the intersection, which is large only at grazing
 * angles; 1e-7 clears it, while anything nearer the light than 1e-7 of the distance
 * touches the light and may be counted as not blocking. */
#define SHADOW_EPSILON 1e-7

struct scene *scene_create(void)
{
    struct scene *scene = xcalloc(1, sizeof *scene, "scene");
    scene->width = 256;
    scene->height = 256;
    scene->background = vec3_zero();
    scene->sky = -1;
    scene->sphereflake_levels = -1;
    scene->light_power = vec3_zero();
    scene->geometry = geometry_create();
    scene->source_hash = FNV1A_OFFSET_BASIS;
    return scene;
}

void scene_hash_line(struct scene *scene, const char *line)
{
    scene->source_hash = fnv1a(scene->source_hash, line, strlen(line) + 1);
}

void scene_free(struct scene *scene)
{
    if (scene == NULL)
        return;
    geometry_free(scene->geometry);
    xfree(scene->light_of_prim);
    xfree(scene->light_cdf);
    xfree(scene->lights);
    xfree(scene->materials);
    xfree(scene);
}

int scene_add_material(struct scene *scene, const struct material *m)
{
    if (scene->n_materials >= MAX_MATERIALS)
        return -1;
    scene->materials = xrealloc(scene->materials, scene->n_materials + 1,
                                sizeof *scene->materials, "materials");
    scene->materials[scene->n_materials] = *m;
    return (int)scene->n_materials++;
}

int scene_find_material(const struct scene *scene, const char *name)
{
    for (size_t i = 0; i < scene->n_materials; i++)
        if (strcmp(scene->materials[i].name, name) == 0)
            return (int)i;
    return -1;
}

/* Whether every channel of power is at most MAX_LIGHT_POWER (and none is NaN). */
static int within_light_power(struct vec3 power)
{
    return power.x <= MAX_LIGHT_POWER && power.y <= MAX_LIGHT_POWER &&
           power.z <= MAX_LIGHT_POWER;
}

static int add_light(struct scene *scene, const struct light *l)
{
    if (scene->n_lights >= MAX_LIGHTS)
        return SCENE_FULL;
    struct vec3 total = vec3_add(scene->light_power, light_power(l));
    if (!within_light_power(total))
        return SCENE_TOO_BRIGHT;
    scene->light_power = total;
    scene->lights = xrealloc(scene->lights, scene->n_lights + 1, sizeof *scene->lights,
                             "lights");
    scene->lights[scene->n_lights] = *l;
    return (int)scene->n_lights++;
}

/* Records primitive id (just added, or -1 for failure) and, if its material emits, the
 * area light described by l. Returns id, or add_light()'s failure, or SCENE_FULL. */
static int register_prim(struct scene *scene, int id, int material, struct light *l)
{
    if (id < 0)
        return SCENE_FULL;
    assert((size_t)id == scene->n_prims);
    scene->light_of_prim = xrealloc(scene->light_of_prim, scene->n_prims + 1,
                                    sizeof *scene->light_of_prim, "light table");
    scene->light_of_prim[scene->n_prims++] = -1;
    const struct material *m = &scene->materials[material];
    if (l == NULL || !material_emits(m))
        return id;
    l->radiance = m->emission;
    l->two_sided = m->two_sided;
    l->prim = id;
    int light = add_light(scene, l);
    if (light < 0)
        return light;
    scene->light_of_prim[id] = light;
    return id;
}

static struct light area_light(enum light_kind kind, struct vec3 position, struct vec3 e1,
                               struct vec3 e2, double radius)
{
    struct light l;
    memset(&l, 0, sizeof l);
    l.kind = kind;
    l.position = position;
    l.e1 = e1;
    l.e2 = e2;
    l.radius = radius;
    return l;
}

int scene_add_sphere(struct scene *scene, struct vec3 centre, double radius, int material)
{
    struct light l = area_light(LIGHT_SPHERE, centre, vec3_zero(), vec3_zero(), radius);
    int id = geometry_add_sphere(scene->geometry, centre, radius, material);
    return register_prim(scene, id, material, &l);
}

int scene_add_triangle(struct scene *scene, const struct vec3 v[3], const struct vec3 *normals,
                       int material)
{
    struct light l = area_light(LIGHT_TRIANGLE, v[0], vec3_sub(v[1], v[0]),
                                vec3_sub(v[2], v[0]), 0.0);
    int id = geometry_add_triangle(scene->geometry, v, normals, material);
    return register_prim(scene, id, material, &l);
}

int scene_add_quad(struct scene *scene, struct vec3 p0, struct vec3 e1, struct vec3 e2,
                   int material)
{
    struct light l = area_light(LIGHT_QUAD, p0, e1, e2, 0.0);
    int id = geometry_add_quad(scene->geometry, p0, e1, e2, material);
    return register_prim(scene, id, material, &l);
}

int scene_add_shape(struct scene *scene, const struct shape_ops *ops, void *shape, int material)
{
    assert(!material_emits(&scene->materials[material]));
    int id = geometry_add_shape(scene->geometry, ops, shape, material);
    return register_prim(scene, id, material, NULL);
}

int scene_add_point_light(struct scene *scene, struct vec3 position, struct vec3 power)
{
    struct light l;
    memset(&l, 0, sizeof l);
    l.kind = LIGHT_POINT;
    l.position = position;
    l.power = power;
    l.prim = -1;
    return add_light(scene, &l);
}

void scene_set_background(struct scene *scene, struct vec3 le, const char *file, int line)
{
    scene->background = le;
    snprintf(scene->background_file, sizeof scene->background_file, "%s", file);
    scene->background_line = line;
}

/* The sky's sphere is the box's circumscribed sphere, widened by a millionth so that
 * rounding leaves every primitive strictly inside it: every photon the sky emits starts
 * outside the scene (emit.c). A scene with no primitive gets a point-sized sphere at the
 * origin, whose sky lights nothing but is still seen and sampled. */
int scene_add_sky(struct scene *scene)
{
    assert(scene->sky < 0);
    if (!(vec3_max_component(scene->background) > 0))
        return -1;
    struct light l;
    memset(&l, 0, sizeof l);
    l.kind = LIGHT_SKY;
    l.radiance = scene->background;
    l.prim = -1;
    struct aabb box = geometry_bounds(scene->geometry);
    if (box.lo.x <= box.hi.x) {
        l.position = vec3_scale(vec3_add(box.lo, box.hi), 0.5);
        l.radius = 0.5 * vec3_length(vec3_sub(box.hi, box.lo)) * (1.0 + 1e-6) +
                   1e-9 * fmax(1.0, vec3_max_abs(l.position));
    }
    int light = add_light(scene, &l);
    if (light >= 0)
        scene->sky = light;
    return light;
}

int scene_add_error(int id, const char *file, int line, const char *keyword,
                    struct error *err)
{
    if (id >= 0)
        return 0;
    if (id == SCENE_TOO_BRIGHT)
        return error_set(err, file, line, "%s: the lights' total power would exceed %g W in "
                         "a channel (an area light's power is pi x radiance x area; the "
                         "limit keeps every photon within its record)", keyword,
                         MAX_LIGHT_POWER);
    return error_set(err, file, line, "%s: more than %d primitives or %d lights", keyword,
                     MAX_PRIMITIVES, MAX_LIGHTS);
}

/* The cumulative distribution of picking lights by power (scene_pick_light). */
static void build_light_cdf(struct scene *scene)
{
    size_t n = scene->n_lights;
    double total = 0.0;
    scene->light_cdf = xmalloc(n + 1, sizeof *scene->light_cdf, "light distribution");
    for (size_t i = 0; i < n; i++)
        total += fmax(0.0, vec3_luminance(light_power(&scene->lights[i])));
    scene->light_cdf[0] = 0.0;
    for (size_t i = 0; i < n; i++) {
        double weight = total > 0 ? fmax(0.0, vec3_luminance(light_power(&scene->lights[i])))
                                        / total
                                  : 1.0 / n;
        scene->light_cdf[i + 1] = scene->light_cdf[i] + weight;
    }
    if (n > 0)
        scene->light_cdf[n] = 1.0; /* exactly, whatever the rounding of the sum */
}

int scene_pick_light(const struct scene *scene, double u, double *probability)
{
    size_t lo = 0, hi = scene->n_lights;
    if (hi == 0)
        return -1;
    /* Binary search for the i with cdf[i] <= u < cdf[i + 1], skipping empty intervals. */
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (scene->light_cdf[mid] <= u)
            lo = mid;
        else
            hi = mid;
    }
    while (scene->light_cdf[lo + 1] - scene->light_cdf[lo] <= 0)
        lo--; /* a black light was landed on only through rounding at its boundary */
    *probability = scene->light_cdf[lo + 1] - scene->light_cdf[lo];
    return (int)lo;
}

double scene_light_probability(const struct scene *scene, int light)
{
    return scene->light_cdf[light + 1] - scene->light_cdf[light];
}

void scene_finish(struct scene *scene, int width, int height)
{
    build_light_cdf(scene);
    scene->width = width;
    scene->height = height;
    camera_setup(&scene->camera, width, height);
    geometry_build(scene->geometry);
}

int scene_occluded(const struct scene *scene, struct vec3 origin, struct vec3 dir,
                   double distance)
{
    return geometry_occluded(scene->geometry, make_ray(origin, dir),
                             distance * (1.0 - SHADOW_EPSILON));
}

double scene_diagonal(const struct scene *scene)
{
    struct aabb box = geometry_bounds(scene->geometry);
    double diagonal = vec3_length(vec3_sub(box.hi, box.lo));
    return isfinite(diagonal) && diagonal > 0 ? diagonal : 1.0;
}
