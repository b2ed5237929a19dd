/*
 * tests/test_import_obj.c -- the obj line's `rotate` and OBJ's `usemtl` (scene/obj.c,
 * scene/parse_objects.c): the triangles of a loaded scene, read back in the order they
 * were added (geometry_visit), against rotations worked out by hand, and per-face
 * materials through `photon export`. The OBJ reader's other rules are test_import.c's.
 *
 * Truths: rotations of the unit vectors in closed form (90 degrees about z takes x to y;
 * 120 degrees about (1, 1, 1) takes x to y to z to x); what a rotation keeps whatever its
 * axis and angle (lengths, areas, the triple product's sign); usemtl's materials as the
 * README states them. Scratch files go to /tmp (files.h).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/rng.h"
#include "../src/scene/scene.h"
#include "files.h"
#include "tests.h"

#define NAME_BYTES 256
#define TEXT_BYTES 4096
#define MAX_COLLECTED 64

/* Scratch files, named by temp_name() in test_import_obj(): the scene names the mesh by
 * its base name, both being in /tmp. */
static char scratch_scene[NAME_BYTES], scratch_mesh[NAME_BYTES], scratch_out[NAME_BYTES],
    scratch_log[NAME_BYTES];

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash != NULL ? slash + 1 : path;
}

/* The triangles of a scene, in the order they were added. */
struct collected {
    size_t n;
    struct vec3 v[MAX_COLLECTED][3];
    struct vec3 normals[MAX_COLLECTED][3]; /* zero when the triangle has none */
    int material[MAX_COLLECTED];
};

static void collect_triangle(void *context, const struct vec3 v[3], const struct vec3 *normals,
                             int material)
{
    struct collected *c = context;
    if (c->n == MAX_COLLECTED)
        return;
    for (int i = 0; i < 3; i++) {
        c->v[c->n][i] = v[i];
        c->normals[c->n][i] = normals != NULL ? normals[i] : vec3_zero();
    }
    c->material[c->n++] = material;
}

static void ignore_sphere(void *context, struct vec3 centre, double radius, int material)
{
    (void)context, (void)centre, (void)radius, (void)material;
}

static void ignore_quad(void *context, struct vec3 p0, struct vec3 e1, struct vec3 e2,
                        int material)
{
    (void)context, (void)p0, (void)e1, (void)e2, (void)material;
}

static void ignore_shape(void *context, const char *name, const char *approximation)
{
    (void)context, (void)name, (void)approximation;
}

/* Writes the mesh and a scene made from scene_format (its %s the mesh's name, given
 * twice for a second obj line) and loads the scene: NULL with *err filled when refused. */
static struct scene *load_with_mesh(const char *scene_format, const char *mesh,
                                    struct error *err)
{
    char text[TEXT_BYTES];
    write_text_file(scratch_mesh, mesh);
    snprintf(text, sizeof text, scene_format, base_name(scratch_mesh), base_name(scratch_mesh));
    write_text_file(scratch_scene, text);
    return scene_load(scratch_scene, err);
}

/* Loads as load_with_mesh() does and collects the triangles; 0, or -1 when refused. */
static int load_triangles(const char *scene_format, const char *mesh, struct collected *c)
{
    struct error err;
    struct scene *scene = load_with_mesh(scene_format, mesh, &err);
    if (scene == NULL) {
        fprintf(stderr, "test_import_obj: %s:%d: %s\n", err.file, err.line, err.message);
        return -1;
    }
    c->n = 0;
    struct primitive_visitor v = {c, ignore_sphere, collect_triangle, ignore_quad,
                                  ignore_shape};
    geometry_visit(scene->geometry, &v);
    scene_free(scene);
    return 0;
}

static int close_vec(struct vec3 a, struct vec3 b, double tolerance)
{
    return vec3_max_abs(vec3_sub(a, b)) <= tolerance;
}

/* ---- rotate ---------------------------------------------------------------------------- */

#define UNIT_FACE "v 1 0 0\nv 0 1 0\nv 0 0 1\nvn 1 0 0\nvn 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//3\n"
#define CAMERA "camera 0 0 -5  0 0 0  0 1 0  40\nmaterial m lambert 0.5 0.5 0.5\n"

/* A rotation as written on the obj line and the images of x, y and z worked out by hand. */
struct turn_case {
    const char *words;  /* "AX AY AZ DEGREES" */
    double image[3][3]; /* R x, R y, R z      */
    int exact;          /* a multiple of 90 degrees: the images exactly */
};

/* truth: closed forms, counter-clockwise seen from the axis's tip (the right-hand rule):
 *   a quarter turn about z takes x to y and y to -x, about x y to z, about y z to x; a
 *   half turn negates the two other axes; 120 degrees about (1, 1, 1) takes x to y, y to
 *   z, z to x, as do -240 degrees; 45 degrees about z takes x to (1, 1, 0) / sqrt 2. The
 *   face's corners are x, y and z, its vertex normals too: each corner i is placed at
 *   2 R e_i + (1, 2, 3) and its normal is R e_i.
 * tolerance: exact for multiples of 90 degrees (obj.c promises it: a floor stays flat),
 *   4e-15 (a few roundings of numbers up to 4) otherwise.
 * catches: the angle's sign or the axis's handedness reversed, radians for degrees, the
 *   axis left unnormalised, normals not turned, the turn applied after the scale or the
 *   translation instead of before them, cos(pi / 2) leaving 6e-17 where 0 is written. */
static void test_rotation_closed_form(struct check *t)
{
    const double h = sqrt(0.5);
    static const struct turn_case cases[] = {
        {"0 0 1 90", {{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}, 1},
        {"1 0 0 90", {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}, 1},
        {"0 1 0 90", {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}, 1},
        {"0 0 1 -90", {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}, 1},
        {"0 0 2.5 180", {{-1, 0, 0}, {0, -1, 0}, {0, 0, 1}}, 1},
        {"0 -3 0 270", {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}, 1},
        {"1 1 1 120", {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, 0},
        {"2 2 2 -240", {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, 0},
        {"0 0 1 360", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 1},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char format[TEXT_BYTES];
        snprintf(format, sizeof format, CAMERA "obj %%s m rotate %s scale 2 translate 1 2 3\n",
                 cases[k].words);
        struct collected c;
        CHECK(t, load_triangles(format, UNIT_FACE, &c) == 0 && c.n == 1);
        double tolerance = cases[k].exact ? 0 : 4e-15;
        for (int i = 0; i < 3 && c.n == 1; i++) {
            const double *e = cases[k].image[i];
            struct vec3 placed = vec3(2 * e[0] + 1, 2 * e[1] + 2, 2 * e[2] + 3);
            int right = close_vec(c.v[0][i], placed, 2 * tolerance) &&
                        close_vec(c.normals[0][i], vec3(e[0], e[1], e[2]), tolerance);
            if (!right)
                fprintf(stderr, "rotate %s: corner %d at (%.17g, %.17g, %.17g)\n",
                        cases[k].words, i, c.v[0][i].x, c.v[0][i].y, c.v[0][i].z);
            CHECK(t, right);
        }
    }
    struct collected c;
    CHECK(t, load_triangles(CAMERA "obj %s m rotate 0 0 1 45\n", UNIT_FACE, &c) == 0 && c.n == 1);
    CHECK(t, c.n == 1 && close_vec(c.v[0][0], vec3(h, h, 0), 3e-16) &&
                 close_vec(c.v[0][1], vec3(-h, h, 0), 3e-16) &&
                 close_vec(c.v[0][2], vec3(0, 0, 1), 0));
}

static double triangle_area(const struct vec3 v[3])
{
    return 0.5 * vec3_length(vec3_cross(vec3_sub(v[1], v[0]), vec3_sub(v[2], v[0])));
}

/* v0 . (v1 x v2): six times the signed volume of the tetrahedron with the origin, which a
 * rotation about an axis through the origin keeps and a reflection negates. */
static double triple_product(const struct vec3 v[3])
{
    return vec3_dot(v[0], vec3_cross(v[1], v[2]));
}

/* Whether the turned triangles keep each triangle's area, each corner's distance from the
 * origin and the triple product, to a relative 1e-13. */
static int rotation_keeps_measures(const struct collected *plain, const struct collected *turned)
{
    int kept = plain->n == turned->n && plain->n > 0;
    for (size_t i = 0; kept && i < plain->n; i++) {
        double a = triangle_area(plain->v[i]), b = triangle_area(turned->v[i]);
        double p = triple_product(plain->v[i]), q = triple_product(turned->v[i]);
        double lengths = 1; /* the scale of the triple product */
        kept = fabs(a - b) <= 1e-13 * a;
        for (int j = 0; j < 3; j++) {
            double r = vec3_length(plain->v[i][j]), s = vec3_length(turned->v[i][j]);
            kept = kept && fabs(r - s) <= 1e-13 * r;
            lengths *= r;
        }
        kept = kept && fabs(p - q) <= 1e-13 * lengths;
    }
    return kept;
}

/* truth: a rotation is an isometry of determinant +1 fixing the origin: whatever the axis
 *   and angle, every triangle keeps its area, its corners' distances from the origin and
 *   its triple product with the origin (the sign says no reflection crept in). 12 random
 *   triangles of random size under 40 random rotations, and +-360 and 0 degrees, which
 *   must place every vertex exactly where no rotation does.
 * tolerance: 1e-13 relative, a few roundings of the rotation; none for the full turns.
 * catches: a matrix that scales (the axis not normalised, sin and cos of different
 *   angles), a reflection (the cross product's sign), a full turn that drifts. */
static void test_rotation_keeps_measures(struct check *t)
{
    char mesh[TEXT_BYTES], format[TEXT_BYTES];
    struct rng rng = rng_stream(54, STREAM_TEST, 0, 0);
    int length = 0;
    for (int i = 0; i < 36; i++)
        length += sprintf(mesh + length, "v %.17g %.17g %.17g\n", 10 * rng_uniform(&rng) - 5,
                          10 * rng_uniform(&rng) - 5, 10 * rng_uniform(&rng) - 5);
    for (int i = 0; i < 12; i++)
        length += sprintf(mesh + length, "f %d %d %d\n", 3 * i + 1, 3 * i + 2, 3 * i + 3);
    static struct collected plain, turned;
    REQUIRE(t, load_triangles(CAMERA "obj %s m\n", mesh, &plain) == 0 && plain.n == 12);
    for (int k = 0; k < 43; k++) {
        double axis[3], degrees = k < 3 ? 360.0 * (k - 1) : 720 * rng_uniform(&rng) - 360;
        for (int j = 0; j < 3; j++)
            axis[j] = 2 * rng_uniform(&rng) - 1;
        snprintf(format, sizeof format, CAMERA "obj %%s m rotate %.17g %.17g %.17g %.17g\n",
                 axis[0], axis[1], axis[2], degrees);
        CHECK(t, load_triangles(format, mesh, &turned) == 0);
        CHECK(t, rotation_keeps_measures(&plain, &turned));
        if (k < 3 && turned.n == plain.n) /* a full turn, or none: the vertices exactly */
            for (size_t i = 0; i < plain.n; i++)
                CHECK(t, memcmp(plain.v[i], turned.v[i], sizeof plain.v[i]) == 0);
    }
}

/* ---- usemtl ----------------------------------------------------------------------------- */

/* Six faces, face k at z = k: before any usemtl; red (with a comment after the name);
 * nosuch; white; late (defined below the first obj line only); nosuch again. */
static const char usemtl_mesh[] =
    "v 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\n"
    "usemtl red # the red one\nv 0 0 2\nv 1 0 2\nv 0 1 2\nf 4 5 6\n"
    "usemtl nosuch\nv 0 0 3\nv 1 0 3\nv 0 1 3\nf 7 8 9\n"
    "usemtl   white  \nv 0 0 4\nv 1 0 4\nv 0 1 4\nf 10 11 12\n"
    "usemtl late\nv 0 0 5\nv 1 0 5\nv 0 1 5\nf 13 14 15\n"
    "usemtl nosuch\nv 0 0 6\nv 1 0 6\nv 0 1 6\nf 16 17 18\n";

/* Materials 0 white, 1 red, 2 late; the mesh placed twice, by white before late is
 * defined and by red after. */
static const char usemtl_scene[] =
    "camera 0 0 -5  0 0 0  0 1 0  40\n"
    "material white lambert 0.7 0.7 0.7\n"
    "material red lambert 0.7 0.1 0.1\n"
    "obj %s white\n"
    "material late lambert 0.1 0.1 0.7\n"
    "obj %s red\n"
    "light point 0 0 -5  10 10 10\n";

/* truth: the README's rule: a face takes the scene material its usemtl names when one of
 *   that name is defined above the obj line, else the obj line's: the first placement
 *   white, red, white, white, white, white (late is not yet defined), the second red,
 *   red, red, white, late, red.
 * tolerance: none. catches: usemtl ignored, an unknown name keeping the last material
 *   found instead of the obj line's, a material defined later found, the comment or the
 *   spaces taken into the name. Its three warnings on stderr are expected (the next test
 *   counts them). */
static void test_usemtl_materials(struct check *t)
{
    static const int expected[12] = {0, 1, 0, 0, 0, 0, 1, 1, 1, 0, 2, 1};
    struct collected c;
    REQUIRE(t, load_triangles(usemtl_scene, usemtl_mesh, &c) == 0 && c.n == 12);
    for (size_t i = 0; i < c.n; i++) {
        CHECK(t, c.v[i][0].z == (double)(i % 6 + 1)); /* the faces in the order written */
        CHECK(t, c.material[i] == expected[i]);
    }
}

/* How many times text occurs in the file name (0 when it cannot be read). */
static int occurrences(const char *name, const char *text)
{
    char *all = read_text_file(name);
    int n = 0;
    for (const char *at = all; at != NULL && (at = strstr(at, text)) != NULL; at++)
        n++;
    free(all);
    return n;
}

/* truth: the README: one warning for each usemtl name no material answers, per obj line
 *   (nosuch twice in one placement: one warning; late is found by the second placement);
 *   the exporters group triangles by material, so pbrt gets three meshes, the one of
 *   late's material (m2) holding only the fifth face, and Blender's script the same.
 * tolerance: none. catches: a warning per face, none at all, per-face materials lost on
 *   export (one mesh per obj line). */
static void test_usemtl_warnings_and_export(struct check *t)
{
    char text[TEXT_BYTES], args[TEXT_BYTES];
    write_text_file(scratch_mesh, usemtl_mesh);
    snprintf(text, sizeof text, usemtl_scene, base_name(scratch_mesh), base_name(scratch_mesh));
    write_text_file(scratch_scene, text);
    snprintf(args, sizeof args, "--format pbrt %s -o %s", scratch_scene, scratch_out);
    CHECK(t, photon_logged("export", args, scratch_log) == 0);
    CHECK(t, occurrences(scratch_log, "photon: warning: ") == 3);
    snprintf(text, sizeof text, "%s:10: usemtl 'nosuch': no material of that name above the "
             "obj line; its faces keep the obj line's 'white'", scratch_mesh);
    CHECK(t, occurrences(scratch_log, text) == 1);
    snprintf(text, sizeof text, "%s:10: usemtl 'nosuch': no material of that name above the "
             "obj line; its faces keep the obj line's 'red'", scratch_mesh);
    CHECK(t, occurrences(scratch_log, text) == 1);
    CHECK(t, occurrences(scratch_log, ":20: usemtl 'late'") == 1);
    CHECK(t, occurrences(scratch_out, "Shape \"trianglemesh\"") == 3);
    CHECK(t, file_contains(scratch_out, "NamedMaterial \"m2\"\n  Shape \"trianglemesh\"\n"
                                        "    \"point3 P\" [\n      0 0 5\n      1 0 5\n"
                                        "      0 1 5\n    ]\n"));
    char script[NAME_BYTES];
    temp_name(script, sizeof script, "import_obj", "out.py");
    snprintf(args, sizeof args, "--format blender %s -o %s", scratch_scene, script);
    CHECK(t, photon_logged("export", args, scratch_log) == 0);
    CHECK(t, file_contains(script, "mesh('mesh 2', M2, "));
    remove(script);
    remove(scratch_out);
    remove(scratch_log);
}

/* ---- bad input -------------------------------------------------------------------------- */

/* truth: each obj line below is wrong in one known way (line 3 of its scene), each usemtl
 *   line (line 4 of the mesh) too; the command refuses the first with "file:line:" and
 *   exit status 2, as every bad scene is.
 * tolerance: none. catches: a zero axis normalised to NaN, angles unbounded, numbers read
 *   outside the shared syntax, the words taken in any order, an empty usemtl skipped. */
static void test_bad_rotations(struct check *t)
{
    static const char *const bad[][2] = {
        {"rotate 0 0 0 90", "the rotation axis must not be zero"},
        {"rotate 0 0 1", "expected 4 numbers (rotation axis x y z, degrees), got 3"},
        {"rotate 0 0 1 400", "from -360 to 360 degrees"},
        {"rotate 0 0 1 -360.5", "from -360 to 360 degrees"},
        {"rotate 0 0 1 nan", "number 'nan' is not finite"},
        {"rotate 0 0 1e999 90", "number '1e999' is not finite"},
        {"rotate 0 0 1 0x10", "'0x10' is not a number"},
        {"rotate x 0 1 90", "'x' is not a number"},
        {"scale 2 rotate 0 0 1 90", "unexpected 'rotate'"},
        {"rotate 0 0 1 90 rotate 1 0 0 90", "unexpected 'rotate'"},
        {"rotate 0 0 1 90 translate 1 2 3 scale 2", "unexpected 'scale'"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char format[TEXT_BYTES];
        snprintf(format, sizeof format, CAMERA "obj %%s m %s\n", bad[i][0]);
        struct error err;
        struct scene *scene = load_with_mesh(format, UNIT_FACE, &err);
        int right = scene == NULL && err.line == 3 && strcmp(err.file, scratch_scene) == 0 &&
                    strncmp(err.message, "obj: ", 5) == 0 && strstr(err.message, bad[i][1]);
        if (!right)
            fprintf(stderr, "'%s': got %s:%d: %s\n", bad[i][0], err.file, err.line,
                    err.message);
        CHECK(t, right);
        scene_free(scene);
    }
    static const char *const empty[] = {"usemtl\n", "usemtl   # nothing\n"};
    for (size_t i = 0; i < 2; i++) {
        char mesh[TEXT_BYTES];
        snprintf(mesh, sizeof mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\n%sf 1 2 3\n", empty[i]);
        struct error err;
        CHECK(t, load_with_mesh(CAMERA "obj %s m\n", mesh, &err) == NULL && err.line == 4 &&
                     strcmp(err.file, scratch_mesh) == 0 &&
                     strstr(err.message, "usemtl: expected a material name") != NULL);
    }
    char text[TEXT_BYTES], args[TEXT_BYTES];
    write_text_file(scratch_mesh, UNIT_FACE);
    snprintf(text, sizeof text, CAMERA "obj %s m rotate 0 0 0 90\n", base_name(scratch_mesh));
    write_text_file(scratch_scene, text);
    snprintf(args, sizeof args, "--format pbrt %s -o %s", scratch_scene, scratch_out);
    CHECK(t, photon_logged("export", args, scratch_log) == 2 && !file_exists(scratch_out));
    snprintf(text, sizeof text, "%s:3: obj: the rotation axis must not be zero", scratch_scene);
    CHECK(t, file_contains(scratch_log, text));
    remove(scratch_log);
}

void test_import_obj(struct check *t)
{
    temp_name(scratch_scene, sizeof scratch_scene, "import_obj", "file.scene");
    temp_name(scratch_mesh, sizeof scratch_mesh, "import_obj", "mesh.obj");
    temp_name(scratch_out, sizeof scratch_out, "import_obj", "out.pbrt");
    temp_name(scratch_log, sizeof scratch_log, "import_obj", "out.log");
    RUN_TEST(t, test_rotation_closed_form);
    RUN_TEST(t, test_rotation_keeps_measures);
    RUN_TEST(t, test_usemtl_materials);
    RUN_TEST(t, test_usemtl_warnings_and_export);
    RUN_TEST(t, test_bad_rotations);
    remove(scratch_scene);
    remove(scratch_mesh);
}
