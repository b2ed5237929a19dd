/*
 * scene/scene.h -- everything a render reads: image size, camera, background, materials,
 * lights and geometry.
 *
 * Life cycle: scene_create(), then the scene_add_*() calls (made by the parser or an
 * importer), then scene_finish() once, which builds the BVH; afterwards the scene is only
 * read. A struct scene owns its materials, lights and geometry; scene_free() releases all.
 *
 * Every primitive whose material emits becomes an area light too (spheres, triangles and
 * quads; emitters on other shapes are refused by the parser), so that a ray that hits an
 * emitter can find its light through light_of_prim. A background that is not black becomes
 * the sky, the last light (light.h), once the geometry is complete (scene_add_sky()): one
 * scene keyword, one light, in every mode.
 */
#ifndef PHOTON_SCENE_H
#define PHOTON_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "../base/error.h"
#include "../geom/geometry.h"
#include "camera.h"
#include "light.h"
#include "material.h"
#include "reach_record.h"

#define MAX_MATERIALS 65536 /* documented limit: far beyond any real scene, bounds memory */
#define MAX_LIGHTS 65536    /* likewise; direct lighting samples every light at each hit */
/* Documented limit on the lights' total power Phi, in W per channel (a point light's
 * power, an area light's pi Le A), summed over all lights. A photon leaves a light with
 * Phi_l weight / (p_pick N) (photon/trace.c); p_pick >= lum(Phi_l) / lum(total) and the
 * emission weights stay below 2^18, so under this limit every emitted photon is below
 * 2^122 W, within the 4-byte RGBE power of the 20-byte photon record (2^127 W, photon.h). */
#define MAX_LIGHT_POWER 1e30

/* Why a scene_add_*() failed: its result when negative. */
#define SCENE_FULL (-1)       /* MAX_PRIMITIVES or MAX_LIGHTS reached                  */
#define SCENE_TOO_BRIGHT (-2) /* the lights' total power would pass MAX_LIGHT_POWER   */

struct scene {
    int width, height;           /* image size given by the file (options may override) */
    struct camera camera;        /* set up for width x height by scene_finish()         */
    int has_camera;              /* whether the file gave a camera                      */
    struct vec3 background;      /* radiance of rays that leave the scene: the sky's Le */
    char background_file[ERROR_FILE_MAX]; /* where the background was given, for the   */
    int background_line;                  /* sky's power limit (scene_add_sky())       */
    int sky;                     /* index of the sky among the lights, or -1: a black
                                    background lights nothing and is no light           */
    int sphereflake_levels;      /* LEVELS of the deepest sphere flake, -1 for none:
                                    how far below the flake's radius its spheres go      */
    struct material *materials;  /* owned; n_materials of them                          */
    size_t n_materials;
    struct light *lights;        /* owned; n_lights of them                             */
    size_t n_lights;
    struct vec3 light_power;     /* sum of the lights' light_power(), each channel at
                                    most MAX_LIGHT_POWER                                 */
    double *light_cdf;           /* owned, set by scene_finish(): n_lights + 1 entries,
                                    light_cdf[i + 1] - light_cdf[i] = light i's probability
                                    of being picked, proportional to its power           */
    int *light_of_prim;          /* owned; for each primitive id, its light or -1       */
    size_t n_prims;              /* primitives added so far (= entries of light_of_prim) */
    struct geometry *geometry;   /* owned                                               */
    struct scene_reach reach;    /* how far the readers' lines reach (reach.h)          */
    uint64_t source_hash;        /* FNV-1a (base/hash.h) of every line the readers took
                                    from the scene's files, in reading order, each with
                                    its '\0' (scene_hash_line): with the options, what a
                                    tile's pixels depend on (app/tile.h)                 */
};

struct scene *scene_create(void);
void scene_free(struct scene *scene); /* NULL is a no-op */

/* Folds a line just read from one of the scene's files (a scene file, an include, an NFF
 * or OBJ import) into source_hash, with its terminating '\0', so that where one line ends
 * is hashed too. The bytes after a '\0' inside a line are not hashed: no reader sees them. */
void scene_hash_line(struct scene *scene, const char *line);

/* Adds a material (copied); returns its index, or -1 beyond MAX_MATERIALS. */
int scene_add_material(struct scene *scene, const struct material *m);
/* Index of the material named name, or -1. */
int scene_find_material(const struct scene *scene, const char *name);

/* Add primitives; each returns the primitive id, or SCENE_FULL beyond MAX_PRIMITIVES or
 * MAX_LIGHTS, or SCENE_TOO_BRIGHT when an emitting primitive would take the lights' power
 * past MAX_LIGHT_POWER. An emitting material makes the primitive an area light as well. */
int scene_add_sphere(struct scene *scene, struct vec3 centre, double radius, int material);
int scene_add_triangle(struct scene *scene, const struct vec3 v[3], const struct vec3 *normals,
                       int material);
int scene_add_quad(struct scene *scene, struct vec3 p0, struct vec3 e1, struct vec3 e2,
                   int material);
/* Procedural shape (ownership passes to the scene); its material must not emit. */
int scene_add_shape(struct scene *scene, const struct shape_ops *ops, void *shape, int material);
/* A point light of power Phi (W per channel); returns its light index, or SCENE_FULL or
 * SCENE_TOO_BRIGHT as above. */
int scene_add_point_light(struct scene *scene, struct vec3 position, struct vec3 power);

/* The background's radiance le (finite, >= 0), given at file:line (kept for the sky's
 * errors); the last one given wins. */
void scene_set_background(struct scene *scene, struct vec3 le, const char *file, int line);

/* Makes a background that is not black the sky: a light of radiance Le whose sphere is
 * the one around the box of every primitive (light.h). Call once, after the last
 * primitive. Returns the sky's light index, -1 for a black background (no sky), or
 * SCENE_FULL or SCENE_TOO_BRIGHT as above (the sky's power Le pi R^2 4 pi grows with the
 * scene's size). */
int scene_add_sky(struct scene *scene);

/* The readers' report of a scene_add_*() result: 0 when id >= 0, else -1 with *err filled
 * as "file:line: keyword: " and what limit id < 0 ran into. */
int scene_add_error(int id, const char *file, int line, const char *keyword,
                    struct error *err);

/* Sets the image size, sets up the camera and builds the BVH. Call once, after the adds. */
void scene_finish(struct scene *scene, int width, int height);

/* Picks a light for one sample with probability proportional to the luminance of its
 * power (Phi), uniformly if every light is black; u uniform in [0, 1). Returns the light
 * and its probability in *probability (> 0), or -1 when the scene has no light. */
int scene_pick_light(const struct scene *scene, double u, double *probability);

/* The length of the diagonal of the box around every primitive of the scene (finished),
 * the scale of "the dimensions of the scene"; 1 when there is nothing, or it is not
 * finite, so that sizes derived from it stay usable. */
double scene_diagonal(const struct scene *scene);

/* The probability with which scene_pick_light() picks light. */
double scene_light_probability(const struct scene *scene, int light);

static inline int scene_intersect(const struct scene *scene, struct ray ray, double tmax,
                                  struct hit *hit)
{
    return geometry_intersect(scene->geometry, ray, tmax, hit);
}

/* Whether the segment from origin along unit dir is blocked before distance. The far end
 * is pulled in by a relative SHADOW_EPSILON so the light's own surface does not block it. */
int scene_occluded(const struct scene *scene, struct vec3 origin, struct vec3 dir,
                   double distance);

/* Loads a scene file (parse.c), or an NFF file when path ends in ".nff" (nff.c). NULL with
 * *err filled on bad input. */
struct scene *scene_load(const char *path, struct error *err);

#endif
