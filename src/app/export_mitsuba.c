/*
 * app/export_mitsuba.c -- the scene as a Mitsuba 3 scene (XML, version 3.0.0), with its
 * triangle meshes in OBJ files beside it: Mitsuba's XML holds no vertices.
 *
 * Conventions:
 *   - Variant. Render with an RGB variant (scalar_rgb, llvm_ad_rgb): our colours are
 *     linear RGB, and a spectral variant would upsample them (see export_pbrt.c).
 *   - Camera. Mitsuba's lookat puts the camera's +x, cross(up, dir), on the left of the
 *     image, which is where our right-handed frame has -u: the picture is not mirrored,
 *     no flip is needed. fov_axis "y" makes "fov" our full vertical field of view. A thin
 *     lens is the "thinlens" sensor: aperture_radius our radius, focus_distance our
 *     distance in focus (its plane, as ours, that far along the view direction).
 *   - Pixels. A "box" reconstruction filter (radius 1/2): the mean over the pixel.
 *   - Lights. An "area" emitter gives radiance Le from the side its shape's normal points
 *     to (a mesh's counter-clockwise side, a sphere's outside), as ours; it has no
 *     two-sided form (noted). A point light's "intensity" is Phi / (4 pi).
 *   - Materials. Mitsuba's diffuse, conductor and rough conductor reflect from the front
 *     only, ours from both sides: they are wrapped in "twosided". Lambert is "diffuse";
 *     a mirror is a "conductor" of material "none" (Fresnel 1) scaled by our reflectance;
 *     glass is "dielectric" (exact Fresnel, radiance scaled by 1/eta^2 on refraction) with
 *     our colour filter as its specular_transmittance, applied at each refraction as
 *     ours; Phong, Ward and Schlick as export_glossy_blend() says (Schlick exactly when
 *     isotropic), through "blendbsdf".
 *   - Geometry. Spheres are spheres; every mesh is an OBJ file NAME-meshK.obj (NAME the
 *     output without .xml), with "face_normals" when it has no vertex normals, so that
 *     Mitsuba does not smooth our flat triangles.
 */
#include <math.h>
#include <string.h>

#include "../base/output.h"
#include "export.h"

#define PI 3.14159265358979323846

/* ---- materials ---- */

static void write_rgb(FILE *f, const char *indent, const char *name, struct vec3 c)
{
    fprintf(f, "%s<rgb name=\"%s\" value=\"", indent, name);
    export_rgb(f, ", ", c);
    fprintf(f, "\"/>\n");
}

/* A mirror of Fresnel 1 (material "none"), smooth or with a microfacet lobe. */
static void write_conductor(FILE *f, const char *indent, struct vec3 reflectance,
                            const struct glossy_blend *rough)
{
    if (rough == NULL) {
        fprintf(f, "%s<bsdf type=\"conductor\">\n", indent);
    } else {
        fprintf(f, "%s<bsdf type=\"roughconductor\">\n", indent);
        fprintf(f, "%s    <string name=\"distribution\" value=\"%s\"/>\n", indent,
                rough->ggx ? "ggx" : "beckmann");
        fprintf(f, "%s    <float name=\"alpha_u\" value=\"%.9g\"/>\n", indent, rough->alpha_u);
        fprintf(f, "%s    <float name=\"alpha_v\" value=\"%.9g\"/>\n", indent, rough->alpha_v);
    }
    fprintf(f, "%s    <string name=\"material\" value=\"none\"/>\n", indent);
    char inner[64];
    snprintf(inner, sizeof inner, "%s    ", indent);
    write_rgb(f, inner, "specular_reflectance", reflectance);
    fprintf(f, "%s</bsdf>\n", indent);
}

static void write_diffuse(FILE *f, const char *indent, struct vec3 reflectance)
{
    char inner[64];
    fprintf(f, "%s<bsdf type=\"diffuse\">\n", indent);
    snprintf(inner, sizeof inner, "%s    ", indent);
    write_rgb(f, inner, "reflectance", reflectance);
    fprintf(f, "%s</bsdf>\n", indent);
}

/* Phong, Ward, Schlick: the blend of export_glossy_blend(); blendbsdf's weight is the
 * second BSDF's. */
static void write_glossy(FILE *f, const struct material *m)
{
    struct glossy_blend g = export_glossy_blend(m);
    const char *indent = "            ";
    fprintf(f, "        <bsdf type=\"blendbsdf\">\n");
    fprintf(f, "            <float name=\"weight\" value=\"%.9g\"/>\n", g.w);
    if (g.base_is_mirror)
        write_conductor(f, indent, g.base, NULL);
    else
        write_diffuse(f, indent, g.base);
    write_conductor(f, indent, g.lobe, &g);
    fprintf(f, "        </bsdf>\n");
    if (!g.exact)
        export_note("mitsuba: material \"%s\": Mitsuba has no %s model; written as a blend "
                    "of a %s surface and a %s lobe (slopes %.3g, %.3g) with weight %.3g: %s",
                    m->name, export_model_name(m), g.base_is_mirror ? "mirror" : "Lambertian",
                    g.ggx ? "GGX" : "Beckmann", g.alpha_u, g.alpha_v, g.w,
                    m->kind == MATERIAL_SCHLICK
                        ? "exact but for the anisotropic lobe's orientation, which Mitsuba "
                          "takes from its own tangent frame"
                        : "the diffuse part is exact, the glossy lobe's shape is not");
}

static void write_material(FILE *f, const struct export_scene *es, size_t i)
{
    const struct material *m = &es->materials[i];
    fprintf(f, "    <!-- material %zu: ", i);
    export_name(f, m->name);
    fprintf(f, " -->\n");
    if (m->kind == MATERIAL_GLASS) {
        fprintf(f, "    <bsdf type=\"dielectric\" id=\"m%zu\">\n", i);
        fprintf(f, "        <float name=\"int_ior\" value=\"%.15g\"/>\n", m->ior);
        fprintf(f, "        <float name=\"ext_ior\" value=\"1\"/>\n");
        write_rgb(f, "        ", "specular_transmittance",
                  vec3_sub(vec3(1, 1, 1), m->absorption));
        fprintf(f, "    </bsdf>\n");
        return;
    }
    /* Ours reflect on both sides. */
    fprintf(f, "    <bsdf type=\"twosided\" id=\"m%zu\">\n", i);
    if (m->kind == MATERIAL_LAMBERT)
        write_diffuse(f, "        ", m->rho);
    else if (m->kind == MATERIAL_MIRROR)
        write_conductor(f, "        ", m->rho, NULL);
    else
        write_glossy(f, m);
    fprintf(f, "    </bsdf>\n");
}

/* ---- shapes ---- */

/* Inside a <shape>: the material, and the area emitter when it emits. */
static void write_surface(FILE *f, const struct export_scene *es, int material)
{
    const struct material *m = &es->materials[material];
    fprintf(f, "        <ref id=\"m%d\"/>\n", material);
    if (material_emits(m)) {
        fprintf(f, "        <emitter type=\"area\">\n");
        write_rgb(f, "            ", "radiance", m->emission);
        fprintf(f, "        </emitter>\n");
    }
}

static void write_sphere(FILE *f, const struct export_scene *es, const struct export_sphere *s)
{
    fprintf(f, "    <shape type=\"sphere\">\n");
    fprintf(f, "        <point name=\"center\" x=\"%.15g\" y=\"%.15g\" z=\"%.15g\"/>\n",
            s->centre.x, s->centre.y, s->centre.z);
    fprintf(f, "        <float name=\"radius\" value=\"%.15g\"/>\n", s->radius);
    write_surface(f, es, s->material);
    fprintf(f, "    </shape>\n");
}

void export_mitsuba_mesh_name(const char *output, size_t k, char *path, size_t size,
                              const char **base)
{
    const char *slash = strrchr(output, '/');
    size_t dir = slash != NULL ? (size_t)(slash + 1 - output) : 0;
    const char *dot = strrchr(output + dir, '.');
    size_t stem = dot != NULL ? (size_t)(dot - output) : strlen(output);
    snprintf(path, size, "%.*s-mesh%zu.obj", (int)(stem < 900 ? stem : 900), output, k);
    *base = path + dir;
}

static int write_obj(const char *name, const struct export_mesh *m, struct error *err)
{
    FILE *f = output_open(name, err); /* declared by export_command() */
    if (f == NULL)
        return -1;
    size_t n = 3 * m->n_triangles;
    fprintf(f, "# %zu triangles, counter-clockwise seen from the front\n", m->n_triangles);
    for (size_t i = 0; i < n; i++)
        fprintf(f, "v %.15g %.15g %.15g\n", m->vertices[i].x, m->vertices[i].y,
                m->vertices[i].z);
    for (size_t i = 0; m->normals != NULL && i < n; i++)
        fprintf(f, "vn %.15g %.15g %.15g\n", m->normals[i].x, m->normals[i].y,
                m->normals[i].z);
    for (size_t t = 0; t < m->n_triangles; t++) {
        size_t a = 3 * t + 1; /* OBJ counts from 1 */
        if (m->normals != NULL)
            fprintf(f, "f %zu//%zu %zu//%zu %zu//%zu\n", a, a, a + 1, a + 1, a + 2, a + 2);
        else
            fprintf(f, "f %zu %zu %zu\n", a, a + 1, a + 2);
    }
    return output_commit(f, err);
}

static int write_mesh(FILE *f, const struct export_scene *es, size_t k, struct error *err)
{
    const struct export_mesh *m = &es->meshes[k];
    char path[1024];
    const char *base;
    export_mitsuba_mesh_name(es->output, k, path, sizeof path, &base);
    if (write_obj(path, m, err) < 0)
        return -1;
    fprintf(f, "    <shape type=\"obj\">\n");
    fprintf(f, "        <string name=\"filename\" value=\"%s\"/>\n", base);
    if (m->normals == NULL)
        fprintf(f, "        <boolean name=\"face_normals\" value=\"true\"/>\n");
    write_surface(f, es, m->material);
    fprintf(f, "    </shape>\n");
    return 0;
}

/* ---- the scene ---- */

static void write_header(FILE *f, const struct export_scene *es)
{
    const struct camera *c = &es->camera;
    fprintf(f, "<!-- ");
    export_name(f, es->scene_path);
    fprintf(f, " for Mitsuba 3, written by photon export%s.\n     render: mitsuba -m "
            "scalar_rgb ", es->channel >= 0 ? " (one channel: every colour grey)" : "");
    export_name(f, es->output);
    fprintf(f, " -->\n");
    fprintf(f, "<scene version=\"3.0.0\">\n");
    fprintf(f, "    <integrator type=\"path\">\n");
    fprintf(f, "        <integer name=\"max_depth\" value=\"-1\"/>\n");
    fprintf(f, "    </integrator>\n");
    fprintf(f, "    <sensor type=\"%s\">\n", c->lens_radius > 0 ? "thinlens" : "perspective");
    if (c->lens_radius > 0) {
        fprintf(f, "        <float name=\"aperture_radius\" value=\"%.15g\"/>\n", c->lens_radius);
        fprintf(f, "        <float name=\"focus_distance\" value=\"%.15g\"/>\n", c->focus);
    }
    fprintf(f, "        <string name=\"fov_axis\" value=\"y\"/>\n");
    fprintf(f, "        <float name=\"fov\" value=\"%.15g\"/>\n", c->fov);
    fprintf(f, "        <transform name=\"to_world\">\n");
    fprintf(f, "            <lookat origin=\"%.15g, %.15g, %.15g\" target=\"%.15g, %.15g, "
               "%.15g\" up=\"%.15g, %.15g, %.15g\"/>\n",
            c->from.x, c->from.y, c->from.z, c->at.x, c->at.y, c->at.z, c->up.x, c->up.y,
            c->up.z);
    fprintf(f, "        </transform>\n");
    fprintf(f, "        <sampler type=\"independent\">\n");
    fprintf(f, "            <integer name=\"sample_count\" value=\"%d\"/>\n", es->spp);
    fprintf(f, "        </sampler>\n");
    fprintf(f, "        <film type=\"hdrfilm\">\n");
    fprintf(f, "            <integer name=\"width\" value=\"%d\"/>\n", es->width);
    fprintf(f, "            <integer name=\"height\" value=\"%d\"/>\n", es->height);
    fprintf(f, "            <string name=\"pixel_format\" value=\"rgb\"/>\n");
    fprintf(f, "            <string name=\"file_format\" value=\"pfm\"/>\n");
    fprintf(f, "            <rfilter type=\"box\"/>\n");
    fprintf(f, "        </film>\n");
    fprintf(f, "    </sensor>\n");
}

static void write_lights(FILE *f, const struct export_scene *es)
{
    for (size_t i = 0; i < es->n_point_lights; i++) {
        const struct light *l = &es->point_lights[i];
        fprintf(f, "    <!-- point light of power %g %g %g W: intensity Phi / (4 pi) -->\n",
                l->power.x, l->power.y, l->power.z);
        fprintf(f, "    <emitter type=\"point\">\n");
        fprintf(f, "        <point name=\"position\" x=\"%.15g\" y=\"%.15g\" z=\"%.15g\"/>\n",
                l->position.x, l->position.y, l->position.z);
        write_rgb(f, "        ", "intensity", vec3_scale(l->power, 1.0 / (4.0 * PI)));
        fprintf(f, "    </emitter>\n");
    }
    struct vec3 b = es->background;
    if (b.x > 0 || b.y > 0 || b.z > 0) {
        fprintf(f, "    <emitter type=\"constant\">\n");
        write_rgb(f, "        ", "radiance", b);
        fprintf(f, "    </emitter>\n");
    }
}

int export_mitsuba(FILE *f, const struct export_scene *es, struct error *err)
{
    write_header(f, es);
    for (size_t i = 0; i < es->n_materials; i++) {
        if (!es->material_used[i])
            continue;
        write_material(f, es, i);
        if (material_emits(&es->materials[i]) && es->materials[i].two_sided)
            export_note("mitsuba: material \"%s\": Mitsuba's area emitters are one-sided; "
                        "its back side does not emit there", es->materials[i].name);
    }
    write_lights(f, es);
    for (size_t i = 0; i < es->n_spheres; i++)
        write_sphere(f, es, &es->spheres[i]);
    for (size_t k = 0; k < es->n_meshes; k++)
        if (write_mesh(f, es, k, err) < 0)
            return -1;
    fprintf(f, "</scene>\n");
    return 0;
}
