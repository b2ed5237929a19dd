/*
 * scene/parse.c -- the scene file reader: one keyword per line (README, "Scene files").
 *
 * A file is read line by line; '#' starts a comment anywhere a token may start; tokens are
 * separated by any white space. Each keyword has one function that takes its numbers and
 * names, checks them (finite, in range, names defined) and adds to the scene. Any problem
 * fills *err with the file, the line and what was expected, and parsing stops: the
 * caller frees the partial scene (scene_load), and nothing has been written anywhere.
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"
#include "../geom/heightfield.h"
#include "../geom/sphereflake.h"
#include "../image/image.h"
#include "scene.h"

#define MAX_LINE 4096         /* longest line, in bytes, including the newline          */
#define MAX_TOKENS 64         /* the longest keyword line (smooth_triangle) has 20      */
#define MAX_INCLUDE_DEPTH 16  /* include nesting; deeper is taken for an include cycle  */
#define MAX_PATH_LENGTH 1024  /* longest path an include may produce                    */

struct parser {
    struct scene *scene;
    const char *file;          /* the file being read, as named                */
    int line;                  /* 1-based line number in file                  */
    int depth;                 /* include depth of this file, 0 at the top     */
    char text[MAX_LINE];       /* the current line, cut into tokens in place   */
    char *tokens[MAX_TOKENS];  /* the current line's tokens                    */
    int n_tokens;
    int next;                  /* index of the next token to be read           */
};

static int parse_file(struct scene *scene, const char *path, int depth, struct error *err);

/* Fills *err with "file:line: keyword: message" and returns -1. */
static int parse_error(const struct parser *ps, struct error *err, const char *message)
{
    return error_set(err, ps->file, ps->line, "%s: %s", ps->tokens[0], message);
}

static const char *read_word(struct parser *ps)
{
    return ps->next < ps->n_tokens ? ps->tokens[ps->next++] : NULL;
}

/* Reads n numbers; `what` names them for the message ("centre x y z, radius"). */
static int read_numbers(struct parser *ps, double *v, int n, const char *what,
                        struct error *err)
{
    for (int i = 0; i < n; i++) {
        const char *word = read_word(ps);
        char *end = NULL;
        if (word == NULL)
            return error_set(err, ps->file, ps->line, "%s: expected %d numbers (%s), got %d",
                             ps->tokens[0], n, what, i);
        v[i] = strtod(word, &end);
        if (end == word || *end != '\0')
            return error_set(err, ps->file, ps->line, "%s: '%s' is not a number (expected %s)",
                             ps->tokens[0], word, what);
        if (!isfinite(v[i]))
            return error_set(err, ps->file, ps->line, "%s: number '%s' is not finite",
                             ps->tokens[0], word);
    }
    return 0;
}

/* Whether the next word is a number (an optional parameter follows). */
static int next_is_number(const struct parser *ps)
{
    if (ps->next >= ps->n_tokens)
        return 0;
    char *end = NULL;
    strtod(ps->tokens[ps->next], &end);
    return end != ps->tokens[ps->next] && *end == '\0';
}

static int expect_end(struct parser *ps, struct error *err)
{
    const char *extra = read_word(ps);
    if (extra == NULL)
        return 0;
    return error_set(err, ps->file, ps->line, "%s: unexpected '%s' at the end of the line",
                     ps->tokens[0], extra);
}

/* Reads a material name that must already be defined; returns its index or -1. */
static int read_material(struct parser *ps, struct error *err)
{
    const char *name = read_word(ps);
    if (name == NULL)
        return parse_error(ps, err, "expected a material name at the end");
    int m = scene_find_material(ps->scene, name);
    if (m < 0)
        return error_set(err, ps->file, ps->line, "%s: undefined material '%s'",
                         ps->tokens[0], name);
    return m;
}

static struct vec3 vec3_at(const double *v) { return vec3(v[0], v[1], v[2]); }

static int is_colour_in(const double *v, double lo, double hi)
{
    for (int i = 0; i < 3; i++)
        if (!(v[i] >= lo && v[i] <= hi))
            return 0;
    return 1;
}

/* "image WIDTH HEIGHT" */
static int parse_image(struct parser *ps, struct error *err)
{
    double v[2];
    if (read_numbers(ps, v, 2, "width, height in pixels", err) < 0)
        return -1;
    for (int i = 0; i < 2; i++)
        if (!(v[i] >= 1 && v[i] <= MAX_IMAGE_SIDE && v[i] == floor(v[i])))
            return error_set(err, ps->file, ps->line,
                             "image: size must be whole numbers from 1 to %d, got %g",
                             MAX_IMAGE_SIDE, v[i]);
    ps->scene->width = (int)v[0];
    ps->scene->height = (int)v[1];
    return expect_end(ps, err);
}

/* "camera FROM_X FROM_Y FROM_Z  AT_X AT_Y AT_Z  UP_X UP_Y UP_Z  FOV_DEGREES" */
static int parse_camera(struct parser *ps, struct error *err)
{
    double v[10];
    if (read_numbers(ps, v, 10, "position x y z, look-at x y z, up x y z, vertical fov", err))
        return -1;
    struct camera *c = &ps->scene->camera;
    c->from = vec3_at(v);
    c->at = vec3_at(v + 3);
    c->up = vec3_at(v + 6);
    c->fov = v[9];
    if (!(c->fov > 0 && c->fov < 180))
        return parse_error(ps, err, "vertical field of view must be in (0, 180) degrees");
    if (!camera_is_valid(c))
        return parse_error(ps, err, "look-at point equals the position, or up is parallel "
                                    "to the viewing direction");
    ps->scene->has_camera = 1;
    return expect_end(ps, err);
}

/* "background R G B": radiance of rays that leave the scene */
static int parse_background(struct parser *ps, struct error *err)
{
    double v[3];
    if (read_numbers(ps, v, 3, "radiance r g b", err) < 0)
        return -1;
    if (!is_colour_in(v, 0, HUGE_VAL))
        return parse_error(ps, err, "radiance must not be negative");
    ps->scene->background = vec3_at(v);
    return expect_end(ps, err);
}

/* Reads an RGB reflectance, each channel in [0, 1]. */
static int read_reflectance(struct parser *ps, struct vec3 *rho, const char *what,
                            struct error *err)
{
    double v[3];
    if (read_numbers(ps, v, 3, what, err) < 0)
        return -1;
    if (!is_colour_in(v, 0, 1))
        return error_set(err, ps->file, ps->line, "%s: %s must be in [0, 1] per channel",
                         ps->tokens[0], what);
    *rho = vec3_at(v);
    return 0;
}

/* Whether a + b <= 1 in every channel: the energy bound of a two-lobe model. */
static int sums_to_at_most_one(struct vec3 a, struct vec3 b)
{
    return a.x + b.x <= 1 && a.y + b.y <= 1 && a.z + b.z <= 1;
}

/* "phong KD_R KD_G KD_B KS_R KS_G KS_B EXPONENT" */
static int parse_phong(struct parser *ps, struct material *m, struct error *err)
{
    if (read_reflectance(ps, &m->rho, "diffuse kd r g b", err) < 0 ||
        read_reflectance(ps, &m->rho_s, "specular ks r g b", err) < 0 ||
        read_numbers(ps, &m->exponent, 1, "exponent", err) < 0)
        return -1;
    if (!sums_to_at_most_one(m->rho, m->rho_s))
        return parse_error(ps, err, "phong: kd + ks must not exceed 1 in any channel");
    if (!(m->exponent >= 0))
        return parse_error(ps, err, "phong: the exponent must not be negative");
    return 0;
}

/* "ward RD_R RD_G RD_B RS_R RS_G RS_B ALPHA_X ALPHA_Y" */
static int parse_ward(struct parser *ps, struct material *m, struct error *err)
{
    double alpha[2];
    if (read_reflectance(ps, &m->rho, "diffuse rho_d r g b", err) < 0 ||
        read_reflectance(ps, &m->rho_s, "specular rho_s r g b", err) < 0 ||
        read_numbers(ps, alpha, 2, "alpha_x, alpha_y", err) < 0)
        return -1;
    if (!sums_to_at_most_one(m->rho, m->rho_s))
        return parse_error(ps, err, "ward: rho_d + rho_s must not exceed 1 in any channel");
    if (!(alpha[0] > 0 && alpha[1] > 0))
        return parse_error(ps, err, "ward: alpha_x and alpha_y must be positive");
    m->alpha_x = alpha[0];
    m->alpha_y = alpha[1];
    return 0;
}

/* "schlick C_R C_G C_B ROUGHNESS [ISOTROPY]" */
static int parse_schlick(struct parser *ps, struct material *m, struct error *err)
{
    if (read_reflectance(ps, &m->rho, "colour r g b", err) < 0 ||
        read_numbers(ps, &m->roughness, 1, "roughness", err) < 0)
        return -1;
    if (!(m->roughness >= 0 && m->roughness <= 1))
        return parse_error(ps, err, "schlick: roughness must be in [0, 1]");
    m->isotropy = 1.0; /* isotropic unless a number follows */
    if (next_is_number(ps) && read_numbers(ps, &m->isotropy, 1, "isotropy", err) < 0)
        return -1;
    if (!(m->isotropy > 0 && m->isotropy <= 1))
        return parse_error(ps, err, "schlick: isotropy must be in (0, 1]");
    return 0;
}

/* The reflection part of "material NAME KIND ...". */
static int parse_material_kind(struct parser *ps, struct material *m, struct error *err)
{
    const char *kind = read_word(ps);
    if (kind == NULL)
        return parse_error(ps, err, "expected a kind after the name: lambert, mirror, glass, "
                                    "phong, ward or schlick");
    if (strcmp(kind, "lambert") == 0 || strcmp(kind, "mirror") == 0) {
        m->kind = kind[0] == 'l' ? MATERIAL_LAMBERT : MATERIAL_MIRROR;
        return read_reflectance(ps, &m->rho, "reflectance r g b", err);
    }
    if (strcmp(kind, "glass") == 0) {
        m->kind = MATERIAL_GLASS;
        if (read_numbers(ps, &m->ior, 1, "index of refraction", err) < 0)
            return -1;
        return m->ior > 0 ? 0 : parse_error(ps, err, "index of refraction must be positive");
    }
    static const struct {
        const char *name;
        enum material_kind kind;
        int (*parse)(struct parser *ps, struct material *m, struct error *err);
    } models[] = {{"phong", MATERIAL_PHONG, parse_phong},
                  {"ward", MATERIAL_WARD, parse_ward},
                  {"schlick", MATERIAL_SCHLICK, parse_schlick}};
    for (size_t i = 0; i < sizeof models / sizeof models[0]; i++)
        if (strcmp(kind, models[i].name) == 0) {
            m->kind = models[i].kind;
            return models[i].parse(ps, m, err);
        }
    return error_set(err, ps->file, ps->line,
                     "material: unknown kind '%s' (expected lambert, mirror, glass, phong, "
                     "ward or schlick)", kind);
}

/* The optional end "emit R G B [twosided]" of a material line. */
static int parse_emission(struct parser *ps, struct material *m, struct error *err)
{
    const char *word = read_word(ps);
    if (word == NULL)
        return 0;
    if (strcmp(word, "emit") != 0)
        return error_set(err, ps->file, ps->line, "material: unexpected '%s' (expected emit)",
                         word);
    double v[3];
    if (read_numbers(ps, v, 3, "emitted radiance r g b", err) < 0)
        return -1;
    if (!is_colour_in(v, 0, HUGE_VAL))
        return parse_error(ps, err, "emitted radiance must not be negative");
    m->emission = vec3_at(v);
    word = read_word(ps);
    if (word != NULL && strcmp(word, "twosided") == 0)
        m->two_sided = 1;
    else if (word != NULL)
        ps->next--; /* not ours: expect_end() reports it */
    return 0;
}

/* "material NAME KIND PARAMETERS [emit R G B [twosided]]" */
static int parse_material(struct parser *ps, struct error *err)
{
    struct material m;
    memset(&m, 0, sizeof m);
    const char *name = read_word(ps);
    if (name == NULL)
        return parse_error(ps, err, "expected a name");
    if (strlen(name) >= MATERIAL_NAME_MAX)
        return parse_error(ps, err, "name is too long");
    if (scene_find_material(ps->scene, name) >= 0)
        return error_set(err, ps->file, ps->line, "material: '%s' is already defined", name);
    strcpy(m.name, name);
    if (parse_material_kind(ps, &m, err) < 0)
        return -1;
    if (parse_emission(ps, &m, err) < 0)
        return -1;
    if (scene_add_material(ps->scene, &m) < 0)
        return parse_error(ps, err, "too many materials");
    return expect_end(ps, err);
}

/* Reports a failed scene_add_*(): the only cause is a documented limit. */
static int check_added(struct parser *ps, int id, struct error *err)
{
    if (id >= 0)
        return 0;
    return error_set(err, ps->file, ps->line, "%s: more than %d primitives or %d lights",
                     ps->tokens[0], MAX_PRIMITIVES, MAX_LIGHTS);
}

/* "sphere CX CY CZ RADIUS MATERIAL" */
static int parse_sphere(struct parser *ps, struct error *err)
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
static int parse_triangle(struct parser *ps, struct error *err)
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
static int parse_quad(struct parser *ps, struct error *err)
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
static int parse_light(struct parser *ps, struct error *err)
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
static int parse_sphereflake(struct parser *ps, struct error *err)
{
    struct sphereflake_params params;
    double v[8];
    int n = 0;
    if (read_numbers(ps, v, 8, "centre x y z, radius, levels, axis x y z", err) < 0)
        return -1;
    if (!(v[4] >= 0 && v[4] <= SPHEREFLAKE_MAX_LEVELS && v[4] == floor(v[4])))
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
static int parse_heightfield(struct parser *ps, struct error *err)
{
    double v[10];
    if (read_numbers(ps, v, 10, "corner x y z, size, resolution, octaves, roughness, "
                                "frequency, height, seed", err) < 0)
        return -1;
    if (!(v[4] == floor(v[4]) && v[5] == floor(v[5]) && v[9] == floor(v[9]) &&
          v[4] >= 0 && v[4] <= HEIGHTFIELD_MAX_RESOLUTION && v[5] >= 0 &&
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

/* "include FILE": FILE is relative to the directory of the including file. */
static int parse_include(struct parser *ps, struct error *err)
{
    const char *name = read_word(ps);
    if (name == NULL)
        return parse_error(ps, err, "expected a file name");
    if (expect_end(ps, err) < 0)
        return -1;
    if (ps->depth + 1 > MAX_INCLUDE_DEPTH)
        return error_set(err, ps->file, ps->line,
                         "include: nested more than %d deep (an include cycle?)",
                         MAX_INCLUDE_DEPTH);
    char path[MAX_PATH_LENGTH];
    const char *slash = strrchr(ps->file, '/');
    int dir_length = (name[0] == '/' || slash == NULL) ? 0 : (int)(slash - ps->file + 1);
    if (dir_length + strlen(name) + 1 > sizeof path)
        return parse_error(ps, err, "path is too long");
    sprintf(path, "%.*s%s", dir_length, ps->file, name);
    return parse_file(ps->scene, path, ps->depth + 1, err);
}

struct keyword {
    const char *name;
    int (*parse)(struct parser *ps, struct error *err);
};

static const struct keyword keywords[] = {
    {"image", parse_image},       {"camera", parse_camera},
    {"background", parse_background}, {"material", parse_material},
    {"sphere", parse_sphere},     {"triangle", parse_triangle},
    {"smooth_triangle", parse_triangle}, {"quad", parse_quad},
    {"light", parse_light},       {"include", parse_include},
    {"sphereflake", parse_sphereflake}, {"heightfield", parse_heightfield},
};

/* Cuts ps->text into tokens at white space, stopping at a '#' that starts a token. */
static int split_tokens(struct parser *ps, struct error *err)
{
    char *s = ps->text;
    ps->n_tokens = 0;
    ps->next = 1;
    for (;;) {
        while (isspace((unsigned char)*s))
            *s++ = '\0';
        if (*s == '\0' || *s == '#')
            return 0;
        if (ps->n_tokens == MAX_TOKENS)
            return error_set(err, ps->file, ps->line, "more than %d words on a line",
                             MAX_TOKENS);
        ps->tokens[ps->n_tokens++] = s;
        while (*s != '\0' && !isspace((unsigned char)*s))
            s++;
    }
}

static int parse_line(struct parser *ps, struct error *err)
{
    if (split_tokens(ps, err) < 0)
        return -1;
    if (ps->n_tokens == 0)
        return 0;
    for (size_t i = 0; i < sizeof keywords / sizeof keywords[0]; i++)
        if (strcmp(ps->tokens[0], keywords[i].name) == 0)
            return keywords[i].parse(ps, err);
    return error_set(err, ps->file, ps->line, "unknown keyword '%.40s'", ps->tokens[0]);
}

/* Reads every line of one file; stops at the first error. */
static int parse_lines(struct parser *ps, FILE *f, struct error *err)
{
    while (fgets(ps->text, sizeof ps->text, f) != NULL) {
        ps->line++;
        size_t length = strlen(ps->text);
        if (length == sizeof ps->text - 1 && ps->text[length - 1] != '\n' && !feof(f))
            return error_set(err, ps->file, ps->line, "line longer than %d bytes", MAX_LINE - 2);
        if (parse_line(ps, err) < 0)
            return -1;
    }
    if (ferror(f))
        return error_set(err, ps->file, 0, "cannot read the file (is it a directory?)");
    return 0;
}

static int parse_file(struct scene *scene, const char *path, int depth, struct error *err)
{
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return error_set(err, path, 0, "cannot open the file");
    /* The parser is large (a line buffer), so it lives on the heap, not the stack. */
    struct parser *ps = xcalloc(1, sizeof *ps, "parser");
    ps->scene = scene;
    ps->file = path;
    ps->depth = depth;
    int status = parse_lines(ps, f, err);
    free(ps);
    fclose(f);
    return status;
}

struct scene *scene_load(const char *path, struct error *err)
{
    struct scene *scene = scene_create();
    if (parse_file(scene, path, 0, err) < 0) {
        scene_free(scene);
        return NULL;
    }
    if (!scene->has_camera) {
        error_set(err, path, 0, "no camera: a scene needs a 'camera' line");
        scene_free(scene);
        return NULL;
    }
    return scene;
}
