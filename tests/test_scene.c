/*
 * tests/test_scene.c -- the scene room: the parser, its errors, the camera, light
 * sampling against closed-form irradiance, and the optics of smooth surfaces.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/hash.h"
#include "../src/base/rng.h"
#include "../src/image/image.h"
#include "../src/scene/optics.h"
#include "../src/scene/scene.h"
#include "files.h"
#include "tests.h"
#include "truths.h"

/* truth: the default scene as the issue specifies it: 10 wall triangles, 1 light quad,
 *   2 spheres; 3 named materials plus the light's; one quad light of radiance (17, 12, 4)
 *   facing down; camera and size as written.
 * catches: keywords silently skipped, the quad's corners taken in the wrong order (the
 *   light would face up), the light's emission lost. */
static void test_cornell_scene_loads(struct check *t)
{
    struct error err;
    struct scene *scene = scene_load("scenes/cornell.scene", &err);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    scene_finish(scene, scene->width, scene->height);
    CHECK(t, scene->width == 256 && scene->height == 256);
    CHECK(t, geometry_primitive_count(scene->geometry) == 13);
    CHECK(t, scene->n_materials == 4 && scene->n_lights == 1);
    const struct light *l = &scene->lights[0];
    CHECK(t, l->kind == LIGHT_QUAD && l->radiance.x == 17 && l->radiance.z == 4);
    CHECK(t, vec3_cross(l->e1, l->e2).y < 0);
    CHECK(t, scene->light_of_prim[l->prim] == 0);
    CHECK(t, scene->camera.fov == 39.3077 && scene->camera.from.z == -800);
    scene_free(scene);
}

/* truth: README's table of shipped scenes, as written there: each loads, and has the
 *   number of lights and primitives it is described with (a procedural object is one).
 * catches: a scene broken by a format change, an include that no longer resolves, an
 *   object silently lost. */
static void test_shipped_scenes_load(struct check *t)
{
    static const struct {
        const char *path;
        size_t lights;
        size_t primitives;
    } shipped[] = {
        {"scenes/cornell.scene", 1, 13},
        {"scenes/cornell-1e-3.scene", 1, 13},
        {"scenes/cornell-1e3.scene", 1, 13},
        {"scenes/cornell-specular.scene", 1, 13},
        {"scenes/ppm-box.scene", 2, 104},      /* 10 walls, 2 lights, 2 lenses, 8 shroud
                                                  quads, 2 balls, 80 facets              */
        {"scenes/analytic/point-in-sphere.scene", 1, 1},
        {"scenes/sphereflake.scene", 3, 3},   /* floor quad, flake, light sphere; the
                                                 sky (a background) is a light too   */
        {"scenes/sphereflake-6.scene", 3, 3},
        {"scenes/landscape.scene", 2, 2209},  /* heightfield, lens of 2208 facets; sky */
        {"scenes/desk.scene", 2, 10912},      /* 29 quads, flake, 2 light spheres,
                                                 glass 8576 and liquid 2304 triangles */
        {"scenes/obj-example.scene", 3, 0},   /* counted below; the sky            */
        {"scenes/every-primitive.nff", 3, 0},
    };
    for (size_t i = 0; i < sizeof shipped / sizeof shipped[0]; i++) {
        struct error err;
        struct scene *scene = scene_load(shipped[i].path, &err);
        CHECK(t, scene != NULL);
        if (scene == NULL) {
            error_print(&err);
            continue;
        }
        scene_finish(scene, scene->width, scene->height);
        CHECK(t, scene->n_lights == shipped[i].lights);
        size_t primitives = geometry_primitive_count(scene->geometry);
        CHECK(t, shipped[i].primitives == 0 ? primitives > 2
                                            : primitives == shipped[i].primitives);
        scene_free(scene);
    }
}

struct bad_scene {
    const char *text;     /* the file's contents                     */
    int line;             /* the line the error must name            */
    const char *message;  /* a part of the message it must contain   */
};

/* truth: each file below is wrong in one known way on one known line.
 * tolerance: none: the line number and the gist of the message must be right.
 * catches: errors reported on the wrong line, NaN or Inf accepted, limits unchecked,
 *   crashes on empty or binary input, undefined names accepted. */
static void test_bad_scenes_are_refused(struct check *t)
{
    static const struct bad_scene cases[] = {
        {"camera 0 0 0 0 0 1 0 1 0 40\nfrobnicate 1 2\n", 2, "unknown keyword"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nsphere 0 0 1\n", 2, "expected 4 numbers"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nsphere 0 0 1 nan m\n", 2, "not finite"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nsphere 0 0 1 inf m\n", 2, "not finite"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nsphere 0 0 1 0x m\n", 2, "not a number"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nsphere 0 0 1 1 nosuch\n", 2, "undefined material"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\nsphere 0 0 1 -1 m\n", 3,
         "radius must be positive"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\nsphere 0 0 1 1 m extra\n", 3,
         "unexpected 'extra'"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 2 1 1\n", 2, "[0, 1]"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\nmaterial m mirror 1 1 1\n", 3,
         "already defined"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m plastic 1\n", 2, "unknown kind"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial g glass -1.5\n", 2, "positive"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial g glass 1.5 1.2 1 1\n", 2, "[0, 1]"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial g glass 1.5 1 1\n", 2, "expected 3 numbers"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nimage 0 10\n", 2, "whole numbers"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nimage 100000 10\n", 2, "whole numbers"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nimage 10.5 10\n", 2, "whole numbers"},
        {"camera 0 0 0 0 0 0 0 1 0 40\n", 1, "look-at point equals"},
        {"camera 0 0 0 0 1 0 0 1 0 40\n", 1, "parallel"},
        {"camera 0 0 0 0 0 1 0 1 0 180\n", 1, "field of view"},
        {"camera 0 0 0 0 0 1 0 1 0 40 aperture -1 focus 2\n", 1, "at least 0"},
        {"camera 0 0 0 0 0 1 0 1 0 40 aperture 0.1 focus 0\n", 1, "above 0"},
        {"camera 0 0 0 0 0 1 0 1 0 40 aperture 0.1\n", 1, "expected 'focus DISTANCE'"},
        {"camera 0 0 0 0 0 1 0 1 0 40 lens 0.1 focus 2\n", 1, "unexpected 'lens'"},
        {"camera 0 0 0 0 0 1 0 1 0 40 aperture 0.1 focus 2 3\n", 1, "unexpected '3'"},
        {"camera 0 0 0 0 0 1 0 1 0 40 aperture 1e13 focus 2\n", 1, "2^40"},
        {"camera 0 0 -5 0 0 0 0 1 0 40\ncamera 0 0 1e14 0 0 99999999999999 0 1 0 40\n", 2,
         "2^40"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\n"
         "quad 0 0 0 1 0 0 1 1 0 0 2 0 m\n", 3, "not a parallelogram"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\n"
         "quad 0 0 0 1 0 0 2 0 0 1 0 0 m\n", 3, "span no area"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial e lambert 0 0 0 emit 1 1 1\n"
         "triangle 0 0 0 1 1 1 2 2 2 e\n", 3, "non-zero area"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nlight point 0 1 0 -1 1 1\n", 2, "negative"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nlight spot 0 1 0 1 1 1\n", 2, "point, sphere or quad"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nlight point 0 1 0 1e300 1 1\n", 2,
         "total power would exceed 1e+30 W"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nlight point 0 1 0 6e29 1 1\n"
         "light point 0 2 0 6e29 1 1\n", 3, "total power"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nlight sphere 0 0 5 1e15 1 1 1\n", 2,
         "total power"}, /* 4 pi^2 r^2 Le = 3.9e31 W */
        {"camera 0 0 0 0 0 1 0 1 0 40\nbackground 1e25 1 1\nmaterial m lambert 1 1 1\n"
         "sphere 0 0 5 1000 m\n", 2, "the sky's power"}, /* 4 pi^2 (1000 sqrt 3)^2 1e25 */
        {"camera 0 0 0 0 0 1 0 1 0 40\nlight sphere 0 0 5 1e200 0 1 0\n", 2,
         "total power"}, /* the area overflows: 0 x inf in red */
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial e lambert 0 0 0 emit 1 1 1\n"
         "triangle 0 0 0 1e16 0 0 0 1e16 0 e\n", 3, "total power"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m mirror 1 1 1 emit 1 -1 1\n", 2, "negative"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nsmooth_triangle 0 0 0 1 0 0 0 1 0 0 0 1 0 0 0 0 0 1 m\n",
         2, "normal is zero"},
        {"camera 0 0 0 0 0 1 0 1 0 40\ninclude test_scene_bad.scene\n", 2, "nested"},
        {"camera 0 0 0 0 0 1 0 1 0 40\ninclude no_such_file.scene\n", 2,
         "include: cannot open 'build/no_such_file.scene': "},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\nobj nothere.obj m\n", 3,
         "obj: cannot open 'build/nothere.obj': "},
        {"camera 0 0 0 0 0 1 0 1 0 40\nnff nothere.nff\n", 2,
         "nff: cannot open 'build/nothere.nff': "},
        {"material m lambert 1 1 1\n", 0, "no camera"},
        {"", 0, "no camera"},
        {"\x01\x02\xff\xfe binary\n", 1, "unknown keyword '\\x01\\x02\\xff\\xfe'"},
        {"sphere \x01\xff\x1b[31m 1 2\n", 1, "'\\x01\\xff\\x1b[31m' is not a number"},
        {"camera 0 0 0 0 0 1 0 1 0 40 # a comment\nsphere", 2, "expected 4 numbers"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\n"
         "sphereflake 0 0 0 1 11 0 0 1 m\n", 3, "levels"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\n"
         "sphereflake 0 0 0 1 1 0 0 1 m m m\n", 3, "more materials"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\n"
         "sphereflake 0 0 0 -1 1 0 0 1 m\n", 3, "sphereflake"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial e lambert 1 1 1 emit 1 1 1\n"
         "sphereflake 0 0 0 1 1 0 0 1 e\n", 3, "emitting"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\n"
         "heightfield 0 0 0 1 1.5 4 0.5 2 0.1 1 m\n", 3, "whole numbers"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\n"
         "heightfield 0 0 0 1 1 4 0.5 2 0.1 1 m\n", 3, "heightfield"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\n"
         "heightfield 0 0 0 1 9 4 0.5 2 0.1 1 m expand extra\n", 3, "unexpected 'extra'"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m phong 0.6 0.6 0.6 0.5 0.5 0.5 10\n", 2,
         "kd + ks"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m ward 0.1 0.1 0.1 0.5 0.5 0.5 0 0.2\n", 2,
         "alpha"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m schlick 0.5 0.5 0.5 0.1 0\n", 2,
         "isotropy"},
        /* reach.h: beyond what double precision resolves at the camera's scale */
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\nquad -1e20 -1 -1e20 "
         "-1e20 -1 1e20 1e20 -1 1e20 1e20 -1 -1e20 m\nlight point 0 0 0 1 1 1\n", 3,
         "reaches 1e+20 from the origin, more than 2^40 times"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 1 1 1\nsphere 0 -1e20 0 1e20 m\n", 3,
         "reaches 2e+20"},
        {"camera 0 0 0 0 0 1 0 1 0 40\nlight point 2e12 0 0 1 1 1\n", 2, "reaches 2e+12"},
        {"camera 1e13 0 0 1e13 0 1 0 1 0 40\n", 1, "reaches 1e+13"},
        {"camera 0 0 0 0 0 1e-7 0 1 0 40\n", 1, "camera: 1e-07 from its look-at point"},
    };
    const char *path = "build/test_scene_bad.scene";
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        FILE *f = fopen(path, "wb");
        CHECK(t, f != NULL);
        if (f == NULL)
            return;
        fputs(cases[i].text, f);
        fclose(f);
        struct error err;
        memset(&err, 0, sizeof err);
        struct scene *scene = scene_load(path, &err);
        CHECK(t, scene == NULL);
        scene_free(scene);
        if (err.line != cases[i].line || strstr(err.message, cases[i].message) == NULL)
            fprintf(stderr, "case %zu: got %s:%d: %s\n", i, err.file, err.line, err.message);
        CHECK(t, err.line == cases[i].line);
        CHECK(t, strstr(err.message, cases[i].message) != NULL);
    }
    remove(path);
}

/* truth: scene.h's limit: the lights' power summed per channel may reach MAX_LIGHT_POWER
 *   exactly, in each channel on its own, and not pass it.
 * tolerance: none (1e30 + 1 rounds to 1e30, so the step past it is 1e15).
 * catches: the limit applied to each light instead of the sum, to the channels' total
 *   instead of each channel, with < for <=; a refused light left in the scene. */
static void test_light_power_limit(struct check *t)
{
    struct scene *scene = scene_create();
    CHECK(t, scene_add_point_light(scene, vec3_zero(), vec3(MAX_LIGHT_POWER, 0, 0)) == 0);
    CHECK(t, scene_add_point_light(scene, vec3_zero(), vec3(0, MAX_LIGHT_POWER, 1)) == 1);
    CHECK(t, scene_add_point_light(scene, vec3_zero(), vec3(0, 0, MAX_LIGHT_POWER - 1)) == 2);
    CHECK(t, scene_add_point_light(scene, vec3_zero(), vec3(1e15, 0, 0)) == SCENE_TOO_BRIGHT);
    CHECK(t, scene_add_point_light(scene, vec3_zero(), vec3(0, 0, 1e15)) == SCENE_TOO_BRIGHT);
    CHECK(t, scene->n_lights == 3);
    scene_free(scene);
}

/* truth: the scene-file grammar (README): "glass IOR R G B" lets R G B through at each
 *   refraction, so it absorbs 1 - R G B; without the colour the glass is clear.
 * tolerance: 1e-15 (1 - 0.8 is not exact in binary).
 * catches: the colour stored as it is instead of as absorption, a clear glass absorbing
 *   everything (absorption left at 1 - 0), the colour's numbers taken for the next line. */
static void test_glass_filter_parsed(struct check *t)
{
    char path[256];
    temp_name(path, sizeof path, "scene", "glass.scene");
    write_text_file(path, "camera 0 0 0 0 0 1 0 1 0 40\nmaterial tinted glass 1.5 0.8 0.5 0.1\n"
                          "material clear glass 1.33\nsphere 0 0 5 1 tinted\n"
                          "sphere 3 0 5 1 clear\n");
    struct error err;
    struct scene *scene = scene_load(path, &err);
    CHECK(t, scene != NULL && scene->n_materials == 2);
    if (scene != NULL && scene->n_materials == 2) {
        const struct material *tinted = &scene->materials[0], *clear = &scene->materials[1];
        CHECK(t, tinted->kind == MATERIAL_GLASS && tinted->ior == 1.5);
        CHECK(t, vec3_max_abs(vec3_sub(tinted->absorption, vec3(0.2, 0.5, 0.9))) <= 1e-15);
        CHECK(t, clear->ior == 1.33 && vec3_max_abs(clear->absorption) == 0);
    }
    scene_free(scene);
    remove(path);
}

/* truth: a long line and a directory are refused, not read past or crashed on. */
static void test_unreadable_scenes_are_refused(struct check *t)
{
    const char *path = "build/test_scene_long.scene";
    FILE *f = fopen(path, "wb");
    CHECK(t, f != NULL);
    if (f == NULL)
        return;
    for (int i = 0; i < 10000; i++)
        fputs("1 ", f);
    fclose(f);
    struct error err;
    CHECK(t, scene_load(path, &err) == NULL && strstr(err.message, "longer") != NULL);
    CHECK(t, scene_load("scenes", &err) == NULL && strstr(err.message, "directory") != NULL);
    remove(path);
}

/* h folded with each line of text (lines end at '\n'; the last may not) and its '\0':
 * the test's own spelling of scene_hash_line() over a file. */
static uint64_t hash_lines(uint64_t h, const char *text)
{
    while (*text != '\0') {
        size_t n = strcspn(text, "\n");
        n += text[n] == '\n';
        h = fnv1a(h, text, n);
        h = fnv1a(h, "", 1);
        text += n;
    }
    return h;
}

/* truth: scene.h's source_hash: FNV-1a over every line read, in reading order, from the
 *   scene file, what it includes and what it imports (an included file's lines come where
 *   its include line stands), each line with its '\0'; recomputed here from the files'
 *   texts. A top-level NFF file hashes its own lines.
 * tolerance: none.
 * catches: an include or an OBJ import left out of the hash (tiles of a scene whose mesh
 *   changed would merge), lines hashed out of order, line ends not hashed. */
static void test_source_hash_covers_every_file(struct check *t)
{
    const char *top = "camera 0 1 -5  0 1 0  0 1 0  40\ninclude test_scene_inc.scene\n"
                      "obj test_scene_mesh.obj m   # the mesh\n";
    const char *inc = "material m lambert 0.5 0.5 0.5\n";
    const char *mesh = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3"; /* no final line break */
    write_text_file("build/test_scene_top.scene", top);
    write_text_file("build/test_scene_inc.scene", inc);
    write_text_file("build/test_scene_mesh.obj", mesh);
    uint64_t h = hash_lines(FNV1A_OFFSET_BASIS, "camera 0 1 -5  0 1 0  0 1 0  40\n"
                                                "include test_scene_inc.scene\n");
    h = hash_lines(hash_lines(h, inc), "obj test_scene_mesh.obj m   # the mesh\n");
    h = hash_lines(h, mesh);
    struct error err;
    struct scene *scene = scene_load("build/test_scene_top.scene", &err);
    CHECK(t, scene != NULL && scene->source_hash == h);
    scene_free(scene);
    write_text_file("build/test_scene_mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 3 2");
    scene = scene_load("build/test_scene_top.scene", &err);
    CHECK(t, scene != NULL && scene->source_hash != h);
    scene_free(scene);
    char *nff = read_text_file("scenes/every-primitive.nff");
    scene = scene_load("scenes/every-primitive.nff", &err);
    CHECK(t, nff != NULL && scene != NULL &&
             scene->source_hash == hash_lines(FNV1A_OFFSET_BASIS, nff));
    scene_free(scene);
    free(nff);
    remove("build/test_scene_top.scene");
    remove("build/test_scene_inc.scene");
    remove("build/test_scene_mesh.obj");
}

/* truth: the camera model of camera.h: the image centre looks along at - from; the top
 *   edge's centre is fov/2 above it; the left edge is on the side of up x (at - from)
 *   ... written out: u = w x up points right, so pixel x = 0 looks towards -u.
 * tolerance: 1e-12, rounding of a few operations on unit vectors.
 * catches: a flipped image (x or y), a horizontal instead of vertical fov, aspect ignored. */
static void test_camera_rays(struct check *t)
{
    struct camera c;
    memset(&c, 0, sizeof c); /* a pinhole: no lens */
    c.from = vec3(1, 2, 3);
    c.at = vec3(1, 2, 13);
    c.up = vec3(0, 5, 0);
    c.fov = 60;
    camera_setup(&c, 200, 100);
    struct ray centre = camera_ray(&c, 100, 50);
    CHECK_CLOSE(t, centre.dir.z, 1.0, 1e-12);
    struct ray top = camera_ray(&c, 100, 0);
    CHECK_CLOSE(t, atan2(top.dir.y, top.dir.z), 30 * PI / 180, 1e-12);
    struct ray left = camera_ray(&c, 0, 50);
    /* w = +z, up = +y: u = w x up = -x, so the left edge looks towards +x */
    CHECK_CLOSE(t, atan2(left.dir.x, left.dir.z), atan(2 * tan(30 * PI / 180)), 1e-12);
    CHECK_CLOSE(t, vec3_length(left.dir), 1.0, 1e-15);
}

/* Irradiance at p with normal n estimated from n_samples light samples (no occlusion). */
static double estimated_irradiance(const struct light *l, struct vec3 p, struct vec3 n,
                                   int n_samples, double *standard_error)
{
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n_samples; i++) {
        struct rng r = rng_stream(3, STREAM_TEST, (uint64_t)i, 0);
        struct light_sample s;
        double e = 0;
        double u1 = rng_uniform(&r), u2 = rng_uniform(&r);
        if (light_sample(l, p, n, u1, u2, &s))
            e = s.li.x * fmax(0.0, vec3_dot(n, s.wi)) / s.pdf;
        sum += e;
        sum2 += e * e;
    }
    double mean = sum / n_samples;
    *standard_error = sqrt(fmax(0.0, sum2 / n_samples - mean * mean) / n_samples);
    return mean;
}

/* truth: closed forms: a sphere of radius a and radiance Le at distance d, wholly above
 *   the horizon of a surface tilted by theta: E = pi Le (a/d)^2 cos theta; a quad light:
 *   Lambert's polygon formula; a triangle light: the same formula; a point light:
 *   E = Phi cos theta / (4 pi d^2).
 * tolerance: 0.5% (the figure), and the estimate must also be within 5 standard
 *   errors estimated from the same samples (40,000 of them), so the check is real.
 * catches: a pdf in area measure used as solid angle, a missing cos at the light, a
 *   non-uniform triangle sampler, the wrong cone angle. */
static void test_light_sampling_irradiance(struct check *t)
{
    const int n = 40000;
    double se;
    struct light sphere = {LIGHT_SPHERE, {0, 10, 0}, {0, 0, 0}, {0, 0, 0}, 2.0, {0, 0, 0},
                           {3, 3, 3}, 0, 0};
    struct vec3 n_tilted = vec3(sin(0.3), cos(0.3), 0);
    double exact = PI * 3 * (2.0 / 10) * (2.0 / 10) * cos(0.3);
    double e = estimated_irradiance(&sphere, vec3_zero(), n_tilted, n, &se);
    CHECK(t, fabs(e - exact) <= 0.005 * exact && fabs(e - exact) <= 5 * se + 1e-12 * exact);

    struct vec3 corners[4] = {{-1, 3, -2}, {2, 3, -2}, {2, 3, 1}, {-1, 3, 1}};
    struct light quad = {LIGHT_QUAD, {-1, 3, -2}, {3, 0, 0}, {0, 0, 3}, 0, {0, 0, 0},
                         {5, 5, 5}, 0, 0};
    struct vec3 p = vec3(0.5, 0, 0.2), n_up = vec3(0.2, 1, 0.1);
    n_up = vec3_normalize(n_up);
    exact = polygon_irradiance(corners, 4, p, n_up, 5);
    e = estimated_irradiance(&quad, p, n_up, n, &se);
    CHECK(t, fabs(e - exact) <= 0.005 * exact && fabs(e - exact) <= 5 * se);

    struct light triangle = {LIGHT_TRIANGLE, {-1, 3, -2}, {3, 0, 0}, {0, 0, 3}, 0, {0, 0, 0},
                             {5, 5, 5}, 0, 0};
    struct vec3 tri[3] = {{-1, 3, -2}, {2, 3, -2}, {-1, 3, 1}};
    exact = polygon_irradiance(tri, 3, p, n_up, 5);
    e = estimated_irradiance(&triangle, p, n_up, n, &se);
    CHECK(t, fabs(e - exact) <= 0.005 * exact && fabs(e - exact) <= 5 * se);

    struct light point = {LIGHT_POINT, {0, 4, 3}, {0, 0, 0}, {0, 0, 0}, 0, {100, 100, 100},
                          {0, 0, 0}, -1, 0};
    exact = 100 * (4.0 / 5) / (4 * PI * 25);
    CHECK_CLOSE(t, estimated_irradiance(&point, vec3_zero(), vec3(0, 1, 0), 1, &se), exact,
                1e-14 * exact);
}

/* truth: the sky of radiance Le seen from a point with normal n: every sample of the
 *   cosine about n brings the irradiance pi Le exactly; the mean of n . wi under that
 *   density is 2/3 (1/2 for a uniform hemisphere); light_pdf() gives the sample's own pdf
 *   (what MIS reads); the power is Le pi R^2 4 pi.
 * tolerance: rounding (1e-12) for the exact ones; 5 standard errors for the mean.
 * catches: samples below the horizon, a uniform instead of a cosine density, a pdf that
 *   MIS would read differently from the one sampled, the disc or the sphere of
 *   directions missing from the power. */
static void test_sky_sampling(struct check *t)
{
    struct light sky;
    memset(&sky, 0, sizeof sky);
    sky.kind = LIGHT_SKY;
    sky.radius = 3.0;
    sky.radiance = vec3(2, 2, 2);
    sky.prim = -1;
    struct vec3 n = vec3_normalize(vec3(0.3, 1, -0.2)), p = vec3(0.5, 0.1, 0.2);
    double sum = 0, sum2 = 0;
    const int n_samples = 20000;
    int all_exact = 1;
    for (int i = 0; i < n_samples; i++) {
        struct rng r = rng_stream(5, STREAM_TEST, (uint64_t)i, 0);
        double u1 = rng_uniform(&r), u2 = rng_uniform(&r);
        struct light_sample s;
        CHECK(t, light_sample(&sky, p, n, u1, u2, &s) && s.distance == INFINITY);
        double cos_theta = vec3_dot(n, s.wi), e = s.li.x * cos_theta / s.pdf;
        all_exact &= cos_theta > 0 && fabs(e - 2 * PI) <= 1e-12 * 2 * PI &&
                     fabs(light_pdf(&sky, p, n, p, s.wi) - s.pdf) <= 1e-12 * s.pdf;
        sum += cos_theta;
        sum2 += cos_theta * cos_theta;
    }
    CHECK(t, all_exact);
    double mean = sum / n_samples, se = sqrt((sum2 / n_samples - mean * mean) / n_samples);
    CHECK(t, fabs(mean - 2.0 / 3.0) <= 5 * se);
    CHECK_CLOSE(t, light_power(&sky).y, 2 * PI * 9 * 4 * PI, 1e-12 * light_power(&sky).y);
}

/* truth: a two-sided light emits from its back too: behind a two-sided quad the irradiance
 *   is Lambert's polygon formula again; inside a two-sided sphere light of radiance Le
 *   every direction meets its inner side, so E = pi Le whatever the normal; each side
 *   emits pi Le A, the power twice the one-sided's. light_pdf() gives each sample's pdf.
 * tolerance: as test_light_sampling_irradiance (0.5% and 5 standard errors; the inside by
 *   ten times the samples, uniform by area there having a long tail); 1e-9 for the pdfs.
 * catches: the back's cosine taken negative (no light), the inside sampled by the cone
 *   of an outside point (none), a uniform-area pdf without d^2 / cos, the back's power
 *   left out of photon emission's share. */
static void test_two_sided_lights(struct check *t)
{
    const int n = 40000;
    double se;
    struct light quad = {LIGHT_QUAD, {-1, 3, -2}, {3, 0, 0}, {0, 0, 3}, 0, {0, 0, 0},
                         {5, 5, 5}, 0, 1};
    struct vec3 corners[4] = {{-1, 3, -2}, {2, 3, -2}, {2, 3, 1}, {-1, 3, 1}};
    struct vec3 p = vec3(0.5, 6, 0.2), n_down = vec3_normalize(vec3(0.2, -1, 0.1));
    double exact = polygon_irradiance(corners, 4, p, n_down, 5);
    double e = estimated_irradiance(&quad, p, n_down, n, &se);
    CHECK(t, exact > 0 && fabs(e - exact) <= 0.005 * exact && fabs(e - exact) <= 5 * se);
    struct light one_sided = quad;
    one_sided.two_sided = 0;
    CHECK_CLOSE(t, light_power(&quad).x, 2 * light_power(&one_sided).x, 1e-12);
    struct light sphere = {LIGHT_SPHERE, {0, 10, 0}, {0, 0, 0}, {0, 0, 0}, 2.0, {0, 0, 0},
                           {3, 3, 3}, 0, 1};
    struct vec3 inside = vec3(0.5, 10.7, -0.4), n_any = vec3_normalize(vec3(0.3, -0.2, 1));
    e = estimated_irradiance(&sphere, inside, n_any, 10 * n, &se);
    CHECK(t, fabs(e - 3 * PI) <= 0.005 * 3 * PI && fabs(e - 3 * PI) <= 5 * se);
    struct light_sample s;
    CHECK(t, light_sample(&sphere, inside, n_any, 0.3, 0.6, &s));
    struct vec3 q = vec3_madd(inside, s.wi, s.distance);
    CHECK_CLOSE(t, vec3_length(vec3_sub(q, sphere.position)), 2.0, 1e-9);
    CHECK_CLOSE(t, light_pdf(&sphere, inside, n_any, q, s.wi), s.pdf, 1e-9 * s.pdf);
    CHECK(t, light_sample(&quad, p, n_down, 0.3, 0.6, &s));
    q = vec3_madd(p, s.wi, s.distance);
    CHECK_CLOSE(t, light_pdf(&quad, p, n_down, q, s.wi), s.pdf, 1e-9 * s.pdf);
}

/* truth: a light cannot illuminate a point behind a one-sided emitter or inside a sphere
 *   light (both emit from the front only). */
static void test_light_sides(struct check *t)
{
    struct light quad = {LIGHT_QUAD, {-1, 3, -2}, {3, 0, 0}, {0, 0, 3}, 0, {0, 0, 0},
                         {5, 5, 5}, 0, 0};
    struct light sphere = {LIGHT_SPHERE, {0, 10, 0}, {0, 0, 0}, {0, 0, 0}, 2.0, {0, 0, 0},
                           {3, 3, 3}, 0, 0};
    struct light_sample s;
    CHECK(t, vec3_cross(quad.e1, quad.e2).y < 0);       /* it faces down, towards y = 0 */
    CHECK(t, light_sample(&quad, vec3(0, 0, 0), vec3(0, 1, 0), 0.5, 0.5, &s));
    CHECK(t, !light_sample(&quad, vec3(0, 5, 0), vec3(0, 1, 0), 0.5, 0.5, &s));
    CHECK(t, !light_sample(&sphere, vec3(0, 10.5, 0), vec3(0, 1, 0), 0.5, 0.5, &s));
}

/* truth: Fresnel's equations at normal incidence, ((eta - 1) / (eta + 1))^2; at grazing
 *   incidence, 1; beyond the critical angle, 1; and reciprocity: the reflectance seen from
 *   the two sides of the boundary is the same for the two angles Snell's law pairs.
 *   Snell's law itself: sin_i = eta sin_t, with the refracted ray on the far side.
 * tolerance: 1e-12, rounding of a few operations.
 * catches: Schlick's approximation instead of exact Fresnel, eta inverted, TIR missed. */
static void test_fresnel_and_snell(struct check *t)
{
    CHECK_CLOSE(t, fresnel_dielectric(1.0, 1.5), 0.04, 1e-12);
    CHECK_CLOSE(t, fresnel_dielectric(0.0, 1.5), 1.0, 1e-12);
    CHECK_CLOSE(t, fresnel_dielectric(cos(60 * PI / 180), 1 / 1.5), 1.0, 0);
    struct vec3 n = vec3(0, 1, 0);
    for (int k = 1; k < 90; k += 7) {
        double theta = k * PI / 180;
        struct vec3 wo = vec3(sin(theta), cos(theta), 0), wi;
        CHECK(t, refract(wo, n, 1.5, &wi));
        double sin_t = sqrt(wi.x * wi.x + wi.z * wi.z);
        CHECK_CLOSE(t, sin(theta), 1.5 * sin_t, 1e-12);
        CHECK(t, wi.y < 0 && wi.x < 0);
        CHECK_CLOSE(t, fresnel_dielectric(cos(theta), 1.5),
                    fresnel_dielectric(-wi.y, 1 / 1.5), 1e-12);
    }
}

/* Renders a 1-pixel view straight down from height 2 at a white floor of +-extent with a
 * 1 W point light at (1, 1, 0) and a blocker of the light at (-1, 1, 0) half way, and
 * returns the pixel's red value; -1 when it does not render. */
static double floor_pixel(const char *extent)
{
    char text[512];
    const char *s = extent;
    snprintf(text, sizeof text, "image 1 1\ncamera 0 2 0 0 0 0 0 0 1 1\n"
             "material w lambert 1 1 1\nquad -%s 0 -%s -%s 0 %s %s 0 %s %s 0 -%s w\n"
             "quad -0.6 0.5 -0.1 -0.4 0.5 -0.1 -0.4 0.5 0.1 -0.6 0.5 0.1 w\n"
             "light point 1 1 0 1 1 1\nlight point -1 1 0 1 1 1\n", s, s, s, s, s, s, s, s);
    write_text_file("build/test_scene_reach.scene", text);
    if (photon_logged("", "--no-progress --mode direct -o build/test_scene_reach.pfm "
                      "build/test_scene_reach.scene", "build/test_scene_reach.log") != 0)
        return -1;
    struct error err;
    struct image *img = pfm_read("build/test_scene_reach.pfm", &err);
    double v = img != NULL ? image_get(img, 0, 0).x : -1;
    image_free(img);
    return v;
}

/* truth: reach.h's measured range: the same view of a floor lit by one light (the other
 *   blocked) renders alike whatever the floor's extent, up to the limit of 2^40 times the
 *   camera's distance (2): a floor of +-1e12 gives the pixel of a floor of +-1e3, and
 *   the closed form Phi cos / (4 pi d^2) / pi = 1 / (8 sqrt(2) pi^2) = 0.0089556 to the
 *   pixel's footprint (0.2%); a floor of +-1e13 is refused.
 * tolerance: 1e-4 relative between the two floors (1e13 moved the pixel by 1.3e-4).
 * catches: a limit set past what the tracer resolves, or so tight it refuses a scene
 *   that renders right; the shadow lost (the pixel would double). */
static void test_reach_renders_alike(struct check *t)
{
    double near = floor_pixel("1e3"), far = floor_pixel("1e12");
    CHECK(t, near > 0 && fabs(far - near) <= 1e-4 * near);
    CHECK_CLOSE(t, near, 1.0 / (8.0 * sqrt(2.0) * PI * PI), 2e-3 * near);
    CHECK(t, floor_pixel("1e13") < 0 && file_contains("build/test_scene_reach.log",
                                                      "build/test_scene_reach.scene:4: "
                                                      "reaches 1e+13"));
    remove("build/test_scene_reach.scene");
    remove("build/test_scene_reach.pfm");
    remove("build/test_scene_reach.png");
    remove("build/test_scene_reach.log");
}

void test_scene(struct check *t)
{
    RUN_TEST(t, test_reach_renders_alike);
    RUN_TEST(t, test_cornell_scene_loads);
    RUN_TEST(t, test_shipped_scenes_load);
    RUN_TEST(t, test_bad_scenes_are_refused);
    RUN_TEST(t, test_light_power_limit);
    RUN_TEST(t, test_glass_filter_parsed);
    RUN_TEST(t, test_unreadable_scenes_are_refused);
    RUN_TEST(t, test_source_hash_covers_every_file);
    RUN_TEST(t, test_camera_rays);
    RUN_TEST(t, test_light_sampling_irradiance);
    RUN_TEST(t, test_light_sides);
    RUN_TEST(t, test_sky_sampling);
    RUN_TEST(t, test_two_sided_lights);
    RUN_TEST(t, test_fresnel_and_snell);
}
