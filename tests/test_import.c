/*
 * tests/test_import.c -- the importers' readers: the NFF reader (scene/nff.c) on the
 * Standard Procedural Databases and on bad files, the OBJ reader (scene/obj.c), and the
 * scene keywords `nff` and `obj`. The shapes they make, the open cone and ear-clipped
 * polygons, are test_import_geom.c's; the obj line's rotate and OBJ's usemtl
 * test_import_obj.c's.
 *
 * Truths: the census of the SPD files kept in tests/data/spd/ (spd.h; test_spd.c checks
 * all 22); the light-power convention written out by hand; the same mesh or cone written
 * two ways (round trips through the readers); bad files refused on the right line.
 * Scratch files go to /tmp (files.h); tests/data/ and scenes/ are read from the top of
 * the repository, where the tests run.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../src/base/rng.h"
#include "../src/geom/polygon.h"
#include "../src/scene/nff.h"
#include "../src/scene/obj.h"
#include "files.h"
#include "spd.h"
#include "tests.h"

#define NAME_MAX_BYTES 256

/* Scratch files, all in one directory (/tmp), named by temp_name() in test_import(). */
static char scratch_nff[NAME_MAX_BYTES], scratch_obj[NAME_MAX_BYTES];
static char scratch_scene[NAME_MAX_BYTES], scratch_mesh[NAME_MAX_BYTES];

/* The file name without its directory: how a scene file in the same directory names it. */
static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash != NULL ? slash + 1 : path;
}

/* ---- NFF: the databases ---------------------------------------------------------------- */

/* truth: the SPD files' census (counted when the files were made, by a strict line-by-line
 *   reader that is not ours, and recounted by a separate script): balls-s3 820 spheres +
 *   1 quad (2 triangles); tree-s5 63 spheres + 63 cones + 1 quad, 7 lights; the head of
 *   gears-s3 a quad and a gear face of 144 vertices (142 triangles), 5 lights; views as
 *   printed.
 * tolerance: none, counts. catches: the one-line `c` swallowing the next entities, the
 *   polygon count formula broken, lights dropped, materials not shared. */
static void test_spd_counts(struct check *t)
{
    static const struct spd_census files[] = {
        {"balls-s3.nff", 820 + 2, 3, 2, SPD_BALLS},
        {"tree-s5.nff", 63 + 63 + 2, 7, 2, SPD_TREE},
        {"gears-s3-head.nff", 2 + 142, 5, 2, SPD_GEARS},
    };
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++)
        check_spd_census(t, SPD_DATA, &files[i]);
}

/* truth: a ray from balls-s3.nff's camera through the image centre meets the flake (the
 *   top sphere of radius 0.5 at the origin), nearer than the origin.
 * catches: the view's from and at swapped, the frame built from the wrong vectors. */
static void test_spd_view(struct check *t)
{
    struct error err;
    struct scene *scene = nff_load(SPD_DATA "/balls-s3.nff", &err);
    REQUIRE(t, scene != NULL);
    scene_finish(scene, 64, 64);
    struct hit h;
    CHECK(t, scene_intersect(scene, camera_ray(&scene->camera, 32, 32), INFINITY, &h));
    CHECK(t, h.t > 1.5 && h.t < vec3_length(scene->camera.from));
    scene_free(scene);
}

/* ---- NFF: conventions ------------------------------------------------------------------ */

#define VIEW "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 8 6\n"

static struct scene *load_nff_text(const char *text, struct error *err)
{
    write_text_file(scratch_nff, text);
    return nff_load(scratch_nff, err);
}

/* truth: the convention of nff.c written out: n = 3 lights, I = sqrt(3) / 6, and
 *   Phi = 4 pi^2 d^2 I colour with d the distance to `at` (to `from` for a light at `at`);
 *   so the irradiance at `at` facing the light, E = Phi / (4 pi d^2), is pi I colour, and a
 *   white Lambertian surface there has radiance E / pi = I colour. Lights before the view
 *   and a yon line are accepted.
 * tolerance: 1e-12 relative, a few roundings.
 * catches: n taken as lights seen so far, d measured from the wrong point, pi lost. */
static void test_nff_light_power(struct check *t)
{
    struct error err;
    struct scene *scene = load_nff_text("l 0 3 4\n" "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\n"
                                        "angle 40\nhither 1\nyon 1000\nresolution 8 6\n"
                                        "l 1 1 1 0.5 0.25 1\nl 0 0 0\n", &err);
    REQUIRE(t, scene != NULL);
    CHECK(t, scene->n_lights == 3 && scene->width == 8 && scene->height == 6);
    double intensity = sqrt(3.0) / 6.0;
    static const double d2[3] = {25, 3, 25}, colour[3][3] = {{1, 1, 1}, {0.5, 0.25, 1},
                                                             {1, 1, 1}};
    for (int i = 0; i < 3; i++) {
        const struct light *l = &scene->lights[i];
        double phi = 4 * PI * PI * d2[i] * intensity;
        CHECK(t, l->kind == LIGHT_POINT);
        CHECK_CLOSE(t, l->power.x, phi * colour[i][0], 1e-12 * phi);
        CHECK_CLOSE(t, l->power.y, phi * colour[i][1], 1e-12 * phi);
        CHECK_CLOSE(t, l->power.z, phi * colour[i][2], 1e-12 * phi);
        struct light_sample ls;
        if (i < 2 && light_sample(l, vec3(0, 0, 0), vec3(0, 1, 0), 0.5, 0.5, &ls))
            CHECK_CLOSE(t, ls.li.x, PI * intensity * colour[i][0], 1e-12);
    }
    scene_free(scene);
}

/* truth: nff.c's mapping of f r g b Kd Ks Shine T ior, case by case, and kd + ks <= 1 in
 *   doubles for 200 random f lines with Kd, Ks up to 2 and colours up to 1.5.
 * tolerance: exact where no arithmetic is done, 1e-15 where a product is.
 * catches: T and Ks tested in the wrong order, the Kd + Ks scaling forgotten, colours
 *   over 1 passed on, equal f lines not shared. */
static void test_nff_materials(struct check *t)
{
    static char text[40000];
    int length = sprintf(text, "%s", VIEW "f 0.5 0.6 0.7 0.8 0 100000 0 0\ns 0 0 0 1\n"
                         "f 1 0.5 0.25 0.3 0.6 20 0 0\ns 3 0 0 1\n"
                         "f 1 1 1 0.7 0.7 11 0 1\ns 6 0 0 1\n"
                         "f 1 1 1 0.1 0.1 100 0.9 1.5\ns 9 0 0 1\n"
                         "f 2 2 2 0.9 0 0 0 0\ns 12 0 0 1\n"
                         "f 0.5 0.6 0.7 0.8 0 100000 0 0\ns 15 0 0 1\n");
    struct rng rng = rng_stream(13, STREAM_TEST, 0, 0);
    for (int i = 0; i < 200; i++)
        length += sprintf(text + length, "f %.17g %.17g %.17g %.17g %.17g 10 0 0\n",
                          1.5 * rng_uniform(&rng), 1.5 * rng_uniform(&rng),
                          1.5 * rng_uniform(&rng), 2 * rng_uniform(&rng),
                          2 * rng_uniform(&rng));
    struct error err;
    struct scene *scene = load_nff_text(text, &err);
    REQUIRE(t, scene != NULL);
    CHECK(t, scene->n_materials == 5 + 200);
    const struct material *m = scene->materials;
    CHECK(t, m[0].kind == MATERIAL_LAMBERT && m[0].rho.x == 0.5 * 0.8 && m[0].rho.z == 0.7 * 0.8);
    CHECK(t, m[1].kind == MATERIAL_PHONG && m[1].rho.y == 0.3 * 0.5 && m[1].rho_s.x == 0.6 &&
                 m[1].exponent == 20);
    CHECK(t, m[2].kind == MATERIAL_PHONG);
    CHECK_CLOSE(t, m[2].rho.x, 0.5, 1e-15);
    CHECK_CLOSE(t, m[2].rho_s.x, 0.5, 1e-15);
    CHECK(t, m[3].kind == MATERIAL_GLASS && m[3].ior == 1.5);
    CHECK(t, m[4].kind == MATERIAL_LAMBERT && m[4].rho.x == 0.9);
    for (size_t i = 0; i < scene->n_materials; i++) {
        struct vec3 sum = vec3_add(scene->materials[i].rho, scene->materials[i].rho_s);
        CHECK(t, vec3_max_component(sum) <= 1 && scene->materials[i].rho.x >= 0);
    }
    scene_finish(scene, 8, 6); /* the sixth sphere, the first f again, shares material 0 */
    struct hit h;
    CHECK(t, scene_intersect(scene, make_ray(vec3(15, 0, -5), vec3(0, 0, 1)), INFINITY, &h));
    CHECK(t, geometry_primitive_count(scene->geometry) == 6 && h.prim == 5 && h.material == 0);
    scene_free(scene);
}

/* Hits of a fixed fan of rays through two scenes must be identical. */
static int same_hits(struct scene *a, struct scene *b, struct vec3 eye, struct vec3 target)
{
    int same = 1, n_hits = 0;
    for (int i = 0; i < 400; i++) {
        struct vec3 aim = vec3_add(target, vec3((i % 20 - 9.5) * 0.12, (i / 20 - 9.5) * 0.12, 0));
        struct ray ray = make_ray(eye, vec3_normalize(vec3_sub(aim, eye)));
        struct hit ha, hb;
        int hit_a = scene_intersect(a, ray, INFINITY, &ha);
        int hit_b = scene_intersect(b, ray, INFINITY, &hb);
        same = same && hit_a == hit_b;
        if (hit_a && hit_b) {
            n_hits++;
            same = same && ha.t == hb.t && ha.ng.x == hb.ng.x && ha.ns.y == hb.ns.y &&
                   ha.u == hb.u && ha.v == hb.v;
        }
    }
    return same && n_hits > 50;
}

/* truth: round trip, the same cone in NFF's two `c` layouts (plus comments, blank lines
 *   and CRLF) gives bit-identical hits; the inside-only cone (negative radii) the same
 *   points with the normal reversed.
 * catches: the three-line layout misread, CR taken into a number, the sign ignored. */
static void test_nff_cone_layouts(struct check *t)
{
    struct error err;
    struct scene *one = load_nff_text(VIEW "f 1 1 1 1 0 0 0 0\nc 0 0 0 1 0 0.5 1 0.3\n", &err);
    struct scene *three = load_nff_text(VIEW "f 1 1 1 1 0 0 0 0\r\n# a comment\r\nc\r\n"
                                        "0 0 0 1 # base\r\n\r\n0 0.5 1 0.3\r\n", &err);
    struct scene *inside = load_nff_text(VIEW "f 1 1 1 1 0 0 0 0\nc 0 0 0 -1 0 0.5 1 -0.3\n",
                                         &err);
    CHECK(t, one != NULL && three != NULL && inside != NULL);
    if (one != NULL && three != NULL && inside != NULL) {
        scene_finish(one, 8, 6);
        scene_finish(three, 8, 6);
        scene_finish(inside, 8, 6);
        CHECK(t, same_hits(one, three, vec3(0.3, 0.2, -5), vec3(0, 0.2, 0.5)));
        struct ray ray = make_ray(vec3(0, -0.6, -5), vec3(0, 0, 1));
        struct hit a, b;
        CHECK(t, scene_intersect(one, ray, INFINITY, &a) && scene_intersect(inside, ray,
                                                                             INFINITY, &b));
        CHECK(t, a.t == b.t && a.ng.x == -b.ng.x && a.ng.y == -b.ng.y && a.ng.z == -b.ng.z);
    }
    scene_free(one);
    scene_free(three);
    scene_free(inside);
}

/* ---- NFF and OBJ: bad input ------------------------------------------------------------ */

struct bad_input {
    const char *text;    /* the file's contents                     */
    int line;            /* the line the error must name            */
    const char *message; /* a part of the message it must contain   */
};

#define F1 "f 1 1 1 1 0 0 0 0\n" /* line 8 after VIEW */

static const struct bad_input bad_nff[] = {
    {"", 0, "no 'v'"},
    {F1 "s 0 0 0 1\n", 0, "no 'v'"},
    {VIEW "s 0 0 0 1\n", 8, "before any 'f'"},
    {VIEW F1 "s 0 0 0\n", 9, "expected 4 numbers"},
    {VIEW F1 "s 0 0 0 nan\n", 9, "not finite"},
    {VIEW F1 "s 0 0 0 -inf\n", 9, "not finite"},
    {VIEW F1 "s 0 0 0 1x\n", 9, "not a number"},
    {VIEW F1 "s 0 0 0 -1\n", 9, "radius must be positive"},
    {VIEW F1 "s 0 0 0 1 2\n", 9, "unexpected '2'"},
    {VIEW F1 "s 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17\n", 9, "more than 16 words"},
    {VIEW F1 "p 0\n", 9, "from 3 to 10000"},
    {VIEW F1 "p 2\n0 0 0\n1 0 0\n", 9, "from 3 to 10000"},
    {VIEW F1 "p 10001\n", 9, "from 3 to 10000"},
    {VIEW F1 "p 1e300\n", 9, "from 3 to 10000"},
    {VIEW F1 "p 3.5\n", 9, "whole number"},
    {VIEW F1 "p 3\n0 0 0\n1 0 0\n", 11, "ends where vertex 3 of 3"},
    {VIEW F1 "p 3\n0 0 0\n1 0\n0 1 0\n", 11, "expected 3 numbers"},
    {VIEW F1 "p 3\n0 0 0\n1 0 0 # c\n\n0 1 0 1\n", 13, "unexpected '1'"},
    {VIEW F1 "p 4\n0 0 0\n1 0 0\n1 1 0\ns 0 0 0 1\n", 13, "'s' is not a number"},
    {VIEW F1 "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 0\n", 12, "normal of vertex 3"},
    {VIEW F1 "pp 3\n0 0 0 0 0 1\n1 0 0\n", 11, "expected 6 numbers"},
    {VIEW F1 "c 0 0 0 1 0 0 1\n", 9, "expected 8 numbers"},
    {VIEW F1 "c\n0 0 0 1\n", 10, "ends where the apex line"},
    {VIEW F1 "c\n0 0 0 1 0 0 1 1\n", 10, "unexpected '0'"},
    {VIEW F1 "c 0 0 0 1 0 0 0 1\n", 9, "coincide"},
    {VIEW F1 "c 0 0 0 1 0 0 1 -1\n", 9, "opposite signs"},
    {VIEW F1 "c 0 0 0 0 0 0 1 0\n", 9, "both zero"},
    {VIEW "f 1 1 1 0.1 0.1 1 0.5 0\n", 8, "index of refraction"},
    {VIEW "f 1 1 1 -1 0 0 0 0\n", 8, "negative"},
    {VIEW "f 1 1 1 1 0 0 0\n", 8, "expected 8 numbers"},
    {VIEW "b 0 0\n", 8, "expected 3 numbers"},
    {VIEW "b -1 0 0\n", 8, "negative"},
    {VIEW "l 0 0 0 1\n", 8, "expected 6 numbers"},
    {VIEW "l 0 0 0 1 -1 1\n", 8, "negative"},
    {VIEW "l 1e200 0 0\n", 8, "overflows"},
    {VIEW "l 1e16 0 0\n", 8, "total power would exceed 1e+30 W"}, /* 2e33 W: scene.h */
    {VIEW "tpp 3\n", 8, "unknown keyword 'tpp'"},
    {VIEW "v\n", 8, "a second view"},
    {"v\nfrom 0 0 -5\nat 0 0 0\nangle 40\n", 4, "expected the line 'up'"},
    {"v\nfrom 0 0 -5\n", 2, "ends where the line 'at'"},
    {"v 1\n", 1, "unexpected '1'"},
    {"v\nfrom 0 0 0\nat 0 0 0\nup 0 1 0\n", 4, "'at' equals 'from'"},
    {"v\nfrom 0 0 -5\nat 0 0 0\nup 0 0 1\n", 4, "parallel"},
    {"v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 180\n", 5, "(0, 180)"},
    {"v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 0 8\n", 7,
     "resolution"},
    {"v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 8.5 8\n", 7,
     "resolution"},
    {"v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 40000 8\n", 7,
     "resolution"},
    {"\x01\x02\xff\xfe garbage\n", 1, "unknown keyword"},
    {"\n\n   \t\n# only comments\n", 0, "no 'v'"},
};

#define THREE_V "v 0 0 0\nv 1 0 0\nv 0 1 0\n" /* lines 1-3 */

static const struct bad_input bad_obj[] = {
    {"", 0, "no faces"},
    {THREE_V "# no face\n", 0, "no faces"},
    {"f 1 2 3\n", 1, "vertex index 1 is out of range (0 defined above)"},
    {THREE_V "f 1 2 4\n", 4, "vertex index 4 is out of range"},
    {THREE_V "f 1 2 0\n", 4, "vertex index 0"},
    {THREE_V "f 1 2 -4\n", 4, "vertex index -4"},
    {THREE_V "f 3 2 1\nv 1 1 1\nf 1 2 5\n", 6, "vertex index 5"},
    {THREE_V "f 99999999999999999999 2 3\n", 4, "out of range"},
    {THREE_V "f -99999999999999999999 2 3\n", 4, "out of range"},
    {THREE_V "f 1 2\n", 4, "at least 3 corners, got 2"},
    {THREE_V "f\n", 4, "at least 3 corners, got 0"},
    {THREE_V "f 1 2 x\n", 4, "whole number"},
    {THREE_V "f 1 2 3.5\n", 4, "whole number"},
    {THREE_V "f 1 2 3 # ok\nf 1 2 +\n", 5, "whole number"},
    {THREE_V "f 1/1 2 3\n", 4, "texture index 1 is out of range"},
    {THREE_V "f 1//1 2//1 3//1\n", 4, "normal index 1 is out of range"},
    {THREE_V "f 1/ 2 3\n", 4, "texture index must be"},
    {THREE_V "vt 0 0\nvn 0 0 1\nf 1/1/1/1 2 3\n", 6, "a corner is"},
    {THREE_V "vn 0 0 1\nf 1//1 2//1 3//\n", 5, "normal index must be"},
    {"v 0 0\n", 1, "expected 3 numbers"},
    {"v 0 0 nan\n", 1, "not finite"},
    {"v 0 0 inf\n", 1, "not finite"},
    {"v 0 0 1e999\n", 1, "not finite"},
    {"v 1 2 3 4 5 6 7 8\n", 1, "more than 7 numbers"},
    {"v 1 2 three\n", 1, "'three' is not a number"},
    {"vn 0 0 0\n", 1, "normal is zero"},
    {"vn 0 0\n", 1, "expected 3 numbers"},
    {"vn 1 0 0 1\n", 1, "more than 3 numbers"},
    {"vt\n", 1, "expected 1 numbers"},
    {"vt 1 2 3 4\n", 1, "more than 3 numbers"},
    {"curv 0 1 2\n", 1, "unknown keyword 'curv'"},
    {THREE_V "f 1 2 3\ncstype bspline\n", 5, "unknown keyword 'cstype'"},
    {"\x01\x02\xff\xfe garbage\n", 1, "unknown keyword"},
    {"v 1e300 0 0\n", 1, "placed vertex is not finite"}, /* scale 1e10 below */
};

/* A new scene with one grey Lambertian material, index 0, for OBJ meshes. */
static struct scene *material_scene(void)
{
    struct scene *scene = scene_create();
    struct material m;
    memset(&m, 0, sizeof m);
    m.kind = MATERIAL_LAMBERT;
    m.rho = vec3(0.5, 0.5, 0.5);
    scene_add_material(scene, &m);
    return scene;
}

/* Loads text as an NFF (obj = 0) or OBJ (obj = 1) file; checks it is refused on the right
 * line with the right words. Returns whether it was. */
static int refused_as_expected(const struct bad_input *bad, int obj, double scale)
{
    struct error err;
    memset(&err, 0, sizeof err);
    const char *path = obj ? scratch_obj : scratch_nff;
    write_text_file(path, bad->text);
    int refused;
    if (obj) {
        struct scene *scene = material_scene();
        struct obj_placement place = obj_unmoved(0);
        place.scale = scale;
        refused = obj_import(scene, path, &place, &err) < 0;
        scene_free(scene);
    } else {
        struct scene *scene = nff_load(path, &err);
        refused = scene == NULL;
        scene_free(scene);
    }
    int right = refused && err.line == bad->line && strstr(err.message, bad->message) != NULL &&
                strcmp(err.file, path) == 0;
    if (!right)
        fprintf(stderr, "%s case '%.30s...': got %s:%d: %s\n", obj ? "OBJ" : "NFF", bad->text,
                err.file, err.line, err.message);
    return right;
}

/* truth: each file above is wrong in one known way on one known line (0: no line, e.g.
 *   a missing view at the end of the file); plus a directory, a missing file and a line
 *   too long. Run under the sanitizers (make check), "nothing crashed" is checked too.
 * tolerance: none: the line number and the gist of the message must be right.
 * catches: errors on the wrong line, NaN or Inf accepted, counts and indices unchecked
 *   (reads out of bounds), truncated entities swallowing the next, crashes on garbage. */
static void test_bad_files_are_refused(struct check *t)
{
    for (size_t i = 0; i < sizeof bad_nff / sizeof bad_nff[0]; i++)
        CHECK(t, refused_as_expected(&bad_nff[i], 0, 1.0));
    size_t n_obj = sizeof bad_obj / sizeof bad_obj[0];
    for (size_t i = 0; i < n_obj; i++)
        CHECK(t, refused_as_expected(&bad_obj[i], 1, i + 1 == n_obj ? 1e10 : 1.0));
    static char long_text[70000];
    memset(long_text, '1', sizeof long_text - 2);
    long_text[0] = 'v';
    long_text[1] = ' ';
    long_text[sizeof long_text - 2] = '\n';
    struct bad_input too_long = {long_text, 1, ""};
    CHECK(t, refused_as_expected(&too_long, 0, 1.0));
    CHECK(t, refused_as_expected(&too_long, 1, 1.0));
    struct error err;
    struct scene *scene = material_scene();
    struct obj_placement place = obj_unmoved(0);
    CHECK(t, nff_load("scenes", &err) == NULL && strstr(err.message, "directory") != NULL);
    CHECK(t, obj_import(scene, "scenes", &place, &err) < 0 && strstr(err.message, "directory"));
    CHECK(t, nff_load("/nonexistent/a.nff", &err) == NULL && strstr(err.message, "cannot open"));
    CHECK(t, obj_import(scene, "/nonexistent/a.obj", &place, &err) < 0 && err.line == 0);
    scene_free(scene);
}

/* truth: scene.h's limit on the lights' total power, MAX_LIGHT_POWER = 1e30 W per
 *   channel: an OBJ face of an emitting material is an area light of power pi Le A, so
 *   with Le = 1 a right triangle of legs 7e14 (pi 2.45e29 = 7.7e29 W) is taken, and a
 *   second one (1.54e30 W in all) is refused on its own line.
 * tolerance: none.
 * catches: a mesh's emitting faces left out of the sum, the refusal without its line. */
static void test_emitting_mesh_power_limit(struct check *t)
{
    struct scene *scene = scene_create();
    struct material m;
    memset(&m, 0, sizeof m);
    m.kind = MATERIAL_LAMBERT;
    m.emission = vec3(1, 1, 1);
    scene_add_material(scene, &m);
    write_text_file(scratch_obj, "v 0 0 0\nv 7e14 0 0\nv 0 7e14 0\nf 1 2 3\nf 1 2 3\n");
    struct obj_placement place = obj_unmoved(0);
    struct error err;
    memset(&err, 0, sizeof err);
    CHECK(t, obj_import(scene, scratch_obj, &place, &err) < 0);
    CHECK(t, scene->n_lights == 1 && err.line == 5 && strstr(err.message, "total power"));
    scene_free(scene);
}

/* truth: a face of 10,001 corners is refused, one of 10,000 accepted as 9,998 triangles
 *   (the documented limit, exactly). catches: an off-by-one at the limit, scratch overrun. */
static void test_polygon_limit(struct check *t)
{
    for (int n = MAX_POLYGON_VERTICES; n <= MAX_POLYGON_VERTICES + 1; n++) {
        FILE *f = fopen(scratch_obj, "wb");
        REQUIRE(t, f != NULL);
        for (int i = 0; i < n; i++)
            fprintf(f, "v %.17g %.17g 0\n", cos(2 * PI * i / n), sin(2 * PI * i / n));
        fputs("f", f);
        for (int i = 1; i <= n; i++)
            fprintf(f, " %d", i);
        fputs("\n", f);
        fclose(f);
        struct scene *scene = material_scene();
        struct obj_placement place = obj_unmoved(0);
        struct error err;
        int status = obj_import(scene, scratch_obj, &place, &err);
        CHECK(t, n == MAX_POLYGON_VERTICES
                     ? status == 0 && geometry_primitive_count(scene->geometry) == (size_t)n - 2
                     : status < 0 && err.line == n + 1 && strstr(err.message, "more than"));
        scene_free(scene);
    }
}

/* ---- OBJ and the scene keywords ------------------------------------------------------- */

/* A scene with one material, a camera and the OBJ text placed by (scale, shift). */
static struct scene *load_obj_text(const char *text, double scale, struct vec3 shift)
{
    struct scene *scene = material_scene();
    struct obj_placement place = obj_unmoved(0);
    place.scale = scale;
    place.translation = shift;
    struct error err;
    write_text_file(scratch_obj, text);
    if (obj_import(scene, scratch_obj, &place, &err) < 0) {
        scene_free(scene);
        return NULL;
    }
    scene->camera.from = vec3(0, 0, 5);
    scene->camera.up = vec3(0, 1, 0);
    scene->camera.fov = 40;
    scene_finish(scene, 8, 8);
    return scene;
}

#define PYRAMID_V "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nv 0 0 1.5\n" \
                  "vn 0 -0.8 0.6\nvn 0.8 0 0.6\nvn 0 0.8 0.6\nvn -0.8 0 0.6\nvn 0 0 1\nvt 0 0\n"

/* truth: round trip, the same pyramid written with positive indices and with negative
 *   ones (and v/vt/vn corners, ignored statements) gives bit-identical hits.
 * catches: a negative index off by one, normals attached to the wrong corner. */
static void test_obj_negative_indices(struct check *t)
{
    struct scene *positive = load_obj_text(PYRAMID_V "f 1//1 2//2 5//5\nf 2//2 3//3 5//5\n"
                                           "f 3//3 4//4 5//5\nf 4//4 1//1 5//5\nf 4 3 2 1\n",
                                           1, vec3_zero());
    struct scene *negative = load_obj_text(PYRAMID_V "o pyramid\ng sides\ns 1\n"
                                           "mtllib x.mtl\nl 1 2\np 1\n"
                                           "f -5/1/-5 -4/-1/-4 -1//-1\nf -4//-4 -3//-3 -1//-1\n"
                                           "f -3//-3 -2//-2 -1/1/-1\nf -2//-2 -5//-5 -1//-1\n"
                                           "f -2 -3 -4 -5\n", 1, vec3_zero());
    CHECK(t, positive != NULL && negative != NULL);
    if (positive != NULL && negative != NULL) {
        CHECK(t, geometry_primitive_count(positive->geometry) == 6);
        CHECK(t, geometry_primitive_count(negative->geometry) == 6);
        CHECK(t, same_hits(positive, negative, vec3(0.3, -0.2, 5), vec3(0, 0, 0.4)));
        CHECK(t, same_hits(positive, negative, vec3(0.3, -0.2, -5), vec3(0, 0, 0.4)));
    }
    scene_free(positive);
    scene_free(negative);
}

/* truth: closed form, vertex p placed at 2 p + (1, 2, 3): the triangle (0,0,0) (1,0,0)
 *   (0,1,0) becomes (1,2,3) (3,2,3) (1,4,3), where x >= 1, y >= 2, x + y <= 5; rays down
 *   -z at (1.5, 2.5) and (2.9, 2.05) hit it at z = 3, one at (2.1, 3.1) misses.
 * catches: scale and translation swapped or applied in the wrong order. */
static void test_obj_placement(struct check *t)
{
    struct scene *scene = load_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 2,
                                        vec3(1, 2, 3));
    REQUIRE(t, scene != NULL);
    struct hit h;
    CHECK(t, scene_intersect(scene, make_ray(vec3(1.5, 2.5, 10), vec3(0, 0, -1)), INFINITY, &h));
    CHECK_CLOSE(t, h.t, 7.0, 1e-12);
    CHECK(t, scene_intersect(scene, make_ray(vec3(2.9, 2.05, 10), vec3(0, 0, -1)), INFINITY,
                             &h));
    CHECK(t, !scene_intersect(scene, make_ray(vec3(2.1, 3.1, 10), vec3(0, 0, -1)), INFINITY,
                              &h));
    scene_free(scene);
}

/* truth: the scene keywords `obj` (with scale and translate) and `nff` read the same as the
 *   importers called directly (closed form as in test_obj_placement); the shipped examples
 *   load with the counts their files give (30 and 19 primitives).
 * catches: paths not made relative to the scene file, the NFF view not taken. */
static void test_scene_keywords(struct check *t)
{
    struct error err;
    char text[1024];
    write_text_file(scratch_mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write_text_file(scratch_nff, VIEW F1 "s 0 0 3 1\nl 0 5 0\n");
    sprintf(text, "material m lambert 0.5 0.5 0.5\nnff %s\nobj %s m scale 2 translate 1 2 3\n",
            base_name(scratch_nff), base_name(scratch_mesh));
    write_text_file(scratch_scene, text);
    struct scene *scene = scene_load(scratch_scene, &err);
    CHECK(t, scene != NULL);
    if (scene != NULL) {
        CHECK(t, scene->has_camera && scene->width == 8 && scene->height == 6);
        CHECK(t, geometry_primitive_count(scene->geometry) == 2 && scene->n_lights == 1);
        scene_finish(scene, 8, 6);
        struct hit h;
        CHECK(t, scene_intersect(scene, make_ray(vec3(1.5, 2.5, 10), vec3(0, 0, -1)), INFINITY,
                                 &h) && fabs(h.t - 7) < 1e-12 && h.material == 0);
        scene_free(scene);
    }
    struct scene *example = scene_load("scenes/obj-example.scene", &err);
    struct scene *every = nff_load("scenes/every-primitive.nff", &err);
    CHECK(t, example != NULL && geometry_primitive_count(example->geometry) == 30);
    CHECK(t, every != NULL && geometry_primitive_count(every->geometry) == 19 &&
                 every->n_lights == 2 && every->n_materials == 8);
    scene_free(example);
    scene_free(every);
}

/* A scene file wrong in one known way; %s in it names the scratch NFF or OBJ file. */
struct bad_keyword {
    const char *format;
    int names_nff;       /* whether %s is the NFF file (else the OBJ mesh)      */
    int line;            /* the line the error must name                        */
    const char *message; /* a part of the message                               */
    int in_import;       /* whether the error must name the imported file       */
};

/* truth: each scene file below is wrong in one known way; an error inside an imported file
 *   names that file and its line, not the scene file's.
 * catches: options misparsed, errors blamed on the wrong file or line. */
static void test_scene_keyword_errors(struct check *t)
{
    static const struct bad_keyword bad[] = {
        {"material m lambert 1 1 1\nobj %s q\n", 0, 2, "undefined material", 0},
        {"material m lambert 1 1 1\nobj %s m scale 0\n", 0, 2, "positive", 0},
        {"material m lambert 1 1 1\nobj %s m translate 1 2\n", 0, 2, "expected 3 numbers", 0},
        {"material m lambert 1 1 1\nobj %s m spin 1\n", 0, 2, "unexpected 'spin'", 0},
        {"nff\n", 1, 1, "expected a file name", 0},
        {"nff %s extra\n", 1, 1, "unexpected 'extra'", 0},
        {"nff %s\n", 1, 9, "radius must be positive", 1},
        {"material m lambert 1 1 1\nobj %s m\n", 1, 1, "v: expected 3 numbers", 1},
    };
    write_text_file(scratch_mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write_text_file(scratch_nff, VIEW F1 "s 0 0 3 -1\n");
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char text[1024];
        const char *import = bad[i].names_nff ? scratch_nff : scratch_mesh;
        sprintf(text, bad[i].format, base_name(import));
        write_text_file(scratch_scene, text);
        struct error err;
        CHECK(t, scene_load(scratch_scene, &err) == NULL && err.line == bad[i].line &&
                     strstr(err.message, bad[i].message) != NULL);
        CHECK(t, strcmp(err.file, bad[i].in_import ? import : scratch_scene) == 0);
    }
    char missing[1024];
    sprintf(missing, "material m lambert 1 1 1\nobj %s.none m\n", base_name(scratch_mesh));
    write_text_file(scratch_scene, missing);
    struct error err;
    CHECK(t, scene_load(scratch_scene, &err) == NULL && err.line == 2 &&
                 strstr(err.message, "obj: cannot open") != NULL);
    CHECK(t, strcmp(err.file, scratch_scene) == 0); /* the line that names the mesh */
}

void test_import(struct check *t)
{
    temp_name(scratch_nff, sizeof scratch_nff, "import", "file.nff");
    temp_name(scratch_obj, sizeof scratch_obj, "import", "file.obj");
    temp_name(scratch_scene, sizeof scratch_scene, "import", "file.scene");
    temp_name(scratch_mesh, sizeof scratch_mesh, "import", "mesh.obj");
    RUN_TEST(t, test_spd_counts);
    RUN_TEST(t, test_spd_view);
    RUN_TEST(t, test_nff_light_power);
    RUN_TEST(t, test_nff_materials);
    RUN_TEST(t, test_nff_cone_layouts);
    RUN_TEST(t, test_bad_files_are_refused);
    RUN_TEST(t, test_emitting_mesh_power_limit);
    RUN_TEST(t, test_polygon_limit);
    RUN_TEST(t, test_obj_negative_indices);
    RUN_TEST(t, test_obj_placement);
    RUN_TEST(t, test_scene_keywords);
    RUN_TEST(t, test_scene_keyword_errors);
    remove(scratch_nff);
    remove(scratch_obj);
    remove(scratch_scene);
    remove(scratch_mesh);
}
