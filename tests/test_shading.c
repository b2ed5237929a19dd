/*
 * tests/test_shading.c -- shading normals, against closed forms: in every mode, a triangle
 * whose shading normal turns away from the camera reflects nothing towards it
 * (scenes/analytic/turned-away.scene); in the photon map, a floor whose shading normal
 * tilts towards a point light is as bright as its shading cosine says
 * (scenes/analytic/tilted-normal.scene).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/image/image.h"
#include "files.h"
#include "tests.h"
#include "truths.h"

/* The scene's triangle, as its file writes it. */
static const struct vec3 corner[3] = {{-1, 0.2, 0}, {0, 1.8, 0}, {1, 0.2, 0}};

/* Whether camera ray r meets the triangle: where it crosses z = 0, inside all three edges
 * (the triangle lies in that plane, so a 2-D test in x, y decides). */
static int meets_triangle(struct ray r)
{
    if (!(fabs(r.dir.z) > 0))
        return 0;
    double t = -r.origin.z / r.dir.z;
    if (!(t > 0))
        return 0;
    double x = r.origin.x + t * r.dir.x, y = r.origin.y + t * r.dir.y;
    int inside = 1;
    for (int i = 0; i < 3; i++) {
        struct vec3 a = corner[i], b = corner[(i + 1) % 3];
        double side = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
        inside = inside && side < 0; /* the corners run clockwise seen from z < 0 */
    }
    return inside;
}

/* Whether all of pixel (x, y) shows the triangle: an 8 x 8 grid over its square, and its
 * corners, all meet it. */
static int pixel_on_triangle(const struct scene *scene, int x, int y)
{
    for (int j = 0; j <= 8; j++)
        for (int i = 0; i <= 8; i++)
            if (!meets_triangle(camera_ray(&scene->camera, x + i / 8.0, y + j / 8.0)))
                return 0;
    return 1;
}

/* truth: L = 0 on every pixel wholly on the triangle (the derivation in the scene file:
 * wo . n_s < 0 there, and a BRDF reflects only into its shading normal's hemisphere); the
 * rest of the image is lit (floor and sky, mean above 0.3), so the black is not that of a
 * scene without light.
 * tolerance: none: every term of every mode is a BRDF value of exactly zero times
 *   something finite.
 * catches: a mode's shortcut that reflects rho / pi times the irradiance without asking
 *   the BRDF whether it reflects towards wo at all (1996's irradiance cache and gathers
 *   did: 0.21 on the triangle, and the smooth octahedron of scenes/obj-example.scene 10%
 *   bright), a gather or photon estimate that tests the geometric normal only. */
static void test_turned_away_normal_in_every_mode(struct check *t)
{
    static const struct {
        const char *mode, *options;
    } modes[] = {
        {"direct", "--spp 4"},
        {"pt", "--spp 16"},
        {"photons", "--spp 4 --photons 100000"},
        {"1994", "--spp 4 --photons 100000 --gather-rays 32"},
        {"1996", "--spp 4 --photons 100000 --gather-rays 32"},
        {"1996", "--spp 4 --photons 100000 --gather-rays 32 --cache-accuracy 0"},
        {"1996", "--paper --spp 4 --photons 100000 --gather-rays 32"},
        {"2008", "--spp 4 --passes 8 --photons-per-pass 20000"},
        {"2009", "--passes 16 --photons-per-pass 20000"},
    };
    const char *path = "scenes/analytic/turned-away.scene";
    struct scene *scene = load_test_scene(path, 0, 0);
    REQUIRE(t, scene != NULL);
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        char options[256];
        snprintf(options, sizeof options, "--mode %s %s", modes[m].mode, modes[m].options);
        struct image *img = photon_render("shading", options, path);
        CHECK(t, img != NULL);
        if (img != NULL) {
            int covered = 0, lit = 0;
            double brightest = 0.0, rest = 0.0;
            for (int y = 0; y < img->height; y++)
                for (int x = 0; x < img->width; x++) {
                    struct vec3 c = image_get(img, x, y);
                    if (pixel_on_triangle(scene, x, y)) {
                        covered++;
                        brightest = fmax(brightest, vec3_max_component(c));
                    } else {
                        lit++;
                        rest += c.y;
                    }
                }
            printf("  shading: %-7s %-33s triangle's brightest %.4f (%d pixels), rest %.3f\n",
                   modes[m].mode, modes[m].options, brightest, covered, rest / lit);
            CHECK(t, covered >= 20);
            CHECK(t, brightest == 0.0);
            CHECK(t, rest / lit > 0.3);
            image_free(img);
        }
    }
    scene_free(scene);
}

/* tilted-normal.scene's light, floor and shading normal (the scene file's derivation). */
#define TILT_PHI 100.0
#define TILT_RHO 0.8
static const struct vec3 tilt_light = {1, 2, 0};

/* L where camera ray r meets the floor y = 0: rho Phi (n_s . (l - x)) / (4 pi^2 d^3). */
static double tilt_truth(struct ray r)
{
    struct vec3 x = vec3_madd(r.origin, r.dir, -r.origin.y / r.dir.y);
    struct vec3 to = vec3_sub(tilt_light, x);
    struct vec3 ns = vec3_normalize(vec3(1, sqrt(3.0), 0));
    double d = vec3_length(to);
    return TILT_RHO * TILT_PHI * vec3_dot(ns, to) / (4 * PI * PI * d * d * d);
}

/* truth: the closed form above, each pixel the mean of an 8 x 8 grid over its square.
 * tolerance: the image mean within 1% and each 8 x 8 quarter within 3% at 2,000,000
 *   photons of 400 an estimate; the geometric cosine in place of the shading one is 9%
 *   dark in the mean, 15% in the darkest quarter.
 * catches: photons stored with the flux through the geometric surface where the BRDF
 *   integrates against the shading normal's cosine (trace.c, shading_share()), a share
 *   turned upside down (as bright as the dark is dark). */
static void test_tilted_normal_in_the_photon_map(struct check *t)
{
    const char *path = "scenes/analytic/tilted-normal.scene";
    struct scene *scene = load_test_scene(path, 0, 0);
    REQUIRE(t, scene != NULL);
    struct image *img = photon_render(
        "shading", "--mode photons --photons 2000000 --gather 400 --spp 4", path);
    CHECK(t, img != NULL);
    if (img != NULL) {
        double sum = 0.0, truth_sum = 0.0, worst = 0.0;
        for (int by = 0; by < img->height; by += 8)
            for (int bx = 0; bx < img->width; bx += 8) {
                double b = 0.0, truth = 0.0;
                for (int y = by; y < by + 8; y++)
                    for (int x = bx; x < bx + 8; x++) {
                        b += image_get(img, x, y).y;
                        for (int j = 0; j < 8; j++)
                            for (int i = 0; i < 8; i++)
                                truth += tilt_truth(camera_ray(
                                             &scene->camera, x + (i + 0.5) / 8,
                                             y + (j + 0.5) / 8)) /
                                         64.0;
                    }
                sum += b;
                truth_sum += truth;
                worst = fmax(worst, fabs(b / truth - 1.0));
            }
        printf("  shading: tilted normal, photons: mean %.4f, worst block %.2f%%\n",
               sum / truth_sum, 100 * worst);
        CHECK(t, fabs(sum / truth_sum - 1.0) <= 0.01);
        CHECK(t, worst <= 0.03);
        image_free(img);
    }
    scene_free(scene);
}

void test_shading(struct check *t)
{
    RUN_TEST(t, test_turned_away_normal_in_every_mode);
    RUN_TEST(t, test_tilted_normal_in_the_photon_map);
}
