/*
 * tests/test_export_blender.c -- `photon export --format blender`: the Python script's
 * numbers against values worked out by hand from a small scene (the script itself runs
 * only where Blender is installed: make crosscheck).
 *
 * The scene (SCENE below), and what each convention makes of it:
 *   - camera from (10, 0, 0) at the origin, up +y, 60 degrees: w = (-1, 0, 0),
 *     u = w x up = (0, 0, -1), v = u x w = (0, 1, 0); Blender's world matrix has the
 *     columns u, v, -w, from, so its rows are (0 0 1 10), (0 1 0 0), (-1 0 0 0), and
 *     angle_y is pi / 3 = 1.04719755 rad;
 *   - the farthest point from the camera is the glass sphere's far side, 13 + 1.5 = 14.5:
 *     UNIT = 2^-ceil(log2 14.5) = 2^-4 = 0.0625;
 *   - the point light of power (100, 200, 400) W: energy max(Phi) = 400 with colour
 *     Phi / 400 = (0.25, 0.5, 1) (Cycles' power P is intensity P / (4 pi));
 *   - the quad light of radiance (17, 12, 4): material light#1 (the glow triangle is
 *     light 0), black, emitting (17, 12, 4) from its front only; glow emits (1, 2, 3)
 *     from both sides;
 *   - glass of ior 1.5 letting (0.9, 0.8, 0.7) through: the refraction's colour;
 *   - the chrome sphere of radius 2: a point cloud; the glass sphere an icosphere;
 *   - Phong kd 0.2, ks 0.3, n 30: Beckmann alpha = sqrt(2 / 32) = 0.25, Blender's
 *     roughness sqrt(alpha) = 0.5; Schlick C 0.8, r 0.25: b = 4 r (1 - r) = 0.75, a = 0,
 *     c = 1 - b = 0.25, so Diffuse 0, GGX 0.6 of alpha sqrt(r) = 0.5 (roughness
 *     0.707106781) and a mirror of 0.2.
 */
#include <stdlib.h>
#include <string.h>

#include "files.h"
#include "tests.h"

#define OUT "build/test_export_blender"

static const char SCENE[] =
    "image 64 48\n"
    "camera 10 0 0  0 0 0  0 1 0  60\n"
    "background 0.25 0.5 0.75\n"
    "material white lambert 0.5 0.5 0.5\n"
    "material chrome mirror 0.9 0.8 0.7\n"
    "material tinted glass 1.5 0.9 0.8 0.7\n"
    "material glow lambert 0 0 0 emit 1 2 3 twosided\n"
    "material plastic phong 0.2 0.2 0.2 0.3 0.3 0.3 30\n"
    "material satin schlick 0.8 0.8 0.8 0.25\n"
    "triangle -1 -1 0  1 -1 0  0 1 0  white\n"
    "triangle -1 -1 1  1 -1 1  0 1 1  glow\n"
    "triangle -1 -1 2  1 -1 2  0 1 2  plastic\n"
    "triangle -1 -1 3  1 -1 3  0 1 3  satin\n"
    "light quad -1 4 -1  1 4 -1  1 4 1  -1 4 1  17 12 4\n"
    "sphere 3 0 0 2 chrome\n"
    "sphere -3 0 0 1.5 tinted\n"
    "light point 0 5 0  100 200 400\n";

/* Exports SCENE with --spp 77 to OUT.py (the notes in OUT.log); the script's text, or
 * NULL (the caller frees). */
static char *export_scene(void)
{
    char scene[256];
    temp_name(scene, sizeof scene, "export_blender", "scene.scene");
    write_text_file(scene, SCENE);
    char args[512];
    snprintf(args, sizeof args, "--format blender --spp 77 %s -o " OUT ".py", scene);
    int status = photon_logged("export", args, OUT ".log");
    remove(scene);
    return status == 0 ? read_text_file(OUT ".py") : NULL;
}

/* truth: the conventions of src/app/export_blender.c, worked out by hand above.
 * catches: a transposed or mirrored camera matrix, degrees for radians, the horizontal
 *   field of view, a point light off by pi or 4 pi, an emitter shining from its back,
 *   absorption written where the filter belongs, a sphere of the wrong radius or glass
 *   made a point cloud (Cycles' points have no inside), the sample count lost. */
static void test_blender_script_numbers(struct check *t)
{
    char *py = export_scene();
    REQUIRE(t, py != NULL);
    CHECK(t, strstr(py, "\nsettings(64, 48, 77)\n") != NULL);
    CHECK(t, strstr(py, "\nUNIT = 0.0625\n") != NULL);
    CHECK(t, strstr(py, "data.type, data.sensor_fit = 'PERSP', 'VERTICAL'") != NULL);
    CHECK(t, strstr(py, "\ncamera(((0, 0, 1, 10),\n"
                        "        (0, 1, 0, 0),\n"
                        "        (-1, 0, 0, 0),\n"
                        "        (0, 0, 0, 1)), 1.04719755, ") != NULL);
    CHECK(t, strstr(py, "\nworld((0.25, 0.5, 0.75))\n") != NULL);
    CHECK(t, strstr(py, "\npoint_light((0, 5, 0), 400, (0.25, 0.5, 1))\n") != NULL);
    /* lengths are ours times UNIT, so the power is UNIT^2 ours: the same irradiance */
    CHECK(t, strstr(py, "data.energy, data.color = UNIT * UNIT * energy, colour") != NULL);
    CHECK(t, strstr(py, "data.shadow_soft_size = 0.0") != NULL);
    CHECK(t, strstr(py, "\nM0 = material('m0 white', 'lambert', rho=(0.5, 0.5, 0.5))\n") != NULL);
    CHECK(t, strstr(py, "\nM1 = material('m1 chrome', 'mirror', rho=(0.9, 0.8, 0.7))\n") != NULL);
    CHECK(t, strstr(py, "\nM2 = material('m2 tinted', 'glass', ior=1.5, "
                        "filter=(0.9, 0.8, 0.7))\n") != NULL);
    CHECK(t, strstr(py, "\nM3 = material('m3 glow', 'lambert', rho=(0, 0, 0),\n"
                        "    emission=(1, 2, 3), two_sided=True)\n") != NULL);
    CHECK(t, strstr(py, "\nM4 = material('m4 plastic', 'glossy', rho=(0.2, 0.2, 0.2), "
                        "rho_s=(0.3, 0.3, 0.3), mirror=(0, 0, 0),\n"
                        "    distribution='BECKMANN', roughness=0.5)\n") != NULL);
    CHECK(t, strstr(py, "\nM5 = material('m5 satin', 'glossy', rho=(0, 0, 0), "
                        "rho_s=(0.6, 0.6, 0.6), mirror=(0.2, 0.2, 0.2),\n"
                        "    distribution='GGX', roughness=0.707106781)\n") != NULL);
    CHECK(t, strstr(py, "\nM6 = material('m6 light#1', 'lambert', rho=(0, 0, 0),\n"
                        "    emission=(17, 12, 4), two_sided=False)\n") != NULL);
    /* emission strength 1 is radiance Le; a Mix on Backfacing darkens the back side */
    CHECK(t, strstr(py, "e = shader(nt, 'ShaderNodeEmission', emission, Strength=1.0)") != NULL);
    CHECK(t, strstr(py, "back = nt.nodes.new('ShaderNodeNewGeometry').outputs['Backfacing']") !=
                 NULL);
    CHECK(t, strstr(py, "e = mix(nt, back, e, None)") != NULL);
    /* glass: Fresnel of our ior mixing refraction through the filter and a white mirror */
    CHECK(t, strstr(py, "fresnel = shader(nt, 'ShaderNodeFresnel', IOR=ior)") != NULL);
    CHECK(t, strstr(py, "refract = sharp(shader(nt, 'ShaderNodeBsdfRefraction', filter, "
                        "IOR=ior))") != NULL);
    CHECK(t, strstr(py, "s = mix(nt, fresnel.outputs[0], refract, reflect)") != NULL);
    CHECK(t, strstr(py, "\nspheres('spheres m1', M1, floats('''\n3 0 0'''),\n"
                        "    floats('''\n2'''))\n") != NULL);
    CHECK(t, strstr(py, "\nsphere_mesh('sphere 1', M2, (-3, 0, 0), 1.5, 6)\n") != NULL);
    CHECK(t, strstr(py, "\nmesh('mesh 0', M0, floats('''\n-1 -1 0  1 -1 0  0 1 0'''))\n") !=
             NULL);
    /* the light quad as two triangles keeping its front (e1 x e2, here -y: facing down) */
    CHECK(t, strstr(py, "floats('''\n-1 4 -1  1 4 -1  1 4 1\n-1 4 -1  1 4 1  -1 4 1'''))") !=
             NULL);
    /* a box pixel filter one pixel wide, nothing biased */
    CHECK(t, strstr(py, "c.pixel_filter_type, c.filter_width, c.film_exposure = 'BOX', 1.0, "
                        "1.0") != NULL);
    CHECK(t, strstr(py, "c.sample_clamp_direct = c.sample_clamp_indirect = 0.0") != NULL);
    CHECK(t, strstr(py, "c.use_denoising = c.use_adaptive_sampling = False") != NULL);
    CHECK(t, strstr(py, "f.write(b'PF\\n%d %d\\n-1.0\\n' % (w, h))") != NULL);
    CHECK(t, strstr(py, "\nrender()\n") != NULL);
    free(py);
}

/* truth: what Cycles cannot render exactly is said on stderr (export.h), never silently.
 * catches: a Phong or Schlick material, or a sphere made a mesh, exported without a word. */
static void test_blender_notes(struct check *t)
{
    char *py = export_scene();
    REQUIRE(t, py != NULL);
    free(py);
    CHECK(t, file_contains(OUT ".log", "material \"plastic\": Cycles has no Phong model"));
    CHECK(t, file_contains(OUT ".log", "material \"satin\": Schlick's model as Diffuse + GGX"));
    CHECK(t, file_contains(OUT ".log", "sphere 1 (material \"tinted\"): glass"));
    CHECK(t, !file_contains(OUT ".log", "\"chrome\""));
}

void test_export_blender(struct check *t)
{
    RUN_TEST(t, test_blender_script_numbers);
    RUN_TEST(t, test_blender_notes);
}
