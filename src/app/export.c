/*
 * app/export.c -- `photon export`: the scene flattened for the writers, and the command
 * (see export.h).
 */
#include "export.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/option_once.h"
#include "../base/output.h"
#include "../image/image.h"
#include "option_values.h"

/* The usage in two parts: one line in a message, two in --help (within 100 columns). */
#define EXPORT_USAGE_NAMES "usage: photon export --format pbrt|mitsuba|blender SCENE -o OUT"
#define EXPORT_USAGE_OPTIONS "[--spp N] [--channel R|G|B] [--width N] [--height N]"
#define EXPORT_USAGE EXPORT_USAGE_NAMES " " EXPORT_USAGE_OPTIONS

/* ---- flattening the geometry ---- */

/* Collects the visited primitives: spheres as they are, triangles into one growing list
 * per (material, with normals) pair, and how many primitives each procedural shape gave. */
struct collector {
    struct export_scene *es;
    size_t cap_spheres;
    size_t *cap_triangles;      /* per mesh */
    int *mesh_of;               /* 2 per material: mesh index without / with normals, or -1 */
    const char *shape_name;     /* the procedural shape being visited, or NULL */
    size_t shape_spheres, shape_triangles;
};

static void used(struct collector *c, int material)
{
    c->es->material_used[material] = 1;
}

static void add_sphere(void *context, struct vec3 centre, double radius, int material)
{
    struct collector *c = context;
    struct export_scene *es = c->es;
    if (es->n_spheres == c->cap_spheres) {
        c->cap_spheres = c->cap_spheres < 16 ? 16 : 2 * c->cap_spheres;
        es->spheres = xrealloc(es->spheres, c->cap_spheres, sizeof *es->spheres, "spheres");
    }
    es->spheres[es->n_spheres].centre = centre;
    es->spheres[es->n_spheres].radius = radius;
    es->spheres[es->n_spheres++].material = material;
    used(c, material);
    c->shape_spheres++;
}

/* The mesh of a material's triangles with or without normals, made when first needed. */
static struct export_mesh *mesh_for(struct collector *c, int material, int with_normals)
{
    struct export_scene *es = c->es;
    int *slot = &c->mesh_of[2 * material + with_normals];
    if (*slot < 0) {
        *slot = (int)es->n_meshes;
        es->meshes = xrealloc(es->meshes, es->n_meshes + 1, sizeof *es->meshes, "meshes");
        c->cap_triangles = xrealloc(c->cap_triangles, es->n_meshes + 1,
                                    sizeof *c->cap_triangles, "meshes");
        struct export_mesh *m = &es->meshes[es->n_meshes++];
        m->material = material;
        m->n_triangles = 0;
        m->vertices = NULL;
        m->normals = NULL;
        c->cap_triangles[*slot] = 0;
    }
    return &es->meshes[*slot];
}

static void add_triangle(void *context, const struct vec3 v[3], const struct vec3 *normals,
                         int material)
{
    struct collector *c = context;
    struct export_mesh *m = mesh_for(c, material, normals != NULL);
    size_t *cap = &c->cap_triangles[m - c->es->meshes];
    if (m->n_triangles == *cap) {
        *cap = *cap < 16 ? 16 : 2 * *cap;
        m->vertices = xrealloc(m->vertices, 3 * *cap, sizeof *m->vertices, "mesh vertices");
        if (normals != NULL)
            m->normals = xrealloc(m->normals, 3 * *cap, sizeof *m->normals, "mesh normals");
    }
    for (int i = 0; i < 3; i++) {
        m->vertices[3 * m->n_triangles + i] = v[i];
        if (normals != NULL)
            m->normals[3 * m->n_triangles + i] = normals[i];
    }
    m->n_triangles++;
    used(c, material);
    c->shape_triangles++;
}

static void add_quad(void *context, struct vec3 p0, struct vec3 e1, struct vec3 e2,
                     int material)
{
    struct vec3 p2 = vec3_add(vec3_add(p0, e1), e2);
    struct vec3 first[3] = {p0, vec3_add(p0, e1), p2};
    struct vec3 second[3] = {p0, p2, vec3_add(p0, e2)};
    add_triangle(context, first, NULL, material);
    add_triangle(context, second, NULL, material);
}

/* Says what the last procedural shape became: the writers' targets store its primitives. */
static void report_shape(struct collector *c)
{
    if (c->shape_name == NULL)
        return;
    if (c->shape_spheres > 0)
        export_note("%s: written as its %zu spheres", c->shape_name, c->shape_spheres);
    if (c->shape_triangles > 0)
        export_note("%s: written as its %zu triangles", c->shape_name, c->shape_triangles);
}

static void begin_or_end_shape(void *context, const char *name, const char *approximation)
{
    struct collector *c = context;
    report_shape(c);
    if (name != NULL && approximation != NULL)
        export_note("%s: no exact equivalent; written as %s", name, approximation);
    c->shape_name = name;
    c->shape_spheres = c->shape_triangles = 0;
}

/* ---- the scene ---- */

static struct vec3 grey(struct vec3 c, int channel)
{
    if (channel < 0)
        return c;
    double v = channel == 0 ? c.x : channel == 1 ? c.y : c.z;
    return vec3(v, v, v);
}

static void make_grey(struct export_scene *es)
{
    int ch = es->channel;
    es->background = grey(es->background, ch);
    for (size_t i = 0; i < es->n_materials; i++) {
        struct material *m = &es->materials[i];
        m->rho = grey(m->rho, ch);
        m->rho_s = grey(m->rho_s, ch);
        m->absorption = grey(m->absorption, ch);
        m->emission = grey(m->emission, ch);
    }
    for (size_t i = 0; i < es->n_point_lights; i++)
        es->point_lights[i].power = grey(es->point_lights[i].power, ch);
}

void export_scene_make(struct export_scene *es, const struct scene *scene, int spp,
                       int channel)
{
    memset(es, 0, sizeof *es);
    es->spheres = NULL;
    es->meshes = NULL;
    es->width = scene->width;
    es->height = scene->height;
    es->camera = scene->camera;
    es->background = scene->background;
    es->spp = spp;
    es->channel = channel;
    es->n_materials = scene->n_materials;
    es->materials = xmalloc(scene->n_materials + 1, sizeof *es->materials, "materials");
    memcpy(es->materials, scene->materials, scene->n_materials * sizeof *es->materials);
    es->material_used = xcalloc(scene->n_materials + 1, sizeof *es->material_used, "materials");
    es->point_lights = xmalloc(scene->n_lights + 1, sizeof *es->point_lights, "lights");
    for (size_t i = 0; i < scene->n_lights; i++)
        if (scene->lights[i].kind == LIGHT_POINT)
            es->point_lights[es->n_point_lights++] = scene->lights[i];

    struct collector c;
    memset(&c, 0, sizeof c);
    c.es = es;
    c.cap_triangles = NULL;
    c.shape_name = NULL;
    c.mesh_of = xmalloc(2 * scene->n_materials + 2, sizeof *c.mesh_of, "meshes");
    for (size_t i = 0; i < 2 * scene->n_materials + 2; i++)
        c.mesh_of[i] = -1;
    struct primitive_visitor v = {&c, add_sphere, add_triangle, add_quad, begin_or_end_shape};
    geometry_visit(scene->geometry, &v);
    xfree(c.mesh_of);
    xfree(c.cap_triangles);
    make_grey(es);
}

void export_scene_free(struct export_scene *es)
{
    for (size_t i = 0; i < es->n_meshes; i++) {
        xfree(es->meshes[i].vertices);
        xfree(es->meshes[i].normals);
    }
    xfree(es->meshes);
    xfree(es->spheres);
    xfree(es->materials);
    xfree(es->material_used);
    xfree(es->point_lights);
}

/* ---- what the writers share ---- */

/* Material names come from the scene file: message_print() quotes their control bytes. */
void export_note(const char *format, ...)
{
    char note[ERROR_MESSAGE_MAX];
    va_list ap;
    va_start(ap, format);
    vsnprintf(note, sizeof note, format, ap);
    va_end(ap);
    message_print("photon: export: %s", note);
}

struct glossy_blend export_glossy_blend(const struct material *m)
{
    struct glossy_blend g;
    if (m->kind == MATERIAL_SCHLICK) {
        double r = m->roughness, b = 4.0 * r * (1.0 - r); /* schlick.c's weights */
        g.w = b;
        g.base_is_mirror = r < 0.5;
        g.base = g.lobe = m->rho;
        g.alpha_u = sqrt(r * m->isotropy);
        g.alpha_v = sqrt(r / m->isotropy);
        g.ggx = 1;
        g.exact = m->isotropy == 1;
        return g;
    }
    double w = fmax(m->rho_s.x, fmax(m->rho_s.y, m->rho_s.z));
    g.w = fmin(fmax(w, 1e-6), 1.0 - 1e-6); /* both parts present: both divisions work */
    g.base_is_mirror = 0;
    g.base = vec3_scale(m->rho, 1.0 / (1.0 - g.w));
    g.lobe = vec3_scale(m->rho_s, 1.0 / g.w);
    if (m->kind == MATERIAL_WARD) {
        g.alpha_u = m->alpha_x;
        g.alpha_v = m->alpha_y;
    } else {
        g.alpha_u = g.alpha_v = sqrt(2.0 / (m->exponent + 2.0));
    }
    g.ggx = 0;
    g.exact = 0;
    return g;
}

const char *export_model_name(const struct material *m)
{
    static const char *const names[] = {"Lambert", "mirror", "glass", "Phong", "Ward",
                                        "Schlick"};
    return names[m->kind];
}

void export_name(FILE *f, const char *name)
{
    for (const char *c = name; *c != '\0'; c++) {
        int plain = (*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') ||
                    (*c >= '0' && *c <= '9') || strchr(" _.#+/,:=()", *c) != NULL ||
                    (*c == '-' && (c == name || c[-1] != '-'));
        fputc(plain ? *c : '_', f);
    }
}

void export_rgb(FILE *f, const char *separator, struct vec3 c)
{
    fprintf(f, "%.9g%s%.9g%s%.9g", c.x, separator, c.y, separator, c.z);
}

/* ---- the command ---- */

struct export_args {
    const char *scene;
    const char *output;
    enum export_format format;
    int spp;
    int channel;
    int width, height; /* the image's size; 0: the scene's */
};

/* By enum export_format: --format's word, and the ending of the file the target reads
 * (pbrt's scene, Mitsuba's XML, the Python script Blender runs), which -o must have. */
static const char *const format_names[] = {"pbrt", "mitsuba", "blender"};
static const char *const format_endings[] = {".pbrt", ".xml", ".py"};

static int parse_format(const char *word, enum export_format *format, struct error *err)
{
    for (int i = 0; i < 3; i++)
        if (strcmp(word, format_names[i]) == 0) {
            *format = (enum export_format)i;
            return 0;
        }
    return error_set(err, "", 0, "export: --format '%s': expected pbrt, mitsuba or blender",
                     word);
}

static int parse_channel(const char *word, int *channel, struct error *err)
{
    static const char channels[] = "RGB";
    for (int i = 0; i < 3; i++)
        if (word[0] == channels[i] && word[1] == '\0') {
            *channel = i;
            return 0;
        }
    return error_set(err, "", 0, "export: --channel '%s': expected R, G or B", word);
}

/* A whole number from 1 to max for the option called name (--spp, --width, --height). */
static int parse_whole(const char *name, const char *word, int max, int *value,
                       struct error *err)
{
    char label[32];
    double v;
    snprintf(label, sizeof label, "export: %s", name);
    if (read_number(label, word, 1, max, NUMBER_WHOLE, &v, err) < 0)
        return -1;
    *value = (int)v;
    return 0;
}

/* -o's name ends in the format's ending, after a name of its own: "x.xml" for pbrt would
 * be read by the wrong program, and ".pbrt" (or "out/.pbrt") is a hidden file of no name.
 * Checked after the scene is read, before anything is written: an -o that is a directory,
 * or an input of the command (the scene, an OBJ file it reads), is named as that, the
 * graver fault, by the output checks (base/output.h). */
static int check_ending(const struct export_args *a, struct error *err)
{
    const char *ending = format_endings[a->format];
    const char *slash = strrchr(a->output, '/');
    const char *base = slash != NULL ? slash + 1 : a->output;
    size_t n = strlen(base), length = strlen(ending);
    if (n > length && strcmp(base + n - length, ending) == 0)
        return 0;
    return error_set(err, "", 0, "export: -o: expected a file name ending in %s for --format "
                     "%s, got '%s'", ending, format_names[a->format], a->output);
}

const struct option_arity export_options[] = {
    {"--format", 1}, {"-o", 1}, {"--spp", 1}, {"--channel", 1}, {"--width", 1},
    {"--height", 1}, {"--help", 0}, {NULL, 0},
};

static int parse_export_args(int argc, char **argv, struct export_args *a, struct error *err)
{
    int has_format = 0;
    a->scene = a->output = NULL;
    a->format = EXPORT_PBRT;
    a->spp = EXPORT_DEFAULT_SPP;
    a->channel = -1;
    a->width = a->height = 0;
    struct option_once once = {{0}, 0};
    for (int i = 1; i < argc; i++) {
        const char *opt = argv[i];
        int takes_value = strcmp(opt, "--format") == 0 || strcmp(opt, "-o") == 0 ||
                          strcmp(opt, "--spp") == 0 || strcmp(opt, "--channel") == 0 ||
                          strcmp(opt, "--width") == 0 || strcmp(opt, "--height") == 0;
        if (takes_value && i + 1 == argc)
            return error_set(err, "", 0, "export: %s needs a value; " EXPORT_USAGE, opt);
        if (takes_value && option_once(&once, "export", argc, argv, i, 1, err) < 0)
            return -1;
        if (strcmp(opt, "--format") == 0) {
            if (parse_format(argv[++i], &a->format, err) < 0)
                return -1;
            has_format = 1;
        } else if (strcmp(opt, "-o") == 0) {
            a->output = argv[++i];
        } else if (strcmp(opt, "--spp") == 0) {
            if (parse_whole(opt, argv[++i], 1 << 24, &a->spp, err) < 0)
                return -1;
        } else if (strcmp(opt, "--width") == 0 || strcmp(opt, "--height") == 0) {
            int *side = opt[2] == 'w' ? &a->width : &a->height;
            if (parse_whole(opt, argv[++i], MAX_IMAGE_SIDE, side, err) < 0)
                return -1;
        } else if (strcmp(opt, "--channel") == 0) {
            if (parse_channel(argv[++i], &a->channel, err) < 0)
                return -1;
        } else if (opt[0] == '-') {
            return error_set(err, "", 0, "export: unknown option '%s'; " EXPORT_USAGE, opt);
        } else if (a->scene == NULL) {
            a->scene = opt;
        } else {
            return error_set(err, "", 0, "export: more than one scene; " EXPORT_USAGE);
        }
    }
    if (!has_format || a->scene == NULL || a->output == NULL)
        return error_set(err, "", 0, "export: needs --format, a scene and -o; " EXPORT_USAGE);
    return 0;
}

/* Mitsuba's meshes go in files beside the output: each declared, and all of them checked
 * with the output, before anything is written. */
static int check_companions(const struct export_args *a, const struct export_scene *es,
                            struct error *err)
{
    for (size_t k = 0; a->format == EXPORT_MITSUBA && k < es->n_meshes; k++) {
        char path[1024];
        const char *base;
        export_mitsuba_mesh_name(a->output, k, path, sizeof path, &base);
        output_declare(path, "a mesh file beside -o");
    }
    return outputs_check(err);
}

/* Writes the scene with the chosen writer, then puts the output and its companions in
 * place together. */
static int write_export(const struct export_args *a, struct export_scene *es,
                        struct error *err)
{
    static int (*const writers[])(FILE *, const struct export_scene *, struct error *) = {
        export_pbrt, export_mitsuba, export_blender};
    if (check_companions(a, es, err) < 0)
        return -1;
    FILE *f = output_open(a->output, err);
    if (f == NULL)
        return -1;
    if (writers[a->format](f, es, err) < 0) {
        output_abandon(f);
        return -1; /* the companions' temporaries go at exit (output.h) */
    }
    if (output_commit(f, err) < 0)
        return -1;
    return outputs_publish(err);
}

/* -o's name goes into what the targets read as data (pbrt's film in a quoted string,
 * Mitsuba's mesh files in attributes): a name those cannot hold is refused. */
static int check_output_name(const char *output, struct error *err)
{
    for (const unsigned char *c = (const unsigned char *)output; *c != '\0'; c++)
        if (*c < 0x20 || *c >= 0x7F || *c == '"' || *c == '\\' || *c == '&' || *c == '<' ||
            *c == '>')
            return error_set(err, "", 0, "export: -o '%s': the files written name it, so it "
                             "must be printable ASCII without \" \\ & < >", output);
    return 0;
}

/* `photon export --help`: what each option and format does (README: Rendering our scenes
 * elsewhere). */
static const char export_help[] =
    EXPORT_USAGE_NAMES "\n                     " EXPORT_USAGE_OPTIONS "\n\n"
    "Writes SCENE for another renderer, with the same camera, image size, lights and\n"
    "materials, so that its image can be compared with photon's (photon compare).\n"
    "  --format pbrt     a pbrt-v4 scene: OUT ends in .pbrt\n"
    "  --format mitsuba  a Mitsuba 3 scene: OUT ends in .xml\n"
    "  --format blender  a Python script for Blender that builds the scene for Cycles: OUT\n"
    "                    ends in .py\n"
    "  -o OUT            the file written (mitsuba: its meshes' OBJ files beside it)\n"
    "  --spp N           the samples a pixel the other renderer is told to take\n"
    "                    (default 1024)\n"
    "  --channel R|G|B   one channel's values on every colour: a grey scene\n"
    "  --width N         the image's width in pixels, as photon's own --width takes it\n"
    "                    (default: the scene's): to match a reference of that size\n"
    "  --height N        the image's height likewise (default: the scene's)\n"
    "What a format cannot express exactly is said on stderr, never left out silently.\n"
    "Exit status 0, or 2 for bad input (nothing written).\n";

int export_command(int argc, char **argv)
{
    struct export_args a;
    struct error err;
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0)
            return fputs(export_help, stdout) < 0;
    if (parse_export_args(argc, argv, &a, &err) < 0 || check_output_name(a.output, &err) < 0 ||
        output_check_one(a.output, "-o", &err) < 0) {
        error_print(&err);
        return 2;
    }
    struct scene *scene = scene_load(a.scene, &err);
    if (scene == NULL || check_ending(&a, &err) < 0) {
        error_print(&err);
        scene_free(scene);
        return 2;
    }
    scene_finish(scene, a.width > 0 ? a.width : scene->width,
                 a.height > 0 ? a.height : scene->height);
    struct export_scene es;
    export_scene_make(&es, scene, a.spp, a.channel);
    es.scene_path = a.scene;
    es.output = a.output;
    int status = write_export(&a, &es, &err);
    export_scene_free(&es);
    scene_free(scene);
    if (status < 0) {
        error_print(&err);
        return error_exit_status(&err);
    }
    return 0;
}
