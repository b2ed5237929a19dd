/*
 * scene/parse_objects.c -- the keywords of scene files that add things to see and light:
 * sphere, triangle, smooth_triangle, quad, light, sphereflake, heightfield, and the
 * imports nff and obj (README: Scene files).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../geom/heightfield.h"
#include "../geom/sphereflake.h"
#include "nff.h"
#include "obj.h"
#include "parser.h"

/* "sphere CX CY CZ RADIUS MATERIAL" */
int parse_sphere(struct parser *ps, struct error *err)
{
    double v[4];
    if (read_numbers(ps, v, 4, "centre x y z, radius", err) < 0)
        return -1;
    if (!(v[3] > 0))
        return parse_error(ps, err, "radius must be positive");
    int m = read_material(ps, err);
    if (m < 0 || expect_end(ps, err) < 0)
        return -1;
    return check_added(ps, scene_add_sphere(ps->scene, vec3_at(v), v[3], m), err);
}

/* Whether edges e1, e2 span a parallelogram of non-zero area, relative to their lengths. */
static int spans_area(struct vec3 e1, struct vec3 e2)
{
    double area = vec3_length(vec3_cross(e1, e2));
    return area > 1e-12 * vec3_length(e1) * vec3_length(e2) && area > 0;
}

/* "triangle V0 V1 V2 MATERIAL" and "smooth_triangle V0 V1 V2 N0 N1 N2 MATERIAL" */
int parse_triangle(struct parser *ps, struct error *err)
{
    int smooth = strcmp(ps->tokens[0], "smooth_triangle") == 0;
    double v[18];
    if (read_numbers(ps, v, smooth ? 18 : 9,
                     smooth ? "three vertices x y z, three normals x y z" : "three vertices x y z",
                     err) < 0)
        return -1;
    struct vec3 vertices[3], normals[3];
    for (int i = 0; i < 3; i++) {
        vertices[i] = vec3_at(v + 3 * i);
        normals[i] = smooth ? vec3_normalize(vec3_at(v + 9 + 3 * i)) : vec3_zero();
        if (smooth && vec3_length2(normals[i]) == 0)
            return parse_error(ps, err, "a vertex normal is zero");
    }
    int m = read_material(ps, err);
    if (m < 0 || expect_end(ps, err) < 0)
        return -1;
    if (material_emits(&ps->scene->materials[m]) &&
        !spans_area(vec3_sub(vertices[1], vertices[0]), vec3_sub(vertices[2], vertices[0])))
        return parse_error(ps, err, "an emitting triangle must have non-zero area");
    return check_added(ps, scene_add_triangle(ps->scene, vertices, smooth ? normals : NULL, m),
                       err);
}

/* Reads the four corners of a parallelogram (counter-clockwise from the front) into p0,
 * e1 = p1 - p0, e2 = p3 - p0. The fourth corner must be p1 + p3 - p0 to within 1e-6 of
 * the longer edge, which tolerates corners written with six significant digits. */
static int read_parallelogram(struct parser *ps, struct vec3 *p0, struct vec3 *e1,
                              struct vec3 *e2, struct error *err)
{
    double v[12];
    if (read_numbers(ps, v, 12, "four corners x y z, counter-clockwise", err) < 0)
        return -1;
    *p0 = vec3_at(v);
    *e1 = vec3_sub(vec3_at(v + 3), *p0);
    *e2 = vec3_sub(vec3_at(v + 9), *p0);
    struct vec3 p2 = vec3_at(v + 6);
    double gap = vec3_length(vec3_sub(vec3_add(*p0, vec3_add(*e1, *e2)), p2));
    if (!(gap <= 1e-6 * fmax(vec3_length(*e1), vec3_length(*e2))))
        return parse_error(ps, err, "the corners are not a parallelogram (p0 + p2 != p1 + p3)");
    if (!spans_area(*e1, *e2))
        return parse_error(ps, err, "the corners span no area");
    return 0;
}

/* "quad P0 P1 P2 P3 MATERIAL" */
int parse_quad(struct parser *ps, struct error *err)
{
    struct vec3 p0, e1, e2;
    if (read_parallelogram(ps, &p0, &e1, &e2, err) < 0)
        return -1;
    int m = read_material(ps, err);
    if (m < 0 || expect_end(ps, err) < 0)
        return -1;
    return check_added(ps, scene_add_quad(ps->scene, p0, e1, e2, m), err);
}

/* A black, emitting material for a light made by the `light` keyword. Its name holds '#',
 * which starts a comment in a scene file, so no file can refer to it. */
static int light_material(struct parser *ps, const double *radiance, struct error *err)
{
    struct material m;
    memset(&m, 0, sizeof m);
    if (!is_colour_in(radiance, 0, HUGE_VAL))
        return parse_error(ps, err, "radiance must not be negative");
    sprintf(m.name, "light#%zu", ps->scene->n_lights);
    m.kind = MATERIAL_LAMBERT;
    m.emission = vec3_at(radiance);
    int index = scene_add_material(ps->scene, &m);
    if (index < 0)
        return parse_error(ps, err, "too many materials");
    return index;
}

/* "light point X Y Z  R G B" (power, W per channel), "light sphere CX CY CZ RADIUS  R G B"
 * and "light quad P0 P1 P2 P3  R G B" (radiance leaving the front). */
int parse_light(struct parser *ps, struct error *err)
{
    const char *kind = read_word(ps);
    double v[4], c[3];
    struct vec3 p0, e1, e2;
    int id, m;
    if (kind != NULL && strcmp(kind, "point") == 0) {
        if (read_numbers(ps, v, 3, "position x y z", err) < 0 ||
            read_numbers(ps, c, 3, "power r g b in watts", err) < 0)
            return -1;
        if (!is_colour_in(c, 0, HUGE_VAL))
            return parse_error(ps, err, "power must not be negative");
        id = scene_add_point_light(ps->scene, vec3_at(v), vec3_at(c));
    } else if (kind != NULL && strcmp(kind, "sphere") == 0) {
        if (read_numbers(ps, v, 4, "centre x y z, radius", err) < 0 ||
            read_numbers(ps, c, 3, "radiance r g b", err) < 0 ||
            (m = light_material(ps, c, err)) < 0)
            return -1;
        if (!(v[3] > 0))
            return parse_error(ps, err, "radius must be positive");
        id = scene_add_sphere(ps->scene, vec3_at(v), v[3], m);
    } else if (kind != NULL && strcmp(kind, "quad") == 0) {
        if (read_parallelogram(ps, &p0, &e1, &e2, err) < 0 ||
            read_numbers(ps, c, 3, "radiance r g b", err) < 0 ||
            (m = light_material(ps, c, err)) < 0)
            return -1;
        id = scene_add_quad(ps->scene, p0, e1, e2, m);
    } else {
        return parse_error(ps, err, "expected point, sphere or quad");
    }
    if (expect_end(ps, err) < 0)
        return -1;
    return check_added(ps, id, err);
}

/* Reads a material for a procedural shape: defined, and not emitting (shapes are not
 * sampled as lights). Returns its index or -1. */
static int read_shape_material(struct parser *ps, struct error *err)
{
    int m = read_material(ps, err);
    if (m >= 0 && material_emits(&ps->scene->materials[m]))
        return parse_error(ps, err, "an emitting material cannot be used here");
    return m;
}

/* Reads the optional last word "expand": store the shape's primitives in the BVH instead
 * of intersecting the shape procedurally (for comparisons). */
static int read_expand(struct parser *ps, struct error *err)
{
    int expand = ps->next < ps->n_tokens && strcmp(ps->tokens[ps->next], "expand") == 0;
    ps->next += expand;
    return expect_end(ps, err) < 0 ? -1 : expand;
}

/* Whether count more primitives stay within MAX_PRIMITIVES. */
static int room_for(const struct parser *ps, double count)
{
    return ps->scene->n_prims + count <= MAX_PRIMITIVES;
}

/* Adds a created shape to the scene; the shape is freed here if it cannot be added. */
static int add_shape(struct parser *ps, const struct shape_ops *ops, void *shape, int material,
                     struct error *err)
{
    if (scene_add_shape(ps->scene, ops, shape, material) >= 0)
        return 0;
    ops->free(shape);
    return check_added(ps, -1, err);
}

static void add_flake_sphere(void *context, struct vec3 centre, double radius, int material)
{
    scene_add_sphere(context, centre, radius, material); /* room_for() checked the count */
}

/* "sphereflake CX CY CZ RADIUS LEVELS AX AY AZ MATERIAL [MATERIAL ...] [expand]": Haines'
 * sphere flake with its top sphere's axis along A; one material per depth, the last one
 * repeating for the depths below. */
int parse_sphereflake(struct parser *ps, struct error *err)
{
    struct sphereflake_params params;
    double v[8];
    int n = 0;
    if (read_numbers(ps, v, 4, "centre x y z, radius", err) < 0 ||
        read_wholes(ps, v + 4, 1, "levels", err) < 0 ||
        read_numbers(ps, v + 5, 3, "axis x y z", err) < 0)
        return -1;
    if (!(v[4] >= 0 && v[4] <= SPHEREFLAKE_MAX_LEVELS))
        return error_set(err, ps->file, ps->line,
                         "sphereflake: levels must be a whole number from 0 to %d",
                         SPHEREFLAKE_MAX_LEVELS);
    params.centre = vec3_at(v);
    params.radius = v[3];
    params.levels = (int)v[4];
    params.orientation = vec3_at(v + 5);
    do {
        if (n > params.levels)
            return parse_error(ps, err, "more materials than depths (levels + 1)");
        params.materials[n] = read_shape_material(ps, err);
        if (params.materials[n++] < 0)
            return -1;
    } while (ps->next < ps->n_tokens && strcmp(ps->tokens[ps->next], "expand") != 0);
    for (int depth = n; depth <= SPHEREFLAKE_MAX_LEVELS; depth++)
        params.materials[depth] = params.materials[n - 1];
    int expand = read_expand(ps, err);
    if (expand < 0)
        return -1;
    if (params.levels > ps->scene->sphereflake_levels)
        ps->scene->sphereflake_levels = params.levels;
    struct error inner;
    struct sphereflake *flake = sphereflake_create(&params, &inner);
    if (flake == NULL)
        return error_set(err, ps->file, ps->line, "%s", inner.message);
    if (!expand)
        return add_shape(ps, &sphereflake_ops, flake, params.materials[0], err);
    int fits = room_for(ps, sphereflake_sphere_count(params.levels));
    if (fits)
        sphereflake_spheres(flake, add_flake_sphere, ps->scene);
    sphereflake_free(flake);
    return check_added(ps, fits ? 0 : -1, err);
}

static void add_terrain_triangle(void *context, const struct vec3 v[3],
                                 const struct vec3 normals[3], int material)
{
    scene_add_triangle(context, v, normals, material); /* room_for() checked the count */
}

/* "heightfield X Y Z SIZE RESOLUTION OCTAVES ROUGHNESS FREQUENCY HEIGHT SEED MATERIAL
 * [expand]": a fractal landscape over the square from corner (X, Z), side SIZE, with
 * RESOLUTION x RESOLUTION height samples about Y (heightfield.h gives each parameter). */
int parse_heightfield(struct parser *ps, struct error *err)
{
    double v[10];
    if (read_numbers(ps, v, 4, "corner x y z, size", err) < 0 ||
        read_wholes(ps, v + 4, 2, "resolution, octaves: whole numbers", err) < 0 ||
        read_numbers(ps, v + 6, 3, "roughness, frequency, height", err) < 0 ||
        read_wholes(ps, v + 9, 1, "seed", err) < 0)
        return -1;
    if (!(v[4] >= 0 && v[4] <= HEIGHTFIELD_MAX_RESOLUTION && v[5] >= 0 &&
          v[5] <= HEIGHTFIELD_MAX_OCTAVES && v[9] >= 0 && v[9] <= 9007199254740992.0))
        return parse_error(ps, err, "resolution, octaves and seed must be whole numbers "
                                    "within their limits (README)");
    struct heightfield_params params = {vec3_at(v), v[3], (int)v[4], (int)v[5], v[6], v[7],
                                        v[8], (uint64_t)v[9], 0};
    params.material = read_shape_material(ps, err);
    if (params.material < 0)
        return -1;
    int expand = read_expand(ps, err);
    if (expand < 0)
        return -1;
    struct error inner;
    struct heightfield *hf = heightfield_create(&params, &inner);
    if (hf == NULL)
        return error_set(err, ps->file, ps->line, "%s", inner.message);
    if (!expand)
        return add_shape(ps, &heightfield_ops, hf, params.material, err);
    double cells = (double)(params.resolution - 1) * (params.resolution - 1);
    int fits = room_for(ps, 2 * cells);
    if (fits)
        heightfield_triangles(hf, add_terrain_triangle, ps->scene);
    heightfield_free(hf);
    return check_added(ps, fits ? 0 : -1, err);
}

/* "nff FILE": the NFF file's view, background, lights and objects (scene/nff.c); FILE is
 * relative to this file's directory. Errors inside it name its own lines. */
int parse_nff(struct parser *ps, struct error *err)
{
    char path[MAX_PATH_LENGTH];
    if (read_path(ps, path, err) < 0 || expect_end(ps, err) < 0 ||
        check_named_file(ps, path, err) < 0)
        return -1;
    return nff_import(ps->scene, path, err);
}

/* "rotate AX AY AZ DEGREES" on an obj line: a turn about an axis through the origin. */
static int read_rotation(struct parser *ps, struct obj_placement *place, struct error *err)
{
    double v[4];
    if (read_numbers(ps, v, 4, "rotation axis x y z, degrees", err) < 0)
        return -1;
    if (vec3_max_abs(vec3_at(v)) == 0)
        return parse_error(ps, err, "the rotation axis must not be zero");
    if (!(fabs(v[3]) <= 360))
        return parse_error(ps, err, "the rotation must be from -360 to 360 degrees");
    place->axis = vec3_at(v);
    place->degrees = v[3];
    return 0;
}

/* The rest of an obj line: "[rotate AX AY AZ DEGREES] [scale S] [translate X Y Z]", each
 * optional, in this order, the order in which they apply (obj.h). */
static int read_placement(struct parser *ps, struct obj_placement *place, struct error *err)
{
    const char *word = read_word(ps);
    if (word != NULL && strcmp(word, "rotate") == 0) {
        if (read_rotation(ps, place, err) < 0)
            return -1;
        word = read_word(ps);
    }
    if (word != NULL && strcmp(word, "scale") == 0) {
        if (read_numbers(ps, &place->scale, 1, "scale", err) < 0)
            return -1;
        if (!(place->scale > 0))
            return parse_error(ps, err, "the scale must be positive");
        word = read_word(ps);
    }
    if (word != NULL && strcmp(word, "translate") == 0) {
        double v[3];
        if (read_numbers(ps, v, 3, "translation x y z", err) < 0)
            return -1;
        place->translation = vec3_at(v);
        word = read_word(ps);
    }
    if (word != NULL)
        return error_set(err, ps->file, ps->line, "obj: unexpected '%s' (expected rotate AX AY "
                         "AZ DEGREES, scale S, then translate X Y Z)", word);
    return 0;
}

/* "obj FILE MATERIAL [rotate AX AY AZ DEGREES] [scale S] [translate X Y Z]": the OBJ
 * mesh's faces (scene/obj.c), each vertex p placed at S R p + (X, Y, Z), R the turn;
 * no turn, S = 1 and no translation by default. */
int parse_obj(struct parser *ps, struct error *err)
{
    char path[MAX_PATH_LENGTH];
    if (read_path(ps, path, err) < 0)
        return -1;
    struct obj_placement place = obj_unmoved(read_material(ps, err));
    if (place.material < 0 || read_placement(ps, &place, err) < 0 ||
        check_named_file(ps, path, err) < 0)
        return -1;
    return obj_import(ps->scene, path, &place, err);
}

