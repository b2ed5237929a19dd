/*
 * scene/nff.c -- the NFF reader (Haines, "Neutral File Format", as SPD 3.14 writes it).
 *
 * How NFF becomes a photon scene (README, "Scene files", in short):
 *   v       `v`, then the lines `from x y z`, `at x y z`, `up x y z`, `angle deg`,
 *           `hither d`, (optionally `yon d`), `resolution w h`, in that order -> the
 *           camera at from looking at at, with up as its up hint (neither unit nor
 *           orthogonal need it be: the camera builds its frame from it), angle as the
 *           image's full vertical field of view (as ray-casting benchmarks on the SPD
 *           files read it; NFF's description measures it between the centres of the
 *           outermost pixels, half a pixel less per edge), and the image size w x h.
 *           hither and yon are ignored. One `v` per file, required.
 *   b r g b -> the background radiance.
 *   l x y z [r g b] -> a point light. NFF lights have no power; the convention: with n
 *           lights in the file, each has intensity I = sqrt(n) / (2 n) (SPD's Readme.txt)
 *           times its colour (white if none), meaning that a white Lambertian surface
 *           facing the light at the view's `at` point has radiance I there, as in Haines'
 *           shading L = Kd I cos(theta). Our point light of power Phi gives irradiance
 *           E = Phi / (4 pi d^2) at normal incidence, and such a surface has radiance
 *           E / pi, so Phi = 4 pi^2 d_at^2 I per channel, d_at the distance from the light
 *           to `at` (to `from` when the light is at `at` itself). Lights may stand anywhere
 *           in the file: their powers are set at its end, once n and `at` are known.
 *   f r g b Kd Ks Shine T ior -> the material of the objects that follow:
 *           T > 0:      glass of index of refraction ior (> 0): clear glass with exact
 *                       Fresnel reflection and refraction; colour, Kd, Ks and T are unused;
 *           else Ks > 0: Phong with kd = Kd * colour, ks = Ks (white), exponent Shine;
 *                       when Kd + Ks > 1 both are divided by Kd + Ks;
 *           else:       Lambert with rho = Kd * colour.
 *           Every number must be >= 0. Colour channels above 1 count as 1 and kd is capped
 *           at 1 - ks per channel, so that kd + ks <= 1 whatever the rounding. `f` lines
 *           with the same eight numbers share one material (lattice-s6 has 1,225 `f` lines
 *           and 4 materials). An object before the first `f` is refused.
 *   s x y z r -> a sphere, r > 0.
 *   c bx by bz br ax ay az ar -> an open cone frustum or cylinder (geom/cone.h), no end
 *           caps: the eight numbers on the `c` line (as SPD 3.14 writes them), or `c` alone
 *           followed by a base line `bx by bz br` and an apex line (the NFF description's
 *           layout). Negative radii (both <= 0: "only the inside is visible") make the
 *           same surface with |r|, its front side inside.
 *   p n, then n lines `x y z` -> a polygon, 3 <= n <= MAX_POLYGON_VERTICES: a triangle as
 *           it is, any other polygon cut into n - 2 triangles by ear clipping in its plane,
 *           concave ones included (gears' 144-vertex faces). A file's triangle count is
 *           thus the sum of n - 2 over its polygons; triangles of zero area are kept
 *           (geometry never hits them) so that the count always holds.
 *   pp n, then n lines `x y z nx ny nz` -> the same, with the vertex normals (normalised;
 *           a zero normal is refused) interpolated for shading.
 *   # ...   a comment, to the end of the line. Blank lines are skipped anywhere.
 * Sidedness: NFF's opaque polygons are one-sided; our surfaces reflect on both sides
 * (modes/surface.h), as SPD advises for the teapot anyway. Tokens are split at any white
 * space (CRLF included); numbers are in base/number.h's syntax (a count or resolution
 * whole: "4", not "4.0"); the file is read a line at a time
 * (mount-s8 is 11.5 MB). Any other keyword (`tpp`, NFF extensions) is refused by name.
 *
 * Errors name the file, the line and the entity ("gears.nff:12: p: ..."); the reader stops
 * at the first. The reader owns its scratch (lights, material table, polygon buffers) and
 * frees it however it ends; what it added to the scene is the scene's.
 */
#include "nff.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/input.h"
#include "../base/number.h"
#include "../geom/cone.h"
#include "../geom/polygon.h"
#include "../geom/triangle.h"
#include "../image/image.h"
#include "reach.h"

#define NFF_MAX_LINE 4096  /* longest line in bytes, newline included; SPD's are < 100 */
#define NFF_MAX_TOKENS 16  /* the longest NFF line, `c` with its 8 numbers, has 9 words */
#define NFF_ENTITY_MAX 16  /* a keyword, kept for messages about its continuation lines */
#define F_NUMBERS 8        /* r g b Kd Ks Shine T ior                                      */

struct nff_light {
    struct vec3 position;
    struct vec3 colour; /* (1, 1, 1) when the `l` line gives none */
    int line;           /* of its `l`, for a message at the end of the file */
};

/* One distinct `f`: its numbers and the material made for them. */
struct f_entry {
    double f[F_NUMBERS];
    int material;
};

struct nff_reader {
    struct scene *scene;              /* borrowed: where everything goes                  */
    const char *file;                 /* as named by the caller                           */
    struct input *in;                 /* borrowed from nff_import(): the file being read  */
    int line;                         /* 1-based number of the line in text               */
    char text[NFF_MAX_LINE];          /* the current line, cut into tokens in place       */
    char *tokens[NFF_MAX_TOKENS];
    int n_tokens;
    int next;                         /* the next token to read                           */
    char entity[NFF_ENTITY_MAX];      /* keyword of the entity being read                 */
    int has_view;                     /* whether the `v` block was read                    */
    struct vec3 from, at;             /* the view's, for the lights' powers               */
    struct nff_light *lights;         /* owned; n_lights used of cap_lights                */
    size_t n_lights, cap_lights;
    int material;                     /* of the last `f`; -1 before the first             */
    struct f_entry *table;            /* owned: open addressing, cap_table slots (a power
                                         of two, or 0), material -1 marks a free slot     */
    size_t n_table, cap_table;
    struct vec3 *vertices;            /* owned scratch: MAX_POLYGON_VERTICES               */
    struct vec3 *normals;             /* owned scratch: MAX_POLYGON_VERTICES               */
    int *triangles;                   /* owned scratch: 3 (MAX_POLYGON_VERTICES - 2)       */
};

/* ---- lines and numbers ---------------------------------------------------------------- */

/* Fills *err with "file:line: entity: message" and returns -1. */
static int nff_error(const struct nff_reader *rd, struct error *err, const char *format, ...)
{
    char message[ERROR_MESSAGE_MAX];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    return error_set(err, rd->file, rd->line, "%s: %s", rd->entity, message);
}

/* Cuts rd->text into tokens at white space, stopping at a '#' that starts a token. */
static int split_tokens(struct nff_reader *rd, struct error *err)
{
    char *s = rd->text;
    rd->n_tokens = 0;
    for (;;) {
        while (isspace((unsigned char)*s))
            *s++ = '\0';
        if (*s == '\0' || *s == '#')
            return 0;
        if (rd->n_tokens == NFF_MAX_TOKENS)
            return error_set(err, rd->file, rd->line, "more than %d words on a line",
                             NFF_MAX_TOKENS);
        rd->tokens[rd->n_tokens++] = s;
        while (*s != '\0' && !isspace((unsigned char)*s))
            s++;
    }
}

/* Reads lines up to one that has a word: 1 with its tokens (rd->next = 0), 0 at the end of
 * the file, -1 with *err filled. */
static int next_line(struct nff_reader *rd, struct error *err)
{
    int status;
    reach_note(rd->scene, rd->file, rd->line); /* what the entity read last added */
    while ((status = input_line(rd->in, rd->text, sizeof rd->text, err)) > 0) {
        rd->line = rd->in->line;
        scene_hash_line(rd->scene, rd->text);
        if (split_tokens(rd, err) < 0)
            return -1;
        rd->next = 0;
        if (rd->n_tokens > 0)
            return 1;
    }
    return status;
}

/* Like next_line(), but the end of the file is an error: the entity needs `what` next. */
static int continuation_line(struct nff_reader *rd, const char *what, struct error *err)
{
    int status = next_line(rd, err);
    if (status == 0)
        return nff_error(rd, err, "the file ends where %s should follow", what);
    return status < 0 ? -1 : 0;
}

/* Reads n numbers in base/number.h's syntax (whole ones when integer != 0) from the
 * current line; `what` names them for messages. */
static int read_numbers_of(struct nff_reader *rd, double *v, int n, int integer,
                           const char *what, struct error *err)
{
    for (int i = 0; i < n; i++) {
        if (rd->next >= rd->n_tokens)
            return nff_error(rd, err, "expected %d numbers (%s), got %d", n, what, i);
        const char *word = rd->tokens[rd->next++];
        enum number_verdict verdict = number_read(word, integer, &v[i]);
        if (verdict == NUMBER_UNWRITTEN)
            return nff_error(rd, err, "'%.40s' %s (expected %s)", word,
                             number_problem(verdict, integer), what);
        if (verdict != NUMBER_OK)
            return nff_error(rd, err, "number '%.40s' %s", word,
                             number_problem(verdict, integer));
    }
    return 0;
}

static int expect_end(struct nff_reader *rd, struct error *err)
{
    if (rd->next >= rd->n_tokens)
        return 0;
    return nff_error(rd, err, "unexpected '%.40s' at the end of the line", rd->tokens[rd->next]);
}

/* Reads exactly n numbers (whole ones when integer != 0) and the end of the line. */
static int read_line_of(struct nff_reader *rd, double *v, int n, int integer, const char *what,
                        struct error *err)
{
    if (read_numbers_of(rd, v, n, integer, what, err) < 0)
        return -1;
    return expect_end(rd, err);
}

static int read_line_numbers(struct nff_reader *rd, double *v, int n, const char *what,
                             struct error *err)
{
    return read_line_of(rd, v, n, 0, what, err);
}

static struct vec3 vec3_at(const double *v) { return vec3(v[0], v[1], v[2]); }

/* ---- the view -------------------------------------------------------------------------- */

struct view_line {
    const char *name;  /* the line's keyword */
    int count;         /* its numbers        */
    const char *what;  /* what they are      */
    int whole;         /* 1: whole numbers   */
};

static const struct view_line view_lines[] = {
    {"from", 3, "eye position x y z", 0},  {"at", 3, "look-at point x y z", 0},
    {"up", 3, "up vector x y z", 0},       {"angle", 1, "field of view in degrees", 0},
    {"hither", 1, "near distance", 0},     {"resolution", 2, "width, height in pixels", 1},
};

/* Reads the view line vl into v. A `yon` line may stand before `resolution`; it is read
 * and ignored like hither. */
static int read_view_line(struct nff_reader *rd, const struct view_line *vl, double *v,
                          struct error *err)
{
    char what[64];
    snprintf(what, sizeof what, "the line '%s'", vl->name);
    if (continuation_line(rd, what, err) < 0)
        return -1;
    if (strcmp(rd->tokens[0], "yon") == 0 && strcmp(vl->name, "resolution") == 0) {
        double yon;
        rd->next = 1;
        if (read_line_numbers(rd, &yon, 1, "far distance", err) < 0 ||
            continuation_line(rd, what, err) < 0)
            return -1;
    }
    if (strcmp(rd->tokens[0], vl->name) != 0)
        return nff_error(rd, err, "expected the line '%s' (%s), got '%.40s'", vl->name, vl->what,
                         rd->tokens[0]);
    rd->next = 1;
    snprintf(what, sizeof what, "%s %s", vl->name, vl->what); /* "resolution width, ..." */
    return read_line_of(rd, v, vl->count, vl->whole, what, err);
}

/* Checks the view line just read (index i of view_lines); camera holds what came before. */
static int check_view_line(struct nff_reader *rd, int i, const double *v, struct camera *camera,
                           struct error *err)
{
    if (i == 2) {
        camera->from = vec3_at(v - 6);
        camera->at = vec3_at(v - 3);
        camera->up = vec3_at(v);
        camera->fov = 90.0; /* stands in until `angle`: the frame is what is checked here */
        if (!camera_is_valid(camera))
            return nff_error(rd, err, "'at' equals 'from', or 'up' is parallel to the "
                                      "viewing direction");
    } else if (i == 3) {
        camera->fov = v[0];
        if (!(v[0] > 0 && v[0] < 180))
            return nff_error(rd, err, "the angle must be in (0, 180) degrees, got %.40s",
                             rd->tokens[1]); /* as typed: "1e3", not "1000" */
    } else if (i == 5) {
        for (int k = 0; k < 2; k++)
            if (!(v[k] >= 1 && v[k] <= MAX_IMAGE_SIDE))
                return nff_error(rd, err, "the resolution must be whole numbers from 1 to %d, "
                                 "got %.40s", MAX_IMAGE_SIDE, rd->tokens[1 + k]);
    }
    return 0;
}

/* "v" and its six lines. */
static int read_view(struct nff_reader *rd, struct error *err)
{
    if (rd->has_view)
        return nff_error(rd, err, "a second view (an NFF file has one)");
    if (expect_end(rd, err) < 0)
        return -1;
    double v[12];   /* from, at, up, angle, hither, resolution: 3 + 3 + 3 + 1 + 1 + 1 */
    static const int place[6] = {0, 3, 6, 9, 10, 10}; /* hither is overwritten: unused */
    struct camera camera;
    memset(&camera, 0, sizeof camera);
    for (int i = 0; i < 6; i++) {
        if (read_view_line(rd, &view_lines[i], v + place[i], err) < 0 ||
            check_view_line(rd, i, v + place[i], &camera, err) < 0)
            return -1;
    }
    struct scene *scene = rd->scene;
    scene->camera = camera;
    scene->has_camera = 1;
    scene->width = (int)v[10];
    scene->height = (int)v[11];
    rd->from = camera.from;
    rd->at = camera.at;
    rd->has_view = 1;
    return 0;
}

/* ---- lights and the background ------------------------------------------------------- */

/* "b r g b" */
static int read_background(struct nff_reader *rd, struct error *err)
{
    double v[3];
    if (read_line_numbers(rd, v, 3, "colour r g b", err) < 0)
        return -1;
    if (!(v[0] >= 0 && v[1] >= 0 && v[2] >= 0))
        return nff_error(rd, err, "the colour must not be negative");
    scene_set_background(rd->scene, vec3_at(v), rd->file, rd->line);
    return 0;
}

/* "l x y z [r g b]": kept until the end of the file, when the powers can be set. */
static int read_light(struct nff_reader *rd, struct error *err)
{
    double v[6] = {0, 0, 0, 1, 1, 1};
    int with_colour = rd->n_tokens - rd->next > 3;
    if (read_line_numbers(rd, v, with_colour ? 6 : 3,
                          with_colour ? "position x y z, colour r g b" : "position x y z",
                          err) < 0)
        return -1;
    if (!(v[3] >= 0 && v[4] >= 0 && v[5] >= 0))
        return nff_error(rd, err, "the colour must not be negative");
    if (rd->scene->n_lights + rd->n_lights >= MAX_LIGHTS)
        return nff_error(rd, err, "more than %d lights", MAX_LIGHTS);
    if (rd->n_lights == rd->cap_lights) {
        rd->cap_lights = rd->cap_lights == 0 ? 8 : 2 * rd->cap_lights;
        rd->lights = xrealloc(rd->lights, rd->cap_lights, sizeof *rd->lights, "NFF lights");
    }
    struct nff_light *l = &rd->lights[rd->n_lights++];
    l->position = vec3_at(v);
    l->colour = vec3_at(v + 3);
    l->line = rd->line;
    return 0;
}

/* The lights' powers by the convention of the header: Phi = 4 pi^2 d_at^2 I colour. */
static int add_lights(struct nff_reader *rd, struct error *err)
{
    double n = (double)rd->n_lights;
    for (size_t i = 0; i < rd->n_lights; i++) {
        const struct nff_light *l = &rd->lights[i];
        double d2 = vec3_length2(vec3_sub(l->position, rd->at));
        if (d2 == 0)
            d2 = vec3_length2(vec3_sub(rd->from, rd->at)); /* > 0: the view is valid */
        double intensity = sqrt(n) / (2.0 * n);            /* n >= 1 inside the loop */
        struct vec3 power = vec3_scale(l->colour, 4.0 * PI * PI * d2 * intensity);
        if (!vec3_is_finite(power))
            return error_set(err, rd->file, l->line, "l: the light is too far from the "
                                                     "view's 'at' point (its power overflows)");
        if (scene_add_error(scene_add_point_light(rd->scene, l->position, power), rd->file,
                            l->line, "l", err) < 0)
            return -1;
    }
    return 0;
}

/* ---- materials ------------------------------------------------------------------------ */

/* The material of "f r g b Kd Ks Shine T ior" (header comment); f checked non-negative. */
static struct material nff_material(const double *f, size_t index)
{
    struct material m;
    memset(&m, 0, sizeof m);
    sprintf(m.name, "nff#%zu", index); /* '#' starts a comment: no scene file can name it */
    double kd = f[3], ks = f[4], sum = f[3] + f[4];
    struct vec3 colour = vec3(fmin(f[0], 1.0), fmin(f[1], 1.0), fmin(f[2], 1.0));
    if (f[6] > 0) {
        m.kind = MATERIAL_GLASS;
        m.ior = f[7];
    } else if (ks > 0) {
        if (sum > 1) {
            kd /= sum; /* sum > 1 */
            ks /= sum;
        }
        m.kind = MATERIAL_PHONG;
        m.rho_s = vec3(ks, ks, ks);
        m.rho = vec3(fmin(kd * colour.x, 1.0 - ks), fmin(kd * colour.y, 1.0 - ks),
                     fmin(kd * colour.z, 1.0 - ks));
        m.exponent = f[5];
    } else {
        m.kind = MATERIAL_LAMBERT;
        m.rho = vec3(fmin(kd * colour.x, 1.0), fmin(kd * colour.y, 1.0),
                     fmin(kd * colour.z, 1.0));
    }
    return m;
}

/* FNV-1a over the numbers' bytes; -0 is first made +0, so equal numbers hash alike. */
static size_t hash_f(const double *f)
{
    uint64_t h = UINT64_C(14695981039346656037);
    for (int i = 0; i < F_NUMBERS; i++) {
        double x = f[i] + 0.0;
        unsigned char bytes[sizeof x];
        memcpy(bytes, &x, sizeof x);
        for (size_t b = 0; b < sizeof x; b++)
            h = (h ^ bytes[b]) * UINT64_C(1099511628211);
    }
    return (size_t)h;
}

/* The slot holding f, or the free slot where it belongs; cap_table is a power of two and
 * at least one slot is free (the table is at most half full), so the probe ends. */
static struct f_entry *find_slot(struct f_entry *table, size_t cap, const double *f)
{
    size_t i = hash_f(f) & (cap - 1);
    for (;; i = (i + 1) & (cap - 1)) {
        if (table[i].material < 0)
            return &table[i];
        int same = 1;
        for (int k = 0; k < F_NUMBERS; k++)
            same = same && table[i].f[k] == f[k];
        if (same)
            return &table[i];
    }
}

/* Doubles the table (from 0 to 64 slots at first), keeping every entry. */
static void grow_table(struct nff_reader *rd)
{
    size_t cap = rd->cap_table == 0 ? 64 : 2 * rd->cap_table;
    struct f_entry *table = xmalloc(cap, sizeof *table, "NFF materials");
    for (size_t i = 0; i < cap; i++)
        table[i].material = -1;
    for (size_t i = 0; i < rd->cap_table; i++)
        if (rd->table[i].material >= 0)
            *find_slot(table, cap, rd->table[i].f) = rd->table[i];
    xfree(rd->table);
    rd->table = table;
    rd->cap_table = cap;
}

/* "f r g b Kd Ks Shine T ior" */
static int read_fill(struct nff_reader *rd, struct error *err)
{
    double f[F_NUMBERS];
    if (read_line_numbers(rd, f, F_NUMBERS, "r g b Kd Ks Shine T ior", err) < 0)
        return -1;
    for (int i = 0; i < F_NUMBERS; i++)
        if (!(f[i] >= 0))
            return nff_error(rd, err, "the numbers must not be negative");
    if (f[6] > 0 && !(f[7] > 0))
        return nff_error(rd, err, "a transmitting material (T > 0) needs an index of "
                                  "refraction > 0");
    if (2 * (rd->n_table + 1) > rd->cap_table)
        grow_table(rd);
    struct f_entry *slot = find_slot(rd->table, rd->cap_table, f);
    if (slot->material < 0) {
        struct material m = nff_material(f, rd->scene->n_materials);
        int index = scene_add_material(rd->scene, &m);
        if (index < 0)
            return nff_error(rd, err, "more than %d materials", MAX_MATERIALS);
        memcpy(slot->f, f, sizeof slot->f);
        slot->material = index;
        rd->n_table++;
    }
    rd->material = slot->material;
    return 0;
}

/* The current material, or -1 with *err filled when no `f` came yet. */
static int current_material(struct nff_reader *rd, struct error *err)
{
    if (rd->material < 0)
        return nff_error(rd, err, "an object before any 'f' line (NFF sets the material "
                                  "first)");
    return rd->material;
}

/* ---- objects ------------------------------------------------------------------------- */

static int check_added(struct nff_reader *rd, int id, struct error *err)
{
    return scene_add_error(id, rd->file, rd->line, rd->entity, err);
}

/* "s x y z r" */
static int read_sphere(struct nff_reader *rd, struct error *err)
{
    double v[4];
    int material = current_material(rd, err);
    if (material < 0 || read_line_numbers(rd, v, 4, "centre x y z, radius", err) < 0)
        return -1;
    if (!(v[3] > 0))
        return nff_error(rd, err, "the radius must be positive, got %.40s", rd->tokens[4]);
    return check_added(rd, scene_add_sphere(rd->scene, vec3_at(v), v[3], material), err);
}

/* "c bx by bz br ax ay az ar", or "c" then "bx by bz br" and "ax ay az ar" lines. */
static int read_cone(struct nff_reader *rd, struct error *err)
{
    double v[8];
    int material = current_material(rd, err);
    if (material < 0)
        return -1;
    if (rd->next < rd->n_tokens) {
        if (read_line_numbers(rd, v, 8, "base x y z, radius, apex x y z, radius", err) < 0)
            return -1;
    } else {
        if (continuation_line(rd, "the base line", err) < 0 ||
            read_line_numbers(rd, v, 4, "base x y z, radius", err) < 0 ||
            continuation_line(rd, "the apex line", err) < 0 ||
            read_line_numbers(rd, v + 4, 4, "apex x y z, radius", err) < 0)
            return -1;
    }
    struct error inner;
    struct cone *cone = cone_create(vec3_at(v), v[3], vec3_at(v + 4), v[7], material, &inner);
    if (cone == NULL)
        return nff_error(rd, err, "%s", inner.message);
    if (scene_add_shape(rd->scene, &cone_ops, cone, material) >= 0)
        return 0;
    cone_free(cone);
    return check_added(rd, -1, err);
}

/* Vertex i of n of a `p` (smooth = 0) or `pp` (smooth = 1) into the scratch arrays. */
static int read_vertex(struct nff_reader *rd, int i, int n, int smooth, struct error *err)
{
    char what[96];
    double v[6];
    snprintf(what, sizeof what, "vertex %d of %d", i + 1, n);
    if (continuation_line(rd, what, err) < 0)
        return -1;
    snprintf(what, sizeof what, "%s of vertex %d of %d", smooth ? "x y z nx ny nz" : "x y z",
             i + 1, n);
    if (read_line_numbers(rd, v, smooth ? 6 : 3, what, err) < 0)
        return -1;
    rd->vertices[i] = vec3_at(v);
    if (!smooth)
        return 0;
    rd->normals[i] = unit_normal(vec3_at(v + 3));
    if (vec3_length2(rd->normals[i]) == 0)
        return nff_error(rd, err, "the normal of vertex %d is zero", i + 1);
    return 0;
}

/* Adds the polygon in the scratch arrays as its n - 2 triangles. */
static int add_polygon(struct nff_reader *rd, int n, int smooth, int material,
                       struct error *err)
{
    polygon_triangulate(rd->vertices, n, rd->triangles);
    for (int k = 0; k < n - 2; k++) {
        const int *corner = rd->triangles + 3 * k;
        struct vec3 v[3], normals[3];
        for (int j = 0; j < 3; j++) {
            v[j] = rd->vertices[corner[j]];
            normals[j] = rd->normals[corner[j]];
        }
        int id = scene_add_triangle(rd->scene, v, smooth ? normals : NULL, material);
        if (check_added(rd, id, err) < 0)
            return -1;
    }
    return 0;
}

/* "p n" or "pp n", then n vertex lines. */
static int read_polygon(struct nff_reader *rd, struct error *err)
{
    int smooth = strcmp(rd->entity, "pp") == 0;
    double count;
    char what[48];
    snprintf(what, sizeof what, "a vertex count from 3 to %d", MAX_POLYGON_VERTICES);
    int material = current_material(rd, err);
    if (material < 0 || read_line_of(rd, &count, 1, 1, what, err) < 0)
        return -1;
    if (!(count >= 3 && count <= MAX_POLYGON_VERTICES))
        return nff_error(rd, err, "the vertex count must be a whole number from 3 to %d, "
                                  "got %.40s", MAX_POLYGON_VERTICES, rd->tokens[1]);
    int n = (int)count;
    for (int i = 0; i < n; i++)
        if (read_vertex(rd, i, n, smooth, err) < 0)
            return -1;
    return add_polygon(rd, n, smooth, material, err);
}

/* ---- the file ------------------------------------------------------------------------ */

struct nff_keyword {
    const char *name;
    int (*read)(struct nff_reader *rd, struct error *err);
};

static const struct nff_keyword nff_keywords[] = {
    {"v", read_view},   {"b", read_background}, {"l", read_light},   {"f", read_fill},
    {"s", read_sphere}, {"c", read_cone},       {"p", read_polygon}, {"pp", read_polygon},
};

static int read_entities(struct nff_reader *rd, struct error *err)
{
    int status;
    while ((status = next_line(rd, err)) > 0) {
        size_t k = 0, n_keywords = sizeof nff_keywords / sizeof nff_keywords[0];
        while (k < n_keywords && strcmp(rd->tokens[0], nff_keywords[k].name) != 0)
            k++;
        if (k == n_keywords)
            return error_set(err, rd->file, rd->line, "unknown keyword '%.40s' (NFF entities "
                             "read here: v b l f s c p pp)", rd->tokens[0]);
        snprintf(rd->entity, sizeof rd->entity, "%s", nff_keywords[k].name);
        rd->next = 1;
        if (nff_keywords[k].read(rd, err) < 0)
            return -1;
    }
    if (status < 0)
        return -1;
    if (!rd->has_view)
        return error_set(err, rd->file, 0, "no 'v' block: an NFF file gives its view");
    return add_lights(rd, err);
}

static struct nff_reader *reader_create(struct scene *scene, const char *path,
                                        struct input *in)
{
    struct nff_reader *rd = xcalloc(1, sizeof *rd, "NFF reader"); /* large: the heap */
    rd->scene = scene;
    rd->file = path;
    rd->in = in;
    rd->lights = NULL;
    rd->material = -1;
    rd->table = NULL;
    rd->vertices = xmalloc(MAX_POLYGON_VERTICES, sizeof *rd->vertices, "polygon vertices");
    rd->normals = xmalloc(MAX_POLYGON_VERTICES, sizeof *rd->normals, "polygon normals");
    rd->triangles = xmalloc(3 * (MAX_POLYGON_VERTICES - 2), sizeof *rd->triangles,
                            "polygon triangles");
    return rd;
}

static void reader_free(struct nff_reader *rd)
{
    xfree(rd->triangles);
    xfree(rd->normals);
    xfree(rd->vertices);
    xfree(rd->table);
    xfree(rd->lights);
    xfree(rd);
}

int nff_import(struct scene *scene, const char *path, struct error *err)
{
    struct input in;
    if (input_open(&in, path, err) < 0)
        return -1;
    struct nff_reader *rd = reader_create(scene, path, &in);
    int status = read_entities(rd, err);
    reader_free(rd);
    input_close(&in);
    return status;
}

struct scene *nff_load(const char *path, struct error *err)
{
    struct scene *scene = scene_create();
    if (nff_import(scene, path, err) < 0 || (reach_note(scene, path, 0), 0) ||
        reach_check(scene, err) < 0) {
        scene_free(scene);
        return NULL;
    }
    return scene;
}
