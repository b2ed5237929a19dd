/*
 * app/export_pbrt.c -- the scene as a pbrt-v4 scene file (pbrt-v4's "File Format" page).
 *
 * Conventions, each one a way to get a different picture:
 *   - Handedness. pbrt's LookAt gives a camera whose +x, drawn to the right of the image,
 *     is up x dir: in our right-handed frame that is -u, and the image would come out
 *     mirrored. "Scale -1 1 1" before LookAt turns camera x round. It applies to the camera
 *     only: WorldBegin resets the transformation, so no surface changes its orientation.
 *   - Field of view. pbrt's "fov" is that of the image's shorter axis; ours is vertical.
 *   - Lens. pbrt's "lensradius" and "focaldistance" are our thin lens's radius and its
 *     distance in focus: a disc about the camera's position, aimed at the plane that far
 *     along the view direction.
 *   - Pixels. A box filter of radius 1/2: the pixel is the mean over its square.
 *   - Samples. pbrt's "zsobol" sampler takes a count that is no power of 2 down to the
 *     power below (37 would be 32 samples, and SPPM's iterations are its samples too):
 *     such counts get "halton", which takes any.
 *   - Lights. pbrt normalises an RGB emitter to the luminance of its colour space's white
 *     (scale /= SpectrumToPhotometric), so "rgb L" [c c c] has luminance c: area lights are
 *     written with their radiance Le, point lights with intensity I = Phi / (4 pi).
 *   - Colour. pbrt renders spectrally: RGB albedos and emitters are upsampled to spectra
 *     and interreflect slightly differently from RGB (a few % in a saturated channel).
 *     With --channel every colour is grey, a constant spectrum, and the picture's
 *     luminance is our channel exactly (the film: "rgb", sensor "cie1931", ISO 100,
 *     shutter 1 s, so the imaging ratio is 1).
 *   - Materials. Lambert is "diffuse"; a mirror of reflectance r (no Fresnel) is a mix
 *     that picks, point by point, a conductor of reflectance 1 with probability r and a
 *     black surface otherwise, whose mean is r times a perfect mirror; glass is
 *     "dielectric" (exact Fresnel, radiance scaled by 1/eta^2 on refraction, as ours).
 *     Phong, Ward and Schlick have no equivalent: "coateddiffuse" comes closest, and
 *     what differs is printed (export_note).
 */
#include <math.h>
#include <string.h>

#include "export.h"

#define PI 3.14159265358979323846

/* pbrt's "fov": the field of view of the shorter image axis, in degrees. */
static double pbrt_fov(const struct export_scene *es)
{
    if (es->width >= es->height)
        return es->camera.fov;
    double t = tan(es->camera.fov * PI / 360.0) * es->width / es->height;
    return atan(t) * 360.0 / PI;
}

/* The output's name with its extension replaced: the film's file name. */
static void film_name(const char *output, char *name, size_t size)
{
    const char *slash = strrchr(output, '/');
    const char *base = slash != NULL ? slash + 1 : output;
    const char *dot = strrchr(base, '.');
    size_t stem = dot != NULL ? (size_t)(dot - base) : strlen(base);
    snprintf(name, size, "%.*s.pfm", (int)(stem < 400 ? stem : 400), base);
}

static int is_power_of_two(int n)
{
    return n > 0 && (n & (n - 1)) == 0;
}

static void write_header(FILE *f, const struct export_scene *es)
{
    const struct camera *c = &es->camera;
    char film[512];
    film_name(es->output, film, sizeof film);
    fprintf(f, "# ");
    export_name(f, es->scene_path);
    fprintf(f, " for pbrt-v4, written by photon export%s\n# render: pbrt ",
            es->channel >= 0 ? " (one channel: every colour grey)" : "");
    export_name(f, es->output);
    fprintf(f, "   (writes ");
    export_name(f, film);
    fprintf(f, ")\n\n");
    fprintf(f, "# pbrt's LookAt would mirror the image: turn camera x round\n");
    fprintf(f, "Scale -1 1 1\n");
    fprintf(f, "LookAt %.15g %.15g %.15g  %.15g %.15g %.15g  %.15g %.15g %.15g\n", c->from.x,
            c->from.y, c->from.z, c->at.x, c->at.y, c->at.z, c->up.x, c->up.y, c->up.z);
    fprintf(f, "# the shorter image axis's field of view (ours, %.9g, is vertical)\n", c->fov);
    fprintf(f, "Camera \"perspective\" \"float fov\" [%.15g]", pbrt_fov(es));
    if (c->lens_radius > 0) /* pbrt's thin lens aims at the plane z = focaldistance, as ours */
        fprintf(f, "\n    \"float lensradius\" [%.15g] \"float focaldistance\" [%.15g]",
                c->lens_radius, c->focus);
    fprintf(f, "\n");
    fprintf(f, "Sampler \"%s\" \"integer pixelsamples\" [%d]\n",
            is_power_of_two(es->spp) ? "zsobol" : "halton", es->spp);
    fprintf(f, "Integrator \"path\" \"integer maxdepth\" [1000] \"bool regularize\" false\n");
    fprintf(f, "PixelFilter \"box\" \"float xradius\" [0.5] \"float yradius\" [0.5]\n");
    fprintf(f, "Film \"rgb\" \"integer xresolution\" [%d] \"integer yresolution\" [%d]\n",
            es->width, es->height);
    fprintf(f, "    \"string filename\" [\"%s\"] \"string sensor\" \"cie1931\" "
               "\"float iso\" [100]\n\n", film);
    fprintf(f, "WorldBegin\n\n");
}

static int is_grey(struct vec3 c)
{
    return c.x == c.y && c.y == c.z;
}

/* A reflectance pbrt accepts: at most 1 in every channel. */
static struct vec3 albedo(struct vec3 c)
{
    return vec3(fmin(c.x, 1.0), fmin(c.y, 1.0), fmin(c.z, 1.0));
}

/* Phong, Ward, Schlick: export_glossy_blend()'s two parts, mixed point by point. pbrt's
 * conductor gets its Fresnel from the reflectance and its lobe is always GGX, so no
 * such blend is exact here. */
static void write_glossy(FILE *f, size_t i, const struct material *m)
{
    struct glossy_blend g = export_glossy_blend(m);
    if (g.base_is_mirror)
        fprintf(f, "MakeNamedMaterial \"m%zu-base\" \"string type\" \"conductor\" "
                   "\"float roughness\" 0 \"rgb reflectance\" [", i);
    else
        fprintf(f, "MakeNamedMaterial \"m%zu-base\" \"string type\" \"diffuse\" "
                   "\"rgb reflectance\" [", i);
    export_rgb(f, " ", albedo(g.base));
    fprintf(f, "]\nMakeNamedMaterial \"m%zu-lobe\" \"string type\" \"conductor\" "
               "\"float uroughness\" [%.9g] \"float vroughness\" [%.9g]\n"
               "    \"bool remaproughness\" false \"rgb reflectance\" [", i, g.alpha_u,
            g.alpha_v);
    export_rgb(f, " ", albedo(g.lobe));
    fprintf(f, "]\nMakeNamedMaterial \"m%zu\" \"string type\" \"mix\" \"string materials\" "
               "[\"m%zu-base\" \"m%zu-lobe\"] \"float amount\" [%.9g]\n", i, i, i, g.w);
    export_note("pbrt: material \"%s\": pbrt has no %s model; written as a mix of a %s "
                "surface and a GGX conductor (slopes %.3g, %.3g) with weight %.3g: the "
                "highlight's shape%s differ", m->name, export_model_name(m),
                g.base_is_mirror ? "mirror" : "Lambertian", g.alpha_u, g.alpha_v, g.w,
                g.base.x > 1 || g.base.y > 1 || g.base.z > 1 ? ", its Fresnel and (clamped "
                                                              "to 1) the base's colour"
                                                            : " and its Fresnel");
}

/* "m<i>": our names may hold any printable byte, pbrt's strings not a quote. */
static void write_material(FILE *f, const struct export_scene *es, size_t i)
{
    const struct material *m = &es->materials[i];
    fprintf(f, "# material %zu: ", i);
    export_name(f, m->name);
    fprintf(f, "\n");
    switch (m->kind) {
    case MATERIAL_LAMBERT:
        fprintf(f, "MakeNamedMaterial \"m%zu\" \"string type\" \"diffuse\" \"rgb reflectance\" [",
                i);
        export_rgb(f, " ", m->rho);
        fprintf(f, "]\n");
        break;
    case MATERIAL_MIRROR:
        if (!is_grey(m->rho)) {
            fprintf(f, "MakeNamedMaterial \"m%zu\" \"string type\" \"conductor\" "
                       "\"rgb reflectance\" [", i);
            export_rgb(f, " ", m->rho);
            fprintf(f, "] \"float roughness\" 0\n");
            export_note("pbrt: material \"%s\": a coloured mirror becomes a conductor, whose "
                        "Fresnel reflectance rises towards 1 at grazing angles", m->name);
            break;
        }
        /* pbrt clamps a conductor's reflectance to 0.9999: within 1e-4 of perfect. */
        fprintf(f, "MakeNamedMaterial \"m%zu-mirror\" \"string type\" \"conductor\" "
                   "\"rgb reflectance\" [1 1 1] \"float roughness\" 0\n", i);
        fprintf(f, "MakeNamedMaterial \"m%zu-black\" \"string type\" \"diffuse\" "
                   "\"rgb reflectance\" [0 0 0]\n", i);
        fprintf(f, "MakeNamedMaterial \"m%zu\" \"string type\" \"mix\" \"string materials\" "
                   "[\"m%zu-black\" \"m%zu-mirror\"] \"float amount\" [%.9g]\n", i, i, i,
                m->rho.x);
        break;
    case MATERIAL_GLASS:
        fprintf(f, "MakeNamedMaterial \"m%zu\" \"string type\" \"dielectric\" \"float eta\" "
                   "[%.15g]\n", i, m->ior);
        if (m->absorption.x > 0 || m->absorption.y > 0 || m->absorption.z > 0)
            export_note("pbrt: material \"%s\": pbrt's dielectric has no colour filter; "
                        "written as clear glass", m->name);
        break;
    default:
        write_glossy(f, i, m);
    }
}

/* Inside an AttributeBegin: the material, and the area light when it emits. */
static void write_surface(FILE *f, const struct export_scene *es, int material)
{
    const struct material *m = &es->materials[material];
    if (material_emits(m)) {
        fprintf(f, "  AreaLightSource \"diffuse\" \"rgb L\" [");
        export_rgb(f, " ", m->emission);
        fprintf(f, "]%s\n", m->two_sided ? " \"bool twosided\" true" : "");
    }
    fprintf(f, "  NamedMaterial \"m%d\"\n", material);
}

static void write_sphere(FILE *f, const struct export_scene *es, const struct export_sphere *s)
{
    fprintf(f, "AttributeBegin\n");
    write_surface(f, es, s->material);
    fprintf(f, "  Translate %.15g %.15g %.15g\n", s->centre.x, s->centre.y, s->centre.z);
    fprintf(f, "  Shape \"sphere\" \"float radius\" [%.15g]\nAttributeEnd\n", s->radius);
}

static void write_points(FILE *f, const char *type, const struct vec3 *p, size_t n)
{
    fprintf(f, "    \"%s\" [\n", type);
    for (size_t i = 0; i < n; i++)
        fprintf(f, "      %.15g %.15g %.15g\n", p[i].x, p[i].y, p[i].z);
    fprintf(f, "    ]\n");
}

static void write_mesh(FILE *f, const struct export_scene *es, const struct export_mesh *m)
{
    size_t n = 3 * m->n_triangles;
    fprintf(f, "AttributeBegin\n");
    write_surface(f, es, m->material);
    fprintf(f, "  Shape \"trianglemesh\"\n");
    write_points(f, "point3 P", m->vertices, n);
    if (m->normals != NULL)
        write_points(f, "normal N", m->normals, n);
    fprintf(f, "    \"integer indices\" [");
    for (size_t i = 0; i < n; i++)
        fprintf(f, "%s%zu", i % 24 == 0 ? "\n      " : " ", i);
    fprintf(f, "\n    ]\nAttributeEnd\n");
}

static void write_lights(FILE *f, const struct export_scene *es)
{
    for (size_t i = 0; i < es->n_point_lights; i++) {
        const struct light *l = &es->point_lights[i];
        fprintf(f, "# point light of power %g %g %g W: intensity Phi / (4 pi)\n", l->power.x,
                l->power.y, l->power.z);
        fprintf(f, "LightSource \"point\" \"point3 from\" [%.15g %.15g %.15g] \"rgb I\" [",
                l->position.x, l->position.y, l->position.z);
        export_rgb(f, " ", vec3_scale(l->power, 1.0 / (4.0 * PI)));
        fprintf(f, "]\n");
    }
    struct vec3 b = es->background;
    if (b.x > 0 || b.y > 0 || b.z > 0) {
        fprintf(f, "# the background: radiance of every ray that leaves the scene\n");
        fprintf(f, "LightSource \"infinite\" \"rgb L\" [");
        export_rgb(f, " ", b);
        fprintf(f, "]\n");
    }
}

int export_pbrt(FILE *f, const struct export_scene *es, struct error *err)
{
    (void)err;
    write_header(f, es);
    for (size_t i = 0; i < es->n_materials; i++)
        if (es->material_used[i])
            write_material(f, es, i);
    fprintf(f, "\n");
    write_lights(f, es);
    for (size_t i = 0; i < es->n_spheres; i++)
        write_sphere(f, es, &es->spheres[i]);
    for (size_t i = 0; i < es->n_meshes; i++)
        write_mesh(f, es, &es->meshes[i]);
    return 0;
}
