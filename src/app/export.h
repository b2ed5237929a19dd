/*
 * app/export.h -- `photon export`: a scene written for another renderer, so that a user
 * of pbrt-v4, Mitsuba 3 or Blender (Cycles) can render the very scene of a reference.
 *
 * export.c loads the scene, flattens its geometry into plain spheres, triangles and quads
 * (a procedural shape through its shape_ops.primitives: a sphere flake as its spheres, a
 * heightfield as its triangles), groups the triangles by material into meshes and hands
 * the result, a struct export_scene, to one writer per format (export_pbrt.c,
 * export_mitsuba.c, export_blender.c). A writer reads nothing else: no mode, no BVH.
 *
 * Conventions every writer keeps (README: Rendering our scenes elsewhere):
 *   - a pinhole or thin-lens camera of our full vertical field of view, right-handed,
 *     +u right;
 *   - a pixel is the mean radiance over its square: a box filter of radius 1/2;
 *   - area lights are one-sided (two_sided materials both) and given by radiance Le;
 *     point lights by power Phi per channel, intensity Phi / (4 pi);
 *   - linear RGB, or with --channel one channel's values on every colour (a grey scene).
 * What a target cannot do exactly, its writer says on stderr (export_note), never silently.
 */
#ifndef PHOTON_EXPORT_H
#define PHOTON_EXPORT_H

#include <stdio.h>

#include "../base/option_equals.h"
#include "../scene/scene.h"

#define EXPORT_DEFAULT_SPP 1024

enum export_format { EXPORT_PBRT, EXPORT_MITSUBA, EXPORT_BLENDER };

struct export_sphere {
    struct vec3 centre;
    double radius;
    int material;
};

/* The triangles of one material, all with vertex normals or all without; quads come as
 * two triangles (p0, p0 + e1, p0 + e1 + e2) and (p0, p0 + e1 + e2, p0 + e2), which keep
 * the front side e1 x e2. Vertices are not shared: triangle t is vertices 3t .. 3t + 2. */
struct export_mesh {
    int material;
    size_t n_triangles;
    struct vec3 *vertices; /* owned: 3 n_triangles, counter-clockwise seen from the front */
    struct vec3 *normals;  /* owned: 3 n_triangles unit shading normals, or NULL        */
};

struct export_scene {
    const char *scene_path;
    int width, height;
    struct camera camera;        /* set up for width x height                         */
    struct vec3 background;      /* radiance of rays that leave the scene              */
    struct material *materials;  /* owned copies (with --channel, grey)                */
    size_t n_materials;
    int *material_used;          /* owned: per material, whether any primitive has it  */
    struct light *point_lights;  /* owned copies of the point lights                   */
    size_t n_point_lights;
    struct export_sphere *spheres; /* owned                                            */
    size_t n_spheres;
    struct export_mesh *meshes;  /* owned                                              */
    size_t n_meshes;
    int spp;                     /* samples a pixel for the target's path tracer      */
    int channel;                 /* -1 RGB; 0, 1, 2: every colour is that channel's     */
    const char *output;          /* the file written (for names of companion files)    */
};

/* Builds the export scene from a finished scene (spp and channel as above). */
void export_scene_make(struct export_scene *es, const struct scene *scene, int spp,
                       int channel);
void export_scene_free(struct export_scene *es);

/* "photon: export: " and a line on stderr: what the target renders differently. */
void export_note(const char *format, ...);

/* Mitsuba's mesh k, NAME-meshK.obj beside the output NAME.xml: into path[size] (with the
 * output's directory) and *base (without it, for the XML, which Mitsuba reads relative to
 * its own folder). export_command() declares each as an output before anything is
 * written (base/output.h). */
void export_mitsuba_mesh_name(const char *output, size_t k, char *path, size_t size,
                              const char **base);

/* The writers: the whole scene to f. 0, or -1 with *err filled. */
int export_pbrt(FILE *f, const struct export_scene *es, struct error *err);
int export_mitsuba(FILE *f, const struct export_scene *es, struct error *err);
int export_blender(FILE *f, const struct export_scene *es, struct error *err);

/* Phong, Ward and Schlick as Mitsuba and pbrt can build them: a blend, with weights 1 - w
 * and w, of a base -- a Lambertian surface, or for Schlick's r < 1/2 a smooth mirror -- of
 * reflectance `base` and a microfacet mirror (Fresnel 1) of reflectance `lobe` and rms
 * slopes alpha_u, alpha_v along our shading frame's t and b; the blend's mean is the sum
 * of the two parts.
 *   Schlick (scene/schlick.c) is exactly such a sum: C a / pi or C c delta, plus C b times
 *   a GGX lobe with alpha_u = sqrt(r p), alpha_v = sqrt(r / p) and Smith masking; so
 *   w = b, both reflectances C. Exact when isotropic (p = 1): the targets orient an
 *   anisotropic lobe by their own tangent frame.
 *   Phong and Ward are rho / pi plus a lobe that is no microfacet model: the closest is a
 *   Beckmann lobe of slopes sqrt(2 / (n + 2)) (Phong's exponent n, Walter et al. 2007,
 *   Sec. 5.2) or Ward's alpha_x, alpha_y. w = the largest channel of rho_s keeps both
 *   reflectances at most 1 where that is possible. Never exact. */
struct glossy_blend {
    double w;              /* the lobe's weight, in (0, 1]                   */
    int base_is_mirror;    /* the base is a smooth mirror, not Lambertian   */
    struct vec3 base;      /* the base's reflectance                        */
    struct vec3 lobe;      /* the lobe's reflectance                        */
    double alpha_u, alpha_v;
    int ggx;               /* the lobe's distribution: 1 GGX, 0 Beckmann      */
    int exact;             /* whether the blend is our model exactly         */
};
struct glossy_blend export_glossy_blend(const struct material *m);
const char *export_model_name(const struct material *m); /* "Phong", "Ward", ... */

/* A name (a material's, a file's) in a comment: letters, digits, " _.#+/,:=()" and a '-'
 * not after another as they are, any other byte as '_': a newline cannot end the comment
 * and start a directive, and an XML comment never holds "--". */
void export_name(FILE *f, const char *name);

/* A colour as the target reads it, with %.9g: enough digits to give back our doubles'
 * floats, which is what every target stores. */
void export_rgb(FILE *f, const char *separator, struct vec3 c);

/* `photon export --format pbrt|mitsuba|blender SCENE -o OUT [--spp N] [--channel R|G|B]
 * [--width N] [--height N]`: argv[0] is "export"; OUT ends in the format's ending, .pbrt,
 * .xml or .py, after a name; --width and --height, as the render command's, replace the
 * scene's image size. Returns the exit status. */
int export_command(int argc, char **argv);

/* Its options, for --NAME=VALUE (app/commands.h); a NULL name ends them. */
extern const struct option_arity export_options[];

#endif
