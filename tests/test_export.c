/*
 * tests/test_export.c -- the export room: `photon export` to pbrt-v4 and Mitsuba 3, read
 * back as text against values worked out by hand from the conventions in app/export_*.c
 * (the field of view of pbrt's shorter axis, intensity Phi / (4 pi), one-sided emitters,
 * the mirror's mix, the glass filter, the quads' triangles, the camera's handedness), a
 * round trip of Mitsuba's mesh files through our own OBJ reader, and the failures: exit
 * status 2, a message, no output file. The Blender writer has its own tests.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "files.h"
#include "tests.h"

#define NAME_BYTES 256
#define ARGS_BYTES 1024

/* Every primitive, material and light kind once. A 20 x 40 image: taller than wide, so
 * pbrt's "fov" (the shorter axis's, here horizontal) differs from ours (vertical, 30). */
static const char every_kind[] =
    "image 20 40\n"
    "camera 0 1 -5  0 1 0  0 1 0  30\n"
    "background 0.1 0.2 0.3\n"
    "material white lambert 0.725 0.71 0.68\n"
    "material half mirror 0.5 0.5 0.5\n"
    "material tinted glass 1.5 0.8 0.9 1\n"
    "material shiny phong 0.3 0.3 0.3  0.5 0.5 0.5  30\n"
    "material brushed ward 0.25 0.245 0.235  0.5 0.5 0.5  0.02 0.08\n"
    "material satin schlick 0.6 0.6 0.6  0.3\n"
    "material glow lambert 0.5 0.5 0.5 emit 2 3 4 twosided\n"
    "quad 0 0 0  4 0 0  4 0 2  0 0 2  white\n"
    "smooth_triangle 0 0 0  1 0 0  0 1 0  0 0 1  0 0 1  0 0 1  shiny\n"
    "triangle 0 0 3  1 0 3  0 1 3  brushed\n"
    "triangle 0 0 4  1 0 4  0 1 4  satin\n"
    "triangle 0 0 5  1 0 5  0 1 5  glow\n"
    "sphere 1 2 3 0.5 tinted\n"
    "sphere -1 2 3 0.25 half\n"
    "sphereflake 0 3 0 0.5 1  0 1 0  white\n"
    "heightfield -1 0 -1  2 3 2  0.5 1  0.1 7  white\n"
    "light point 0 4 0  100 100 40\n"
    "light quad -1 3 -1  1 3 -1  1 3 1  -1 3 1  17 12 4\n";

struct exported {
    char scene[NAME_BYTES], out[NAME_BYTES], log[NAME_BYTES];
    char *text; /* the output's text, NULL when it was not written */
    int status;
};

/* Writes scene_text to a temporary scene, exports it with the given words and reads the
 * output back. out_suffix: ".pbrt" or ".xml". */
static void export_scene(struct exported *e, const char *what, const char *scene_text,
                         const char *words, const char *out_suffix)
{
    char args[ARGS_BYTES];
    temp_name(e->scene, sizeof e->scene, "export", what);
    strncat(e->scene, ".scene", sizeof e->scene - strlen(e->scene) - 1);
    temp_name(e->out, sizeof e->out, "export", what);
    strncat(e->out, out_suffix, sizeof e->out - strlen(e->out) - 1);
    temp_name(e->log, sizeof e->log, "export", what);
    strncat(e->log, ".log", sizeof e->log - strlen(e->log) - 1);
    write_text_file(e->scene, scene_text);
    snprintf(args, sizeof args, "%s %s -o %s", words, e->scene, e->out);
    e->status = photon_logged("export", args, e->log);
    e->text = read_text_file(e->out);
}

/* The name of Mitsuba's k-th mesh file beside the output of a ".xml" export. */
static void mesh_file(char *name, size_t size, const struct exported *e, int k)
{
    snprintf(name, size, "%.*s-mesh%d.obj", (int)(strlen(e->out) - 4), e->out, k);
}

/* Removes what export_scene() made, Mitsuba's mesh files included. */
static void exported_free(struct exported *e)
{
    char mesh[NAME_BYTES];
    free(e->text);
    remove(e->scene);
    for (int k = 0;; k++) {
        mesh_file(mesh, sizeof mesh, e, k);
        if (remove(mesh) != 0)
            break;
    }
    remove(e->out);
    remove(e->log);
}

static int has(const struct exported *e, const char *text)
{
    return e->text != NULL && strstr(e->text, text) != NULL;
}

/* Whether a appears in the output before b (both present). */
static int before(const struct exported *e, const char *a, const char *b)
{
    const char *pa = e->text != NULL ? strstr(e->text, a) : NULL;
    const char *pb = e->text != NULL ? strstr(e->text, b) : NULL;
    return pa != NULL && pb != NULL && pa < pb;
}

static void test_pbrt_camera_and_film(struct check *t)
{
    struct exported e;
    export_scene(&e, "camera", every_kind, "--format pbrt --spp 37", ".pbrt");
    REQUIRE(t, e.status == 0 && e.text != NULL);
    /* pbrt's LookAt puts up x dir on the right: without the flip, a mirror image. */
    CHECK(t, before(&e, "Scale -1 1 1\n", "LookAt 0 1 -5  0 1 0  0 1 0\n"));
    CHECK(t, before(&e, "LookAt", "WorldBegin"));
    /* 2 atan(tan(15 deg) x 20 / 40) = 15.2614804248601 degrees, the horizontal field. */
    CHECK(t, has(&e, "\"float fov\" [15.2614804248601]"));
    /* 37 is no power of 2, which "zsobol" would take down to 32: "halton" takes it. */
    CHECK(t, has(&e, "Sampler \"halton\" \"integer pixelsamples\" [37]"));
    CHECK(t, has(&e, "PixelFilter \"box\" \"float xradius\" [0.5] \"float yradius\" [0.5]"));
    CHECK(t, has(&e, "\"integer xresolution\" [20] \"integer yresolution\" [40]"));
    CHECK(t, has(&e, "\"string sensor\" \"cie1931\" \"float iso\" [100]"));
    exported_free(&e);

    /* A wide image: the shorter axis is the vertical one, whose field is ours. */
    char wide[sizeof every_kind];
    strcpy(wide, every_kind);
    memcpy(strstr(wide, "image 20 40"), "image 40 20", 11);
    export_scene(&e, "wide", wide, "--format pbrt", ".pbrt");
    CHECK(t, has(&e, "\"float fov\" [30]"));
    CHECK(t, has(&e, "Sampler \"zsobol\" \"integer pixelsamples\" [1024]"));
    exported_free(&e);
}

static void test_pbrt_lights(struct check *t)
{
    struct exported e;
    export_scene(&e, "lights", every_kind, "--format pbrt", ".pbrt");
    REQUIRE(t, e.status == 0 && e.text != NULL);
    /* Phi / (4 pi): 100 / 4 pi = 7.95774715459477, 40 / 4 pi = 3.18309886183791. */
    CHECK(t, has(&e, "LightSource \"point\" \"point3 from\" [0 4 0] "
                     "\"rgb I\" [7.95774715 7.95774715 3.18309886]"));
    /* The area light: its radiance, one-sided; the glowing material two-sided. */
    CHECK(t, has(&e, "AreaLightSource \"diffuse\" \"rgb L\" [17 12 4]\n"));
    CHECK(t, has(&e, "AreaLightSource \"diffuse\" \"rgb L\" [2 3 4] \"bool twosided\" true"));
    CHECK(t, has(&e, "LightSource \"infinite\" \"rgb L\" [0.1 0.2 0.3]"));
    exported_free(&e);
}

static void test_pbrt_materials_and_shapes(struct check *t)
{
    struct exported e;
    export_scene(&e, "materials", every_kind, "--format pbrt", ".pbrt");
    REQUIRE(t, e.status == 0 && e.text != NULL);
    CHECK(t, has(&e, "\"string type\" \"diffuse\" \"rgb reflectance\" [0.725 0.71 0.68]"));
    /* A mirror of 0.5: a perfect conductor half of the time, black the other half. */
    CHECK(t, has(&e, "\"m1-mirror\" \"string type\" \"conductor\" \"rgb reflectance\" [1 1 1]"));
    CHECK(t, has(&e, "\"string materials\" [\"m1-black\" \"m1-mirror\"] \"float amount\" [0.5]"));
    CHECK(t, has(&e, "\"m2\" \"string type\" \"dielectric\" \"float eta\" [1.5]"));
    /* Schlick's r = 0.3: glossy weight 4 r (1 - r) = 0.84 over a mirror, slope sqrt(0.3). */
    CHECK(t, has(&e, "\"m5-base\" \"string type\" \"conductor\""));
    CHECK(t, has(&e, "\"float uroughness\" [0.547722558]"));
    CHECK(t, has(&e, "[\"m5-base\" \"m5-lobe\"] \"float amount\" [0.84]"));
    /* Phong's n = 30: slope sqrt(2 / 32) = 0.25; weight 0.5 doubles both parts. */
    CHECK(t, has(&e, "\"m3-base\" \"string type\" \"diffuse\" \"rgb reflectance\" [0.6 0.6 0.6]"));
    CHECK(t, has(&e, "\"float uroughness\" [0.25] \"float vroughness\" [0.25]"));
    /* Spheres as spheres, the quad as two triangles keeping its front side. */
    CHECK(t, has(&e, "  Translate 1 2 3\n  Shape \"sphere\" \"float radius\" [0.5]"));
    CHECK(t, has(&e, "      0 0 0\n      4 0 0\n      4 0 2\n      0 0 0\n      4 0 2\n"
                     "      0 0 2\n"));
    CHECK(t, has(&e, "\"normal N\" [\n      0 0 1\n      0 0 1\n      0 0 1\n    ]"));
    /* What pbrt cannot do is said, and what the shapes became. */
    CHECK(t, file_contains(e.log, "\"tinted\": pbrt's dielectric has no colour filter"));
    CHECK(t, file_contains(e.log, "\"shiny\": pbrt has no Phong model"));
    CHECK(t, file_contains(e.log, "\"brushed\": pbrt has no Ward model"));
    CHECK(t, file_contains(e.log, "sphereflake: written as its 10 spheres"));
    CHECK(t, file_contains(e.log, "heightfield: written as its 8 triangles"));
    exported_free(&e);
}

/* --channel G: every colour the green one, a constant spectrum in pbrt. */
static void test_channel(struct check *t)
{
    struct exported e;
    export_scene(&e, "channel", every_kind, "--format pbrt --channel G", ".pbrt");
    REQUIRE(t, e.status == 0 && e.text != NULL);
    CHECK(t, has(&e, "\"rgb reflectance\" [0.71 0.71 0.71]"));
    CHECK(t, has(&e, "\"rgb L\" [12 12 12]\n"));
    CHECK(t, has(&e, "\"rgb I\" [7.95774715 7.95774715 7.95774715]"));
    CHECK(t, has(&e, "LightSource \"infinite\" \"rgb L\" [0.2 0.2 0.2]"));
    CHECK(t, !has(&e, "0.725"));
    exported_free(&e);
}

static void test_mitsuba(struct check *t)
{
    struct exported e;
    export_scene(&e, "mitsuba", every_kind, "--format mitsuba --spp 8", ".xml");
    REQUIRE(t, e.status == 0 && e.text != NULL);
    CHECK(t, has(&e, "<string name=\"fov_axis\" value=\"y\"/>\n"
                     "        <float name=\"fov\" value=\"30\"/>"));
    CHECK(t, has(&e, "<lookat origin=\"0, 1, -5\" target=\"0, 1, 0\" up=\"0, 1, 0\"/>"));
    CHECK(t, has(&e, "<integer name=\"sample_count\" value=\"8\"/>"));
    CHECK(t, has(&e, "<rfilter type=\"box\"/>"));
    CHECK(t, has(&e, "<rgb name=\"intensity\" value=\"7.95774715, 7.95774715, 3.18309886\"/>"));
    /* Reflecting materials on both sides; glass with its filter 1 - absorption. */
    CHECK(t, has(&e, "<bsdf type=\"twosided\" id=\"m0\">\n        <bsdf type=\"diffuse\">"));
    CHECK(t, has(&e, "<bsdf type=\"dielectric\" id=\"m2\">"));
    CHECK(t, has(&e, "<rgb name=\"specular_transmittance\" value=\"0.8, 0.9, 1\"/>"));
    CHECK(t, has(&e, "<string name=\"material\" value=\"none\"/>\n"
                     "            <rgb name=\"specular_reflectance\" value=\"0.5, 0.5, 0.5\"/>"));
    /* Schlick's isotropic blend is exact: GGX, no note; Ward's is not. */
    CHECK(t, has(&e, "<string name=\"distribution\" value=\"ggx\"/>"));
    CHECK(t, !file_contains(e.log, "\"satin\""));
    CHECK(t, file_contains(e.log, "mitsuba: material \"brushed\": Mitsuba has no Ward model"));
    CHECK(t, file_contains(e.log, "\"glow\": Mitsuba's area emitters are one-sided"));
    CHECK(t, has(&e, "<point name=\"center\" x=\"1\" y=\"2\" z=\"3\"/>"));

    /* The white quad's mesh: its two triangles, in our winding. */
    const char *base = strrchr(e.out, '/') + 1;
    char mesh[NAME_BYTES], line[NAME_BYTES];
    mesh_file(mesh, sizeof mesh, &e, 0);
    snprintf(line, sizeof line, "<string name=\"filename\" value=\"%.*s-mesh0.obj\"/>",
             (int)(strlen(base) - 4), base);
    CHECK(t, has(&e, line));
    CHECK(t, file_contains(mesh, "v 0 0 0\nv 4 0 0\nv 4 0 2\nv 0 0 0\nv 4 0 2\nv 0 0 2\n"));
    CHECK(t, file_contains(mesh, "f 1 2 3\nf 4 5 6\n"));

    /* Round trip: the mesh file, read by our OBJ reader and exported again, comes back
     * with the same vertices and faces. */
    char again[2 * NAME_BYTES];
    snprintf(again, sizeof again, "image 20 40\ncamera 0 1 -5  0 1 0  0 1 0  30\n"
                                  "material white lambert 0.725 0.71 0.68\nobj %s white\n",
             mesh);
    struct exported r;
    export_scene(&r, "again", again, "--format mitsuba", ".xml");
    char mesh_again[NAME_BYTES];
    mesh_file(mesh_again, sizeof mesh_again, &r, 0);
    CHECK(t, r.status == 0);
    char *first = read_text_file(mesh), *second = read_text_file(mesh_again);
    CHECK(t, first != NULL && second != NULL && strcmp(first, second) == 0);
    free(first);
    free(second);
    exported_free(&r);
    exported_free(&e);
}

/* Every shipped scene exports in every text format (the NFF one through the same path,
 * its cone as facets, said on stderr). */
static void test_shipped_scenes(struct check *t)
{
    static const char *const scenes[] = {"scenes/cornell.scene", "scenes/every-primitive.nff",
                                         "scenes/cardioid-ring.scene"};
    char out[NAME_BYTES], log[NAME_BYTES], args[ARGS_BYTES];
    temp_name(out, sizeof out, "export", "shipped.pbrt");
    temp_name(log, sizeof log, "export", "shipped.log");
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        snprintf(args, sizeof args, "--format pbrt %s -o %s", scenes[i], out);
        CHECK(t, photon_logged("export", args, log) == 0);
        CHECK(t, file_contains(out, "WorldBegin"));
        if (i == 1)
            CHECK(t, file_contains(log, "cone: no exact equivalent; written as 128 flat facets"));
    }
    remove(out);
    remove(log);
}

/* words with every "OUT" replaced by out and every "BAD" by bad, into args. */
static void substitute(char *args, size_t size, const char *words, const char *out,
                       const char *bad)
{
    size_t n = 0;
    while (*words != '\0' && n + 1 < size) {
        const char *with = strncmp(words, "OUT", 3) == 0 ? out
                           : strncmp(words, "BAD", 3) == 0 ? bad
                                                           : NULL;
        if (with != NULL) {
            n += (size_t)snprintf(args + n, size - n, "%s", with);
            words += 3;
        } else {
            args[n++] = *words++;
        }
    }
    args[n < size ? n : size - 1] = '\0';
}

/* Bad input: exit status 2, a message on stderr, and no output file; --help, status 0
 * and the usage on stdout. */
static void test_failures(struct check *t)
{
    static const struct {
        const char *args, *message;
    } cases[] = {
        {"--format povray scenes/cornell.scene -o OUT.pbrt", "--format 'povray': expected pbrt"},
        {"--format pbrt scenes/cornell.scene -o /nonexistent-dir/x.pbrt", "nonexistent-dir"},
        {"--format pbrt scenes/no-such.scene -o OUT.pbrt", "no-such.scene"},
        {"--format pbrt scenes/cornell.scene -o OUT.pbrt --channel Y", "--channel 'Y'"},
        {"--format pbrt scenes/cornell.scene -o OUT.pbrt --spp 0",
         "--spp: expected a whole number from 1 to 16777216, got '0'"},
        {"--format pbrt scenes/cornell.scene", "needs --format, a scene and -o"},
        {"--format mitsuba BAD -o OUT.xml", ":2: "},
    };
    char out[NAME_BYTES], pbrt[NAME_BYTES + 8], xml[NAME_BYTES + 8], log[NAME_BYTES];
    char bad[NAME_BYTES], args[ARGS_BYTES];
    temp_name(out, sizeof out, "export", "failed"); /* OUT: the cases add the ending */
    snprintf(pbrt, sizeof pbrt, "%s.pbrt", out);
    snprintf(xml, sizeof xml, "%s.xml", out);
    temp_name(log, sizeof log, "export", "failed.log");
    temp_name(bad, sizeof bad, "export", "bad.scene");
    write_text_file(bad, "image 8 8\nsphere 0 0 0 1 undefined\n");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        substitute(args, sizeof args, cases[i].args, out, bad);
        CHECK(t, photon_logged("export", args, log) == 2);
        CHECK(t, file_contains(log, cases[i].message));
        CHECK(t, !file_exists(pbrt) && !file_exists(xml));
    }
    CHECK(t, photon_logged("export", "--help", log) == 0);
    CHECK(t, file_contains(log, "usage: photon export --format pbrt|mitsuba|blender SCENE"));
    CHECK(t, file_contains(log, "--channel R|G|B   one channel's values"));
    remove(bad);
    remove(log);
}

/* truth: export.h: names reach the exported files only where the target can read them: a
 *   scene's path in a comment with every byte a comment could not hold as '_' (a newline
 *   would end a comment line and start a directive, "--" would end an XML comment, '<'
 *   would start an XML tag); an -o name that must go into the target's data (pbrt's film
 *   in a quoted string, Mitsuba's mesh files in attributes) with '"', '\\', '&', '<'
 *   or '>' is refused, status 2, nothing written.
 * catches: a scene named "a\n#--<b>" that puts a directive, a broken comment or a tag
 *   into the file; -o 'a"b.pbrt' breaking pbrt's quoting. */
static void test_names_escaped(struct check *t)
{
    static const char *const formats[][2] = {{"pbrt", "pbrt"}, {"mitsuba", "xml"},
                                             {"blender", "py"}};
    char scene[NAME_BYTES], out[NAME_BYTES], log[NAME_BYTES], args[ARGS_BYTES];
    temp_name(scene, sizeof scene, "export", "a\n#--<b>.scene");
    temp_name(log, sizeof log, "export", "names.log");
    char command[ARGS_BYTES];
    snprintf(command, sizeof command, "cp scenes/cornell.scene '%s'", scene);
    CHECK(t, run_command(command) == 0);
    for (int i = 0; i < 3; i++) {
        char ending[16];
        snprintf(ending, sizeof ending, "names.%s", formats[i][1]);
        temp_name(out, sizeof out, "export", ending);
        snprintf(args, sizeof args, "--format %s '%s' -o %s", formats[i][0], scene, out);
        CHECK(t, photon_logged("export", args, log) == 0);
        CHECK(t, !file_contains(out, "\n#--<b>") && !file_contains(out, "#--") &&
                 file_contains(out, "a_#-__b_.scene"));
        remove(out);
        snprintf(args, sizeof args, "--format %s scenes/cornell.scene -o '%s\"x.%s'",
                 formats[i][0], out, formats[i][1]);
        CHECK(t, photon_logged("export", args, log) == 2 &&
                 file_contains(log, "must be printable ASCII without"));
    }
    run_command("rm -f /tmp/photon_test_export_*names*");
    remove(scene);
    remove(log);
}

/* truth: each format's thin lens (pbrt-v4's "perspective" camera, Mitsuba 3's "thinlens"
 *   sensor, Blender's depth of field), as their documentation names it, carries our
 *   radius and distance in focus; a pinhole writes none of it. (That the three render
 *   what we render is make crosscheck's to show: Cycles on the defocused edge.)
 * tolerance: none (text).
 * catches: a lens dropped from an export, the radius written as a diameter, the
 *   distance in focus written as the look-at distance, a lens written for a pinhole. */
static void test_lens_exports(struct check *t)
{
    static const char *const lens[][3] = {
        {"pbrt", ".pbrt", "\"float lensradius\" [0.25] \"float focaldistance\" [3.5]"},
        {"mitsuba", ".xml", "<sensor type=\"thinlens\">\n"
                            "        <float name=\"aperture_radius\" value=\"0.25\"/>\n"
                            "        <float name=\"focus_distance\" value=\"3.5\"/>"},
        {"blender", ".py", ", 0.25, 3.5)\n# the background"},
    };
    /* a pinhole: no lens in pbrt and Mitsuba, radius 0 in Blender's camera() */
    static const char *const pinhole[3][2] = {
        {"lensradius", ""}, {"thinlens", ""}, {"", ", 0, 0)\n# the background"}};
    char defocused[sizeof every_kind + 32], words[64];
    strcpy(defocused, every_kind);
    char *fov = strstr(defocused, "  30\n");
    snprintf(fov, sizeof defocused - (size_t)(fov - defocused), "  30 aperture 0.25 focus 3.5%s",
             strstr(every_kind, "  30\n") + 4);
    for (int i = 0; i < 3; i++) {
        struct exported e;
        snprintf(words, sizeof words, "--format %s", lens[i][0]);
        export_scene(&e, "lens", defocused, words, lens[i][1]);
        CHECK(t, e.status == 0 && has(&e, lens[i][2]));
        exported_free(&e);
        export_scene(&e, "pinhole", every_kind, words, lens[i][1]);
        CHECK(t, e.status == 0 && e.text != NULL);
        CHECK(t, pinhole[i][0][0] == '\0' || !has(&e, pinhole[i][0]));
        CHECK(t, pinhole[i][1][0] == '\0' || has(&e, pinhole[i][1]));
        exported_free(&e);
    }
}

void test_export(struct check *t)
{
    RUN_TEST(t, test_pbrt_camera_and_film);
    RUN_TEST(t, test_pbrt_lights);
    RUN_TEST(t, test_pbrt_materials_and_shapes);
    RUN_TEST(t, test_channel);
    RUN_TEST(t, test_mitsuba);
    RUN_TEST(t, test_lens_exports);
    RUN_TEST(t, test_shipped_scenes);
    RUN_TEST(t, test_failures);
    RUN_TEST(t, test_names_escaped);
}
