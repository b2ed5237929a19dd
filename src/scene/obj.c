/*
 * scene/obj.c -- the Wavefront OBJ reader: polygon meshes, as triangles.
 *
 * What is read (README, "Scene files", in short):
 *   v x y z [w | r g b]  a vertex, placed at scale * R (x, y, z) + translation (obj.h); a
 *                        fourth number (w) or three more (a vertex colour) are ignored.
 *   vn x y z             a vertex normal (normalised, turned by R; zero is refused).
 *   vt u [v [w]]         a texture coordinate: only counted, so faces may name it.
 *   f c1 c2 c3 ...       a face of 3 <= n <= MAX_POLYGON_VERTICES corners, each `v`,
 *                        `v/vt`, `v//vn` or `v/vt/vn`. Indices count from 1; a negative
 *                        index counts back from the last element defined (-1 is the last).
 *                        An index must name an element defined above its line. The face
 *                        becomes n - 2 triangles by ear clipping (geom/polygon.h), all of
 *                        the current material; the vertex normals are interpolated when
 *                        every corner names one, else the face is flat.
 *   usemtl NAME          the faces below take the scene's material NAME, if the scene
 *                        defines one above the obj line; else the placement's, with one
 *                        warning per such NAME (the rest of the line, spaces and all): an
 *                        OBJ file's material names are often the exporter's own, so a
 *                        mesh still loads, and the warning says why it looks uniform.
 *   o g s mtllib l p     tolerated and ignored (names, groups, smoothing groups, material
 *                        libraries, and lines and points, which have no area).
 *   # ...                a comment, to the end of the line; blank lines are skipped.
 * Any other keyword is refused by name: free-form curves and surfaces are not supported,
 * and a mesh silently missing parts would be worse than a clear message. So is a file
 * with no face at all. Numbers are in base/number.h's syntax ("1.0e-05", "-0.5"; not
 * "0x1"), indices whole ("-1", not "+1"); the file is read a line at a time.
 * Placement turns normals by R only: a positive uniform scale and a translation do not
 * turn them.
 *
 * The reader owns its arrays (vertices, normals, scratch, names warned of) and frees them
 * however it ends; the triangles it adds are the scene's.
 */
#include "obj.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/input.h"
#include "../base/number.h"
#include "../geom/polygon.h"
#include "../geom/triangle.h"

#define OBJ_MAX_LINE 65536   /* longest line in bytes, newline included: a face of
                                thousands of corners fits                            */
#define OBJ_KEYWORD_MAX 16   /* keywords are kept this long for messages            */

struct obj_reader {
    struct scene *scene;               /* borrowed                                      */
    const struct obj_placement *place; /* borrowed                                      */
    struct vec3 axis;                  /* the turn R: unit axis (zero for no turn),     */
    double cos_turn, sin_turn;         /*   cosine and sine of its angle                */
    int material;                      /* the current material (usemtl), for new faces  */
    char *unknown;                     /* owned: the usemtl names warned of, each ended
                                          by '\0', unknown_length bytes of unknown_cap   */
    size_t unknown_length, unknown_cap;
    const char *file;
    struct input *in;                  /* borrowed from obj_import(): the file read     */
    int line;                          /* 1-based number of the line in text            */
    char *text;                        /* owned: OBJ_MAX_LINE bytes, the current line   */
    char *cursor;                      /* the first byte of text not yet read           */
    char keyword[OBJ_KEYWORD_MAX];     /* the current line's keyword                    */
    struct vec3 *positions;            /* owned; placed vertices, n of cap              */
    size_t n_positions, cap_positions;
    struct vec3 *normals;              /* owned; unit normals, n of cap                 */
    size_t n_normals, cap_normals;
    size_t n_texcoords;                /* counted only                                  */
    struct vec3 *face_v, *face_n;      /* owned scratch: MAX_POLYGON_VERTICES each      */
    int *triangles;                    /* owned scratch: 3 (MAX_POLYGON_VERTICES - 2)   */
};

/* Fills *err with "file:line: keyword: message" and returns -1. */
static int obj_error(const struct obj_reader *rd, struct error *err, const char *format, ...)
{
    char message[ERROR_MESSAGE_MAX];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    return error_set(err, rd->file, rd->line, "%s: %s", rd->keyword, message);
}

/* The next word of the line, cut off in place; NULL at the end of the line or at a '#'. */
static char *next_word(struct obj_reader *rd)
{
    char *s = rd->cursor;
    while (isspace((unsigned char)*s))
        s++;
    if (*s == '\0' || *s == '#') {
        rd->cursor = s;
        *s = '\0';
        return NULL;
    }
    char *word = s;
    while (*s != '\0' && !isspace((unsigned char)*s))
        s++;
    if (*s != '\0')
        *s++ = '\0';
    rd->cursor = s;
    return word;
}

/* Reads the next line into rd->text: 1, 0 at the end of the file, -1 with *err filled. */
static int read_line(struct obj_reader *rd, struct error *err)
{
    int status = input_line(rd->in, rd->text, OBJ_MAX_LINE, err);
    if (status <= 0)
        return status;
    rd->line = rd->in->line;
    scene_hash_line(rd->scene, rd->text);
    rd->cursor = rd->text;
    return 1;
}

/* Reads a finite number; `what` names it for messages. 1 with *x, 0 at the end of the
 * line, -1 with *err filled. */
static int read_number(struct obj_reader *rd, double *x, const char *what, struct error *err)
{
    const char *word = next_word(rd);
    if (word == NULL)
        return 0;
    enum number_verdict verdict = number_read(word, 0, x);
    if (verdict == NUMBER_UNWRITTEN)
        return obj_error(rd, err, "'%.40s' is not a number (expected %s)", word, what);
    if (verdict != NUMBER_OK)
        return obj_error(rd, err, "number '%.40s' %s", word, number_problem(verdict, 0));
    return 1;
}

/* Reads between min and max numbers to the end of the line; returns how many, or -1. */
static int read_numbers(struct obj_reader *rd, double *v, int min, int max, const char *what,
                        struct error *err)
{
    int n = 0;
    for (;;) {
        double x;
        int status = read_number(rd, &x, what, err);
        if (status < 0)
            return -1;
        if (status == 0)
            break;
        if (n == max)
            return obj_error(rd, err, "more than %d numbers (%s)", max, what);
        v[n++] = x;
    }
    if (n < min)
        return obj_error(rd, err, "expected %d numbers (%s), got %d", min, what, n);
    return n;
}

/* Room for one more element in *array (capacity *cap), growing geometrically. */
static void *reserve_one(void *array, size_t *cap, size_t n, size_t size, const char *what)
{
    if (n < *cap)
        return array;
    *cap = *cap < 64 ? 64 : 2 * *cap;
    return xrealloc(array, *cap, size, what);
}

/* The sine and cosine of an angle in degrees, exact at multiples of 90: a quarter turn
 * then takes axis-aligned faces to axis-aligned faces exactly (a floor stays flat), where
 * cos(pi / 2) in doubles is 6e-17, not 0. */
static void sin_cos_degrees(double degrees, double *s, double *c)
{
    static const double quarter_sin[4] = {0, 1, 0, -1}; /* sin(k 90 degrees), k = 0..3 */
    double quarters = degrees / 90.0;
    if (quarters == floor(quarters)) {
        int k = ((int)fmod(quarters, 4.0) + 4) % 4; /* fmod: no int overflow */
        *s = quarter_sin[k];
        *c = quarter_sin[(k + 1) % 4]; /* cos(k 90) = sin((k + 1) 90) */
        return;
    }
    *s = sin(degrees * (PI / 180.0));
    *c = cos(degrees * (PI / 180.0));
}

/* p turned by the placement's R, about the unit axis k by Rodrigues' formula:
 * p cos + (k x p) sin + k (k . p) (1 - cos), counter-clockwise seen from k's tip. */
static struct vec3 turned(const struct obj_reader *rd, struct vec3 p)
{
    if (rd->sin_turn == 0 && rd->cos_turn == 1)
        return p; /* no turn (0 or 360 degrees): p exactly */
    struct vec3 k = rd->axis;
    struct vec3 q = vec3_madd(vec3_scale(p, rd->cos_turn), vec3_cross(k, p), rd->sin_turn);
    return vec3_madd(q, k, vec3_dot(k, p) * (1.0 - rd->cos_turn));
}

/* "v x y z [w | r g b]" */
static int read_position(struct obj_reader *rd, struct error *err)
{
    double v[7];
    if (read_numbers(rd, v, 3, 7, "x y z [w | r g b]", err) < 0)
        return -1;
    if (rd->n_positions == OBJ_MAX_VERTICES)
        return obj_error(rd, err, "more than %d vertices", OBJ_MAX_VERTICES);
    const struct obj_placement *place = rd->place;
    struct vec3 p = vec3_madd(place->translation, turned(rd, vec3(v[0], v[1], v[2])),
                              place->scale);
    if (!vec3_is_finite(p))
        return obj_error(rd, err, "the placed vertex is not finite (scale too large?)");
    rd->positions = reserve_one(rd->positions, &rd->cap_positions, rd->n_positions,
                                sizeof *rd->positions, "OBJ vertices");
    rd->positions[rd->n_positions++] = p;
    return 0;
}

/* "vn x y z" */
static int read_normal(struct obj_reader *rd, struct error *err)
{
    double v[3];
    if (read_numbers(rd, v, 3, 3, "x y z", err) < 0)
        return -1;
    if (rd->n_normals == OBJ_MAX_VERTICES)
        return obj_error(rd, err, "more than %d normals", OBJ_MAX_VERTICES);
    struct vec3 n = turned(rd, unit_normal(vec3(v[0], v[1], v[2]))); /* unit: no overflow */
    if (vec3_length2(n) == 0)
        return obj_error(rd, err, "the normal is zero");
    rd->normals = reserve_one(rd->normals, &rd->cap_normals, rd->n_normals,
                              sizeof *rd->normals, "OBJ normals");
    rd->normals[rd->n_normals++] = n;
    return 0;
}

/* "vt u [v [w]]" */
static int read_texcoord(struct obj_reader *rd, struct error *err)
{
    double v[3];
    if (read_numbers(rd, v, 1, 3, "u [v [w]]", err) < 0)
        return -1;
    if (rd->n_texcoords == OBJ_MAX_VERTICES)
        return obj_error(rd, err, "more than %d texture coordinates", OBJ_MAX_VERTICES);
    rd->n_texcoords++;
    return 0;
}

/* Parses one index at *s (stopping at '/' or the end) into a 0-based index below count.
 * An index is a whole number in base/number.h's syntax: the OBJ specification writes
 * reference numbers as integers, negative ones with '-' (relative), never with '+'.
 * Returns 0, or -1 with *err filled; `what` names the element ("vertex"). */
static int parse_index(struct obj_reader *rd, char **s, size_t count, const char *what,
                       size_t *index, struct error *err)
{
    char text[24]; /* longer than any index in range: its digits do not fit, it is refused */
    size_t n = strcspn(*s, "/");
    double i = 0;
    if (n < sizeof text) {
        memcpy(text, *s, n);
        text[n] = '\0';
    }
    if (n >= sizeof text || number_read(text, 1, &i) != NUMBER_OK)
        return obj_error(rd, err, "a %s index must be a whole number", what);
    *s += n;
    if (i == 0 || (i > 0 && i > (double)count) || (i < 0 && -i > (double)count))
        return obj_error(rd, err, "%s index %s is out of range (%zu defined above)", what, text,
                         count);
    *index = i > 0 ? (size_t)i - 1 : count - (size_t)(-i);
    return 0;
}

/* One corner "v", "v/vt", "v//vn" or "v/vt/vn" into face slot k; *has_normal says
 * whether it named a normal. */
static int parse_corner(struct obj_reader *rd, char *s, int k, int *has_normal,
                        struct error *err)
{
    size_t v, vt, vn;
    if (parse_index(rd, &s, rd->n_positions, "vertex", &v, err) < 0)
        return -1;
    rd->face_v[k] = rd->positions[v];
    *has_normal = 0;
    if (*s == '\0')
        return 0;
    s++; /* the first '/' */
    if (*s != '/' && parse_index(rd, &s, rd->n_texcoords, "texture", &vt, err) < 0)
        return -1;
    if (*s == '\0')
        return 0;
    s++; /* the second '/' */
    if (parse_index(rd, &s, rd->n_normals, "normal", &vn, err) < 0)
        return -1;
    if (*s != '\0')
        return obj_error(rd, err, "a corner is v, v/vt, v//vn or v/vt/vn");
    rd->face_n[k] = rd->normals[vn];
    *has_normal = 1;
    return 0;
}

/* Adds the face in the scratch arrays as n - 2 triangles. */
static int add_face(struct obj_reader *rd, int n, int smooth, struct error *err)
{
    polygon_triangulate(rd->face_v, n, rd->triangles);
    for (int k = 0; k < n - 2; k++) {
        struct vec3 v[3], normals[3];
        for (int j = 0; j < 3; j++) {
            v[j] = rd->face_v[rd->triangles[3 * k + j]];
            normals[j] = rd->face_n[rd->triangles[3 * k + j]];
        }
        int id = scene_add_triangle(rd->scene, v, smooth ? normals : NULL, rd->material);
        if (scene_add_error(id, rd->file, rd->line, rd->keyword, err) < 0)
            return -1;
    }
    return 0;
}

/* "f c1 c2 c3 ..." */
static int read_face(struct obj_reader *rd, struct error *err)
{
    int n = 0, smooth = 1;
    char *word;
    while ((word = next_word(rd)) != NULL) {
        if (n == MAX_POLYGON_VERTICES)
            return obj_error(rd, err, "more than %d corners", MAX_POLYGON_VERTICES);
        int has_normal;
        if (parse_corner(rd, word, n++, &has_normal, err) < 0)
            return -1;
        smooth = smooth && has_normal;
    }
    if (n < 3)
        return obj_error(rd, err, "a face needs at least 3 corners, got %d", n);
    return add_face(rd, n, smooth, err);
}

/* The rest of the line without the white space around it, cut off at a '#'. */
static char *rest_of_line(struct obj_reader *rd)
{
    char *s = rd->cursor + strspn(rd->cursor, " \t\r\n\f\v");
    char *end = s + strcspn(s, "#");
    while (end > s && isspace((unsigned char)end[-1]))
        end--;
    *end = '\0';
    rd->cursor = end;
    return s;
}

/* Whether name is among the usemtl names warned of; adds it if not. */
static int warned_before(struct obj_reader *rd, const char *name)
{
    for (size_t at = 0; at < rd->unknown_length; at += strlen(rd->unknown + at) + 1)
        if (strcmp(rd->unknown + at, name) == 0)
            return 1;
    size_t length = strlen(name) + 1;
    if (rd->unknown_length + length > rd->unknown_cap) {
        rd->unknown_cap = 2 * (rd->unknown_length + length);
        rd->unknown = xrealloc(rd->unknown, rd->unknown_cap, 1, "OBJ material names");
    }
    memcpy(rd->unknown + rd->unknown_length, name, length);
    rd->unknown_length += length;
    return 0;
}

/* "usemtl NAME": the scene's material NAME for the faces below, or the placement's. */
static int read_usemtl(struct obj_reader *rd, struct error *err)
{
    const char *name = rest_of_line(rd);
    if (*name == '\0')
        return obj_error(rd, err, "expected a material name");
    int m = scene_find_material(rd->scene, name);
    rd->material = m >= 0 ? m : rd->place->material;
    if (m < 0 && !warned_before(rd, name))
        message_print("photon: warning: %s:%d: usemtl '%.200s': no material of that name "
                      "above the obj line; its faces keep the obj line's '%s'",
                      rd->file, rd->line, name,
                      rd->scene->materials[rd->place->material].name);
    return 0;
}

struct obj_keyword {
    const char *name;
    int (*read)(struct obj_reader *rd, struct error *err); /* NULL: tolerated, ignored */
};

static const struct obj_keyword obj_keywords[] = {
    {"v", read_position}, {"vn", read_normal}, {"vt", read_texcoord}, {"f", read_face},
    {"o", NULL},          {"g", NULL},         {"s", NULL},           {"usemtl", read_usemtl},
    {"mtllib", NULL},     {"l", NULL},         {"p", NULL},
};

static int read_statement(struct obj_reader *rd, struct error *err)
{
    const char *word = next_word(rd);
    if (word == NULL)
        return 0; /* blank or a comment */
    size_t k = 0, n_keywords = sizeof obj_keywords / sizeof obj_keywords[0];
    while (k < n_keywords && strcmp(word, obj_keywords[k].name) != 0)
        k++;
    if (k == n_keywords)
        return error_set(err, rd->file, rd->line, "unknown keyword '%.40s' (read here: v vn vt "
                         "f usemtl; ignored: o g s mtllib l p)", word);
    snprintf(rd->keyword, sizeof rd->keyword, "%s", word);
    return obj_keywords[k].read != NULL ? obj_keywords[k].read(rd, err) : 0;
}

/* Every line; a file without a face is refused, since placing nothing is surely a mistake
 * (a wrong file, or one of free-form surfaces only). */
static int read_statements(struct obj_reader *rd, struct error *err)
{
    int status;
    size_t n_prims = rd->scene->n_prims;
    while ((status = read_line(rd, err)) > 0)
        if (read_statement(rd, err) < 0)
            return -1;
    if (status == 0 && rd->scene->n_prims == n_prims)
        return error_set(err, rd->file, 0, "no faces: the file adds nothing to the scene");
    return status;
}

struct obj_placement obj_unmoved(int material)
{
    struct obj_placement place;
    place.material = material;
    place.scale = 1.0;
    place.translation = vec3_zero();
    place.degrees = 0.0;
    place.axis = vec3_zero();
    return place;
}

int obj_import(struct scene *scene, const char *path, const struct obj_placement *place,
               struct error *err)
{
    struct input in;
    if (input_open(&in, path, err) < 0)
        return -1;
    struct obj_reader *rd = xcalloc(1, sizeof *rd, "OBJ reader");
    rd->scene = scene;
    rd->place = place;
    rd->file = path;
    rd->in = &in;
    rd->material = place->material;
    rd->unknown = NULL;
    rd->axis = place->degrees != 0 ? unit_normal(place->axis) : vec3_zero();
    sin_cos_degrees(place->degrees, &rd->sin_turn, &rd->cos_turn);
    rd->positions = NULL;
    rd->normals = NULL;
    rd->text = xmalloc(OBJ_MAX_LINE, 1, "OBJ line");
    rd->face_v = xmalloc(MAX_POLYGON_VERTICES, sizeof *rd->face_v, "OBJ face");
    rd->face_n = xmalloc(MAX_POLYGON_VERTICES, sizeof *rd->face_n, "OBJ face");
    rd->triangles = xmalloc(3 * (MAX_POLYGON_VERTICES - 2), sizeof *rd->triangles, "OBJ face");
    int status = read_statements(rd, err);
    xfree(rd->triangles);
    xfree(rd->face_n);
    xfree(rd->face_v);
    xfree(rd->text);
    xfree(rd->normals);
    xfree(rd->positions);
    xfree(rd->unknown);
    xfree(rd);
    input_close(&in);
    return status;
}
